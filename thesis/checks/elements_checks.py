"""Checks of thesis ch. 2 (element energies, assembly, reduction) against what it prints.

The printed formulas are typed in below as the thesis prints them, with the
reading taken where the scan is garbled; camdyn's values come from
camdyn.thesis.theory.elements / assembly / reduction, where every energy is
integrated from its displacement function.  Formulas lost in the scan
((2.8), (2.12), (2.14), (2.24), (2.31), (2.34)-(2.38)) are compared through
the printed equations or matrices that show their coefficients ((2.32),
(2.33), (2.39), (2.40)).
"""
from __future__ import annotations

import math
from functools import lru_cache

import sympy as sp

from .check import Check

# -- printed forms (typed in; readings in the docstrings) ---------------------------------

x1, x2 = sp.symbols("x1 x2", real=True)
EA, EI, GIp, l, m, J, r2, i = sp.symbols("EA EI GIp l m J r2 i", positive=True)


def _c4():
    from camdyn.thesis.theory.assembly import EI4, a, i1
    return 3 * EI4 / (a**3 * i1 * (i1 - 1) ** 2)                 # after (2.31), as printed


def printed_2_40():
    """(M, C, B, K) of (2.40) in (x4, x5, psi6 l6, psi7 l8, x8), reading of the scan.

    Mass entries as read: m4 a34 + 1/3 m5, 1/6 m5, 1/3 m5 + 33/140 m6,
    11/280 m6, 2/105 m6 + i2^2 J7/(3 l8^2), i2 J7/(6 l8^2), J7/(3 l8^2) +
    2/105 m8, 11/280 m8, 33/140 m8; stiffness c4 + (EA/l)5, -(EA/l)5,
    (EA/l)5 + 3(EI/l^3)6, -3(EI/l^3)6, 3(EI/l^3)6 + i2^2 (GIp)7/(l8^2 l7),
    -i2 (GIp)7/(l8^2 l7), (GIp)7/(l8^2 l7) + 3(EI/l^3)8, -3(EI/l^3)8,
    3(EI/l^3)8; right-hand side -(1/2 m4 a24 i1, 0, 0, 0, 0) h'' +
    (c4 i1, 0, 0, 0, 0) h.  a14, a24, a34 are returned as symbols.
    """
    from camdyn.thesis.theory.assembly import EA5, EI6, EI8, GIp7, J7, i1, i2, l5, l6, l7, l8, m4, m5, m6, m8
    a14, a24, a34 = sp.symbols("a14 a24 a34")
    R = sp.Rational
    M = sp.Matrix([
        [m4 * a34 + R(1, 3) * m5, R(1, 6) * m5, 0, 0, 0],
        [R(1, 6) * m5, R(1, 3) * m5 + R(33, 140) * m6, R(11, 280) * m6, 0, 0],
        [0, R(11, 280) * m6, R(2, 105) * m6 + i2**2 * J7 / (3 * l8**2), i2 * J7 / (6 * l8**2), 0],
        [0, 0, i2 * J7 / (6 * l8**2), J7 / (3 * l8**2) + R(2, 105) * m8, R(11, 280) * m8],
        [0, 0, 0, R(11, 280) * m8, R(33, 140) * m8]])
    c4, k5, k6, k7, k8 = _c4(), EA5 / l5, 3 * EI6 / l6**3, GIp7 / (l8**2 * l7), 3 * EI8 / l8**3
    C = sp.Matrix([
        [c4 + k5, -k5, 0, 0, 0],
        [-k5, k5 + k6, -k6, 0, 0],
        [0, -k6, k6 + i2**2 * k7, -i2 * k7, 0],
        [0, 0, -i2 * k7, k7 + k8, -k8],
        [0, 0, 0, -k8, k8]])
    B = sp.Matrix([R(1, 2) * m4 * a24 * i1, 0, 0, 0, 0])
    K = sp.Matrix([c4 * i1, 0, 0, 0, 0])
    return M, C, B, K, (a14, a24, a34)


