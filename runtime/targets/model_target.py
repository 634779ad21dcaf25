"""A model as a target: a built-in generated model or a user's model file, one run of it.

:class:`ModelTarget` reads the residual-vibration figures the model's manifest declares (U0
(3.5), U0'' (3.6), the largest deceleration in the rise and its T, fig. 4.11) and, where the
model has the outputs, the cam's largest speed deviation and the shaft's largest wind-up
over the run (sec. 5.5.5, fig. 5.6).  :class:`StateTarget` reads the state at the run's end
(any model, `camdyn integrate`).  A grid of parameter sets of a model with an adaptive method
runs in compiled chunks that hold no GIL (runtime/engine/finder.pyx).
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass, replace
from functools import cached_property
from pathlib import Path

import numpy as np

from ..core import methods as _methods
from ..core.errors import CamdynInputError, SimulationError, on_disk
from ..core.compiled import available, load
from ..core.simulator import Simulator
from ..engine import finder, driver
from ..measure import batch, references
from ..measure.contract import fit_window
from ..measure.extremes import extreme, place_error
from ..measure.modes import slowest_periods
from ..measure.residual import FIGURES as RESIDUAL_FIGURES, residual
from .base import Batch, Figure, Outcome, Parameter, Target, Window

DEFAULT_T_END = 3.0
"""End of a run of a model with a rise, in its time unit: the rise and two rise times of dwell
(T = t/t_m for the thesis's models); longer where a figure's window needs it."""

RUN_EXTREMES = (
    Figure("Bdot_dev_max", "the cam's largest speed deviation max |B' - 1| over the run "
           "(sec. 5.5.5, fig. 5.6)", output="Bdot_dev", dwell=True),
    Figure("windup_max", "the shaft's largest wind-up max (T - B) over the run (sec. 5.5.5, "
           "fig. 5.6)", output="windup", dwell=True),
)
"""Figures over the whole run, for a model that has their output (CAMSHAFT-2)."""
RUN_WANTED = {f.name: batch.Wanted(f.output, absolute=f.name == "Bdot_dev_max", minimum=False)
              for f in RUN_EXTREMES}
"""How each of RUN_EXTREMES is found: the largest |B' - 1| and T - B, scanned as a single run's
extremes are (12 samples a step, the best refined), in a run and in a grid's chunk alike."""

SAMPLES = 20.0
CANDIDATES = 4
"""A grid's compiled scan takes about SAMPLES x rtol^(1/5) samples a recorded step (every
stride-th recorded point, or several a step at loose tolerances; :func:`scan_density`) and
refines its CANDIDATES best peaks on the dense output, then checks the others
(runtime/engine/finder.pyx)."""


# recorded points per period of the fastest mode that carries amplitude, at least, as
# (factor, p) of factor rtol^(-1/p): DP54's error per step goes as h^5, and CAMSHAFT-1 at rtol
# 1e-9 takes 87 steps a period at tau = 0.06 (fig. 4.11's fastest), 1.4 rtol^(-1/5); DOP853's
# as h^8, and its fewest over tau 0.06-0.15, Fa 0-10, rtol 1e-6-1e-12 (the exact dwell's
# points included) are 0.47 rtol^(-1/8), 8.4 a period at rtol 1e-9; RKN12's as h^11, its
# fewest over the same grid 0.39 rtol^(-1/12) (3.9 a period at tau 0.06, Fa 10, rtol 1e-12)
POINTS_PER_PERIOD = {"dop853": (0.45, 8.0), "rkn12": (0.37, 12.0)}


RISE_SAMPLES = 18.0
"""Samples a period of the fastest mode in the rise's scan where the steps are sparser than
that: the parabola through three samples then stands within 3.4e-4 of the peak of a sine it
samples (14 a period: 9.4e-4), so that no peak the finder's 1e-3 cut-off passes over can be
the deepest (runtime/engine/finder.pyx, _extreme).  The dwell's scan takes more (1.4
SAMPLES, within 6e-5), its peaks being all equal where it is undamped."""


def scan_density(method) -> tuple[int, int, int]:
    """(per_step, stride, rise_per_step) of a grid's compiled scan: about 1.4 SAMPLES (28)
    samples a period of the fastest mode in the dwell and RISE_SAMPLES in the rise, whatever
    the method's step density (POINTS_PER_PERIOD; DP54's rule for the others): DP54 every 3rd
    recorded point at rtol 1e-9 (the rise too), every point at 1e-8, 2 a step at 1e-6; DOP853
    5 a step at rtol 1e-9, 3 in the rise."""
    factor, p = POINTS_PER_PERIOD.get(method.name, (1.4, 5.0))
    points = factor * method.rtol ** (-1.0 / p)       # recorded points a period, at least
    k = points / 1.4
    if k >= SAMPLES:
        return 1, int(k // SAMPLES), 0
    return math.ceil(SAMPLES / k), 1, math.ceil(RISE_SAMPLES / points)


def model_file(name: str, scenes: bool = False) -> Path | None:
    """The model file ``name`` names, checked on disk without opening it (runtime/core/errors.py
    on_disk); None where ``name`` is no path on disk and does not end in .py (a built-in
    model's name, or with ``scenes`` a scene file (.toml) or a built-in scene's).  Refused in
    one line naming the path: a missing .py file, a folder, named pipe, device or socket, a
    file that is not .py (nor, with ``scenes``, .toml), a file this process may not read."""
    what = on_disk(name)
    allowed = "a model file (.py) or a scene file (.toml)" if scenes else "a model file (.py)"
    if what is None:
        if name.endswith(".py"):
            raise CamdynInputError(f"{name}: no such model file")
        return None
    if what != "file":
        if name.replace("-", "_") in available() and not name.endswith(".py"):
            return None      # a folder that happens to bear a built-in model's name
        raise CamdynInputError(f"{name} is a {what}, not {allowed}")
    path = Path(name)
    if scenes and path.suffix == ".toml":
        return None
    if path.suffix != ".py":
        raise CamdynInputError(f"{name}: neither a model file (.py) nor a scene file (.toml)"
                               if scenes else f"{name}: not a model file (a .py file defining "
                               "build())")
    if not os.access(path, os.R_OK):
        raise CamdynInputError(f"{name}: cannot read the model file (permission denied)")
    return path


def model_ref(name: str) -> str:
    """A built-in model's name (one-dof and one_dof both work) or a model file's absolute path
    (a Dask worker may run elsewhere); a CamdynInputError for anything else."""
    path = model_file(name)
    if path is not None:
        return str(path.resolve())
    if name.replace("-", "_") in available():
        return name.replace("-", "_")
    raise CamdynInputError(f"MODEL {name!r} is neither a model file (.py) nor a built-in model "
                           f"({built_in_names()})")


def built_in_names() -> str:
    """The built-in models in words short enough for a one-line error: the thesis's and the
    paper's by name, the DYNACAM variants and the beam's modes counted (camdyn integrate
    --help and camdyn scenes list them)."""
    names = available()
    dynacam = [n for n in names if n.startswith("dynacam_")]
    beams = [n for n in names if n.startswith("beam") and n[4:].isdigit()]
    rest = [n for n in names if n not in dynacam and n not in beams]
    return (", ".join(rest) + (f", beam1-beam{len(beams)}" if beams else "")
            + (f" and {len(dynacam)} DYNACAM variants" if dynacam else ""))


def load_ref(ref: str, progress=None):
    """The compiled model of a reference made by :func:`model_ref` (a model file is built on
    first use, runtime/core/ondemand.py)."""
    if ref.endswith(".py"):
        from ..core import ondemand

        return ondemand.model_file(ref, progress)
    return load(ref)


def parameters_of(model) -> dict:
    """The model's parameters as its manifest declares them."""
    out = {}
    for spec in model.manifest["parameters"]:
        out[spec["name"]] = Parameter(spec["name"], spec.get("unit", ""), spec.get("doc", ""),
                                      -math.inf if spec["low"] is None else spec["low"],
                                      math.inf if spec["high"] is None else spec["high"],
                                      spec["open_low"], spec["open_high"])
    return out


def _hashable_names(names) -> tuple:
    """Names given as a sequence or one comma-separated string, as a tuple (a frozen target's
    field); anything else is kept for Simulator to refuse by name."""
    if names is None:
        return ()
    if isinstance(names, str):
        return tuple(n.strip() for n in names.split(","))
    try:
        return tuple(names)
    except TypeError:
        return (names,)


def _hashable_law(law):
    return tuple(sorted(law.items())) if isinstance(law, dict) else law


@dataclass(frozen=True)
class ModelTarget(Target):
    """One run of a model from its declared start (or ``initial`` values) to ``t_end``.

    ref         a built-in model's name or a model file's absolute path (:func:`model_ref`)
    params      (name, value) pairs given; the others take the manifest's defaults
    method_name dp54, dop853, rodas4 (rtol), rk4, koster (step)
    t_end       the run's end in the model's time; None: DEFAULT_T_END, or longer where a
                figure's window needs it (``end_given`` says the user chose it)
    law, theta  the cam law of the inputs (a name, a composed full turn, or {family: name})
    atol, state_atol
                an adaptive method's absolute tolerances (runtime/core/methods.py DP54):
                atol in units of each state's tolerance scale, state_atol (name, value) pairs
                in the state's own units
    max_steps   the step budget of a run (None: the Simulator's); the run one notch tighter
                of an error estimate has the same budget
    dependent   a constrained model's dependent coordinates (names; empty: the declared ones),
                Simulator's ``dependent``
    exact       step over linear, time-invariant intervals with their exact propagator
                (Simulator's ``exact_segments``; None: the method's default)
    """

    ref: str
    params: tuple = ()
    method_name: str = "dp54"
    rtol: float | None = None
    step: float | None = None
    t_end: float | None = None
    end_given: bool = False
    law: object = "cycloidal"
    theta: float | None = None
    initial: tuple = ()
    label: str = ""
    atol: float | None = None
    state_atol: tuple = ()
    max_steps: int | None = None
    dependent: tuple = ()
    exact: bool | None = None

    kind = "model"
    chunk = 32
    """Grid points per compiled call at least (runtime/targets/grid.py default_chunk makes
    them larger on a large grid)."""

    @classmethod
    def of(cls, name: str, params: dict | None = None, *, method: str = "dp54", rtol=None,
           step=None, t_end=None, law="cycloidal", theta=None, initial: dict | None = None,
           label: str = "", progress=None, atol=None, state_atol=None, max_steps=None,
           dependent=None, exact=None):
        """The target of a model named on the command line or in code, checked: parameters
        in range, the method's options, the cam law, the initial values, the tolerances."""
        t = cls(model_ref(str(name)), (), method, rtol, step,
                None if t_end is None else float(t_end), t_end is not None,
                _hashable_law(law), theta, tuple(sorted((initial or {}).items())), label,
                atol, tuple(dict(state_atol or {}).items()), max_steps,
                _hashable_names(dependent), exact)
        t.load(progress)
        t = t.with_parameters(params or {})
        t.method()
        t.simulator          # the law, the initial values and the span checked now
        return t

    # -- description ---------------------------------------------------------------------

    def load(self, progress=None):
        return load_ref(self.ref, progress)

    @cached_property
    def model(self):
        return self.load()

    @property
    def name(self) -> str:
        return self.model.name

    @property
    def title(self) -> str:
        return self.label or self.model.manifest.get("title", self.model.name)

    @property
    def values(self) -> dict:
        return dict(self.params)

    def parameters(self) -> dict:
        return parameters_of(self.model)

    @cached_property
    def spec(self) -> dict:
        """The manifest's residual-vibration declaration: error and acceleration outputs, the
        end of the rise."""
        spec = self.model.manifest.get("residual")
        if not spec:
            raise CamdynInputError(f"model {self.model.name} declares no residual-vibration "
                                   "outputs; use one that does (camshaft1, camshaft2, one_dof, "
                                   "...), or camdyn integrate for the state at t_end")
        return spec

    def figures(self) -> tuple:
        spec = self.spec
        out = (Figure("U0", "amplitude of the positional error after the rise (3.5)",
                      output=spec["error"], dwell=True),
               Figure("U0dd", "amplitude of the residual acceleration after the rise (3.6)",
                      output=spec["acceleration"], dwell=True),
               Figure("Xdd_min_rise", "largest deceleration in the rise (fig. 4.11b)"),
               Figure("T_at_Xdd_min", "where it is (fig. 4.11c)", place=True))
        return out + tuple(f for f in RUN_EXTREMES if f.output in self.model.output_names)

    @property
    def end(self) -> float:
        return DEFAULT_T_END if self.t_end is None else self.t_end

    # -- variations --------------------------------------------------------------------------

    def with_parameters(self, values: dict):
        if not values:
            return self
        self.model.parameter_vector(values)           # names and ranges, named in the message
        merged = {**dict(self.params), **{k: float(v) for k, v in values.items()}}
        return replace(self, params=tuple(sorted(merged.items())))

    def with_settings(self, **changes):
        if "t_end" in changes and "end_given" not in changes:
            changes["end_given"] = changes["t_end"] is not None
        end = changes.get("t_end")
        if end is not None:
            if not (isinstance(end, (int, float)) and math.isfinite(end) and end > 0):
                raise CamdynInputError(f"t_end={end!r} must be a finite number > 0")
            rise_end = (self.model.manifest.get("residual") or {}).get("rise_end")
            if rise_end is not None and type(self) is not StateTarget and not end > rise_end:
                raise CamdynInputError(f"t_end={end:g} must exceed the end of the rise, "
                                       f"{rise_end:g}")
        if "method" in changes:
            changes["method_name"] = changes.pop("method")
        if "law" in changes:
            changes["law"] = _hashable_law(changes["law"])
        if "state_atol" in changes:
            changes["state_atol"] = tuple(dict(changes["state_atol"] or {}).items())
        out = replace(self, **changes)
        if changes.get("atol") is not None or changes.get("state_atol"):
            out.method()                # the tolerances checked now, not at the first run
        return out

    def method(self):
        # an adaptive method without rtol takes methods.DEFAULT_RTOL
        return _methods.make(self.method_name, rtol=self.rtol, step=self.step, atol=self.atol,
                             state_atol=self.state_atol)

    def tighter(self):
        m = self.method().tighter()
        if m is None:
            return None
        if not m.adaptive:
            return replace(self, rtol=None, step=m.step)
        return replace(self, rtol=m.rtol, step=None, atol=m.atol, state_atol=m.state_atol)

    def default_step(self) -> float:
        """A fixed step of 1/100 of the shortest period of the dwell's modes: the thesis's
        fine step 0.01 tau for the one-DOF model and CAMSHAFT-1 (sec. 4.4.2), 0.01 min(tau,
        tau_b) for CAMSHAFT-2, whose flywheel period is tau_b = tau (Fa/Fv)^(1/2) (5.19)."""
        sim = Simulator(self.model, self.end, "dp54", law=self._law, theta=self.theta,
                        y0=self._y0, dependent=self.dependent or None)
        p = self.model.parameter_vector(self.values)
        J = driver.eval_jacobian_fd(self.model.capsule, p, sim.law_codes, sim.law_pars,
                                        np.zeros(1), sim.initial_state(p)[None, :],
                                        np.ascontiguousarray(self.model.state_scales()),
                                        part=sim.part)[0]
        lam = np.linalg.eigvals(J)
        osc = lam.imag[lam.imag > 1e-9 * np.abs(lam)]
        if not osc.size:
            raise CamdynInputError(f"argument --step: required for {self.name} (it has no "
                                   "oscillation whose period would set one)")
        return 0.01 * 2 * math.pi / osc.max()

    # -- the run -----------------------------------------------------------------------------

    @property
    def _law(self):
        return dict(self.law) if isinstance(self.law, tuple) else self.law

    @cached_property
    def _y0(self):
        if not self.initial:
            return None
        m = self.model
        y0 = m.initial_state(m.parameter_vector(self.values))
        for name, value in self.initial:
            if name not in m.state_names:
                raise CamdynInputError(f"argument --initial: {m.name} has no state {name}; its "
                                       f"states are {', '.join(m.state_names)}")
            y0[m.state_names.index(name)] = value
        return y0

    @cached_property
    def simulator(self) -> Simulator:
        if not isinstance(self._law, str) and not self.model.manifest.get("cam_instances"):
            # a full turn drives the cam inputs; without one it would be dropped unread
            raise CamdynInputError(f"argument --turn: {self.model.name} has no cam input to drive")
        budget = {} if self.max_steps is None else {"max_steps": self.max_steps}
        return Simulator(self.model, self.end, self.method(), law=self._law, theta=self.theta,
                         y0=self._y0, dependent=self.dependent or None,
                         exact_segments=self.exact, dense_output=True, **budget)

    def window(self) -> Window | None:
        sim = self.simulator
        p = self.model.parameter_vector(self.values)
        return self._window(p[None, :], sim.initial_state(p)[None, :])[0]

    def _window(self, P, Y0):
        """(Window of the worst point, index of that point) over parameter sets P."""
        spec = self.spec
        sim = self.simulator
        dwell = [f for f in self.figures() if f.dwell]
        periods = slowest_periods(self.model, P, sim.law_codes, sim.law_pars, sim.t0, Y0,
                                  [f.output for f in dwell],
                                  np.array(sim.modes0, dtype=np.intc) if sim.modes0 else None)
        worst = int(np.argmax(periods.max(axis=1))) if len(P) else 0
        rise_end = float(spec["rise_end"])
        unit = self.model.manifest["time"]["unit"]
        w = Window(available=self.end - rise_end,
                   needed={f.name: float(periods[worst, k]) for k, f in enumerate(dwell)},
                   setting="t_end", end=self.end, end_for=lambda need: rise_end + need,
                   given=self.end_given, unit="" if unit == "t_m" else unit)
        return w, worst

    def extended(self, needed: float):
        return replace(self, t_end=max(DEFAULT_T_END, float(self.spec["rise_end"]) + needed),
                       end_given=False)

    def run(self, progress=None) -> Outcome:
        c0 = time.process_time()
        res = self.simulator.run(self.values)
        out = self.read(res)
        # integration and figures
        out.stats["cpu_seconds"] = out.record["cpu_seconds"] = time.process_time() - c0
        return out

    def read(self, res) -> Outcome:
        """The figures of a finished run (a camdyn Result, or a SciPy peer's run)."""
        fig = residual(res)
        figures = fig.as_dict()
        sampling = dict(fig.sampling)
        t0, t1 = float(res.t[0]), float(res.t[-1])
        for f in self.figures()[4:]:
            w = RUN_WANTED[f.name]
            e = extreme(res, w.name, t0, t1, absolute=w.absolute, minimum=w.minimum,
                        per_step=w.per_step, candidates=w.candidates)
            figures[f.name] = e.value
            sampling[f.name] = e.sampling_error
        stats = {k: int(v) for k, v in res.stats.items() if k != "seconds"} \
            if hasattr(res, "stats") else {}
        stats["stiff_from_T"] = getattr(res, "stiff_from_T", None)
        record = {"model": self.model.name, **res.params, "law": self._law_name,
                  "method": self.method_name, "t_end": self.end}
        if self.theta is not None or self._law_name == "modified-sine":
            laws = getattr(res, "laws", None)
            if laws is not None:
                record["theta"] = next(iter(laws.values())).par
        record.update(rtol=self.rtol, step=self.step, **figures)
        record.update({k: stats[k] for k in ("n_steps", "n_rejected", "n_rhs") if k in stats})
        record["stiff_from_T"] = stats["stiff_from_T"]
        return Outcome(figures, sampling, {}, list(getattr(res, "warnings", [])), record, stats,
                       res)

    @property
    def _law_name(self):
        law = self._law
        return law if isinstance(law, str) else getattr(law, "key", str(law))

    def references(self) -> dict:
        """Closed forms to print beside the run, where the thesis has them (3.5), (3.6)."""
        return references.beside(self.model.name, self._law_name,
                                 dict(zip(self.model.parameter_names,
                                          self.model.parameter_vector(self.values))))

    # -- a grid ------------------------------------------------------------------------------

    def fit_points(self, names: tuple, points: np.ndarray):
        """Check a grid (names, ranges, the window every point needs) before any run: the
        target itself, or extended to the longest dwell a point needs, or a refusal naming
        the point."""
        self.check_points(names, points)
        P = self._grid_parameters(names, points)
        sim = self.simulator
        Y0 = sim.batch_inputs(P).Y0
        w, worst = self._window(P, Y0)
        return fit_window(self, w, at=", ".join(f"{k} = {v:g}"
                                                for k, v in zip(names, points[worst])))

    def _grid_parameters(self, names, points) -> np.ndarray:
        n = len(points)
        P = np.tile(self.model.parameter_vector(self.values), (n, 1))
        cols = [self.model.parameter_names.index(k) for k in names]
        P[:, cols] = points
        return np.ascontiguousarray(P)

    def run_points(self, names: tuple, points: np.ndarray) -> Batch:
        if not self.simulator.method.adaptive:
            return self._points_one_by_one(names, points)
        return self.residual_points(names, points)

    def _points_one_by_one(self, names, points) -> Batch:
        """Fixed-step methods (their stability check lives in Simulator.run): one run at a
        time, one Simulator; the adaptive methods' points run in compiled chunks
        (:meth:`residual_points`), constrained models and rises that end at an output's
        crossing included."""
        figs = self.figure_names()
        out = np.full((len(points), len(figs)), np.nan)
        samp = np.zeros_like(out)
        warnings, steps = [], np.empty(len(points))
        for j, pt in enumerate(points):
            o = self.read(self.simulator.run({**self.values, **dict(zip(names, map(float, pt)))}))
            out[j] = [o.figures[f] for f in figs]
            samp[j] = [o.sampling.get(f, 0.0) for f in figs]
            warnings.append(list(o.warnings))
            steps[j] = o.stats["n_steps"]
        return Batch(out, samp, warnings, steps)

    def residual_points(self, names, points, reference: bool = False) -> Batch:
        """The residual-vibration figures of every point (a model with an adaptive method whose
        rise ends at a time or where a state or output crosses a level) in one compiled call
        holding no GIL: the sweep's scan (:func:`scan_density`, the CANDIDATES best peaks
        refined), or with ``reference`` the scan of a single run (runtime/measure/residual.py:
        12 samples a step, the best refined), whose figures equal a single run's bit for bit;
        and the extremes over the whole run (RUN_EXTREMES, CAMSHAFT-2's) as :meth:`read` finds
        them on a single run, bit for bit.  A constrained model's points start from their
        consistent states, solved beforehand as Simulator.run solves them (Simulator.start),
        each with the note a single run gives where that moved it."""
        model, sim, spec = self.model, self.simulator, self.spec
        b = sim.batch_inputs(self._grid_parameters(names, points))
        notes = [None] * len(points)
        if hasattr(model.module, "consistent_state"):
            starts = [sim.start(p, y0) for p, y0 in zip(b.P, b.Y0)]
            b = replace(b, Y0=np.ascontiguousarray([y for y, _ in starts], dtype=float))
            notes = [note for _, note in starts]
        n, ns = len(points), len(model.state_names)
        index = {k: i for i, k in enumerate(model.state_names)}
        index.update({k: ns + i for i, k in enumerate(model.output_names)})
        i_rise = index[spec["rise_state"]] if spec.get("rise_state") else -1
        per_step, stride, rise_per_step = (12, 1, 0) if reference else scan_density(sim.method)
        candidates = 1 if reference else CANDIDATES
        figures = np.empty((n, len(finder.FIGURE_COLUMNS)))
        stats = np.empty((n, len(finder.STAT_COLUMNS)), dtype=np.int64)
        secs = np.empty(n)
        extra = self.figures()[len(RESIDUAL_FIGURES):]
        run_figures = np.empty((n, 2 * len(extra)))
        finder.sweep_residual(
            model.capsule, b.method, b.law_codes, b.law_pars, b.P, b.Y0, b.stops, b.n_stops,
            b.t0, b.first_step, b.h_max, b.rtol, b.atol, b.max_steps, b.modes0, b.max_events,
            index[spec["error"]], index[spec["acceleration"]], float(spec["rise_end"]), i_rise,
            per_step, candidates, figures, stats, secs, 0, n, 4096, stride,
            exact=sim.exact_segments, part=b.part, rise_per_step=rise_per_step,
            run_which=np.array([index[RUN_WANTED[f.name].name] for f in extra], dtype=np.intc),
            run_kind=np.array([RUN_WANTED[f.name].kind for f in extra], dtype=np.intc),
            run_figures=run_figures)
        bad = np.flatnonzero(stats[:, 0] != 0)
        if bad.size:
            j = int(bad[0])
            at = ", ".join(f"{k} = {v:g}" for k, v in zip(names, points[j]))
            if stats[j, 0] == -1:
                raise CamdynInputError(f"{model.name} at {at}: the run must cover the rise and "
                                       f"part of the dwell after it (t_end = {sim.t_end:g})")
            why = driver.STATUS_TEXT[int(stats[j, 0])]
            try:        # the failed point alone, through Simulator.run, says why
                sim.run({**self.values, **dict(zip(names, map(float, points[j])))})
            except SimulationError as exc:
                why = str(exc).split(": ", 1)[-1]
            raise SimulationError(f"{model.name} with {sim.method.name} at {at}: {why}")
        col = {c: k for k, c in enumerate(finder.FIGURE_COLUMNS)}
        samp = np.zeros((n, 4 + len(extra)))
        for k, f in enumerate(RESIDUAL_FIGURES[:3]):     # the extremes; the last is a place
            samp[:, k] = figures[:, col[f + "_sampling"]]
        samp[:, 3] = [place_error(t) for t in figures[:, 3]]
        samp[:, 4:] = run_figures[:, 1::2]
        return Batch(np.hstack([figures[:, :4], run_figures[:, 0::2]]), samp,
                     [[note] if note else [] for note in notes], stats[:, 1].astype(float))

    # -- other studies -------------------------------------------------------------------

    def problem(self):
        """The run as a work-precision study takes it (runtime/studies/precision.py)."""
        from .problem import Problem

        return Problem(label=self.title, model=self.model, params=self.values, t_end=self.end,
                       law=self._law, theta=self.theta, y0=self.simulator.initial_state(
                           self.model.parameter_vector(self.values)),
                       read=lambda run: _only(self.read(run).figures, self.scored()),
                       kind=self.kind)


@dataclass(frozen=True)
class StateTarget(ModelTarget):
    """Any model run to ``t_end``: its figures are the states at the end of the run (`camdyn
    integrate`); t_end is required, there being no rise to set it."""

    kind = "model-state"

    def figures(self) -> tuple:
        m = self.model
        spec = {s["name"]: s for s in m.manifest["states"]}
        return tuple(Figure(n, f"state {n} at t_end", spec[n].get("unit", ""),
                            scale=float(spec[n]["scale"])) for n in m.state_names)

    def window(self):
        return None

    fit_points = Target.fit_points      # no dwell to fit: the run ends where the user says

    @property
    def end(self) -> float:
        if self.t_end is None:
            raise CamdynInputError(f"argument --t-end: required for {self.name} (it declares no "
                                   "rise whose dwell would set the run's length)")
        return self.t_end

    def read(self, res) -> Outcome:
        final = res.sample([res.t[-1]])
        figures = {n: float(final[n][0]) for n in self.model.state_names}
        stats = {k: int(v) for k, v in res.stats.items() if k != "seconds"}
        stats["stiff_from_T"] = res.stiff_from_T
        record = {"model": self.model.name, "method": self.method_name, "t_end": self.end,
                  "time_unit": self.model.manifest["time"]["unit"], "state": figures,
                  "n_steps": stats["n_steps"], "n_rhs": stats["n_rhs"],
                  "exact_segments": res.exact_segments}
        if self.model.manifest.get("n_constraints"):
            record["dependent"] = list(res.dependent)
        return Outcome(figures, {}, {}, list(res.warnings), record, stats, res)

    def run_points(self, names, points) -> Batch:
        """An adaptive method's points in one compiled call holding no GIL
        (runtime/measure/batch.py): every state at t_end as :meth:`read` samples it (the same
        numbers, bit for bit); fixed-step methods one at a time (their stability check lives
        in Simulator.run)."""
        sim = self.simulator
        if not sim.method.adaptive:
            return self._points_one_by_one(names, points)
        P = self._grid_parameters(names, points)
        starts = [sim.start(p) for p in P]
        m = self.model
        wanted = tuple(batch.Wanted(k, absolute=False, minimum=False) for k in m.state_names)
        ends = np.full((len(P), len(wanted), 2), sim.t_end)
        runs = batch.run_batch(sim, P, np.array([y for y, _ in starts]), sim.t_end, wanted, ends)
        bad = np.flatnonzero(runs.stats["status"] != 0)
        if bad.size:
            j = int(bad[0])
            sim.run({**self.values, **dict(zip(names, map(float, points[j])))})   # says why
            at = ", ".join(f"{k} = {v:g}" for k, v in zip(names, points[j]))
            raise SimulationError(f"{m.name} with {sim.method.name} at {at}: "
                                  f"{driver.STATUS_TEXT[int(runs.stats['status'][j])]}")
        return Batch(runs.value, np.zeros_like(runs.value),
                     [[note] if note else [] for _, note in starts],
                     runs.stats["n_steps"].astype(float))

    def problem(self):
        from .problem import Problem

        return Problem(label=self.title, model=self.model, params=self.values, t_end=self.end,
                       law=self._law, theta=self.theta,
                       y0=self.simulator.initial_state(self.model.parameter_vector(self.values)),
                       read=lambda run: {}, kind=self.kind)


def _only(figures: dict, names) -> dict:
    return {k: figures[k] for k in names if figures.get(k) is not None}
