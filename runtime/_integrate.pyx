# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
"""Compiled integration loops over generated models.

One C function per method (RK4, Dormand-Prince 5(4), the thesis's CAMSHAFT-1
scheme), sharing the trajectory record, the breakpoint handling and the
dense-output representation.  The model is called through the function
pointers of its ModelC (camdyn/runtime/abi.pxd); no Python object is touched
between the start and the end of a run.

Breakpoints.  The caller passes the stop times (cam-law breakpoints in time,
then the end time).  Each interval between stops is integrated on its own:
the cam-law segments (modes) are fixed at its start, steps are shortened to
land on its end, and the state is recorded twice at a stop, once as the left
limit (old modes) and once as the right limit (new modes).

Dense output.  Every step i (from point i to point i + 1) stores four vectors
r1..r4 and the state between is

    y(t_i + s h) = y_i + s (r1 + (1 - s) (r2 + s (r3 + (1 - s) r4)))

(Hairer's continuous extension form).  DP54 fills r4 with its fourth-order
interpolant; RK4 and the thesis scheme use r4 = 0, the cubic Hermite
interpolant of values and slopes at both ends.
"""
from cpython.pycapsule cimport PyCapsule_GetPointer, PyCapsule_IsValid
from libc.math cimport INFINITY, ceil, fabs, fmax, fmin, isfinite, pow, sqrt
from libc.stdlib cimport free, malloc, realloc
from libc.string cimport memcpy, memset
from posix.time cimport CLOCK_MONOTONIC, clock_gettime, timespec

import numpy as np

from camdyn.runtime.abi cimport CAMDYN_ABI, Ctx, ModelC

# method codes, shared with camdyn.runtime.methods
cdef enum:
    M_RK4 = 0
    M_DP54 = 1
    M_KOSTER = 2

RK4 = M_RK4
DP54 = M_DP54
KOSTER = M_KOSTER

# run status codes
cdef enum:
    OK = 0
    MAX_STEPS = 1
    STEP_UNDERFLOW = 2
    NOT_FINITE = 3
    NO_MEMORY = 4
    NO_CONVERGENCE = 5
    BAD_MODEL = 6

STATUS_TEXT = {
    OK: "ok",
    MAX_STEPS: "the step budget (max_steps) was used up",
    STEP_UNDERFLOW: "the step size fell below the resolution of the time axis",
    NOT_FINITE: "the state became non-finite (NaN or inf)",
    NO_MEMORY: "out of memory while recording the trajectory",
    NO_CONVERGENCE: "the mid-step acceleration of the thesis scheme did not converge; use a smaller step",
    BAD_MODEL: "the model is not a purely second-order model, which the thesis scheme requires",
}


cdef ModelC* model_pointer(object capsule) except NULL:
    if not PyCapsule_IsValid(capsule, b"camdyn.ModelC"):
        raise TypeError("expected the MODEL capsule of a generated camdyn model")
    cdef ModelC* m = <ModelC*> PyCapsule_GetPointer(capsule, b"camdyn.ModelC")
    if m.abi_version != CAMDYN_ABI:
        raise RuntimeError(f"generated model built for ABI {m.abi_version}, runtime has {CAMDYN_ABI}; "
                           "rebuild (pip install) after `camdyn derive`")
    return m


# -- trajectory record ---------------------------------------------------------

cdef struct Record:
    Py_ssize_t n
    Py_ssize_t cap
    int ns
    int nm
    double* t
    double* y
    double* dense      # 4 * ns per point: the step that starts there (zero if none)
    int* mode          # nm per point: modes in force from that point on


cdef int rec_init(Record* r, int ns, int nm, Py_ssize_t cap) noexcept nogil:
    r.n = 0
    r.cap = cap if cap > 16 else 16
    r.ns = ns
    r.nm = nm
    r.t = <double*> malloc(r.cap * sizeof(double))
    r.y = <double*> malloc(r.cap * ns * sizeof(double))
    r.dense = <double*> malloc(r.cap * 4 * ns * sizeof(double))
    r.mode = <int*> malloc(r.cap * (nm if nm > 0 else 1) * sizeof(int))
    if r.t == NULL or r.y == NULL or r.dense == NULL or r.mode == NULL:
        return -1
    return 0


