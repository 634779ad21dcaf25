# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
"""Diagnostic variant of the yardstick that calls camdyn's generated model.

The loop is the yardstick's (bench/yardstick.pyx: RK4, split at T = 1, t and y
recorded per step), but every evaluation of (4.15) goes through the ModelC
function pointer of a generated camdyn model, with the cam-law segment fixed
per interval as camdyn does.  Timing it against the yardstick isolates the
cost of the generated right-hand side; timing camdyn's own loop against it
isolates camdyn's loop and recording overhead.

Benchmark code only, not part of the camdyn package.
"""
from cpython.pycapsule cimport PyCapsule_GetPointer, PyCapsule_IsValid
from libc.math cimport ceil

import numpy as np

from camdyn.runtime.engine.abi cimport CAMDYN_ABI, Ctx, ModelC


cdef inline long n_steps(double length, double h) noexcept nogil:
    cdef long n = <long> ceil(length / h * (1.0 - 1e-12))
    return n if n > 0 else 1


cdef long rk4_interval(ModelC* m, Ctx* ctx, double a, double b, double hmax, double* y,
                       double* tr, double* yr, long k) noexcept nogil:
    """RK4 over [a, b] for a two-state model through its rhs pointer."""
    cdef long j, n = n_steps(b - a, hmax)
    cdef double h = (b - a) / n, t = a
    cdef double k1[2]
    cdef double k2[2]
    cdef double k3[2]
    cdef double k4[2]
    cdef double ys[2]
    cdef int i
    m.update_modes(a, y, ctx)
    tr[k] = t
    yr[2 * k] = y[0]
    yr[2 * k + 1] = y[1]
    k += 1
    for j in range(n):
        m.rhs(t, y, k1, ctx)
        for i in range(2):
            ys[i] = y[i] + 0.5 * h * k1[i]
        m.rhs(t + 0.5 * h, ys, k2, ctx)
        for i in range(2):
            ys[i] = y[i] + 0.5 * h * k2[i]
        m.rhs(t + 0.5 * h, ys, k3, ctx)
        for i in range(2):
            ys[i] = y[i] + h * k3[i]
        m.rhs(t + h, ys, k4, ctx)
        for i in range(2):
            y[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
        t = a + (j + 1) * h if j + 1 < n else b
        tr[k] = t
        yr[2 * k] = y[0]
        yr[2 * k + 1] = y[1]
        k += 1
    return k


def rk4_model(object capsule, double[::1] p, int[::1] law, double[::1] law_par, double h,
              double t_end=3.0):
    """The yardstick's RK4 over [0, 1] and [1, t_end] on a generated model; returns (t, y)."""
    if not PyCapsule_IsValid(capsule, b"camdyn.ModelC"):
        raise TypeError("expected the MODEL capsule of a generated camdyn model")
    cdef ModelC* m = <ModelC*> PyCapsule_GetPointer(capsule, b"camdyn.ModelC")
    if m.abi_version != CAMDYN_ABI or m.n_states != 2 or m.n_instances != 1:
        raise ValueError("a two-state, one-cam-input model of the current ABI is expected")
    cdef long n = n_steps(1.0, h) + n_steps(t_end - 1.0, h) + 2
    t_arr = np.empty(n)
    y_arr = np.empty((n, 2))
    cdef double[::1] tr = t_arr
    cdef double[:, ::1] yr = y_arr
    cdef int mode[1]
    cdef double y[2]
    cdef double kconst[128]
    cdef Ctx ctx
    cdef long k = 0
    ctx.p = &p[0]
    ctx.law = &law[0]
    ctx.law_par = &law_par[0]
    ctx.mode = mode
    ctx.k = kconst
    ctx.cache = kconst + m.n_const
    ctx.variant = 0
    ctx.part = NULL
    if m.n_const + m.n_cache > 128:
        raise ValueError("too many parameter constants for the probe")
    m.prepare(&ctx)
    y[0] = 0.0
    y[1] = 0.0
    with nogil:
        k = rk4_interval(m, &ctx, 0.0, 1.0, h, y, &tr[0], &yr[0, 0], k)
        k = rk4_interval(m, &ctx, 1.0, t_end, h, y, &tr[0], &yr[0, 0], k)
    return t_arr, y_arr