def printed_2_45():
    """(M, C, K) of (2.45): M = diag(1/3 m4, m5 + 1/3 m6, 0, J7/l8^2, 1/3 m8), C as (2.40).

    Reading: the first diagonal entry is scanned "tm,"; it is read 1/3 m4,
    the rigid lever of length b pivoting at its end ((2.41) with the sum
    a14 + a24 + a34 = 1/3 of the element), like 1/3 m6 and 1/3 m8 (2.44).
    """
    from camdyn.thesis.theory.assembly import J7, l8, m4, m5, m6, m8
    _, C, _, K, _ = printed_2_40()
    M = sp.diag(m4 / 3, m5 + m6 / 3, 0, J7 / l8**2, m8 / 3)
    return M, C, K


def printed_2_46():
    """(M, C, K) of (2.46) in (x4, x5, x8); c678 as read in camdyn.thesis.theory.assembly.c678.

    Reading: the mass matrix is lost in the scan; it is (2.45) without the
    rows of psi6 l6 and psi7 l8 (J7 put to zero).  Stiffness as far as
    readable: c4 + (EA/l)5, -(EA/l)5, -i2 c678, c678; the x5 entry
    (EA/l)5 + i2^2 c678 follows from the spring c678 acting between i2 x5 and x8.
    """
    from camdyn.thesis.theory.assembly import EA5, c678, i1, i2, l5, m4, m5, m6, m8
    c4, k5, k = _c4(), EA5 / l5, c678()
    M = sp.diag(m4 / 3, m5 + m6 / 3, m8 / 3)
    C = sp.Matrix([[c4 + k5, -k5, 0], [-k5, k5 + i2**2 * k, -i2 * k], [0, -i2 * k, k]])
    K = sp.Matrix([c4 * i1, 0, 0])
    return M, C, K


def printed_2_47(n: int):
    """(M, C, K) of (2.47): diag(m_i); C_ii = c_i + c_{i+1} (c_n last), C_i,i+1 = -c_{i+1};
    K_ii = c_i, K_i,i+1 = -c_{i+1}."""
    from camdyn.thesis.theory.assembly import chain_symbols
    _, _, ms, cs = chain_symbols(n)
    M = sp.diag(*ms)
    C, K = sp.zeros(n, n), sp.zeros(n, n)
    for j in range(n):
        C[j, j] = cs[j] + (cs[j + 1] if j + 1 < n else 0)
        K[j, j] = cs[j]
        if j + 1 < n:
            C[j, j + 1] = C[j + 1, j] = -cs[j + 1]
            K[j, j + 1] = -cs[j + 1]
    return M, C, K


# -- the exact reference for sec. 2.2.2.1 -------------------------------------------------

def cantilever_beta(mass_ratio: float = 0.0) -> float:
    """First root beta l of the Euler-Bernoulli cantilever (2.1c) with end mass m2 = mass_ratio m1.

    Frequency equation of a clamped-free uniform beam with a point mass at
    the free end: 1 + cos(bl) cosh(bl) + mu bl (cos(bl) sinh(bl) -
    sin(bl) cosh(bl)) = 0, mu = m2/m1; mu = 0 is the plain cantilever,
    1 + cos(bl) cosh(bl) = 0.  omega = (bl)^2 (EI/(m1 l^3))^(1/2).
    """
    from scipy.optimize import brentq

    def f(b, mu):
        return 1 + math.cos(b) * math.cosh(b) + mu * b * (math.cos(b) * math.sinh(b)
                                                          - math.sin(b) * math.cosh(b))

    b0 = brentq(f, 1.0, 3.0, args=(0.0,), xtol=1e-15)
    if mass_ratio == 0:
        return b0
    # the end mass only lowers the root: f > 0 near 0, f(b0) < 0 for mu > 0
    return brentq(f, 1e-6, b0, args=(mass_ratio,), xtol=1e-15)


def omega_exact(mass_ratio: float = 0.0) -> float:
    """Exact lowest natural frequency in units (EI/(m1 l^3))^(1/2)."""
    return cantilever_beta(mass_ratio) ** 2


# -- the comparisons ---------------------------------------------------------------------

def _zero(expr) -> bool:
    # rational functions of the parameters: cancel decides, simplify only as a fallback
    return sp.cancel(sp.expand(expr)) == 0 or sp.simplify(expr) == 0


def _zero_matrix(A) -> bool:
    return all(_zero(e) for e in A)


@lru_cache(maxsize=None)
def _elements():
    from camdyn.thesis.theory import elements as E
    return {
        "bar": E.bar(x1, x2, EA, l, m), "shaft": E.shaft(x1, x2, GIp, l, J, r2, i),
        "beam": E.beam(x1, x2, EI, l, m),
        "bar.rigid": E.bar(x1, x2, EA, l, m, "rigid"),
        "shaft.rigid": E.shaft(x1, x2, GIp, l, J, r2, i, "rigid"),
        "beam.rigid": E.beam(x1, x2, EI, l, m, "rigid"),
    }