cdef void rec_free(Record* r) noexcept nogil:
    free(r.t)
    free(r.y)
    free(r.dense)
    free(r.mode)
    r.t = NULL
    r.y = NULL
    r.dense = NULL
    r.mode = NULL


cdef int rec_push(Record* r, double t, const double* y, const int* mode) noexcept nogil:
    """Append a point; its step coefficients start as zero."""
    cdef Py_ssize_t cap
    cdef void* p
    if r.n == r.cap:
        cap = 2 * r.cap
        p = realloc(r.t, cap * sizeof(double))
        if p == NULL:
            return -1
        r.t = <double*> p
        p = realloc(r.y, cap * r.ns * sizeof(double))
        if p == NULL:
            return -1
        r.y = <double*> p
        p = realloc(r.dense, cap * 4 * r.ns * sizeof(double))
        if p == NULL:
            return -1
        r.dense = <double*> p
        p = realloc(r.mode, cap * (r.nm if r.nm > 0 else 1) * sizeof(int))
        if p == NULL:
            return -1
        r.mode = <int*> p
        r.cap = cap
    r.t[r.n] = t
    memcpy(&r.y[r.n * r.ns], y, r.ns * sizeof(double))
    memset(&r.dense[r.n * 4 * r.ns], 0, 4 * r.ns * sizeof(double))
    if r.nm > 0:
        memcpy(&r.mode[r.n * r.nm], mode, r.nm * sizeof(int))
    r.n += 1
    return 0


cdef inline void hermite(int ns, double h, const double* y0, const double* y1,
                         const double* f0, const double* f1, double* rc) noexcept nogil:
    """Coefficients r1..r4 of the cubic Hermite interpolant (r4 = 0)."""
    cdef int i
    cdef double d, b
    for i in range(ns):
        d = y1[i] - y0[i]
        b = h * f0[i] - d
        rc[i] = d
        rc[ns + i] = b
        rc[2 * ns + i] = d - h * f1[i] - b
        rc[3 * ns + i] = 0.0


cdef inline bint all_finite(int n, const double* y) noexcept nogil:
    cdef int i
    for i in range(n):
        if not isfinite(y[i]):
            return False
    return True


# -- the run: intervals between stops --------------------------------------------

cdef struct Run:
    ModelC* m
    Ctx* ctx
    Record* rec
    int method
    double h           # fixed step (RK4, thesis scheme); initial/last step (DP54)
    double h_max
    double rtol
    const double* atol
    long max_steps
    long n_steps
    long n_rejected
    long n_rhs
    double t_fail
    double err_old     # DP54 PI controller memory


