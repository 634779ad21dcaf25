"""What the input campaign (tests/test_campaign*.py) found in the commands, each now right:

* `camdyn polydyne --no-error-estimate --json` printed NaN for every estimate (JSON has no
  NaN: a strict reader refuses the answer) and its text "± nan"; the estimates are now left
  out of the JSON, and the text says there is none.  Its --out was checked after both sweeps
  ran: a file of the user's there is now refused first.
* `camdyn laws` took an option given as 0 (--tau 0, --fa 0) for one not given (0.0 == False):
  `--tau 0 --no-error-estimate` was refused naming --no-error-estimate instead of --tau's
  range, and `--fa 0` beside --rise or --sweep was dropped unread instead of refused.
* `camdyn profile` (and the design page) took a contact line of any width above 0: at 1e-300
  m the force per length overflowed, NumPy warned on stderr, and the stress check blamed the
  profile ("not convex enough for the follower") for what the width did; a STEP plate that
  thin reached the CAD kernel ("Bnd_Box is void"), and a bore of 1e-300 m was cut.  Widths,
  the plate's thickness and a bore are now at least a micrometre, as the radii.
* `camdyn profile --arcs 1e-6` of a profile that cusps (an oscillating flat face swinging
  30 deg over the cycloid's 90 deg) fitted arcs round the cusp for two minutes before refusing
  at the fit's limit of 200000 arcs (round a cusp the arcs shrink with the tolerance).  A
  profile failing its undercut or cusp check now gets at most 2000 arcs a layer, a smooth one
  20000, and the refusal names the cusp and its cam angle.
* `camdyn stability` of a model without a rise (a model file, motor1) printed "reference":
  [NaN, ...] in its JSON (the figure there is every state at t_end, held as NaN); it now gives
  those states by name.
* `camdyn integrate --no-error-estimate --json` printed the states and outputs with no
  estimate and no word of it (the text says "(no error estimate)"): each now has its null
  estimate beside it, as `camdyn residual` gives.
* `camdyn stability --methods dp54 --steps 0.01` mapped dp54 over its default tolerances and
  dropped the steps unread (and --rtols beside fixed-step methods only, likewise); a grid no
  method of the map takes is now refused, naming it.
* `camdyn profile --groove` of a pitch curve convex all round said of the outer wall
  "smallest concave |rho_p| = inf mm at 19.43 deg": there is no concave part, and it says so.
"""
from __future__ import annotations

import json
import os

import pytest

from .test_campaign import Ran, run


def _strict(text: str):
    """JSON as a strict reader takes it: NaN and Infinity refused."""
    def refuse(token):
        raise ValueError(f"{token} is not JSON")
    return json.loads(text, parse_constant=refuse)


def test_polydyne_without_estimates_prints_json_and_says_so(tmp_path):
    """--no-error-estimate: strict JSON with no estimate keys, the text "(no error estimate)";
    and the polydyne still does what it is for: at its design tau the one-DOF output follows
    the degree-9 rise exactly, so U0 there is nil against the uncompensated rise's (thesis
    (3.1); README "Compensated cams")."""
    argv = ["polydyne", "--design-tau", "0.15", "--taus", "0.1:0.2:3", "--quiet",
            "--no-error-estimate", "--json", "--out", str(tmp_path / "j")]
    code, out, err = run(argv)
    assert code == 0, err
    answer = _strict(out)
    assert not [k for k in answer if k.endswith("_error")], list(answer)
    assert answer["tau"][1] == pytest.approx(0.15)
    assert answer["polydyne:U0"][1] < 1e-8 * answer["plain:U0"][1]
    assert _strict((tmp_path / "j" / "polydyne.json").read_text()) == \
        {**answer, "files": answer["files"]}
    code, out, err = run([*argv[:-3], "--out", str(tmp_path / "t")])
    assert code == 0 and "nan" not in out.lower()
    assert out.count("(no error estimate)") == 2, out


def test_polydyne_with_estimates_gives_numbers_for_them(tmp_path):
    code, out, err = run(["polydyne", "--design-tau", "0.15", "--taus", "0.1:0.2:3", "--quiet",
                          "--json", "--out", str(tmp_path)])
    answer = _strict(out)
    for key in ("polydyne:U0_error", "plain:U0_error", "polydyne:U0dd_error"):
        assert all(e is not None and e >= 0 for e in answer[key]), key


