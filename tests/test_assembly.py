"""Assembly, condensation, chain and frequency equation (thesis sec. 2.2.2, (2.40)-(2.50)).

Beyond the registry checks: properties the printed matrices must have
(symmetry, definiteness, diagonal M of (2.45)), static condensation keeping
the static stiffness and the natural frequencies of the massless-coordinate
system, the chain (2.47) against the closed-form eigenvalues of a uniform
chain, and the frequency equation (2.50) against numpy.linalg.eigvals.
"""
import numpy as np
import pytest
import scipy.linalg
import sympy as sp

from camdyn.thesis.theory import assembly as A
from camdyn.thesis.theory import elements as E

# a plausible steel mechanism in SI units (only for the numerical properties below)
VALUES = {
    A.EI4: 2.0e3, A.a: 0.05, A.i1: 2.0, A.EA5: 2.0e7, A.l5: 0.5, A.EI6: 1.0e3, A.l6: 0.1,
    A.GIp7: 5.0e3, A.l7: 0.4, A.EI8: 1.5e3, A.l8: 0.2,
    A.m4: 0.5, A.m5: 0.4, A.m6: 0.3, A.J7: 1.0e-4, A.m8: 0.6, A.c_g: 0.0,
}


def _num(M, values=VALUES):
    return np.array(M.subs(values), dtype=float)


@pytest.mark.parametrize("kinetic", ["elastic", "rigid"])
def test_fig_2_4_matrices_symmetric_and_definite(kinetic):
    """M and C of (2.40)/(2.45) are symmetric; C is positive definite (every coordinate is tied
    to the frame through the chain) and so is M of (2.40); M of (2.45) is diagonal and
    positive semidefinite with the one zero at psi6 l6."""
    s = A.fig_2_4(kinetic)
    assert s.M == s.M.T and s.C == s.C.T
    C = _num(s.C)
    assert np.all(np.linalg.eigvalsh(C) > 0)
    M = _num(s.M)
    if kinetic == "elastic":
        assert np.all(np.linalg.eigvalsh(M) > 0)
    else:
        assert s.M.is_diagonal()
        assert list(np.diag(M) == 0) == [False, False, True, False, False]


def test_stiffness_is_the_same_in_2_40_and_2_45():
    """Only T changes between the two variants: C and K agree, B (the h'' term) vanishes in (2.45)."""
    el, ri = A.fig_2_4("elastic"), A.fig_2_4("rigid")
    assert el.C == ri.C and el.K == ri.K
    assert ri.B == sp.zeros(5, 1) and el.B != sp.zeros(5, 1)


def test_follower_spring_adds_c_g_at_x8_only():
    """(2.38)-(2.39): the follower spring c_g adds to the x8 diagonal and nowhere else."""
    with_g, without = A.fig_2_4("elastic", True), A.fig_2_4("elastic")
    diff = (with_g.C - without.C).applyfunc(sp.simplify)
    want = sp.zeros(5, 5)
    want[4, 4] = A.c_g
    assert diff == want


def test_static_input_moves_the_chain_rigidly():
    """A static cam lift h moves every node by its kinematic transmission when the chain is
    otherwise unloaded: x4 = x5 = i1 h, psi6 l6 = i1 h, psi7 l8 = i1 i2 h = x8 (C x = K h)."""
    s = A.fig_2_4()
    x = s.C.LUsolve(s.K).applyfunc(sp.simplify)
    want = [A.i1, A.i1, A.i1, A.i1 * A.i2, A.i1 * A.i2]
    assert all(sp.simplify(x[j] - want[j]) == 0 for j in range(5))


def _exact(A_, values=VALUES):
    """A matrix with the numbers of VALUES as exact rationals (exact and fast comparisons)."""
    return A_.subs({k: sp.nsimplify(v, rational=True) for k, v in values.items()})