cdef int step_interval_fixed(Run* run, double a, double b, double* y, double* work) noexcept nogil:
    """RK4 or the thesis scheme over [a, b] in equal steps no longer than run.h."""
    cdef ModelC* m = run.m
    cdef int ns = m.n_states, nq = m.n_q
    cdef long k, nstep = <long> ceil((b - a) / run.h * (1.0 - 1e-12))
    if nstep < 1:
        nstep = 1
    cdef double h = (b - a) / nstep, t = a, th, amax, diff, prev
    cdef double* k1 = work
    cdef double* k2 = work + ns
    cdef double* k3 = work + 2 * ns
    cdef double* k4 = work + 3 * ns
    cdef double* yn = work + 4 * ns
    cdef double* f0 = work + 5 * ns
    cdef double* f1 = work + 6 * ns
    cdef double* acc = work + 7 * ns
    cdef double* rc
    cdef int i, it
    if run.method == M_RK4:
        m.rhs(t, y, k1, run.ctx)
        run.n_rhs += 1
    for k in range(nstep):
        if run.n_steps >= run.max_steps:
            run.t_fail = t
            return MAX_STEPS
        rc = &run.rec.dense[(run.rec.n - 1) * 4 * ns]
        if run.method == M_RK4:
            for i in range(ns):
                yn[i] = y[i] + 0.5 * h * k1[i]
            m.rhs(t + 0.5 * h, yn, k2, run.ctx)
            for i in range(ns):
                yn[i] = y[i] + 0.5 * h * k2[i]
            m.rhs(t + 0.5 * h, yn, k3, run.ctx)
            for i in range(ns):
                yn[i] = y[i] + h * k3[i]
            m.rhs(t + h, yn, k4, run.ctx)
            for i in range(ns):
                yn[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
            m.rhs(t + h, yn, k2, run.ctx)  # slope at the new point: next k1
            run.n_rhs += 4
            hermite(ns, h, y, yn, k1, k2, rc)
            memcpy(k1, k2, ns * sizeof(double))
        else:
            # thesis (4.23)-(4.31): acceleration constant over the step, equal to
            # its value at mid-step theta = h/2 with X + dX, dX = X' theta + X'' theta^2/2
            th = 0.5 * h
            m.rhs(t, y, k1, run.ctx)
            run.n_rhs += 1
            for i in range(nq):
                acc[i] = k1[nq + i]
            prev = INFINITY
            for it in range(100):
                for i in range(nq):
                    yn[i] = y[i] + y[nq + i] * th + 0.5 * acc[i] * th * th
                    yn[nq + i] = y[nq + i] + acc[i] * th
                m.rhs(t + th, yn, k2, run.ctx)
                run.n_rhs += 1
                amax = 0.0
                diff = 0.0
                for i in range(nq):
                    diff = fmax(diff, fabs(k2[nq + i] - acc[i]))
                    amax = fmax(amax, fabs(k2[nq + i]))
                    acc[i] = k2[nq + i]
                # converged, or stalled at the rounding level of the acceleration
                if diff <= 1e-13 * (1.0 + amax) or (diff >= prev and diff <= 1e-9 * (1.0 + amax)):
                    break
                prev = diff
            else:
                run.t_fail = t
                return NO_CONVERGENCE
            for i in range(nq):
                yn[nq + i] = y[nq + i] + acc[i] * h                       # (4.28), (4.29)
                yn[i] = y[i] + (y[nq + i] + 0.5 * acc[i] * h) * h         # (4.30), (4.31)
                f0[i] = y[nq + i]
                f1[i] = yn[nq + i]
                f0[nq + i] = acc[i]
                f1[nq + i] = acc[i]
            hermite(ns, h, y, yn, f0, f1, rc)  # exact: X quadratic, X' linear
        if not all_finite(ns, yn):
            run.t_fail = t
            return NOT_FINITE
        t = a + (k + 1) * h if k + 1 < nstep else b
        memcpy(y, yn, ns * sizeof(double))
        run.n_steps += 1
        if rec_push(run.rec, t, y, run.ctx.mode) != 0:
            return NO_MEMORY
    return OK


# Dormand-Prince 5(4) (Dormand & Prince 1980) with Hairer's dense output
cdef double C2 = 1.0 / 5, C3 = 3.0 / 10, C4 = 4.0 / 5, C5 = 8.0 / 9
cdef double A21 = 1.0 / 5
cdef double A31 = 3.0 / 40, A32 = 9.0 / 40
cdef double A41 = 44.0 / 45, A42 = -56.0 / 15, A43 = 32.0 / 9
cdef double A51 = 19372.0 / 6561, A52 = -25360.0 / 2187, A53 = 64448.0 / 6561, A54 = -212.0 / 729
cdef double A61 = 9017.0 / 3168, A62 = -355.0 / 33, A63 = 46732.0 / 5247, A64 = 49.0 / 176
cdef double A65 = -5103.0 / 18656
cdef double B1 = 35.0 / 384, B3 = 500.0 / 1113, B4 = 125.0 / 192, B5 = -2187.0 / 6784
cdef double B6 = 11.0 / 84
cdef double E1 = 71.0 / 57600, E3 = -71.0 / 16695, E4 = 71.0 / 1920, E5 = -17253.0 / 339200
cdef double E6 = 22.0 / 525, E7 = -1.0 / 40
cdef double D1 = -12715105075.0 / 11282082432, D3 = 87487479700.0 / 32700410799
cdef double D4 = -10690763975.0 / 1880347072, D5 = 701980252875.0 / 199316789632
cdef double D6 = -1453857185.0 / 822651844, D7 = 69997945.0 / 29380423


cdef double dp_norm(int ns, const double* v, const double* y0, const double* y1,
                    double rtol, const double* atol) noexcept nogil:
    cdef int i
    cdef double s = 0.0, sc, e
    for i in range(ns):
        sc = atol[i] + rtol * fmax(fabs(y0[i]), fabs(y1[i]))
        e = v[i] / sc
        s += e * e
    return sqrt(s / ns)


cdef double dp_initial_step(Run* run, double t, const double* y, const double* f0,
                            double* y1, double* f1, double span) noexcept nogil:
    """Starting step from the sizes of y, y' and y'' (Hairer, Norsett, Wanner, II.4)."""
    cdef int ns = run.m.n_states, i
    cdef double d0 = dp_norm(ns, y, y, y, run.rtol, run.atol)
    cdef double d1 = dp_norm(ns, f0, y, y, run.rtol, run.atol)
    cdef double h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
    h0 = fmin(h0, span)
    for i in range(ns):
        y1[i] = y[i] + h0 * f0[i]
    run.m.rhs(t + h0, y1, f1, run.ctx)
    run.n_rhs += 1
    for i in range(ns):
        f1[i] = f1[i] - f0[i]
    cdef double d2 = dp_norm(ns, f1, y, y, run.rtol, run.atol) / h0
    cdef double h1
    if fmax(d1, d2) <= 1e-15:
        h1 = fmax(1e-6, h0 * 1e-3)
    else:
        h1 = pow(0.01 / fmax(d1, d2), 0.2)
    return fmin(fmin(100.0 * h0, h1), span)


cdef int step_interval_dp54(Run* run, double a, double b, double* y, double* work) noexcept nogil:
    cdef ModelC* m = run.m
    cdef Ctx* ctx = run.ctx
    cdef int ns = m.n_states, i
    cdef double* k1 = work
    cdef double* k2 = work + ns
    cdef double* k3 = work + 2 * ns
    cdef double* k4 = work + 3 * ns
    cdef double* k5 = work + 4 * ns
    cdef double* k6 = work + 5 * ns
    cdef double* k7 = work + 6 * ns
    cdef double* yn = work + 7 * ns
    cdef double* ys = work + 8 * ns
    cdef double* ev = work + 9 * ns
    cdef double t = a, h, err, fac, hmin
    cdef bint last, rejected = False
    cdef double* rc
    # slopes jump at a breakpoint: start every interval afresh
    m.rhs(t, y, k1, ctx)
    run.n_rhs += 1
    if run.h <= 0.0:
        run.h = dp_initial_step(run, t, y, k1, yn, k2, fmin(b - a, run.h_max))
    h = fmin(run.h, run.h_max)
    run.err_old = 1e-4
    while t < b:
        if run.n_steps + run.n_rejected >= run.max_steps:
            run.t_fail = t
            return MAX_STEPS
        hmin = 16.0 * 2.220446049250313e-16 * fmax(fabs(t), fabs(b))
        if h < hmin:
            run.t_fail = t
            return STEP_UNDERFLOW
        last = t + 1.01 * h >= b
        if last:
            h = b - t
        for i in range(ns):
            ys[i] = y[i] + h * A21 * k1[i]
        m.rhs(t + C2 * h, ys, k2, ctx)
        for i in range(ns):
            ys[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i])
        m.rhs(t + C3 * h, ys, k3, ctx)
        for i in range(ns):
            ys[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i])
        m.rhs(t + C4 * h, ys, k4, ctx)
        for i in range(ns):
            ys[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i])
        m.rhs(t + C5 * h, ys, k5, ctx)
        for i in range(ns):
            ys[i] = y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i])
        m.rhs(t + h, ys, k6, ctx)
        for i in range(ns):
            yn[i] = y[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i])
        m.rhs(t + h, yn, k7, ctx)
        run.n_rhs += 6
        for i in range(ns):
            ev[i] = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i])
        err = dp_norm(ns, ev, y, yn, run.rtol, run.atol)
        if not isfinite(err):
            # a NaN in a trial stage: retry smaller unless the start itself is bad
            if not all_finite(ns, y):
                run.t_fail = t
                return NOT_FINITE
            h *= 0.2
            run.n_rejected += 1
            rejected = True
            continue
        if err <= 1.0:
            # accepted: PI step-size control (Gustafsson), exponents as in Hairer's DOPRI5
            if err == 0.0:
                fac = 10.0
            else:
                fac = 0.9 * pow(err, -0.17) * pow(run.err_old, 0.04)
                fac = fmin(10.0, fmax(0.2, fac))
            if rejected:
                fac = fmin(fac, 1.0)
            run.err_old = fmax(err, 1e-4)
            rc = &run.rec.dense[(run.rec.n - 1) * 4 * ns]
            for i in range(ns):
                rc[i] = yn[i] - y[i]
                rc[ns + i] = h * k1[i] - rc[i]
                rc[2 * ns + i] = rc[i] - h * k7[i] - rc[ns + i]
                rc[3 * ns + i] = h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i]
                                      + D6 * k6[i] + D7 * k7[i])
            t = b if last else t + h
            memcpy(y, yn, ns * sizeof(double))
            memcpy(k1, k7, ns * sizeof(double))
            run.n_steps += 1
            if rec_push(run.rec, t, y, ctx.mode) != 0:
                return NO_MEMORY
            if not last:
                run.h = h
            h = fmin(h * fac, run.h_max)
            rejected = False
        else:
            fac = fmax(0.2, 0.9 * pow(err, -0.2))
            h *= fac
            run.n_rejected += 1
            rejected = True
    return OK


