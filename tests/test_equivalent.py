"""Natural frequencies and equivalent masses of CAMSHAFT-2 (thesis secs 5.5.7, 5.6):
the closed forms of thesis/theory/equivalent.py against each other and against derivations
from the energies of the frozen system."""
import math

import numpy as np
import pytest
import sympy as sp

from camdyn.thesis.theory import equivalent as eq
from camdyn.thesis.checks.check import matches_printed

S, FA, FV, W2 = eq.slope, eq.Fa, eq.Fv, eq.w_ex2_sym


def _dimensionless_frozen():
    """M, K of CAMSHAFT-2 frozen at slope s, from the energies of derive/models/camshaft2.py
    (kinetic 1/2 X'^2 + B'^2/(2 Fv), potential 1/2 w_ex^2 [(H - X)^2 + (T - B)^2/Fa]) linearized
    at X = H: K = Hessian of the potential, the H'' (H - X) term vanishing."""
    M = sp.diag(1, 1 / FV)
    K = W2 * sp.Matrix([[1, -S], [-S, S**2 + 1 / FA]])
    return M, K


def test_5_39_solves_the_frequency_equation_of_the_frozen_system():
    """(5.39) are the roots of (5.37), written here from the energies of fig. 5.3 (sec. 5.5.7)."""
    poly = eq.frequency_polynomial()
    for root in eq.eigenvalues_reduced(eq.m_x, eq.c_x, eq.m_beta, eq.c_beta, eq.tan_a):
        assert sp.simplify(poly.subs(eq.lam, root)) == 0


def test_5_43_is_5_39_with_5_40_to_5_42():
    """Insertion of (5.40)-(5.42) in (5.39) gives (5.43): c_x/m_x = w_ex^2, c_beta'/m_beta' = w_eb^2,
    tan a = (dH/dB) tan a_me, Fa = (c_x/c_beta') tan^2 a_me (5.12a), w_eb^2 = w_ex^2 Fv/Fa."""
    w_eb2 = W2 * FV / FA
    subs = {eq.c_x: W2 * eq.m_x, eq.c_beta: w_eb2 * eq.m_beta, eq.tan_a: S * eq.tan_me}
    tan_me = sp.sqrt(FA * w_eb2 * eq.m_beta / (W2 * eq.m_x))
    for reduced, printed in zip(eq.eigenvalues_reduced(eq.m_x, eq.c_x, eq.m_beta, eq.c_beta, eq.tan_a),
                                eq.eigenvalues(S, FA, FV, W2)):
        assert sp.simplify(reduced.subs(subs).subs(eq.tan_me, tan_me) - printed) == 0


def test_5_43_are_the_eigenvalues_of_the_dimensionless_model():
    """det(K - lambda M) of the dimensionless CAMSHAFT-2 (5.15), (5.16) vanishes at both roots (5.43)."""
    M, K = _dimensionless_frozen()
    for root in eq.eigenvalues(S, FA, FV, W2):
        assert sp.simplify((K - root * M).det()) == 0


def test_5_46_product_is_independent_of_the_slope():
    """w_el^2 w_eh^2 = w_ex^2 w_eb^2 (5.46): no slope left, in (5.43) and in (5.37)."""
    low, high = eq.eigenvalues(S, FA, FV, W2)
    product = sp.simplify(sp.expand(low * high))
    assert S not in product.free_symbols
    assert sp.simplify(product - W2**2 * FV / FA) == 0
    assert eq.tan_a not in eq.frequency_polynomial().subs(eq.lam, 0).free_symbols


def test_5_43_zero_slope_gives_the_uncoupled_eigenvalues():
    """At dH/dB = 0 the motions are uncoupled (sec. 5.5.7.1): w_ex^2 and w_eb^2 = w_ex^2 Fv/Fa, the
    lower one first, in both cases of sec. 5.5.7 (w_ex < w_eb: Fv > Fa, and w_ex > w_eb)."""
    for ratio in (sp.Integer(3), sp.Rational(1, 3)):
        values = [sp.simplify(e) for e in eq.eigenvalues(0, FA, ratio * FA, W2)]
        assert values == sorted([W2, ratio * W2], key=lambda v: float(v / W2))


