"""A DYNACAM scene (thesis ch. 6-8) as a target: the variant its options select, run from
the consistent initial state over the scene's span, its summary's figures.

The figures are those `camdyn simulate` prints: the characteristic numbers tau, Fa, Fv of
the scene's parameters (4.3)-(5.52) (exact: they follow from the parameters), the extremes of
X'' in the rise, U0'' and U0 in the dwell after it, whether and where the follower leaves
the cam, the largest speed variations, and with a [turn] the return's figures
(runtime/targets/dynacam.py).  The dwell after the rise is the scene's to set (run.T_end): a
dwell shorter than a figure's window is refused, naming run.T_end; a full turn's dwells end
at the cam's next motion, so a figure read there from too short a dwell carries an estimate
of that error (runtime/measure/modes.py) and a warning instead.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from ..core.errors import CamdynInputError, SimulationError
from ..core.methods import ADAPTIVE, METHODS
from ..core.simulator import Simulator, absolute_tolerances
from ..engine import driver
from ..measure import batch
from ..measure.modes import amplitude_from, amplitude_times, slowest_periods
from . import dynacam, scene_files
from .base import Batch, Figure, Outcome, Parameter, Target, Window
from .problem import Problem

FIGURES = (
    Figure("tau", "T_e/t_m of the follower system (4.3), (4.39), (4.12)", estimate="exact"),
    Figure("Fa", "shaft stiffness factor (4.14)", estimate="exact"),
    Figure("Fv", "flywheel factor (5.52)", estimate="exact"),
    Figure("Xdd_min_rise", "largest deceleration in the rise, x'' t_m^2/h_m"),
    Figure("T_at_Xdd_min", "where it is, nominal T", place=True),
    Figure("Xdd_max_rise", "largest acceleration in the rise"),
    Figure("U0dd", "residual acceleration amplitude after the rise", output="Xdd", dwell=True),
    Figure("U0", "positional error amplitude after the rise, about the dwell's static "
                 "equilibrium", output="U", dwell=True),
    Figure("U_static", "positional error at the dwell's static equilibrium: the follower "
                       "train and the shaft pressed by the spring (-(F_0 + c_s h)/(c_x h_m) "
                       "on a rigid shaft)", estimate="exact"),
    Figure("jump_occurs", "the follower leaves the cam (1) or not (0)", estimate="none"),
    Figure("jump_T", "where it first leaves, nominal T", place=True),
    Figure("speed_variation_max", "largest variation of the fictitious angular velocity",
           output="speed_var", dwell=True),
    Figure("motor_speed_variation_max", "largest speed variation of the motor",
           output="motor_speed_var", dwell=True),
)
"""A scene's figures, in the order of its table."""

RETURN_FIGURES = (
    Figure("Xdd_absmax_return", "largest |X''| during the return of a full turn"),
    Figure("U0dd_return", "residual acceleration amplitude after the return", output="Xdd",
           dwell=True),
    Figure("U0_return", "positional error amplitude after the return, about the dwell's "
                        "static equilibrium", output="U", dwell=True),
    Figure("U_static_return", "positional error at the static equilibrium of the dwell "
                              "after the return", estimate="exact"),
)
"""A full turn's ([turn]) figures besides."""

WINDOW_OUTPUTS = {"U0": "U", "U0dd": "Xdd", "U0_return": "U", "U0dd_return": "Xdd"}
"""The dwell figures of a full turn that may be read from a dwell shorter than their window,
and the output each is read from."""


@dataclass(frozen=True)
class ShortDwell:
    """A dwell figure read from [a, b], shorter than ``period``, the slowest mode its output
    sees; ``times`` where its amplitude is sampled (runtime/measure/modes.py
    amplitude_times)."""

    name: str
    output: str
    a: float
    b: float
    period: float
    times: np.ndarray