def _lever(kinetic="elastic"):
    # the symbols of fig. 2.4, so that the (cached) element is built once for all checks
    from camdyn.thesis.theory.assembly import EI4, a, h, i1, m4, x4
    from camdyn.thesis.theory.elements import overhung_lever
    return overhung_lever(h, x4, EI4, a, i1, m4, kinetic)


def _bar_V():
    return _zero(_elements()["bar"].V - EA / (2 * l) * (x2 - x1) ** 2)              # (2.6)


def _bar_eom():
    """(2.32)-(2.33) for component 5 between x4 and x5, left-hand sides (Q's aside)."""
    from camdyn.thesis.theory import elements as E
    from camdyn.thesis.theory.assembly import EA5, l5, m5, x4, x5
    e = E.bar(x4, x5, EA5, l5, m5)
    lhs = E.lagrange_equations(e.T, e.V, e.nodes, "bar")
    R, k = sp.Rational, EA5 / l5
    printed = [R(1, 2) * m5 * (R(2, 3) * E.accel(x4) + R(1, 3) * E.accel(x5)) - k * (x5 - x4),
               R(1, 2) * m5 * (R(1, 3) * E.accel(x4) + R(2, 3) * E.accel(x5)) + k * (x5 - x4)]
    return all(_zero(d - p) for d, p in zip(lhs, printed))


def _beam_F():
    from camdyn.thesis.theory.elements import cantilever_deflection
    _, F = cantilever_deflection(x1, x2, EI, l)
    return _zero(F - 3 * EI * (x2 - x1) / l**3)                                   # (2.19)


def _beam_xe():
    from camdyn.thesis.theory.elements import cantilever_deflection, z
    xe, _ = cantilever_deflection(x1, x2, EI, l)
    return _zero(xe - 3 * (x2 - x1) / (2 * l**3) * (l * z**2 - z**3 / 3))         # (2.20)


def _beam_V():
    return _zero(_elements()["beam"].V - 3 * EI / (2 * l**3) * (x2 - x1) ** 2)      # (2.22)


def _beam_eom_2_39():
    """x8 equation of component 8 with the follower spring c_g (2.39)."""
    from camdyn.thesis.theory import elements as E
    from camdyn.thesis.theory.assembly import EI8, c_g, l8, m8, psi7_l8, x8
    e8, cg = E.beam(psi7_l8, x8, EI8, l8, m8), E.spring(sp.Integer(0), x8, c_g)
    lhs = E.lagrange_equations(e8.T + cg.T, e8.V + cg.V, (psi7_l8, x8), "beam8")
    R, k = sp.Rational, 3 * EI8 / l8**3
    printed = (R(1, 2) * m8 * (R(11, 140) * E.accel(psi7_l8) + R(33, 70) * E.accel(x8))
               + (k + c_g) * x8 - k * psi7_l8)
    return _zero(lhs[1] - printed)


def _generic_eom():
    """(2.28)-(2.29) from (2.25)-(2.26) by Lagrange's equation (2.27)."""
    from camdyn.thesis.theory import elements as E
    g = E.generic()
    lhs = E.lagrange_equations(g.T, g.V, g.nodes, "generic")
    xjdd, xj1dd = E.accel(E.xj), E.accel(E.xj1)
    m_, c_, a1, a2, a3 = E.m_, E.c_, E.a1, E.a2, E.a3
    printed = [m_ / 2 * (2 * a1 * xjdd + a2 * xj1dd) - c_ * (E.xj1 - E.xj),
               m_ / 2 * (a2 * xjdd + 2 * a3 * xj1dd) + c_ * (E.xj1 - E.xj)]
    return all(_zero(d - p) for d, p in zip(lhs, printed))


def _lever_c4():
    from camdyn.thesis.theory.assembly import m4
    from camdyn.thesis.theory.elements import generic_form
    c, *_ = generic_form(_lever(), m4)
    return _zero(c - _c4())


