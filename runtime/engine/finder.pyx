# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
"""Headline figures of runs in compiled code: extremes on the dense output, and whole sweeps.

A run's figures (U0 (3.5), U0'' (3.6), the largest deceleration in the rise and its instant,
fig. 4.11) are extremes of a state or an output over part of the run.  They are found here as
runtime/measure/residual.py's reference finds them, without the GIL and without a Python call per
evaluation:

1. a scan: the dense output at ``per_step`` evenly spaced times in every recorded step inside
   [a, b], and b (the knots a, b and the recorded times; a time on a recorded point takes the
   step that ends there, as ``dense_eval`` does);
2. the ``n_cand`` best local maxima of the scanned score (|v|, v or -v), ranked by the vertex of
   the parabola through each and its two neighbours, are refined by Brent's bounded minimizer
   on the dense output between the neighbours; the best of the scan and the refinements wins;
3. the sampling check: any other peak whose parabola, raised by the most a refined peak's
   parabola fell short of its refined value, reaches above that best is refined too (up to
   16 more); what a peak left over could still add is the extreme's sampling error,
   returned beside it (0 when nothing is left).  Every figure so carries the error of the scan that found it.

With per_step = 12 and one candidate this is the reference's recipe (12 samples a step, the
best refined).  A sweep samples fewer (every 3rd recorded point at rtol 1e-9, where DP54 takes
87 steps or more a period of the fastest mode that carries amplitude; runtime/studies/sweep.py's
scan_density) and refines the 4 best peaks by the parabola through each and its neighbours;
where several peaks are equal to within the integration error (the undamped dwell, every
peak of U is U0), any of them is U0 to that error.  Samples on recorded points read a cache
of the outputs there, filled by one evaluation of the model's outputs per point.

``sweep_residual`` runs a chunk of parameter sets through the model's compiled loops and these
finders in one call that holds no GIL: one record buffer reused for every run, no Python object
per run.  Threads can run chunks side by side (runtime/studies/sweep.py).
"""
from cpython.pycapsule cimport PyCapsule_GetPointer, PyCapsule_IsValid
from libc.math cimport NAN, INFINITY, fabs, sqrt
from libc.stdlib cimport free, malloc
from libc.string cimport memcpy
from posix.time cimport CLOCK_MONOTONIC, clock_gettime, timespec

import numpy as np

from camdyn.runtime.engine.abi cimport *
from camdyn.runtime.engine.dense cimport dense_component

cdef enum:
    MAX_CAND = 16
    PEAKS = 160

# the columns sweep_residual fills: the figures, then their sampling errors
FIGURE_COLUMNS = ("U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min", "T_rise_end",
                  "U0_sampling", "U0dd_sampling", "Xdd_min_rise_sampling")
STAT_COLUMNS = ("status", "n_steps", "n_rejected", "n_rhs", "n_points")


cdef struct Rec:
    # a read-only view of one run's record and what evaluating its outputs needs
    ModelC* m
    Ctx* ctx
    const double* rows
    const int* modes
    Py_ssize_t n
    int ns
    int nm
    int width
    int nx             # dense-output extras per row (dense.pxd)
    double* y          # ns scratch doubles
    double* out        # n_outputs scratch doubles


cdef ModelC* _model(object capsule) except NULL:
    if not PyCapsule_IsValid(capsule, b"camdyn.ModelC"):
        raise TypeError("expected the MODEL capsule of a generated camdyn model")
    cdef ModelC* m = <ModelC*> PyCapsule_GetPointer(capsule, b"camdyn.ModelC")
    if m.abi_version != CAMDYN_ABI:
        raise RuntimeError(f"generated model built for ABI {m.abi_version}, runtime has {CAMDYN_ABI}")
    return m


cdef inline double _t(Rec* r, Py_ssize_t i) noexcept nogil:
    return r.rows[i * r.width]


cdef Py_ssize_t _step_of(Rec* r, double tq) noexcept nogil:
    """The step dense_eval takes for tq: the last point before tq (or the first point), past
    a stop recorded twice."""
    cdef Py_ssize_t lo = 0, hi = r.n - 1, mid
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if _t(r, mid) < tq:
            lo = mid
        else:
            hi = mid
    while lo + 1 < r.n and _t(r, lo + 1) == _t(r, lo):
        lo += 1
    return lo