def short_dwells(scene, model, p, sim, y0, t_m: float, t_end: float, present) -> list:
    """The ShortDwells of a full turn's run with parameters p from y0 to t_end: of the dwell
    figures in ``present`` (those the run reaches), the ones whose dwell is shorter than one
    period of the slowest mode their output sees at the start (sim's laws, modes and t0)."""
    spans = dynacam.dwell_spans(scene, t_m, t_end)
    present = {k.split(":")[0] for k in present}      # U0 is read as U0:max and U0:min
    names = [k for k in spans if k in present]
    periods = slowest_periods(model, p, sim.law_codes, sim.law_pars, sim.t0, y0,
                              [WINDOW_OUTPUTS[k] for k in names],
                              np.array(sim.modes0, dtype=np.intc) if sim.modes0 else None)[0]
    out = []
    for k, name in enumerate(names):
        a, b = spans[name]
        period = float(periods[k])
        if period <= 0 or b - a >= period:
            continue
        out.append(ShortDwell(name, WINDOW_OUTPUTS[name], a, b, period,
                              amplitude_times(a, b, period)))
    return out


def _level(d: ShortDwell, figures: dict) -> float:
    """What the oscillation of a short dwell's output is about: U's static equilibrium
    (runtime/targets/dynacam.py dwell_static), 0 for X''."""
    key = dynacam.STATIC.get(d.name)
    return float(figures.get(key) or 0.0) if key else 0.0


def window_errors(short: list, bounds: list, figures: dict, t_m: float) -> tuple[dict, list]:
    """(figure -> the part of the oscillation its short dwell does not show, the warning of
    each) from the amplitude each ShortDwell shows (``bounds``, modes.amplitude_bound)."""
    window, notes = {}, []
    for d, bound in zip(short, bounds):
        window[d.name] = max(0.0, bound - figures[d.name])
        notes.append(f"{d.name} is read from a dwell of {(d.b - d.a) / t_m:.3g} (T), shorter "
                     f"than one period of the slowest mode it sees ({d.period / t_m:.3g}): "
                     f"its estimate includes {window[d.name]:.2g} for the part of the "
                     "oscillation the dwell does not show")
    return window, notes


