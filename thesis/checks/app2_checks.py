"""Checks of the cam-law characteristics (thesis App. 2) against the printed values."""
from __future__ import annotations

from .check import Check


def _props(key, theta=None):
    from camdyn.thesis.theory.lawtable import properties

    return properties(key, theta)


def _torque_identity() -> bool:
    """(A.2.12)-(A.2.14): max of H' H'' of the cycloid is (3 sqrt 3/2) pi, at T = 1/3."""
    import sympy as sp

    from camdyn.derive.camlaws import LAWS, T

    H = LAWS["cycloidal"].rise[0]
    value = (H.diff(T) * H.diff(T, 2)).subs(T, sp.Rational(1, 3))
    return sp.simplify(value - 3 * sp.sqrt(3) / 2 * sp.pi) == 0 and \
        abs(_props("cycloidal").T_torque_max - 1 / 3) < 1e-9


def _envelope_identity() -> bool:
    """The cycloid's residual envelope C tau^p is tau^3/pi, the envelope of (3.5) for tau << 1."""
    import math

    p = _props("cycloidal")
    return p.residual_order == 3 and math.isclose(p.residual_coeff, 1 / math.pi, rel_tol=1e-14)


def _modsine_quarter() -> bool:
    """theta = 1/4 turns the modified sine into the cycloid (all characteristics equal)."""
    a, b = _props("modified-sine", 0.25).as_dict(), _props("cycloidal").as_dict()
    return all(k == "key" or abs(a[k] - b[k]) < 1e-12 for k in a if a[k] is not None)


def checks() -> list[Check]:
    cyc = lambda attr: (lambda: getattr(_props("cycloidal"), attr))
    ms = lambda attr: (lambda: getattr(_props("modified-sine", 0.1), attr))
    return [
        Check("app2.cycloid.velocity_peak", "cycloid: peak velocity H'max", "(A.2.9), sec. 4.4.1", "2",
              cyc("H1_max"), exact=True),
        Check("app2.cycloid.acceleration_peak", "cycloid: peak acceleration H''max = 2 pi", "(A.2.8)",
              "6.28", cyc("H2_max"), exact=True),
        Check("app2.cycloid.jerk_0", "cycloid: jerk at T = 0", "(A.2.16)", "39.4", cyc("jerk_0"),
              exact=True),
        Check("app2.cycloid.jerk_half", "cycloid: jerk at T = 0.5", "(A.2.16)", "-39.4", cyc("jerk_half"),
              exact=True),
        Check("app2.cycloid.jerk_1", "cycloid: jerk at T = 1", "(A.2.16)", "39.4", cyc("jerk_1"),
              exact=True),
        Check("app2.cycloid.torque", "cycloid: max torque factor (3 sqrt 3/2) pi at T = 1/3",
              "(A.2.12)-(A.2.14)", None, _torque_identity, rule="identity"),
        Check("app2.cycloid.envelope", "cycloid: one-DOF residual envelope tau^3/pi", "(3.5), App. 2",
              None, _envelope_identity, rule="identity"),
        Check("app2.modsine.peak", "modified sine (theta = 0.1): peak acceleration", "(A.2.17), fig. 8.7",
              "5.40", ms("H2_max"), exact=True),
        Check("app2.modsine.jerk_0", "modified sine (theta = 0.1): jerk at T = 0", "(A.2.21)", "85",
              ms("jerk_0"), exact=True),
        Check("app2.modsine.jerk_1", "modified sine (theta = 0.1): jerk at T = 1", "(A.2.21)", "85",
              ms("jerk_1"), exact=True),
        Check("app2.modsine.jerk_half", "modified sine (theta = 0.1): jerk at T = 0.5", "(A.2.22)", "-21.2",
              ms("jerk_half"), exact=True),
        Check("app2.modsine.quarter_is_cycloid", "modified sine at theta = 1/4 equals the cycloid",
              "(A.2.17)", None, _modsine_quarter, rule="identity"),
    ]
