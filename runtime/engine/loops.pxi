# The integration loops of camdyn: classical RK4, Dormand-Prince 5(4) and 8(5,3), RODAS4,
# Radau IIA of order 5 (RADAU5), and the thesis's CAMSHAFT-1 scheme (4.23)-(4.31), written once
# here.
#
# Every generated model module includes this file after defining its inline
# `rhs`, `update_modes` and `prepare` (see camdyn/derive/templates/model.pyx.j2),
# so the C compiler inlines the model into every stage; camdyn.runtime.engine.driver
# calls the resulting `run_loops` through ModelC.run once per run.  The types
# (Run, Record, Ctx) and codes are in abi.pxd.
#
# Breakpoints.  The run goes from stop to stop (cam-law breakpoints in time,
# then the end time).  The cam segments (modes) are fixed at the start of each
# interval, steps are shortened to land on its end, and the state is recorded
# twice at a stop: as the left limit (old modes and slope) and as the right
# limit (new modes, new slope).
#
# Dense output.  Every point stores its slope f and the step starting there its
# extras, the terms of Hairer's continuous extension beyond the cubic Hermite
# interpolant (dense.pxd): none for RK4 and the thesis scheme, DP54's fourth-order term,
# two for RODAS4 and RADAU5 (the quintic over the step and the start of the one before,
# _rec_three_point), DOP853's four terms of its seventh-order extension.

from libc.math cimport NAN, cos, exp, fabs, fmax, fmin, isfinite, isnan, log, pow, sin, sqrt
from libc.stdlib cimport free, malloc
from libc.string cimport memcpy, memset

from camdyn.runtime.engine.dense cimport dense_component, fit_extras, fit_matrix
from camdyn.runtime.engine.dop853 cimport D8_A, D8_C, D8_D, D8_E3, D8_E5
from camdyn.runtime.engine.linalg cimport clu_factor, clu_solve, lu_factor, lu_solve
from camdyn.runtime.engine.radau cimport *
from camdyn.runtime.engine.rkn12 cimport RK12_A, RK12_BP, RK12_BPL, RK12_BV, RK12_BVL, RK12_C


cdef inline bint _finite(int n, const double* y) noexcept nogil:
    cdef int i
    for i in range(n):
        if not isfinite(y[i]):
            return False
    return True


cdef int _rec_grow(Record* r) noexcept nogil:
    """Double the record's capacity in buffers of its own (copying what is there)."""
    cdef Py_ssize_t cap = 2 * r.cap if r.cap >= 32 else 64
    cdef double* rows = <double*> malloc(cap * r.width * sizeof(double))
    cdef int* mode = <int*> malloc(cap * (_NM if _NM > 0 else 1) * sizeof(int))
    if rows == NULL or mode == NULL:
        free(rows)
        free(mode)
        return -1
    if r.n:
        memcpy(rows, r.rows, r.n * r.width * sizeof(double))
        if _NM:
            memcpy(mode, r.mode, r.n * _NM * sizeof(int))
    if r.owned:
        free(r.rows)
        free(r.mode)
    r.rows = rows
    r.mode = mode
    r.cap = cap
    r.owned = True
    return 0


cdef inline int _rec_point(Run* run, double t, const double* y, const double* f) noexcept nogil:
    cdef Record* r = &run.rec
    cdef Py_ssize_t n = r.n
    cdef double* row
    # a point is recorded only finite: an error test that a NaN or an overflow slipped
    # through (one that compares false) must not leave a run that reads as finished
    if not (_finite(_NS, y) and _finite(_NS, f)):
        return -2
    if n == r.cap:
        if _rec_grow(r) != 0:
            return -1
    row = r.rows + n * r.width
    row[0] = t
    memcpy(row + 1, y, _NS * sizeof(double))
    memcpy(row + 1 + _NS, f, _NS * sizeof(double))
    if r.n_extra:
        memset(row + 1 + 2 * _NS, 0, r.n_extra * _NS * sizeof(double))
    if _NM:
        memcpy(&r.mode[n * _NM], run.ctx.mode, _NM * sizeof(int))
    r.n = n + 1
    return 0


cdef inline int _rec_failure(const double* y, const double* f) noexcept nogil:
    """Why _rec_point refused a point: a state or slope not finite, else no memory."""
    if not (_finite(_NS, y) and _finite(_NS, f)):
        return STATUS_NOT_FINITE
    return STATUS_NO_MEMORY


cdef inline void _rec_three_point(Run* run) noexcept nogil:
    """The extras of the record's last step (rows n-2 to n-1) that make its interpolant the
    quintic through the value and slope at both its ends and at the start of the step before
    (row n-3): a Hermite interpolant over three accepted points, O(h^6) like the methods' own
    values there, where the cubic Hermite one is O(h^4).  For RADAU5 (order 5) and RODAS4
    (order 4), whose collocation or Rosenbrock stages give no interpolant better than the
    cubic one (stage order 3); they call it from their second step of an interval on, and a
    record without two extras keeps the cubic one.

    With h the step, r h the one before, and s in units of h from the step's start, the
    quintic is H3(s) + s^2 (1 - s)^2 (e0 + e1 s), H3 the cubic Hermite part (dense.pxd); its
    value and slope at s = -r fix e0 - r e1 and then e1."""
    cdef Record* rec = &run.rec
    cdef const double* p
    cdef const double* a
    cdef const double* b
    cdef double* ex
    cdef double h, r, s1, q, dq, v0, v1, v2, g, H, dH, e1, u
    cdef int c
    if rec.n_extra < 2 or rec.n < 3:
        return
    b = rec.rows + (rec.n - 1) * rec.width
    a = b - rec.width
    p = a - rec.width
    h = b[0] - a[0]
    if not (p[0] < a[0] and h > 0.0):
        return
    r = (a[0] - p[0]) / h
    s1 = 1.0 + r                            # 1 - s at s = -r
    q = r * r * s1 * s1
    dq = -2.0 * r * s1 * (1.0 + 2.0 * r)
    ex = <double*> a + 1 + 2 * _NS
    for c in range(_NS):
        v0 = b[1 + c] - a[1 + c]
        v1 = h * a[1 + _NS + c] - v0
        v2 = v0 - h * b[1 + _NS + c] - v1
        u = v1 - r * v2                     # v1 + s v2 at s = -r
        g = v0 + s1 * u
        H = a[1 + c] - r * g
        dH = g - r * (s1 * v2 - u)
        u = (p[1 + c] - H) / q              # e0 - r e1
        e1 = (h * p[1 + _NS + c] - dH - dq * u) / q
        ex[c] = u + r * e1
        ex[_NS + c] = e1


cdef inline bint _crossed(int direction, double g) noexcept nogil:
    # strict: an element that switched at g = 0 exactly (a gap closed at rest, as in a dwell)
    # must still see the next crossing in the other direction
    return g > 0.0 if direction > 0 else g < 0.0


cdef inline void _dense(double s, double h, const double* y0, const double* y1, const double* f0,
                        const double* f1, const double* ex, int nx, double* out) noexcept nogil:
    """The step's continuous extension at s in [0, 1] (dense.pxd); ex: its nx extras, or NULL."""
    cdef int i
    if ex == NULL:
        nx = 0
    for i in range(_NS):
        out[i] = dense_component(s, h, y0[i], y1[i], f0[i], f1[i], ex + i if nx else NULL, nx,
                                 _NS)


cdef int _cut_extras(double s_cut, double h, const double* y0, const double* y1,
                     const double* f0, const double* f1, double* ex, int nx, const double* yc,
                     const double* fc) noexcept nogil:
    """The extras of the step cut at s_cut (state yc, slope fc there) that keep the whole
    step's extension on [0, s_cut]: fitted to it at the interior nodes (dense.pxd)."""
    cdef double vals[8 * _NS]
    cdef double W[64]
    cdef double tmp[_NS]
    cdef int j
    if ex == NULL or nx <= 0:
        return 0
    if fit_matrix(nx, W) != 0:
        return -1
    for j in range(nx):
        _dense(s_cut * (j + 1.0) / (nx + 1.0), h, y0, y1, f0, f1, ex, nx, tmp)
        memcpy(vals + j * _NS, tmp, sizeof(tmp))
    fit_extras(nx, _NS, W, s_cut * h, y0, yc, f0, fc, vals, ex)
    return 0


cdef double _locate(Ctx* ctx, int k, double t, double h, const double* y0, const double* y1,
                    const double* f0, const double* f1, const double* ex, int nx, double ga,
                    double gb) noexcept nogil:
    """Step fraction where event k crosses (Illinois method on the continuous extension):
    an iterate where g is exactly zero, else the bracket's end on the crossed side."""
    cdef double a = 0.0, b = 1.0, s, gs
    cdef int it, side = 0, d = _EDIR[k]
    cdef double ys[_NS]
    cdef double gtmp[_NE1]
    for it in range(100):
        s = (a * gb - b * ga) / (gb - ga)
        if not (a < s < b):
            s = 0.5 * (a + b)
        _dense(s, h, y0, y1, f0, f1, ex, nx, ys)
        events(t + s * h, ys, gtmp, ctx)
        gs = gtmp[k]
        if gs == 0.0:
            # on the switching surface itself.  The strict test calls g = 0 not crossed, so b
            # may still be the step end: the first secant hits a g linear in t exactly (the
            # cam argument in a dwell), and b would put the rise start at the end of the step
            return s
        if _crossed(d, gs):
            b, gb = s, gs
            if side == -1:
                ga *= 0.5
            side = -1
        else:
            a, ga = s, gs
            if side == 1:
                gb *= 0.5
            side = 1
        if b - a <= 1e-14:
            break
    return b


cdef int _event_in_step(Run* run, double t, double h, const double* y0, const double* y1,
                        const double* f0, const double* f1, const double* ex, int nx,
                        double* g0, double* g1, double* s_hit) noexcept nogil:
    """The event that crosses first within the step, or -1; its step fraction in s_hit."""
    events(t + h, y1, g1, run.ctx)
    return _first_event(run, t, h, y0, y1, f0, f1, ex, nx, g0, g1, s_hit)


cdef inline bint _any_crossed(const double* g0, const double* g1) noexcept nogil:
    """Whether an event function crossed in its direction between the step's ends."""
    cdef int k
    for k in range(_NE):
        if not _crossed(_EDIR[k], g0[k]) and _crossed(_EDIR[k], g1[k]):
            return True
    return False


cdef int _first_event(Run* run, double t, double h, const double* y0, const double* y1,
                      const double* f0, const double* f1, const double* ex, int nx,
                      const double* g0, const double* g1, double* s_hit) noexcept nogil:
    """_event_in_step with the event functions at the step's end already in g1."""
    cdef int k, hit = -1
    cdef double s
    s_hit[0] = 2.0
    for k in range(_NE):
        if not _crossed(_EDIR[k], g0[k]) and _crossed(_EDIR[k], g1[k]):
            s = _locate(run.ctx, k, t, h, y0, y1, f0, f1, ex, nx, g0[k], g1[k])
            if s < s_hit[0]:
                s_hit[0] = s
                hit = k
    return hit


cdef inline int _project_accepted(Ctx* ctx, double t, double* y, double* f, double* g,
                                  long* n_rhs) noexcept nogil:
    """A constrained model's projection of an accepted state onto its constraints (the model's
    project(), its formulation 2), with the slope f and the event functions g (unless NULL)
    at the projected state: so the record, whose rows are the dense output's end points and
    slopes, and the next step both start from it.  STATUS_OK, or STATUS_NO_CONVERGENCE."""
    cdef int r
    if not _PROJECTS:
        return STATUS_OK
    r = project(t, y, ctx)
    if r < 0:
        return STATUS_NO_CONVERGENCE
    if r > 0:
        rhs(t, y, f, ctx)
        n_rhs[0] += 1
        if _NE > 0 and g != NULL:
            events(t, y, g, ctx)
    return STATUS_OK


cdef int _apply_event(Run* run, int k, double t, double* y, double* f, double* g0) noexcept nogil:
    """Record the left limit at an event, apply it, record the right limit; f becomes the
    new slope and g0 the event functions in the new modes."""
    run.n_events += 1
    if run.n_events > run.max_events:
        return STATUS_EVENT_STORM
    if _rec_point(run, t, y, f) != 0:
        return _rec_failure(y, f)
    on_event(k, t, y, run.ctx)
    if _PROJECTS and project(t, y, run.ctx) < 0:   # the right limit on the constraints too
        return STATUS_NO_CONVERGENCE
    rhs(t, y, f, run.ctx)
    run.n_rhs += 1
    if _rec_point(run, t, y, f) != 0:
        return _rec_failure(y, f)
    events(t, y, g0, run.ctx)
    if g0[k] == 0.0:
        # the event was located on its surface exactly: if it stays armed (a breakpoint that
        # switches nothing), g = 0 would count as not yet crossed and it would fire again at
        # once; it has crossed, so say so
        g0[k] = 5e-324 if _EDIR[k] > 0 else -5e-324
    return STATUS_OK


# the thesis scheme turns from fixed-point iteration to Newton's method once a sweep leaves more
# than this fraction of the mid-step residual (about 13 more sweeps to rounding level)
cdef extern from *:
    """
    #define NEWTON_RATIO 0.1
    """
    const double NEWTON_RATIO


cdef int _koster_newton_matrix(Ctx* ctx, double t, const double* ym, const double* acc,
                               const double* fm, double theta, double* J, double* W,
                               int* piv, double* ya, double* fa) noexcept nogil:
    """W = I - d a_mid/d a, LU-factored in place (piv), for the thesis scheme's mid-step
    equation g(a) = a - F(t, X + X' theta + a theta^2/2, X' + a theta) = 0 at the iterate a
    (acc; ym is the mid-step state there and fm its slope).  Returns the right-hand-side calls
    spent (they count in n_rhs), or a negative code (below).

    The model's symbolic Jacobian where it has one (_JAC_SYMBOLIC): d a_mid/d a =
    dF/dX theta^2/2 + dF/dX' theta, the rows _NQ.._2NQ-1 of df/dy, no rhs calls.  Else the
    mid-step map itself is differenced forward in each a_j (_NQ calls), increment sqrt(eps)
    times the size of the accelerations: an error in W only slows Newton down (linear
    convergence with a factor ~ that error), it does not move the solution.  -2 when W is
    not finite (the state is blowing up), -1 when it is singular."""
    cdef int i, j, calls = 0
    cdef double tt = 0.5 * theta * theta, d, aj, scale = 0.0
    if _JAC_SYMBOLIC:
        jacobian(t, ym, J, NULL, ctx)
        for i in range(_NQ):
            for j in range(_NQ):
                W[i * _NQ + j] = -(J[(_NQ + i) * _NS + j] * tt + J[(_NQ + i) * _NS + _NQ + j] * theta)
    else:
        for i in range(_NQ):
            scale = fmax(scale, fmax(fabs(acc[i]), fabs(fm[_NQ + i])))
        if scale == 0.0:
            scale = 1.0
        memcpy(ya, ym, _NS * sizeof(double))
        for j in range(_NQ):
            aj = acc[j]
            d = 1.4901161193847656e-08 * fmax(fabs(aj), scale)
            d = (aj + d) - aj       # the increment actually represented
            ya[j] = ym[j] + d * tt
            ya[_NQ + j] = ym[_NQ + j] + d * theta
            rhs(t, ya, fa, ctx)
            calls += 1
            for i in range(_NQ):
                W[i * _NQ + j] = -(fa[_NQ + i] - fm[_NQ + i]) / d
            ya[j] = ym[j]
            ya[_NQ + j] = ym[_NQ + j]
    for i in range(_NQ):
        W[i * _NQ + i] += 1.0
    if not _finite(_NQ * _NQ, W):
        return -2
    if lu_factor(_NQ, W, piv) != 0:
        return -1
    return calls


