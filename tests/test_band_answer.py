"""`camdyn design` over a machine's speed band (thesis/design/band/answer.py and the command).

The ranking's rules on stand-in answers (laws that pass first, by the worst residual, ties
within the estimates by the least preload, then by the peak acceleration; the laws that fail
after them, one whose velocity jumps last); the checks that fail a law; the JSON's keys, each
figure with its estimate, in SI; the text's units; the command's options read as the machine
file reads them; bad inputs refused in one line; the template; and the packaging station
(spec.TEMPLATE) end to end.
"""
from __future__ import annotations

import json
import math
from dataclasses import replace
from types import SimpleNamespace as NS

import numpy as np
import pytest

from camdyn.runtime.cli import build_parser, main
from camdyn.thesis.design.band import answer, spec, units

RPM = 2 * math.pi / 60


def packaging(**kw):
    """spec.TEMPLATE's machine: 25 mm in 120 deg, 0.8 kg, 2e6 N/m, 300:600 rpm."""
    return replace(spec.from_dict(__import__("tomllib").loads(spec.TEMPLATE)), **kw)


# -- stand-ins of the five steps' answers (band_api.md's dataclasses) -------------------------

def residual(value, error=1e-9, speed=500 * RPM):
    return NS(value=value, error=error, speed=speed, speed_error=0.5 * RPM, tau=0.1,
              curve_speeds=np.array([300 * RPM, speed, 600 * RPM]),
              curve_values=np.array([value / 2, value, value / 3]),
              curve_errors=np.full(3, error), warnings=())


def peaks(acc, acc_error=1e-3):
    return NS(acceleration_max=acc, acceleration_max_error=acc_error, jerk_max=1e5,
              jerk_max_error=1.0)


def spring(preload_min, error=0.01, used=None, jump=None):
    th = np.linspace(0, 360, 5)
    return NS(preload_min_kinetostatic=0.9 * preload_min, preload_min_kinetostatic_error=0.001,
              binding_part_kinetostatic="return", binding_angle_deg_kinetostatic=200.0,
              binding_angle_deg_kinetostatic_error=0.01,
              preload_min=preload_min, preload_min_error=error, binding_part="rise",
              binding_angle_deg=60.0, binding_angle_deg_error=0.1,
              preload_used=preload_min if used is None else used, preload_used_error=None,
              jump_speed=jump, jump_speed_error=None if jump is None else 0.1,
              theta_deg=th, contact_force_lo=th + 10, contact_force_hi=th + 5,
              jump_margin_speeds=np.array([300 * RPM, 600 * RPM]),
              jump_margin=np.array([20.0, 5.0]), warnings=())


def contact(alpha=20.0, undercut=False, hertz=500e6, allowed=1200e6):
    return NS(pressure_angle_max_deg=alpha, pressure_angle_max_deg_error=1e-3,
              rho_min=0.02, rho_min_error=1e-6, undercut=undercut, hertz_stress_max=hertz,
              hertz_stress_max_error=1e3, hertz_allowed=allowed, warnings=())


def drive():
    return NS(torque_max=1.5, torque_max_error=1e-4, flywheel_inertia=None, warnings=())


def law(name, value, preload=40.0, acc=100.0, m=None, *, error=1e-9, jumps=False, **parts):
    """A LawAnswer of stand-ins, checked against ``m`` as design_band checks it."""
    m = m or packaging()
    a = answer.LawAnswer(name, None, residual=residual(value, error), peaks=peaks(acc),
                         spring=parts.get("spring", spring(preload)),
                         contact=parts.get("contact", contact()), drive=drive(),
                         velocity_jumps=jumps)
    a.reasons = answer.checks(m, a)
    a.passed = not a.reasons
    return a


def band(laws, m=None):
    m = m or packaging()
    ranking = answer.rank(laws)
    best = next(x for x in laws if x.law == ranking[0][0])
    ladder = NS(model="one_dof", params={"q": 0.0}, why="Fa = 0 without a camshaft (ch. 8)")
    return answer.BandAnswer(m, ladder, laws, ranking, best.law if best.passed else None, [])


# -- the ranking's rules ---------------------------------------------------------------------------

