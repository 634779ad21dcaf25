"""The Rayleigh-beam follower of the paper as a target: a case (runtime/targets/beam_case.py),
whole cam revolutions of the generated beam<N> module, the tip response.

Figures: the largest tip deflection |v_E| over the run (the paper's headline figure), the
largest constraint residual |Phi| (the solver's own check: the exact solution has 0) and the
lowest transverse natural frequency with the rod frozen at the outer dwell (an eigenproblem,
exact to rounding).  A cam profile whose groove wall is undercut for this roller is reported,
not refused: the model follows the pitch curve, so the run shows the designed motion, which a
cam cut for this roller could not give.
"""
from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np

from ..core.errors import CamdynInputError, SimulationError
from ..core.methods import METHODS
from ..core.compiled import load
from ..core.simulator import absolute_tolerances
from ..engine import driver
from ..measure import batch
from . import beam, scene_files
from .base import Batch, Figure, Outcome, Parameter, Target
from .beam_case import N_MAX, Case, check
from .problem import Problem

FIGURES = (
    Figure("max_abs_tip_deflection", "largest tip deflection |v_E| (the paper's figs 4-9)", "m"),
    Figure("max_constraint_residual", "largest constraint residual |Phi| (6), (7)", "m"),
    Figure("dwell_frequency_hz", "lowest transverse natural frequency at the outer dwell", "Hz",
           estimate="exact"),
)

UNITS = {"omega": "rad/s", "rod_radius": "m", "distance": "m", "base_radius": "m",
         "rise": "m", "roller_inertia": "kg m^2", "roller_radius": "m", "roller_mass": "kg",
         "E": "Pa", "rho": "kg/m^3", "w_B": "rad/s", "max_abs_tip_deflection": "m",
         "max_constraint_residual": "m", "dwell_frequency_hz": "Hz", "cpu_seconds": "s",
         "figures_cpu_seconds": "s"}
"""Units of the record's entries, for the table."""

INPUTS = ("omega", "modes", "rod_radius", "distance", "base_radius", "rise", "revolutions",
          "rayleigh", "roller_inertia", "formulation", "method")
"""The case's fields a user sets on the command line, in the order of its record."""


