"""DYNACAM's followers beyond the translating roller (derive/models/dynacam.py).

The rocker (option ``rocker``): an oscillating roller follower reduced to the roller centre's
arc (thesis sec. 2.4), the shaft's deflections reaching it as (6.22) has them reach the
translating follower, through ratios of the rocker's geometry (_rocker).  The flat face
(option ``flat_face``): a sideways shift of the cam does not move it.  Both options: a flat
face on the rocker's arm (_rocker_flat).

References independent of the generated code and of _rocker's algebra:

* the rocker of runtime/cam/follower.py (its own frame: the cam turning clockwise, the pivot
  at (a, 0)), moved against a cam shifted by a small vector; how far the roller must swing to
  stay on the pitch curve is solved exactly there (SciPy's fsolve on the contact condition);
* the flat-faced rocker of runtime/cam/follower.py (the same frame), whose face is moved
  against the shifted cam until it touches it again, solved exactly (fsolve on the face's
  support distance and the cam angle that touches it);
* the translating DYNACAM, which a rocker with a 1 km arm square to the line to the cam
  centre must reproduce, and the translating flat face, which a flat face on an arm pivoted
  1 km away must reproduce.
"""
import json
import math
import warnings

import numpy as np
import pytest
from scipy.optimize import fsolve

from camdyn.runtime.cam.follower import OscillatingFlat, OscillatingRoller
from camdyn.runtime.core.compiled import load
from camdyn.runtime.core.laws import choose
from camdyn.runtime.core.simulator import Simulator
from camdyn.runtime.engine import driver

ROCKER = "dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring_rocker"
TRANSLATING = "dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring"
FLAT = "dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring_flat"
FLAT_ROCKER = FLAT + "_rocker"
GEOMETRY = {"R_b": 0.05, "d_p": 0.12, "l_a": 0.09, "h_m": 0.02, "beta_m": 1.2, "beta_0": 0.0}
FACE = {**GEOMETRY, "f_f": 0.01}


def _h(beta, h_m, beta_m):
    """The cycloidal rise (A.2.8) over [0, beta_m], h_m high."""
    B = beta / beta_m
    return h_m * (B - math.sin(2 * math.pi * B) / (2 * math.pi))


def _uniform(beta, h_m, beta_m):
    """The uniform rise, h_m beta/beta_m: its slope is the mean slope everywhere."""
    return h_m * beta / beta_m


def _face_swing(beta, shift, law=_h):
    """The flat face's displacement along the arc at l_a when the cam is shifted by (y, z) at
    cam angle beta, in follower.py's frame as :func:`_swing` has it (e_z the face's normal at
    the rise start).  Unknowns: the swing psi and the cam angle b1 at which the nominal motion
    put the face's normal where it points now, in the cam's frame; the face touches the
    shifted cam where its support equals the nominal one there plus the shift along the
    normal."""
    g = FACE
    f = OscillatingFlat(base_radius=g["R_b"], pivot_distance=g["d_p"], face_offset=g["f_f"])

    def face(psi):
        (th, _, _), (k, _, _) = f.face((np.array(psi), np.array(0.0), np.array(0.0)))
        return float(th), float(k)

    th0, _ = face(0.0)
    e_z = np.array([math.cos(th0), math.sin(th0)])
    e_y = np.array([-e_z[1], e_z[0]])
    y, z = shift
    D = y * e_y - z * e_z
    psi_b = law(beta, g["h_m"], g["beta_m"]) / g["l_a"]

    def touch(u):
        psi, b1 = u
        th, k = face(psi)
        th1, k1 = face(law(b1, g["h_m"], g["beta_m"]) / g["l_a"])
        # the cam turns clockwise: a ground direction theta_g lies at phi + theta_g on the cam
        return [b1 + th1 - beta - th, k1 - k + D @ np.array([math.cos(th), math.sin(th)])]

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        psi, _ = fsolve(touch, [psi_b, beta], xtol=1e-14)
    return (psi - psi_b) * g["l_a"]


