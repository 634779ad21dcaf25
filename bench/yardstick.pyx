# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
"""The yardstick: a hand-written, fully compiled RK4 loop for CAMSHAFT-1.

Thesis (4.15) with the cycloidal rise, written out by hand and inlined into the
loop (no function pointers, no cam-law dispatch, no dense output):

    X'' = (2 pi/tau)^2 (H - X) / (1 + Fa H'^2)
    H = T - sin(2 pi T)/(2 pi),  H' = 1 - cos(2 pi T)   for 0 <= T < 1
    H = 1,                       H' = 0                  for T >= 1 (dwell)

The steps are those of camdyn's RK4: the rise [0, 1] and the dwell [1, t_end]
are integrated separately, each in n = ceil(len/h (1 - 1e-12)) equal steps of
len/n, four right-hand-side evaluations per step.  Like camdyn it records the
state after every step (the breakpoint T = 1 twice, left and right limit) so
that both do the same useful work.

This module is benchmark code only; it is not part of the camdyn package.
"""
from libc.math cimport M_PI, ceil, cos, sin
from posix.time cimport CLOCK_MONOTONIC, clock_gettime, timespec

import numpy as np


cdef inline double accel(double T, double X, double w2, double Fa, bint rise) noexcept nogil:
    """X'' of (4.15); cycloidal H during the rise, H = 1, H' = 0 in the dwell."""
    cdef double c, H, Hd
    if rise:
        c = 2.0 * M_PI * T
        H = T - sin(c) / (2.0 * M_PI)
        Hd = 1.0 - cos(c)
        return w2 * (H - X) / (1.0 + Fa * Hd * Hd)
    return w2 * (1.0 - X)


cdef inline long n_steps(double length, double h) noexcept nogil:
    """Equal steps no longer than h over an interval, as camdyn's RK4 cuts it."""
    cdef long n = <long> ceil(length / h * (1.0 - 1e-12))
    return n if n > 0 else 1


cdef long rk4_interval(double a, double b, double hmax, bint rise, double w2, double Fa,
                       double* s, double* tr, double* yr, long k, bint record) noexcept nogil:
    """Classical RK4 over [a, b]; s = [X, X'] in and out; returns the next record slot."""
    cdef long j, n = n_steps(b - a, hmax)
    cdef double h = (b - a) / n, t = a, X = s[0], V = s[1]
    cdef double kx1, kv1, kx2, kv2, kx3, kv3, kx4, kv4
    if record:
        tr[k] = t
        yr[2 * k] = X
        yr[2 * k + 1] = V
        k += 1
    for j in range(n):
        kx1 = V
        kv1 = accel(t, X, w2, Fa, rise)
        kx2 = V + 0.5 * h * kv1
        kv2 = accel(t + 0.5 * h, X + 0.5 * h * kx1, w2, Fa, rise)
        kx3 = V + 0.5 * h * kv2
        kv3 = accel(t + 0.5 * h, X + 0.5 * h * kx2, w2, Fa, rise)
        kx4 = V + h * kv3
        kv4 = accel(t + h, X + h * kx3, w2, Fa, rise)
        X = X + h / 6.0 * (kx1 + 2.0 * kx2 + 2.0 * kx3 + kx4)
        V = V + h / 6.0 * (kv1 + 2.0 * kv2 + 2.0 * kv3 + kv4)
        t = a + (j + 1) * h if j + 1 < n else b
        if record:
            tr[k] = t
            yr[2 * k] = X
            yr[2 * k + 1] = V
            k += 1
    s[0] = X
    s[1] = V
    return k


def rk4(double tau, double Fa, double h, double t_end=3.0, bint record=True):
    """RK4 from X = X' = 0 at T = 0 to t_end, split at the breakpoint T = 1.

    Returns (t, y, X1, V1): the recorded points (empty when record is False)
    and the state at T = 1, from which U0 is computed.
    """
    cdef double w2 = (2.0 * M_PI / tau) ** 2
    cdef long n = (n_steps(1.0, h) + n_steps(t_end - 1.0, h) + 2) if record else 0
    t_arr = np.empty(n)
    y_arr = np.empty((n, 2))
    cdef double[::1] tr = t_arr
    cdef double[:, ::1] yr = y_arr
    cdef double* tp = &tr[0] if n else NULL
    cdef double* yp = &yr[0, 0] if n else NULL
    cdef double s[2]
    cdef double X1, V1
    cdef long k = 0
    s[0] = 0.0
    s[1] = 0.0
    with nogil:
        k = rk4_interval(0.0, 1.0, h, True, w2, Fa, s, tp, yp, k, record)
        X1 = s[0]
        V1 = s[1]
        k = rk4_interval(1.0, t_end, h, False, w2, Fa, s, tp, yp, k, record)
    return t_arr, y_arr, X1, V1


def rhs_cost_ns(double tau, double Fa, double T, double X, long n):
    """Mean wall time of one inlined evaluation of (4.15) during the rise, in ns."""
    cdef double w2 = (2.0 * M_PI / tau) ** 2, acc = 0.0, tt = T
    cdef timespec a, b
    cdef long k
    with nogil:
        clock_gettime(CLOCK_MONOTONIC, &a)
        for k in range(n):
            acc += accel(tt, X, w2, Fa, True)
            tt += 1e-9  # a new argument each call: nothing can be hoisted
        clock_gettime(CLOCK_MONOTONIC, &b)
    if acc != acc:
        raise FloatingPointError("non-finite acceleration")
    return ((b.tv_sec - a.tv_sec) * 1e9 + (b.tv_nsec - a.tv_nsec)) / n
