"""The worked examples of thesis App. 7 and the impact estimate of sec. 7.4.4.

App. 7 computes, for each mechanism of :mod:`camdyn.thesis.theory.mechanisms`, the figures that
select a response graph of ch. 4 (fig. 4.11):

    c_c       stiffness of the uncoupled follower system, 1/c_c = sum 1/c_i (4.3), (4.40)
    m         equivalent mass by Rayleigh's method with the static deflection (4.39), (5.50):
              m = sum m_i ((1/c_i')/(1/c_c))^2, 1/c_i' the flexibility between the frame and m_i
    T_e       2 pi (m/c_c)^(1/2) (4.11), (4.39)
    t_m       beta_m/w_s (App. 7 (8))
    tau       T_e/t_m (4.12)
    tan a_me  h_m'/(R_1/2' beta_m) (4.13)
    c_tan     1/c_tan = 1/c_beta' + 1/c_y' (4.4)
    Fa        (c_c/c_tan) tan^2 a_me (4.14)
    dip       c_max/c_min = 1 + 4 Fa (4.19), c_min = c_c/dip
    m_tan     (5.51), Fv = (m/m_tan) tan^2 a_me (5.52) = m_x h_m^2/(J beta_m^2) (5.14b)

All functions work in SI units.  Where the thesis carries a *rounded* intermediate result
into the next step, :func:`impact_as_printed` and the checks say so; :func:`indexing_figures`,
:func:`follower_figures` and :func:`impact_estimate` carry full precision.

Sec. 7.4.4 (impact after the gear backlash of the indexing mechanism) combines
    r_e from (3.16) with S = s_0.5'/h_m',
    the instantaneous period tau_T = tau (1 + H'_T^2 Fa)^(1/2) from (4.32) at T = 0.68,
    U_sn'' = 2 pi r_e/tau_T (3.12), and
    X''_0.68 = X''_(s=0) - U_sn'',
where X''_(s=0) = -7.4 is read from the 4-DOF simulation without backlash (fig. 7.15).  Only
that last number needs a model beyond this module: the thesis takes it from DYNACAM.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .mechanisms import INDEXING, SPRING_LOADED, IndexingMechanism, SpringLoadedFollower, omega


# -- the formulas --------------------------------------------------------------------------------
def series(*stiffnesses: float) -> float:
    """Overall stiffness of springs in series, 1/c = sum 1/c_i (4.3), (4.4), (4.40)."""
    return 1.0 / sum(1.0 / c for c in stiffnesses)


def reduce_mass(m: float, i: float) -> float:
    """Mass at a point that moves 1/i times the output, reduced to the output: m/i^2 (sec. 2.4)."""
    return m / i**2


def reduce_stiffness(c: float, i: float) -> float:
    """Stiffness reduced to the output member, c/i^2 (sec. 2.4)."""
    return c / i**2


def equivalent_mass(terms, c_c: float) -> float:
    """Equivalent mass (4.39), (5.50): sum of m_i ((1/c_i')/(1/c_c))^2 over (m_i, c_i') pairs, c_i'
    the stiffness between the frame and m_i (None: m_i moves with the full deflection)."""
    return sum(m if c is None else m * (c_c / c) ** 2 for m, c in terms)


def natural_period(m: float, c: float) -> float:
    """T_e = 2 pi (m/c)^(1/2) (4.11), (4.39)."""
    return 2 * math.pi * math.sqrt(m / c)


def rise_time(beta_m: float, w_s: float) -> float:
    """t_m = beta_m/w_s (App. 7 (8))."""
    return beta_m / w_s


def mean_slope(h_m: float, R_half: float, beta_m: float) -> float:
    """tan alpha_me = h_m'/(R_1/2' beta_m) (4.13); the ratio is the same at the roller and reduced."""
    return h_m / (R_half * beta_m)


def shaft_factor(c_c: float, c_tan: float, tan_me: float) -> float:
    """Shaft stiffness factor Fa = (c_c/c_tan) tan^2 alpha_me (4.14)."""
    return c_c / c_tan * tan_me**2


def stiffness_dip(Fa: float, Hd_max: float = 2.0) -> float:
    """c_max/c_min = 1 + H'max^2 Fa, 1 + 4 Fa for the cycloid (4.18), (4.19)."""
    return 1 + Hd_max**2 * Fa