def test_the_smallest_worst_residual_ranks_first_whatever_the_spring():
    laws = [law("a", 3e-6, preload=10), law("b", 1e-6, preload=90), law("c", 2e-6, preload=50)]
    assert [n for n, _ in answer.rank(laws)] == ["b", "c", "a"]


def test_residuals_equal_within_their_estimates_go_by_the_least_preload_then_acceleration():
    """1.00 and 1.05 um with 0.05 um estimates each are a tie (|dv| <= e1 + e2): the one
    with the smaller preload first; equal preloads too (40 and 40.01 N, 0.01 N each): the
    smaller peak acceleration first.  2 um with the same estimate is no tie."""
    laws = [law("tied-more-spring", 1.00e-6, preload=60, error=0.05e-6),
            law("tied-less-spring", 1.05e-6, preload=40, error=0.05e-6),
            law("same-spring-faster", 1.05e-6, preload=40.01, acc=300, error=0.05e-6),
            law("clear", 2e-6, preload=1, acc=1, error=0.05e-6)]
    order = [n for n, _ in answer.rank(laws)]
    assert order == ["tied-less-spring", "same-spring-faster", "tied-more-spring", "clear"]
    reasons = dict(answer.rank(laws))
    assert "as tied-less-spring's within the estimates, and so are the preloads" in \
        reasons["same-spring-faster"]


def test_failing_laws_follow_with_their_reasons_a_velocity_jump_last():
    m = packaging()
    laws = [law("steep", 0.1e-6, contact=contact(alpha=35.0)),
            law("jumps", 0.01e-6, jumps=True),
            law("ok", 5e-6),
            law("two-fails", 0.2e-6, contact=contact(alpha=40.0, hertz=2e9))]
    ranking = answer.rank(laws)
    assert [n for n, _ in ranking] == ["ok", "steep", "two-fails", "jumps"]
    why = dict(ranking)
    assert why["ok"].startswith("passes every check")
    assert "pressure angle 35 ± 0.001 deg beyond the limit 30 deg" in why["steep"]
    assert "Hertz contact pressure 2000" in why["two-fails"] and "1200 MPa" in why["two-fails"]
    assert "velocity jumps" in why["jumps"]
    a = band(laws, m)
    assert a.recommended == "ok"


def test_no_law_passing_recommends_none_and_shows_the_nearest():
    a = band([law("steep", 1e-6, contact=contact(alpha=35.0))])
    assert a.recommended is None and a.chosen.law == "steep"
    assert "no candidate passes every check; the nearest is steep" in answer.text(a)


@pytest.mark.parametrize("parts, words", [
    ({"contact": contact(undercut=True)}, "undercut or has a cusp"),
    ({"contact": contact(hertz=1300e6)}, "beyond the allowable 1200 MPa"),
    ({"spring": spring(40.0, jump=550 * RPM)}, "the follower leaves the cam from 550"),
    ({"spring": spring(40.0, used=30.0)}, "the spring's preload 30 N is below the least"),
])
def test_each_check_fails_a_law_naming_its_figure(parts, words):
    a = law("x", 1e-6, **parts)
    assert not a.passed and len(a.reasons) == 1 and words in a.reasons[0], a.reasons


def test_a_preload_or_a_jump_beyond_the_band_passes():
    """A preload within its estimate of the least (40 - 0.01 N) and a jump above the top
    speed hold."""
    assert law("x", 1e-6, spring=spring(40.0, used=39.99, jump=601 * RPM)).passed


def test_the_velocity_jump_is_the_uniform_laws_alone():
    """H'(0+) = 1 for the uniform law (constant velocity over the rise), 0 for every other
    law of the library (each starts from rest)."""
    from camdyn.runtime.core import laws

    assert [n for n in laws.NAMES if answer.velocity_jumps(n, None)] == ["uniform"]