def integrate(object capsule, int method, double[::1] p, int[::1] law, double[::1] law_par,
              double[::1] y0, double t0, double[::1] stops, double h, double h_max,
              double rtol, double[::1] atol, long max_steps):
    """Integrate a generated model from t0 through every stop time.

    Returns a dict: t, y, dense, mode (the record), n_steps, n_rejected,
    n_rhs, status (0 = ok), message, t_fail.
    """
    cdef ModelC* m = model_pointer(capsule)
    cdef int ns = m.n_states, nm = m.n_instances
    if p.shape[0] != m.n_params or y0.shape[0] != ns or atol.shape[0] != ns:
        raise ValueError("parameter, state or tolerance vector of the wrong length")
    if law.shape[0] != m.n_families or law_par.shape[0] != m.n_families:
        raise ValueError("one cam law per cam input family expected")
    if method == M_KOSTER and ns != 2 * m.n_q:
        return {"status": BAD_MODEL, "message": STATUS_TEXT[BAD_MODEL]}
    cdef int[::1] mode = np.zeros(max(nm, 1), dtype=np.intc)
    cdef double[::1] y = np.array(y0, dtype=float)
    cdef double[::1] work = np.zeros(10 * ns)
    cdef Ctx ctx
    ctx.p = &p[0]
    ctx.law = &law[0] if m.n_families > 0 else NULL
    ctx.law_par = &law_par[0] if m.n_families > 0 else NULL
    ctx.mode = &mode[0]
    ctx.work = NULL
    cdef Record rec
    cdef Run run
    run.m = m
    run.ctx = &ctx
    run.rec = &rec
    run.method = method
    run.h = h
    run.h_max = h_max
    run.rtol = rtol
    run.atol = &atol[0]
    run.max_steps = max_steps
    run.n_steps = 0
    run.n_rejected = 0
    run.n_rhs = 0
    run.t_fail = t0
    run.err_old = 1e-4
    cdef int status = OK, k
    cdef double a = t0, b
    cdef Py_ssize_t guess = 64 if method == M_DP54 else <Py_ssize_t> ((stops[stops.shape[0] - 1] - t0) / h) + 8 + 2 * stops.shape[0]
    if rec_init(&rec, ns, nm, guess) != 0:
        rec_free(&rec)
        raise MemoryError("cannot allocate the trajectory record")
    with nogil:
        for k in range(stops.shape[0]):
            b = stops[k]
            if b <= a:
                continue
            m.update_modes(a, &y[0], &ctx)
            if rec_push(&rec, a, &y[0], ctx.mode) != 0:
                status = NO_MEMORY
                break
            if method == M_DP54:
                status = step_interval_dp54(&run, a, b, &y[0], &work[0])
            else:
                status = step_interval_fixed(&run, a, b, &y[0], &work[0])
            if status != OK:
                break
            a = b
    try:
        n = rec.n
        out = {
            "t": np.asarray(<double[:n]> rec.t).copy() if n else np.zeros(0),
            "y": np.asarray(<double[:n * ns]> rec.y).reshape(n, ns).copy() if n else np.zeros((0, ns)),
            "dense": np.asarray(<double[:n * 4 * ns]> rec.dense).reshape(n, 4, ns).copy() if n else np.zeros((0, 4, ns)),
            "mode": (np.asarray(<int[:n * nm]> rec.mode).reshape(n, nm).copy() if n and nm
                     else np.zeros((n, nm), dtype=np.intc)),
        }
    finally:
        rec_free(&rec)
    out.update(n_steps=run.n_steps, n_rejected=run.n_rejected, n_rhs=run.n_rhs, status=status,
               message=STATUS_TEXT[status], t_fail=run.t_fail, h_last=run.h)
    return out


