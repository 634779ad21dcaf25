"""`camdyn beam-follower`: the JSON, the table, the figures, and bad input refused
with one line naming the flag, status 2.  Runs in-process through cli.main, short runs."""
import json
import math
import subprocess
import sys
from dataclasses import fields
from pathlib import Path

import pytest

from camdyn.runtime.targets import beam
from camdyn.runtime import cli

SHORT = ["--revolutions", "0.25"]   # the rise and the start of the outer dwell


def run_cli(capsys, *args):
    """(status, stdout, stderr) of cli.main; argparse's own errors end in SystemExit(2)."""
    try:
        rc = cli.main(["beam-follower", *args])
    except SystemExit as exc:
        rc = exc.code
    out, err = capsys.readouterr()
    return rc, out, err


def run_json(capsys, *args):
    rc, out, err = run_cli(capsys, *args, "--json")
    assert rc == 0, err
    return json.loads(out), err


def test_help_defaults_are_those_of_the_case(capsys):
    """The help quotes beam.Case's own defaults (one home: runtime/targets/beam_case.py), every flag is
    a field of the case, and N runs to the largest beam<N> that camdyn derive declares."""
    from camdyn.derive.models import beam as declared

    case = beam.Case()
    from camdyn.runtime.cli import beam_follower

    assert set(beam_follower.FLAGS) <= {f.name for f in fields(beam.Case)}
    assert beam.N_MAX == declared.N_MAX
    rc, out, _ = run_cli(capsys, "--help")
    assert rc == 0
    text = " ".join(out.split())
    for key in ("omega", "rod_radius", "distance", "base_radius", "rise"):
        assert f"default {getattr(case, key):g}" in text, key
    assert f"1 to {declared.N_MAX} (default {case.modes})" in text
    assert f"m_r r_r^2/2 = {case.J_r:g}" in text


def test_json_keys_inputs_and_residual(capsys):
    out, err = run_json(capsys, *SHORT)
    assert {"max_abs_tip_deflection", "max_constraint_residual", "dwell_frequency_hz",
            "cpu_seconds", "undercut", "n_steps", "model"} <= set(out)
    # the inputs used: the paper's data, the roller inertia resolved to the uniform disc
    assert out["omega"] == 240.0 and out["modes"] == 3 and out["model"] == "beam3"
    assert (out["rod_radius"], out["distance"], out["base_radius"], out["rise"]) == \
        (0.005, 0.112, 0.026, 0.015)
    assert out["revolutions"] == 0.25 and out["rayleigh"] is True
    assert out["formulation"] == "augmented"
    assert out["roller_inertia"] == pytest.approx(0.05 * 0.005**2 / 2, rel=1e-15)
    assert out["roller_inertia_default"] is True
    assert out["undercut"] is None
    assert out["max_constraint_residual"] < 1e-8
    assert 1e-5 < out["max_abs_tip_deflection"] < 1e-3           # 0.178 mm over the rise
    assert out["dwell_frequency_hz"] == pytest.approx(674.23, rel=1e-4)
    assert out["cpu_seconds"] > 0 and out["n_steps"] > 100
    assert "figures" not in out
    assert "Traceback" not in err


def test_both_formulations_agree(capsys):
    aug, _ = run_json(capsys, *SHORT, "--formulation", "augmented")
    par, _ = run_json(capsys, *SHORT, "--formulation", "partitioned")
    assert par["formulation"] == "partitioned"
    assert par["max_abs_tip_deflection"] == pytest.approx(aug["max_abs_tip_deflection"], rel=1e-6)
    assert max(aug["max_constraint_residual"], par["max_constraint_residual"]) < 1e-8
    assert par["dwell_frequency_hz"] == aug["dwell_frequency_hz"]


