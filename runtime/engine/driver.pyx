# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
"""Driver of the compiled integration loops, and compiled evaluation helpers.

The loops themselves (runtime/engine/loops.pxi) are compiled into every generated
model with its right-hand side inlined; ``Integrator.run`` prepares the buffers
and calls them through the model's ModelC.run, once, without the GIL.  The record
is written straight into NumPy arrays sized in advance (the last run's again, once
nothing refers to them any more); only when a run outgrows them (adaptive steps)
do the loops move to buffers of their own, which are copied once at the end.

The helpers below (outputs, rhs, dense output) serve post-processing and
tests; they call the model through its function pointers.
"""
from cpython.buffer cimport (PyBUF_C_CONTIGUOUS, PyBUF_FORMAT, PyBUF_WRITABLE, PyBuffer_Release,
                             PyObject_GetBuffer)
from cpython.dict cimport PyDict_GetItem, PyDict_Next
from cpython.float cimport PyFloat_AS_DOUBLE, PyFloat_CheckExact
from cpython.object cimport PyObject
from cpython.mem cimport PyMem_Free, PyMem_Malloc
from cpython.pycapsule cimport PyCapsule_GetPointer, PyCapsule_IsValid
from cpython.ref cimport Py_REFCNT
from libc.math cimport NAN, fabs, fmax, isfinite
from libc.stdlib cimport free
from libc.string cimport memcpy
from posix.time cimport CLOCK_MONOTONIC, clock_gettime, timespec

import numpy as np

from camdyn.runtime.engine.abi cimport *
from camdyn.runtime.engine.dense cimport dense_component
from camdyn.runtime.engine.partition cimport check_partition
from camdyn.runtime.engine.dop853 cimport D8_A, D8_C, D8_D, D8_E3, D8_E5
from camdyn.runtime.engine.linalg cimport clu_factor, clu_solve, lu_factor, lu_solve
from camdyn.runtime.engine.radau cimport *
from camdyn.runtime.engine.rkn12 cimport RK12_A, RK12_BP, RK12_BPL, RK12_BV, RK12_BVL, RK12_C

RK4 = METHOD_RK4
DP54 = METHOD_DP54
KOSTER = METHOD_KOSTER
RODAS = METHOD_RODAS
DOP853 = METHOD_DOP853
RADAU = METHOD_RADAU
RKN12 = METHOD_RKN12

cdef class RunRecord:
    """What Integrator.run returns: the status (STATUS_TEXT), the record (``rows``: t, states and
    slopes at every recorded point; ``modes`` in force from each point on; ``n`` of them
    filled), step and right-hand-side counts, where a failed run stopped (``t_fail``), the wall
    time of the compiled loops, the number of events and, for DP54 and DOP853, the time where
    Hairer's stiffness test first fired (``t_stiff``, NaN if it never did); for a fixed-step run with the
    stability check (``stab_mode``), the largest h |lambda|/b it saw (``stab_ratio``, -1 without a
    check; beyond 1 the step is unstable), where (``stab_t``), that eigenvalue's |lambda|
    (``stab_rho``), the boundary b in its direction (``stab_b``), and the Jacobians checked.

    An extension type rather than a named tuple: it is made once per run, and filling its
    fields from C costs a fraction of building a tuple of sixteen Python objects."""

    cdef readonly int status
    cdef readonly object rows, modes
    cdef readonly Py_ssize_t n
    cdef readonly long n_steps, n_rejected, n_rhs, n_events, n_checks, n_jac, n_lu
    cdef readonly double t_fail, seconds, t_stiff, stab_ratio, stab_t, stab_rho, stab_b

    def __repr__(self):
        return (f"RunRecord(status={self.status}, n={self.n}, n_steps={self.n_steps}, "
                f"n_rejected={self.n_rejected}, n_rhs={self.n_rhs}, t_fail={self.t_fail!r}, "
                f"seconds={self.seconds!r}, n_events={self.n_events}, t_stiff={self.t_stiff!r}, "
                f"stab_ratio={self.stab_ratio!r}, stab_t={self.stab_t!r}, "
                f"stab_rho={self.stab_rho!r}, stab_b={self.stab_b!r}, n_checks={self.n_checks})")


STATUS_TEXT = {
    STATUS_OK: "ok",
    STATUS_MAX_STEPS: "the step budget (max_steps) was used up",
    STATUS_STEP_UNDERFLOW: "the step size fell below the resolution of the time axis",
    STATUS_NOT_FINITE: "the state became non-finite (NaN or inf)",
    STATUS_NO_MEMORY: "out of memory while recording the trajectory",
    STATUS_NO_CONVERGENCE: ("the mid-step acceleration of the thesis scheme did not converge; "
                            "use a smaller step"),
    STATUS_BAD_MODEL: ("the model is not purely second order (or has events), which the thesis "
                       "scheme and RKN12 require"),
    STATUS_EVENT_STORM: "more events than max_events (chattering contact or friction?)",
    STATUS_UNSTABLE: "the step is beyond the method's stability boundary; use a smaller step",
}
UNSTABLE = STATUS_UNSTABLE
NO_CONVERGENCE = STATUS_NO_CONVERGENCE
PROJECTION_TEXT = ("the projection onto the constraints did not converge (formulation 2: no "
                   "configuration on them near the step's end, or Phi_Q losing rank there); "
                   "try a tighter rtol or formulation 0")
