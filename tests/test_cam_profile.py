"""camdyn profile: the cam itself against closed forms and read back."""
import csv
import json
import math
import subprocess
import sys

import numpy as np
import pytest

from camdyn.runtime.cam.profile import CamProfile
from camdyn.runtime.cli import main
from camdyn.runtime.core.errors import CamdynInputError

H, RB, RR = 0.015, 0.026, 0.005


def cycloid(h=H, rb=RB, rr=RR, e=0.0, **kw):
    return CamProfile(stroke=h, base_radius=rb, roller_radius=rr, offset=e, law="cycloidal", **kw)


@pytest.mark.parametrize("groove", [False, True])
@pytest.mark.parametrize("e", [0.0, 0.01])
def test_circle_cam(groove, e):
    cam = cycloid(h=0.0, e=e, groove=groove, points_per_degree=2)
    t = cam.table
    r_p = np.hypot(t["x_pitch"], t["y_pitch"])
    assert np.max(np.abs(r_p - (RB + RR))) < 1e-12
    assert np.max(np.abs(t["rho_pitch"] - (RB + RR))) < 1e-12
    assert np.max(np.abs(np.hypot(t["x_profile"], t["y_profile"]) - RB)) < 1e-12
    assert np.max(np.abs(t["rho_profile"] - RB)) < 1e-12
    if groove:
        assert np.max(np.abs(np.hypot(t["x_outer"], t["y_outer"]) - (RB + 2 * RR))) < 1e-12
    # pressure angle of a circle: -e over the prime circle's chord
    assert np.allclose(np.tan(np.radians(t["alpha_deg"])), -e / math.sqrt((RB + RR)**2 - e * e),
                       rtol=0, atol=1e-14)
    assert all(c.ok for c in cam.checks)
    # strict JSON even where a curvature sign never occurs (rho infinite)
    json.dumps(cam.summary(), allow_nan=False)


def test_pressure_angle_cycloid_closed_form():
    beta = math.radians(100)
    cam = cycloid(angles_deg=(100, 80, 120, 60), points_per_degree=4)
    phi = np.linspace(0.0, beta, 1001)
    x = phi / beta
    s = H * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    ds = H / beta * (1 - np.cos(2 * np.pi * x))
    alpha = cam.pressure_angle(phi)
    assert np.max(np.abs(np.tan(alpha) - ds / (RB + RR + s))) < 1e-10
    assert np.max(np.abs(cam.cam.displacement(phi)[0] - s)) < 1e-15
    # the table's column at the sampled angles is the same closed form
    t = cam.table
    k = t["phi_deg"] <= 100
    xk = np.radians(t["phi_deg"][k]) / beta
    ref = H / beta * (1 - np.cos(2 * np.pi * xk)) / (RB + RR + H * (xk - np.sin(2 * np.pi * xk) / (2 * np.pi)))
    assert np.max(np.abs(np.tan(np.radians(t["alpha_deg"][k])) - ref)) < 1e-10


def test_pressure_angle_offset_closed_form():
    e, beta = 0.008, math.pi / 2
    cam = cycloid(e=e)
    phi = np.linspace(0.0, beta, 777)
    x = phi / beta
    s = H * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    ds = H / beta * (1 - np.cos(2 * np.pi * x))
    d0 = math.sqrt((RB + RR)**2 - e * e)
    assert np.max(np.abs(np.tan(cam.pressure_angle(phi)) - (ds - e) / (d0 + s))) < 1e-10
    # geometric meaning: the angle between the follower axis (rotated into the cam frame)
    # and the pitch curve's normal
    t = cam.tangent(phi)
    axis = np.array([np.cos(phi), np.sin(phi)])
    normal = np.array([t[1], -t[0]]) / np.hypot(t[0], t[1])
    sin_a = axis[0] * normal[1] - axis[1] * normal[0]
    assert np.max(np.abs(np.arcsin(-sin_a) - cam.pressure_angle(phi))) < 1e-12
    # the offset lowers the rise's largest pressure angle
    assert np.max(cam.pressure_angle(phi)) < np.max(cycloid().pressure_angle(phi))


def test_curvature_polar_formula_zero_offset():
    """e = 0: the parametric curvature equals profile.RDFD's polar formula (paper (4))."""
    cam = cycloid()
    phi = np.linspace(0, 2 * np.pi, 5001)
    assert np.max(np.abs(cam.curvature(phi) - cam.cam.pitch_curvature(phi))) < 1e-9