def test_polydyne_refuses_a_users_file_in_out_before_its_runs(tmp_path, monkeypatch):
    def ran(*a, **k):
        raise Ran("the sweeps ran before --out was refused")
    monkeypatch.setattr("camdyn.runtime.studies.polydyne.compensation", ran)
    mine = b"my own\n"
    (tmp_path / "polydyne.json").write_bytes(mine)
    code, out, err = run(["polydyne", "--design-tau", "0.15", "--quiet", "--out", str(tmp_path)])
    (line,) = err.strip().splitlines()
    assert code == 2 and not out and line.startswith("camdyn polydyne: error: ")
    assert "polydyne.json exists and camdyn did not write it" in line
    assert os.listdir(tmp_path) == ["polydyne.json"]
    assert (tmp_path / "polydyne.json").read_bytes() == mine


@pytest.mark.parametrize("argv, words", [
    (["laws", "--tau", "0", "--no-error-estimate"], "argument --tau: tau=0 is out of range"),
    (["laws", "--fa", "0", "--no-error-estimate"], "argument --tau: required with --fa"),
    (["laws", "--sweep", "spring_loaded", "--fa", "0"], "argument --fa: not with --sweep"),
    (["laws", "--sweep", "spring_loaded", "--tau", "0"], "argument --tau: not with --sweep"),
    (["laws", "--rise", "rise.toml", "--fa", "0"], "argument --fa: not with --rise"),
    (["laws", "--rise", "rise.toml", "--theta", "0"], "argument --theta: not with --rise"),
])
def test_laws_takes_an_option_given_as_zero_for_given(argv, words, monkeypatch):
    """Refused in one line naming the option given as 0 (the selection's own check of --tau
    before its runs; the others before the sweep or the selection is reached: their entry
    points fail the test then)."""
    def ran(*a, **k):
        raise Ran("a run started")
    monkeypatch.setattr("camdyn.thesis.design.shape_sweep.sweep_scene", ran)
    if "--sweep" in argv or "--rise" in argv:
        monkeypatch.setattr("camdyn.thesis.design.selection.select", ran)
    code, out, err = run(argv)
    (line,) = err.strip().splitlines()
    assert code == 2 and not out and line.startswith("camdyn laws: error: "), err
    assert words in line, line


@pytest.mark.parametrize("extra, words", [
    (["--contact-force", "500", "--roller-width", "1e-300"], "roller-width=1e-300 is out of range"),
    (["--contact-force", "500", "--cam-width", "1e-300", "--follower", "translating-flat"],
     "cam-width=1e-300 is out of range"),
    (["--step", "--cam-width", "1e-300"], "cam-width=1e-300 is out of range"),
    (["--step", "--cam-width", "0.01", "--bore", "1e-300"], "bore=1e-300 is out of range"),
])
def test_a_contact_line_or_a_plate_thinner_than_a_micrometre_is_refused(extra, words, tmp_path):
    argv = ["profile", "--stroke", "0.02", "--base-radius", "0.04", "--points-per-degree", "1",
            *(["--roller-radius", "0.008"] if "--follower" not in extra else []), *extra,
            "--out", str(tmp_path)]
    code, out, err = run(argv)
    (line,) = err.strip().splitlines()
    assert code == 2 and not out and line.startswith("camdyn profile: error: "), err
    assert words in line and ">= 1e-06" in line, line
    assert os.listdir(tmp_path) == []


def test_the_thinnest_contact_line_is_hertz_s(tmp_path):
    """At the least width a flat face carries the line contact of Johnson (4.45) where the
    profile's radius of curvature is least: p0 = (P' E*/(pi rho_min))^(1/2), P' = F/L,
    1/E* = 2 (1 - nu^2)/E for two bodies of E = 210 GPa, nu = 0.3 (given as E:nu)."""
    import math

    e_star = 1 / (2 * (1 - 0.3 ** 2) / 210e9)
    code, out, err = run(["profile", "--follower", "translating-flat", "--stroke", "0.01",
                          "--base-radius", "0.05", "--points-per-degree", "2",
                          "--contact-force", "500", "--cam-width", "1e-6", "--materials",
                          "210e9:0.3,210e9:0.3", "--json", "--out", str(tmp_path)])
    assert code in (0, 1), err
    js = json.loads(out)
    want = math.sqrt(500 / 1e-6 * e_star / (math.pi * js["min_rho_profile"]))
    # the figure's own estimate plus the radius's (rho enters as rho^(-1/2))
    tol = js["hertz_stress_max_error"] + want * js["min_rho_profile_error"] / js["min_rho_profile"]
    assert abs(js["hertz_stress_max"] - want) <= tol + 1e-12 * want