"""What STATUS_NO_CONVERGENCE means in every method but the thesis scheme: a constrained
model's project() failed after an accepted step (loops.pxi, _project_accepted)."""
CHECK_OFF, CHECK_ESTIMATE, CHECK_STOP = 0, 1, 2

# Integrator.run allocates its record with these, called positionally: looking up np.empty
# and passing dtype by keyword cost a tenth of a microsecond in a call that takes a few
_empty = np.empty
_FLOAT = np.dtype(float)
_INTC = np.dtype(np.intc)

# doubles of scratch (state, constants, cam cache, stability vector, modes) Integrator.run
# keeps on the stack; a larger model's go on the heap
cdef enum:
    SCRATCH_LOCAL = 256
# the largest record (bytes of rows and modes) an Integrator keeps for its next run: enough
# for the short runs whose fixed cost it saves, little for the simulators simulate() keeps
cdef enum:
    SPARE_BYTES = 262144


cdef int _export(object obj, Py_buffer* view, int ndim, char code, bint writable,
                 str what) except -1:
    """A C-contiguous buffer of obj, ndim dimensions of the C type ``code`` ('d' double, 'i'
    int), as a typed memoryview would take it, without the memoryview: making one costs a
    tenth of a microsecond, and Integrator.run takes four arrays in a call of a few.  The
    caller releases the view."""
    PyObject_GetBuffer(obj, view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT
                                  | (PyBUF_WRITABLE if writable else 0))
    cdef const char* fmt = view.format
    if fmt != NULL and (fmt[0] == b'@' or fmt[0] == b'='):
        fmt += 1
    if (view.ndim != ndim or fmt == NULL or fmt[0] != code or fmt[1] != 0 or view.itemsize !=
            (<Py_ssize_t> sizeof(double) if code == b'd' else <Py_ssize_t> sizeof(int))):
        PyBuffer_Release(view)
        raise ValueError(f"{what}: expected a C-contiguous {ndim}-d array of "
                         f"{'float64' if code == b'd' else 'intc'}")
    return 0


cdef bint _refill(object rows, object modes, Py_buffer* rb, Py_buffer* mb, Py_ssize_t cap,
                  int width, int nm):
    """Whether a kept record (rows, modes) takes cap points of this width, its buffers then
    exported into rb and mb; not when the arrays were changed (shape, type, flags) since."""
    try:
        _export(rows, rb, 2, b'd', True, "record")
    except Exception:
        return False
    try:
        _export(modes, mb, 2, b'i', True, "record modes")
    except Exception:
        PyBuffer_Release(rb)
        return False
    if rb.shape[0] >= cap and rb.shape[1] == width and mb.shape[0] == rb.shape[0] \
            and mb.shape[1] == nm:
        return True
    PyBuffer_Release(rb)
    PyBuffer_Release(mb)
    return False


cdef ModelC* model_pointer(object capsule) except NULL:
    if not PyCapsule_IsValid(capsule, b"camdyn.ModelC"):
        raise TypeError("expected the MODEL capsule of a generated camdyn model")
    cdef ModelC* m = <ModelC*> PyCapsule_GetPointer(capsule, b"camdyn.ModelC")
    if m.abi_version != CAMDYN_ABI:
        raise RuntimeError(f"generated model built for ABI {m.abi_version}, runtime has {CAMDYN_ABI}; "
                           "rebuild (pip install -e .) after `camdyn derive`")
    return m


cdef class ParameterTable:
    """A model's parameters (names, defaults, ranges) for CompiledModel.parameter_vector's
    common case, checked in C: every value given an exact float, finite and in its range.
    The same checks in Python cost about half a microsecond a call, a tenth of a short run."""

    cdef dict index                      # name -> position
    cdef double[::1] defaults, lo, hi    # lo, hi: -inf, inf where unbounded
    cdef int[::1] open_lo, open_hi       # 1 where the bound itself is excluded

    def __init__(self, names, defaults, lo, hi, open_lo, open_hi):
        self.index = {name: k for k, name in enumerate(names)}
        self.defaults = np.array(defaults, dtype=float)
        self.lo, self.hi = np.array(lo, dtype=float), np.array(hi, dtype=float)
        self.open_lo = np.array(open_lo, dtype=np.intc)
        self.open_hi = np.array(open_hi, dtype=np.intc)
        if not (len(self.index) == self.defaults.shape[0] == self.lo.shape[0] == self.hi.shape[0]
                == self.open_lo.shape[0] == self.open_hi.shape[0]):
            raise ValueError("one name, default and range per parameter expected")

    def vector(self, values):
        """The parameter vector: the defaults, overridden by ``values`` ({name: float}); None
        unless values is a dict whose every value is an exact float (not an int, a bool or
        a NumPy scalar), finite and in its parameter's range, under a parameter's name.  The
        caller's own checks take what this declines, and say what is wrong."""
        cdef Py_ssize_t pos = 0, k, n = self.defaults.shape[0]
        cdef PyObject* key
        cdef PyObject* value
        cdef PyObject* entry
        cdef double x
        cdef double* v
        cdef Py_buffer vb
        if type(values) is not dict:
            return None
        vec = _empty(n, _FLOAT)
        _export(vec, &vb, 1, b'd', True, "parameter vector")
        v = <double*> vb.buf
        PyBuffer_Release(&vb)    # vec, which owns the memory, stays referenced here
        memcpy(v, &self.defaults[0], n * sizeof(double))
        while PyDict_Next(values, &pos, &key, &value):
            entry = PyDict_GetItem(self.index, <object> key)
            if entry == NULL or not PyFloat_CheckExact(<object> value):
                return None
            k = <object> entry
            x = PyFloat_AS_DOUBLE(<object> value)
            if not (isfinite(x) and (self.lo[k] < x if self.open_lo[k] else self.lo[k] <= x)
                    and (x < self.hi[k] if self.open_hi[k] else x <= self.hi[k])):
                return None
            v[k] = x
        return vec