def _swing(beta, shift, law=_h, g=GEOMETRY):
    """The roller centre's displacement along its arc when the cam is shifted by (y, z) at
    cam angle beta, in follower.py's frame: z along the line from the cam centre to the
    roller at the rise start, y square to it, opposite to the cam surface's motion there (so
    (6.22)'s signs), the cam moved by y e_y - z e_z."""
    f = OscillatingRoller(roller_radius=0.0, base_radius=g["R_b"], pivot_distance=g["d_p"],
                          arm_length=g["l_a"])

    def centre(psi):
        (g0, g1), _, _ = f.centre((np.array(psi), np.array(0.0), np.array(0.0)))
        return np.array([float(g0), float(g1)])

    G0 = centre(0.0)
    e_z = G0 / np.hypot(*G0)
    e_y = np.array([-e_z[1], e_z[0]])         # +90 deg from e_z: against a clockwise cam's surface
    y, z = shift
    D = y * e_y - z * e_z
    psi_b = law(beta, g["h_m"], g["beta_m"]) / g["l_a"]

    def contact(u):
        psi, b1 = u
        a = -(beta - b1)                      # the cam turns clockwise
        rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        return centre(psi) - D - rot @ centre(law(b1, g["h_m"], g["beta_m"]) / g["l_a"])

    with warnings.catch_warnings():
        # at 1e-14 fsolve says it cannot improve further: the solution is there to rounding
        warnings.simplefilter("ignore", RuntimeWarning)
        psi, _ = fsolve(contact, [psi_b, beta], xtol=1e-14)
    return (psi - psi_b) * g["l_a"]


def _ratio_exact(beta, unit, swing=_swing, law=_h, **geometry):
    """-d(swing)/d(shift) along ``unit`` ((1, 0): y, (0, 1): z), by central differences of the
    exact swing over +-1e-6 m (the second order, the pitch curve's curvature, cancels)."""
    d = 1e-6
    up, down = (swing(beta, (k * d * unit[0], k * d * unit[1]), law, **geometry) for k in (1, -1))
    return -(up - down) / (2 * d)


def _outputs(name, params, beta):
    model = load(name)
    p = model.parameter_vector(params)
    law = choose("cycloidal")
    codes, pars = np.array([law.code], dtype=np.intc), np.array([law.par])
    Y = np.zeros((len(beta), len(model.state_names)))
    Y[:, model.state_names.index("beta")] = beta
    out = driver.eval_outputs(model.capsule, p, codes, pars, np.zeros(len(beta)), Y)
    return {k: out[:, i] for i, k in enumerate(model.output_names)}


@pytest.mark.parametrize("beta", [0.15, 0.45, 0.6, 0.9])
def test_ratios_are_the_exact_swing_of_a_rocker_against_a_shifted_cam(beta):
    """i_y (the output tan_alpha) and i_z against the derivatives of the exact swing: 1e-7
    relative (what central differences over 1e-6 m leave, with the swing solved to 1e-14;
    measured 3e-9 and less)."""
    out = _outputs(ROCKER, GEOMETRY, np.array([beta]))
    for key, unit in (("tan_alpha", (1, 0)), ("i_z", (0, 1))):
        assert out[key][0] == pytest.approx(_ratio_exact(beta, unit), rel=1e-7), key


@pytest.mark.parametrize("beta", [0.15, 0.45, 0.6, 0.9, 1.1])
def test_ratios_are_the_exact_swing_of_a_flat_face_against_a_shifted_cam(beta):
    """A flat face on the arm, 1 cm off the pivot: i_y and i_z (_rocker_flat) against the
    derivatives of the exact swing, 1e-7 relative as for the roller (measured 5e-9 and less)."""
    out = _outputs(FLAT_ROCKER, FACE, np.array([beta]))
    for key, unit in (("tan_alpha", (1, 0)), ("i_z", (0, 1))):
        assert out[key][0] == pytest.approx(_ratio_exact(beta, unit, _face_swing), rel=1e-7), key


