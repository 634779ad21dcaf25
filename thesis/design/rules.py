"""The rules of secs 8.2-8.5 a design breaks ("violated") or should mind ("note"), with the
remedies (8.5) suggests."""
from __future__ import annotations

from .machine import Machine

COMMON_SHAFT_FA = 0.3
"""Sec. 8.5 rule (3): Fa <= 0.3 on a shaft that drives several mechanisms (interaction)."""
TAN_ALPHA_MAX = 0.5
"""Sec. 8.2.7 (3): tan alpha_me = 1/2 'is considered to be a maximum for practical design
reasons' (the scan prints the fraction as '-!'; 0.13/(0.178 1.47) = 0.497 there)."""
GRAPH_TAU = (0.06, 0.7)
GRAPH_FA = 2.0
"""The range of the printed graphs of fig. 4.11 (tau axis, largest Fa curve)."""


def rules(M: Machine, ratio_design: float, common_shaft: bool, motor_out: dict | None,
          limited_by: str = "accuracy", law: str = "cycloidal") -> list[dict]:
    """The rules of secs 8.2.6-8.5 the design breaks ("violated") or should mind ("note")."""
    out = []

    def add(kind, rule, text):
        out.append({"status": kind, "rule": rule, "text": text})

    if ratio_design > 1:
        k = ratio_design
        if law != "cycloidal":
            how = ("(8.5) and (3.6) are the cycloid's; the limits above say how far tau and Fa "
                   "must come down (rules 1, 3, 4: a shorter stroke, a longer t_m, a stiffer, "
                   "lighter follower)")
        elif limited_by == "accuracy":
            how = (f"By (8.5), u0 ~ h_m' (2 pi/t_m)^3 (m/c)^(3/2)/pi (Fa = 0): shorten the stroke "
                   f"by {k:.3g} (rule 1), or lengthen t_m by {k ** (1 / 3):.3g} (rule 3), or raise "
                   f"c/m by {k ** (2 / 3):.3g} (rule 4)")
        else:
            how = (f"By (3.6), u0'' ~ 4 pi h_m' T_e/t_m^3 (Fa = 0, small tau): shorten the stroke "
                   f"by {k:.3g}, or lengthen t_m by {k ** (1 / 3):.3g}, or raise c/m by {k ** 2:.3g}")
        add("violated", "sec. 8.5 (3), (8.5)",
            f"the envelope at tau = {M.tau:.3g}, Fa = {M.Fa:.3g} is {k:.3g} times the "
            f"requirement ({limited_by}).  {how}" + ("; with Fa > 0 see the limits above"
                                                      if law == "cycloidal" else ""))
    if M.Fa > COMMON_SHAFT_FA:
        if common_shaft:
            add("violated", "sec. 8.5 (3)", f"Fa = {M.Fa:.3g} > {COMMON_SHAFT_FA} on a common "
                "shaft: mechanisms driven from one shaft interact (ref. 35)")
        else:
            add("note", "sec. 8.5 (3)", f"Fa = {M.Fa:.3g} > {COMMON_SHAFT_FA}: allowed only if "
                "this shaft drives no other mechanism (--common-shaft checks it)")
    if M.tan_alpha_me is not None and M.tan_alpha_me > TAN_ALPHA_MAX:
        add("violated", "sec. 8.2.7 (3)", f"tan alpha_me = {M.tan_alpha_me:.3g} > 1/2, the "
            "practical maximum; Fa grows with its square (4.14): a larger beta_m or R_1/2 (rule 10)")
    if M.ratio is not None and M.ratio != 1:
        add("note", "sec. 8.5 (6), (7)", f"i = {M.ratio:.4g}: stiffnesses before the output "
            f"member count reduced by i^2 = {M.ratio ** 2:.3g}; rule (6) asks i about 1")
    if not GRAPH_TAU[0] <= M.tau <= GRAPH_TAU[1] or M.Fa > GRAPH_FA:
        add("note", "fig. 4.11", f"(tau, Fa) = ({M.tau:.3g}, {M.Fa:.3g}) lies beyond the printed "
            f"graphs (tau {GRAPH_TAU[0]}-{GRAPH_TAU[1]}, Fa <= {GRAPH_FA:g}); the envelope is "
            "computed here")
    if M.tau < 0.1:
        add("note", "sec. 8.2.6", "tau < 0.1: measured points lie far below the envelope there "
            "(tuning); the envelope is the safe reading")
    if motor_out is not None and not motor_out["rule_8_4"]:
        add("violated", "(8.4)", f"the slip limit {motor_out['delta_lim']:.3g} exceeds the rated "
            f"slip {motor_out['delta_n']:.3g}: the motor would be overloaded")
    add("note", "sec. 8.5 (2), sec. 8.2.8", "the graphs hold without backlash and without damping "
        "(the safe side); with backlash use sec. 3.6 ((3.11), (3.12), (3.16))")
    return out
