"""The contact stress along a cam from a dynamic run of a DYNACAM scene
(runtime/targets/scene_force.py, `camdyn profile --contact-force-from SCENE`).

Independent reference: a stiff follower (linkage and shafts stiff, tau = 0.02 for the linkage)
driven at constant speed follows its cam almost rigidly, so the force its run gives along the
last full turn is the kinetostatic force M omega^2 s'' + c_s s + F_0 of runtime/cam/load.py on
the same cam, computed without any run.  What remains between them is the linkage's static
compliance (c_s F/c_x, 2e-3 N) and its residual vibration; measured relative differences
1e-4 (largest force), 3.2e-4 (least), 4.7e-5 (Hertz's peak), the peak's angle 0.002 deg
apart; asserted 1e-3 and 0.01 deg.
"""
import json
import math

import pytest

from camdyn.runtime.cli import main

SCENE = """\
kind = "dynacam"
title = "stiff follower on a spring"
law = "cycloidal"

[options]
roller = "contact"
spring = true

[parameters]
h_m = 0.01
beta_m = 1.0
R_b = 0.06
omega_s = 20.0
J = 1e6
k = 1e9
q_b = 0.2
m_x = 1.0
c_x = 3.9e7
q_x = 0.2
m_y = 0.1
c_y = 1e9
q_y = 0.2
m_z = 0.1
c_z = 1e9
q_z = 0.2
F_0 = 50.0
c_s = 1000.0

[run]
T_start = -0.1
T_end = {T_end}
rtol = 1e-8

[turn]
upper_dwell = 60
return = 80
"""
OMEGA, R_B, R_R = 20.0, 0.06, 0.01


def _scene(tmp_path, T_end=6.5):
    path = tmp_path / "stiff.toml"
    path.write_text(SCENE.format(T_end=T_end))
    return path


def _json(capsys, argv, status=0):
    assert main(argv) == status
    return json.loads(capsys.readouterr().out)


def test_a_stiff_follower_gives_the_kinetostatic_stress(tmp_path, capsys):
    dyn = _json(capsys, ["profile", "--contact-force-from", str(_scene(tmp_path)),
                         "--roller-radius", str(R_R), "--roller-width", "0.01",
                         "--out", str(tmp_path / "d"), "--json"])
    rise = math.degrees(1.0)
    kin = _json(capsys, ["profile", "--base-radius", str(R_B - R_R), "--roller-radius", str(R_R),
                         "--stroke", "0.01", "--angles", f"{rise!r},60,80,{300 - 80 - rise!r}",
                         "--speed", repr(OMEGA * 60 / (2 * math.pi)), "--follower-mass", "1",
                         "--spring-rate", "1000", "--spring-preload", "50",
                         "--roller-width", "0.01", "--out", str(tmp_path / "k"), "--json"])
    # the scene's cam is the profile's: a translating roller on the prime circle R_b
    for key in ("max_abs_pressure_angle_deg", "min_rho_profile", "min_rho_pitch"):
        assert dyn[key] == pytest.approx(kin[key], rel=1e-12), key
    a, b = dyn["contact_stress"], kin["contact_stress"]
    assert "run of stiff follower on a spring" in a["contact_force"]
    for key in ("contact_force_max", "contact_force_min", "hertz_stress_max"):
        assert a[key] == pytest.approx(b[key], rel=1e-3), key
        assert 0.0 < a[key + "_error"] < 1e-4 * a[key], key
    assert abs(a["hertz_stress_max_angle_deg"] - b["hertz_stress_max_angle_deg"]) < 0.01
    # the inertia force is a fair part of it: the check would see a wrong cam angle
    assert b["contact_force_max"] - (50.0 + 1000.0 * 0.01) > 15.0
    assert dyn["contact_force_from"] == str(tmp_path / "stiff.toml")
    assert not a["warnings"]


