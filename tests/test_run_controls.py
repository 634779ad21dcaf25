"""The run's controls and what comes back, on every command that integrates: --atol and
--state-atol (and a scene's [run] atol, state_atol), the tolerance scales of rate states, the
outputs at the end of the run with their estimates, and an estimate whose second run fails
("estimate unavailable").  Short runs, in-process through cli.main."""
import json
import math

import numpy as np
import pytest

from camdyn.runtime import cli
from camdyn.runtime.core.compiled import load
from camdyn.runtime.core.methods import DP54
from camdyn.runtime.core.simulator import Simulator, simulate, tolerance_scales
from camdyn.runtime.targets.model_target import ModelTarget


def run_cli(capsys, *args):
    try:
        rc = cli.main(list(args))
    except SystemExit as exc:
        rc = exc.code
    out, err = capsys.readouterr()
    return rc, out, err


# -- --atol and --state-atol -------------------------------------------------------------------

def test_atol_and_state_atol_reach_the_run(capsys):
    """The state integrate reports is that of a Simulator given the same tolerances, to the last
    bit, and the tolerances change the run (more steps for a tighter atol)."""
    args = ["integrate", "one_dof", "--t-end", "2", "--set", "tau=0.3", "--json"]
    rc, out, err = run_cli(capsys, *args, "--atol", "1e-12", "--state-atol", "Xd=1e-14")
    assert rc == 0, err
    got = json.loads(out)
    method = DP54(rtol=1e-8, atol=1e-12, state_atol=(("Xd", 1e-14),))
    ref = Simulator("one_dof", 2.0, method).run({"tau": 0.3})
    assert got["n_steps"] == ref.stats["n_steps"]
    assert got["state"]["X"] == pytest.approx(ref["X"][-1], rel=1e-14)
    rc, out, _ = run_cli(capsys, *args)
    assert json.loads(out)["n_steps"] < got["n_steps"]


def test_the_tighter_twin_tightens_every_tolerance():
    t = ModelTarget.of("one_dof", {"tau": 0.3}, rtol=1e-8, atol=1e-6, state_atol={"X": 1e-7})
    m = t.tighter().method()
    assert (m.rtol, m.atol) == pytest.approx((1e-10, 1e-8))
    assert dict(m.state_atol) == pytest.approx({"X": 1e-9})


@pytest.mark.parametrize("args, flag, words", [
    (["--atol", "0"], "--atol", "atol > 0"),
    (["--atol", "nan"], "--atol", "atol > 0"),
    (["--atol=-1e-9"], "--atol", "atol > 0"),
    (["--state-atol", "nope=1e-9"], "--state-atol", "its states are X, Xd"),
    (["--state-atol", "X=-1"], "--state-atol", "> 0"),
    (["--state-atol", "X"], "--state-atol", "is not NAME=VALUE"),
    (["--method", "rk4", "--step", "0.01", "--atol", "1e-6"], "", "rk4 takes step"),
])
def test_bad_tolerance_is_one_line_status_2(capsys, args, flag, words):
    rc, out, err = run_cli(capsys, "integrate", "one_dof", "--t-end", "2", *args)
    assert rc == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(f"camdyn integrate: error: {('argument ' + flag) if flag else ''}")
    assert words in err


@pytest.mark.parametrize("command", [
    ["residual", "--model", "one-dof", "--tau", "0.3"],
    ["simulate", "spring_loaded"],
    ["sweep", "one_dof", "--grid", "tau=0.3,0.4"],
    ["run", "spring_loaded"],
    ["beam-follower"],
])
def test_every_integrating_command_takes_the_tolerances(capsys, tmp_path, command):
    """--atol and --state-atol on every command that integrates adaptively: checked before any
    run, in one line naming the flag (an unknown state lists the model's states)."""
    extra = ["--out", str(tmp_path / "o")] if command[0] in ("sweep", "run") else []
    rc, out, err = run_cli(capsys, *command, *extra, "--atol", "0")
    assert rc == 2 and err.count("\n") == 1 and "argument --atol: " in err, err
    rc, out, err = run_cli(capsys, *command, *extra, "--state-atol", "nope=1e-9")
    assert rc == 2 and err.count("\n") == 1 and "argument --state-atol: " in err, err
    assert "has no state nope; its states are" in err


def test_residual_atol_is_the_runs():
    """camdyn residual's --atol is the method's: U0 equals a Python run with that atol."""
    import argparse

    from camdyn.runtime.cli import residual
    from camdyn.runtime.measure.residual import residual as figures

    args = argparse.Namespace(model="one-dof", tau=0.3, fa=None, fv=None, q=0.0,
                              law="cycloidal", theta=None, method="dp54", rtol=None, step=None,
                              t_end=None, atol=1e-9, state_atol=None)
    t = residual.target(args)
    assert t.method().atol == 1e-9
    res = simulate("one_dof", {"tau": 0.3, "q": 0.0}, 3.0, "dp54", rtol=1e-10, atol=1e-9)
    assert t.run().figures["U0"] == pytest.approx(figures(res).U0, rel=1e-12)


