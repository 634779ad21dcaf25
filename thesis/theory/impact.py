"""Impact after traversal of backlash (thesis sec. 3.6, (3.8)-(3.16)) and the decay of the
residual vibration over a dwell (sec. 3.4, (3.7)).

Everything the thesis derives by hand is derived here again with SymPy from the physics the
text states, and kept beside the formula as printed, so that a check comparing the two can fail:

ramp response (3.8)-(3.12)
    The impact is modelled as a sudden jump of the input velocity: h' = 0 for t < 0 and
    h' = v_b t for t >= 0 (3.8).  With it as the input of the one-DOF model (3.1),
    m x'' + c x = c h', the follower starts from rest and lags behind the ramp.
    :func:`ramp_response` solves (3.1) from rest; the amplitude of u = x - h follows as
    sqrt(u^2 + (u'/w_e)^2), which is constant for any harmonic signal of frequency w_e.
    **Reading taken** for the scanned-away (3.9) and (3.10): u_sn = v_b T_e/(2 pi) and
    u_sn'' = 2 pi v_b/T_e, the only dimensional forms whose reduction with r_e = v_b t_m/h_m'
    (stated in the text) and tau = T_e/t_m gives the printed (3.11) U_sn = r_e tau/(2 pi) and
    (3.12) U_sn'' = 2 pi r_e/tau.

backlash traversal (3.13)-(3.15)
    At the reversal of the force the members lose contact with zero differences of position,
    velocity and acceleration; the difference in acceleration then grows with the rate of
    change k = h''' of the nominal acceleration: delta h'' = k t, so delta h' = k t^2/2 and
    delta h = k t^3/6.  The backlash s' is used up at t_b (delta h(t_b) = s', (3.14)) and the
    velocity difference there is the impact speed (3.13).  Eliminating t_b gives the printed
    (3.15), v_b = 1/2 (h''')^(1/3) (6 s')^(2/3).  The scan's "1-h; t 2" and "-1;- h' tb3" are
    read as 1/2 k t_b^2 and 1/6 k t_b^3, as the integration requires.

impact speed of the cycloid (3.16)
    (3.16) itself is illegible in the scan.  **Reading taken**: (3.15) made dimensionless with
    h''' = H''' h_m'/t_m^3, s' = S h_m' (S = s'/h_m', the relative backlash used in sec. 7.4.4
    and fig. 7.11) and r_e = v_b t_m/h_m', at the reversal points of the cycloid where
    |H'''| = 4 pi^2 (A.2.16):

        r_e = 1/2 (4 pi^2)^(1/3) (6 S)^(2/3) = (18 pi^2 S^2)^(1/3) = 5.62 S^(2/3).

    The thesis's own number supports it: S = 1.27e-2 gives r_e = 0.306, printed 0.31 (sec. 7.4.4).

damping over a dwell (3.7)
    The printed decay law is :data:`camdyn.thesis.theory.forms.decay`,
    U0n/U00 = exp(-n 2 pi q/(1 - q^2)^(1/2)), with n = t_d/(tau t_m) free vibrations within
    the dwell t_d (sec. 3.4).  :func:`damped_free_vibration` is the free motion of the damped
    one-DOF model (d = 2 q sqrt(m c), (6.47)); over n *damped* periods 2 pi/(w_e (1 - q^2)^(1/2))
    its amplitude falls exactly by (3.7).  The thesis counts n in undamped periods
    (n = t_d/(tau t_m)); then the exact decay over t_d is exp(-2 pi q n), and (3.7) overstates
    the decay by the factor exp(-2 pi q n ((1 - q^2)^(-1/2) - 1)), 0.993 at the thesis's
    q = 0.06, n = 10: both round to the printed 2 %.
    The inverse, used in sec. 7.4.5 to measure damping from a record, is (7.10),
    q ~ ln(U00/U0n)/(2 pi n) for q << 1.
"""
from __future__ import annotations

import math
from functools import lru_cache
from types import MappingProxyType

import sympy as sp

from . import forms

pi = sp.pi

