"""The campaign (tests/test_campaign.py) over the cam itself: `camdyn profile` for every
follower, law and law file, with the contact stress and the STEP solid, and `camdyn design`
with a rocker, the follower spring, the flywheel and the whole turn.

`camdyn profile` ends with 1 after its report when one of its checks fails (the follower
leaves the cam, a cusp, an undercut, the pressure angle): the judge takes that as an answer
whose JSON says "ok": false and whose stderr holds the checks' warnings only.  The findings of
the review of these commands are drawn as explicit inputs with the verdict they now have.
"""
from __future__ import annotations

import json

import pytest
from hypothesis import given, strategies as st

from .test_campaign import (LAWS, LONG, QUICK, VALUE, Opt, campaign_session, choice,  # noqa: F401
                            command, few, flag, judge, law_choice, law_folder, laws_in, many,
                            num, run, with_out)

FOLLOWERS = ["translating-roller", "translating-flat", "oscillating-roller", "oscillating-flat"]
SWING = choice(["45", "18", "30", "10"], ["60", "89", "90", "44.9", "0", "-10", "nan", "1e300"])
FLAT_SWING = choice(["30", "18", "10"], ["45", "60", "89", "90", "44.9", "0", "nan", "1e300"])
"""An oscillating flat face's arm must turn slower than the cam: swing < beta/2 = 45 deg over
the cycloid's 90 deg rise."""
GEOMETRY = {
    "translating-roller": {"--stroke": num(0.02, 0.01), "--base-radius": num(0.04),
                           "--roller-radius": num(0.01)},
    "translating-flat": {"--stroke": num(0.02, 0.01), "--base-radius": num(0.04)},
    "oscillating-roller": {"--swing": SWING, "--pivot-distance": num(0.1),
                           "--arm-length": num(0.08), "--base-radius": num(0.04),
                           "--roller-radius": num(0.008)},
    "oscillating-flat": {"--swing": FLAT_SWING, "--pivot-distance": num(0.1),
                         "--base-radius": num(0.04)},
}
"""Each follower's geometry: its ordinary values, or VALUE's absurd ones."""

PROFILE_ANGLES = choice(["90,90,90,90", "120,60,100,80", "45,135,90,90", "100,100,100,60"],
                        ["0,180,90,90", "a", "", "360,0,0,0", "1e-300,180,90,90",
                         "nan,90,90,90", "90,90,90", "179,1,179,1", "100,100,100,100"])
MATERIALS = choice(["steel,steel", "steel,brass", "210e9:0.3,steel", "210e9:0.3,110e9:0.34",
                    "aluminium,phosphor-bronze", "cast-iron,stainless-steel"],
                   ["x:y", "bronze", "steel", "", "nan:0.3,steel", "1e300:0.3,steel",
                    "210e9:0.5,steel", "210e9:-1,steel", "0:0.3,steel", "steel,steel,steel",
                    "1e-300:0.3,1e-300:0.3", "inf:0.3,steel", "steel,"])
CROWN = Opt(st.sampled_from(["0.1", "0.05"]),
            st.one_of(st.sampled_from(["1e-9", "1e-300", "1e300", "0", "-1", "nan", "inf"]), VALUE))
SCENES = choice(["spring_loaded", "rocker", "fig8_1a"],
                ["indexing", "default", "nope", "beam_paper", "@blend.toml", "@empty.toml",
                 "@folder.csv", ""])