cdef double _value_in(Rec* r, double tq, Py_ssize_t i, int which) noexcept nogil:
    """State (which < ns) or output (which - ns) at tq through step i's dense output
    (dense.pxd), outputs in the step's modes."""
    cdef const double* a = r.rows + i * r.width
    cdef const double* b
    cdef int ns = r.ns, c
    cdef double h, s
    if i + 1 >= r.n or _t(r, i + 1) <= a[0]:
        for c in range(ns):
            r.y[c] = a[1 + c]
    else:
        b = a + r.width
        h = b[0] - a[0]
        s = (tq - a[0]) / h
        for c in range(ns):
            r.y[c] = dense_component(s, h, a[1 + c], b[1 + c], a[1 + ns + c], b[1 + ns + c],
                                     a + 1 + 2 * ns + c, r.nx, ns)
    if which < ns:
        return r.y[which]
    if r.nm:
        memcpy(r.ctx.mode, r.modes + i * r.nm, r.nm * sizeof(int))
        r.m.refresh(r.ctx)
    r.m.outputs(tq, r.y, r.out, r.ctx)
    return r.out[which - ns]


cdef inline double _score(Rec* r, double tq, Py_ssize_t i, int which, int kind) noexcept nogil:
    """What is maximized: |v| (kind 0), v (kind 1), -v (kind 2), -|v| (kind 3)."""
    return _as_score(_value_in(r, tq, i, which), kind)


cdef inline double _as_score(double v, int kind) noexcept nogil:
    if kind == 0:
        return fabs(v)
    if kind == 1:
        return v
    return -v if kind == 2 else -fabs(v)


cdef inline double _neg_score_at(Rec* r, double tq, int which, int kind) noexcept nogil:
    return -_score(r, tq, _step_of(r, tq), which, kind)


cdef double _brent_min(Rec* r, int which, int kind, double lo, double hi, double xatol,
                       double* x_out) noexcept nogil:
    """Bounded minimum of -score on [lo, hi] by Brent's method (golden sections, parabolic
    steps when they behave), stopping when the bracket is within sqrt(eps)|x| + xatol/3 of x,
    as SciPy's bounded minimizer does."""
    cdef double golden = 0.3819660112501051, sqrt_eps = 1.4901161193847656e-08
    cdef double a = lo, b = hi, v, w, x, fv, fw, fx, d = 0.0, e = 0.0
    cdef double xm, tol1, tol2, p, q, rr, u, fu
    cdef int it
    x = a + golden * (b - a)
    v = x
    w = x
    fx = _neg_score_at(r, x, which, kind)
    fv = fx
    fw = fx
    for it in range(500):
        xm = 0.5 * (a + b)
        tol1 = sqrt_eps * fabs(x) + xatol / 3.0
        tol2 = 2.0 * tol1
        if fabs(x - xm) <= tol2 - 0.5 * (b - a):
            break
        rr = 0.0
        q = 0.0
        p = 0.0
        if fabs(e) > tol1:
            # parabola through x, w, v
            rr = (x - w) * (fx - fv)
            q = (x - v) * (fx - fw)
            p = (x - v) * q - (x - w) * rr
            q = 2.0 * (q - rr)
            if q > 0.0:
                p = -p
            q = fabs(q)
            rr = e
            e = d
        if fabs(p) < fabs(0.5 * q * rr) and p > q * (a - x) and p < q * (b - x):
            d = p / q
            u = x + d
            if (u - a) < tol2 or (b - u) < tol2:
                d = tol1 if xm >= x else -tol1
        else:
            e = (b - x) if x < xm else (a - x)
            d = golden * e
        if fabs(d) >= tol1:
            u = x + d
        else:
            u = x + (tol1 if d > 0 else -tol1)
        fu = _neg_score_at(r, u, which, kind)
        if fu <= fx:
            if u >= x:
                a = x
            else:
                b = x
            v = w
            fv = fw
            w = x
            fw = fx
            x = u
            fx = fu
        else:
            if u < x:
                a = u
            else:
                b = u
            if fu <= fw or w == x:
                v = w
                fv = fw
                w = u
                fw = fu
            elif fu <= fv or v == x or v == w:
                v = u
                fv = fu
    x_out[0] = x
    return -fx