def test_a_follower_that_leaves_the_cam_is_named(tmp_path, capsys):
    """At 35 rad/s the inertia force over the rise's deceleration exceeds what the spring
    holds: the run's roller lifts where the kinetostatic force first falls below zero (36.347
    deg by the kinetostatic check; the run's first free span starts 0.014 deg from it, asserted
    0.1 deg), is thrown off for longer than that force stays negative (the run's span ends at
    63.4 deg, the kinetostatic one at 49.2 deg), and its force is zero, never negative, there."""
    text = SCENE.format(T_end=6.5).replace("omega_s = 20.0", "omega_s = 35.0")
    (tmp_path / "fast.toml").write_text(text)
    dyn = _json(capsys, ["profile", "--contact-force-from", str(tmp_path / "fast.toml"),
                         "--roller-radius", str(R_R), "--roller-width", "0.01",
                         "--out", str(tmp_path / "f"), "--json"], status=1)
    rise = math.degrees(1.0)
    kin = _json(capsys, ["profile", "--base-radius", str(R_B - R_R), "--roller-radius", str(R_R),
                         "--stroke", "0.01", "--angles", f"{rise!r},60,80,{300 - 80 - rise!r}",
                         "--speed", repr(35.0 * 60 / (2 * math.pi)), "--follower-mass", "1",
                         "--spring-rate", "1000", "--spring-preload", "50",
                         "--roller-width", "0.01", "--out", str(tmp_path / "k"), "--json"],
                status=1)           # the follower leaves the cam: a failed check

    def kept(out):
        return [c for c in out["contact_stress"]["checks"] if c["check"] == "contact kept"][0]
    a, b = kept(dyn), kept(kin)
    assert not a["ok"] and "follower leaves the cam: in a run of" in a["message"]
    assert dyn["contact_stress"]["contact_force_min"] == 0.0
    (lo, hi), (klo, khi) = a["intervals_deg"][0], b["intervals_deg"][0]
    assert abs(lo - klo) < 0.1
    assert hi > khi + 5.0 and hi < 90.0


@pytest.mark.parametrize("argv,words", [
    (["--contact-force-from", "{scene}", "--stroke", "0.01", "--roller-radius", "0.01"],
     ["--stroke", "comes from the scene"]),
    (["--contact-force-from", "{scene}"], ["--roller-radius"]),
    (["--contact-force-from", "{scene}", "--roller-radius", "0.07"], ["roller-radius", "0.06"]),
    (["--contact-force-from", "{short}", "--roller-radius", "0.01"],
     ["run.T_end >= 6.183", "full turn"]),
    (["--contact-force-from", "spring_loaded", "--roller-radius", "0.01"], ["[turn]"]),
    (["--contact-force-from", "default", "--roller-radius", "0.01"], ["DYNACAM"]),
    (["--contact-force-from", "{scene}", "--roller-radius", "0.01", "--contact-force", "5"],
     ["one way"]),
    (["--stroke", "0.01"], ["--base-radius"]),
    (["--contact-force-from", "{bilateral}", "--roller-radius", "0.01"],
     ["held on both sides", "bilateral", "contact"]),
])
def test_refused_in_one_line(tmp_path, capsys, argv, words):
    scene = _scene(tmp_path)
    (tmp_path / "short.toml").write_text(SCENE.format(T_end=6.0))
    # the built-in variant with a bilateral roller has no spring
    (tmp_path / "bilateral.toml").write_text(
        SCENE.format(T_end=6.5).replace('roller = "contact"\nspring = true', 'roller = "bilateral"')
        .replace("F_0 = 50.0\n", "").replace("c_s = 1000.0\n", ""))
    argv = [a.format(scene=scene, short=tmp_path / "short.toml",
                     bilateral=tmp_path / "bilateral.toml") for a in argv]
    rc = main(["profile", *argv, "--out", str(tmp_path / "o")])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and err[0].startswith("camdyn profile: error:")
    for w in words:
        assert w in err[0]
    assert not (tmp_path / "o").exists()
