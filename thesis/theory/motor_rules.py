"""The motor's side of sec. 8.3 in NumPy: the first-order speed deviation (A.5.33) with its
printed coefficients, the slip it gives, the peak slip of fig. 8.6, the selection rules
(8.1)-(8.4) and the worm gear's efficiency (A.5.34).

These need no SymPy, so `camdyn design` sizes a motor without loading it (its import alone
takes longer than the rest of a design).  :mod:`.motor_theory` holds the same equations
symbolically (the coefficients A'..E' of (A.5.33) as printed, and derived again), the
second-order motor (A.5.25), and the readings of (8.1)-(8.4); it offers these functions
under its own name too.  tests/test_motor.py holds (A.5.33) here equal to its symbolic form.
"""
from __future__ import annotations

import math

import numpy as np

M_MAX = 3 * math.sqrt(3) * math.pi / 2
"""M_max/Mc of the cycloid, at T = 1/3 (A.2.14); 8.162, printed 8.2 in (8.2)
(motor_theory.M_MAX_FACTOR)."""


def bracket_A5_33(T, tau_m: float):
    """The bracket of (A.5.33) with A'..E' as printed (motor_theory.A5_33): dw/w_s =
    4 delta_n/(tau_m 3^(3/2) P) times this, 0 <= T <= 1."""
    m = tau_m
    w1, w2 = (2 * math.pi * m) ** 2 + 1, (4 * math.pi * m) ** 2 + 1
    B, C = -m / w1, (m / 2) / w2
    D, E = 2 * math.pi * m**2 / w1, -2 * math.pi * m**2 / w2
    A = -2 * math.pi * m**2 / w1 + 2 * math.pi * m**2 / w2
    return (A * np.exp(-T / m) + B * np.sin(2 * np.pi * T) + C * np.sin(4 * np.pi * T)
            + D * np.cos(2 * np.pi * T) + E * np.cos(4 * np.pi * T))


def speed_first_order(Tq, tau_m: float) -> np.ndarray:
    """u(T) = dw/(k w_s) of the first-order motor (A.5.33), k = 4 delta_n/(3^(3/2) P).

    u = (bracket of (A.5.33))/tau_m during the rise; for T > 1 the decay u(1) exp(-(T - 1)/tau_m)
    of (A.5.28).
    """
    Tq = np.asarray(Tq, dtype=float)
    Tr = np.clip(Tq, 0.0, 1.0)
    u = np.asarray(bracket_A5_33(Tr, tau_m), dtype=float) / tau_m
    late = Tq > 1.0
    if np.any(late):
        u1 = float(bracket_A5_33(1.0, tau_m)) / tau_m
        u = np.array(u, dtype=float)
        u[late] = u1 * np.exp(-(Tq[late] - 1.0) / tau_m)
    return u


def slip(Tq, tau_m: float, *, delta_n: float, P: float, eta_g: float = 1.0,
         speed=None) -> np.ndarray:
    """delta(T) = -dw/w_s for the nominal load of the cycloid, of the motor whose u(T, tau_m)
    is ``speed``: the first-order (A.5.33) unless given (the second-order (A.5.25) is
    motor_theory.second_order's).

    Proportional to delta_n/P (A.5.33) and, with the motor driving through a gear of
    efficiency eta_g, to 1/eta_g (sec. A.5.4.3.2: the motor supplies M_ma/eta_g).
    """
    u = (speed or speed_first_order)(Tq, tau_m)
    return -4 * delta_n / (3 ** 1.5 * P * eta_g) * u


def relative_slip_peak(tau_m: float, speed=None) -> tuple[float, float]:
    """(delta_max/delta_n, T at the maximum) at P = 1: the curve of fig. 8.6 (reading in
    motor_theory's module docstring); the first-order motor (A.5.33) unless ``speed`` (as
    :func:`slip`).

    Limits: 1 for tau_m -> 0 (static slip at peak torque, delta_n/P), and
    4/(3^(3/2) pi tau_m) for tau_m -> infinity (the inertia integrates the load up to T = 1/2).
    """
    from ..numerics import maximize

    def g(x):
        return float(slip(np.array([x]), tau_m, delta_n=1.0, P=1.0, speed=speed)[0])

    grid = np.linspace(0.0, 2.0, 801)
    vals = slip(grid, tau_m, delta_n=1.0, P=1.0, speed=speed)
    k = int(np.argmax(vals))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    x, v = maximize(g, lo, hi, xatol=1e-10)
    best = max((vals[k], grid[k]), (v, x))
    return float(best[0]), float(best[1])


def required_overdimensioning(tau_m: float, delta_n: float, delta_lim: float, *,
                              eta_g: float = 1.0, spring: bool = False, speed=None) -> float:
    """P = v_v (delta_max/delta_n)(tau_m) delta_n/(eta_g delta_lim) (8.1).

    Reading ((8.1) itself is lost): the slip is inversely proportional to P (A.5.33) and to
    eta_g (sec. A.5.4.3.2) and grows by a factor v_v = 5 with a follower spring
    (sec. A.5.4.3.3, v_v = 1 without), fig. 8.6 giving delta_max/delta_n at P = 1.
    """
    v_v = 5.0 if spring else 1.0
    rel, _ = relative_slip_peak(tau_m, speed)
    return v_v * rel * delta_n / (eta_g * delta_lim)


def required_torque(m: float, h_m: float, w_s: float, t_m: float, P: float) -> float:
    """Rated motor torque reduced to the camshaft, M_ena = 8.2 m h_m'^2 P/(w_s t_m^3) (8.2).

    8.2 is M_max/Mc = 3^(3/2) pi/2 = 8.162 of the cycloid (A.2.14); the exact factor is used.
    """
    return M_MAX * m * h_m**2 * P / (w_s * t_m**3)


def required_power(m: float, h_m: float, t_m: float, P: float) -> float:
    """Rated power N_n = M_ena w_s = 8.2 m h_m'^2 P/t_m^3 ((8.3) with w_n ~ w_s; reading).

    With P from (8.1): N_n = 8.2 m h_m'^2 v_v (delta_max/delta_n) delta_n/(eta_g delta_lim t_m^3),
    independent of the shaft speed.
    """
    return M_MAX * m * h_m**2 * P / t_m**3


def slip_within_rated(delta_lim: float, delta_n: float) -> bool:
    """(8.4), reading: "to prevent overload, slip should not exceed the nominal slip",
    delta_lim <= delta_n."""
    return delta_lim <= delta_n


def worm_gear_efficiency(alpha: float, mu: float, driving: bool = True) -> float:
    """Power out over power in: tan(alpha)/tan(alpha + mu) driving (A.5.34), tan(alpha - mu)/tan(alpha)
    driven (zero or less: self-locking)."""
    if driving:
        return math.tan(alpha) / math.tan(alpha + mu)
    return math.tan(alpha - mu) / math.tan(alpha)
