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
of the outputs there, filled by one evaluation of the model's outputs per point.  The rise
may take its own, lower density (``rise_per_step``: its peaks are not all equal as an undamped
dwell's are, so the finder's 1e-3 cut-off asks less of the parabolas).  Where the dwell was
stepped over exactly, U0 and U0'' come in closed form from the state at the end of the rise
(``_dwell_closed_form``) and a sweep steps over that dwell in one go.

``sweep_residual`` runs a chunk of parameter sets through the model's compiled loops and these
finders in one call that holds no GIL: one record buffer reused for every run, no Python object
per run.  Threads can run chunks side by side (runtime/studies/sweep.py).
"""
from cpython.pycapsule cimport PyCapsule_GetPointer, PyCapsule_IsValid
from libc.math cimport NAN, INFINITY, atan2, cos, exp, fabs, fmax, isnan, log, sin, sqrt
from libc.stdlib cimport free, malloc
from libc.string cimport memcpy
from posix.time cimport CLOCK_MONOTONIC, clock_gettime, timespec

import numpy as np

from camdyn.runtime.engine.abi cimport *
from camdyn.runtime.engine.dense cimport dense_component
from camdyn.runtime.engine.partition cimport check_partition

cdef enum:
    MAX_CAND = 16
    PEAKS = 160

# the columns sweep_residual fills: the figures, then their sampling errors
FIGURE_COLUMNS = ("U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min", "T_rise_end",
                  "U0_sampling", "U0dd_sampling", "Xdd_min_rise_sampling")
STAT_COLUMNS = ("status", "n_steps", "n_rejected", "n_rhs", "n_points")


cdef struct Rec:
    # a view of one run's record and what evaluating its outputs needs; the only writes into
    # it are the DOP853 dense output a run left out, made where it is wanted (_fill)
    ModelC* m
    Ctx* ctx
    double* rows
    const int* modes
    Py_ssize_t n
    int ns
    int nm
    int width
    int nx             # dense-output extras per row (dense.pxd)
    double* y          # ns scratch doubles
    double* out        # n_outputs scratch doubles
    bint hermite       # a left-out step's values from the cubic Hermite interpolant (the
                       # scan's samples), else from its dense output, made on the spot
    long n_hermite     # values so taken
    long n_fill        # right-hand-side calls made filling left-out steps


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


cdef inline bint _left_out(Rec* r, Py_ssize_t i) noexcept nogil:
    """Whether step i's DOP853 dense output was left out of the run (loops.pxi)."""
    return r.nx == 4 and isnan(r.rows[i * r.width + 1 + 2 * r.ns])


cdef void _fill(Rec* r, Py_ssize_t i) noexcept nogil:
    """Step i's left-out dense output, made by the model in the step's modes (dense_fill)."""
    if r.nm:
        memcpy(r.ctx.mode, r.modes + i * r.nm, r.nm * sizeof(int))
        r.m.refresh(r.ctx)
    r.n_fill += r.m.dense_fill(r.ctx, r.rows + i * r.width)


cdef void _fill_between(Rec* r, double a, double b) noexcept nogil:
    """Every left-out step that starts before b, from the one a lies in on (_fill)."""
    cdef Py_ssize_t i = _step_of(r, a)
    while i + 1 < r.n and _t(r, i) < b:
        if _left_out(r, i):
            _fill(r, i)
        i += 1


cdef double _value_in(Rec* r, double tq, Py_ssize_t i, int which) noexcept nogil:
    """State (which < ns) or output (which - ns) at tq through step i's dense output
    (dense.pxd), outputs in the step's modes.  A step whose dense output the run left out
    gets it first (_fill), unless r.hermite takes its cubic Hermite interpolant."""
    cdef const double* a = r.rows + i * r.width
    cdef const double* b
    cdef int ns = r.ns, c, nx = r.nx
    cdef double h, s
    if i + 1 >= r.n or _t(r, i + 1) <= a[0]:
        for c in range(ns):
            r.y[c] = a[1 + c]
    else:
        if _left_out(r, i):
            if r.hermite:
                nx = 0
                r.n_hermite += 1
            else:
                _fill(r, i)
        b = a + r.width
        h = b[0] - a[0]
        s = (tq - a[0]) / h
        for c in range(ns):
            r.y[c] = dense_component(s, h, a[1 + c], b[1 + c], a[1 + ns + c], b[1 + ns + c],
                                     a + 1 + 2 * ns + c, nx, ns)
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


cdef double _verify(Rec* r, Scan* S, int k, int which, int kind, double* miss,
                    double* hmiss) noexcept nogil:
    """How high peak k of S.P may reach, from one more evaluation: the score at its vertex
    (a value the output takes, so a floor) and the parabola through it and the two samples
    nearest to it (the estimate), the bound being the estimate raised by its distance from
    the floor.  ``miss``: the largest |vertex - value at the vertex| seen, how far a first
    parabola may be off; ``hmiss``, where the scan took cubic Hermite values in left-out
    steps: the largest |Hermite value - dense output's| at the vertices, how far those
    samples may be off."""
    cdef Peaks* P = &S.P
    cdef double xv = P.xv[k], fv, hv, k2, x2, xa, ya, xb, yb
    cdef Py_ssize_t i = _step_of(r, xv)
    cdef int c, nx = r.nx
    if r.n_hermite > 0:
        r.nx = 0
        hv = _score(r, xv, i, which, kind)
        r.nx = nx
    fv = _score(r, xv, i, which, kind)
    if r.n_hermite > 0 and fabs(hv - fv) > hmiss[0]:
        hmiss[0] = fabs(hv - fv)
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