# -- scene files ---------------------------------------------------------------------------------

def _scene(tmp_path, name, extra):
    from camdyn.runtime.targets import scene_files

    text = scene_files.builtin(name).read_text()
    path = tmp_path / f"{name}.toml"
    path.write_text(text.replace("[run]\n", "[run]\n" + extra, 1))
    return str(path)


@pytest.mark.parametrize("name", ["spring_loaded", "beam_paper", "default"])
def test_scene_run_table_takes_the_tolerances(tmp_path, name):
    from camdyn.runtime.targets.resolve import scene

    path = _scene(tmp_path, name, "atol = 1e-7\n")
    assert scene(path).method().atol == 1e-7
    assert scene(path).tighter().method().atol == pytest.approx(1e-9)


@pytest.mark.parametrize("name", ["spring_loaded", "beam_paper", "default"])
@pytest.mark.parametrize("extra, words", [
    ("atol = 0\n", "run.atol=0 is out of range: atol > 0"),
    ("atol = \"x\"\n", "run.atol must be a number"),
    ("state_atol = 1e-9\n", "[run.state_atol] must be a table"),
    ("state_atol = { x = -1.0 }\n", "run.state_atol.x=-1 is out of range"),
])
def test_scene_bad_tolerance_is_refused_by_name(tmp_path, name, extra, words):
    from camdyn.runtime.core.errors import CamdynInputError
    from camdyn.runtime.targets.resolve import scene

    with pytest.raises(CamdynInputError) as exc:
        scene(_scene(tmp_path, name, extra))
    assert words in str(exc.value)


def test_scene_state_atol_unknown_state_lists_the_states(capsys, tmp_path):
    path = _scene(tmp_path, "spring_loaded", "state_atol = { nope = 1e-9 }\n")
    rc, out, err = run_cli(capsys, "simulate", path)
    assert rc == 2 and err.count("\n") == 1 and "has no state nope; its states are" in err


def test_scene_unknown_run_key_names_the_settings(tmp_path):
    from camdyn.runtime.core.errors import CamdynInputError
    from camdyn.runtime.targets.resolve import scene

    with pytest.raises(CamdynInputError, match="run.atoll is not a run setting; settings are "
                                               ".*atol, state_atol"):
        scene(_scene(tmp_path, "spring_loaded", "atoll = 1e-9\n"))


# -- tolerance scales of rate states -----------------------------------------------------------

def test_rate_scales_follow_the_drive():
    """A rate's tolerance scale is its coordinate's times the drive rate: 1 for the thesis's
    models (time in rises), Omega for the beam follower (time in s, the cam at Omega from the
    start)."""
    m = load("one_dof")
    p = m.parameter_vector()
    np.testing.assert_array_equal(tolerance_scales(m, p, m.initial_state(p)), m.state_scales())
    from camdyn.runtime.targets import beam

    case = beam.Case(omega=300.0)
    b = load(case.model)
    y0 = beam.initial_state(case, b)
    scales = tolerance_scales(b, b.parameter_vector(beam.parameters(case)), y0)
    n = b.manifest["n_q"]
    np.testing.assert_allclose(scales[:n], b.state_scales()[:n], rtol=0)
    np.testing.assert_allclose(scales[n:], b.state_scales()[n:] * 300.0, rtol=1e-15)


# -- outputs at the end --------------------------------------------------------------------------

def _one_dof_closed_form(tau: float, T: float) -> tuple[float, float]:
    """(U, X'') at T > 1 of the undamped one-DOF follower (3.1) after a cycloidal rise, from
    rest: X'' + w^2 X = w^2 H, w = 2 pi/tau, solved by hand on the rise and as a free vibration
    about H = 1 after it."""
    w, P = 2 * math.pi / tau, 2 * math.pi
    X1 = 1 - 0 + P**2 / (w * (w * w - P * P)) * math.sin(w)
    Xd1 = 1 - w * w / (w * w - P * P) + P**2 / (w * w - P * P) * math.cos(w)
    u1 = X1 - 1
    U = u1 * math.cos(w * (T - 1)) + Xd1 / w * math.sin(w * (T - 1))
    return U, -w * w * U


def test_integrate_json_outputs_at_the_end_against_the_closed_form(capsys):
    rc, out, err = run_cli(capsys, "integrate", "one_dof", "--t-end", "2", "--set", "tau=0.3",
                           "--json")
    assert rc == 0, err
    got = json.loads(out)
    U, Xdd = _one_dof_closed_form(0.3, 2.0)
    assert set(got["outputs"]) == set(load("one_dof").output_names)
    for name, exact in (("U", U), ("Xdd", Xdd)):
        v, e = got["outputs"][name], got["outputs_error"][name]
        assert 0 < e < 1e-5 * abs(exact)
        assert abs(v - exact) < e       # the estimate covers the error
    # the estimate is 1.5 times the change one notch tighter: an independent run at rtol/100
    tight = simulate("one_dof", {"tau": 0.3}, 2.0, "dp54", rtol=1e-10)
    assert got["outputs_error"]["U"] == pytest.approx(
        1.5 * abs(got["outputs"]["U"] - tight["U"][-1]), rel=1e-9)


