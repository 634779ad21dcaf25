"""Chapter 3, the one-DOF model at constant angular velocity: figs 3.3 and 3.4."""
from __future__ import annotations

import math

import numpy as np

from .figure import Claim, Figure
from .plotting import dwell_shade, plt, save

TAUS_3_3 = (2 / 9, 1 / 4, 2 / 5, 1.0)
"""The curves of fig. 3.3 (legend read as tau = 2/9, 1/4, 2/5, 1)."""


def _fig3_3(out_dir, quick):
    from camdyn.runtime.core.simulator import simulate

    T = np.linspace(0.0, 2.0, 1201 if quick else 4001)
    p = plt()
    fig, ax = p.subplots(2, 1, figsize=(7.5, 6.5), sharex=True)
    for tau in TAUS_3_3:
        s = simulate("camshaft1", {"tau": tau, "Fa": 0.0}, 2.0, "dp54", rtol=1e-10).sample(T)
        ax[0].plot(T, s["X"], lw=0.9, label=f"tau = {tau:.3g}")
        ax[1].plot(T, s["Xdd"], lw=0.9, label=f"tau = {tau:.3g}")
    ax[0].plot(T, s["H"], "k--", lw=0.7, label="nominal H")
    ax[1].plot(T, s["Hdd"], "k--", lw=0.7, label="nominal H''")
    ax[0].set_ylabel("X = x/h_m")
    ax[1].set_ylabel("X'' = x'' t_m^2/h_m")
    ax[1].set_xlabel("T = t/t_m")
    for a in ax:
        dwell_shade(a)
        a.legend(fontsize=7, loc="upper right")
    ax[0].set_title("one DOF, constant angular velocity (Fa = 0), cycloidal rise")
    return [save(fig, out_dir, "fig3_3")]


def _fig3_4(out_dir, quick):
    from camdyn.runtime.core.simulator import simulate

    tau, q, td = 0.15, 0.06, 1.5
    T = np.linspace(0.0, 1.0 + td, 2001 if quick else 6001)
    s = simulate("one_dof", {"tau": tau, "q": q}, 1.0 + td, "dp54", rtol=1e-11).sample(T)
    w = 2 * math.pi / tau
    dwell = T >= 1.0
    # the amplitude at the start of the dwell, from u and u' of the damped free vibration
    s0, wd = q * w, w * math.sqrt(1 - q * q)
    k = int(np.argmax(dwell))
    A0 = math.hypot(s["U"][k], (s["Xd"][k] + s0 * s["U"][k]) / wd)
    p = plt()
    fig, ax = p.subplots(figsize=(7.5, 3.8))
    ax.plot(T, s["U"] * 1e3, lw=0.8, label="U = X - H (x 1e3)")
    env = A0 * np.exp(-s0 * (T[dwell] - 1.0)) * 1e3
    ax.plot(T[dwell], env, "r--", lw=0.8, label="envelope exp(-q w_e (t - t_m)), (3.7)")
    ax.plot(T[dwell], -env, "r--", lw=0.8)
    ax.set_xlabel("T = t/t_m")
    ax.set_ylabel("U x 1e3")
    ax.set_title(f"damping during the dwell: tau = {tau:g}, t_d/t_m = {td:g}, q = {q:g}; "
                 f"U0n/U00 = {env[-1] / env[0]:.3f}", fontsize=9)
    dwell_shade(ax)
    ax.legend(fontsize=7)
    return [save(fig, out_dir, "fig3_4")]


def _fig3_5(out_dir, quick):
    """One DOF under the ramp h' = v_b t (the law 'uniform' during 0 <= T < 1), tau = 0.13."""
    from camdyn.runtime.core.simulator import simulate

    tau = 0.13
    T = np.linspace(0.0, 1.0, 1001 if quick else 3001)
    s = simulate("one_dof", {"tau": tau}, 1.0, "dp54", rtol=1e-11, law="uniform").sample(T)
    p = plt()
    fig, ax = p.subplots(2, 1, figsize=(7.5, 5.5), sharex=True)
    ax[0].plot(T, s["X"], lw=0.9, label="x/h_m")
    ax[0].plot(T, s["H"], "k--", lw=0.7, label="ramp h/h_m = T")
    ax[1].plot(T, s["U"], lw=0.9, label="U = X - H")
    amp = tau / (2 * math.pi)
    ax[1].axhline(-amp, color="r", lw=0.6, ls="--", label="amplitude r_e tau/(2 pi), (3.11)")
    ax[1].axhline(amp, color="r", lw=0.6, ls="--")
    ax[1].set_xlabel("T = t/t_m")
    ax[0].set_title(f"one DOF under a ramp input, tau = {tau:g} (r_e = 1)", fontsize=9)
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    return [save(fig, out_dir, "fig3_5")]


def figures() -> list[Figure]:
    return [
        Figure("3.3", "thesis", "One-DOF model at constant angular velocity: output position "
               "and acceleration over a cycloidal rise and dwell, tau = 2/9, 1/4, 2/5, 1",
               _fig3_3,
               claims=(Claim("table3I.U0.0.4"), Claim("table3I.U0dd.0.4"),
                       Claim("table3I.U0.0.222"), Claim("zero_points")),
               note="CAMSHAFT-1 with Fa = 0 is the model of ch. 3 (3.1); the residual amplitudes "
                    "of the curves are those of Table 3-I and (3.5), (3.6)."),
        Figure("3.4", "thesis", "Decay of the residual vibration during the dwell, one DOF "
               "with relative damping q = 0.06, tau = 0.15, dwell 1.5 t_m",
               _fig3_4,
               claims=(Claim("eq3_7.decay.formula"), Claim("eq3_7.decay.simulated")),
               note="generated model one_dof (3.1) with viscous damping; envelope by (3.7)."),
        Figure("3.5", "thesis", "Response of the one-DOF model to a ramp input (a follower "
               "that meets a uniformly moving cam): a free vibration about the ramp",
               _fig3_5, claims=(Claim("ch3_6.eq3_11.simulated"), Claim("ch3_6.eq3_12.simulated")),
               note="law 'uniform' (H = T) on the generated one_dof model, as the checks of "
                    "(3.11), (3.12) run it."),
    ]
