"""The CAMSHAFT-1 study of thesis ch. 4 as a target, and its main job (`camdyn run`'s
default): report and charts.

As a target it is CAMSHAFT-1 (4.15) with the scene's law, method and tolerance at the
response's tau and its largest Fa (what a work-precision study or a sweep of the scene
runs).  Its main job writes into the output folder

    report.md      what was run and the key figures next to the thesis's, each with its
                   error estimate, and the runs' warnings; with a [follower], its design
                   point (tau, Fa) and the reduced figures it came from
    report.json    the same for machines
    response.png   X'' against T at one tau for several Fa (fig. 4.10)
    graphs.png     U0, max deceleration and its instant, U0dd against tau (fig. 4.11), U0 and
                   U0dd with their envelopes through the maxima (secs 3.5, 8.2.6); a
                   follower's design point marked
    envelopes.csv  U0 and U0dd and their envelopes per Fa and tau, with U0's and U0dd's
                   error estimates
"""
from __future__ import annotations

import json
import math
import time
from dataclasses import dataclass

import numpy as np

from ..core.methods import ADAPTIVE
from ..core.outdir import out_folder, writing, write_text
from ..measure import references
from ..measure.contract import answer, chart_note, quotient
from ..measure.envelope import envelope, envelope_error, tau_grid
from ..measure.residual import FIGURES as RESIDUAL_FIGURES
from . import scene_files
from .grid import run_grid
from .model_target import ModelTarget


def load_scene(path: str | None = None) -> dict:
    """The study scene at ``path`` (a file or a built-in name) or the embedded default, checked
    (:func:`camdyn.runtime.targets.scene_files.check_study`)."""
    data, where = scene_files.read("default" if path is None else path)
    scene_files.expect_kind(data, where, scene_files.STUDY)
    return scene_files.check_study(data, where)


FILES = ("report.md", "report.json", "response.png", "graphs.png", "envelopes.csv")
"""What the study writes into its folder."""