cdef Py_ssize_t _walk(Rec* r, double a, double b, int per_step, int which, int kind, Scan* S,
                      double* out, Py_ssize_t cap, int w1, int w2) noexcept nogil:
    """The scan's samples of [a, b]: a, per_step evenly spaced times in every interval between
    the knots (a, the distinct recorded times inside (a, b), b), b; a knot takes the step that
    ends there, a sample inside an interval the step it lies in.  With S each is scored for
    ``which`` and taken; else the time, the value of w1 and that of w2 (one evaluation of the
    model's outputs for both) go to out[k], out[cap + k], out[2 cap + k] while k < cap.
    Returns the number of samples (more than cap: out holds the first cap)."""
    cdef Py_ssize_t i = 0, istep = 0, k = 0
    cdef double tk = a, tk1, tq
    cdef int q
    cdef bint more = True
    k = _sample(r, a, _step_of(r, a), which, kind, S, out, cap, w1, w2, k)
    while i < r.n and _t(r, i) <= a:
        i += 1
    while more:
        # next knot: the next distinct recorded time inside (tk, b), else b
        while i < r.n and _t(r, i) <= tk:
            i += 1
        tk1 = _t(r, i) if i < r.n and _t(r, i) < b else b
        # the step every sample in (tk, tk1] lies in, as _step_of finds it: the last point
        # before the first one past tk
        istep = i - 1 if i > 0 else 0
        if tk1 > tk and per_step > 1:
            for q in range(1, per_step):
                tq = tk + (tk1 - tk) * q / per_step
                k = _sample(r, tq, istep, which, kind, S, out, cap, w1, w2, k)
        if tk1 >= b:
            more = False
        else:
            k = _sample(r, tk1, istep, which, kind, S, out, cap, w1, w2, k)
        tk = tk1
    if b > a:
        k = _sample(r, b, _step_of(r, b), which, kind, S, out, cap, w1, w2, k)
    return k


cdef inline void _pair_in(Rec* r, double tq, Py_ssize_t i, int w1, int w2, double* v1,
                          double* v2) noexcept nogil:
    """Figures w1 and w2 (states, then outputs) at tq through step i, from one evaluation of
    the model's outputs."""
    _value_in(r, tq, i, w1 if w1 >= w2 else w2)
    v1[0] = r.y[w1] if w1 < r.ns else r.out[w1 - r.ns]
    v2[0] = r.y[w2] if w2 < r.ns else r.out[w2 - r.ns]


cdef inline Py_ssize_t _sample(Rec* r, double tq, Py_ssize_t i, int which, int kind, Scan* S,
                               double* out, Py_ssize_t cap, int w1, int w2,
                               Py_ssize_t k) noexcept nogil:
    if S != NULL:
        _take(S, tq, _score(r, tq, i, which, kind))
    elif k < cap:
        out[k] = tq
        _pair_in(r, tq, i, w1, w2, out + cap + k, out + 2 * cap + k)
    return k + 1



cdef int _extreme(Rec* r, int which, double a, double b, int kind, int per_step, int n_cand,
                  const double* cache, int stride, double* value, double* at,
                  double* sampling, const double* st=NULL, const double* sv=NULL,
                  Py_ssize_t n_samples=0, double htol=0.0) noexcept nogil:
    """The largest score on [a, b] (module doc); value (v for kinds 1, 2; |v| for 0, 3) and
    its time into value/at, and into ``sampling`` the estimate of the error the scan leaves:
    how far a peak not refined may rise above the value, its parabola's vertex raised by the
    most a refined peak's vertex fell short of it (0 when every peak that could be higher
    was refined).  ``cache``: NULL, or the value at every ``stride``-th recorded
    point j > 0 as the dense output gives it there (step j - 1 at its end); with it (and
    per_step 1) the scan reads those points only.  Returns the number of samples scanned
    (0: an empty span)."""
    cdef Py_ssize_t i, istep = 0, j
    cdef double tk, tk1, tq, delta = 0.0, excess, miss, hmiss
    cdef double bound[PEAKS]
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
    r.n_hermite = 0        # this scan's own
    if not b >= a:
        return 0
    if st != NULL:
        for j in range(n_samples):
            _take(&S, st[j], _as_score(sv[j], kind))
    elif cache != NULL and per_step == 1:
        _take(&S, a, _score(r, a, _step_of(r, a), which, kind))
        # the recorded points on the stride inside (a, b), first of a pair at a stop
        j = _step_of(r, a) + 1
        j += (stride - j % stride) % stride
        while j < r.n and _t(r, j) < b:
            if _t(r, j) > a and _t(r, j) > _t(r, j - 1):
                _take(&S, _t(r, j), _as_score(cache[j], kind))
            j += stride
        if b > a:
            _take(&S, b, _score(r, b, _step_of(r, b), which, kind))
    else:
        # a step whose DOP853 dense output the run left out is scanned on its cubic Hermite
        # interpolant, made only where a peak is refined or verified; how far that
        # interpolant is off at the vertices counts in the sampling check (hmiss)
        r.hermite = True
        _walk(r, a, b, per_step, which, kind, &S, NULL, 0, 0, 0)
        r.hermite = False
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
    hmiss = 0.0
    for k in range(S.P.n):
        bound[k] = -INFINITY if S.P.done[k] else _verify(r, &S, k, which, kind, &miss, &hmiss)
    for k in range(S.P.n):
        if S.P.done[k]:
            continue
        # the samples beside a vertex may be Hermite values, each off by up to hmiss
        excess = bound[k] + 2.0 * hmiss - S.best
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
    # a cubic Hermite scan off by more than htol (0: 1e-9 of the extreme) is no scan to
    # trust: the left-out steps of [a, b] are made and the scan is made again on them, as a
    # run that made its dense output scans it (large steps; small ones keep their Hermite)
    # (once: the scan again runs with htol infinite, so that steps the fill could not make,
    # or a miss that is no number, cannot call it again and again until the stack is gone)
    if r.n_hermite > 0 and hmiss > (htol if htol > 0.0 else 1e-9 * fabs(S.best)):
        _fill_between(r, a, b)
        return _extreme(r, which, a, b, kind, per_step, n_cand, cache, stride, value, at,
                        sampling, st, sv, n_samples, INFINITY)
    value[0] = -S.best if kind >= 2 else S.best
    at[0] = S.best_t
    return <int> (S.n if S.n < 2147483647 else 2147483647)


cdef double _recorded(Rec* r, Py_ssize_t k, int which) noexcept nogil:
    """State (which < ns) or output (which - ns) at recorded point k, the output from the
    point's own state in its own modes (as a Result's outputs at its recorded points)."""
    cdef const double* a = r.rows + k * r.width
    if which < r.ns:
        return a[1 + which]
    if r.nm:
        memcpy(r.ctx.mode, r.modes + k * r.nm, r.nm * sizeof(int))
        r.m.refresh(r.ctx)
    r.m.outputs(a[0], a + 1, r.out, r.ctx)
    return r.out[which - r.ns]


