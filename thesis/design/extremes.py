"""The largest value of a function of T (a run's dense output, a law's closed form), found on
a grid and refined, with what the refinement and the rounding leave in its value and its place.

A flat maximum is placed only as well as the rounding lets its top be told from its flanks:
with the function's rounding r (the spread of its values a few 1e-11 around the maximum) and
its curvature g'', the place is known to sqrt(4 r/|g''|), which for the check run's X''
(rounding ~2e-13 against g'' ~ 2e3) is some 1e-8 in T, far more than the refinement's
bracket.  Where peaks tie (a follower vibrating evenly in a dwell), the place is any of them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camdyn.thesis.numerics import EPS

XATOL = 1e-9
"""The bracket in T to which an extreme is refined."""

ZOOM = 41
"""Points of each refining grid: each spans two steps of the one before, so that the bracket
shrinks twentyfold a pass, all its points in one call of the function (a run's dense output
answers 41 points about as fast as one)."""

CANDIDATES = 3
"""The grid's largest local maxima refined (a peak the grid rounds off may be a close
second there)."""


@dataclass(frozen=True)
class Extreme:
    """The largest value of a function of T, where it is, what the refinement and the rounding
    leave (``error`` in the value, ``T_error`` in the place), and every local maximum of the
    grid with how high the function may reach near it (for the places that tie)."""

    T: float
    value: float
    error: float
    T_error: float
    peaks_T: np.ndarray
    peaks_top: np.ndarray
    spacing: float

    def farthest_tie(self, allowance: float) -> float:
        """How far from T lies the farthest peak that may come within ``allowance`` of the
        largest value, plus the grid's spacing (0 without one): where peaks tie (a follower
        vibrating evenly in a dwell), the place is any of them."""
        near = self.peaks_top >= self.value - allowance
        near &= np.abs(self.peaks_T - self.T) > self.spacing
        if not near.any():
            return 0.0
        return float(np.max(np.abs(self.peaks_T[near] - self.T))) + self.spacing


NOISE_STEPS = 1e-11 * np.arange(-4, 5)
"""Offsets in T at which the function is sampled around its maximum to see its rounding: its
change there from the curvature is some 1e-19 of g'', far below it."""


def _local_maxima(v: np.ndarray) -> np.ndarray:
    """Indices of the grid's local maxima (ends included), largest first."""
    n = v.size
    if n == 1:
        return np.array([0])
    left = np.r_[True, v[1:] >= v[:-1]]
    right = np.r_[v[:-1] >= v[1:], True]
    idx = np.flatnonzero(left & right)
    return idx[np.argsort(-v[idx], kind="stable")]


def _curvature(T, v, i) -> float:
    """|g''| at the grid's index i from its second difference (0 at an end, or not finite)."""
    if not 0 < i < T.size - 1:
        return 0.0
    h1, h2 = T[i] - T[i - 1], T[i + 1] - T[i]
    c = abs(2 * ((v[i + 1] - v[i]) / h2 - (v[i] - v[i - 1]) / h1) / (h1 + h2))
    return c if math.isfinite(c) else 0.0


def _slope(T, v, i) -> float:
    """|g'| at a grid's end i, from the point next to it."""
    if T.size < 2:
        return 0.0
    j = 1 if i == 0 else T.size - 2
    s = abs(v[j] - v[i]) / abs(T[j] - T[i])
    return s if math.isfinite(s) else 0.0


def zoom(g, lo: float, hi: float) -> tuple[float, float]:
    """(T, g(T)) at the largest value of g on [lo, hi], g unimodal there: grids of ZOOM
    points, each over the two steps around the best of the one before, down to XATOL."""
    x, fx = lo, -math.inf
    while True:
        T = np.linspace(lo, hi, ZOOM)
        v = np.asarray(g(T), dtype=float)
        j = int(np.argmax(v))
        if v[j] > fx:
            x, fx = float(T[j]), float(v[j])
        step = T[1] - T[0]
        if 2 * step <= XATOL:
            return x, fx
        lo, hi = max(lo, x - step), min(hi, x + step)


