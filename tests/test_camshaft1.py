"""CAMSHAFT-1 (thesis ch. 4) against the one-DOF model, (4.19), (4.22) and the thesis's figures."""
import numpy as np
import pytest

from camdyn.thesis.theory import numeric as cf
from camdyn.runtime.measure.residual import residual
from camdyn.runtime.measure.extremes import extreme
from camdyn.runtime.core.simulator import simulate

from .conftest import residual_of


@pytest.mark.parametrize("method,opts", [("rk4", {"step": 0.002}), ("koster", {"step": 0.002}),
                                         ("dp54", {"rtol": 1e-9})])
def test_fa_zero_is_the_one_dof_model(method, opts):
    """At Fa = 0, CAMSHAFT-1 is the one-DOF model of ch. 3: fixed steps give the same states
    up to rounding (the generated expressions differ in form); DP54's step-size choices
    may differ by rounding, so there the two agree to the tolerance."""
    a = simulate("camshaft1", {"tau": 0.15, "Fa": 0.0}, 3.0, method, **opts)
    b = simulate("one_dof", {"tau": 0.15}, 3.0, method, **opts)
    if method == "dp54":
        T = np.linspace(0.0, 3.0, 601)
        np.testing.assert_allclose(a.sample(T)["X"], b.sample(T)["X"], rtol=0, atol=1e-7)
    else:
        np.testing.assert_array_equal(a.t, b.t)
        np.testing.assert_allclose(a.y, b.y, rtol=0, atol=1e-12)


@pytest.mark.parametrize("Fa", [0.3, 2.0, 3.34])
def test_stiffness_dip_4_19_from_generated_outputs(Fa):
    """min of c/c_c over the cycloidal rise is 1/(1 + 4 Fa), at T = 1/2 (4.19)."""
    res = simulate("camshaft1", {"tau": 0.15, "Fa": Fa}, 3.0, "dp54", rtol=1e-8)
    c_min, t_min = extreme(res, "c_rel", 0.0, 1.0, absolute=False, minimum=True)
    assert 1.0 / c_min == pytest.approx(float(cf.evaluate("stiffness_dip", Fa=Fa)), rel=1e-9)
    assert t_min == pytest.approx(0.5, abs=1e-5)
    c_max, _ = extreme(res, "c_rel", 1.0, 3.0, absolute=False, minimum=False)
    assert c_max == 1.0


def _window_max(Fa, a, b, n=100):
    return max(residual_of("camshaft1", float(t), Fa, rtol=1e-8).U0 for t in np.linspace(a, b, n))


def _approx_max(Fa, a, b, xi=1.5):
    return float(np.max(cf.evaluate("U0_approx", tau=np.linspace(a, b, 3000), Fa=Fa, xi=xi)))


@pytest.mark.parametrize("a,b", [(0.15, 0.25), (0.2, 0.3)])
def test_approximate_solution_4_22_small_fa(a, b):
    """(4.22) holds the stiffness at c_c/(1 + 3/2 Fa) (4.21).  For a small stiffness
    variation (Fa = 0.1, dip 1.4) at the higher practical tau (the thesis: "agrees to some
    extent ... about tau = 0.2", sec. 4.7 (3)) its largest U0 in a tau window agrees with the
    numerical one within 25 %.  Pointwise comparison is meaningless: the zero points of
    (4.22) and of the numerical solution do not coincide.  Below tau = 0.15 it overestimates
    (by 36 % in [0.1, 0.2] at Fa = 0.1), as the thesis says of low tau."""
    ratio = _approx_max(0.1, a, b) / _window_max(0.1, a, b)
    assert 0.75 < ratio < 1.25, ratio


@pytest.mark.parametrize("Fa", [0.1, 0.25, 0.5])
@pytest.mark.parametrize("a,b", [(0.1, 0.2), (0.15, 0.25), (0.2, 0.3)])
def test_approximate_solution_4_22_stated_range(Fa, a, b):
    """Up to the edge of the range the thesis states for (4.20)-(4.22), Fa < 1/2, the
    approximation stays within the factor 2.5 the thesis itself reports (sec. 4.7 (3))."""
    ratio = _approx_max(Fa, a, b) / _window_max(Fa, a, b)
    assert 1 / 2.5 < ratio < 2.5, ratio


def test_thesis_scheme_agrees_with_dp54_at_fine_step():
    """At dT = 0.01 tau the thesis scheme gives U0 within 0.1 % of DP54 at rtol 1e-10."""
    for tau, Fa in ((0.15, 2.0), (0.2, 1.5)):
        fine = residual(simulate("camshaft1", {"tau": tau, "Fa": Fa}, 3.0, "koster", step=0.01 * tau)).U0
        assert fine == pytest.approx(residual_of("camshaft1", tau, Fa).U0, rel=1e-3)


def test_approximation_4_22_is_3_5_with_tau_stretched():
    """(4.22) is (3.5) with tau multiplied by (1 + xi Fa)^(1/2) (sec. 4.4.1: the constant stiffness
    c_c/(1 + xi Fa) lengthens the natural period by that factor), so at Fa = 0 it is (3.5) itself.
    Checked symbolically (SymPy difference 0) and through the lambdified closed forms at tau up to
    0.7, where the factor 1/(1 - tau^2 (1 + xi Fa)) matters most (measured 4e-16)."""
    import sympy as sp

    from camdyn.thesis.theory import forms as th

    stretched = th.U0.subs(th.tau, th.tau * sp.sqrt(1 + th.xi * th.Fa))
    assert sp.simplify(th.U0_approx - stretched) == 0
    assert sp.simplify(th.U0_approx.subs(th.Fa, 0) - th.U0) == 0
    for tau, Fa, xi in ((0.45, 0.3, 2.0), (0.7, 0.1, 1.5), (0.3, 2.0, 1.5), (0.15, 0.5, 2.0)):
        approx = float(cf.evaluate("U0_approx", tau=tau, Fa=Fa, xi=xi))
        assert approx == pytest.approx(cf.U0(tau * np.sqrt(1 + xi * Fa)), rel=1e-12)
