# The C interface between generated models and camdyn.runtime.
#
# A generated module fills one ModelC with pointers to its nogil functions and
# hands it to Python as a PyCapsule named "camdyn.ModelC".  Its `run` is the
# set of integration loops of runtime/engine/loops.pxi, compiled inside the model's
# module so that the right-hand side is inlined into every stage; the driver
# in camdyn.runtime.engine.driver calls it once per run.  The other pointers serve
# evaluation from Python (outputs, one-off rhs calls).
#
# State layout: y = [q_1..q_n, q'_1..q'_n, first-order states...].
# This header has no .pyx of its own on purpose: cimporting it never imports
# a module at run time.

cdef enum:
    CAMDYN_ABI = 15

# method codes
cdef enum:
    METHOD_RK4 = 0
    METHOD_DP54 = 1
    METHOD_KOSTER = 2
    METHOD_RODAS = 3       # RODAS4, linearly implicit (stiff problems)
    METHOD_DOP853 = 4      # Dormand-Prince 8(5,3), explicit, high order
    METHOD_RADAU = 5       # Radau IIA of order 5 (RADAU5), implicit (stiff problems; ABI 9)
    METHOD_RKN12 = 6       # Runge-Kutta-Nystrom 12(10), explicit, q'' free of q' (ABI 12)

# run status codes
cdef enum:
    STATUS_OK = 0
    STATUS_MAX_STEPS = 1
    STATUS_STEP_UNDERFLOW = 2
    STATUS_NOT_FINITE = 3
    STATUS_NO_MEMORY = 4
    STATUS_NO_CONVERGENCE = 5
    STATUS_BAD_MODEL = 6
    STATUS_EVENT_STORM = 7
    STATUS_UNSTABLE = 8     # a fixed step beyond the method's stability boundary (stab_mode 2)

cdef struct Ctx:
    const double* p        # parameters, in manifest order
    double* k              # parameter-only constants, filled by prepare()
    const int* law         # cam law code per cam input family
    const double* law_par  # cam law parameter (theta of the modified sine) per family
    int* mode              # cam segment per cam input instance, then the force elements' modes
    int variant            # bit i set: cam instance i sits in a dwell (set by update_modes)
    double* cache          # per cam instance [argument, H, H', H'', H''']: the last evaluation;
                           # in a dwell H holds the dwell value (n_cache doubles)
    const int* part        # a constrained model's coordinate partition for this run: the n_c
                           # dependent coordinates' indices, then the n_q - n_c independent
                           # ones'; NULL for the model's declared one (ABI 11).  Per run, not
                           # per module, so that runs on other threads may choose otherwise

cdef struct Record:
    # one row per recorded point: [t, y (ns), f (ns), extra (n_extra x ns)]; f is
    # the slope there (left limit at the end of an interval), `extra` the higher
    # dense-output terms of the step that starts at the point (dense.pxd): none for
    # the cubic Hermite interpolant (RK4, the thesis scheme), one for DP54's quartic, two
    # for RADAU5's and RODAS4's quintic over three points (ABI 14), four for DOP853's
    # degree-7 extension (ABI 8).
    # `mode` holds the modes in force from the point on.
    Py_ssize_t n
    Py_ssize_t cap
    int width              # doubles per row: 1 + (2 + n_extra) ns
    int n_extra
    bint owned             # buffers were (re)allocated by the loop: the driver frees them
    double* rows
    int* mode

cdef struct Run:
    Ctx* ctx
    Record rec
    int method
    const double* stops    # end times of the intervals (breakpoints, then t_end)
    int n_stops
    double t0
    double* y              # state, in and out
    double h               # fixed step; adaptive: first step (0 = automatic), then the last one
    double h_max
    double rtol
    const double* atol
    long max_steps
    long n_steps
    long n_rejected
    long n_rhs
    long n_events          # events located and applied
    long n_jac             # Jacobians evaluated by the implicit methods (ABI 9)
    long n_lu              # LU factorizations of their iteration matrices (ABI 9)
    long max_events
    double t_fail
    double err_old
    double t_stiff         # DP54, DOP853: where Hairer's stiffness test first fired; NaN if never
    # the fixed-step stability check (RK4, the thesis scheme; loops.pxi, _stab_check): h |lambda|
    # of the model's Jacobian against the method's boundary b in lambda's direction (ABI 6)
    int stab_mode          # 0 no check; 1 estimate only (the stability map's runs); 2 estimate
                           # and stop with STATUS_UNSTABLE where h |lambda|/b first exceeds 1
    const double* stab_bound  # b at |Re lambda|/|lambda| = k/(n_stab_bound - 1), k = 0, 1, ...
    int n_stab_bound       # (one value: the same boundary in every direction)
    double* stab_work      # n_states + 2 doubles the check keeps between intervals, or NULL
    double stab_ratio      # largest h |lambda|/b seen (-1 before the first check), ...
    double stab_t          # ... where, ...
    double stab_rho        # ... |lambda| of the limiting eigenvalue there ...
    double stab_b          # ... and b in its direction
    long n_checks          # Jacobians checked
    bint exact             # step over an interval exactly where the model is linear and time
                           # invariant there (loops.pxi, _loop_exact; ABI 7)
    bint skip_dense        # DOP853: leave out the dense output's three stages (a sixth of a
                           # step's calls) where no event crossed, its extras NaN but the
                           # second, the step's length, so that ModelC.dense_fill makes them
                           # where they are wanted (ABI 15); RKN12: all of it, and whoever
                           # needs it runs again with it (Result.record; ABI 12)
    bint exact_whole       # with exact: every linear interval in one step, its end alone
                           # recorded and no dense output across it (the extras zero): for a
                           # figure read off its end state in closed form (finder.pyx's
                           # sweep_residual; ABI 13)

