"""Compiled integrators, dense output, breakpoints, Result API and input errors."""
import math

import numpy as np
import pytest

from camdyn.runtime.engine import driver
from camdyn.runtime.core import methods
from camdyn.runtime.core.errors import CamdynInputError, SimulationError
from camdyn.runtime.core.compiled import load
from camdyn.runtime.measure.residual import residual
from camdyn.runtime.core.simulator import simulate, stop_times


def test_breakpoints_are_stops_recorded_twice():
    """Integration restarts exactly at T = 1 (and at the law's interior breakpoints)."""
    res = simulate("camshaft1", {"tau": 0.15}, 3.0, "dp54", rtol=1e-8, law="modified-sine", theta=0.1)
    for b in (0.1, 0.9, 1.0):
        hits = np.flatnonzero(res.t == b)
        assert len(hits) == 2, b
        i, j = hits
        np.testing.assert_array_equal(res.y[i], res.y[j])
        assert not np.array_equal(res.mode[i], res.mode[j])   # left and right segment
    cm = load("camshaft1")
    assert stop_times(cm, cm.parameter_vector({}), res.laws, 0.0, 3.0).tolist() == [0.1, 0.9, 1.0, 3.0]


def test_left_and_right_limits_at_a_breakpoint():
    """The simple-harmonic law jumps in H'' at T = 0 and 1: outputs at the doubled point give
    both one-sided values."""
    res = simulate("one_dof", {"tau": 0.3}, 2.0, "dp54", rtol=1e-9, law="simple-harmonic")
    i, j = np.flatnonzero(res.t == 1.0)
    assert res["Hdd"][i] == pytest.approx(-np.pi**2 / 2)
    assert res["Hdd"][j] == 0.0


def test_dp54_dense_output_is_fourth_order():
    """Dense output between steps on a harmonic dwell: error shrinks ~h^5 per step size."""
    errs = []
    for rtol in (1e-6, 1e-8):
        res = simulate("one_dof", {"tau": 0.5}, 3.0, "dp54", rtol=rtol)
        T = np.linspace(1.0, 3.0, 2001)
        s = res.sample(T)
        from camdyn.thesis.theory import numeric as cf

        errs.append(np.max(np.abs(s["U"] - cf.evaluate("u_dwell", T=T, tau=0.5))))
    assert errs[1] < errs[0] / 30
    assert errs[1] < 1e-8


@pytest.mark.parametrize("beta_0", [0.1, 0.3, 0.7, 1.3, 2.9])
def test_rise_start_after_a_long_dwell_step(beta_0):
    """A cam turning at constant speed, everything else at rest in the dwell: the steps grow to
    a large part of the dwell, and the cam argument, linear in t there, is what the event
    search's first secant hits exactly (g = 0).  The rise starts where the cam reaches
    beta_0, to 1e-12 rad.  (Returning the far end of the bracket after such a hit started it
    at beta = 1.11 for beta_0 = 0.3, the end of the dwell step, and 1.4e-9 late for 1.3.)"""
    m = load("dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring")
    p = dict(h_m=0.01, beta_m=1.0, beta_0=beta_0, R_b=1.0, omega_s=1.0, J=1e6, k=1e9, q_b=0.05,
             m_x=1.0, c_x=1e6, q_x=0.05, m_y=1.0, c_y=1e9, q_y=0.05, m_z=1.0, c_z=1e9, q_z=0.05,
             F_0=0.0, c_s=0.0)
    y0 = np.zeros(len(m.state_names))
    y0[m.state_names.index("betad")] = 1.0
    res = simulate("dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring", p, beta_0 + 1.5, "dp54", rtol=1e-8, y0=y0)
    first = np.flatnonzero(res.mode[:, 0] == 1)[0]    # the cam law's first rise segment
    assert res["beta"][first] == pytest.approx(beta_0, abs=1e-12)