def _lever_eom_2_30():
    from camdyn.thesis.theory import elements as E
    from camdyn.thesis.theory.assembly import h, i1, m4, x4
    e = _lever()
    a14, a24, _ = _lever_coeffs()
    lhs = E.lagrange_equations(e.T, e.V, e.nodes, "lever")
    c4 = _c4()
    printed = (sp.Rational(1, 2) * m4 * (2 * a14 * i1**2 * E.accel(h) + a24 * i1 * E.accel(x4))
               - c4 * (i1 * x4 - i1**2 * h))
    return _zero(lhs[0] - printed)


def _rigid_2_41():
    """Rigid T of every element = (2.26) with x_j = x_{j+1}: 1/2 m (a1 + a2 + a3) x_{j+1}'^2."""
    from camdyn.thesis.theory.assembly import m4, x4
    from camdyn.thesis.theory.elements import generic_form, rate
    els = _elements()
    cases = [(els[n], els[n + ".rigid"], mass, x2)
             for n, mass in (("bar", m), ("shaft", J / r2**2), ("beam", m))]
    cases.append((_lever(), _lever("rigid"), m4, x4))
    for elastic, rigid, mass, node in cases:
        _, A1, A2, A3 = generic_form(elastic, mass)
        if not _zero(rigid.T - mass / 2 * (A1 + A2 + A3) * rate(node) ** 2):
            return False
    return True


def _rigid(name, printed):
    from camdyn.thesis.theory.elements import rate
    return lambda: _zero(_elements()[name].T - printed(rate(x2)))


def _fig24(kinetic="elastic"):
    from camdyn.thesis.theory.assembly import fig_2_4
    return fig_2_4(kinetic)


@lru_cache(maxsize=None)
def _lever_coeffs():
    from camdyn.thesis.theory.assembly import m4
    from camdyn.thesis.theory.elements import generic_form
    _, a14, a24, a34 = generic_form(_lever(), m4)
    return a14, a24, a34


def _with_lever(A, syms):
    return A.subs(dict(zip(syms, _lever_coeffs())))


def _M_2_40():
    M, *_, syms = printed_2_40()
    return _zero_matrix(_fig24().M - _with_lever(M, syms))


def _C_2_40():
    _, C, *_ = printed_2_40()
    return _zero_matrix(_fig24().C - C)


def _rhs_2_40():
    _, _, B, K, syms = printed_2_40()
    s = _fig24()
    return _zero_matrix(s.B - _with_lever(B, syms)) and _zero_matrix(s.K - K)


def _first_rows_2_40():
    """The rows of h in the first (unnumbered) display before (2.40), with Qh:
    a14 m4 i1^2, 1/2 m4 a24 i1 (mass); c4 i1^2, -c4 i1 (stiffness)."""
    from camdyn.thesis.theory.assembly import COORDS_2_4, assemble, fig_2_4_elements, h, i1, m4
    s = assemble(fig_2_4_elements(), (h,) + COORDS_2_4)
    a14, a24, _ = _lever_coeffs()
    c4 = _c4()
    want_M = [a14 * m4 * i1**2, m4 * a24 * i1 / 2, 0, 0, 0, 0]
    want_C = [c4 * i1**2, -c4 * i1, 0, 0, 0, 0]
    return all(_zero(s.M[0, j] - want_M[j]) and _zero(s.C[0, j] - want_C[j]) for j in range(6))


def _M_2_45():
    M, _, _ = printed_2_45()
    return _zero_matrix(_fig24("rigid").M - M)


def _C_K_2_45():
    _, C, K = printed_2_45()
    s = _fig24("rigid")
    return _zero_matrix(s.C - C) and _zero_matrix(s.K - K) and _zero_matrix(s.B)


def _psi6_massless():
    from camdyn.thesis.theory.assembly import COORDS_2_4, psi6_l6
    j = COORDS_2_4.index(psi6_l6)
    return all(e == 0 for e in _fig24("rigid").M.row(j))


def _three_dof_2_46():
    from camdyn.thesis.theory.assembly import three_dof
    M, C, K = printed_2_46()
    s = three_dof()
    return _zero_matrix(s.M - M) and _zero_matrix(s.C - C) and _zero_matrix(s.K - K)


def _chain_2_47():
    from camdyn.thesis.theory.assembly import chain
    for n in range(1, 6):
        s = chain(n)
        M, C, K = printed_2_47(n)
        if not (_zero_matrix(s.M - M) and _zero_matrix(s.C - C) and _zero_matrix(s.K - K)):
            return False
    return True