@pytest.mark.parametrize("law", ["cycloidal", "modified-sine", "3-4-5"])
def test_curvature_finite_differences_offset(law):
    """Radius of curvature against central differences of the sampled pitch curve (step
    0.01 deg); relative error below 1e-5 away from the segment ends."""
    from camdyn.runtime.core.laws import NAMES
    if law not in NAMES:
        pytest.skip(f"no {law} law")
    cam = CamProfile(stroke=H, base_radius=RB, roller_radius=RR, offset=0.006,
                     angles_deg=(120, 60, 100, 80), law=law)
    hstep = math.radians(0.01)
    phi = np.linspace(0.01, 2 * np.pi - 0.01, 3001)
    ends = cam.cam.breakpoints
    phi = phi[np.min(np.abs(phi[:, None] - ends[None, :]), axis=1) > 3 * hstep]
    pm, p0, pp = cam.pitch(phi - hstep), cam.pitch(phi), cam.pitch(phi + hstep)
    d1 = (pp - pm) / (2 * hstep)
    d2 = (pp - 2 * p0 + pm) / hstep**2
    kappa_fd = (d1[0] * d2[1] - d1[1] * d2[0]) / np.hypot(d1[0], d1[1])**3
    kappa = cam.curvature(phi)
    scale = np.max(np.abs(kappa))
    assert np.max(np.abs(kappa_fd - kappa)) / scale < 1e-5
    # and the profile's radius of curvature is the pitch curve's less the roller
    t = cam.table
    assert np.allclose(t["rho_profile"], t["rho_pitch"] - RR, rtol=0, atol=1e-15)


def test_undercut_named_and_default_clean():
    good = cycloid()
    assert all(c.ok for c in good.checks), [c.message for c in good.checks]
    bad = CamProfile(stroke=0.03, base_radius=0.004, roller_radius=0.012, law="cycloidal",
                     angles_deg=(60, 120, 60, 120), max_pressure_angle_deg=80)
    cut = [c for c in bad.failures if c.name == "undercut"]
    assert len(cut) == 1
    c = cut[0]
    assert c.value < 0.012 and c.intervals_deg
    lo, hi = c.intervals_deg[0]
    assert lo <= c.worst_deg <= hi
    assert f"{c.worst_deg:.2f} deg" in c.message and "undercut" in c.message
    # at the named angle the pitch curve's radius of curvature is below the roller radius
    k = bad.curvature(math.radians(c.worst_deg))[0]
    assert 0 < 1 / k < 0.012


def test_pressure_angle_check_named():
    cam = cycloid(rb=0.008, rr=0.004, angles_deg=(45, 135, 90, 90))
    pa = [c for c in cam.checks if c.name == "pressure angle"][0]
    assert not pa.ok and pa.value > 30
    assert 0 < pa.worst_deg < 45
    a = np.degrees(cam.pressure_angle(np.radians(np.linspace(0, 45, 4501))))
    assert pa.value >= a.max() - 1e-9 and pa.value - a.max() < 1e-3
    assert f"{pa.worst_deg:.2f} deg" in pa.message


def test_groove_outer_wall_undercut():
    # a groove cam whose concave flank is sharper than the roller: the outer wall cusps
    cam = CamProfile(stroke=0.03, base_radius=0.01, roller_radius=0.012, law="cycloidal",
                     angles_deg=(40, 140, 40, 140), groove=True, max_pressure_angle_deg=89)
    names = {c.name for c in cam.failures}
    assert "undercut outer" in names
    assert cycloid(groove=True).failures == []


def _read_csv(path):
    with open(path) as fh:
        rows = list(csv.reader(fh))
    return rows[0], np.array(rows[1:], dtype=float)