cdef inline double _vertex(double x0, double y0, double x1, double y1, double x2, double y2,
                           double* at) noexcept nogil:
    """Height of the parabola through three samples at its vertex, when the vertex is a
    maximum between x0 and x2 (its place into ``at``); else y1 at x1 (the ranking key of a
    candidate peak)."""
    cdef double d = (x0 - x1) * (x0 - x2) * (x1 - x2), a, b, xv
    at[0] = x1
    if d == 0.0:
        return y1
    a = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / d
    b = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / d
    if a >= 0.0:
        return y1
    xv = -b / (2.0 * a)
    if xv < x0 or xv > x2:
        return y1
    at[0] = xv
    return y1 + a * (xv - x1) * (xv - x1) + (2.0 * a * x1 + b) * (xv - x1)


cdef struct Cands:
    int n
    int cap
    double key[MAX_CAND]
    double lo[MAX_CAND]
    double hi[MAX_CAND]


cdef inline void _offer(Cands* c, double key, double lo, double hi) noexcept nogil:
    """Keep the cap best candidates by key (sorted, best first)."""
    cdef int j
    if c.n == c.cap and key <= c.key[c.n - 1]:
        return
    j = c.n if c.n < c.cap else c.cap - 1
    while j > 0 and c.key[j - 1] < key:
        c.key[j] = c.key[j - 1]
        c.lo[j] = c.lo[j - 1]
        c.hi[j] = c.hi[j - 1]
        j -= 1
    c.key[j] = key
    c.lo[j] = lo
    c.hi[j] = hi
    if c.n < c.cap:
        c.n += 1


cdef struct Peaks:
    # the PEAKS highest local maxima of the scan by the vertex of their parabola, whatever the
    # candidates are ranked by, with the three samples around each: what the sampling check
    # verifies; ``dropped`` the highest vertex that did not fit
    int n
    double dropped
    double key[PEAKS]
    double xv[PEAKS]
    double ts[PEAKS][3]
    double ss[PEAKS][3]
    bint done[PEAKS]


cdef inline void _note_peak(Peaks* P, double key, double xv, double t0, double s0, double t1,
                            double s1, double t2, double s2) noexcept nogil:
    cdef int j, c
    if P.n == PEAKS and key <= P.key[P.n - 1]:
        if key > P.dropped:
            P.dropped = key
        return
    if P.n == PEAKS and P.key[P.n - 1] > P.dropped:
        P.dropped = P.key[P.n - 1]
    j = P.n if P.n < PEAKS else PEAKS - 1
    while j > 0 and P.key[j - 1] < key:
        P.key[j] = P.key[j - 1]
        P.xv[j] = P.xv[j - 1]
        for c in range(3):
            P.ts[j][c] = P.ts[j - 1][c]
            P.ss[j][c] = P.ss[j - 1][c]
        P.done[j] = P.done[j - 1]
        j -= 1
    P.key[j] = key
    P.xv[j] = xv
    P.ts[j][0] = t0
    P.ts[j][1] = t1
    P.ts[j][2] = t2
    P.ss[j][0] = s0
    P.ss[j][1] = s1
    P.ss[j][2] = s2
    P.done[j] = False
    if P.n < PEAKS:
        P.n += 1


cdef inline void _mark_done(Peaks* P, double lo, double hi) noexcept nogil:
    cdef int j
    for j in range(P.n):
        if P.ts[j][0] == lo and P.ts[j][2] == hi:
            P.done[j] = True


cdef struct Scan:
    # the scan's last three samples, its best sample, its candidate peaks and its highest peaks
    double t0, t1, t2, s0, s1, s2, best, best_t
    Py_ssize_t n
    bint by_vertex
    Cands c
    Peaks P


