"""The asynchronous motor and the worm gear: thesis App. 5, sec. 6.7 and sec. 8.3.

The generated models ``motor2`` and ``motor1`` (camdyn/derive/models/motor.py)
integrate the motor equations; this module holds the theory they are checked
against: the motor constants, the equations written as the thesis writes them,
the analytic solutions (A.5.25) and (A.5.33) as printed (readings below), their
symbolic derivation, the slip graph of fig. 8.6, the motor selection rules
(8.1)-(8.4) and the worm-gear efficiency (6.71)-(6.72).  The printed solutions are
typed in, not derived from the models, so that comparing the two can fail.

Notation (SI; reduced magnitudes carry the index a, "at the camshaft")
    w_mains   angular frequency of the mains, 2 pi 50 s^-1 (the thesis's motors)
    p         number of pole pairs; w_mains/p is the synchronous motor speed
    i_r       reduction ratio w/w_m < 1 (sec. A.5.3); w_s = i_r w_mains/p is the
              synchronous camshaft speed
    M_en, N_n, delta_n   rated torque, rated power, rated slip (index n, (8.3))
    delta_k, M_k         critical (breakdown) slip and torque (A.5.3), (A.5.4a)
    G, G_a    slope of the linearised torque-speed line, motor shaft / camshaft
    J_m, J_ma polar moment of inertia of the motor, motor shaft / camshaft
    T_el, T_m electrical (A.5.3) and mechanical (A.5.11) time constants
    tau_el = T_el/t_m, tau_m = T_m/t_m (A.5.24), T = t/t_m
    dw = w - w_s  speed deviation of the camshaft; slip delta = -dw/w_s
    Mc = m h_m'^2/(w_s t_m^3): torque scale of the nominal motion (A.2.7)
    P = M_ena/M_max: ratio of overdimensioning (A.5.15)

Thesis formulas and where they live
    (A.5.1), (A.5.2)       torque-speed slope G_p at P, electrical lag -> :func:`electromagnetic_torque`
    (A.5.3)                T_el = 1/(delta_k w_mains)        -> :func:`electrical_time_constant`
    (A.5.4a)               slope at zero torque              -> :func:`slope_at_zero_torque`
    (A.5.4b), (A.5.4c)     G from rated torque / power       -> :func:`slope_rated`, :func:`slope_from_power`
    (A.5.6), (A.5.7)       reduction, G_a = G/i_r^2, J_ma = J_m/i_r^2 -> :func:`reduce_to_camshaft`
    (A.5.10), (A.5.13)     second-order equation             -> :func:`equation_A5_10`, :func:`equation_A5_13`
    (A.5.11), (A.5.12)     T_m = J_m/G = J_m delta_n w_mains^2/(N_n p^2) -> :func:`mechanical_time_constant`
    (A.5.14), (A.5.17)     q = (1/2) sqrt(T_m/T_el), w_e^2 = 1/(T_el T_m) -> :func:`relative_damping`
    (A.2.12)-(A.2.14), (A.5.15)  the load 4 M_max/3^(3/2) (sin 2 pi T - sin 4 pi T/2),
                           M_max = (3^(3/2) pi/2) Mc          -> :data:`M_MAX_FACTOR`, :func:`load_printed`
    (A.5.16)               right-hand side with w_s delta_n/T_m -> :func:`equation_A5_16_prefactor`
    (A.5.18)-(A.5.25)      second-order solution             -> :data:`A5_25`, :func:`speed_second_order`
    (A.5.26)-(A.5.33)      first-order solution              -> :data:`A5_33`, :func:`speed_first_order`
                           (in NumPy, with the functions below down to (8.4) and
                           worm_gear_efficiency: :mod:`.motor_rules`)
    the same, derived again with SymPy                       -> :func:`derive_second_order`,
                                                                :func:`derive_first_order`
    both in SI for the generated models                      -> :func:`speed_deviation`
    fig. 8.6               peak slip against tau_m            -> :func:`relative_slip_peak`
    (8.1)-(8.4)            motor selection                    -> :func:`required_overdimensioning`,
                           :func:`required_torque`, :func:`required_power`, :func:`slip_within_rated`
    (6.71), (6.72), (A.5.34)  worm gear                       -> :func:`worm_gear_torque`,
                           :func:`worm_gear_efficiency`, :func:`worm_force_ratio`

Readings taken where the scan is garbled
    (A.5.3)   "T_el = 1/(delta_k w_mains)": the fraction bar and the two factors are
              legible; 1/(0.37 * 2 pi 50) = 8.60e-3 s reproduces the printed value.
    (A.5.4a)  lost.  Reading: Kloss's formula M_e = 2 M_k/(delta/delta_k + delta_k/delta)
              near delta = 0, slope 2 M_k p/(delta_k w_mains); the text only calls it
              "the slope of the tangent OK at 0".
    (A.5.4b)  "dM_e/dw_m = -G = -M_en p/(delta_n w_mains)" (legible), (A.5.4c) with
              N_n = M_en w_mains/p (the text: "nearly equal to").
    (A.5.6)   M_ea = -G_a dw/(1 + T_el D) (the thesis's D = d/dt), (A.5.7)
              J_ma D dw = M_ea - M_ma, M_ma the load torque reduced to the camshaft.
    (A.5.10)  "T_el J_m D^2 dw + J_m D dw + G dw = -i_r^2 M_ma (1 + T_el D)": legible;
              it is the reduced equation multiplied by i_r^2, so J_m, G belong to the motor
              shaft while dw and M_ma are at the camshaft.
    (A.5.11)  lost; T_m = J_m/G follows from (A.5.13) (1/(T_el T_m) multiplies dw) and
              (A.5.12), whose fig. A.5.3 version "T_m = J_m delta_n w_mains^2/(N_n p^2)"
              is half legible.
    (A.5.15), (A.5.16), (A.5.27)  the factor printed "3312" is 3^(3/2): with
              M_max = 3^(3/2) pi/2 Mc (A.2.14, legible) the cycloid's load 2 pi Mc
              (sin 2 pi T - 1/2 sin 4 pi T) is 4 M_max/3^(3/2) (...).
    (A.5.24)  lost; tau_el = T_el/t_m, tau_m = T_m/t_m, T = t/t_m as the captions of
              figs A.5.6, A.5.7 use them (tau_m = 0.113/0.088 = 1.284, tau_e = 9.77e-2).
    (A.5.25)  dw/w_s = 4 delta_n/(tau_el tau_m 3^(3/2) P) {exp(-T/(2 tau_el)) [A' exp(s T)
              + B' exp(-s T)] + C' sin 2 pi T + D' sin 4 pi T + E' cos 2 pi T + F' cos 4 pi T},
              s = ((q^2 - 1)/(tau_el tau_m))^(1/2).  The scan does not show where the
              braces close; the prefactor must multiply the whole bracket: only then do
              the printed C'..F' satisfy (A.5.16) (checked symbolically, and the quasi-static
              limit tau -> 0 gives the static slip delta_n/P at peak torque).  C', D', E', F'
              as printed; A', B' as printed up to the sign of their first term
              (A' = -[...]/(2 s) - (E' + F')/2, B' = +[...]/(2 s) - (E' + F')/2), which the
              initial conditions (A.5.21) fix.
    (A.5.33)  dw/w_s = 4 delta_n/(tau_m 3^(3/2) P) [A' exp(-T/tau_m) + B' sin 2 pi T
              + C' sin 4 pi T + D' cos 2 pi T + E' cos 4 pi T], coefficients all legible.
    After the rise (T > 1) the thesis gives no formula ((A.5.19), (A.5.29) hold "within
    0 <= t <= t_m"); the load vanishes with its derivative at T = 1, so the motor decays
    freely from the state it has at T = 1: :func:`speed_second_order`,
    :func:`speed_first_order` continue with the homogeneous solution.
    q <= 1: the thesis writes (A.5.18) for q > 1 only; the printed form stays valid with
    an imaginary s (complex arithmetic, real result), except at q = 1 exactly.  The
    750 r.p.m. motor of fig. A.5.3 (T_m = 0.0321 s) has q = 0.97 in fact, against the
    text's "q > 1" for all of them.
    Numerically, exp(-T/(2 tau_el)) exp(+-s T) is evaluated as exp(r T) with the roots
    r = -1/(2 tau_el) +- s of (A.5.18), the same function without overflow for small tau_el.
    Fig. 8.6: only the caption survives.  Reading: the peak of the slip during the
    cycle, relative to the rated slip, delta_max/delta_n at P = 1 (the graph "has been
    drawn for P = 1"; the slip is proportional to delta_n by (A.5.33)), from the
    first-order solution (A.5.33) as sec. 8.3 says.
    (8.1)-(8.4): only fragments survive, reading in :func:`required_overdimensioning`
    and the functions after it.
    (6.71), (6.72): driving F_out = F_in/tan(alpha + mu) is legible, the driven case is
    lost; from the force balance on the helix with the friction force reversed,
    F_out = F_in/tan(alpha - mu) (:func:`worm_force_ratio`); with F_in' = F_in/tan alpha
    this gives (6.72) with tan(alpha + mu) for M_ma > 0 and tan(alpha - mu) for M_ma < 0.
"""
from __future__ import annotations