cdef bint _recorded_at(Rec* r, double t) noexcept nogil:
    """Whether t is a recorded point (the end of a step, not a time inside one)."""
    cdef Py_ssize_t i = _step_of(r, t)
    return _t(r, i) == t or (i + 1 < r.n and _t(r, i + 1) == t)


cdef double _crossing(Rec* r, int which, double level, int* ok) noexcept nogil:
    """First time the state or output ``which`` (outputs after the ns states) reaches
    ``level``: the first recorded point at or past it, then bisection on the dense output of
    the step before it to 1e-14."""
    cdef Py_ssize_t k = 0
    cdef double lo, hi, mid
    cdef int it
    ok[0] = 1
    while k < r.n and _recorded(r, k, which) - level < 0:
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


cdef void _fill_cache(Rec* r, int w1, int w2, double* c1, double* c2, int stride,
                      double t_stop=INFINITY) noexcept nogil:
    """Figures w1 and w2 at every stride-th recorded point j > 0 up to the first at or past
    t_stop as the dense output gives them there (step j - 1 at its end), from one evaluation
    of the outputs per point."""
    cdef Py_ssize_t j
    c1[0] = NAN
    c2[0] = NAN
    j = stride
    while j < r.n and _t(r, j - stride) < t_stop:
        if _t(r, j) > _t(r, j - 1):
            _pair_in(r, _t(r, j), j - 1, w1, w2, c1 + j, c2 + j)
        j += stride


# -- the dwell of a one-DOF model in closed form -------------------------------------------
#
# Where a run stepped over the dwell exactly (runtime/engine/loops.pxi, _loop_exact) the
# dwell is y' = A y + c with A and c constant; for two states the solution from the state
# y1 at the end of the rise is, with z = y1 - y*, y* = -A^-1 c the rest point,
#     y(t1 + s) = y* + e^(A s) z,
# and an output affine in y, o = g.y + o*, moves as o* + w(s), w(s) = g.e^(A s) z: for
# complex eigenvalues alpha +- i beta, w = e^(alpha s) (p cos(beta s) + q sin(beta s)) with
# p = g.z, q = g.(A - alpha I) z / beta (an overdamped dwell, with real eigenvalues, is left
# to the scan).  The extremes of w lie where w' = 0, at beta s = theta0 + k pi, and successive extremes of one sign grow or shrink by the same factor e^(alpha pi/beta),
# so the largest |o| on [0, L] is at an end or at one of the first two or last two of
# them: U0 (3.5) and U0'' (3.6) from y1 exactly, without a scan.

cdef inline double _dot2(const double* g, const double* v) noexcept nogil:
    return g[0] * v[0] + g[1] * v[1]


cdef bint _affine_output(Rec* r, double t, const double* y, int which, double* g,
                         double* o0) noexcept nogil:
    """Whether output/state ``which`` is affine in y at time t (checked by differences: a
    second difference along each state and a mixed one, to rounding); if so its gradient into
    g and its value at y into o0."""
    cdef double yy[2]
    cdef double d[2]
    cdef double f0, f1, f2, f11, f12, tol
    cdef int i
    if which < 2:
        g[0] = 1.0 if which == 0 else 0.0
        g[1] = 1.0 - g[0]
        o0[0] = y[which]
        return True
    d[0] = 1.0 + fabs(y[0])
    d[1] = 1.0 + fabs(y[1])
    r.m.outputs(t, y, r.out, r.ctx)
    f0 = r.out[which - 2]
    tol = 0.0
    for i in range(2):
        yy[0] = y[0]
        yy[1] = y[1]
        yy[i] += d[i]
        r.m.outputs(t, yy, r.out, r.ctx)
        f1 = r.out[which - 2]
        yy[i] += d[i]
        r.m.outputs(t, yy, r.out, r.ctx)
        f2 = r.out[which - 2]
        g[i] = (f1 - f0) / d[i]
        tol = fmax(tol, fabs(f1) + fabs(f2))
        if not fabs(f2 - 2.0 * f1 + f0) <= 1e-12 * (tol + fabs(f0)):
            return False
    yy[0] = y[0] + d[0]
    yy[1] = y[1] + d[1]
    r.m.outputs(t, yy, r.out, r.ctx)
    f12 = r.out[which - 2]
    f11 = f0 + g[0] * d[0] + g[1] * d[1]
    o0[0] = f0
    return fabs(f12 - f11) <= 1e-12 * (tol + fabs(f0) + fabs(f12))


cdef double _dwell_largest(const double* A, const double* z, const double* g, double o_rest,
                           double L, int* ok) noexcept nogil:
    """max |o_rest + g.e^(A s) z| over s in [0, L] (see above); ok 0 where the eigenvalues are
    real (an overdamped dwell) or nearly equal, where no closed form is taken."""
    cdef double tr = A[0] + A[3], det = A[0] * A[3] - A[1] * A[2]
    cdef double disc = 0.25 * tr * tr - det, alpha, beta, p, q, x, best, theta0, s
    cdef double Az[2]
    cdef double v[2]
    cdef int k, n_ext
    ok[0] = 1
    p = _dot2(g, z)
    Az[0] = A[0] * z[0] + A[1] * z[1]
    Az[1] = A[2] * z[0] + A[3] * z[1]
    best = fmax(fabs(o_rest + p), 0.0)
    if fabs(disc) <= 1e-10 * (0.25 * tr * tr + fabs(det)):
        ok[0] = 0
        return NAN
    if disc < 0.0:
        alpha = 0.5 * tr
        beta = sqrt(-disc)
        v[0] = Az[0] - alpha * z[0]
        v[1] = Az[1] - alpha * z[1]
        q = _dot2(g, v) / beta
        # w' = e^(alpha s) ((alpha p + beta q) cos(beta s) + (alpha q - beta p) sin(beta s))
        theta0 = atan2(alpha * p + beta * q, beta * p - alpha * q)
        while theta0 <= 0.0:
            theta0 += 3.141592653589793
        n_ext = <int> ((beta * L - theta0) / 3.141592653589793) + 1 if beta * L > theta0 else 0
        for k in range(n_ext):
            if k >= 2 and k < n_ext - 2:
                continue
            s = (theta0 + k * 3.141592653589793) / beta
            if s < L:
                x = o_rest + exp(alpha * s) * (p * cos(beta * s) + q * sin(beta * s))
                best = fmax(best, fabs(x))
        x = o_rest + exp(alpha * L) * (p * cos(beta * L) + q * sin(beta * L))
        return fmax(best, fabs(x))
    ok[0] = 0        # real eigenvalues (an overdamped dwell): the scan finds them
    return NAN


