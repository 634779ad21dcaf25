"""Exact steps over the dwell (runtime/engine/loops.pxi, _loop_exact).

Where every cam input sits in a dwell and the model is linear and time invariant there
(derive/codegen.py, _linear_in_dwell), the loops step with the interval's propagator
e^(A h) instead of the method.  Checked against the closed-form free vibration of the one-DOF
model (thesis (3.3) with the damping of (6.47)), against the same dwell integrated by DP54 at
rtol 1e-13, and for what must not change: models that are not linear there, the thesis scheme,
the stability map's runs, and the dense output's accuracy at rtol.
"""
import json
import math

import numpy as np
import pytest

from camdyn.runtime.core.methods import RADAU5
from camdyn.runtime.core.simulator import Simulator

DWELL = (1.0, 3.0)       # after the rise (T = 1) to the end of the run


def _free_vibration(tau, q, x0, v0, s):
    """X(1 + s), X'(1 + s) of X'' + 2 q w X' + w^2 (X - 1) = 0, w = 2 pi/tau: the dwell of
    thesis (3.3) with the damping of (6.47), in closed form."""
    w = 2 * math.pi / tau
    wd = w * math.sqrt(1 - q * q)
    c, d = x0 - 1.0, (v0 + q * w * (x0 - 1.0)) / wd
    e = np.exp(-q * w * s)
    x = 1.0 + e * (c * np.cos(wd * s) + d * np.sin(wd * s))
    v = e * (-q * w * (c * np.cos(wd * s) + d * np.sin(wd * s))
             + wd * (-c * np.sin(wd * s) + d * np.cos(wd * s)))
    return x, v


@pytest.mark.parametrize("method, kw", [("dp54", {"rtol": 1e-8}), ("rk4", {"step": 0.02}),
                                        ("rodas4", {"rtol": 1e-5}), ("dop853", {"rtol": 1e-8})])
@pytest.mark.parametrize("q", [0.0, 0.1])
def test_the_dwell_of_one_dof_is_its_closed_form(method, kw, q):
    """Every recorded point of the dwell equals the closed-form solution to 1e-12, whatever
    the method and its setting (one right-hand-side call for the whole interval)."""
    tau, y0 = 0.15, [1.02, -0.3]
    res = Simulator("one_dof", DWELL[1], method, t0=DWELL[0], y0=y0, exact_segments=True,
                    **kw).run({"tau": tau, "q": q})
    x, v = _free_vibration(tau, q, *y0, res.t - DWELL[0])
    assert np.abs(res["X"] - x).max() < 1e-12
    assert np.abs(res["Xd"] - v).max() < 1e-12 * 2 * math.pi / tau
    assert res.stats["n_rhs"] == 1


@pytest.mark.parametrize("model, params", [("camshaft1", {"tau": 0.15, "Fa": 2.0}),
                                           ("one_dof", {"tau": 0.1, "q": 0.05}),
                                           ("chain3", {})])
@pytest.mark.parametrize("method, kw", [("dp54", {"rtol": 1e-10}), ("rk4", {"step": 0.01}),
                                        ("rodas4", {"rtol": 1e-6}), ("dop853", {"rtol": 1e-10})])
def test_the_dwell_equals_its_integration(model, params, method, kw):
    """From the state at the end of a rise, the exact dwell ends where DP54 at rtol 1e-13
    (exact steps off) ends, to 1e-11 of the stroke in the positions and of the stroke times
    the highest frequency (below 100 here) in the rates; the dense output of DP54 and DOP853
    between the exact points stays within their rtol (their extras pass through the exact
    state at interior nodes), the same record for both."""
    rise = Simulator(model, DWELL[0], "dp54", rtol=1e-12).run(params)
    y1 = rise.y[-1]
    exact = Simulator(model, DWELL[1], method, t0=DWELL[0], y0=y1, exact_segments=True,
                      **kw).run(params)
    ref = Simulator(model, DWELL[1], "dp54", rtol=1e-13, t0=DWELL[0], y0=y1,
                    exact_segments=False).run(params)
    n = len(exact.model.state_names) // 2
    err = np.abs(exact.y[-1] - ref.y[-1])
    assert err[:n].max() <= 1e-11 and err[n:].max() <= 1e-11 * 100
    scale = np.abs(ref.y).max(axis=0)
    assert exact.stats["n_rhs"] == 1 and ref.stats["n_rhs"] > 1000
    if method in ("dp54", "dop853"):
        T = np.linspace(*DWELL, 3001)
        a, b = exact.sample(T), ref.sample(T)
        for name in exact.model.state_names:
            assert np.abs(a[name] - b[name]).max() <= 2 * kw["rtol"] * scale.max(), name
    if method == "dop853":
        # every adaptive method records an exact segment alike (a degree-7 extension through
        # the exact state, abi.pxd extra_terms), whatever its own steps' interpolant
        dp54 = Simulator(model, DWELL[1], "dp54", t0=DWELL[0], y0=y1, exact_segments=True,
                         **kw).run(params)
        assert np.array_equal(exact.t, dp54.t) and np.array_equal(exact.y, dp54.y)