def test_a_flat_face_on_the_arm_at_the_rise_start():
    """At the rise start the face is square to the line to the cam centre: i_y = 0, and a
    shift along that line turns the face about the pivot by the shift over the pivot's distance
    along the face, so i_z = l_a/(d_p^2 - (R_b - f_f)^2)^(1/2); the face's support distance
    (output R_c) is R_b: 1e-12."""
    g = FACE
    out = _outputs(FLAT_ROCKER, FACE, np.array([0.0]))
    assert abs(out["tan_alpha"][0]) < 1e-12
    assert out["i_z"][0] == pytest.approx(g["l_a"] / math.sqrt(g["d_p"] ** 2 - (g["R_b"] - g["f_f"]) ** 2),
                                          rel=1e-12)
    assert out["R_c"][0] == pytest.approx(g["R_b"], rel=1e-12)


@pytest.mark.parametrize("name, params, swing", [(ROCKER, GEOMETRY, _swing),
                                                 (FLAT_ROCKER, FACE, _face_swing)])
def test_a_rocker_scene_takes_its_ratios_in_mid_rise_at_the_mean_slope(name, params, swing):
    """tau, Fa and Fv of a rocker scene use the ratios i_y, i_z in mid-rise under the mean
    slope h_m/beta_m (runtime/targets/dynacam.py, mean_ratios), as (4.13) takes the
    translating follower's slope: against the exact swing under the uniform rise, 1e-7."""
    from camdyn.runtime.core.variants import Options
    from camdyn.runtime.targets.dynacam import mean_ratios

    opts = Options(roller="contact", spring=True, rocker=True, flat_face=name == FLAT_ROCKER)
    i_y, i_z = mean_ratios(opts, params)
    beta = params["beta_m"] / 2
    assert i_y == pytest.approx(_ratio_exact(beta, (1, 0), swing, _uniform), rel=1e-7)
    assert i_z == pytest.approx(_ratio_exact(beta, (0, 1), swing, _uniform), rel=1e-7)


def test_the_rocker_scene_s_characteristics_by_hand():
    """tau, Fa, Fv of the built-in scene ``rocker`` by hand from its TOML: the ratios i_y, i_z
    in mid-rise from the exact swing under the uniform rise (whose slope is the mean slope
    h_1 = h_m/beta_m), the shaft taken to the contact as (4.3)-(5.52) take it to R_1/2: the
    compliance C = h_1^2/k + i_y^2/c_y, the shaft's mass M = (J h_1^2/k^2 + m_y i_y^2/c_y^2)
    /C^2, c_c = 1/(1/c_x + i_z^2/c_z), m = m_x + m_z (c_c i_z/c_z)^2; tau = 2 pi (m/c_c)^(1/2)
    /t_m, Fa = c_c C, Fv = m/M: 1e-6 (the ratios' differences, 1e-7)."""
    import tomllib
    from importlib import resources

    from camdyn.runtime.targets import dynacam, scene_files

    raw = tomllib.loads(resources.files("camdyn.runtime.scenes").joinpath("rocker.toml").read_text())
    p = raw["parameters"]
    sc = scene_files.load("rocker")
    got = dynacam.characteristics(sc.options, sc.parameters)
    g = {**p, "beta_0": 0.0}
    i_y = _ratio_exact(p["beta_m"] / 2, (1, 0), _swing, _uniform, g=g)
    i_z = _ratio_exact(p["beta_m"] / 2, (0, 1), _swing, _uniform, g=g)
    h_1 = p["h_m"] / p["beta_m"]
    C = h_1**2 / p["k"] + i_y**2 / p["c_y"]
    M = (p["J"] * h_1**2 / p["k"] ** 2 + p["m_y"] * i_y**2 / p["c_y"] ** 2) / C**2
    c_c = 1 / (1 / p["c_x"] + i_z**2 / p["c_z"])
    m = p["m_x"] + p["m_z"] * (c_c * i_z / p["c_z"]) ** 2
    want = {"tau": 2 * math.pi * math.sqrt(m / c_c) * p["omega_s"] / p["beta_m"], "Fa": c_c * C,
            "Fv": m / M}
    for key, value in want.items():
        assert got[key] == pytest.approx(value, rel=1e-6), key


