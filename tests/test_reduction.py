"""Reduction to a point of interest, thesis sec. 2.4, (2.55)-(2.59).

The thesis requires that reduction changes "none of the dynamic properties of
the model"; the tests solve the same systems in their own coordinates and
after reduction and compare natural frequencies (also damped ones), energies
and the squeeze-film response.
"""
import numpy as np
import pytest
import sympy as sp

from camdyn.thesis.theory import assembly as A
from camdyn.thesis.theory import elements as E
from camdyn.thesis.theory import reduction as R

xA, xB, x2 = sp.symbols("xA xB x2", real=True)
m1, m2, c1, c2, d1 = sp.symbols("m1 m2 c1 c2 d1", positive=True)
NUM = {m1: 2.0, m2: 0.7, c1: 3.0e4, c2: 1.2e5, d1: 40.0}


def _lever_system(i):
    """Mass m1 and spring c1 (to the frame) at A; a lever with ratio i to B; spring c2
    from B to mass m2.  Own coordinates (xA, x2); the lever is the constraint xB = i xA (2.51)."""
    lv = E.Lever(sp.Integer(1), sp.nsimplify(i))
    own = A.assemble([E.lumped_mass(xA, m1), E.spring(sp.Integer(0), xA, c1),
                      E.spring(lv.output(xA), x2, c2), E.lumped_mass(x2, m2)], (xA, x2))
    red = A.assemble([E.lumped_mass(xB, R.mass(m1, lv.i)),
                      E.spring(sp.Integer(0), xB, R.stiffness(c1, lv.i)),
                      E.spring(xB, x2, c2), E.lumped_mass(x2, m2)], (xB, x2))
    return own, red, lv.i


def _num(M):
    return np.array(M.subs(NUM), dtype=float)


def _state_eigs(M, C, D):
    n = M.shape[0]
    Minv = np.linalg.inv(M)
    S = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ C, -Minv @ D]])
    ev = np.linalg.eigvals(S)
    return ev[np.lexsort((ev.imag, ev.real))]


@pytest.mark.parametrize("i", [0.4, 1.0, 2.5, 7.0])
def test_lever_coupled_two_dof_frequencies_unchanged(i):
    """Natural frequencies of the lever-coupled system in its own coordinates equal those of
    the model reduced to B with (2.56), (2.57), to 1e-12."""
    own, red, _ = _lever_system(i)
    lam_own = np.sort(np.linalg.eigvals(np.linalg.solve(_num(own.M), _num(own.C))).real)
    lam_red = np.sort(np.linalg.eigvals(np.linalg.solve(_num(red.M), _num(red.C))).real)
    assert lam_red == pytest.approx(lam_own, rel=1e-12)
    # and through the frequency equation (2.50)
    assert A.eigenvalues(own.M.subs(NUM), own.C.subs(NUM)) == pytest.approx(list(lam_own), rel=1e-10)


@pytest.mark.parametrize("i", [0.4, 2.5])
def test_damped_frequencies_unchanged(i):
    """A viscous damper d1 at A reduced by (2.58): the complex eigenvalues (decay rates and
    damped frequencies) of the state equations are unchanged, to 1e-10."""
    own, red, ii = _lever_system(i)
    D_own = np.diag([NUM[d1], 0.0])
    D_red = np.diag([float(R.damper(NUM[d1], float(ii))), 0.0])
    e_own = _state_eigs(_num(own.M), _num(own.C), D_own)
    e_red = _state_eigs(_num(red.M), _num(red.C), D_red)
    assert np.allclose(e_own, e_red, rtol=1e-10, atol=0)
    assert np.all(e_own.real < 0)


def test_wrong_exponent_would_change_the_frequencies():
    """The test above can fail: reducing the mass with 1/i instead of 1/i^2 shifts the
    frequencies (i = 2.5)."""
    own, _, ii = _lever_system(2.5)
    wrong = A.assemble([E.lumped_mass(xB, m1 / ii), E.spring(sp.Integer(0), xB, R.stiffness(c1, ii)),
                        E.spring(xB, x2, c2), E.lumped_mass(x2, m2)], (xB, x2))
    lam_own = np.sort(np.linalg.eigvals(np.linalg.solve(_num(own.M), _num(own.C))).real)
    lam_w = np.sort(np.linalg.eigvals(np.linalg.solve(_num(wrong.M), _num(wrong.C))).real)
    assert np.max(np.abs(lam_w - lam_own) / lam_own) > 0.05


