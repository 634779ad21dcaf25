"""A run's states and outputs against time, as a CSV table and a chart (`camdyn integrate
--out`), each value with its error estimate where the run has a twin one notch tighter: the
difference of the two dense outputs at the same times, times the method's factor (the answer
contract's discretisation estimate, runtime/measure/contract.py, at every time)."""
from __future__ import annotations

import numpy as np

from ..core.outdir import out_folder, writing
from ..measure.contract import chart_note


def write_series(answer, out_dir) -> list:
    """States and outputs of ``answer``'s run against time: <model>.csv (a column
    ``<name>_error`` beside each, empty without an estimate) and <model>.png (± the estimate
    shaded, the largest estimates and the warnings in a footnote) in ``out_dir``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    res, tight = answer.result, answer.tight_result
    out = out_folder(out_dir)
    m = res.model
    names = m.state_names + m.output_names
    units = {s["name"]: s.get("unit", "") for s in m.manifest["states"] + m.manifest["outputs"]}
    tname = m.manifest["time"]["name"]
    T = np.unique(np.concatenate([res.t, np.linspace(res.t[0], res.t[-1], 1001)]))
    smp = res.sample(T)
    twin = tight.sample(T) if tight is not None else None
    err = {n: (np.abs(smp[n] - twin[n]) * answer.factor if twin is not None
               else np.full(T.shape, np.nan)) for n in names}
    csv = out / f"{m.name}.csv"
    header = [tname] + [x for n in names for x in (n, f"{n}_error")]
    with writing(csv), open(csv, "w") as fh:
        fh.write(",".join(header) + "\n")
        for i in range(T.size):
            cells = [repr(float(T[i]))]
            for n in names:
                cells.append(repr(float(smp[n][i])))
                cells.append("" if np.isnan(err[n][i]) else f"{err[n][i]:.3g}")
            fh.write(",".join(cells) + "\n")
    fig, axes = plt.subplots(len(names), 1, figsize=(7, 1.8 * len(names) + 1.0), sharex=True,
                             squeeze=False)
    for ax, n in zip(axes[:, 0], names):
        line, = ax.plot(T, smp[n], lw=0.9)
        if twin is not None:
            ax.fill_between(T, smp[n] - err[n], smp[n] + err[n], color=line.get_color(),
                            alpha=0.25, lw=0)
        ax.set_ylabel(f"{n} [{units.get(n, '')}]", fontsize=8)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel(f"{tname} [{m.manifest['time']['unit']}]")
    axes[0, 0].set_title(m.manifest.get("title", m.name), fontsize=9)
    fig.text(0.01, 0.01, chart_note({n: (smp[n], err[n]) for n in names}, answer.warnings),
             fontsize=6.5, wrap=True)
    fig.tight_layout(rect=(0, 0.6 / (1.8 * len(names) + 1.0), 1, 1))
    png = out / f"{m.name}.png"
    with writing(png):
        fig.savefig(png, dpi=110)
    plt.close(fig)
    return [str(csv), str(png)]
