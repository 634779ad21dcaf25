"""Assembly of element energies into mass and stiffness matrices, thesis sec. 2.2.2.

The thesis writes the equations of each component with (2.28)-(2.29) and adds
them to eliminate the nodal forces Q_j; it notes that the same set follows
from T and V of the complete system, which is what :func:`assemble` does:
with the free coordinates x and the prescribed inputs h (the cam motion),

    M x'' + C x = -B h'' + K h,

M = d2T/dx'dx', C = d2V/dxdx, B = d2T/dx'dh', K = -d2V/dxdh.  This is the
form of (2.40) (whose right-hand side is -(1/2 m4 a24 i1, 0, ...) h'' +
(c4 i1, 0, ...) h) and of (2.48), M x'' + C x = K h.

Contents: the mechanism of fig. 2.4 with elastic displacement functions in T
((2.40), static and dynamic coupling) or rigid-body kinetic energies ((2.45),
diagonal M); static condensation of massless coordinates to the three-DOF
form (2.46); the series chain of fig. 2.12 (2.47)-(2.48); the frequency
equation (2.50).
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

from .elements import Element, bar, beam, overhung_lever, rate, shaft, spring


@dataclass(frozen=True)
class System:
    """M x'' + C x = -B h'' + K h for coordinates ``coords`` and inputs ``inputs``."""

    coords: tuple
    inputs: tuple
    M: sp.Matrix
    C: sp.Matrix
    B: sp.Matrix
    K: sp.Matrix

    def subs(self, values) -> "System":
        f = lambda A: A.subs(values)  # noqa: E731
        return System(self.coords, self.inputs, f(self.M), f(self.C), f(self.B), f(self.K))


def assemble(elements, coords, inputs=()) -> System:
    """Mass and stiffness matrices from the summed element energies.

    Raises ValueError when T or V is not a quadratic form of the coordinates
    and inputs (the linearisation the thesis assumes: mutual positions hardly
    change during the rise, sec. 2.2.2.1 (4)).
    """
    T = sum((e.T for e in elements), sp.Integer(0))
    V = sum((e.V for e in elements), sp.Integer(0))
    q, v = tuple(coords), tuple(rate(x) for x in coords)
    hs, hv = tuple(inputs), tuple(rate(x) for x in inputs)
    n, k = len(q), len(hs)
    M = sp.Matrix(n, n, lambda r, s: sp.factor(sp.diff(T, v[r], v[s])))
    C = sp.Matrix(n, n, lambda r, s: sp.factor(sp.diff(V, q[r], q[s])))
    B = sp.Matrix(n, k, lambda r, s: sp.factor(sp.diff(T, v[r], hv[s])))
    K = sp.Matrix(n, k, lambda r, s: sp.factor(-sp.diff(V, q[r], hs[s])))
    # what remains after the quadratic parts in x must not depend on x
    for expr, vars_ in ((T, v + hv), (V, q + hs)):
        H = sp.hessian(expr, vars_)
        vec = sp.Matrix(vars_)
        if sp.cancel(sp.expand(expr - (vec.T * H * vec)[0] / 2)) != 0:
            raise ValueError("energies are not quadratic forms of the coordinates")
    return System(q, hs, M, C, B, K)


# -- the cam-operated transfer mechanism of fig. 2.4 -------------------------------------

h, x4, x5, psi6_l6, psi7_l8, x8 = sp.symbols("h x4 x5 psi6_l6 psi7_l8 x8", real=True)
"""Cam input h(t) and the nodal coordinates of fig. 2.4: x4, x5, psi6 l6, psi7 l8, x8."""

m4, m5, m6, m8, J7 = sp.symbols("m4 m5 m6 m8 J7", positive=True)
EI4, a, i1 = sp.symbols("EI4 a i1", positive=True)
EA5, l5, EI6, l6, GIp7, l7, EI8, l8 = sp.symbols("EA5 l5 EI6 l6 GIp7 l7 EI8 l8", positive=True)
c_g = sp.Symbol("c_g", nonnegative=True)
i2 = l8 / l6
"""Transmission of the shaft, i2 = l8/l6 (after (2.45))."""

COORDS_2_4 = (x4, x5, psi6_l6, psi7_l8, x8)


def fig_2_4_elements(kinetic: str = "elastic", follower_spring: bool = False) -> list[Element]:
    """Components 4 to 8 of fig. 2.4, each from its displacement function.

    Reading of the mechanism (the figures are missing in the scan): taken
    from the nodal coordinates named in the text, the forces of fig. 2.9 as
    described, and the entries of (2.40) that are readable.

    4 roller lever (pivot, roller at a, x4 at b = i1 a), 5 bar x4-x5, 6 beam
    pivoting on the shaft (psi6 l6) with its end at x5, 7 shaft from psi6 (at
    radius l6) to psi7 (at radius l8), 8 output beam pivoting on the shaft
    (psi7 l8) with its end at x8, optional follower spring c_g from x8 to the
    frame ((2.38)-(2.39); the thesis drops it from (2.40) on).
    """
    out = [
        overhung_lever(h, x4, EI4, a, i1, m4, kinetic),
        bar(x4, x5, EA5, l5, m5, kinetic),
        beam(psi6_l6, x5, EI6, l6, m6, kinetic),
        shaft(psi6_l6, psi7_l8, GIp7, l7, J7, l8, i2, kinetic),
        beam(psi7_l8, x8, EI8, l8, m8, kinetic),
    ]
    if follower_spring:
        out.append(spring(sp.Integer(0), x8, c_g))
    return out


@lru_cache(maxsize=None)
def fig_2_4(kinetic: str = "elastic", follower_spring: bool = False) -> System:
    """The five-coordinate system of fig. 2.4 with the cam motion h as input.

    ``kinetic="elastic"``: T from the elastic displacement functions, the
    mass matrix of (2.40) with dynamic coupling; ``"rigid"``: rigid-body
    kinetic energies (2.41)-(2.44), the diagonal mass matrix of (2.45).  The
    stiffness matrix is the same in both.
    """
    return assemble(fig_2_4_elements(kinetic, follower_spring), COORDS_2_4, (h,))


def c678() -> sp.Expr:
    """Stiffness of beam 6, shaft 7 and beam 8 in series, measured at radius l8 (fig. 2.11).

    Reading taken (the formula after "The stiffness of that system is given
    by c678" is lost in the scan): the three compliances add once each is
    reduced to radius l8 by (2.57); beam 6 sits at radius l6, so its
    compliance counts i2^2 times:
        1/c678 = i2^2 l6^3/(3 (EI)6) + l7 l8^2/(GIp)7 + l8^3/(3 (EI)8).
    """
    return 1 / (i2**2 * l6**3 / (3 * EI6) + l7 * l8**2 / GIp7 + l8**3 / (3 * EI8))


def condense(system: System, keep) -> System:
    """Static condensation: eliminate the coordinates not in ``keep``.

    With x = (x_k, x_e) the eliminated coordinates follow the kept ones
    statically, x_e = -C_ee^-1 (C_ek x_k - K_e h), and the energies are
    rewritten in x_k: C_kk - C_ke C_ee^-1 C_ek, K_k - C_ke C_ee^-1 K_e and
    the mass matrix transformed the same way (P^T M P, with P the static
    shape; the input inertia B picks up M times the static response to h).
    This is exact when the eliminated coordinates carry no mass (their
    equations are then algebraic), which is the case the thesis uses for
    psi6 l6 (no mass in (2.45)) and psi7 l8 (J7 put to zero) on the way to
    (2.46); with mass on them it is only the Guyan approximation.
    """
    keep = list(keep)
    ki = [system.coords.index(x) for x in keep]
    ei = [j for j in range(len(system.coords)) if j not in ki]
    C, M = system.C, system.M
    Cee, Cek = C.extract(ei, ei), C.extract(ei, ki)
    cols = list(range(system.K.cols))
    Ke = system.K.extract(ei, cols)
    Cee_inv = Cee.inv()
    # x = P x_k + R h: the static shape of the eliminated coordinates
    P = sp.zeros(len(system.coords), len(ki))
    R = sp.zeros(len(system.coords), system.K.cols)
    for r, j in enumerate(ki):
        P[j, r] = 1
    Pe, Re = -Cee_inv * Cek, Cee_inv * Ke
    for r, j in enumerate(ei):
        P[j, :] = Pe[r, :]
        R[j, :] = Re[r, :]
    simp = lambda A: A.applyfunc(sp.factor)  # noqa: E731
    Mr = simp(P.T * M * P)
    Cr = simp(P.T * C * P)
    Kr = simp(P.T * (system.K - C * R))
    Br = simp(P.T * (system.B + M * R))
    return System(tuple(keep), system.inputs, Mr, Cr, Br, Kr)


@lru_cache(maxsize=None)
def three_dof() -> System:
    """The three-DOF system (2.46): (2.45) with J7 -> 0, psi6 l6 and psi7 l8 eliminated."""
    return condense(fig_2_4("rigid").subs({J7: 0}), (x4, x5, x8))


# -- the series chain of fig. 2.12 and the frequency equation ----------------------------

def chain_symbols(n: int):
    """(x, h, m, c) symbol tuples x1..xn, h1..hn, m1..mn, c1..cn of fig. 2.12."""
    x = sp.symbols(f"x1:{n + 1}", real=True)
    hh = sp.symbols(f"h1:{n + 1}", real=True)
    m = sp.symbols(f"m1:{n + 1}", positive=True)
    c = sp.symbols(f"c1:{n + 1}", positive=True)
    return x, hh, m, c


def chain(n: int) -> System:
    """n lumped masses in series, spring c_i from x_{i-1} + h_i(t) to x_i (x_0 = frame), fig. 2.12.

    Derived from the energies T = sum 1/2 m_i x_i'^2 and
    V = sum 1/2 c_i (x_i - x_{i-1} - h_i)^2; the result is (2.47),
    M x'' + C x = K h (2.48), with C tridiagonal (c_i + c_{i+1} on the
    diagonal, c_n last) and K upper bidiagonal (c_i, -c_{i+1}).  Reading of
    the figure: input h_i acts at the frame end of spring i, as the rows
    c_i h_i - c_{i+1} h_{i+1} of the right-hand side of (2.47) require.
    """
    from .elements import lumped_mass

    if n < 1:
        raise ValueError("a chain needs at least one mass")
    x, hh, m, c = chain_symbols(n)
    elements = [lumped_mass(x[j], m[j]) for j in range(n)]
    for j in range(n):
        left = (x[j - 1] if j else sp.Integer(0)) + hh[j]
        elements.append(spring(left, x[j], c[j]))
    return assemble(elements, x, hh)


LAMBDA = sp.Symbol("lambda")
"""The eigenvalue of (2.50), lambda = omega^2 (D^2 replaced by -lambda)."""


def frequency_equation(M: sp.Matrix, C: sp.Matrix, lam: sp.Symbol = LAMBDA) -> sp.Expr:
    """The left-hand side of (2.50), |-lambda E + C M^-1|, a polynomial in lambda.

    M must be invertible: the thesis takes degrees of freedom only where
    there is mass (after (2.48)).
    """
    M, C = sp.Matrix(M), sp.Matrix(C)
    if sp.simplify(M.det()) == 0:
        raise ValueError("the mass matrix is singular: condense the massless coordinates first")
    # Berkowitz keeps the determinant a polynomial in lambda (no division)
    return sp.expand((-lam * sp.eye(M.rows) + C * M.inv()).det(method="berkowitz"))


def eigenvalues(M, C) -> list[float]:
    """The roots lambda = omega^2 of (2.50) for numeric M, C, ascending.

    Floats are taken as exact rationals first, so that the polynomial is exact
    and only its roots are approximated.
    """
    exact = lambda A: sp.Matrix(A).applyfunc(lambda v: sp.nsimplify(v, rational=True))  # noqa: E731
    poly = sp.Poly(frequency_equation(exact(M), exact(C)), LAMBDA)
    roots = poly.nroots(n=30, maxsteps=500)
    return sorted(float(sp.re(r)) for r in roots)
