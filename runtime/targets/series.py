"""A run's states and outputs against time, as a CSV table and a chart (`camdyn integrate
--out`)."""
from __future__ import annotations

import numpy as np

from ..core.errors import out_folder


def write_series(res, out_dir) -> list:
    """states and outputs against time: <model>.csv and <model>.png in ``out_dir``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = out_folder(out_dir)
    m = res.model
    names = m.state_names + m.output_names
    units = {s["name"]: s.get("unit", "") for s in m.manifest["states"] + m.manifest["outputs"]}
    tname = m.manifest["time"]["name"]
    T = np.unique(np.concatenate([res.t, np.linspace(res.t[0], res.t[-1], 1001)]))
    smp = res.sample(T)
    csv = out / f"{m.name}.csv"
    np.savetxt(csv, np.column_stack([T] + [smp[n] for n in names]), delimiter=",",
               header=",".join([tname] + names), comments="")
    fig, axes = plt.subplots(len(names), 1, figsize=(7, 1.8 * len(names) + 0.6), sharex=True,
                             squeeze=False)
    for ax, n in zip(axes[:, 0], names):
        ax.plot(T, smp[n], lw=0.9)
        ax.set_ylabel(f"{n} [{units.get(n, '')}]", fontsize=8)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel(f"{tname} [{m.manifest['time']['unit']}]")
    axes[0, 0].set_title(m.manifest.get("title", m.name), fontsize=9)
    fig.tight_layout()
    png = out / f"{m.name}.png"
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return [str(csv), str(png)]