def fixed_step_points(double t0, double[::1] stops, double h):
    """Points a fixed-step run records: both ends of every interval and each step."""
    cdef Py_ssize_t k, n = 0
    cdef double a = t0
    for k in range(stops.shape[0]):
        if stops[k] > a:
            n += fixed_steps(a, stops[k], h) + 1
            a = stops[k]
    return n


cdef class Integrator:
    """A prepared run of one model: method, cam laws, start and tolerances fixed.

    ``run(p, stops, cap)`` integrates from t0 through every stop time with the
    parameter vector p; ``cap`` is the number of points to reserve (exact for
    fixed steps, a guess for DP54).  It returns a RunRecord: ``rows`` has one row
    [t, y, f, extra] per recorded point (see abi.pxd), ``modes`` the modes in force from
    each point, ``seconds`` the wall time of the compiled loops.

    With ``dense`` False (or ``run(..., dense=False)``) a DOP853 run leaves out the three
    stages of its dense output, a sixth of its right-hand-side calls, on every step where no
    event crossed, and records NaN for the step's extra terms but the second, the step's
    length (ModelC.dense_fill makes them from it later); the steps are the same either way.
    """

    cdef ModelC* m
    cdef object capsule
    cdef int method
    cdef double t0, h, h_max, rtol
    cdef long max_steps, max_events
    cdef double[::1] y0, atol, law_par, stab_bound
    cdef int[::1] law, modes0
    cdef const int[::1] part
    cdef int stab_mode
    cdef bint exact
    cdef readonly bint dense
    cdef readonly int width, n_states
    cdef object spare_rows, spare_modes     # the last run's record, for the next (run)

    def __init__(self, object capsule, int method, int[::1] law, double[::1] law_par,
                 double[::1] y0, double t0, double h, double h_max, double rtol,
                 double[::1] atol, long max_steps, int[::1] modes0=None, long max_events=1000000,
                 int stab_mode=0, double[::1] stab_bound=None, bint exact=False,
                 const int[::1] part=None, bint dense=True):
        self.m = model_pointer(capsule)
        check_partition(self.m, part)
        self.part = None if part is None else np.array(part, dtype=np.intc)
        self.capsule = capsule
        cdef int ns = self.m.n_states, ne = self.m.n_modes - self.m.n_instances
        if y0.shape[0] != ns or atol.shape[0] != ns:
            raise ValueError("state or tolerance vector of the wrong length")
        if law.shape[0] != max(self.m.n_families, 1) or law_par.shape[0] != law.shape[0]:
            raise ValueError("one cam law per cam input family expected")
        if modes0 is None:
            modes0 = np.zeros(ne, dtype=np.intc)
        if modes0.shape[0] != ne:
            raise ValueError(f"{ne} initial modes of the force elements expected")
        self.method, self.t0, self.h, self.h_max, self.rtol = method, t0, h, h_max, rtol
        self.max_steps, self.max_events = max_steps, max_events
        self.y0, self.atol, self.law, self.law_par = y0.copy(), atol.copy(), law.copy(), law_par.copy()
        self.modes0 = np.array(modes0, dtype=np.intc)
        if stab_mode and adaptive_method(method):
            raise ValueError("the stability check is the fixed-step methods' (rk4, koster)")
        if stab_mode and (stab_bound is None or stab_bound.shape[0] < 1):
            raise ValueError("the stability check needs the method's boundary (stab_bound)")
        self.stab_mode = stab_mode
        self.exact = exact
        self.dense = dense
        self.stab_bound = stab_bound.copy() if stab_mode else np.ones(1)
        self.n_states = ns
        self.width = 1 + (2 + extra_terms(method, exact)) * ns

    def run(self, p, stops, Py_ssize_t cap, y0=None, dense=None):
        cdef int nm = self.m.n_modes
        cdef Py_buffer pb, sb, rb, mb
        cdef RunRecord out
        cdef double[::1] y_start = self.y0 if y0 is None else np.ascontiguousarray(y0, dtype=float)
        if y_start.shape[0] != self.n_states:
            raise ValueError("initial state of the wrong length")
        if cap < 16:
            cap = 16
        # the last run's record, refilled when nothing refers to it any more (its RunRecord,
        # the Result and every view of its arrays are gone): new arrays and the first export
        # of their buffers cost about as much as the shortest runs' other bookkeeping
        # together.  Taken out of self while in use, so that a run in another thread (the
        # loops release the GIL) cannot take it too
        rows, modes = self.spare_rows, self.spare_modes
        self.spare_rows = self.spare_modes = None
        if not (rows is not None and Py_REFCNT(rows) == 1 and Py_REFCNT(modes) == 1
                and _refill(rows, modes, &rb, &mb, cap, self.width, nm)):
            rows = _empty((cap, self.width), _FLOAT)
            modes = _empty((cap, nm), _INTC)
            _export(rows, &rb, 2, b'd', True, "record")
            try:
                _export(modes, &mb, 2, b'i', True, "record modes")
            except BaseException:
                PyBuffer_Release(&rb)
                raise
        try:
            _export(p, &pb, 1, b'd', False, "parameter vector")
            try:
                _export(stops, &sb, 1, b'd', False, "stop times")
                try:
                    if pb.shape[0] != self.m.n_params:
                        raise ValueError("parameter vector of the wrong length")
                    out = self._run(<const double*> pb.buf, <const double*> sb.buf, sb.shape[0],
                                    &y_start[0], <double*> rb.buf, <int*> mb.buf, rb.shape[0],
                                    self.dense if dense is None else dense)
                finally:
                    PyBuffer_Release(&sb)
            finally:
                PyBuffer_Release(&pb)
            if out.rows is None:
                out.rows, out.modes = rows, modes
                if self.spare_rows is None and rb.len + mb.len <= SPARE_BYTES:
                    self.spare_rows, self.spare_modes = rows, modes
        finally:
            PyBuffer_Release(&rb)
            PyBuffer_Release(&mb)
        return out

    cdef RunRecord _run(self, const double* p, const double* stops, Py_ssize_t n_stops,
                        const double* y0, double* rows, int* modes, Py_ssize_t cap,
                        bint dense):
        """The compiled loops on the prepared buffers; a RunRecord without rows and modes
        unless the loops outgrew the ones given (cap points), whose copy it then holds."""
        cdef ModelC* m = self.m
        cdef int ns = m.n_states, nm = m.n_modes, ncam = m.n_instances, j
        # small scratch: the state, the parameter constants, the cam cache, the stability
        # check's vector; then the modes.  On the stack where it fits (every generated model
        # so far): the heap's allocations cost as much as a short run's other bookkeeping
        cdef Py_ssize_t n_scratch = 2 * ns + m.n_const + m.n_cache + 3
        cdef Py_ssize_t n_words = n_scratch + (nm + 2) // 2
        cdef double local_scratch[SCRATCH_LOCAL]
        cdef double* scratch = local_scratch
        if n_words > SCRATCH_LOCAL:
            scratch = <double*> PyMem_Malloc(n_words * sizeof(double))
            if scratch == NULL:
                raise MemoryError()
        cdef int* mode = <int*> (scratch + n_scratch)
        memcpy(scratch, y0, ns * sizeof(double))
        for j in range(nm - ncam):
            mode[ncam + j] = self.modes0[j]
        cdef Ctx ctx
        ctx.p = p
        ctx.k = scratch + ns
        ctx.cache = scratch + ns + m.n_const
        ctx.law = &self.law[0]
        ctx.law_par = &self.law_par[0]
        ctx.mode = mode
        ctx.variant = 0
        ctx.part = NULL if self.part is None else &self.part[0]
        cdef Run run
        run.ctx = &ctx
        run.rec.n = 0
        run.rec.cap = cap
        run.rec.width = self.width
        run.rec.n_extra = extra_terms(self.method, self.exact)
        run.rec.owned = False
        run.rec.rows = rows
        run.rec.mode = modes if nm else NULL
        run.method = self.method
        run.stops = stops
        run.n_stops = n_stops
        run.t0 = self.t0
        run.y = scratch
        run.h = self.h
        run.h_max = self.h_max
        run.rtol = self.rtol
        run.atol = &self.atol[0]
        run.max_steps = self.max_steps
        run.max_events = self.max_events
        run.n_events = 0
        run.n_steps = 0
        run.n_rejected = 0
        run.n_rhs = 0
        run.t_fail = self.t0
        run.err_old = 1e-4
        run.t_stiff = NAN
        run.stab_mode = self.stab_mode
        run.stab_bound = &self.stab_bound[0]
        run.n_stab_bound = self.stab_bound.shape[0]
        run.stab_work = scratch + ns + m.n_const + m.n_cache + 1
        run.stab_ratio = -1.0
        run.stab_t = NAN
        run.stab_rho = NAN
        run.stab_b = NAN
        run.n_checks = 0
        run.n_jac = 0
        run.n_lu = 0
        run.exact = self.exact
        run.skip_dense = not dense
        run.exact_whole = False
        cdef int status
        cdef timespec c0, c1
        with nogil:
            clock_gettime(CLOCK_MONOTONIC, &c0)
            status = m.run(&run)
            clock_gettime(CLOCK_MONOTONIC, &c1)
        if scratch != local_scratch:
            PyMem_Free(scratch)
        cdef Py_ssize_t n = run.rec.n
        cdef RunRecord out = RunRecord.__new__(RunRecord)
        cdef double[:, ::1] rv
        cdef int[:, ::1] mv
        if run.rec.owned:
            try:
                out.rows = _empty((n, self.width), _FLOAT)
                out.modes = _empty((n, nm), _INTC)
                rv, mv = out.rows, out.modes
                if n:
                    memcpy(&rv[0, 0], run.rec.rows, n * self.width * sizeof(double))
                    if nm:
                        memcpy(&mv[0, 0], run.rec.mode, n * nm * sizeof(int))
            finally:
                free(run.rec.rows)
                free(run.rec.mode)
        out.status = status
        out.n = n
        out.n_steps = run.n_steps
        out.n_rejected = run.n_rejected
        out.n_rhs = run.n_rhs
        out.t_fail = run.t_fail
        out.seconds = (c1.tv_sec - c0.tv_sec) + 1e-9 * (c1.tv_nsec - c0.tv_nsec)
        out.n_events = run.n_events
        out.t_stiff = run.t_stiff
        out.stab_ratio = run.stab_ratio
        out.stab_t = run.stab_t
        out.stab_rho = run.stab_rho
        out.stab_b = run.stab_b
        out.n_checks = run.n_checks
        out.n_jac = run.n_jac
        out.n_lu = run.n_lu
        return out