def frequency_factor(Fa: float, Hd: float = 2.0) -> float:
    """w_eT/w_e = (1 + H'^2 Fa)^(-1/2) (4.32); at T = 0.5 of the cycloid H' = 2."""
    return 1 / math.sqrt(1 + Hd**2 * Fa)


def tau_at(tau: float, Fa: float, Hd: float) -> float:
    """Instantaneous tau_T = tau (1 + H'^2 Fa)^(1/2) (4.32), sec. 7.4.4."""
    return tau * math.sqrt(1 + Hd**2 * Fa)


def tangential_mass(terms, c_tan: float) -> float:
    """Equivalent cam mass (5.51): sum m_j ((1/c_j')/(1/c_tan))^2 over (m_beta', c_beta'),
    (m_y', c_y')."""
    return sum(m * (c_tan / c) ** 2 for m, c in terms)


def flywheel_factor(m: float, m_tan: float, tan_me: float) -> float:
    """Fv = (m/m_tan) tan^2 alpha_me (5.52)."""
    return m / m_tan * tan_me**2


def flywheel_factor_J(m_x: float, h_m: float, J: float, beta_m: float) -> float:
    """Fv = m_x h_m^2/(J beta_m^2) (5.14b), h_m the stroke at the cam (same point as m_x)."""
    return m_x * h_m**2 / (J * beta_m**2)


def cycloid_velocity(T: float) -> float:
    """H' = 1 - cos 2 pi T (A.2.10)."""
    return 1 - math.cos(2 * math.pi * T)


def backlash_at_half_rise(s_r: float, gear: float, h_m: float, beta_m: float, i: float,
                          Hd: float = 2.0) -> float:
    """Overall backlash at R_red at half the cam rise (fig. 7.7): i (s_r + phi dh/dbeta).

    Reading taken: the gear backlash phi (an angle of the camshaft) moves the roller by
    phi dh/dbeta = phi H' h_m/beta_m, with H' = 2 at half the rise of the cycloid (A.2.10); the
    roller backlash adds at the roller; both are reduced to R_red by i.
    """
    return i * (s_r + gear * Hd * h_m / beta_m)


# -- the two mechanisms --------------------------------------------------------------------------
@dataclass(frozen=True)
class Figures:
    """What App. 7 computes for a mechanism (SI units), full precision."""

    c_c: float
    m: float
    T_e: float
    t_m: float
    tau: float
    tan_alpha_me: float
    c_tan: float
    Fa: float
    dip: float
    c_min: float
    freq_factor: float
    m_tan: float | None = None
    Fv: float | None = None


def _common(c_c, m, beta_m, w_s, h_m, R_half, flex_tan, m_tan=None) -> Figures:
    T_e = natural_period(m, c_c)
    t_m = rise_time(beta_m, w_s)
    tan_me = mean_slope(h_m, R_half, beta_m)
    c_tan = 1.0 / flex_tan
    Fa = shaft_factor(c_c, c_tan, tan_me)
    dip = stiffness_dip(Fa)
    return Figures(c_c=c_c, m=m, T_e=T_e, t_m=t_m, tau=T_e / t_m, tan_alpha_me=tan_me,
                   c_tan=c_tan, Fa=Fa, dip=dip, c_min=c_c / dip, freq_factor=frequency_factor(Fa),
                   m_tan=m_tan, Fv=None if m_tan is None else flywheel_factor(m, m_tan, tan_me))


def indexing_c_c(mech: IndexingMechanism = INDEXING) -> float:
    """c_c of the indexing mechanism from c1 and the App. 6 reading of c_4z (4.3), 3.644e6 N/m."""
    i = mech.i.value
    return series(mech.c1.value, reduce_stiffness(mech.c_z.value, i))


