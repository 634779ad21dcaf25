"""Rayleigh's estimate of the lowest natural frequency of a lumped chain (sec. 4.6, App. 3).

The chain is the uncoupled follower linkage of fig. 4.12 / fig. A.3.1::

    frame --c1-- m1 --c2-- m2 -- ... --cn-- mn      (mn: the output member)

Everything here takes the masses ``m = (m1 .. mn)`` and the stiffnesses
``c = (c1 .. cn)`` as sequences, ``c[i]`` being the spring between mass i - 1
(the frame for i = 0) and mass i, so any n >= 1 and any positive values do.

Thesis formulas and where they live
    (4.33)  amplitudes as multiples of x_n, x_i = a_i x_n        -> :func:`rayleigh_quotient`
    (4.34)  V_max = 1/2 sum c_i (x_i - x_(i-1))^2                  -> :func:`energies`
    (4.35)  T_max = 1/2 w_e^2 sum m_i x_i^2                         -> :func:`energies`
    (4.36)  w_e^2 from V_max = T_max                                -> :func:`eq_4_36`
    (4.37)  static deflection by a load at m_n as the mode          -> :func:`static_mode`
    (4.38), (A.3.1)  the lowest eigenvalue by Rayleigh              -> :func:`rayleigh_eigenvalue`
    (4.39)  the period of the lowest natural vibration              -> :func:`rayleigh_period`
    (4.40), (A.3.2)  overall stiffness 1/c = sum 1/c_i              -> :func:`overall_stiffness`
    (A.3.3) exact eigenvalues from the characteristic determinant   -> :func:`exact_eigenvalues`
    (A.3.4) intermediate masses ignored, w_e^2 = c/m_n              -> :func:`approximate_eigenvalue`
    (A.3.5), (A.3.11)  range of validity                            -> :func:`within_validity`
    (A.3.6)-(A.3.10)  the two-DOF family of fig. A.3.8 / A.3.9      -> :func:`fig_A3_9_chain`, :func:`eq_A3_10`

Readings taken where the scan is garbled
    (4.36) is lost entirely.  Read as the ratio of the two energies with the
        amplitude of m_n cancelled: w_e^2 = sum c_i (a_i - a_(i-1))^2 / sum m_i a_i^2,
        a_0 = 0 (the frame), a_n = 1; this is what the text says is equated.
    (4.37) a_i = (sum_(j<=i) 1/c_j) / (sum_(j<=n) 1/c_j): under a load F at m_n every
        spring carries F, so the deflection at m_i is F sum_(j<=i) 1/c_j.
    (4.38) is printed as (4.36) with (4.37) inserted; the numerator collapses to the
        overall stiffness c (sum c_i (1/c_i)^2 c^2 = c), which is the form (A.3.1).
    (A.3.5) the sum of the intermediate contributions sum_(i<n) m_i a_i^2 must not
        exceed m_n/4 ("25 % of m_2", sec. A.3.5; sec. 4.6 says the same in words).
    (A.3.11) the sum of the intermediate masses m_1 + .. + m_(n-1) at most 3 m_n, the
        reading sec. 4.6 gives in words ("on condition that the sum of the
        intermediate masses is less than 3 times the mass on the free edge").
    (A.3.8) 1/c_1 + 1/c_2 = 1/c = 2 (the caption of fig. A.3.9 is garbled; "1/c is
        maintained at 2" is legible, and (A.3.9), w_e^2 = 0.4 = 2^-1/(1 + 1/4), and
        (A.3.10) both follow from it).
    Error.  App. 3 never defines it in legible text.  Taken as the relative error of
        the frequency (not of the eigenvalue), w_Rayleigh/w_exact - 1, since sec. 4.6
        speaks of "errors in the lowest natural frequency".

What the readings give against the printed numbers (checked in
thesis/checks/rayleigh_checks.py): fig. A.3.3 at m1 = 1 (contribution 25 %) 2.33 %
(printed 2.6 %, read from the graph); at m1 = 1.4: 4.0 % (printed 5 %; the 4 %
crossing is at m1 = 1.399); fig. A.3.9 at m1 = 3: 7.2 % by (A.3.9) and (A.3.10)
themselves (printed 4 %; the 4 % crossing is at m1 = 1.65).  So the rule
(A.3.5) + (A.3.11) bounds the two-DOF error by 7.2 %, not by the 4 % that
sec. 4.6 and A.3.6.3 state.
"""
from __future__ import annotations