def rkn12_tableau():
    """The RKN12(10) pair the loop runs (rkn12.pxd) as arrays: c (17), A (17 x 17, lower
    triangle), the order-12 weights bp (positions) and bv (velocities), the order-10 ones bpl
    and bvl."""
    cdef int i, j
    c, A = np.empty(17), np.zeros((17, 17))
    bp, bv, bpl, bvl = np.empty(17), np.empty(17), np.empty(17), np.empty(17)
    for i in range(17):
        c[i] = RK12_C[i]
        bp[i], bv[i], bpl[i], bvl[i] = RK12_BP[i], RK12_BV[i], RK12_BPL[i], RK12_BVL[i]
        for j in range(i):
            A[i, j] = RK12_A[i][j]
    return {"c": c, "A": A, "bp": bp, "bv": bv, "bpl": bpl, "bvl": bvl}


def dop853_tableau():
    """The tableau the DOP853 loop runs (dop853.pxd) as arrays: c (16), A (16 x 16: stages 1-12,
    row 12 the new point's weights b, rows 13-15 the dense-output stages), e5 and e3 (13, the
    error estimators' weights), d (4 x 16, the dense-output extras)."""
    cdef int i, j
    c, A, d = np.empty(16), np.empty((16, 16)), np.empty((4, 16))
    e5, e3 = np.empty(13), np.empty(13)
    for i in range(16):
        c[i] = D8_C[i]
        for j in range(16):
            A[i, j] = D8_A[i][j]
    for i in range(4):
        for j in range(16):
            d[i, j] = D8_D[i][j]
    for j in range(13):
        e5[j] = D8_E5[j]
        e3[j] = D8_E3[j]
    return {"c": c, "A": A, "e5": e5, "e3": e3, "d": d}


