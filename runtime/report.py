"""The main job: the CAMSHAFT-1 study of thesis ch. 4 on a scene, as report and charts.

Writes into the output folder
    report.md      what was run and the key figures next to the thesis's
    report.json    the same figures for machines
    response.png   X'' against T at one tau for several Fa (fig. 4.10)
    graphs.png     U0, max deceleration and its instant, U0dd against tau (fig. 4.11), U0 and
                   U0dd with their envelopes through the maxima (secs 3.5, 8.2.6)
    envelopes.csv  U0 and U0dd and their envelopes per Fa and tau
"""
from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path

import numpy as np

from . import closed_forms
from .envelope import envelope, tau_grid
from .errors import CamdynInputError
from .residual import residual
from .simulate import simulate
from .sweep import RESIDUAL_FIGURES, Target, sweep

def load_scene(path: str | None) -> dict:
    """The study scene at ``path`` (a file or a built-in name) or the embedded default, checked
    (:func:`camdyn.runtime.scene.check_study`)."""
    from . import scene as scenes

    data, where = scenes.read("default" if path is None else path)
    scenes.expect_kind(data, where, scenes.STUDY)
    return scenes.check_study(data, where)


def _run(tau, Fa, scene):
    integ = scene["run"]
    return simulate("camshaft1", {"tau": tau, "Fa": Fa}, 3.0, integ["method"],
                    rtol=integ["rtol"], law=scene["law"])


def main_job(scene: dict, out: Path, progress: bool = True) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out.mkdir(parents=True, exist_ok=True)
    t_start = time.perf_counter()
    say = (lambda msg: print(msg, file=sys.stderr, flush=True)) if progress else (lambda msg: None)
    resp, graphs = scene["study"]["response"], scene["study"]["graphs"]

    # fig. 4.10: response curves
    say(f"response curves at tau = {resp['tau']} for Fa = {resp['Fa']}")
    fig, ax = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    T = np.linspace(0.0, 3.0, 3001)
    summary = {"scene": scene["title"], "law": scene["law"], "response": []}
    for Fa in resp["Fa"]:
        r = _run(resp["tau"], Fa, scene)
        s = r.sample(T)
        fig_r = residual(r)
        summary["response"].append({"Fa": Fa, **fig_r.as_dict(), **r.stats})
        ax[0].plot(T, s["Xdd"], label=f"Fa = {Fa:g}")
        ax[1].plot(T, s["U"], label=f"Fa = {Fa:g}")
    ax[0].plot(T, s["Hdd"], "k--", lw=0.8, label="nominal H''")
    ax[0].set_ylabel("X''  (h_m'/t_m^2)")
    ax[1].set_ylabel("U = X - H  (h_m')")
    ax[1].set_xlabel("T = t/t_m")
    ax[0].set_title(f"CAMSHAFT-1, {scene['law']} rise, tau = {resp['tau']:g} (cf. thesis fig. 4.10)")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "response.png", dpi=120)
    plt.close(fig)

    # fig. 4.11: graphs against tau
    # uniform in 1/tau, so that every tuning dip of (3.5) is resolved alike (runtime/envelope.py)
    taus = tau_grid(graphs["tau_min"], graphs["tau_max"], graphs["n_tau"])
    # one compiled sweep over (Fa, tau) on every core (runtime/sweep.py)
    say(f"  graphs: {len(taus) * len(graphs['Fa'])} runs")
    integ = scene["run"]
    swept = sweep(Target("model", "camshaft1", 3.0, integ["method"], integ["rtol"], scene["law"]),
                  {"Fa": graphs["Fa"], "tau": taus}, progress=progress)
    rows = {Fa: [{k: float(swept[k][j * len(taus) + i]) for k in RESIDUAL_FIGURES}
                 for i in range(len(taus))] for j, Fa in enumerate(graphs["Fa"])}
    fig, ax = plt.subplots(2, 2, figsize=(11, 8))
    envelopes = {}
    for k, (Fa, vals) in enumerate(rows.items()):
        colour = f"C{k}"
        U0 = [v["U0"] for v in vals]
        U0dd = [v["U0dd"] for v in vals]
        # the curves a designer reads (secs 3.5, 8.2.6): through the maxima, bold; the raw
        # graph thin beneath them
        envelopes[Fa] = {"U0": envelope(taus, U0), "U0dd": envelope(taus, U0dd)}
        ax[0, 0].semilogy(taus, U0, color=colour, lw=0.6, alpha=0.6)
        ax[0, 0].semilogy(taus, envelopes[Fa]["U0"](taus), color=colour, lw=1.8,
                          label=f"Fa = {Fa:g}")
        ax[0, 1].plot(taus, [-v["Xdd_min_rise"] for v in vals], color=colour, label=f"Fa = {Fa:g}")
        ax[1, 0].plot(taus, [v["T_at_Xdd_min"] for v in vals], color=colour, label=f"Fa = {Fa:g}")
        ax[1, 1].plot(taus, U0dd, color=colour, lw=0.6, alpha=0.6)
        ax[1, 1].plot(taus, envelopes[Fa]["U0dd"](taus), color=colour, lw=1.8,
                      label=f"Fa = {Fa:g}")
    if scene["law"] == "cycloidal":
        fine = np.linspace(graphs["tau_min"], min(graphs["tau_max"], 0.99), 600)
        ax[0, 0].semilogy(fine, closed_forms.U0(fine), "k:", lw=0.8, label="(3.5)")
    ax[0, 0].set_ylabel("U0 (bold: envelope through the maxima)")
    ax[0, 1].set_ylabel("-X''min during rise")
    ax[1, 0].set_ylabel("T at X''min")
    ax[1, 1].set_ylabel("U0'' (bold: envelope through the maxima)")
    for a in ax.ravel():
        a.set_xlabel("tau")
        a.grid(alpha=0.3, which="both")
    ax[0, 0].legend(fontsize=7)
    fig.suptitle(f"CAMSHAFT-1 response graphs, {scene['law']} rise (cf. thesis fig. 4.11a-c)")
    fig.tight_layout()
    fig.savefig(out / "graphs.png", dpi=120)
    plt.close(fig)

    summary["graphs"] = {"tau": taus.tolist(), "rows": {str(Fa): v for Fa, v in rows.items()}}
    # the envelopes as data: their maxima per Fa, and the curves on the graph's tau grid
    summary["envelopes"] = {str(Fa): {k: {"tau_at_maxima": e.tau.tolist(),
                                          "maxima": e.value.tolist()} for k, e in env.items()}
                            for Fa, env in envelopes.items()}
    with open(out / "envelopes.csv", "w") as fh:
        fh.write("Fa,tau,U0,U0_envelope,U0dd,U0dd_envelope\n")
        for Fa, vals in rows.items():
            e = envelopes[Fa]
            for tau, v in zip(taus, vals):
                fh.write(f"{Fa:g},{tau:.10g},{v['U0']:.10g},{e['U0'](tau):.10g},"
                         f"{v['U0dd']:.10g},{e['U0dd'](tau):.10g}\n")
    ratio = None
    by_fa = {d["Fa"]: d for d in summary["response"]}
    if 0.0 in by_fa and 2.0 in by_fa:
        ratio = by_fa[2.0]["U0"] / by_fa[0.0]["U0"]
    summary["U0_ratio_Fa2_Fa0"] = ratio
    summary["elapsed_seconds"] = time.perf_counter() - t_start
    (out / "report.json").write_text(json.dumps(summary, indent=1))
    (out / "report.md").write_text(_markdown(scene, summary))
    say(f"done in {summary['elapsed_seconds']:.1f} s")
    return out / "report.md"