# -- the fixed-step stability check (RK4, the thesis scheme) ----------------------------
#
# A fixed step is stable while h lambda lies inside the method's region of absolute stability
# for every eigenvalue lambda of the Jacobian df/dy, frozen along the run (the boundaries and
# the warning's criterion: runtime/core/stability.py).  The loop checks it at the start of a
# step, from the model's generated Jacobian (``jacobian(t, y, J, NULL, ctx)``, the ABI's; the
# constrained models difference rhs() in it):
#
# * _NS = 1, 2: the eigenvalues in closed form;
# * _NS > 2: the dominant eigenvalues from a power iteration whose vector q is kept from
#   check to check (run.stab_work): the Ritz values of the Krylov plane {q, J q} (two-step
#   Arnoldi), iterated until the plane is invariant to STAB_TOL (the residual of J p, p the
#   plane's second basis vector, against the 2 x 2 projection).  A plane, not a vector: the
#   fastest mode of a mechanism is a complex pair (+-i omega), on which a plain power
#   iteration never settles, and so is a pair of equal frequencies (a shaft's bending in y
#   and z), whose four-dimensional eigenspace every plane {q, J q} in it spans invariantly.
#   Warm-started, one or two products J x a check.  The velocities are scaled by the last
#   |lambda| (D^-1 J D, D = diag(1, sigma, 1) on q, q', first-order states), which makes the
#   mechanical Jacobian [[0, I], [A, B]] nearly normal, so that Ritz values of a nearly
#   invariant plane are nearly eigenvalues.  The limit is taken from that pair: another
#   eigenvalue limits instead only if its |lambda| is within the boundary's spread (2.62 to
#   2.96 for RK4, 12 %) of the largest and in a less favourable direction.
#
# Where.  At the start of every interval and after every event (the modes, and with them the
# Jacobian, change there), and in between every `period` steps: at most STAB_PERIOD (a
# symbolic Jacobian) or STAB_PERIOD _NS (a differenced one, 4 _NS rhs calls), STAB_FAR times
# that while h |lambda|/b < 1/STAB_FAR (the stiffness must grow that much first), and at least
# STAB_PER_INTERVAL times an interval (a cam segment: the stiffness a cam drives changes on
# its scale), shortened as h|lambda|/b approaches 1: from the growth since the last check
# (after a jump: over the next step) the steps left to the boundary are extrapolated and the
# next check comes after half of them.  So a stiffness that grows with the cam's motion is
# caught within a step of where h |lambda| crosses the boundary, and a run far inside it pays
# for a check every 64 steps (measured in the docstring of runtime/core/stability.py).  A
# stiffness that grows with the state alone (a contact's penetration) is caught within
# `period` steps.
cdef extern from *:
    """
    #define STAB_PERIOD 16
    #define STAB_FAR 4
    #define STAB_PER_INTERVAL 8
    #define STAB_MAXIT 100
    #define STAB_TOL 1e-6
    """
    const long STAB_PERIOD
    const long STAB_FAR
    const long STAB_PER_INTERVAL
    const int STAB_MAXIT
    const double STAB_TOL


cdef inline double _stab_bound(const Run* run, double re, double mag) noexcept nogil:
    """The boundary |h lambda| in the direction of lambda, reflected into the left half-plane
    (a mode that grows physically is judged by its magnitude): run.stab_bound interpolated at
    u = |Re lambda|/|lambda|."""
    cdef int n = run.n_stab_bound, k
    cdef double u
    if n <= 1 or mag == 0.0:
        return run.stab_bound[0]
    u = fabs(re) / mag * (n - 1)
    if not u < n - 1:        # the real axis, or NaN (a Jacobian blowing up)
        return run.stab_bound[n - 1]
    k = <int> u
    return run.stab_bound[k] + (u - k) * (run.stab_bound[k + 1] - run.stab_bound[k])


cdef inline double _stab_limit(const Run* run, double mag, double re, double* rho,
                               double* bnd) noexcept nogil:
    """run.h |lambda|/b of one eigenvalue (|lambda| = mag, real part re); rho and bnd take
    |lambda| and b when it limits more than what they hold (rho < 0: nothing yet)."""
    cdef double b = _stab_bound(run, re, mag), r = run.h * mag / b
    if rho[0] < 0.0 or r > run.h * rho[0] / bnd[0]:
        rho[0] = mag
        bnd[0] = b
    return r


cdef inline double _stab_pair(const Run* run, double a, double b, double c, double d, double* rho,
                       double* bnd) noexcept nogil:
    """The limiting eigenvalue of [[a, b], [c, d]]: its run.h |lambda|/b, |lambda| into rho and
    b into bnd."""
    cdef double m = 0.5 * (a + d), det = a * d - b * c, disc = m * m - det, s, l1
    rho[0] = -1.0
    if disc < 0.0:           # a complex pair m +- i sqrt(-disc): |lambda|^2 = det
        s = sqrt(det)
        return _stab_limit(run, s, m, rho, bnd)
    s = sqrt(disc)
    l1 = m + s if m >= 0.0 else m - s      # the larger root without cancellation
    _stab_limit(run, fabs(l1), l1, rho, bnd)
    l1 = det / l1 if l1 != 0.0 else 0.0
    _stab_limit(run, fabs(l1), l1, rho, bnd)
    return run.h * rho[0] / bnd[0]


cdef inline double _stab_start(int i) noexcept nogil:
    """A fixed, generic start vector (no structural zeros)."""
    return 1.0 + 0.5 * sin(1.3 * i + 0.7)


cdef inline void _stab_matvec(const double* J, const double* d, const double* x,
                              double* z) noexcept nogil:
    """z = D^-1 J D x, D = diag(d)."""
    cdef int i, j
    cdef double s
    for i in range(_NS):
        s = 0.0
        for j in range(_NS):
            s += J[i * _NS + j] * d[j] * x[j]
        z[i] = s / d[i]


cdef inline double _velocity_scale(const double* J) noexcept nogil:
    """sqrt of the largest row sum of |A|, A = dq''/dq (the block of J): a mechanism's
    frequencies in the units of J, which scales q' to the size of q; 1 where A vanishes."""
    cdef int i, j
    cdef double sigma = 0.0, row
    for i in range(_NQ):
        row = 0.0
        for j in range(_NQ):
            row += fabs(J[(_NQ + i) * _NS + j])
        sigma = fmax(sigma, row)
    return sqrt(sigma) if sigma > 0.0 else 1.0


cdef double _stab_krylov(const Run* run, const double* J, double* work, bint fresh,
                         double* rho, double* bnd) noexcept nogil:
    """_NS > 2: the dominant eigenvalues of J from the Krylov plane {q, J q} of a power
    iteration whose vector q (work[0:_NS]) is kept from check to check; see the block comment
    above."""
    cdef double* q = work
    cdef double w[_NS]
    cdef double p[_NS]
    cdef double v[_NS]
    cdef double d[_NS]
    cdef double sigma = work[_NS + 1], scale, a, beta, qv, pv, nw, res, hn, s
    cdef int i, j, it
    if not sigma > 0.0:
        # no |lambda| measured yet: the size of A = dq''/dq
        sigma = _velocity_scale(J)
    # q in the coordinates of the new scaling, and a trace of the generic vector added: a mode
    # that q lost (decayed under the power iteration, or absent from the last modes' dominant
    # pair) can come back when the Jacobian changes
    scale = work[_NS] / sigma if work[_NS] > 0.0 else 1.0
    work[_NS] = sigma
    s = 0.0
    for i in range(_NS):
        if _NQ <= i < 2 * _NQ:
            q[i] *= scale
        s = fmax(s, fabs(q[i]))
    for i in range(_NS):
        q[i] += (1e-3 if fresh else 1e-8) * s * _stab_start(i) if s > 0.0 else _stab_start(i)
        d[i] = sigma if _NQ <= i < 2 * _NQ else 1.0
    s = 0.0
    for i in range(_NS):
        s += q[i] * q[i]
    s = 1.0 / sqrt(s)
    for i in range(_NS):
        q[i] *= s
    _stab_matvec(J, d, q, w)
    for it in range(STAB_MAXIT):
        # the plane {q, J q}: J q = a q + beta p exactly, J p = qv q + pv p + the residual
        a = 0.0
        for i in range(_NS):
            a += q[i] * w[i]
        beta = 0.0
        nw = 0.0
        for i in range(_NS):
            p[i] = w[i] - a * q[i]
            beta += p[i] * p[i]
            nw += w[i] * w[i]
        beta = sqrt(beta)
        if not nw > 0.0:
            rho[0] = 0.0
            bnd[0] = run.stab_bound[0]
            return 0.0
        if beta <= 1e-12 * sqrt(nw):
            # q is an eigenvector: a real eigenvalue a
            rho[0] = -1.0
            return _stab_limit(run, fabs(a), a, rho, bnd)
        for i in range(_NS):
            p[i] /= beta
        _stab_matvec(J, d, p, v)
        qv = 0.0
        pv = 0.0
        for i in range(_NS):
            qv += q[i] * v[i]
            pv += p[i] * v[i]
        res = 0.0
        for i in range(_NS):
            s = v[i] - qv * q[i] - pv * p[i]
            res += s * s
        hn = a * a + beta * beta + qv * qv + pv * pv
        if res <= STAB_TOL * STAB_TOL * hn or it == STAB_MAXIT - 1:
            break
        # the power iteration's next vector J q, and J (J q) = a J q + beta J p without a product
        nw = 1.0 / sqrt(nw)
        for i in range(_NS):
            q[i] = w[i] * nw
            w[i] = (a * w[i] + beta * v[i]) * nw
    s = _stab_pair(run, a, qv, beta, pv, rho, bnd)
    if rho[0] > 0.0:
        work[_NS + 1] = rho[0]
    return s


cdef double _stab_check(Run* run, Ctx* ctx, double t, const double* y, double* J,
                               bint fresh, double* rho, double* bnd) noexcept nogil:
    """run.h |lambda|/b of the limiting eigenvalue of df/dy at (t, y) (NaN where the Jacobian
    is not finite); |lambda| into rho, b into bnd.  ``fresh``: the first check since the
    Jacobian may have jumped (an interval's start, an event)."""
    cdef double local[_NS + 2]
    cdef double* work = run.stab_work
    cdef double r
    cdef int i
    jacobian(t, y, J, NULL, ctx)
    run.n_checks += 1
    rho[0] = -1.0
    # a non-finite Jacobian gives NaN below (its comparisons are all false)
    if _NS == 1:
        return _stab_limit(run, fabs(J[0]), J[0], rho, bnd)
    if _NS == 2:
        return _stab_pair(run, J[0], J[1], J[2], J[3], rho, bnd)
    if not _finite(_NS * _NS, J):
        return NAN      # and the kept vector stays clean
    if work == NULL or run.n_checks == 1:
        if work == NULL:
            work = local
        for i in range(_NS):
            work[i] = _stab_start(i)
        work[_NS] = 0.0
        work[_NS + 1] = 0.0
        fresh = True
    return _stab_krylov(run, J, work, fresh, rho, bnd)


# The loop calls the check through a pointer set when the module is imported: the compiler
# cannot inline it then.  Inlined, its code sat in the stepping loop and cost RK4 about 15 %
# per step even with the check off (registers spilled around it), against an indirect call
# every STAB_PERIOD steps.
ctypedef double (*_stab_check_fn)(Run* run, Ctx* ctx, double t, const double* y, double* J,
                                  bint fresh, double* rho, double* bnd) noexcept nogil
cdef _stab_check_fn _stab_check_call = _stab_check


cdef inline long _stab_period_max(long nstep, double r) noexcept nogil:
    """The most steps between two checks in an interval of nstep steps, the last check having
    found h |lambda|/b = r: STAB_PERIOD (a differenced Jacobian: times _NS), STAB_FAR times
    that while r < 1/STAB_FAR (|lambda| must then grow STAB_FAR-fold before a step is
    unstable), and at most an STAB_PER_INTERVAL-th of the interval."""
    cdef long p = STAB_PERIOD if _JAC_SYMBOLIC else STAB_PERIOD * _NS
    if r * STAB_FAR < 1.0:
        p *= STAB_FAR
    if nstep < p * STAB_PER_INTERVAL:
        p = nstep // STAB_PER_INTERVAL
    return p if p > 1 else 1


cdef inline long _stab_period(double r, double r_last, long since, long period_max) noexcept nogil:
    """Steps to the next check: period_max, or half the steps to the boundary extrapolated
    from the growth of h |lambda|/b since the last check (r_last, ``since`` steps ago)."""
    cdef double grow, p
    if r >= 1.0 or not (r_last >= 0.0 and since > 0 and r > r_last):
        return period_max
    grow = (r - r_last) / since
    p = 0.5 * (1.0 - r) / grow
    if p >= period_max:
        return period_max
    return <long> p if p >= 1.0 else 1