import math
from typing import Sequence

import numpy as np
import sympy as sp

CONTRIBUTION_LIMIT = 0.25
"""(A.3.5): intermediate mass contributions at most 25 % of the output mass m_n."""

MASS_LIMIT = 3.0
"""(A.3.11): sum of the intermediate masses at most 3 m_n (sec. 4.6, sec. A.3.6.2)."""


# ---------------------------------------------------------------------------- numeric


def _chain(m: Sequence[float], c: Sequence[float], *, positive_masses: bool = False):
    m = np.asarray(m, dtype=float)
    c = np.asarray(c, dtype=float)
    if m.ndim != 1 or m.shape != c.shape or m.size == 0:
        raise ValueError("masses and stiffnesses must be two sequences of the same length n >= 1")
    if np.any(c <= 0) or not np.all(np.isfinite(c)):
        raise ValueError("stiffnesses must be positive and finite")
    if m[-1] <= 0 or np.any(m < 0) or (positive_masses and np.any(m <= 0)):
        raise ValueError("masses must be positive (intermediate ones may be 0 for Rayleigh)")
    return m, c


def overall_stiffness(c: Sequence[float]) -> float:
    """Overall stiffness c of the springs in series, 1/c = sum 1/c_i (4.40), (A.3.2)."""
    c = np.asarray(c, dtype=float)
    return float(1.0 / np.sum(1.0 / c))


def static_mode(c: Sequence[float]) -> np.ndarray:
    """Static deflection under a load at m_n, scaled to a_n = 1 (4.37).

    a_i is the flexibility between the frame and m_i over the overall flexibility:
    the ratio sec. 4.6 squares to weigh each mass.
    """
    flex = np.cumsum(1.0 / np.asarray(c, dtype=float))
    return flex / flex[-1]


def mass_contributions(m: Sequence[float], c: Sequence[float]) -> np.ndarray:
    """m_i a_i^2 for i = 1..n; the last one is m_n itself (the terms of (A.3.1))."""
    m, c = _chain(m, c)
    return m * static_mode(c) ** 2


def intermediate_contribution(m: Sequence[float], c: Sequence[float]) -> float:
    """sum_(i<n) m_i a_i^2, the measure of accuracy of sec. A.3.5 / (A.3.5), in mass units."""
    return float(np.sum(mass_contributions(m, c)[:-1]))


def equivalent_mass(m: Sequence[float], c: Sequence[float]) -> float:
    """The numerator of (4.39): m_n plus the intermediate contributions."""
    return float(np.sum(mass_contributions(m, c)))


def rayleigh_quotient(m: Sequence[float], c: Sequence[float], mode: Sequence[float]) -> float:
    """w_e^2 for an assumed mode x_i = a_i x_n (4.33), from V_max = T_max (4.34)-(4.36).

    ``mode`` holds a_1 .. a_n (any scale; the quotient is homogeneous of degree 0).
    """
    m, c = _chain(m, c)
    a = np.asarray(mode, dtype=float)
    if a.shape != m.shape:
        raise ValueError("one mode amplitude per mass")
    stretch = np.diff(np.concatenate(([0.0], a)))  # a_0 = 0: the frame does not move
    return float(np.sum(c * stretch**2) / np.sum(m * a**2))


def rayleigh_eigenvalue(m: Sequence[float], c: Sequence[float]) -> float:
    """Lowest eigenvalue by Rayleigh with the static deflection (4.38), (A.3.1).

    w_e^2 = c [m_n + sum_(i<n) m_i ((sum_(j<=i) 1/c_j)/(1/c))^2]^-1
    """
    m, c = _chain(m, c)
    return overall_stiffness(c) / equivalent_mass(m, c)


def rayleigh_period(m: Sequence[float], c: Sequence[float]) -> float:
    """Period of the lowest natural vibration (4.39): T_e = 2 pi sqrt(equivalent mass / c)."""
    m, c = _chain(m, c)
    return 2 * math.pi * math.sqrt(equivalent_mass(m, c) / overall_stiffness(c))


def approximate_eigenvalue(m: Sequence[float], c: Sequence[float]) -> float:
    """w_e^2 = c/m_n with the intermediate masses ignored (A.3.4)."""
    m, c = _chain(m, c)
    return overall_stiffness(c) / float(m[-1])