# -- symbols (primes of the thesis dropped: all magnitudes are reduced to the output member) --
t = sp.Symbol("t", nonnegative=True)
"""Time since the start of the ramp, or since the force reversal."""
v_b = sp.Symbol("v_b", positive=True)
"""Impact speed, the velocity jump of the ramp (3.8)."""
w_e = sp.Symbol("omega_e", positive=True)
"""Natural angular frequency 2 pi/T_e of the one-DOF model."""
T_e = sp.Symbol("T_e", positive=True)
"""Period of natural vibration (4.11)."""
t_m = sp.Symbol("t_m", positive=True)
"""Cam rise time."""
h_m = sp.Symbol("h_m", positive=True)
"""Stroke h_m' of the output member."""
tau = forms.tau
"""T_e/t_m (3.3)."""
r_e = sp.Symbol("r_e", positive=True)
"""Relative impact speed v_b t_m/h_m' (sec. 3.6)."""
k = sp.Symbol("k", positive=True)
"""Rate of change h''' of the nominal acceleration at the force reversal (sec. 3.6)."""
s = sp.Symbol("s", positive=True)
"""Backlash s' (reduced to the output member)."""
t_b = sp.Symbol("t_b", positive=True)
"""Instant of impact, measured from the force reversal."""
S = sp.Symbol("S", positive=True)
"""Relative backlash s'/h_m'."""
H3 = sp.Symbol("H3", positive=True)
"""|H'''| = |h'''| t_m^3/h_m' at the reversal point."""
q = forms.q
"""Relative damping, d = 2 q sqrt(m c) (6.47)."""
n = forms.n
"""Number of free vibrations within the dwell."""

# -- as printed (typed in from the thesis, never derived) --------------------------------------
U_sn_printed = r_e * tau / (2 * pi)
"""Relative positional error amplitude after impact (3.11)."""
Udd_sn_printed = 2 * pi * r_e / tau
"""Relative residual acceleration amplitude after impact (3.12)."""
v_b_at_impact_printed = k * t_b**2 / 2
"""Velocity difference at the instant of impact (3.13)."""
backlash_printed = k * t_b**3 / 6
"""Relative position of the members at t_b, equal to the backlash (3.14)."""
v_b_printed = sp.Rational(1, 2) * k ** sp.Rational(1, 3) * (6 * s) ** sp.Rational(2, 3)
"""Impact speed after traversing the backlash s' (3.15)."""
u_sn_reading = v_b * T_e / (2 * pi)
"""Amplitude of the positional error after impact (3.9), as read (see the module docstring)."""
udd_sn_reading = 2 * pi * v_b / T_e
"""Amplitude of the residual acceleration after impact (3.10), as read."""
r_e_cycloid_reading = (18 * pi**2 * S**2) ** sp.Rational(1, 3)
"""Relative impact speed at a reversal point of the cycloid (3.16), as read (module docstring)."""
CYCLOID_JERK = 4 * pi**2
"""|H'''| of the cycloid at T = 0, 1/2, 1 (A.2.16)."""


# -- derivations ---------------------------------------------------------------------------------
@lru_cache(maxsize=None)  # pure and slow (dsolve, solve): derive once
def ramp_response() -> sp.Expr:
    """x(t) of x'' = w_e^2 (h' - x) ((3.1) divided by m) with the ramp h' = v_b t (3.8), from rest."""
    x = sp.Function("x")
    sol = sp.dsolve(x(t).diff(t, 2) + w_e**2 * (x(t) - v_b * t), x(t),
                    ics={x(0): 0, x(t).diff(t).subs(t, 0): 0})
    return sol.rhs


def harmonic_amplitude(signal: sp.Expr, omega: sp.Expr = w_e) -> sp.Expr:
    """Amplitude of a harmonic ``signal`` of angular frequency ``omega``: sqrt(u^2 + (u'/w)^2).

    Constant in t exactly when the signal is harmonic, so a t left in the result shows that
    the signal was not a pure vibration of that frequency.
    """
    return sp.simplify(sp.sqrt(signal**2 + (signal.diff(t) / omega) ** 2))


@lru_cache(maxsize=None)
def impact_amplitudes() -> tuple[sp.Expr, sp.Expr]:
    """(u_sn, u_sn''): amplitudes of u = x - h' and of its acceleration after the ramp, (3.9)
    and (3.10), written with T_e = 2 pi/w_e."""
    u = ramp_response() - v_b * t
    amp = harmonic_amplitude(u)
    amp_dd = harmonic_amplitude(u.diff(t, 2))
    to_Te = {w_e: 2 * pi / T_e}
    return sp.simplify(amp.subs(to_Te)), sp.simplify(amp_dd.subs(to_Te))


def dimensionless(expr: sp.Expr, scale: sp.Expr) -> sp.Expr:
    """``expr``/``scale`` with v_b = r_e h_m'/t_m and T_e = tau t_m (sec. 3.6, (3.3))."""
    return sp.simplify((expr / scale).subs({v_b: r_e * h_m / t_m, T_e: tau * t_m}))


