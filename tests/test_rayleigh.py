"""Rayleigh's method (sec. 4.6, (4.33)-(4.40)) and its accuracy study (App. 3).

The printed values are compared by `camdyn check --topic rayleigh`
(camdyn/thesis/checks/rayleigh_checks.py); these tests cover the properties around
them, each against the thesis or an independent computation.
"""
import math

import numpy as np
import pytest
import scipy.linalg
import sympy as sp
from scipy.optimize import brentq

from camdyn.thesis.theory import rayleigh as r
from camdyn.thesis.checks.check import matches_printed


def _random_chain(rng, n):
    return np.exp(rng.normal(0, 1, n)), np.exp(rng.normal(0, 1, n))


def test_one_dof_rayleigh_is_exact(rng):
    """n = 1: the static deflection is the only mode, so (A.3.1), (A.3.4) and the exact c1/m1 coincide."""
    for _ in range(20):
        m, c = _random_chain(rng, 1)
        exact = c[0] / m[0]
        assert r.rayleigh_eigenvalue(m, c) == pytest.approx(exact, rel=1e-14)
        assert r.approximate_eigenvalue(m, c) == pytest.approx(exact, rel=1e-14)
        assert r.exact_lowest_eigenvalue(m, c) == pytest.approx(exact, rel=1e-14)
        assert r.frequency_error(m, c) == pytest.approx(0.0, abs=1e-14)
        assert r.rayleigh_period(m, c) == pytest.approx(2 * math.pi * math.sqrt(m[0] / c[0]), rel=1e-14)


@pytest.mark.parametrize("n", [2, 3, 5, 8, 13])
def test_exact_eigenvalues_against_generalized_eigenproblem(rng, n):
    """(A.3.3) by the tridiagonal solver against scipy's dense generalized K v = lambda M v."""
    for _ in range(10):
        m, c = _random_chain(rng, n)
        M, K = r.chain_matrices(m, c)
        reference = scipy.linalg.eigh(K, M, eigvals_only=True)
        np.testing.assert_allclose(r.exact_eigenvalues(m, c), reference, rtol=1e-10)


@pytest.mark.parametrize("n", [2, 3, 4, 6, 10, 20])
def test_rayleigh_is_an_upper_bound(rng, n):
    """Rayleigh's quotient of any trial mode bounds the lowest eigenvalue from above, and
    ignoring masses (A.3.4) raises it further: exact <= (A.3.1) <= (A.3.4)."""
    for _ in range(50):
        m, c = _random_chain(rng, n)
        exact = r.exact_lowest_eigenvalue(m, c)
        ray = r.rayleigh_eigenvalue(m, c)
        assert exact <= ray * (1 + 1e-12)
        assert ray <= r.approximate_eigenvalue(m, c) * (1 + 1e-12)
        assert r.frequency_error(m, c) >= -1e-12


def test_rayleigh_quotient_is_stationary_at_the_eigenvectors(rng):
    """(4.36) with an exact eigenvector returns its eigenvalue (scipy's vectors, independent of (4.37)),
    and with the static deflection (4.37) it returns (A.3.1)."""
    for n in (2, 4, 7):
        m, c = _random_chain(rng, n)
        M, K = r.chain_matrices(m, c)
        lam, vec = scipy.linalg.eigh(K, M)
        for k in range(n):
            assert r.rayleigh_quotient(m, c, vec[:, k]) == pytest.approx(lam[k], rel=1e-10)
        assert r.rayleigh_quotient(m, c, r.static_mode(c)) == pytest.approx(r.rayleigh_eigenvalue(m, c),
                                                                             rel=1e-13)


def test_static_mode_is_the_deflection_under_a_tip_load(rng):
    """(4.37) against K^-1 F with a unit load at m_n, scaled to a_n = 1."""
    m, c = _random_chain(rng, 6)
    _, K = r.chain_matrices(m, c)
    load = np.zeros(6)
    load[-1] = 1.0
    x = np.linalg.solve(K, load)
    np.testing.assert_allclose(r.static_mode(c), x / x[-1], rtol=1e-12)
    assert x[-1] == pytest.approx(1 / r.overall_stiffness(c), rel=1e-12)  # (4.40)


def test_error_is_second_order_in_the_intermediate_masses():
    """The mode error is O(eps) when the intermediate masses are eps, so Rayleigh's eigenvalue
    error is O(eps^2): dividing the masses by 10 divides the error by about 100."""
    c = [1.0, 2.0, 0.7, 1.5]

    def err(eps):
        m = [eps, 2 * eps, 0.5 * eps, 1.0]
        return r.rayleigh_eigenvalue(m, c) / r.exact_lowest_eigenvalue(m, c) - 1

    ratio = err(1e-2) / err(1e-3)
    assert ratio == pytest.approx(100, rel=0.05)