def chain_matrices(m: Sequence[float], c: Sequence[float]) -> tuple[np.ndarray, np.ndarray]:
    """Mass and stiffness matrices (M, K) of the chain of fig. A.3.1, M x'' + K x = 0.

    Row i of M^-1 K is row i of the determinant (A.3.3):
    -c_i/m_i, (c_i + c_(i+1))/m_i, -c_(i+1)/m_i, with c_(n+1) = 0 (free end).
    """
    m, c = _chain(m, c)
    n = m.size
    K = np.zeros((n, n))
    for i in range(n):
        K[i, i] += c[i]
        if i > 0:  # spring c_i between m_(i-1) and m_i
            K[i - 1, i - 1] += c[i]
            K[i - 1, i] -= c[i]
            K[i, i - 1] -= c[i]
    return np.diag(m), K


def exact_eigenvalues(m: Sequence[float], c: Sequence[float]) -> np.ndarray:
    """All eigenvalues w_e1^2 < .. < w_en^2 of the chain, the roots of (A.3.3), ascending.

    Solved as the symmetric tridiagonal M^-1/2 K M^-1/2, whose eigenvalues are those
    of the determinant (A.3.3) and which LAPACK solves stably for any n.
    """
    from scipy.linalg import eigh_tridiagonal

    m, c = _chain(m, c, positive_masses=True)
    c_next = np.append(c[1:], 0.0)
    diag = (c + c_next) / m
    off = -c[1:] / np.sqrt(m[:-1] * m[1:])
    return eigh_tridiagonal(diag, off, eigvals_only=True)


def exact_lowest_eigenvalue(m: Sequence[float], c: Sequence[float]) -> float:
    """w_e1^2, the lowest root of (A.3.3)."""
    return float(exact_eigenvalues(m, c)[0])


def two_dof_eigenvalues(m1, m2, c1, c2):
    """Both eigenvalues of the two-DOF chain in closed form (A.3.3 for n = 2), vectorised.

    m1 m2 l^2 - (m2 (c1 + c2) + m1 c2) l + c1 c2 = 0; the lower root is taken in the
    form 2 C/(B + sqrt(B^2 - 4 A C)), which does not cancel when m1 is small.
    """
    m1, m2, c1, c2 = (np.asarray(v, dtype=float) for v in (m1, m2, c1, c2))
    A = m1 * m2
    B = m2 * (c1 + c2) + m1 * c2
    C = c1 * c2
    root = np.sqrt(B * B - 4 * A * C)
    return 2 * C / (B + root), (B + root) / (2 * A)


def frequency_error(m: Sequence[float], c: Sequence[float], method: str = "rayleigh") -> float:
    """Relative error of the lowest natural frequency, w_method/w_exact - 1 (App. 3).

    ``method`` is "rayleigh" ((A.3.1)) or "approximate" ((A.3.4)).  Both are upper
    bounds of the exact value, so the error is >= 0.
    """
    estimate = {"rayleigh": rayleigh_eigenvalue, "approximate": approximate_eigenvalue}[method]
    return math.sqrt(estimate(m, c) / exact_lowest_eigenvalue(m, c)) - 1.0


def within_validity(m: Sequence[float], c: Sequence[float], *,
                    contribution_limit: float = CONTRIBUTION_LIMIT,
                    mass_limit: float = MASS_LIMIT) -> bool:
    """Is the chain inside the range of validity of (A.3.5) and (A.3.11)?

    (A.3.5): sum_(i<n) m_i a_i^2 <= m_n/4; (A.3.11): m_1 + .. + m_(n-1) <= 3 m_n.
    The thesis attaches "errors below 4 %" to this rule; its own (A.3.9), (A.3.10)
    give 7.2 % at the corner m_1 = 3 m_2 of the two-DOF family (module docstring).
    """
    m, c = _chain(m, c)
    mn = float(m[-1])
    return (intermediate_contribution(m, c) <= contribution_limit * mn * (1 + 1e-12)
            and float(np.sum(m[:-1])) <= mass_limit * mn * (1 + 1e-12))


# ------------------------------------------------------------ chains of the App. 3 figures


def fig_A3_3_chain(m1: float) -> tuple[list[float], list[float]]:
    """Fig. A.3.2 / A.3.3: two DOF, c1 = c2 = 1, m2 = 1, m1 varied."""
    return [float(m1), 1.0], [1.0, 1.0]


