"""Followers of a disk cam (runtime/cam/follower.py): against closed forms derived here and
against differences of the computed curves.

Closed forms.  A translating flat face touches the cam at (r_b + s, s') in the follower's
frame, and the profile's radius of curvature is r_b + s + s'' (the support function p of a
convex curve has radius p + p'').  An eccentric circle cam (radius R_c, centre at distance
eps from the shaft) moves any follower in a motion known in closed form, and whatever the
follower, the profile must come out as that circle: under a rocker with a roller the roller
centre stays at R_c + r_r from the circle's centre, whence the arm angle psi(phi); under a
rocker with a flat face the face stays tangent to the circle, whence psi(phi) implicitly.
"""
import json
import math

import numpy as np
import pytest
import sympy as sp

from camdyn.runtime.cam.follower import OscillatingFlat, OscillatingRoller
from camdyn.runtime.cam.profile import CamProfile
from camdyn.runtime.cli import main

RB, H = 0.03, 0.01


def flat(**kw):
    return CamProfile(follower="translating-flat", stroke=H, base_radius=RB, **kw)


def test_translating_flat_face_closed_form():
    """rho = r_b + s + s'', the contact at s' from the slide's axis (cycloidal rise, 100 deg)."""
    beta = math.radians(100)
    cam = flat(angles_deg=(100, 80, 120, 60), offset=0.004)
    phi = np.linspace(0.0, beta, 2001)[1:-1]
    x = phi / beta
    s = H * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    ds = H / beta * (1 - np.cos(2 * np.pi * x))
    dds = H / beta**2 * 2 * np.pi * np.sin(2 * np.pi * x)
    c = cam.contact(phi)
    assert np.max(np.abs(1.0 / c.kappa_profile - (RB + s + dds))) < 1e-15
    assert np.max(np.abs(c.face_position - (ds - 0.004))) < 1e-15
    assert np.max(np.abs(c.pressure_angle)) == 0.0
    # the contact point in the follower frame, rotated into the cam's
    want = np.array([(RB + s) * np.cos(phi) - ds * np.sin(phi), (RB + s) * np.sin(phi) + ds * np.cos(phi)])
    assert np.max(np.abs(np.array([c.x, c.y]) - want)) < 1e-16
    # the face width: s' from -2h/beta_return to 2h/beta_rise (cycloidal s'max = 2h/beta)
    ex = cam.summary()
    lo, hi = ex["face_travel"]
    assert abs(hi - (2 * H / beta - 0.004)) < 1e-12
    assert abs(lo - (-2 * H / math.radians(120) - 0.004)) < 1e-12
    assert abs(ex["face_width"] - 2 * H * (1 / beta + 1 / math.radians(120))) < 1e-12


def test_translating_flat_face_cusp_named():
    """A cycloid over 30 deg with a 10 mm base circle: r_b + s + s'' < 0 near the rise's
    end, where s'' = -2 pi h/beta^2 at x = 3/4; the check names it and it agrees with the
    closed form's root."""
    beta = math.radians(30)
    cam = CamProfile(follower="translating-flat", stroke=0.01, base_radius=0.01,
                     angles_deg=(30, 150, 90, 90))
    cusp = next(c for c in cam.checks if c.name == "cusp")
    assert not cusp.ok and cusp.intervals_deg
    lo, hi = cusp.intervals_deg[0]

    def rho(x):
        return 0.01 + 0.01 * (x - math.sin(2 * math.pi * x) / (2 * math.pi)) \
            + 0.01 / beta**2 * 2 * math.pi * math.sin(2 * math.pi * x)
    from scipy.optimize import brentq
    x0 = brentq(rho, 0.5, 0.75)
    x1 = brentq(rho, 0.75, 0.999)
    assert abs(lo - math.degrees(x0 * beta)) < 1e-8 and abs(hi - math.degrees(x1 * beta)) < 1e-8
    # worst at the least rho: 3/4 of the rise, rho = r_b + s(3/4) - 2 pi h/beta^2 there
    from scipy.optimize import minimize_scalar
    rmin = minimize_scalar(rho, bounds=(0.5, 1.0), method="bounded",
                           options={"xatol": 1e-12}).fun
    assert abs(cusp.value - rmin) < 1e-12
    assert f"{cusp.worst_deg:.2f}" in cusp.message and "cusp" in cusp.message
    assert any("cusp" in w for w in cam.summary()["warnings"])


