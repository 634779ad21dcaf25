"""RKN12(10) (Dormand, El-Mikkawy & Prince 1987; runtime/engine/rkn12.pxd, loops.pxi): its
tableau's conditions, closed forms, CAMSHAFT-1 (4.15) against a tight DP54 reference, the
dense output made on demand, and the models it must refuse."""
from __future__ import annotations

import math

import numpy as np
import pytest

from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.core.simulator import Simulator, simulate
from camdyn.runtime.engine import driver

from .test_exact_segments import _free_vibration

TAB = driver.rkn12_tableau()


@pytest.mark.parametrize("k", range(12))
def test_velocity_weights_integrate_polynomials_to_degree_11(k):
    """sum b'_i c_i^k = 1/(k + 1) for k <= 11 (order 12); the order-10 weights to k <= 9."""
    c = TAB["c"]
    assert np.dot(TAB["bv"], c**k) == pytest.approx(1 / (k + 1), abs=2e-15)
    if k <= 9:
        assert np.dot(TAB["bvl"], c**k) == pytest.approx(1 / (k + 1), abs=2e-15)


@pytest.mark.parametrize("k", range(11))
def test_position_weights_integrate_twice(k):
    """sum b_i c_i^k = 1/((k + 1)(k + 2)) for k <= 10: q(h) = q + h q' + h^2 sum b_i g_i is
    exact for g = t^k; the order-10 weights to k <= 8."""
    c = TAB["c"]
    assert np.dot(TAB["bp"], c**k) == pytest.approx(1 / ((k + 1) * (k + 2)), abs=2e-15)
    if k <= 8:
        assert np.dot(TAB["bpl"], c**k) == pytest.approx(1 / ((k + 1) * (k + 2)), abs=2e-15)


def test_stage_rows_integrate_twice():
    """sum_j a_ij = c_i^2/2 (every stage's position right for a constant g) and, from the
    third stage on, sum_j a_ij c_j = c_i^3/6 (for a linear one; the second stage has one
    coefficient, which the first condition takes)."""
    c, A = TAB["c"], TAB["A"]
    assert np.abs(A.sum(axis=1) - c**2 / 2).max() < 1e-14
    assert np.abs((A @ c - c**3 / 6)[2:]).max() < 1e-14
    assert abs(A[1] @ c - c[1] ** 3 / 6) > 1e-7


@pytest.mark.parametrize("tau", [0.07, 0.15])
def test_the_free_vibration_to_its_closed_form(tau):
    """The undamped one-DOF dwell (3.1) integrated step by step (exact steps off) at rtol 1e-11:
    every recorded point and 3001 samples of the dense output (degree 11, made on first use)
    within 1e-10 of the closed form."""
    y0 = [1.02, -0.3]
    res = Simulator("one_dof", 3.0, "rkn12", rtol=1e-11, t0=1.0, y0=y0,
                    exact_segments=False).run({"tau": tau})
    x, v = _free_vibration(tau, 0.0, *y0, res.t - 1.0)
    w = 2 * math.pi / tau
    assert np.abs(res["X"] - x).max() < 1e-10 and np.abs(res["Xd"] - v).max() < 1e-10 * w
    T = np.linspace(1.0, 3.0, 3001)
    s = res.sample(T)
    x, v = _free_vibration(tau, 0.0, *y0, T - 1.0)
    assert np.abs(s["X"] - x).max() < 1e-10 and np.abs(s["Xd"] - v).max() < 1e-10 * w
    # long steps, a sixth of a period and more, between the points the dense output joins
    assert w * np.diff(res.t).max() > 0.8


def test_camshaft1_against_dp54_with_fewer_calls_than_dop853():
    """CAMSHAFT-1 (4.15), tau 0.15, Fa 2: U0 at rtol 1e-11 within 1e-12 of DP54's at rtol
    1e-13; the dense output over the rise within 1e-10 of DP54's; and at rtol 1e-10 fewer than
    two thirds of DOP853's right-hand-side calls at rtol 1e-10 for no larger an error in the
    state at the end of the rise."""
    p = {"tau": 0.15, "Fa": 2.0}
    ref = simulate("camshaft1", p, 3.0, "dp54", rtol=1e-13, exact_segments=False)
    run = simulate("camshaft1", p, 3.0, "rkn12", rtol=1e-11)

    def at_one(r):
        i = int(np.searchsorted(r.t, 1.0))     # the left limit at the end of the rise
        return r.y[i]
    w = 2 * math.pi / 0.15
    u0 = [math.hypot(at_one(r)[0] - 1, at_one(r)[1] / w) for r in (ref, run)]
    assert abs(u0[0] - u0[1]) < 1e-12
    T = np.linspace(0.0, 1.0, 1001)
    assert np.abs(run.sample(T)["X"] - ref.sample(T)["X"]).max() < 1e-10
    runs = {m: simulate("camshaft1", p, 3.0, m, rtol=1e-10) for m in ("dop853", "rkn12")}
    err = {m: np.abs(at_one(r) - at_one(ref)).max() for m, r in runs.items()}
    assert err["rkn12"] <= err["dop853"]
    assert runs["rkn12"].stats["n_rhs"] * 3 < runs["dop853"].stats["n_rhs"] * 2


def test_dense_output_on_first_use_takes_the_same_steps():
    """CAMSHAFT-1 at rtol 1e-9, dwell integrated: the run with the dense output left to its
    first use and the one making it as it goes record the same points bit for bit; the first
    makes 128 calls fewer a step; their dense outputs agree to rounding."""
    p = {"tau": 0.15, "Fa": 2.0}
    lean, full = (Simulator("camshaft1", 3.0, "rkn12", rtol=1e-9, exact_segments=False,
                            dense_output=d).run(p) for d in (False, True))
    assert np.array_equal(lean.t, full.t) and np.array_equal(lean.y, full.y)
    assert full.stats["n_rhs"] - lean.stats["n_rhs"] == 128 * full.stats["n_steps"]
    T = np.linspace(0.0, 3.0, 901)
    assert np.abs(lean.sample(T)["X"] - full.sample(T)["X"]).max() < 1e-15
    assert lean.n_extra == 8


@pytest.mark.parametrize("model, params, msg", [
    ("camshaft2", {}, "camshaft2: it has events"),
    ("one_dof", {"tau": 0.1, "q": 0.1}, "one_dof: the acceleration X'' depends on the velocity Xd"),
    ("pendulum_xy", {}, "pendulum_xy: it is constrained"),
])
def test_models_it_cannot_integrate_are_refused(model, params, msg):
    with pytest.raises(CamdynInputError, match=msg):
        simulate(model, params, 1.0, "rkn12")


def test_first_order_states_are_refused():
    """motor2 (the motor's slip, a first-order state, App. 5) is refused before any run."""
    with pytest.raises(CamdynInputError, match="motor2: it has first-order states"):
        Simulator("motor2", 1.0, "rkn12")


def test_the_undamped_one_dof_and_the_chain_run():
    """The models it is for: one-DOF with q = 0 (the velocity block of the Jacobian vanishes
    exactly at these parameters) and the chain, against DOP853 at rtol 1e-11 to 1e-9."""
    for name, p in (("one_dof", {"tau": 0.12, "q": 0.0}), ("chain3", {})):
        a = simulate(name, p, 3.0, "rkn12", rtol=1e-11)
        b = simulate(name, p, 3.0, "dop853", rtol=1e-11)
        assert np.abs(a.y[-1] - b.y[-1]).max() < 1e-9 * max(1.0, np.abs(b.y[-1]).max())