@dataclass(frozen=True)
class StudyTarget(ModelTarget):
    """CAMSHAFT-1 with a study scene's settings; ``scene`` the checked study table."""

    scene: object = None

    kind = scene_kind = scene_files.STUDY

    scene_doc = "the CAMSHAFT-1 study of thesis ch. 4 (figs 4.10, 4.11): report and charts"

    @staticmethod
    def parse(data: dict, where: str):
        """The scene file's tables, checked (runtime/targets/scene_files.py)."""
        return scene_files.check_study(data, where)

    @classmethod
    def from_scene(cls, data: dict, label: str = ""):
        resp, run = data["study"]["response"], data["run"]
        adaptive = run["method"] in ADAPTIVE
        t = cls.of("camshaft1", {"tau": resp["tau"], "Fa": max(resp["Fa"])},
                   method=run["method"], rtol=run["rtol"] if adaptive else None,
                   law=data["law"], theta=data.get("theta"), label=label or data["title"],
                   **scene_files.tolerances(run))
        return cls(**{**t.__getstate__(), "scene": data})

    @property
    def name(self) -> str:
        return self.label

    @property
    def title(self) -> str:
        return self.scene["title"] if self.scene else self.label

    def job(self, out_dir, estimate: bool = True, progress=None) -> dict:
        """`camdyn run`: the study (module doc); returns report.json's record with the files
        written and the text to print."""
        record = self.study(out_dir, estimate, progress)
        record["lines"] = [f"report: {out_dir / 'report.md'}"]
        if "design_point" in record:
            d = record["design_point"]
            record["lines"].insert(0, f"design point of the follower: tau = {d['tau']:.4g}, "
                                      f"Fa = {d['Fa']:.4g}; U0 = {_pm(d['U0'], d['U0_error'])}")
        return record

    def study(self, out_dir, estimate: bool = True, progress=None) -> dict:
        """The study (module doc); returns report.json's record with the files written."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        say = progress or (lambda msg: None)
        out_dir = out_folder(out_dir, files=FILES)     # a file of the user's: refused now
        t_start = time.perf_counter()
        scene = self.scene
        resp, graphs = scene["study"]["response"], scene["study"]["graphs"]

        # fig. 4.10: response curves
        say(f"response curves at tau = {resp['tau']} for Fa = {resp['Fa']}")
        fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
        T = np.linspace(0.0, 3.0, 3001)
        summary = {"scene": scene["title"], "law": scene["law"], "response": []}
        warnings = []
        for Fa in resp["Fa"]:
            a = answer(self.with_parameters({"tau": resp["tau"], "Fa": Fa}), estimate=estimate)
            r = a.result
            s = r.sample(T)
            row = {"Fa": Fa, **{k: a.figures[k] for k in RESIDUAL_FIGURES}}
            row.update({f"{k}_error": a.errors.get(k) for k in RESIDUAL_FIGURES})
            row.update(r.stats)
            row["warnings"] = list(a.warnings)
            warnings += [f"Fa = {Fa:g}: {w}" for w in a.warnings]
            summary["response"].append(row)
            ax[0].plot(T, s["Xdd"], label=_fa_label(Fa, scene))
            ax[1].plot(T, s["U"], label=_fa_label(Fa, scene))
        ax[0].plot(T, s["Hdd"], "k--", lw=0.8, label="nominal H''")
        ax[0].set_ylabel("X''  (h_m'/t_m^2)")
        ax[1].set_ylabel("U = X - H  (h_m')")
        ax[1].set_xlabel("T = t/t_m")
        ax[0].set_title(f"CAMSHAFT-1, {scene['law']} rise, tau = {resp['tau']:g} "
                        "(cf. thesis fig. 4.10)")
        for a_ in ax:
            a_.grid(alpha=0.3)
            a_.legend(fontsize=8)
        resp_rows = summary["response"]
        fig.text(0.01, 0.01, chart_note(
            {k: ([d[k] for d in resp_rows], [d[f"{k}_error"] for d in resp_rows])
             for k in RESIDUAL_FIGURES[:3]}, warnings), fontsize=7)
        fig.tight_layout(rect=(0, 0.05, 1, 1))
        with writing(out_dir / "response.png") as path:
            fig.savefig(path, dpi=120)
        plt.close(fig)

        # fig. 4.11: graphs against tau, uniform in 1/tau so that every tuning dip of (3.5) is
        # resolved alike (runtime/measure/envelope.py), in one compiled grid on every core
        taus = tau_grid(graphs["tau_min"], graphs["tau_max"], graphs["n_tau"])
        say(f"  graphs: {len(taus) * len(graphs['Fa'])} runs"
            f"{', each with its error estimate' if estimate else ''}")
        pts = np.array([[Fa, tau] for Fa in graphs["Fa"] for tau in taus])
        grid = run_grid(self, ("Fa", "tau"), pts, estimate=estimate)
        cols = grid.columns
        keys = RESIDUAL_FIGURES
        rows = {Fa: [{k: float(cols[k][j * len(taus) + i]) for k in keys}
                     | {f"{k}_error": _float(cols[f"{k}_error"][j * len(taus) + i]) for k in keys}
                     for i in range(len(taus))] for j, Fa in enumerate(graphs["Fa"])}
        if grid.warned:
            warnings.append(f"{grid.warned} of {len(pts)} graph runs warned (envelopes.csv)")
        fig, ax = plt.subplots(2, 2, figsize=(11, 8))
        envelopes, envelope_errors = {}, {}
        for k, (Fa, vals) in enumerate(rows.items()):
            colour = f"C{k}"
            label = _fa_label(Fa, scene)
            U0 = [v["U0"] for v in vals]
            U0dd = [v["U0dd"] for v in vals]
            # the curves a designer reads (secs 3.5, 8.2.6): through the maxima, bold; the
            # raw graph thin beneath them
            envelopes[Fa] = {"U0": envelope(taus, U0), "U0dd": envelope(taus, U0dd)}
            if estimate:
                envelope_errors[Fa] = {
                    k: envelope_error(taus, [v[k] for v in vals],
                                      [np.nan if v[f"{k}_error"] is None else v[f"{k}_error"]
                                       for v in vals])(taus) for k in ("U0", "U0dd")}
            ax[0, 0].semilogy(taus, U0, color=colour, lw=0.6, alpha=0.6)
            ax[0, 0].semilogy(taus, envelopes[Fa]["U0"](taus), color=colour, lw=1.8,
                              label=label)
            ax[0, 1].plot(taus, [-v["Xdd_min_rise"] for v in vals], color=colour,
                          label=label)
            ax[1, 0].plot(taus, [v["T_at_Xdd_min"] for v in vals], color=colour,
                          label=label)
            ax[1, 1].plot(taus, U0dd, color=colour, lw=0.6, alpha=0.6)
            ax[1, 1].plot(taus, envelopes[Fa]["U0dd"](taus), color=colour, lw=1.8,
                          label=label)
        design = _design_row(scene, summary["response"])
        if design is not None:
            _mark(ax, design, f"C{list(rows).index(design['Fa'])}")
        if scene["law"] == "cycloidal":
            fine = np.linspace(graphs["tau_min"], min(graphs["tau_max"], 0.99), 600)
            ax[0, 0].semilogy(fine, references.U0(fine), "k:", lw=0.8, label="(3.5)")
        ax[0, 0].set_ylabel("U0 (bold: envelope through the maxima)")
        ax[0, 1].set_ylabel("-X''min during rise")
        ax[1, 0].set_ylabel("T at X''min")
        ax[1, 1].set_ylabel("U0'' (bold: envelope through the maxima)")
        for a_ in ax.ravel():
            a_.set_xlabel("tau")
            a_.grid(alpha=0.3, which="both")
        ax[0, 0].legend(fontsize=7)
        fig.suptitle(f"CAMSHAFT-1 response graphs, {scene['law']} rise "
                     "(cf. thesis fig. 4.11a-c)")
        fig.text(0.01, 0.01, chart_note(
            {k: (cols[k], cols[f"{k}_error"]) for k in keys}, cols["warnings"],
            points=len(pts)), fontsize=7)
        fig.tight_layout(rect=(0, 0.06, 1, 1))
        with writing(out_dir / "graphs.png") as path:
            fig.savefig(path, dpi=120)
        plt.close(fig)

        summary["graphs"] = {"tau": taus.tolist(), "rows": {str(Fa): v for Fa, v in rows.items()}}
        # the envelopes as data: their maxima per Fa, and the curves on the graph's tau grid
        summary["envelopes"] = {str(Fa): {k: {"tau_at_maxima": e.tau.tolist(),
                                              "maxima": e.value.tolist()}
                                          for k, e in env.items()}
                                for Fa, env in envelopes.items()}
        with writing(out_dir / "envelopes.csv") as path, open(path, "w") as fh:
            fh.write("Fa,tau,U0,U0_error,U0_envelope,U0_envelope_error,U0dd,U0dd_error,"
                     "U0dd_envelope,U0dd_envelope_error,warnings\n")
            for j, (Fa, vals) in enumerate(rows.items()):
                e = envelopes[Fa]
                ee = envelope_errors.get(Fa, {"U0": [None] * len(taus),
                                              "U0dd": [None] * len(taus)})
                for i, (tau, v) in enumerate(zip(taus, vals)):
                    w = cols["warnings"][j * len(taus) + i]
                    fh.write(f"{Fa:g},{tau:.10g},{v['U0']:.10g},{_cell(v['U0_error'])},"
                             f"{e['U0'](tau):.10g},{_cell(ee['U0'][i])},"
                             f"{v['U0dd']:.10g},{_cell(v['U0dd_error'])},"
                             f"{e['U0dd'](tau):.10g},{_cell(ee['U0dd'][i])},\"{w}\"\n")
        ratio, ratio_error = None, None
        by_fa = {d["Fa"]: d for d in summary["response"]}
        if 0.0 in by_fa and 2.0 in by_fa:
            a2, a0 = by_fa[2.0], by_fa[0.0]
            ratio = a2["U0"] / a0["U0"]
            if a2["U0_error"] is not None and a0["U0_error"] is not None:
                ratio, ratio_error = quotient(a2["U0"], a2["U0_error"], a0["U0"], a0["U0_error"])
                if not math.isfinite(ratio_error):
                    warnings.append("the U0 ratio of Fa = 2 to Fa = 0 is not bounded: U0 at "
                                    "Fa = 0 may be zero within its estimate; tighten rtol")
                    ratio_error = None
        summary["U0_ratio_Fa2_Fa0"] = ratio
        summary["U0_ratio_Fa2_Fa0_error"] = ratio_error
        if design is not None:
            summary["design_point"] = design
            if not graphs["tau_min"] <= design["tau"] <= graphs["tau_max"]:
                warnings.append(f"the design point's tau = {design['tau']:.4g} lies outside the "
                                f"graphs' tau range [{graphs['tau_min']:g}, "
                                f"{graphs['tau_max']:g}]: widen [study.graphs]")
        summary["warnings"] = warnings
        summary["elapsed_seconds"] = time.perf_counter() - t_start
        write_text(out_dir / "report.json", json.dumps(summary, indent=1, default=_json))
        write_text(out_dir / "report.md", self._markdown(summary))
        say(f"done in {summary['elapsed_seconds']:.1f} s")
        summary["files"] = [str(out_dir / f) for f in FILES]
        return summary

    def _markdown(self, summary) -> str:
        scene = self.scene
        resp = scene["study"]["response"]
        lines = [f"# {scene['title']}", "",
                 f"Model CAMSHAFT-1 (thesis (4.15)-(4.18)), {scene['law']} rise, integrated with "
                 f"{scene['run']['method']} at rtol {scene['run']['rtol']:g} "
                 "over T in [0, 3].  Every figure is given with its error estimate: the run "
                 "again one notch tighter (rtol/10, or half the step), plus what the scan "
                 "that found it leaves.", "",
                 f"## Response at tau = {resp['tau']:g} (cf. fig. 4.10)", "",
                 "| Fa | U0 | U0'' | X''min in rise | at T | steps | ms |",
                 "|---:|---:|---:|---:|---:|---:|---:|"]
        for d in summary["response"]:
            lines.append(f"| {d['Fa']:g} | {_pm(d['U0'], d['U0_error'])} | "
                         f"{_pm(d['U0dd'], d['U0dd_error'])} | "
                         f"{_pm(d['Xdd_min_rise'], d['Xdd_min_rise_error'])} | "
                         f"{_pm(d['T_at_Xdd_min'], d['T_at_Xdd_min_error'])} | {d['n_steps']} | "
                         f"{1e3 * d['seconds']:.2f} |")
        if "design_point" in summary:
            lines += _design_lines(summary["design_point"])
        if summary["U0_ratio_Fa2_Fa0"] is not None:
            lines += ["", f"U0 at Fa = 2 over U0 at Fa = 0: **"
                      f"{_pm(summary['U0_ratio_Fa2_Fa0'], summary['U0_ratio_Fa2_Fa0_error'], 3)}"
                      "** (thesis sec. 4.7 (1): about 17.5 at tau = 0.15)."]
        lines += ["", "## Warnings", ""]
        lines += [f"- {w}" for w in summary["warnings"]] or ["None."]
        lines += ["", "## Charts", "", "![response](response.png)", "", "![graphs](graphs.png)",
                  "", f"Elapsed: {summary['elapsed_seconds']:.1f} s.", ""]
        return "\n".join(lines)


def _fa_label(Fa: float, scene: dict) -> str:
    """A curve's legend: its Fa, and whether it is a follower's design point's."""
    mine = "design" in scene and Fa == scene["design"]["Fa"]
    return f"Fa = {Fa:g}" + (" (follower)" if mine else "")