def _markdown(scene, summary) -> str:
    resp = scene["study"]["response"]
    lines = [f"# {scene['title']}", "",
             f"Model CAMSHAFT-1 (thesis (4.15)-(4.18)), {scene['law']} rise, integrated with "
             f"{scene['run']['method']} at rtol {scene['run']['rtol']:g} "
             "over T in [0, 3].", "",
             f"## Response at tau = {resp['tau']:g} (cf. fig. 4.10)", "",
             "| Fa | U0 | U0'' | X''min in rise | at T | steps | ms |",
             "|---:|---:|---:|---:|---:|---:|---:|"]
    for d in summary["response"]:
        lines.append(f"| {d['Fa']:g} | {d['U0']:.4g} | {d['U0dd']:.4g} | {d['Xdd_min_rise']:.4g} | "
                     f"{d['T_at_Xdd_min']:.3f} | {d['n_steps']} | {1e3 * d['seconds']:.2f} |")
    if summary["U0_ratio_Fa2_Fa0"] is not None:
        lines += ["", f"U0 at Fa = 2 over U0 at Fa = 0: **{summary['U0_ratio_Fa2_Fa0']:.1f}** "
                  "(thesis sec. 4.7 (1): about 17.5 at tau = 0.15)."]
    lines += ["", "## Charts", "", "![response](response.png)", "", "![graphs](graphs.png)", "",
              f"Elapsed: {summary['elapsed_seconds']:.1f} s.", ""]
    return "\n".join(lines)
