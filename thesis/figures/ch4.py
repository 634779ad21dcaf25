"""Chapter 4, CAMSHAFT-1: figs 4.10 and 4.11a-c, drawn from one run of the CAMSHAFT-1 study of
``camdyn run`` (runtime/targets/camshaft1_study.py), whose report.json holds every graph's data."""
from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path

import numpy as np

from .figure import Claim, Figure, Trend
from .plotting import copy, plt, save

QUICK_GRAPHS = {"n_tau": 48, "Fa": [0.0, 0.5, 2.0]}
"""--quick: a coarser tau grid (3 points per tuning dip) and three Fa of the six."""


@lru_cache(maxsize=None)
def study(out_dir: str, quick: bool) -> dict:
    """Run the default scene's study once into out_dir/camshaft1_study (report.md, graphs.png,
    response.png, envelopes.csv, report.json) and return report.json."""
    from camdyn.runtime.targets.camshaft1_study import StudyTarget, load_scene

    scene = load_scene(None)
    if quick:
        scene = {**scene, "study": {**scene["study"],
                                    "graphs": {**scene["study"]["graphs"], **QUICK_GRAPHS}}}
    where = Path(out_dir) / "camshaft1_study"
    StudyTarget.from_scene(scene).study(where)
    data = json.loads((where / "report.json").read_text())
    data["folder"] = str(where)
    return data


def _fig4_10(out_dir, quick):
    data = study(str(out_dir), quick)
    return [copy(Path(data["folder"]) / "response.png", Path(out_dir) / "fig4_10.png")]


def _graphs(data):
    taus = np.array(data["graphs"]["tau"])
    return taus, {float(Fa): rows for Fa, rows in data["graphs"]["rows"].items()}


def _graph_with_envelopes(out_dir, quick, figure: str, closed_form: str, log: bool):
    """fig. 4.11a (U0) or 4.11c (U0''): the raw graph per Fa, the envelope through its maxima
    in bold, and the closed form (3.5) or (3.6) of Fa = 0 dotted."""
    from camdyn.runtime.measure import references as closed_forms
    from camdyn.runtime.measure.envelope import envelope

    data = study(str(out_dir), quick)
    taus, rows = _graphs(data)
    p = plt()
    fig, ax = p.subplots(figsize=(7.5, 5))
    draw = ax.semilogy if log else ax.plot
    for k, (Fa, vals) in enumerate(rows.items()):
        values = [v[closed_form] for v in vals]
        draw(taus, values, color=f"C{k}", lw=0.5, alpha=0.6)
        draw(taus, envelope(taus, values)(taus), color=f"C{k}", lw=1.8, label=f"Fa = {Fa:g}")
    fine = np.linspace(taus.min(), min(taus.max(), 0.99), 600)
    eq = "(3.5)" if closed_form == "U0" else "(3.6)"
    draw(fine, getattr(closed_forms, closed_form)(fine), "k:", lw=0.8, label=f"{eq}, Fa = 0")
    ax.set_xlabel("tau")
    ax.set_ylabel(f"{closed_form.replace('dd', chr(39) * 2)} (bold: through the maxima)")
    ax.grid(alpha=0.3, which="both" if log else "major")
    ax.legend(fontsize=7)
    return [save(fig, out_dir, figure)]


def _fig4_11a(out_dir, quick):
    return _graph_with_envelopes(out_dir, quick, "fig4_11a", "U0", log=True)


def _fig4_11b(out_dir, quick):
    data = study(str(out_dir), quick)
    taus, rows = _graphs(data)
    p = plt()
    fig, ax = p.subplots(2, 1, figsize=(7.5, 6), sharex=True)
    for k, (Fa, vals) in enumerate(rows.items()):
        ax[0].plot(taus, [-v["Xdd_min_rise"] for v in vals], color=f"C{k}", label=f"Fa = {Fa:g}")
        ax[1].plot(taus, [v["T_at_Xdd_min"] for v in vals], color=f"C{k}", label=f"Fa = {Fa:g}")
    ax[0].axhline(2 * np.pi, color="k", ls="--", lw=0.7, label="nominal 2 pi")
    ax[0].set_ylabel("-X''min during the rise")
    ax[1].set_ylabel("T at X''min")
    ax[1].set_xlabel("tau")
    for a in ax:
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=7)
    return [save(fig, out_dir, "fig4_11b")]


