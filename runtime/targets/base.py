"""What every target is: its parameters with their ranges, its headline figures, its runs.

A target is one thing camdyn can run (a built-in model or a model file, the CAMSHAFT-1
study, a DYNACAM scene, the Rayleigh-beam follower) with every setting of the run decided:
values of its parameters, method and tolerance, time span, cam law.  It is plain data (it
pickles to a Dask worker); what is heavy to make (the compiled model, a prepared Simulator,
a consistent initial state) is made on first use and kept.

Every command reaches the compiled loop through a target:

* ``parameters()``: what may vary (``--set``, a sweep's grid), with units and ranges;
* ``figures()``: the headline figures a run gives, each a :class:`Figure`;
* ``with_parameters(values)``, ``with_settings(...)``: the same target changed, checked;
* ``tighter()``: the same target one notch more accurate, for the error estimate;
* ``window()``: the dwell its figures are read from against the one they need;
* ``run()``: one run, as an :class:`Outcome`;
* ``run_points(names, points)``: many runs over a grid of parameter values, as a
  :class:`Batch` (the model targets do it in compiled code);
* ``problem()``: the run as a work-precision study or a stability map takes it;
* ``main_job(out_dir, answer)``: the files `camdyn run` writes.

The answer contract (runtime/measure/contract.py) is applied to what ``run`` and
``run_points`` return, on every road.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..core.errors import CamdynInputError


@dataclass(frozen=True)
class Parameter:
    """A parameter a user may set: its range as the model's manifest (or the case) declares it."""

    name: str
    unit: str = ""
    doc: str = ""
    low: float = -math.inf
    high: float = math.inf
    open_low: bool = False
    open_high: bool = False
    integer: bool = False

    def admits(self, value: float) -> bool:
        above = self.low < value if self.open_low else self.low <= value
        below = value < self.high if self.open_high else value <= self.high
        ok = math.isfinite(value) and above and below
        return ok and (not self.integer or float(value).is_integer())

    @property
    def range(self) -> str:
        """The range in words: "0 < tau < 1", "Fa >= 0", "any number"."""
        parts = []
        if self.low > -math.inf:
            parts.append(f"{self.low:g} {'<' if self.open_low else '<='} ")
        parts.append(self.name)
        if self.high < math.inf:
            parts.append(f" {'<' if self.open_high else '<='} {self.high:g}")
        text = "".join(parts)
        if text == self.name:
            text = "any number"
        return text + (", whole" if self.integer else "")

    def check(self, value, where: str = "") -> float:
        """``value`` as a float, or a CamdynInputError naming the parameter and its range."""
        if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
            raise CamdynInputError(f"{where}{self.name} must be a number, got {value!r}")
        v = float(value)
        if not self.admits(v):
            doc = f" ({self.doc})" if self.doc else ""
            raise CamdynInputError(f"{where}{self.name}={v:g} is out of range: {self.range}"
                                   f"{' ' + self.unit if self.unit else ''}{doc}")
        return v


@dataclass(frozen=True)
class Figure:
    """A headline figure of a target's runs.

    estimate   "run": its error is estimated (discretisation by a tighter run, sampling by
               the scan that found it, the window it was read from); "exact": it follows from
               the parameters or an eigenproblem, not from the integration, so its error is
               0; "none": a yes or no (a jump occurs), nothing to estimate
    output     the state or output it is read from (for the window it needs), if any
    dwell      read in a dwell after a rise: needs a window of one period of the slowest
               mode its output sees (runtime/measure/modes.py)
    place      where an extreme lies rather than its value: Brent locates it to
               sqrt(eps)|T|, so its error tells of the locator more than of the run (a
               work-precision study does not score it)
    scale      the size below which the figure counts as zero (a state's scale, for a state
               that may end near zero); 0 for an amplitude or extreme, which is judged
               against itself: the contract warns where the estimate exceeds half of
               |figure| + scale (runtime/measure/contract.py)
    """

    name: str
    doc: str = ""
    unit: str = ""
    estimate: str = "run"
    output: str | None = None
    dwell: bool = False
    place: bool = False
    scale: float = 0.0


@dataclass
class Outcome:
    """One run of a target, before the contract adds its error estimates.

    figures    headline figure -> value (None where the run does not reach it)
    sampling   figure -> the sampling error of the scan that found it
    window     figure -> the error of reading it from a dwell shorter than it needs, where
               the dwell could not be extended (runtime/measure/modes.py)
    warnings   what the run says about its own reliability, one line each
    record     everything the command shows, in its order (the JSON's shape)
    stats      steps, right-hand-side calls, CPU seconds, where DP54 found it stiff
    result     the run itself (camdyn.runtime.core.result.Result), for diagrams
    """

    figures: dict
    sampling: dict = field(default_factory=dict)
    window: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)
    record: dict = field(default_factory=dict)
    stats: dict = field(default_factory=dict)
    result: object = None


@dataclass
class Batch:
    """Many runs of a target over grid points, as arrays: figures (n, n_figures) in the order
    of ``target.figures()``, their sampling errors alike, one list of warnings per point,
    steps (n,)."""

    figures: np.ndarray
    sampling: np.ndarray
    warnings: list
    steps: np.ndarray


