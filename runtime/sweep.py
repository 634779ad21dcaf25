"""Sweeps: the headline figures of a model or a scene over a grid of its parameters.

``sweep(target, {"Fa": [...], "tau": [...]})`` runs every combination of the grid's values
(the first axis slowest) and returns a :class:`SweepResult`: a table with a column per axis
and per figure, written as CSV (and Parquet when pyarrow is installed) with a chart per figure.

target
    a generated model's name (camshaft1, camshaft2, ...) or a model file (.py): the residual-
    vibration figures its manifest declares (U0 (3.5), U0'' (3.6), the largest deceleration in
    the rise and its T, fig. 4.11), over [0, t_end];
    a camshaft1-study scene (``default``): CAMSHAFT-1 with the scene's law, method and rtol over
    T in [0, 3], the figures of fig. 4.11;
    a DYNACAM scene: every figure of its summary (runtime/dynacam.py), the jump and the largest
    speed variations included; the grid's names are the scene's [parameters];
    a beam-follower scene: the tip's largest deflection (runtime/beam.py); the names are the
    fields of its case.

How the work is spread.  A model's runs with an adaptive method never come back to Python:
runtime/_figures.pyx integrates a chunk of grid points and finds their figures holding no GIL,
so ``jobs`` threads run chunks side by side on as many cores (threads rather than processes:
no pickling, no start-up, one copy of the model; BENCHMARKS-sweep.md has the measurements).
Scene sweeps (whose runs need Python: the equilibrium start of a DYNACAM run) take the same
threads, which overlap only in the compiled integration.  With ``dask`` (a
``distributed.Client``, a cluster, or a scheduler's address) the chunks go to a Dask cluster
instead; every worker must import camdyn.
"""
from __future__ import annotations

import math
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field, replace
from itertools import product
from pathlib import Path

import numpy as np

from .errors import CamdynInputError, SimulationError, out_folder

RESIDUAL_FIGURES = ("U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min")
"""The figures of a model sweep (runtime/residual.py), in the table's order."""

DYNACAM_FIGURES = ("tau", "Fa", "Fv", "Xdd_min_rise", "T_at_Xdd_min", "Xdd_max_rise", "U0dd",
                   "U0", "jump_occurs", "jump_T", "speed_variation_max",
                   "motor_speed_variation_max")
"""The figures of a DYNACAM scene sweep (runtime/dynacam.py's summary); jump_T and a missing
motor's speed variation are NaN where there is none (jump_occurs says which)."""

RETURN_FIGURES = ("Xdd_absmax_return", "U0dd_return", "U0_return")
"""With a [turn] a DYNACAM scene sweep adds the return's figures (runtime/dynacam.py)."""

BEAM_FIGURES = ("max_abs_tip_deflection", "max_constraint_residual", "dwell_frequency_hz")
"""The figures of a beam-follower scene sweep (runtime/beam.py's summary)."""

SAMPLES = 20.0
CANDIDATES = 4
"""A model sweep's scan takes about SAMPLES x rtol^(1/5) samples a recorded step (every
stride-th recorded point, or several a step at loose tolerances; :func:`scan_density`) and
refines its CANDIDATES best peaks on the dense output (runtime/_figures.pyx says why that
suffices; tests/test_figures_compiled.py compares with the reference's 12 samples a step)."""


