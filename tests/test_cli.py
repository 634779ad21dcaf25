"""The command line: JSON keys, values, and one-line errors with status 2."""
import json
import subprocess
import sys

import pytest

from camdyn.runtime import closed_forms as cf


def camdyn(*args):
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args],
                          capture_output=True, text=True, timeout=300)


def test_residual_json_one_dof():
    p = camdyn("residual", "--model", "one-dof", "--tau", "0.4", "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert {"U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min"} <= set(out)
    assert out["U0"] == pytest.approx(cf.U0(0.4), rel=1e-8)
    assert out["U0dd"] == pytest.approx(cf.U0dd(0.4), rel=1e-8)
    assert 0 <= out["T_at_Xdd_min"] <= 1 and out["Xdd_min_rise"] < 0


@pytest.mark.parametrize("method", ["rk4", "koster", "dp54"])
def test_residual_json_camshaft1_methods(method):
    p = camdyn("residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2", "--method", method, "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["method"] == method and out["Fa"] == 2.0
    assert out["U0"] == pytest.approx(0.01606, rel=2e-3)


def test_residual_text_and_law():
    p = camdyn("residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "0.5", "--law", "modified-sine",
               "--theta", "0.125")
    assert p.returncode == 0, p.stderr
    assert "U0 " in p.stdout and "theta" in p.stdout


@pytest.mark.parametrize("args,argument", [
    (["--model", "one-dof", "--tau", "0"], "--tau"),
    (["--model", "one-dof", "--tau", "1"], "--tau"),
    (["--model", "one-dof", "--tau", "-0.2"], "--tau"),
    (["--model", "camshaft1", "--tau", "0.15", "--fa", "-1"], "--fa"),
    (["--model", "camshaft1", "--tau", "0.15", "--law", "spline"], "--law"),
    (["--model", "camshaft1", "--tau", "0.15", "--method", "euler"], "--method"),
    (["--model", "camshaft1", "--tau", "0.15", "--rtol", "1e-6", "--step", "0.01"], "--step"),
    (["--model", "camshaft1", "--tau", "0.15", "--method", "rk4", "--step", "-1"], "step"),
    (["--model", "one-dof", "--tau", "0.15", "--fa", "1"], "--fa"),
    (["--model", "camshaft1", "--tau", "0.15", "--q", "0.05"], "--q"),
    (["--model", "one-dof", "--tau", "0.15", "--q", "1.5"], "--q"),
    (["--model", "camshaft2", "--tau", "0.15"], "--model"),
    (["--model", "one-dof"], "--tau"),
    (["--model", "one-dof", "--tau", "0.2", "--law", "modified-sine", "--theta", "0.5"], "--theta"),
])
def test_bad_arguments_one_line_status_2(args, argument):
    p = camdyn("residual", *args)
    assert p.returncode == 2
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1, p.stderr
    assert argument in lines[0]
    assert "Traceback" not in p.stderr
    assert p.stdout == ""


def test_derive_check_exit_codes(tmp_path):
    p = camdyn("derive", "--check", "--out", str(tmp_path))
    assert p.returncode == 1
    assert "missing: camshaft1.pyx" in p.stderr


def test_laws_table_json():
    p = camdyn("laws", "--json")
    assert p.returncode == 0, p.stderr
    rows = {r["key"]: r for r in json.loads(p.stdout)}
    assert rows["cycloidal"]["H2_max"] == pytest.approx(2 * 3.141592653589793)
    assert rows["modified-sine"]["H2_max"] == pytest.approx(5.398, abs=1e-3)   # theta = 0.1
    assert set(rows) == {"cycloidal", "modified-sine", "3-4-5", "simple-harmonic", "parabolic",
                         "4-5-6-7", "modified-trapezoid", "uniform"}