def _design_row(scene: dict, response: list) -> dict | None:
    """A follower's design point (scene_files.study_follower) with the figures of its
    response run and, as sec. 3.3 scales them, the residual vibration at the output:
    u0 = U0 h_m', u0'' = U0'' h_m'/t_m^2."""
    design = scene.get("design")
    if design is None:
        return None
    (row,) = [r for r in response if r["Fa"] == design["Fa"]]
    h, t_m = design["figures"]["stroke"]["value"], design["figures"]["t_m"]["value"]
    out = {**design, **{k: row[k] for k in RESIDUAL_FIGURES},
           **{f"{k}_error": row[f"{k}_error"] for k in RESIDUAL_FIGURES}}
    for name, key, scale in (("u0", "U0", h), ("u0dd", "U0dd", h / t_m**2)):
        out[name] = row[key] * scale
        error = row[f"{key}_error"]
        out[f"{name}_error"] = None if error is None else error * scale
    return out


def _mark(ax, design: dict, colour: str) -> None:
    """The design point on the four graphs of fig. 4.11, at its response run's figures."""
    label = f"design point: tau = {design['tau']:.3g}, Fa = {design['Fa']:.3g}"
    for a_, value in ((ax[0, 0], design["U0"]), (ax[0, 1], -design["Xdd_min_rise"]),
                      (ax[1, 0], design["T_at_Xdd_min"]), (ax[1, 1], design["U0dd"])):
        a_.axvline(design["tau"], color=colour, lw=0.6, ls=":")
        a_.plot([design["tau"]], [value], marker="*", ms=11, color=colour, mec="k", mew=0.6,
                ls="none", label=label, zorder=5)


