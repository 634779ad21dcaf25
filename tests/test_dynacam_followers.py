"""DYNACAM's followers beyond the translating roller (derive/models/dynacam.py).

The rocker (option ``rocker``): an oscillating roller follower reduced to the roller centre's
arc (thesis sec. 2.4), the shaft's deflections reaching it as (6.22) has them reach the
translating follower, through ratios of the rocker's geometry (_rocker).  The flat face
(option ``flat_face``): a sideways shift of the cam does not move it.

References independent of the generated code and of _rocker's algebra:

* the rocker of runtime/cam/follower.py (its own frame: the cam turning clockwise, the pivot
  at (a, 0)), moved against a cam shifted by a small vector; how far the roller must swing to
  stay on the pitch curve is solved exactly there (SciPy's fsolve on the contact condition);
* the translating DYNACAM, which a rocker with a 1 km arm square to the line to the cam
  centre must reproduce.
"""
import json
import math
import warnings

import numpy as np
import pytest
from scipy.optimize import fsolve

from camdyn.runtime.cam.follower import OscillatingRoller
from camdyn.runtime.core.compiled import load
from camdyn.runtime.core.laws import choose
from camdyn.runtime.core.simulator import Simulator
from camdyn.runtime.engine import driver

ROCKER = "dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring_rocker"
TRANSLATING = "dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring"
FLAT = "dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring_flat"
GEOMETRY = {"R_b": 0.05, "d_p": 0.12, "l_a": 0.09, "h_m": 0.02, "beta_m": 1.2, "beta_0": 0.0}


def _h(beta, h_m, beta_m):
    """The cycloidal rise (A.2.8) over [0, beta_m], h_m high."""
    B = beta / beta_m
    return h_m * (B - math.sin(2 * math.pi * B) / (2 * math.pi))


def _swing(beta, shift):
    """The roller centre's displacement along its arc when the cam is shifted by (y, z) at
    cam angle beta, in follower.py's frame: z along the line from the cam centre to the
    roller at the rise start, y square to it, opposite to the cam surface's motion there (so
    (6.22)'s signs), the cam moved by y e_y - z e_z."""
    g = GEOMETRY
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
    psi_b = _h(beta, g["h_m"], g["beta_m"]) / g["l_a"]

    def contact(u):
        psi, b1 = u
        a = -(beta - b1)                      # the cam turns clockwise
        rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        return centre(psi) - D - rot @ centre(_h(b1, g["h_m"], g["beta_m"]) / g["l_a"])

    with warnings.catch_warnings():
        # at 1e-14 fsolve says it cannot improve further: the solution is there to rounding
        warnings.simplefilter("ignore", RuntimeWarning)
        psi, _ = fsolve(contact, [psi_b, beta], xtol=1e-14)
    return (psi - psi_b) * g["l_a"]


def _ratio_exact(beta, unit):
    """-d(swing)/d(shift) along ``unit`` ((1, 0): y, (0, 1): z), by central differences of the
    exact swing over +-1e-6 m (the second order, the pitch curve's curvature, cancels)."""
    d = 1e-6
    up, down = (_swing(beta, (k * d * unit[0], k * d * unit[1])) for k in (1, -1))
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


def test_ratios_at_the_rise_start():
    """At the rise start the cam is a circle there: i_y = 0, and the arm, not square to the
    line to the cam centre, makes i_z = 1/cos of the angle between them (the law of cosines
    in the triangle cam centre, pivot, roller): 1e-12."""
    g = GEOMETRY
    out = _outputs(ROCKER, GEOMETRY, np.array([0.0]))
    cos_gamma = (g["R_b"] ** 2 + g["l_a"] ** 2 - g["d_p"] ** 2) / (2 * g["R_b"] * g["l_a"])
    assert abs(out["tan_alpha"][0]) < 1e-12
    assert out["i_z"][0] == pytest.approx(1.0 / math.sqrt(1.0 - cos_gamma**2), rel=1e-12)


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
    ({"flat_face": True, "rocker": True},
     "option flat_face=true with rocker=true: an oscillating flat face is not derived"),
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