cdef bint _dwell_closed_form(Rec* r, double t1, double t_end, int w_err, int w_acc,
                             double* U0, double* U0dd) noexcept nogil:
    """U0 and U0'' of a two-state model's exact dwell [t1, t_end] in closed form (see above);
    False, leaving the scan to find them, where the record shows the dwell is not linear and
    time invariant (a recorded rate off A y + c, a mode that changes), where an output is not
    affine in the state, or where the eigenvalues are real or (nearly) equal."""
    cdef Py_ssize_t i1, j
    cdef const double* row
    cdef const double* last = r.rows + (r.n - 1) * r.width
    cdef double A[4]
    cdef double c[2]
    cdef double y1[2]
    cdef double z[2]
    cdef double ystar[2]
    cdef double g[2]
    cdef double o_rest, o1, scale, det, L = t_end - t1, tm = 0.5 * (t1 + t_end)
    cdef int k, ok
    if r.ns != 2 or not L > 0.0:
        return False
    i1 = _step_of(r, t1)
    _value_in(r, t1, i1, 0)
    y1[0] = r.y[0]
    y1[1] = r.y[1]
    # the dwell's modes (those of its last point), A and c there
    if r.nm:
        memcpy(r.ctx.mode, r.modes + (r.n - 1) * r.nm, r.nm * sizeof(int))
        r.m.refresh(r.ctx)
    r.m.jac(t_end, last + 1, A, NULL, r.ctx)
    r.m.rhs(t_end, last + 1, c, r.ctx)
    c[0] -= A[0] * last[1] + A[1] * last[2]
    c[1] -= A[2] * last[1] + A[3] * last[2]
    # every recorded point of the dwell on y' = A y + c, in the same modes
    for j in range(i1 + 1, r.n):
        row = r.rows + j * r.width
        if row[0] <= t1:       # the rise's own end (a stop is recorded twice)
            continue
        if r.nm:
            for k in range(r.nm):
                if r.modes[j * r.nm + k] != r.modes[(r.n - 1) * r.nm + k]:
                    return False
        for k in range(2):
            o1 = A[2 * k] * row[1] + A[2 * k + 1] * row[2] + c[k]
            scale = fabs(A[2 * k] * row[1]) + fabs(A[2 * k + 1] * row[2]) + fabs(c[k])
            if not fabs(row[3 + k] - o1) <= 1e-10 * scale + 1e-300:
                return False
    det = A[0] * A[3] - A[1] * A[2]
    if not fabs(det) > 1e-12 * (fabs(A[0] * A[3]) + fabs(A[1] * A[2])):
        return False
    ystar[0] = (-A[3] * c[0] + A[1] * c[1]) / det
    ystar[1] = (A[2] * c[0] - A[0] * c[1]) / det
    z[0] = y1[0] - ystar[0]
    z[1] = y1[1] - ystar[1]
    if not _affine_output(r, tm, ystar, w_err, g, &o_rest):
        return False
    U0[0] = _dwell_largest(A, z, g, o_rest, L, &ok)
    if not ok:
        return False
    if not _affine_output(r, tm, ystar, w_acc, g, &o_rest):
        return False
    U0dd[0] = _dwell_largest(A, z, g, o_rest, L, &ok)
    return ok != 0


# -- one record, from Python -------------------------------------------------------------------

cdef class _View:
    """A Rec over a recorded run's arrays, with the buffers it points into kept alive."""
    cdef Rec r
    cdef Ctx ctx
    cdef object keep
    cdef double[::1] p, k, law_par, y, out
    cdef int[::1] law, mode
    cdef const int[::1] part
    cdef double[:, ::1] rows
    cdef const int[:, ::1] modes

    def __init__(self, object capsule, double[::1] p, int[::1] law, double[::1] law_par, rows,
                 modes, int ns, int nx, part=None):
        cdef ModelC* m = _model(capsule)
        self.part = None if part is None else np.array(part, dtype=np.intc)
        check_partition(m, self.part)
        self.keep = capsule
        # rows as the Result keeps them, so that the dense output made in left-out steps
        # (_fill) stays made for the next figure of the run
        arr = np.ascontiguousarray(rows, dtype=float)
        self.rows = arr if arr.flags.writeable else arr.copy()
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
        self.ctx.part = NULL if self.part is None else &self.part[0]
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
        self.r.hermite = False
        self.r.n_hermite = 0
        self.r.n_fill = 0


def extreme(object capsule, double[::1] p, int[::1] law, double[::1] law_par, rows, modes,
            int ns, int nx, int which, double a, double b, bint absolute, bint minimum,
            int per_step=12, int n_cand=1, part=None, double hermite_tol=0.0):
    """(value, time, sampling error, calls) of the extreme of state/output ``which`` (outputs
    after the ns states) on [a, b] of a recorded run (rows as Result keeps them); see the
    module doc and _extreme.  ``calls``: the right-hand-side calls made filling in the DOP853
    dense output the run left out, in place in ``rows`` where they are writable; its scan
    reads the cubic Hermite interpolant there while that is off by at most ``hermite_tol``
    at the peaks (0: 1e-9 of the extreme), else it makes them all.  ``part``: a
    constrained model's coordinate partition (Ctx.part), None for the declared one; so in
    the other functions of a recorded run."""
    if per_step < 1:
        raise ValueError("per_step must be at least 1")
    cdef _View v = _View(capsule, p, law, law_par, rows, modes, ns, nx, part)
    cdef double value = NAN, at = NAN, sampling = 0.0
    cdef int kind = (3 if minimum else 0) if absolute else (2 if minimum else 1)
    if v.r.n == 0:
        raise ValueError("empty record")
    with nogil:
        _extreme(&v.r, which, a, b, kind, per_step, n_cand, NULL, 1, &value, &at, &sampling,
                 NULL, NULL, 0, hermite_tol)
    return value, at, sampling, v.r.n_fill