def test_all_is_every_law_and_the_polydyne_at_the_bands_centre():
    m = packaging()
    todo, warnings = answer.candidates(m)
    from camdyn.runtime.core import laws

    assert [n for n, _ in todo] == laws.NAMES and warnings == []
    (theta,) = [t for n, t in todo if n == "polydyne"]
    assert theta == pytest.approx(0.5 * (m.tau(300 * RPM) + m.tau(600 * RPM)), rel=1e-12)
    # beyond tau_d < 1 the polydyne is left out, said
    fast = replace(m, speeds=(6000 * RPM, 9000 * RPM))
    todo, warnings = answer.candidates(fast)
    assert "polydyne" not in [n for n, _ in todo] and "polydyne is left out" in warnings[0]


# -- JSON and text --------------------------------------------------------------------------------

def test_json_is_si_every_figure_with_its_estimate():
    laws = [law("cycloidal", 12e-6), law("steep", 1e-6, contact=contact(alpha=35.0))]
    d = answer.as_json(band(laws))
    json.dumps(d, allow_nan=False)
    assert d["recommended"] == "cycloidal"
    assert d["model"] == {"name": "one_dof", "params": {"q": 0.0},
                          "why": "Fa = 0 without a camshaft (ch. 8)"}
    required = {"law", "residual_max", "residual_max_error", "residual_max_speed_rpm",
                "acceleration_max", "spring_preload_min_kinetostatic", "spring_preload_min",
                "pressure_angle_max_deg", "rho_min", "hertz_stress_max"}
    for x in d["laws"]:
        assert required <= set(x)
        for key, v in x.items():
            if isinstance(v, float) and not key.endswith("_error"):
                assert f"{key}_error" in x, key
    c = d["laws"][0]
    assert c["residual_max"] == 12e-6 and c["rho_min"] == 0.02           # m, not um or mm
    assert c["hertz_stress_max"] == 500e6                                 # Pa
    assert c["residual_max_speed_rpm"] == pytest.approx(500.0, rel=1e-12)
    assert c["residual_max_speed"] == pytest.approx(500 * RPM, rel=1e-12)  # rad/s
    assert d["machine"]["speeds"] == pytest.approx([300 * RPM, 600 * RPM], rel=1e-12)
    assert not d["laws"][1]["passed"] and "pressure angle" in d["laws"][1]["reasons"][0]


def test_text_in_a_designers_units_every_figure_with_its_estimate():
    t = answer.text(band([law("cycloidal", 12.5e-6, error=0.02e-6)]))
    assert "worst residual um" in t and "at rpm" in t and "Hertz MPa" in t
    row = next(line for line in t.splitlines() if "cycloidal" in line and " ok" in line)
    assert "12.5 ± 0.02" in row            # um
    assert "500 ± 0.5" in row              # rpm
    assert "20 ± 0.001" in row             # pressure angle, deg
    assert "20 ± 0.001" in row and "500 ± 0.001" in row   # rho mm, Hertz MPa
    assert "recommended: cycloidal" in t and "model: one_dof (q = 0): Fa = 0" in t
    # the warnings, each named by its law (the command line gives them on stderr instead)
    a = band([law("cycloidal", 12.5e-6)])
    a.laws[0].warnings = ["spring: a warning", "cycloidal: its own"]
    t = answer.text(a)
    assert "warning: cycloidal: spring: a warning" in t and "warning: cycloidal: its own" in t
    assert "warning" not in answer.text(a, warnings=False)


def test_a_rockers_preload_is_a_torque_at_its_pivot():
    m = replace(packaging(), follower="oscillating-roller", stroke=None, swing=18.0,
                pivot_distance=0.1, arm_length=0.08, mass=None, inertia=0.0039,
                stiffness=None, torsional_stiffness=12800.0)
    a = band([law("cycloidal", 1e-6, m=m)], m)
    t = answer.text(a)
    assert "preload N m" in t and "N m at the pivot" in t
    assert "spring rate 1000 N m/rad at the pivot (1.562e+05 N/m at the roller)" in t
    d = answer.as_json(a)["laws"][0]
    assert d["spring_preload_used_at_pivot"] == pytest.approx(40.0 * 0.08, rel=1e-12)


# -- the command: the machine from options and from its file ---------------------------------------