def _circle_rocker_motion(a, l, eps, rho0):
    """psi(phi) of a rocker's roller on an eccentric circle cam, with its derivatives: the
    roller centre A + l u(psi) stays at rho0 from the circle's centre eps (cos phi, -sin phi)
    (the cam turns clockwise).  With D = A - E: D . u = (rho0^2 - |D|^2 - l^2)/(2 l), and
    D . u = -D_x cos psi + D_y sin psi = |D| sin(psi - gamma), gamma = atan2(D_x, D_y)."""
    ph = sp.symbols("phi")
    dx, dy = a - eps * sp.cos(ph), eps * sp.sin(ph)
    d = sp.sqrt(dx**2 + dy**2)
    psi = sp.atan2(dx, dy) + sp.asin((rho0**2 - d**2 - l**2) / (2 * l * d))
    return [sp.lambdify(ph, sp.diff(psi, ph, k), "numpy") for k in range(3)]


@pytest.mark.parametrize("eps", [0.004, 0.009])
def test_circle_cam_under_a_rocker_with_a_roller(eps):
    """Profile on the circle, pitch curve on the circle grown by the roller, both curvatures
    exact, pressure angle between the line of centres and the arm's normal."""
    a, l, rr, rc = 0.09, 0.07, 0.008, 0.03
    rho0 = rc + rr
    f = _circle_rocker_motion(a, l, eps, rho0)
    geo = OscillatingRoller(base_radius=rc - eps, roller_radius=rr, pivot_distance=a,
                            arm_length=l)
    phi = np.linspace(0.0, 2 * np.pi, 721)
    psi = f[0](phi)
    # the arm's lowest angle puts the roller on the prime circle r_c - eps + r_r: the start
    from scipy.optimize import minimize_scalar
    low = minimize_scalar(lambda x: float(f[0](x)), bounds=(np.pi / 2, 3 * np.pi / 2),
                          method="bounded", options={"xatol": 1e-12}).fun
    assert abs(low - geo.psi0) < 1e-12
    c = geo.contact(phi, np.array([psi - geo.psi0, f[1](phi), f[2](phi)]))
    px, py = c.pitch
    assert np.max(np.abs(np.hypot(px - eps, py) - rho0)) < 1e-15
    assert np.max(np.abs(np.hypot(c.x - eps, c.y) - rc)) < 1e-15
    assert np.max(np.abs(c.kappa_pitch * rho0 - 1)) < 1e-12
    assert np.max(np.abs(c.kappa_profile * rc - 1)) < 1e-12
    # ground frame: normal from the circle's centre to the roller's, velocity along the arm's
    # normal (sin psi, cos psi)
    ex, ey = eps * np.cos(phi), -eps * np.sin(phi)
    cx, cy = a - l * np.cos(psi), l * np.sin(psi)
    n = np.array([cx - ex, cy - ey]) / rho0
    v = np.array([np.sin(psi), np.cos(psi)])
    want = np.arctan2(n[0] * v[1] - n[1] * v[0], n[0] * v[0] + n[1] * v[1])
    assert np.max(np.abs(c.pressure_angle - want)) < 1e-12


@pytest.mark.parametrize("f_off", [0.0, 0.012, -0.01])
def test_circle_cam_under_a_flat_faced_rocker(f_off):
    """The face stays tangent to the circle: a sin psi + f = eps sin(psi - phi) + R_c
    (support of the face = the circle's centre's projection plus R_c); psi from that by
    root finding, psi' and psi'' by implicit differentiation.  The envelope is the circle."""
    from scipy.optimize import brentq

    a, eps, rc = 0.1, 0.006, 0.03
    geo = OscillatingFlat(base_radius=rc - eps, pivot_distance=a, face_offset=f_off)
    phi = np.linspace(0.0, 2 * np.pi, 361)

    def F(p, x):
        return a * math.sin(p) + f_off - eps * math.sin(p - x) - rc
    psi = np.array([brentq(F, geo.psi0 - 0.5, geo.psi0 + 0.5, args=(x,), xtol=1e-15)
                    for x in phi])
    Fp = a * np.cos(psi) - eps * np.cos(psi - phi)
    Fx = eps * np.cos(psi - phi)
    Fxx = eps * np.sin(psi - phi)
    Fpx = -eps * np.sin(psi - phi)
    Fpp = -a * np.sin(psi) + eps * np.sin(psi - phi)
    d1 = -Fx / Fp
    d2 = -(Fxx + 2 * Fpx * d1 + Fpp * d1**2) / Fp
    c = geo.contact(phi, np.array([psi - geo.psi0, d1, d2]))
    assert np.max(np.abs(np.hypot(c.x - eps, c.y) - rc)) < 1e-13
    assert np.max(np.abs(c.kappa_profile * rc - 1)) < 1e-9
    # pressure angle of a face on an arm: atan2(-f, w), zero with the face through the pivot
    assert np.max(np.abs(c.pressure_angle - np.arctan2(-f_off, c.face_position))) < 1e-12