def test_options_reach_the_case(capsys):
    """Every flag lands in the run: Euler-Bernoulli rod without roller inertia, 2 modes."""
    out, _ = run_json(capsys, "--revolutions", "0.05", "--no-rayleigh", "--roller-inertia", "0",
                      "--modes", "2", "--omega", "120", "--rod-radius", "0.004",
                      "--distance", "0.11", "--base-radius", "0.025", "--rise", "0.014")
    assert out["rayleigh"] is False and out["roller_inertia"] == 0.0
    assert out["roller_inertia_default"] is False
    assert out["modes"] == 2 and out["model"] == "beam2" and out["omega"] == 120.0
    assert (out["rod_radius"], out["distance"], out["base_radius"], out["rise"]) == \
        (0.004, 0.11, 0.025, 0.014)
    c = beam.Case(modes=2, rayleigh=False, roller_inertia=0.0, rod_radius=0.004, distance=0.11,
                  base_radius=0.025, rise=0.014)
    assert out["dwell_frequency_hz"] == pytest.approx(beam.dwell_frequency(c), rel=1e-12)


def test_text_table(capsys):
    rc, out, err = run_cli(capsys, "--revolutions", "0.05")
    assert rc == 0, err
    rows = {line.split()[0]: line.split()[1:] for line in out.splitlines()}
    assert rows["max_abs_tip_deflection"][-1] == "m"
    assert float(rows["max_constraint_residual"][0]) < 1e-8
    assert rows["dwell_frequency_hz"][-1] == "Hz"
    assert rows["undercut"] == ["no"]
    assert "beam follower: N = 3" in err          # the progress line


def test_undercut_is_a_warning_not_a_refusal(capsys):
    """r_b = 2 mm, S_T = 30 mm: the outer wall is undercut near the start of the rise; the run
    goes on (the model follows the pitch curve), the JSON carries the message, stderr warns."""
    out, err = run_json(capsys, "--revolutions", "0.05", "--base-radius", "0.002", "--rise", "0.03")
    assert out["undercut"].startswith("undercut: the outer wall is undercut")
    assert out["max_constraint_residual"] < 1e-8
    warn = [line for line in err.splitlines() if "warning" in line]
    assert len(warn) == 1 and "undercut" in warn[0]


BAD = [
    (["--omega", "0"], "--omega"),
    (["--omega", "-240"], "--omega"),
    (["--omega", "nan"], "--omega"),
    (["--modes", "0"], "--modes"),
    (["--modes", "7"], "--modes"),
    (["--modes", "2.5"], "--modes"),
    (["--rod-radius", "0"], "--rod-radius"),
    (["--rod-radius", "-0.005"], "--rod-radius"),
    (["--rod-radius", "five"], "--rod-radius"),
    (["--distance", "0"], "--distance"),
    (["--distance", "-0.112"], "--distance"),
    (["--base-radius", "0"], "--base-radius"),
    (["--base-radius", "0.09"], "--base-radius"),    # the roller past the guide at the top
    (["--rise", "0"], "--rise"),
    (["--rise", "-0.015"], "--rise"),
    (["--revolutions", "0"], "--revolutions"),
    (["--revolutions", "-1"], "--revolutions"),
    (["--roller-inertia", "-1e-7"], "--roller-inertia"),
    (["--roller-inertia", "inf"], "--roller-inertia"),
    (["--formulation", "lagrange"], "--formulation"),
    (["--rayleigh=no"], "--rayleigh"),
]


@pytest.mark.parametrize("args,flag", BAD)
def test_bad_input_one_line_status_2(capsys, args, flag):
    rc, out, err = run_cli(capsys, *args, "--json")
    assert rc == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert flag in lines[0]
    assert "Traceback" not in err
    assert out == ""


def test_out_that_is_a_file_is_refused_before_running(capsys, tmp_path):
    f = tmp_path / "not_a_dir"
    f.write_text("")
    rc, out, err = run_cli(capsys, "--out", str(f / "figs"), "--revolutions", "0.01")
    assert rc == 2 and out == ""
    assert err.count("\n") == 1 and "--out" in err


def test_out_refused_when_a_figure_run_would_be(capsys, tmp_path):
    """r_b = 80 mm leaves 12 mm of free rod at the top of the stroke (d = 112 mm), but fig. 6
    takes d down to 102 mm, where only 2 mm would be left, less than the roller radius: --out
    is refused before anything runs, although the case itself is valid."""
    rc, out, err = run_cli(capsys, "--base-radius", "0.08", "--revolutions", "0.01",
                           "--out", str(tmp_path / "figs"))
    assert rc == 2 and out == ""
    assert err.count("\n") == 1 and "--out" in err and "fig6_distance" in err
    assert not (tmp_path / "figs").exists()


