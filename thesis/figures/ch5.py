"""Chapter 5, CAMSHAFT-2 (the cam's inertia as a second degree of freedom): figs 5.6, 5.7."""
from __future__ import annotations

from functools import lru_cache

import numpy as np

from ..checks.check import Check
from .figure import Claim, Figure
from .plotting import dwell_shade, plt, save

CURVES_5_6 = ((0.15, 10.0, "(1) Fa = 0.15, Fv = 10: rigid shaft, light cam"),
              (1.5, 10.0, "(2) Fa = 1.5, Fv = 10: flexible shaft, light cam"),
              (1.5, 0.1, "(3) Fa = 1.5, Fv = 0.1: flexible shaft, heavy cam"))
"""The three curves of fig. 5.6 at tau = 0.16 (legend of fig. 5.6, sec. 5.5.5)."""

FV_5_7 = (0.1, 1.0, 10.0)
"""Fv of the drawn curves of fig. 5.7 (the printed ones are not legible); the limits Fv -> 0
((3.5), one DOF) and Fv -> infinity (CAMSHAFT-1) are drawn too (sec. 5.7 (2))."""


def _fig5_6(out_dir, quick):
    from camdyn.runtime.core.simulator import simulate

    T = np.linspace(0.0, 2.0, 1201 if quick else 4001)
    rows = (("X", "X"), ("Xdd", "X''"), ("Bdd", "B''"), ("windup", "dB (wind-up)"),
            ("Bdot_dev", "dB' (speed variation)"))
    p = plt()
    fig, ax = p.subplots(len(rows), 1, figsize=(7.5, 10), sharex=True)
    for Fa, Fv, label in CURVES_5_6:
        s = simulate("camshaft2", {"tau": 0.16, "Fa": Fa, "Fv": Fv}, 2.0, "dp54",
                     rtol=1e-10).sample(T)
        for a, (key, _) in zip(ax, rows):
            a.plot(T, s[key], lw=0.8, label=label)
    for a, (_, ylabel) in zip(ax, rows):
        a.set_ylabel(ylabel)
        dwell_shade(a)
    ax[0].legend(fontsize=7, loc="lower right")
    ax[-1].set_xlabel("T = t/t_m")
    ax[0].set_title("CAMSHAFT-2, cycloidal rise, tau = 0.16", fontsize=9)
    return [save(fig, out_dir, "fig5_6")]


@lru_cache(maxsize=None)
def _sweep(Fa: float, quick: bool) -> tuple:
    """(taus, {Fv: U0 list}, U0 of CAMSHAFT-1) on the graph grid of fig. 4.11."""
    from camdyn.runtime.measure.envelope import tau_grid
    from camdyn.runtime.measure.residual import residual
    from camdyn.runtime.core.simulator import simulate

    taus = tau_grid(0.06, 0.7, 48 if quick else 240)
    curves = {Fv: [residual(simulate("camshaft2", {"tau": float(t), "Fa": Fa, "Fv": Fv}, 3.0,
                                     "dp54", rtol=1e-9)).U0 for t in taus] for Fv in FV_5_7}
    one = [residual(simulate("camshaft1", {"tau": float(t), "Fa": Fa}, 3.0, "dp54",
                             rtol=1e-9)).U0 for t in taus]
    return taus, curves, one


def _fig5_7(Fa: float, name: str):
    def build(out_dir, quick):
        from camdyn.runtime.measure import references as closed_forms
        from camdyn.runtime.measure.envelope import envelope

        taus, curves, one = _sweep(Fa, quick)
        p = plt()
        fig, ax = p.subplots(figsize=(7.5, 5))
        for k, (Fv, U0) in enumerate(curves.items()):
            ax.semilogy(taus, U0, color=f"C{k}", lw=0.5, alpha=0.6)
            ax.semilogy(taus, envelope(taus, U0)(taus), color=f"C{k}", lw=1.8, label=f"Fv = {Fv:g}")
        ax.semilogy(taus, envelope(taus, one)(taus), "k-", lw=1.0,
                    label="Fv -> inf (CAMSHAFT-1)")
        fine = np.linspace(taus.min(), taus.max(), 600)
        ax.semilogy(fine, closed_forms.U0(fine), "k:", lw=0.8, label="Fv -> 0 (3.5)")
        ax.set_xlabel("tau")
        ax.set_ylabel("U0 (bold: envelope through the maxima)")
        ax.set_title(f"CAMSHAFT-2 response graph, Fa = {Fa:g}", fontsize=9)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
        return [save(fig, out_dir, name)]
    return build