def test_result_access_and_outputs():
    res = simulate("camshaft1", {"tau": 0.2, "Fa": 1.0}, 3.0, "rk4", step=0.01)
    assert res.state_names == ["X", "Xd"]
    assert set(res.output_names) >= {"Xdd", "U", "H"}
    np.testing.assert_allclose(res["U"], res["X"] - res["H"], atol=1e-15)
    # the Xdd output is (4.15) at the recorded points
    w2 = (2 * np.pi / 0.2) ** 2
    np.testing.assert_allclose(res["Xdd"], w2 * (res["H"] - res["X"]) / (1 + res["Hd"] ** 2),
                               rtol=1e-12, atol=1e-12)
    s = res.sample([0.5, 1.5])
    assert set(s) >= {"t", "X", "Xd", "Xdd"}
    with pytest.raises(KeyError, match="neither a state nor an output"):
        res["nope"]
    with pytest.raises(CamdynInputError, match="must lie in"):
        res.sample([4.0])
    # RK4 over the rise (100 steps, 4 calls each and one at its start), the dwell stepped over
    # exactly (200 steps, one call for the interval)
    assert res.stats["n_steps"] == 300 and res.stats["n_rhs"] == 4 * 100 + 1 + 1


def test_rhs_cost_is_measurable():
    cm = load("camshaft1")
    ns = driver.rhs_cost_ns(cm.capsule, cm.parameter_vector({}), np.array([0], dtype=np.intc),
                                np.array([0.0]), 0.3, np.array([0.1, 0.2]), 100000)
    assert 0 < ns < 1e5


@pytest.mark.parametrize("params,match", [
    ({"tau": -1}, "tau=-1 is out of range: 0 < tau <= 10"),
    ({"Fa": -0.5}, "Fa=-0.5 is out of range: 0 <= Fa <= 100"),
    ({"tau": float("nan")}, "tau=nan is out of range"),
    ({"tau": "0.1"}, "tau must be a number"),
    ({"omega": 1.0}, "has no parameter omega"),
])
def test_bad_parameters_are_named(params, match):
    with pytest.raises(CamdynInputError, match=match):
        simulate("camshaft1", params, 3.0)


def test_bad_options_are_named():
    with pytest.raises(CamdynInputError, match="unknown model 'camshaft9'"):
        simulate("camshaft9", {}, 3.0)
    with pytest.raises(CamdynInputError, match="unknown method 'euler'"):
        simulate("camshaft1", {}, 3.0, "euler")
    with pytest.raises(CamdynInputError, match="step=0.0 is out of range"):
        simulate("camshaft1", {}, 3.0, "rk4", step=0.0)
    with pytest.raises(CamdynInputError, match="rk4 takes step"):
        simulate("camshaft1", {}, 3.0, "rk4", rtol=1e-6)
    with pytest.raises(CamdynInputError, match="dp54 takes rtol"):
        simulate("camshaft1", {}, 3.0, "dp54", step=0.01)
    with pytest.raises(CamdynInputError, match="rtol=2.0 is out of range"):
        simulate("camshaft1", {}, 3.0, "dp54", rtol=2.0)
    with pytest.raises(CamdynInputError, match="t_end=-1 must be finite and greater than t0=0"):
        simulate("camshaft1", {}, -1.0)
    with pytest.raises(CamdynInputError, match="y0 must be 2 finite numbers"):
        simulate("camshaft1", {}, 3.0, y0=[0.0])
    with pytest.raises(CamdynInputError, match="max_steps"):
        simulate("camshaft1", {}, 3.0, "rk4", step=1e-7, max_steps=1000)


def test_step_budget_is_reported_not_hidden():
    with pytest.raises(SimulationError, match=r"step budget .* at T = "):
        simulate("camshaft1", {"tau": 0.05}, 3.0, "dp54", rtol=1e-12, max_steps=50)


def test_method_objects():
    m = methods.DP54(rtol=1e-6, atol=1e-9)
    res = simulate("one_dof", {"tau": 0.4}, 3.0, m)
    assert res.method is m
    with pytest.raises(CamdynInputError, match="inside the method object"):
        simulate("one_dof", {"tau": 0.4}, 3.0, m, rtol=1e-3)
    assert isinstance(methods.make("koster", step=0.01), methods.Koster)


def test_residual_needs_the_dwell():
    res = simulate("one_dof", {"tau": 0.4}, 0.9, "dp54", rtol=1e-8)
    with pytest.raises(CamdynInputError, match="must cover the rise"):
        residual(res)