def test_three_dof_chain_of_fig_3_6():
    """Sec. 3.7.2: unit masses and stiffnesses give w_e^2 = 0.198, 1.555, 3.247 (thesis)."""
    lam = r.exact_eigenvalues([1, 1, 1], [1, 1, 1])
    for value, printed in zip(lam, ("0.198", "1.555", "3.247")):
        assert matches_printed(value, printed)


def test_two_dof_closed_form(rng):
    """The vectorised quadratic of the 2 x 2 (A.3.3) against the tridiagonal solver."""
    for _ in range(50):
        m, c = _random_chain(rng, 2)
        lo, hi = r.two_dof_eigenvalues(m[0], m[1], c[0], c[1])
        np.testing.assert_allclose([lo, hi], r.exact_eigenvalues(m, c), rtol=1e-12)


def test_eq_A3_10_numerically():
    """Printed (A.3.10) evaluated on m1 = 0.3 .. 10 against the eigenvalues of the fig. A.3.8 chain."""
    f = sp.lambdify(r.m1_sym, r.eq_A3_10(), "numpy")
    for m1 in (0.3, 0.5, 1.0, 2.0, 3.0, 10.0):
        np.testing.assert_allclose(f(m1), r.exact_eigenvalues(*r.fig_A3_9_chain(m1)), rtol=1e-12)
    # and the chain holds (A.3.6)-(A.3.8) exactly
    for m1 in (0.3, 3.0):
        m, c = r.fig_A3_9_chain(m1)
        assert r.intermediate_contribution(m, c) == pytest.approx(0.25, rel=1e-14)
        assert 1 / r.overall_stiffness(c) == pytest.approx(2.0, rel=1e-14)
        assert r.rayleigh_eigenvalue(m, c) == pytest.approx(0.4, rel=1e-14)  # (A.3.9)


def test_two_dof_symbolic_roots(rng):
    """The roots SymPy derives from the determinant (A.3.3), evaluated, against the numeric solver."""
    lo, hi = r.two_dof_eigenvalues_symbolic()
    (m1, m2), (c1, c2) = r.chain_symbols(2)
    f = sp.lambdify((m1, m2, c1, c2), (lo, hi), "math")
    for _ in range(20):
        m, c = _random_chain(rng, 2)
        np.testing.assert_allclose(f(*m, *c), r.exact_eigenvalues(m, c), rtol=1e-12)


def test_eq_A3_10_comparison_detects_a_wrong_formula():
    """The sum-and-product comparison of the check app3.eqA3_10.identity rejects (A.3.10) with
    4/(2 sqrt m1 - 1) changed to 3/(2 sqrt m1 - 1)."""
    s = sp.sqrt(r.m1_sym)
    A = (2 + s) / (2 * s - 1)
    wrong = ((A - sp.sqrt(A**2 - 3 / (2 * s - 1))) / 2, (A + sp.sqrt(A**2 - 3 / (2 * s - 1))) / 2)
    d1, d2 = r.two_dof_eigenvalues_symbolic(*r.fig_A3_9_symbolic())
    assert sp.simplify(sp.expand(d1 * d2) - sp.expand(wrong[0] * wrong[1])) != 0
    p1, p2 = r.eq_A3_10()
    assert sp.simplify(sp.expand(d1 * d2) - sp.expand(p1 * p2)) == 0


def test_eq_4_36_as_read():
    """(4.36), lost in the scan, as derived from (4.34) = (4.35) for three masses."""
    a1, a2 = sp.symbols("a1 a2", real=True)
    (m1, m2, m3), (c1, c2, c3) = r.chain_symbols(3)
    expected = (c1 * a1**2 + c2 * (a2 - a1) ** 2 + c3 * (1 - a2) ** 2) / (m1 * a1**2 + m2 * a2**2 + m3)
    assert sp.cancel(r.eq_4_36(3) - expected) == 0


def test_eq_4_38_comparison_detects_another_mode():
    """The comparison of app3.eq4_38.identity fails when (4.36) gets another mode than (4.37),
    e.g. the linear a_1 = 1/2 (which is (4.37) only for c1 = c2)."""
    derived = r.eq_4_36(2).subs(sp.Symbol("a1", real=True), sp.Rational(1, 2))
    assert sp.cancel(sp.together(derived - r.eq_A3_1_printed(2))) != 0
    (_, _), (c1, c2) = r.chain_symbols(2)
    assert sp.cancel(sp.together((derived - r.eq_A3_1_printed(2)).subs(c2, c1))) == 0