PROFILE_OPTIONS = {
    "--offset": num(0.005, 0), "--face-offset": num(0, 0.01),
    "--law": law_choice(), "--law-parameter": num(0.1, 0.3),
    "--return-law": law_choice(["cycloidal", "uniform", "simple-harmonic", "parabolic"]),
    "--return-law-parameter": num(0.1), "--angles": PROFILE_ANGLES, "--groove": flag(),
    "--max-pressure-angle": num(30, 45), "--cutter-radius": num(0.005, 0.02),
    "--arcs": Opt(st.sampled_from(["1e-4", "1e-6"]), st.sampled_from(["1e-9", "1e-10", "2", "0",
                                                                      "nan", "-1"])),
    "--json": flag(), "--step": flag(),        # a plate without its thickness: refused
}
CONTACT = {
    "--contact-force": num(100, 500), "--speed": num(300, 100),
    "--follower-mass": num(1, 0.0039), "--spring-rate": num(1000, 6.4),
    "--spring-preload": num(50, 0.8), "--roller-width": num(0.01), "--cam-width": num(0.01),
    "--materials": MATERIALS, "--crown-radius": CROWN, "--allowable-stress": num(1e9, 2e9),
}
FORCE = {"--contact-force": num(100, 500),
         "--speed": num(300, 100)}
SOLID = {"--cam-width": num(0.01, 0.005), "--bore": num(0.01, 0.02)}
POINTS = choice(["1", "2"], ["0", "1001", "x", "1.5", "-1", ""])


def profile_argv(quick=False):
    """A follower (or none, or a word), its geometry, up to three of the profile's options,
    and either nothing more, the contact stress under a force (given, a speed's, a scene
    run's), or the STEP solid."""
    def one(follower):
        head = ["profile"] + ([] if follower == "" else ["--follower", follower])
        geometry = GEOMETRY.get(follower, {"--stroke": num(0.02), "--base-radius": num(0.04)})
        plain = command(head, {**geometry, "--points-per-degree": POINTS}, PROFILE_OPTIONS)
        stress = command(head, {**geometry, "--points-per-degree": POINTS,
                                "--contact-force": num(100, 500),
                                "--roller-width" if "roller" in follower else "--cam-width":
                                    num(0.01)}, {**CONTACT, **PROFILE_OPTIONS}, most=3)
        speed = command(head, {**geometry, "--points-per-degree": POINTS, "--speed": num(300),
                               "--follower-mass": num(1, 0.0039), "--spring-rate": num(1000),
                               "--spring-preload": num(50), "--roller-width": num(0.01),
                               "--cam-width": num(0.01)}, CONTACT, most=2)
        scene = command(["profile"], {"--contact-force-from": SCENES, "--points-per-degree": POINTS,
                               "--roller-radius": num(0.008), "--roller-width": num(0.01)},
                        {"--base-radius": num(0.04), "--law": law_choice()}, most=1)
        solid = command(head, {**geometry, "--points-per-degree": POINTS, "--step": flag(),
                               "--cam-width": num(0.01)}, {**SOLID, "--arcs": num(1e-5)}, most=1)
        return st.one_of(plain, plain, stress, speed, scene, solid)
    return st.sampled_from(FOLLOWERS * 2 + ["rocker", ""]).flatmap(one)


def profile_case(argv, law_folder, out):
    argv = with_out(laws_in(argv, law_folder), out)
    return judge(argv, *run(argv))


@few(25)
@given(argv=profile_argv(True))
def test_quick_campaign_over_profile(argv, law_folder, tmp_path_factory):
    profile_case(argv, law_folder, tmp_path_factory.mktemp("p"))


@pytest.mark.slow
@many(150)
@given(argv=profile_argv())
def test_campaign_over_profile(argv, law_folder, tmp_path_factory):
    profile_case(argv, law_folder, tmp_path_factory.mktemp("p"))


# -- camdyn design ----------------------------------------------------------------------------

DESIGN_ANGLES = choice(["120,60,100,80", "90,90,90,90", "90,60,120,90"], [
    "120,60,100", "a,b,c,d", "", "120,60,100,90", "0,120,140,100", "120,60,0,180",
    "120,-10,150,100", "nan,120,120,120", "inf,120,120,120", "120,60,100,80,0",
    "1e-300,120,120,120", "359,0.5,0.25,0.25"])
CAM_ANGLE = Opt(st.sampled_from(["2.0944", "120deg", "1.5708", "90deg"]),
                st.one_of(st.sampled_from(["110deg", "0deg", "400deg", "nan", "-1", "1e300deg",
                                           "deg", "120 deg", "0"]), VALUE))