def _fig5_8(out_dir, quick):
    """Frozen natural frequencies of CAMSHAFT-2 along the rise (the generated M, K at each cam
    position, thesis/checks/camshaft2_checks.py) for w_ex > w_eb and w_ex < w_eb."""
    from ..checks.camshaft2_checks import frozen_eigenvalues

    B = np.linspace(0.0, 1.0, 51 if quick else 201)
    p = plt()
    fig, ax = p.subplots(1, 2, figsize=(10, 4), sharey=True)
    for a, (Fa, Fv, title) in zip(ax, ((1.5, 0.1, "(a) w_ex > w_eb: Fa = 1.5, Fv = 0.1"),
                                       (1.5, 10.0, "(b) w_ex < w_eb: Fa = 1.5, Fv = 10"))):
        w = np.sqrt(np.array([frozen_eigenvalues(float(b), Fa, Fv) for b in B]))
        a.semilogy(B, w[:, 0], lw=1.2, label="lowest w_el/w_ex")
        a.semilogy(B, w[:, 1], lw=1.2, label="highest w_eh/w_ex")
        a.set_title(title, fontsize=9)
        a.set_xlabel("cam position B")
        a.grid(alpha=0.3, which="both")
    ax[0].set_ylabel("natural frequency / w_ex")
    ax[0].legend(fontsize=8)
    return [save(fig, out_dir, "fig5_8")]


def _U0_heavy_cam_limit() -> float:
    """U0 of CAMSHAFT-2 at Fv = 1e-6 (the limit Fv -> 0), Fa = 0.3, tau = 2/5."""
    from camdyn.runtime.measure.residual import residual
    from camdyn.runtime.core.simulator import simulate

    return residual(simulate("camshaft2", {"tau": 0.4, "Fa": 0.3, "Fv": 1e-6}, 3.0, "dp54",
                             rtol=1e-10)).U0


LIMIT_FV0_FA03 = Check("fig5_7b.limit_Fv0", "U0 at Fv = 1e-6, Fa = 0.3, tau = 2/5 (the one-DOF "
                       "value whatever Fa)", "sec. 5.7 (2), Table 3-I", "2.43e-2",
                       _U0_heavy_cam_limit)


def figures() -> list[Figure]:
    return [
        Figure("5.6", "thesis", "CAMSHAFT-2 at tau = 0.16: output position and acceleration, cam "
               "angular acceleration, shaft wind-up and speed variation for a rigid or flexible "
               "shaft and a light or heavy cam", _fig5_6,
               claims=(Claim("ch5.sec5_5_5.speed"), Claim("ch5.sec5_5_5.speed_heavy"),
                       Claim("ch5.sec5_5_5.windup_time"))),
        Figure("5.8", "thesis", "Shift of the two natural frequencies of CAMSHAFT-2 along the "
               "rise, the coupling largest at B = 1/2, for w_ex > w_eb and w_ex < w_eb", _fig5_8,
               claims=(Claim("ch5.max_slope.exact"), Claim("ch5.zero_slope.exact"),
                       Claim("ch5.max_slope.eq5_53"), Claim("ch5.eq5_43.generated")),
               note="The thesis sketches the shift; drawn here are the eigenvalues of the "
                    "generated model frozen at each cam position (as the checks of (5.43) use)."),
        Figure("5.7a", "thesis", "CAMSHAFT-2 response graph: U0 against tau for several Fv "
               "at Fa = 1", _fig5_7(1.0, "fig5_7a"),
               claims=(Claim("ch5.limit_Fv0.U0.0.105"), Claim("ch5.limit_Fvinf.median")),
               note="The Fv of the printed curves are not legible: Fv = 0.1, 1, 10 drawn, with "
                    "both limits of sec. 5.7 (2)."),
        Figure("5.7b", "thesis", "CAMSHAFT-2 response graph: U0 against tau for several Fv "
               "at Fa = 0.3", _fig5_7(0.3, "fig5_7b"),
               claims=(Claim(LIMIT_FV0_FA03),),
               note="As 5.7a; the limit Fv -> 0 is the one-DOF (3.5) whatever Fa."),
    ]