cdef int _loop_fixed(Run* run, double a, double b) noexcept nogil:
    """RK4 or the thesis scheme over [a, b] in equal steps no longer than run.h.

    State and stages live in local arrays of compile-time size (_NS, _NQ from
    the including model) and the context is a local copy, so that the compiler
    can keep them in registers.  After an event the rest of the interval is cut
    into equal steps again.  With run.stab_mode the stability check runs at the start of a
    step (see the block comment above _stab_check).
    """
    cdef Ctx local_ctx = run.ctx[0]
    cdef Ctx* ctx = &local_ctx
    cdef int i, it, ev, status = STATUS_OK
    cdef long k = 0, nstep = fixed_steps(a, b, run.h), n_rhs = 0, n_steps = run.n_steps
    cdef long max_steps = run.max_steps
    cdef bint rk4 = run.method == METHOD_RK4
    cdef double h = (b - a) / nstep, hh = 0.5 * h, h6 = h / 6.0, t = a, tn, amax, diff, prev, s_hit
    cdef double y[_NS]
    cdef double k1[_NS]
    cdef double k2[_NS]
    cdef double k3[_NS]
    cdef double k4[_NS]
    cdef double yn[_NS]
    cdef double fn[_NS]
    cdef double acc[_NQ1]
    cdef double g0[_NE1]
    cdef double g1[_NE1]
    cdef int piv[_NQ1]
    cdef int calls
    cdef bint newton
    cdef double* Jm = NULL     # df/dy (the check, koster's Newton) and koster's Newton matrix,
    cdef double* Wm = NULL     # allocated on first use
    # the stability check: the step (k) it comes at next (-1: never), the step it came at
    # last, the most steps between, its last ratio
    cdef bint fresh = True
    cdef long k_check = 0 if run.stab_mode != 0 else -1, k_last = 0
    cdef double ratio, ratio_last = -1.0, s_rho, s_bnd
    # copies the check is handed: were the addresses of y and of the context to reach a call
    # the compiler cannot see into, they could no longer live in registers through the steps
    cdef double y_chk[_NS]
    cdef Ctx ctx_chk
    if k_check == 0:
        Jm = <double*> malloc((_NS * _NS + _NQ * _NQ) * sizeof(double))
        if Jm == NULL:
            return STATUS_NO_MEMORY
        Wm = Jm + _NS * _NS
    memcpy(y, run.y, sizeof(y))
    rhs(t, y, k1, ctx)
    n_rhs += 1
    if _rec_point(run, t, y, k1) != 0:
        free(Jm)
        return _rec_failure(y, k1)
    if _NE > 0:
        events(t, y, g0, ctx)
    while k < nstep:
        if n_steps >= max_steps:
            status = STATUS_MAX_STEPS
            break
        if k == k_check:
            memcpy(y_chk, y, sizeof(y))
            ctx_chk = local_ctx
            ratio = _stab_check_call(run, &ctx_chk, t, y_chk, Jm, fresh, &s_rho, &s_bnd)
            if ratio == ratio:      # not NaN (a state blowing up is NOT_FINITE's to report)
                if ratio > run.stab_ratio:
                    run.stab_ratio = ratio
                    run.stab_t = t
                    run.stab_rho = s_rho
                    run.stab_b = s_bnd
                if ratio > 1.0 and run.stab_mode == 2:
                    status = STATUS_UNSTABLE
                    break
                # after a jump, the next step's check measures the growth to extrapolate
                k_check = k + (1 if fresh else
                               _stab_period(ratio, ratio_last, k - k_last,
                                            _stab_period_max(nstep, ratio)))
                ratio_last = ratio
            else:
                k_check = k + _stab_period_max(nstep, 1.0)
            k_last = k
            fresh = False
        # the new time is computed once, so that the last stage and the slope at the new
        # point see the very same t (the model caches cam-law values by argument)
        tn = a + (k + 1) * h if k + 1 < nstep else b
        if rk4:
            for i in range(_NS):
                yn[i] = y[i] + hh * k1[i]
            rhs(t + hh, yn, k2, ctx)
            for i in range(_NS):
                yn[i] = y[i] + hh * k2[i]
            rhs(t + hh, yn, k3, ctx)
            for i in range(_NS):
                yn[i] = y[i] + h * k3[i]
            rhs(tn, yn, k4, ctx)
            for i in range(_NS):
                yn[i] = y[i] + h6 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i])
            n_rhs += 3
        else:
            # thesis (4.23)-(4.31): X'' held constant over the step at its value at
            # mid-step theta = h/2, taken at X + dX, dX = X' theta + X'' theta^2/2 (4.24),
            # with the mid-step velocity X' + X'' theta: the equation
            # g(a) = a - F(t + theta, X + X' theta + a theta^2/2, X' + a theta) = 0.
            # Fixed-point iteration first (cheap where it contracts fast: factor (h w)^2/8 on
            # y'' = -w^2 y); once a sweep leaves more than NEWTON_RATIO of the residual (or
            # it grows), Newton's method, g'(a) = I - dF/dX theta^2/2 - dF/dX' theta, which converges up
            # to the scheme's stability boundary h w = 2 sqrt(2) and beyond (the fixed point
            # stops contracting there), and in one step for a linear model: the thesis's own
            # elimination of dX by hand (4.25)
            for i in range(_NQ):
                acc[i] = k1[_NQ + i]
            prev = 1e300
            newton = False
            for it in range(100):
                for i in range(_NQ):
                    yn[i] = y[i] + (y[_NQ + i] + 0.5 * acc[i] * hh) * hh
                    yn[_NQ + i] = y[_NQ + i] + acc[i] * hh
                rhs(t + hh, yn, k2, ctx)
                n_rhs += 1
                if not _finite(_NS, k2):
                    # a run blowing up (a step beyond the stability boundary): say so, not
                    # "did not converge"
                    status = STATUS_NOT_FINITE
                    break
                amax = 0.0
                diff = 0.0
                for i in range(_NQ):
                    diff = fmax(diff, fabs(k2[_NQ + i] - acc[i]))
                    amax = fmax(amax, fabs(k2[_NQ + i]))
                # converged, or stalled at the rounding level of the acceleration; either way
                # the last evaluation F(a) is taken, as a fixed-point sweep would
                if diff <= 1e-13 * (1.0 + amax) or (diff >= prev and diff <= 1e-9 * (1.0 + amax)):
                    for i in range(_NQ):
                        acc[i] = k2[_NQ + i]
                    break
                if not newton and it >= 1 and not (diff <= NEWTON_RATIO * prev):
                    newton = True
                    if Jm == NULL:
                        # heap, not stack: _NS^2 grows fast for models built from user files
                        Jm = <double*> malloc((_NS * _NS + _NQ * _NQ) * sizeof(double))
                        if Jm == NULL:
                            status = STATUS_NO_MEMORY
                            break
                        Wm = Jm + _NS * _NS
                if newton:
                    calls = _koster_newton_matrix(ctx, t + hh, yn, acc, k2, hh, Jm, Wm, piv, k3, k4)
                    if calls < 0:       # singular or non-finite Newton matrix
                        status = STATUS_NOT_FINITE if calls == -2 else STATUS_NO_CONVERGENCE
                        break
                    n_rhs += calls
                    for i in range(_NQ):
                        k3[i] = k2[_NQ + i] - acc[i]        # -g(a)
                    lu_solve(_NQ, Wm, piv, k3)
                    for i in range(_NQ):
                        acc[i] += k3[i]
                else:
                    for i in range(_NQ):
                        acc[i] = k2[_NQ + i]
                prev = diff
            else:
                status = STATUS_NO_CONVERGENCE
            if status != STATUS_OK:
                break
            for i in range(_NQ):
                yn[i] = y[i] + (y[_NQ + i] + 0.5 * acc[i] * h) * h      # (4.30), (4.31)
                yn[_NQ + i] = y[_NQ + i] + acc[i] * h                    # (4.28), (4.29)
        if not _finite(_NS, yn):
            status = STATUS_NOT_FINITE
            break
        rhs(tn, yn, fn, ctx)   # slope at the new point: recorded, and the next step's k1
        n_rhs += 1
        n_steps += 1
        if _NE > 0:
            ev = _event_in_step(run, t, tn - t, y, yn, k1, fn, NULL, 0, g0, g1, &s_hit)
            if ev >= 0:
                # cut the step at the crossing: state from the step's cubic Hermite extension
                _dense(s_hit, tn - t, y, yn, k1, fn, NULL, 0, k2)
                tn = t + s_hit * (tn - t)
                memcpy(y, k2, sizeof(y))
                rhs(tn, y, k1, ctx)
                n_rhs += 1
                t = tn
                status = _apply_event(run, ev, t, y, k1, g0)
                if status != STATUS_OK:
                    break
                # the event refreshed run.ctx (the rhs variant of the new cam segments)
                local_ctx = run.ctx[0]
                a = t   # equal steps again over the rest of the interval
                k = 0
                if k_check >= 0:    # new modes: check the new Jacobian before the next step
                    k_check = 0
                    k_last = 0
                    fresh = True
                nstep = fixed_steps(a, b, run.h) if b > a else 0
                if nstep:
                    h = (b - a) / nstep
                    hh = 0.5 * h
                    h6 = h / 6.0
                continue
            memcpy(g0, g1, sizeof(g0))
        t = tn
        memcpy(y, yn, sizeof(y))
        memcpy(k1, fn, sizeof(k1))
        k += 1
        status = _project_accepted(ctx, t, y, k1, g0, &n_rhs)
        if status != STATUS_OK:
            break
        if _rec_point(run, t, y, k1) != 0:
            status = _rec_failure(y, k1)
            break
    free(Jm)
    memcpy(run.y, y, sizeof(y))
    run.n_rhs += n_rhs
    run.n_steps = n_steps
    if status != STATUS_OK:
        run.t_fail = t
    return status


# Dormand-Prince 5(4) (Dormand & Prince 1980) and Hairer's dense-output weights,
# as C compile-time constants
cdef extern from *:
    """
    #define DP_C2 (1.0 / 5)
    #define DP_C3 (3.0 / 10)
    #define DP_C4 (4.0 / 5)
    #define DP_C5 (8.0 / 9)
    #define DP_A21 (1.0 / 5)
    #define DP_A31 (3.0 / 40)
    #define DP_A32 (9.0 / 40)
    #define DP_A41 (44.0 / 45)
    #define DP_A42 (-56.0 / 15)
    #define DP_A43 (32.0 / 9)
    #define DP_A51 (19372.0 / 6561)
    #define DP_A52 (-25360.0 / 2187)
    #define DP_A53 (64448.0 / 6561)
    #define DP_A54 (-212.0 / 729)
    #define DP_A61 (9017.0 / 3168)
    #define DP_A62 (-355.0 / 33)
    #define DP_A63 (46732.0 / 5247)
    #define DP_A64 (49.0 / 176)
    #define DP_A65 (-5103.0 / 18656)
    #define DP_B1 (35.0 / 384)
    #define DP_B3 (500.0 / 1113)
    #define DP_B4 (125.0 / 192)
    #define DP_B5 (-2187.0 / 6784)
    #define DP_B6 (11.0 / 84)
    #define DP_E1 (71.0 / 57600)
    #define DP_E3 (-71.0 / 16695)
    #define DP_E4 (71.0 / 1920)
    #define DP_E5 (-17253.0 / 339200)
    #define DP_E6 (22.0 / 525)
    #define DP_E7 (-1.0 / 40)
    #define DP_D1 (-12715105075.0 / 11282082432)
    #define DP_D3 (87487479700.0 / 32700410799)
    #define DP_D4 (-10690763975.0 / 1880347072)
    #define DP_D5 (701980252875.0 / 199316789632)
    #define DP_D6 (-1453857185.0 / 822651844)
    #define DP_D7 (69997945.0 / 29380423)
    """
    const double DP_C2
    const double DP_C3
    const double DP_C4
    const double DP_C5
    const double DP_A21
    const double DP_A31
    const double DP_A32
    const double DP_A41
    const double DP_A42
    const double DP_A43
    const double DP_A51
    const double DP_A52
    const double DP_A53
    const double DP_A54
    const double DP_A61
    const double DP_A62
    const double DP_A63
    const double DP_A64
    const double DP_A65
    const double DP_B1
    const double DP_B3
    const double DP_B4
    const double DP_B5
    const double DP_B6
    const double DP_E1
    const double DP_E3
    const double DP_E4
    const double DP_E5
    const double DP_E6
    const double DP_E7
    const double DP_D1
    const double DP_D3
    const double DP_D4
    const double DP_D5
    const double DP_D6
    const double DP_D7


cdef inline double _absmax(double a, double b) noexcept nogil:
    a = -a if a < 0.0 else a
    b = -b if b < 0.0 else b
    return a if a > b else b


cdef inline double _rms(const double* v, const double* y0, const double* y1,
                        double rtol, const double* atol) noexcept nogil:
    cdef int i
    cdef double s = 0.0, e
    for i in range(_NS):
        e = v[i] / (atol[i] + rtol * _absmax(y0[i], y1[i]))
        s += e * e
    return sqrt(s / _NS)


cdef double _dp_first_step(Run* run, double t, const double* y, const double* f0,
                           double span, double order) noexcept nogil:
    """Starting step from the sizes of y, y' and y'' for a method of the given order (Hairer,
    Norsett & Wanner, II.4)."""
    cdef int i
    cdef double y1[_NS]
    cdef double f1[_NS]
    cdef double d0 = _rms(y, y, y, run.rtol, run.atol)
    cdef double d1 = _rms(f0, y, y, run.rtol, run.atol)
    cdef double h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
    cdef double d2, h1
    h0 = fmin(h0, span)
    for i in range(_NS):
        y1[i] = y[i] + h0 * f0[i]
    rhs(t + h0, y1, f1, run.ctx)
    run.n_rhs += 1
    for i in range(_NS):
        f1[i] -= f0[i]
    d2 = _rms(f1, y, y, run.rtol, run.atol) / h0
    if fmax(d1, d2) <= 1e-15:
        h1 = fmax(1e-6, h0 * 1e-3)
    else:
        h1 = pow(0.01 / fmax(d1, d2), 1.0 / order)
    return fmin(fmin(100.0 * h0, h1), span)


cdef double _stiff_ratio(const double* yn, const double* ys, const double* fn,
                         const double* fs) noexcept nogil:
    """|lambda| of the Jacobian along yn - ys, from two slopes at the same time: Hairer's
    stiffness test (DOPRI5, DOP853; Hairer & Wanner, Solving ODEs II, sec. IV.2), 0 when
    yn = ys.
    The norm: DOPRI5's Euclidean one reads |K x|/|x| = omega^2, not omega, for a difference
    along the positions of an undamped oscillator (J = [[0, 1], [-K, 0]] is far from normal
    when omega >> 1) and flags the one-DOF model at rtol 1e-6.  Here the positions are weighted
    by the frequency estimate omega2 = |w_q'|/|v_q| (v = yn - ys, w = fn - fs, w_q = v_q'
    exactly), which makes the ratio omega for both an undamped and an overdamped mode;
    first-order states count plainly."""
    cdef int i
    cdef double st_a = 0.0    # |v_q|^2
    cdef double st_b = 0.0    # |v_q'|^2 (+ first-order states)
    cdef double st_c = 0.0    # |w_q'|^2 (+ first-order states)
    cdef double st_wq = 0.0   # |w_q|^2
    cdef double d, e, num, den
    for i in range(_NS):
        d = yn[i] - ys[i]
        e = fn[i] - fs[i]
        if i < _NQ:
            st_a += d * d
            st_wq += e * e
        else:
            st_b += d * d
            st_c += e * e
    if st_a > 0.0:
        d = sqrt(st_c / st_a) if _NQ > 0 else 1.0
        num = d * st_wq + st_c
        den = d * st_a + st_b
    else:
        num = st_wq + st_c
        den = st_a + st_b
    return sqrt(num / den) if den > 0.0 else 0.0


