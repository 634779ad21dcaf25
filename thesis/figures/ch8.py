"""Chapter 8 and App. 5: the model ladder of fig. 8.3, the motor slip of fig. 8.6 and the
motor responses of fig. A.5.7."""
from __future__ import annotations

import numpy as np

from . import Claim, Figure
from ._plot import dwell_shade, plt, save


def _fig8_3(case: str):
    """Curves (4)-(6) of fig. 8.3a/b: the 4-DOF DYNACAM run without damping and follower spring
    (scene fig8_1a/b.toml) against CAMSHAFT-2 and CAMSHAFT-1 with its tau, Fa, Fv."""
    def build(out_dir, quick):
        from camdyn.runtime import dynacam
        from camdyn.runtime.simulate import simulate

        from ..checks.dynacam import _run   # the checks' cached run: one simulation for both

        sc, summary, res = _run(f"fig8_1{case}")
        tau, Fa, Fv = summary["tau"], summary["Fa"], summary["Fv"]
        T4 = dynacam.nominal_T(sc, res)
        T = np.linspace(0.0, sc.T_end, 1501 if quick else 3001)
        two = simulate("camshaft2", {"tau": tau, "Fa": Fa, "Fv": Fv}, sc.T_end, "dp54",
                       rtol=1e-10).sample(T)
        one = simulate("camshaft1", {"tau": tau, "Fa": Fa}, sc.T_end, "dp54",
                       rtol=1e-10).sample(T)
        p = plt()
        fig, ax = p.subplots(2, 1, figsize=(7.5, 6.5), sharex=True)
        ax[0].plot(T4, res["Xdd"], lw=0.9, label="(4) 4 DOF (DYNACAM)")
        ax[0].plot(T, two["Xdd"], lw=0.9, ls="--", label="(5) 2 DOF (CAMSHAFT-2)")
        ax[0].plot(T, one["Xdd"], lw=0.9, ls=":", label="(6) 1 DOF (CAMSHAFT-1)")
        ax[1].plot(T4, res["Bdd"], lw=0.9, label="(4) 4 DOF")
        ax[1].plot(T, two["Bdd"], lw=0.9, ls="--", label="(5) 2 DOF")
        ax[0].set_ylabel("X''")
        ax[1].set_ylabel("B''")
        ax[1].set_xlabel("T = t/t_m")
        for a in ax:
            dwell_shade(a)
            a.legend(fontsize=7, loc="lower right")
        ax[0].set_title(f"spring-loaded follower, fig. 8.1{case}: tau = {tau:.3g}, Fa = {Fa:.3g}, "
                        f"Fv = {Fv:.3g}; no damping, no follower spring", fontsize=9)
        return [save(fig, out_dir, f"fig8_3{case}")]
    return build