def test_a_rocker_with_a_long_arm_has_the_characteristics_of_the_translating_follower():
    """tau, Fa, Fv (4.3)-(5.52) of App. 7's spring-held follower as a rocker on a 1 km arm
    square to the line to the cam centre: the translating follower's to 1e-5 (measured 2e-6,
    going as 1/l_a; a 1 m arm's Fa differs by 2e-3); and the flat face's Fa is the
    torsion's alone, c_c (h_m/beta_m)^2/k (4.14) with c_tan = c_beta, the y deflection not
    reaching it."""
    from dataclasses import replace

    from camdyn.runtime.core.variants import Options
    from camdyn.runtime.targets.dynacam import characteristics

    base = load(TRANSLATING)
    p = dict(zip(base.parameter_names, base.parameter_vector()))
    opts = Options(roller="contact", spring=True)
    ref = characteristics(opts, p)
    for arm, tol in ((1000.0, 1e-5), (1.0, None)):
        got = characteristics(replace(opts, rocker=True),
                              {**p, "l_a": arm, "d_p": math.hypot(arm, p["R_b"])})
        if tol is None:
            assert abs(got["Fa"] / ref["Fa"] - 1) > 1e-3
        for key in ("tau", "Fa", "Fv") if tol else ():
            assert got[key] == pytest.approx(ref[key], rel=tol), key
    flat = characteristics(replace(opts, flat_face=True), p)
    c_c = 1 / (1 / p["c_x"] + 1 / p["c_z"])
    assert flat["Fa"] == pytest.approx(c_c * (p["h_m"] / p["beta_m"]) ** 2 / p["k"], rel=1e-12)
    assert flat["tau"] == pytest.approx(ref["tau"], rel=1e-12)


def test_ratios_at_the_rise_start():
    """At the rise start the cam is a circle there: i_y = 0, and the arm, not square to the
    line to the cam centre, makes i_z = 1/cos of the angle between them (the law of cosines
    in the triangle cam centre, pivot, roller): 1e-12."""
    g = GEOMETRY
    out = _outputs(ROCKER, GEOMETRY, np.array([0.0]))
    cos_gamma = (g["R_b"] ** 2 + g["l_a"] ** 2 - g["d_p"] ** 2) / (2 * g["R_b"] * g["l_a"])
    assert abs(out["tan_alpha"][0]) < 1e-12
    assert out["i_z"][0] == pytest.approx(1.0 / math.sqrt(1.0 - cos_gamma**2), rel=1e-12)


def test_a_flat_face_pivoted_far_away_is_the_translating_flat_face():
    """A flat face on an arm pivoted 10 km from the cam centre along the face, its motion
    reduced to the arc at 10 km: over a rise and a dwell of App. 7's spring-held follower the
    contact force, U and the cam torque follow the translating flat face's to 2e-5 of their
    largest values (measured 7e-6, going as 1/l_a: the face's normal turns with the arm, so
    it sees the cam turn at 1 - h'/l_a of its speed; a pivot 100 m away leaves 7e-4)."""
    base = load(FLAT)
    pv, names = base.parameter_vector(), base.parameter_names
    t_m = pv[names.index("beta_m")] / pv[names.index("omega_s")]
    R_b = pv[names.index("R_b")]
    T = np.linspace(0.0, 2.5 * t_m, 400)

    def run(name, p):
        return Simulator(name, 2.5 * t_m, "dp54", rtol=1e-10).run(p).sample(T)

    ref = run(FLAT, {})
    for arm, tol in ((1e4, 2e-5), (100.0, None)):
        got = run(FLAT_ROCKER, {"l_a": arm, "d_p": math.hypot(arm, R_b), "f_f": 0.0})
        worst = max(np.abs(ref[k] - got[k]).max() / np.abs(ref[k]).max() for k in ("Fx", "U", "torque"))
        assert worst <= tol if tol else worst > 1e-4, (arm, worst)