def test_rules_keep_the_energies():
    """Energy argument, independent of the force argument of the thesis: with the velocity at B
    v_B = i v_A, 1/2 m v_A^2 = 1/2 m' v_B^2, 1/2 c f_A^2 = 1/2 c' f_B^2 and the dissipation
    1/2 d v_A^2 = 1/2 d' v_B^2."""
    i, v, f, m, c, d = sp.symbols("i v f m c d", positive=True)
    assert sp.simplify(m * v**2 - R.mass(m, i) * (i * v) ** 2) == 0
    assert sp.simplify(c * f**2 - R.stiffness(c, i) * (i * f) ** 2) == 0
    assert sp.simplify(d * v**2 - R.damper(d, i) * (i * v) ** 2) == 0
    # a backlash s at A is traversed at B as i s: the lever maps it (2.51), (2.55)
    s = sp.Symbol("s", positive=True)
    assert E.Lever(1, i).output(s) == R.length(s, i)


@pytest.mark.parametrize("i", [0.5, 3.0])
def test_squeeze_film_reduced_viscosity(i):
    """(A.4.11) with numbers: a force F at B loads the film at A with i F; the film's approach
    velocity at A, times i, equals the velocity of the reduced film (eta/i^3 (2.59), all
    dimensions times i (2.55)) under F, to 1e-12."""
    eta, b, Re, s, F = 0.05, 0.012, 0.03, 2e-5, 150.0
    w = sp.Symbol("w", positive=True)

    def velocity(eta_, b_, Re_, s_, force):
        return float(sp.solve(sp.Eq(R.squeeze_force(eta_, w, b_, Re_, s_), force), w)[0])

    w_B = i * velocity(eta, b, Re, s, i * F)
    w_red = velocity(R.viscosity(eta, i), R.length(b, i), R.length(Re, i), R.length(s, i), F)
    assert w_red == pytest.approx(w_B, rel=1e-12)


def test_frame_stiffness_by_statics():
    """sec. 2.4.3: pivot stiffness c_M reduced to B by ((a + b)/a)^2.  Numbers: lever with A
    held, pivot spring c_M, force F at B; equilibrium and the small-rotation kinematics give
    the deflection at B, compared with F/c', to 1e-12."""
    a, b, cM, F = 0.08, 0.2, 5.0e6, 100.0
    # unknowns: pivot deflection f_M and rotation phi about A; B at distance a + b from A
    # moment about A: c_M f_M a = F (a + b); kinematics: f_M = a phi, f_B = (a + b) phi
    f_M = F * (a + b) / (a * cM)
    f_B = (a + b) * f_M / a
    assert f_B == pytest.approx(F / R.frame_stiffness(cM, a, b), rel=1e-12)


def test_fig_2_4_reduced_to_the_output_is_the_chain_2_47():
    """sec. 2.4.6: the three-DOF model (2.46) reduced to the output radius l8 (x4, x5 by
    i2 = l8/l6) has no transmission ratios left: it is the chain (2.47) with n = 3, masses
    (m4/3, m5 + m6/3)/i2^2 and m8/3, stiffnesses c4/i2^2, (EA/l)5/i2^2, c678, and the input
    h' = i1 i2 h at the head; and its eigenvalues are those of (2.46)."""
    t = A.three_dof()
    r = R.reduce_system(t, (A.i2, A.i2, 1))
    ch = A.chain(3)
    _, hs, ms, cs = A.chain_symbols(3)
    c4 = 3 * A.EI4 / (A.a**3 * A.i1 * (A.i1 - 1) ** 2)
    sub = {ms[0]: R.mass(A.m4 / 3, A.i2), ms[1]: R.mass(A.m5 + A.m6 / 3, A.i2), ms[2]: A.m8 / 3,
           cs[0]: R.stiffness(c4, A.i2), cs[1]: R.stiffness(A.EA5 / A.l5, A.i2), cs[2]: A.c678()}
    zero = lambda X: X.applyfunc(sp.simplify) == sp.zeros(*X.shape)  # noqa: E731
    assert zero(r.M - ch.M.subs(sub))
    assert zero(r.C - ch.C.subs(sub))
    # K h with h1 = h' = i1 i2 h, h2 = h3 = 0
    Kh = ch.K.subs(sub) * sp.Matrix([A.i1 * A.i2 * A.h, 0, 0])
    assert zero(r.K * sp.Matrix([A.h]) - Kh)
    from tests.test_assembly import VALUES
    lam_t = A.eigenvalues(t.M.subs(VALUES), t.C.subs(VALUES))
    lam_r = A.eigenvalues(r.M.subs(VALUES), r.C.subs(VALUES))
    assert lam_r == pytest.approx(lam_t, rel=1e-10)