def test_5_48_equals_5_49_with_the_slope_dependent_follower_mass_and_5_51():
    """Sec. 5.6 (1), (2): (5.48) is (5.49) with m = m_x + m_z' ((1/c_z')/(1/c))^2 and m_tan (5.51)."""
    c_c = 1 / eq.constant_flexibility(eq.c_x, eq.c_z)
    c_tan = 1 / eq.tangential_flexibility(eq.c_beta, eq.c_y)
    four = eq.equivalent_mass_4dof(eq.m_x, eq.m_z, eq.m_beta, eq.m_y, eq.c_x, eq.c_z, eq.c_beta,
                                   eq.c_y, eq.tan_a)
    m_tan = eq.cam_mass(eq.m_beta, eq.m_y, eq.c_beta, eq.c_y)
    exact = eq.follower_mass(eq.m_x, eq.m_z, eq.c_x, eq.c_z, eq.tan_a, c_tan)
    assert sp.simplify(four - eq.equivalent_mass_2dof(exact, m_tan, c_c, c_tan, eq.tan_a)) == 0


def test_5_50_drops_the_slope_with_a_small_nonnegative_error():
    """With (5.50) (tan a = 0 in the follower mass) (5.49) equals (5.48) at zero slope only; the
    difference is m_z' (c_c^2 - c^2)/c_z'^2 >= 0, c (5.47) <= c_c: "only a slight error"."""
    c_c = 1 / eq.constant_flexibility(eq.c_x, eq.c_z)
    c_tan = 1 / eq.tangential_flexibility(eq.c_beta, eq.c_y)
    four = eq.equivalent_mass_4dof(eq.m_x, eq.m_z, eq.m_beta, eq.m_y, eq.c_x, eq.c_z, eq.c_beta,
                                   eq.c_y, eq.tan_a)
    two = eq.equivalent_mass_2dof(eq.follower_mass(eq.m_x, eq.m_z, eq.c_x, eq.c_z),
                                  eq.cam_mass(eq.m_beta, eq.m_y, eq.c_beta, eq.c_y), c_c, c_tan, eq.tan_a)
    c = eq.overall_stiffness(eq.c_x, eq.c_z, eq.c_beta, eq.c_y, eq.tan_a)
    diff = sp.simplify(two - four)
    assert diff != 0
    assert sp.simplify(diff - eq.m_z * (c_c**2 - c**2) / eq.c_z**2) == 0
    assert sp.simplify(diff.subs(eq.tan_a, 0)) == 0


def test_5_47_is_4_5_with_4_3_and_4_4():
    """1/c = 1/c_x + 1/c_z' + tan^2 a (1/c_beta' + 1/c_y') = 1/c_c + tan^2 a/c_tan."""
    lhs = 1 / eq.overall_stiffness(eq.c_x, eq.c_z, eq.c_beta, eq.c_y, eq.tan_a)
    rhs = 1 / eq.overall_stiffness_2dof(1 / eq.constant_flexibility(eq.c_x, eq.c_z),
                                        1 / eq.tangential_flexibility(eq.c_beta, eq.c_y), eq.tan_a)
    assert sp.simplify(lhs - rhs) == 0


def test_5_52_of_the_two_dof_mechanism_is_5_14():
    """Without m_z', m_y' and with rigid z', y' (fig. 5.1), (5.50)-(5.52) give
    Fv = m_x h_m^2/(J beta_m^2) (5.14b), m_beta' = J/R'^2, tan a_me = h_m'/(R' beta_m) (4.13)."""
    J, R, h_m, beta_m = sp.symbols("J R h_m beta_m", positive=True)
    fv = eq.flywheel_factor(eq.follower_mass(eq.m_x, 0, eq.c_x, sp.oo),
                            eq.cam_mass(J / R**2, 0, eq.c_beta, sp.oo), h_m / (R * beta_m))
    assert sp.simplify(fv - eq.m_x * h_m**2 / (J * beta_m**2)) == 0


def test_4_14_of_the_two_dof_mechanism_is_5_12b():
    """Fa = (c_c/c_tan) tan^2 a_me (4.14) with c_c = c_x, c_tan = c_beta' = k/R'^2 is
    c_x h_m^2/(k beta_m^2) (5.12b), free of the pitch radius (sec. 5.3.2.1)."""
    k, R, h_m, beta_m = sp.symbols("k R h_m beta_m", positive=True)
    fa = eq.shaft_factor(1 / eq.constant_flexibility(eq.c_x, sp.oo),
                         1 / eq.tangential_flexibility(k / R**2, sp.oo), h_m / (R * beta_m))
    assert sp.simplify(fa - eq.c_x * h_m**2 / (k * beta_m**2)) == 0


