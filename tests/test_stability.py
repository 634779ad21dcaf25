"""Failure is reported, never returned as a number.

Fixed-step methods (RK4, the thesis scheme "koster") refuse a step beyond their stability
boundary and warn near it: the compiled loop checks h |lambda| as it goes (runtime/engine/loops.pxi,
the boundaries in camdyn.runtime.core.stability); DP54 reports where Hairer's stiffness
test fired (stiff_from_T).  References:

* RK4's stability function R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24 and its region: Hairer &
  Wanner, Solving ODEs II, sec. IV.2, fig. 2.1; on the imaginary axis |R(ix)|^2 =
  1 - x^6/72 + x^8/576, so the interval is |x| <= 2 sqrt(2) = 2.828; on the negative real axis
  it ends at 2.785.  An undamped oscillator (the one-DOF model, thesis (3.1)) has
  lambda = +-i omega: the imaginary-axis limit is the one that applies.
* The thesis scheme (4.23)-(4.31) on y'' = -w^2 y: its step matrix (stability.koster_amplification).
* DP54's stiffness test: Hairer & Wanner, sec. IV.2 "Automatic stiffness detection", and the
  code DOPRI5 (3.25, 15 detections, reset after 6 non-stiff steps).
"""
import json
import math
import subprocess
import sys

import numpy as np
import pytest

from camdyn.runtime.core import stability
from camdyn.runtime.core.errors import SimulationError, UnstableStep
from camdyn.runtime.core.simulator import Simulator, simulate

OMEGA = 2 * math.pi / 0.05   # one-DOF model at tau = 0.05: X'' = (2 pi/tau)^2 (H - X)


def camdyn(*args):
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args],
                          capture_output=True, text=True)


# -- the boundaries --------------------------------------------------------------------

def test_rk4_boundaries_from_its_stability_function():
    """Imaginary axis: 2 sqrt(2) exactly (|R(ix)|^2 = 1 - x^6/72 + x^8/576); negative real
    axis: 2.785 (R(-x) = +1: the degree-4 polynomial leaves the unit disc through +1).  ray_boundary finds both from R alone."""
    x = 2 * math.sqrt(2)
    assert abs(stability.rk4_R(1j * x)) == pytest.approx(1.0, abs=1e-12)
    assert abs(stability.rk4_R(1j * 0.999 * x)) < 1 < abs(stability.rk4_R(1j * 1.001 * x))
    assert stability.rk4_R(-stability.RK4_REAL) == pytest.approx(1.0, abs=1e-9)
    assert stability.ray_boundary(stability.rk4_R, math.pi / 2) == pytest.approx(x, rel=1e-6)
    assert stability.ray_boundary(stability.rk4_R, math.pi) == pytest.approx(2.7853, abs=1e-4)
    # the boundary used for an eigenvalue follows its direction
    b = stability.boundary("rk4", np.array([125j, -125.0, -1e-9 + 125j]))
    assert b == pytest.approx([x, stability.RK4_REAL, x], rel=1e-6)


def test_koster_boundary_measured_on_the_test_equation():
    """The thesis scheme on y'' = -w^2 y: measured, the step matrix keeps spectral radius 1 up
    to h w = 2 sqrt(2) = 2.828 and exceeds it beyond; theory: determinant 1 and trace
    2 - x^2/(1 + x^2/8), so |trace| <= 2 exactly for x^2 <= 8.  No amplitude error below it."""
    xs = np.linspace(0.01, 3.5, 35000)
    radius = np.array([np.abs(np.linalg.eigvals(stability.koster_amplification(x))).max()
                       for x in xs])
    measured = xs[np.argmax(radius > 1 + 1e-9)]
    assert measured == pytest.approx(stability.KOSTER_BOUNDARY, abs=2e-4)
    assert stability.KOSTER_BOUNDARY == pytest.approx(2 * math.sqrt(2))
    assert np.allclose(radius[xs < 2.8], 1.0, atol=1e-9)
    for x in (0.5, 2.0, 3.0):
        m = stability.koster_amplification(x)
        assert np.linalg.det(m) == pytest.approx(1.0, abs=1e-12)


