"""Checks of topic 'impact': impact after backlash, sec. 3.6 (3.8)-(3.16), and the decay of the
residual vibration over a dwell, sec. 3.4 (3.7) with its inverse (7.10).

Formulas and derivations: camdyn/thesis/theory/impact.py (its docstring gives the readings of the
scanned-away (3.9), (3.10) and (3.16)).  The ramp of (3.8) is the cam law "uniform"
(H = T on 0 <= T < 1), so the compiled one-DOF model run under it is the impact model with
r_e = 1 up to T = 1.
"""
from __future__ import annotations

import math

from camdyn.thesis.runcache import cached_runs

from .check import Check

# sec. 3.4: "at the usual values of tau = 0.15, t_d/t_m = 1.5 and q = 0.06 ... 2 %" (n = 10)
TAU_DWELL, TD_OVER_TM, Q_DWELL = 0.15, 1.5, 0.06
RAMP_TAU = 0.13  # 7.7 free vibrations within the ramp 0 <= T < 1, so the extremes lie inside it


def _im():
    from camdyn.thesis.theory import impact

    return impact


def _zero(expr) -> bool:
    import sympy as sp

    return sp.simplify(expr) == 0


def _eq_3_9_3_10_reading() -> bool:
    im = _im()
    amp, amp_dd = im.impact_amplitudes()
    return _zero(amp - im.u_sn_reading) and _zero(amp_dd - im.udd_sn_reading)


def _eq_3_11() -> bool:
    im = _im()
    amp, _ = im.impact_amplitudes()
    return _zero(im.dimensionless(amp, im.h_m) - im.U_sn_printed)


def _eq_3_12() -> bool:
    im = _im()
    _, amp_dd = im.impact_amplitudes()
    return _zero(im.dimensionless(amp_dd, im.h_m / im.t_m**2) - im.Udd_sn_printed)


def _eq_3_13_3_14() -> bool:
    im = _im()
    bt = im.backlash_traversal()
    return (_zero(bt["dhd"].subs(im.t, im.t_b) - im.v_b_at_impact_printed)
            and _zero(bt["dh"].subs(im.t, im.t_b) - im.backlash_printed))


def _eq_3_15() -> bool:
    im = _im()
    return _zero(im.backlash_traversal()["v_b"] - im.v_b_printed)


def _eq_3_16() -> bool:
    im = _im()
    return _zero(im.r_e_from_3_15().subs(im.H3, im.CYCLOID_JERK) - im.r_e_cycloid_reading)


def _cycloid_jerk() -> bool:
    """H''' of camdyn's cycloid at the reversal points T = 0, 1/2, 1 is +4 pi^2, -4 pi^2, +4 pi^2."""
    import sympy as sp

    from camdyn.derive import camlaws

    H3 = camlaws.LAWS["cycloidal"].rise[0].diff(camlaws.T, 3)
    want = {0: 1, sp.Rational(1, 2): -1, 1: 1}
    return all(_zero(H3.subs(camlaws.T, T) - sign * _im().CYCLOID_JERK) for T, sign in want.items())


@cached_runs
def _ramp(tau: float):
    """Dense-output amplitudes of U and X'' of the compiled one-DOF model under the ramp."""
    from camdyn.runtime.measure.extremes import extreme
    from camdyn.runtime.core.simulator import simulate

    res = simulate("one_dof", {"tau": tau}, 1.0, "dp54", rtol=1e-11, law="uniform")
    u, _ = extreme(res, "U", 0.0, 1.0, absolute=True, minimum=False)
    a, _ = extreme(res, "Xdd", 0.0, 1.0, absolute=True, minimum=False)
    return u, a


def _identity_3_7() -> bool:
    from camdyn.thesis.theory import forms

    im = _im()
    x, _ = im.damped_free_vibration()
    return _zero(im.damped_residual(x)) and _zero(im.decay_after_damped_periods() - forms.decay)


@cached_runs
def _dwell_decay(tau: float, q: float, td: float) -> float:
    """Envelope ratio A(1 + td)/A(1) of the damped one-DOF model after a cycloidal rise.

    In the dwell the motion is a damped free vibration, u = A e^(-s T) cos(w_d T + phi), so
    A = (u^2 + ((u' + s u)/w_d)^2)^(1/2) at any instant (s = q w_e): no peak needs to be found
    and the dwell is exactly t_d long.
    """
    import numpy as np

    from camdyn.runtime.core.simulator import simulate

    res = simulate("one_dof", {"tau": tau, "q": q}, 1.0 + td, "dp54", rtol=1e-11)
    w = 2 * math.pi / tau
    s, wd = q * w, w * math.sqrt(1 - q * q)
    st = res.sample([1.0, 1.0 + td])
    u, v = st["U"], st["Xd"]  # H' = 0 in the dwell, so u' = X'
    amp = np.sqrt(u**2 + ((v + s * u) / wd) ** 2)
    return float(amp[1] / amp[0])