import cmath
import math
from functools import lru_cache

import numpy as np
import sympy as sp

from . import motor_rules as _rules
# the numeric half, without SymPy (what camdyn design needs), offered here under this name too
from .motor_rules import (M_MAX, required_power, required_torque, slip_within_rated,  # noqa: F401
                          speed_first_order, worm_gear_efficiency)

# --------------------------------------------------------------------- thesis data

MAINS_FREQUENCY = 50.0
"""Hz; the thesis's synchronous speeds 3000/1500/1000/750 r.p.m. are 50 Hz with p = 1..4."""

THESIS = {
    "T_el": 8.6e-3,            # s, (A.5.3) with the measured critical slip
    "delta_k": 0.37,           # critical slip, measured (fig. A.5.4)
    "delta_k_habiger": 0.59,   # critical slip by Habiger's method (sec. A.5.4.1.2)
    "T_m": {3000: 0.113, 1500: 0.0398, 1000: 0.0392, 750: 0.0321},  # s, fig. A.5.3
    "q_3000": 1.8,             # (A.5.14) for the 3000 r.p.m. motor
    "M_en": 1.29,              # N m, rated torque of the test motor (fig. A.5.4, "129")
    "N_n": 370.0,              # W, its rated power (fig. A.5.4)
    "delta_n": 0.085,          # rated slip (figs A.5.3, A.5.7)
    "p_3000": 1,
    "t_m": 0.088,              # s, cam rise time of the test mechanism (fig. A.5.6)
    "tau_m": 1.284,            # fig. A.5.6, A.5.7
    "tau_el": 9.77e-2,         # fig. A.5.7 ("T_e = 9.77e-2")
    "P": 5.2,                  # ratio of overdimensioning (fig. A.5.6, A.5.7)
    "slip_measured": 0.016,    # max slip, measured (fig. A.5.6)
    "slip_simulated": 0.018,   # max slip, DYNACAM curve (1) of fig. A.5.7
    "spring_factor": 4.5,      # curves (1)/(3) of fig. A.5.7 (sec. A.5.4.3.3)
    "torque_factor": 3.3,      # max torque with/without spring (sec. A.5.4.3.3)
    "analytic_factor": 1.3,    # curve (6) against (5) (sec. A.5.4.3.5)
    "v_v": (1, 5),             # (8.1): without/with follower spring
    "M_max_factor": 8.2,       # (8.2)
    "alpha": 0.36,             # rad, worm helix (sec. A.5.4.3.2)
    "mu": 0.05,                # rad, angle of friction
    "eta_g": 0.87,             # (A.5.34)
    "J_rotor": 40e-3,          # kg m^2, fig. A.5.8
    "J_pulley_small": 0.14e-3,  # kg m^2, fig. A.5.8
    "J_pulley_big": 60e-3,     # kg m^2, fig. A.5.8, before reduction by 2.73
    "pulley_ratio": 2.73,
    "J_pulley_reduced": 8e-3,  # kg m^2, fig. A.5.8
    "J_total": 48e-3,          # kg m^2, fig. A.5.8
    "inertia_factor": 1.2,     # sec. A.5.4.3.1
}
"""Numbers of App. 5, sec. 6.7 and sec. 8.3 as printed."""