@pytest.mark.parametrize("groove", [False, True])
def test_dxf_reads_back(tmp_path, groove):
    ezdxf = pytest.importorskip("ezdxf")
    cam = cycloid(groove=groove, e=0.004, points_per_degree=3)
    files = cam.write_all(tmp_path)
    head, data = _read_csv(files["csv"])
    col = {h: i for i, h in enumerate(head)}
    doc = ezdxf.readfile(files["dxf"])
    layers = {l.dxf.name for l in doc.layers}
    want = {"PITCH", "PROFILE", "BASE_CIRCLE"} | ({"PROFILE_OUTER"} if groove else set())
    assert want <= layers
    assert groove == ("PROFILE_OUTER" in layers)
    msp = doc.modelspace()
    polys = {p.dxf.layer: p for p in msp.query("LWPOLYLINE")}
    for layer, x, y in (("PITCH", "x_pitch", "y_pitch"), ("PROFILE", "x_profile", "y_profile"),
                        ("PROFILE_OUTER", "x_outer", "y_outer")):
        if layer not in want:
            continue
        p = polys[layer]
        assert p.closed
        v = np.array(list(p.vertices()))
        assert v.shape == (360 * 3, 2)
        assert np.max(np.abs(v[:, 0] - data[:, col[x]] * 1e3)) < 1e-9
        assert np.max(np.abs(v[:, 1] - data[:, col[y]] * 1e3)) < 1e-9
    circles = list(msp.query("CIRCLE"))
    assert len(circles) == 1 and abs(circles[0].dxf.radius - RB * 1e3) < 1e-12
    assert doc.units == ezdxf.units.MM
    # CSV columns as documented
    expect = ["phi_deg", "s", "x_pitch", "y_pitch", "x_profile", "y_profile"]
    expect += ["x_outer", "y_outer"] if groove else []
    expect += ["alpha_deg", "rho_pitch", "rho_profile"] + (["rho_outer"] if groove else [])
    assert head == expect


def test_bad_input_named():
    with pytest.raises(CamdynInputError, match="angles must sum to 360"):
        cycloid(angles_deg=(90, 90, 90, 80))
    with pytest.raises(CamdynInputError, match=r"offset=.*\|offset\| <"):
        cycloid(e=0.05)
    with pytest.raises(CamdynInputError, match="roller-radius"):
        cycloid(rr=0.0)
    with pytest.raises(CamdynInputError, match="stroke"):
        cycloid(h=-1e-3)
    with pytest.raises(CamdynInputError, match="unknown cam law"):
        CamProfile(stroke=H, base_radius=RB, roller_radius=RR, law="nope")


def test_cli_writes_everything(tmp_path, capsys):
    out = tmp_path / "cam"
    rc = main(["profile", "--law", "cycloidal", "--stroke", "0.015", "--base-radius", "0.026",
               "--roller-radius", "0.005", "--offset", "0", "--angles", "90,90,90,90",
               "--groove", "--out", str(out), "--json", "--points-per-degree", "2"])
    assert rc == 0
    cap = capsys.readouterr()
    js = json.loads(cap.out)
    assert js["ok"] and js["kind"] == "groove" and cap.err == ""
    for kind in ("csv", "dxf", "png", "json"):
        assert (out / f"cam.{kind}").stat().st_size > 0
    assert json.loads((out / "cam.json").read_text())["checks"] == js["checks"]
    # a failed check: a warning line naming the angle, and in the JSON; status 1
    rc = main(["profile", "--stroke", "0.015", "--base-radius", "0.008", "--roller-radius",
               "0.004", "--angles", "45,135,90,90", "--out", str(out), "--json",
               "--points-per-degree", "1"])
    cap = capsys.readouterr()
    assert rc == 1
    js = json.loads(cap.out)
    assert not js["ok"]
    warn = [l for l in cap.err.splitlines() if "warning" in l]
    assert len(warn) == 1 and "pressure angle" in warn[0] and "at cam angle" in warn[0]


@pytest.mark.parametrize("argv, names", [
    (["--angles", "90,90,90"], "angles"),
    (["--angles", "90,90,90,x"], "--angles"),
    (["--offset", "0.1"], "offset"),
    (["--base-radius", "-1"], "base-radius"),
    (["--max-pressure-angle", "95"], "max-pressure-angle"),
    (["--law", "nope"], "--law"),
    (["--out", "__a_file__"], "--out"),
    # laws.choose's message said theta; the option is named now
    (["--stroke", "inf"], "stroke=inf is out of range: it must be finite"),   # read 'inf >= 0'
    (["--law-parameter", "0.2"], "law-parameter (cycloidal)"),
    (["--return-law", "modified-sine", "--return-law-parameter", "0.7"],
     "return-law-parameter (modified-sine)"),
    (["--return-law", "cycloidal", "--return-law-parameter", "0.2"],
     "return-law-parameter (cycloidal)"),
])
def test_cli_refuses_bad_input(tmp_path, capsys, argv, names):
    base = {"--stroke": "0.015", "--base-radius": "0.026", "--roller-radius": "0.005",
            "--out": str(tmp_path)}
    for k, v in zip(argv[::2], argv[1::2]):
        base[k] = v
    if base["--out"] == "__a_file__":          # --out naming an existing file, not a folder
        (tmp_path / "f").write_text("")
        base["--out"] = str(tmp_path / "f")
    args = ["profile"] + [x for kv in base.items() for x in kv]
    try:
        rc = main(args)
    except SystemExit as exc:
        rc = exc.code
    assert rc == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and names in err and err.startswith("camdyn profile")