@pytest.mark.parametrize("kind,kw", [
    ("translating-roller", dict(stroke=0.012, roller_radius=0.008, offset=0.005)),
    ("translating-flat", dict(stroke=0.008, offset=0.002)),
    ("oscillating-roller", dict(swing_deg=18, roller_radius=0.008, pivot_distance=0.09,
                                arm_length=0.07)),
    ("oscillating-flat", dict(swing_deg=8, pivot_distance=0.09, face_offset=0.01)),
])
def test_profile_curvature_against_differences(kind, kw):
    """The profile's curvature against central differences of its computed points (step
    0.01 deg), away from the segment ends; relative error below 1e-5."""
    cam = CamProfile(follower=kind, base_radius=RB, law="3-4-5", angles_deg=(120, 60, 100, 80),
                     **kw)
    hs = math.radians(0.01)
    phi = np.linspace(0.01, 2 * np.pi - 0.01, 2001)
    ends = cam.cam.breakpoints
    phi = phi[np.min(np.abs(phi[:, None] - ends[None, :]), axis=1) > 3 * hs]

    def pts(x):
        c = cam.contact(x)
        return np.array([c.x, c.y])
    pm, p0, pp = pts(phi - hs), pts(phi), pts(phi + hs)
    d1 = (pp - pm) / (2 * hs)
    d2 = (pp - 2 * p0 + pm) / hs**2
    k_fd = (d1[0] * d2[1] - d1[1] * d2[0]) / np.hypot(d1[0], d1[1])**3
    k = cam.profile_curvature(phi)
    assert np.max(np.abs(k_fd - k)) / np.max(np.abs(k)) < 1e-5
    assert all(c.ok for c in cam.checks if c.name != "pressure angle")
    # and the profile's normal is the follower's: the tangent of the profile is square to
    # the roller's line of centres, or along the face
    c = cam.contact(phi)
    if cam.roller:
        nx, ny = c.pitch[0] - c.x, c.pitch[1] - c.y
        assert np.max(np.abs(d1[0] * nx + d1[1] * ny) / np.hypot(d1[0], d1[1])
                      / np.hypot(nx, ny)) < 1e-6


def test_rocker_profile_touches_the_roller_at_every_angle():
    """Envelope check in the ground frame: rotating the profile back by phi, its nearest
    point to the roller centre lies at the roller radius (sampled densely)."""
    cam = CamProfile(follower="oscillating-roller", base_radius=RB, roller_radius=0.008,
                     pivot_distance=0.09, arm_length=0.07, swing_deg=18, points_per_degree=50)
    t = cam.table
    prof = np.array([t["x_profile"], t["y_profile"]])
    for deg in (10.0, 45.0, 100.0, 200.0, 250.0):
        phi = math.radians(deg)
        c = cam.contact(phi)
        centre = np.array([c.pitch[0][0], c.pitch[1][0]])
        gap = np.min(np.hypot(prof[0] - centre[0], prof[1] - centre[1]))
        assert abs(gap - 0.008) < 2e-7   # the sampling's chord error at 50 points a degree


