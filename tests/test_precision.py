"""Work-precision studies (runtime/studies/precision.py) and the SciPy peers (runtime/studies/peers.py): the reference is good enough, the scores are true errors, errors fall at the methods'
orders, a peer on the generated rhs converges to the same answer, the command writes its files
and refuses bad input in one line."""
import csv
import json

import numpy as np
import pytest

from camdyn.runtime.measure import references as closed_forms
from camdyn.runtime.studies import peers, precision
from camdyn.runtime.cli import main
from camdyn.runtime.targets.resolve import load_scene
from camdyn.runtime.core.compiled import load
from camdyn.runtime.measure.residual import residual
from camdyn.runtime.core.simulator import simulate

TAU = 0.15


@pytest.fixture(scope="module")
def problem():
    return precision.problem("one_dof", {"tau": TAU}, None)


@pytest.fixture(scope="module")
def study(problem):
    return precision.study(problem, methods=["dp54", "rk4"], peers=["DOP853"], quick=True)


def _ok(st, method):
    return [r for r in st.rows if r.method == method and r.status == "ok"]


def test_reference_error_estimate_small_against_the_ladder(study):
    est = study.reference["error_estimate"]
    assert 0 < est < 1e-9
    errors = [r.error for r in study.rows if r.status == "ok"]
    assert est < 0.01 * min(errors)


def test_reference_meets_the_closed_form(study):
    assert study.reference["figures"]["U0"] == pytest.approx(closed_forms.U0(TAU), rel=1e-9)
    assert study.reference["figures"]["U0dd"] == pytest.approx(closed_forms.U0dd(TAU), rel=1e-9)


@pytest.mark.parametrize("method,kw", [("dp54", {"rtol": 1e-6}), ("rk4", {"step": 0.004})])
def test_scored_error_is_the_true_error(problem, study, method, kw):
    """U0 has a closed form (3.5): the scored error of U0 agrees with the true one within 5 %
    (the reference's own error is far below the run's)."""
    res = simulate("one_dof", {"tau": TAU}, 3.0, method, **kw)
    figs = problem.figures(res)
    scored = precision.score(problem, figs, res.y[-1], study.reference)["U0"]
    true = abs(residual(res).U0 - closed_forms.U0(TAU)) / closed_forms.U0(TAU)
    assert true > 1e-8
    assert scored == pytest.approx(true, rel=0.05)


def _slope(x, y):
    return np.polyfit(np.log(x), np.log(y), 1)[0]


def test_errors_fall_at_the_methods_orders(study):
    dp = _ok(study, "dp54")
    assert len(dp) == len(precision.rtol_ladder(True))
    assert all(a.error > b.error for a, b in zip(dp, dp[1:]))
    # DP54, order 5: error against right-hand-side calls
    assert -6.5 < _slope([r.n_rhs for r in dp], [r.error for r in dp]) < -4.0
    rk = _ok(study, "rk4")
    assert len(rk) >= 3
    assert all(a.error > b.error for a, b in zip(rk, rk[1:]))
    # RK4, order 4: error against the step
    assert 3.4 < _slope([r.setting for r in rk], [r.error for r in rk]) < 4.6


def test_peer_rows_scored_and_falling(study):
    rows = _ok(study, "DOP853")
    assert len(rows) == len(precision.rtol_ladder(True))
    assert rows[-1].error < 1e-6 and rows[-1].n_rhs > 0 and rows[-1].cpu_seconds > 0


def test_radau_on_the_generated_rhs_and_jacobian_reaches_the_reference(problem, study):
    rtol = 1e-8
    run = peers.run_peer("Radau", "one_dof", {"tau": TAU}, 3.0, rtol)
    assert run.ok and run.n_rhs > 0 and run.n_jac > 0
    err = precision.score(problem, problem.figures(run), run.y_end, study.reference)
    assert err["error"] < 50 * rtol