def radau_constants():
    """The constants the RADAU5 loop runs (radau.pxd): c (3), gamma, alpha, beta, T and TI
    (3 x 3), dd (3), and the Newton sweeps nit."""
    T = np.array([[RA_T11, RA_T12, RA_T13], [RA_T21, RA_T22, RA_T23], [RA_T31, 1.0, 0.0]])
    TI = np.array([[RA_TI11, RA_TI12, RA_TI13], [RA_TI21, RA_TI22, RA_TI23],
                   [RA_TI31, RA_TI32, RA_TI33]])
    return {"c": np.array([RA_C1, RA_C2, 1.0]), "gamma": RA_GAMMA, "alpha": RA_ALPHA,
            "beta": RA_BETA, "T": T, "TI": TI, "dd": np.array([RA_DD1, RA_DD2, RA_DD3]),
            "nit": RA_NIT}


def solve_lu(A, b):
    """x with A x = b by the LU routines the implicit loops factor with (linalg.pxd): lu_factor
    and lu_solve for a real A and b, clu_factor and clu_solve where either is complex; None
    where a pivot vanishes (A singular)."""
    A, b = np.asarray(A), np.asarray(b)
    cdef int n = A.shape[0]
    if A.shape != (n, n) or b.shape != (n,) or n < 1:
        raise ValueError("A must be n x n and b of length n >= 1")
    cdef int[::1] piv = np.empty(n, dtype=np.intc)
    cdef double[::1] ar = np.array(A.real, dtype=float).ravel()
    cdef double[::1] br = np.array(b.real, dtype=float)
    cdef double[::1] ai, bi
    if np.iscomplexobj(A) or np.iscomplexobj(b):
        ai = np.array(A.imag, dtype=float).ravel()
        bi = np.array(b.imag, dtype=float)
        if clu_factor(n, &ar[0], &ai[0], &piv[0]) != 0:
            return None
        clu_solve(n, &ar[0], &ai[0], &piv[0], &br[0], &bi[0])
        return np.asarray(br) + 1j * np.asarray(bi)
    if lu_factor(n, &ar[0], &piv[0]) != 0:
        return None
    lu_solve(n, &ar[0], &piv[0], &br[0])
    return np.asarray(br)


# -- evaluation helpers (vectorized, compiled) ------------------------------------

def dense_eval(const double[:] t, const double[:, :] y, const double[:, :] f,
               const double[:, :] extra, const double[::1] tq):
    """States at the times tq from a record; returns (Y, index of the step used).

    A query on a stop time takes the step that ends there (left limit) unless it
    is the first time of the record.  ``extra``: the rows' dense-output extras (n x
    n_extra ns, dense.pxd), or an empty array for the cubic Hermite interpolant.
    """
    cdef Py_ssize_t n = t.shape[0], nq = tq.shape[0], ns = y.shape[1]
    Y = np.empty((nq, ns))
    idx = np.empty(nq, dtype=np.intp)
    cdef double[:, ::1] Yv = Y
    cdef Py_ssize_t[::1] iv = idx
    cdef Py_ssize_t j, lo, hi, mid, i, c, x
    cdef int nx = extra.shape[1] // ns if extra.shape[0] == n and ns else 0
    cdef double[::1] e = np.empty(max(nx, 1))
    cdef double s, h
    if n == 0:
        raise ValueError("empty record")
    for j in range(nq):
        if tq[j] < t[0] or tq[j] > t[n - 1]:
            raise ValueError(f"time {tq[j]} outside the integrated span [{t[0]}, {t[n - 1]}]")
        lo = 0
        hi = n - 1
        while hi - lo > 1:   # last point with t[i] < tq (or the first point)
            mid = (lo + hi) // 2
            if t[mid] < tq[j]:
                lo = mid
            else:
                hi = mid
        i = lo
        while i + 1 < n and t[i + 1] == t[i]:   # a stop recorded twice
            i += 1
        iv[j] = i
        if i + 1 >= n or t[i + 1] <= t[i]:
            for c in range(ns):
                Yv[j, c] = y[i, c]
            continue
        h = t[i + 1] - t[i]
        s = (tq[j] - t[i]) / h
        for c in range(ns):
            for x in range(nx):
                e[x] = extra[i, x * ns + c]
            Yv[j, c] = dense_component(s, h, y[i, c], y[i + 1, c], f[i, c], f[i + 1, c], &e[0],
                                       nx, 1)
    return Y, idx