def test_koster_step_matrix_is_the_compiled_scheme():
    """The matrix of the analysis is what the compiled scheme does: the one-DOF model in the
    dwell (H = 1) is y'' = -w^2 y about X = 1; 20 steps at h w = 2 agree with M^20."""
    h = 2.0 / OMEGA
    n = 20
    y0 = np.array([1.01, 0.0])
    res = simulate("one_dof", {"tau": 0.05}, 1.0 + n * h, "koster", step=h, t0=1.0, y0=y0)
    m = np.linalg.matrix_power(stability.koster_amplification(2.0), n)
    got = res.y[-1]
    want = m @ np.array([0.01, 0.0])          # (X - 1, X'/w)
    assert got[0] - 1 == pytest.approx(want[0], abs=1e-12)
    assert got[1] / OMEGA == pytest.approx(want[1], abs=1e-12)


def test_warning_thresholds_are_one_percent_per_period():
    """The warning levels are where one period of an undamped mode is off by 1 % (amplitude
    and phase): RK4 at h omega = 0.662, koster (second order, phase only) at 0.278."""
    for method, level in (("rk4", stability.WARN_RK4), ("koster", stability.WARN_KOSTER)):
        assert stability.per_period_error(method, level) == pytest.approx(0.01, rel=2e-3)
        assert stability.per_period_error(method, 0.9 * level) < 0.01
    # the thesis's fine step 0.01 tau is far inside; its limit 0.1 tau (sec. 4.4.2) is not
    assert stability.per_period_error("koster", 2 * math.pi * 0.01) < 1e-3
    assert stability.per_period_error("koster", 2 * math.pi * 0.1) > 0.04


# -- fixed steps refused and warned ------------------------------------------------------

def test_rk4_refused_beyond_the_imaginary_axis_limit_accepted_below():
    """One-DOF, tau = 0.05, undamped: refused at h omega = 1.01 * 2 sqrt(2); accepted (with a
    warning) at 0.99 * 2 sqrt(2) and at 2.80, above the real-axis limit 2.785, where the run
    stays bounded as |R(2.8 i)| < 1 says."""
    with pytest.raises(SimulationError) as exc:
        simulate("one_dof", {"tau": 0.05}, 3.0, "rk4", step=1.01 * stability.RK4_IMAG / OMEGA,
                 exact_segments=False)
    msg = str(exc.value)
    for part in ("with rk4", "step h = 0.0227", "h*rho = 2.857", "rho = 125.66", "at T = 0",
                 "largest stable step 0.02026", "use a smaller step"):
        assert part in msg, msg
    assert "\n" not in msg
    for x in (0.99 * stability.RK4_IMAG, 2.80):
        res = simulate("one_dof", {"tau": 0.05}, 3.0, "rk4", step=x / OMEGA, exact_segments=False)
        assert res.stability.stable and res.stability.h_rho == pytest.approx(x, rel=1e-6)
        assert np.abs(res["X"]).max() < 2
        assert len(res.warnings) == 1 and "near its stability limit" in res.warnings[0]


def _first_crossing(res, h: float, t0: float, t1: float, n: int = 20001) -> tuple:
    """The two grid points between which h rho first exceeds RK4's boundary along a reference
    run, rho the largest |lambda| of the generated Jacobian (driver.eval_jacobian, NumPy's
    eigenvalues) on a fine grid; the eigenvalues there are imaginary (an undamped oscillator),
    so the boundary is 2 sqrt(2)."""
    from camdyn.runtime.engine import driver

    ts = np.linspace(t0, t1, n)
    s = res.sample(ts)
    Y = np.column_stack([s[k] for k in res.state_names])
    rho = np.empty(n)
    for j, (t, y) in enumerate(zip(ts, Y)):
        ev = np.linalg.eigvals(driver.eval_jacobian(res.model.capsule, res.p, res.law_codes,
                                                    res.law_pars, float(t), y))
        assert np.all(np.abs(ev.real) <= 1e-9 * np.abs(ev))
        rho[j] = np.abs(ev).max()
    k = int(np.argmax(h * rho > stability.RK4_IMAG))
    assert k > 0, "no crossing on the grid"
    return float(ts[k - 1]), float(ts[k])