def _omega_form():
    from camdyn.thesis.theory.elements import clamped_beam_omega_squared
    return _zero(clamped_beam_omega_squared(0) - sp.Rational(140, 11))


def _omega(kinetic):
    from camdyn.thesis.theory.elements import clamped_beam_omega_squared
    return lambda: math.sqrt(float(clamped_beam_omega_squared(0, kinetic)))


def _rigid_error_percent():
    return 100 * (omega_exact() - _omega("rigid")()) / omega_exact()


@lru_cache(maxsize=None)
def _rules():
    from camdyn.thesis.theory import reduction as R
    return R.derive_rules()


def _reduction(name, printed):
    def compute():
        from camdyn.thesis.theory import reduction as R
        s, m_, c_, d_, eta = sp.symbols("s m c d eta", positive=True)
        value = {"length": s, "mass": m_, "stiffness": c_, "damper": d_, "viscosity": eta,
                 "frame": c_}[name]
        if name == "frame":
            arm_a, arm_b = sp.symbols("a b", positive=True)
            return _zero(_rules()[name] - printed(value, arm_a, arm_b))
        return _zero(_rules()[name] - printed(value, R.i))
    return compute


def _lever_2_51():
    from camdyn.thesis.theory.elements import Lever
    arm_a, arm_b, theta = sp.symbols("a b theta", positive=True)
    lv = Lever(arm_a, arm_b)
    # both arms turn through the same small angle: strokes a theta and b theta
    return _zero(lv.output(arm_a * theta) - arm_b * theta) and _zero(lv.i - arm_b / arm_a)