cdef inline void _take(Scan* S, double tq, double sc) noexcept nogil:
    """One sample: slide the window and offer its middle if that is a local maximum."""
    cdef double v, xv
    S.t0 = S.t1
    S.s0 = S.s1
    S.t1 = S.t2
    S.s1 = S.s2
    S.t2 = tq
    S.s2 = sc
    S.n += 1
    if S.n == 2 and S.s1 >= S.s2:
        _offer(&S.c, S.s1, S.t1, S.t2)
        _note_peak(&S.P, S.s1, S.t1, S.t1, S.s1, 0.5 * (S.t1 + S.t2), S.s1, S.t2, S.s2)
    elif S.n >= 3 and S.s1 >= S.s0 and S.s1 >= S.s2:
        v = _vertex(S.t0, S.s0, S.t1, S.s1, S.t2, S.s2, &xv)
        _offer(&S.c, v if S.by_vertex else S.s1, S.t0, S.t2)
        _note_peak(&S.P, v, xv, S.t0, S.s0, S.t1, S.s1, S.t2, S.s2)
    if sc > S.best:
        S.best = sc
        S.best_t = tq


cdef inline double _refine(Rec* r, Scan* S, int which, int kind, double lo, double hi,
                           double key, double* delta) noexcept nogil:
    """Brent on [lo, hi]; the best so far updated; delta the largest |vertex - refined| seen
    (how far a parabola through three samples is from the peak it stands for)."""
    cdef double x, sc
    sc = _brent_min(r, which, kind, lo, hi, 1e-12 * (fabs(hi) if fabs(hi) > 1.0 else 1.0), &x)
    if sc > S.best:
        S.best = sc
        S.best_t = x
    if fabs(key - sc) > delta[0]:
        delta[0] = fabs(key - sc)
    _mark_done(&S.P, lo, hi)
    return sc


cdef double _verify(Rec* r, Scan* S, int k, int which, int kind, double* miss) noexcept nogil:
    """How high peak k of S.P may reach, from one more evaluation: the score at its vertex
    (a value the output takes, so a floor) and the parabola through it and the two samples
    nearest to it (the estimate), the bound being the estimate raised by its distance from
    the floor.  ``miss``: the largest |vertex - value at the vertex| seen, how far a first
    parabola may be off."""
    cdef Peaks* P = &S.P
    cdef double xv = P.xv[k], fv, k2, x2, xa, ya, xb, yb
    cdef int c
    fv = _score(r, xv, _step_of(r, xv), which, kind)
    if fabs(P.key[k] - fv) > miss[0]:
        miss[0] = fabs(P.key[k] - fv)
    # the samples on either side of the vertex, nearest first
    xa = P.ts[k][0]
    ya = P.ss[k][0]
    xb = P.ts[k][2]
    yb = P.ss[k][2]
    for c in range(3):
        if P.ts[k][c] <= xv and P.ts[k][c] > xa:
            xa = P.ts[k][c]
            ya = P.ss[k][c]
        if P.ts[k][c] >= xv and P.ts[k][c] < xb:
            xb = P.ts[k][c]
            yb = P.ss[k][c]
    if xa < xv < xb:
        k2 = _vertex(xa, ya, xv, fv, xb, yb, &x2)
    else:
        k2 = fv
    if k2 < fv:
        k2 = fv
    return k2 + (k2 - fv)