def equal_contribution_chain(n: int, contribution: float = 0.25,
                             flexibility: float = 2.0) -> tuple[list[float], list[float]]:
    """Figs A.3.4-A.3.6: n DOF, equal c_i, equal intermediate masses, m_n = 1.

    1/c = sum 1/c_i = ``flexibility`` in n equal parts, so c_i = n/flexibility and
    a_i = i/n; the intermediate masses are chosen so that sum_(i<n) m_i a_i^2 equals
    ``contribution`` (A.3.5 held at its limit, fig. A.3.7).
    """
    if n < 2:
        raise ValueError("the figures need at least one intermediate mass (n >= 2)")
    a = np.arange(1, n) / n
    m_mid = contribution / float(np.sum(a * a))
    return [m_mid] * (n - 1) + [1.0], [n / flexibility] * n


def fig_A3_9_chain(m1: float) -> tuple[list[float], list[float]]:
    """Fig. A.3.8 / A.3.9: two DOF, m2 = 1, (A.3.6)-(A.3.8) held as m1 varies.

    m1 ((1/c1)/(1/c))^2 = 1/4 with 1/c = 2 gives 1/c1 = 1/sqrt(m1) (A.3.7) and
    1/c2 = 2 - 1/sqrt(m1) (A.3.8), positive only for m1 > 1/4.
    """
    if m1 <= 0.25:
        raise ValueError("(A.3.6)-(A.3.8) need m1 > 1/4 m2 (c2 > 0)")
    s = math.sqrt(m1)
    return [float(m1), 1.0], [s, s / (2 * s - 1)]


def error_curve(chains, values) -> dict[str, np.ndarray]:
    """Exact and estimated lowest eigenvalues, and frequency errors, along a family.

    ``chains`` maps one parameter value to (m, c), e.g. :func:`fig_A3_3_chain`.
    Keys: x, exact (w_e1^2), exact2 (w_e2^2, NaN for n = 1), rayleigh, approximate,
    error_rayleigh, error_approximate (relative frequency errors).
    """
    rows = []
    for x in values:
        m, c = chains(x)
        lam = exact_eigenvalues(m, c)
        r, a = rayleigh_eigenvalue(m, c), approximate_eigenvalue(m, c)
        rows.append((x, lam[0], lam[1] if lam.size > 1 else np.nan, r, a,
                     math.sqrt(r / lam[0]) - 1, math.sqrt(a / lam[0]) - 1))
    cols = np.array(rows, dtype=float).T
    keys = ("x", "exact", "exact2", "rayleigh", "approximate", "error_rayleigh", "error_approximate")
    return dict(zip(keys, cols))


def error_curve_A3_3(m1_values) -> dict[str, np.ndarray]:
    """Fig. A.3.3 a/b: frequencies and errors of the two-DOF chain c1 = c2 = m2 = 1 against m1."""
    return error_curve(fig_A3_3_chain, m1_values)


def error_curve_A3_7(n_values=(2, 3, 4)) -> dict[str, np.ndarray]:
    """Fig. A.3.7: against the number of DOF at constant contribution 1/4 and 1/c = 2."""
    return error_curve(equal_contribution_chain, n_values)


def error_curve_A3_9(m1_values) -> dict[str, np.ndarray]:
    """Fig. A.3.9: the two-DOF family of (A.3.6)-(A.3.8) against m1/m2 (> 1/4)."""
    return error_curve(fig_A3_9_chain, m1_values)


def m1_at_error(curve: str, error: float) -> float:
    """The m1/m2 at which the Rayleigh frequency error of fig. A.3.3 or A.3.9 reaches ``error``.

    The error grows monotonically with m1 on both families, so the crossing is unique.
    """
    from scipy.optimize import brentq

    chains = {"A3_3": fig_A3_3_chain, "A3_9": fig_A3_9_chain}[curve]
    lo = 1e-6 if curve == "A3_3" else 0.25 + 1e-9
    return float(brentq(lambda x: frequency_error(*chains(x)) - error, lo, 1e3, xtol=1e-12))