def checks() -> list[Check]:
    im_ref = "camdyn/thesis/theory/impact.py"
    out = [
        Check("ch3_6.eq3_9_3_10.reading", "ramp response of (3.1): amplitudes v_b T_e/(2 pi) and "
              "2 pi v_b/T_e (derived by dsolve)", "(3.8)-(3.10)", None, _eq_3_9_3_10_reading,
              rule="identity", note=f"(3.9), (3.10) are lost in the scan; reading in {im_ref}"),
        Check("ch3_6.eq3_11.identity", "U_sn = r_e tau/(2 pi) from the derived ramp response",
              "(3.11)", None, _eq_3_11, rule="identity"),
        Check("ch3_6.eq3_12.identity", "U_sn'' = 2 pi r_e/tau from the derived ramp response",
              "(3.12)", None, _eq_3_12, rule="identity"),
        Check("ch3_6.eq3_11.simulated", "one DOF under the ramp (law 'uniform'), tau = 0.13: "
              "amplitude of U over (3.11) with r_e = 1", "(3.8), (3.11)", "1",
              lambda: _ramp(RAMP_TAU)[0] / (RAMP_TAU / (2 * math.pi)), rule="abs:1e-8",
              note="the printed formula as the printed value: the ratio must be 1"),
        Check("ch3_6.eq3_12.simulated", "one DOF under the ramp, tau = 0.13: amplitude of X'' "
              "over (3.12) with r_e = 1", "(3.8), (3.12)", "1",
              lambda: _ramp(RAMP_TAU)[1] / (2 * math.pi / RAMP_TAU), rule="abs:1e-8",
              note="X'' = U'' under the ramp (H'' = 0); the ratio must be 1"),
        Check("ch3_6.eq3_13_3_14.identity", "delta h'' = k t integrated from the force reversal: "
              "velocity 1/2 k t_b^2 (3.13), position 1/6 k t_b^3 = s' (3.14)", "(3.13), (3.14)",
              None, _eq_3_13_3_14, rule="identity"),
        Check("ch3_6.eq3_15.identity", "impact speed v_b = 1/2 (h''')^(1/3) (6 s')^(2/3) from "
              "(3.13), (3.14) with t_b eliminated", "(3.15)", None, _eq_3_15, rule="identity"),
        Check("ch3_6.eq3_16.jerk", "camdyn's cycloid: H''' = +-4 pi^2 at T = 0, 1/2, 1",
              "(A.2.16), sec. 3.6", None, _cycloid_jerk, rule="identity"),
        Check("ch3_6.eq3_16.identity", "r_e of (3.15) made dimensionless, cycloid: "
              "(18 pi^2 S^2)^(1/3)", "(3.16)", None, _eq_3_16, rule="identity",
              note=f"(3.16) is illegible; reading in {im_ref}"),
        Check("eq3_7.identity", "damped free vibration of (3.1) decays by (3.7) over n damped "
              "periods", "(3.7), (6.47)", None, _identity_3_7, rule="identity"),
        Check("eq3_7.n", "free vibrations within the dwell n = t_d/(tau t_m) at tau = 0.15, "
              "t_d/t_m = 1.5", "sec. 3.4", "10",
              lambda: _im().dwell_vibrations(TD_OVER_TM, TAU_DWELL), exact=True),
        Check("eq3_7.decay.formula", "U0n/U00 by (3.7) at n = 10, q = 0.06", "(3.7), sec. 3.4",
              "0.02", lambda: _im().decay_ratio(10, Q_DWELL), note="'only 2 % ... is left'",
              exact=True),
        Check("eq3_7.decay.simulated", "envelope ratio over a dwell of 1.5 t_m, damped one DOF "
              "(tau = 0.15, q = 0.06) after a cycloidal rise", "(3.7), sec. 3.4, fig. 3.4", "0.02",
              lambda: _dwell_decay(TAU_DWELL, Q_DWELL, TD_OVER_TM),
              note="0.02305 = exp(-2 pi q n) with n in undamped periods; (3.7) gives 0.02289"),
        Check("eq3_7.eq7_10.follower", "relative damping of the follower from the decay of "
              "fig. 7.17 (n = 9, U00/U09 = 3.7) by (7.10)", "(7.10), sec. 7.4.5", "0.023",
              lambda: _im().q_from_decrement(3.7, 9), note="printed 'q = 2.3 %'", exact=True),
        Check("eq3_7.eq7_10.shaft", "relative damping of the camshaft rotation from fig. 7.18 "
              "(n = 2, U00/U02 = 3.84) by (7.10)", "(7.10), sec. 7.4.5", "0.11",
              lambda: _im().q_from_decrement(3.84, 2), note="printed 'as high as 11 %'",
              exact=True),
    ]
    return out