def _fig4_11c(out_dir, quick):
    return _graph_with_envelopes(out_dir, quick, "fig4_11c", "U0dd", log=False)


def _decel_trend() -> Trend:
    """-X''min during the rise at tau = 0.15 for Fa = 0, 0.5, 1, 2: rising with Fa, above 2 pi."""
    from camdyn.runtime.measure.residual import residual
    from camdyn.runtime.core.simulator import simulate

    fas = (0.0, 0.5, 1.0, 2.0)
    d = [-residual(simulate("camshaft1", {"tau": 0.15, "Fa": Fa}, 3.0, "dp54",
                            rtol=1e-9)).Xdd_min_rise for Fa in fas]
    text = ", ".join("{:.3g}" for _ in d) + f" at Fa = {', '.join(f'{f:g}' for f in fas)}"
    return Trend(text, tuple(d), all(b > a for a, b in zip(d, d[1:])) and d[-1] > 2 * np.pi)


def _lag_trend() -> Trend:
    """X'' at T = 0.25 (nominal peak 2 pi) for Fa = 2, tau = 0.15: below the nominal."""
    from camdyn.runtime.core.simulator import simulate

    v = float(simulate("camshaft1", {"tau": 0.15, "Fa": 2.0}, 1.0, "dp54",
                       rtol=1e-9).sample([0.25])["Xdd"][0])
    return Trend(f"X''(0.25) = {{:.3g}} against 2 pi = {2 * np.pi:.3g}", (v,), v < 2 * np.pi)


def figures() -> list[Figure]:
    note = ("Drawn from the CAMSHAFT-1 study of `camdyn run` (runtime/targets/camshaft1_study.py), the same runs "
            "that give out/report.md.")
    return [
        Figure("4.10", "thesis", "CAMSHAFT-1 (variable fictitious angular velocity): output "
               "acceleration and positional error at tau = 0.15 for Fa = 0, 0.5, 2", _fig4_10,
               claims=(Claim("sec4_7.magnification.0.15"), Claim("eq4_19.dip.2"),
                       Claim(trend=_lag_trend, reference="sec. 4.5.1, fig. 4.10 curve (3)",
                             text="at Fa = 2 the acceleration does not reach its nominal peak "
                                  "2 pi at T = 0.25 (the cam lags)")), note=note),
        Figure("4.11a", "thesis", "CAMSHAFT-1 response graph: relative positional error U0 "
               "against tau for several Fa, with the envelopes through the maxima", _fig4_11a,
               claims=(Claim("sec4_7.magnification.0.2"), Claim("table3I.U0.0.105")), note=note),
        Figure("4.11b", "thesis", "CAMSHAFT-1 response graph: largest deceleration during the "
               "rise and the instant T where it occurs, against tau", _fig4_11b,
               claims=(Claim(trend=_decel_trend, reference="sec. 4.5.2, fig. 4.11b",
                             text="the deceleration during the rise exceeds its nominal value "
                                  "2 pi, the more the larger Fa (tau = 0.15)"),),
               note=note + " The text puts the largest deceleration 'at about T = 0.7'; these "
                           "runs give T = 0.71-0.98, later for larger Fa."),
        Figure("4.11c", "thesis", "CAMSHAFT-1 response graph: amplitude U0'' of the residual "
               "acceleration after the rise against tau", _fig4_11c,
               claims=(Claim("table3I.U0dd.0.105"), Claim("table3I.U0dd.0.4")), note=note),
    ]
