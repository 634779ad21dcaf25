"""Many runs of one model in one compiled call that holds no GIL, each run's extremes found on
its record as :func:`runtime.measure.extremes.extreme` finds them on a Result (the same scan,
refinement and sampling check, runtime/engine/finder.pyx ``sweep_extremes``): the figures of a
chunk of grid points equal, bit for bit, those of the same points run one at a time.

What differs from point to point (parameters, initial state, the run's end and so its stop
times and largest step) is made beforehand in Python, as a table; everything else (method,
tolerances, cam laws, modes) is one Simulator's.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.simulator import Simulator, stop_times
from ..engine import finder
from .extremes import Extreme, column


@dataclass(frozen=True)
class Wanted:
    """An extreme wanted of every run: of state or output ``name``, |v| (``absolute``), its
    least (``minimum``) or largest value, scanned as :func:`extremes.extreme` scans."""

    name: str
    absolute: bool
    minimum: bool
    per_step: int = 12
    candidates: int = 1
    hermite_tol: float = 0.0
    """How far the cubic Hermite interpolant may be off at the peaks for the scan to read it
    in steps whose DOP853 dense output the run left out (0: 1e-9 of the extreme); beyond,
    those steps are made (runtime/engine/finder.pyx, _extreme)."""

    @property
    def kind(self) -> int:
        return (3 if self.minimum else 0) if self.absolute else (2 if self.minimum else 1)


@dataclass
class Runs:
    """The runs of :func:`run_batch`: per run and wanted extreme its value, where it is and its
    sampling error (NaN where not wanted or not reached); the loops' statistics (``stats[name]``
    for finder.RUN_STATS, ``status`` 0 for a run that finished), where DP54's stiffness test
    fired (NaN: never) and the first recorded time in the watched mode (NaN: none)."""

    value: np.ndarray
    at: np.ndarray
    sampling: np.ndarray
    stats: dict
    t_stiff: np.ndarray
    first_in_mode: np.ndarray | None
    samples: np.ndarray | None = None
    """samples[j, k, i]: sampled set k of run j at its i-th time (:func:`run_batch`)."""

    def extreme(self, j: int, k: int) -> Extreme | None:
        v = self.value[j, k]
        return None if v != v else Extreme(float(v), float(self.at[j, k]),
                                           float(self.sampling[j, k]))


def run_batch(sim: Simulator, P: np.ndarray, Y0: np.ndarray, t_end: np.ndarray,
              wanted: tuple, spans: np.ndarray, mode: tuple | None = None,
              atol: np.ndarray | None = None, samples: tuple = (),
              sample_times: np.ndarray | None = None) -> Runs:
    """Run the rows of P from the rows of Y0, each to its own ``t_end`` (its stop times and
    largest step as a Simulator to that end makes them), with ``sim``'s method, laws and modes;
    ``spans[j, k]`` = (a, b) of wanted extreme k in run j (-inf, inf: the run's ends; NaN: not
    wanted).  ``mode`` = (name, value) of a force element's mode to watch for.  ``samples``:
    names of states or outputs, set k of ``sample_times[j, k, :]`` (NaN-padded) sampled on
    run j's dense output as Result.sample samples it, into ``Runs.samples`` (NaN where the
    time is NaN)."""
    m, meth = sim.model, sim.method
    P = np.ascontiguousarray(np.atleast_2d(P), dtype=float)
    n = len(P)
    t_end = np.broadcast_to(np.asarray(t_end, dtype=float), (n,))
    stops = [stop_times(m, p, sim.laws, sim.t0, te) for p, te in zip(P, t_end)]
    width = max(len(s) for s in stops) if n else 1
    S = np.empty((n, width))
    for j, s in enumerate(stops):
        S[j, :len(s)] = s
        S[j, len(s):] = t_end[j]
    h_max = np.minimum(meth.max_step, t_end - sim.t0)
    spans = np.asarray(spans, dtype=float).reshape(n, len(wanted), 2)
    value, at, samp = (np.empty((n, len(wanted))) for _ in range(3))
    stats = np.empty((n, len(finder.RUN_STATS)), dtype=np.int64)
    t_stiff = np.empty(n)
    col, val, first = -1, 0, None
    if mode is not None:
        specs = m.manifest.get("modes", [])
        k = [s["name"] for s in specs].index(mode[0])
        col = len(m.manifest["cam_instances"]) + k
        val = specs[k]["values"].index(mode[1])
        first = np.empty(n)
    which_s = T_s = V_s = None
    if samples:
        which_s = np.array([column(m, name) for name in samples], dtype=np.intc)
        T_s = np.ascontiguousarray(np.asarray(sample_times, dtype=float).reshape(
            n, len(samples), -1))
        V_s = np.empty_like(T_s)
    finder.sweep_extremes(
        m.capsule, meth.code, sim.law_codes, sim.law_pars, P,
        np.ascontiguousarray(Y0, dtype=float), S, np.array([len(s) for s in stops], dtype=np.intc),
        sim.t0, sim.first_step, np.ascontiguousarray(h_max), sim.loop_rtol,
        np.ascontiguousarray(sim.atol, dtype=float), sim.max_steps,
        np.array(sim.modes0, dtype=np.intc), sim.max_events,
        np.array([column(m, w.name) for w in wanted], dtype=np.intc),
        np.array([w.kind for w in wanted], dtype=np.intc),
        np.array([w.per_step for w in wanted], dtype=np.intc),
        np.array([w.candidates for w in wanted], dtype=np.intc),
        np.ascontiguousarray(spans[:, :, 0]), np.ascontiguousarray(spans[:, :, 1]),
        value, at, samp, stats, t_stiff, col, val, first, exact=sim.exact_segments,
        atol_rows=None if atol is None else np.ascontiguousarray(atol, dtype=float),
        part=sim.part, sample_which=which_s, sample_t=T_s, sample_v=V_s,
        dense=sim.integrator.dense,
        hermite_tol=np.array([w.hermite_tol for w in wanted], dtype=float))
    return Runs(value, at, samp, {k: stats[:, i] for i, k in enumerate(finder.RUN_STATS)},
                t_stiff, first, V_s)