def test_a_long_arm_square_to_the_cam_centre_is_the_translating_follower():
    """A rocker whose 1 km arm leaves the roller square to the line to the cam centre: over a
    rise and a dwell (App. 7's spring-held follower, the default parameters) the contact force,
    the positional error U and the cam torque follow the translating DYNACAM's to 2e-5 of
    their largest value (measured 6e-6; an arm of 1 m leaves 6e-3: the difference goes as
    1/l_a, as the arc's sag over the stroke, h_m^2/(2 l_a), does)."""
    base = load(TRANSLATING)
    t_m = base.parameter_vector()[base.parameter_names.index("beta_m")] / \
        base.parameter_vector()[base.parameter_names.index("omega_s")]
    R_b = base.parameter_vector()[base.parameter_names.index("R_b")]
    arm = {"l_a": 1000.0, "d_p": math.hypot(1000.0, R_b)}
    T = np.linspace(0.0, 2.5 * t_m, 400)
    runs = [Simulator(name, 2.5 * t_m, "dp54", rtol=1e-10).run(p).sample(T)
            for name, p in ((TRANSLATING, {}), (ROCKER, arm))]
    for key in ("Fx", "U", "torque"):
        a, b = runs[0][key], runs[1][key]
        assert np.abs(a - b).max() <= 2e-5 * np.abs(a).max(), key


@pytest.mark.parametrize("options, words", [
    ({"rocker": True, "cam": "axial"},
     'option rocker=true with cam="axial": a rocker is derived for a radial cam'),
    ({"rocker": True, "cam_friction": True},
     "option rocker=true with cam_friction=true: the friction on the cam"),
    ({"flat_face": True, "rocker": True, "cam_friction": True},
     "option flat_face=true with cam_friction=true: the friction on the cam"),
    ({"flat_face": True, "roller": "groove"},
     'option flat_face=true with roller="groove": a flat face cannot run in a groove')])
def test_a_follower_is_refused_where_it_is_not_derived(options, words):
    """Both the declaration and the run time's options (from the catalog) refuse the pairs
    no variant has, in the same words."""
    from camdyn.derive.models import dynacam
    from camdyn.runtime.core import variants

    for cls in (dynacam.Options, variants.Options):
        with pytest.raises(ValueError, match=words):
            cls(**options)


def test_the_rocker_scene_runs_and_an_arm_that_cannot_reach_is_refused(tmp_path):
    """runtime/scenes/rocker.toml (README's rocker) runs through `camdyn simulate`, the rocker
    an option of the scene; an arm too short for its pivot to reach the base pitch circle is
    refused in one line naming the three lengths and the rule, before anything runs."""
    import subprocess
    import sys
    from importlib import resources

    ok = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "simulate", "rocker", "--json"],
                        capture_output=True, text=True, timeout=300)
    assert ok.returncode == 0, ok.stderr
    assert json.loads(ok.stdout)["variant"] == ROCKER
    text = resources.files("camdyn.runtime.scenes").joinpath("rocker.toml").read_text()
    bad = tmp_path / "short_arm.toml"
    bad.write_text(text.replace("l_a = 0.08 ", "l_a = 0.01 "))
    out = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "simulate", str(bad)],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode != 0
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and "l_a = 0.01 m" in lines[0] and "d_p = 0.1 m" in lines[0] \
        and "R_b = 0.048 m" in lines[0] and "|d_p - l_a| < R_b < d_p + l_a" in lines[0]


def test_a_flat_face_is_the_roller_on_a_shaft_rigid_sideways():
    """A flat face square to the follower's motion feels no sideways shift of the cam (i_y =
    0): over a rise and a dwell of App. 7's spring-held follower its shaft's tangential
    deflection y stays exactly 0, and the cam angle, z, x, the contact force, the torque and
    the speed variation are those of the translating roller on a shaft that cannot deflect
    sideways (shaft_y = false), both at rtol 1e-10, to 1e-8 of their largest values (measured
    3e-11; the runs step differently, y counting in the flat face's error norm); the roller
    on the flexible shaft differs by 0.2 in Fx, so the comparison can tell."""
    base = load(TRANSLATING)
    pv, names = base.parameter_vector(), base.parameter_names
    t_m = pv[names.index("beta_m")] / pv[names.index("omega_s")]
    T = np.linspace(0.0, 2.5 * t_m, 400)
    flat, rigid, roller = (Simulator(name, 2.5 * t_m, "dp54", rtol=1e-10).run({}).sample(T)
                           for name in (FLAT, TRANSLATING.replace("_shafty", ""), TRANSLATING))
    assert not np.any(flat["y"]) and not np.any(flat["yd"])
    for key in ("beta", "z", "x", "Fx", "torque", "speed_var", "U"):
        scale = np.abs(rigid[key]).max()
        assert np.abs(flat[key] - rigid[key]).max() <= 1e-8 * scale, key
    assert max(np.abs(roller[k] - rigid[k]).max() / np.abs(rigid[k]).max()
               for k in ("Fx", "torque")) > 0.1