OPTIONS = ["--speed", "300:600rpm", "--stroke", "25mm", "--angles", "120,60,120,60",
           "--mass", "0.8kg", "--stiffness", "2e6N/m", "--base-radius", "40mm",
           "--roller-radius", "10mm", "--roller-width", "12mm", "--spring-rate", "1000",
           "--spring-margin", "0.3", "--materials", "steel,steel", "--allowable-stress",
           "1200MPa", "--laws", "all"]


def _args(argv):
    return build_parser(only="design").parse_args(["design", *argv])


def test_the_options_give_the_machine_its_file_gives(tmp_path):
    """The template's machine as options equals the template read from its file (the title
    and the file's name apart)."""
    from camdyn.runtime.cli import design as command

    path = tmp_path / "machine.toml"
    path.write_text(spec.TEMPLATE)
    from_file = command.machine_of(_args([str(path)]), spec, units)
    from_options = command.machine_of(_args(OPTIONS), spec, units)
    assert replace(from_file, title="machine", source="") == from_options
    assert from_options.speeds == pytest.approx((300 * RPM, 600 * RPM), rel=1e-12)
    assert from_options.stroke == pytest.approx(0.025, rel=1e-12)
    # a bare --speed is in r.p.m. as the single-speed design's is
    bare = command.machine_of(_args([*OPTIONS[2:], "--speed", "300:600"]), spec, units)
    assert bare.speeds == pytest.approx(from_options.speeds, rel=1e-12)
    # --laws beside the file chooses among its laws
    two = command.machine_of(_args([str(path), "--laws", "cycloidal,3-4-5"]), spec, units)
    assert two.laws == ("cycloidal", "3-4-5")


def _refused(capsys, argv, words):
    code = main(["design", *argv])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err, err
    (line,) = err.strip().splitlines()
    assert line.startswith("camdyn design: error: ") and words in line, line


@pytest.mark.parametrize("argv, words", [
    (["--speed", "300:600rpm", "--stroke", "25mm"],
     "missing: --angles, --base-radius, --roller-radius, --mass, --stiffness"),
    (["--speed", "300:600rpm", "--follower", "oscillating-roller"],
     "missing: --angles, --base-radius, --pivot-distance, --swing, --arm-length, "
     "--roller-radius, --arm-inertia, --arm-stiffness"),
    ([*OPTIONS[:3], "25kg", *OPTIONS[4:]], "--stroke='25kg': kg is no unit of length"),
    ([*OPTIONS, "--tau", "0.1"], "argument --tau: the single-speed design's"),
    ([*OPTIONS, "--law", "3-4-5"], "the band design takes --laws"),
    ([*OPTIONS[:-1], "bogus"], "--laws: unknown cam law 'bogus'"),
    ([*OPTIONS, "--step"], "argument --step: the STEP plate needs its thickness"),
    ([*OPTIONS, "--speed", "600:300rpm"], "the speeds must be positive, the lowest first"),
    ([*OPTIONS, "--base-radius", "5mm"], "--roller-radius=0.01 m must be below --base-radius"),
    (["/no/such/machine.toml"], "machine file /no/such/machine.toml not found"),
])
def test_bad_input_is_one_line(capsys, argv, words):
    _refused(capsys, argv, words)


def test_a_machine_file_takes_only_laws_beside_it(capsys, tmp_path):
    path = tmp_path / "m.toml"
    path.write_text(spec.TEMPLATE)
    _refused(capsys, [str(path), "--mass", "1kg"],
             "argument --mass: the machine file")
    path.write_text(spec.TEMPLATE.replace('mass = "0.8 kg"', ""))
    _refused(capsys, [str(path)], "missing: train.mass")


def test_single_speed_design_takes_units_and_keeps_its_numbers(capsys):
    """--stroke 25mm is --stroke 0.025 in the single-speed design, --speed 450rpm is
    --speed 450; a word that is no number is refused in one line as argparse's float did."""
    common = ["--tau", "0.15", "--fa", "0", "--no-check", "--json", "--quiet"]
    assert main(["design", "--stroke", "0.025", *common]) == 0
    plain = json.loads(capsys.readouterr().out)
    assert main(["design", "--stroke", "25mm", *common]) == 0
    assert json.loads(capsys.readouterr().out) == plain
    _refused(capsys, ["--stroke", "0.02", "--tau", "0.1", "--fa", "0", "--mass", "1..2"],
             "argument --mass: invalid float value: '1..2'")