@dataclass(frozen=True)
class DynacamTarget(Target):
    """A checked DYNACAM scene and how its runs are made: ``notches`` tighter than its own
    method (for the error estimate)."""

    scene: object                    # scene_files.DynacamScene
    label: str = ""
    notches: int = 0

    kind = scene_kind = scene_files.DYNACAM

    scene_doc = "a DYNACAM mechanism (thesis ch. 6-8): summary and diagrams"

    @staticmethod
    def parse(data: dict, where: str):
        """The scene file's tables, checked (runtime/targets/scene_files.py)."""
        return scene_files.from_dict(data, where)

    @classmethod
    def from_scene(cls, scene, label: str = ""):
        return cls(scene, label)

    @property
    def name(self) -> str:
        return self.label or self.scene.path

    @property
    def title(self) -> str:
        return self.scene.title

    def parameters(self) -> dict:
        declared = scene_files.declared_parameters(self.scene.options)
        return {k: Parameter(k, s.unit, s.doc, s.low, s.high, s.open_low, s.open_high)
                for k, s in declared.items() if k != "beta_0"}

    def figures(self) -> tuple:
        return FIGURES + (RETURN_FIGURES if self.scene.turn is not None else ())

    def with_parameters(self, values: dict):
        if not values:
            return self
        try:
            return replace(self, scene=scene_files.replace(self.scene, parameters=dict(values)))
        except CamdynInputError as exc:
            raise CamdynInputError(str(exc).replace("parameters.", "", 1)) from None

    def check_points(self, names, points) -> None:
        """Names and ranges as the scene file checks them (a [turn] depends on beta_m too), at
        each axis's ends."""
        super().check_points(names, points)
        for k, name in enumerate(names):
            for v in (points[:, k].min(), points[:, k].max()):
                try:
                    self.with_parameters({name: float(v)})
                except CamdynInputError as exc:
                    raise CamdynInputError(f"grid {name}: {exc}") from None

    def with_settings(self, method=None, rtol=None, atol=None, state_atol=None, **rest):
        if rest:
            raise CamdynInputError(f"{', '.join(rest)} of a scene come from the scene file")
        changes = {}
        if atol is not None or state_atol:
            # checked as the scene file's [run] is
            tol = scene_files.tolerances({k: v for k, v in (("atol", atol), (
                "state_atol", dict(state_atol or {}))) if v})
            changes.update(tol)
        if method is not None:
            if not METHODS[method].adaptive:
                raise CamdynInputError(f"method {method}: a dynacam scene takes an adaptive "
                                       f"method, {', '.join(ADAPTIVE)}")
            changes["method"] = method
        if rtol is not None:
            changes["rtol"] = rtol
        return replace(self, scene=replace(self.scene, **changes)) if changes else self

    def method(self):
        m = dynacam.scene_method(self.scene)
        for _ in range(self.notches):
            m = m.tighter()
        return m

    def tighter(self):
        return None if self.method().tighter() is None else replace(self, notches=self.notches + 1)

    @cached_property
    def prepared(self) -> dynacam.Prepared:
        return dynacam.prepare(self.scene, self.method())

    def window(self) -> Window:
        pr, sc = self.prepared, self.scene
        dwell = [f for f in self.figures() if f.dwell and f.output in pr.model.output_names]
        sim = pr.simulator
        p = pr.model.parameter_vector(pr.params)
        periods = slowest_periods(pr.model, p, sim.law_codes, sim.law_pars, sim.t0, pr.y0,
                                  [f.output for f in dwell],
                                  np.array(sim.modes0, dtype=np.intc) if sim.modes0 else None)[0]
        spans = dynacam.dwell_spans(sc, pr.t_m, pr.t_end)
        after_rise = spans["U0"][1] - spans["U0"][0]
        return Window(available=after_rise / pr.t_m,
                      needed={f.name: float(periods[k]) / pr.t_m for k, f in enumerate(dwell)
                              if f.name in ("U0", "U0dd", "speed_variation_max",
                                            "motor_speed_variation_max")},
                      setting="run.T_end", end=sc.T_end, end_for=lambda need: 1.0 + need,
                      given=True, fixed=sc.turn is not None)

    def run(self, progress=None) -> Outcome:
        pr, sc = self.prepared, self.scene
        w = self.window()
        r = dynacam.run_scene(sc, progress, prepared=pr)
        s = r.summary
        figures = {f.name: s.get(f.name) for f in self.figures()}
        figures["jump_occurs"] = bool(s["jump"]["occurs"])
        figures["jump_T"] = s["jump"]["T"]
        warnings = list(s["warnings"])
        window = {}
        if w.fixed:
            window, notes = self._window_errors(r.result, figures)
            warnings += notes
        stats = {k: s[k] for k in ("n_steps", "n_events", "cpu_seconds", "stiff_from_T")}
        return Outcome(figures, dict(r.sampling), window, warnings, s, stats, r.result)

    chunk = 16
    """Grid points per chunk: each point's consistent initial state is solved in Python before
    the chunk's runs go to compiled code together (:meth:`run_points`)."""

    def run_points(self, names: tuple, points: np.ndarray) -> Batch:
        """The points' runs in one compiled call holding no GIL (runtime/measure/batch.py), each
        from its consistent initial state solved beforehand, the figures found on each record
        as a single run finds them (the same numbers, bit for bit).  With a full turn a dwell
        figure read from a dwell shorter than its window takes its estimate from the record
        (:meth:`_window_errors`): the compiled call samples the dense output where
        runtime/measure/modes.py amplitude_bound samples a single run's, so the estimates and
        their warnings are the single runs' too, bit for bit.  A full turn's cam law depends
        on the rise angle beta_m: points with different ones go in one call each."""
        scenes = [self.with_parameters(dict(zip(names, map(float, pt)))).scene for pt in points]
        figs = self.figure_names()
        n = len(points)
        out = np.full((n, len(figs)), np.nan)
        samp = np.zeros_like(out)
        warnings, steps = [[] for _ in range(n)], np.empty(n)
        groups: dict = {}
        for j, sc in enumerate(scenes):
            key = None if sc.turn is None else scene_files.turn_angles(sc)
            groups.setdefault(key, []).append(j)
        own = None if self.scene.turn is None else scene_files.turn_angles(self.scene)
        for key, idx in groups.items():
            sim = self.prepared.simulator if key == own else Simulator(
                self.prepared.model, self.prepared.t_end, self.method(),
                law=scenes[idx[0]].cam_law(), modes=self.scene.modes,
                max_steps=dynacam.MAX_STEPS, dense_output=True)
            self._run_group(names, points, scenes, idx, sim, out, samp, warnings, steps)
        return Batch(out, samp, warnings, steps)

    def _run_group(self, names, points, scenes, idx, sim, out, samp, warnings, steps) -> None:
        """The runs of points ``idx`` (one cam law, ``sim``'s) in one compiled call, their rows
        of the batch filled in."""
        model = self.prepared.model
        idx = np.asarray(idx)
        scenes = [scenes[j] for j in idx]
        placed = [dynacam.placed(sc) for sc in scenes]
        P = np.array([model.parameter_vector(params) for params, _, _ in placed])
        Y0 = np.array([dynacam.equilibrium(model, p, sim) for p in P])
        t_end = np.array([end for _, _, end in placed])
        keys, wanted, spans = None, {}, []
        for sc, (_, ch, end) in zip(scenes, placed):
            keys, sp = dynacam.headline_spans(sc, ch["t_m"], sim.t0, end, model.output_names)
            spans.append({s.key: s for s in sp})
            for s in sp:
                wanted.setdefault(s.key, batch.Wanted(s.name, s.absolute, s.minimum))
        order = list(wanted)
        ab = np.full((len(idx), len(order), 2), np.nan)
        for j, sp in enumerate(spans):
            for k, key in enumerate(order):
                if key in sp:
                    ab[j, k] = sp[key].a, sp[key].b
        # a full turn's dwells shorter than their window: the times their estimate samples
        short = [[] for _ in idx]
        if self.scene.turn is not None:
            short = [short_dwells(sc, model, p, sim, y0, ch["t_m"], end, spans[j])
                     for j, (sc, p, y0, (_, ch, end)) in enumerate(zip(scenes, P, Y0, placed))]
        width = max((len(d.times) for sh in short for d in sh), default=0)
        times = np.full((len(idx), len(WINDOW_OUTPUTS), width), np.nan)
        for j, sh in enumerate(short):
            for d in sh:
                times[j, list(WINDOW_OUTPUTS).index(d.name), :len(d.times)] = d.times
        contact = self.scene.options.roller == "contact"
        # each point's own absolute tolerances, as its single run takes them from its start
        atol = np.array([absolute_tolerances(model, sim.method, y0) for y0 in Y0])
        runs = batch.run_batch(sim, P, Y0, t_end, tuple(wanted.values()), ab,
                               mode=("roller", "free") if contact else None, atol=atol,
                               samples=tuple(WINDOW_OUTPUTS.values()) if width else (),
                               sample_times=times if width else None)
        self._check_runs(runs, names, points[idx])
        figs = self.figure_names()
        for j, (sc, (_, ch, _)) in enumerate(zip(scenes, placed)):
            figures, sampling = dict.fromkeys(keys), {}
            for k, key in enumerate(order):
                if key in spans[j]:
                    dynacam.read_span(spans[j][key], runs.extreme(j, k), ch["t_m"], sc.T_start,
                                      figures, sampling)
            dynacam.combine_static(figures, sampling, {
                key: dynacam.dwell_static(model, P[j], sim.law_codes, sim.law_pars, t,
                                          dynacam.turned(model, P[j], Y0[j], t - sim.t0,
                                                         lifted=key == "U0"))
                for key, t in dynacam.static_times(spans[j].values()).items()})
            figures.update(tau=ch["tau"], Fa=ch["Fa"], Fv=ch["Fv"])
            first = np.nan if runs.first_in_mode is None else runs.first_in_mode[j]
            figures["jump_occurs"] = float(first == first)
            figures["jump_T"] = first / ch["t_m"] + sc.T_start if first == first else None
            bounds = [amplitude_from(d.times, runs.samples[j, list(WINDOW_OUTPUTS).index(
                d.name), :len(d.times)] - _level(d, figures), d.period) for d in short[j]]
            window, notes = window_errors(short[j], bounds, figures, ch["t_m"])
            g = idx[j]
            for k, f in enumerate(figs):
                v = figures.get(f)
                out[g, k] = np.nan if v is None else float(v)
                samp[g, k] = sampling.get(f, 0.0) + window.get(f, 0.0)
            warnings[g] = notes
            steps[g] = float(runs.stats["n_steps"][j])

    def _check_runs(self, runs, names, points) -> None:
        """A run of the batch that failed, run alone: it raises what it ran into."""
        bad = np.flatnonzero(runs.stats["status"] != 0)
        if not bad.size:
            return
        pt = dict(zip(names, map(float, points[int(bad[0])])))
        self.with_parameters(pt).run()
        raise SimulationError(f"{self.name} at {', '.join(f'{k} = {v:g}' for k, v in pt.items())}:"
                              f" {driver.STATUS_TEXT[int(runs.stats['status'][bad[0]])]}")

    def _window_errors(self, res, figures) -> tuple[dict, list]:
        """A full turn's dwells end at the cam's next motion: a dwell figure read from a span
        shorter than one period of the slowest mode its output sees carries the difference
        between the amplitude the span shows (runtime/measure/modes.py) and its value."""
        pr = self.prepared
        p = pr.model.parameter_vector(pr.params)
        short = short_dwells(self.scene, pr.model, p, pr.simulator, pr.y0, pr.t_m, pr.t_end,
                             {k for k, v in figures.items() if v is not None})
        bounds = [amplitude_from(d.times, res.sample(d.times)[d.output] - _level(d, figures),
                                 d.period) for d in short]
        return window_errors(short, bounds, figures, pr.t_m)

    def problem(self) -> Problem:
        pr, sc = self.prepared, self.scene
        return Problem(label=sc.title, model=pr.model, params=pr.params, t_end=pr.t_end,
                       read=lambda run: {k: v for k, v in dynacam.headline(sc, run, pr.t_m)[0]
                                         .items() if v is not None and k in self.scored()},
                       kind=self.kind, law=sc.cam_law(), y0=pr.y0, modes=dict(sc.modes))

    def table(self, out: dict) -> list:
        """The summary as `camdyn simulate` prints it, each figure with its estimate."""
        from ..measure.contract import exact_figures, note, plus_minus

        def fmt(v):
            return "-" if v is None else f"{float(v):.4g}"

        exact = exact_figures(self)
        lines = [self.scene.title]
        for key in dynacam.KEYS:
            v = out.get(key)
            if key == "jump":
                v = f"from T = {v['T']:.4g}" if v["occurs"] else "no"
                extra = plus_minus(out.get("jump_T_error"))
            else:
                extra = note(out, key, exact)
            lines.append(f"  {key:26s} {v if isinstance(v, str) else fmt(v)}{extra}")
        if "turn" in out:
            t = out["turn"]
            lines.append(f"  full turn: rise, upper dwell, return, lower dwell "
                         f"{', '.join(f'{a:.4g}' for a in t['angles_deg'])} deg; return law "
                         f"{t['return_law']}")
            for key in ("Xdd_absmax_return", "U0dd_return", "U0_return", "U_static_return"):
                v = out.get(key)
                lines.append(f"  {key:26s} {'not reached' if v is None else fmt(v)}"
                             f"{note(out, key, exact) if v is not None else ''}")
        lines += [f"wrote {f}" for f in out.get("figures", [])]
        return lines

    def main_files(self) -> list:
        """The diagrams main_job writes (runtime/targets/dynacam_diagrams.py plot), named
        before the run from the outputs the scene's model has: one per diagram that has
        something to draw."""
        from pathlib import Path

        from .dynacam_diagrams import DIAGRAMS

        names = set(self.prepared.model.output_names)
        drawn = {"gaps": ("gear_gap", "roller_gap")}
        stem = Path(self.scene.path).stem
        return [f"{stem}_{key}.png" for key, _, _ in DIAGRAMS
                if names & set(drawn.get(key, (key,)))]

    def main_job(self, out_dir, answer, progress=None) -> list:
        from .dynacam_diagrams import plot

        return plot(self.scene, answer.result, answer.as_dict(), out_dir)