@lru_cache(maxsize=None)
def backlash_traversal() -> MappingProxyType:
    """The traversal of sec. 3.6 integrated from the force reversal (all differences zero at t = 0).

    Returns the differences of acceleration, velocity and position as functions of t, the
    instant of impact t_b (delta h(t_b) = s', (3.14)) and the impact speed v_b = delta h'(t_b)
    (3.13), (3.15).
    """
    u = sp.Dummy("u", nonnegative=True)
    dhdd = k * t
    dhd = sp.integrate(dhdd.subs(t, u), (u, 0, t))
    dh = sp.integrate(dhd.subs(t, u), (u, 0, t))
    roots = [r for r in sp.solve(sp.Eq(dh.subs(t, t_b), s), t_b) if r.is_positive]
    if len(roots) != 1:
        raise ValueError(f"no unique positive instant of impact: {roots}")
    tb = roots[0]
    return MappingProxyType({"dhdd": dhdd, "dhd": dhd, "dh": dh, "t_b": tb,
                             "v_b": sp.simplify(dhd.subs(t, tb))})


def r_e_from_3_15() -> sp.Expr:
    """r_e = v_b t_m/h_m' with (3.15) in the dimensionless numbers: h''' = H3 h_m'/t_m^3,
    s' = S h_m' (the step from (3.15) to (3.16))."""
    vb = v_b_printed.subs({k: H3 * h_m / t_m**3, s: S * h_m})
    return sp.simplify(sp.powsimp(vb * t_m / h_m, force=True))


def damped_free_vibration() -> tuple[sp.Expr, sp.Expr]:
    """(x, T_d): free motion exp(-q w_e t) cos(w_d t) of the damped one-DOF model and its period.

    Valid for 0 <= q < 1; w_d = w_e (1 - q^2)^(1/2).
    """
    w_d = w_e * sp.sqrt(1 - q**2)
    return sp.exp(-q * w_e * t) * sp.cos(w_d * t), 2 * pi / w_d


def damped_residual(x: sp.Expr) -> sp.Expr:
    """Left side of x'' + 2 q w_e x' + w_e^2 x = 0 ((3.1) at rest input with d = 2 q sqrt(m c))."""
    return sp.simplify(x.diff(t, 2) + 2 * q * w_e * x.diff(t) + w_e**2 * x)


def decay_after_damped_periods() -> sp.Expr:
    """Amplitude ratio of the damped free vibration after n damped periods (to compare with (3.7))."""
    x, T_d = damped_free_vibration()
    return sp.simplify(sp.exp(-q * w_e * (t + n * T_d)) / sp.exp(-q * w_e * t))


# -- numbers -------------------------------------------------------------------------------------
def impact_speed(jerk: float, backlash: float) -> float:
    """v_b = 1/2 (h''')^(1/3) (6 s')^(2/3) (3.15), any consistent units."""
    return 0.5 * abs(jerk) ** (1 / 3) * (6 * backlash) ** (2 / 3)


def r_e_from_backlash(S: float, H3: float = 4 * math.pi**2) -> float:
    """Relative impact speed r_e for the relative backlash S = s'/h_m' (3.16); H3 = |H'''| at the
    reversal point, 4 pi^2 for the cycloid (A.2.16)."""
    return 0.5 * abs(H3) ** (1 / 3) * (6 * S) ** (2 / 3)


def U_sn(r_e: float, tau: float) -> float:
    """Relative positional error amplitude after impact, r_e tau/(2 pi) (3.11)."""
    return r_e * tau / (2 * math.pi)


def Udd_sn(r_e: float, tau: float) -> float:
    """Relative residual acceleration amplitude after impact, 2 pi r_e/tau (3.12)."""
    return 2 * math.pi * r_e / tau


def dwell_vibrations(td_over_tm: float, tau: float) -> float:
    """n = t_d/(tau t_m), the number of (undamped) free vibrations within the dwell (sec. 3.4)."""
    return td_over_tm / tau


def decay_ratio(n: float, q: float) -> float:
    """U0n/U00 = exp(-n 2 pi q/(1 - q^2)^(1/2)) (3.7)."""
    return math.exp(-n * 2 * math.pi * q / math.sqrt(1 - q * q))


def envelope_decay(td_over_tm: float, tau: float, q: float) -> float:
    """Exact amplitude ratio of the damped free vibration over a dwell t_d: exp(-q w_e t_d)."""
    return math.exp(-q * 2 * math.pi / tau * td_over_tm)


def q_from_decrement(ratio: float, n: float, exact: bool = False) -> float:
    """Relative damping from the amplitude ratio U00/U0n over n vibrations.

    Default: (7.10), q ~ ln(U00/U0n)/(2 pi n), for q << 1 (sec. 7.4.5).  exact=True inverts (3.7)
    itself: with x = ln(ratio)/(2 pi n), q = x/(1 + x^2)^(1/2).
    """
    x = math.log(ratio) / (2 * math.pi * n)
    return x / math.sqrt(1 + x * x) if exact else x
