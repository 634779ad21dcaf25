"""Checks of topic 'examples': the worked examples of App. 7 (indexing mechanism and
spring-loaded cam follower) and the impact estimate of sec. 7.4.4.

Data: camdyn/thesis/theory/mechanisms.py (every number with unit and source, and the results as
printed); computations: camdyn/thesis/theory/examples.py.

Where the thesis evidently carried a rounded intermediate result into the next step, the
check does the same and says so in its note (e.g. the stiffness dip from the printed
Fa = 3.34); the full-precision chain is then checked separately or its distance from the
printed value is asserted in tests/test_examples.py.
"""
from __future__ import annotations

from camdyn.thesis.runcache import cached_runs

from .check import Check


def _m():
    from camdyn.thesis.theory import mechanisms

    return mechanisms


def _ex():
    from camdyn.thesis.theory import examples

    return examples


def _p(mech: str, name: str) -> str:
    return _m().MECHANISMS[mech].printed[name].text


def _pf(mech: str, name: str) -> float:
    return float(_p(mech, name))


def _idx():
    return _ex().indexing_figures()


def _fol(table: bool = False):
    m = _m().SPRING_LOADED
    return _ex().follower_figures(c_c=m.c_c_table.value if table else None)


@cached_runs
def camshaft1_Xdd(tau: float, Fa: float, T: float) -> float:
    """X''(T) of CAMSHAFT-1 (4.15) with the cycloid, from camdyn's dense output."""
    from camdyn.runtime.core.simulator import simulate

    res = simulate("camshaft1", {"tau": tau, "Fa": Fa}, 1.0, "dp54", rtol=1e-10)
    return float(res.sample([T])["Xdd"][0])


def _eq_5_14_identity() -> bool:
    """(5.52) with m_tan = J/R^2 and tan a_me = h_m/(R beta_m) (4.13) is (5.14b)."""
    import sympy as sp

    m, J, R, h, b = sp.symbols("m J R h_m beta_m", positive=True)
    ex = _ex()
    tan_me = ex.mean_slope(h, R, b)
    return sp.simplify(ex.flywheel_factor(m, J / R**2, tan_me) - ex.flywheel_factor_J(m, h, J, b)) == 0


def _eq_5_12b_identity() -> bool:
    """(4.14) with c_tan = c_beta' = k/R^2 (two-DOF model) is (5.12b) Fa = c_x h_m^2/(k beta_m^2)."""
    import sympy as sp

    c, k, R, h, b = sp.symbols("c_x k R h_m beta_m", positive=True)
    ex = _ex()
    return sp.simplify(ex.shaft_factor(c, k / R**2, ex.mean_slope(h, R, b))
                       - c * h**2 / (k * b**2)) == 0