cdef int _ctx_init(Ctx* ctx, ModelC* m, double[::1] p, double[::1] k, int[::1] law,
                   double[::1] law_par, int[::1] mode, const int[::1] part=None) except -1:
    """Point ctx at the arrays; k holds the constants, then the cam cache; ``part`` the
    coordinate partition (checked), None for the declared one."""
    check_partition(m, part)
    ctx.part = NULL if part is None else &part[0]
    ctx.p = &p[0]
    ctx.k = &k[0]
    ctx.cache = &k[m.n_const]
    ctx.law = &law[0]
    ctx.law_par = &law_par[0]
    ctx.mode = &mode[0]
    ctx.variant = 0
    m.prepare(ctx)
    return 0


cdef int[::1] _mode_buffer(ModelC* m, element_modes):
    """Mode array: cam segments (filled per point), then the force elements' modes."""
    md = np.zeros(max(m.n_modes, 1), dtype=np.intc)
    ne = m.n_modes - m.n_instances
    if element_modes is not None and ne:
        em = np.asarray(element_modes, dtype=np.intc).ravel()
        if em.shape[0] != ne:
            raise ValueError(f"{ne} modes of the force elements expected")
        md[m.n_instances:m.n_modes] = em
    return md


def _rows_contiguous(y):
    """y itself when each row is contiguous (views into a record), else a C copy."""
    y = np.asarray(y, dtype=float)
    return y if y.ndim == 2 and y.strides[1] == sizeof(double) else np.ascontiguousarray(y)


def eval_outputs(object capsule, double[::1] p, int[::1] law, double[::1] law_par,
                 const double[:] t, y_in, mode=None, element_modes=None,
                 const int[::1] part=None):
    """Outputs at the points (t, y).  ``mode``: all modes per point (as recorded); else
    the cam segments are looked up and the force elements take ``element_modes``.  ``part``:
    a constrained model's coordinate partition (Ctx.part), None for the declared one."""
    cdef const double[:, :] y = _rows_contiguous(y_in)
    cdef ModelC* m = model_pointer(capsule)
    cdef Py_ssize_t n = t.shape[0], j
    cdef int nm = m.n_modes
    if y.shape[1] != m.n_states:
        raise ValueError("state array of the wrong width")
    out = np.empty((n, m.n_outputs))
    cdef double[:, ::1] o = out
    cdef int[::1] md = _mode_buffer(m, element_modes)
    cdef double[::1] k = np.empty(m.n_const + m.n_cache + 1)
    cdef int[:, ::1] given
    cdef bint have = mode is not None and nm > 0
    if have:
        given = np.ascontiguousarray(mode, dtype=np.intc)
    cdef Ctx ctx
    _ctx_init(&ctx, m, p, k, law, law_par, md, part)
    for j in range(n):
        if have:
            memcpy(&md[0], &given[j, 0], nm * sizeof(int))
            m.refresh(&ctx)
        else:
            m.update_modes(t[j], &y[j, 0], &ctx)
        m.outputs(t[j], &y[j, 0], &o[j, 0], &ctx)
    return out


def eval_rhs(object capsule, double[::1] p, int[::1] law, double[::1] law_par,
             const double[:] t, y_in, element_modes=None, const int[::1] part=None):
    """dy/dt at the points (t, y), cam segments looked up per point; ``part`` as
    :func:`eval_outputs` takes it."""
    cdef const double[:, :] y = _rows_contiguous(y_in)
    cdef ModelC* m = model_pointer(capsule)
    cdef Py_ssize_t n = t.shape[0], j
    if y.shape[1] != m.n_states:
        raise ValueError("state array of the wrong width")
    out = np.empty((n, m.n_states))
    cdef double[:, ::1] o = out
    cdef int[::1] md = _mode_buffer(m, element_modes)
    cdef double[::1] k = np.empty(m.n_const + m.n_cache + 1)
    cdef Ctx ctx
    _ctx_init(&ctx, m, p, k, law, law_par, md, part)
    for j in range(n):
        m.update_modes(t[j], &y[j, 0], &ctx)
        m.rhs(t[j], &y[j, 0], &o[j, 0], &ctx)
    return out


