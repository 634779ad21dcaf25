"""The compiled headline figures (runtime/engine/finder.pyx) against the Python and SciPy reference
of runtime/measure/extremes.py (``extreme_reference``, ``residual_reference``: 12 samples a recorded
step, the best sample refined by SciPy's bounded Brent minimizer), on grids of CAMSHAFT-1 (4.15)
runs and a CAMSHAFT-2 (5.15) run, whose rise ends when the cam angle B reaches 1; the sweep's
figures at Fa = 0 against the closed form (3.5), (3.6) of the one-DOF model; and the sampling
check (a peak the scan left that may be higher is refined; what is left is the sampling error).

The compiled finder refines, besides the reference's peak, every peak whose parabola rises above
the best by more than the refined parabolas were off.  In the undamped dwell every peak of U is
U0 to within the integration error (the peaks drift by ~1e-8 of U0 at rtol 1e-9), so there the
compiled U0 may be a neighbouring peak's, at most that drift above the reference's and never
below it.
"""
import numpy as np
import pytest

from camdyn.runtime.measure import references as closed_forms
from camdyn.runtime.studies import sweep
from camdyn.runtime.measure.residual import residual, residual_reference
from camdyn.runtime.measure.extremes import extreme, extreme_reference
from camdyn.runtime.core.simulator import Simulator
from camdyn.runtime.targets.model_target import ModelTarget

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
            e = extreme(r, name, a, b, absolute=absolute, minimum=minimum)
            v, t = e
            v_ref, t_ref = extreme_reference(r, name, a, b, absolute=absolute, minimum=minimum)
            if absolute and minimum:
                # on a kink (a zero of U) a parabola means little: the check may find a lower
                # kink than the reference's, never a higher one by more than 1e-8 of max |v|;
                # with more kinks than it refines, the bound it leaves as sampling error is a
                # loose one (measured up to 6e-5 of max |v|)
                assert v <= v_ref + 1e-8 * np.abs(r[name]).max(), (tau, Fa, name, a, b)
                assert e.sampling_error <= 1e-3 * np.abs(r[name]).max(), (tau, Fa, name, a, b)
                continue
            assert e.sampling_error == 0.0, (tau, Fa, name, a, b)
            # the value the dense output takes where the finder says
            s = r.sample([t])[name][0]
            assert (abs(s) if absolute else s) == pytest.approx(v, rel=1e-14, abs=1e-300)
            better = (v_ref - v) if minimum else (v - v_ref)
            scale = 1e-6 * np.abs(r[name]).max()
            assert better >= -1e-12 * max(abs(v_ref), scale), (tau, Fa, name, a, b)
            if better > 1e-12 * max(abs(v_ref), scale):     # another, as high, peak
                assert better <= 1e-7 * max(abs(v_ref), scale), (tau, Fa, name, a, b)
            else:
                assert abs(t - t_ref) <= 5e-8, (tau, Fa, name, a, b, t, t_ref)


def test_residual_equals_the_reference(runs):
    """residual() (compiled) against residual_reference() on the 4 x 4 grid: U0, U0'' at or
    above the reference's by at most the dwell's peak drift (1e-7 relative), X''min in the
    rise (one peak) to 1e-12 relative, its T to 5e-8 (SciPy's stopping tolerance, as in
    test_extreme_equals_the_reference); no sampling error left on the values, and on T the
    bound of the refinement that places it (extremes.place_error)."""
    from camdyn.runtime.measure.extremes import place_error

    for key, r in runs.items():
        fast, ref = residual(r), residual_reference(r)
        for name in ("U0", "U0dd"):
            got, want = getattr(fast, name), getattr(ref, name)
            assert want * (1 - 1e-12) <= got <= want * (1 + 1e-7), (key, name)
        assert fast.Xdd_min_rise == pytest.approx(ref.Xdd_min_rise, rel=1e-12), key
        assert fast.T_at_Xdd_min == pytest.approx(ref.T_at_Xdd_min, abs=5e-8), key
        assert {v for k, v in fast.sampling.items() if k != "T_at_Xdd_min"} == {0.0}, key
        assert fast.sampling["T_at_Xdd_min"] == place_error(fast.T_at_Xdd_min), key


