"""Brent's root finder, a bounded maximum and the not-a-knot cubic spline for `camdyn design`,
without SciPy.

`camdyn design` is meant to answer within a second.  Importing scipy.optimize (brentq,
minimize_scalar) and scipy.interpolate (CubicSpline) took 0.45 s of the 1.1 s a design call
took (SciPy 1.17 rewrites the docstrings of its array-API functions when the packages load);
nothing else of SciPy is needed on that path.  The three jobs are small and classic, so they
are done here, and tests/test_design_numerics.py holds them to SciPy's results.

* :func:`brentq`: Brent's method (R. P. Brent, *Algorithms for Minimization without
  Derivatives*, 1973, ch. 4): inverse quadratic interpolation or a secant step where it stays
  well inside the bracket and shrinks it fast enough, bisection otherwise; it stops when half
  the bracket is within (xtol + rtol |x|)/2, as SciPy's brentq does.
* :func:`maximize`: the largest value of a function unimodal on [lo, hi], by golden-section
  search (J. Kiefer, 1953) to a bracket of xatol.
* :class:`CubicSpline`: the cubic spline through the points with a continuous third derivative
  at the second and the last but one point (not-a-knot, SciPy's default), from the second
  derivatives at the points: a tridiagonal system once the two not-a-knot rows are folded
  into their neighbours, solved by elimination.  Beyond the ends the end pieces continue.
"""
from __future__ import annotations

import numpy as np

EPS = np.finfo(float).eps


def brentq(f, a: float, b: float, xtol: float = 2e-12, rtol: float = 4 * EPS,
           maxiter: int = 100) -> float:
    """A root of f in [a, b], where f(a) and f(b) differ in sign."""
    fa, fb = f(a), f(b)
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if (fa > 0) == (fb > 0):
        raise ValueError("brentq: f(a) and f(b) must differ in sign")
    c, fc = a, fa                   # the other end of the bracket: f(c) and f(b) differ in sign
    d = e = b - a                   # the last step and the one before
    for _ in range(maxiter):
        if (fb > 0) == (fc > 0):
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):       # b the best so far
            a, fa = b, fb
            b, fb = c, fc
            c, fc = a, fa
        tol = 0.5 * (xtol + rtol * abs(b))
        m = 0.5 * (c - b)
        if fb == 0.0 or abs(m) <= tol:
            return b
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:              # two points: the secant
                p, q = 2.0 * m * s, 1.0 - s
            else:                   # three: inverse quadratic interpolation
                q, r = fa / fc, fb / fc
                p = s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0))
                q = (q - 1.0) * (r - 1.0) * (s - 1.0)
            if p > 0:
                q = -q
            else:
                p = -p
            # taken if it lands inside the bracket's better three quarters and halves the
            # step before last; bisection otherwise
            if 2.0 * p < min(3.0 * m * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = m
        else:
            d = e = m
        a, fa = b, fb
        b = b + (d if abs(d) > tol else (tol if m > 0 else -tol))
        fb = f(b)
    raise RuntimeError(f"brentq: no convergence in {maxiter} iterations")


GOLDEN = (3.0 - 5.0 ** 0.5) / 2.0
"""The fraction of the bracket golden-section search cuts off each step."""


def maximize(f, lo: float, hi: float, xatol: float = 1e-10) -> tuple[float, float]:
    """(x, f(x)) at the largest value of f on [lo, hi], f unimodal there."""
    a, b = float(lo), float(hi)
    c, d = a + GOLDEN * (b - a), b - GOLDEN * (b - a)
    fc, fd = f(c), f(d)
    while b - a > xatol:
        if fc >= fd:                # the maximum lies in [a, d]
            b, d, fd = d, c, fc
            c = a + GOLDEN * (b - a)
            fc = f(c)
        else:                       # in [c, b]
            a, c, fc = c, d, fd
            d = b - GOLDEN * (b - a)
            fd = f(d)
    return (c, fc) if fc >= fd else (d, fd)


class CubicSpline:
    """The not-a-knot cubic spline through (x, y), x strictly increasing, at least 3 points."""

    def __init__(self, x, y):
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        if x.ndim != 1 or x.shape != y.shape or x.size < 3 or np.any(np.diff(x) <= 0):
            raise ValueError("CubicSpline: x and y of one length >= 3, x strictly increasing")
        self.x, self.y = x, y
        self.M = self._second_derivatives(x, y)

    @staticmethod
    def _second_derivatives(x, y) -> np.ndarray:
        h = np.diff(x)
        delta = np.diff(y) / h
        n = x.size - 1
        if n == 2:                  # not-a-knot at the only inner point: one parabola
            return np.full(3, 2.0 * (delta[1] - delta[0]) / (x[2] - x[0]))
        # rows i = 1 .. n-1: h[i-1] M[i-1] + 2 (h[i-1] + h[i]) M[i] + h[i] M[i+1] = r[i]
        lo = h[:-1].copy()
        di = 2.0 * (h[:-1] + h[1:])
        up = h[1:].copy()
        r = 6.0 * np.diff(delta)
        # not-a-knot: M0 = ((h0 + h1) M1 - h0 M2)/h1, and likewise at the other end, folded
        # into the first and the last row
        di[0] += h[0] * (h[0] + h[1]) / h[1]
        up[0] -= h[0] * h[0] / h[1]
        di[-1] += h[-1] * (h[-1] + h[-2]) / h[-2]
        lo[-1] -= h[-1] * h[-1] / h[-2]
        m = n - 1
        for i in range(1, m):      # elimination (the system is diagonally dominant)
            w = lo[i] / di[i - 1]
            di[i] -= w * up[i - 1]
            r[i] -= w * r[i - 1]
        inner = np.empty(m)
        inner[-1] = r[-1] / di[-1]
        for i in range(m - 2, -1, -1):
            inner[i] = (r[i] - up[i] * inner[i + 1]) / di[i]
        M = np.empty(n + 1)
        M[1:n] = inner
        M[0] = ((h[0] + h[1]) * M[1] - h[0] * M[2]) / h[1]
        M[n] = ((h[-1] + h[-2]) * M[n - 1] - h[-1] * M[n - 2]) / h[-2]
        return M

    def __call__(self, xs):
        xs = np.asarray(xs, dtype=float)
        x, y, M = self.x, self.y, self.M
        i = np.clip(np.searchsorted(x, xs, side="right") - 1, 0, x.size - 2)
        h = x[i + 1] - x[i]
        a, b = x[i + 1] - xs, xs - x[i]
        return ((M[i] * a**3 + M[i + 1] * b**3) / (6.0 * h)
                + (y[i] / h - M[i] * h / 6.0) * a + (y[i + 1] / h - M[i + 1] * h / 6.0) * b)
