"""`camdyn profile`, the cam room and the law files: what an adversarial review found, each
now right, warned or refused in one line.

* An oscillating flat face whose arm turns as fast as the cam (psi' = 1) has no profile: its
  contact runs off to infinity along the face.  For the cycloid psi'max = 2 swing/beta, so
  the largest swing is beta/2 whatever the lengths; refused with that bound.
* A STEP plate of a profile that cusps is refused before the CAD kernel sees it (the other
  files written, status 1), and a solid the kernel refuses is one line.
* Hertz's elliptical contact (Johnson (4.37)-(4.39)) for every ratio of the relative
  curvatures, against the complete elliptic integrals at 40 digits (mpmath) solved by
  another root finder.
* Law files that cannot be read are one line naming the file on every command that takes
  --law.
* A failed check is status 1, the JSON still printed.
* A law whose velocity jumps fails the profile's curvature check, for every follower; one
  whose acceleration jumps warns where a speed's or a run's force is used; both found from
  the law, held to one-sided differences of the sampled lift.
"""
from __future__ import annotations

import contextlib
import io
import json
import math
from pathlib import Path

import numpy as np
import pytest

from camdyn.runtime.cam import step as step_module
from camdyn.runtime.cam.load import ContactLoad
from camdyn.runtime.cam.motion import RDFD
from camdyn.runtime.cam.profile import CamProfile
from camdyn.runtime.cam.stress import ContactSpec, _ellipticity, point_contact
from camdyn.runtime.cli import main
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.core.laws import NAMES, choose