W_MAINS = 2 * math.pi * MAINS_FREQUENCY

# --------------------------------------------------------------------------- symbols

t, t_m = sp.symbols("t t_m", positive=True)
T = sp.Symbol("T", real=True)
Dop = sp.Symbol("D")
"""The thesis's operator D = d/dt (eqs (A.5.2), (A.5.10))."""
J_m, J_ma, G, G_a, i_r = sp.symbols("J_m J_ma G G_a i_r", positive=True)
T_el, T_m, tau_el, tau_m = sp.symbols("T_el T_m tau_el tau_m", positive=True)
M_en, M_ena, N_n, p, delta_n, delta_k, M_k = sp.symbols(
    "M_en M_ena N_n p delta_n delta_k M_k", positive=True)
w_mains, w_s, w_m = sp.symbols("w_mains w_s w_m", positive=True)
Mc, P = sp.symbols("Mc P", positive=True)
s_ = sp.Symbol("s")
"""s = ((q^2 - 1)/(tau_el tau_m))^(1/2) of (A.5.25): real for q > 1, imaginary for q < 1."""
alpha, mu = sp.symbols("alpha mu", positive=True)

pi = sp.pi

# --------------------------------------------------------------------- motor constants


def electrical_time_constant(delta_k: float, w_mains: float = W_MAINS) -> float:
    """T_el = 1/(delta_k w_mains) (A.5.3)."""
    return 1.0 / (delta_k * w_mains)


