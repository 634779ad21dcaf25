"""The cam laws themselves: figs A.2.2, A.2.3 (nominal characteristics of the cycloid and the
modified sine) and fig. 8.7 (the two accelerations side by side), from runtime/core/laws.py, the
library the simulations use."""
from __future__ import annotations

import numpy as np

from .figure import Claim, Figure
from .plotting import plt, save


def _characteristics(law: str, theta, name: str, title: str):
    def build(out_dir, quick):
        from camdyn.runtime.core.laws import choose

        T = np.linspace(0.0, 1.0, 1001)
        H = choose(law, theta).evaluate(T)
        rows = ((H[:, 0], "H"), (H[:, 1], "H'"), (H[:, 2], "H''"), (H[:, 3], "H'''"),
                (H[:, 1] * H[:, 2], "H' H'' (torque)"))
        p = plt()
        fig, ax = p.subplots(len(rows), 1, figsize=(6.5, 9), sharex=True)
        for a, (v, label) in zip(ax, rows):
            a.plot(T, v, lw=1.0)
            a.set_ylabel(label)
            a.grid(alpha=0.3)
        ax[-1].set_xlabel("T = t/t_m")
        ax[0].set_title(title, fontsize=9)
        return [save(fig, out_dir, name)]
    return build


def _fig8_7(out_dir, quick):
    from camdyn.runtime.core.laws import choose

    T = np.linspace(0.0, 1.0, 1001)
    p = plt()
    fig, ax = p.subplots(figsize=(7, 4))
    for law, theta, label in (("cycloidal", None, "cycloidal"),
                              ("modified-sine", 0.1, "modified sine, theta = 0.1")):
        H = choose(law, theta).evaluate(T)
        ax.plot(T, H[:, 2], lw=1.2, label=f"{label}: peak {H[:, 2].max():.3g}")
    ax.axvline(0.1, color="0.6", lw=0.6)
    ax.set_xlabel("T = t/t_m")
    ax.set_ylabel("H''")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return [save(fig, out_dir, "fig8_7")]


def figures() -> list[Figure]:
    return [
        Figure("8.7", "thesis", "Nominal accelerations of the cycloidal and the modified sine "
               "law (peak at theta = 0.1)", _fig8_7,
               claims=(Claim("app2.modsine.peak"), Claim("app2.cycloid.acceleration_peak"))),
        Figure("A.2.2", "thesis", "Nominal characteristics of the cycloidal law: displacement, "
               "velocity, acceleration, jerk and the torque factor H'H''",
               _characteristics("cycloidal", None, "figA2_2", "cycloidal law"),
               claims=(Claim("app2.cycloid.velocity_peak"), Claim("app2.cycloid.acceleration_peak"),
                       Claim("app2.cycloid.jerk_0"), Claim("app2.cycloid.jerk_half"),
                       Claim("app2.cycloid.torque"))),
        Figure("A.2.3", "thesis", "Nominal characteristics of the modified sine law, theta = 0.1",
               _characteristics("modified-sine", 0.1, "figA2_3", "modified sine law, theta = 0.1"),
               claims=(Claim("app2.modsine.peak"), Claim("app2.modsine.jerk_0"),
                       Claim("app2.modsine.jerk_half"), Claim("app2.modsine.quarter_is_cycloid"))),
    ]