cdef int _extreme(Rec* r, int which, double a, double b, int kind, int per_step, int n_cand,
                  const double* cache, int stride, double* value, double* at,
                  double* sampling) noexcept nogil:
    """The largest score on [a, b] (module doc); value (v for kinds 1, 2; |v| for 0, 3) and
    its time into value/at, and into ``sampling`` the estimate of the error the scan leaves:
    how far a peak not refined may rise above the value, its parabola's vertex raised by the
    most a refined peak's vertex fell short of it (0 when every peak that could be higher
    was refined).  ``cache``: NULL, or the value at every ``stride``-th recorded
    point j > 0 as the dense output gives it there (step j - 1 at its end); with it (and
    per_step 1) the scan reads those points only.  Returns the number of samples scanned
    (0: an empty span)."""
    cdef Py_ssize_t i, istep = 0, j
    cdef double tk, tk1, tq, delta = 0.0, excess, miss, bound
    cdef int q, k, extra = 0
    cdef Scan S
    cdef bint more = True
    S.n = 0
    S.t1 = S.t2 = S.s1 = S.s2 = 0.0
    S.best = -INFINITY
    S.best_t = a
    S.c.n = 0
    S.c.cap = n_cand if 0 < n_cand <= MAX_CAND else 1
    S.P.n = 0
    S.P.dropped = -INFINITY
    # one candidate: the best sample, as the reference takes it; several: the best peaks
    S.by_vertex = S.c.cap > 1
    sampling[0] = 0.0
    if not b >= a:
        return 0
    _take(&S, a, _score(r, a, _step_of(r, a), which, kind))
    if cache != NULL and per_step == 1:
        # the recorded points on the stride inside (a, b), first of a pair at a stop
        j = _step_of(r, a) + 1
        j += (stride - j % stride) % stride
        while j < r.n and _t(r, j) < b:
            if _t(r, j) > a and _t(r, j) > _t(r, j - 1):
                _take(&S, _t(r, j), _as_score(cache[j], kind))
            j += stride
    else:
        # the knots a < recorded times < b, b; per_step samples in each knot interval
        i = 0
        while i < r.n and _t(r, i) <= a:
            i += 1
        tk = a
        while more:
            # next knot: the next distinct recorded time inside (tk, b), else b
            while i < r.n and _t(r, i) <= tk:
                i += 1
            tk1 = _t(r, i) if i < r.n and _t(r, i) < b else b
            if tk1 > tk and per_step > 1:
                istep = _step_of(r, 0.5 * (tk + tk1))   # the step every sample inside lies in
                for q in range(1, per_step):
                    tq = tk + (tk1 - tk) * q / per_step
                    _take(&S, tq, _score(r, tq, istep, which, kind))
            if tk1 >= b:
                more = False
            else:
                _take(&S, tk1, _score(r, tk1, _step_of(r, tk1), which, kind))
            tk = tk1
    # b itself (once, when it is not a itself)
    if b > a:
        _take(&S, b, _score(r, b, _step_of(r, b), which, kind))
    if S.n >= 2 and S.s2 >= S.s1:
        _offer(&S.c, S.s2, S.t1, S.t2)
        _note_peak(&S.P, S.s2, S.t2, S.t1, S.s1, 0.5 * (S.t1 + S.t2), S.s2, S.t2, S.s2)
    if S.n == 1:
        _offer(&S.c, S.s2, S.t2, S.t2)
    for k in range(S.c.n):
        # a peak whose parabola lies 1e-3 of the best one's below it cannot be the largest:
        # at 25 samples a period the parabola is within ~1e-5 of the peak
        if S.by_vertex and k > 0 and S.c.key[k] < S.c.key[0] - 1e-3 * fabs(S.c.key[0]):
            break
        if S.c.hi[k] > S.c.lo[k]:
            _refine(r, &S, which, kind, S.c.lo[k], S.c.hi[k], S.c.key[k], &delta)
    # the sampling check: a peak left unrefined may be the true extreme; one evaluation at
    # its vertex bounds how high it may reach (_verify), and one that may reach above the
    # best is refined too, while the budget lasts; what the peaks left over could still add
    # is the sampling error
    # (every peak kept is verified: the vertices of the peaks refined first are no fair
    # sample of how far a vertex may be off, their best samples lying near their tops)
    miss = 0.0
    for k in range(S.P.n):
        if S.P.done[k]:
            continue
        bound = _verify(r, &S, k, which, kind, &miss)
        excess = bound - S.best
        if excess <= 1e-13 * fabs(S.best):
            continue
        if extra < MAX_CAND and S.P.ts[k][2] > S.P.ts[k][0]:
            _refine(r, &S, which, kind, S.P.ts[k][0], S.P.ts[k][2], S.P.key[k], &delta)
            extra += 1
        elif excess > sampling[0]:
            sampling[0] = excess
    # peaks beyond the PEAKS kept, unverified
    if S.P.dropped + 3.0 * miss - S.best > sampling[0]:
        sampling[0] = S.P.dropped + 3.0 * miss - S.best
    value[0] = -S.best if kind >= 2 else S.best
    at[0] = S.best_t
    return <int> (S.n if S.n < 2147483647 else 2147483647)


cdef double _crossing(Rec* r, int which, double level, int* ok) noexcept nogil:
    """First time the state ``which`` reaches ``level``: the first recorded point at or past
    it, then bisection on the dense output of the step before it to 1e-14."""
    cdef Py_ssize_t k = 0
    cdef double lo, hi, mid
    cdef int it
    ok[0] = 1
    while k < r.n and r.rows[k * r.width + 1 + which] - level < 0:
        k += 1
    if k == r.n:
        ok[0] = 0
        return NAN
    if k == 0:
        return _t(r, 0)
    lo = _t(r, k - 1)
    hi = _t(r, k)
    if lo == hi:
        return lo
    for it in range(200):
        if hi - lo <= 1e-14:
            break
        mid = 0.5 * (lo + hi)
        if _value_in(r, mid, _step_of(r, mid), which) - level < 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