def slope_at_zero_torque(M_k: float, delta_k: float, p: int, w_mains: float = W_MAINS) -> float:
    """-dM_e/dw_m at M_e = 0: 2 M_k p/(delta_k w_mains) (A.5.4a, reading: Kloss's formula)."""
    return 2.0 * M_k * p / (delta_k * w_mains)


def slope_rated(M_en: float, delta_n: float, p: int, w_mains: float = W_MAINS) -> float:
    """G = M_en p/(delta_n w_mains): the line ON from zero to rated torque (A.5.4b)."""
    return M_en * p / (delta_n * w_mains)


def slope_from_power(N_n: float, delta_n: float, p: int, w_mains: float = W_MAINS) -> float:
    """G = N_n p^2/(delta_n w_mains^2) (A.5.4c), with N_n ~ M_en w_mains/p."""
    return N_n * p**2 / (delta_n * w_mains**2)


def reduce_to_camshaft(G: float, J_m: float, i_r: float) -> tuple[float, float]:
    """(G_a, J_ma) = (G/i_r^2, J_m/i_r^2), i_r = w/w_m < 1 (sec. A.5.3, (A.5.6), (A.5.7))."""
    return G / i_r**2, J_m / i_r**2


def mechanical_time_constant(J_m: float, G: float) -> float:
    """T_m = J_m/G (A.5.11); the same for reduced magnitudes, J_ma/G_a."""
    return J_m / G


def mechanical_time_constant_catalogue(J_m: float, N_n: float, delta_n: float, p: int,
                                       w_mains: float = W_MAINS) -> float:
    """T_m = J_m delta_n w_mains^2/(N_n p^2) (A.5.12, fig. A.5.3): from catalogue data."""
    return J_m * delta_n * w_mains**2 / (N_n * p**2)


def relative_damping(T_m: float, T_el: float) -> float:
    """q = (1/2) (T_m/T_el)^(1/2) of the second-order motor (A.5.14)."""
    return 0.5 * math.sqrt(T_m / T_el)


def natural_frequency(T_m: float, T_el: float) -> float:
    """w_e = (T_el T_m)^(-1/2) (A.5.17)."""
    return 1.0 / math.sqrt(T_el * T_m)


def electromagnetic_torque(dw, G_p, T_el):
    """M_e/dw = -G_p/(1 + T_el D) (A.5.2) as a SymPy expression in the operator D."""
    return -G_p * dw / (1 + T_el * Dop)


# --------------------------------------------------------------------- the load

M_MAX_FACTOR = 3 * sp.sqrt(3) * pi / 2
"""M_max/Mc of the cycloid, at T = 1/3 (A.2.14); 8.162, printed 8.2 in (8.2) (its value
motor_rules.M_MAX)."""


def load_nominal() -> sp.Expr:
    """M_ma/Mc = H'(T) H''(T) of the cycloid (A.2.7), (A.2.11): the load of motor1/motor2."""
    return (1 - sp.cos(2 * pi * T)) * 2 * pi * sp.sin(2 * pi * T)


def load_printed() -> sp.Expr:
    """M_ma = 4 M_ena/(3^(3/2) P) (sin 2 pi T - 1/2 sin 4 pi T) (A.5.15), in units of Mc.

    With P = M_ena/M_max, M_ena/P = M_max = M_MAX_FACTOR Mc.
    """
    return 4 * M_MAX_FACTOR / 3 ** sp.Rational(3, 2) * (sp.sin(2 * pi * T) - sp.sin(4 * pi * T) / 2)


def forcing() -> sp.Expr:
    """f(T) = sin 2 pi T - 1/2 sin 4 pi T, the shape of the load in (A.5.15)-(A.5.33)."""
    return sp.sin(2 * pi * T) - sp.sin(4 * pi * T) / 2


# --------------------------------------------------------------------- the equations


def equation_A5_10() -> tuple[sp.Expr, sp.Expr]:
    """(derived, printed) left minus right side of (A.5.10), both zero on solutions.

    Derived: M_ea from (A.5.7), J_ma dw' = M_ea - M_ma, put into (A.5.6),
    T_el M_ea' + M_ea = -G_a dw, then multiplied by i_r^2 (J_m = i_r^2 J_ma, G = i_r^2 G_a).
    """
    dw = sp.Function("dw")(t)
    M_ma = sp.Function("M_ma")(t)
    M_ea = J_ma * dw.diff(t) + M_ma                       # (A.5.7)
    a5_6 = T_el * M_ea.diff(t) + M_ea + G_a * dw          # (A.5.6), = 0
    derived = sp.expand(i_r**2 * a5_6).subs({J_ma: J_m / i_r**2, G_a: G / i_r**2})
    printed = (T_el * J_m * dw.diff(t, 2) + J_m * dw.diff(t) + G * dw
               + i_r**2 * (M_ma + T_el * M_ma.diff(t)))
    return sp.expand(derived), printed


