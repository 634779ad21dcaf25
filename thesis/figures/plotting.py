"""Matplotlib (Agg) for the figure builders: one look for every picture, one place to save."""
from __future__ import annotations

from pathlib import Path

from camdyn.runtime.core.outdir import writing


def plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as pyplot

    return pyplot


def save(fig, out_dir, name: str) -> str:
    """Write ``fig`` as out_dir/name.png (110 dpi) and close it; returns the path."""
    fig.tight_layout()
    with writing(Path(out_dir) / f"{name}.png") as path:
        fig.savefig(path, dpi=110)
    plt().close(fig)
    return str(path)


def copy(src, dst) -> str:
    """A picture another command drew (the study's charts) copied to ``dst``; its path."""
    import shutil

    with writing(dst) as path:
        shutil.copyfile(src, path)
    return str(path)


def dwell_shade(ax) -> None:
    """The rise 0 <= T <= 1 shaded, as the thesis marks the cam rise time."""
    ax.axvspan(0.0, 1.0, color="0.93", zorder=0)
    ax.grid(alpha=0.3)


def dynacam_diagrams(sc, summary, res, folder, keys) -> list:
    """DYNACAM's diagrams ``keys`` (of runtime.dynacam.DIAGRAMS) of a run, drawn by
    runtime.dynacam.plot into ``folder``, in the order of ``keys``."""
    from camdyn.runtime.targets import dynacam_diagrams as dynacam

    written = dynacam.plot(sc, res, summary, Path(folder), keys)
    stem = Path(sc.path).stem        # dynacam.plot names them <scene>_<key>.png
    return [p for k in keys for p in written if Path(p).stem == f"{stem}_{k}"]