def test_out_writes_figures_4_to_9(capsys, tmp_path):
    """18 short runs (a fiftieth of a revolution: the start of the rise)."""
    rc, out, err = run_cli(capsys, "--revolutions", "0.02", "--json", "--out", str(tmp_path))
    assert rc == 0, err
    res = json.loads(out)
    names = sorted(Path(f).name for f in res["figures"])
    assert names == [f"{k}.png" for k in sorted(beam.FIGURES)]
    assert len(names) == 6
    for f in res["figures"]:
        data = Path(f).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 5000
    progress = [line for line in err.splitlines() if line.strip().startswith("[")]
    assert len(progress) == 18 and progress[-1].strip().startswith("[18/18] fig9_rise")
    # the main case is a curve of every figure: run once, for the main answer, and reused
    assert sum("its run is reused" in line for line in progress) == 6
    assert res["figures_cpu_seconds"] > 0


def test_installed_entry_point_smoke():
    exe = Path(sys.executable).with_name("camdyn")
    if not exe.exists():
        pytest.skip(f"no camdyn script next to {sys.executable}")
    p = subprocess.run([str(exe), "beam-follower", "--revolutions", "0.05", "--json"],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["max_constraint_residual"] < 1e-8 and math.isfinite(out["max_abs_tip_deflection"])
    bad = subprocess.run([str(exe), "beam-follower", "--base-radius", "-1"],
                         capture_output=True, text=True, timeout=300)
    assert bad.returncode == 2 and bad.stdout == ""
    assert bad.stderr.count("\n") == 1 and "--base-radius" in bad.stderr
    assert "Traceback" not in bad.stderr


def test_default_tolerances_against_a_tight_reference(capsys):
    """The command's defaults (DOP853, the mode amplitudes to MODE_ATOL of the rod's deflection
    scale, their rates to that times the fastest frozen frequency, beam_case.py): max |v_E|
    over a quarter revolution within 3 times its estimate of a DP54 run at rtol 1e-11 with
    every state at the library's default tolerance (measured: 1.1 times), and the
    estimate below 1e-6 of the figure."""
    from dataclasses import replace

    from camdyn.runtime.targets.beam_case import MODE_ATOL
    from camdyn.runtime.targets.beam_scene import BeamTarget

    out, _ = run_json(capsys, *SHORT)
    assert out["method"] == "dop853"
    ref, _ = beam.run(beam.Case(revolutions=0.25, rtol=1e-11))
    tip, err = out["max_abs_tip_deflection"], out["max_abs_tip_deflection_error"]
    assert 0 < err < 1e-6 * tip
    assert abs(tip - ref["max_abs_tip_deflection"]) < 3 * err
    t = BeamTarget.of(replace(beam.Case(), mode_atol=MODE_ATOL))
    assert t.tighter().case.mode_atol == pytest.approx(MODE_ATOL / 10)
    b1 = dict(t.method().state_atol)["b1"]
    assert b1 == pytest.approx(MODE_ATOL * beam.deflection_scale(t.case), rel=1e-15)
    # the rates' at the fastest frozen frequency: N = 3, 35.19 kHz at the outer dwell
    b1d = dict(t.method().state_atol)["b1d"]
    assert beam.fastest_frequency(t.case) == pytest.approx(35190, rel=1e-4)
    assert b1d == pytest.approx(b1 * 2 * math.pi * beam.fastest_frequency(t.case), rel=1e-15)
    assert dict(t.tighter().method().state_atol)["b1"] == pytest.approx(b1 / 10, rel=1e-12)


@pytest.mark.parametrize("value", ["0", "nan", "-1"])
def test_bad_mode_atol_is_one_line(capsys, value):
    rc, out, err = run_cli(capsys, f"--mode-atol={value}")
    assert rc == 2 and err.count("\n") == 1 and "argument --mode-atol: " in err