def fill(object capsule, double[::1] p, int[::1] law, double[::1] law_par, rows, modes,
         int ns, int nx, tq=None, part=None):
    """Make, in place in ``rows`` (writable), the DOP853 dense output the run left out of the
    steps that the times ``tq`` fall in (as dense_eval takes them), or of every step (None);
    returns the right-hand-side calls made."""
    if not (isinstance(rows, np.ndarray) and rows.flags.writeable and rows.flags.c_contiguous):
        raise ValueError("rows must be a writable C-contiguous array")
    cdef _View v = _View(capsule, p, law, law_par, rows, modes, ns, nx, part)
    cdef double[::1] times = np.ascontiguousarray(tq if tq is not None else [], dtype=float)
    cdef Py_ssize_t i, j
    cdef bint every = tq is None
    with nogil:
        if every:
            _fill_between(&v.r, _t(&v.r, 0), _t(&v.r, v.r.n - 1))
        else:
            for j in range(times.shape[0]):
                i = _step_of(&v.r, times[j])
                if i + 1 < v.r.n and _left_out(&v.r, i):
                    _fill(&v.r, i)
    return v.r.n_fill


def crossing(object capsule, double[::1] p, int[::1] law, double[::1] law_par, rows, modes,
             int ns, int nx, int which, double level, part=None):
    """First time state or output ``which`` (outputs after the ns states) reaches ``level``
    (NaN if never)."""
    cdef _View v = _View(capsule, p, law, law_par, rows, modes, ns, nx, part)
    cdef int ok
    cdef double t
    with nogil:
        t = _crossing(&v.r, which, level, &ok)
    return t


def dwell_figures(object capsule, double[::1] p, int[::1] law, double[::1] law_par, rows,
                  modes, int ns, int nx, double t1, double t_end, int i_error, int i_acc, part=None):
    """(U0, U0'') of a run whose dwell [t1, t_end] was stepped over exactly, in closed form
    from the state at t1 (_dwell_closed_form), or None where no closed form applies (more
    than two states, a dwell that is not linear and time invariant, outputs not affine)."""
    cdef _View v = _View(capsule, p, law, law_par, rows, modes, ns, nx, part)
    cdef double u0 = NAN, u0dd = NAN
    cdef bint ok
    if v.r.n == 0 or not v.r.rows[0] <= t1 <= t_end <= v.r.rows[(v.r.n - 1) * v.r.width]:
        raise ValueError("the span must lie in the run")
    with nogil:
        ok = _dwell_closed_form(&v.r, t1, t_end, i_error, i_acc, &u0, &u0dd)
    return (u0, u0dd) if ok else None


# -- a chunk of a sweep -----------------------------------------------------------------------

cdef struct Chunk:
    # what every run of a chunk shares, and the buffers they reuse one after the other
    ModelC* m
    Ctx ctx
    Run run
    int method
    const int* law
    const double* law_par
    double t0
    double h
    double rtol
    const double* atol
    long max_steps
    long max_events
    const int* modes0
    const int* part    # the coordinate partition of the runs (Ctx.part), or NULL
    bint exact
    bint whole         # with exact: a linear interval in one step (Run.exact_whole)
    bint dense         # DOP853: the dense output made as the run goes, else where wanted
    int width
    Py_ssize_t cap
    double* rows
    int* rmode
    double* scratch    # the state, the model's constants and cache, a state and the outputs
    int* mode


cdef int _chunk_open(Chunk* c, ModelC* m, int method, const int* law, const double* law_par,
                     double t0, double h, double rtol, const double* atol, long max_steps,
                     const int* modes0, long max_events, bint exact, Py_ssize_t cap) noexcept:
    """The buffers of a chunk's runs (0), or -1 when memory is short (all freed)."""
    cdef int ns = m.n_states, nm = m.n_modes
    c.m = m
    c.method = method
    c.law = law
    c.law_par = law_par
    c.t0 = t0
    c.h = h
    c.rtol = rtol
    c.atol = atol
    c.max_steps = max_steps
    c.max_events = max_events
    c.modes0 = modes0
    c.part = NULL
    c.exact = exact
    c.whole = False
    c.dense = True
    c.width = 1 + (2 + extra_terms(method, exact)) * ns
    c.cap = cap if cap >= 64 else 64
    c.rows = <double*> malloc(c.cap * c.width * sizeof(double))
    c.rmode = <int*> malloc(c.cap * (nm if nm > 0 else 1) * sizeof(int))
    c.scratch = <double*> malloc((2 * ns + m.n_const + m.n_cache + m.n_outputs + 1) * sizeof(double))
    c.mode = <int*> malloc((nm + 1) * sizeof(int))
    if c.rows == NULL or c.rmode == NULL or c.scratch == NULL or c.mode == NULL:
        _chunk_close(c)
        return -1
    return 0


cdef void _chunk_close(Chunk* c) noexcept nogil:
    free(c.rows)
    free(c.rmode)
    free(c.scratch)
    free(c.mode)
    c.rows = NULL
    c.rmode = NULL
    c.scratch = NULL
    c.mode = NULL


cdef int _chunk_run(Chunk* c, const double* p, const double* y0, const double* stops,
                    int n_stops, double h_max) noexcept nogil:
    """One run of the chunk from y0 with parameters p to the last of its stops, recorded in the
    chunk's buffer (grown as needed and kept for the next run); its status."""
    cdef ModelC* m = c.m
    cdef int ns = m.n_states, nm = m.n_modes, ncam = m.n_instances, j, status
    memcpy(c.scratch, y0, ns * sizeof(double))
    for j in range(nm - ncam):
        c.mode[ncam + j] = c.modes0[j]
    c.ctx.p = p
    c.ctx.k = c.scratch + ns
    c.ctx.cache = c.scratch + ns + m.n_const
    c.ctx.law = c.law
    c.ctx.law_par = c.law_par
    c.ctx.mode = c.mode
    c.ctx.variant = 0
    c.ctx.part = c.part
    c.run.ctx = &c.ctx
    c.run.rec.n = 0
    c.run.rec.cap = c.cap
    c.run.rec.width = c.width
    c.run.rec.n_extra = extra_terms(c.method, c.exact)
    c.run.rec.owned = True       # ours (malloc): the loops may grow and free it
    c.run.rec.rows = c.rows
    c.run.rec.mode = c.rmode
    c.run.method = c.method
    c.run.stops = stops
    c.run.n_stops = n_stops
    c.run.t0 = c.t0
    c.run.y = c.scratch
    c.run.h = c.h
    c.run.h_max = h_max
    c.run.rtol = c.rtol
    c.run.atol = c.atol
    c.run.max_steps = c.max_steps
    c.run.max_events = c.max_events
    c.run.n_events = 0
    c.run.n_steps = 0
    c.run.n_rejected = 0
    c.run.n_rhs = 0
    c.run.t_fail = c.t0
    c.run.err_old = 1e-4
    c.run.t_stiff = NAN
    c.run.stab_mode = 0      # adaptive methods only (checked by the callers)
    c.run.stab_bound = NULL
    c.run.n_stab_bound = 0
    c.run.stab_work = NULL
    c.run.stab_ratio = -1.0
    c.run.n_checks = 0
    c.run.n_jac = 0
    c.run.n_lu = 0
    c.run.exact = c.exact
    c.run.skip_dense = not c.dense   # else made where the figures' scans want it (_fill)
    c.run.exact_whole = c.exact and c.whole
    status = m.run(&c.run)
    # keep the (possibly grown) buffers for the next run
    c.rows = c.run.rec.rows
    c.rmode = c.run.rec.mode
    c.cap = c.run.rec.cap
    return status