# -- evaluation helpers (vectorized, compiled) ------------------------------------

def dense_eval(double[::1] t, double[:, ::1] y, double[:, :, ::1] dense, double[::1] tq):
    """States at the times tq from the record; returns (Y, step index per query).

    A query on a stop time takes the step that ends there (left limit) unless it
    is the first time of the record.
    """
    cdef Py_ssize_t n = t.shape[0], nq = tq.shape[0], ns = y.shape[1]
    Y = np.empty((nq, ns))
    idx = np.empty(nq, dtype=np.intp)
    cdef double[:, ::1] Yv = Y
    cdef Py_ssize_t[::1] iv = idx
    cdef Py_ssize_t j, lo, hi, mid, i, k
    cdef double s, s1, hh
    if n == 0:
        raise ValueError("empty record")
    for j in range(nq):
        if tq[j] < t[0] or tq[j] > t[n - 1]:
            raise ValueError(f"time {tq[j]} outside the integrated span [{t[0]}, {t[n - 1]}]")
        # last point with t[i] < tq (or the first point)
        lo = 0
        hi = n - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if t[mid] < tq[j]:
                lo = mid
            else:
                hi = mid
        i = lo
        # skip zero-length steps (a stop recorded twice)
        while i + 1 < n and t[i + 1] == t[i]:
            i += 1
        if i + 1 >= n or t[i + 1] <= t[i]:
            for k in range(ns):
                Yv[j, k] = y[i, k]
            iv[j] = i
            continue
        hh = t[i + 1] - t[i]
        s = (tq[j] - t[i]) / hh
        s1 = 1.0 - s
        for k in range(ns):
            Yv[j, k] = y[i, k] + s * (dense[i, 0, k] + s1 * (dense[i, 1, k] + s * (dense[i, 2, k]
                                                                                 + s1 * dense[i, 3, k])))
        iv[j] = i
    return Y, idx


