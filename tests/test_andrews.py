"""Andrews' squeezing mechanism (examples/andrews_squeezer.py): seven bodies, six loop
constraints, against its published reference solution.

Reference: the angles at t = 0.03 s of problem "andrews" of the IVP test set of F. Mazzia and
C. Magherini (University of Bari; its Fortran file gives them in subroutine SOLN, computed
with RADAU5 at tight tolerances), the problem of E. Hairer and G. Wanner, Solving ODEs II,
sec. VII.7.  The model file declares the book's mass matrix, spring, torque and constraints;
nothing here comes from camdyn's own runs.

Measured (relative error of the worst of the seven angles at t = 0.03, rtol 1e-8): dp54
4.3e-9 projection, 1.6e-7 augmented without Baumgarte's terms, 3.5e-9 partitioned; rodas4
5.3e-10, 7.5e-8, 6.2e-11; dop853 2.4e-9, 7.1e-8, 2.4e-9.  At rtol 1e-10 every method and
formulation is within 2e-10 to 1e-9 of the reference (the reference's own last digits: at
rtol 1e-12 rodas4 still differs by 2.7e-10).  Asserted 1e-6 at rtol 1e-8.
"""
import os
from pathlib import Path

import numpy as np
import pytest

from camdyn.runtime.core import ondemand
from camdyn.runtime.core.simulator import Simulator, simulate

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "andrews_squeezer.py"
ANGLES = ("beta", "Theta", "gamma", "Phi", "delta", "Omega", "epsilon")
REFERENCE = np.array([0.1581077119629904e+2, -0.1575637105984298e+2, 0.4082224013073101e-1,
                      -0.5347301163226948e+0, 0.5244099658805304e+0, 0.5347301163226948e+0,
                      0.1048080741042263e+1])
"""The seven angles at t = 0.03 s (IVP test set, "andrews", SOLN)."""
FORMULATIONS = {"augmented": 0.0, "partitioned": 1.0, "projection": 2.0}


@pytest.fixture(scope="module")
def squeezer(tmp_path_factory):
    """The model file built on demand into a cache of the test's own (about 40 s once)."""
    cache = tmp_path_factory.mktemp("cache")
    old = os.environ.get(ondemand.ENV_CACHE)
    os.environ[ondemand.ENV_CACHE] = str(cache)
    try:
        yield ondemand.model_file(EXAMPLE)
    finally:
        if old is None:
            del os.environ[ondemand.ENV_CACHE]
        else:
            os.environ[ondemand.ENV_CACHE] = old


def _angles(res):
    return np.array([res[name][-1] for name in ANGLES])


@pytest.mark.parametrize("method", ["dp54", "rodas4", "dop853"])
@pytest.mark.parametrize("formulation", sorted(FORMULATIONS))
def test_reference_solution_at_0_03(squeezer, method, formulation):
    """Every method in every formulation reaches the published angles at rtol 1e-8 to 1e-6
    relative (worst measured 1.6e-7: dp54 augmented without Baumgarte's terms)."""
    res = simulate(squeezer, {"formulation": FORMULATIONS[formulation], "w_B": 0.0},
                   t_end=0.03, method=method, rtol=1e-8)
    err = np.abs(_angles(res) - REFERENCE) / np.abs(REFERENCE)
    assert err.max() < 1e-6, dict(zip(ANGLES, err))


@pytest.mark.parametrize("rtol", [1e-8, 1e-10])
def test_rodas4_with_the_exact_jacobian(squeezer, rtol, record_property):
    """rodas4, projection: the exact Jacobian costs no right-hand-side calls, so a step costs
    its five stages, the slope at the new point and the one at the projected state (7 a
    step, against 7 + 2 n_states + 2 = 37 with differences), and the method keeps its order
    on the constraints: measured 1,294 steps and 9,215 calls at rtol 1e-8, 4,107 and 28,861
    at rtol 1e-10 (with the difference Jacobian and Baumgarte's terms: 2,090 steps and
    75,000 calls at rtol 1e-8).  Asserted: at most 8 calls per attempted step, and a
    tenfold tighter tolerance costing at most 10^(1/4) x 1.5 the steps of an order-4 method
    (measured 3.2), the error within 1e-6 (rtol 1e-8) and 1e-8 (rtol 1e-10) of the
    reference."""
    res = simulate(squeezer, {"formulation": 2.0}, t_end=0.03, method="rodas4", rtol=rtol)
    st = res.stats
    record_property("n_steps", st["n_steps"])
    record_property("n_rhs", st["n_rhs"])
    print(f"rodas4 rtol {rtol:g}: {st['n_steps']} steps, {st['n_rhs']} rhs calls")
    assert st["n_rhs"] <= 8 * (st["n_steps"] + st["n_rejected"])
    err = np.abs(_angles(res) - REFERENCE) / np.abs(REFERENCE)
    assert err.max() < (1e-6 if rtol == 1e-8 else 1e-8)