def test_scenes_template_machine(capsys, tmp_path):
    """The template on stdout is spec.TEMPLATE; into --out it is machine.toml, read back as
    the packaging station; a user's machine.toml there is refused and kept."""
    assert main(["scenes", "--template", "machine"]) == 0
    assert capsys.readouterr().out == spec.TEMPLATE
    assert main(["scenes", "--template", "machine", "--out", str(tmp_path / "a")]) == 0
    assert spec.load(tmp_path / "a" / "machine.toml") == replace(
        packaging(), source=str(tmp_path / "a" / "machine.toml"))
    (tmp_path / "b").mkdir()
    (tmp_path / "b" / "machine.toml").write_text("mine")
    assert main(["scenes", "--template", "machine", "--out", str(tmp_path / "b")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "camdyn did not write it" in err[0]
    assert (tmp_path / "b" / "machine.toml").read_text() == "mine"


@pytest.mark.parametrize("argv, words", [
    (["--stroke", ":", "--speed", "300:600"], "--stroke=':': not a number with a unit"),
    (["--speed", "", "--stroke", "25mm", "--base-radius", "40mm"],
     "--speed='': not a number with a unit"),
])
def test_a_unit_string_pint_cannot_read_is_one_line(capsys, argv, words):
    """':' failed an assertion inside Pint (a traceback); '' as a speed is no speed (it
    read as 1 rpm with the r.p.m. put after it)."""
    _refused(capsys, argv, words)


# -- the packaging station end to end ---------------------------------------------------------------

def _run(argv):
    import contextlib
    import io

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    return code, out.getvalue(), err.getvalue()


def _station(folder, *options):
    """`camdyn design machine.toml ... --json` of spec.TEMPLATE (the packaging station)."""
    path = folder / "machine.toml"
    path.write_text(spec.TEMPLATE)
    code, stdout, stderr = _run(["design", str(path), *options, "--json"])
    return NS(code=code, d=json.loads(stdout) if stdout else None, err=stderr, path=path)


@pytest.fixture(scope="module")
def station(tmp_path_factory):
    """--laws all: every candidate (about 2 s of one core, more on a busy machine)."""
    return _station(tmp_path_factory.mktemp("station"), "--laws", "all")


@pytest.fixture(scope="module")
def three(tmp_path_factory):
    """The cycloid, the uniform law and the polydyne, with --out."""
    folder = tmp_path_factory.mktemp("three")
    r = _station(folder, "--laws", "cycloidal,uniform,polydyne", "--out", str(folder / "out"))
    r.out = folder / "out"
    return r


@pytest.mark.slow
def test_the_station_answers_every_law_and_recommends_one_that_passes(station):
    from camdyn.runtime.core import laws

    assert station.code == 0, station.err
    d = station.d
    assert [x["law"] for x in d["laws"]] == laws.NAMES
    assert all(x["residual_max"] is not None and x["residual_max_error"] is not None
               for x in d["laws"])
    assert sorted(r["law"] for r in d["ranking"]) == sorted(laws.NAMES)
    _recommended_passes(d)
    assert d["ranking"][-1]["law"] == "uniform"


def _recommended_passes(d):
    """The recommended law is ranked first and passes its checks, read off its figures
    against spec.TEMPLATE's limits (30 deg, 1200 MPa, 600 rpm)."""
    best = next(x for x in d["laws"] if x["law"] == d["recommended"])
    assert d["ranking"][0]["law"] == d["recommended"]
    assert best["passed"] and best["reasons"] == []
    assert best["pressure_angle_max_deg"] <= 30.0 and not best["undercut"]
    assert best["hertz_stress_max"] <= 1200e6
    assert best["jump_speed"] is None or best["jump_speed"] > 600 * RPM


def test_three_laws_answered_the_uniform_last(three):
    assert three.code == 0, three.err
    d = three.d
    assert [x["law"] for x in d["laws"]] == ["cycloidal", "uniform", "polydyne"]
    _recommended_passes(d)
    (uniform,) = [x for x in d["laws"] if x["law"] == "uniform"]
    assert not uniform["passed"] and d["ranking"][-1]["law"] == "uniform"
    assert any("velocity jumps" in r for r in uniform["reasons"])
    (poly,) = [x for x in d["laws"] if x["law"] == "polydyne"]
    m = packaging()
    assert poly["law_parameter"] == pytest.approx(0.5 * sum(m.taus), rel=1e-12)
    # --json: no progress lines; every line on stderr one warning
    assert all(line.startswith("camdyn design: warning: ") for line in
               three.err.strip().splitlines())


def test_the_figures_are_si(three):
    """The cycloid's peak acceleration at 600 rpm is 2 pi h/t_m^2 (H''max = 2 pi, App. 2),
    t_m = beta_m/w = (120 deg)/(600 rpm) = 1/30 s: 141.37 m/s^2; each speed also in rpm."""
    (cyc,) = [x for x in three.d["laws"] if x["law"] == "cycloidal"]
    expected = 2 * math.pi * 0.025 * 30.0 ** 2
    assert cyc["acceleration_max"] == pytest.approx(expected, rel=1e-9)
    assert abs(cyc["acceleration_max"] - expected) <= cyc["acceleration_max_error"] + \
        1e-12 * expected
    assert cyc["residual_max_speed_rpm"] == pytest.approx(cyc["residual_max_speed"] / RPM,
                                                          rel=1e-12)
    assert 300 * RPM <= cyc["residual_max_speed"] <= 600 * RPM


def test_out_holds_the_report_and_the_chosen_design(three):
    """--out: the report, the charts, design.json as printed, the chosen machine file (the
    recommended law, its sized preload) that reads back, the cam as `camdyn profile` writes it."""
    from camdyn.thesis.design.band import charts, export, report

    d, out = three.d, three.out
    for name in (*export.files(), *report.FILES, *charts.FILES):
        assert (out / name).is_file(), name
    written = json.loads((out / "design.json").read_text())
    assert written["recommended"] == d["recommended"] and written["laws"] == d["laws"]
    chosen = spec.load(out / "machine.toml")
    best = next(x for x in d["laws"] if x["law"] == d["recommended"])
    assert chosen.laws == (d["recommended"],)
    assert chosen.spring_preload == pytest.approx(best["spring_preload_used"], rel=1e-9)
    assert replace(chosen, laws=packaging().laws, spring_preload=None, source="") == \
        replace(packaging(), source="")
    html = (out / "report.html").read_text()
    assert html.count("data:image/png;base64,") == len(charts.FILES)
    assert "Recommended:" in (out / "report.md").read_text()
    assert "PROFILE" in (out / "cam.dxf").read_text()
    assert (out / "cam.csv").read_text().startswith("phi_deg,")


def test_the_options_answer_as_the_file_does_one_progress_line_a_law(three):
    """The station as options, the cycloid alone: the same figures as the file's run, and
    one progress line on stderr."""
    code, stdout, stderr = _run(["design", *OPTIONS[:-1], "cycloidal", "--json"])
    assert code == 0, stderr
    (mine,) = json.loads(stdout)["laws"]
    (theirs,) = [x for x in three.d["laws"] if x["law"] == "cycloidal"]
    assert mine == theirs
    code, stdout, stderr = _run(["design", *OPTIONS[:-1], "cycloidal"])
    progress = [line for line in stderr.splitlines() if "warning" not in line]
    assert code == 0 and len(progress) == 1 and progress[0].startswith(
        "camdyn design: cycloidal (1/1): worst residual ")
    assert "recommended: cycloidal" in stdout and "worst residual um" in stdout


def test_no_law_passing_is_status_1_with_the_answer():
    """The uniform law alone fails (its velocity jumps): status 1, as camdyn profile's failed
    checks, the answer printed all the same, "recommended" null."""
    code, stdout, stderr = _run(["design", *OPTIONS[:-1], "uniform", "--json"])
    d = json.loads(stdout)
    assert code == 1 and d["recommended"] is None and not d["laws"][0]["passed"]
    assert "Traceback" not in stderr