cdef void _fill_cache(Rec* r, int w1, int w2, double* c1, double* c2, int stride) noexcept nogil:
    """Figures w1 and w2 at every recorded point j > 0 as the dense output gives them there
    (step j - 1 at its end), from one evaluation of the outputs per point."""
    cdef Py_ssize_t j
    cdef int ns = r.ns
    cdef int w = w1 if w1 >= w2 else w2
    c1[0] = NAN
    c2[0] = NAN
    j = stride
    while j < r.n:
        if _t(r, j) > _t(r, j - 1):
            _value_in(r, _t(r, j), j - 1, w)
            c1[j] = r.y[w1] if w1 < ns else r.out[w1 - ns]
            c2[j] = r.y[w2] if w2 < ns else r.out[w2 - ns]
        j += stride


# -- one record, from Python -------------------------------------------------------------------

cdef class _View:
    """A Rec over a recorded run's arrays, with the buffers it points into kept alive."""
    cdef Rec r
    cdef Ctx ctx
    cdef object keep
    cdef double[::1] p, k, law_par, y, out
    cdef int[::1] law, mode
    cdef const double[:, ::1] rows
    cdef const int[:, ::1] modes

    def __init__(self, object capsule, double[::1] p, int[::1] law, double[::1] law_par, rows,
                 modes, int ns, int nx):
        cdef ModelC* m = _model(capsule)
        self.keep = capsule
        self.rows = np.ascontiguousarray(rows, dtype=float)
        nm = m.n_modes
        self.modes = np.ascontiguousarray(modes, dtype=np.intc).reshape(-1, nm) if nm else \
            np.zeros((1, 1), dtype=np.intc)
        self.p, self.law, self.law_par = p, law, law_par
        self.k = np.empty(m.n_const + m.n_cache + 1)
        self.mode = np.zeros(max(nm, 1), dtype=np.intc)
        self.y = np.empty(max(ns, 1))
        self.out = np.empty(max(m.n_outputs, 1))
        self.ctx.p = &self.p[0]
        self.ctx.k = &self.k[0]
        self.ctx.cache = &self.k[m.n_const]
        self.ctx.law = &self.law[0]
        self.ctx.law_par = &self.law_par[0]
        self.ctx.mode = &self.mode[0]
        self.ctx.variant = 0
        m.prepare(&self.ctx)
        if nm and self.modes.shape[0]:
            memcpy(&self.mode[0], &self.modes[0, 0], nm * sizeof(int))
        self.r.m = m
        self.r.ctx = &self.ctx
        self.r.rows = &self.rows[0, 0]
        self.r.modes = &self.modes[0, 0]
        self.r.n = self.rows.shape[0]
        self.r.ns = ns
        self.r.nm = nm
        self.r.width = self.rows.shape[1]
        self.r.nx = nx
        self.r.y = &self.y[0]
        self.r.out = &self.out[0]


def extreme(object capsule, double[::1] p, int[::1] law, double[::1] law_par, rows, modes,
            int ns, int nx, int which, double a, double b, bint absolute, bint minimum,
            int per_step=12, int n_cand=1):
    """(value, time, sampling error) of the extreme of state/output ``which`` (outputs after
    the ns states) on [a, b] of a recorded run (rows as Result keeps them); see the module
    doc and _extreme."""
    if per_step < 1:
        raise ValueError("per_step must be at least 1")
    cdef _View v = _View(capsule, p, law, law_par, rows, modes, ns, nx)
    cdef double value = NAN, at = NAN, sampling = 0.0
    cdef int kind = (3 if minimum else 0) if absolute else (2 if minimum else 1)
    if v.r.n == 0:
        raise ValueError("empty record")
    with nogil:
        _extreme(&v.r, which, a, b, kind, per_step, n_cand, NULL, 1, &value, &at, &sampling)
    return value, at, sampling