def test_5_53_is_4_38_with_5_49_to_5_52():
    """(5.53) as printed is c/m_eq, (4.38), with (4.5), (5.49)-(5.51), (4.14), (5.52)."""
    assert sp.simplify(eq.rayleigh_4_38_two_dof() - eq.lowest_eigenvalue_rayleigh(S, FA, FV, W2)) == 0


def test_5_53_is_the_rayleigh_quotient_of_the_static_deflection():
    """An independent route to (5.53): the Rayleigh quotient of the dimensionless frozen CAMSHAFT-2
    with its static deflection under a load at X, v = K^-1 e_X, as the mode (sec. 4.6)."""
    M, K = _dimensionless_frozen()
    v = K.inv() * sp.Matrix([1, 0])
    quotient = (v.T * K * v)[0] / (v.T * M * v)[0]
    assert sp.simplify(quotient - eq.lowest_eigenvalue_rayleigh(S, FA, FV, W2)) == 0


def test_5_53_at_zero_slope_is_w_ex2():
    """Sec. 5.6: "w_el^2 = w_ex^2 at zero slope (dH/dB = 0)" by (5.53), for every Fa, Fv."""
    assert sp.simplify(eq.lowest_eigenvalue_rayleigh(0, FA, FV, W2) - W2) == 0


def test_sec_5_6_values_at_maximum_slope():
    """Fa = Fv = 2, dH/dB = 2 (sec. 5.6): (5.43) gives 0.1 w_ex^2, (5.53) 0.101 (9/89), (4.32) 0.111
    (1/9); and (5.43) at zero slope w_ex^2 (w_eb = w_ex because Fa = Fv)."""
    two = sp.Integer(2)
    low = eq.eigenvalues(two, two, two)[0]
    assert sp.simplify(low - (5 - 2 * sp.sqrt(6))) == 0
    assert matches_printed(float(low), "0.1")
    assert eq.lowest_eigenvalue_rayleigh(two, two, two) == sp.Rational(9, 89)
    assert matches_printed(float(sp.Rational(9, 89)), "0.101")
    assert matches_printed(float(eq.eigenvalue_camshaft1(two, two)), "0.111")
    assert [sp.simplify(e) for e in eq.eigenvalues(0, two, two)] == [1, 1]


def test_5_53_bounds_5_43_from_above_and_4_32_bounds_both():
    """A Rayleigh quotient is never below the lowest eigenvalue; the massless cam of (4.32) lies above
    both (the cam mass lowers the frequency).  Over slopes 0..2, Fa 0.1..3.35, Fv 0.1..10."""
    s = np.linspace(0.0, 2.0, 21)[:, None, None]
    fa = np.array([0.1, 0.4, 1.0, 2.0, 3.35])[None, :, None]
    fv = np.array([0.1, 0.64, 2.0, 7.5, 10.0])[None, None, :]
    exact = eq.eigenvalues(s, fa, fv)[0]
    rayleigh = eq.lowest_eigenvalue_rayleigh(s, fa, fv)
    one_dof = eq.eigenvalue_camshaft1(s, fa) * np.ones_like(exact)
    assert np.all(rayleigh >= exact * (1 - 1e-12))
    assert np.all(one_dof >= rayleigh * (1 - 1e-12))


def test_numeric_eigenvalues_match_a_matrix_solve():
    """The closed form (5.43) against numpy's eigenvalues of the dimensionless frozen system."""
    for s, fa, fv in [(0.3, 0.4, 1.14), (2.0, 3.35, 7.5), (1.0, 1.5, 0.1)]:
        M = np.diag([1.0, 1.0 / fv])
        K = np.array([[1.0, -s], [-s, s * s + 1.0 / fa]])
        ref = np.sort(np.linalg.eigvals(np.linalg.solve(M, K)).real)
        assert np.allclose(eq.eigenvalues(s, fa, fv), ref, rtol=1e-12, atol=0)
        assert math.isclose(eq.eigenvalue_product(fa, fv), ref[0] * ref[1], rel_tol=1e-12)


def test_follower_mass_refuses_a_slope_without_c_tan():
    with pytest.raises(ValueError, match="c_tan"):
        eq.follower_mass(1.0, 0.1, 1.0, 2.0, tan_alpha=0.5)
