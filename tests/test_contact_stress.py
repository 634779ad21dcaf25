"""Contact stress between cam and follower (runtime/cam/stress.py, runtime/cam/load.py).

References: Hertz's line contact in closed form (Johnson, Contact Mechanics, sec. 4.3), the
elliptical contact checked against an independent computation (the surface displacement of
the Hertz pressure by Boussinesq's integral must be the gap's quadratic form), the
kinetostatic force against its closed form for a translating face, and by virtual work with
differences of the computed geometry for a rocker.
"""
import json
import math

import numpy as np
import pytest
from scipy.integrate import quad

from camdyn.runtime.cam.load import ContactLoad
from camdyn.runtime.cam.profile import CamProfile
from camdyn.runtime.cam.stress import (MATERIALS, ContactSpec, contact_modulus, line_contact,
                                       point_contact)
from camdyn.runtime.cli import main
from camdyn.runtime.core.errors import CamdynInputError

STEEL = MATERIALS["steel"]


def test_contact_modulus_steel():
    E, nu = STEEL
    assert abs(contact_modulus(STEEL, STEEL) - E / (2 * (1 - nu * nu))) < 1e-3


def test_line_contact_closed_form():
    """p0 = sqrt(P' E*/(pi R)) and b = sqrt(4 P' R/(pi E*)); the load is the half-ellipse's
    area, P' = pi b p0 / 2."""
    Es = 1.1e11
    for F, L, R in ((500.0, 0.01, 0.004), (20.0, 0.002, 0.05)):
        p0, b = line_contact(F, L, 1.0 / R, Es)
        assert abs(p0 - math.sqrt(F / L * Es / (math.pi * R))) < 1e-9 * p0
        assert abs(b - math.sqrt(4 * F / L * R / (math.pi * Es))) < 1e-12 * b
        assert abs(math.pi * b * p0 / 2 - F / L) < 1e-9 * F / L


def _displacement(x, y, p0, a, b, Es):
    """Normal surface displacement (times nothing: both bodies through E*) under the Hertz
    pressure p0 sqrt(1 - x^2/a^2 - y^2/b^2), Boussinesq's integral in polar coordinates
    about the point."""
    def inner(th):
        c, s = math.cos(th), math.sin(th)
        qa = c * c / a / a + s * s / b / b
        qb = 2 * (x * c / a / a + y * s / b / b)
        qc = x * x / a / a + y * y / b / b - 1
        rmax = (-qb + math.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)
        return quad(lambda r: p0 * math.sqrt(max(0.0, 1 - (x + r * c)**2 / a / a
                                                 - (y + r * s)**2 / b / b)),
                    0, rmax, epsabs=0, epsrel=1e-11, limit=200)[0]
    return quad(inner, 0, 2 * math.pi, epsabs=0, epsrel=1e-11, limit=400)[0] / (math.pi * Es)


@pytest.mark.parametrize("ratio", [1.0, 4.0, 25.0])
def test_point_contact_against_boussinesq(ratio):
    """Inside the ellipse the two surfaces must close the gap A x^2 + B y^2 exactly: the
    displacement differences from the centre equal A x^2 and B y^2 (to 1e-9 relative), and
    the pressure carries the load."""
    F, Es, A = 150.0, 1.1e11, 30.0
    p0, a, b = point_contact(F, A, A * ratio, Es)
    assert a >= b
    u0 = _displacement(0, 0, p0, a, b, Es)
    for x, y, want in ((0.5 * a, 0, A * (0.5 * a)**2), (0, 0.6 * b, A * ratio * (0.6 * b)**2)):
        assert abs((u0 - _displacement(x, y, p0, a, b, Es)) / want - 1) < 1e-9
    assert abs(2 / 3 * math.pi * a * b * p0 - F) < 1e-12 * F
    if ratio == 1.0:   # a sphere on a plane: p0 = (6 F E*^2 / (pi^3 R^2))^(1/3), R = 1/(2A)
        R = 1 / (2 * A)
        assert abs(p0 - (6 * F * Es**2 / (math.pi**3 * R**2))**(1 / 3)) < 1e-12 * p0


def test_cam_stress_line_contact_at_the_least_radius():
    """Translating roller, e = 0, cycloid: the peak pressure of a constant force sits where
    the profile is tightest, p0 = sqrt(P' E* (1/rho + 1/r_r)/pi) with rho the profile's least
    radius of curvature (polar formula of the pitch curve, minus the roller)."""
    cam = CamProfile(stroke=0.015, base_radius=0.026, roller_radius=0.005)
    spec = ContactSpec(ContactLoad(force=500.0), roller_width=0.01)
    out = cam.stress_summary(spec)
    th = np.linspace(0, 2 * np.pi, 200001)
    rho_min = 1.0 / np.max(cam.cam.pitch_curvature(th)) - 0.005
    Es = contact_modulus(STEEL, STEEL)
    want = math.sqrt(500 / 0.01 * Es * (1 / rho_min + 1 / 0.005) / math.pi)
    assert abs(out["hertz_stress_max"] - want) < 1e-6 * want
    assert out["hertz_stress_max_error"] < 1e-6 * want