def test_rodas4_keeps_its_order_in_the_tolerance(squeezer):
    """Steps of rodas4 (projection) against rtol: an order-4 method whose error estimate is of
    order 3 takes about 10^(1/4) = 1.8 times the steps for each tenfold tighter tolerance;
    measured 1,294 -> 4,107 (3.2x, 1.78 a decade) from 1e-8 to 1e-10.  The difference
    Jacobian with Baumgarte's terms lost that order: 1.85 million steps at rtol 1e-12.
    Asserted: at most 4x over the two decades."""
    n = [simulate(squeezer, {"formulation": 2.0}, t_end=0.03, method="rodas4",
                  rtol=rtol).stats["n_steps"] for rtol in (1e-8, 1e-10)]
    assert n[1] < 4 * n[0]


def test_projection_keeps_the_state_on_the_constraints(squeezer):
    """Projection (dp54, rtol 1e-6): every recorded state satisfies the six loop constraints
    to rounding (measured |g| <= 4e-17 m, asserted 1e-14 m), where the augmented form without
    Baumgarte's terms drifts (measured 6.4e-8 m by t = 0.03; asserted 100 times the
    projection's)."""
    res = simulate(squeezer, {"formulation": 2.0}, t_end=0.03, method="dp54", rtol=1e-6)
    phi = _residuals(res)
    assert phi.max() < 1e-14
    drift = _residuals(simulate(squeezer, {"formulation": 0.0, "w_B": 0.0}, t_end=0.03,
                                method="dp54", rtol=1e-6))
    assert drift.max() > 100 * phi.max()


def _residuals(res):
    """|g_k| of the book's loop constraints (7.7), typed in with its data (table 7.1), at
    every recorded state, in m."""
    rr, d, ss, e, zt, zf, u = 7e-3, 28e-3, 35e-3, 2e-2, 4e-2, 2e-2, 4e-2
    xa, ya, xb, yb = -.06934, -.00227, -.03635, .03273
    be, th, ga, ph, de, om, ep = (res[name] for name in ANGLES)
    crank_x = rr * np.cos(be) - d * np.cos(be + th)
    crank_y = rr * np.sin(be) - d * np.sin(be + th)
    g = [crank_x - ss * np.sin(ga) - xb, crank_y + ss * np.cos(ga) - yb,
         crank_x - e * np.sin(ph + de) - zt * np.cos(de) - xa,
         crank_y + e * np.cos(ph + de) - zt * np.sin(de) - ya,
         crank_x - zf * np.cos(om + ep) - u * np.sin(ep) - xa,
         crank_y - zf * np.sin(om + ep) + u * np.cos(ep) - ya]
    return np.abs(np.array(g))


def test_initial_values_from_the_independent_angle(squeezer):
    """Given only the crank angle beta (the others 0.1 rad off the book's consistent values,
    the rates 0), the run starts from the dependent angles of Newton's method on the six
    constraints, with a note naming them: the book's (7.10) values (measured 3.9e-16 rad,
    asserted 1e-12 rad)."""
    y0 = squeezer.initial_state()
    book = y0[:7].copy()
    y0[1:7] += 0.1
    sim = Simulator(squeezer, 0.03, "dp54", rtol=1e-8, y0=y0)
    res = sim.run({"formulation": 2.0})
    assert np.abs(res.y[0][:7] - book).max() < 1e-12
    assert any("recovered from the independent coordinates" in w for w in res.warnings)
