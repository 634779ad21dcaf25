"""The command line: JSON keys, values, and one-line errors with status 2."""
import json
import math
import subprocess
import sys

import pytest
from scipy.integrate import solve_ivp

from camdyn.thesis.theory import numeric as cf


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


def _camshaft1_U0(tau, Fa):
    """U0 of CAMSHAFT-1 (4.15), X'' = (2 pi/tau)^2 (H - X)/(1 + H'^2 Fa), cycloidal rise, by
    SciPy's DOP853 at rtol 1e-12 over 0 <= T <= 1.  In the dwell H = 1, H' = 0: the free
    vibration U = X - 1 has the exact amplitude (U^2 + (U'/w)^2)^(1/2), w = 2 pi/tau, which
    is the refined extremum of |U| over any dwell longer than tau."""
    w = 2 * math.pi / tau

    def rhs(T, y):
        H = T - math.sin(2 * math.pi * T) / (2 * math.pi)
        Hd = 1 - math.cos(2 * math.pi * T)
        return [y[1], w**2 * (H - y[0]) / (1 + Fa * Hd**2)]
    s = solve_ivp(rhs, (0.0, 1.0), [0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-15)
    return math.hypot(s.y[0, -1] - 1, s.y[1, -1] / w)


@pytest.mark.parametrize("method, rel", [("rk4", 1e-6), ("koster", 3e-4), ("dp54", 1e-7)])
def test_residual_json_camshaft1_methods(method, rel):
    """`camdyn residual` for CAMSHAFT-1 at tau = 0.15, Fa = 2 (U0 = 0.016064) with each method at
    the CLI's defaults, against _camshaft1_U0.  Measured: rk4 (step tau/100) 4.8e-8, dp54
    (rtol 1e-10) 4.1e-9, koster (step tau/100) 7.6e-5.  The thesis's scheme (4.23)-(4.31)
    holds the acceleration constant over a step, so it converges only in the square of the
    step (halving it quarters the error: 1.9e-5 measured at tau/200; sec. 4.4.2: dT = 0.1 tau
    against 0.01 tau moves U0 by 1.5 %), hence its wider tolerance.  The former expected value
    0.01606 was the program's own output, rounded."""
    p = camdyn("residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2", "--method", method, "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["method"] == method and out["Fa"] == 2.0
    assert out["U0"] == pytest.approx(_camshaft1_U0(0.15, 2.0), rel=rel)


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
                         "4-5-6-7", "modified-trapezoid", "uniform", "sine-constant-cosine",
                         "5-6-7-8-9", "polydyne"}


# -- camshaft2 (thesis ch. 5) ---------------------------------------------------------------------

def test_residual_json_camshaft2():
    """--model camshaft2 with --fa and --fv: the keys of the other models plus Bdot_dev_max and
    windup_max; at tau = 0.16, Fa = 1.5, Fv = 10 the cam's speed error is "a maximum of 30 %"
    (sec. 5.5.5), and the figures equal those of the API run (DP54, rtol 1e-10)."""
    from camdyn.thesis.checks import camshaft2_checks as c2

    p = camdyn("residual", "--model", "camshaft2", "--tau", "0.16", "--fa", "1.5", "--fv", "10", "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert {"U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min", "Bdot_dev_max", "windup_max"} <= set(out)
    assert out["model"] == "camshaft2" and out["Fa"] == 1.5 and out["Fv"] == 10.0
    assert out["Bdot_dev_max"] == pytest.approx(0.30, rel=0.10)
    assert out["Bdot_dev_max"] == pytest.approx(c2.speed_deviation(**c2.FIG_5_6)[0], rel=1e-9)
    assert out["U0"] == pytest.approx(c2.residual2(0.16, 1.5, 10.0).U0, rel=1e-9)
    # largest T - B (shaft wound by the driving torque): 0.0095 at T = 0.38, before the cam
    # overtakes the input near T = 0.68 (fig. 5.6, Delta B-curve (2))
    assert 0 < out["windup_max"] < c2.windup_extreme(**c2.FIG_5_6)[0]
    assert "U0_closed_form" not in out


def test_residual_camshaft2_small_fv_is_the_one_dof_closed_form():
    """Fv -> 0 is the constant-speed model of ch. 3 (sec. 5.7 (2)): U0 within 1e-4 of (3.5)."""
    p = camdyn("residual", "--model", "camshaft2", "--tau", "0.4", "--fa", "1", "--fv", "1e-6", "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["U0"] == pytest.approx(cf.U0(0.4), rel=1e-4)
    assert out["Bdot_dev_max"] < 1e-4


def test_residual_camshaft2_koster_default_step_follows_the_shaft_period():
    """With the thesis scheme the default step is 0.01 min(tau, tau_b), tau_b = tau (Fa/Fv)^(1/2)
    (sec. 5.4): at Fv = 10, Fa = 0.15 that is 0.01 * 0.16 * 0.122; U0 within 0.5 % of DP54."""
    p = camdyn("residual", "--model", "camshaft2", "--tau", "0.16", "--fa", "0.15", "--fv", "10",
               "--method", "koster", "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["step"] == pytest.approx(0.01 * 0.16 * (0.15 / 10) ** 0.5, rel=1e-12)
    from camdyn.thesis.checks import camshaft2_checks as c2
    assert out["U0"] == pytest.approx(c2.residual2(0.16, 0.15, 10.0).U0, rel=5e-3)


@pytest.mark.parametrize("args,argument", [
    (["--model", "one-dof", "--tau", "0.15", "--fv", "2"], "--fv"),
    (["--model", "camshaft1", "--tau", "0.15", "--fa", "1", "--fv", "2"], "--fv"),
    (["--model", "camshaft2", "--tau", "0.15", "--fa", "1"], "--fv"),
    (["--model", "camshaft2", "--tau", "0.15", "--fv", "2"], "--fa"),
    (["--model", "camshaft2", "--tau", "0.15", "--fa", "1", "--fv", "0"], "--fv"),
    (["--model", "camshaft2", "--tau", "0.15", "--fa", "1", "--fv", "-3"], "--fv"),
    (["--model", "camshaft2", "--tau", "0.15", "--fa", "0", "--fv", "2"], "--fa"),
    (["--model", "camshaft2", "--tau", "0.15", "--fa", "1", "--fv", "2", "--q", "0.05"], "--q"),
    (["--model", "camshaft2", "--tau", "0", "--fa", "1", "--fv", "2"], "--tau"),
])
def test_camshaft2_bad_arguments_one_line_status_2(args, argument):
    p = camdyn("residual", *args)
    assert p.returncode == 2
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1, p.stderr
    assert argument in lines[0]
    assert "Traceback" not in p.stderr
    assert p.stdout == ""


def test_simulate_text_table_matches_the_json():
    """`camdyn simulate spring_loaded` without --json prints one row per summary figure; each
    number in the table is the JSON's to the table's 4 significant digits (the text form once
    crashed on a helper moved with `camdyn check`, while only --json was tested)."""
    p = camdyn("simulate", "spring_loaded")
    assert p.returncode == 0, p.stderr
    rows = dict(line.split(None, 1) for line in p.stdout.splitlines()[1:] if line.strip())
    j = json.loads(camdyn("simulate", "spring_loaded", "--json").stdout)
    for key in ("tau", "Fa", "Fv", "Xdd_min_rise", "T_at_Xdd_min", "U0dd", "speed_variation_max"):
        # a figure with an error estimate reads "value ± error"; one that follows from the
        # parameters (tau, Fa, Fv: (4.3)-(5.52)) "value (exact)", its estimate 0 in the JSON
        value, *rest = rows[key].split()
        assert float(value) == pytest.approx(j[key], rel=5e-4), key
        if j[f"{key}_error"] == 0.0:
            assert rest == ["(exact)"], key
        else:
            assert rest[0] == "±" and float(rest[1]) == pytest.approx(j[f"{key}_error"], rel=5e-2), key


@pytest.mark.parametrize("argv", [
    ["run"], ["laws", "--tau", "0.1", "--fa", "0"], ["simulate", "spring_loaded"],
    ["design", "--stroke", "0.02", "--tau", "0.2", "--fa", "0.1", "--no-check"],
    ["sweep", "one_dof", "--grid", "tau=0.1:0.2:3"],
])
def test_out_naming_a_file_is_refused_in_one_line(tmp_path, capsys, argv):
    """Every --out names a folder: a file there gives one line naming --out, exit 2, before
    any run (it was a FileExistsError traceback after the runs in five commands)."""
    from camdyn.runtime.cli import main

    f = tmp_path / "a_file"
    f.write_text("")
    assert main([*argv, "--out", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "--out" in err and "is a file" in err


@pytest.mark.parametrize("argv", [["simulate", "spring_loaded"],
                                  ["sweep", "one_dof", "--grid", "tau=0.2", "--quiet"]])
def test_out_below_a_file_is_one_line(tmp_path, capsys, argv):
    """--out below a file cannot be made: simulate raised NotADirectoryError with a traceback
    (dynacam.plot); one line naming --out, exit 2."""
    from camdyn.runtime.cli import main

    (tmp_path / "f").write_text("")
    assert main([*argv, "--out", str(tmp_path / "f" / "sub")]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "argument --out" in err, err


@pytest.mark.parametrize("argv", [["scenes"], ["sweep", "camshaft1", "--grid", "tau=0.2,0.3",
                                               "--quiet", "--out", "{tmp}"]])
def test_closed_stdout_stops_without_a_traceback(tmp_path, argv):
    """`camdyn ... | head -1`: stdout's reader gone, the command printed a BrokenPipeError
    traceback (or 'Exception ignored' at exit). Now: no traceback, exit status 1."""
    import os

    r, w = os.pipe()
    os.close(r)                                  # no reader: the first flush gets EPIPE
    try:
        p = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli",
                            *[a.replace("{tmp}", str(tmp_path)) for a in argv]],
                           stdout=w, stderr=subprocess.PIPE, text=True, timeout=120)
    finally:
        os.close(w)
    assert p.returncode == 1, p.stderr
    assert "Traceback" not in p.stderr and "Exception ignored" not in p.stderr, p.stderr


@pytest.mark.parametrize("argv", [
    ["sweep", "one_dof", "--grid", "tau=0.1:0.2:3", "--quiet"],
    ["profile", "--stroke", "0.015", "--base-radius", "0.026", "--roller-radius", "0.005"],
    ["stability", "one_dof", "--param", "tau=0.1:0.2:2"],
    ["run"],
])
def test_out_below_a_file_is_refused_before_the_runs(tmp_path, capsys, argv):
    """An --out folder that cannot be made (below a file) is one line naming --out from
    runtime/core/outdir.out_folder, the one place every command makes its folder, before any run
    (camdyn sweep reported it after its runs)."""
    from camdyn.runtime.cli import main

    (tmp_path / "f").write_text("")
    assert main([*argv, "--out", str(tmp_path / "f" / "sub")]) == 2
    cap = capsys.readouterr()
    assert "runs of" not in cap.out
    err = cap.err.strip()
    assert "\n" not in err and "argument --out: cannot create the folder" in err


def test_refused_input_leaves_no_out_folder(tmp_path, capsys):
    """--out is checked before the runs but made only when there is something to write: a
    refused input leaves no empty folder behind (the checks of sweep, run and stability)."""
    from camdyn.runtime.cli import main

    for argv in (["sweep", "camshaft1", "--grid", "Q=0.1:0.3:3"],
                 ["stability", "one_dof", "--param", "tau=0.1:0.2:2", "--threshold", "2"]):
        new = tmp_path / argv[0]
        assert main([*argv, "--out", str(new)]) == 2
        assert not new.exists(), argv[0]
    capsys.readouterr()


def test_help_texts_state_the_librarys_defaults():
    """The defaults a help text names are the ones the library applies (each has one home:
    methods.DEFAULT_RTOL, the model target's DEFAULT_T_END, the sweep's MODEL_RTOL, the
    residual command's RESIDUAL_RTOL)."""
    from camdyn.runtime.cli import residual as residual_cmd
    from camdyn.runtime.core.methods import DEFAULT_RTOL
    from camdyn.runtime.studies.sweep import MODEL_RTOL
    from camdyn.runtime.targets.model_target import DEFAULT_T_END

    def helptext(*argv):
        return " ".join(subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *argv,
                                        "--help"], capture_output=True, text=True).stdout.split())

    import re

    def number(text, pattern):
        return float(re.search(pattern, text).group(1))

    assert number(helptext("integrate"), r"tolerance \(default ([0-9.e-]+)\)") == DEFAULT_RTOL
    assert number(helptext("residual"), r"tolerance \(default ([0-9.e-]+)\)") \
        == residual_cmd.RESIDUAL_RTOL
    sweep = helptext("sweep")
    assert number(sweep, r"scene's, ([0-9.e-]+) for a model\)") == MODEL_RTOL
    assert number(sweep, r"past the rise \(default ([0-9.]+)\)") == DEFAULT_T_END