@dataclass(frozen=True)
class Window:
    """The dwell a target's figures are read from, against the one each needs.

    available  length of the dwell after the rise, in the model's time
    needed     figure -> one period of the slowest mode its output sees (0: none)
    setting    how the user changes the run's end ("t_end", "run.T_end")
    end        the run's end now, in the setting's own units
    end_for    needed length -> the end that setting must reach for it
    given      the end was given by the user (refuse) or defaulted (extend)
    fixed      the dwell ends at the next cam motion, not at the run's end: it cannot be
               extended, and a figure read from it carries an estimate of the error instead
    unit       the time unit, for messages
    """

    available: float
    needed: dict
    setting: str
    end: float
    end_for: object
    given: bool
    fixed: bool = False
    unit: str = ""

    def short(self) -> dict:
        """Figure -> period needed, for every figure whose dwell is shorter than that."""
        return {k: v for k, v in self.needed.items() if v > self.available * (1 + 1e-12)}


class Target:
    """The interface every target implements (module doc); see its subclasses.

    Subclasses are frozen dataclasses; what they make on first use (cached properties: the
    compiled model, a Simulator, an initial state) stays out of their pickles, so that a
    target travels to a Dask worker as plain data and makes them again there."""

    def __getstate__(self):
        from dataclasses import fields

        return {f.name: getattr(self, f.name) for f in fields(self)}

    def __setstate__(self, state):
        self.__dict__.update(state)

    kind = "target"
    """What it is, for the records it writes (report.json's "kind"); never switched on."""

    chunk = 1
    """Grid points per chunk of a grid's runs (runtime/targets/grid.py): one, where each run
    needs Python (a scene's consistent initial state)."""

    time_name = "T"
    """The time its runs' messages name (stiffness notes): T = t/t_m of the rise."""

    name: str
    title: str

    def parameters(self) -> dict:
        raise NotImplementedError

    def figures(self) -> tuple:
        raise NotImplementedError

    def figure_names(self) -> tuple:
        return tuple(f.name for f in self.figures())

    def estimated(self) -> tuple:
        """The figures whose error a tighter run estimates."""
        return tuple(f.name for f in self.figures() if f.estimate == "run")

    def scored(self) -> tuple:
        """The figures a work-precision study scores: those a run decides (not exact, not a
        yes or no, not the place of an extreme)."""
        return tuple(f.name for f in self.figures() if f.estimate == "run" and not f.place)

    def with_parameters(self, values: dict):
        raise NotImplementedError

    def with_settings(self, **changes):
        raise NotImplementedError

    def method(self):
        """The integration method object of the runs (camdyn.runtime.core.methods)."""
        raise NotImplementedError

    def tighter(self):
        """The same target one notch more accurate (rtol/10, half the step), or None."""
        raise NotImplementedError

    def window(self) -> Window | None:
        return None

    def extended(self, needed: float):
        """The same target with its run long enough for a dwell of ``needed``."""
        raise NotImplementedError

    def run(self, progress=None) -> Outcome:
        raise NotImplementedError

    def run_points(self, names: tuple, points: np.ndarray) -> Batch:
        """Runs over grid points (one row of ``points`` per run, columns ``names``): one run
        at a time; targets that can do better (compiled chunks) override this."""
        figs = self.figure_names()
        out = np.full((len(points), len(figs)), np.nan)
        samp = np.zeros((len(points), len(figs)))
        warnings, steps = [], np.empty(len(points))
        for j, pt in enumerate(points):
            o = self.with_parameters(dict(zip(names, map(float, pt)))).run()
            for k, f in enumerate(figs):
                v = o.figures.get(f)
                out[j, k] = np.nan if v is None else float(v)
                samp[j, k] = o.sampling.get(f, 0.0) + o.window.get(f, 0.0)
            warnings.append(list(o.warnings))
            steps[j] = o.stats.get("n_steps", np.nan)
        return Batch(out, samp, warnings, steps)

    def fit_points(self, names: tuple, points: np.ndarray):
        """Check a grid before any run (:meth:`check_points`); the target to run it with."""
        self.check_points(names, points)
        return self

    def check_points(self, names: tuple, points: np.ndarray) -> None:
        """Refuse grid points a run cannot take (names, ranges, the window), before any run."""
        allowed = self.parameters()
        for k, name in enumerate(names):
            if name not in allowed:
                raise CamdynInputError(
                    f"grid {name}: not a parameter of {self.name}; its parameters are "
                    + ", ".join(f"{p.name} ({p.range})" for p in allowed.values()))
            for v in np.unique(points[:, k]):
                allowed[name].check(float(v), "grid ")

    def problem(self):
        raise NotImplementedError

    def main_files(self) -> list:
        """The names of the files :meth:`main_job` writes, known before the run, so that a
        file of the user's among them is refused before anything runs (default: none)."""
        return []

    def main_job(self, out_dir, answer, progress=None) -> list:
        """The files `camdyn run` writes besides report.json (default: none)."""
        return []

    def table(self, out: dict) -> list:
        """The answer (``Answer.as_dict()``) as lines of text, each figure with its estimate."""
        from ..measure.contract import exact_figures, with_errors

        return with_errors(out, exact_figures(self))

    def job(self, out_dir, estimate: bool = True, progress=None) -> dict:
        """`camdyn run`: the answer, the target's files (diagrams) and report.json in
        ``out_dir``; returns report.json's record with ``lines``, the text to print."""
        import json

        from ..core.outdir import claim, out_folder, write_text
        from ..measure.contract import answer

        # a file of the user's among what the job writes: refused before the run
        for name in ["report.json", *self.main_files()]:
            claim(out_dir / name)
        a = answer(self, estimate=estimate, progress=progress)
        out = a.as_dict()
        out_folder(out_dir)
        files = self.main_job(out_dir, a, progress)
        if files:
            out["figures"] = files
        record = {"kind": self.kind, "scene": self.name, "title": self.title, **out}
        path = out_dir / "report.json"
        write_text(path, json.dumps(record, indent=1))
        record["lines"] = self.table(out) + [f"report: {path}"]
        return record