def _fig8_6(out_dir, quick):
    from .. import motor_theory as mt

    taus = np.logspace(-1.3, 1.3, 30 if quick else 90)
    first = [mt.relative_slip_peak(t)[0] for t in taus]
    tau_el = mt.THESIS["tau_el"]
    second = [mt.relative_slip_peak(t, tau_el)[0] for t in taus]
    p = plt()
    fig, ax = p.subplots(figsize=(7, 4.5))
    ax.loglog(taus, first, lw=1.5, label="first-order motor (A.5.33)")
    ax.loglog(taus, second, "--", lw=1.0, label=f"second order (A.5.25), tau_el = {tau_el:g}")
    ax.loglog(taus, 4 / (3 ** 1.5 * np.pi * taus), "k:", lw=0.8, label="inertia limit 4/(3^1.5 pi tau_m)")
    tm = mt.THESIS["tau_m"]
    ax.axvline(tm, color="0.5", lw=0.7)
    ax.text(tm * 1.05, 0.05, f"test motor, tau_m = {tm:g}", fontsize=7, rotation=90)
    ax.set_xlabel("tau_m = T_m/t_m")
    ax.set_ylabel("peak slip / rated slip  (P = 1)")
    ax.set_title("asynchronous motor driving a cycloidal cam: relative slip", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    return [save(fig, out_dir, "fig8_6")]


def _figA5_7(out_dir, quick):
    from .. import motor_theory as mt

    d = mt.THESIS
    T = np.linspace(0.0, 3.0, 601 if quick else 1501)
    six = mt.slip(T, d["tau_m"], delta_n=d["delta_n"], P=d["P"], tau_el=d["tau_el"])
    first = mt.slip(T, d["tau_m"], delta_n=d["delta_n"], P=d["P"])
    one = six * d["analytic_factor"] * d["spring_factor"] / d["eta_g"]
    p = plt()
    fig, ax = p.subplots(figsize=(7.5, 4.5))
    ax.plot(T, 100 * six, lw=1.2, label="(6) analytic, second order (A.5.25)")
    ax.plot(T, 100 * first, ":", lw=1.0, label="first order (A.5.33)")
    ax.plot(T, 100 * one, "--", lw=1.0,
            label="(1) rebuilt: (6) x 1.3 (flexibility) x 4.5 (spring) / 0.87 (gear)")
    ax.axhline(100 * d["slip_simulated"], color="C3", lw=0.6, label="printed peak of (1), 1.8 %")
    ax.axhline(100 * d["slip_measured"], color="C4", lw=0.6, label="measured peak, 1.6 % (fig. A.5.6)")
    ax.set_xlabel("T = t/t_m")
    ax.set_ylabel("slip delta [%]")
    ax.set_title(f"test motor: tau_m = {d['tau_m']:g}, tau_el = {d['tau_el']:g}, P = {d['P']:g}, "
                 f"delta_n = {d['delta_n']:g}", fontsize=9)
    dwell_shade(ax)
    ax.legend(fontsize=7)
    return [save(fig, out_dir, "figA5_7")]


def figures() -> list[Figure]:
    not_drawn = ("Curves (1) measured, (2), (3) with damping and follower spring are not drawn: "
                 "(1) is a measurement, and the damping of (2), (3) is not printed for this "
                 "build.")
    return [
        Figure("8.3a", "thesis", "Spring-loaded follower with c_z' << c_x: output and cam "
               "acceleration of the 4-, 2- and 1-DOF models (no damping, no follower spring)",
               _fig8_3("a"), claims=(Claim("sec8_2_4.factor_a"), Claim("sec8_2_5.one_vs_two_a")),
               note="scene fig8_1a.toml. " + not_drawn),
        Figure("8.3b", "thesis", "Spring-loaded follower with c_z' >> c_x: output and cam "
               "acceleration of the 4-, 2- and 1-DOF models (no damping, no follower spring)",
               _fig8_3("b"), claims=(Claim("sec8_2_4.factor_b"), Claim("sec8_2_5.one_vs_two_b")),
               note="scene fig8_1b.toml. " + not_drawn),
        Figure("8.6", "thesis", "Peak slip of an asynchronous motor driving a cycloidal cam, "
               "relative to its rated slip, against tau_m = T_m/t_m", _fig8_6,
               claims=(Claim("app5.eq_8_1.curve1"), Claim("app5.sec_A5_4_3_1.inertia")),
               note="Only the caption survives in the scan; the curve is the reading of "
                    "thesis/motor_theory.py (peak of (A.5.33) at P = 1)."),
        Figure("A.5.7", "thesis", "Slip of the test motor over a cam rise: analytic curve (6) and "
               "curve (1) rebuilt from it with the printed factors", _figA5_7,
               claims=(Claim("app5.chain.curve1"), Claim("app5.generated.motor2"),
                       Claim("app5.tau_m"), Claim("app5.tau_el")),
               note="Curves (2)-(5) are DYNACAM runs with the motor whose parameters are not all "
                    "printed; curve (1) is rebuilt by the factors of sec. A.5.4.3.2-A.5.4.3.5."),
    ]