@pytest.mark.parametrize("h", [0.03, 0.025, 0.02])
def test_an_instability_that_starts_midway_is_caught_where_it_starts(h):
    """CAMSHAFT-1 (Fa = 2) starting mid-rise, where its stiffness c = c_c/(1 + Fa H'^2) is least
    (rho = 42): the step is stable there, and h rho crosses RK4's boundary as H' falls towards the
    dwell (rho = 2 pi/tau = 125.7).  The loop stops at the first step whose start lies past the
    crossing found independently (eigenvalues of the generated Jacobian along a DP54 run), with
    rho there; h = 0.02 never crosses and runs (with its warning)."""
    p, y0 = {"tau": 0.05, "Fa": 2.0}, [0.5, 1.9]
    steps = 0.5 / math.ceil(0.5 / h * (1 - 1e-12))      # the equal steps of [0.5, 1]
    if h * OMEGA <= stability.RK4_IMAG:
        res = simulate("camshaft1", p, 3.0, "rk4", step=h, t0=0.5, y0=y0, exact_segments=False)
        assert res.stability.stable and res.stability.rho == pytest.approx(OMEGA, rel=1e-9)
        return
    ref = simulate("camshaft1", p, 1.0, "dp54", rtol=1e-10, t0=0.5, y0=y0)
    lo, hi = _first_crossing(ref, h, 0.5, 1.0)
    with pytest.raises(UnstableStep) as exc:
        simulate("camshaft1", p, 3.0, "rk4", step=h, t0=0.5, y0=y0, exact_segments=False)
    e = exc.value.estimate
    assert lo <= e.T < hi + steps                            # the first step start past it
    assert e.h_rho > stability.RK4_IMAG and not e.stable
    assert e.rho == pytest.approx(OMEGA / math.sqrt(1 + 2 * (1 - math.cos(2 * math.pi * e.T)) ** 2),
                                  rel=1e-9)                  # 2 pi/tau/sqrt(1 + Fa H'^2) there
    assert f"at T = {e.T:.6g}" in str(exc.value) and f"h*rho = {e.h_rho:.4g}" in str(exc.value)


def test_a_contact_that_closes_midway_is_caught_when_it_closes():
    """The roller (sec. 9.2.1) flying free in the groove of a dwell, roller and follower moving
    together at V = 0.01 (no force acts): it reaches the upper wall at T = 1 + (S/2)/V = 1.05,
    where the contact spring kappa c switches on.  h = 0.001 is stable in free flight (the
    linkage with the free roller, omega sqrt(1 + 1/mu) = 192, h rho = 0.19) and beyond the
    boundary in contact: the run stops at the event with rho the contact mode's frequency from
    det(K - w^2 M) = 0, M = diag(1, mu), K = omega^2 [[1, -1], [-1, kappa + 1]] (the model's
    docstring), a four-state Jacobian (the loop's power iteration, not a closed form)."""
    tau, mu, kappa, S, V = 0.15, 0.05, 1000.0, 0.001, 0.01
    w = 2 * math.pi / tau
    K = w ** 2 * np.array([[1.0, -1.0], [-1.0, kappa + 1.0]])
    fast = math.sqrt(np.linalg.eigvals(np.linalg.solve(np.diag([1.0, mu]), K)).real.max())
    p = {"tau": tau, "mu": mu, "kappa": kappa, "S": S}
    y0 = [1 + S / 2, 1 + S / 2, V, V]
    free = simulate("roller", p, 1.04, "rk4", step=1e-3, t0=1.0, y0=y0, modes={"contact": "free"})
    assert free.stability.rho == pytest.approx(w * math.sqrt(1 + 1 / mu), rel=1e-9)
    with pytest.raises(UnstableStep) as exc:
        simulate("roller", p, 1.5, "rk4", step=1e-3, t0=1.0, y0=y0, modes={"contact": "free"})
    e = exc.value.estimate
    assert e.T == pytest.approx(1 + S / 2 / V, abs=1e-9)
    assert e.rho == pytest.approx(fast, rel=1e-6)                   # 5926.8
    assert e.h_rho == pytest.approx(1e-3 * fast, rel=1e-6)


