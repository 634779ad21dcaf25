"""A follower reduced to the output of the one- and two-DOF models, and the design point
(tau, Fa) it gives them.

Thesis sec. 2.4 reduces a linkage to its output member with the ratio between them.  A rocker
(an oscillating roller follower) is reduced so to its roller centre's arc, the ratio being its
arm l, pivot to roller centre:

    h_m' = l Phi          (2.55)   the stroke, Phi the swing
    m    = J/l^2          (2.56)   J the arm's inertia about the pivot
    c_c  = k_t/l^2        (2.57)   k_t the arm's torsional stiffness at the pivot

The models' cam slope is the law's for any follower so reduced.  At the output, the camshaft
turning at w_s and the rise taking the cam angle beta_m:

    t_m = beta_m/w_s                        App. 7 (8)
    T_e = 2 pi (m/c_c)^(1/2)                (4.39)
    tau = T_e/t_m                           (4.12)
    tan alpha_me = h_m'/(R_1/2 beta_m)      (4.13)
    Fa  = (c_c/c_tan) tan^2 alpha_me        (4.14)

`camdyn design` (thesis/design/machine.py) and a camshaft1-study scene's ``[follower]``
(runtime/targets/scene_files.py) both form their figures here, so the two give the same
design point bit for bit.  No checks here: each caller checks its inputs, bounded by
:data:`LARGEST`, and names them its own way (a command-line option, a scene key).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

LARGEST = 1e12
"""The largest value a design input takes in SI units unless it has a bound of its own: far
beyond any machine, and far enough below the largest float that the products and squares of
the design formulas stay finite (a rise time of 1e300 s overflowed them)."""


def arc_stroke(arm_length: float, swing_deg: float) -> float:
    """h_m' = l Phi (2.55): the arc the roller centre travels, Phi in degrees."""
    return arm_length * math.radians(swing_deg)


def arc_mass(inertia: float, arm_length: float) -> float:
    """m = J/l^2 (2.56): the arm's inertia about the pivot as a mass at the roller."""
    return inertia / arm_length**2


def arc_stiffness(torsional_stiffness: float, arm_length: float) -> float:
    """c_c = k_t/l^2 (2.57): the arm's torsional stiffness at the pivot as one at the roller."""
    return torsional_stiffness / arm_length**2


def shaft_speed(rpm: float) -> float:
    """w_s in rad/s of a camshaft turning at ``rpm`` r.p.m."""
    return rpm * 2 * math.pi / 60


def rise_time(beta_m: float, w_s: float) -> float:
    """t_m = beta_m/w_s (App. 7 (8))."""
    return beta_m / w_s


def natural_period(m: float, c: float) -> float:
    """T_e = 2 pi (m/c_c)^(1/2) (4.39)."""
    return 2 * math.pi * math.sqrt(m / c)


def period_ratio(T_e: float, t_m: float) -> float:
    """tau = T_e/t_m (4.12)."""
    return T_e / t_m


def mean_slope(stroke: float, pitch_radius: float, beta_m: float) -> float:
    """tan alpha_me = h_m'/(R_1/2 beta_m) (4.13), stroke and radius both at the cam."""
    return stroke / (pitch_radius * beta_m)


def shaft_factor(c_c: float, c_tan: float, tan_alpha_me: float) -> float:
    """Fa = (c_c/c_tan) tan^2 alpha_me (4.14)."""
    return c_c / c_tan * tan_alpha_me**2


FORMULAS = {"w_s": "2 pi n/60 (n in r.p.m.)", "t_m": "beta_m/w_s (App. 7 (8))",
            "T_e": "2 pi (m/c_c)^(1/2) (4.39)", "tau": "T_e/t_m (4.12)",
            "tan_alpha_me": "h_m'/(R_1/2 beta_m) (4.13)",
            "Fa": "(c_c/c_tan) tan^2 alpha_me (4.14)"}
"""Where each figure of :class:`DesignPoint` after the follower's own comes from."""
ROCKER_FORMULAS = {"stroke": "l Phi (2.55)", "mass": "J/l^2 (2.56)", "stiffness": "k_t/l^2 (2.57)"}
"""Where a rocker's stroke, mass and stiffness at its roller come from (sec. 2.4)."""


@dataclass(frozen=True)
class DesignPoint:
    """The machine at the output and the design point it gives (App. 7 (5)-(12)), in the
    units of :data:`UNITS`."""

    stroke: float           # h_m'
    mass: float             # m
    stiffness: float        # c_c
    w_s: float
    t_m: float
    T_e: float
    tau: float
    tan_alpha_me: float
    Fa: float


UNITS = {"stroke": "m", "mass": "kg", "stiffness": "N/m", "w_s": "rad/s", "t_m": "s", "T_e": "s",
         "tau": "1", "tan_alpha_me": "1", "Fa": "1"}
"""The unit of each figure of :class:`DesignPoint`, in its order."""


def design_point(*, stroke: float, mass: float, stiffness: float, speed: float,
                 cam_angle: float, pitch_radius: float, c_tan: float) -> DesignPoint:
    """tau (4.12) and Fa (4.14) of a follower at the output: ``speed`` in r.p.m., ``cam_angle``
    beta_m in rad, the rest in SI.  Raises ZeroDivisionError or OverflowError where the inputs
    leave no finite figure (the caller names them)."""
    w_s = shaft_speed(speed)
    t_m = rise_time(cam_angle, w_s)
    T_e = natural_period(mass, stiffness)
    tan_me = mean_slope(stroke, pitch_radius, cam_angle)
    return DesignPoint(stroke=stroke, mass=mass, stiffness=stiffness, w_s=w_s, t_m=t_m, T_e=T_e,
                       tau=period_ratio(T_e, t_m), tan_alpha_me=tan_me,
                       Fa=shaft_factor(stiffness, c_tan, tan_me))
