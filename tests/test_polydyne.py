"""The compensated cam (polydyne) of the one-DOF follower, thesis (3.1).

The law: H = P + (tau_d/2 pi)^2 P'' with P the degree-9 rise 5-6-7-8-9 (P' to P'''' zero at
both ends).  References: at the design tau the output follows P exactly, so the residual
vibration after the rise vanishes (U0 below 1e-9 of the stroke); off the design tau the
residual is checked against an independent integration of X'' = (2 pi/tau)^2 (H - X) by
SciPy with H written out here from the polynomial.
"""
import json
import math

import numpy as np
import pytest
from numpy.polynomial import Polynomial as Poly
from scipy.integrate import solve_ivp

from camdyn.runtime.cli import main
from camdyn.runtime.core import laws

P9 = Poly([0, 0, 0, 0, 0, 126, -420, 540, -315, 70])


def test_degree_nine_rise_and_the_law():
    """P: P(0) = 0, P(1) = 1, derivatives 1..4 zero at both ends; the polydyne's H, H', H''
    from the library equal P + c P'' and its derivatives, H'' zero at both ends."""
    for k in range(1, 5):
        assert abs(P9.deriv(k)(0.0)) < 1e-12 and abs(P9.deriv(k)(1.0)) < 1e-9
    assert P9(1.0) == pytest.approx(1.0, abs=1e-15)
    td = 0.2
    c = (td / (2 * math.pi))**2
    law = laws.choose("polydyne", td)
    T = np.linspace(0.0, 1.0, 101)[:-1]
    got = law.evaluate(T)
    H = P9 + c * P9.deriv(2)
    for k in range(4):
        assert np.max(np.abs(got[:, k] - H.deriv(k)(T))) < 1e-9 * max(1.0, np.max(np.abs(H.deriv(k)(T))))
    assert abs(law.evaluate(np.array([0.0]))[0, 2]) < 1e-12
    plain = laws.choose("5-6-7-8-9").evaluate(T)
    assert np.max(np.abs(plain[:, 0] - P9(T))) < 1e-13


def _u0_scipy(tau, td):
    w = 2 * math.pi / tau
    H = P9 + (td / (2 * math.pi))**2 * P9.deriv(2)
    sol = solve_ivp(lambda t, y: [y[1], w * w * (H(t) - y[0])], (0, 1), [0, 0],
                    method="DOP853", rtol=1e-12, atol=1e-15)
    x, v = sol.y[:, -1]
    return math.hypot(x - 1, v / w)


def _residual(capsys, *argv):
    rc = main(["residual", "--model", "one-dof", "--method", "dop853", "--json", *argv])
    assert rc == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("td", [0.1, 0.25])
def test_residual_vanishes_at_the_design_tau(capsys, td):
    out = _residual(capsys, "--tau", str(td), "--law", "polydyne", "--design-tau", str(td))
    assert out["U0"] < 1e-9
    plain = _residual(capsys, "--tau", str(td), "--law", "5-6-7-8-9")
    assert plain["U0"] > 1e-6 and plain["U0"] > 1e3 * out["U0"]   # the plain cam rings


@pytest.mark.parametrize("tau,td", [(0.15, 0.2), (0.3, 0.2), (0.2, 0.1)])
def test_residual_off_design_against_scipy(capsys, tau, td):
    out = _residual(capsys, "--tau", str(tau), "--law", "polydyne", "--design-tau", str(td))
    ref = _u0_scipy(tau, td)
    assert abs(out["U0"] - ref) < 1e-10       # of the stroke; both runs at rtol <= 1e-10


def test_output_follows_the_degree_nine_rise_at_the_design_tau():
    from camdyn.runtime.core.simulator import simulate

    r = simulate("one_dof", {"tau": 0.2}, 1.0, "dop853", law="polydyne", theta=0.2, rtol=1e-12)
    assert np.max(np.abs(r.y[:, 0] - P9(r.t))) < 1e-10


def test_design_tau_refusals(tmp_path, capsys):
    for argv, name in ((["--law", "cycloidal", "--design-tau", "0.2"], "polydyne"),
                       (["--law", "polydyne", "--design-tau", "1.5"], "tau_d"),
                       (["--law", "polydyne", "--design-tau", "0.2", "--theta", "0.2"], "one")):
        rc = main(["residual", "--model", "one-dof", "--tau", "0.2", *argv])
        err = capsys.readouterr().err.strip().splitlines()
        assert rc == 2 and len(err) == 1 and name in err[0], err


def test_polydyne_command_charts_both(tmp_path, capsys):
    rc = main(["polydyne", "--design-tau", "0.2", "--taus", "0.15:0.25:3", "--out",
               str(tmp_path), "--json", "--quiet"])
    out = json.loads(capsys.readouterr().out)
    assert rc == 0 and out["tau"] == [0.15, 0.2, 0.25]
    assert out["polydyne:U0"][1] < 1e-9 < out["plain:U0"][1]
    assert abs(out["polydyne:U0"][0] - _u0_scipy(0.15, 0.2)) < 1e-9
    assert (tmp_path / "polydyne.png").stat().st_size > 0
    assert json.loads((tmp_path / "polydyne.json").read_text())["design_tau"] == 0.2
    rc = main(["polydyne", "--design-tau", "1.2", "--out", str(tmp_path)])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and "--design-tau" in err[0]


def test_the_cam_of_a_polydyne_rise():
    """camdyn profile with the polydyne law (tau_d 0.2): over the rise the lift is
    h (P + (tau_d/2 pi)^2 P'')(phi/beta) to 1e-12 h, and the return mirrors it; its velocity
    and acceleration against the same polynomial's derivatives, so the pressure angle and the
    curvature come from the compensated motion, not the plain degree-9 rise."""
    from camdyn.runtime.cam.profile import CamProfile

    td, h, beta = 0.2, 0.015, math.radians(90)
    cam = CamProfile(stroke=h, base_radius=0.03, roller_radius=0.005, offset=0.0,
                     angles_deg=(90, 90, 90, 90), law="polydyne", law_parameter=td)
    H = P9 + (td / (2 * math.pi))**2 * P9.deriv(2)
    phi = np.linspace(0.0, beta, 721)
    S = cam.cam.displacement(phi)
    T = phi / beta
    assert np.abs(S[0] - h * H(T)).max() < 1e-12 * h
    assert np.abs(S[1] - h * H.deriv(1)(T) / beta).max() < 1e-10 * h / beta
    assert np.abs(S[2] - h * H.deriv(2)(T) / beta**2).max() < 1e-9 * h / beta**2
    ret = np.radians(180.0) + phi          # the return: H mirrored over its 90 deg
    assert np.abs(cam.cam.displacement(ret)[0] - h * H(1.0 - T)).max() < 1e-12 * h