@pytest.mark.parametrize("model,params,t", [("chain3", {"tau": 0.1}, 0.0),
                                            ("camshaft2", {}, 0.0),
                                            ("camshaft2", {}, 0.5)])
def test_more_states_the_check_refuses_and_accepts_at_the_boundary(model, params, t):
    """Models of more than two states: the loop estimates the dominant eigenvalues by a power
    iteration on the Krylov plane {q, J q}; the step 1.01 x boundary/rho (rho from NumPy's
    eigenvalues of the generated Jacobian at the start) is refused there and 0.99 x accepted
    over a step, with rho to 1e-7."""
    from camdyn.runtime.engine import driver
    from camdyn.runtime.core.compiled import load

    m = load(model)
    sim = Simulator(model, 3.0, "dp54")
    y = sim.initial_state(m.parameter_vector(params))
    if t:
        y = simulate(model, params, t, "dp54", rtol=1e-10).y[-1]
    ev = np.linalg.eigvals(driver.eval_jacobian(m.capsule, m.parameter_vector(params),
                                                sim.law_codes, sim.law_pars, t,
                                                np.ascontiguousarray(y)))
    rho = np.abs(ev).max()
    assert np.abs(ev.real).max() <= 1e-9 * rho                      # undamped: 2 sqrt(2)
    h = 1.01 * stability.RK4_IMAG / rho
    with pytest.raises(UnstableStep) as exc:
        simulate(model, params, t + 3 * h, "rk4", step=h, t0=t, y0=y, exact_segments=False)
    assert exc.value.estimate.T == t and exc.value.estimate.rho == pytest.approx(rho, rel=1e-7)
    res = simulate(model, params, t + 0.99 / 1.01 * h, "rk4", step=0.99 / 1.01 * h, t0=t, y0=y,
                   exact_segments=False)
    assert res.stability.stable and res.stability.rho == pytest.approx(rho, rel=1e-7)


@pytest.mark.parametrize("model,params,y0,t0", [
    ("motor1", {}, [0.0], 0.2),                        # lambda = -100: the negative real axis
    ("one_dof", {"tau": 0.05, "q": 0.5}, [1.0, 0.0], 1.0),  # a damped pair, 120 deg
])
def test_the_loop_reads_the_boundary_in_the_eigenvalue_direction(model, params, y0, t0):
    """The compiled check's boundary follows the direction of lambda as ray_boundary does (the
    first exit of |R| > 1 along the ray): refused just beyond it, accepted just inside."""
    from camdyn.runtime.engine import driver
    from camdyn.runtime.core.compiled import load

    m = load(model)
    sim = Simulator(model, t0 + 1.0, "dp54", t0=t0, y0=y0)
    ev = np.linalg.eigvals(driver.eval_jacobian(m.capsule, m.parameter_vector(params),
                                                sim.law_codes, sim.law_pars, t0,
                                                np.array(y0, dtype=float)))
    lam = ev[np.argmax(np.abs(ev))]
    b = stability.ray_boundary(stability.rk4_R, math.atan2(abs(lam.imag), -abs(lam.real)))
    for factor, stable in ((1.002, False), (0.998, True)):
        h = factor * b / abs(lam)
        run = Simulator(model, t0 + 5 * h, "rk4", step=h, t0=t0, y0=y0, check_stability=False,
                        exact_segments=False)
        e = run.run(params).stability
        assert e.stable is stable and e.boundary == pytest.approx(b, rel=2e-5)
        assert e.rho == pytest.approx(abs(lam), rel=1e-9)


