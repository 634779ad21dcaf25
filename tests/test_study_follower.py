"""A camshaft1-study scene's [follower]: the machine behind the CAMSHAFT-1 study, from which
its design point (tau, Fa) is formed (runtime/targets/scene_files.py, runtime/cam/reduction.py).

The built-in scene rocker_study (README's rocker) against a hand computation from thesis
(2.55)-(2.57), (4.12)-(4.14), (4.39) and App. 7 (8), and against `camdyn design` for the same
inputs; a translating follower given the rocker's reduced figures against the rocker; the
refusals, one line each through `camdyn run`; a short run's report.json and report.md.
"""
from __future__ import annotations

import json
import math
import subprocess
import sys
import tomllib

import pytest

from camdyn.runtime.cam import reduction as red
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.targets import scene_files as scenes
from camdyn.runtime.targets.resolve import load_scene
from camdyn.thesis.theory import examples as ex

ROCKER_TEXT = scenes.builtin("rocker_study").read_text()
FOLLOWER = tomllib.loads(ROCKER_TEXT)["follower"]
CAMSHAFT = {k: FOLLOWER[k] for k in ("speed", "cam_angle", "pitch_radius", "c_tan")}


def _cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args], capture_output=True,
                          text=True, timeout=300, cwd=cwd)


def _toml(table: dict) -> str:
    """A flat TOML table; floats by repr, which reads back bit for bit."""
    return "\n".join(f"{k} = {json.dumps(v) if isinstance(v, (str, bool)) else repr(v)}"
                     for k, v in table.items())


def _scene(tmp_path, follower: dict, name="scene.toml", response: str = "", n_tau=240) -> str:
    """rocker_study.toml with another [follower] table (and [study.response] lines)."""
    head, rest = ROCKER_TEXT.split("[follower]\n", 1)
    rest = rest[rest.index("[study.graphs]"):].replace("n_tau = 240", f"n_tau = {n_tau}")
    text = f"{head}[follower]\n{_toml(follower)}\n\n{response}{rest}"
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def _by_hand(l, Phi_deg, J, k_t, rpm, beta_deg, R, c_tan) -> dict:
    """The design point written out from the thesis: the rocker reduced to its arc, h_m' =
    l Phi (2.55), m = J/l^2 (2.56), c_c = k_t/l^2 (2.57); t_m = beta_m/w_s (App. 7 (8)),
    T_e = 2 pi (m/c_c)^(1/2) (4.39), tau = T_e/t_m (4.12), tan alpha_me = h_m'/(R_1/2 beta_m)
    (4.13), Fa = (c_c/c_tan) tan^2 alpha_me (4.14)."""
    Phi, beta = Phi_deg * math.pi / 180.0, beta_deg * math.pi / 180.0
    h, m, c = l * Phi, J / (l * l), k_t / (l * l)
    t_m = beta / (rpm * math.pi / 30.0)
    T_e = 2.0 * math.pi * (m / c) ** 0.5
    tan_me = h / (R * beta)
    return {"stroke": h, "mass": m, "stiffness": c, "t_m": t_m, "T_e": T_e, "tau": T_e / t_m,
            "tan_alpha_me": tan_me, "Fa": c * tan_me**2 / c_tan}


def test_rocker_study_design_point_is_the_hand_computation_and_camdyn_design():
    """rocker_study's tau and Fa (and stroke, m, c_c, t_m, T_e, tan alpha_me) equal the
    thesis's formulas written out here (rel 1e-12: the hand computation orders its floating
    operations differently), and equal bit for bit what `camdyn design --swing ... --json`
    gives for the same inputs (its "machine" keys); tau = 0.147, Fa = 0.492 as the scene's
    comment says (3 digits)."""
    kind, sc = load_scene("rocker_study")
    assert kind == scenes.STUDY
    d = sc["design"]
    f = FOLLOWER
    want = _by_hand(f["arm_length"], f["swing"], f["arm_inertia"], f["arm_stiffness"],
                    f["speed"], f["cam_angle"], f["pitch_radius"], f["c_tan"])
    for key, value in want.items():
        assert d["figures"][key]["value"] == pytest.approx(value, rel=1e-12), key
    assert (d["tau"], d["Fa"]) == (d["figures"]["tau"]["value"], d["figures"]["Fa"]["value"])
    assert sc["study"]["response"] == {"tau": d["tau"], "Fa": [0.0, d["Fa"]]}
    assert d["Fa"] in sc["study"]["graphs"]["Fa"]
    assert round(d["tau"], 3) == 0.147 and round(d["Fa"], 3) == 0.492

    p = _cli("design", "--swing", repr(f["swing"]), "--arm-length", repr(f["arm_length"]),
             "--arm-inertia", repr(f["arm_inertia"]), "--arm-stiffness", repr(f["arm_stiffness"]),
             "--speed", repr(f["speed"]), "--cam-angle", f"{f['cam_angle']!r}deg",
             "--pitch-radius", repr(f["pitch_radius"]), "--c-tan", repr(f["c_tan"]),
             "--no-check", "--json")
    assert p.returncode == 0, p.stderr
    machine = json.loads(p.stdout)["machine"]
    for key in want:
        assert machine[key] == d["figures"][key]["value"], key