cdef int _cut_at_event(Run* run, Ctx* ctx, int hit, double s_hit, double* t, double h,
                       double* y, const double* yn, double* f0, const double* f1, double* ex,
                       int nx, double* g0, long* n_rhs) noexcept nogil:
    """Cut the step at the crossing s_hit, keeping its extension on the shortened part (the
    record's row of the step start holds ex), then apply the event: t, y and f0 become the
    right limit there."""
    cdef double yc[_NS]
    cdef double fc[_NS]
    cdef double tc = t[0] + s_hit * h
    _dense(s_hit, h, y, yn, f0, f1, ex, nx, yc)
    rhs(tc, yc, fc, ctx)
    n_rhs[0] += 1
    if _cut_extras(s_hit, h, y, yn, f0, f1, ex, nx, yc, fc) != 0:
        return STATUS_BAD_MODEL
    t[0] = tc
    memcpy(y, yc, sizeof(yc))
    memcpy(f0, fc, sizeof(fc))
    return _apply_event(run, hit, tc, y, f0, g0)


cdef int _loop_dp54(Run* run, double a, double b) noexcept nogil:
    """Dormand-Prince 5(4) over [a, b]: local extrapolation, PI step-size control."""
    cdef Ctx local_ctx = run.ctx[0]
    cdef Ctx* ctx = &local_ctx
    cdef int i, status = STATUS_OK
    cdef double y[_NS]
    cdef double k1[_NS]
    cdef double k2[_NS]
    cdef double k3[_NS]
    cdef double k4[_NS]
    cdef double k5[_NS]
    cdef double k6[_NS]
    cdef double k7[_NS]
    cdef double yn[_NS]
    cdef double ys[_NS]
    cdef double ev[_NS]
    cdef double* r4
    cdef double g0[_NE1]
    cdef double g1[_NE1]
    cdef int hit
    cdef double s_hit
    cdef double t = a, h, err, fac, rtol = run.rtol
    cdef const double* atol = run.atol
    cdef long n_steps = run.n_steps, n_rej = run.n_rejected, n_rhs = 0, max_steps = run.max_steps
    cdef bint last, rejected = False
    # Hairer's stiffness test (DOPRI5, Hairer & Wanner, Solving ODEs II, sec. IV.2): counters
    # of detections (iasti) and of non-stiff steps since the last one (nonsti), per interval
    cdef int iasti = 0, nonsti = 0
    memcpy(y, run.y, sizeof(y))
    # slopes jump at a breakpoint: every interval starts afresh
    rhs(t, y, k1, ctx)
    n_rhs += 1
    if _rec_point(run, t, y, k1) != 0:
        return _rec_failure(y, k1)
    if _NE > 0:
        events(t, y, g0, ctx)
    if run.h <= 0.0:
        run.h = _dp_first_step(run, t, y, k1, fmin(b - a, run.h_max), 5.0)
    h = fmin(run.h, run.h_max)
    run.err_old = 1e-4
    while t < b:
        if n_steps + n_rej >= max_steps:
            status = STATUS_MAX_STEPS
            break
        if h < 16.0 * 2.220446049250313e-16 * fabs(t):   # where t + h no longer moves t
            status = STATUS_STEP_UNDERFLOW
            break
        last = t + 1.01 * h >= b
        if last:
            h = b - t
        for i in range(_NS):
            ys[i] = y[i] + h * DP_A21 * k1[i]
        rhs(t + DP_C2 * h, ys, k2, ctx)
        for i in range(_NS):
            ys[i] = y[i] + h * (DP_A31 * k1[i] + DP_A32 * k2[i])
        rhs(t + DP_C3 * h, ys, k3, ctx)
        for i in range(_NS):
            ys[i] = y[i] + h * (DP_A41 * k1[i] + DP_A42 * k2[i] + DP_A43 * k3[i])
        rhs(t + DP_C4 * h, ys, k4, ctx)
        for i in range(_NS):
            ys[i] = y[i] + h * (DP_A51 * k1[i] + DP_A52 * k2[i] + DP_A53 * k3[i] + DP_A54 * k4[i])
        rhs(t + DP_C5 * h, ys, k5, ctx)
        for i in range(_NS):
            ys[i] = y[i] + h * (DP_A61 * k1[i] + DP_A62 * k2[i] + DP_A63 * k3[i] + DP_A64 * k4[i]
                                + DP_A65 * k5[i])
        rhs(t + h, ys, k6, ctx)
        for i in range(_NS):
            yn[i] = y[i] + h * (DP_B1 * k1[i] + DP_B3 * k3[i] + DP_B4 * k4[i] + DP_B5 * k5[i]
                                + DP_B6 * k6[i])
        rhs(t + h, yn, k7, ctx)
        n_rhs += 6
        for i in range(_NS):
            ev[i] = h * (DP_E1 * k1[i] + DP_E3 * k3[i] + DP_E4 * k4[i] + DP_E5 * k5[i]
                         + DP_E6 * k6[i] + DP_E7 * k7[i])
        err = _rms(ev, y, yn, rtol, atol)
        if not isfinite(err):
            # a NaN in a trial stage: retry smaller unless the start itself is bad
            if not _finite(_NS, y):
                status = STATUS_NOT_FINITE
                break
            h *= 0.2
            n_rej += 1
            rejected = True
            continue
        if err <= 1.0:
            # accepted: PI step-size control (Gustafsson), exponents as in Hairer's DOPRI5
            if err == 0.0:
                fac = 10.0
            else:
                fac = fmin(10.0, fmax(0.2, 0.9 * pow(err, -0.17) * pow(run.err_old, 0.04)))
            if rejected:
                fac = fmin(fac, 1.0)
            run.err_old = fmax(err, 1e-4)
            r4 = run.rec.rows + (run.rec.n - 1) * run.rec.width + 1 + 2 * _NS
            for i in range(_NS):
                r4[i] = h * (DP_D1 * k1[i] + DP_D3 * k3[i] + DP_D4 * k4[i] + DP_D5 * k5[i]
                             + DP_D6 * k6[i] + DP_D7 * k7[i])
            n_steps += 1
            # stiffness test (Hairer's DOPRI5): stages 6 and 7 sit at the same time t + h
            # (FSAL), so h |k7 - k6|/|yn - ys| estimates h times the spectral radius of the
            # Jacobian there (_stiff_ratio); beyond 3.25 (near the boundary of DP5's
            # stability region, 3.31 on the negative real axis) the step is limited by
            # stability, not accuracy.  Fired at the 15th detection, counted back to zero
            # after 6 non-stiff steps (DOPRI5's IASTI, NONSTI); only the first time is
            # recorded, the run goes on.
            if h * _stiff_ratio(yn, ys, k7, k6) > 3.25:
                nonsti = 0
                iasti += 1
                if iasti == 15 and isnan(run.t_stiff):
                    run.t_stiff = t
            else:
                nonsti += 1
                if nonsti == 6:
                    iasti = 0
            if _NE > 0:
                hit = _event_in_step(run, t, h, y, yn, k1, k7, r4, 1, g0, g1, &s_hit)
                if hit >= 0:
                    status = _cut_at_event(run, ctx, hit, s_hit, &t, h, y, yn, k1, k7, r4, 1,
                                           g0, &n_rhs)
                    if status != STATUS_OK:
                        break
                    # the event refreshed run.ctx (the rhs variant of the new cam segments)
                    local_ctx = run.ctx[0]
                    rejected = False
                    continue
                memcpy(g0, g1, sizeof(g0))
            t = b if last else t + h
            memcpy(y, yn, sizeof(y))
            memcpy(k1, k7, sizeof(k1))
            status = _project_accepted(ctx, t, y, k1, g0, &n_rhs)
            if status != STATUS_OK:
                break
            if _rec_point(run, t, y, k1) != 0:
                status = _rec_failure(y, k1)
                break
            if not last:
                run.h = h
            h = fmin(h * fac, run.h_max)
            rejected = False
        else:
            h *= fmax(0.2, 0.9 * pow(err, -0.2))
            n_rej += 1
            rejected = True
    memcpy(run.y, y, sizeof(y))
    run.n_steps = n_steps
    run.n_rejected = n_rej
    run.n_rhs += n_rhs
    if status != STATUS_OK:
        run.t_fail = t
    return status


# -- DOP853: Dormand-Prince 8(5,3) (Hairer, Norsett & Wanner I, sec. II.10) ---------------
#
# The explicit Runge-Kutta pair of order 8 of Hairer, Norsett & Wanner, Solving ODEs I,
# sec. II.10, as in their code DOP853: 12 stages, the last at t + h, and the slope at the new
# point (FSAL, stage 13, the next step's first).  Its error estimate combines an embedded
# fifth-order and a third-order one, err = e5^2/sqrt(e5^2 + 0.01 e3^2) (norms of the scaled
# differences), which keeps the fifth-order estimate from being too optimistic on large steps.
# Dense output of order 7 from three more stages per accepted step (c = 0.1, 0.2, 7/9): four
# extras in the record (dense.pxd).  Stiffness test as DOP853's: stage 12 and the new slope
# sit at the same time, and h |lambda| beyond 6.1 (near the boundary of its stability region
# on the negative real axis) counts as a stiff step.  The tableau: dop853.pxd.

cdef inline void _d8_sum(const double* w, int n, double h, const double* K, const double* base,
                         double* out) noexcept nogil:
    """out = base + h sum_j<n w_j K_j (base NULL: 0)."""
    cdef int i, j
    cdef double acc
    for i in range(_NS):
        acc = 0.0
        for j in range(n):
            acc += w[j] * K[j * _NS + i]
        out[i] = (base[i] if base != NULL else 0.0) + h * acc


cdef inline double _inv_root8(double x) noexcept nogil:
    """x^(-1/8) by three square roots: the same value to rounding as pow(x, -0.125), in a
    few instructions instead of libm's general power (a step's largest cost after its stages)."""
    return 1.0 / sqrt(sqrt(sqrt(x)))


cdef int _loop_dop853(Run* run, double a, double b) noexcept nogil:
    """Dormand-Prince 8(5,3) over [a, b] (see above): DOP853's error estimate, step control
    with exponent 1/8 and factors in [1/3, 6], dense output of order 7, events, stiffness test."""
    cdef Ctx local_ctx = run.ctx[0]
    cdef Ctx* ctx = &local_ctx
    cdef int i, st, status = STATUS_OK
    cdef double y[_NS]
    cdef double yn[_NS]
    cdef double ys[_NS]
    cdef double y12[_NS]          # stage 12's argument (at t + h), for the stiffness test
    cdef double K[16 * _NS]       # the stages' slopes; K[12] the new point's
    cdef double w5[_NS]
    cdef double w3[_NS]
    cdef double* ex
    cdef double g0[_NE1]
    cdef double g1[_NE1]
    cdef int hit
    cdef double s_hit
    cdef double t = a, h, err, err5, err3, sc, fac, rtol = run.rtol
    cdef const double* atol = run.atol
    cdef long n_steps = run.n_steps, n_rej = run.n_rejected, n_rhs = 0, max_steps = run.max_steps
    cdef bint last, rejected = False
    cdef int iasti = 0, nonsti = 0
    memcpy(y, run.y, sizeof(y))
    rhs(t, y, K, ctx)
    n_rhs += 1
    if _rec_point(run, t, y, K) != 0:
        return _rec_failure(y, K)
    if _NE > 0:
        events(t, y, g0, ctx)
    if run.h <= 0.0:
        run.h = _dp_first_step(run, t, y, K, fmin(b - a, run.h_max), 8.0)
    h = fmin(run.h, run.h_max)
    while t < b:
        if n_steps + n_rej >= max_steps:
            status = STATUS_MAX_STEPS
            break
        if h < 16.0 * 2.220446049250313e-16 * fabs(t):   # where t + h no longer moves t
            status = STATUS_STEP_UNDERFLOW
            break
        last = t + 1.01 * h >= b
        if last:
            h = b - t
        for st in range(1, 12):
            _d8_sum(D8_A[st], st, h, K, y, ys)
            rhs(t + D8_C[st] * h, ys, K + st * _NS, ctx)
        memcpy(y12, ys, sizeof(ys))
        _d8_sum(D8_A[12], 12, h, K, y, yn)
        rhs(t + h, yn, K + 12 * _NS, ctx)
        n_rhs += 12
        _d8_sum(D8_E5, 12, h, K, NULL, w5)
        _d8_sum(D8_E3, 12, h, K, NULL, w3)
        err5 = 0.0
        err3 = 0.0
        for i in range(_NS):
            sc = atol[i] + rtol * _absmax(y[i], yn[i])
            err5 += (w5[i] / sc) * (w5[i] / sc)
            err3 += (w3[i] / sc) * (w3[i] / sc)
        # a NaN in err5 must not read as a perfect step (NaN > 0 is false): it is passed on
        # as NaN, which the test below rejects
        err = err5 / sqrt(_NS * (err5 + 0.01 * err3)) if err5 > 0.0 else (0.0 if err5 == 0.0
                                                                          else NAN)
        if not isfinite(err):
            if not _finite(_NS, y):
                status = STATUS_NOT_FINITE
                break
            h *= 0.2
            n_rej += 1
            rejected = True
            continue
        if err <= 1.0:
            fac = 6.0 if err == 0.0 else fmin(6.0, fmax(1.0 / 3.0, 0.9 * _inv_root8(err)))
            if rejected:
                fac = fmin(fac, 1.0)
            n_steps += 1
            if h * _stiff_ratio(yn, y12, K + 12 * _NS, K + 11 * _NS) > 6.1:
                nonsti = 0
                iasti += 1
                if iasti == 15 and isnan(run.t_stiff):
                    run.t_stiff = t
            else:
                nonsti += 1
                if nonsti == 6:
                    iasti = 0
            # the dense output's three stages and its four extras, in the row of the step start;
            # a run may leave them out where no event crossed (events are located on them):
            # the extras NaN then, but the second the step's length, from which dense_fill
            # makes them later, bit for bit, where they are wanted
            ex = run.rec.rows + (run.rec.n - 1) * run.rec.width + 1 + 2 * _NS
            if _NE > 0:
                events(t + h, yn, g1, run.ctx)
            if not run.skip_dense or (_NE > 0 and _any_crossed(g0, g1)):
                for st in range(13, 16):
                    _d8_sum(D8_A[st], st, h, K, y, ys)
                    rhs(t + D8_C[st] * h, ys, K + st * _NS, ctx)
                n_rhs += 3
                for st in range(4):
                    _d8_sum(D8_D[st], 16, h, K, NULL, ex + st * _NS)
            else:
                for i in range(4 * _NS):
                    ex[i] = NAN
                ex[1] = h
            if _NE > 0:
                hit = _first_event(run, t, h, y, yn, K, K + 12 * _NS, ex, 4, g0, g1, &s_hit)
                if hit >= 0:
                    status = _cut_at_event(run, ctx, hit, s_hit, &t, h, y, yn, K, K + 12 * _NS,
                                           ex, 4, g0, &n_rhs)
                    if status != STATUS_OK:
                        break
                    # the event refreshed run.ctx (the rhs variant of the new cam segments)
                    local_ctx = run.ctx[0]
                    rejected = False
                    continue
                memcpy(g0, g1, sizeof(g0))
            t = b if last else t + h
            memcpy(y, yn, sizeof(y))
            memcpy(K, K + 12 * _NS, _NS * sizeof(double))
            status = _project_accepted(ctx, t, y, K, g0, &n_rhs)
            if status != STATUS_OK:
                break
            if _rec_point(run, t, y, K) != 0:
                status = _rec_failure(y, K)
                break
            if not last:
                run.h = h
            h = fmin(h * fac, run.h_max)
            rejected = False
        else:
            h *= fmax(1.0 / 3.0, 0.9 * _inv_root8(err))
            n_rej += 1
            rejected = True
    memcpy(run.y, y, sizeof(y))
    run.n_steps = n_steps
    run.n_rejected = n_rej
    run.n_rhs += n_rhs
    if status != STATUS_OK:
        run.t_fail = t
    return status