def test_condensation_keeps_the_static_stiffness():
    """Static condensation: the compliance seen at x4, x5, x8 is unchanged,
    (C_r)^-1 = (C^-1) restricted to the kept coordinates (exact rational numbers)."""
    s = A.fig_2_4("rigid")
    r = A.condense(s, (A.x4, A.x5, A.x8))
    keep = [0, 1, 4]
    full = _exact(s.C).inv().extract(keep, keep)
    assert full == _exact(r.C).inv()


def test_c678_is_the_series_stiffness_between_x5_and_x8():
    """fig. 2.11: with x5 held, a unit force at x8 deflects it by 1/c678 (numerically, from the
    five-coordinate stiffness matrix)."""
    C = _num(A.fig_2_4().C)
    free = [2, 3, 4]                       # psi6 l6, psi7 l8, x8 with x4, x5 held
    f = np.array([0.0, 0.0, 1.0])
    defl = np.linalg.solve(C[np.ix_(free, free)], f)[2]
    assert 1 / defl == pytest.approx(float(A.c678().subs(VALUES)), rel=1e-12)


def test_condensed_three_dof_has_the_frequencies_of_2_45_without_shaft_mass():
    """With J7 = 0 the coordinates psi6 l6, psi7 l8 carry no mass: (2.45) has three finite
    eigenvalues and they are those of (2.46) (generalized eigenproblem with singular M)."""
    s = A.fig_2_4("rigid")
    vals = {**VALUES, A.J7: 0.0}
    lam = scipy.linalg.eigvals(_num(s.C, vals), _num(s.M, vals))
    finite = np.sort(lam[np.isfinite(lam)].real)
    assert len(finite) == 3
    t = A.three_dof()
    three = np.sort(np.linalg.eigvals(np.linalg.solve(_num(t.M, vals), _num(t.C, vals))).real)
    assert finite == pytest.approx(three, rel=1e-9)


def test_small_shaft_mass_hardly_matters():
    """After (2.45): equating the shaft mass J7/l8^2 to zero 'will introduce hardly any error'.
    The two lowest eigenvalues of (2.45) approach those of (2.46) as J7 -> 0; to first order the
    relative change is (J7/l8^2) phi7^2/(phi^T M phi) with the modal amplitude phi7 of psi7 l8
    close to phi8 and phi^T M phi > 1/3 m8 phi8^2, so it stays below (J7/l8^2)/(1/3 m8)."""
    t = A.three_dof()
    three = np.sort(np.linalg.eigvals(np.linalg.solve(_num(t.M), _num(t.C))).real)
    s = A.fig_2_4("rigid")
    changes = []
    for J7 in (1e-4, 1e-5, 1e-6):
        vals = {**VALUES, A.J7: J7}
        lam = scipy.linalg.eigvals(_num(s.C, vals), _num(s.M, vals))
        low = np.sort(lam[np.isfinite(lam)].real)[:2]
        change = np.max(np.abs(low - three[:2]) / three[:2])
        assert change < J7 / VALUES[A.l8] ** 2 / (VALUES[A.m8] / 3)
        changes.append(change)
    # and it vanishes with J7 (first order: a tenth per decade)
    assert changes[2] / changes[0] == pytest.approx(1e-2, rel=0.05)


def test_condense_input_terms():
    """Condensation also carries the input: the kept system reproduces the static response
    to h of the full system at the kept coordinates (exact rational numbers)."""
    s = A.fig_2_4("rigid").subs({A.J7: 0})
    r = A.condense(s, (A.x4, A.x5, A.x8))
    full = _exact(s.C).LUsolve(_exact(s.K))
    kept = _exact(r.C).LUsolve(_exact(r.K))
    assert [full[j] for j in (0, 1, 4)] == list(kept)


def test_assemble_rejects_non_quadratic_energies():
    x = sp.Symbol("x", real=True)
    e = E.Element("odd", "-", (x,), sp.Integer(0), x**4)
    with pytest.raises(ValueError):
        A.assemble([e], (x,))