def test_a_translating_follower_with_the_rockers_reduced_figures_is_the_rocker(tmp_path):
    """A translating follower given stroke l Phi, mass J/l^2 and stiffness k_t/l^2 directly
    (as the rocker's reduction forms them, written with repr) has the rocker's design point
    bit for bit (tolerance 0), and so has a rocker given its mass and stiffness at the roller;
    the rocker's figures say which formula they came from, the others that they were given."""
    f = FOLLOWER
    l = f["arm_length"]
    at_roller = {"mass": f["arm_inertia"] / l**2, "stiffness": f["arm_stiffness"] / l**2}
    translating = {"kind": "translating-roller", "stroke": l * math.radians(f["swing"]),
                   **at_roller, **CAMSHAFT}
    rocker_at_roller = {"kind": "oscillating-roller", "swing": f["swing"], "arm_length": l,
                        **at_roller, **CAMSHAFT}
    _, rocker = load_scene("rocker_study")
    for i, table in enumerate((translating, rocker_at_roller)):
        _, sc = load_scene(_scene(tmp_path, table, name=f"s{i}.toml"))
        assert (sc["design"]["tau"], sc["design"]["Fa"]) == (rocker["design"]["tau"],
                                                             rocker["design"]["Fa"])
        assert sc["study"] == rocker["study"]
    figures = sc["design"]["figures"]
    assert figures["stroke"]["formula"] == "l Phi (2.55)"
    assert figures["mass"]["formula"] == figures["stiffness"]["formula"] == "given at the roller"
    assert rocker["design"]["figures"]["mass"]["formula"] == "J/l^2 (2.56)"
    assert rocker["design"]["figures"]["stiffness"]["formula"] == "k_t/l^2 (2.57)"


def test_the_runtimes_formulas_are_the_theorys():
    """runtime/cam/reduction.py's t_m, T_e, tan alpha_me and Fa equal bit for bit those typed
    in from the thesis in thesis/theory/examples.py (App. 7 (8), (4.39), (4.13), (4.14)), on
    App. 7's two machines and the rocker (tolerance 0)."""
    for m, c, beta, w_s, h, R, c_tan in ((45.0, 3.65e6, 1.745, 2 * math.pi, 0.1, 0.085, 1.57e5),
                                         (1.46, 0.376e6, 0.436, 4.974, 0.0309, 0.075, 3.83e4),
                                         (0.609375, 2.5e5, 2.0944, 31.416, 0.02513, 0.0605, 2e4)):
        assert red.rise_time(beta, w_s) == ex.rise_time(beta, w_s)
        assert red.natural_period(m, c) == ex.natural_period(m, c)
        tan_me = red.mean_slope(h, R, beta)
        assert tan_me == ex.mean_slope(h, R, beta)
        assert red.shaft_factor(c, c_tan, tan_me) == ex.shaft_factor(c, c_tan, tan_me)


REFUSED = {
    "the response's tau with a follower": (
        dict(FOLLOWER), "[study.response]\ntau = 0.15\n\n",
        ("study.response.tau and [follower]", "give one or the other")),
    "a rocker's key on a translating follower": (
        {**FOLLOWER, "kind": "translating-roller"}, "",
        ('follower.swing is refused with kind = "translating-roller"', "it takes stroke")),
    "a swing of 200 deg": (
        {**FOLLOWER, "swing": 200.0}, "",
        ("follower.swing=200 is out of range: 0 < swing < 180 (deg",)),
    "a missing speed": (
        {k: v for k, v in FOLLOWER.items() if k != "speed"}, "",
        ("follower.speed is missing (r.p.m.",)),
}


@pytest.mark.parametrize("case", sorted(REFUSED))
def test_a_bad_follower_is_refused_in_one_line_by_camdyn_run(tmp_path, case):
    """`camdyn run SCENE` refuses the scene with exit status 2, one line on stderr naming the
    key, its value and the range allowed (or what to do), nothing on stdout, no out folder."""
    follower, response, words = REFUSED[case]
    p = _cli("run", _scene(tmp_path, follower, response=response), "--out", str(tmp_path / "out"))
    lines = p.stderr.strip().splitlines()
    assert p.returncode == 2 and len(lines) == 1, p.stderr
    for w in words:
        assert w in lines[0], lines[0]
    assert p.stdout == "" and not (tmp_path / "out").exists()


