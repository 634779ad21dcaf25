"""The compiled headline figures (runtime/_figures.pyx) against the Python and SciPy reference
of runtime/residual.py (``extreme_reference``, ``residual_reference``: 12 samples a recorded
step, the best refined by SciPy's bounded Brent minimizer), on grids of CAMSHAFT-1 (4.15)
runs and a CAMSHAFT-2 (5.15) run, whose rise ends when the cam angle B reaches 1; and the
sweep's figures at Fa = 0 against the closed form (3.5), (3.6) of the one-DOF model.
"""
import numpy as np
import pytest

from camdyn.runtime import closed_forms, sweep
from camdyn.runtime.residual import extreme, extreme_reference, residual, residual_reference
from camdyn.runtime.simulate import Simulator

TAUS = (0.07, 0.15, 0.33, 0.6)
FAS = (0.0, 0.5, 2.0, 10.0)


@pytest.fixture(scope="module")
def sim():
    return Simulator("camshaft1", 3.0, "dp54", rtol=1e-9, law="cycloidal")


@pytest.fixture(scope="module")
def runs(sim):
    return {(tau, Fa): sim.run({"tau": tau, "Fa": Fa}) for tau in TAUS for Fa in FAS}


def _close(a, b, rel, scale):
    return abs(a - b) <= rel * max(abs(b), scale)


@pytest.mark.parametrize("absolute,minimum", [(True, False), (False, False), (False, True),
                                              (True, True)])
def test_extreme_equals_the_reference(runs, absolute, minimum):
    """The same recipe (12 samples a step, the best refined) in C and in Python/SciPy, on U
    and X'' over the rise, the dwell and a window inside one step, 16 runs.  The two scans
    place their samples alike but for the last bits (t_k + (t_k+1 - t_k) q/12 against NumPy's
    sum), which moves Brent's path: both stop within SciPy's tolerance sqrt(eps)|t| + 1e-12/3
    (1.1e-8 at T = 0.76), so the times differ by up to that (measured 1.1e-8), the values by a
    part in 1e-15 at a smooth extremum.  The smallest |U| in the dwell sits on a kink (a zero
    of U), located only to where |U| drowns in rounding: both give 3e-11 of the stroke.
    Asserted: values 1e-12 relative (1e-8 of max |v| for the smallest |v|), times 5e-8."""
    for (tau, Fa), r in runs.items():
        k = len(r.t) // 2
        for name, a, b in (("U", 1.0, 3.0), ("Xdd", 0.0, 1.0), ("Xdd", 1.0, 3.0),
                           ("U", r.t[k] + 0.1 * (r.t[k + 1] - r.t[k]), r.t[k + 1])):
            v, t = extreme(r, name, a, b, absolute=absolute, minimum=minimum)
            v_ref, t_ref = extreme_reference(r, name, a, b, absolute=absolute, minimum=minimum)
            if absolute and minimum:
                assert abs(v - v_ref) <= 1e-8 * np.abs(r[name]).max(), (tau, Fa, name, a, b)
                continue
            assert _close(v, v_ref, 1e-12, 1e-6 * np.abs(r[name]).max()), (tau, Fa, name, a, b)
            assert abs(t - t_ref) <= 5e-8, (tau, Fa, name, a, b, t, t_ref)


def test_residual_equals_the_reference(runs):
    """residual() (compiled) against residual_reference() on the 4 x 4 grid: U0, U0'',
    X''min in the rise to 1e-12 relative, its T to 5e-8 (SciPy's stopping tolerance, as in
    test_extreme_equals_the_reference)."""
    for key, r in runs.items():
        fast, ref = residual(r), residual_reference(r)
        for name in ("U0", "U0dd", "Xdd_min_rise"):
            assert getattr(fast, name) == pytest.approx(getattr(ref, name), rel=1e-12), (key, name)
        assert fast.T_at_Xdd_min == pytest.approx(ref.T_at_Xdd_min, abs=5e-8), key


def test_camshaft2_rise_ends_where_B_reaches_one():
    """CAMSHAFT-2 (5.15)-(5.18): the compiled crossing of B = 1 (bisection to 1e-14) and the
    figures after it equal the reference's (brentq to 1e-14): values 1e-12, T 5e-8."""
    r = Simulator("camshaft2", 3.0, "dp54", rtol=1e-10).run({"tau": 0.2, "Fa": 1.0, "Fv": 2.0})
    fast, ref = residual(r), residual_reference(r)
    for name in ("U0", "U0dd", "Xdd_min_rise"):
        assert getattr(fast, name) == pytest.approx(getattr(ref, name), rel=1e-12), name
    assert fast.T_at_Xdd_min == pytest.approx(ref.T_at_Xdd_min, abs=5e-8)


def test_sweep_figures_equal_the_reference_on_a_grid(runs):
    """The sweep's own scan (every 3rd recorded point at rtol 1e-9, the 4 best peaks refined
    on the dense output; sweep.scan_density) against the
    reference's (12 samples a step) on the 4 x 4 grid.  Where several peaks are equal to
    within the integration error (every peak of the undamped dwell is U0), either scan may
    refine another one: measured U0, U0'' within 5e-8 relative (at rtol 1e-9, the dwell's
    peaks differ by ~1e-12 of the stroke: that much of U0 = 1e-5 .. 1e-1), X''min 2e-13, its
    T 4e-8.  Asserted: U0, U0'' 2e-7 relative, X''min 1e-11 (of 1e-6 of the largest |X''| where
    it is near zero: the rise's minimum at T = 0 when X'' never goes below zero), T 2e-7."""
    pts = np.array([[tau, Fa] for tau, Fa in runs])
    figs, _ = sweep.run_chunk(sweep.resolve("camshaft1"), ("tau", "Fa"), pts)
    for j, key in enumerate(runs):
        ref = residual_reference(runs[key])
        U0, U0dd, xmin, T = figs[j]
        assert U0 == pytest.approx(ref.U0, rel=2e-7), key
        assert U0dd == pytest.approx(ref.U0dd, rel=2e-7), key
        assert _close(xmin, ref.Xdd_min_rise, 1e-11, 1e-6 * np.abs(runs[key]["Xdd"]).max()), key
        assert T == pytest.approx(ref.T_at_Xdd_min, abs=2e-7), key


def test_sweep_at_Fa_0_is_the_closed_form():
    """At Fa = 0 CAMSHAFT-1 is the one-DOF model (3.1): U0 (3.5) and U0'' (3.6) in closed form,
    tau^3 |sin(pi/tau)|/(pi (1 - tau^2)) and 4 pi tau |sin(pi/tau)|/(1 - tau^2).  Away from the
    dips at tau = 1/n, within 1e-6 relative (rtol 1e-9; measured 3e-9)."""
    taus = np.array([0.0712, 0.137, 0.2345, 0.41, 0.58, 0.77])
    res = sweep.sweep("camshaft1", {"Fa": [0.0], "tau": taus}, jobs=1, progress=False)
    assert res["U0"] == pytest.approx(closed_forms.U0(taus), rel=1e-6)
    assert res["U0dd"] == pytest.approx(closed_forms.U0dd(taus), rel=1e-6)