def test_a_whole_run_keeps_its_residual():
    """CAMSHAFT-1 (4.15) at tau 0.15, Fa 2: U0 from the run with the exact dwell equals the one
    integrated throughout, to the rise's own error (DP54 at rtol 1e-11 both)."""
    from camdyn.runtime.measure.residual import residual

    params = {"tau": 0.15, "Fa": 2.0}
    a = residual(Simulator("camshaft1", 3.0, "dp54", rtol=1e-11, exact_segments=True).run(params))
    b = residual(Simulator("camshaft1", 3.0, "dp54", rtol=1e-11,
                           exact_segments=False).run(params))
    assert abs(a.U0 - b.U0) < 1e-9
    assert abs(a.U0dd - b.U0dd) < 1e-6 * abs(b.U0dd)


@pytest.mark.parametrize("model, params", [("camshaft2", {}), ("roller", {})])
def test_models_not_linear_in_the_dwell_are_integrated(model, params):
    """A cam turned by a state (CAMSHAFT-2) or a contact that can open (the roller): the
    switch is off, the run the same bit for bit as with exact steps off."""
    a = Simulator(model, 2.0, "dp54", rtol=1e-8, exact_segments=True).run(params)
    b = Simulator(model, 2.0, "dp54", rtol=1e-8, exact_segments=False).run(params)
    assert np.array_equal(a.y, b.y) and a.stats["n_rhs"] == b.stats["n_rhs"]


def test_the_thesis_scheme_and_the_stability_map_integrate_the_dwell():
    """The thesis scheme is run as the thesis ran it, and the stability map must see what an
    unstable RK4 step does in the dwell: neither steps over it."""
    assert not Simulator("one_dof", 3.0, "koster", step=0.01).exact_segments
    assert Simulator("one_dof", 3.0, "rk4", step=0.01).exact_segments
    assert not Simulator("one_dof", 3.0, "dp54").exact_segments
    off = Simulator("one_dof", 3.0, "rk4", step=0.05, check_stability=False,
                    exact_segments=False).run({"tau": 0.1})
    assert abs(off.y[-1, 0]) > 1e3       # h w = 3.1 > 2.83: RK4 blows up in the dwell


def test_exact_segments_must_be_a_bool():
    from camdyn.runtime.core.errors import CamdynInputError

    with pytest.raises(CamdynInputError, match="exact_segments must be True or False"):
        Simulator("one_dof", 3.0, "dp54", exact_segments="yes")


def _largest_of(f, span, n=4001):
    """max |f| over [0, span] of a smooth f (vectorised): a fine grid, then Brent around its
    best sample to 1e-13."""
    from scipy.optimize import minimize_scalar

    s = np.linspace(0.0, span, n)
    k = int(np.argmax(np.abs(f(s))))
    lo, hi = s[max(k - 1, 0)], s[min(k + 1, n - 1)]
    opt = minimize_scalar(lambda x: -abs(f(np.array([x]))[0]), bounds=(lo, hi),
                          method="bounded", options={"xatol": 1e-13})
    return max(abs(f(np.array([0.0, span]))).max(), -opt.fun)