@dataclass(frozen=True)
class BeamTarget(Target):
    """A checked case of the beam follower."""

    case: Case
    label: str = "beam-follower"
    title: str = "Rayleigh-beam follower"

    kind = scene_kind = scene_files.BEAM
    time_name = "t"

    scene_doc = "the paper's Rayleigh-beam follower: tip response"

    @staticmethod
    def parse(data: dict, where: str):
        """The scene file's tables, checked (runtime/targets/scene_files.py)."""
        return scene_files.beam_from_dict(data, where)

    @classmethod
    def from_scene(cls, scene, label: str = ""):
        return cls(scene.case, label or scene.path, scene.title)

    @classmethod
    def of(cls, case: Case, label: str = "beam-follower"):
        return cls(check(case), label)

    @property
    def name(self) -> str:
        return self.label

    def parameters(self) -> dict:
        out = {f.name: Parameter(f.name, doc="a positive number", low=0.0, open_low=True)
               for f in fields(self.case) if f.type == "float"}
        out["modes"] = Parameter("modes", doc="assumed modes N", low=1, high=N_MAX, integer=True)
        return out

    def figures(self) -> tuple:
        # the constraint residual ought to be 0: it is judged against the rise, the size of
        # the motion, not against itself (rounding leaves it at 1e-16 m, unresolved by any run)
        tip, phi, freq = FIGURES
        return tip, replace(phi, scale=self.case.rise), freq

    def with_parameters(self, values: dict):
        if not values:
            return self
        # numbers from a grid or --set: the case's integer field (modes) takes them as integers
        vals = {k: int(v) if k == "modes" and float(v).is_integer() else v
                for k, v in values.items()}
        try:
            return replace(self, case=check(replace(self.case, **vals)))
        except TypeError as exc:
            raise CamdynInputError(f"the beam follower has no parameter: {exc}") from None

    def with_settings(self, method=None, rtol=None, atol=None, state_atol=None, **rest):
        if rest:
            raise CamdynInputError(f"{', '.join(rest)} of a beam-follower scene come from the "
                                   "scene file")
        changes = {k: v for k, v in (("method", method), ("rtol", rtol), ("atol", atol))
                   if v is not None}
        if state_atol:
            changes["state_atol"] = tuple(dict(state_atol).items())
        return replace(self, case=check(replace(self.case, **changes))) if changes else self

    def method(self):
        return beam.integrator(self.case)

    def tighter(self):
        base = self.method()
        m = base.tighter()
        if m is None:
            return None
        c, k = self.case, base.notch
        return replace(self, case=replace(
            c, rtol=m.rtol, atol=m.atol, state_atol=tuple((n, v / k) for n, v in c.state_atol),
            mode_atol=None if c.mode_atol is None else c.mode_atol / k))

    def run(self, progress=None) -> Outcome:
        from ..cam.motion import RDFD

        case = self.case
        cut = RDFD.of(case.rise, case.base_radius, case.roller_radius, case.law).undercut()
        summary, res = beam.run(case, progress)
        record = {key: getattr(case, key) for key in INPUTS}
        record["roller_inertia"] = case.J_r
        record["roller_inertia_default"] = case.roller_inertia is None
        for key in ("law", "roller_radius", "roller_mass", "E", "rho", "rtol", "w_B"):
            record[key] = getattr(case, key)
        record["model"] = summary["model"]
        for f in FIGURES:
            record[f.name] = summary[f.name]
        record["undercut"] = cut.message if cut else None
        record["n_steps"] = summary["n_steps"]
        record["stiff_from_T"] = summary["stiff_from_T"]   # model time t, s
        record["cpu_seconds"] = summary["cpu_seconds"]
        warnings = list(summary["warnings"])
        if cut:
            warnings.append(_undercut_warning(cut))
        stats = {k: summary[k] for k in ("n_steps", "cpu_seconds", "stiff_from_T")}
        return Outcome({f.name: summary[f.name] for f in FIGURES}, dict(summary["sampling"]), {},
                       warnings, record, stats, res)

    chunk = 8
    """Grid points per chunk: each point's consistent initial state is solved in Python before
    the chunk's runs go to compiled code together (:meth:`run_points`)."""

    def run_points(self, names: tuple, points: np.ndarray) -> Batch:
        """The points' runs in compiled calls holding no GIL (runtime/measure/batch.py), one
        for each beam<N> model the points use, every run from its consistent initial state
        solved beforehand, the figures found on each record as a single run finds them (the
        same numbers, bit for bit)."""
        from ..cam.motion import RDFD

        cases = [self.with_parameters(dict(zip(names, map(float, pt)))).case for pt in points]
        figs = self.figure_names()
        out = np.full((len(points), len(figs)), np.nan)
        samp = np.zeros_like(out)
        warnings, steps = [[] for _ in points], np.empty(len(points))
        groups: dict = {}
        for j, case in enumerate(cases):
            groups.setdefault(case.model, []).append(j)
        wanted = (beam.TIP, *beam.RESIDUALS)
        for rows in groups.values():
            sim, model = beam.simulator(cases[rows[0]])
            P = np.array([model.parameter_vector(beam.parameters(cases[j])) for j in rows])
            starts = [sim.start(p, beam.initial_state(cases[j], model)) for j, p in zip(rows, P)]
            t_end = np.array([cases[j].revolutions * cases[j].period for j in rows])
            # each case's own absolute tolerances (they follow its cam speed, beam.integrator)
            atol = np.array([absolute_tolerances(model, beam.integrator(cases[j]),
                                                 beam.initial_state(cases[j], model))
                             for j in rows])
            runs = batch.run_batch(sim, P, np.array([y for y, _ in starts]), t_end, wanted,
                                   np.full((len(rows), len(wanted), 2), [-np.inf, np.inf]),
                                   atol=atol)
            bad = np.flatnonzero(runs.stats["status"] != 0)
            if bad.size:
                j = rows[int(bad[0])]
                beam.run(cases[j])          # the failed point alone: it raises what it ran into
                raise SimulationError(f"{self.name} at " + ", ".join(
                    f"{k} = {v:g}" for k, v in zip(names, points[j])) + ": " +
                    driver.STATUS_TEXT[int(runs.stats["status"][bad[0]])])
            for i, j in enumerate(rows):
                tip, *phi = (runs.extreme(i, k) for k in range(len(wanted)))
                worst, sampling = beam.largest(tip, phi)
                figures = {"max_abs_tip_deflection": tip.value, "max_constraint_residual": worst,
                           "dwell_frequency_hz": beam.dwell_frequency(cases[j])}
                out[j] = [figures[f] for f in figs]
                samp[j] = [sampling.get(f, 0.0) for f in figs]
                c = cases[j]
                cut = RDFD.of(c.rise, c.base_radius, c.roller_radius, c.law).undercut()
                warnings[j] = ([starts[i][1]] if starts[i][1] else []) + \
                    ([_undercut_warning(cut)] if cut else []) + \
                    beam.large_deflection(c, tip.value)
                steps[j] = runs.stats["n_steps"][i]
        return Batch(out, samp, warnings, steps)

    def table(self, out: dict) -> list:
        """The record as a table with units, each figure with its estimate."""
        from ..measure.contract import exact_figures, note

        exact = exact_figures(self)
        rows = [(k, v) for k, v in out.items()
                if k not in ("figures", "warnings", "error_sources") and not k.endswith("_error")]
        rows = [(k, ("yes, see the warning" if v else "no") if k == "undercut" else v)
                for k, v in rows]
        width = max(len(k) for k, _ in rows)
        lines = []
        for k, v in rows:
            text = f"{v:.6g}" if isinstance(v, float) else str(v)
            text += note(out, k, exact)
            lines.append(f"{k:<{width}}  {text} {UNITS.get(k, '')}".rstrip())
        lines += [f"wrote {f}" for f in out.get("figures", [])]
        return lines

    def check_points(self, names, points) -> None:
        allowed = self.parameters()
        for k, name in enumerate(names):
            if name not in allowed:
                raise CamdynInputError(
                    f"grid {name}: not a parameter of {self.name}; its parameters are "
                    + ", ".join(f"{p.name} ({p.doc})" for p in allowed.values()))
        for pt in points:
            try:
                self.with_parameters(dict(zip(names, map(float, pt))))
            except CamdynInputError as exc:
                raise CamdynInputError(f"grid {exc}") from None

    def problem(self) -> Problem:
        case = self.case
        model = load(case.model)
        return Problem(label=f"{self.title}: {case.model}, {case.formulation}", model=model,
                       params=beam.parameters(case), t_end=case.revolutions * case.period,
                       read=lambda run: {"max_abs_tip_deflection": beam.tip_max(run)},
                       kind=self.kind, law=case.law, y0=beam.initial_state(case, model))

    @staticmethod
    def figure_files() -> list:
        """The names of the paper's figures :meth:`paper_figures` writes."""
        return [f"{name}.png" for name in beam.FIGURES]

    def paper_figures(self, out_dir, progress=None, estimate: bool = True, known=None) -> list:
        """PNG files of the paper's figs 4-9 in ``out_dir``: the tip deflection v_E against the
        cam angle Omega t (deg), one field of this case varied per figure (beam.FIGURES).
        Every curve is one answer (runtime/measure/contract.py): its largest |v_E| with its
        estimate in the legend, and the runs' warnings in the footnote.  A case that several
        figures draw (this case itself, in most of them) runs once; ``known``, this case's
        answer where the caller has it already, is not run again."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np

        from ..core.outdir import out_folder, writing
        from ..measure.contract import answer, chart_note, plus_minus

        out = out_folder(out_dir, files=self.figure_files())
        written = []
        answers = {} if known is None else {self.case: known}
        for (name, (field, values, label)), file in zip(beam.FIGURES.items(),
                                                         self.figure_files()):
            fig, ax = plt.subplots(figsize=(8, 4.4))
            tips, errors, warnings = [], [], []
            for v in values:
                case = self.with_parameters({field: v})
                a = answers.get(case.case)
                if a is None:
                    a = answers[case.case] = answer(case, estimate=estimate, progress=progress)
                elif progress:
                    progress("the same case as an earlier curve: its run is reused")
                res, omega = a.result, v if field == "omega" else self.case.omega
                tip, err = a.figures["max_abs_tip_deflection"], a.errors["max_abs_tip_deflection"]
                tips.append(tip)
                errors.append(err)
                warnings += [f"{label} = {v:g}: {w}" for w in a.warnings]
                t = np.linspace(0.0, res.t[-1], 4000)
                ax.plot(np.degrees(omega * t), res.sample(t)["vE"] * 1e3, lw=0.8,
                        label=f"{label} = {v:g}: max |v_E| = {tip * 1e3:.4g}"
                              f"{plus_minus(None if err is None else err * 1e3)} mm")
            ax.set_xlabel("cam angle [deg]")
            ax.set_ylabel("tip deflection v_E [mm]")
            ax.set_title(f"{name.replace('_', ' ')}: transverse response at the roller pin E")
            ax.grid(True, lw=0.3)
            ax.legend(fontsize=8)
            fig.text(0.01, 0.01, chart_note({"max |v_E|": (tips, errors)}, warnings),
                     fontsize=7)
            fig.tight_layout(rect=(0, 0.06, 1, 1))
            path = out / file
            with writing(path):
                fig.savefig(path, dpi=110)
            plt.close(fig)
            written.append(str(path))
        return written

    def figure_runs(self) -> list:
        """The runs of the paper's figs 4-9 (one field of this case varied each): (figure,
        field, value), each refused before anything runs if this case does not allow it."""
        planned = []
        for name, (field, values, _) in beam.FIGURES.items():
            for v in values:
                try:
                    check(replace(self.case, **{field: v}))
                except CamdynInputError as exc:
                    raise CamdynInputError(
                        f"argument --out: {name} sets {field}={v:g}, which this case does not "
                        f"allow: {exc}") from None
                planned.append((name, field, v))
        return planned



def _undercut_warning(cut) -> str:
    return f"{cut.message} The run follows the pitch curve all the same."