def equation_A5_13() -> sp.Expr:
    """(A.5.13): D^2 dw + D dw/T_el + dw/(T_el T_m) + i_r^2 M_ma (1 + T_el D)/(T_el J_m), = 0.

    It is (A.5.10) divided by T_el J_m with T_m = J_m/G (A.5.11).
    """
    dw = sp.Function("dw")(t)
    M_ma = sp.Function("M_ma")(t)
    return (dw.diff(t, 2) + dw.diff(t) / T_el + dw / (T_el * T_m)
            + i_r**2 * (M_ma + T_el * M_ma.diff(t)) / (T_el * J_m))


def equation_A5_16_prefactor() -> tuple[sp.Expr, sp.Expr]:
    """(from (A.5.15), printed (A.5.16)) factors of the bracket on the right-hand side.

    (A.5.15): 4 i_r^2 M_ena/(T_el J_m 3^(3/2) P); (A.5.16): 4 w_s delta_n/(T_el T_m 3^(3/2) P),
    after w_s = i_r w_mains/p, M_ena = M_en/i_r, G = M_en p/(delta_n w_mains) (A.5.4b),
    T_m = J_m/G (A.5.11).
    """
    c = 4 / (3 ** sp.Rational(3, 2) * P)
    a5_15 = c * i_r**2 * M_ena / (T_el * J_m)
    a5_16 = c * w_s * delta_n / (T_el * T_m)
    subs = {M_ena: M_en / i_r, w_s: i_r * w_mains / p,
            T_m: J_m / (M_en * p / (delta_n * w_mains))}
    return a5_15.subs(subs), a5_16.subs(subs)


# -------------------------------------------------- the analytic solutions as printed


def _printed_A5_25() -> dict:
    e = tau_el
    m = tau_m
    a0 = -4 * pi**2 + 1 / (e * m)
    a1 = -16 * pi**2 + 1 / (e * m)
    den0 = (2 * pi / e) ** 2 + a0**2
    den1 = (4 * pi / e) ** 2 + a1**2
    C = (-1 / (e * m)) / den0
    D = (1 / (2 * e * m)) / den1
    E = (2 * pi / e - 2 * pi * e * a0) / den0
    F = (-2 * pi / e + 2 * pi * e * a1) / den1
    A, B = A5_25_AB(C, D, E, F)
    return {"A": A, "B": B, "C": C, "D": D, "E": E, "F": F}


def A5_25_AB(C, D, E, F) -> tuple:
    """A', B' of (A.5.25) as printed, in terms of C'..F' (reading of the signs in the module docstring)."""
    bracket = 2 * pi * C + 4 * pi * D + (E + F) / (2 * tau_el)
    return -bracket / (2 * s_) - (E + F) / 2, bracket / (2 * s_) - (E + F) / 2


A5_25 = _printed_A5_25()
"""Coefficients A'..F' of (A.5.25) as printed (reading in the module docstring),
in tau_el, tau_m and s = ((q^2 - 1)/(tau_el tau_m))^(1/2)."""

S_OF_TAU = sp.sqrt((tau_m / (4 * tau_el) - 1) / (tau_el * tau_m))
"""s of (A.5.25) with q^2 = tau_m/(4 tau_el) (A.5.14)."""


def bracket_A5_25(coefficients: dict | None = None) -> sp.Expr:
    """The bracket of (A.5.25): dw/w_s = 4 delta_n/(tau_el tau_m 3^(3/2) P) times this, 0 <= T <= 1."""
    c = A5_25 if coefficients is None else coefficients
    return (sp.exp(-T / (2 * tau_el)) * (c["A"] * sp.exp(s_ * T) + c["B"] * sp.exp(-s_ * T))
            + c["C"] * sp.sin(2 * pi * T) + c["D"] * sp.sin(4 * pi * T)
            + c["E"] * sp.cos(2 * pi * T) + c["F"] * sp.cos(4 * pi * T))


def _printed_A5_33() -> dict:
    m = tau_m
    B = -m / ((2 * pi * m) ** 2 + 1)
    C = (m / 2) / ((4 * pi * m) ** 2 + 1)
    D = 2 * pi * m**2 / ((2 * pi * m) ** 2 + 1)
    E = -2 * pi * m**2 / ((4 * pi * m) ** 2 + 1)
    A = -2 * pi * m**2 / ((2 * pi * m) ** 2 + 1) + 2 * pi * m**2 / ((4 * pi * m) ** 2 + 1)
    return {"A": A, "B": B, "C": C, "D": D, "E": E}