def test_a_flat_faced_rocker_scene_runs_and_a_face_that_cannot_touch_is_refused(tmp_path):
    """The rocker scene with ``flat_face = true``, the base circle 40 mm and the face on the
    pivot's line (f_f = 0): `camdyn simulate` runs the flat-faced rocker variant; a face
    80 mm behind the pivot, which
    cannot touch the base circle (|R_b - f_f| < d_p), is refused in one line naming the three
    lengths, before anything runs."""
    import subprocess
    import sys
    from importlib import resources

    text = resources.files("camdyn.runtime.scenes").joinpath("rocker.toml").read_text()
    text = text.replace("rocker = true", "rocker = true\nflat_face = true")
    text = text.replace("R_b = 0.048 ", "R_b = 0.040 ").replace("l_a = 0.08 ", "l_a = 0.08\nf_f = 0.0 ")
    good = tmp_path / "flat_rocker.toml"
    good.write_text(text)
    ok = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "simulate", str(good), "--json"],
                        capture_output=True, text=True, timeout=300)
    assert ok.returncode == 0, ok.stderr
    summary = json.loads(ok.stdout)
    assert summary["variant"] == FLAT_ROCKER
    bad = tmp_path / "far_face.toml"
    bad.write_text(text.replace("f_f = 0.0 ", "f_f = -0.08 "))
    out = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "simulate", str(bad)],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode != 0
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and "f_f = -0.08 m" in lines[0] and "d_p = 0.1 m" in lines[0] \
        and "R_b = 0.04 m" in lines[0] and "|R_b - f_f| < d_p" in lines[0]


def test_the_one_and_two_dof_models_take_the_rocker_of_a_scene():
    """`camdyn simulate rocker --model auto` runs the rocker in CAMSHAFT-2, CAMSHAFT-1 and the
    one-DOF model (the chain of sec. 8.2): their tau, Fa, Fv are the rocker's own, the shaft
    taken to the contact with its ratios (to 1e-12: the same numbers), not the translating
    follower's (4.3)-(5.52) of the same parameters (i_y 9 % lower than tan alpha_me, so Fa
    1.9 % and Fv 3.3 % lower; asserted above 1 %); and the criterion c_z'/c_x of sec. 8.2.4
    compares c_x with the shaft's stiffness as the contact feels it, c_z/i_z^2 (i_z = 1.0023
    here: 1e-12 tells it from c_z)."""
    from dataclasses import replace

    from camdyn.runtime.studies import least_model
    from camdyn.runtime.targets import dynacam, scene_files

    sc = scene_files.load("rocker")
    ch = dynacam.characteristics(sc.options, sc.parameters)
    translating = dynacam.characteristics(replace(sc.options, rocker=False), sc.parameters)
    by_key = {c.key: c for c in least_model.chain(sc)}
    for key, names in (("camshaft2", ("tau", "Fa", "Fv")), ("camshaft1", ("tau", "Fa")),
                       ("one_dof", ("tau",))):
        for name in names:
            assert by_key[key].params[name] == pytest.approx(ch[name], rel=1e-12), (key, name)
    assert abs(ch["Fa"] / translating["Fa"] - 1) > 1e-2 and abs(ch["Fv"] / translating["Fv"] - 1) > 1e-2
    crit = {c.name: c.value for c in by_key["camshaft2"].criteria}
    p = sc.parameters
    assert crit["c_z'/c_x"] == pytest.approx(p["c_z"] / ch["i_z_me"] ** 2 / p["c_x"], rel=1e-12)