@pytest.mark.parametrize("q", [0.0, 0.1, 0.95])
def test_residual_figures_of_an_exact_dwell_in_closed_form(q):
    """U0 (3.5) and U0'' (3.6) of the one-DOF model (thesis (3.3), damping (6.47)) whose
    dwell was stepped over exactly come from the state at the end of the rise without a
    scan (no sampling error): equal, to 1e-11 of each, to the largest |X - 1| and |X''| of
    the free vibration from that state, found independently (undamped, lightly and heavily
    damped; the solution e^(A s) from SciPy's expm)."""
    from scipy.linalg import expm

    from camdyn.runtime.measure.residual import residual

    tau = 0.15
    w = 2 * math.pi / tau
    res = Simulator("one_dof", 3.0, "dop853", rtol=1e-10).run({"tau": tau, "q": q})
    assert res.exact_segments
    figs = residual(res)
    assert figs.sampling["U0"] == 0.0 and figs.sampling["U0dd"] == 0.0
    y1 = res.sample([1.0])
    z = np.array([y1["X"][0] - 1.0, y1["Xd"][0]])
    A = np.array([[0.0, 1.0], [-w * w, -2 * q * w]])
    states = lambda s: np.array([expm(A * x) @ z for x in np.atleast_1d(s)])  # noqa: E731
    U0 = _largest_of(lambda s: states(s)[:, 0], 2.0)
    U0dd = _largest_of(lambda s: states(s) @ A[1], 2.0)
    assert figs.U0 == pytest.approx(U0, rel=1e-11, abs=1e-15)
    assert figs.U0dd == pytest.approx(U0dd, rel=1e-11, abs=1e-12)
    if q == 0.0:      # the amplitude of a harmonic oscillation, the benchmark's own formula
        assert figs.U0 == pytest.approx(math.hypot(z[0], z[1] / w), rel=1e-13)


def test_sweeps_and_single_runs_take_the_same_closed_form():
    """A sweep of CAMSHAFT-1 (4.15) with DOP853 (its dwell exact) gives the U0 and U0'' that
    single runs give, to rounding, with no sampling error; the scan of the same runs' dense
    output (the exact steps off) agrees to the integration's error.  The sweep needs only the
    state at the end of the rise, so it steps over the dwell in one go: its runs take the
    single run's steps in the rise and one more."""
    from camdyn.runtime.measure.residual import residual
    from camdyn.runtime.studies.sweep import sweep
    from camdyn.runtime.targets.model_target import ModelTarget

    target = ModelTarget.of("camshaft1", t_end=3.0, method="dop853", rtol=1e-10)
    grid = {"Fa": [0.0, 3.0], "tau": [0.06, 0.15, 0.5]}
    table = sweep(target, grid, jobs=1, progress=False, estimate=False)
    for k, (fa, tau) in enumerate(zip(table.columns["Fa"], table.columns["tau"])):
        params = {"Fa": float(fa), "tau": float(tau)}
        one = residual(Simulator("camshaft1", 3.0, "dop853", rtol=1e-10).run(params))
        scan = residual(Simulator("camshaft1", 3.0, "dop853", rtol=1e-10,
                                  exact_segments=False).run(params))
        assert table.columns["U0"][k] == pytest.approx(one.U0, rel=1e-13, abs=1e-17)
        assert table.columns["U0dd"][k] == pytest.approx(one.U0dd, rel=1e-13, abs=1e-13)
        assert one.U0 == pytest.approx(scan.U0, rel=1e-7, abs=1e-12)
        assert one.U0dd == pytest.approx(scan.U0dd, rel=1e-7, abs=1e-9)
        run = Simulator("camshaft1", 3.0, "dop853", rtol=1e-10).run(params)
        in_rise = np.unique(run.t[run.t <= 1.0]).size - 1
        assert table.columns["n_steps"][k] == in_rise + 1      # the dwell: one step