def test_cli_followers_json(tmp_path, capsys):
    rc = main(["profile", "--follower", "oscillating-roller", "--pivot-distance", "0.09",
               "--arm-length", "0.07", "--swing", "18", "--base-radius", "0.03",
               "--roller-radius", "0.008", "--out", str(tmp_path / "r"), "--json"])
    out = json.loads(capsys.readouterr().out)
    # its pressure angle reaches 38 deg, beyond the default limit: a failed check, status 1
    assert rc == 1 and out["follower"] == "oscillating-roller" and not out["ok"]
    cam = CamProfile(follower="oscillating-roller", base_radius=0.03, roller_radius=0.008,
                     pivot_distance=0.09, arm_length=0.07, swing_deg=18)
    phi = np.linspace(0, 2 * np.pi, 360001)
    assert abs(out["max_abs_pressure_angle_deg"]
               - np.degrees(np.max(np.abs(cam.pressure_angle(phi))))) < 1e-6
    assert abs(out["min_rho_profile"] - 1 / np.max(np.abs(cam.profile_curvature(phi)))) < 1e-9
    assert abs(out["min_rho_profile"] - (out["min_rho_pitch"] - 0.008)) < 1e-12
    assert abs(out["start_angle_deg"] - math.degrees(math.acos((0.09**2 + 0.07**2 - 0.038**2)
                                                               / (2 * 0.09 * 0.07)))) < 1e-12
    rc = main(["profile", "--follower", "translating-flat", "--stroke", "0.01", "--base-radius",
               "0.03", "--out", str(tmp_path / "f"), "--json"])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and out["max_abs_pressure_angle_deg"] == 0.0
    assert abs(out["face_width"] - 2 * 0.01 * 2 / (math.pi / 2)) < 1e-12
    assert "min_rho_pitch" not in out and out["min_rho_profile"] > 0
    import ezdxf
    doc = ezdxf.readfile(tmp_path / "f" / "cam.dxf")
    assert "PITCH" not in [layer.dxf.name for layer in doc.layers]


@pytest.mark.parametrize("argv,names", [
    (["--follower", "oscillating-roller", "--base-radius", "0.03", "--roller-radius", "0.008"],
     ["pivot-distance", "swing", "arm-length"]),
    (["--follower", "oscillating-flat", "--stroke", "0.01", "--swing", "10", "--pivot-distance",
      "0.08", "--base-radius", "0.03"], ["stroke"]),
    (["--follower", "translating-flat", "--stroke", "0.01", "--base-radius", "0.03",
      "--roller-radius", "0.01"], ["roller-radius"]),
    (["--follower", "oscillating-roller", "--base-radius", "0.03", "--roller-radius", "0.008",
      "--pivot-distance", "0.2", "--arm-length", "0.05", "--swing", "10"], ["arm-length", "0.038"]),
    (["--follower", "oscillating-flat", "--base-radius", "0.03", "--pivot-distance", "0.02",
      "--swing", "10"], ["face-offset", "pivot-distance"]),
    (["--follower", "oscillating-roller", "--base-radius", "0.03", "--roller-radius", "0.008",
      "--pivot-distance", "0.09", "--arm-length", "0.07", "--swing", "95"], ["swing", "90"]),
    (["--follower", "translating-flat", "--stroke", "0.01", "--base-radius", "0.03",
      "--groove"], ["groove"]),
])
def test_cli_refuses_follower_input_in_one_line(tmp_path, capsys, argv, names):
    rc = main(["profile", *argv, "--out", str(tmp_path)])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and err[0].startswith("camdyn profile: error:")
    for n in names:
        assert n in err[0]


def test_cutter_path_is_the_offset_profile():
    """A cutter of the roller's radius runs on the pitch curve; for a flat face the cutter's
    centre stays at r_c from the profile (its nearest profile point, densely sampled)."""
    cam = CamProfile(follower="translating-roller", stroke=0.012, base_radius=RB,
                     roller_radius=0.008, offset=0.004, cutter_radius=0.008)
    t = cam.table
    assert np.max(np.hypot(t["x_cutter"] - t["x_pitch"], t["y_cutter"] - t["y_pitch"])) < 1e-15
    cam = CamProfile(follower="translating-flat", stroke=0.008, base_radius=RB,
                     cutter_radius=0.01, points_per_degree=50)
    t = cam.table
    for i in range(0, t["x_cutter"].size, 1500):
        gap = np.min(np.hypot(t["x_profile"] - t["x_cutter"][i], t["y_profile"] - t["y_cutter"][i]))
        assert abs(gap - 0.01) < 1e-8


def test_cutter_gouge_named():
    """A rocker's cam with a concave part: a cutter larger than its least concave |rho|
    gouges there; the check's value is that radius (dense sampling: 1e-9 m)."""
    kw = dict(follower="oscillating-roller", swing_deg=20, base_radius=0.03,
              roller_radius=0.008, pivot_distance=0.08, arm_length=0.06)
    cam = CamProfile(**kw)
    phi = np.linspace(0, 2 * np.pi, 720001)
    k = cam.profile_curvature(phi)
    rho_concave = 1.0 / np.max(-k)
    big = CamProfile(**kw, cutter_radius=1.2 * rho_concave)
    small = CamProfile(**kw, cutter_radius=0.8 * rho_concave)
    cb = next(c for c in big.checks if c.name == "cutter")
    cs = next(c for c in small.checks if c.name == "cutter")
    assert not cb.ok and cs.ok and "gouges" in cb.message
    assert abs(cb.value - rho_concave) < 1e-9 and abs(cs.value - rho_concave) < 1e-9
    with pytest.raises(Exception, match="groove"):
        CamProfile(stroke=0.01, base_radius=RB, roller_radius=0.008, groove=True,
                   cutter_radius=0.005)