def eval_outputs(object capsule, double[::1] p, int[::1] law, double[::1] law_par,
                 double[::1] t, double[:, ::1] y, mode=None):
    """Outputs at the points (t, y); modes per point, or looked up when None."""
    cdef ModelC* m = model_pointer(capsule)
    cdef Py_ssize_t n = t.shape[0], j
    cdef int nm = m.n_instances
    out = np.empty((n, m.n_outputs))
    cdef double[:, ::1] o = out
    cdef int[::1] md = np.zeros(max(nm, 1), dtype=np.intc)
    cdef int[:, ::1] given
    cdef bint have = mode is not None and nm > 0
    if have:
        given = np.ascontiguousarray(mode, dtype=np.intc)
    cdef Ctx ctx
    ctx.p = &p[0]
    ctx.law = &law[0] if m.n_families > 0 else NULL
    ctx.law_par = &law_par[0] if m.n_families > 0 else NULL
    ctx.mode = &md[0]
    ctx.work = NULL
    if y.shape[1] != m.n_states:
        raise ValueError("state array of the wrong width")
    for j in range(n):
        if have:
            memcpy(&md[0], &given[j, 0], nm * sizeof(int))
        else:
            m.update_modes(t[j], &y[j, 0], &ctx)
        m.outputs(t[j], &y[j, 0], &o[j, 0], &ctx)
    return out