A5_33 = _printed_A5_33()
"""Coefficients A'..E' of (A.5.33) as printed; A' is printed both as -D' - E' (A.5.32)
and written out, the written-out form is kept here."""


def bracket_A5_33(coefficients: dict | None = None) -> sp.Expr:
    """The bracket of (A.5.33): dw/w_s = 4 delta_n/(tau_m 3^(3/2) P) times this, 0 <= T <= 1."""
    c = A5_33 if coefficients is None else coefficients
    return (c["A"] * sp.exp(-T / tau_m) + c["B"] * sp.sin(2 * pi * T) + c["C"] * sp.sin(4 * pi * T)
            + c["D"] * sp.cos(2 * pi * T) + c["E"] * sp.cos(4 * pi * T))


def ode_second_order(v: sp.Expr) -> sp.Expr:
    """Residual of (A.5.16) in T for the bracket v of (A.5.25), = 0 on solutions.

    With dw/w_s = k v/(tau_el tau_m), k = 4 delta_n/(3^(3/2) P), (A.5.16) times t_m^2/k reads
    v'' + v'/tau_el + v/(tau_el tau_m) = -(f + tau_el f'), f = :func:`forcing`; the
    2 pi T_el/t_m (cos - cos) term of (A.5.16) is tau_el f'.
    """
    f = forcing()
    return (v.diff(T, 2) + v.diff(T) / tau_el + v / (tau_el * tau_m)
            + f + tau_el * f.diff(T))


def ode_first_order(v: sp.Expr) -> sp.Expr:
    """Residual of (A.5.27) in T for the bracket v of (A.5.33): v' + v/tau_m = -f, = 0 on solutions.

    (dw/w_s = k v/tau_m; (A.5.27) is (A.5.16) with T_el = 0.)
    """
    return v.diff(T) + v / tau_m + forcing()


# ------------------------------------------------------- the same, derived with SymPy


def derive_second_order() -> dict:
    """A'..F' of (A.5.25) derived again: undetermined coefficients, then (A.5.21).

    The particular solution (A.5.19) C sin 2 pi T + D sin 4 pi T + E cos 2 pi T + F cos 4 pi T
    put into :func:`ode_second_order` gives four linear equations, (A.5.20); the initial
    conditions dw = D dw = 0 at T = 0 (A.5.21) then give A and B (A.5.22), with the
    homogeneous roots -1/(2 tau_el) +- s.
    """
    A, B, C, D, E, F = sp.symbols("A B C D E F")
    part = (C * sp.sin(2 * pi * T) + D * sp.sin(4 * pi * T)
            + E * sp.cos(2 * pi * T) + F * sp.cos(4 * pi * T))
    res = sp.expand(ode_second_order(part))
    eqs = [res.coeff(fn) for fn in (sp.sin(2 * pi * T), sp.sin(4 * pi * T),
                                    sp.cos(2 * pi * T), sp.cos(4 * pi * T))]
    sol = sp.solve(eqs, [C, D, E, F], dict=True)[0]
    hom = sp.exp(-T / (2 * tau_el)) * (A * sp.exp(s_ * T) + B * sp.exp(-s_ * T))
    v = hom + part.subs(sol)
    ab = sp.solve([v.subs(T, 0), v.diff(T).subs(T, 0)], [A, B], dict=True)[0]
    out = {k.name: sp.simplify(val) for k, val in sol.items()}
    out.update({k.name: val for k, val in ab.items()})
    return out


def A5_20_printed() -> list:
    """The four equations (A.5.20) in the dimensionless form of (A.5.25), as printed.

    Printed in t_m, T_el, T_m with gamma = 4 delta_n/(T_el T_m 3^(3/2) P); multiplied by
    t_m^2 (tau_el tau_m/k) they become these, each = 0.
    """
    C, D, E, F = sp.symbols("C D E F")
    e, m = tau_el, tau_m
    a0 = -4 * pi**2 + 1 / (e * m)
    a1 = -16 * pi**2 + 1 / (e * m)
    return [a0 * C - 2 * pi / e * E + 1,
            a1 * D - 4 * pi / e * F - sp.Rational(1, 2),
            a0 * E + 2 * pi / e * C + 2 * pi * e,
            a1 * F + 4 * pi / e * D - 2 * pi * e]


