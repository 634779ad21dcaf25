"""Data of the two mechanisms measured in thesis ch. 7 and worked out in App. 7.

* the **indexing mechanism** (fig. 7.1, fig. A.7.1, dynamic models fig. A.7.2, A.7.3, fig. 7.14;
  backlash fig. 7.7; DYNACAM input listing App. 6), and
* the **spring-loaded cam follower mechanism** (fig. 7.2, fig. A.7.4, dynamic models
  fig. A.7.5, A.7.6, A.7.7, fig. 8.1b).

Every number is a :class:`Quantity`: its value in SI units (m, kg, s, rad, N/m, m/N), the
unit, where the thesis gives it, the text as printed (with the printed unit) when it is
printed, and a note on the reading when the scan is unclear.  The later 4-DOF work turns
these into scene files, so inputs that App. 7 does not print (its scan lost them) are taken
from the App. 6 listing where it can be read, and say so.

Conventions
    Primed magnitudes of the thesis are reduced to the output member at R_red with the
    transmission ratio i (sec. 2.4, App. 7 (2)): lengths times i, masses and stiffnesses
    divided by i^2.  Fields named ``*_red`` are already reduced; the others are where the
    thesis gives them (at the follower roller / cam).

Readings of the scan (the rest is legible)
    * beta_m of the indexing mechanism is printed "1-71.5 rad" (fig. A.7.2) and "1·71.5rad"
      (fig. 7.14); the scan renders a printed "4" as "1." elsewhere too ("Fa =3·31." for 3.34
      in fig. A.7.3, "0·1.58" for 0.458 in fig. 8.1a).  Read: 1.745 rad (100 deg), which gives
      the printed t_m = 0.278 s at 60 r.p.m. and the printed tan alpha_me = 0.379.
    * beta_m of the spring-loaded follower, printed "0·1.36 rad" (fig. A.7.5): 0.436 rad (25 deg),
      same rule; it gives the printed tan alpha_me = 0.458 and t_m = 0.088 s.
    * the spring-loaded follower's speed is printed "47·5 r.p.m. (w_s = 0·495 rad/s)".  0.495 rad/s
      would give t_m = 0.88 s against the printed 0.088 s: read 4.95 rad/s (47.5 r.p.m. is
      4.97 rad/s; either gives t_m = 0.088 s).  The value used is the one from 47.5 r.p.m.
    * the exponent of c_1 = "14.10 N/m" (fig. A.7.2) is lost: 14e6 N/m, as App. 6 (CX=14.E6)
      and fig. 7.14 give.
    * App. 6 listing (CSMP), indexing mechanism, read where needed: IX=1.745 (i), SROLS=74.2E-6
      (roller backlash, 0.074 mm in fig. A.7.2), HMS=56.18E-3 (h_m, 56.2 mm in fig. A.7.2),
      RGS=0.085 (R_1/2), CZS=1.5E7 ("Czl•l 0 5!7"), MZS=1.? ("HZS•I.a", the digit after the
      point is illegible; 1.5 taken), ST=1.020E-2 ("Sh1 0 020E•2", gear backlash in rad at the
      camshaft; the listing forms SAS = ST/BM, the dimensionless tooth backlash of fig. 7.13b),
      N=3600 revolutions per hour (60 r.p.m.).

What App. 7 prints as *results* (c_c, T_e, tau, tan alpha_me, Fa, ...) is in each mechanism's
``printed`` mapping, as printed, for the checks (camdyn/thesis/checks/examples_checks.py).  The
computations are in :mod:`camdyn.thesis.theory.examples`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, fields

__all__ = ["Quantity", "Printed", "IndexingMechanism", "SpringLoadedFollower", "INDEXING",
           "SPRING_LOADED", "MECHANISMS"]


@dataclass(frozen=True)
class Quantity:
    """One number of a mechanism."""

    value: float
    """Value in the SI unit ``unit``."""
    unit: str
    """SI unit of ``value`` ("1" for a pure number)."""
    source: str
    """Where the thesis gives it, e.g. "App. 7, fig. A.7.2"."""
    printed: str | None = None
    """The text as printed, with the printed unit ("56.2 mm"); None when the number is not
    printed (read from the App. 6 listing only, or derived)."""
    note: str = ""
    """Reading taken, uncertainty, or why the value was chosen."""

    def __float__(self) -> float:
        return float(self.value)


@dataclass(frozen=True)
class Printed:
    """A result the thesis prints, as printed (the string a check compares with)."""

    text: str
    """The number exactly as printed (digits and exponent), e.g. "3.34" or "0.253e6"."""
    unit: str
    """Unit of the printed number ("1" for a pure number)."""
    source: str
    note: str = ""


def _q(value, unit, source, printed=None, note=""):
    return Quantity(float(value), unit, source, printed, note)


@dataclass(frozen=True)
class IndexingMechanism:
    """Indexing table driven by a globoidal indexing cam through a worm-gear reduction
    (fig. 7.1, fig. A.7.1); dynamic model fig. A.7.2, reduced fig. A.7.3.

    Chain of the follower linkage (fig. A.7.2), from the output to the cam: table mass m1 at
    R_red, stiffness c1, mass m2 at R2 = R_red/i (the part carrying the rollers), the roller
    in the cam groove with backlash s_r, the cam on its shaft (deflection along the follower
    c_z, tangential c_y, torsion of the shafts c_beta).
    """

    R_red: Quantity
    i: Quantity
    m1: Quantity
    c1: Quantity
    m2: Quantity
    m_z: Quantity
    c_z: Quantity
    flex_tan: Quantity
    h_m: Quantity
    R_half: Quantity
    beta_m: Quantity
    speed: Quantity
    s_r: Quantity
    gear_backlash: Quantity
    h_m_out: Quantity
    s_half_out: Quantity
    q_linkage: Quantity
    q_shaft: Quantity
    eta_roller: Quantity
    roller_width: Quantity
    roller_radius: Quantity
    eta_gear: Quantity
    gear_module: Quantity
    gear_teeth: Quantity
    gear_width: Quantity
    gear_radius: Quantity
    pressure_angle: Quantity
    printed: dict = field(default_factory=dict, compare=False)

    name = "indexing mechanism"


@dataclass(frozen=True)
class SpringLoadedFollower:
    """Spring-loaded cam follower mechanism (fig. 7.2, fig. A.7.4): the output member on an
    arm, roller follower on a radial cam, camshaft driven through shafts, a coupling and a
    V-belt; dynamic model fig. A.7.5, reduced fig. A.7.6, two-DOF fig. A.7.7 (fig. 8.1b).

    App. 7 prints only the result of the equivalent-mass sum (5.50) and of the tangential
    mass (5.51); their terms (m2, m_4z, c2, c_z, m_beta, m_y, c_beta, c_y) are lost in the scan,
    so ``m``, ``c_c``, ``flex_tan`` and ``m_tan`` are inputs here.
    """

    R_red: Quantity
    i: Quantity
    m1: Quantity
    m9: Quantity
    m: Quantity
    c_c: Quantity
    c_c_table: Quantity
    flex_tan: Quantity
    m_tan: Quantity
    c_vbelt: Quantity
    h_m: Quantity
    R_half: Quantity
    beta_m: Quantity
    speed: Quantity
    q_linkage: Quantity
    q_shaft: Quantity
    printed: dict = field(default_factory=dict, compare=False)

    name = "spring-loaded cam follower mechanism"


def omega(speed: Quantity) -> float:
    """Angular velocity in rad/s of a speed given in r.p.m."""
    assert speed.unit == "rpm"
    return speed.value * 2 * math.pi / 60


INDEXING = IndexingMechanism(
    R_red=_q(0.500, "m", "App. 7, A.7.2 (1), fig. A.7.1", "500 mm",
             "pitch radius of the tools on the indexing table; X is expressed there"),
    i=_q(1.745, "1", "App. 7, A.7.2 (2)", "1.745",
         "i = R_red/R2, the only transmission ratio of the follower mechanism (App. 6: IX)"),
    m1=_q(42.0, "kg", "App. 7, fig. A.7.2 and fig. A.7.3", "42 kg",
          "indexing table, reduced at R_red"),
    c1=_q(14e6, "N/m", "App. 7, fig. A.7.2; App. 6 CX=14.E6", "14e6 N/m",
          "at R_red; the scan lost the exponent in fig. A.7.2 (read from App. 6)"),
    m2=_q(15.2, "kg", "App. 7, fig. A.7.2", "15.2 kg",
          "at R2 (roller side); reduced 15.2/i^2 = 5 kg, printed in fig. A.7.3"),
    m_z=_q(1.5, "kg", "App. 6 listing, MZS",
           note="cam mass moving with the shaft deflection along the follower, at the roller. "
                "Scan 'HZS•I.a': the digit after the point is illegible, 1.5 taken; any digit "
                "changes the equivalent mass by less than 0.3 kg (it stays 45 kg, fig. 7.14)"),
    c_z=_q(15e6, "N/m", "App. 6 listing, CZS",
           note="shaft stiffness along the follower at the roller; scan 'Czl•l 0 5!7' read "
                "1.5E7. Not printed in App. 7; with c1 it gives c_c = 3.644e6 N/m, printed "
                "3.65e6 (a two-digit 1.5E7 cannot resolve the difference)"),
    flex_tan=_q(6.365e-6, "m/N", "App. 7, A.7.2 (10)", "6.365e-6 m/N",
                "1/c_tan = 1/c_beta' + 1/c_4y' (4.4), at R_red; App. 7 prints only the sum, "
                "c_beta' is the overall stiffness of shafts (4) and (5)"),
    h_m=_q(56.2e-3, "m", "App. 7, fig. A.7.2 (App. 6 HMS=56.18E-3)", "56.2 mm",
           "stroke at the roller"),
    R_half=_q(85e-3, "m", "App. 7, fig. A.7.2 (App. 6 RGS=0.085)", "85 mm",
              "pitch radius at half the stroke (4.1)"),
    beta_m=_q(1.745, "rad", "App. 7, fig. A.7.2; fig. 7.14", "1.745 rad",
              "scan '1-71.5 rad': the scan renders 4 as '1.' (module docstring); 100 deg"),
    speed=_q(60.0, "rpm", "App. 7, fig. A.7.2; App. 6 N=3600 per hour", "60 r.p.m.",
             "w_s = 2 pi rad/s, printed"),
    s_r=_q(0.074e-3, "m", "App. 7, fig. A.7.2 (App. 6 SROLS=74.2E-6)", "0.074 mm",
           "backlash of the roller in the groove, at the roller; fig. 7.7 prints it at R_red: "
           "s_r' = 0.13 mm"),
    gear_backlash=_q(1.020e-2, "rad", "App. 6 listing, ST",
                     note="backlash of the reduction-gear teeth as a camshaft angle; scan "
                          "'Sh1 0 020E•2' read 1.020E-2.  Supported by fig. 7.7: with the "
                          "roller backlash it gives 1.276 mm at half the cam rise at R_red, "
                          "printed 1.27 mm"),
    h_m_out=_q(0.1, "m", "sec. 7.4.4", "0.1 m",
               "stroke of the output member as sec. 7.4.4 rounds it (i h_m = 98.1 mm)"),
    s_half_out=_q(1.27e-3, "m", "fig. 7.7, sec. 7.4.4", "1.27e-3 m",
                  "overall backlash at half the cam rise, at R_red (s_0.5'); fig. 7.11 "
                  "prints s'/h_m' = 1.27e-2"),
    q_linkage=_q(0.065, "1", "fig. 7.19", "0.065",
                 "q_x = q_y = q_z of the simulation of fig. 7.19; fig. 7.11 used instead "
                 "q = q0 exp(b |H' - X'|), q0 = 0.013, b = 19 (sec. 7.4.5)"),
    q_shaft=_q(0.4, "1", "fig. 7.19", "0.4", "q_beta of the simulation of fig. 7.19"),
    # squeeze films (sec. 6.5.2, 6.5.12; App. 4): only the App. 6 listing gives these
    eta_roller=_q(0.1, "Pa s", "App. 6 listing, VISRS", note="lubricant viscosity in the cam groove; "
                  "scan 'Y!SRS•Ool' read VISRS=0.1 (the listing reduces it as VISR = VISRS/IX**3, (2.59))"),
    roller_width=_q(14e-3, "m", "App. 6 listing, BROLS", note="scan 'BR0LSe14.E.3': 14 mm"),
    roller_radius=_q(15e-3, "m", "App. 6 listing, RROLS",
                     note="scan 'RROLSW15 0 1•3' read 15.E-3; R_e' = R_r' for a roller on a cam of "
                          "much larger curvature radius (6.36)"),
    eta_gear=_q(0.1, "Pa s", "App. 6 listing, VISTW", note="lubricant viscosity of the worm gear; "
                "scan 'VISTW•O.I'"),
    gear_module=_q(4e-3, "m", "App. 6 listing, MODULW", note="scan 'M0DULiol•4oE•3': 4 mm"),
    gear_teeth=_q(54, "1", "App. 6 listing, ZT",
                  note="scan 'zr•S4' read ZT=54; it gives the pitch radius m z/2 = 0.108 m that the "
                       "listing also sets ('R~•Oo108')"),
    gear_width=_q(2.7e-2, "m", "App. 6 listing, BTW", note="scan '.aTW•2.71i•2' read 2.7E-2"),
    gear_radius=_q(0.108, "m", "App. 6 listing", note="pitch radius of the worm wheel on the camshaft"),
    pressure_angle=_q(math.radians(20), "rad", "fig. 6.4; App. 6 listing",
                      note="fig. 6.4 prints alpha_n = 20 deg; the listing's 0.085 m z is "
                           "(m z sin 20 deg/2)/2 = R_e'/2 (6.4)"),
    printed={
        "c_c": Printed("3.65e6", "N/m", "App. 7, A.7.2 (5); table 7-I",
                       "1/c_c = 1/c1 + 1/c_4z' (4.3), tan alpha = 0"),
        "c_c_measured": Printed("2.75e6", "N/m", "table 7-I, fig. 7.5a"),
        "c_min_measured": Printed("0.298e6", "N/m", "table 7-I, fig. 7.5b; sec. 7.4.1.2 (7.9)"),
        "m": Printed("45", "kg", "fig. 7.14",
                     "equivalent mass (4.39); scan 'gm=45kg'.  App. 7 (6) lost the number"),
        "m2_red": Printed("5", "kg", "fig. A.7.3"),
        "T_e": Printed("2.2e-2", "s", "App. 7, A.7.2 (7), fig. A.7.3"),
        "t_m": Printed("0.278", "s", "App. 7, A.7.2 (8), fig. A.7.2"),
        "tau": Printed("0.08", "1", "App. 7, A.7.2 (9), fig. A.7.3, fig. 7.11b, fig. 7.14"),
        "tan_alpha_me": Printed("0.379", "1", "App. 7, A.7.2 (11), fig. A.7.3"),
        "Fa": Printed("3.34", "1", "App. 7, A.7.2 (12), fig. 7.11b, fig. 7.14, sec. 7.4.3",
                      "table 5-I lists the same mechanism (tau 0.08, Fv 7.5) with Fa 3.35"),
        "dip": Printed("14.4", "1", "App. 7, A.7.2 (12); sec. 7.4.4", "c_max/c_min = 1 + 4 Fa (4.19)"),
        "c_min": Printed("0.253e6", "N/m", "App. 7, A.7.2 (12); table 7-I"),
        "freq_factor": Printed("0.264", "1", "sec. 7.4.3", "1/(1 + 4 Fa)^(1/2) at T = 0.5 (4.32)"),
        "Fv": Printed("7.5", "1", "fig. A.7.3 (scan 'Fy :75'); table 5-I (0.08, 3.35, 7.5)",
                      "not reproduced: needs m_beta', m_y' (App. 6 MBS illegible)"),
        "s_r_red": Printed("0.13", "mm", "fig. 7.7", "roller backlash at R_red"),
        "frame_lower": Printed("0.25", "1", "sec. 7.4.1.2", "'the measured c_c proves to be 25% lower'"),
        "frame_ratio": Printed("3", "1", "sec. 7.4.1.2",
                               "'reduced frame stiffness being about 3 times as high as that of "
                               "the mechanism'"),
        "c_min_diff": Printed("0.15", "1", "sec. 7.4.1.2",
                              "'c_min = 0.253e6 N/m differs by only 15 %' from the measured 0.298e6"),
        # sec. 7.4.4, impact after the gear backlash
        "S": Printed("1.27e-2", "1", "fig. 7.11b caption; sec. 7.4.4", "s'/h_m' at alpha = alpha_max"),
        "r_e": Printed("0.31", "1", "sec. 7.4.4", "(3.16) with s_0.5' = 1.27e-3 m, h_m' = 0.1 m"),
        "Hd_068": Printed("1.42", "1", "sec. 7.4.4", "H' = 1 - cos 2 pi T at T = 0.68 (A.2.10)"),
        "tau_068": Printed("0.222", "1", "sec. 7.4.4", "tau_T = tau (1 + H'^2 Fa)^(1/2) (4.32)"),
        "Xdd_s0_068": Printed("-7.4", "1", "sec. 7.4.4, fig. 7.15",
                              "X'' at T = 0.68 without backlash, read from the 4-DOF DYNACAM "
                              "simulation of fig. 7.15"),
        "Xdd_068": Printed("-16.2", "1", "sec. 7.4.4", "X''_0.68 = X''_(s=0) - U_sn''"),
        "Xdd_068_fig7_11b": Printed("-14", "1", "sec. 7.4.4, fig. 7.11b",
                                    "4-DOF simulation with backlash, damping and squeeze"),
        "Xdd_068_fig7_16": Printed("-16", "1", "sec. 7.4.4, fig. 7.16",
                                   "4-DOF simulation with backlash, zero damping and viscosity"),
    },
)


SPRING_LOADED = SpringLoadedFollower(
    R_red=_q(0.175, "m", "App. 7, A.7.3.1 (1)", "175 mm",
             "position of the output member (1) on the arm (2)"),
    i=_q(2.06, "1", "App. 7, A.7.3.1 (2)", "2.06", "i = R_red/R3"),
    m1=_q(1.3, "kg", "App. 7, fig. A.7.5", "1.3 kg", "output member (1)"),
    m9=_q(0.05, "kg", "App. 7, fig. A.7.5", "0.05 kg"),
    m=_q(1.46, "kg", "App. 7, A.7.3.1 (6), A.7.3.2; fig. A.7.7", "1.46 kg",
         "equivalent follower mass (4.39)/(5.50), m = m_129 + m_4z ((1/c_z')/(1/c_c))^2; "
         "its terms are lost in the scan, so it is an input here"),
    c_c=_q(0.376e6, "N/m", "App. 7, A.7.3.1 (5)", "0.376e6 N/m",
           "1/c_c = 1/c2 + 1/c_z' (4.3); gives the printed T_e = 1.24e-2 s and tau = 0.141 "
           "(0.37e6 gives tau = 0.142)"),
    c_c_table=_q(0.37e6, "N/m", "table 7-I; fig. A.7.7; sec. 7.2", "0.37e6 N/m",
                 "the same stiffness to two digits; it reproduces the printed Fa = 2.04 and "
                 "c_min = 0.0405e6 N/m, which 0.376e6 does not (Fa 2.07)"),
    flex_tan=_q(26.14e-6, "m/N", "App. 7, A.7.3.1 (10)", "26.14e-6 m/N",
                "1/c_tan = 1/c_beta' + 1/c_4y' (4.4); c_beta' includes shaft (5), coupling (6), "
                "shaft (7) and the measured V-belt stiffness (8); its terms are lost in the scan"),
    m_tan=_q(0.116, "kg", "App. 7, A.7.3.2", "0.116 kg",
             "equivalent cam mass (5.51); its terms are lost in the scan"),
    c_vbelt=_q(0.746e6, "N/m", "fig. 7.6c", "0.746e6 N/m",
               "measured stiffness of the V-belt drive on the camshaft side at R = 75 mm"),
    h_m=_q(15e-3, "m", "App. 7, fig. A.7.5", "15 mm", "stroke at the roller"),
    R_half=_q(75e-3, "m", "App. 7, fig. A.7.5", "75 mm", "pitch radius at half the stroke (4.1)"),
    beta_m=_q(0.436, "rad", "App. 7, fig. A.7.5", "0.436 rad",
              "scan '0·1.36 rad' read 0.436 (module docstring); 25 deg"),
    speed=_q(47.5, "rpm", "App. 7, fig. A.7.5", "47.5 r.p.m.",
             "printed 'w_s = 0·495 rad/s', read 4.95 rad/s (module docstring)"),
    q_linkage=_q(0.023, "1", "sec. 7.4.5", "2.3 %",
                 "from the decay of fig. 7.17, n = 9, ratio 3.7 (7.10)"),
    q_shaft=_q(0.12, "1", "sec. 8.2.2", "12 %",
               "q_beta of the simulations of fig. 8.3; sec. 7.4.5 measures 'as high as 11 %'"),
    printed={
        "c_c": Printed("0.376e6", "N/m", "App. 7, A.7.3.1 (5)"),
        "c_c_measured": Printed("0.354e6", "N/m", "table 7-I, fig. 7.6a"),
        "m": Printed("1.46", "kg", "App. 7, A.7.3.1 (6), A.7.3.2"),
        "T_e": Printed("1.24e-2", "s", "App. 7, A.7.3.1 (7), fig. A.7.6"),
        "t_m": Printed("0.088", "s", "App. 7, A.7.3.1 (8), fig. A.7.5, fig. A.7.6; sec. 7.2"),
        "tau": Printed("0.141", "1", "App. 7, A.7.3.1 (9), fig. A.7.6, fig. 7.12, fig. 8.1b"),
        "tan_alpha_me": Printed("0.458", "1", "App. 7, A.7.3.1 (11), fig. A.7.6, fig. 8.1b"),
        "c_tan": Printed("0.0383e6", "N/m", "fig. A.7.7"),
        "Fa": Printed("2.04", "1", "App. 7, A.7.3.1 (12), fig. A.7.6, fig. 7.12, fig. 8.1b"),
        "c_min": Printed("0.0405e6", "N/m", "table 7-I (calculated, fig. A.7.6)"),
        "c_min_measured": Printed("0.0428e6", "N/m", "table 7-I, fig. 7.6b"),
        "freq_factor": Printed("0.33", "1", "sec. 7.4.3", "1/(1 + 4 Fa)^(1/2) (4.32)"),
        "m_tan": Printed("0.116", "kg", "App. 7, A.7.3.2"),
        "Fv": Printed("2.68", "1", "App. 7, A.7.3.2; fig. 8.1b; fig. 8.3b; sec. 8.2.5"),
    },
)

MECHANISMS = {"indexing": INDEXING, "spring-loaded": SPRING_LOADED}


def quantities(mech) -> dict[str, Quantity]:
    """The Quantity fields of a mechanism, by name."""
    return {f.name: getattr(mech, f.name) for f in fields(mech)
            if isinstance(getattr(mech, f.name), Quantity)}
