"""The cam mechanism on a low-tuned foundation (sec. 7.2, (7.1)-(7.6), fig. 7.3).

Two DOF: the foundation f (mass m_f on the tyres c_f, frame at rest) carries the
cam, which drives the follower output mass m_x through the follower stiffness
c_c with the cam motion h'(t) relative to the foundation.  x and f are absolute
displacements (the accelerometer measures absolute accelerations, sec. 7.3)::

    m_x x'' = c_c (f + h' - x)
    m_f f'' = -c_f f - c_c (f + h' - x)        (the follower spring reacts on the cam)

Natural frequencies of the uncoupled parts: w_ex^2 = c_c/m_x (follower rigidly
supported), w_ef^2 = c_f/m_f (foundation alone); the coupling enters through
c_c/m_f.

Thesis formulas and where they live
    (7.1)  x/h' by partial fractions                    -> :func:`transfer_function_printed`,
           derived from the equations of motion        -> :func:`transfer_function_derived`,
           its two coefficients                        -> :func:`modal_coefficients`
    roots "by analogy with (5.38)"                      -> :func:`root_formula`, :func:`eigenvalues`
    (7.3), (7.4) first-order roots                      -> :func:`eq_7_3`, :func:`eq_7_4`,
                                                           :func:`eigenvalues` (approx=True)
    tau_i = 2 pi/(w_ei t_m), as tau = T_e/t_m (3.3)      -> :func:`tau_of`
    (3.6), (7.5) residual acceleration amplitude        -> :func:`residual_acceleration`
    (7.2), (7.6) amplitude ratios                       -> :func:`amplitude_ratios`
    the thesis's example, all at once                   -> :func:`thesis_case`

Readings taken where the scan is garbled
    Fig. 7.3 shows only the labels x and f; the equations above are the reading (the
    cam sits on the foundation, c_f is printed "c1", m_f "m1" in the scan).  They
    reproduce the printed root formula and the printed structure of (7.1), both
    checked symbolically (thesis/checks/foundation_checks.py).
    (7.1): x/h' = w_ex^2 [(w_ef^2 - w_e1^2)/(w_e1^2 (w_e2^2 - w_e1^2)) 1/(1 + (D/w_e1)^2)
                          + (w_e2^2 - w_ef^2)/(w_e2^2 (w_e2^2 - w_e1^2)) 1/(1 + (D/w_e2)^2)].
    (7.3): w_e1^2 = w_ex^2 w_ef^2/(w_ex^2 + w_ef^2 + c_c/m_f); (7.4): w_e2^2 = w_ex^2 +
        w_ef^2 + c_c/m_f - (7.3).  Both follow from sqrt(x + dx) ~ sqrt(x) + dx/(2 sqrt x)
        with x = (w_ex^2 + w_ef^2 + c_c/m_f)^2, dx = -4 w_ex^2 w_ef^2, as the text says.
    (7.2), (7.5), (7.6): printed without the factor |sin(pi/tau_i)| of (3.6), i.e. on the
        envelope through the maxima, as sec. 3.7.3 compares contributions.  So
        U0i'' ~ |coefficient_i| tau_i/|1 - tau_i^2| and U0'' ~ tau/(1 - tau^2).

Reproduction of the printed numbers (thesis/checks/foundation_checks.py has them all)
    tau1: 2.287 from the exact root (printed 2.28, truncated), 2.292 from (7.3).
    tau2: 0.15962 from (7.4) and from the exact root (printed 0.1595, 0.08 % off).
    U01'' : U02'' : U0'' = 0.0341 : 0.984 : 1 with the exact roots (printed
    3.5e-2 : 0.99 : 1).  The coefficient of the low mode is about m_x/m_f because
    w_ef^2 - w_e1^2 ~ w_ef^2 m_x/m_f is a small difference, of the size of the
    error of (7.3) itself: (7.3) taken literally gives 0.050 instead of 0.034.
    Frequency shift w_e2/w_ex - 1 = 0.52 % (printed "about 0.5 %").
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

# --------------------------------------------------------------------- thesis data

THESIS = {
    "m_x": 1.875,        # kg, equivalent follower mass
    "m_f": 180.0,        # kg, foundation
    "c_c": 0.37e6,       # N/m, follower stiffness
    "t_m": 0.088,        # s, cam rise time
    "w_ex2": 19.8e4,     # s^-2, printed; c_c/m_x of the rounded c_c is 19.73e4
    "f_ex": 71.0,        # Hz, printed
    "tau": 0.1605,       # printed
    "f_ef": 5.0,         # Hz, measured (fig. 7.4b)
    "w_ef2": 9.85e2,     # s^-2, printed
    "cc_mf": 20.6e2,     # s^-2, printed
}
"""The data of sec. 7.2 as printed."""

# --------------------------------------------------------------------------- symbolic

m_x, m_f, c_c, c_f = sp.symbols("m_x m_f c_c c_f", positive=True)
D = sp.Symbol("D")
"""The differential operator d/dt, as the thesis writes transfer functions (sec. 3.7)."""
w_ex2, w_ef2, r_cf = sp.symbols("w_ex2 w_ef2 r", positive=True)
"""w_ex^2 = c_c/m_x, w_ef^2 = c_f/m_f and r = c_c/m_f."""


def transfer_function_derived() -> sp.Expr:
    """x/h' from the two equations of motion by Cramer's rule, as sec. 3.7.1 does.

    Operator form: [m_x D^2 + c_c, -c_c; -c_c, m_f D^2 + c_f + c_c] (x, f) =
    (c_c h', -c_c h').
    """
    A = sp.Matrix([[m_x * D**2 + c_c, -c_c], [-c_c, m_f * D**2 + c_f + c_c]])
    rhs = sp.Matrix([c_c, -c_c])  # per unit h'
    numerator = A.copy()
    numerator[:, 0] = rhs
    return sp.cancel(numerator.det() / A.det())


def frequency_substitution() -> dict:
    """c_c, c_f in terms of m_x, m_f and w_ex^2, w_ef^2 (then c_c/m_f = m_x w_ex^2/m_f)."""
    return {c_c: m_x * w_ex2, c_f: m_f * w_ef2}


def root_formula(S=None, P=None) -> tuple[sp.Expr, sp.Expr]:
    """w_e1,2^2 = 1/2 {S -/+ [S^2 - 4 w_ex^2 w_ef^2]^(1/2)}, S = w_ex^2 + w_ef^2 + c_c/m_f.

    The roots of the frequency equation "similar to (5.37)", printed "by analogy with
    (5.38)" just before (7.3).
    """
    S = w_ex2 + w_ef2 + r_cf if S is None else S
    P = w_ex2 * w_ef2 if P is None else P
    root = sp.sqrt(S**2 - 4 * P)
    return (S - root) / 2, (S + root) / 2


def eq_7_3() -> sp.Expr:
    """(7.3): w_e1^2 = w_ex^2 w_ef^2/(w_ex^2 + w_ef^2 + c_c/m_f)."""
    return w_ex2 * w_ef2 / (w_ex2 + w_ef2 + r_cf)


def eq_7_4() -> sp.Expr:
    """(7.4): w_e2^2 = w_ex^2 (1 + w_ef^2/w_ex^2 + c_c/(m_f w_ex^2)) - w_ex^2 w_ef^2/(w_ex^2 + w_ef^2 + c_c/m_f)."""
    return (w_ex2 * (1 + w_ef2 / w_ex2 + r_cf / w_ex2)
            - w_ex2 * w_ef2 / (w_ex2 + w_ef2 + r_cf))


def transfer_function_printed(l1=None, l2=None) -> sp.Expr:
    """(7.1) as printed, with w_e1^2 = l1, w_e2^2 = l2 (default: the exact roots)."""
    if l1 is None or l2 is None:
        l1, l2 = root_formula()
    return w_ex2 * ((w_ef2 - l1) / (l1 * (l2 - l1)) / (1 + D**2 / l1)
                    + (l2 - w_ef2) / (l2 * (l2 - l1)) / (1 + D**2 / l2))


# --------------------------------------------------------------------------- numeric


def eigenvalues(w_ex2: float, w_ef2: float, cc_mf: float, *, approx: bool = False) -> tuple[float, float]:
    """(w_e1^2, w_e2^2): the exact roots, or (7.3), (7.4) with ``approx=True``."""
    S = w_ex2 + w_ef2 + cc_mf
    P = w_ex2 * w_ef2
    if approx:
        return P / S, S - P / S
    root = math.sqrt(S * S - 4 * P)
    # the lower root as P/(upper root): no cancellation of two nearly equal numbers
    upper = (S + root) / 2
    return P / upper, upper


def modal_coefficients(w_ex2: float, w_ef2: float, l1: float, l2: float) -> tuple[float, float]:
    """The coefficients of 1/(1 + (D/w_ei)^2) in (7.1); they add up to 1 (x = h' statically)."""
    return (w_ex2 * (w_ef2 - l1) / (l1 * (l2 - l1)),
            w_ex2 * (l2 - w_ef2) / (l2 * (l2 - l1)))


def tau_of(lam: float, t_m: float) -> float:
    """tau_i = T_ei/t_m = 2 pi/(w_ei t_m) (3.3)."""
    return 2 * math.pi / (math.sqrt(lam) * t_m)


def residual_acceleration(tau: float, *, envelope: bool = False) -> float:
    """U0'' = 4 pi tau/|1 - tau^2| |sin(pi/tau)| (3.6), (7.5), cycloidal rise, in h_m/t_m^2.

    ``envelope=True`` drops |sin(pi/tau)| (the maxima), as (7.2) and (7.6) are printed.
    """
    amp = 4 * math.pi * tau / abs(1 - tau * tau)
    return amp if envelope else amp * abs(math.sin(math.pi / tau))


def amplitude_ratios(w_ex2: float, w_ef2: float, cc_mf: float, t_m: float, *,
                     approx: bool = False, envelope: bool = True) -> tuple[float, float, float]:
    """U01'' : U02'' : U0'' (7.6), normalised to U0'' = 1.

    U0i'' = |coefficient_i of (7.1)| times (3.6) at tau_i; U0'' is (7.5), the follower on a
    rigid support (tau = 2 pi/(w_ex t_m)).  ``envelope`` as in :func:`residual_acceleration`.
    """
    l1, l2 = eigenvalues(w_ex2, w_ef2, cc_mf, approx=approx)
    A1, A2 = modal_coefficients(w_ex2, w_ef2, l1, l2)
    U0 = residual_acceleration(tau_of(w_ex2, t_m), envelope=envelope)
    return (abs(A1) * residual_acceleration(tau_of(l1, t_m), envelope=envelope) / U0,
            abs(A2) * residual_acceleration(tau_of(l2, t_m), envelope=envelope) / U0,
            1.0)


@dataclass(frozen=True)
class FoundationCase:
    """All derived figures of sec. 7.2 for one set of data."""
    w_ex2: float
    w_ef2: float
    cc_mf: float
    t_m: float
    approx: bool
    l1: float
    l2: float
    A1: float
    A2: float
    tau: float
    tau1: float
    tau2: float
    ratios: tuple[float, float, float]
    shift: float
    """w_e2/w_ex - 1, the frequency shift of the follower mode."""


def case(w_ex2: float, w_ef2: float, cc_mf: float, t_m: float, *, approx: bool = False) -> FoundationCase:
    """Eigenvalues, coefficients, tau's, ratios (7.6) and shift for given data."""
    l1, l2 = eigenvalues(w_ex2, w_ef2, cc_mf, approx=approx)
    A1, A2 = modal_coefficients(w_ex2, w_ef2, l1, l2)
    return FoundationCase(w_ex2, w_ef2, cc_mf, t_m, approx, l1, l2, A1, A2,
                          tau_of(w_ex2, t_m), tau_of(l1, t_m), tau_of(l2, t_m),
                          amplitude_ratios(w_ex2, w_ef2, cc_mf, t_m, approx=approx),
                          math.sqrt(l2 / w_ex2) - 1)


def case_from_masses(m_x: float, m_f: float, c_c: float, c_f: float, t_m: float, *,
                     approx: bool = False) -> FoundationCase:
    """:func:`case` from the physical data (kg, N/m, s)."""
    return case(c_c / m_x, c_f / m_f, c_c / m_f, t_m, approx=approx)


def thesis_case(*, approx: bool = False) -> FoundationCase:
    """Sec. 7.2 with the frequencies as printed: w_ex^2 = 19.8e4, w_ef^2 = 9.85e2, c_c/m_f = 20.6e2."""
    d = THESIS
    return case(d["w_ex2"], d["w_ef2"], d["cc_mf"], d["t_m"], approx=approx)