def test_koster_failure_mode_is_explained():
    """A step far beyond the thesis's stability limit (dT <= 0.1 tau) makes the mid-step
    iteration diverge: the error says so instead of returning garbage."""
    with pytest.raises(SimulationError, match="use a smaller step"):
        simulate("one_dof", {"tau": 0.1}, 3.0, "koster", step=0.1)


def test_every_recorded_value_is_finite():
    res = simulate("camshaft1", {"tau": 0.06, "Fa": 3.0}, 3.0, "dp54", rtol=1e-6)
    assert np.all(np.isfinite(res.y)) and all(np.all(np.isfinite(v)) for v in res.outputs.values())
    assert math.isfinite(residual(res).U0)


@pytest.mark.parametrize("params", [{"tau": 0.15, "Fa": 2.0}, {"tau": 1, "Fa": 0}, {"tau": np.float64(0.2)},
                                    {"tau": 10.0, "Fa": -0.0}, {}])
def test_parameter_checks_in_c_agree_with_python(params):
    """Floats in range are checked in C (driver.ParameterTable); the rest take the Python checks,
    which place ints and NumPy numbers and name what they refuse.  Either way the same vector."""
    cm = load("camshaft1")
    vec = cm.parameter_vector(params)
    expected = cm._defaults.copy()
    for name, value in params.items():
        expected[cm.parameter_names.index(name)] = float(value)
    assert vec.dtype == float and vec.flags.c_contiguous
    assert vec.tobytes() == expected.tobytes()
    fast = cm._param_table.vector(params)
    assert fast is None or fast.tobytes() == expected.tobytes()
    assert (fast is not None) == all(type(v) is float for v in params.values())


@pytest.mark.parametrize("value, match", [(True, "tau must be a number, got True"),
                                          (0.0, "tau=0 is out of range"),
                                          (math.inf, "tau=inf is out of range"),
                                          (10.000001, "tau=10 is out of range")])
def test_parameters_refused_in_c_are_named_in_python(value, match):
    assert load("camshaft1")._param_table.vector({"tau": value}) is None
    with pytest.raises(CamdynInputError, match=match):
        simulate("camshaft1", {"tau": value}, 3.0, "rk4", step=0.01)


def test_a_record_still_referred_to_is_never_refilled():
    """Integrator.run refills the last run's record only once nothing refers to it (a Result
    dropped): results kept, or views of them, keep their values while later runs go on."""
    from camdyn.runtime.core.simulator import Simulator
    sim = Simulator("camshaft1", 3.0, "rk4", step=1 / 64)
    first = sim.run({"tau": 0.15, "Fa": 2.0})
    y_first = first.y.copy()
    view = sim.run({"tau": 0.2, "Fa": 1.0}).y      # the Result dropped, a view of it kept
    y_view = view.copy()
    for tau in (0.1, 0.3):
        sim.run({"tau": tau})
    np.testing.assert_array_equal(first.y, y_first)
    np.testing.assert_array_equal(view, y_view)
    # a record nobody refers to any more is refilled, not allocated again
    p = sim.model.parameter_vector({})
    stops, cap = sim.stops_and_capacity(p)
    out = sim.integrator.run(p, stops, cap)
    rows = id(out.rows)
    del out
    assert id(sim.integrator.run(p, stops, cap).rows) == rows


def test_runs_of_one_simulator_in_threads_keep_their_own_records():
    """The loops release the GIL: runs of one Simulator in several threads at once must each
    write their own record (the one kept for reuse is taken out while in use)."""
    from concurrent.futures import ThreadPoolExecutor
    from camdyn.runtime.core.simulator import Simulator
    sim = Simulator("camshaft1", 3.0, "rk4", step=1 / 1000)   # a record small enough to keep
    taus = [0.1 + 0.01 * k for k in range(8)]
    serial = {tau: sim.run({"tau": tau}).y.copy() for tau in taus}

    def last_state(tau):
        return tau, sim.run({"tau": tau}).y[-1].copy()

    with ThreadPoolExecutor(4) as pool:
        for tau, y in pool.map(last_state, taus * 8):
            np.testing.assert_array_equal(y, serial[tau][-1])