cdef int dense_fill(Ctx* ctx, double* row) noexcept nogil:
    """The DOP853 dense output a run left out of a recorded row (its extras NaN but the
    second, the step's length h): the step from the row's t, y and slope made again, its
    stages and the extras exactly as the loop makes them, into the row.  The calls made
    (16); 0 for a row that holds its dense output or is not a left-out DOP853 row.  ``ctx``
    in the row's modes."""
    cdef double* y = row + 1
    cdef double* ex = row + 1 + 2 * _NS
    cdef double t = row[0], h = ex[1]
    cdef double K[16 * _NS]
    cdef double ys[_NS]
    cdef int st
    if not isnan(ex[0]) or not h > 0.0:
        return 0
    memcpy(K, row + 1 + _NS, _NS * sizeof(double))
    for st in range(1, 12):
        _d8_sum(D8_A[st], st, h, K, y, ys)
        rhs(t + D8_C[st] * h, ys, K + st * _NS, ctx)
    _d8_sum(D8_A[12], 12, h, K, y, ys)
    rhs(t + h, ys, K + 12 * _NS, ctx)
    for st in range(13, 16):
        _d8_sum(D8_A[st], st, h, K, y, ys)
        rhs(t + D8_C[st] * h, ys, K + st * _NS, ctx)
    for st in range(4):
        _d8_sum(D8_D[st], 16, h, K, NULL, ex + st * _NS)
    return 16


# -- RKN12(10): models whose accelerations do not depend on velocities -------------------
#
# Where q'' = g(t, q) and the state is (q, q') alone (CAMSHAFT-1 (4.15), the undamped one-DOF
# follower (3.1), the chain), a Runge-Kutta-Nystrom method integrates q'' directly: its stages
# take only positions, so it reaches order 12 with 17 stages where a first-order method of
# that order would need many more.  The pair of Dormand, El-Mikkawy & Prince (1987; rkn12.pxd)
# carries an embedded solution of order 10 whose difference from the order-12 one is the
# error estimate (exponent 1/11, factors in [1/4, 4], 0.9 safety).  The slope at the new point
# serves as the next step's first stage: 17 calls a step.  The method has no continuous
# extension of its order, so its dense output is made from the method itself: the state at the
# eight interior nodes s_j = j/9 by steps of length s_j h from the step's start (each as
# accurate as the step), through which the extras (dense.pxd, eight of them: degree 11) are
# fitted.  That costs 128 calls a step, so a run leaves it out unless asked (Run.skip_dense),
# and whoever needs it runs again with it (Result.record).  Events are not offered.

cdef void _rk12_stages(Ctx* ctx, double t, const double* y, double h, double* G,
                       double* ys, double* dy) noexcept nogil:
    """Stages 1 to 16 of a step of length h from (t, y) into G (G[i _NQ + k], stage i of
    coordinate k); stage 0, g at (t, q), already in G."""
    cdef int st, j, k
    cdef double acc, c
    for k in range(_NQ, _NS):
        ys[k] = y[k]               # g does not read the velocities: any value serves
    for st in range(1, 17):
        c = RK12_C[st]
        for k in range(_NQ):
            acc = 0.0
            for j in range(st):
                acc += RK12_A[st][j] * G[j * _NQ + k]
            ys[k] = y[k] + c * h * y[_NQ + k] + h * h * acc
        rhs(t + c * h, ys, dy, ctx)
        for k in range(_NQ):
            G[st * _NQ + k] = dy[_NQ + k]


cdef inline void _rk12_new(const double* y, double h, const double* G, double* yn,
                           double* e) noexcept nogil:
    """The order-12 state after the step into yn and, unless e is NULL, its difference from
    the order-10 one (the error estimate) into e."""
    cdef int j, k
    cdef double p, pl, v, vl, g
    for k in range(_NQ):
        p = pl = v = vl = 0.0
        for j in range(17):
            g = G[j * _NQ + k]
            p += RK12_BP[j] * g
            v += RK12_BV[j] * g
            if e != NULL:
                pl += RK12_BPL[j] * g
                vl += RK12_BVL[j] * g
        yn[k] = y[k] + h * y[_NQ + k] + h * h * p
        yn[_NQ + k] = y[_NQ + k] + h * v
        if e != NULL:
            e[k] = h * h * (p - pl)
            e[_NQ + k] = h * (v - vl)


cdef int _loop_rkn12(Run* run, double a, double b) noexcept nogil:
    """RKN12(10) over [a, b] (see above): the embedded error estimate, step control with
    exponent 1/11 and factors in [1/4, 4], the dense output from interior steps on request."""
    cdef Ctx local_ctx = run.ctx[0]
    cdef Ctx* ctx = &local_ctx
    cdef int i, j, status = STATUS_OK
    cdef double y[_NS]
    cdef double yn[_NS]
    cdef double ys[_NS]
    cdef double dy[_NS]
    cdef double f[_NS]
    cdef double fn[_NS]
    cdef double e[_NS]
    cdef double G[17 * _NQ]
    cdef double vals[8 * _NS]
    cdef double W[64]
    cdef double* ex
    cdef double t = a, h, err, sc, fac, rtol = run.rtol
    cdef const double* atol = run.atol
    cdef long n_steps = run.n_steps, n_rej = run.n_rejected, n_rhs = 0, max_steps = run.max_steps
    cdef bint last, rejected = False, dense = not run.skip_dense
    if _NE > 0 or _NS != 2 * _NQ or run.rec.n_extra != 8 or fit_matrix(8, W) != 0:
        return STATUS_BAD_MODEL
    memcpy(y, run.y, sizeof(y))
    rhs(t, y, f, ctx)
    n_rhs += 1
    if _rec_point(run, t, y, f) != 0:
        return _rec_failure(y, f)
    if run.h <= 0.0:
        run.h = _dp_first_step(run, t, y, f, fmin(b - a, run.h_max), 12.0)
    h = fmin(run.h, run.h_max)
    while t < b:
        if n_steps + n_rej >= max_steps:
            status = STATUS_MAX_STEPS
            break
        if h < 16.0 * 2.220446049250313e-16 * fabs(t):
            status = STATUS_STEP_UNDERFLOW
            break
        last = t + 1.01 * h >= b
        if last:
            h = b - t
        memcpy(G, f + _NQ, _NQ * sizeof(double))
        _rk12_stages(ctx, t, y, h, G, ys, dy)
        n_rhs += 16
        _rk12_new(y, h, G, yn, e)
        err = 0.0
        for i in range(_NS):
            sc = atol[i] + rtol * _absmax(y[i], yn[i])
            err += (e[i] / sc) * (e[i] / sc)
        err = sqrt(err / _NS)
        if not isfinite(err):
            if not _finite(_NS, y):
                status = STATUS_NOT_FINITE
                break
            h *= 0.25
            n_rej += 1
            rejected = True
            continue
        if err <= 1.0:
            fac = 4.0 if err == 0.0 else fmin(4.0, fmax(0.25, 0.9 * pow(err, -1.0 / 11.0)))
            if rejected:
                fac = fmin(fac, 1.0)
            rhs(t + h, yn, fn, ctx)
            n_rhs += 1
            n_steps += 1
            ex = run.rec.rows + (run.rec.n - 1) * run.rec.width + 1 + 2 * _NS
            if dense:
                for j in range(8):
                    memcpy(G, f + _NQ, _NQ * sizeof(double))
                    _rk12_stages(ctx, t, y, (j + 1.0) / 9.0 * h, G, ys, dy)
                    _rk12_new(y, (j + 1.0) / 9.0 * h, G, vals + j * _NS, NULL)
                n_rhs += 8 * 16
                fit_extras(8, _NS, W, h, y, yn, f, fn, vals, ex)
            else:
                for i in range(8 * _NS):
                    ex[i] = NAN
            t = b if last else t + h
            memcpy(y, yn, sizeof(y))
            memcpy(f, fn, sizeof(f))
            status = _project_accepted(ctx, t, y, f, NULL, &n_rhs)
            if status != STATUS_OK:
                break
            if _rec_point(run, t, y, f) != 0:
                status = _rec_failure(y, f)
                break
            if not last:
                run.h = h
            h = fmin(h * fac, run.h_max)
            rejected = False
        else:
            h *= fmax(0.25, 0.9 * pow(err, -1.0 / 11.0))
            n_rej += 1
            rejected = True
    memcpy(run.y, y, sizeof(y))
    run.n_steps = n_steps
    run.n_rejected = n_rej
    run.n_rhs += n_rhs
    if status != STATUS_OK:
        run.t_fail = t
    return status


# -- RODAS4: the stiff solver (Hairer & Wanner II, sec. IV.7) ---------------------------
#
# Hairer & Wanner, Solving ODEs II, sec. IV.7: a Rosenbrock method in the form (7.25),
#
#     (I/(h gamma) - J) u_i = f(t + alpha_i h, y + sum_j a_ij u_j) + sum_j (c_ij/h) u_j
#                             + gamma_i h df/dt,
#
# with J = df/dy and df/dt at the step's start.  RODAS4 is stiffly accurate: the argument
# of stage 6 is the embedded third-order solution and y_1 = that + u_6, so u_6 itself is the
# error estimate.  One LU of (I/(h gamma) - J) serves all six stages: no Newton iteration
# that could fail to converge.  Dense output and event location use the cubic Hermite
# interpolant of the record (O(h^4), as accurate as the method), so no `extra` is stored.
# Coefficients: Hairer & Wanner's RODAS4 as tabulated in sec. IV.7 and in their code RODAS
# (subroutine ROCOEF, METH = 1); gamma_i = RO4_D_i, alpha_i = RO4_C_i, alpha_5 = alpha_6 = 1.
cdef extern from *:
    """
    #define RO4_GAMMA 0.25
    #define RO4_C2 0.386
    #define RO4_C3 0.21
    #define RO4_C4 0.63
    #define RO4_D1 0.25
    #define RO4_D2 (-0.1043)
    #define RO4_D3 0.1035
    #define RO4_D4 (-0.3620000000000023e-01)
    #define RO4_A21 1.544
    #define RO4_A31 0.9466785280815826
    #define RO4_A32 0.2557011698983284
    #define RO4_A41 3.314825187068521
    #define RO4_A42 2.896124015972201
    #define RO4_A43 0.9986419139977817
    #define RO4_A51 1.221224509226641
    #define RO4_A52 6.019134481288629
    #define RO4_A53 12.53708332932087
    #define RO4_A54 (-0.6878860361058950)
    #define RO4_C21 (-5.6688)
    #define RO4_C31 (-2.430093356833875)
    #define RO4_C32 (-0.2063599157091915)
    #define RO4_C41 (-0.1073529058151375)
    #define RO4_C42 (-9.594562251023355)
    #define RO4_C43 (-20.47028614809616)
    #define RO4_C51 7.496443313967647
    #define RO4_C52 (-10.24680431464352)
    #define RO4_C53 (-33.99990352819905)
    #define RO4_C54 11.70890893206160
    #define RO4_C61 8.083246795921522
    #define RO4_C62 (-7.981132988064893)
    #define RO4_C63 (-31.52159432874371)
    #define RO4_C64 16.31930543123136
    #define RO4_C65 (-6.058818238834054)
    """
    const double RO4_GAMMA
    const double RO4_C2
    const double RO4_C3
    const double RO4_C4
    const double RO4_D1
    const double RO4_D2
    const double RO4_D3
    const double RO4_D4
    const double RO4_A21
    const double RO4_A31
    const double RO4_A32
    const double RO4_A41
    const double RO4_A42
    const double RO4_A43
    const double RO4_A51
    const double RO4_A52
    const double RO4_A53
    const double RO4_A54
    const double RO4_C21
    const double RO4_C31
    const double RO4_C32
    const double RO4_C41
    const double RO4_C42
    const double RO4_C43
    const double RO4_C51
    const double RO4_C52
    const double RO4_C53
    const double RO4_C54
    const double RO4_C61
    const double RO4_C62
    const double RO4_C63
    const double RO4_C64
    const double RO4_C65