@pytest.mark.parametrize("edit, words", [
    ({"stroke": 0.02}, ("follower.stroke is refused", "arm_length x swing (2.55)")),
    ({"mass": 0.6}, ("follower.arm_inertia and follower.mass", "not both")),
    ({"colour": 3}, ("follower.colour is not a follower key",)),
    ({"kind": "flat-face"}, ("follower.kind='flat-face': choose",)),
    ({"arm_length": True}, ("follower.arm_length must be a number",)),
    ({"arm_length": 1e-200}, ("arm_length=1e-200", "give no finite tau and Fa")),
    ({"cam_angle": 360.0}, ("follower.cam_angle=360 is out of range: 0 < cam_angle < 360",)),
    ({"arm_stiffness": 1e-6}, ("arm_stiffness=1e-06", "give tau = T_e/t_m (4.12) =",
                               "range 0 < tau <= 10")),
    ({"c_tan": 1.0}, ("c_tan=1", "give Fa = (c_c/c_tan) tan^2 alpha_me (4.14) =",
                      "range 0 <= Fa <= 100")),
])
def test_every_follower_input_is_checked_by_name(tmp_path, edit, words):
    """Each input of [follower] is checked before anything runs: a CamdynInputError of one
    line naming the key and its value (and its range, or the formula and CAMSHAFT-1's range
    for a tau or Fa out of the manifest's, naming the inputs they came from)."""
    with pytest.raises(CamdynInputError) as info:
        load_scene(_scene(tmp_path, {**FOLLOWER, **edit}))
    msg = str(info.value)
    assert "\n" not in msg
    for w in words:
        assert w in msg, msg


def test_an_empty_response_table_is_allowed_with_a_follower(tmp_path):
    """[study.response] may be given empty beside a [follower] (its tau and Fa are the
    follower's); any other key there is unknown."""
    _, sc = load_scene(_scene(tmp_path, FOLLOWER, response="[study.response]\n\n"))
    assert sc["study"]["response"]["tau"] == sc["design"]["tau"]
    with pytest.raises(CamdynInputError, match="unknown key study.response.colour"):
        load_scene(_scene(tmp_path, FOLLOWER, response="[study.response]\ncolour = 1\n\n"))


def test_a_short_rocker_study_reports_its_design_point(tmp_path):
    """`camdyn run` on the rocker study with n_tau = 8 writes report.json with the design
    point (tau, Fa as loaded, bit for bit; the reduced figures with their formulas; U0 and
    U0'' of its response run, and u0 = U0 h_m' (sec. 3.3) to rel 1e-12), the response at
    Fa = 0 and the follower's Fa, the follower's Fa among the graphs' rows; report.md
    states the point with the formulas; graphs.png is written.  The README's figures there,
    U0 = 1.60e-3 and 6.2e-4 on a rigid camshaft, to their printed digits."""
    path = _scene(tmp_path, FOLLOWER, n_tau=8)
    _, sc = load_scene(path)
    out = tmp_path / "out"
    p = _cli("run", path, "--out", str(out), "--quiet")
    assert p.returncode == 0, p.stderr
    assert p.stdout.startswith(f"design point of the follower: tau = {sc['design']['tau']:.4g}")
    rep = json.loads((out / "report.json").read_text())
    d = rep["design_point"]
    assert (d["tau"], d["Fa"]) == (sc["design"]["tau"], sc["design"]["Fa"])
    assert d["figures"] == sc["design"]["figures"] and d["follower"] == {**FOLLOWER}
    (row,) = [r for r in rep["response"] if r["Fa"] == d["Fa"]]
    assert (d["U0"], d["U0dd"]) == (row["U0"], row["U0dd"])
    assert d["u0"] == pytest.approx(row["U0"] * d["figures"]["stroke"]["value"], rel=1e-12)
    assert [r["Fa"] for r in rep["response"]] == [0.0, d["Fa"]]
    assert round(d["U0"], 5) == 1.60e-3 and round(rep["response"][0]["U0"], 5) == 6.2e-4
    assert str(d["Fa"]) in rep["graphs"]["rows"] and len(rep["graphs"]["tau"]) >= 8
    md = (out / "report.md").read_text()
    assert "## Design point of the follower (oscillating-roller)" in md
    for formula in ("l Phi (2.55)", "J/l^2 (2.56)", "k_t/l^2 (2.57)", "beta_m/w_s (App. 7 (8))",
                    "T_e/t_m (4.12)", "(c_c/c_tan) tan^2 alpha_me (4.14)"):
        assert formula in md
    assert (out / "graphs.png").stat().st_size > 10_000