def checks() -> list[Check]:
    from camdyn.thesis.theory import reduction as R

    ident = lambda key, item, ref, fn, note="": Check(  # noqa: E731
        f"ch2.{key}", item, ref, None, fn, rule="identity", note=note)
    return [
        # a. longitudinally moving bar
        ident("bar.V_2_6", "bar: V integrated over the linear stretch (2.4), (2.5)", "(2.6)", _bar_V),
        ident("bar.eom_2_32_2_33", "bar: Lagrange's equations of component 5 from the integrated T, V",
              "(2.32), (2.33)", _bar_eom, "(2.8) is lost in the scan; its coefficients 2/3, 1/3 are "
              "read from (2.32)-(2.33)"),
        # c. transversely moving beam
        ident("beam.F_2_19", "beam: end force for the elastic deflection x2 - x1", "(2.19)", _beam_F),
        ident("beam.xe_2_20", "beam: static deflection under an end force", "(2.20)", _beam_xe,
              "scan garbled; read as 3 (x2 - x1)/(2 l^3) (l z^2 - z^3/3)"),
        ident("beam.V_2_22", "beam: V integrated over (2.20)", "(2.22)", _beam_V),
        ident("beam.eom_2_39", "beam 8 with follower spring: x8 equation", "(2.39)", _beam_eom_2_39,
              "(2.24) and (2.38) are lost in the scan; 11/140 and 33/70 are read from (2.39)"),
        # generic forms
        ident("generic.eom_2_28_2_29", "generic component: Lagrange (2.27) on (2.25)-(2.26)",
              "(2.28), (2.29)", _generic_eom),
        # component 4
        ident("lever4.c4", "roller lever: stiffness at x4 from the overhung-beam deflection",
              "after (2.31)", _lever_c4, "printed 3 (EI)4/(a^3 i1 (i1 - 1)^2)"),
        ident("lever4.eom_2_30", "roller lever: h equation, x_j = i1 h", "(2.30)", _lever_eom_2_30,
              "a14, a24 integrated from the overhung-beam deflection (their printed values are lost)"),
        # rigid kinetic energy
        ident("rigid.T_2_41", "rigid T = (2.26) with x_j = x_{j+1}, bar, shaft, beam, lever",
              "(2.41)", _rigid_2_41),
        ident("rigid.T_2_42", "rigid bar: T = 1/2 m x'^2", "(2.42)",
              _rigid("bar.rigid", lambda v: m * v**2 / 2)),
        ident("rigid.T_2_43", "rigid shaft: T = 1/2 J/r2^2 (phi2' r2)^2", "(2.43)",
              _rigid("shaft.rigid", lambda v: J / r2**2 * v**2 / 2)),
        ident("rigid.T_2_44", "rigid beam pivoting about one end: T = 1/2 (1/3 m) x'^2", "(2.44)",
              _rigid("beam.rigid", lambda v: m / 3 * v**2 / 2), "also sec. 2.2.2.2, fig. 2.10"),
        # fig. 2.4
        ident("fig24.rows_h", "fig. 2.4: rows of h before (2.40) (a14 m4 i1^2, 1/2 m4 a24 i1, "
              "c4 i1^2, -c4 i1)", "before (2.40)", _first_rows_2_40),
        ident("fig24.M_2_40", "fig. 2.4: mass matrix with elastic displacement functions",
              "(2.40)", _M_2_40, "entries as read from the scan, see printed_2_40"),
        ident("fig24.C_2_40", "fig. 2.4: stiffness matrix", "(2.40)", _C_2_40,
              "entries as read from the scan, see printed_2_40"),
        ident("fig24.rhs_2_40", "fig. 2.4: input terms -1/2 m4 a24 i1 h'' + c4 i1 h", "(2.40)", _rhs_2_40),
        ident("fig24.M_2_45", "fig. 2.4: diagonal mass matrix of the rigid kinetic energies",
              "(2.45)", _M_2_45, "first entry scanned 'tm,', read 1/3 m4"),
        ident("fig24.C_2_45", "fig. 2.4: stiffness and input of (2.45) as in (2.40), no h'' term",
              "(2.45)", _C_K_2_45),
        ident("fig24.psi6_massless", "fig. 2.4: the mass term of psi6 l6 is zero", "after (2.45)",
              _psi6_massless),
        ident("fig24.three_dof_2_46", "fig. 2.4: psi6 l6, psi7 l8 condensed (J7 = 0)", "(2.46)",
              _three_dof_2_46, "c678 formula lost in the scan; read as the series stiffness of "
              "6, 7, 8 at radius l8"),
        # chain
        ident("chain.2_47", "chain of fig. 2.12 from its energies, n = 1..5", "(2.47), (2.48)", _chain_2_47),
        # sec. 2.2.2.1: accuracy of the assumed shape
        ident("clamped.omega2_140_11", "clamped beam, m2 = 0: omega^2 = 140/11 EI/(m1 l^3)",
              "sec. 2.2.2.1", _omega_form),
        Check("ch2.clamped.omega_element", "clamped beam, m2 = 0, element (2.22)+(2.24)",
              "sec. 2.2.2.1", "3.57", _omega("elastic"), note="in units (EI/(m1 l^3))^(1/2)",
              exact=True),
        Check("ch2.clamped.omega_exact", "clamped beam, exact first root of 1 + cos bl cosh bl = 0",
              "sec. 2.2.2.1, (2.1c)", "3.52", omega_exact, note="(bl)^2, bl by brentq", exact=True),
        Check("ch2.clamped.omega_rigid", "clamped beam, m2 = 0, rigid kinetic energy (2.44)",
              "sec. 2.2.2.2", "3", _omega("rigid"), rule="rel:1e-12", exact=True),
        Check("ch2.clamped.rigid_error", "error of the rigid kinetic energy, percent of the exact value",
              "sec. 2.2.2.2", "15", _rigid_error_percent, note="'about 15 %'", exact=True),
        # reduction
        ident("lever.i_2_51", "lever: i = h_out/h_in = b/a", "(2.51)", _lever_2_51),
        ident("reduce.length_2_55", "reduced linear dimension s' = i s", "(2.55)",
              _reduction("length", R.length)),
        ident("reduce.mass_2_56", "reduced mass m' = m/i^2", "(2.56)", _reduction("mass", R.mass)),
        ident("reduce.stiffness_2_57", "reduced stiffness c' = c/i^2", "(2.57)",
              _reduction("stiffness", R.stiffness)),
        ident("reduce.frame_2_4_3", "frame stiffness at the pivot reduced by ((a + b)/a)^2",
              "sec. 2.4.3", _reduction("frame", R.frame_stiffness)),
        ident("reduce.damper_2_58", "reduced damper d' = d/i^2", "(2.58)", _reduction("damper", R.damper)),
        ident("reduce.viscosity_2_59", "reduced viscosity eta' = eta/i^3 from the squeeze law",
              "(2.59), (A.4.11)", _reduction("viscosity", R.viscosity),
              "all linear dimensions of the film (b, s, R_e) reduced by (2.55)"),
    ]