ctypedef void (*prep_fn)(Ctx* ctx) noexcept nogil
ctypedef void (*rhs_fn)(double t, const double* y, double* dy, Ctx* ctx) noexcept nogil
ctypedef void (*out_fn)(double t, const double* y, double* out, Ctx* ctx) noexcept nogil
ctypedef void (*mode_fn)(double t, const double* y, Ctx* ctx) noexcept nogil
ctypedef int (*run_fn)(Run* run) noexcept nogil
ctypedef void (*event_fn)(double t, const double* y, double* g, Ctx* ctx) noexcept nogil
ctypedef void (*action_fn)(int k, double t, double* y, Ctx* ctx) noexcept nogil
ctypedef void (*ms_fn)(double t, const double* y, double* M, double* K, Ctx* ctx) noexcept nogil
ctypedef void (*jac_fn)(double t, const double* y, double* J, double* ft, Ctx* ctx) noexcept nogil
ctypedef int (*proj_fn)(double t, double* y, Ctx* ctx) noexcept nogil
ctypedef int (*fill_fn)(Ctx* ctx, double* row) noexcept nogil

cdef struct ModelC:
    int abi_version        # CAMDYN_ABI; checked before any call
    int n_q                # second-order coordinates
    int n_states
    int n_params
    int n_outputs
    int n_families         # cam input families (H, ...)
    int n_instances        # distinct cam input arguments (one segment mode each)
    int n_modes            # all modes: the cam segments first, then the force elements'
    int n_events
    int n_const            # parameter-only constants
    int n_cache            # doubles of ctx.cache
    prep_fn prepare        # fills ctx.k from ctx.p
    rhs_fn rhs             # dy = f(t, y)
    out_fn outputs         # named outputs at (t, y)
    mode_fn update_modes   # segment of every cam input at (t, y), right-continuous
    prep_fn refresh        # ctx.variant from ctx.mode (after setting modes by hand)
    event_fn events        # event functions g_k(t, y)
    action_fn on_event     # modes (and state resets) at event k
    ms_fn mass_stiffness   # M and K = -df/dq, for frozen (linearized) analyses
    jac_fn jac             # J = d(dy/dt)/dy, row-major n_states x n_states (ABI 4; the
                           # manifest's "jacobian" says how: "symbolic" or "finite-difference"),
                           # and df/dt into ft unless NULL where the manifest's
                           # "time_derivative" is "symbolic" (ABI 5)
    run_fn run             # the integration loops (loops.pxi) with this model's rhs inlined
    proj_fn project        # a constrained model's projection of y onto its constraints, in
                           # place (1; -1 without convergence; 0, y untouched, unless its
                           # formulation is 2), which the loops call after every accepted
                           # step; NULL for unconstrained models (ABI 10)
    fill_fn dense_fill     # a recorded DOP853 row's left-out dense output, made (loops.pxi;
                           # the calls made, 0 if the row has it; ABI 15)


cdef inline bint partition_ok(const ModelC* m, const int* part, Py_ssize_t n) noexcept nogil:
    """``part`` (n entries) is a coordinate partition of the constrained model m (Ctx.part):
    each of its n_q coordinates once.  The generated code indexes with it unchecked."""
    cdef Py_ssize_t i, j
    if m.project == NULL or n != m.n_q:
        return False
    for i in range(n):
        if not 0 <= part[i] < n:
            return False
        for j in range(i):
            if part[j] == part[i]:
                return False
    return True


cdef inline bint adaptive_method(int method) noexcept nogil:
    return (method == METHOD_DP54 or method == METHOD_RODAS or method == METHOD_DOP853
            or method == METHOD_RADAU or method == METHOD_RKN12)


cdef inline int extra_terms(int method, bint exact) noexcept nogil:
    """Dense-output terms beyond the cubic Hermite interpolant a record holds per step: RKN12's
    eight (degree 11, fitted to interior steps; loops.pxi, _loop_rkn12), DOP853's four, DP54's
    one, RADAU5's and RODAS4's two (the quintic Hermite interpolant over three points,
    loops.pxi, _rec_three_point), none for the others; four for every other adaptive method
    that steps over linear segments exactly, whose record there is a degree-7 extension
    through the exact state (loops.pxi, _loop_exact).  A method's own steps leave the terms it
    lacks zero, which is its own interpolant (dense.pxd)."""
    if method == METHOD_RKN12:
        return 8
    if method == METHOD_DOP853 or (exact and adaptive_method(method)):
        return 4
    if method == METHOD_RADAU or method == METHOD_RODAS:
        return 2
    return 1 if method == METHOD_DP54 else 0


cdef inline long fixed_steps(double a, double b, double h) noexcept nogil:
    """Number of equal steps no longer than h over [a, b] (RK4, thesis scheme)."""
    cdef double x = (b - a) / h * (1.0 - 1e-12)
    cdef long n = <long> x
    if n < x:
        n += 1
    return n if n > 0 else 1