cdef void _chunk_record(Chunk* c, Rec* rec) noexcept nogil:
    """A view of the last run's record, to find its figures on."""
    cdef ModelC* m = c.m
    cdef int ns = m.n_states
    rec.m = m
    rec.ctx = &c.ctx
    rec.rows = c.rows
    rec.modes = c.rmode
    rec.n = c.run.rec.n
    rec.ns = ns
    rec.nm = m.n_modes
    rec.width = c.width
    rec.nx = extra_terms(c.method, c.exact)
    rec.y = c.scratch + ns + m.n_const + m.n_cache
    rec.out = rec.y + ns
    rec.hermite = False
    rec.n_hermite = 0
    rec.n_fill = 0


cdef ModelC* _chunk_model(object capsule, int method, const double[:, ::1] P,
                          const double[:, ::1] Y0, const double[::1] atol,
                          const int[::1] modes0) except NULL:
    """The model of a chunk's runs, the arrays' widths checked against it."""
    cdef ModelC* m = _model(capsule)
    if P.shape[1] != m.n_params or Y0.shape[1] != m.n_states or atol.shape[0] != m.n_states:
        raise ValueError("parameter, state or tolerance arrays of the wrong width")
    if modes0.shape[0] != m.n_modes - m.n_instances:
        raise ValueError("one initial mode per force element expected")
    if not adaptive_method(method):
        raise ValueError("the compiled sweep takes the adaptive methods (dp54, dop853, rodas4)")
    return m