def _design_lines(d: dict) -> list[str]:
    """report.md's section on a follower's design point: its inputs, the figures each with
    the formula it came from, and the residual vibration there."""
    f = d["follower"]
    lines = ["", f"## Design point of the follower ({f['kind']})", "",
             "Given: " + ", ".join(f"{k} = {v:g}" for k, v in f.items() if k != "kind") + ".",
             "", "| figure | value | unit | from |", "|---|---:|---|---|"]
    lines += [f"| {k} | {v['value']:.6g} | {v['unit']} | {v['formula']} |"
              for k, v in d["figures"].items()]
    lines += ["", f"At tau = {d['tau']:.4g}, Fa = {d['Fa']:.4g}: "
              f"U0 = {_pm(d['U0'], d['U0_error'])}, "
              f"U0'' = {_pm(d['U0dd'], d['U0dd_error'])}; at the output u0 = U0 h_m' = "
              f"{_pm(d['u0'], d['u0_error'])} m, u0'' = U0'' h_m'/t_m^2 = "
              f"{_pm(d['u0dd'], d['u0dd_error'])} m/s^2 (sec. 3.3)."]
    return lines


def _float(v):
    v = float(v)
    return None if math.isnan(v) else v


def _cell(v) -> str:
    return "" if v is None else f"{v:.3g}"


def _pm(v, e, digits: int = 4) -> str:
    return f"{v:.{digits}g}" + (" (no error estimate)" if e is None else f" ± {e:.2g}")


def _json(v):
    if isinstance(v, (np.floating, np.integer)):
        return v.item()
    raise TypeError(f"not JSON: {v!r}")
