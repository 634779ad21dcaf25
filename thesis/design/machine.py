"""What the designer gives, turned into the machine's figures (App. 7 (5)-(12)):
T_e = 2 pi (m/c_c)^(1/2) (4.39), t_m = beta_m/w_s (App. 7 (8)), tau = T_e/t_m (4.12),
tan alpha_me = h_m'/(i R_1/2 beta_m) (4.13), Fa = (c_c/c_tan) tan^2 alpha_me (4.14); every
input checked, every figure with the way it was found.  The formulas, and a rocker's reduction
to its roller (2.55)-(2.57), are the runtime's (runtime/cam/reduction.py), which a
camshaft1-study scene's [follower] forms its design point with: the two agree bit for bit.
thesis/theory/examples.py types the same formulas in from the thesis, and tests compare.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from camdyn.runtime.cam import reduction as red
from camdyn.runtime.core.errors import CamdynInputError

from .limits import FA_CAP, TAU_CAP


def positive(name: str, flag: str, value, unit: str, upper: float | None = red.LARGEST):
    """``value`` as a float > 0 and < ``upper``, None for None; else a CamdynInputError naming
    the option ``flag``, the quantity and its unit."""
    if value is None:
        return None
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise CamdynInputError(f"argument {flag}: {name} must be a number, got {value!r}") from None
    if not (math.isfinite(v) and v > 0 and (upper is None or v < upper)):
        rng = f"0 < {name} < {upper:g}" if upper is not None else f"{name} > 0"
        raise CamdynInputError(f"argument {flag}: {name}={v:g} is out of range: {rng} ({unit})")
    return v


SHORTEST_ARM = 1e-6
"""The shortest rocker arm taken (m), as camdyn profile's shortest radius."""


def rocker(*, swing_deg, arm_length, stroke=None, inertia=None, mass=None,
           torsional_stiffness=None, stiffness=None) -> tuple:
    """(stroke, mass, stiffness) of a rocker reduced to its roller centre's arc, as sec. 2.4
    reduces a linkage with the ratio l (the arm) from the swing to the arc: h_m' = l Phi
    (2.55), m = J/l^2 (2.56), c = k_t/l^2 (2.57), J the arm's inertia about the pivot and
    k_t its torsional stiffness there.  The one- and two-DOF models take the rocker so: their
    cam slope is the law's for any follower reduced to its output.  A quantity given at the
    roller already (mass, stiffness) is taken as it is; the stroke must not be given too."""
    for flag, value in (("--swing", swing_deg), ("--arm-length", arm_length)):
        if value is None:
            raise CamdynInputError(f"argument {flag}: a rocker needs --swing and --arm-length")
    Phi = positive("swing", "--swing", swing_deg, "deg", upper=180.0)
    l = positive("l", "--arm-length", arm_length, "m")
    if l < SHORTEST_ARM:
        # J/l^2 and k_t/l^2 overflow long before l reaches 0 (1e-200 squared is 0)
        raise CamdynInputError(f"argument --arm-length: l={l:g} is out of range: "
                               f"{SHORTEST_ARM:g} <= l < {red.LARGEST:g} (m)")
    if stroke is not None:
        raise CamdynInputError("argument --stroke: a rocker's stroke is its arc, --arm-length x "
                               "--swing; give one or the other")
    for name, at_pivot, at_roller, flag in (("inertia", inertia, mass, "--arm-inertia"),
                                            ("stiffness", torsional_stiffness, stiffness,
                                             "--arm-stiffness")):
        if at_pivot is not None and at_roller is not None:
            raise CamdynInputError(f"argument {flag}: the arm's {name} about the pivot or the "
                                   f"{name} at the roller, not both")
    J = positive("J", "--arm-inertia", inertia, "kg m^2")
    k_t = positive("k_t", "--arm-stiffness", torsional_stiffness, "N m/rad")
    return (red.arc_stroke(l, Phi), mass if J is None else red.arc_mass(J, l),
            stiffness if k_t is None else red.arc_stiffness(k_t, l))