def scan_density(method) -> tuple[int, int]:
    """(per_step, stride) of a model sweep's scan.  An adaptive method's steps per period of
    the fastest mode that carries amplitude grow as rtol^(-1/5) (DP54's error per step goes
    as h^5): CAMSHAFT-1 at rtol 1e-9 takes 87 a period at tau = 0.06 (the grid's fastest),
    1.4 rtol^(-1/5).  The scan keeps about SAMPLES per rtol^(-1/5) steps, i.e. 25 or more a
    period: every 3rd recorded point at rtol 1e-9, every point at 1e-8, 2 a step at 1e-6."""
    k = method.rtol ** -0.2
    if k >= SAMPLES:
        return 1, int(k // SAMPLES)
    return math.ceil(SAMPLES / k), 1

CHUNK = 32
"""Grid points per compiled call: small enough for a live progress bar and even shares."""


# -- the grid ---------------------------------------------------------------------------------

def parse_axis(text: str) -> tuple[str, np.ndarray]:
    """``NAME=START:STOP:N[:lin|log|inv]`` (N values; log: geometric; inv: uniform in 1/value,
    as the tau grid of fig. 4.11, runtime/envelope.py) or ``NAME=a,b,c``."""
    name, sep, rng = text.partition("=")
    name = name.strip()
    if not sep or not name:
        raise CamdynInputError(f"argument --grid: {text!r} is not NAME=START:STOP:N[:lin|log|inv] "
                               "or NAME=a,b,c")
    parts = rng.split(":")
    syntax = CamdynInputError(f"argument --grid: {text!r} is not NAME=START:STOP:N[:lin|log|inv] "
                              "or NAME=a,b,c")
    try:
        if len(parts) == 1:
            values = np.array([float(v) for v in rng.split(",") if v.strip()])
        elif len(parts) in (3, 4):
            a, b, n = float(parts[0]), float(parts[1]), int(parts[2])
            spacing = parts[3] if len(parts) == 4 else "lin"
        else:
            raise syntax
    except ValueError:
        raise syntax from None
    if len(parts) > 1:
        if spacing not in ("lin", "log", "inv"):
            raise syntax
        if not (np.isfinite(a) and np.isfinite(b)):
            # before linspace, which warns on inf and nan
            raise CamdynInputError(f"argument --grid: {name}: {rng!r} must give finite numbers")
        if not 1 <= n <= 1_000_000:
            raise CamdynInputError(f"argument --grid: {name}: N={n} is out of range: "
                                   "1 <= N <= 1000000")
        if spacing != "lin" and not (a > 0 and b > 0):
            raise CamdynInputError(f"argument --grid: {name}: a {spacing} grid needs "
                                   "START, STOP > 0")
        if spacing == "log":
            values = np.geomspace(a, b, n)
        elif spacing == "inv":
            values = 1.0 / np.linspace(1.0 / a, 1.0 / b, n)
        else:
            values = np.linspace(a, b, n)
    if values.size == 0 or not np.all(np.isfinite(values)):
        raise CamdynInputError(f"argument --grid: {name}: {rng!r} must give finite numbers")
    return name, values


MAX_POINTS = 1_000_000
"""The most grid points of one sweep, all axes combined (as N of one axis)."""


def parse_grid(texts) -> dict:
    """{name: values} of repeated ``--grid`` texts (:func:`parse_axis`); a name given twice
    is refused (a dict would keep the last one without a word)."""
    grid: dict = {}
    for text in texts:
        name, values = parse_axis(text)
        if name in grid:
            raise CamdynInputError(f"argument --grid: {name} is given twice; give each "
                                   "parameter one axis")
        grid[name] = values
    return grid


def _axes(grid: dict) -> dict:
    if not isinstance(grid, dict) or not grid:
        raise CamdynInputError("a sweep needs a grid: {parameter name: values}")
    out = {}
    for name, values in grid.items():
        v = np.atleast_1d(np.asarray(values, dtype=float)).ravel()
        if v.size == 0 or not np.all(np.isfinite(v)):
            raise CamdynInputError(f"grid {name}: give finite numbers, got {values!r}")
        out[str(name)] = v
    total = math.prod(v.size for v in out.values())
    if total > MAX_POINTS:
        # the table of every combination would not fit in memory (1e5 x 1e5 needed 75 GiB)
        raise CamdynInputError(f"grid {' x '.join(f'{k} ({v.size})' for k, v in out.items())}: "
                               f"{total:.3g} points; at most {MAX_POINTS:,} in one sweep")
    return out


def _points(axes: dict) -> np.ndarray:
    """Every combination, the first axis slowest: shape (n_points, n_axes)."""
    mesh = np.meshgrid(*axes.values(), indexing="ij")
    return np.stack([m.ravel() for m in mesh], axis=1)


# -- the result -------------------------------------------------------------------------------

@dataclass
class SweepResult:
    """A sweep's table: ``columns[name]`` for every axis, figure and statistic, one row per
    grid point (the first axis slowest)."""

    target: str
    axes: dict                   # name -> the axis's values
    figures: tuple
    columns: dict
    seconds: float = 0.0         # wall time of the runs
    where: str = "local"         # "local, K threads" or "dask <address>"
    stats: tuple = ("n_steps",)
    meta: dict = field(default_factory=dict)

    def __len__(self) -> int:
        return len(next(iter(self.columns.values())))

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            return self.columns[name]
        except KeyError:
            raise KeyError(f"no column {name!r}; columns: {', '.join(self.columns)}") from None

    @property
    def names(self) -> list:
        return [*self.axes, *self.figures, *self.stats]

    def rows(self) -> list[dict]:
        return [{k: self.columns[k][i].item() for k in self.names} for i in range(len(self))]

    def to_csv(self, path) -> Path:
        path = Path(path)
        names = self.names
        with open(path, "w") as fh:
            fh.write(",".join(names) + "\n")
            for i in range(len(self)):
                fh.write(",".join(_cell(self.columns[k][i]) for k in names) + "\n")
        return path

    def to_parquet(self, path) -> Path:
        try:
            import pyarrow as pa
            import pyarrow.parquet as pq
        except ImportError:
            raise CamdynInputError("Parquet needs pyarrow: pip install pyarrow") from None
        path = Path(path)
        pq.write_table(pa.table({k: self.columns[k] for k in self.names}), path)
        return path

    def charts(self, out_dir) -> list[Path]:
        """One PNG per figure (not its error estimate) against the last axis with more than
        one value, a line for every combination of the other axes (up to 12, evenly picked)."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        out_dir = Path(out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        names = list(self.axes)
        shape = tuple(len(v) for v in self.axes.values())
        multi = [k for k, n in enumerate(shape) if n > 1]
        x_ax = multi[-1] if multi else len(names) - 1
        others = [k for k in range(len(names)) if k != x_ax]
        combos = list(product(*[range(shape[k]) for k in others]))
        if len(combos) > 12:
            combos = [combos[int(round(j))] for j in np.linspace(0, len(combos) - 1, 12)]
        x = self.axes[names[x_ax]]
        written = []
        for fig_name in [f for f in self.figures if not f.endswith("_error")]:
            data = np.asarray(self.columns[fig_name], dtype=float).reshape(shape)
            fig, ax = plt.subplots(figsize=(7, 4.2))
            for c in combos:
                idx = [0] * len(names)
                for k, j in zip(others, c):
                    idx[k] = j
                idx[x_ax] = slice(None)
                label = ", ".join(f"{names[k]} = {self.axes[names[k]][j]:g}"
                                  for k, j in zip(others, c))
                # a marker where the x axis has one value: a line of one point draws nothing
                ax.plot(x, data[tuple(idx)], lw=1.0, label=label or None,
                        marker="o" if len(x) == 1 else None)
            finite = data[np.isfinite(data)]
            if finite.size and finite.min() > 0 and finite.max() > 100 * finite.min():
                ax.set_yscale("log")     # U0 and U0'' span decades between the dips of (3.5)
            ax.set_xlabel(names[x_ax])
            ax.set_ylabel(fig_name)
            ax.set_title(f"{self.target}: {fig_name}", fontsize=10)
            ax.grid(alpha=0.3)
            if combos and combos[0]:
                ax.legend(fontsize=7)
            fig.tight_layout()
            path = out_dir / f"{fig_name}.png"
            fig.savefig(path, dpi=110)
            plt.close(fig)
            written.append(path)
        return written

    def write(self, out_dir) -> list[Path]:
        """sweep.csv, sweep.parquet (with pyarrow) and the charts into ``out_dir``."""
        out_dir = out_folder(out_dir)
        files = [self.to_csv(out_dir / "sweep.csv")]
        try:
            files.append(self.to_parquet(out_dir / "sweep.parquet"))
        except CamdynInputError:
            pass
        return files + self.charts(out_dir)


def _cell(v) -> str:
    v = float(v)
    if math.isnan(v):
        return ""
    return f"{v:.17g}" if v != int(v) or abs(v) >= 1e15 else str(int(v))


# -- targets ------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Target:
    """What a sweep runs, as plain data (so that it pickles to Dask workers): ``kind`` model,
    dynacam or beam; ``name`` the model name, model file or scene; the run's settings."""

    kind: str
    name: str
    t_end: float | None = None
    method: str | None = None
    rtol: float | None = None
    law: str | None = None
    step: float | None = None      # fixed-step methods (rk4, koster) of a model

    def tighter(self) -> "Target | None":
        """The same target one notch more accurate (runtime/accuracy.py: rtol/10, or half the
        step), for the error estimates; None at the tightest rtol."""
        from . import accuracy

        if self.kind == "model":
            method, rtol = self.method, self.rtol
        elif self.kind == "dynacam":
            sc = _built(self)
            method, rtol = sc.method, sc.rtol
        else:
            case = _built(self).case
            method, rtol = case.method, case.rtol
        settings = accuracy.tighter_settings(method, rtol, self.step)
        if settings is None:
            return None
        return replace(self, method=method, rtol=settings[0], step=settings[1])

    @property
    def figures(self) -> tuple:
        if self.kind == "dynacam":
            return dynacam_figures(_built(self))
        return {"model": RESIDUAL_FIGURES, "beam": BEAM_FIGURES}[self.kind]

    @property
    def estimated(self) -> tuple:
        """The figures that get an error estimate: not a DYNACAM scene's tau, Fa, Fv (they
        follow from its parameters, not from the run) nor its jump_occurs (a yes or no)."""
        return tuple(f for f in self.figures
                     if not (self.kind == "dynacam" and f in ("tau", "Fa", "Fv", "jump_occurs")))

    def allowed(self) -> dict:
        """Grid names this target takes: name -> a description of the allowed range."""
        built = _built(self)
        if self.kind == "model":
            return {p["name"]: p.get("range", "any number") for p in built[0].manifest["parameters"]}
        if self.kind == "dynacam":
            return {k: "as the variant's manifest declares" for k in built.parameters}
        from dataclasses import fields

        return {f.name: "a positive number" for f in fields(built.case)
                if f.type == "float"}


def resolve(target, *, t_end=None, method=None, rtol=None, law=None, step=None) -> Target:
    """The Target of a model name, a model file, or a scene (built-in name or TOML file)."""
    from . import scene as scenes
    from .models import available

    if isinstance(target, Target):
        return target
    name = str(target)
    if rtol is not None and method in ("rk4", "koster"):
        raise CamdynInputError(f"rtol applies to the adaptive methods dp54 and rodas4; {method} "
                               "takes step")
    if name.endswith(".py") or name.replace("-", "_") in available():
        if name.endswith(".py") and not Path(name).is_file():
            raise CamdynInputError(f"{name}: no such model file")
        # a model file by its absolute path: a Dask worker may run elsewhere
        model = str(Path(name).resolve()) if name.endswith(".py") else name.replace("-", "_")
        adaptive = (method or "dp54") in ("dp54", "rodas4")
        return Target("model", model, 3.0 if t_end is None else float(t_end),
                      method or "dp54", 1e-9 if rtol is None and adaptive else rtol,
                      law or "cycloidal", step)
    try:
        kind, sc = scenes.load_any(name)
    except CamdynInputError as exc:
        raise CamdynInputError(f"{name!r} is neither a model ({', '.join(available())}), a model "
                               f"file (.py) nor a scene: {exc}") from None
    if kind == scenes.STUDY:
        if t_end is not None and t_end <= 1.0:
            raise CamdynInputError(f"t_end={t_end:g} must exceed the end of the rise, T = 1")
        run = sc["run"]
        method = method or run["method"]
        adaptive = method in ("dp54", "rodas4")
        return Target("model", "camshaft1", 3.0 if t_end is None else float(t_end), method,
                      (run["rtol"] if rtol is None else rtol) if adaptive else None,
                      law or sc["law"], step)
    if any(v is not None for v in (t_end, law, step)):
        raise CamdynInputError("t_end, law and step of a scene sweep come from the scene file")
    if method in ("rk4", "koster"):
        # else refused later by the first grid value's scene, as if the grid were at fault
        raise CamdynInputError(f"method {method}: a {kind} scene takes an adaptive method, "
                               "dp54 or rodas4")
    return Target("dynacam" if kind == "dynacam" else "beam", name, None, method, rtol, None)


_BUILT: dict = {}


def _built(target: Target):
    """The heavy objects of a target, made once per process: (model, Simulator) for a model,
    the Scene for a DYNACAM scene, the BeamScene for a beam follower."""
    hit = _BUILT.get(target)
    if hit is not None:
        return hit
    from . import scene as scenes

    if target.kind == "model":
        from .models import load
        from .simulate import Simulator

        if target.name.endswith(".py"):
            from . import ondemand

            model = ondemand.model_file(target.name)
        else:
            model = load(target.name)
        if not model.manifest.get("residual"):
            raise CamdynInputError(f"model {model.name} declares no residual-vibration outputs; "
                                   "sweep a model that does (camshaft1, camshaft2, one_dof, ...) "
                                   "or a scene")
        sim = Simulator(model, target.t_end, target.method, rtol=target.rtol, law=target.law,
                        step=target.step)
        hit = (model, sim)
    else:
        kind, sc = scenes.load_any(target.name)
        if target.method is not None or target.rtol is not None:
            if kind == "dynacam":
                sc = replace(sc, method=target.method or sc.method, rtol=target.rtol or sc.rtol)
            else:
                sc = replace(sc, case=replace(sc.case, method=target.method or sc.case.method,
                                              rtol=target.rtol or sc.case.rtol))
        hit = sc
    _BUILT[target] = hit
    return hit


def _check_names(target: Target, axes: dict) -> None:
    """Unknown grid names and values out of range are refused, naming them."""
    allowed = target.allowed()
    for name, values in axes.items():
        if name not in allowed:
            raise CamdynInputError(
                f"grid {name}: not a parameter of {target.name}; its parameters are "
                + ", ".join(f"{k} ({v})" for k, v in allowed.items()))
        if target.kind == "model":
            model = _built(target)[0]
            for v in values:
                try:
                    model.parameter_vector({name: float(v)})
                except CamdynInputError as exc:
                    raise CamdynInputError(f"grid {name}: {exc}") from None
        elif target.kind == "beam":
            from .beam_case import check

            case = _built(target).case
            for v in values:
                try:
                    check(replace(case, **{name: float(v)}))
                except CamdynInputError as exc:
                    raise CamdynInputError(f"grid {name}: {exc}") from None
        else:
            from . import scene as scenes

            sc = _built(target)
            for v in (values.min(), values.max()):
                try:
                    scenes.replace(sc, parameters={name: float(v)})
                except CamdynInputError as exc:
                    raise CamdynInputError(f"grid {name}: {exc}") from None


# -- running a chunk (locally or on a Dask worker) ----------------------------------------------

def run_chunk(target: Target, names: tuple, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Figures (n, n_figures) and steps (n,) of grid points ``points`` (n, len(names))."""
    if target.kind == "model":
        model, sim = _built(target)
        if sim.method.adaptive:
            return _model_chunk_compiled(model, sim, names, points)
        return _model_chunk_python(sim, names, points)
    if target.kind == "dynacam":
        return _dynacam_chunk(_built(target), names, points)
    return _beam_chunk(_built(target), names, points)


def _model_chunk_compiled(model, sim, names, points):
    from . import _figures, _integrate
    from .simulate import stop_times

    n = len(points)
    cols = [model.parameter_names.index(k) for k in names]
    P = np.tile(model.parameter_vector(), (n, 1))
    P[:, cols] = points
    # stop times depend on the parameters only through the cam inputs' affine arguments
    stops, cache = [], {}
    for p in P:
        key = repr(model.cam_time_affine(p))
        s = cache.get(key)
        if s is None:
            s = cache[key] = stop_times(model, p, sim.laws, sim.t0, sim.t_end)
        stops.append(s)
    width = max(len(s) for s in stops)
    S = np.full((n, width), sim.t_end)
    for j, s in enumerate(stops):
        S[j, :len(s)] = s
    NS = np.array([len(s) for s in stops], dtype=np.intc)
    Y0 = (np.tile(sim._y_init, (n, 1)) if sim._y0_given
          else np.array([model.initial_state(p) for p in P]))
    # tolerances and steps as Simulator gives them to its Integrator
    method, ns = sim.method, len(model.state_names)
    base = method.atol if method.atol is not None else 1e-3 * method.rtol
    atol = np.ascontiguousarray(base * model.state_scales(), dtype=float)
    for name, value in method.state_atol:
        atol[model.state_names.index(name)] = value
    spec = model.manifest["residual"]
    index = {k: i for i, k in enumerate(model.state_names)}
    index.update({k: ns + i for i, k in enumerate(model.output_names)})
    i_rise = index[spec["rise_state"]] if spec.get("rise_state") else -1
    if i_rise >= ns:
        return _model_chunk_python(sim, names, points)
    per_step, stride = scan_density(method)
    figures = np.empty((n, len(_figures.FIGURE_COLUMNS)))
    stats = np.empty((n, len(_figures.STAT_COLUMNS)), dtype=np.int64)
    secs = np.empty(n)
    _figures.sweep_residual(
        model.capsule, method.code, sim.law_codes, sim.law_pars, np.ascontiguousarray(P),
        np.ascontiguousarray(Y0, dtype=float), S, NS, sim.t0, method.first_step or 0.0,
        min(method.max_step, sim.t_end - sim.t0), method.rtol, atol, sim.max_steps,
        np.array(sim.modes0, dtype=np.intc), 1_000_000, index[spec["error"]],
        index[spec["acceleration"]], float(spec["rise_end"]), i_rise, per_step, CANDIDATES,
        figures, stats, secs, 0, n, 4096, stride)
    bad = np.flatnonzero(stats[:, 0] != 0)
    if bad.size:
        j = int(bad[0])
        at = ", ".join(f"{k} = {v:g}" for k, v in zip(names, points[j]))
        if stats[j, 0] == -1:
            raise CamdynInputError(f"{model.name} at {at}: the run must cover the rise and part "
                                   f"of the dwell after it (t_end = {sim.t_end:g})")
        raise SimulationError(f"{model.name} with {method.name} at {at}: "
                              f"{_integrate.STATUS_TEXT[int(stats[j, 0])]}")
    return figures[:, :4], stats[:, 1].astype(float)


def _model_chunk_python(sim, names, points):
    """Fixed-step methods (their stability checks live in Simulator.run): one run at a time."""
    from .residual import residual

    out = np.empty((len(points), len(RESIDUAL_FIGURES)))
    steps = np.empty(len(points))
    for j, pt in enumerate(points):
        res = sim.run(dict(zip(names, map(float, pt))))
        r = residual(res)
        out[j] = [getattr(r, k) for k in RESIDUAL_FIGURES]
        steps[j] = res.stats["n_steps"]
    return out, steps


def dynacam_figures(sc) -> tuple:
    """A DYNACAM scene's figures: its summary's, and the return's with a [turn]."""
    return DYNACAM_FIGURES + (RETURN_FIGURES if sc.turn is not None else ())


def _dynacam_chunk(sc, names, points):
    from . import dynacam, scene as scenes

    figures = dynacam_figures(sc)
    out = np.full((len(points), len(figures)), np.nan)
    steps = np.empty(len(points))
    for j, pt in enumerate(points):
        s = scenes.replace(sc, parameters=dict(zip(names, map(float, pt))))
        summary, _ = dynacam.run(s)
        for k, key in enumerate(figures):
            if key == "jump_occurs":
                out[j, k] = float(summary["jump"]["occurs"])
            elif key == "jump_T":
                out[j, k] = np.nan if summary["jump"]["T"] is None else summary["jump"]["T"]
            elif summary.get(key) is not None:
                out[j, k] = summary[key]
        steps[j] = summary["n_steps"]
    return out, steps


def _beam_chunk(sc, names, points):
    from . import beam
    from .beam_case import check

    out = np.empty((len(points), len(BEAM_FIGURES)))
    steps = np.empty(len(points))
    for j, pt in enumerate(points):
        case = check(replace(sc.case, **dict(zip(names, map(float, pt)))))
        summary, _ = beam.run(case)
        out[j] = [summary[k] for k in BEAM_FIGURES]
        steps[j] = summary["n_steps"]
    return out, steps


def _check_dwell(target: Target, axes: dict) -> None:
    """U0 and U0'' are the largest |U|, |X''| in the dwell after the rise: a dwell shorter than
    one period of the residual vibration (tau in T, (3.3), (4.12)) gives a smaller number
    without a word.  Models with a time-dependent rise end (rise_state) are not checked."""
    if target.kind != "model":
        return
    model = _built(target)[0]
    spec = model.manifest["residual"]
    if spec.get("rise_state") or "tau" not in model.parameter_names:
        return
    tau = axes["tau"].max() if "tau" in axes else \
        model.parameter_vector()[model.parameter_names.index("tau")]
    need = float(spec["rise_end"]) + float(tau)
    if target.t_end < need:
        raise CamdynInputError(f"t_end={target.t_end:g} leaves less than one period of the "
                               f"residual vibration (tau = {tau:g}) after the rise at T = "
                               f"{spec['rise_end']:g}: U0 would be too small; give t_end >= "
                               f"{need:g}")


# -- the sweep ------------------------------------------------------------------------------------

def default_jobs() -> int:
    """All cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


def sweep(target, grid: dict, *, jobs: int | None = None, dask=None, progress: bool = True,
          t_end: float | None = None, method: str | None = None, rtol: float | None = None,
          law: str | None = None, step: float | None = None, chunk: int | None = None,
          errors: bool = False) -> SweepResult:
    """Run ``target`` (module doc) at every point of ``grid`` ({name: values}); ``jobs``
    threads (default: every core), or the Dask cluster ``dask``; a progress bar on stderr.

    ``errors``: every grid point again one notch more accurately (rtol/10, or half the step),
    and a column ``<figure>_error`` = |v - v'| (times Richardson's factor for fixed steps) for
    every figure (runtime/accuracy.py); twice the time."""
    tgt = resolve(target, t_end=t_end, method=method, rtol=rtol, law=law, step=step)
    axes = _axes(grid)
    _check_names(tgt, axes)
    _check_dwell(tgt, axes)
    if dask is not None and jobs is not None:
        raise CamdynInputError("--jobs and --dask: give one (threads here, or the Dask "
                               "cluster's workers)")
    jobs = default_jobs() if jobs is None else jobs
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise CamdynInputError(f"jobs={jobs!r}: give a positive whole number of threads")
    pts = _points(axes)
    names = tuple(axes)
    size = chunk or (CHUNK if tgt.kind == "model" else 1)
    if isinstance(size, bool) or not isinstance(size, int) or size < 1:
        raise CamdynInputError(f"chunk={size!r}: give a positive whole number of grid points")
    pieces = [pts[i:i + size] for i in range(0, len(pts), size)]
    tight = None
    if errors:
        tight = tgt.tighter()
        if tight is None:
            raise CamdynInputError(f"rtol={tgt.rtol:g} is the tightest there is: no error "
                                   "estimate (give a larger rtol)")
    todo = [(t, p) for t in ([tgt] if tight is None else [tgt, tight]) for p in pieces]
    bar = _bar(len(pts) * (2 if tight else 1), progress, tgt.name)
    start = time.perf_counter()
    try:
        if dask is not None:
            results, where = _on_dask(dask, todo, names, bar)
        else:
            results = _local(todo, names, jobs, bar)
            where = f"local, {jobs} thread{'s' if jobs > 1 else ''}"
    finally:
        bar.close()
    seconds = time.perf_counter() - start
    figs = np.concatenate([r[0] for r in results[:len(pieces)]])
    steps = np.concatenate([r[1] for r in results[:len(pieces)]])
    columns = {k: pts[:, i].copy() for i, k in enumerate(names)}
    columns.update({k: figs[:, i] for i, k in enumerate(tgt.figures)})
    figures = tgt.figures
    if tight is not None:
        from .accuracy import factor

        tfigs = np.concatenate([r[0] for r in results[len(pieces):]])
        est = np.abs(figs - tfigs) * factor(tight.method or "dp54")
        columns.update({f"{k}_error": est[:, i] for i, k in enumerate(tgt.figures)
                        if k in tgt.estimated})
        figures = tuple(x for k in tgt.figures
                        for x in ((k, f"{k}_error") if k in tgt.estimated else (k,)))
    columns["n_steps"] = steps
    return SweepResult(tgt.name, axes, figures, columns, seconds, where,
                       meta={"target": tgt, "tight": tight})


class _NoBar:
    def update(self, n=1):
        pass

    def close(self):
        pass


def _bar(total: int, progress: bool, label: str):
    if not progress:
        return _NoBar()
    from tqdm import tqdm

    return tqdm(total=total, desc=f"sweep {label}", unit="run", file=sys.stderr, leave=False,
                mininterval=0.2)


def _local(todo, names, jobs, bar) -> list:
    """run_chunk of every (target, points) of ``todo``, in order."""
    if jobs == 1 or len(todo) == 1:
        out = []
        for tgt, piece in todo:
            out.append(run_chunk(tgt, names, piece))
            bar.update(len(piece))
        return out
    for tgt in {t for t, _ in todo}:
        _built(tgt)     # build once, before the threads share it
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(run_chunk, tgt, names, piece) for tgt, piece in todo]
        out = []
        for fut, (_, piece) in zip(futures, todo):
            out.append(fut.result())
            bar.update(len(piece))
    return out


def _on_dask(dask, todo, names, bar) -> tuple[list, str]:
    try:
        from distributed import Client
    except ImportError:
        raise CamdynInputError("--dask needs dask.distributed: pip install 'camdyn[dask]'") from None
    own = False
    if isinstance(dask, Client):
        client = dask
    elif isinstance(dask, str):
        try:
            client = Client(dask, timeout=10)
        except (OSError, TimeoutError, ValueError) as exc:     # ValueError: no port in it
            raise CamdynInputError(f"argument --dask: no Dask scheduler at {dask}: {exc}") from None
        own = True
    else:                          # a cluster object (LocalCluster, ...)
        client = Client(dask)
        own = True
    try:
        futures = client.map(run_chunk, [t for t, _ in todo], [names] * len(todo),
                             [p for _, p in todo], pure=False)
        out = []
        for fut, (_, piece) in zip(futures, todo):
            out.append(fut.result())
            bar.update(len(piece))
        where = f"dask {client.scheduler.address}"
    finally:
        if own:
            client.close()
    return out, where