cdef int _jacobian(Run* run, Ctx* ctx, double t, const double* y, const double* f0, double span,
                   const double* ymag, double h, double* J, double* ft) noexcept nogil:
    """J = df/dy (row-major: J[i * _NS + j] = df_i/dy_j) and ft = df/dt at (t, y) unless ft is
    NULL; returns the right-hand-side calls spent (they count in n_rhs).

    The model's generated Jacobian where it is symbolic (_JAC_SYMBOLIC, set by the template);
    else central differences, increment eps^(1/3) times the state's size: a Rosenbrock method is
    not a W-method, an error dJ in the Jacobian enters its local error as h^2 dJ f, which
    forward differences (dJ ~ sqrt(eps) |f|/|y|) made dominant on the beam follower, whose
    rhs rounds at the level of large internal terms (half the steps rejected, the step
    shrinking like rtol^(1/2)); central differences cut dJ to ~eps^(2/3) for 2 n + 2 calls.

    The increment's floor: not only the state's declared scale (1e3 atol/rtol), which for the
    beam's modal rates is the amplitudes' 1e-5 while the rates themselves are ~1, but also
    ymag_j, the largest |y_j| of the interval so far, and |h f_j|, what y_j changes by over
    the coming step (f must be smooth over that range anyway for the step to be accurate, and
    an error dJ_ij enters only multiplied by such a change).  Without them a modal rate passing
    through zero got an increment ~1e-10 while the constrained rhs rounds at 2e-7 |f| (the
    ill-conditioned augmented solve of beam6): its Jacobian column came out 30 % wrong, the
    error estimate fell like h instead of h^4 and the step collapsed to 1e-12 s in bursts
    (1813 of them in the first 0.003 s at rtol 1e-6; 1.37 M steps a revolution).
    """
    cdef int i, j
    cdef double yj, d, dt
    cdef double yp[_NS]
    cdef double fp[_NS]
    cdef double fm[_NS]
    cdef int calls = 0
    if _JAC_SYMBOLIC:
        # the model's generated Jacobian (derived symbolically with the equations): exact, and
        # no rhs calls; its manifest says "symbolic"; df/dt with it where derived
        jacobian(t, y, J, ft if _FT_SYMBOLIC else NULL, ctx)
        if _FT_SYMBOLIC or ft == NULL:
            return 0
    else:
        memcpy(yp, y, sizeof(yp))
        for j in range(_NS):
            yj = y[j]
            # relative to the state, but not below its scale (atol = 1e-3 rtol scale by
            # default): a state passing through zero (a beam's mode amplitude at rest) would
            # otherwise get an increment at which rounding in f swamps the difference
            d = fmax(6.055454452393343e-06 * fmax(fmax(fabs(yj), ymag[j]), 1e3 * run.atol[j] / run.rtol),
                     fabs(h * f0[j]))
            if d == 0.0:
                d = 6.055454452393343e-06
            yp[j] = yj + d
            d = yp[j] - yj      # the increment actually represented
            rhs(t, yp, fp, ctx)
            yp[j] = yj - d
            rhs(t, yp, fm, ctx)
            for i in range(_NS):
                J[i * _NS + j] = (fp[i] - fm[i]) / (2.0 * d)
            yp[j] = yj
        calls = 2 * _NS
    if ft == NULL:
        return calls     # an implicit Runge-Kutta method needs no df/dt
    # the cam inputs make f depend on t; the increment scales with the interval when t ~ 0.
    # (Only where df/dt is not derived: a kink of f in t near the trajectory, a unilateral
    # contact, spoils this quotient and with it the method's order.)
    dt = 6.055454452393343e-06 * fmax(fabs(t), span)
    dt = (t + dt) - t
    rhs(t + dt, y, fp, ctx)
    rhs(t - dt, y, fm, ctx)
    for i in range(_NS):
        ft[i] = (fp[i] - fm[i]) / (2.0 * dt)
    return calls + 2


cdef int _loop_rodas(Run* run, double a, double b) noexcept nogil:
    """RODAS4 over [a, b]: one fresh Jacobian per accepted point (kept through rejections),
    one LU per attempted step, the DP54 loop's breakpoint, event and failure handling."""
    cdef Ctx local_ctx = run.ctx[0]
    cdef Ctx* ctx = &local_ctx
    cdef int i, hit, status = STATUS_OK
    cdef double y[_NS]
    cdef double f0[_NS]
    cdef double ft[_NS]
    cdef double u1[_NS]
    cdef double u2[_NS]
    cdef double u3[_NS]
    cdef double u4[_NS]
    cdef double u5[_NS]
    cdef double u6[_NS]
    cdef double ys[_NS]
    cdef double yn[_NS]
    cdef double fn[_NS]
    cdef double ymag[_NS]   # largest |y_j| of the interval so far: the Jacobian's increments
    cdef int piv[_NS]
    cdef double g0[_NE1]
    cdef double g1[_NE1]
    cdef double t = a, tn, h, hinv, err, fac, s_hit, rtol = run.rtol
    cdef const double* atol = run.atol
    cdef long n_steps = run.n_steps, n_rej = run.n_rejected, n_rhs = 0, max_steps = run.max_steps
    cdef bint last, rejected = False, have_jac = False
    cdef long n_acc = 0         # steps recorded since the interval's start or the last event
    # heap, not stack: _NS^2 grows fast for models built from user files
    cdef double* J = <double*> malloc(2 * _NS * _NS * sizeof(double))
    cdef double* W
    if J == NULL:
        return STATUS_NO_MEMORY
    W = J + _NS * _NS
    memcpy(y, run.y, sizeof(y))
    for i in range(_NS):
        ymag[i] = fabs(y[i])
    # slopes jump at a breakpoint: every interval starts afresh
    rhs(t, y, f0, ctx)
    n_rhs += 1
    if _rec_point(run, t, y, f0) != 0:
        free(J)
        return _rec_failure(y, f0)
    if _NE > 0:
        events(t, y, g0, ctx)
    if run.h <= 0.0:
        run.h = _dp_first_step(run, t, y, f0, fmin(b - a, run.h_max), 5.0)
    h = fmin(run.h, run.h_max)
    while t < b:
        if n_steps + n_rej >= max_steps:
            status = STATUS_MAX_STEPS
            break
        if h < 16.0 * 2.220446049250313e-16 * fabs(t):   # where t + h no longer moves t
            status = STATUS_STEP_UNDERFLOW
            break
        last = t + 1.01 * h >= b
        if last:
            h = b - t
        # one time for the last stages and the new point (the model caches cam values by t)
        tn = b if last else t + h
        if not have_jac:
            n_rhs += _jacobian(run, ctx, t, y, f0, b - a, ymag, h, J, ft)
            run.n_jac += 1
            have_jac = True
        hinv = 1.0 / h
        for i in range(_NS * _NS):
            W[i] = -J[i]
        for i in range(_NS):
            W[i * _NS + i] += hinv / RO4_GAMMA
        run.n_lu += 1
        if lu_factor(_NS, W, piv) != 0:
            # 1/(h gamma) is an eigenvalue of J: any other step avoids it
            h *= 0.5
            n_rej += 1
            rejected = True
            continue
        for i in range(_NS):
            u1[i] = f0[i] + h * RO4_D1 * ft[i]
        lu_solve(_NS, W, piv, u1)
        for i in range(_NS):
            ys[i] = y[i] + RO4_A21 * u1[i]
        rhs(t + RO4_C2 * h, ys, fn, ctx)
        for i in range(_NS):
            u2[i] = fn[i] + hinv * RO4_C21 * u1[i] + h * RO4_D2 * ft[i]
        lu_solve(_NS, W, piv, u2)
        for i in range(_NS):
            ys[i] = y[i] + RO4_A31 * u1[i] + RO4_A32 * u2[i]
        rhs(t + RO4_C3 * h, ys, fn, ctx)
        for i in range(_NS):
            u3[i] = fn[i] + hinv * (RO4_C31 * u1[i] + RO4_C32 * u2[i]) + h * RO4_D3 * ft[i]
        lu_solve(_NS, W, piv, u3)
        for i in range(_NS):
            ys[i] = y[i] + RO4_A41 * u1[i] + RO4_A42 * u2[i] + RO4_A43 * u3[i]
        rhs(t + RO4_C4 * h, ys, fn, ctx)
        for i in range(_NS):
            u4[i] = (fn[i] + hinv * (RO4_C41 * u1[i] + RO4_C42 * u2[i] + RO4_C43 * u3[i])
                     + h * RO4_D4 * ft[i])
        lu_solve(_NS, W, piv, u4)
        for i in range(_NS):
            ys[i] = y[i] + RO4_A51 * u1[i] + RO4_A52 * u2[i] + RO4_A53 * u3[i] + RO4_A54 * u4[i]
        rhs(tn, ys, fn, ctx)
        for i in range(_NS):
            u5[i] = fn[i] + hinv * (RO4_C51 * u1[i] + RO4_C52 * u2[i] + RO4_C53 * u3[i]
                                    + RO4_C54 * u4[i])
        lu_solve(_NS, W, piv, u5)
        for i in range(_NS):
            ys[i] += u5[i]      # the embedded third-order solution
        rhs(tn, ys, fn, ctx)
        for i in range(_NS):
            u6[i] = fn[i] + hinv * (RO4_C61 * u1[i] + RO4_C62 * u2[i] + RO4_C63 * u3[i]
                                    + RO4_C64 * u4[i] + RO4_C65 * u5[i])
        lu_solve(_NS, W, piv, u6)
        for i in range(_NS):
            yn[i] = ys[i] + u6[i]
        n_rhs += 5
        err = _rms(u6, y, yn, rtol, atol)
        if not isfinite(err):
            # a NaN in a trial stage: retry smaller unless the start itself is bad
            if not _finite(_NS, y):
                status = STATUS_NOT_FINITE
                break
            h *= 0.2
            n_rej += 1
            rejected = True
            continue
        if err <= 1.0:
            # standard controller for the embedded order 3 (err ~ h^4), limits as in RODAS
            # err^(-1/4) as two square roots: a pow a step cost RODAS4 a tenth of its step
            fac = 6.0 if err == 0.0 else fmin(6.0, fmax(0.2, 0.9 / sqrt(sqrt(err))))
            if rejected:
                fac = fmin(fac, 1.0)
            rhs(tn, yn, fn, ctx)   # slope at the new point: recorded, and the next step's f0
            n_rhs += 1
            n_steps += 1
            have_jac = False
            if _NE > 0:
                hit = _event_in_step(run, t, h, y, yn, f0, fn, NULL, 0, g0, g1, &s_hit)
                if hit >= 0:
                    # cut the step at the crossing: state from the step's cubic Hermite extension
                    _dense(s_hit, h, y, yn, f0, fn, NULL, 0, ys)
                    t = t + s_hit * h
                    memcpy(y, ys, sizeof(y))
                    rhs(t, y, f0, ctx)
                    n_rhs += 1
                    status = _apply_event(run, hit, t, y, f0, g0)
                    if status != STATUS_OK:
                        break
                    # the event refreshed run.ctx (the rhs variant of the new cam segments)
                    local_ctx = run.ctx[0]
                    rejected = False
                    n_acc = 0
                    continue
                memcpy(g0, g1, sizeof(g0))
            t = tn
            memcpy(y, yn, sizeof(y))
            memcpy(f0, fn, sizeof(f0))
            status = _project_accepted(ctx, t, y, f0, g0, &n_rhs)
            if status != STATUS_OK:
                break
            for i in range(_NS):
                ymag[i] = fmax(ymag[i], fabs(y[i]))
            if _rec_point(run, t, y, f0) != 0:
                status = _rec_failure(y, f0)
                break
            n_acc += 1
            if n_acc >= 2:
                _rec_three_point(run)
            if not last:
                run.h = h
            h = fmin(h * fac, run.h_max)
            rejected = False
        else:
            h *= fmax(0.2, 0.9 / sqrt(sqrt(err)))
            n_rej += 1
            rejected = True
    free(J)
    memcpy(run.y, y, sizeof(y))
    run.n_steps = n_steps
    run.n_rejected = n_rej
    run.n_rhs += n_rhs
    if status != STATUS_OK:
        run.t_fail = t
    return status


# -- RADAU5: Radau IIA of order 5 (Hairer & Wanner II, sec. IV.8) -----------------------
#
# The three-stage collocation method at the right Radau points c = (4 - sqrt 6)/10,
# (4 + sqrt 6)/10, 1, as in Hairer & Wanner's code RADAU5 (Solving ODEs II, sec. IV.8).  The
# stage increments Z = (z1, z2, z3), z_i = Y_i - y, solve Z = h (A x I) F(Z); the simplified
# Newton iteration transforms them with T (TI = T^-1) to W = (TI x I) Z, which turns A^-1
# into diag(gamma, [[alpha, -beta], [beta, alpha]]) and the iteration matrix into one real
# system (gamma/h - J) and one complex one ((alpha + i beta)/h - J) (w2 + i w3) = r2 + i r3,
# each factored by an LU of linalg.pxd (the complex one in complex arithmetic, its real and
# imaginary parts apart: half the flops of the equivalent real system of size 2n, and half its
# rows to sweep in every solve), the factors kept while h and the Jacobian stay.  The error
# estimate is RADAU5's (sec. IV.8, "Error estimation"): (gamma/h - J)^-1
# (f(y) + (e1 z1 + e2 z2 + e3 z3)/h), one more solve with the real factors, and after a
# rejected or a first step that once more with f at y + err, which removes the estimate's
# O(1) error on very stiff components.  The constants: radau.pxd.

cdef int _radau_matrices(const double* J, double h, double* E1, int* piv1, double* E2r,
                         double* E2i, int* piv2) noexcept nogil:
    """Factor gamma/h - J (E1) and (alpha + i beta)/h - J (E2r + i E2i), both n x n; nonzero
    when one is singular."""
    cdef int i
    cdef double g = RA_GAMMA / h, al = RA_ALPHA / h, be = RA_BETA / h
    memset(E2i, 0, _NS * _NS * sizeof(double))
    for i in range(_NS * _NS):
        E1[i] = -J[i]
        E2r[i] = -J[i]
    for i in range(_NS):
        E1[i * _NS + i] += g
        E2r[i * _NS + i] += al
        E2i[i * _NS + i] = be
    if lu_factor(_NS, E1, piv1) != 0:
        return 1
    return clu_factor(_NS, E2r, E2i, piv2)