def _arc_distance(p, centre, a0, a1, r):
    """Distance of points p (n, 2) from the CCW arc of ezdxf's bulge_to_arc (angles in rad)."""
    d = p - np.asarray(centre)[None, :]
    ang = np.mod(np.arctan2(d[:, 1], d[:, 0]) - a0, 2 * np.pi)
    span = np.mod(a1 - a0, 2 * np.pi)
    on = np.abs(np.hypot(d[:, 0], d[:, 1]) - r)
    ends = np.minimum(np.hypot(*(p - (centre[0] + r * np.cos(a0), centre[1] + r * np.sin(a0))).T),
                      np.hypot(*(p - (centre[0] + r * np.cos(a1), centre[1] + r * np.sin(a1))).T))
    return np.where(ang <= span, on, ends)


@pytest.mark.parametrize("kind,kw", [
    ("translating-roller", dict(stroke=0.015, roller_radius=0.005, cutter_radius=0.006)),
    ("oscillating-flat", dict(swing_deg=8, pivot_distance=0.09, face_offset=0.01)),
])
def test_dxf_arcs_within_tolerance_and_tangent(tmp_path, kind, kw):
    """The DXF's arcs, read back through ezdxf and turned into circles by ezdxf itself: every
    point of the exact profile (60 a degree) lies within the tolerance of the chain, and
    consecutive arcs share their tangent (G1)."""
    import ezdxf
    from ezdxf.math import bulge_to_arc

    tol = 1e-6
    cam = CamProfile(follower=kind, base_radius=0.026 if "roller" in kind else 0.03,
                     arc_tolerance=tol, **kw)
    path = cam.write_dxf(tmp_path / "cam.dxf")
    doc = ezdxf.readfile(path)
    layers = ["PROFILE"] + (["PITCH", "CUTTER"] if "roller" in kind else [])
    for layer in layers:
        line = next(e for e in doc.modelspace() if e.dxftype() == "LWPOLYLINE"
                    and e.dxf.layer == layer)
        pts = np.array([(x, y, b) for x, y, _, _, b in line.get_points()]) / [1e3, 1e3, 1]
        assert 8 < len(pts) < 1000 and line.closed
        arcs = []
        for k in range(len(pts)):
            s, e = pts[k], pts[(k + 1) % len(pts)]
            # ezdxf gives every arc counter-clockwise from a0 to a1: a clockwise one (bulge
            # < 0) is run from a1 back to a0
            c, a0, a1, r = bulge_to_arc(s[:2], e[:2], s[2])
            arcs.append((np.array([c[0], c[1]]), a0, a1, r, s[2] < 0))
        t = cam.table
        shift = {"PROFILE": 0.0, "PITCH": kw.get("roller_radius", 0),
                 "CUTTER": kw.get("cutter_radius", 0)}[layer]
        phi = np.linspace(0, 2 * np.pi, 21601)[:-1]
        c = cam.contact(phi)
        exact = np.column_stack([c.x + shift * c.normal[0], c.y + shift * c.normal[1]])
        dist = np.min([_arc_distance(exact, a[0], a[1], a[2], a[3]) for a in arcs], axis=0)
        assert np.max(dist) < 1.01 * tol, (layer, np.max(dist))
        # G1: the tangent leaving each vertex on the next arc equals the one arriving
        for k in range(len(arcs)):
            (c0, a0, a1, r0, cw0), (c1, b0, b1, r1, cw1) = arcs[k], arcs[(k + 1) % len(arcs)]
            end_ang = a0 if cw0 else a1
            start_ang = b1 if cw1 else b0
            t_in = np.array([-np.sin(end_ang), np.cos(end_ang)]) * (-1 if cw0 else 1)
            t_out = np.array([-np.sin(start_ang), np.cos(start_ang)]) * (-1 if cw1 else 1)
            assert np.hypot(*(t_in - t_out)) < 1e-6
