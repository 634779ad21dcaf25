"""The response graphs of fig. 4.11 for any law and Fa, and their envelopes through the maxima.

A designer reads U0(tau, Fa) and U0''(tau, Fa) from the envelopes through the graphs' maxima
(secs 3.5, 8.2.6), never from a tuning dip.  Here the graphs are computed with CAMSHAFT-1
(4.15) for the chosen law on a grid uniform in 1/tau (runtime/measure/envelope.py), so any law
and any Fa can be read, also beyond the printed graphs (tau 0.06-0.7, Fa 0-2).
"""
from __future__ import annotations

import math
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from camdyn.runtime.core import laws
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.measure.envelope import dips, maxima, through_maxima
from camdyn.runtime.targets.grid import default_jobs
from camdyn.runtime.targets.model_target import ModelTarget

from ..numerics import CubicSpline

PER_DIP = 12
"""Samples per unit of 1/tau (one tuning dip of (3.5) at Fa = 0; wider at Fa > 0)."""
LATTICE_CAP = 0.95
"""The largest tau sampled (windows around tau up to limits.TAU_CAP reach beyond it)."""
CHUNK = 32
"""Runs a thread takes at least: fewer are not worth a thread's start."""
METHOD, RTOL = "dop853", 1e-11
"""Method and tolerance of the graph runs: DOP853 (its dwell exact) takes 97 us a run at rtol
1e-11 where DP54 took 204 us at 1e-9, and errs some 10 to 100 times less (RUN_ERROR)."""
RUN_ERROR = (1e-8, 2e-11)
"""A bound on the graph runs' own error in U0, relative and absolute (in units of the stroke),
and the same relative error in U0'': against runs at rtol 1e-13 over tau 0.02-0.85, Fa 0-10
and four laws the error stays within 0.53 of it (1e-11 absolute at tau = 0.02, 3e-6
relative there; below 1e-8 relative from tau = 0.05 on).  DP54 at rtol 1e-9 erred up to
3e-11 absolute, 7e-7 relative at tau = 0.05."""


def run_errors(U0: float, U0dd: float) -> tuple[float, float]:
    """The bound RUN_ERROR on the graph runs' error at a point of the graphs (U0, U0'')."""
    rel = RUN_ERROR[0] + RUN_ERROR[1] / U0
    return rel * U0, rel * U0dd


def phase_factor(law: str, theta, Fa: float) -> float:
    """Mean of (1 + H'^2 Fa)^(-1/2) over the rise: the natural frequency of CAMSHAFT-1 falls
    by this on average (4.32), so its tuning dips lie 1/phase_factor apart in 1/tau."""
    T = np.linspace(0.0, 1.0, 2001)
    hd = laws.choose(law, theta).evaluate(T)[:, 1]
    return float(np.mean((1.0 + hd**2 * Fa) ** -0.5))


class Upper:
    """The envelope through the maxima of a sampled graph, as runtime/measure/envelope.py's Envelope
    draws it (log-linear between the maxima, held flat beyond the outermost one where the
    graph dips on that side, never below the graph), with two refinements the design solver needs: the answer
    is flagged where it rests on a held maximum (the top of the tau range at small Fa,
    :meth:`unbracketed`), and the graph between samples is a spline, not a line.
    Extrapolating the maxima instead (a power law through the outermost two) fails where
    the dips fade out: at Fa = 0.8 the last two
    maxima below tau = 0.15 rise as tau^11.  Between samples the graph is a cubic spline in 1/tau, on whose uniform grid the
    samples lie: near the top of a lobe, where the graph rises above the line through the
    maxima, straight lines would cut the lobe short by ~(pi h)^2/8 (0.9 % at 12 samples per
    dip), the spline by some 1e-5.  The kinks at the dips ring in the spline only over a
    sample or two, where the line through the maxima lies far above the graph anyway."""

    def __init__(self, tau, value):
        t = np.asarray(tau, float)
        v = np.asarray(value, float)
        if t.size < 3 or np.any(v < 0) or np.any(np.diff(t) <= 0):
            raise CamdynInputError("an envelope needs at least 3 samples, tau ascending, values >= 0")
        self.t, self.v = t, v
        self.mt, self.mv = maxima(t, v)
        self._spline = CubicSpline(1.0 / t[::-1], v[::-1])

    def graph(self, tau):
        return np.maximum(self._spline(1.0 / np.asarray(tau, float)), 0.0)

    def through(self, x):
        """runtime/measure/envelope.py's curve through the maxima at x (NaN where the graph is its own
        envelope)."""
        return through_maxima(x, self.mt, self.mv, dips(self.t, self.v))

    def unbracketed(self, tau) -> bool:
        """Is tau beyond the last maximum with a dip in between, the held value above the
        graph there (so that it sets the envelope)?  There the flat hold may lie
        below the curve the maxima to come would draw (at Fa = 0 beyond tau = 0.4: (3.5) dips
        to zero at tau = 1/2 and then rises without a maximum)."""
        if self.mt.size == 0:
            return False
        d = dips(self.t, self.v)
        return bool(tau > self.mt[-1] and np.any((d > self.mt[-1]) & (d <= tau))
                    and self.mv[-1] > self.graph(tau))

    def __call__(self, tau):
        x = np.atleast_1d(np.asarray(tau, float))
        if np.any(x < self.t[0]) or np.any(x > self.t[-1]):
            raise CamdynInputError(f"tau outside the samples {self.t[0]:g}..{self.t[-1]:g}")
        out = self.graph(x)
        through = self.through(x)
        out = np.where(np.isnan(through), out, np.maximum(out, np.nan_to_num(through)))
        return float(out[0]) if np.ndim(tau) == 0 else out