def derive_first_order() -> dict:
    """A'..E' of (A.5.33) derived again: (A.5.30) by undetermined coefficients, A' from (A.5.31)."""
    A, B, C, D, E = sp.symbols("A B C D E")
    part = (B * sp.sin(2 * pi * T) + C * sp.sin(4 * pi * T)
            + D * sp.cos(2 * pi * T) + E * sp.cos(4 * pi * T))
    res = sp.expand(ode_first_order(part))
    eqs = [res.coeff(fn) for fn in (sp.sin(2 * pi * T), sp.sin(4 * pi * T),
                                    sp.cos(2 * pi * T), sp.cos(4 * pi * T))]
    sol = sp.solve(eqs, [B, C, D, E], dict=True)[0]
    v = A * sp.exp(-T / tau_m) + part.subs(sol)
    a = sp.solve(v.subs(T, 0), A, dict=True)[0]
    out = {k.name: sp.simplify(val) for k, val in sol.items()}
    out["A"] = sp.simplify(a[A])
    return out


def dsolve_first_order() -> sp.Expr:
    """(A.5.27) with v(0) = 0 solved by ``sympy.dsolve``: a derivation independent of the ansatz."""
    v = sp.Function("v")
    eq = sp.Eq(v(T).diff(T) + v(T) / tau_m, -forcing())
    return sp.dsolve(eq, v(T), ics={v(0): 0}, hint="1st_linear").rhs


# ------------------------------------------------------------------ numeric solutions


_r1, _r2 = sp.symbols("r1 r2")


@lru_cache(maxsize=None)
def _lambdified():
    """(A.5.25) and its derivative as NumPy functions.  exp(-T/(2 tau_el)) exp(+-s T) as
    exp(r T), r = -1/(2 tau_el) +- s: the same function, but without overflow when s T is
    large (tau_el -> 0)."""
    c = A5_25
    v = (c["A"] * sp.exp(_r1 * T) + c["B"] * sp.exp(_r2 * T)
         + c["C"] * sp.sin(2 * pi * T) + c["D"] * sp.sin(4 * pi * T)
         + c["E"] * sp.cos(2 * pi * T) + c["F"] * sp.cos(4 * pi * T))
    args = (T, tau_m, tau_el, s_, _r1, _r2)
    return sp.lambdify(args, v, "numpy"), sp.lambdify(args, v.diff(T), "numpy")


def _roots(tm: float, te: float) -> tuple[complex, complex, complex]:
    """(s, r1, r2) of (A.5.18); r1 = -1/(2 tau_el) + s taken as 1/(tau_el tau_m r2), which does not
    lose digits when s is close to 1/(2 tau_el)."""
    s2 = (tm / (4 * te) - 1) / (te * tm)
    if s2 == 0:
        raise ValueError("q = 1 exactly: (A.5.25) divides by s = 0 (critical damping)")
    s = cmath.sqrt(s2)
    r2 = -1 / (2 * te) - s
    return s, 1 / (te * tm * r2), r2


def _real(z) -> np.ndarray:
    z = np.asarray(z)
    if np.iscomplexobj(z):
        return z.real
    return z


def _free_decay_second_order(x: np.ndarray, v1: float, dv1: float, tm: float, te: float) -> np.ndarray:
    """Homogeneous solution of (A.5.16) from v(1) = v1, v'(1) = dv1, x = T - 1 >= 0: (A.5.18) with
    the constants fitted at T = 1 (complex for q < 1, the result real)."""
    s, r1, r2 = _roots(tm, te)
    c1 = (dv1 - r2 * v1) / (2 * s)
    c2 = (r1 * v1 - dv1) / (2 * s)
    return _real(c1 * np.exp(r1 * x) + c2 * np.exp(r2 * x))


def speed_second_order(Tq, tau_m: float, tau_el: float) -> np.ndarray:
    """u(T) = dw/(k w_s) of the second-order motor (A.5.25), k = 4 delta_n/(3^(3/2) P).

    u = (bracket of (A.5.25))/(tau_el tau_m) during the rise; for T > 1 the free decay
    from the state at T = 1.  In SI, dw = (2 pi Mc/G_a) u (:func:`speed_deviation`).
    """
    Tq = np.asarray(Tq, dtype=float)
    f, df = _lambdified()
    args = (complex(tau_m), complex(tau_el), *_roots(tau_m, tau_el))
    scale = 1.0 / (tau_el * tau_m)
    Tr = np.clip(Tq, 0.0, 1.0)
    u = _real(f(Tr.astype(complex), *args)) * scale
    late = Tq > 1.0
    if np.any(late):
        v1 = float(_real(f(complex(1.0), *args))) * scale
        dv1 = float(_real(df(complex(1.0), *args))) * scale
        u = np.array(u, dtype=float)
        u[late] = _free_decay_second_order(Tq[late] - 1.0, v1, dv1, tau_m, tau_el)
    return u


def second_order(tau_el: float | None):
    """u(T, tau_m) of the second-order motor (A.5.25) at this tau_el, for the functions of
    :mod:`.motor_rules`; None (their first-order motor) without one."""
    if not tau_el:
        return None
    return lambda Tq, tau_m: speed_second_order(Tq, tau_m, tau_el)


