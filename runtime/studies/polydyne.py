"""The compensated cam against the cam it compensates: the residual vibration of the one-DOF
follower (thesis (3.1)) after a polydyne rise designed for one tau, over a range of tau
(speed), beside the degree-9 rise 5-6-7-8-9 used as the cam law itself.

At the design tau the polydyne's output follows the degree-9 rise exactly and its residual
vanishes; away from it the compensation is partial.  Both curves come from compiled sweeps
(runtime/studies/sweep.py) with their error estimates.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..core.errors import CamdynInputError
from ..measure.contract import chart_note

UNCOMPENSATED = "5-6-7-8-9"
"""The law whose motion the polydyne makes the output follow."""


@dataclass
class Compensation:
    design_tau: float
    q: float
    tau: np.ndarray
    columns: dict = field(default_factory=dict)   # "<law>:<figure>" -> values
    warnings: list = field(default_factory=list)

    def as_dict(self) -> dict:
        """JSON's view: an estimate a point has none of is null (JSON has no NaN)."""
        def cells(values):
            return [float(v) if np.isfinite(v) else None for v in np.asarray(values, dtype=float)]
        return {"design_tau": self.design_tau, "q": self.q, "tau": self.tau.tolist(),
                **{k: cells(v) for k, v in self.columns.items()}, "warnings": self.warnings}


def compensation(design_tau: float, taus, q: float = 0.0, *, progress: bool = False,
                 estimate: bool = True) -> Compensation:
    """U0 and U0'' (with their errors) over ``taus`` for the polydyne designed for
    ``design_tau`` and for the uncompensated degree-9 rise."""
    from ..targets.model_target import ModelTarget
    from .sweep import sweep

    taus = np.asarray(taus, dtype=float)
    if taus.ndim != 1 or taus.size < 2:
        raise CamdynInputError("tau range: at least two values")
    out = Compensation(float(design_tau), float(q), taus)
    for key, law, theta in (("polydyne", "polydyne", design_tau), ("plain", UNCOMPENSATED, None)):
        target = ModelTarget.of("one_dof", {"q": q}, method="dop853", rtol=1e-10, law=law,
                                theta=theta)
        res = sweep(target, {"tau": taus}, progress=progress, estimate=estimate)
        # without the tighter sweep the table's estimates are NaN: no column, not a NaN one
        for fig in ("U0", "U0dd") + (("U0_error", "U0dd_error") if estimate else ()):
            if fig in res.columns:
                out.columns[f"{key}:{fig}"] = np.asarray(res[fig], dtype=float)
        out.warnings += [f"{law}, tau = {t:g}: {w}" for t, w in zip(taus, res["warnings"]) if w]
    return out


def chart(result: Compensation, path) -> None:
    """U0 against tau, compensated and not, the design tau marked, log scale."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 5))
    floor = 1e-16
    for key, label, style in (("plain", f"{UNCOMPENSATED} as the cam law", "k-"),
                              ("polydyne", f"polydyne, designed for tau = {result.design_tau:g}",
                               "b-")):
        u = np.maximum(result.columns[f"{key}:U0"], floor)
        ax.semilogy(result.tau, u, style, lw=1.2, label=label)
        err = result.columns.get(f"{key}:U0_error")
        if err is not None:
            ax.fill_between(result.tau, np.maximum(u - err, floor), u + err, color=style[0],
                            alpha=0.2, lw=0)
    ax.axvline(result.design_tau, color="r", ls="--", lw=0.8, label="design tau")
    ax.set_xlabel("tau = T_e/t_m (3.3): faster cam to the right")
    ax.set_ylabel("residual amplitude U0 (of the stroke)")
    ax.set_title(f"one-DOF follower, q = {result.q:g}: compensated cam against uncompensated")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    worst = {"U0 polydyne, largest estimate": (float(np.max(result.columns["polydyne:U0"])),
                                               float(np.max(result.columns.get(
                                                   "polydyne:U0_error", [0.0]))))}
    fig.text(0.01, 0.01, chart_note(worst, result.warnings) + " (bands: the error estimates)",
             fontsize=7)
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    fig.savefig(path, dpi=110)
    plt.close(fig)