def test_cli_subprocess_one_line(tmp_path):
    r = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "profile", "--stroke", "0.01",
                        "--base-radius", "0.02", "--roller-radius", "0.005",
                        "--angles", "100,100,100,100", "--out", str(tmp_path)],
                       capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stderr.count("\n") == 1 and "sum to 360" in r.stderr


def test_return_law_of_its_own():
    """--return-law: over the return S = h (1 - H(u)) with H the 3-4-5 polynomial
    10u^3 - 15u^4 + 6u^5 written out here, S' = -h 30 u^2 (1 - u)^2 / beta_return (to 1e-12);
    the rise keeps its cycloid; the breakpoints are the return law's; the summary names both."""
    h = 0.015
    cam = CamProfile(stroke=h, base_radius=0.026, roller_radius=0.005,
                     angles_deg=(100.0, 60.0, 120.0, 80.0), law="modified-sine",
                     return_law="3-4-5")
    b_ret, start = np.radians(120.0), np.radians(160.0)
    u = np.linspace(0.0, 1.0, 201, endpoint=False)
    S = cam.cam.displacement(start + b_ret * u)
    np.testing.assert_allclose(S[0], h * (1 - (10 * u**3 - 15 * u**4 + 6 * u**5)), atol=1e-12 * h)
    np.testing.assert_allclose(S[1], -h * 30 * u**2 * (1 - u)**2 / b_ret, atol=1e-12 * h)
    rise = CamProfile(stroke=h, base_radius=0.026, roller_radius=0.005,
                      angles_deg=(100.0, 60.0, 120.0, 80.0), law="modified-sine")
    phi = np.radians(np.linspace(0.0, 100.0, 101, endpoint=False))
    np.testing.assert_array_equal(cam.cam.displacement(phi), rise.cam.displacement(phi))
    # the modified sine's breakpoints 1/8, 7/8 inside the rise only: 3-4-5 has none
    inside = [b for b in cam.cam.breakpoints if start < b < start + b_ret]
    assert inside == []
    summary = cam.summary()
    assert summary["law"] == "modified-sine" and summary["return_law"] == "3-4-5"
    with pytest.raises(CamdynInputError, match="return-law-parameter"):
        CamProfile(stroke=h, base_radius=0.026, roller_radius=0.005, return_law_parameter=0.1)


@pytest.mark.parametrize("e", [0.0, 0.008])
def test_summary_extremes_refined_with_their_sampling_error(e):
    """The summary's largest |alpha| and least |rho_p| are refined between the samples: at one
    sample per degree they agree with a dense independent scan of the closed forms (50,000
    samples per degree of rise) far better than the coarse samples do, and the error each
    carries covers what the coarse samples missed."""
    cam = cycloid(e=e, points_per_degree=1)
    s = cam.summary()
    phi = np.linspace(0.0, 2 * np.pi, 360 * 50_000 + 1)
    a_ref = math.degrees(float(np.max(np.abs(cam.pressure_angle(phi)))))
    rho_ref = 1.0 / float(np.max(np.abs(cam.curvature(phi))))
    coarse = cam.table
    a_coarse = float(np.max(np.abs(coarse["alpha_deg"])))
    rho_coarse = float(np.min(np.abs(coarse["rho_pitch"])))
    assert abs(s["max_abs_pressure_angle_deg"] - a_ref) < 1e-8
    assert abs(s["min_rho_pitch"] - rho_ref) < 1e-10
    assert s["max_abs_pressure_angle_deg_error"] >= abs(a_coarse - a_ref) * 0.99
    assert s["min_rho_pitch_error"] >= abs(rho_coarse - rho_ref) * 0.99
    json.dumps(s, allow_nan=False)