def test_kinetostatic_force_translating_face():
    """F_n = m omega^2 s'' + k s + F0 for a translating flat face (lever 1), and the follower
    leaves the cam exactly where that is negative (cycloid: its roots in closed form)."""
    beta = math.pi / 2
    h, m, k, F0, rpm = 0.01, 0.8, 3000.0, 15.0, 900.0
    cam = CamProfile(follower="translating-flat", stroke=h, base_radius=0.03)
    load = ContactLoad(speed_rpm=rpm, mass=m, spring_rate=k, preload=F0)
    w = 2 * math.pi * rpm / 60
    phi = np.linspace(0.01, beta - 0.01, 501)
    x = phi / beta
    s = h * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    dds = h / beta**2 * 2 * np.pi * np.sin(2 * np.pi * x)
    force, _ = cam.contact_stress(phi, ContactSpec(load, cam_width=0.01))
    assert np.max(np.abs(force - (m * w * w * dds + k * s + F0))) < 1e-9
    out = cam.stress_summary(ContactSpec(load, cam_width=0.01))
    kept = next(c for c in out["checks"] if c["check"] == "contact kept")
    from scipy.optimize import brentq

    def g(x):
        return (m * w * w * h / beta**2 * 2 * math.pi * math.sin(2 * math.pi * x)
                + k * h * (x - math.sin(2 * math.pi * x) / (2 * math.pi)) + F0)
    lo, hi = brentq(g, 0.5, 0.75), brentq(g, 0.75, 0.999)
    assert not kept["ok"]
    assert abs(kept["intervals_deg"][0][0] - math.degrees(lo * beta)) < 1e-7
    assert abs(kept["intervals_deg"][0][1] - math.degrees(hi * beta)) < 1e-7
    assert any("leaves the cam" in msg for msg in out["warnings"])


def test_kinetostatic_force_rocker_by_virtual_work():
    """A rocker with a roller: F_n (n . dC/dpsi) = I omega^2 psi'' + k psi + M0, dC/dpsi by
    central differences of the roller centre, n from the pitch curve's tangent by
    differences of the computed pitch points."""
    I, k, M0, rpm = 2e-4, 40.0, 3.0, 300.0
    cam = CamProfile(follower="oscillating-roller", base_radius=0.03, roller_radius=0.008,
                     pivot_distance=0.09, arm_length=0.07, swing_deg=18)
    load = ContactLoad(speed_rpm=rpm, mass=I, spring_rate=k, preload=M0)
    phi = np.linspace(0.2, 1.4, 41)
    force, _ = cam.contact_stress(phi, ContactSpec(load, roller_width=0.01))
    geo = cam.geometry
    M = cam.cam.displacement(phi)
    psi = geo.psi0 + M[0]
    dpsi = 1e-6
    C = lambda p: np.array([0.09 - 0.07 * np.cos(p), 0.07 * np.sin(p)])
    dC = (C(psi + dpsi) - C(psi - dpsi)) / (2 * dpsi)
    hs = 1e-6
    P = lambda x: np.array(cam.contact(x).pitch)
    t = (P(phi + hs) - P(phi - hs)) / (2 * hs)
    # the tangent back in the ground frame, then its outward normal
    c, s = np.cos(-phi), np.sin(-phi)
    tg = np.array([t[0] * c - t[1] * s, t[0] * s + t[1] * c])
    n = np.array([tg[1], -tg[0]]) / np.hypot(tg[0], tg[1])
    Q = I * (2 * math.pi * rpm / 60)**2 * M[2] + k * M[0] + M0
    assert np.max(np.abs(force * np.sum(n * dC, axis=0) - Q)) < 1e-6 * np.max(np.abs(Q))


def test_crowned_roller_is_a_point_contact():
    cam = CamProfile(stroke=0.015, base_radius=0.026, roller_radius=0.005)
    line = cam.stress_summary(ContactSpec(ContactLoad(force=200.0), roller_width=0.01))
    crown = cam.stress_summary(ContactSpec(ContactLoad(force=200.0), roller_width=0.01,
                                           crown_radius=0.1))
    phi = math.radians(crown["hertz_stress_max_angle_deg"])
    kap = float(cam.profile_curvature(phi)[0]) + 1 / 0.005
    want = point_contact(200.0, 0.5 * kap, 0.5 / 0.1, contact_modulus(STEEL, STEEL))[0]
    assert abs(crown["hertz_stress_max"] - want) < 1e-9 * want
    assert crown["hertz_stress_max"] > line["hertz_stress_max"]   # the crown concentrates it


def test_cli_hertz_json_and_refusals(tmp_path, capsys):
    rc = main(["profile", "--stroke", "0.015", "--base-radius", "0.026", "--roller-radius",
               "0.005", "--contact-force", "500", "--roller-width", "0.01", "--materials",
               "steel,210e9:0.3", "--allowable-stress", "1e9", "--out", str(tmp_path), "--json"])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and out["ok"]
    Es = contact_modulus(STEEL, (210e9, 0.3))
    assert abs(out["contact_stress"]["contact_modulus"] - Es) < 1e-3
    assert out["hertz_stress_max"] > 0 and out["hertz_stress_max_error"] >= 0
    json.dumps(out, allow_nan=False)
    for argv, name in ((["--contact-force", "500"], "roller-width"),
                       (["--roller-width", "0.01"], "--contact-force"),
                       (["--contact-force", "-5", "--roller-width", "0.01"], "contact-force"),
                       (["--contact-force", "5", "--speed", "100", "--roller-width", "0.01"],
                        "one way"),
                       (["--contact-force", "5", "--roller-width", "0.01", "--materials",
                         "steel,1e9:0.7"], "Poisson")):
        rc = main(["profile", "--stroke", "0.015", "--base-radius", "0.026", "--roller-radius",
                   "0.005", *argv, "--out", str(tmp_path)])
        err = capsys.readouterr().err.strip().splitlines()
        assert rc == 2 and len(err) == 1 and name in err[0], err


def test_material_refusals_name_the_input():
    with pytest.raises(CamdynInputError, match="unobtainium"):
        ContactSpec(ContactLoad(force=1.0), roller_width=0.01, materials=("steel", "unobtainium"))
