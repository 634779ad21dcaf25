"""One point through every command that reaches it: the same figures, the same error
estimates and the same warnings on every road (the answer contract, runtime/measure/contract.py).

Three points: the one-DOF model (3.1) at tau = 0.05 with RK4 at a step near its stability
limit (h omega = 1.26: a warning, and U0, U0'' whose estimates exceed half of them: a warning
each), through `camdyn residual`, `camdyn sweep` (its table) and `camdyn integrate` (whose
figures are the final state, with the step's warning); CAMSHAFT-1
(4.15) at tau = 0.15, Fa = 2 with DP54 at rtol 1e-9 through `residual` and `sweep` (a compiled
chunk, whose scan differs from a single run's: equal to within the estimates' sampling part
and 1e-9 relative; measured: U0 and U0'' to the bit, X''min 5e-15, its T 3e-10, Brent's
stopping tolerance); the spring-loaded DYNACAM scene (fig. 7.2)
through `camdyn simulate`, `camdyn run` (its report.json) and `camdyn sweep` (its table, over
one of its own parameters at its own value), which run the same target: equal to the bit.
"""
import csv
import json

import pytest

from camdyn.runtime.cli import main


def _json(capsys, *argv):
    assert main(list(argv)) == 0
    return json.loads(capsys.readouterr().out)


def _table(capsys, tmp_path, *argv) -> dict:
    out = tmp_path / "sweep"
    assert main([*argv, "--out", str(out), "--quiet"]) == 0
    err = capsys.readouterr().err
    with open(out / "sweep.csv") as fh:
        (row,) = list(csv.DictReader(fh))
    return row, err


FIGS = ("U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min")


def test_a_warned_fixed_step_point_says_the_same_on_every_road(capsys, tmp_path):
    res = _json(capsys, "residual", "--model", "one-dof", "--tau", "0.05", "--method", "rk4",
                "--step", "0.01", "--json")
    row, err = _table(capsys, tmp_path, "sweep", "one_dof", "--grid", "tau=0.05", "--method",
                      "rk4", "--step", "0.01")
    integ = _json(capsys, "integrate", "one_dof", "--set", "tau=0.05", "--method", "rk4",
                  "--step", "0.01", "--t-end", "3", "--json")
    # the step's warning, and U0 and U0'' that its estimates do not resolve (the answer
    # contract words an estimate above half its figure as a warning): the same on each road
    assert len(res["warnings"]) == 3 and "near its stability limit" in res["warnings"][0]
    for w, k in zip(res["warnings"][1:], ("U0", "U0dd")):
        assert w.startswith(f"{k} = ") and res[f"{k}_error"] > 0.5 * res[k]
    assert row["warnings"] == "; ".join(res["warnings"])
    assert integ["warnings"][0] == res["warnings"][0]
    assert "1 of 1 points warned" in err
    for k in FIGS:
        assert float(row[k]) == res[k], k
        assert float(row[f"{k}_error"]) == res[f"{k}_error"], k
    # the same run: its final state is the one integrate reports
    assert integ["state"]["X"] == pytest.approx(1.0, abs=res["U0"] + res["U0_error"])


def test_a_compiled_sweep_point_equals_the_single_run(capsys, tmp_path):
    res = _json(capsys, "residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2",
                "--rtol", "1e-9", "--json")
    row, _ = _table(capsys, tmp_path, "sweep", "camshaft1", "--grid", "tau=0.15",
                    "--grid", "Fa=2")
    assert row["warnings"] == "" and res["warnings"] == []
    for k in FIGS:
        sampling = res["error_sources"][k]["sampling"] if k in res["error_sources"] else 0.0
        assert float(row[k]) == pytest.approx(res[k], rel=1e-9, abs=sampling), k
        # the estimates: a run one notch tighter on both roads, its difference read by
        # either scan, so equal to the part of the figures that differs
        assert float(row[f"{k}_error"]) == pytest.approx(res[f"{k}_error"], rel=0.05,
                                                          abs=1e-9 * abs(res[k])), k


def test_the_study_and_the_design_check_run_give_the_single_runs_answer(capsys, tmp_path):
    """CAMSHAFT-1 at tau = 0.15, Fa = 2: the CAMSHAFT-1 study of `camdyn run` (its response
    row, DP54 rtol 1e-9, fig. 4.10) and the check run of `camdyn design` (rtol 1e-10) run the
    same target as `camdyn residual` at those tolerances: equal to the bit, estimates and
    warnings too."""
    res9 = _json(capsys, "residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2",
                 "--rtol", "1e-9", "--json")
    assert main(["run", "--out", str(tmp_path / "run"), "--quiet"]) == 0
    capsys.readouterr()
    rep = json.loads((tmp_path / "run" / "report.json").read_text())
    (row,) = [r for r in rep["response"] if r["Fa"] == 2.0]
    res10 = _json(capsys, "residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2",
                  "--rtol", "1e-10", "--json")
    des = _json(capsys, "design", "--stroke", "0.02", "--tau", "0.15", "--fa", "2",
                "--accuracy", "1e-4", "--json")
    check = des["check_run"]
    assert check["model"] == "camshaft1"
    for k in FIGS:
        assert row[k] == res9[k] and row[f"{k}_error"] == res9[f"{k}_error"], k
        # the design states more of the same run's error (the rounding of a flat top, which
        # thesis/design/extremes.py place_resolution adds), never less
        assert check[k] == res10[k] and check[f"{k}_error"] >= res10[f"{k}_error"], k
    assert row["warnings"] == res9["warnings"] == []
    assert check["warnings"] == res10["warnings"] == des["warnings"] == []


def test_a_scene_point_is_the_same_on_every_road(capsys, tmp_path):
    from camdyn.runtime.targets import scene_files

    sim = _json(capsys, "simulate", "spring_loaded", "--json")
    assert main(["run", "spring_loaded", "--out", str(tmp_path / "run"), "--quiet"]) == 0
    capsys.readouterr()
    rep = json.loads((tmp_path / "run" / "report.json").read_text())
    c_x = scene_files.load("spring_loaded").parameters["c_x"]
    row, _ = _table(capsys, tmp_path, "sweep", "spring_loaded", "--grid", f"c_x={c_x!r}")
    for k in ("Xdd_min_rise", "T_at_Xdd_min", "Xdd_max_rise", "U0dd", "U0",
              "speed_variation_max", "motor_speed_variation_max"):
        assert rep[k] == sim[k] == float(row[k]), k
        assert rep[f"{k}_error"] == sim[f"{k}_error"] == float(row[f"{k}_error"]), k
    for k in ("tau", "Fa", "Fv"):
        assert rep[f"{k}_error"] == sim[f"{k}_error"] == float(row[f"{k}_error"]) == 0.0
    assert rep["warnings"] == sim["warnings"] == [] and row["warnings"] == ""