def crossing(object capsule, double[::1] p, int[::1] law, double[::1] law_par, rows, modes,
             int ns, int nx, int which, double level):
    """First time state ``which`` reaches ``level`` (NaN if never)."""
    cdef _View v = _View(capsule, p, law, law_par, rows, modes, ns, nx)
    cdef int ok
    cdef double t
    with nogil:
        t = _crossing(&v.r, which, level, &ok)
    return t


# -- a chunk of a sweep -----------------------------------------------------------------------

def sweep_residual(object capsule, int method, int[::1] law, double[::1] law_par,
                   const double[:, ::1] P, const double[:, ::1] Y0, const double[:, ::1] stops,
                   const int[::1] n_stops, double t0, double h, double h_max, double rtol,
                   const double[::1] atol, long max_steps, const int[::1] modes0, long max_events,
                   int i_error, int i_acc, double rise_end, int i_rise, int per_step, int n_cand,
                   double[:, ::1] figures, long[:, ::1] stats, double[::1] seconds,
                   Py_ssize_t start, Py_ssize_t stop, Py_ssize_t cap=4096, int stride=1,
                   bint figures_too=True, bint exact=False):
    """Run parameter sets start..stop-1 (rows of P, initial states Y0, stop times) and write
    the FIGURE_COLUMNS of each into ``figures`` and the STAT_COLUMNS into ``stats``; seconds[j]:
    wall time of run j with its figures.  i_error, i_acc: the error and acceleration outputs
    (index among states then outputs); i_rise: the state whose crossing of rise_end ends the
    rise, or -1 (the rise ends at time rise_end).  With per_step 1 the scan samples every
    ``stride``-th recorded point (its peaks are refined between the samples around them).
    ``figures_too`` False: integrate only (bench/sweep.py splits the cost with it).  ``exact``:
    intervals where the model is linear and time invariant are stepped over exactly
    (runtime/engine/loops.pxi, _loop_exact), as Simulator(exact_segments=True) does.
    No GIL is held while it runs.

    A run that fails leaves its status (runtime/driver.STATUS_TEXT) and NaN figures; a run
    whose span does not cover the rise and part of the dwell after it, status -1."""
    cdef ModelC* m = _model(capsule)
    cdef int ns = m.n_states, nm = m.n_modes, ncam = m.n_instances, width, j, status, ok
    cdef Py_ssize_t g
    if P.shape[1] != m.n_params or Y0.shape[1] != ns or atol.shape[0] != ns:
        raise ValueError("parameter, state or tolerance arrays of the wrong width")
    if figures.shape[1] != len(FIGURE_COLUMNS):
        raise ValueError(f"figures must have {len(FIGURE_COLUMNS)} columns (FIGURE_COLUMNS)")
    if modes0.shape[0] != nm - ncam:
        raise ValueError("one initial mode per force element expected")
    if not adaptive_method(method):
        raise ValueError("the compiled sweep takes the adaptive methods (dp54, dop853, rodas4)")
    if per_step < 1 or not (0 < n_cand <= MAX_CAND) or stride < 1:
        raise ValueError(f"per_step >= 1, stride >= 1 and 1 <= n_cand <= {MAX_CAND}")
    if per_step > 1:
        stride = 1
    width = 1 + (2 + extra_terms(method)) * ns
    if cap < 64:
        cap = 64
    cdef double* rows = <double*> malloc(cap * width * sizeof(double))
    cdef int* rmode = <int*> malloc(cap * (nm if nm > 0 else 1) * sizeof(int))
    cdef double* scratch = <double*> malloc((2 * ns + m.n_const + m.n_cache + m.n_outputs + 1) * sizeof(double))
    cdef int* mode = <int*> malloc((nm + 1) * sizeof(int))
    if rows == NULL or rmode == NULL or scratch == NULL or mode == NULL:
        free(rows)
        free(rmode)
        free(scratch)
        free(mode)
        raise MemoryError()
    cdef Ctx ctx
    cdef Run run
    cdef Rec rec
    cdef double* cache = NULL     # error, then acceleration, at every recorded point
    cdef Py_ssize_t ccap = 0
    cdef double t1, t_end, v, at, samp
    cdef timespec c0, c1
    with nogil:
        for g in range(start, stop):
            clock_gettime(CLOCK_MONOTONIC, &c0)
            memcpy(scratch, &Y0[g, 0], ns * sizeof(double))
            for j in range(nm - ncam):
                mode[ncam + j] = modes0[j]
            ctx.p = &P[g, 0]
            ctx.k = scratch + ns
            ctx.cache = scratch + ns + m.n_const
            ctx.law = &law[0]
            ctx.law_par = &law_par[0]
            ctx.mode = mode
            ctx.variant = 0
            run.ctx = &ctx
            run.rec.n = 0
            run.rec.cap = cap
            run.rec.width = width
            run.rec.n_extra = extra_terms(method)
            run.rec.owned = True       # ours (malloc): the loops may grow and free it
            run.rec.rows = rows
            run.rec.mode = rmode
            run.method = method
            run.stops = &stops[g, 0]
            run.n_stops = n_stops[g]
            run.t0 = t0
            run.y = scratch
            run.h = h
            run.h_max = h_max
            run.rtol = rtol
            run.atol = &atol[0]
            run.max_steps = max_steps
            run.max_events = max_events
            run.n_events = 0
            run.n_steps = 0
            run.n_rejected = 0
            run.n_rhs = 0
            run.t_fail = t0
            run.err_old = 1e-4
            run.t_stiff = NAN
            run.stab_mode = 0      # adaptive methods only (checked above)
            run.stab_bound = NULL
            run.n_stab_bound = 0
            run.stab_work = NULL
            run.stab_ratio = -1.0
            run.n_checks = 0
            run.n_jac = 0
            run.n_lu = 0
            run.exact = exact
            status = m.run(&run)
            # keep the (possibly grown) buffers for the next run
            rows = run.rec.rows
            rmode = run.rec.mode
            cap = run.rec.cap
            stats[g, 0] = status
            stats[g, 1] = run.n_steps
            stats[g, 2] = run.n_rejected
            stats[g, 3] = run.n_rhs
            stats[g, 4] = run.rec.n
            for j in range(8):
                figures[g, j] = NAN
            if status == STATUS_OK and run.rec.n > 0 and figures_too:
                rec.m = m
                rec.ctx = &ctx
                rec.rows = rows
                rec.modes = rmode
                rec.n = run.rec.n
                rec.ns = ns
                rec.nm = nm
                rec.width = width
                rec.nx = extra_terms(method)
                rec.y = scratch + ns + m.n_const + m.n_cache
                rec.out = rec.y + ns
                t_end = rows[(rec.n - 1) * width]
                t1 = rise_end
                ok = 1
                if i_rise >= 0:
                    t1 = _crossing(&rec, i_rise, rise_end, &ok)
                if not ok or not (rows[0] <= 0.0 and t_end > t1):
                    stats[g, 0] = -1
                else:
                    figures[g, 4] = t1
                    if rec.n > ccap:
                        free(cache)
                        ccap = rec.n + rec.n // 4
                        cache = <double*> malloc(2 * ccap * sizeof(double))
                        if cache == NULL:
                            ccap = 0
                    if cache != NULL:
                        _fill_cache(&rec, i_error, i_acc, cache, cache + ccap, stride)
                    _extreme(&rec, i_error, t1, t_end, 0, per_step, n_cand, cache, stride, &v, &at,
                             &samp)
                    figures[g, 0] = v
                    figures[g, 5] = samp
                    _extreme(&rec, i_acc, t1, t_end, 0, per_step, n_cand,
                             cache + ccap if cache != NULL else NULL, stride, &v, &at, &samp)
                    figures[g, 1] = v
                    figures[g, 6] = samp
                    _extreme(&rec, i_acc, rows[0] if rows[0] > 0.0 else 0.0, t1, 2, per_step,
                             n_cand, cache + ccap if cache != NULL else NULL, stride, &v, &at,
                             &samp)
                    figures[g, 2] = v
                    figures[g, 3] = at
                    figures[g, 7] = samp
            clock_gettime(CLOCK_MONOTONIC, &c1)
            seconds[g] = (c1.tv_sec - c0.tv_sec) + 1e-9 * (c1.tv_nsec - c0.tv_nsec)
    free(rows)
    free(rmode)
    free(scratch)
    free(mode)
    free(cache)
    return cap