def test_camshaft2_rise_ends_where_B_reaches_one():
    """CAMSHAFT-2 (5.15)-(5.18): the compiled crossing of B = 1 (bisection to 1e-14) and the
    figures after it equal the reference's (brentq to 1e-14): values 1e-12, T 5e-8."""
    r = Simulator("camshaft2", 3.0, "dp54", rtol=1e-10).run({"tau": 0.2, "Fa": 1.0, "Fv": 2.0})
    fast, ref = residual(r), residual_reference(r)
    for name in ("U0", "U0dd"):
        got, want = getattr(fast, name), getattr(ref, name)
        assert want * (1 - 1e-12) <= got <= want * (1 + 1e-7), name
    assert fast.Xdd_min_rise == pytest.approx(ref.Xdd_min_rise, rel=1e-12)
    assert fast.T_at_Xdd_min == pytest.approx(ref.T_at_Xdd_min, abs=5e-8)


def test_sweep_figures_equal_the_reference_on_a_grid(runs):
    """The sweep's own scan (every 3rd recorded point at rtol 1e-9, the 4 best peaks refined
    on the dense output and the others checked; runtime/targets/model_target.py's scan_density) against the
    reference's (12 samples a step) on the 4 x 4 grid.  Where several peaks are equal to
    within the integration error (every peak of the undamped dwell is U0), either scan may
    refine another one: measured U0, U0'' within 5e-8 relative (at rtol 1e-9, the dwell's
    peaks differ by ~1e-12 of the stroke: that much of U0 = 1e-5 .. 1e-1), X''min 2e-13, its
    T 4e-8.  Asserted: U0, U0'' 2e-7 relative, X''min 1e-11 (of 1e-6 of the largest |X''| where
    it is near zero: the rise's minimum at T = 0 when X'' never goes below zero), T 2e-7."""
    pts = np.array([[tau, Fa] for tau, Fa in runs])
    figs = ModelTarget.of("camshaft1", rtol=1e-9).run_points(("tau", "Fa"), pts).figures
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


def test_the_sampling_check_finds_the_peak_a_coarse_scan_misses():
    """CAMSHAFT-2 (5.15) at rtol 1e-4 (5 recorded points a period of the dwell) scanned at its
    recorded points only: the best sample's peak, refined, is 5.4e-5 below the largest |U|
    (the reference recipe finds that); the sampling check verifies every other peak at its
    vertex, refines the one that may be higher and equals a fine scan's (64 samples a step)
    to 1e-12 relative, with no sampling error left."""
    r = Simulator("camshaft2", 3.0, "dp54", rtol=1e-4).run({"tau": 0.2, "Fa": 1.0, "Fv": 2.0})
    fine = extreme_reference(r, "U", 1.05, 3.0, absolute=True, minimum=False, per_step=64)
    naive = extreme_reference(r, "U", 1.05, 3.0, absolute=True, minimum=False, per_step=1)
    coarse = extreme(r, "U", 1.05, 3.0, absolute=True, minimum=False, per_step=1)
    assert fine.value - naive.value > 1e-5 * fine.value
    assert coarse.value == pytest.approx(fine.value, rel=1e-12)
    assert coarse.sampling_error == 0.0


def test_a_scan_with_more_peaks_than_it_verifies_states_its_sampling_error():
    """The one-DOF dwell (3.4) at tau = 0.0213 (between the dips of (3.5) at 1/47 and 1/46)
    over 6 time units of the rise: 470 peaks of |U|, more than the check keeps (160); the
    peaks it could not verify leave a sampling error, which covers the difference to a fine
    scan."""
    r = Simulator("one_dof", 6.0, "dp54", rtol=1e-6).run({"tau": 0.0213})
    fine = extreme_reference(r, "U", 1.0, 6.0, absolute=True, minimum=False, per_step=64)
    coarse = extreme(r, "U", 1.0, 6.0, absolute=True, minimum=False, per_step=1)
    assert coarse.sampling_error > 0.0
    assert abs(coarse.value - fine.value) <= coarse.sampling_error