def test_peer_restarts_at_state_driven_cam_events():
    """CAMSHAFT-2's cam leaves the rise where B reaches 1 (an event): DOP853 stops there
    and reaches camdyn's final state."""
    params = {"tau": TAU, "Fa": 0.5, "Fv": 1.0}
    run = peers.run_peer("DOP853", "camshaft2", params, 3.0, 1e-10)
    ref = simulate("camshaft2", params, 3.0, "dp54", rtol=1e-12)
    assert run.ok and len(run.pieces) == 2          # one restart, where B reaches 1
    assert np.max(np.abs(run.y_end - ref.y[-1])) < 1e-7


def test_failed_and_skipped_peers_say_why():
    run = peers.run_peer("RK45", "one_dof", {"tau": TAU}, 3.0, 1e-10, max_rhs=200)
    assert run.status == "failed" and "200" in run.message and run.y_end is None
    run = peers.run_peer("Radau", "roller", None, 1.0, 1e-6)
    assert run.status == "skipped" and "modes" in run.message
    assert peers.skip_reason("odeint", load("camshaft2")) is not None


def test_unstable_fixed_step_is_refused_not_scored(problem, study):
    row = precision.camdyn_row(problem, study.reference, "rk4", 0.5)
    assert row.status == "refused" and row.error is None and "stability" in row.message


def test_cli_writes_chart_csv_and_json(tmp_path, capsys):
    rc = main(["precision", "one_dof", "--set", "tau=0.2", "--quick", "--methods", "dp54",
               "--peers", "LSODA", "odeint", "--out", str(tmp_path), "--json"])
    cap = capsys.readouterr()
    assert rc == 0, cap.err
    out = json.loads(cap.out)
    assert {r["method"] for r in out["rows"]} == {"dp54", "LSODA", "odeint"}
    assert "reference dp54" in cap.err and "dp54 rtol=" in cap.err   # progress on stderr
    png, csv_path, js = (tmp_path / f"one_dof_precision.{e}" for e in ("png", "csv", "json"))
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    rows = list(csv.DictReader(csv_path.open()))
    assert len(rows) == 3 * len(precision.rtol_ladder(True))
    assert all(float(r["error"]) > 0 for r in rows if r["status"] == "ok")
    assert json.loads(js.read_text())["reference"]["rtol"] == precision.REFERENCE_RTOL


@pytest.mark.parametrize("argv,word", [
    (["one_dof", "--set", "tau=2"], "tau"),
    (["no_such_model"], "SCENE_OR_MODEL"),
    (["one_dof", "--peers", "Euler"], "--peers"),
    (["pendulum_xy"], "--t-end"),
    (["one_dof", "--set", "tau"], "--set"),
    (["indexing", "--t-end", "2"], "--t-end"),
    (["beam_paper", "--t-end", "2"], "--t-end"),
    (["beam_paper", "--set", "modes=9"], "modes"),
])
def test_cli_refuses_bad_input_in_one_line(tmp_path, capsys, argv, word):
    rc = main(["precision", *argv, "--out", str(tmp_path)])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2
    assert len(err) == 1 and err[0].startswith("camdyn precision: error:") and word in err[0]


def test_beam_scene_figure_is_the_beam_followers():
    """`camdyn precision beam_paper` scores max |v_E|, taken as runtime/targets/beam.py's summary takes
    it: the same run (N = 1, DP54 at rtol 1e-8) gives the same figure to 1e-12."""
    from dataclasses import replace

    from camdyn.runtime.targets import beam, scene_files as scene
    from camdyn.runtime.core.methods import DP54

    pr = precision.problem("beam_paper", {"modes": 1}, None)
    assert pr.kind == "beam-follower" and pr.model.name == "beam1"
    got = pr.figures(pr.simulator(DP54(rtol=1e-8)).run(pr.params))["max_abs_tip_deflection"]
    case = replace(load_scene("beam_paper")[1].case, modes=1, rtol=1e-8, method="dp54",
                   mode_atol=None)
    want = beam.run(case)[0]["max_abs_tip_deflection"]
    assert got == pytest.approx(want, rel=1e-12)
