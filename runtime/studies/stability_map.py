"""Stability maps: where each method is fine, inaccurate, refused or blew up.

A map is a grid of a step (fixed-step methods rk4, koster) or an rtol (dp54, rodas4) against
values of the problem's stiffness parameter (tau for the one-DOF model and CAMSHAFT-1, the
contact stiffness ratio kappa for the roller model).  Every cell is one run of one rise and
dwell (to ``t_end``), classified by :func:`classify_cell`:

fine        finished, its headline figure within ``threshold`` (relative) of the reference
inaccurate  finished, bounded, the figure off by more than the threshold
refused     a fixed step beyond the method's stability boundary, refused by the check of
            runtime/core/stability.py (the default behaviour of every command)
blew up     the run failed (SimulationError: non-finite state, the thesis scheme's mid-step
            iteration not converging, step collapse or step budget of an adaptive method), or
            a state grew past ``BLOWUP`` times its largest value in the reference run, or the
            residual vibration (U) grew by more than ``GROWTH`` from the first fifth of the
            dwell to the last (``dwell_growth``; the models do not excite it there)

A refused step is also run with the check off (``Simulator(check_stability=False)``), and its
outcome kept in ``outcome``: so the map shows whether the check refused what would have
blown up.  ``check_stability=False`` makes ``status`` that outcome.

Headline figure: U0, the residual amplitude after the rise (thesis (3.5), sec. 3.3) for
models that declare one; else the state at t_end, its error the largest over the states of
|y - y_ref|/(|y_ref| + scale).  Reference: DP54 at rtol ``REF_RTOL``, the model's target
(runtime/targets/model_target.py) with its window and its own error estimate (the answer contract,
runtime/measure/contract.py): a reference whose estimate is not well inside the threshold
cannot tell fine from inaccurate, and the map says so in its warnings.  CPU time: the
process time of the run that gave the outcome (integration, stability check), not of the
figure's extraction; ``loop_seconds`` the compiled loops' own wall time alone; with step
counts and right-hand-side calls.

The theoretical boundary drawn for a fixed-step method is h = b/|lambda| with the limiting
eigenvalue lambda of the difference Jacobian along the reference run and b the method's
boundary in its direction (runtime/core/stability.py: 2 sqrt(2) on the imaginary axis, 2.785 on
the negative real one); for koster also the thesis's criterion Delta T = 0.1 tau
(h omega = 0.2 pi, sec. 4.4.2).
"""
from __future__ import annotations

import csv
import json
import math
import time
from dataclasses import asdict, dataclass, field

import numpy as np

from ..core import stability as _stability
from ..core.errors import CamdynInputError, SimulationError, UnstableStep
from ..core.methods import METHODS
from ..core.outdir import write_text, writing
from ..core.compiled import CompiledModel
from ..core.simulator import Simulator
from ..measure.contract import answer, fit_window

CLASSES = ("fine", "inaccurate", "refused", "blew up")
COLOURS = {"fine": "#4caf50", "inaccurate": "#ffc107", "refused": "#9e9e9e", "blew up": "#e53935"}
REF_RTOL = 1e-11   # the reference run (DP54)
BLOWUP = 100.0     # a state beyond BLOWUP x (its reference maximum + scale) has blown up
GROWTH = 2.0       # so has a residual vibration grown by more than this over the dwell
MAX_CELLS = 2000
THESIS_STEP_X = 0.2 * math.pi   # sec. 4.4.2: Delta T = 0.1 tau is h omega = 0.1 * 2 pi


@dataclass
class Cell:
    """One run of the map: ``setting`` is the step (fixed) or rtol (adaptive)."""

    method: str
    param: float
    setting: float
    status: str
    outcome: str
    refused: bool
    reason: str
    figure: float | None
    error: float | None
    cpu_seconds: float
    loop_seconds: float | None
    n_steps: int | None
    n_rhs: int | None
    h_rho: float | None


