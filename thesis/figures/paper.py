"""The paper's figs 4-9 (Rayleigh-beam follower of a roller cam, RDFD motion): the tip
deflection v_E against the cam angle with one parameter varied (runtime/targets/beam.py, its FIGURES
table), each with the trend the paper states, computed from the same runs."""
from __future__ import annotations

import numpy as np

from camdyn.thesis.runcache import cached_runs

from .figure import Claim, Figure, Trend
from .plotting import plt, save

STATEMENTS = {
    "fig4_modes": ("Convergence of the tip response with the number of modes N = 2, 3, 4",
                   "the responses with N = 3 and N = 4 almost coincide (peaks within 1 %)"),
    "fig5_omega": ("Tip response for cam speeds Omega = 120, 240, 360 rad/s",
                   "the response grows with the cam speed"),
    "fig6_distance": ("Tip response for distances d = 102, 112, 122 mm from the cam centre",
                      "the response amplitude is larger for a larger distance d"),
    "fig7_rod_radius": ("Tip response for rod radii 7, 5, 3 mm",
                        "the response is larger for a thinner rod"),
    "fig8_base_radius": ("Tip response for base-circle radii 30, 26, 22 mm",
                         "the response is larger for a smaller base circle"),
    "fig9_rise": ("Tip response for total rises S_T = 8, 15, 22 mm",
                  "a larger total rise gives a larger response"),
}
"""name in beam.FIGURES -> (caption, the paper's statement, sec. 4 and 5 of the paper)."""


@cached_runs
def _sweep(name: str) -> tuple:
    """(values, peaks max |v_E| in m, sampled curves) of one figure's three runs."""
    from camdyn.runtime.targets import beam

    field, values, _ = beam.FIGURES[name]
    case = beam.Case()
    peaks, curves = [], []
    for v, s, res in beam.sweep(case, field, values):
        t = np.linspace(0.0, res.t[-1], 4000)
        omega = v if field == "omega" else case.omega
        curves.append((np.degrees(omega * t), res.sample(t)["vE"]))
        peaks.append(s["max_abs_tip_deflection"])
    return values, peaks, curves


def _builder(name: str):
    def build(out_dir, quick):
        from camdyn.runtime.targets import beam

        _, _, label = beam.FIGURES[name]
        values, peaks, curves = _sweep(name)
        p = plt()
        fig, ax = p.subplots(figsize=(8, 4))
        for v, pk, (deg, vE) in zip(values, peaks, curves):
            ax.plot(deg, vE * 1e3, lw=0.8, label=f"{label} = {v:g} (peak {pk * 1e3:.3g} mm)")
        ax.set_xlabel("cam angle [deg]")
        ax.set_ylabel("tip deflection v_E [mm]")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=8)
        return [save(fig, out_dir, f"paper_{name}")]
    return build


def _trend(name: str):
    def compute() -> Trend:
        _, peaks, _ = _sweep(name)
        mm = tuple(p * 1e3 for p in peaks)
        text = "peaks " + ", ".join("{:.4g}" for _ in mm) + " mm"
        if name == "fig4_modes":
            rel = abs(peaks[1] - peaks[2]) / peaks[2]
            return Trend(text + "; N = 3 against 4: {:.1e} relative", mm + (rel,), rel < 0.01)
        return Trend(text, mm, all(b > a for a, b in zip(peaks, peaks[1:])))
    return compute


def figures() -> list[Figure]:
    out = []
    for k, (name, (caption, statement)) in enumerate(STATEMENTS.items(), start=4):
        out.append(Figure(f"paper {k}", "paper", caption, _builder(name),
                          claims=(Claim(trend=_trend(name), text=statement,
                                        reference=f"paper sec. 4, fig. {k}"),),
                          note="paper case of sec. 4 (runtime/targets/beam.py Case()); base radii of "
                               "fig. 8 taken (not printed)" if k == 8 else
                               "paper case of sec. 4 (runtime/targets/beam.py Case())"))
    return out