def eval_rhs(object capsule, double[::1] p, int[::1] law, double[::1] law_par,
             double[::1] t, double[:, ::1] y):
    """dy/dt at the points (t, y), cam segments looked up per point."""
    cdef ModelC* m = model_pointer(capsule)
    cdef Py_ssize_t n = t.shape[0], j
    out = np.empty((n, m.n_states))
    cdef double[:, ::1] o = out
    cdef int[::1] md = np.zeros(max(m.n_instances, 1), dtype=np.intc)
    cdef Ctx ctx
    ctx.p = &p[0]
    ctx.law = &law[0] if m.n_families > 0 else NULL
    ctx.law_par = &law_par[0] if m.n_families > 0 else NULL
    ctx.mode = &md[0]
    ctx.work = NULL
    if y.shape[1] != m.n_states:
        raise ValueError("state array of the wrong width")
    for j in range(n):
        m.update_modes(t[j], &y[j, 0], &ctx)
        m.rhs(t[j], &y[j, 0], &o[j, 0], &ctx)
    return out


def rhs_cost_ns(object capsule, double[::1] p, int[::1] law, double[::1] law_par,
                double t, double[::1] y, long n):
    """Mean wall time of one right-hand-side call in ns, over n calls in C."""
    cdef ModelC* m = model_pointer(capsule)
    cdef double[::1] dy = np.zeros(m.n_states)
    cdef int[::1] md = np.zeros(max(m.n_instances, 1), dtype=np.intc)
    cdef Ctx ctx
    cdef timespec a, b
    cdef long k
    cdef double tt = t, acc = 0.0
    ctx.p = &p[0]
    ctx.law = &law[0] if m.n_families > 0 else NULL
    ctx.law_par = &law_par[0] if m.n_families > 0 else NULL
    ctx.mode = &md[0]
    ctx.work = NULL
    m.update_modes(t, &y[0], &ctx)
    with nogil:
        clock_gettime(CLOCK_MONOTONIC, &a)
        for k in range(n):
            m.rhs(tt, &y[0], &dy[0], &ctx)
            acc += dy[m.n_states - 1]
            tt += 1e-9  # defeat hoisting of the call out of the loop
        clock_gettime(CLOCK_MONOTONIC, &b)
    if acc != acc:
        pass
    return ((b.tv_sec - a.tv_sec) * 1e9 + (b.tv_nsec - a.tv_nsec)) / n
