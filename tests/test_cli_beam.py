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
    out, _ = run_json(capsys, "--revolutions", "0.15", "--no-rayleigh", "--roller-inertia", "0",
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
    rc, out, err = run_cli(capsys, "--revolutions", "0.1")
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
    out, err = run_json(capsys, "--revolutions", "0.15", "--base-radius", "0.002", "--rise", "0.03")
    assert out["undercut"].startswith("undercut: the outer wall is undercut")
    assert out["max_constraint_residual"] < 1e-8
    warn = [line for line in err.splitlines() if "warning" in line]
    assert sum("undercut" in w for w in warn) == 1
    # a 30 mm rise on a 2 mm base circle bends the rod beyond small deflections, and says so
    assert sum("beyond small deflections" in w for w in warn) == 1


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
    rc, out, err = run_cli(capsys, "--out", str(f / "figs"), "--revolutions", "0.1")
    assert rc == 2 and out == ""
    assert err.count("\n") == 1 and "--out" in err


def test_out_refused_when_a_figure_run_would_be(capsys, tmp_path):
    """r_b = 80 mm leaves 12 mm of free rod at the top of the stroke (d = 112 mm), but fig. 6
    takes d down to 102 mm, where only 2 mm would be left, less than the roller radius: --out
    is refused before anything runs, although the case itself is valid."""
    rc, out, err = run_cli(capsys, "--base-radius", "0.08", "--revolutions", "0.1",
                           "--out", str(tmp_path / "figs"))
    assert rc == 2 and out == ""
    assert err.count("\n") == 1 and "--out" in err and "fig6_distance" in err
    assert not (tmp_path / "figs").exists()


def test_out_writes_figures_4_to_9(capsys, tmp_path):
    """18 short runs (a quarter of a revolution: the rise, longer than one period of the slowest mode of every figure's rod, 0.205 of a revolution at most)."""
    rc, out, err = run_cli(capsys, *SHORT, "--json", "--out", str(tmp_path))
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
    p = subprocess.run([str(exe), "beam-follower", "--revolutions", "0.1", "--json"],
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
    # the estimate's run is two notches tighter (rtol/100, runtime/core/methods.py)
    assert t.tighter().case.mode_atol == pytest.approx(MODE_ATOL / 100)
    b1 = dict(t.method().state_atol)["b1"]
    assert b1 == pytest.approx(MODE_ATOL * beam.deflection_scale(t.case), rel=1e-15)
    # the rates' at the fastest frozen frequency: N = 3, 35.19 kHz at the outer dwell
    b1d = dict(t.method().state_atol)["b1d"]
    assert beam.fastest_frequency(t.case) == pytest.approx(35190, rel=1e-4)
    assert b1d == pytest.approx(b1 * 2 * math.pi * beam.fastest_frequency(t.case), rel=1e-15)
    assert dict(t.tighter().method().state_atol)["b1"] == pytest.approx(b1 / 100, rel=1e-12)


@pytest.mark.parametrize("value", ["0", "nan", "-1"])
def test_bad_mode_atol_is_one_line(capsys, value):
    rc, out, err = run_cli(capsys, f"--mode-atol={value}")
    assert rc == 2 and err.count("\n") == 1 and "argument --mode-atol: " in err


# -- cases that cannot be answered: refused at once, naming the flag ------------------------------

def one_refusal(capsys, *args, flag):
    """The case is refused in one line naming ``flag``, status 2, nothing on stdout."""
    rc, out, err = run_cli(capsys, *args)
    assert rc == 2 and out == "", err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(f"camdyn beam-follower: error: argument {flag}:"), err
    return err


def test_a_rod_too_slender_is_refused_with_the_rod_that_would_hold(capsys):
    """A 1 nm rod (it crashed the figure finder once, a NaN run's rows scanned without end)
    would be bent by S_T Omega^2/w_1^2 = 8.5e13 m: refused, naming the thinnest rod whose
    deflection scale stays within SMALL_DEFLECTION of its free length.  That rod is checked
    against the scale computed here from the model's frozen frequency: within 0.2 % of the
    limit (the bisection's 0.1 %), and 1 % thinner exceeds it."""
    from dataclasses import replace

    err = one_refusal(capsys, "--rod-radius", "1e-9", "--no-error-estimate", flag="--rod-radius")
    a = float(err.split("rod_radius >= ")[1].split(" m")[0])
    case = replace(beam.Case(), rod_radius=a)
    limit = beam.SMALL_DEFLECTION * case.free_length_raised
    # the message prints 3 digits: the printed radius lies within 0.5 % of the one found
    assert beam.deflection_scale(replace(case, rod_radius=a * 1.005)) <= limit
    assert beam.deflection_scale(replace(case, rod_radius=a * 0.99)) > limit


def test_an_absurd_speed_is_refused_naming_omega(capsys):
    """Omega = 1e9 rad/s (one revolution 6 ns, against the rod's 1.5 ms period) used to answer a
    tip deflection from a run the rod could not answer; the largest speed it names keeps the
    scale at the limit: S_T Omega^2/w_1^2 = SMALL_DEFLECTION L there (closed form in Omega)."""
    err = one_refusal(capsys, "--omega", "1e9", flag="--omega")
    top = float(err.split("omega <= ")[1].split(" rad/s")[0])
    c = beam.Case()
    w1 = 2 * math.pi * beam.dwell_frequency(c)
    assert top == pytest.approx(w1 * math.sqrt(beam.SMALL_DEFLECTION * c.free_length_raised
                                               / c.rise), rel=1e-3)
    one_refusal(capsys, "--omega", "1e300", flag="--omega")


def test_a_run_beyond_the_step_budget_is_refused_at_once(capsys):
    """--revolutions 1e9 ran for minutes; it is refused before any run, and the number of
    revolutions it names fits the budget at the predicted steps a revolution."""
    err = one_refusal(capsys, "--revolutions", "1e9", "--no-error-estimate", flag="--revolutions")
    fits = float(err.split("revolutions <= ")[1])
    from dataclasses import replace

    case = replace(beam.Case(), method="dop853")
    per = beam.predicted_steps(case)          # one revolution
    assert fits * per <= beam.STEP_BUDGET < (fits + 1) * per


def test_predicted_steps_are_a_lower_bound():
    """The prediction that refuses a run must not exceed what the run takes: the paper's case
    at N = 3 and N = 6 (DOP853 with the mode tolerance, as the command runs it) and RADAU5."""
    from dataclasses import replace

    for case in (replace(beam.Case(), method="dop853", mode_atol=3e-5, revolutions=0.25),
                 replace(beam.Case(), modes=6, method="dop853", mode_atol=3e-5,
                         revolutions=0.25, rtol=1e-6),
                 replace(beam.Case(), method="radau5", mode_atol=3e-5, revolutions=0.25)):
        _, res = beam.run(case)
        assert beam.predicted_steps(case) <= res.stats["n_steps"], case


def test_least_frequency_is_the_inner_dwells():
    """The window rule's period: the rod frozen at the inner dwell (the longest free rod),
    against the 40-element Rayleigh cantilever of tests/beam_reference.py there (the model's
    Ritz value lies above by at most RITZ_EXCESS of N = 3, tests/test_beam_energy.py)."""
    from . import beam_reference as ref

    c = beam.Case()
    fe = ref.dwell_frequencies_fe(beam.parameters(c), inner=True)[0]
    assert 0 <= beam.least_frequency(c) / fe - 1 < 2.5e-5
    assert beam.least_revolutions(c) == pytest.approx(c.omega / (2 * math.pi * fe), rel=3e-5)


FAST = ["--omega", "6500", "--rod-radius", "0.007", "--rise", "0.004"]
"""A thick rod, a small rise, a fast cam: one revolution (0.97 ms) is shorter than one period
of the rod's slowest mode (1.14 ms), while its deflection stays small."""


def test_a_short_run_is_extended_where_the_end_was_left_to_camdyn(capsys):
    """The window rule of the answer contract: without --revolutions the run covers the whole
    revolutions that one period of the slowest mode needs (2 here); given, it is refused."""
    from dataclasses import replace

    out, _ = run_json(capsys, *FAST, "--no-error-estimate")
    case = replace(beam.Case(), omega=6500.0, rod_radius=0.007, rise=0.004)
    need = beam.least_revolutions(case)
    assert 1 < need < 2 and out["revolutions"] == 2.0
    err = one_refusal(capsys, *FAST, "--revolutions", "1", flag="--revolutions")
    assert f"revolutions >= {need:.3g}" in err


def test_large_tip_deflection_is_warned(capsys):
    """A 1.5 mm rod deflects 5.3 mm, 8 % of its 66 mm: warned (the linear beam leaves out the
    rod's shortening), in the JSON and on stderr; the paper's rod is not."""
    out, err = run_json(capsys, "--rod-radius", "0.0015", "--no-error-estimate")
    length = beam.Case().free_length_raised
    assert out["max_abs_tip_deflection"] > beam.LARGE_DEFLECTION * length
    assert sum("beyond small deflections" in w for w in out["warnings"]) == 1
    assert "warning: the rod's tip deflects" in err
    out, err = run_json(capsys, *SHORT, "--no-error-estimate")
    assert out["max_abs_tip_deflection"] < beam.LARGE_DEFLECTION * length
    assert not any("beyond small deflections" in w for w in out["warnings"])


def test_a_run_that_turns_non_finite_fails_where_it_happens():
    """The compiled loops record a point only when it is finite: a run of the 1 nm rod straight
    through the Simulator (past the case's checks) used to finish with NaN rows (DOP853 read a
    NaN error as a perfect step, RADAU5's fmax(err, 1e-10) an accepted one); now every
    adaptive method ends it with the non-finite status (DP54, whose norm passes a NaN on,
    keeps this run finite)."""
    from dataclasses import replace

    from camdyn.runtime.core.compiled import load
    from camdyn.runtime.core.errors import SimulationError
    from camdyn.runtime.core.simulator import Simulator

    for method in ("dop853", "radau5"):
        case = replace(beam.Case(), rod_radius=1e-9, method=method, mode_atol=3e-5)
        model = load(case.model)
        sim = Simulator(model, case.period, beam.integrator(case), law=case.law,
                        y0=beam.initial_state(case, model), max_steps=200_000)
        with pytest.raises(SimulationError, match="non-finite"):
            sim.run(beam.parameters(case))