def slip(Tq, tau_m: float, *, delta_n: float, P: float, eta_g: float = 1.0,
         tau_el: float | None = None) -> np.ndarray:
    """delta(T) = -dw/w_s for the nominal load of the cycloid, (A.5.25) with tau_el or (A.5.33)
    (motor_rules.slip)."""
    return _rules.slip(Tq, tau_m, delta_n=delta_n, P=P, eta_g=eta_g, speed=second_order(tau_el))


def relative_slip_peak(tau_m: float, tau_el: float | None = None) -> tuple[float, float]:
    """(delta_max/delta_n, T at the maximum) at P = 1, the curve of fig. 8.6: first order
    (A.5.33) unless tau_el is given (motor_rules.relative_slip_peak)."""
    return _rules.relative_slip_peak(tau_m, second_order(tau_el))


def required_overdimensioning(tau_m: float, delta_n: float, delta_lim: float, *,
                              eta_g: float = 1.0, spring: bool = False,
                              tau_el: float | None = None) -> float:
    """P (8.1), first order unless tau_el is given (motor_rules.required_overdimensioning,
    where its reading is)."""
    return _rules.required_overdimensioning(tau_m, delta_n, delta_lim, eta_g=eta_g,
                                            spring=spring, speed=second_order(tau_el))


def speed_deviation(t_s, *, J_ma: float, G_a: float, t_m: float, Mc: float, T_el: float = 0.0) -> np.ndarray:
    """dw(t) [rad/s] of the motors ``motor2`` (T_el > 0) and ``motor1`` (T_el = 0), from the
    analytic solutions, for the load Mc H'(T) H''(T) of the cycloid.

    The thesis's scale 4 w_s delta_n/(3^(3/2) P) equals 2 pi Mc/G_a: M_ena/G_a = w_s delta_n
    ((A.5.4b) reduced) and M_ena/P = M_max = 3^(3/2) pi Mc/2 (A.2.14).
    """
    Tq = np.asarray(t_s, dtype=float) / t_m
    tm = J_ma / G_a / t_m
    u = speed_first_order(Tq, tm) if T_el == 0 else speed_second_order(Tq, tm, T_el / t_m)
    return 2 * math.pi * Mc / G_a * u


# ----------------------------------------------------------- motor selection (sec. 8.3)


# ------------------------------------------------------------------ worm gear (sec. 6.7)


def worm_force_ratio(driving: bool = True) -> sp.Expr:
    """F_out/F_in on the worm helix from the force balance (6.71), derived.

    The helix is a plane at the lead angle alpha (h_out/h_in = tan alpha, fig. 6.17); the
    wheel tooth slides along it, the normal force N and the friction force tan(mu) N
    opposing the sliding act on the tooth.  F_in is the tangential force on the worm,
    F_out the force along the wheel's circumference.  Driving (worm pushes the wheel):
    cot(alpha + mu); driven (wheel pushes the worm): the sliding, and so the friction,
    reverse: cot(alpha - mu).
    """
    N = sp.Symbol("N", positive=True)
    normal = sp.Matrix([sp.sin(alpha), sp.cos(alpha)])       # into the tooth
    tangent = sp.Matrix([-sp.cos(alpha), sp.sin(alpha)])     # tooth relative to the worm, driving
    sliding = tangent if driving else -tangent
    on_tooth = N * normal - sp.tan(mu) * N * sliding
    F_out, F_in = on_tooth[1], on_tooth[0]
    return sp.simplify(sp.expand_trig(F_out / F_in))


def worm_gear_torque(M_ma, alpha: float, mu: float):
    """Camshaft torque M from the motor torque M_ma (reduced) through a worm gear (6.72).

    M = M_ma tan(alpha)/tan(alpha + mu) when the motor drives (M_ma > 0), M = M_ma tan(alpha)/
    tan(alpha - mu) when the camshaft drives the motor (M_ma < 0): the sign of M follows
    M_ma.  A self-locking gear (alpha <= mu) cannot be driven from the camshaft:
    ValueError for M_ma < 0 there.
    """
    M_ma = np.asarray(M_ma, dtype=float)
    if alpha <= mu and np.any(M_ma < 0):
        raise ValueError(f"self-locking worm gear (alpha = {alpha} <= mu = {mu}) cannot be driven backwards")
    ta = math.tan(alpha)
    M = np.where(M_ma > 0, M_ma * ta / math.tan(alpha + mu),
                 np.where(M_ma < 0, M_ma * ta / math.tan(alpha - mu) if alpha > mu else 0.0, 0.0))
    return float(M) if M.ndim == 0 else M