cdef int _loop_radau(Run* run, double a, double b) noexcept nogil:
    """RADAU5 over [a, b]: simplified Newton iterations with a Jacobian kept while they converge
    fast and LU factors kept while h stays, Gustafsson's predictive step control, the DP54
    loop's breakpoint, event and failure handling (the rules and constants of Hairer's
    RADAU5, subroutine RADCOR)."""
    cdef Ctx local_ctx = run.ctx[0]
    cdef Ctx* ctx = &local_ctx
    cdef int i, hit, newt, status = STATUS_OK
    cdef double y[_NS]
    cdef double f0[_NS]
    cdef double z1[_NS]
    cdef double z2[_NS]
    cdef double z3[_NS]
    cdef double w1[_NS]
    cdef double w2[_NS]
    cdef double w3[_NS]
    cdef double k1[_NS]
    cdef double k2[_NS]
    cdef double k3[_NS]
    cdef double r2[_NS]     # the complex system's right-hand side r2 + i r3, then its solution
    cdef double r3[_NS]
    cdef double ak1[_NS]     # the last step's collocation polynomial (RADAU5's CONT), for the
    cdef double ak2[_NS]     # Newton iteration's starting values
    cdef double ak3[_NS]
    cdef double ys[_NS]
    cdef double yn[_NS]
    cdef double fn[_NS]
    cdef double ev[_NS]
    cdef double wt[_NS]     # 1/(atol + rtol |y|): the Newton iteration's error weights
    cdef double ymag[_NS]   # largest |y_j| of the interval so far: the Jacobian's increments
    cdef int piv1[_NS]
    cdef int piv2[_NS]
    cdef double g0[_NE1]
    cdef double g1[_NE1]
    cdef double t = a, tn, h, h_lu = 0.0, hold = 0.0, hnew, hacc = 0.0, erracc = 0.0
    cdef double err, fac, quot, facgus, s_hit, rtol = run.rtol
    cdef double theta, thq, thqold = 0.0, dyno, dynold = 0.0, dyth, faccon = 1.0, x
    # log(faccon): RADAU5 raises faccon to the power 0.8 every step (towards 1, so that a
    # fast contraction measured long ago stops vouching for a one-sweep convergence); in
    # logarithms that is a product, and one exp a step replaces a pow
    cdef double lfac = 0.0
    cdef double hinv, gh, ah, bh
    cdef double c1q, c2q, c3q, a1, a2, a3
    cdef const double* atol = run.atol
    cdef long n_steps = run.n_steps, n_rej = run.n_rejected, n_rhs = 0, max_steps = run.max_steps
    cdef long n_acc = 0         # steps accepted since the interval's start or the last event
    cdef bint last, rejected = False, first = True, need_jac = True, fresh_jac = False
    cdef bint have_cont = False, converged, slow
    # Hairer's `thet`: the Jacobian is kept after a step whose Newton iteration contracted by
    # at least this much a sweep.  0.001, RADAU5's default for small systems, where the
    # Jacobian is generated (a few products); 0.1, the value RADAU5's notes give for costly
    # ones, where it is differenced (2 n_states right-hand-side calls)
    cdef double thet = 0.001 if _JAC_SYMBOLIC else 0.1
    # Newton's tolerance in units of the error weights (SciPy's Radau and RADAU5: at most 0.03)
    cdef double fnewt = fmax(10.0 * 2.220446049250313e-16 / rtol, fmin(0.03, sqrt(rtol)))
    cdef double cfac = RA_SAFE * (1 + 2 * RA_NIT)
    # heap, not stack: _NS^2 grows fast for models built from user files
    cdef double* J = <double*> malloc(4 * _NS * _NS * sizeof(double))
    cdef double* E1
    cdef double* E2r
    cdef double* E2i
    if J == NULL:
        return STATUS_NO_MEMORY
    E1 = J + _NS * _NS
    E2r = E1 + _NS * _NS
    E2i = E2r + _NS * _NS
    memcpy(y, run.y, sizeof(y))
    for i in range(_NS):
        ymag[i] = fabs(y[i])
    # slopes jump at a breakpoint: every interval starts afresh
    rhs(t, y, f0, ctx)
    n_rhs += 1
    if _rec_point(run, t, y, f0) != 0:
        free(J)
        return _rec_failure(y, f0)
    if _NE > 0:
        events(t, y, g0, ctx)
    if run.h <= 0.0:
        run.h = _dp_first_step(run, t, y, f0, fmin(b - a, run.h_max), 5.0)
    h = fmin(run.h, run.h_max)
    while t < b:
        if n_steps + n_rej >= max_steps:
            status = STATUS_MAX_STEPS
            break
        if h < 16.0 * 2.220446049250313e-16 * fabs(t):   # where t + h no longer moves t
            status = STATUS_STEP_UNDERFLOW
            break
        last = t + 1.01 * h >= b
        if last:
            h = b - t
        # one time for the last stage and the new point (the model caches cam values by t)
        tn = b if last else t + h
        if need_jac:
            n_rhs += _jacobian(run, ctx, t, y, f0, b - a, ymag, h, J, NULL)
            run.n_jac += 1
            need_jac = False
            fresh_jac = True
            h_lu = 0.0
        if h != h_lu:
            run.n_lu += 1
            if _radau_matrices(J, h, E1, piv1, E2r, E2i, piv2) != 0:
                # gamma/h or (alpha + i beta)/h is an eigenvalue of J: any other step avoids it
                h *= 0.5
                n_rej += 1
                rejected = True
                continue
            h_lu = h
        for i in range(_NS):
            wt[i] = 1.0 / (atol[i] + rtol * fabs(y[i]))
        # starting values: the last step's collocation polynomial extrapolated to the stages
        if have_cont:
            c3q = h / hold
            c1q = RA_C1 * c3q
            c2q = RA_C2 * c3q
            for i in range(_NS):
                z1[i] = c1q * (ak1[i] + (c1q - RA_C2M1) * (ak2[i] + (c1q - RA_C1M1) * ak3[i]))
                z2[i] = c2q * (ak1[i] + (c2q - RA_C2M1) * (ak2[i] + (c2q - RA_C1M1) * ak3[i]))
                z3[i] = c3q * (ak1[i] + (c3q - RA_C2M1) * (ak2[i] + (c3q - RA_C1M1) * ak3[i]))
                w1[i] = RA_TI11 * z1[i] + RA_TI12 * z2[i] + RA_TI13 * z3[i]
                w2[i] = RA_TI21 * z1[i] + RA_TI22 * z2[i] + RA_TI23 * z3[i]
                w3[i] = RA_TI31 * z1[i] + RA_TI32 * z2[i] + RA_TI33 * z3[i]
        else:
            memset(z1, 0, sizeof(z1))
            memset(z2, 0, sizeof(z2))
            memset(z3, 0, sizeof(z3))
            memset(w1, 0, sizeof(w1))
            memset(w2, 0, sizeof(w2))
            memset(w3, 0, sizeof(w3))
        # the simplified Newton iteration (RADAU5's loop 40): theta, its contraction rate,
        # predicts whether it converges within RA_NIT sweeps; if not, a smaller step at once
        lfac = 0.8 * fmax(lfac, -36.04365338911715)     # log(2.220446049250313e-16)
        faccon = exp(lfac)
        hinv = 1.0 / h
        gh = RA_GAMMA * hinv
        ah = RA_ALPHA * hinv
        bh = RA_BETA * hinv
        theta = thet
        newt = 0
        converged = False
        slow = False
        while newt < RA_NIT:
            for i in range(_NS):
                ys[i] = y[i] + z1[i]
            rhs(t + RA_C1 * h, ys, k1, ctx)
            for i in range(_NS):
                ys[i] = y[i] + z2[i]
            rhs(t + RA_C2 * h, ys, k2, ctx)
            for i in range(_NS):
                ys[i] = y[i] + z3[i]
            rhs(tn, ys, k3, ctx)
            n_rhs += 3
            for i in range(_NS):
                a1 = RA_TI11 * k1[i] + RA_TI12 * k2[i] + RA_TI13 * k3[i]
                a2 = RA_TI21 * k1[i] + RA_TI22 * k2[i] + RA_TI23 * k3[i]
                a3 = RA_TI31 * k1[i] + RA_TI32 * k2[i] + RA_TI33 * k3[i]
                k1[i] = a1 - gh * w1[i]
                r2[i] = a2 - (ah * w2[i] - bh * w3[i])
                r3[i] = a3 - (ah * w3[i] + bh * w2[i])
            lu_solve(_NS, E1, piv1, k1)
            clu_solve(_NS, E2r, E2i, piv2, r2, r3)
            newt += 1
            dyno = 0.0
            for i in range(_NS):
                x = k1[i] * wt[i]
                dyno += x * x
                x = r2[i] * wt[i]
                dyno += x * x
                x = r3[i] * wt[i]
                dyno += x * x
            dyno = sqrt(dyno / (3 * _NS))
            if not isfinite(dyno):
                break
            if newt > 1 and newt < RA_NIT:
                thq = dyno / dynold
                theta = thq if newt == 2 else sqrt(thq * thqold)
                thqold = thq
                if theta >= 0.99:
                    break
                faccon = theta / (1.0 - theta)
                lfac = log(faccon)
                dyth = faccon * dyno / fnewt
                for i in range(RA_NIT - 1 - newt):
                    dyth *= theta
                if dyth >= 1.0:
                    # would not converge in the sweeps left: a step it converges on
                    h *= 0.8 * pow(fmax(1e-4, fmin(20.0, dyth)), -1.0 / (4 + RA_NIT - 1 - newt))
                    slow = True
                    break
            dynold = fmax(dyno, 2.220446049250313e-16)
            for i in range(_NS):
                w1[i] += k1[i]
                w2[i] += r2[i]
                w3[i] += r3[i]
                z1[i] = RA_T11 * w1[i] + RA_T12 * w2[i] + RA_T13 * w3[i]
                z2[i] = RA_T21 * w1[i] + RA_T22 * w2[i] + RA_T23 * w3[i]
                z3[i] = RA_T31 * w1[i] + w2[i]
            if faccon * dyno <= fnewt:
                converged = True
                break
        err = 0.0
        if converged:
            # the error estimate (8.19), refined by (8.20) after a first or rejected step
            for i in range(_NS):
                k2[i] = (RA_DD1 * z1[i] + RA_DD2 * z2[i] + RA_DD3 * z3[i]) * hinv
                ev[i] = k2[i] + f0[i]
            lu_solve(_NS, E1, piv1, ev)
            for i in range(_NS):
                yn[i] = y[i] + z3[i]
            # not fmax, which would turn a NaN into 1e-10, an accepted step
            err = _rms(ev, y, yn, rtol, atol)
            if err < 1e-10:
                err = 1e-10
            if err >= 1.0 and (first or rejected):
                for i in range(_NS):
                    ys[i] = y[i] + ev[i]
                rhs(t, ys, k1, ctx)
                n_rhs += 1
                for i in range(_NS):
                    ev[i] = k1[i] + k2[i]
                lu_solve(_NS, E1, piv1, ev)
                err = _rms(ev, y, yn, rtol, atol)
                if err < 1e-10:
                    err = 1e-10
            converged = isfinite(err)
        if not converged:
            if not _finite(_NS, y):
                status = STATUS_NOT_FINITE
                break
            # diverging, too slow or a NaN in a stage: RADAU5's unexpected rejection, a new
            # Jacobian unless this one is fresh
            if not slow:
                h *= 0.5
            n_rej += 1
            rejected = True
            if not fresh_jac:
                need_jac = True
            continue
        fac = fmin(RA_SAFE, cfac / (newt + 2 * RA_NIT))
        quot = fmax(RA_FACR, fmin(RA_FACL, sqrt(sqrt(err)) / fac))
        hnew = h / quot
        if err < 1.0:
            first = False
            if n_acc > 0:
                # Gustafsson's predictive controller (RADAU5's PRED)
                facgus = (hacc / h) * sqrt(sqrt(err * err / erracc)) / RA_SAFE
                quot = fmax(quot, fmax(RA_FACR, fmin(RA_FACL, facgus)))
                hnew = h / quot
            hacc = h
            erracc = fmax(1e-2, err)
            n_acc += 1
            n_steps += 1
            rhs(tn, yn, fn, ctx)   # slope at the new point: recorded, and the next step's f0
            n_rhs += 1
            # the collocation polynomial of the step, for the next step's starting values
            for i in range(_NS):
                ak1[i] = (z2[i] - z3[i]) * RA_IC2M1
                x = (z1[i] - z2[i]) * RA_IC1MC2
                ak2[i] = (x - ak1[i]) * RA_IC1M1
                ak3[i] = ak2[i] - (x - z1[i] * RA_IC1) * RA_IC2
            if _NE > 0:
                hit = _event_in_step(run, t, h, y, yn, f0, fn, NULL, 0, g0, g1, &s_hit)
                if hit >= 0:
                    # cut the step at the crossing: state from the step's cubic Hermite extension
                    _dense(s_hit, h, y, yn, f0, fn, NULL, 0, ys)
                    t = t + s_hit * h
                    memcpy(y, ys, sizeof(y))
                    rhs(t, y, f0, ctx)
                    n_rhs += 1
                    status = _apply_event(run, hit, t, y, f0, g0)
                    if status != STATUS_OK:
                        break
                    # the event refreshed run.ctx (the rhs variant of the new cam segments):
                    # a new Jacobian, and nothing to extrapolate from
                    local_ctx = run.ctx[0]
                    rejected = False
                    first = True
                    need_jac = True
                    have_cont = False
                    n_acc = 0
                    continue
                memcpy(g0, g1, sizeof(g0))
            hold = h
            have_cont = True
            t = tn
            memcpy(y, yn, sizeof(y))
            memcpy(f0, fn, sizeof(f0))
            for i in range(_NS):
                ymag[i] = fmax(ymag[i], fabs(y[i]))
            if _rec_point(run, t, y, f0) != 0:
                status = _rec_failure(y, f0)
                break
            if n_acc >= 2:
                _rec_three_point(run)
            if not last:
                run.h = h
            hnew = fmin(hnew, run.h_max)
            if rejected:
                hnew = fmin(hnew, h)
            rejected = False
            fresh_jac = False
            # keep h, and with it the LU factors, when the Newton iteration converged fast and
            # the new step would be at most 20 % longer (RADAU5's QUOT1, QUOT2)
            if not (theta <= thet and RA_QUOT1 <= hnew / h <= RA_QUOT2):
                h = hnew
            if theta > thet:
                need_jac = True
        else:
            n_rej += 1
            if first:
                h *= 0.1
            else:
                h = hnew
            rejected = True
            if not fresh_jac:
                need_jac = True
    free(J)
    memcpy(run.y, y, sizeof(y))
    run.n_steps = n_steps
    run.n_rejected = n_rej
    run.n_rhs += n_rhs
    if status != STATUS_OK:
        run.t_fail = t
    return status


# -- exact steps over a linear, time-invariant interval -----------------------------------
#
# Where the model is linear and time invariant, y' = A y + c with A and c constant (every cam
# input in a dwell, nothing that switches: derive/codegen.py, _linear_in_dwell, decides it from
# the symbolic right-hand side, _lti_now at run time), the solution is known in closed form,
#
#     y(t + h) = Phi y(t) + Gam,   Phi = e^(A h),   Gam = int_0^h e^(A s) ds c,
#
# both read off the exponential of the augmented matrix h [[A, c], [0, 0]] (Van Loan's
# block form), computed once an interval by scaling and squaring a Taylor series.  The
# interval is then recorded at equal steps, each one matrix-vector product, exact to
# rounding whatever the step: no discretisation error, no stability limit, no stages.  The
# steps are those RK4 would take (the recorded grid the user asked for), or, for the
# adaptive methods, as long as the dense output between the points allows at rtol.  The
# extras of a step (dense.pxd) are fitted to the exact state at its interior nodes
# s_j = j/(n_extra + 1), whose propagators are powers of the first one.  On a mode of
# frequency w the interpolant then errs by (h w)^p/p! times max |s^2 (1 - s)^2 prod (s - s_j)|
# of the amplitude, p = 4 + n_extra: (h w)^4/384 for the cubic Hermite one (RODAS4), about
# (h w)^5/1.3e4 for DP54's quartic, (h w)^8/4.7e8 for DOP853's degree 7, (h w)^12/9.4e14 for
# RKN12's degree 11 (rounded down to 10^4, 10^8 and 10^14 below).