TIMING = [{"--rise-time": num(0.1, 0.05)}, {"--speed": num(300, 150), "--cam-angle": CAM_ANGLE},
          {"--speed": num(300, 150), "--angles": DESIGN_ANGLES}]
"""How the rise's time is given: directly, by the speed and the rise's angle, or by the speed
and the whole turn."""
TRANSLATING = [{"--mass": num(1, 2), "--stiffness": num(1e5, 1e6)}, {"--tau": num(0.15, 0.3)}]
SHAFT = [{"--fa": num(0.5, 0)}, {"--c-tan": num(1e5), "--pitch-radius": num(0.06)},
         {"--c-tan": num(1e5), "--tan-alpha-me": num(0.2)}]
DESIGN_OPTIONS = {
    "--accuracy": num(1e-4, 20e-6), "--residual-acceleration": num(10),
    "--law": law_choice(), "--theta": num(0.1),
    "--spring-margin": Opt(st.sampled_from(["0.3", "0", "10"]), st.one_of(VALUE, st.just("11"))),
    "--spring-rate": num(1000), "--spring-mass": num(0.02),
    "--speed-fluctuation": Opt(st.sampled_from(["0.05"]), st.one_of(VALUE, st.just("1"))),
    "--json": flag(), "--common-shaft": flag(), "--ratio": num(2),
}
ROCKER = {"--swing": num(18, 45), "--arm-length": num(0.08),
          "--arm-inertia": num(0.0039), "--arm-stiffness": num(12800, 1600)}


def design_argv(quick=False):
    """A translating follower (stroke, mass and stiffness or tau) or a rocker, the rise's
    timing, the shaft, the requirement, and up to three more (the spring, the flywheel)."""
    check = st.sampled_from([["--no-check"]] * (3 if quick else 1) + [[]])

    def one(follower, timing, shaft):
        required = {**follower, **timing, **shaft, "--accuracy": num(1e-4, 20e-6)}
        return command(check.map(lambda c: ["design", "--quiet", *c]), required,
                       {k: v for k, v in DESIGN_OPTIONS.items() if k not in required})
    translating = [{"--stroke": num(0.02, 0.05), **t} for t in TRANSLATING]
    return st.tuples(st.sampled_from(translating * 2 + [ROCKER]), st.sampled_from(TIMING),
                     st.sampled_from(SHAFT)).flatmap(lambda a: one(*a))


@few(20)
@given(argv=design_argv(True))
def test_quick_campaign_over_design(argv, law_folder, tmp_path_factory):
    argv = with_out(laws_in(argv, law_folder), tmp_path_factory.mktemp("d"))
    judge(argv, *run(argv))


@pytest.mark.slow
@many(100)
@given(argv=design_argv())
def test_campaign_over_design(argv, law_folder, tmp_path_factory):
    argv = with_out(laws_in(argv, law_folder), tmp_path_factory.mktemp("d"))
    judge(argv, *run(argv))


# -- the findings: each input with the verdict it now has -------------------------------------

OSC_FLAT = ["profile", "--follower", "oscillating-flat", "--pivot-distance", "0.1",
            "--base-radius", "0.04", "--points-per-degree", "2"]
DESIGN_ROCKER = ["design", "--swing", "18", "--arm-length", "0.08", "--arm-inertia", "0.0039",
                 "--arm-stiffness", "12800", "--speed", "300", "--fa", "0", "--accuracy",
                 "20e-6", "--spring-margin", "0.3", "--spring-rate", "1000", "--quiet"]