def checks() -> list[Check]:
    I, F = "indexing", "spring-loaded"
    a72, a73 = "App. 7, A.7.2", "App. 7, A.7.3"
    ex = _ex
    out = [
        # -- indexing mechanism, App. 7 A.7.2 --------------------------------------------------
        Check("app7.indexing.c_c", "indexing: c_c from c1 = 14e6 N/m and App. 6's c_4z = 1.5E7 N/m "
              "(4.3), in N/m", f"{a72} (5)", _p(I, "c_c"), lambda: ex().indexing_c_c(),
              rule="rel:0.005", note="3.644e6: App. 6's two-digit 1.5E7 cannot give the third digit",
              exact=True),
        Check("app7.indexing.m2_red", "indexing: m2 = 15.2 kg reduced to R_red, m2/i^2 (kg)",
              "fig. A.7.2, A.7.3", _p(I, "m2_red"),
              lambda: ex().reduce_mass(_m().INDEXING.m2.value, _m().INDEXING.i.value), exact=True),
        Check("app7.indexing.m", "indexing: equivalent mass by (4.39) (kg)", "fig. 7.14, (4.39)",
              _p(I, "m"), lambda: _idx().m,
              note="cam mass m_z = 1.5 kg is an App. 6 reading; without it 44.7 kg, also 45",
              exact=True),
        Check("app7.indexing.T_e", "indexing: T_e = 2 pi (m/c_c)^(1/2) (s)", f"{a72} (7)",
              _p(I, "T_e"), lambda: _idx().T_e, exact=True),
        Check("app7.indexing.t_m", "indexing: t_m = beta_m/w_s at 60 r.p.m. (s)", f"{a72} (8)",
              _p(I, "t_m"), lambda: _idx().t_m, exact=True),
        Check("app7.indexing.tau", "indexing: tau = T_e/t_m", f"{a72} (9), (4.12)", _p(I, "tau"),
              lambda: _idx().tau, exact=True),
        Check("app7.indexing.tan_alpha_me", "indexing: tan alpha_me = h_m/(R_1/2 beta_m)",
              f"{a72} (11), (4.13)", _p(I, "tan_alpha_me"), lambda: _idx().tan_alpha_me,
              exact=True),
        Check("app7.indexing.Fa", "indexing: Fa = (c_c/c_tan) tan^2 alpha_me, 1/c_tan = 6.365e-6 m/N",
              f"{a72} (12), (4.14)", _p(I, "Fa"), lambda: _idx().Fa, exact=True),
        Check("app7.indexing.dip", "indexing: stiffness dip 1 + 4 Fa from the printed Fa = 3.34",
              f"{a72} (12), (4.19)", _p(I, "dip"), lambda: ex().stiffness_dip(_pf(I, "Fa")),
              note="with the unrounded Fa = 3.3353 the dip is 14.34", exact=True),
        Check("app7.indexing.c_min", "indexing: c_min = c_c/dip from the printed c_c and dip (N/m)",
              f"{a72} (12), table 7-I", _p(I, "c_min"),
              lambda: _pf(I, "c_c") / _pf(I, "dip"),
              note="with the unrounded dip 14.34 it is 0.2545e6", exact=True),
        Check("app7.indexing.freq_factor", "indexing: lowest natural frequency at T = 0.5 over "
              "that at T = 0, 1/(1 + 4 Fa)^(1/2)", "sec. 7.4.3, (4.32)", _p(I, "freq_factor"),
              lambda: _idx().freq_factor, exact=True),
        Check("app7.indexing.s_r_red", "indexing: roller backlash 0.074 mm at R_red, i s_r (mm)",
              "fig. 7.7, fig. A.7.2", _p(I, "s_r_red"),
              lambda: 1e3 * _m().INDEXING.i.value * _m().INDEXING.s_r.value, exact=True),
        Check("app7.indexing.s_half", "indexing: overall backlash at half the cam rise at R_red, "
              "roller plus App. 6's gear backlash 1.02e-2 rad through dh/dbeta = 2 h_m/beta_m (m)",
              "fig. 7.7, sec. 7.4.4", _m().INDEXING.s_half_out.printed.split()[0],
              lambda: ex().indexing_backlash(),
              note="1.2756e-3 (truncated as printed); ST = 1.020E-2 is a reading of App. 6",
              exact=True),
        Check("app7.indexing.frame_lower", "indexing: measured c_c (2.75e6) lower than calculated "
              "(3.65e6) by", "sec. 7.4.1.2, table 7-I", _p(I, "frame_lower"),
              lambda: 1 - _pf(I, "c_c_measured") / _pf(I, "c_c"), exact=True),
        Check("app7.indexing.frame_ratio", "indexing: frame stiffness, in series with the calculated "
              "c_c to give the measured one, over c_c", "sec. 7.4.1.2, table 7-I",
              _p(I, "frame_ratio"),
              lambda: 1 / (1 / _pf(I, "c_c_measured") - 1 / _pf(I, "c_c")) / _pf(I, "c_c"),
              rule="rel:0.05", note="'about 3 times'; 3.05", exact=True),
        Check("app7.indexing.c_min_diff", "indexing: calculated c_min 0.253e6 against the measured "
              "0.298e6, (measured - calculated)/measured", "sec. 7.4.1.2, table 7-I",
              _p(I, "c_min_diff"),
              lambda: 1 - _pf(I, "c_min") / _pf(I, "c_min_measured"),
              note="'differs by only 15 %'; relative to the calculated value it would be 18 %",
              exact=True),
        # -- sec. 7.4.4 ----------------------------------------------------------------------------
        Check("app7.sec7_4_4.S", "indexing: relative backlash s_0.5'/h_m' = 1.27e-3 m/0.1 m",
              "sec. 7.4.4, fig. 7.11b", _p(I, "S"),
              lambda: _m().INDEXING.s_half_out.value / _m().INDEXING.h_m_out.value, exact=True),
        Check("app7.sec7_4_4.r_e", "indexing: relative impact speed (3.16) at S = 1.27e-2, "
              "|H'''| = 4 pi^2", "sec. 7.4.4, (3.15), (3.16)", _p(I, "r_e"),
              lambda: ex().indexing_impact().r_e, exact=True),
        Check("app7.sec7_4_4.Hd_068", "cycloid H' = 1 - cos 2 pi T at T = 0.68", "sec. 7.4.4, (A.2.10)",
              _p(I, "Hd_068"), lambda: ex().cycloid_velocity(0.68), note="1.4258, truncated as printed",
              exact=True),
        Check("app7.sec7_4_4.tau_068", "indexing: tau_0.68 = tau (1 + H'^2 Fa)^(1/2) with the "
              "printed tau = 0.08, Fa = 3.34, H' = 1.42", "sec. 7.4.4, (4.32)", _p(I, "tau_068"),
              lambda: ex().impact_as_printed()["tau_068"],
              note="with the unrounded H' = 1.4258 it is 0.2233", exact=True),
        Check("app7.sec7_4_4.Xdd_068", "indexing: X''_0.68 = X''_(s=0) - 2 pi r_e/tau_0.68 with the "
              "printed r_e = 0.31, tau_0.68 = 0.222, X''_(s=0) = -7.4", "sec. 7.4.4, (3.12)",
              _p(I, "Xdd_068"), lambda: ex().impact_as_printed()["Xdd_068"],
              note="X''_(s=0) = -7.4 is read from the 4-DOF simulation of fig. 7.15", exact=True),
        Check("app7.sec7_4_4.Xdd_068.full", "indexing: X''_0.68 at full precision (r_e = 0.306, "
              "tau_0.68 = 0.2233), X''_(s=0) = -7.4 as printed", "sec. 7.4.4, (3.12), (3.16), (4.32)",
              _p(I, "Xdd_068"), lambda: ex().indexing_impact().Xdd, rule="rel:0.02",
              note="-16.01: the printed -16.2 carries the rounded r_e and tau_0.68", exact=True),
        Check("app7.sec7_4_4.Xdd_s0.camshaft1", "indexing without backlash: X''(0.68) of CAMSHAFT-1 "
              "at tau = 0.08, Fa = 3.34 against the 4-DOF value of fig. 7.15",
              "sec. 7.4.4, fig. 7.14, fig. 7.15", _p(I, "Xdd_s0_068"),
              lambda: camshaft1_Xdd(_pf(I, "tau"), _pf(I, "Fa"), 0.68), rule="rel:0.05",
              note="a different model: the one-DOF model of fig. 7.14 (undamped) for the 4-DOF "
                   "DYNACAM run of fig. 7.15; -7.63"),
        # -- spring-loaded follower, App. 7 A.7.3 ---------------------------------------------
        Check("app7.follower.t_m", "follower: t_m = beta_m/w_s at 47.5 r.p.m. (s)", f"{a73}.1 (8)",
              _p(F, "t_m"), lambda: _fol().t_m, exact=True),
        Check("app7.follower.T_e", "follower: T_e = 2 pi (m/c_c)^(1/2), m = 1.46 kg, "
              "c_c = 0.376e6 N/m (s)", f"{a73}.1 (7)", _p(F, "T_e"), lambda: _fol().T_e,
              exact=True),
        Check("app7.follower.tau", "follower: tau = T_e/t_m", f"{a73}.1 (9)", _p(F, "tau"),
              lambda: _fol().tau, exact=True),
        Check("app7.follower.tan_alpha_me", "follower: tan alpha_me = h_m/(R_1/2 beta_m)",
              f"{a73}.1 (11), (4.13)", _p(F, "tan_alpha_me"), lambda: _fol().tan_alpha_me,
              note="0.4587, truncated as printed", exact=True),
        Check("app7.follower.c_tan", "follower: c_tan = 1/26.14e-6 m/N (N/m)", "fig. A.7.7, (4.4)",
              _p(F, "c_tan"), lambda: _fol().c_tan, exact=True),
        Check("app7.follower.Fa", "follower: Fa = (c_c/c_tan) tan^2 alpha_me with c_c = 0.37e6 N/m",
              f"{a73}.1 (12), (4.14)", _p(F, "Fa"), lambda: _fol(table=True).Fa,
              note="0.37e6 N/m of table 7-I and fig. A.7.7; App. 7's 0.376e6 gives 2.07",
              exact=True),
        Check("app7.follower.c_min", "follower: c_min = c_c/(1 + 4 Fa), c_c = 0.37e6 N/m (N/m)",
              "table 7-I, (4.19)", _p(F, "c_min"), lambda: _fol(table=True).c_min,
              note="0.376e6 N/m with its own Fa gives 0.04055e6, also 0.0405e6", exact=True),
        Check("app7.follower.freq_factor", "follower: 1/(1 + 4 Fa)^(1/2) at the printed Fa = 2.04",
              "sec. 7.4.3, (4.32)", _p(F, "freq_factor"),
              lambda: ex().frequency_factor(_pf(F, "Fa")), exact=True),
        Check("app7.follower.Fv", "follower: Fv = (m/m_tan) tan^2 alpha_me, m = 1.46 kg, "
              "m_tan = 0.116 kg", f"{a73}.2, (5.52)", _p(F, "Fv"), lambda: _fol().Fv,
              rule="rel:0.015",
              note="2.648 from the printed inputs; only with m, m_tan, beta_m all at the edge of "
                   "their rounding (1.465, 0.1155, 0.4355) does it reach 2.675: the unrounded "
                   "m, m_tan are lost with the terms of (5.50), (5.51)", exact=True),
        Check("app7.eq5_14.identity", "(5.52) with m_tan = J/R_1/2^2 is (5.14b) Fv = m h_m^2/(J beta_m^2)",
              "(5.14), (5.52)", None, _eq_5_14_identity, rule="identity"),
        Check("app7.eq5_12b.identity", "(4.14) with c_tan = k/R_1/2^2 is (5.12b) Fa = c_x h_m^2/(k beta_m^2)",
              "(5.12b), (4.14)", None, _eq_5_12b_identity, rule="identity"),
    ]
    return out