def write_figures(directory) -> list:
    """Draw figs A.3.3, A.3.7 and A.3.9 as PNG files into ``directory`` (on request only)."""
    from pathlib import Path

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, curve, x, title in (
            ("fig_A3_3.png", error_curve_A3_3, np.linspace(0.05, 5, 200),
             "fig. A.3.3: c1 = c2 = 1, m2 = 1"),
            ("fig_A3_9.png", error_curve_A3_9, np.linspace(0.3, 5, 200),
             "fig. A.3.9: contribution 1/4, 1/c1 + 1/c2 = 2")):
        d = curve(x)
        fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
        a.plot(d["x"], np.sqrt(d["exact"]), label="w_e1 exact (A.3.3)")
        a.plot(d["x"], np.sqrt(d["exact2"]), label="w_e2 exact (A.3.3)")
        a.plot(d["x"], np.sqrt(d["rayleigh"]), "--", label="Rayleigh (A.3.1)")
        a.plot(d["x"], np.sqrt(d["approximate"]), ":", label="m1 ignored (A.3.4)")
        a.set_xlabel("m1/m2")
        a.set_ylabel("natural frequency")
        a.legend()
        b.plot(d["x"], 100 * d["error_rayleigh"], label="Rayleigh")
        b.plot(d["x"], 100 * d["error_approximate"], label="m1 ignored")
        b.set_xlabel("m1/m2")
        b.set_ylabel("error of w_e1 [%]")
        b.set_ylim(0, 25)
        b.grid(True)
        b.legend()
        fig.suptitle(title)
        fig.savefig(out / name, dpi=100)
        plt.close(fig)
        paths.append(out / name)
    d = error_curve_A3_7(range(2, 11))
    fig, a = plt.subplots(figsize=(5, 4))
    a.plot(d["x"], d["exact"], "o-", label="w_e1^2 exact (A.3.3)")
    a.plot(d["x"], d["rayleigh"], "s--", label="Rayleigh (A.3.1)")
    a.set_xlabel("number of degrees of freedom")
    a.set_ylabel("lowest eigenvalue")
    a.legend()
    fig.suptitle("fig. A.3.7: contribution 1/4, 1/c = 2")
    fig.savefig(out / "fig_A3_7.png", dpi=100)
    plt.close(fig)
    paths.append(out / "fig_A3_7.png")
    return paths


# --------------------------------------------------------------------------- symbolic

w2 = sp.Symbol("w_e2", positive=True)
"""The squared angular frequency w_e^2 of the assumed harmonic motion."""
xn = sp.Symbol("x_n", positive=True)
"""Amplitude of the output mass m_n, the reference of (4.33)."""


def chain_symbols(n: int) -> tuple[list[sp.Symbol], list[sp.Symbol]]:
    """Positive symbols m1 .. mn and c1 .. cn."""
    m = list(sp.symbols(f"m1:{n + 1}", positive=True))
    c = list(sp.symbols(f"c1:{n + 1}", positive=True))
    return m, c


def mode_symbols(n: int) -> list:
    """a_1 .. a_(n-1) as symbols and a_n = 1: the mode (4.33) in units of x_n."""
    return list(sp.symbols(f"a1:{n}", real=True)) + [sp.Integer(1)]


def energies(n: int):
    """(V_max, T_max) of the chain in the mode (4.33), x_i = a_i x_n (4.34), (4.35).

    The velocity amplitude of a harmonic motion is w_e x_i, hence the w_e^2 in T_max.
    """
    m, c = chain_symbols(n)
    a = mode_symbols(n)
    x = [ai * xn for ai in a]
    stretch = [x[0]] + [x[i] - x[i - 1] for i in range(1, n)]
    V = sp.Rational(1, 2) * sum(ci * s**2 for ci, s in zip(c, stretch))
    T = sp.Rational(1, 2) * w2 * sum(mi * xi**2 for mi, xi in zip(m, x))
    return V, T


def eq_4_36(n: int) -> sp.Expr:
    """w_e^2 in terms of the mode amplitudes a_i: the root of V_max = T_max (4.36)."""
    V, T = energies(n)
    (sol,) = sp.solve(sp.Eq(V, T), w2)
    return sp.factor(sol)


def static_mode_symbolic(n: int) -> list:
    """(4.37) in symbols: a_i = sum_(j<=i) 1/c_j / sum_(j<=n) 1/c_j."""
    _, c = chain_symbols(n)
    total = sum(1 / cj for cj in c)
    return [sum(1 / cj for cj in c[: i + 1]) / total for i in range(n)]