def test_a_sweep_whose_dwell_has_no_closed_form_scans_it():
    """The chain of three masses (six states: the closed form takes two) and the one-DOF
    dwell (3.3) lightly damped (q = 0.1 in (6.47): the closed form): the sweep's U0, U0''
    equal single runs' residual() to 1e-7 relative (two scans of one record for the chain,
    the same closed form for the one-DOF), the chain's dwell recorded step by step, the
    one-DOF's in one step."""
    from camdyn.runtime.measure.residual import residual
    from camdyn.runtime.studies.sweep import sweep
    from camdyn.runtime.targets.model_target import ModelTarget

    for name, grid in (("chain3", {"tau": [0.15, 0.4]}), ("one_dof", {"q": [0.1], "tau": [0.15, 0.4]})):
        target = ModelTarget.of(name, t_end=3.0, method="dop853", rtol=1e-9)
        table = sweep(target, grid, jobs=1, progress=False, estimate=False)
        for k in range(len(table.columns["tau"])):
            params = {a: float(table.columns[a][k]) for a in grid}
            run = Simulator(name, 3.0, "dop853", rtol=1e-9).run(params)
            one = residual(run)
            assert table.columns["U0"][k] == pytest.approx(one.U0, rel=1e-7), params
            assert table.columns["U0dd"][k] == pytest.approx(one.U0dd, rel=1e-7), params
            in_rise = np.unique(run.t[run.t <= 1.0]).size - 1
            if name == "chain3":
                assert table.columns["n_steps"][k] == run.stats["n_steps"] > in_rise + 10
            else:
                assert table.columns["n_steps"][k] == in_rise + 1


def test_the_record_of_a_damped_stiff_dwell_thins_out():
    """The roller held on its damped contact spring (kappa 1000, zeta 0.1): the contact mode,
    about 30 times the follower's frequency, rings out early in the dwell.  Stepped over
    exactly, the record's steps lengthen once it has (the ladder of _loop_exact): within the
    first tenth of the dwell they are as short as the contact mode needs, at its end at least
    100 times longer (measured 256), and the whole dwell takes fewer points than a uniform
    record at the first step would by a factor of 20 (measured 41 against 8192).  Between the
    points the record stays within rtol of the follower's motion integrated by DP54 at rtol
    1e-12 (measured 4e-9 at rtol 1e-5)."""
    params = {"kappa": 1000.0, "zeta": 0.1}
    rise = Simulator("roller_bilateral", 1.0, "dp54", rtol=1e-12).run(params)
    y1 = rise.y[-1]
    atol = (("R", 1.0), ("Rd", 1e3))
    exact = Simulator("roller_bilateral", 3.0, RADAU5(rtol=1e-5, state_atol=atol), t0=1.0,
                      y0=y1, exact_segments=True).run(params)
    ref = Simulator("roller_bilateral", 3.0, "dp54", rtol=1e-12, t0=1.0, y0=y1,
                    exact_segments=False).run(params)
    h = np.diff(exact.t)
    first, last = h[exact.t[:-1] < 1.2], h[-5:]
    assert last.min() >= 100 * first.min()
    assert len(exact.t) * 20 < 2.0 / first.min()
    T = np.linspace(1.0, 3.0, 4001)
    err = np.abs(exact.sample(T)["X"] - ref.sample(T)["X"]).max()
    assert err < 1e-5 * np.abs(ref["X"]).max(), err


def test_integrate_command_steps_over_the_dwell_on_request(capsys):
    """`camdyn integrate --exact-segments on` with radau5 on the roller held on its damped
    contact spring: the same end state as the run integrating the dwell (within the two runs'
    tolerance, rtol 1e-6 of the follower's stroke), in fewer recorded points (the dwell's
    record thins out, test above); a bad value is one line with status 2."""
    from camdyn.runtime.cli import main

    base = ["integrate", "roller_bilateral", "--set", "kappa=1000", "--set", "zeta=0.1",
            "--t-end", "3", "--method", "radau5", "--rtol", "1e-6", "--json",
            "--no-error-estimate"]
    runs = {}
    for flag in ("on", "off"):
        assert main(base + ["--exact-segments", flag]) == 0
        runs[flag] = json.loads(capsys.readouterr().out)
    on, off = runs["on"], runs["off"]
    assert on["exact_segments"] is True and off["exact_segments"] is False
    assert on["n_steps"] * 2 < off["n_steps"]
    assert abs(on["state"]["X"] - off["state"]["X"]) < 1e-6 * 1.0
    with pytest.raises(SystemExit) as exc:        # argparse's refusal
        main(base + ["--exact-segments", "maybe"])
    assert exc.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--exact-segments" in err[0]