def test_koster_refused_beyond_its_boundary():
    """The thesis scheme at h w = 2 pi (step = tau): refused before it runs, and the message
    still says to use a smaller step (tests/test_runtime.py)."""
    with pytest.raises(SimulationError, match="thesis scheme.*use a smaller step"):
        simulate("one_dof", {"tau": 0.05}, 3.0, "koster", step=0.05)


def test_cli_rk4_beyond_the_limit_exits_1_with_one_line():
    """RK4 beyond its stability limit on the one-DOF model: it once printed "U0": 1.13e+69 and
    exit 0."""
    p = camdyn("residual", "--model", "one-dof", "--tau", "0.05", "--method", "rk4", "--step",
               "0.03", "--json")
    assert p.returncode == 1
    assert p.stdout == ""
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1, p.stderr
    for part in ("camdyn residual: run failed:", "rk4", "h = 0.03", "rho = 125.66", "T = 0",
                 "largest stable step 0.02026"):
        assert part in lines[0], lines[0]


def test_cli_camshaft1_near_the_limit_warns_fine_step_does_not():
    """RK4 near its stability limit on CAMSHAFT-1: U0 78 % low at step 0.02 (h rho = 2.51, RK4 damps the
    residual vibration by |R(2.51 i)| = 0.51 a step); it now warns, in JSON and on stderr.
    The run's estimates say the same of its figures: U0 and U0'' carry estimates larger than
    half themselves (U0 = 5.6e-06 ± 2.0e-05, the true value 2.58e-05), which the answer
    contract words as a warning each.  The fine step 0.002 (h rho = 0.25) gives no warning."""
    p = camdyn("residual", "--model", "camshaft1", "--tau", "0.05", "--fa", "2", "--method",
               "rk4", "--step", "0.02", "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert len(out["warnings"]) == 3 and "near its stability limit" in out["warnings"][0]
    assert "h*rho = 2.51" in out["warnings"][0]
    for w, fig in zip(out["warnings"][1:], ("U0", "U0dd")):
        assert w.startswith(f"{fig} = ") and "does not resolve" in w
        assert out[f"{fig}_error"] > 0.5 * out[fig]
    assert out["stiff_from_T"] is None
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 3 and lines[0].startswith("camdyn residual: warning: rk4 step h = 0.02")
    p = camdyn("residual", "--model", "camshaft1", "--tau", "0.05", "--fa", "2", "--method",
               "rk4", "--step", "0.002", "--json")
    assert p.returncode == 0, p.stderr
    assert json.loads(p.stdout)["warnings"] == [] and p.stderr == ""


# -- DP54: Hairer's stiffness test -------------------------------------------------------

def test_dp54_reports_where_a_stiff_problem_became_stiff():
    """One-DOF nearly critically damped (q = 0.99, eigenvalues -omega (0.99 +- 0.14 i)): once
    the residual vibration has died out in the dwell, a loose tolerance lets the step grow
    until h |lambda| reaches DP5's boundary (3.3): stiff by Hairer's definition."""
    res = simulate("one_dof", {"tau": 0.05, "q": 0.99}, 3.0, "dp54", rtol=1e-6)
    assert res.stiff_from_T is not None and 1.0 < res.stiff_from_T < 3.0
    assert res.warnings == [] and res.stability is None


@pytest.mark.parametrize("model,params,rtol", [
    ("one_dof", {"tau": 0.05}, 1e-6),          # undamped: accuracy-limited all along
    ("camshaft1", {"tau": 0.05, "Fa": 2.0}, 1e-10),
    ("chain3", {"tau": 0.1}, 1e-8),
])
def test_dp54_non_stiff_runs_report_none(model, params, rtol):
    """Undamped oscillators are never stiff for DP54 in this sense.  The undamped one-DOF case
    guards the norm: DOPRI5's Euclidean ratio would read omega^2 there and fire."""
    assert simulate(model, params, 3.0, "dp54", rtol=rtol).stiff_from_T is None


def test_cli_stiff_note_and_json():
    p = camdyn("residual", "--model", "one-dof", "--tau", "0.05", "--q", "0.99", "--rtol",
               "1e-6", "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert 1.0 < out["stiff_from_T"] < 3.0
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("camdyn residual: note: the problem became stiff at T = ")
    assert "the implicit (L-stable) method rodas4 (--method rodas4) would take larger steps" in lines[0]


def test_method_names_without_the_compiled_runtime_are_the_methods():
    """`camdyn derive` builds its parser with the known method names when the compiled runtime
    is older than its sources; they are the methods of runtime/core/methods.py."""
    import builtins

    from camdyn.runtime import cli
    from camdyn.runtime.core import methods

    real_import = builtins.__import__

    def no_methods(name, globals=None, locals=None, fromlist=(), level=0):
        if level >= 1 and fromlist and "methods" in fromlist:
            raise ImportError("stale runtime")
        return real_import(name, globals, locals, fromlist, level)

    builtins.__import__ = no_methods
    try:
        fallback = cli.common.method_names()
    finally:
        builtins.__import__ = real_import
    assert fallback == (sorted(methods.METHODS), list(methods.ADAPTIVE))


def test_existing_failures_stay():
    """The step budget and the thesis scheme's non-convergence are still errors of their own."""
    with pytest.raises(SimulationError, match="step budget"):
        simulate("camshaft1", {"tau": 0.05}, 3.0, "dp54", rtol=1e-12, max_steps=50)
    # h w = 2.6: inside the stability boundary; the mid-step fixed-point iteration contracts
    # by x^2/8 = 0.85 only (it used to fail here), Newton's method solves it: the run completes
    res = simulate("one_dof", {"tau": 0.05}, 3.0, "koster", step=2.6 / OMEGA)
    assert np.all(np.isfinite(res.y))
    # a genuinely unsolved mid-step equation still fails with its own message, no number:
    # CAMSHAFT-2 (omega ~ 190) at h omega ~ 5.7, twice the boundary, the check off
    with pytest.raises(SimulationError, match="did not converge"):
        Simulator("camshaft2", 1.5, "koster", step=0.03, check_stability=False).run({})


def test_finite_difference_jacobian_of_the_compiled_rhs():
    """eval_jacobian_fd against the one-DOF model's Jacobian by hand, thesis (3.1) with the damper
    of (6.47): d(X, X')/dT = (X', w^2 (H - X) - 2 q w (X' - H')), J = [[0, 1], [-w^2, -2 q w]]."""
    from camdyn.runtime.engine import driver
    from camdyn.runtime.core.compiled import load

    m = load("one_dof")
    res = simulate("one_dof", {"tau": 0.05, "q": 0.1}, 1.5, "dp54", rtol=1e-8)
    J = driver.eval_jacobian_fd(m.capsule, res.p, res.law_codes, res.law_pars, res.t[:5],
                                 res.y[:5], np.ones(2), res.mode[:5])
    want = np.array([[0.0, 1.0], [-OMEGA ** 2, -2 * 0.1 * OMEGA]])
    assert np.allclose(J, want[None], rtol=1e-7, atol=1e-6)


def test_cli_integrate_refuses_and_reports():
    p = camdyn("integrate", "one_dof", "--set", "tau=0.05", "--t-end", "3", "--method", "rk4",
               "--step", "0.03")
    assert p.returncode == 1 and p.stdout == ""
    assert len(p.stderr.strip().splitlines()) == 1
    assert p.stderr.startswith("camdyn integrate: run failed: one_dof with rk4: step h = 0.03")
    p = camdyn("integrate", "one_dof", "--set", "tau=0.05", "--t-end", "3", "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["stiff_from_T"] is None and out["warnings"] == []
