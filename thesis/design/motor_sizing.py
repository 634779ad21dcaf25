"""The motor by sec. 8.3: tau_m = T_m/t_m, the peak slip of fig. 8.6, the overdimensioning P
(8.1), the rated torque (8.2) and power (8.3), and (8.4); the formulas are the theory's
(thesis/theory/motor_rules.py, in NumPy; with an electrical time constant the second-order
motor of thesis/theory/motor_theory.py, SymPy's)."""
from __future__ import annotations

import math

from camdyn.runtime.core.errors import CamdynInputError

from .machine import positive

RATED_SLIP = 0.085
"""delta_n of the motors of fig. A.5.3, taken when none is given."""

MOTOR_T_M = {3000: 0.113, 1500: 0.0398, 1000: 0.0392, 750: 0.0321}
"""Mechanical time constants T_m (s) of the thesis's motors by synchronous speed (fig. A.5.3)."""


def motor(*, t_m, T_m, delta_n, delta_lim, eta_g=1.0, spring=False, T_el=None, mass=None,
          stroke=None, w_s=None) -> dict:
    """Sec. 8.3: tau_m = T_m/t_m, delta_max/delta_n from fig. 8.6 (first order (A.5.33), as
    sec. 8.3 says; second order (A.5.25) with T_el), P (8.1), M_ena (8.2), N_n (8.3), (8.4);
    the torque and power need the mass (at the output member, with the stroke h_m' there),
    the torque also the shaft speed."""
    from camdyn.thesis.theory import motor_rules as mt

    tau_m = T_m / t_m
    tau_el = speed = None
    if T_el is not None:
        from camdyn.thesis.theory.motor_theory import second_order   # SymPy's: only with T_el

        tau_el = T_el / t_m
        speed = second_order(tau_el)
    rel, T_peak = mt.relative_slip_peak(tau_m, speed)
    P = mt.required_overdimensioning(tau_m, delta_n, delta_lim, eta_g=eta_g, spring=spring,
                                     speed=speed)
    out = {"T_m": T_m, "tau_m": tau_m, "tau_el": tau_el, "delta_n": delta_n,
           "delta_lim": delta_lim, "eta_g": eta_g, "v_v": 5 if spring else 1,
           "slip_peak_rel": rel, "T_slip_peak": T_peak, "P": P,
           "M_ena": None, "N_n": None, "rule_8_4": bool(mt.slip_within_rated(delta_lim, delta_n))}
    if mass is not None:
        out["N_n"] = mt.required_power(mass, stroke, t_m, P)
        if w_s is not None:
            out["M_ena"] = mt.required_torque(mass, stroke, w_s, t_m, P)
    return out


def settings(*, motor_rpm=None, motor_tm=None, slip_limit=None, rated_slip=None, motor_tel=None,
             gear_efficiency=None, worm=None, spring=False) -> dict | None:
    """The motor's arguments of :func:`motor` from what the designer gives (the options of
    `camdyn design`), every one checked; None without a motor."""
    given = [motor_rpm, motor_tm, slip_limit]
    only = {"--motor-tel": motor_tel, "--rated-slip": rated_slip,
            "--gear-efficiency": gear_efficiency, "--worm": worm, "--spring": spring or None}
    stray = [k for k, v in only.items() if v is not None]
    if stray and all(v is None for v in given):
        # they enter (8.1)-(8.3) only: without a motor they would be dropped unread
        raise CamdynInputError(f"argument {stray[0]}: applies to the motor (sec. 8.3) only; "
                               "give --motor-rpm or --motor-tm and --slip-limit")
    if all(v is None for v in given):
        return None
    delta_n = RATED_SLIP if rated_slip is None else rated_slip
    if slip_limit is None:
        raise CamdynInputError("argument --slip-limit: required with a motor (delta_lim, "
                               "the largest slip allowed, 0 < delta_lim < 1; (8.1))")
    if (motor_rpm is None) == (motor_tm is None):
        raise CamdynInputError("arguments --motor-rpm, --motor-tm: give one (the motor's "
                               "mechanical time constant T_m, fig. A.5.3, (A.5.11))")
    if motor_rpm is not None:
        if motor_rpm not in MOTOR_T_M:
            raise CamdynInputError(f"argument --motor-rpm: {motor_rpm:g} is not one of "
                                   f"{', '.join(str(k) for k in MOTOR_T_M)} (fig. A.5.3)")
        T_m = MOTOR_T_M[int(motor_rpm)]
    else:
        T_m = positive("T_m", "--motor-tm", motor_tm, "s, motor's mechanical time constant "
                       "(A.5.11)")
    for flag, v in (("--slip-limit", slip_limit), ("--rated-slip", delta_n)):
        if not (math.isfinite(v) and 0 < v < 1):
            raise CamdynInputError(f"argument {flag}: {v:g} is out of range: 0 < slip < 1")
    if worm is not None and gear_efficiency is not None:
        raise CamdynInputError("argument --worm: not allowed with --gear-efficiency; give one")
    eta = 1.0
    if gear_efficiency is not None:
        eta = gear_efficiency
        if not 0 < eta <= 1:
            raise CamdynInputError(f"argument --gear-efficiency: eta_g={eta:g} is out of "
                                   "range: 0 < eta_g <= 1")
    if worm is not None:
        alpha, mu = worm
        if not (0 < alpha < math.pi / 2 and 0 <= mu and alpha + mu < math.pi / 2):
            raise CamdynInputError(f"argument --worm: alpha={alpha:g}, mu={mu:g} rad out of "
                                   "range: 0 < alpha, 0 <= mu, alpha + mu < pi/2")
        from camdyn.thesis.theory import motor_rules as mt

        eta = mt.worm_gear_efficiency(alpha, mu)       # motor driving (6.72), (A.5.34)
    T_el = positive("T_el", "--motor-tel", motor_tel, "s, electrical time constant (A.5.3)")
    return {"T_m": T_m, "delta_n": delta_n, "delta_lim": slip_limit, "eta_g": eta,
            "spring": spring, "T_el": T_el}