def sweep_residual(object capsule, int method, int[::1] law, double[::1] law_par,
                   const double[:, ::1] P, const double[:, ::1] Y0, const double[:, ::1] stops,
                   const int[::1] n_stops, double t0, double h, double h_max, double rtol,
                   const double[::1] atol, long max_steps, const int[::1] modes0, long max_events,
                   int i_error, int i_acc, double rise_end, int i_rise, int per_step, int n_cand,
                   double[:, ::1] figures, long[:, ::1] stats, double[::1] seconds,
                   Py_ssize_t start, Py_ssize_t stop, Py_ssize_t cap=4096, int stride=1,
                   bint figures_too=True, bint exact=False, const int[::1] run_which=None,
                   const int[::1] run_kind=None, double[:, ::1] run_figures=None,
                   const int[::1] part=None, int rise_per_step=0):
    """Run parameter sets start..stop-1 (rows of P, initial states Y0, stop times) and write
    the FIGURE_COLUMNS of each into ``figures`` and the STAT_COLUMNS into ``stats``; seconds[j]:
    wall time of run j with its figures.  i_error, i_acc: the error and acceleration outputs
    (index among states then outputs); i_rise: the state whose crossing of rise_end ends the
    rise, or -1 (the rise ends at time rise_end).  With per_step 1 the scan samples every
    ``stride``-th recorded point (its peaks are refined between the samples around them).
    ``rise_per_step``: the rise's own density (0: per_step), for a dwell scanned more densely
    than the rise needs.
    ``figures_too`` False: integrate only (bench/sweep.py splits the cost with it).  ``exact``:
    intervals where the model is linear and time invariant are stepped over exactly
    (runtime/engine/loops.pxi, _loop_exact), as Simulator(exact_segments=True) does; a run
    whose U0 and U0'' then come in closed form from the state at the end of the rise
    (_dwell_closed_form) takes each such interval in one step (Run.exact_whole), and a run
    whose dwell has no closed form is run again with it recorded step by step.
    ``run_which``, ``run_kind``: extremes over the whole run besides (state or output, score
    as :func:`sweep_extremes` takes them), found as :func:`extreme` finds them on a recorded
    run (12 samples a step, the best refined: the same bits); value and sampling error of
    extreme k into run_figures[g, 2k] and [g, 2k + 1].  ``part``: a constrained model's
    coordinate partition (Ctx.part) for every run, None for the declared one.  No GIL is held
    while it runs.

    A run that fails leaves its status (runtime/driver.STATUS_TEXT) and NaN figures; a run
    whose span does not cover the rise and part of the dwell after it, status -1."""
    cdef ModelC* m = _chunk_model(capsule, method, P, Y0, atol, modes0)
    check_partition(m, part)
    if figures.shape[1] != len(FIGURE_COLUMNS):
        raise ValueError(f"figures must have {len(FIGURE_COLUMNS)} columns (FIGURE_COLUMNS)")
    if per_step < 1 or not (0 < n_cand <= MAX_CAND) or stride < 1:
        raise ValueError(f"per_step >= 1, stride >= 1 and 1 <= n_cand <= {MAX_CAND}")
    if per_step > 1:
        stride = 1
    # the rise's scan: its own density, or the dwell's
    cdef int rise_ps = rise_per_step if rise_per_step > 0 else per_step
    cdef int n_run = 0 if run_which is None else run_which.shape[0]
    if n_run and (run_kind is None or run_kind.shape[0] != n_run or run_figures is None
                  or run_figures.shape[1] != 2 * n_run or run_figures.shape[0] < stop):
        raise ValueError("run_kind (one per run_which) and run_figures (two columns each) "
                         "are needed with run_which")
    cdef Chunk c
    if _chunk_open(&c, m, method, &law[0], &law_par[0], t0, h, rtol, &atol[0], max_steps,
                   &modes0[0] if modes0.shape[0] else NULL, max_events, exact, cap) != 0:
        raise MemoryError()
    c.part = NULL if part is None else &part[0]
    cdef Rec rec
    cdef double* cache = NULL     # error, then acceleration, at every recorded point
    cdef Py_ssize_t ccap = 0
    cdef double* samples = NULL   # the dwell's scan: times, error, acceleration (scap each)
    cdef Py_ssize_t scap = 0, n_samp
    cdef bint closed
    cdef Py_ssize_t g
    cdef int j, status, ok, width = c.width
    cdef double t1, t_end, v, at, samp
    cdef double* rows
    cdef timespec c0, c1
    # the figures of a dwell in closed form need its end state alone: each linear interval in
    # one step, run again recorded step by step where the closed form is not taken
    cdef bint whole = exact and figures_too and n_run == 0 and i_rise < 0
    with nogil:
        for g in range(start, stop):
            clock_gettime(CLOCK_MONOTONIC, &c0)
            c.whole = whole
            while True:
                status = _chunk_run(&c, &P[g, 0], &Y0[g, 0], &stops[g, 0], n_stops[g], h_max)
                stats[g, 0] = status
                stats[g, 1] = c.run.n_steps
                stats[g, 2] = c.run.n_rejected
                stats[g, 3] = c.run.n_rhs
                stats[g, 4] = c.run.rec.n
                for j in range(8):
                    figures[g, j] = NAN
                for j in range(2 * n_run):
                    run_figures[g, j] = NAN
                if status == STATUS_OK and c.run.rec.n > 0 and figures_too:
                    _chunk_record(&c, &rec)
                    rows = c.rows
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
                        n_samp = 0
                        closed = exact and _dwell_closed_form(&rec, t1, t_end, i_error, i_acc, &v,
                                                              &at)
                        if c.whole and not (closed and _recorded_at(&rec, t1)):
                            # the scan needs the dwell recorded step by step: run it again
                            c.whole = False
                            continue
                        if closed:
                            figures[g, 0] = v
                            figures[g, 1] = at
                            figures[g, 5] = 0.0
                            figures[g, 6] = 0.0
                        elif per_step > 1:
                            # U0 and U0'' scan the same span: one evaluation of the outputs a
                            # sample serves both
                            n_samp = _walk(&rec, t1, t_end, per_step, 0, 0, NULL, samples, scap,
                                           i_error, i_acc)
                            if n_samp > scap:
                                free(samples)
                                scap = n_samp + n_samp // 4
                                samples = <double*> malloc(3 * scap * sizeof(double))
                                if samples == NULL:
                                    scap = 0
                                    n_samp = 0
                                else:
                                    _walk(&rec, t1, t_end, per_step, 0, 0, NULL, samples, scap,
                                          i_error, i_acc)
                        if cache != NULL and (rise_ps == 1 or (per_step == 1 and not closed)):
                            # the scans that sample the recorded points alone read them here
                            _fill_cache(&rec, i_error, i_acc, cache, cache + ccap, stride,
                                        INFINITY if per_step == 1 and not closed else t1)
                        if not closed:
                            _extreme(&rec, i_error, t1, t_end, 0, per_step, n_cand, cache, stride,
                                     &v, &at, &samp, samples if n_samp else NULL, samples + scap,
                                     n_samp)
                            figures[g, 0] = v
                            figures[g, 5] = samp
                            _extreme(&rec, i_acc, t1, t_end, 0, per_step, n_cand,
                                     cache + ccap if cache != NULL else NULL, stride, &v, &at, &samp,
                                     samples if n_samp else NULL, samples + 2 * scap, n_samp)
                            figures[g, 1] = v
                            figures[g, 6] = samp
                        _extreme(&rec, i_acc, rows[0] if rows[0] > 0.0 else 0.0, t1, 2, rise_ps,
                                 n_cand, cache + ccap if cache != NULL and rise_ps == 1 else NULL,
                                 stride, &v, &at, &samp)
                        figures[g, 2] = v
                        figures[g, 3] = at
                        figures[g, 7] = samp
                        for j in range(n_run):
                            _extreme(&rec, run_which[j], rows[0], t_end, run_kind[j], 12, 1, NULL,
                                     1, &v, &at, &samp)
                            run_figures[g, 2 * j] = v
                            run_figures[g, 2 * j + 1] = samp
                break
            clock_gettime(CLOCK_MONOTONIC, &c1)
            seconds[g] = (c1.tv_sec - c0.tv_sec) + 1e-9 * (c1.tv_nsec - c0.tv_nsec)
    cap = c.cap
    _chunk_close(&c)
    free(cache)
    free(samples)
    return cap


# the statistics sweep_extremes writes of every run
RUN_STATS = ("status", "n_steps", "n_rejected", "n_rhs", "n_points", "n_events")