def eq_4_38_derived(n: int) -> sp.Expr:
    """(4.36) with the static deflection (4.37) inserted: the derivation of (4.38)."""
    expr = eq_4_36(n)
    a = mode_symbols(n)
    return expr.subs(dict(zip(a[:-1], static_mode_symbolic(n)[:-1])), simultaneous=True)


def eq_A3_1_printed(n: int) -> sp.Expr:
    """(A.3.1) as printed: w_e^2 = c [m_n + sum_(i<n) m_i ((sum_(j<=i) 1/c_j)/(1/c))^2]^-1."""
    m, c = chain_symbols(n)
    inv_c = sum(1 / cj for cj in c)  # (A.3.2)
    contributions = sum(m[i] * (sum(1 / cj for cj in c[: i + 1]) / inv_c) ** 2 for i in range(n - 1))
    return (1 / inv_c) / (m[-1] + contributions)


def eq_4_39_printed(n: int) -> sp.Expr:
    """(4.39) as printed: T_e = 2 pi sqrt(sum_i m_i ((sum_(j<=i) 1/c_j)/(1/c))^2 / c)."""
    m, c = chain_symbols(n)
    inv_c = sum(1 / cj for cj in c)
    mass = sum(m[i] * (sum(1 / cj for cj in c[: i + 1]) / inv_c) ** 2 for i in range(n))
    return 2 * sp.pi * sp.sqrt(mass * inv_c)


def characteristic_matrix_A3_3(n: int, lam: sp.Symbol) -> sp.Matrix:
    """The determinant (A.3.3) as printed: row i has -c_i/m_i, (c_i + c_(i+1))/m_i - lambda,
    -c_(i+1)/m_i, with c_(n+1) = 0."""
    m, c = chain_symbols(n)
    c_ext = c + [sp.Integer(0)]
    A = sp.zeros(n, n)
    for i in range(n):
        A[i, i] = (c_ext[i] + c_ext[i + 1]) / m[i] - lam
        if i > 0:
            A[i, i - 1] = -c_ext[i] / m[i]
        if i < n - 1:
            A[i, i + 1] = -c_ext[i + 1] / m[i]
    return A


def two_dof_eigenvalues_symbolic(m=None, c=None) -> tuple[sp.Expr, sp.Expr]:
    """(w_e1^2, w_e2^2) of two DOF from the determinant (A.3.3) in closed form.

    ``m``, ``c``: two expressions each (default: the symbols m1, m2, c1, c2).  The
    determinant times m1 m2 is the quadratic a2 l^2 + a1 l + a0, a2 = m1 m2 (n = 2).
    """
    ms, cs = chain_symbols(2)
    lam = sp.Symbol("lambda")
    det = sp.expand(characteristic_matrix_A3_3(2, lam).det() * ms[0] * ms[1])
    a2, a1, a0 = sp.Poly(det, lam).all_coeffs()
    values = dict(zip(ms + cs, list(m or ms) + list(c or cs)))
    a2, a1, a0 = (sp.sympify(k).subs(values) for k in (a2, a1, a0))
    root = sp.sqrt(a1**2 - 4 * a2 * a0)
    return (-a1 - root) / (2 * a2), (-a1 + root) / (2 * a2)


m1_sym = sp.Symbol("m1", positive=True)
"""The intermediate mass m1/m2 of figs A.3.8, A.3.9."""


def fig_A3_9_symbolic():
    """(m, c) of fig. A.3.8 in the symbol m1 (m2 = 1): c1 = sqrt(m1) (A.3.7), 1/c2 = 2 - 1/c1 (A.3.8)."""
    c1 = sp.sqrt(m1_sym)
    c2 = 1 / (2 - 1 / c1)
    return [m1_sym, sp.Integer(1)], [c1, c2]


def eq_A3_10() -> tuple[sp.Expr, sp.Expr]:
    """(A.3.10) as printed, (w_e1^2, w_e2^2) of fig. A.3.8:

    1/2 {(2 + sqrt m1)/(2 sqrt m1 - 1) -/+ [((2 + sqrt m1)/(2 sqrt m1 - 1))^2 - 4/(2 sqrt m1 - 1)]^(1/2)}
    """
    s = sp.sqrt(m1_sym)
    A = (2 + s) / (2 * s - 1)
    root = sp.sqrt(A**2 - 4 / (2 * s - 1))
    return (A - root) / 2, (A + root) / 2