def eval_jacobian_fd(object capsule, double[::1] p, int[::1] law, double[::1] law_par,
                  const double[:] t, y_in, const double[::1] scale, mode=None, element_modes=None,
                  const int[::1] part=None):
    """Jacobians df/dy of the first-order right-hand side at the points (t, y), by central
    differences of the compiled rhs (steps 1e-6 max(|y_i|, scale_i)); shape (n, ns, ns).

    ``mode``: all modes per point (as recorded), held fixed while the state is perturbed, as
    the integration loops hold them within a step; else the cam segments are looked up at each
    point and the force elements take ``element_modes``.  For stability estimates
    (camdyn.runtime.core.stability); it does not depend on a generated Jacobian.  ``part``
    as :func:`eval_outputs` takes it."""
    cdef const double[:, :] y = _rows_contiguous(y_in)
    cdef ModelC* m = model_pointer(capsule)
    cdef Py_ssize_t n = t.shape[0], j
    cdef int ns = m.n_states, nm = m.n_modes, r, c
    if y.shape[1] != ns or scale.shape[0] != ns:
        raise ValueError("state or scale array of the wrong width")
    J = np.empty((n, ns, ns))
    cdef double[:, :, ::1] Jv = J
    cdef double[::1] yp = np.empty(ns), fp = np.empty(ns), fm = np.empty(ns)
    cdef int[::1] md = _mode_buffer(m, element_modes)
    cdef double[::1] k = np.empty(m.n_const + m.n_cache + 1)
    cdef int[:, ::1] given
    cdef bint have = mode is not None and nm > 0
    cdef double d
    if have:
        given = np.ascontiguousarray(mode, dtype=np.intc)
    cdef Ctx ctx
    _ctx_init(&ctx, m, p, k, law, law_par, md, part)
    for j in range(n):
        if have:
            memcpy(&md[0], &given[j, 0], nm * sizeof(int))
            m.refresh(&ctx)
        else:
            m.update_modes(t[j], &y[j, 0], &ctx)
        for c in range(ns):
            yp[c] = y[j, c]
        for c in range(ns):
            d = 1e-6 * fmax(fabs(y[j, c]), scale[c])
            if not d > 0.0:
                d = 1e-6
            yp[c] = y[j, c] + d
            m.rhs(t[j], &yp[0], &fp[0], &ctx)
            yp[c] = y[j, c] - d
            m.rhs(t[j], &yp[0], &fm[0], &ctx)
            yp[c] = y[j, c]
            for r in range(ns):
                Jv[j, r, c] = (fp[r] - fm[r]) / (2.0 * d)
    return J


def linearize(object capsule, const double[:, ::1] P, int[::1] law, double[::1] law_par,
              const double[::1] t, const double[:, ::1] Y, const double[::1] scale,
              const int[::1] outputs, element_modes=None, const int[::1] part=None):
    """The frozen linear system at n points, each with its own parameters: J[j] = df/dy at
    (t[j], Y[j]) with parameters P[j], and G[j, i] = d(output outputs[i])/dy there, both by
    central differences (steps 1e-6 max(|y_c|, scale_c)), the force elements in
    ``element_modes``; shapes (n, ns, ns) and (n, len(outputs), ns).  One call for a whole
    grid of parameter sets: what camdyn.runtime.measure.modes reads the dwell's modes from.
    ``part`` as :func:`eval_outputs` takes it."""
    cdef ModelC* m = model_pointer(capsule)
    check_partition(m, part)
    cdef Py_ssize_t n = P.shape[0], j
    cdef int ns = m.n_states, no = outputs.shape[0], r, c, i
    if P.shape[1] != m.n_params or Y.shape[0] != n or Y.shape[1] != ns or t.shape[0] != n \
            or scale.shape[0] != ns:
        raise ValueError("parameter, time, state or scale arrays of the wrong shape")
    for i in range(no):
        if not 0 <= outputs[i] < m.n_outputs:
            raise ValueError("output index out of range")
    J = np.empty((n, ns, ns))
    G = np.empty((n, no, ns))
    cdef double[:, :, ::1] Jv = J, Gv = G
    cdef double[::1] yp = np.empty(ns), fp = np.empty(ns), fm = np.empty(ns)
    cdef double[::1] op = np.empty(max(m.n_outputs, 1)), om = np.empty(max(m.n_outputs, 1))
    cdef int[::1] md = _mode_buffer(m, element_modes)
    cdef double[::1] k = np.empty(m.n_const + m.n_cache + 1)
    cdef double d
    cdef Ctx ctx
    ctx.k = &k[0]
    ctx.cache = &k[m.n_const]
    ctx.law = &law[0]
    ctx.law_par = &law_par[0]
    ctx.mode = &md[0]
    ctx.variant = 0
    ctx.part = NULL if part is None else &part[0]
    for j in range(n):
        ctx.p = &P[j, 0]
        m.prepare(&ctx)
        m.update_modes(t[j], &Y[j, 0], &ctx)
        for c in range(ns):
            yp[c] = Y[j, c]
        for c in range(ns):
            d = 1e-6 * fmax(fabs(Y[j, c]), scale[c])
            if not d > 0.0:
                d = 1e-6
            yp[c] = Y[j, c] + d
            m.rhs(t[j], &yp[0], &fp[0], &ctx)
            m.outputs(t[j], &yp[0], &op[0], &ctx)
            yp[c] = Y[j, c] - d
            m.rhs(t[j], &yp[0], &fm[0], &ctx)
            m.outputs(t[j], &yp[0], &om[0], &ctx)
            yp[c] = Y[j, c]
            for r in range(ns):
                Jv[j, r, c] = (fp[r] - fm[r]) / (2.0 * d)
            for i in range(no):
                Gv[j, i, c] = (op[outputs[i]] - om[outputs[i]]) / (2.0 * d)
    return J, G