def indexing_mass(mech: IndexingMechanism = INDEXING, c_c: float | None = None,
                  with_cam_mass: bool = True) -> float:
    """Equivalent mass (4.39) of the indexing mechanism at R_red.

    m1 moves with the full static deflection; m2 (at the rollers) and the cam mass m_z move
    with the deflection of the cam shaft along the follower, c_4z'.  c_4z' is taken from the
    printed c_c and c1 by (4.3) (1/c_4z' = 1/c_c - 1/c1), which keeps the chain at the printed
    c_c; App. 6's 1.5E7 agrees to 0.2 %.  with_cam_mass=False leaves out the App. 6 reading
    of m_z (44.7 kg instead of 45.0 kg).
    """
    i = mech.i.value
    c_c = float(mech.printed["c_c"].text) if c_c is None else c_c
    c_4z = 1.0 / (1.0 / c_c - 1.0 / mech.c1.value)
    m_roller = reduce_mass(mech.m2.value + (mech.m_z.value if with_cam_mass else 0.0), i)
    return equivalent_mass([(mech.m1.value, None), (m_roller, c_4z)], c_c)


def indexing_figures(mech: IndexingMechanism = INDEXING) -> Figures:
    """App. 7, A.7.2, with the printed c_c = 3.65e6 N/m (the value App. 7 carries on)."""
    c_c = float(mech.printed["c_c"].text)
    return _common(c_c, indexing_mass(mech, c_c), mech.beta_m.value, omega(mech.speed),
                   mech.h_m.value, mech.R_half.value, mech.flex_tan.value)


def follower_figures(mech: SpringLoadedFollower = SPRING_LOADED, c_c: float | None = None) -> Figures:
    """App. 7, A.7.3, with c_c = 0.376e6 N/m (A.7.3.1 (5)) unless another c_c is given.

    The printed tau = 0.141 follows from 0.376e6 N/m (0.37e6 gives 0.142); the printed
    Fa = 2.04 and c_min = 0.0405e6 N/m follow from the 0.37e6 N/m of table 7-I and fig. A.7.7
    (``c_c=SPRING_LOADED.c_c_table.value``); 0.376e6 gives Fa = 2.07.
    """
    c_c = mech.c_c.value if c_c is None else c_c
    return _common(c_c, mech.m.value, mech.beta_m.value, omega(mech.speed), mech.h_m.value,
                   mech.R_half.value, mech.flex_tan.value, m_tan=mech.m_tan.value)


def indexing_backlash(mech: IndexingMechanism = INDEXING) -> float:
    """Overall backlash at half the cam rise at R_red (fig. 7.7) from the roller backlash and the
    App. 6 gear backlash, in m."""
    return backlash_at_half_rise(mech.s_r.value, mech.gear_backlash.value, mech.h_m.value,
                                 mech.beta_m.value, mech.i.value)


# -- sec. 7.4.4 ----------------------------------------------------------------------------------
@dataclass(frozen=True)
class ImpactEstimate:
    """Van der Hoek's estimate of the deceleration after the impact (sec. 7.4.4)."""

    S: float
    """Relative backlash s'/h_m'."""
    r_e: float
    """Relative impact speed (3.16)."""
    T: float
    Hd: float
    """Nominal velocity H' at T (A.2.10)."""
    tau_T: float
    """Instantaneous tau at T (4.32)."""
    Udd_sn: float
    """Impact acceleration amplitude (3.12) with tau_T."""
    Xdd_s0: float
    """Acceleration at T without backlash (from a simulation: fig. 7.15 in the thesis)."""

    @property
    def Xdd(self) -> float:
        """X''_T = X''_(s=0) - U_sn'': the impact deceleration superposed (sec. 7.4.4)."""
        return self.Xdd_s0 - self.Udd_sn


def impact_estimate(S: float, tau: float, Fa: float, Xdd_s0: float, T: float = 0.68,
                    H3: float = 4 * math.pi**2) -> ImpactEstimate:
    """Sec. 7.4.4 at full precision: r_e (3.16), tau_T (4.32), U_sn'' (3.12), X''_T."""
    from . import impact    # SymPy's: imported where used, so that `camdyn design` starts fast

    r_e = impact.r_e_from_backlash(S, H3)
    Hd = cycloid_velocity(T)
    tau_T = tau_at(tau, Fa, Hd)
    return ImpactEstimate(S=S, r_e=r_e, T=T, Hd=Hd, tau_T=tau_T,
                          Udd_sn=impact.Udd_sn(r_e, tau_T), Xdd_s0=Xdd_s0)


