"""The thesis's diagrams of a DYNACAM run (figs 7.11, 7.12, 7.15, 7.16): X'', B'', the shaft's
torque, the backlash positions and the speed variations against the nominal time T."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..core.outdir import out_folder, writing
from ..measure.contract import chart_note
from .dynacam import nominal_T
from .scene_files import DynacamScene

DIAGRAMS = (
    ("Xdd", "X''", "acceleration of the output member, x'' t_m^2/h_m"),
    ("Bdd", "B''", "angular acceleration of the cam, beta'' t_m^2/beta_m"),
    ("torque", "M [N m]", "torque in the camshaft"),
    ("gaps", "gap", "backlash positions: gear (rad) and roller (m)"),
    ("speed_var", "dOmega_fic/w_s", "variation of the fictitious angular velocity"),
    ("motor_speed_var", "dw/w_s", "speed variation of the motor"),
)


NOTED = {"Xdd": ("Xdd_min_rise", "Xdd_max_rise", "U0dd", "U0"),
         "speed_var": ("speed_variation_max",), "motor_speed_var": ("motor_speed_variation_max",)}
"""The headline figures each diagram shows, noted with their estimates beneath it."""


def plot(scene: DynacamScene, res, summary: dict, out_dir, keys=None) -> list:
    """The thesis's diagrams (figs 7.11, 7.12, 7.15, 7.16) as PNG files in ``out_dir``, each
    with a footnote: the figures it shows with their estimates (``summary`` is the answer,
    ``<figure>_error`` beside each figure) and the run's warnings; only those of ``keys``
    (of DIAGRAMS) if given."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out_dir = out_folder(out_dir)
    T = nominal_T(scene, res)
    names = res.output_names
    written = []
    for key, ylabel, title in DIAGRAMS:
        if keys is not None and key not in keys:
            continue
        if key == "gaps":
            series = [(n, res[n]) for n in ("gear_gap", "roller_gap") if n in names]
        else:
            series = [(key, res[key])] if key in names else []
        if not series:
            continue
        fig, axes = plt.subplots(len(series), 1, figsize=(7, 2.6 * len(series)), sharex=True,
                                 squeeze=False)
        for ax, (n, v) in zip(axes[:, 0], series):
            ax.plot(T, v, lw=0.8)
            ax.axvspan(0, 1, color="0.93", zorder=0)
            if scene.turn is not None:      # the return, shaded as the rise
                turn = scene.cam_law()
                ax.axvspan(1 + turn.up, 1 + turn.up + turn.r, color="0.93", zorder=0)
            ax.set_ylabel(n if key == "gaps" else ylabel)
            ax.grid(alpha=0.3)
        if key == "Xdd":
            H = scene.cam_law().evaluate(np.maximum(T, 0.0) if scene.turn else np.clip(T, 0, 1))
            inside = (T > 0) if scene.turn else ((T > 0) & (T < 1))
            axes[0, 0].plot(T, np.where(inside, H[:, 2], 0.0), "k--", lw=0.7,
                            label="nominal H''")
            axes[0, 0].plot([summary["T_at_Xdd_min"]], [summary["Xdd_min_rise"]], "rv")
            axes[0, 0].legend(loc="upper right", fontsize=8)
        axes[-1, 0].set_xlabel("T = t/t_m")
        fig.suptitle(f"{scene.title}\n{title} (tau={summary['tau']:.3g}, Fa={summary['Fa']:.3g})",
                     fontsize=9)
        shown = {k: (summary[k], summary.get(f"{k}_error")) for k in NOTED.get(key, ())
                 if summary.get(k) is not None}
        fig.text(0.01, 0.01, chart_note(shown, summary.get("warnings", [])), fontsize=7)
        fig.tight_layout(rect=(0, 0.06 if len(series) == 1 else 0.035, 1, 1))
        path = out_dir / f"{Path(scene.path).stem}_{key}.png"
        with writing(path):
            fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(str(path))
    return written
