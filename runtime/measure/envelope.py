"""Envelopes through the maxima of the response graphs (thesis secs 3.5, 8.2.6; fig. 4.11).

The residual amplitude U0(tau) of a rise and dwell vanishes where the rise time is a multiple
of the natural period (tau = 1/n for the cycloid, (3.5)): the tuning dips.  A designer does
not count on a dip (the parameters are never known that well, sec. 8.2.6) and reads the curve
through the maxima instead: the envelope.  Here it is taken from sampled graphs: every
interior local maximum of the samples, refined by the parabola through it and its two
neighbours (in tau), then joined by straight lines in log(value) between the maxima and held
flat beyond the outermost ones where the graph dips on that side (else the graph is the envelope).  The grid must resolve the dips: :func:`tau_grid` spaces tau
uniformly in 1/tau, in which the dips of (3.5) are equally spaced (one per unit of 1/tau).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.errors import CamdynInputError


def tau_grid(tau_min: float, tau_max: float, n: int) -> np.ndarray:
    """n values of tau from tau_min to tau_max, uniform in 1/tau: the dips of (3.5) at
    tau = 1/k lie one unit of 1/tau apart, so every dip gets n/(1/tau_min - 1/tau_max) points
    (fig. 4.11 spans tau 0.06-0.7: 15 dips)."""
    if not (0 < tau_min < tau_max) or n < 2:
        raise CamdynInputError(f"tau grid {tau_min:g}..{tau_max:g} with {n} points: need "
                               "0 < tau_min < tau_max and at least 2 points")
    return np.sort(1.0 / np.linspace(1.0 / tau_max, 1.0 / tau_min, n))


@dataclass(frozen=True)
class Envelope:
    """The curve through the maxima of a graph: ``tau`` and ``value`` at the maxima, the
    samples themselves (``sample_tau``, ``sample_value``), and ``__call__`` for any tau inside
    the samples: log-linear between maxima and never below the graph.  Beyond the outermost
    maximum the maximum is held flat where the graph dips on that side (on the flank before
    the dip too, so the envelope makes no V); where the graph rises or
    falls away from it without a dip (U0 towards tau = 1 on a stiff camshaft, or a window of a
    graph without dips, as U0 at large Fa, fig. 4.11a) the graph is its own envelope."""

    tau: np.ndarray
    value: np.ndarray
    sample_tau: np.ndarray
    sample_value: np.ndarray

    def __call__(self, tau):
        t = np.asarray(tau, dtype=float)
        graph = np.interp(t, self.sample_tau, self.sample_value)
        through = through_maxima(np.atleast_1d(t), self.tau, self.value,
                                 dips(self.sample_tau, self.sample_value)).reshape(t.shape)
        out = np.where(np.isnan(through), graph, np.maximum(graph, np.nan_to_num(through)))
        return float(out) if out.ndim == 0 else out


def dips(tau, values) -> np.ndarray:
    """tau of the interior local minima of the samples (tau ascending): the tuning dips."""
    t, v = np.asarray(tau, float), np.asarray(values, float)
    return t[1:-1][(v[1:-1] < v[:-2]) & (v[1:-1] <= v[2:])]


def through_maxima(x, mt, mv, dip_tau) -> np.ndarray:
    """The curve through the maxima (mt, mv) at x: log-linear in tau between them; beyond the
    outermost maximum its value held flat where the graph dips (``dip_tau``) beyond that
    maximum, on the flank before the dip as well as past it, else NaN (the graph is its own
    envelope there); NaN everywhere without maxima."""
    x = np.asarray(x, float)
    out = np.full(x.shape, np.nan)
    if len(mt) == 0:
        return out
    inside = (x >= mt[0]) & (x <= mt[-1])
    out[inside] = np.exp(np.interp(x[inside], mt, np.log(mv)))
    # the flank between the outermost maximum and a dip beyond it is held too: reading the
    # graph there made the envelope fall into the dip and rise again (a V between tau = 0.42
    # and 1/2 at Fa = 0, where `camdyn design` found tau = 0.47 met but tau_max = 0.38)
    after, before = np.any(dip_tau > mt[-1]), np.any(dip_tau < mt[0])
    for k in np.flatnonzero(~inside):
        if x[k] > mt[-1] and after:
            out[k] = mv[-1]
        elif x[k] < mt[0] and before:
            out[k] = mv[0]
    return out


def maxima(tau, values) -> tuple[np.ndarray, np.ndarray]:
    """The interior local maxima of the samples (tau ascending), each refined by the parabola
    through it and its neighbours: (tau at the maxima, value there)."""
    t = np.asarray(tau, dtype=float)
    v = np.asarray(values, dtype=float)
    if t.shape != v.shape or t.ndim != 1 or t.size < 3:
        raise CamdynInputError("an envelope needs at least 3 samples of tau and value, alike")
    order = np.argsort(t)
    t, v = t[order], v[order]
    out_t, out_v = [], []
    for i in range(1, t.size - 1):
        if not (v[i] >= v[i - 1] and v[i] > v[i + 1]):
            continue
        x0, x1, x2 = t[i - 1:i + 2]
        y0, y1, y2 = v[i - 1:i + 2]
        # the parabola's vertex (Lagrange form, unequal spacing)
        d = (x0 - x1) * (x0 - x2) * (x1 - x2)
        a = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / d
        b = (x2 ** 2 * (y0 - y1) + x1 ** 2 * (y2 - y0) + x0 ** 2 * (y1 - y2)) / d
        if a < 0:
            xv = -b / (2 * a)
            if x0 <= xv <= x2:
                c = y1 - a * x1 ** 2 - b * x1
                out_t.append(xv)
                out_v.append(max(a * xv ** 2 + b * xv + c, y1))
                continue
        out_t.append(x1)
        out_v.append(y1)
    return np.array(out_t), np.array(out_v)


def envelope_error(tau, values, errors):
    """The error of :func:`envelope` of a sampled graph, as a function of tau: what the
    sampling leaves plus what the samples' own errors (``errors``, the answer contract's) move
    it by.  The first: the envelope of every other sample against that of all (a maximum
    refined from samples twice as far apart moves by more than one refined from all, so this
    bounds it), the largest difference at tau and at the samples on either side of it (the
    two curves cross, so their difference at one point can vanish).  The second: the
    envelope of the values raised by their errors against it.  NaN beyond the outermost
    maxima where the envelope is the outermost maximum held over a dip: a maximum the
    samples just miss at their end could raise it there by any amount (read it from a window
    that brackets tau with maxima); where the graph is its own envelope the estimate stands.
    NaN too where a sample has no estimate."""
    t, v = np.asarray(tau, float), np.asarray(values, float)
    e = np.asarray(errors, float)
    order = np.argsort(t)
    t, v, e = t[order], v[order], e[order]
    full = envelope(t, v)
    half = envelope(t[::2], v[::2]) if t.size >= 6 else None
    raised = envelope(t, v + e) if np.all(np.isfinite(e)) else None

    def gap(x):
        at = full(x)
        return np.abs(half(x) - at) + np.abs(raised(x) - at)

    def error(x):
        x = np.asarray(x, float)
        if half is None or raised is None:
            out = np.full(np.shape(x), np.nan)
        else:
            k = np.clip(np.searchsorted(t, x), 1, t.size - 1)
            out = np.maximum(gap(x), np.maximum(gap(t[k - 1]), gap(t[k])))
            inside = ((x >= full.tau[0]) & (x <= full.tau[-1]) if full.tau.size
                      else np.zeros(np.shape(x), dtype=bool))
            held = through_maxima(np.atleast_1d(x), full.tau, full.value,
                                  dips(full.sample_tau, full.sample_value)).reshape(np.shape(x))
            graph = np.interp(x, full.sample_tau, full.sample_value)
            own = np.isnan(held) | (graph >= np.nan_to_num(held))
            out = np.where(inside | own, out, np.nan)
        return float(out) if np.ndim(out) == 0 else out

    return error


def envelope(tau, values) -> Envelope:
    """The envelope of a sampled graph (module doc); with no interior maximum, the graph."""
    mt, mv = maxima(tau, values)
    t = np.asarray(tau, float)
    order = np.argsort(t)
    t, v = t[order], np.asarray(values, float)[order]
    if np.any(mv <= 0):
        raise CamdynInputError("an envelope of values that are not all positive")
    return Envelope(mt, mv, t, v)