def indexing_impact(mech: IndexingMechanism = INDEXING, Xdd_s0: float | None = None) -> ImpactEstimate:
    """Sec. 7.4.4 from the mechanism data with the thesis's inputs s_0.5' = 1.27e-3 m,
    h_m' = 0.1 m, tau = 0.08, Fa = 3.34 and X''_(s=0) = -7.4 (fig. 7.15) unless given."""
    p = mech.printed
    S = mech.s_half_out.value / mech.h_m_out.value
    x0 = float(p["Xdd_s0_068"].text) if Xdd_s0 is None else Xdd_s0
    return impact_estimate(S, float(p["tau"].text), float(p["Fa"].text), x0)


def impact_as_printed(mech: IndexingMechanism = INDEXING) -> dict[str, float]:
    """The chain of sec. 7.4.4 as the thesis evaluates it, each step from the *printed* result
    of the step before: H'_0.68 = 1.42 (truncated from 1.426) into tau_0.68, r_e = 0.31 and
    tau_0.68 = 0.222 into U_sn''."""
    p = mech.printed
    tau, Fa = float(p["tau"].text), float(p["Fa"].text)
    tau_T = tau_at(tau, Fa, float(p["Hd_068"].text))
    from . import impact

    Udd = impact.Udd_sn(float(p["r_e"].text), float(p["tau_068"].text))
    return {"tau_068": tau_T, "Udd_sn": Udd, "Xdd_068": float(p["Xdd_s0_068"].text) - Udd}


def contact_ratio_rack(z: float, alpha: float) -> float:
    """Contact ratio of a gear of z standard teeth (addendum = module) meshing with a rack,
    the worm's axial section: the path of contact over the base pitch, pi m cos alpha.  The
    App. 6 listing evaluates the same expression (EPS, for the contact ratio of (6.3))."""
    path_wheel = math.sqrt((z / 2 + 1) ** 2 - (z / 2 * math.cos(alpha)) ** 2) - z / 2 * math.sin(alpha)
    path_rack = 1 / math.sin(alpha)
    return (path_wheel + path_rack) / (math.pi * math.cos(alpha))


def gear_squeeze_coefficient(eta: float, eps: float, b: float, R_e: float, R: float) -> float:
    """V_T of the generated model, so that the torque the gear film passes is
    M = V_T (phi' - phi_r') gap^(-3/2) (gap in rad): (6.5), (6.6) with the teeth at the pitch
    radius R of the wheel, V_T = 12 pi eta eps b (R_e/2)^(3/2) R^(1/2).  (Reducing everything
    to R_b' first by (2.59), as the thesis does, gives the same number.)"""
    return 12 * math.pi * eta * eps * b * (R_e / 2) ** 1.5 * math.sqrt(R)


def roller_squeeze_coefficient(eta: float, b: float, R_r: float) -> float:
    """V_R = 12 pi eta' b' (R_r'/2)^(3/2) (6.38), reduced magnitudes, so that the roller film
    passes F_x = V_R (h_c' - h_r') gap^(-3/2) (6.37)."""
    return 12 * math.pi * eta * b * (R_r / 2) ** 1.5


def indexing_squeeze(mech: IndexingMechanism = INDEXING) -> dict[str, float]:
    """The squeeze coefficients of the indexing mechanism from the App. 6 data, reduced to the
    output member (roller: lengths times i, viscosity over i^3, (2.55), (2.59))."""
    i = mech.i.value
    alpha = mech.pressure_angle.value
    z, m_t = mech.gear_teeth.value, mech.gear_module.value
    eps = contact_ratio_rack(z, alpha)
    R_e = m_t * z * math.sin(alpha) / 2          # (6.4)
    V_T = gear_squeeze_coefficient(mech.eta_gear.value, eps, mech.gear_width.value, R_e,
                                   mech.gear_radius.value)
    V_R = roller_squeeze_coefficient(mech.eta_roller.value / i**3, i * mech.roller_width.value,
                                     i * mech.roller_radius.value)
    return {"eps": eps, "R_e": R_e, "V_T": V_T, "V_R": V_R}