def test_fig_A3_3_closed_forms_at_m1_equal_m2():
    """c1 = c2 = m1 = m2 = 1: w_e1^2 = (3 - sqrt 5)/2, Rayleigh 2/5, (A.3.4) 1/2, so the frequency
    errors are sqrt(4/5/(3 - sqrt 5)) - 1 = 2.33 % and sqrt(1/(3 - sqrt 5)) - 1 = 14.4 %."""
    d = r.error_curve_A3_3([1.0])
    assert d["exact"][0] == pytest.approx((3 - math.sqrt(5)) / 2, rel=1e-14)
    assert d["exact2"][0] == pytest.approx((3 + math.sqrt(5)) / 2, rel=1e-14)
    assert d["error_rayleigh"][0] == pytest.approx(math.sqrt(0.8 / (3 - math.sqrt(5))) - 1, rel=1e-12)
    assert d["error_approximate"][0] == pytest.approx(math.sqrt(1 / (3 - math.sqrt(5))) - 1, rel=1e-12)


def test_fig_A3_3_highest_frequency_is_far_from_the_lowest():
    """Sec. A.3.5 (1): w_e2 stays far from w_e1 even for m1 > m2.  With c1 = c2 = m2 = 1 the ratio
    lambda2/lambda1 depends on a^2/b = (2 + m1)^2/m1 only, smallest (8) at m1 = 2, where
    w_e2/w_e1 = (sqrt 8 + 2)/(sqrt 8 - 2) to the power 1/2 = 1 + sqrt 2."""
    m1 = np.linspace(0.05, 20, 4000)
    d = r.error_curve_A3_3(m1)
    ratio = np.sqrt(d["exact2"] / d["exact"])
    assert ratio.min() == pytest.approx(1 + math.sqrt(2), rel=1e-6)
    assert m1[np.argmin(ratio)] == pytest.approx(2.0, abs=0.01)


def test_fig_A3_3_and_A3_9_error_curves():
    """Both families: Rayleigh's error grows with m1 and stays far below that of (A.3.4)
    (sec. A.3.5 (3)); the 4 % crossings against an independent root search on the closed form."""
    for curve, m1 in ((r.error_curve_A3_3, np.linspace(0.05, 5, 200)),
                      (r.error_curve_A3_9, np.linspace(0.26, 5, 200))):
        d = curve(m1)
        assert np.all(np.diff(d["error_rayleigh"]) > 0)
        assert np.all(d["error_rayleigh"] < d["error_approximate"])

    def err_A3_3(m1):
        lo, _ = r.two_dof_eigenvalues(m1, 1.0, 1.0, 1.0)
        return math.sqrt(0.5 / (1 + m1 / 4) / lo) - 1.04

    def err_A3_9(m1):
        s = math.sqrt(m1)
        lo, _ = r.two_dof_eigenvalues(m1, 1.0, s, s / (2 * s - 1))
        return math.sqrt(0.4 / lo) - 1.04

    assert r.m1_at_error("A3_3", 0.04) == pytest.approx(brentq(err_A3_3, 0.1, 10, xtol=1e-13), rel=1e-9)
    assert r.m1_at_error("A3_9", 0.04) == pytest.approx(brentq(err_A3_9, 0.3, 10, xtol=1e-13), rel=1e-9)
    # the thesis's "1.4" (sec. A.3.5 (2)) is where the error is 4 %, not 5 %
    assert r.m1_at_error("A3_3", 0.04) == pytest.approx(1.4, abs=0.002)


def test_fig_A3_7_hardly_changes_with_the_number_of_dof():
    """Fig. A.3.7: at constant contribution 1/4 (and 1/c = 2) the exact w_e1^2 rises slowly with n
    towards the continuum of a uniform bar (stiffness 1/2, mass 3/4) with a unit end mass:
    beta tan beta = 3/4, w^2 = (2/3) beta^2 = 0.39666, just below Rayleigh's 0.4 for every n."""
    beta = brentq(lambda b: b * math.tan(b) - 0.75, 0.1, 1.5, xtol=1e-15)
    continuum = 2 / 3 * beta**2
    lam = [r.exact_lowest_eigenvalue(*r.equal_contribution_chain(n)) for n in (2, 3, 4, 10, 100, 1000)]
    assert np.all(np.diff(lam) > 0)
    assert lam[-1] < continuum < 0.4
    # the lumped mass converges as 1/n: the error shrinks tenfold from n = 100 to n = 1000
    assert (continuum - lam[-2]) / (continuum - lam[-1]) == pytest.approx(10, rel=0.1)
    assert continuum - lam[-1] < 2e-5
    for n in (2, 3, 4, 10, 100):
        assert r.rayleigh_eigenvalue(*r.equal_contribution_chain(n)) == pytest.approx(0.4, rel=1e-13)


