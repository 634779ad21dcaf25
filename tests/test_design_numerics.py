"""Brent's root finder and the not-a-knot cubic spline of the design solver
(thesis/numerics.py), held to SciPy's brentq and CubicSpline, the independent
computations they stand in for."""
import numpy as np
import pytest
import scipy.interpolate
import scipy.optimize

from camdyn.thesis.numerics import CubicSpline, brentq, maximize


@pytest.mark.parametrize("n", [3, 4, 5, 7, 50, 600])
def test_spline_is_scipys_not_a_knot_spline(n):
    """Uneven points, values and extrapolation half a unit beyond both ends: SciPy's
    CubicSpline (not-a-knot) to 1e-13 of the largest value (measured 1.2e-15)."""
    rng = np.random.default_rng(n)
    x = np.cumsum(rng.uniform(0.1, 1.0, n))
    y = rng.normal(size=n)
    xs = np.linspace(x[0] - 0.5, x[-1] + 0.5, 5001)
    ref = scipy.interpolate.CubicSpline(x, y)(xs)
    assert np.abs(CubicSpline(x, y)(xs) - ref).max() < 1e-13 * np.abs(ref).max()
    assert np.abs(CubicSpline(x, y)(x) - y).max() < 1e-13   # through the points


def test_spline_refuses_what_it_cannot_fit():
    for x, y in (([0, 1], [0, 1]), ([0, 2, 1], [0, 1, 2]), ([0, 1, 2], [0, 1])):
        with pytest.raises(ValueError):
            CubicSpline(x, y)


CASES = [(lambda t: t**3 - 2 * t - 5, 2.0, 3.0), (np.cos, 0.0, 3.0),
         (lambda t: np.exp(t) - 1e3, 0.0, 20.0), (lambda t: np.tanh(50 * (t - 0.3)), 0.0, 1.0),
         (lambda t: t - 1e-9, -1.0, 1.0), (lambda t: np.sign(t - 0.7) * abs(t - 0.7) ** 0.2, 0.0, 1.0)]


@pytest.mark.parametrize("k", range(len(CASES)))
@pytest.mark.parametrize("xtol, rtol", [(1e-10, 1e-9), (1e-13, 1e-11)])
def test_brentq_finds_scipys_root_within_the_tolerance(k, xtol, rtol):
    """The same root as SciPy's brentq within xtol + rtol |x| (both stop when half the
    bracket is within half of that), in no more evaluations than 1.2 times SciPy's."""
    f, a, b = CASES[k]
    calls = []

    def counted(t):
        calls.append(t)
        return f(t)
    x = brentq(counted, a, b, xtol=xtol, rtol=rtol)
    ref, info = scipy.optimize.brentq(f, a, b, xtol=xtol, rtol=rtol, full_output=True)
    assert abs(x - ref) <= xtol + rtol * abs(ref)
    assert len(calls) <= 1.2 * info.function_calls + 1


def test_brentq_needs_a_sign_change():
    with pytest.raises(ValueError, match="differ in sign"):
        brentq(lambda t: t * t + 1, -1.0, 1.0)
    assert brentq(lambda t: t, 0.0, 1.0) == 0.0


@pytest.mark.parametrize("f, lo, hi", [(lambda t: -(t - 0.3) ** 2, 0.0, 1.0),
                                       (lambda t: np.sin(t), 0.5, 3.0),
                                       (lambda t: t * np.exp(-4 * t), 0.0, 2.0),
                                       (lambda t: -abs(t - 0.71), 0.0, 1.0)])
def test_maximize_finds_scipys_bounded_maximum(f, lo, hi):
    """A value no lower than that of SciPy's bounded minimize_scalar on -f (both to xatol
    1e-10) by more than 1e-15, at a place within 1e-7 of SciPy's: where the maximum is smooth
    the values there agree to rounding over a width of about sqrt(eps) (measured 1.1e-8 for
    sin on [0.5, 3]), so neither search fixes the place closer."""
    x, v = maximize(f, lo, hi, xatol=1e-10)
    r = scipy.optimize.minimize_scalar(lambda t: -f(t), bounds=(lo, hi), method="bounded",
                                       options={"xatol": 1e-10})
    assert abs(x - r.x) < 1e-7
    assert v >= -r.fun - 1e-15 and lo <= x <= hi