def eval_events(object capsule, double[::1] p, int[::1] law, double[::1] law_par, double t,
                double[::1] y, element_modes=None):
    """The event functions at one point (cam segments looked up)."""
    cdef ModelC* m = model_pointer(capsule)
    g = np.empty(max(m.n_events, 1))
    cdef double[::1] gv = g
    cdef int[::1] md = _mode_buffer(m, element_modes)
    cdef double[::1] k = np.empty(m.n_const + m.n_cache + 1)
    cdef Ctx ctx
    _ctx_init(&ctx, m, p, k, law, law_par, md)
    m.update_modes(t, &y[0], &ctx)
    m.events(t, &y[0], &gv[0], &ctx)
    return g[:m.n_events]


def consistent_state(object capsule, object module, double[::1] p, int[::1] law,
                     double[::1] law_par, double t, double[::1] y, element_modes=None,
                     const int[::1] part=None):
    """(y with its dependent coordinates and their rates recovered from the independent ones,
    the largest |Phi| and |Phi'| of y) of a constrained model (its module's
    consistent_state), the coordinates partitioned by ``part`` (Ctx.part; None: as
    declared); a ValueError when Newton's method fails: its text "singular" where Phi_Q
    restricted to the dependent coordinates is, else "no convergence"."""
    cdef ModelC* m = model_pointer(capsule)
    check_partition(m, part)
    cdef double[::1] k = np.empty(m.n_const + m.n_cache + 1)
    cdef int[::1] md = _mode_buffer(m, element_modes)
    if y.shape[0] != m.n_states:
        raise ValueError("state vector of the wrong length")
    out = np.empty(m.n_states)
    status, phi, phid = module.consistent_state(p, k, law, law_par, md, t, y, out,
                                                None if part is None else np.asarray(part))
    if status:
        raise ValueError("singular" if status == 2 else "no convergence")
    return out, phi, phid


def eval_mass_stiffness(object capsule, double[::1] p, int[::1] law, double[::1] law_par, double t,
                        double[::1] y, element_modes=None):
    """Mass matrix M and stiffness K = -df/dq at one point: the frozen system M q'' + K q."""
    cdef ModelC* m = model_pointer(capsule)
    cdef int n = m.n_q
    M = np.zeros((n, n))
    K = np.zeros((n, n))
    cdef double[:, ::1] Mv = M, Kv = K
    cdef int[::1] md = _mode_buffer(m, element_modes)
    cdef double[::1] k = np.empty(m.n_const + m.n_cache + 1)
    cdef Ctx ctx
    if y.shape[0] != m.n_states:
        raise ValueError("state vector of the wrong length")
    _ctx_init(&ctx, m, p, k, law, law_par, md)
    m.update_modes(t, &y[0], &ctx)
    if n:
        m.mass_stiffness(t, &y[0], &Mv[0, 0], &Kv[0, 0], &ctx)
    return M, K


def eval_jacobian(object capsule, double[::1] p, int[::1] law, double[::1] law_par, double t,
                  double[::1] y, element_modes=None, bint with_time=False,
                  const int[::1] part=None):
    """J = d(dy/dt)/dy at one point (n_states x n_states), cam segments looked up as by
    eval_rhs, the force elements in ``element_modes``: the Jacobian of the current modes.
    How the model forms it (symbolically or by differences in C) is its manifest's
    "jacobian".  ``with_time``: (J, df/dt), for a model whose manifest's "time_derivative"
    is "symbolic" (else df/dt comes back NaN).  ``part`` as :func:`eval_outputs` takes it."""
    cdef ModelC* m = model_pointer(capsule)
    cdef int ns = m.n_states
    J = np.zeros((ns, ns))
    ft = np.full(ns, np.nan)
    cdef double[:, ::1] Jv = J
    cdef double[::1] ftv = ft
    cdef int[::1] md = _mode_buffer(m, element_modes)
    cdef double[::1] k = np.empty(m.n_const + m.n_cache + 1)
    cdef Ctx ctx
    if y.shape[0] != ns:
        raise ValueError("state vector of the wrong length")
    _ctx_init(&ctx, m, p, k, law, law_par, md, part)
    m.update_modes(t, &y[0], &ctx)
    if ns:
        m.jac(t, &y[0], &Jv[0, 0], &ftv[0] if with_time else NULL, &ctx)
    return (J, ft) if with_time else J


def rhs_cost_ns(object capsule, double[::1] p, int[::1] law, double[::1] law_par,
                double t, double[::1] y, long n):
    """Mean wall time of one right-hand-side call in ns, over n calls in C through
    the model's function pointer (the loops inline it and pay less)."""
    cdef ModelC* m = model_pointer(capsule)
    cdef double[::1] dy = np.zeros(m.n_states)
    cdef int[::1] md = _mode_buffer(m, None)
    cdef double[::1] k = np.empty(m.n_const + m.n_cache + 1)
    cdef Ctx ctx
    cdef timespec a, b
    cdef long j
    cdef double tt = t
    _ctx_init(&ctx, m, p, k, law, law_par, md)
    m.update_modes(t, &y[0], &ctx)
    with nogil:
        clock_gettime(CLOCK_MONOTONIC, &a)
        for j in range(n):
            m.rhs(tt, &y[0], &dy[0], &ctx)
            tt += 1e-12  # keep the call from being hoisted out of the loop
        clock_gettime(CLOCK_MONOTONIC, &b)
    return ((b.tv_sec - a.tv_sec) * 1e9 + (b.tv_nsec - a.tv_nsec)) / n