def test_write_figures_draws_the_three_figures(tmp_path):
    """write_figures creates the folder it is given and writes figs A.3.3, A.3.9 (two panels, 10 x 4 in)
    and A.3.7 (5 x 4 in) there as PNG files at 100 dpi: the signature and the IHDR size of each
    file (PNG specification) are 1000 x 400 and 500 x 400 pixels, and it returns their paths."""
    import struct

    out = tmp_path / "figures" / "app3"
    paths = r.write_figures(out)
    expected = {"fig_A3_3.png": (1000, 400), "fig_A3_9.png": (1000, 400), "fig_A3_7.png": (500, 400)}
    assert sorted(p.name for p in paths) == sorted(expected)
    for p in paths:
        assert p.parent == out and p.is_file()
        head = p.read_bytes()[:24]
        assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR"
        assert struct.unpack(">II", head[16:24]) == expected[p.name]


def test_within_validity_rule_A3_5_A3_11():
    """(A.3.5) contribution <= m_n/4 and (A.3.11) sum of intermediate masses <= 3 m_n."""
    assert r.within_validity([2.0], [1.0])                  # one DOF: no intermediate mass
    assert r.within_validity(*r.fig_A3_3_chain(1.0))        # contribution exactly 1/4
    assert not r.within_validity(*r.fig_A3_3_chain(1.01))   # contribution 0.2525
    assert r.within_validity(*r.fig_A3_9_chain(3.0))        # both limits reached
    assert not r.within_validity(*r.fig_A3_9_chain(3.1))    # mass limit exceeded
    # many intermediate masses near the frame: small contribution, large sum
    m, c = [0.8, 0.8, 0.8, 0.8, 1.0], [100.0, 100.0, 100.0, 100.0, 1.0]
    assert r.intermediate_contribution(m, c) < 0.25 and not r.within_validity(m, c)
    assert r.within_validity(m, c, mass_limit=4.0)
    # the output mass scales both limits: m1 = 1 contributes 1/4, allowed from m2 = 1 on
    assert r.within_validity([1.0, 2.0], [1.0, 1.0]) and not r.within_validity([1.0, 0.99], [1.0, 1.0])


def test_worst_error_inside_the_rule_for_two_dof():
    """Over all two-DOF chains inside (A.3.5) + (A.3.11) (c1 = 1, c2 = k, m2 = 1 by scaling), the
    largest frequency error is at the corner m1 = 3, contribution 1/4, the fig. A.3.9 chain:
    7.24 %, not the 4 % of sec. 4.6 (see the errata check app3.figA3_9.error.m1_3)."""
    m1, k = np.meshgrid(np.linspace(0.01, 3.0, 300), np.logspace(-3, 3, 600))
    contribution = m1 * (k / (1 + k)) ** 2
    lo, _ = r.two_dof_eigenvalues(m1, 1.0, 1.0, k)
    c = k / (1 + k)
    err = np.sqrt(c / (1 + contribution) / lo) - 1
    worst = err[contribution <= 0.25].max()
    corner = r.frequency_error(*r.fig_A3_9_chain(3.0))
    assert corner == pytest.approx(0.0724, abs=5e-4)
    assert 0.07 < worst <= corner + 1e-12


def test_bad_input():
    with pytest.raises(ValueError):
        r.rayleigh_eigenvalue([1.0, 1.0], [1.0])
    with pytest.raises(ValueError):
        r.rayleigh_eigenvalue([1.0, 1.0], [1.0, 0.0])
    with pytest.raises(ValueError):
        r.rayleigh_eigenvalue([1.0, 0.0], [1.0, 1.0])   # output mass must be positive
    with pytest.raises(ValueError):
        r.exact_eigenvalues([0.0, 1.0], [1.0, 1.0])     # M must be invertible
    with pytest.raises(ValueError):
        r.fig_A3_9_chain(0.25)
    # a massless intermediate node is fine for Rayleigh: it adds no contribution
    assert r.rayleigh_eigenvalue([0.0, 1.0], [1.0, 1.0]) == pytest.approx(0.5)