FINDINGS = {
    # a NaN traceback: the face's arm as fast as the cam (psi' = 1), refused with its bound
    "flat face arm as fast as the cam": ([*OSC_FLAT, "--swing", "60"], "refused",
                                         "swing < 45 deg"),
    # a gmsh traceback: the STEP plate of a cusping profile, refused before the CAD kernel
    # (the other files written, the cusp failing its check)
    "STEP plate of a cusping profile": ([*OSC_FLAT, "--swing", "10", "--step", "--cam-width",
                                         "0.01"], "checks failed", "cusp"),
    # a brentq traceback: the crowned roller of 1 nm crown radius
    "crown radius 1e-9": (["profile", "--contact-force", "100", "--stroke", "0.02",
                           "--base-radius", "0.04", "--roller-radius", "0.01", "--roller-width",
                           "0.01", "--crown-radius", "1e-9", "--points-per-degree", "1"],
                          "answered", "not small beside the radii"),
    # printed ok: a flat face under the uniform law's velocity jumps fails its cusp check
    "flat face under the uniform law": (["profile", "--follower", "translating-flat", "--law",
                                         "uniform", "--stroke", "0.02", "--base-radius", "0.04",
                                         "--points-per-degree", "1"], "checks failed", "cusp"),
    # a failed check is status 1 (the pressure angle beyond its limit)
    "profile status 1 on FAIL": (["profile", "--stroke", "0.015", "--base-radius", "0.008",
                                  "--roller-radius", "0.004", "--angles", "45,135,90,90",
                                  "--points-per-degree", "1"], "checks failed",
                                 "pressure angle"),
    # the rocker's preload over the whole turn binds in the return (the rise alone missed it)
    "design rocker preload over the whole turn": ([*DESIGN_ROCKER, "--angles", "120,60,100,80"],
                                                  "answered", "binding: the dynamic motion in "
                                                              "the return"),
    "design clash of --cam-angle and --angles": ([*DESIGN_ROCKER, "--cam-angle", "110deg",
                                                  "--angles", "120,60,100,80"], "refused",
                                                 "differs from --cam-angle"),
    "design clash of --rise-time and --angles": ([*DESIGN_ROCKER, "--rise-time", "0.05",
                                                  "--angles", "120,60,100,80"], "refused",
                                                 "differs from --rise-time"),
}


@pytest.mark.parametrize("name", sorted(FINDINGS))
def test_the_cam_findings_have_their_verdicts(name, tmp_path):
    """Each finding's exact input through the judge: the verdict it has now (refused in one
    line, answered, or answered with the failed check named), and the words that say why, on
    stderr or stdout."""
    argv, verdict, words = FINDINGS[name]
    argv = with_out(argv, tmp_path)
    code, out, err = run(argv)
    assert judge(argv, code, out, err, feature="findings") == verdict, (code, out, err)
    assert words in out + err, (words, out, err)
    if argv[0] == "profile" and verdict == "checks failed":
        for kind in ("csv", "dxf", "png", "json"):          # written all the same
            assert (tmp_path / f"cam.{kind}").stat().st_size > 0
        assert not (tmp_path / "cam.step").exists()


def test_a_failed_check_with_json_is_judged_by_its_ok():
    """The judge's rule for `camdyn profile`'s status 1: the JSON's "ok" false and stderr the
    warnings only; an "ok": true with status 1, or another line on stderr, is a finding."""
    from .test_campaign import _verdict

    argv = ["profile", "--json"]
    warn = "camdyn profile: warning: cusp: ...\n"
    assert _verdict(argv, 1, json.dumps({"ok": False}), warn)[0] == "checks failed"
    assert _verdict(argv, 1, json.dumps({"ok": True}), warn)[0] == "wrong answer"
    assert _verdict(argv, 1, json.dumps({"ok": False}), warn + "oops\n")[0] == "wrong answer"
    assert _verdict(argv, 1, json.dumps({"ok": False, "x": float("nan")}), warn)[0] == \
        "wrong answer"
    assert _verdict(["profile"], 1, "ok pressure angle\n", warn)[0] == "wrong answer"
    assert _verdict(["simulate", "--json"], 1, "{}", "camdyn simulate: run failed: x\n")[0] == \
        "wrong answer"