@dataclass
class StabilityMap:
    """The cells of a map, with the grid, the reference figures and the boundary lines."""

    model: str
    param: str
    values: list
    fixed: dict
    settings: dict          # method -> steps or rtols
    threshold: float
    figure: str
    check_stability: bool
    reference: list         # the reference figure per parameter value (a model without a
                            # rise: its states at t_end by name)
    step_limit: dict        # fixed method -> b/|lambda| per parameter value (the theory line)
    cells: list = field(default_factory=list)
    reference_run: str = f"DP54 rtol {REF_RTOL:g}"   # what the figures are measured against
    reference_error: list = field(default_factory=list)   # its estimate, relative, per value
    t_end: list = field(default_factory=list)       # each value's run end (its window)
    warnings: list = field(default_factory=list)

    def rows(self) -> list[dict]:
        return [asdict(c) for c in self.cells]

    def counts(self) -> dict:
        out = {}
        for c in self.cells:
            out.setdefault(c.method, dict.fromkeys(CLASSES, 0))[c.status] += 1
        return out

    def as_dict(self) -> dict:
        d = {k: v for k, v in asdict(self).items() if k != "cells"}
        d["counts"] = self.counts()
        d["cells"] = self.rows()
        return d

    def write_csv(self, path) -> str:
        rows = self.rows()
        with writing(path), open(path, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
        return str(path)

    def write_json(self, path) -> str:
        write_text(path, json.dumps(self.as_dict(), indent=1))
        return str(path)

    def plot(self, path) -> str:
        """One panel per method: cells coloured by class, CPU time (ms) written in each."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.patches import Patch

        methods = list(self.settings)
        fig, axes = plt.subplots(1, len(methods), figsize=(4.6 * len(methods), 4.6),
                                 squeeze=False)
        xe = _edges(np.asarray(self.values, float), _log(self.values))
        for ax, meth in zip(axes[0], methods):
            ys = np.asarray(self.settings[meth], float)
            ye = _edges(ys)
            for c in (c for c in self.cells if c.method == meth):
                i, j = self.values.index(c.param), list(ys).index(c.setting)
                ax.add_patch(plt.Rectangle((xe[i], ye[j]), xe[i + 1] - xe[i], ye[j + 1] - ye[j],
                                           color=COLOURS[c.status], ec="white", lw=0.5))
                if len(self.values) * len(ys) <= 160:
                    ax.text(math.sqrt(xe[i] * xe[i + 1]) if _log(self.values) else
                            0.5 * (xe[i] + xe[i + 1]), math.sqrt(ye[j] * ye[j + 1]),
                            f"{1e3 * c.cpu_seconds:.2g}", ha="center", va="center", fontsize=6)
            ax.set_xlim(xe[0], xe[-1])
            ax.set_ylim(ye[0], ye[-1])
            ax.set_yscale("log")
            if _log(self.values):
                ax.set_xscale("log")
            if meth in self.step_limit:
                xs = np.asarray(self.values, float)
                lim = np.asarray(self.step_limit[meth], float)
                ax.plot(xs, lim, "k-", lw=1.5, label="theory: h |lambda| = boundary")
                if meth == "koster":
                    ax.plot(xs, lim * THESIS_STEP_X / _stability.KOSTER_BOUNDARY, "k--", lw=1,
                            label="thesis: Delta T = 0.1 tau")
                ax.legend(fontsize=7, loc="lower right")
            ax.set_xlabel(self.param)
            ax.set_ylabel("step" if meth in self.step_limit or not METHODS[meth].adaptive
                          else "rtol")
            ax.set_title(f"{self.model}: {meth}", fontsize=9)
        handles = [Patch(color=COLOURS[k], label=k) for k in CLASSES]
        fig.legend(handles=handles, loc="upper center", ncol=4, fontsize=8)
        ref_note = (f", good to {max(self.reference_error):.2g} relative"
                    if self.reference_error else "")
        warned = (f"; {len(self.warnings)} warning{'s' if len(self.warnings) > 1 else ''}: "
                  f"{self.warnings[0][:100]}" if self.warnings else "; no warnings")
        fig.text(0.01, 0.01, f"numbers: CPU ms per run; inaccurate: |{self.figure} error| > "
                             f"{self.threshold:g} (relative, against {self.reference_run}"
                             f"{ref_note}){warned}", fontsize=7)
        fig.tight_layout(rect=(0, 0.03, 1, 0.93))
        with writing(path):
            fig.savefig(path, dpi=110)
        plt.close(fig)
        return str(path)


def _log(values) -> bool:
    """A geometric grid (constant ratios, not constant differences)."""
    v = np.asarray(values, float)
    if len(v) < 3 or v.min() <= 0:
        return False
    r = v[1:] / v[:-1]
    return bool(np.allclose(r, r[0], rtol=1e-6) and not np.allclose(np.diff(v), v[1] - v[0]))


def _edges(v: np.ndarray, geo: bool = True) -> np.ndarray:
    """Cell edges around sorted grid values: midpoints, geometric ones on a log axis."""
    if len(v) == 1:
        return np.array([v[0] / 1.2, v[0] * 1.2]) if v[0] > 0 else np.array([v[0] - 1, v[0] + 1])
    w = np.log(v) if geo else v
    mid = 0.5 * (w[1:] + w[:-1])
    e = np.concatenate([[2 * w[0] - mid[0]], mid, [2 * w[-1] - mid[-1]]])
    return np.exp(e) if geo else e


# -- one cell -----------------------------------------------------------------------------

@dataclass(frozen=True)
class Reference:
    """The reference run of one parameter value: its figure, the figure's relative error
    estimate (the answer contract's, in the norm of :func:`figure_error`), the states' largest
    values, the run, and the run's end (the window its figure needs)."""

    figure: float
    state: np.ndarray
    y_max: np.ndarray
    result: object
    error: float
    t_end: float
    warnings: tuple


def figure_name(model: CompiledModel) -> str:
    return "U0" if model.manifest.get("residual") else "y(t_end)"


def headline(model: CompiledModel, res):
    """U0 (a residual model), else the state at t_end."""
    if model.manifest.get("residual"):
        from ..measure.residual import residual

        return residual(res).U0
    return np.asarray(res.y[-1], float)


def figure_error(model: CompiledModel, value, ref: Reference) -> float:
    if model.manifest.get("residual"):
        return abs(value - ref.figure) / abs(ref.figure) if ref.figure else abs(value)
    return float(np.max(np.abs(value - ref.state) / (np.abs(ref.state) + model.state_scales())))


def target_of(name, t_end=None, law: str = "cycloidal", progress=None):
    """The target a map runs (runtime/targets/resolve.py): a model with a rise (its U0), or
    any model to t_end (its state; to the end a rise's run takes, DEFAULT_T_END, unless
    given).  ``t_end`` None leaves a rise's run end to its target and its window."""
    from ..targets.model_target import DEFAULT_T_END, StateTarget
    from ..targets.resolve import model

    target = model(str(name), progress=progress, t_end=t_end, law=law)
    if isinstance(target, StateTarget) and target.t_end is None:
        target = target.with_settings(t_end=DEFAULT_T_END)
    return target


def reference(target) -> Reference:
    """The reference of ``target`` at its parameter values: its window fitted (extended where
    camdyn chose the run's end, refused where the user gave one too short), then one run at
    DP54, rtol REF_RTOL, with its error estimate."""
    t = fit_window(target).with_settings(method="dp54", rtol=REF_RTOL)
    a = answer(t)
    res, m = a.result, t.model
    value = headline(m, res)
    if np.ndim(value) == 0:
        rel = (a.errors["U0"] or 0.0) / abs(value) if value else (a.errors["U0"] or 0.0)
    else:
        e = np.array([a.errors[n] or 0.0 for n in m.state_names])
        rel = float(np.max(e / (np.abs(value) + m.state_scales())))
    return Reference(figure=value if np.ndim(value) == 0 else float("nan"),
                     state=np.asarray(res.y[-1], float), y_max=np.abs(res.y).max(axis=0),
                     result=res, error=float(rel), t_end=t.end, warnings=tuple(a.warnings))


def reference_figure(model: CompiledModel, ref: Reference):
    """The reference's headline figure as a map reports it: U0, or every state at t_end by
    name (the figure of a model without a rise; Reference.figure is NaN there, which JSON
    cannot hold)."""
    if np.ndim(ref.figure) == 0 and math.isfinite(ref.figure):
        return float(ref.figure)
    return dict(zip(model.state_names, (float(v) for v in ref.state)))


def step_limit(model: CompiledModel, method: str, ref: Reference) -> float:
    """b/|lambda| of the limiting eigenvalue along the reference run (the theory line)."""
    res = ref.result
    idx = _stability.sample_indices(res.t, len(res.t))
    ev = _stability.spectra(model, res.p, res.law_codes, res.law_pars, res.t[idx], res.y[idx],
                            res.mode[idx])
    est = _stability.assess(method, 1.0, res.t[idx], ev)
    return math.inf if est is None else est.largest_stable_step / _stability.SAFETY


def dwell_growth(model: CompiledModel, res) -> float:
    """A residual model's error output (U) in the dwell: its largest |value| over the last
    fifth of the dwell over that over the first fifth (0 without a dwell).  The models are
    undamped or damped there: a residual vibration that grows is the method's instability."""
    spec = model.manifest.get("residual")
    if not spec or spec.get("rise_state"):
        return 0.0
    t0, t1 = float(spec["rise_end"]), float(res.t[-1])
    if t1 <= t0:
        return 0.0
    u, t = np.abs(res[spec["error"]]), res.t
    first = u[(t >= t0) & (t <= t0 + 0.2 * (t1 - t0))]
    last = u[t >= t1 - 0.2 * (t1 - t0)]
    if not first.size or not last.size:
        return 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        g = last.max() / first.max()
    return float(g) if np.isfinite(g) else (math.inf if last.max() > 0 else 0.0)


def _outcome(model, sim, params, ref: Reference, threshold: float) -> tuple:
    """(outcome, reason, figure, error, cpu, loop seconds, n_steps, n_rhs, h_rho) of one run."""
    c0 = time.process_time()
    try:
        res = sim.run(params)
    except UnstableStep:
        raise
    except SimulationError as exc:
        return "blew up", str(exc), None, None, time.process_time() - c0, None, None, None, None
    cpu = time.process_time() - c0
    st, h_rho = res.stats, (res.stability.h_rho if res.stability is not None else None)
    n = (float(st["seconds"]), int(st["n_steps"]), int(st["n_rhs"]))
    bound = BLOWUP * (ref.y_max + model.state_scales())
    if not np.all(np.abs(res.y).max(axis=0) <= bound):
        return ("blew up", f"a state grew past {BLOWUP:g} x its reference maximum", None, None,
                cpu, *n, h_rho)
    grew = dwell_growth(model, res)
    if grew > GROWTH:
        return ("blew up", f"the residual vibration grew {grew:.3g}-fold over the dwell", None,
                None, cpu, *n, h_rho)
    try:
        value = headline(model, res)
    except (SimulationError, CamdynInputError) as exc:
        return "blew up", str(exc), None, None, cpu, *n, h_rho
    err = figure_error(model, value, ref)
    fig = float(value) if np.ndim(value) == 0 else None
    if not math.isfinite(err):
        return "blew up", "non-finite figure", fig, None, cpu, *n, h_rho
    return ("fine" if err <= threshold else "inaccurate"), "", fig, err, cpu, *n, h_rho


def classify_cell(model, method: str, setting: float, params: dict, ref: Reference, *,
                  threshold: float, t_end: float, law: str = "cycloidal",
                  check_stability: bool = True, param: float = float("nan")) -> Cell:
    """One cell: run ``method`` at ``setting`` (step or rtol) and classify it (module doc)."""
    m = model.model if hasattr(model, "model") else target_of(model, t_end, law).model
    fixed = not METHODS[method].adaptive
    kw = {"step": setting} if fixed else {"rtol": setting}
    refused = False
    try:
        out = _outcome(m, Simulator(m, ref.t_end, method, law=law, exact_segments=False, **kw),
                       params, ref, threshold)
    except UnstableStep:
        refused = True
        out = _outcome(m, Simulator(m, ref.t_end, method, law=law, check_stability=False,
                                    exact_segments=False, **kw),
                       params, ref, threshold)
    status = "refused" if refused and check_stability else out[0]
    return Cell(method, float(param), float(setting), status, out[0], refused, *out[1:])


# -- the map ------------------------------------------------------------------------------

def run_map(model, param: str, values, methods, *, steps=None, rtols=None,
            fixed: dict | None = None, threshold: float = 1e-3, t_end: float | None = None,
            law: str = "cycloidal", check_stability: bool = True, progress=None) -> StabilityMap:
    """The map of ``methods`` over ``values`` of parameter ``param``: fixed-step methods over
    ``steps``, adaptive ones over ``rtols`` (a list, or a dict method -> list).  ``model`` is a
    model's name or file, or its target (:func:`target_of`); ``t_end`` None leaves each run's
    end to the window its figure needs."""
    target = model if hasattr(model, "model") else target_of(model, t_end, law, progress)
    m = target.model
    fixed = dict(fixed or {})
    if param not in m.parameter_names:
        raise CamdynInputError(f"model {m.name} has no parameter {param}; its parameters are "
                               f"{', '.join(m.parameter_names)}")
    if param in fixed:
        raise CamdynInputError(f"{param} is the map's parameter; do not also fix it")
    values = sorted(float(v) for v in values)
    if not values:
        raise CamdynInputError("the parameter grid is empty")
    if not (isinstance(threshold, (int, float)) and 0 < threshold < 1):
        raise CamdynInputError(f"threshold={threshold!r} is out of range: 0 < threshold < 1")
    settings = {}
    for meth in methods:
        if meth not in METHODS:
            raise CamdynInputError(f"unknown method {meth!r}; choose from {', '.join(METHODS)}")
        grid = rtols if METHODS[meth].adaptive else steps
        grid = grid.get(meth) if isinstance(grid, dict) else grid
        if not grid:
            raise CamdynInputError(f"method {meth} needs a grid of "
                                   f"{'rtols' if METHODS[meth].adaptive else 'steps'}")
        settings[meth] = sorted(float(s) for s in grid)
    if meth_koster_unusable(m, settings):
        raise CamdynInputError(f"method koster needs a purely second-order model; {m.name} has "
                               f"first-order states")
    n_cells = len(values) * sum(len(s) for s in settings.values())
    if n_cells > MAX_CELLS:
        raise CamdynInputError(f"the map has {n_cells} cells; at most {MAX_CELLS}")
    say = progress or (lambda msg: None)
    refs, limits = [], {k: [] for k in settings if not METHODS[k].adaptive}
    for v in values:
        params = {**fixed, param: v}
        m.parameter_vector(params)   # names and ranges checked before any run
    for v in values:
        refs.append(reference(target.with_parameters({**fixed, param: v})))
        for k in limits:
            limits[k].append(step_limit(m, k, refs[-1]))
    smap = StabilityMap(m.name, param, values, fixed, settings, threshold, figure_name(m),
                        check_stability, [reference_figure(m, r) for r in refs], limits,
                        reference_error=[r.error for r in refs], t_end=[r.t_end for r in refs])
    for v, r in zip(values, refs):
        smap.warnings += [f"the reference at {param} = {v:g}: {w}" for w in r.warnings]
        if r.error > 0.1 * threshold:
            smap.warnings.append(
                f"the reference at {param} = {v:g} is only good to {r.error:.2g} (relative), "
                f"not well inside the threshold {threshold:g}: it cannot tell fine from "
                "inaccurate there; raise --threshold")
    for meth, grid in settings.items():
        for v, ref in zip(values, refs):
            params = {**fixed, param: v}
            row = [classify_cell(target, meth, s, params, ref, threshold=threshold,
                                 t_end=ref.t_end, law=law, check_stability=check_stability,
                                 param=v) for s in grid]
            smap.cells += row
            say(f"{m.name} {meth} {param}={v:g}: " + " ".join(c.status.replace(" ", "_")
                                                            for c in row))
    return smap


def meth_koster_unusable(m: CompiledModel, settings: dict) -> bool:
    return "koster" in settings and len(m.state_names) != 2 * int(m.manifest.get("n_q", 0))


def largest_fine(smap: StabilityMap, method: str) -> list:
    """Per parameter value the largest step (or rtol) up to which every cell is fine (a
    coarser cell that is fine by coincidence, its error crossing zero, does not count);
    None if the finest is not."""
    out = []
    for v in smap.values:
        best = None
        for c in sorted((c for c in smap.cells if c.method == method and c.param == v),
                        key=lambda c: c.setting):
            if c.status != "fine":
                break
            best = c.setting
        out.append(best)
    return out


TAU_MAXIMA = [float(f"{2 / (2 * k + 1):.6g}") for k in (13, 9, 6, 4, 2)]
"""tau at the maxima 2/(2k + 1) of |sin(pi/tau)| in U0 (3.5), k = 13, 9, 6, 4, 2: near a zero
of U0 (tau = 1/n) a relative error means nothing."""

DEFAULT_PARAMS = {"one_dof": ("tau", TAU_MAXIMA), "camshaft1": ("tau", TAU_MAXIMA),
                  "roller": ("kappa", list(np.geomspace(100, 10000, 3)))}
"""The stiffness parameter's grid of a map when none is given."""


def study(name: str, param, methods, fixed: dict, rtols, steps, *, threshold: float,
          t_end: float | None, law: str, check_stability: bool = True,
          progress=None) -> StabilityMap:
    """The map of a model (a built-in one or a model file) over ``param`` = (name, values),
    or its default grid: ``methods`` (default: rk4, koster where the model is second order,
    dp54, rodas4), ``rtols`` (default 1e-3 .. 1e-10, 8), ``steps`` (default: 10 on a log grid
    around the theory's boundary over the grid, 1/50 of the smallest to 1.6 x the largest)."""
    target = target_of(name, t_end, law, progress)
    model = target.model
    if param is None:
        param = DEFAULT_PARAMS.get(model.name)
        if param is None:
            raise CamdynInputError(f"argument --param: required for {model.name} "
                                   f"(NAME=START:STOP:N, e.g. one of "
                                   f"{', '.join(model.parameter_names)})")
    pname, values = param
    methods = methods or [k for k in ("rk4", "koster", "dp54", "rodas4")
                          if not (k == "koster"
                                  and len(model.state_names) != 2 * model.manifest["n_q"])]
    for k in methods:
        if k not in METHODS:
            raise CamdynInputError(f"argument --methods: unknown method {k!r}; choose from "
                                   f"{', '.join(METHODS)}")
    # a grid no method of the map runs over would be dropped unread: refused, naming it
    for grid, flag, adaptive, what in ((steps, "--steps", False, "a fixed step (rk4, koster)"),
                                       (rtols, "--rtols", True, "a tolerance (dp54, dop853, "
                                                                "rodas4, radau5, rkn12)")):
        if grid and not any(METHODS[k].adaptive == adaptive for k in methods):
            raise CamdynInputError(f"argument {flag}: no method of the map ({', '.join(methods)})"
                                   f" takes {what}; leave {flag} out or add such a method to "
                                   "--methods")
    rtols = rtols or list(np.geomspace(1e-3, 1e-10, 8))
    if any(not r < 1 for r in rtols):
        raise CamdynInputError("argument --rtols: every rtol must be < 1")
    if not steps:
        lims = []
        for v in values:
            p = {**fixed, pname: v}
            model.parameter_vector(p)
            lims.append(step_limit(model, "rk4", reference(target.with_parameters(p))))
        steps = list(np.geomspace(min(lims) / 50, max(lims) * 1.6, 10))
    return run_map(target, pname, values, methods, steps=steps, rtols=rtols, fixed=fixed,
                   threshold=threshold, t_end=t_end, law=law, check_stability=check_stability,
                   progress=progress)
