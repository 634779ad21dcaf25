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
from ..core.simulator import absolute_tolerances
from ..engine import driver
from ..measure import batch
from ..measure.modes import amplitude_bound, slowest_periods
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
    Figure("U0", "positional error amplitude after the rise", output="U", dwell=True),
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
    Figure("U0_return", "positional error amplitude after the return", output="U", dwell=True),
)
"""A full turn's ([turn]) figures besides."""


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
        as a single run finds them (the same numbers, bit for bit).  A full turn's points run
        one at a time: a figure read from a dwell shorter than its window takes its estimate
        from the run's record (:meth:`_window_errors`)."""
        if self.scene.turn is not None:
            return super().run_points(names, points)
        pr = self.prepared
        model, sim = pr.model, pr.simulator
        scenes = [self.with_parameters(dict(zip(names, map(float, pt)))).scene for pt in points]
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
        ab = np.full((len(points), len(order), 2), np.nan)
        for j, sp in enumerate(spans):
            for k, key in enumerate(order):
                if key in sp:
                    ab[j, k] = sp[key].a, sp[key].b
        contact = self.scene.options.roller == "contact"
        # each point's own absolute tolerances, as its single run takes them from its start
        atol = np.array([absolute_tolerances(model, sim.method, y0) for y0 in Y0])
        runs = batch.run_batch(sim, P, Y0, t_end, tuple(wanted.values()), ab,
                               mode=("roller", "free") if contact else None, atol=atol)
        self._check_runs(runs, names, points)
        figs = self.figure_names()
        out = np.full((len(points), len(figs)), np.nan)
        samp = np.zeros_like(out)
        for j, (sc, (_, ch, _)) in enumerate(zip(scenes, placed)):
            figures, sampling = dict.fromkeys(keys), {}
            for k, key in enumerate(order):
                if key in spans[j]:
                    dynacam.read_span(spans[j][key], runs.extreme(j, k), ch["t_m"], sc.T_start,
                                      figures, sampling)
            figures.update(tau=ch["tau"], Fa=ch["Fa"], Fv=ch["Fv"])
            first = np.nan if runs.first_in_mode is None else runs.first_in_mode[j]
            figures["jump_occurs"] = float(first == first)
            figures["jump_T"] = first / ch["t_m"] + sc.T_start if first == first else None
            for k, f in enumerate(figs):
                v = figures.get(f)
                out[j, k] = np.nan if v is None else float(v)
                samp[j, k] = sampling.get(f, 0.0) + 0.0
        return Batch(out, samp, [[] for _ in points], runs.stats["n_steps"].astype(float))

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
        sim = pr.simulator
        p = pr.model.parameter_vector(pr.params)
        spans = dynacam.dwell_spans(self.scene, pr.t_m, pr.t_end)
        outputs = {"U0": "U", "U0dd": "Xdd", "U0_return": "U", "U0dd_return": "Xdd"}
        names = [k for k in spans if figures.get(k) is not None]
        periods = slowest_periods(pr.model, p, sim.law_codes, sim.law_pars, sim.t0, pr.y0,
                                  [outputs[k] for k in names],
                                  np.array(sim.modes0, dtype=np.intc) if sim.modes0 else None)[0]
        window, notes = {}, []
        for k, name in enumerate(names):
            a, b = spans[name]
            period = float(periods[k])
            if period <= 0 or b - a >= period:
                continue
            bound = amplitude_bound(res, outputs[name], a, b, period)
            window[name] = max(0.0, bound - figures[name])
            notes.append(f"{name} is read from a dwell of {(b - a) / pr.t_m:.3g} (T), shorter "
                         f"than one period of the slowest mode it sees ({period / pr.t_m:.3g}): "
                         f"its estimate includes {window[name]:.2g} for the part of the "
                         "oscillation the dwell does not show")
        return window, notes

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
            for key in ("Xdd_absmax_return", "U0dd_return", "U0_return"):
                v = out.get(key)
                lines.append(f"  {key:26s} {'not reached' if v is None else fmt(v)}"
                             f"{plus_minus(out.get(f'{key}_error'))}")
        lines += [f"wrote {f}" for f in out.get("figures", [])]
        return lines

    def main_job(self, out_dir, answer, progress=None) -> list:
        from .dynacam_diagrams import plot

        return plot(self.scene, answer.result, answer.as_dict(), out_dir)