def sweep_extremes(object capsule, int method, int[::1] law, double[::1] law_par,
                   const double[:, ::1] P, const double[:, ::1] Y0, const double[:, ::1] stops,
                   const int[::1] n_stops, double t0, double h, const double[::1] h_max,
                   double rtol, const double[::1] atol, long max_steps, const int[::1] modes0,
                   long max_events, const int[::1] which, const int[::1] kind,
                   const int[::1] per_step, const int[::1] n_cand, const double[:, ::1] A,
                   const double[:, ::1] B, double[:, ::1] value, double[:, ::1] at,
                   double[:, ::1] sampling, long[:, ::1] stats, double[::1] t_stiff,
                   int mode_col=-1, int mode_value=0, double[::1] first_in_mode=None,
                   Py_ssize_t cap=4096, bint exact=False, const double[:, ::1] atol_rows=None,
                   const int[::1] part=None, const int[::1] sample_which=None,
                   const double[:, :, ::1] sample_t=None, double[:, :, ::1] sample_v=None,
                   bint dense=True, const double[::1] hermite_tol=None):
    """Run every parameter set (rows of P, initial states Y0, stop tables, h_max per run) and
    find extreme k of each run as :func:`extreme` finds it on a recorded run (the same scan,
    refinement and sampling check, so the same bits): state or output ``which[k]`` on
    [A[g, k], B[g, k]] (-inf: the run's start; +inf: its end; NaN in A: not wanted, NaN
    out), score ``kind[k]`` (0 |v|, 1 v, 2 -v, 3 -|v|), ``per_step[k]`` samples a recorded step,
    ``n_cand[k]`` peaks refined.  value, at, sampling: (n, n_figures); stats: the RUN_STATS;
    t_stiff: where Hairer's stiffness test first fired (NaN: never).  With ``mode_col`` >= 0,
    first_in_mode[g] is the first recorded time whose mode ``mode_col`` (among all modes, the
    cam segments first) is ``mode_value`` (NaN: none).  ``part`` as :func:`sweep_residual`
    takes it.  With ``sample_which``, sample_v[g, k, i] is state or output ``sample_which[k]``
    at time sample_t[g, k, i] on run g's dense output, as Result.sample gives it (NaN where the
    time is NaN or outside the run): what a figure needs of a record besides its extremes
    (runtime/measure/modes.py amplitude_bound).  ``dense`` False: DOP853 leaves its dense
    output out but where an event crosses, and the figures make it where they want it, as a
    Simulator's run with dense_output False and its Result (``hermite_tol[k]`` as
    :func:`extreme` takes it; None: 0).  No GIL is held while it runs.

    A run that fails leaves its status (runtime/driver.STATUS_TEXT) and NaN figures."""
    cdef ModelC* m = _chunk_model(capsule, method, P, Y0, atol, modes0)
    check_partition(m, part)
    cdef Py_ssize_t n = P.shape[0], nf = which.shape[0], g
    cdef int k, status, nm = m.n_modes, ns = m.n_states
    if not (Y0.shape[0] == stops.shape[0] == n_stops.shape[0] == h_max.shape[0] == A.shape[0]
            == B.shape[0] == value.shape[0] == at.shape[0] == sampling.shape[0] == stats.shape[0]
            == t_stiff.shape[0] == n):
        raise ValueError("one row per run expected in every per-run array")
    if not (kind.shape[0] == per_step.shape[0] == n_cand.shape[0] == A.shape[1] == B.shape[1]
            == value.shape[1] == at.shape[1] == sampling.shape[1] == nf):
        raise ValueError("one column per figure expected in every per-figure array")
    if stats.shape[1] != len(RUN_STATS):
        raise ValueError(f"stats must have {len(RUN_STATS)} columns (RUN_STATS)")
    for k in range(nf):
        if not (0 <= which[k] < ns + m.n_outputs and 0 <= kind[k] <= 3 and per_step[k] >= 1
                and 0 < n_cand[k] <= MAX_CAND):
            raise ValueError(f"figure {k}: a state or output, kind 0-3, per_step >= 1 and "
                             f"1 <= n_cand <= {MAX_CAND}")
    if mode_col >= nm or (mode_col >= 0 and (first_in_mode is None or first_in_mode.shape[0] != n)):
        raise ValueError("mode_col must name a mode, with first_in_mode one value per run")
    if atol_rows is not None and (atol_rows.shape[0] != n or atol_rows.shape[1] != ns):
        raise ValueError("atol_rows: one absolute tolerance per state and run")
    if hermite_tol is not None and hermite_tol.shape[0] != nf:
        raise ValueError("hermite_tol: one per figure")
    cdef const double* htol = NULL if hermite_tol is None else &hermite_tol[0]
    cdef Py_ssize_t n_sets = 0 if sample_which is None else sample_which.shape[0], n_times = 0
    if n_sets:
        if (sample_t is None or sample_v is None or sample_t.shape[0] != n
                or sample_t.shape[1] != n_sets or sample_v.shape[0] != n
                or sample_v.shape[1] != n_sets or sample_v.shape[2] != sample_t.shape[2]):
            raise ValueError("sample_t and sample_v: (runs, len(sample_which), times) each")
        n_times = sample_t.shape[2]
        for k in range(n_sets):
            if not 0 <= sample_which[k] < ns + m.n_outputs:
                raise ValueError(f"sample set {k}: a state or output expected")
    cdef Chunk c
    if _chunk_open(&c, m, method, &law[0], &law_par[0], t0, h, rtol, &atol[0], max_steps,
                   &modes0[0] if modes0.shape[0] else NULL, max_events, exact, cap) != 0:
        raise MemoryError()
    c.part = NULL if part is None else &part[0]
    c.dense = dense
    cdef Rec rec
    cdef Py_ssize_t i
    cdef double a, b, v, t, samp
    with nogil:
        for g in range(n):
            if atol_rows is not None:
                c.atol = &atol_rows[g, 0]
            status = _chunk_run(&c, &P[g, 0], &Y0[g, 0], &stops[g, 0], n_stops[g], h_max[g])
            stats[g, 0] = status
            stats[g, 1] = c.run.n_steps
            stats[g, 2] = c.run.n_rejected
            stats[g, 3] = c.run.n_rhs
            stats[g, 4] = c.run.rec.n
            stats[g, 5] = c.run.n_events
            t_stiff[g] = c.run.t_stiff
            if mode_col >= 0:
                first_in_mode[g] = NAN
            for k in range(nf):
                value[g, k] = NAN
                at[g, k] = NAN
                sampling[g, k] = NAN
            for k in range(n_sets):
                for i in range(n_times):
                    sample_v[g, k, i] = NAN
            if status != STATUS_OK or c.run.rec.n == 0:
                continue
            _chunk_record(&c, &rec)
            for k in range(n_sets):
                for i in range(n_times):
                    t = sample_t[g, k, i]
                    if _t(&rec, 0) <= t <= _t(&rec, rec.n - 1):
                        sample_v[g, k, i] = _value_in(&rec, t, _step_of(&rec, t), sample_which[k])
            if mode_col >= 0:
                for i in range(rec.n):
                    if c.rmode[i * nm + mode_col] == mode_value:
                        first_in_mode[g] = _t(&rec, i)
                        break
            for k in range(nf):
                a = A[g, k]
                b = B[g, k]
                if a != a:
                    continue
                if a == -INFINITY:
                    a = _t(&rec, 0)
                if b == INFINITY:
                    b = _t(&rec, rec.n - 1)
                if not (_t(&rec, 0) <= a <= b <= _t(&rec, rec.n - 1)):
                    continue
                _extreme(&rec, which[k], a, b, kind[k], per_step[k], n_cand[k], NULL, 1, &v, &t,
                         &samp, NULL, NULL, 0, 0.0 if htol == NULL else htol[k])
                value[g, k] = v
                at[g, k] = t
                sampling[g, k] = samp
    cap = c.cap
    _chunk_close(&c)
    return cap