def test_arcs_round_a_large_cusp_are_refused_after_a_bounded_fit(tmp_path, monkeypatch):
    """The cusping flat face at --arcs 1e-6: refused in one line naming the cusp, its cam
    angle and what to do, after at most CUSP_ARCS arcs (each span's bi-arc counted: the fit
    halves a span into two, so fewer than twice as many bi-arcs are made as arcs kept) where
    it made 200000; at 0.1 mm the same cusp is fitted (1934 arcs, within CUSP_ARCS)."""
    from camdyn.runtime.cam import biarc
    from camdyn.runtime.cam.profile import CUSP_ARCS

    made = []
    real = biarc.biarc

    def counted(*a):
        made.append(1)
        return real(*a)
    monkeypatch.setattr(biarc, "biarc", counted)
    argv = ["profile", "--follower", "oscillating-flat", "--swing", "30", "--pivot-distance",
            "0.1", "--base-radius", "0.04", "--points-per-degree", "2", "--json"]
    code, out, err = run([*argv, "--arcs", "1e-6", "--out", str(tmp_path / "fine")])
    (line,) = err.strip().splitlines()
    assert code == 2 and not out and line.startswith("camdyn profile: error: arcs=1e-06 m: "), err
    assert f"more than {CUSP_ARCS} tangent arcs round the cusp" in line
    assert "cam angle 52.47 deg" in line and "coarser --arcs" in line
    assert len(made) < 2 * CUSP_ARCS + 10
    code, out, err = run([*argv, "--arcs", "1e-4", "--out", str(tmp_path / "coarse")])
    js = json.loads(out)
    assert code == 1 and not js["ok"] and 100 < js["arcs"]["PROFILE"] <= CUSP_ARCS, err


def _motor1(G_a: float, t_end: float, J_ma=0.05, t_m=0.1, Mc=1.0) -> float:
    """dw(t_end) of the first-order motor (thesis sec. A.5.4.2, derive/models/motor.py):
    J_ma dw' = -G_a dw - Mc H'(T) H''(T), T = t/t_m, the cycloid H' = 1 - cos 2 pi T,
    H'' = 2 pi sin 2 pi T over the rise and the dwell's H' = 0 after it; from rest, by SciPy's
    DOP853 at rtol 1e-12, restarted at the rise's end."""
    import math

    from scipy.integrate import solve_ivp

    def rhs(t, y):
        T = t / t_m
        load = Mc * (1 - math.cos(2 * math.pi * T)) * 2 * math.pi * math.sin(2 * math.pi * T) \
            if T < 1 else 0.0
        return [(-G_a * y[0] - load) / J_ma]
    y = [0.0]
    for a, b in ((0.0, min(t_m, t_end)), (min(t_m, t_end), t_end)):
        if b > a:
            y = solve_ivp(rhs, (a, b), y, method="DOP853", rtol=1e-12, atol=1e-15).y[:, -1]
    return float(y[0])


def test_stability_of_a_model_without_a_rise_reports_its_states(tmp_path):
    """Strict JSON; the reference figure per G_a the motor's state dw at t_end, by name, as
    SciPy solves the equation (to 1e-7 of its size plus 1e-12 rad/s)."""
    code, out, err = run(["stability", "motor1", "--param", "G_a=1,5", "--methods", "rk4",
                          "--steps", "0.001", "--t-end", "0.3", "--json", "--quiet",
                          "--out", str(tmp_path)])
    assert code == 0, err
    js = _strict(out)
    assert _strict((tmp_path / "stability_motor1_G_a.json").read_text())["reference"] == \
        js["reference"]
    for G_a, ref in zip((1.0, 5.0), js["reference"]):
        assert list(ref) == ["dw"]
        want = _motor1(G_a, 0.3)
        assert abs(ref["dw"] - want) <= 1e-7 * abs(want) + 1e-12, (G_a, ref, want)