def cam_angle(text) -> float:
    """beta_m in rad from '1.745' (rad) or '100deg' (degrees)."""
    if text is None:
        return None
    s = str(text).strip().lower()
    deg = s.endswith("deg")
    v = positive("beta_m", "--cam-angle", s[:-3] if deg else s, "rad, or degrees as '100deg'")
    v = math.radians(v) if deg else v
    if v >= 2 * math.pi:
        raise CamdynInputError(f"argument --cam-angle: beta_m={v:g} rad is out of range: "
                               "0 < beta_m < 2 pi (rad, or degrees as '100deg')")
    return v


@dataclass
class Machine:
    """The machine's figures (App. 7 (5)-(12)) and where each came from."""

    stroke: float
    t_m: float | None = None
    T_e: float | None = None
    tau: float = 0.0
    Fa: float = 0.0
    mass: float | None = None
    stiffness: float | None = None
    c_tan: float | None = None
    tan_alpha_me: float | None = None
    beta_m: float | None = None
    w_s: float | None = None
    ratio: float | None = None
    pitch_radius: float | None = None
    sources: dict = field(default_factory=dict)


def machine(*, stroke, rise_time=None, cam_angle_rad=None, speed=None, mass=None, stiffness=None,
            tau=None, Fa=None, c_tan=None, pitch_radius=None, ratio=None,
            tan_alpha_me=None) -> Machine:
    """tau and Fa from what the designer gives (App. 7 (5)-(12)); every input checked."""
    h = positive("h_m'", "--stroke", stroke, "m, stroke of the output member")
    if h is None:
        raise CamdynInputError("argument --stroke: required (h_m' > 0, m, stroke of the output "
                               "member)")
    t_m = positive("t_m", "--rise-time", rise_time, "s")
    beta = cam_angle_rad
    rpm = positive("speed", "--speed", speed, "r.p.m. of the camshaft")
    m = positive("m", "--mass", mass, "kg, equivalent mass (4.39) at the output member")
    c = positive("c_c", "--stiffness", stiffness, "N/m, stiffness of the uncoupled follower (4.3)")
    tau = positive("tau", "--tau", tau, "T_e/t_m (4.12)", upper=TAU_CAP)
    c_t = positive("c_tan", "--c-tan", c_tan, "N/m, tangential stiffness (4.4)")
    R = positive("R_1/2", "--pitch-radius", pitch_radius, "m, pitch radius at half the stroke "
                  "(4.1), at the cam")
    i = positive("i", "--ratio", ratio, "transmission ratio output/cam, h_m' = i h_m")
    tan_me = positive("tan alpha_me", "--tan-alpha-me", tan_alpha_me, "mean slope (4.13)")
    if Fa is not None:
        try:
            Fa = float(Fa)
        except (TypeError, ValueError):
            raise CamdynInputError(f"argument --fa: Fa must be a number, got {Fa!r}") from None
        if not (math.isfinite(Fa) and 0 <= Fa <= FA_CAP):
            raise CamdynInputError(f"argument --fa: Fa={Fa:g} is out of range: 0 <= Fa <= "
                                   f"{FA_CAP:g} (shaft stiffness factor (4.14))")
    src = {}
    M = Machine(stroke=h, mass=m, stiffness=c, c_tan=c_t, beta_m=beta, ratio=i, pitch_radius=R)
    # the rise time: given, or beta_m/w_s (App. 7 (8))
    if t_m is not None and (rpm is not None and beta is not None):
        raise CamdynInputError("argument --rise-time: not allowed with both --cam-angle and "
                               "--speed (t_m = beta_m/w_s, App. 7 (8)); give one or the other")
    if rpm is not None:
        M.w_s = red.shaft_speed(rpm)
        if beta is not None:
            t_m = red.rise_time(beta, M.w_s)
            src["t_m"] = "beta_m/w_s (App. 7 (8))"
        elif t_m is not None:
            M.beta_m = beta = t_m * M.w_s
            src["beta_m"] = "t_m w_s"
        else:
            raise CamdynInputError("argument --speed: needs --cam-angle (t_m = beta_m/w_s) or "
                                   "--rise-time")
    elif beta is not None and t_m is None:
        raise CamdynInputError("argument --cam-angle: needs --speed (t_m = beta_m/w_s, App. 7 (8))")
    elif t_m is not None:
        src["t_m"] = "given"
    M.t_m = t_m
    # T_e and tau: m and c_c (4.39), or tau given
    if tau is not None:
        if m is not None and c is not None:
            raise CamdynInputError("argument --tau: not allowed with both --mass and --stiffness "
                                   "(tau = 2 pi (m/c_c)^(1/2)/t_m, (4.39), (4.12)); give tau or m "
                                   "and c_c")
        M.tau = tau
        src["tau"] = "given"
        if t_m is not None:
            M.T_e = tau * t_m
            src["T_e"] = "tau t_m"
            w2 = (2 * math.pi / M.T_e) ** 2
            if m is not None:
                M.stiffness = m * w2
                src["stiffness"] = "m (2 pi/T_e)^2 (4.39)"
            elif c is not None:
                M.mass = c / w2
                src["mass"] = "c_c (T_e/2 pi)^2 (4.39)"
    else:
        if m is None or c is None:
            raise CamdynInputError("arguments --mass, --stiffness: give both (T_e = 2 pi "
                                   "(m/c_c)^(1/2), (4.39)) or give --tau")
        if t_m is None:
            raise CamdynInputError("argument --rise-time: required with --mass and --stiffness "
                                   "(tau = T_e/t_m, (4.12)); or --cam-angle with --speed")
        M.T_e = red.natural_period(m, c)
        M.tau = red.period_ratio(M.T_e, t_m)
        src["T_e"] = "2 pi (m/c_c)^(1/2) (4.39)"
        src["tau"] = "T_e/t_m (4.12)"
        if not M.tau < TAU_CAP:
            raise CamdynInputError(f"arguments --mass, --stiffness, --rise-time: they give tau = "
                                   f"T_e/t_m = {M.tau:.3g}, out of range: 0 < tau < {TAU_CAP:g} "
                                   "(the rise must outlast the natural period)")
    # tan alpha_me (4.13) and Fa (4.14)
    if tan_me is not None:
        if R is not None:
            raise CamdynInputError("argument --tan-alpha-me: not allowed with --pitch-radius "
                                   "(tan alpha_me = h_m'/(i R_1/2 beta_m), (4.13)); give one")
        M.tan_alpha_me = tan_me
        src["tan_alpha_me"] = "given"
    elif R is not None:
        if beta is None:
            raise CamdynInputError("argument --pitch-radius: needs the cam angle (--cam-angle, "
                                   "or --rise-time with --speed) for tan alpha_me = h_m'/(i "
                                   "R_1/2 beta_m) (4.13)")
        M.tan_alpha_me = red.mean_slope(h / (i or 1.0), R, beta)
        src["tan_alpha_me"] = "h_m'/(i R_1/2 beta_m) (4.13)"
    if Fa is not None:
        if c_t is not None:
            raise CamdynInputError("argument --fa: not allowed with --c-tan (Fa = (c_c/c_tan) "
                                   "tan^2 alpha_me, (4.14)); give one")
        M.Fa = Fa
        src["Fa"] = "given"
    elif c_t is not None:
        if M.tan_alpha_me is None or M.stiffness is None:
            raise CamdynInputError("argument --c-tan: Fa = (c_c/c_tan) tan^2 alpha_me (4.14) needs "
                                   "c_c (--stiffness, or --mass with --tau and t_m) and tan alpha_me "
                                   "(--pitch-radius with the cam angle, or --tan-alpha-me)")
        M.Fa = red.shaft_factor(M.stiffness, c_t, M.tan_alpha_me)
        src["Fa"] = "(c_c/c_tan) tan^2 alpha_me (4.14)"
        if not M.Fa <= FA_CAP:
            raise CamdynInputError(f"argument --c-tan: it gives Fa = (c_c/c_tan) tan^2 alpha_me = "
                                   f"{M.Fa:.3g}, out of range: 0 <= Fa <= {FA_CAP:g}")
    else:
        raise CamdynInputError("argument --fa: give --fa, or --c-tan with the pitch radius "
                               "(Fa = (c_c/c_tan) tan^2 alpha_me, (4.14)); --fa 0 for a rigid shaft")
    M.sources = src
    return M