def largest(g, grids) -> Extreme:
    """The largest value of g (T array -> values) over the grids (sorted T arrays, one per
    piece where g is smooth), each grid's CANDIDATES largest local maxima refined by
    zooming in between their neighbours (:func:`zoom`).

    Its errors: the refinement leaves |g''| XATOL^2/2 in the value and XATOL in the place (at a
    piece's end, where the grid starts XATOL/10 inside it, the slope times that); the
    function's rounding, seen as the spread of its values at NOISE_STEPS around the maximum,
    adds that spread to the value and sqrt(4 spread/|g''|) to the place, for a flat maximum
    is placed only as well as the rounding lets its top be told from its flanks."""
    best, at, peaks_T, peaks_top, spacing = None, None, [], [], 0.0
    for T in grids:
        v = np.asarray(g(T), dtype=float)
        order = _local_maxima(v)
        h = float(np.max(np.diff(T))) if T.size > 1 else 0.0
        spacing = max(spacing, h)
        curv = np.array([_curvature(T, v, i) for i in order]) if order.size < 200 else \
            np.full(order.size, _curvature(T, v, order[0]))
        peaks_T.append(T[order])
        with np.errstate(invalid="ignore"):
            peaks_top.append(v[order] + 0.5 * curv * h**2)
        for i in order[:CANDIDATES]:
            lo, hi = T[max(i - 1, 0)], T[min(i + 1, T.size - 1)]
            x, fx = float(T[i]), float(v[i])
            if hi - lo > XATOL:
                xr, fr = zoom(g, lo, hi)
                if fr > fx:
                    x, fx = xr, fr
            if best is None or fx > best[1]:
                best, at = (x, fx), (T, v, i)
    x, fx = best
    T, v, i = at
    if not math.isfinite(fx):
        return Extreme(x, fx, 0.0, XATOL, np.concatenate(peaks_T), np.concatenate(peaks_top),
                       spacing)
    lo, hi = T[0], T[-1]
    around = np.clip(x + NOISE_STEPS * max(1.0, abs(x)), lo, hi)
    vals = np.asarray(g(around), dtype=float)
    noise = float(np.ptp(vals[np.isfinite(vals)])) if np.isfinite(vals).any() else 0.0
    rounding = noise + 8 * EPS * abs(fx)
    curv = _curvature(T, v, i)
    if 0 < i < T.size - 1:
        err = 0.5 * curv * XATOL**2 + rounding
        T_err = XATOL + (math.sqrt(4 * rounding / curv) if curv > 0 else 0.0)
    else:
        err = _slope(T, v, i) * XATOL / 10 + rounding
        T_err = XATOL
    return Extreme(x, fx, err, T_err, np.concatenate(peaks_T), np.concatenate(peaks_top),
                   spacing)


def place_resolution(result, output: str, T: float) -> tuple[float, float]:
    """(rounding, place): the spread of a run's ``output`` at NOISE_STEPS around T, and the
    place's resolution sqrt(4 spread/|g''|) there (g'' from samples 1e-3 apart), for an
    extreme another scan found (the answer contract's)."""
    t0, t1 = float(result.t[0]), float(result.t[-1])
    near = np.clip(T + NOISE_STEPS * max(1.0, abs(T)), t0, t1)
    v = np.asarray(result.sample(near)[output], dtype=float)
    rounding = float(np.ptp(v)) + 8 * EPS * float(np.max(np.abs(v)))
    h = 1e-3
    if T - h < t0 or T + h > t1:
        return rounding, 0.0
    a, b, c = np.asarray(result.sample(np.array([T - h, T, T + h]))[output], dtype=float)
    curv = abs(a - 2 * b + c) / h**2
    return rounding, (math.sqrt(4 * rounding / curv) if curv > 0 else 0.0)