class Graphs:
    """U0 and U0'' of CAMSHAFT-1 (4.15) for one law, run once per (tau, Fa) and kept.

    tau is always taken on the lattice 1/tau = k/per_dip, so windows around different tau
    share their runs.  The runs a window lacks go to compiled code together, as a sweep's
    chunks do (runtime/targets/model_target.py residual_points), on ``jobs`` threads, with
    the sweep's scan; with ``reference`` the scan of a single run, whose figures are those
    of residual() on each run alone, bit for bit (the answers of `camdyn design` differ by
    1e-13 relative at most)."""

    def __init__(self, law: str = "cycloidal", theta=None, per_dip: int = PER_DIP,
                 jobs: int | None = None, reference: bool = False):
        laws.choose(law, theta)
        self.law, self.theta, self.per_dip = law, theta, per_dip
        self.jobs = default_jobs() if jobs is None else jobs
        self._cache: dict = {}
        self._targets: dict = {}
        self._threads = None
        self.reference = reference
        self.runs = 0

    def _target(self, t_end: float) -> ModelTarget:
        if t_end not in self._targets:
            self._targets[t_end] = ModelTarget.of("camshaft1", method=METHOD, rtol=RTOL,
                                                  law=self.law, theta=self.theta, t_end=t_end)
        return self._targets[t_end]

    @staticmethod
    def t_end(tau: float) -> float:
        """Two periods of the dwell or more (its period is tau in T whatever Fa: H' = 0
        there), in steps of 0.1 so that few simulators are prepared."""
        return 1.0 + 0.1 * math.ceil((2.0 * tau + 0.05) / 0.1)

    def _run(self, keys) -> None:
        """Run the (tau, Fa) not yet kept, those of one run end together, in ``jobs`` chunks
        on as many threads (the compiled chunks hold no GIL)."""
        todo: dict = {}
        for key in dict.fromkeys(keys):
            if key not in self._cache:
                todo.setdefault(self.t_end(key[0]), []).append(key)
        for t_end, group in todo.items():
            pts = np.array(group, dtype=float)
            target = self._target(t_end)
            pieces = np.array_split(pts, min(self.jobs, math.ceil(len(pts) / CHUNK)))
            done = self._pool().map(lambda piece: target.residual_points(
                ("tau", "Fa"), piece, reference=self.reference), pieces)
            rows = np.concatenate([b.figures for b in done])
            for (tau, Fa), r in zip(group, rows):
                self._cache[tau, Fa] = (tau, float(r[0]), float(r[1]))
            self.runs += len(group)

    def _pool(self) -> ThreadPoolExecutor:
        if self._threads is None:
            self._threads = ThreadPoolExecutor(max_workers=self.jobs)
        return self._threads

    def point(self, k: int, Fa: float, per_dip: int) -> tuple[float, float, float]:
        """(tau, U0, U0'') at 1/tau = k/per_dip."""
        tau = per_dip / k              # correctly rounded: equal for k/n and 2k/2n
        self._run([(tau, Fa)])
        return self._cache[tau, Fa]

    def samples(self, x_lo: float, x_hi: float, Fa: float, per_dip: int | None = None):
        """(tau, U0, U0'') arrays on the lattice points with x_lo <= 1/tau <= x_hi."""
        n = per_dip or self.per_dip
        ks = range(max(math.ceil(x_lo * n), math.ceil(n / LATTICE_CAP)), math.floor(x_hi * n) + 1)
        self._run([(n / k, Fa) for k in ks])
        pts = np.array([self._cache[n / k, Fa] for k in ks])
        order = np.argsort(pts[:, 0])
        return pts[order, 0], pts[order, 1], pts[order, 2]

    def envelopes(self, x_lo, x_hi, Fa, per_dip=None):
        t, u0, u2 = self.samples(x_lo, x_hi, Fa, per_dip)
        return Upper(t, u0), Upper(t, u2)

    def at(self, tau: float, Fa: float, per_dip: int | None = None, width: float | None = None):
        """(U0_env, U0''_env) at tau: the envelopes of a window of +-1.5 dip spacings around
        tau (``width`` in 1/tau to fix the window, so that it does not move with Fa)."""
        w = 1.5 / phase_factor(self.law, self.theta, Fa) if width is None else width
        x = 1.0 / tau
        e0, e2 = self.envelopes(x - w, x + w, Fa, per_dip)
        return float(e0(tau)), float(e2(tau))