def run(argv):
    """camdyn ``argv`` in this process: (status, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else 2
    return code, out.getvalue(), err.getvalue()


def refused(argv, status=2):
    """The one stderr line of a refused run (status, no traceback, nothing on stdout)."""
    code, out, err = run(argv)
    assert "Traceback" not in err, err
    lines = err.strip().splitlines()
    assert code == status and len(lines) == 1 and not out.strip(), (code, out, err)
    assert lines[0].startswith(f"camdyn {argv[0]}: error:"), lines[0]
    return lines[0]


# -- 1. an oscillating flat face whose arm outruns the cam -------------------------------

@pytest.mark.parametrize("pivot, base", [(0.1, 0.04), (0.3, 0.02)])
def test_a_flat_face_arm_as_fast_as_the_cam_is_refused_with_the_largest_swing(tmp_path,
                                                                             pivot, base):
    """Cycloid, H'max = 2 at T = 1/2: psi'max = 2 swing/beta_rise, so psi' < 1 needs swing
    < beta_rise/2 = 45 deg over a 90 deg rise, whatever the pivot distance and base radius
    (the face turns in the cam frame at 1 - psi', follower.py)."""
    line = refused(["profile", "--follower", "oscillating-flat", "--swing", "60",
                    "--pivot-distance", str(pivot), "--base-radius", str(base),
                    "--out", str(tmp_path)])
    assert "swing=60 deg" in line and "swing < 45 deg" in line
    assert "1.333 times" in line and "at cam angle 45.00 deg" in line   # 2 * 60/90 at T = 1/2
    with pytest.raises(CamdynInputError, match=r"swing < 45 deg"):
        CamProfile(follower="oscillating-flat", swing_deg=45.0, pivot_distance=pivot,
                   base_radius=base)


def test_a_flat_face_just_inside_the_bound_gives_finite_figures():
    """At swing 44 deg the face turns at 1 - 88/90 > 0 in the cam frame: every figure is a
    number (the cusp it has is named), none NaN.  The bound is the rise's beta/2: 60 deg over
    a 120 deg rise; the return turns the arm back, against the cam, and bounds nothing."""
    cam = CamProfile(follower="oscillating-flat", swing_deg=44.0, pivot_distance=0.1,
                     base_radius=0.04)
    out = cam.summary()
    assert not out["ok"] and any("cusp" in w for w in out["warnings"])
    for key in ("max_abs_pressure_angle_deg", "min_rho_profile", "face_width"):
        assert math.isfinite(out[key]) and math.isfinite(out[f"{key}_error"])
    CamProfile(follower="oscillating-flat", swing_deg=59.0, pivot_distance=0.1,
               base_radius=0.04, angles_deg=(120, 200, 20, 20))
    with pytest.raises(CamdynInputError, match=r"rise over 120 deg .* swing < 60 deg"):
        CamProfile(follower="oscillating-flat", swing_deg=61.0, pivot_distance=0.1,
                   base_radius=0.04, angles_deg=(120, 200, 20, 20))


# -- 2. a STEP plate of a profile that is no closed simple curve ------------------------

CUSPING = ["profile", "--follower", "oscillating-flat", "--swing", "10", "--pivot-distance",
           "0.1", "--base-radius", "0.04", "--step", "--cam-width", "0.01"]


def test_a_step_plate_of_a_cusping_profile_is_refused_and_the_rest_written(tmp_path,
                                                                          monkeypatch):
    pytest.importorskip("gmsh")

    def no_kernel():
        raise AssertionError("the CAD kernel was reached")
    monkeypatch.setattr(step_module, "_session", no_kernel)
    code, out, err = run([*CUSPING, "--out", str(tmp_path), "--json"])
    assert code == 1 and "Traceback" not in err
    js = json.loads(out)
    assert not js["ok"] and js["step"]["written"] is False and "step" not in js["files"]
    step_lines = [l for l in err.splitlines() if "cam.step" in l]
    assert len(step_lines) == 1 and "closed simple profile" in step_lines[0]
    assert "cusp" in step_lines[0]
    assert not (tmp_path / "cam.step").exists()
    for kind in ("csv", "dxf", "png", "json"):
        assert (tmp_path / f"cam.{kind}").stat().st_size > 0


def test_the_kernels_refusal_is_one_line(tmp_path, monkeypatch):
    """Whatever gmsh still raises (its bare Exception) is one warning line, status 1."""
    pytest.importorskip("gmsh")

    def broken(gmsh, arcs, thickness, bore):
        raise Exception("Curve loop is not closed")
    monkeypatch.setattr(step_module, "_plate", broken)
    code, out, err = run(["profile", "--stroke", "0.02", "--base-radius", "0.04",
                          "--roller-radius", "0.01", "--step", "--cam-width", "0.01",
                          "--points-per-degree", "2", "--out", str(tmp_path)])
    assert code == 1 and "Traceback" not in err
    lines = [l for l in err.splitlines() if "cam.step" in l]
    assert len(lines) == 1 and "Curve loop is not closed" in lines[0]
    assert not (tmp_path / "cam.step").exists() and (tmp_path / "cam.dxf").exists()
    cam = CamProfile(stroke=0.02, base_radius=0.04, roller_radius=0.01, points_per_degree=2)
    with pytest.raises(step_module.StepError, match="could not build"):
        step_module.write_step(cam, tmp_path / "api.step", 0.01)


# -- 3. Hertz's elliptical contact over the whole range of B/A ----------------------------

def _mp_ellipse(ratio, force, A, e_star):
    """b/a and p0 from Johnson (4.37)-(4.39) in K and E at 40 digits, b/a by the Anderson-
    Bjorck bracketing solver on a bracket found by scanning ln(b/a)."""
    import mpmath as mp

    mp.mp.dps = 40
    ratio = mp.mpf(ratio)

    def g(k):
        m = 1 - k * k
        K, E = mp.ellipk(m), mp.ellipe(m)
        return (E / (k * k) - K) / (K - E) - ratio
    x = mp.mpf(0)
    step = mp.mpf("0.5")
    hi = mp.mpf(1) - mp.mpf(10) ** -30
    while True:
        lo = mp.exp(x - step)
        if g(lo) > 0:
            break
        hi, x = lo, x - step
    k = mp.findroot(g, (lo, hi), solver="anderson", tol=mp.mpf(10) ** -35)
    m = 1 - k * k
    K, E = mp.ellipk(m), mp.ellipe(m)
    a = (3 * force * (K - E) / (2 * mp.pi * e_star * m * A)) ** (mp.mpf(1) / 3)
    return float(k), float(3 * force / (2 * mp.pi * a * a * k))


@pytest.mark.parametrize("ratio", [1 + 1e-6, 1.01, 2.0, 10.0, 1e3, 1e6, 8e6, 1e9, 1e12])
def test_ellipticity_and_peak_pressure_against_the_elliptic_integrals(ratio):
    """b/a to 1e-12 and p0 to 1e-12 of the 40-digit solution, from a circle to a contact
    a million times longer than wide (the crowned roller of 1 nm crown radius had B/A 8e6,
    beyond the old bracket)."""
    F, A, Es = 100.0, 60.0, 1.13e11
    k_want, p0_want = _mp_ellipse(ratio, F, A, Es)
    assert _ellipticity(ratio) == pytest.approx(k_want, rel=1e-12)
    assert point_contact(F, A, A * ratio, Es)[0] == pytest.approx(p0_want, rel=1e-12)


def test_a_nearly_round_contact_is_the_spheres():
    """B/A -> 1: p0 -> (6 F E*^2/(pi^3 R^2))^(1/3), R = 1/(2 A), continuously (1e-11)."""
    F, A, Es = 150.0, 30.0, 1.1e11
    sphere = (6 * F * Es**2 / (math.pi**3 * (1 / (2 * A)) ** 2)) ** (1 / 3)
    for ratio in (1.0, 1 + 1e-13, 1 + 1e-10):
        assert point_contact(F, A, A * ratio, Es)[0] == pytest.approx(sphere, rel=1e-9)
    with pytest.raises(CamdynInputError, match="out of range 1 to 1e\\+100"):
        _ellipticity(1e101)


def test_a_needle_crown_is_computed_and_warned_of(tmp_path):
    """The crown radius of 1 nm: the ellipse is found (no traceback), and its width across
    the crown, thousands of times the crown radius, is named as beyond Hertz's theory; a
    crown of 0.1 m is not."""
    base = ["profile", "--contact-force", "100", "--stroke", "0.02", "--base-radius", "0.04",
            "--roller-radius", "0.01", "--roller-width", "0.01", "--points-per-degree", "1",
            "--json"]
    code, out, err = run([*base, "--crown-radius", "1e-9", "--out", str(tmp_path / "a")])
    assert code == 0 and "Traceback" not in err
    js = json.loads(out)
    assert math.isfinite(js["hertz_stress_max"])
    warned = [w for w in js["warnings"] if "not small beside the radii" in w]
    assert len(warned) == 1 and "crown radius 1e-06 mm" in warned[0]
    cam = CamProfile(stroke=0.02, base_radius=0.04, roller_radius=0.01, points_per_degree=1)
    spec = ContactSpec(ContactLoad(force=100.0), roller_width=0.01, crown_radius=0.1)
    assert not cam.stress_summary(spec)["warnings"]


# -- 4. law files that cannot be read ------------------------------------------------------

BAD_FILES = {
    "binary.csv": bytes(range(256)) * 4,
    "latin1.csv": "0,0\n1,0.5\n2,1\n# \xe9\n".encode("latin-1"),
    "nul.csv": b"0,0\n1\x00,1\n",
    "empty.csv": b"",
    "empty.toml": b"",
    "syntax.toml": b"[[point]\nT = 0\n",
    "scalar.toml": b"point = 3\n",
    "control.toml": b"[bspline]\ncontrol = 5\n",
}


@pytest.mark.parametrize("name", sorted(BAD_FILES))
def test_a_law_file_that_cannot_be_read_is_one_line(tmp_path, name):
    path = tmp_path / name
    path.write_bytes(BAD_FILES[name])
    line = refused(["residual", "--model", "one-dof", "--tau", "0.15", "--law", str(path)])
    assert name in line


def test_a_folder_or_an_unreadable_file_is_one_line(tmp_path, monkeypatch):
    (tmp_path / "dir.csv").mkdir()
    line = refused(["residual", "--model", "one-dof", "--tau", "0.15", "--law",
                    str(tmp_path / "dir.csv")])
    assert "dir.csv" in line and "is a folder" in line
    locked = tmp_path / "locked.csv"
    locked.write_text("0,0\n")
    real = Path.read_text

    def denied(self, *args, **kwargs):
        if self.name == "locked.csv":
            raise PermissionError(13, "Permission denied", str(self))
        return real(self, *args, **kwargs)
    monkeypatch.setattr(Path, "read_text", denied)
    line = refused(["residual", "--model", "one-dof", "--tau", "0.15", "--law", str(locked)])
    assert "locked.csv" in line and "Permission denied" in line


SLOW = pytest.mark.slow        # each builds its command's parser and imports (1-3 s)


@pytest.mark.parametrize("argv", [
    ["profile", "--stroke", "0.02", "--base-radius", "0.04", "--roller-radius", "0.01",
     "--out", "{out}", "--return-law"],
    pytest.param(["design", "--stroke", "0.02", "--tau", "0.15", "--fa", "0", "--out",
                  "{out}"], marks=SLOW),
    pytest.param(["sweep", "one-dof", "--grid", "tau=0.1:0.2:2", "--out", "{out}"],
                 marks=SLOW),
    pytest.param(["integrate", "one-dof", "--t-end", "1"], marks=SLOW),
    pytest.param(["stability", "one-dof"], marks=SLOW),
    pytest.param(["laws", "--rise"], marks=SLOW),
])
def test_every_command_that_takes_a_law_file_refuses_a_binary_one(tmp_path, argv):
    path = tmp_path / "bin.csv"
    path.write_bytes(BAD_FILES["binary.csv"])
    argv = [a.replace("{out}", str(tmp_path / "o")) for a in argv]
    argv = argv + [str(path)] if argv[-1] in ("--rise", "--return-law") else \
        argv + ["--law", str(path)]
    line = refused(argv)
    assert "bin.csv" in line and "not a UTF-8 text file" in line


# -- 5. a failed check is status 1 ---------------------------------------------------------

def test_a_failed_check_is_status_1_with_the_json_and_the_files(tmp_path):
    """The cycloid over 45 deg on a base circle of 8 mm: its pressure angle passes 30 deg."""
    code, out, err = run(["profile", "--stroke", "0.015", "--base-radius", "0.008",
                          "--roller-radius", "0.004", "--angles", "45,135,90,90",
                          "--points-per-degree", "1", "--out", str(tmp_path), "--json"])
    js = json.loads(out)
    assert code == 1 and not js["ok"] and "Traceback" not in err
    assert [l for l in err.splitlines() if "pressure angle" in l]
    assert (tmp_path / "cam.json").exists()
    code, out, err = run(["profile", "--stroke", "0.015", "--base-radius", "0.008",
                          "--roller-radius", "0.004", "--angles", "45,135,90,90",
                          "--points-per-degree", "1", "--out", str(tmp_path / "t")])
    assert code == 1 and "FAIL pressure angle" in out


# -- 6. laws whose velocity or acceleration jumps -----------------------------------------

def _difference_jumps(cam: RDFD, order: int, h: float = 1e-4):
    """Jumps of S' or S'' at the segment ends from the sampled lift S alone: one-sided
    differences of second order on each side (S': (-3 S0 + 4 S1 - S2)/(2 h); S'': (2 S0 - 5 S1
    + 4 S2 - S3)/h^2), a jump where the sides differ by more than 1e-3 of the larger side's
    size over the turn's largest |S^(order)| from central differences."""
    def s(x):
        return cam.displacement(np.asarray(x, dtype=float))[0]
    grid = np.linspace(0.0, 2 * np.pi, 20001)
    if order == 1:
        scale = np.abs((s(grid + h) - s(grid - h)) / (2 * h)).max()
    else:
        scale = np.abs((s(grid + h) - 2 * s(grid) + s(grid - h)) / h**2).max()
    out = {}
    for b in cam.breakpoints[:-1]:
        sides = []
        for sgn in (-1.0, 1.0):
            S = s(b + sgn * h * np.arange(4))
            sides.append(sgn * (-3 * S[0] + 4 * S[1] - S[2]) / (2 * h) if order == 1 else
                         (2 * S[0] - 5 * S[1] + 4 * S[2] - S[3]) / h**2)
        if abs(sides[1] - sides[0]) > 1e-3 * scale:
            out[round(math.degrees(b), 6)] = tuple(sides)
    return out


ANGLES = [(90, 90, 90, 90), (60, 0, 150, 150), (30, 120, 170, 40)]


@pytest.mark.parametrize("law", NAMES)
@pytest.mark.parametrize("angles", ANGLES)
def test_the_jumps_found_from_the_law_are_those_of_the_sampled_lift(law, angles):
    r = np.radians(angles)
    cam = RDFD(0.02, 0.04, 0.01, choose(law), beta_rise=r[0], dwell_outer=r[1],
               beta_fall=r[2])
    for order in (1, 2):
        found = {round(math.degrees(t), 6): (lv, rv) for t, lv, rv in cam.jumps(order)}
        want = _difference_jumps(cam, order)
        assert set(found) == set(want), (law, angles, order, found, want)
        for t, (lv, rv) in found.items():
            wl, wr = want[t]
            assert abs((rv - lv) - (wr - wl)) < 1e-3 * max(abs(wr - wl), 1e-300)


BLEND = """# a rise whose velocity jumps inside: H = 3.125 T^2 to T = 0.4, then 1 - (25/18)(1 - T)^2
[[point]]
T = 0
H = 0
"H'" = "match"
[[point]]
T = 0.4
H = 0.5
[[point]]
T = 1
H = 1
"H'" = "match"
"""


def test_a_velocity_jump_inside_a_law_file_fails_the_check(tmp_path):
    """H'(0.4-) = 2.5, H'(0.4+) = 2 (25/18) 0.6 = 5/3: a velocity jump at 0.4 x 90 = 36 deg
    into the rise and the return (180 + 36 = 216 deg), found and held to the sampled lift's
    differences; S' = h H'/beta on either side."""
    path = tmp_path / "kink.toml"
    path.write_text(BLEND)
    cam = CamProfile(stroke=0.02, base_radius=0.04, roller_radius=0.01, law=str(path),
                     points_per_degree=2)
    found = {round(math.degrees(t), 6) for t, _, _ in cam.velocity_jumps}
    assert found == set(_difference_jumps(cam.cam, 1)) == {36.0, 216.0}
    (t, lv, rv), = [j for j in cam.velocity_jumps if abs(math.degrees(j[0]) - 36) < 1e-9]
    beta = math.pi / 2
    assert lv == pytest.approx(0.02 * 2.5 / beta, rel=1e-9)
    assert rv == pytest.approx(0.02 * (5 / 3) / beta, rel=1e-9)
    (under,) = [c for c in cam.summary()["checks"] if c["check"] == "undercut"]
    assert not under["ok"] and "36.00, 216.00" in under["message"]


@pytest.mark.parametrize("geometry", [
    dict(follower="translating-roller", stroke=0.02, roller_radius=0.01),
    dict(follower="oscillating-roller", swing_deg=15.0, pivot_distance=0.09, arm_length=0.07,
         roller_radius=0.008),
    dict(follower="translating-flat", stroke=0.02),
    dict(follower="oscillating-flat", swing_deg=15.0, pivot_distance=0.1),
])
def test_every_follower_fails_a_law_whose_velocity_jumps(geometry):
    out = CamProfile(law="uniform", base_radius=0.04, points_per_degree=2, **geometry).summary()
    (curv,) = [c for c in out["checks"] if c["check"] in ("undercut", "cusp")]
    assert not out["ok"] and not curv["ok"]
    assert "jumps at cam angle 0.00, 90.00, 180.00, 270.00 deg" in curv["message"]
    assert [0.0, 0.0] in curv["intervals_deg"] and [90.0, 90.0] in curv["intervals_deg"]


def test_the_pitch_curve_turns_a_corner_where_the_velocity_jumps():
    """The sampled pitch points alone: their chord directions on either side of 90 deg
    differ by the pressure angle's jump, atan(s'/(r_b + r_r + h)) (uniform: s' = h/beta);
    the cycloid's agree to the chords' own turning there."""
    h, rb, rr = 0.02, 0.04, 0.01
    for law, want in (("uniform", math.atan(h / (math.pi / 2) / (rb + rr + h))),
                      ("cycloidal", 0.0)):
        cam = CamProfile(stroke=h, base_radius=rb, roller_radius=rr, law=law)
        d = 1e-6
        p = cam.pitch(np.pi / 2 + np.array([-2 * d, -d, d, 2 * d]))
        before = np.arctan2(*(p[:, 1] - p[:, 0])[::-1])
        after = np.arctan2(*(p[:, 3] - p[:, 2])[::-1])
        turn = np.angle(np.exp(1j * (after - before)))      # near +-pi: wrapped
        assert abs(turn - want) < 1e-5


def test_an_acceleration_jump_is_warned_of_with_a_speed_and_not_with_a_constant_force(tmp_path):
    """Simple harmonic: H'' = (pi^2/2) cos(pi T) jumps from 0 to pi^2/2 at the rise's start
    and back at its end (and so on the return); a kinetostatic force jumps with it."""
    geometry = ["profile", "--law", "simple-harmonic", "--stroke", "0.01", "--base-radius",
                "0.04", "--roller-radius", "0.01", "--roller-width", "0.01",
                "--points-per-degree", "1", "--json"]
    code, out, err = run([*geometry, "--speed", "100", "--follower-mass", "1", "--spring-rate",
                          "1000", "--spring-preload", "50", "--out", str(tmp_path / "k")])
    js = json.loads(out)
    assert code == 0 and js["ok"]
    jumps = [w for w in js["warnings"] if "acceleration d2s/dphi2 jumps" in w]
    assert len(jumps) == 1 and "0.00, 90.00, 180.00, 270.00 deg" in jumps[0]
    assert any("acceleration d2s/dphi2 jumps" in l for l in err.splitlines())
    cam = CamProfile(law="simple-harmonic", stroke=0.01, base_radius=0.04, roller_radius=0.01,
                     points_per_degree=1)
    spec = ContactSpec(ContactLoad(force=100.0), roller_width=0.01)
    assert not cam.stress_summary(spec)["warnings"]