# -- chain (2.47)-(2.48) and frequency equation (2.50) ------------------------------------

@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_uniform_chain_eigenvalues_closed_form(n):
    """Unit masses and springs: the roots of (2.50) are 2 - 2 cos((2k - 1) pi/(2n + 1)),
    k = 1..n (fixed-free chain), to 1e-12."""
    s = A.chain(n)
    _, _, ms, cs = A.chain_symbols(n)
    unit = {**{q: 1 for q in ms}, **{q: 1 for q in cs}}
    lam = A.eigenvalues(s.M.subs(unit), s.C.subs(unit))
    want = sorted(2 - 2 * np.cos((2 * k - 1) * np.pi / (2 * n + 1)) for k in range(1, n + 1))
    assert lam == pytest.approx(want, abs=1e-12)


def test_three_mass_chain_matches_fig_3_6():
    """Fig. 3.6 (thesis): unit masses and stiffnesses, eigenvalues 0.198, 1.555, 3.247."""
    s = A.chain(3)
    _, _, ms, cs = A.chain_symbols(3)
    unit = {**{q: 1 for q in ms}, **{q: 1 for q in cs}}
    lam = A.eigenvalues(s.M.subs(unit), s.C.subs(unit))
    assert lam == pytest.approx([0.198, 1.555, 3.247], abs=6e-4)


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_frequency_equation_against_numpy(n, rng):
    """(2.50) |-lambda E + C M^-1| = 0 has the eigenvalues of M^-1 C (numpy), random chain."""
    s = A.chain(n)
    _, _, ms, cs = A.chain_symbols(n)
    vals = {**{q: float(v) for q, v in zip(ms, rng.uniform(0.2, 3.0, n))},
            **{q: float(v) for q, v in zip(cs, rng.uniform(0.5, 5.0, n))}}
    M, C = s.M.subs(vals), s.C.subs(vals)
    lam = A.eigenvalues(M, C)
    ref = np.sort(np.linalg.eigvals(np.linalg.solve(_num(M, {}), _num(C, {}))).real)
    assert lam == pytest.approx(list(ref), rel=1e-10)


def test_frequency_equation_with_dynamic_coupling():
    """(2.50) also holds for the coupled mass matrix of (2.40) (numbers of VALUES)."""
    s = A.fig_2_4()
    M, C = s.M.subs(VALUES), s.C.subs(VALUES)
    lam = np.array(A.eigenvalues(M, C))
    ref = np.sort(scipy.linalg.eigvals(_num(C, {}), _num(M, {})).real)
    assert lam == pytest.approx(ref, rel=1e-8)


def test_frequency_equation_polynomial_and_singular_mass():
    """Degree n, leading coefficient (-1)^n; a massless coordinate is refused (after (2.48))."""
    s = A.chain(2)
    poly = sp.Poly(A.frequency_equation(s.M, s.C), A.LAMBDA)
    assert poly.degree() == 2 and poly.LC() == 1
    # lambda = 0 gives det(C)/det(M) = c1 c2/(m1 m2)
    _, _, ms, cs = A.chain_symbols(2)
    assert sp.simplify(poly.eval(0) - cs[0] * cs[1] / (ms[0] * ms[1])) == 0
    with pytest.raises(ValueError):
        A.frequency_equation(A.fig_2_4("rigid").M, A.fig_2_4("rigid").C)


def test_chain_input_is_the_spring_force_of_h():
    """(2.47) right-hand side: a static input h_i alone displaces masses i..n by h_i and leaves
    the others at rest (the springs before i carry no force)."""
    n = 4
    s = A.chain(n)
    for k in range(n):
        hvec = sp.zeros(n, 1)
        hvec[k] = 1
        x = s.C.LUsolve(s.K * hvec).applyfunc(sp.simplify)
        assert list(x) == [0] * k + [1] * (n - k)