def test_integrate_multipliers_at_the_end(capsys):
    """pendulum_xy: its multiplier lambda_rod (after its own outputs) at the end against the
    rod's force from the state there, lambda = m (v^2 - g y)/(2 L^2) for Phi = x^2 + y^2 - L^2."""
    rc, out, err = run_cli(capsys, "integrate", "pendulum_xy", "--t-end", "2", "--json")
    assert rc == 0, err
    got = json.loads(out)
    m = load("pendulum_xy")
    assert list(got["outputs"]) == m.output_names and m.output_names[-1] == "lambda_rod"
    p = {s["name"]: s["default"] for s in m.manifest["parameters"]}
    s = got["state"]
    lam = p["m"] * (s["xd"] ** 2 + s["yd"] ** 2 - p["g"] * s["y"]) / (2 * p["L"] ** 2)
    e = got["outputs_error"]["lambda_rod"]
    assert e is not None and abs(got["outputs"]["lambda_rod"] - lam) < 10 * e + 1e-12 * abs(lam)


def test_simulate_json_outputs_at_the_end(capsys):
    rc, out, err = run_cli(capsys, "simulate", "spring_loaded", "--json")
    assert rc == 0, err
    got = json.loads(out)
    from camdyn.runtime.targets import dynacam, scene_files

    sc = scene_files.load("spring_loaded")
    _, res = dynacam.run(sc)
    _, tight = dynacam.run(sc, method=dynacam.scene_method(sc).tighter())
    assert list(got["outputs"]) == res.output_names
    for name in ("Xdd", "U"):
        assert got["outputs"][name] == res[name][-1]
        assert got["outputs_error"][name] == pytest.approx(
            1.5 * abs(res[name][-1] - tight[name][-1]), rel=1e-9, abs=1e-300)
    rc, out, _ = run_cli(capsys, "simulate", "spring_loaded")
    assert "outputs at the end of the run (T = 1.5):" in out


# -- an estimate whose second run fails ------------------------------------------------------

def _budget() -> int:
    """A step budget (accepted and rejected steps) the run keeps and its twin one notch
    tighter exhausts."""
    def steps(rtol):
        s = simulate("one_dof", {"tau": 0.3}, 2.0, "dp54", rtol=rtol).stats
        return s["n_steps"] + s["n_rejected"]

    base, tight = steps(1e-8), steps(1e-9)
    assert tight > base + 10
    return base + 10


def test_failed_estimate_run_leaves_the_answer(capsys):
    budget = _budget()
    args = ["integrate", "one_dof", "--t-end", "2", "--set", "tau=0.3", "--max-steps", str(budget)]
    rc, out, err = run_cli(capsys, *args, "--json")
    assert rc == 0, err
    got = json.loads(out)
    free = simulate("one_dof", {"tau": 0.3}, 2.0, "dp54", rtol=1e-8)
    assert got["state"]["X"] == pytest.approx(free["X"][-1], rel=1e-14)
    assert got["outputs"]["U"] == free["U"][-1]
    assert set(got["state_error"].values()) == {None}
    assert set(got["outputs_error"].values()) == {None}
    assert got["estimate_unavailable"].startswith("the run one notch tighter failed (one_dof "
                                                  "with dp54: the step budget")
    (w,) = got["warnings"]
    assert w.startswith("estimate unavailable: the run one notch tighter failed")
    assert err.startswith("camdyn integrate: warning: estimate unavailable: ")
    rc, out, err = run_cli(capsys, *args)
    assert rc == 0 and out.count("(estimate unavailable)") == 2 + len(free.output_names)


def test_failed_estimate_run_in_a_sweep_keeps_the_points():
    """A grid's tighter chunk that fails: the figures stay (equal to a sweep without the
    estimate), the estimates are NaN and the warnings column says why."""
    from camdyn.runtime.studies import sweep

    budget = _budget()
    t = ModelTarget.of("one_dof", {"tau": 0.3}, rtol=1e-8, t_end=2.0, max_steps=budget)
    res = sweep.sweep(t, {"tau": [0.3]}, jobs=1, progress=False)
    plain = sweep.sweep(t, {"tau": [0.3]}, jobs=1, progress=False, estimate=False)
    assert res["U0"][0] == plain["U0"][0]
    assert math.isnan(res["U0_error"][0])
    assert "estimate unavailable: the run one notch tighter failed" in res["warnings"][0]