def test_integrate_without_estimates_says_so_beside_every_number():
    """Every state and output with its estimate key: null without the tighter run, a number
    with it; the state X(2) of the one-DOF model (3.1) after the cycloidal rise, 1 + U(2),
    within its estimate of the free vibration's closed form:  U(T) = U0 cos(w (T - 1) +
    phase), amplitude U0 (3.5) from SciPy (tests/test_cli_findings.py)."""
    import math

    from .test_cli_findings import _one_dof_amplitudes

    code, out, err = run(["integrate", "one_dof", "--set", "tau=0.3", "--t-end", "2",
                          "--json", "--no-error-estimate"])
    js = _strict(out)
    assert code == 0 and set(js["state_error"]) == set(js["state"]) == {"X", "Xd"}, err
    assert set(js["outputs_error"]) == set(js["outputs"]) and js["outputs"]
    assert all(v is None for v in [*js["state_error"].values(), *js["outputs_error"].values()])
    code, out, err = run(["integrate", "one_dof", "--set", "tau=0.3", "--t-end", "2", "--json"])
    js = _strict(out)
    U0, _ = _one_dof_amplitudes(0.3)
    w = 2 * math.pi / 0.3
    amplitude = math.hypot(js["state"]["X"] - 1, js["state"]["Xd"] / w)
    assert abs(amplitude - U0) <= js["state_error"]["X"] + js["state_error"]["Xd"] / w + 1e-12


@pytest.mark.parametrize("methods, grid, words", [
    (["dp54"], ["--steps", "0.01"], "argument --steps: no method of the map (dp54) takes a "
                                    "fixed step"),
    (["dop853", "rodas4"], ["--steps", "0.01,0.02"], "argument --steps: no method"),
    (["rk4"], ["--rtols", "1e-6"], "argument --rtols: no method of the map (rk4) takes a "
                                   "tolerance"),
    (["rk4", "koster"], ["--rtols", "1e-6,1e-8"], "argument --rtols: no method"),
])
def test_stability_refuses_a_grid_no_method_takes(methods, grid, words, tmp_path, monkeypatch):
    def ran(*a, **k):
        raise Ran("the map ran")
    monkeypatch.setattr("camdyn.runtime.studies.stability_map.run_map", ran)
    monkeypatch.setattr("camdyn.runtime.studies.stability_map.reference", ran)
    code, out, err = run(["stability", "one_dof", "--param", "tau=0.2,0.3", "--methods",
                          *methods, *grid, "--quiet", "--out", str(tmp_path)])
    (line,) = err.strip().splitlines()
    assert code == 2 and not out and line.startswith("camdyn stability: error: "), err
    assert words in line, line
    assert os.listdir(tmp_path) == []


def _pitch_curvature(cam, n=72001):
    """The signed curvature of the sampled pitch curve (x' y'' - y' x'')/(x'^2 + y'^2)^(3/2)
    by central differences over the turn (n points), independent of the profile's formulas."""
    import numpy as np

    phi = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    p = cam.pitch(phi)
    x, y = p[0], p[1]
    h = phi[1] - phi[0]
    dx, dy = (np.roll(x, -1) - np.roll(x, 1)) / (2 * h), (np.roll(y, -1) - np.roll(y, 1)) / (2 * h)
    ddx = (np.roll(x, -1) - 2 * x + np.roll(x, 1)) / h**2
    ddy = (np.roll(y, -1) - 2 * y + np.roll(y, 1)) / h**2
    return (dx * ddy - dy * ddx) / (dx * dx + dy * dy) ** 1.5


@pytest.mark.parametrize("stroke, base, concave", [(0.02, 0.04, False), (0.04, 0.01, True)])
def test_a_groove_s_outer_wall_says_whether_the_pitch_curve_is_concave(stroke, base, concave):
    """The outer wall's check against the pitch curve's own curvature: convex all round (no
    concave part: said so, no infinite radius), or concave somewhere (its least concave
    radius, a number, within 1e-3 of the sampled curve's)."""
    import numpy as np

    from camdyn.runtime.cam.profile import CamProfile

    cam = CamProfile(stroke=stroke, base_radius=base, roller_radius=0.005, groove=True,
                     points_per_degree=2)
    kappa = _pitch_curvature(cam)
    sign = np.sign(np.median(kappa))               # the pitch curve's sense of turning
    (outer,) = [c for c in cam.checks if c.name == "undercut outer"]
    assert (sign * kappa < 0).any() == concave
    if concave:
        least = 1 / np.max(-sign * kappa)
        assert "inf" not in outer.message and outer.value == pytest.approx(least, rel=1e-3)
    else:
        assert outer.message == "no undercut of the outer wall: the pitch curve has no concave part"