cdef void _matmul(int m, const double* A, const double* B, double* C) noexcept nogil:
    cdef int i, j, k
    cdef double s
    for i in range(m):
        for j in range(m):
            s = 0.0
            for k in range(m):
                s += A[i * m + k] * B[k * m + j]
            C[i * m + j] = s


cdef inline void _affine(const double* M, const double* x, const double* v,
                         double* out) noexcept nogil:
    """out = M x + v (M _NS x _NS, row-major)."""
    cdef int i, j
    cdef double s
    for i in range(_NS):
        s = v[i]
        for j in range(_NS):
            s += M[i * _NS + j] * x[j]
        out[i] = s


cdef int _expm_affine(const double* A, const double* c, double h, double* Phi,
                      double* Gam) noexcept nogil:
    """Phi = e^(A h) and Gam = int_0^h e^(A s) ds c from e^Z, Z = h [[A, c], [0, 0]]; -1 when
    out of memory or not finite."""
    cdef int m = _NS + 1, i, j, k, squarings = 0
    cdef double norm = 0.0, col, term, total
    cdef double* Z = <double*> malloc(4 * m * m * sizeof(double))
    cdef double* T
    cdef double* S
    cdef double* W
    if Z == NULL:
        return -1
    T, S, W = Z + m * m, Z + 2 * m * m, Z + 3 * m * m
    memset(Z, 0, m * m * sizeof(double))
    for i in range(_NS):
        for j in range(_NS):
            Z[i * m + j] = h * A[i * _NS + j]
        Z[i * m + _NS] = h * c[i]
    for j in range(m):
        col = 0.0
        for i in range(m):
            col += fabs(Z[i * m + j])
        norm = fmax(norm, col)
    if not isfinite(norm):
        free(Z)
        return -1
    # scaled to norm <= 1/2, the Taylor series' terms fall below rounding within 20
    while norm > 0.5:
        norm *= 0.5
        squarings += 1
    term = pow(0.5, squarings)
    for i in range(m * m):
        Z[i] *= term
    memset(S, 0, m * m * sizeof(double))
    for i in range(m):
        S[i * m + i] = 1.0
    memcpy(T, S, m * m * sizeof(double))
    for k in range(1, 30):
        _matmul(m, T, Z, W)
        term = 0.0
        total = 0.0
        for i in range(m * m):
            T[i] = W[i] / k
            S[i] += T[i]
            term = fmax(term, fabs(T[i]))
            total = fmax(total, fabs(S[i]))
        if term <= 1e-18 * total:
            break
    for k in range(squarings):
        _matmul(m, S, S, W)
        memcpy(S, W, m * m * sizeof(double))
    for i in range(_NS):
        for j in range(_NS):
            Phi[i * _NS + j] = S[i * m + j]
        Gam[i] = S[i * m + _NS]
    free(Z)
    return 0


cdef double _lti_rate(const double* A) noexcept nogil:
    """An upper bound of |lambda| for every eigenvalue of A: Gershgorin's on D^-1 A D, D = 1 on
    q and z, sigma on q' (sigma^2 the largest row sum of |dq''/dq|), which for a mechanism's
    [[0, I], [-K, -C]] comes within a small factor of its largest frequency."""
    cdef int i, j
    cdef double sigma = _velocity_scale(A), row, bound = 0.0, d_i, d_j
    for i in range(_NS):
        d_i = sigma if _NQ <= i < 2 * _NQ else 1.0
        row = 0.0
        for j in range(_NS):
            d_j = sigma if _NQ <= j < 2 * _NQ else 1.0
            row += fabs(A[i * _NS + j]) * d_j / d_i
        bound = fmax(bound, row)
    return bound


cdef inline double* _gam(double* L, int nx) noexcept nogil:
    """Gam of a rung's first propagator pair: a rung's block holds (Phi, Gam) to s_j H,
    j = 1 .. nx + 1, the nx + 1 Phi first, then the Gam, then the extras' affine map X
    (nx _NS x _NS) and x0 (nx _NS): (2 nx + 1)(_NS^2 + _NS) doubles."""
    return L + (nx + 1) * _NS * _NS


cdef void _exact_level(int nx, const double* W, double H, const double* A, const double* c,
                       double* L) noexcept nogil:
    """Complete a rung's block L (_gam) whose first propagator pair (to H/(nx + 1)) is in
    place: its powers to the other nodes and the step's end, and the extras of a step of
    length H as an affine map of the step's starting state."""
    cdef double* P = L
    cdef double* G = L + (nx + 1) * _NS * _NS
    cdef double* X = G + (nx + 1) * _NS
    cdef double* x0 = X + nx * _NS * _NS
    cdef double ys[_NS]
    cdef double yn[_NS]
    cdef double fs[_NS]
    cdef double fn[_NS]
    cdef double vals[8 * _NS]
    cdef double ex[8 * _NS]
    cdef int i, j
    for j in range(1, nx + 1):
        _matmul(_NS, P, P + (j - 1) * _NS * _NS, P + j * _NS * _NS)
        _affine(P, G + (j - 1) * _NS, G, G + j * _NS)
    if nx == 0:
        return
    # every input of fit_extras is affine in the step's starting state, so are the extras:
    # X y + x0, fitted once from the zero state and the unit states
    for i in range(_NS + 1):
        memset(ys, 0, sizeof(ys))
        if i < _NS:
            ys[i] = 1.0
        _affine(P + nx * _NS * _NS, ys, G + nx * _NS, yn)
        _affine(A, ys, c, fs)
        _affine(A, yn, c, fn)
        for j in range(nx):
            _affine(P + j * _NS * _NS, ys, G + j * _NS, vals + j * _NS)
        fit_extras(nx, _NS, W, H, ys, yn, fs, fn, vals, x0 if i == _NS else ex)
        if i < _NS:
            for j in range(nx * _NS):
                X[j * _NS + i] = ex[j]
    for i in range(_NS):
        for j in range(nx * _NS):
            X[j * _NS + i] -= x0[j]


cdef int _loop_exact(Run* run, double a, double b) noexcept nogil:
    """[a, b] in exact steps, the model being linear and time invariant there (see above).

    A fixed-step method's record takes its steps.  An adaptive method's record takes steps on
    a dyadic ladder H_k = h0 2^k, h0 = (b - a)/2^K within the bound that the highest rate of
    A sets for the interpolant (see above), and climbs it as the content fades: every step
    compares its interpolant with the exact state at s = 1/(2 (n_extra + 1)) (the first node
    of the level below, where the interpolant's error is near its largest), in the step
    control's norm; a step whose error exceeds the tolerance is taken again one rung lower
    (the lowest one always holds), and the next step is as many rungs higher as keep 2^p times
    the error a rung within half of it (p = 4 + n_extra, the interpolant's order) with the
    position on that rung's grid.  A damped fast mode (a stiff contact) then sets the
    record's density only while it rings.  With run.exact_whole the interval is one step."""
    cdef Ctx* ctx = run.ctx
    cdef Record* r = &run.rec
    cdef int nx = r.n_extra, i, j, k = 0, K = 0, kmax, status = STATUS_OK
    cdef char ready[64]
    cdef bint whole = run.exact_whole
    cdef bint adaptive = adaptive_method(run.method) and not whole
    cdef double t = a, h, h0, H, rate, err = 0.0, grow, v
    cdef double y[_NS]
    cdef double yn[_NS]
    cdef double f[_NS]
    cdef double fn[_NS]
    cdef double c[_NS]
    cdef double yt[_NS]
    cdef double yi[_NS]
    cdef double ex[8 * _NS]
    cdef double W[64]
    cdef double* A
    # block 0 the root, the propagator pair to h0/(2 (nx + 1)) (rung 0's test pair), block
    # k + 1 rung k, whose first pair is the square of the block below's (its test pair)
    cdef double* blocks
    cdef double* L
    cdef double* T
    cdef double* row
    cdef long size = (2 * nx + 1) * (_NS * _NS + _NS), idx = 0, n0, stride, done = 0
    if fit_matrix(nx, W) != 0:
        return STATUS_BAD_MODEL
    A = <double*> malloc(_NS * _NS * sizeof(double))
    if A == NULL:
        return STATUS_NO_MEMORY
    memcpy(y, run.y, sizeof(y))
    rhs(t, y, f, ctx)
    jacobian(t, y, A, NULL, ctx)
    run.n_rhs += 1
    for i in range(_NS):
        c[i] = f[i]
        for j in range(_NS):
            c[i] -= A[i * _NS + j] * y[j]
    if not _finite(_NS, f):
        run.t_fail = t
        free(A)
        return STATUS_NOT_FINITE
    if adaptive:
        rate = _lti_rate(A)
        h = (pow(1e14 * fmax(run.rtol, 1e-14), 1.0 / 12.0) if nx == 8 else
             pow(1e8 * fmax(run.rtol, 1e-14), 0.125) if nx == 4 else
             pow(1e4 * fmax(run.rtol, 1e-14), 0.2) if nx == 1 else
             pow(384.0 * fmax(run.rtol, 1e-14), 0.25))
        h = h / rate if rate > 0.0 else b - a
        if run.h_max > 0.0:
            h = fmin(h, run.h_max)
        while K < 40 and (b - a) / (<double> (1L << K)) > h:
            K += 1
        n0 = 1L << K
        kmax = K
        while run.h_max > 0.0 and kmax > 0 and (b - a) / (<double> (1L << (K - kmax))) > run.h_max:
            kmax -= 1
    else:
        n0 = 1 if whole or run.h >= b - a else fixed_steps(a, b, run.h)
        kmax = 0
        if run.n_steps + n0 > run.max_steps:
            run.t_fail = t
            free(A)
            return STATUS_MAX_STEPS
    h0 = (b - a) / n0
    blocks = <double*> malloc((kmax + 2) * size * sizeof(double))
    if blocks == NULL:
        free(A)
        return STATUS_NO_MEMORY
    if _expm_affine(A, c, 0.5 * h0 / (nx + 1), blocks, _gam(blocks, nx)) != 0:
        run.t_fail = t
        free(A)
        free(blocks)
        return STATUS_NOT_FINITE
    if _rec_point(run, t, y, f) != 0:
        free(A)
        free(blocks)
        return _rec_failure(y, f)
    # every rung's first pair now, a matrix product each; the rest of a rung (_exact_level)
    # only once a step is taken on it
    for k in range(kmax + 1):
        T = blocks + k * size
        L = T + size
        _matmul(_NS, T, T, L)
        _affine(T, _gam(T, nx), _gam(T, nx), _gam(L, nx))
    k = 0
    memset(ready, 0, sizeof(ready))
    while idx < n0:
        T = blocks + k * size          # the test pair
        L = T + size
        if not ready[k]:
            _exact_level(nx, W, h0 * (1L << k), A, c, L)
            ready[k] = 1
        stride = 1L << k
        H = h0 * stride
        _affine(L + nx * _NS * _NS, y, _gam(L, nx) + nx * _NS, yn)
        _affine(A, yn, c, fn)
        if whole:      # no dense output across the interval: the Hermite part alone
            memset(ex, 0, sizeof(ex))
        elif nx:       # the step's extras, X y + x0
            row = L + (nx + 1) * (_NS * _NS + _NS)
            for j in range(nx * _NS):
                v = row[nx * _NS * _NS + j]
                for i in range(_NS):
                    v += row[j * _NS + i] * y[i]
                ex[j] = v
        if adaptive:
            _affine(T, y, _gam(T, nx), yt)
            _dense(0.5 / (nx + 1), H, y, yn, f, fn, ex, nx, yi)
            for i in range(_NS):
                yi[i] -= yt[i]
            err = _rms(yi, y, yn, run.rtol, run.atol)
            if err > 1.0 and k > 0:
                k -= 1
                continue
        t = a + (idx + stride) * h0 if idx + stride < n0 else b
        if not _finite(_NS, yn):
            run.t_fail = t
            status = STATUS_NOT_FINITE
            break
        if nx:     # the extras of the step from the last recorded point
            memcpy(r.rows + (r.n - 1) * r.width + 1 + 2 * _NS, ex, nx * _NS * sizeof(double))
        memcpy(y, yn, sizeof(y))
        memcpy(f, fn, sizeof(f))
        if _rec_point(run, t, y, f) != 0:
            status = _rec_failure(y, f)
            break
        idx += stride
        done += 1
        if adaptive:
            if run.n_steps + done >= run.max_steps and idx < n0:
                run.t_fail = t
                status = STATUS_MAX_STEPS
                break
            # up as many rungs as the error allows (2^p times more a rung) and the grid admits
            grow = err * (1L << (4 + nx))
            while k < kmax and grow <= 0.5 and idx % (2 * stride) == 0:
                k += 1
                stride *= 2
                grow *= (1L << (4 + nx))
    run.n_steps += done
    memcpy(run.y, y, sizeof(y))
    free(A)
    free(blocks)
    return status


cdef int run_loops(Run* run) noexcept nogil:
    """Integrate from run.t0 through every stop; the record and statistics go into run."""
    cdef int k, status = STATUS_OK
    cdef double a = run.t0, b
    if run.method == METHOD_KOSTER and _NS != 2 * _NQ:
        return STATUS_BAD_MODEL
    run.n_events = 0
    prepare(run.ctx)
    for k in range(run.n_stops):
        b = run.stops[k]
        if b <= a:
            continue
        # segments are decided inside the interval: a stop computed as (b_k - b)/a may round
        # to a hair before the breakpoint, where its start would still see the old segment
        update_modes(0.5 * (a + b), run.y, run.ctx)
        if run.exact and _lti_now(run.ctx):
            status = _loop_exact(run, a, b)
        elif run.method == METHOD_DP54:
            status = _loop_dp54(run, a, b)
        elif run.method == METHOD_DOP853:
            status = _loop_dop853(run, a, b)
        elif run.method == METHOD_RKN12:
            status = _loop_rkn12(run, a, b)
        elif run.method == METHOD_RODAS:
            status = _loop_rodas(run, a, b)
        elif run.method == METHOD_RADAU:
            status = _loop_radau(run, a, b)
        else:
            status = _loop_fixed(run, a, b)
        if status != STATUS_OK:
            return status
        a = b
    return STATUS_OK
