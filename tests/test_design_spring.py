"""`camdyn design`'s follower spring (secs 4.5.5, 7.5) and flywheel (ch. 5), against an
independent integration of the one-DOF follower (3.1) by SciPy and against closed forms."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from camdyn.runtime.cli import main
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.thesis.design.method import design

H_M, T_M, MASS = 0.05, 0.1, 2.0          # stroke (m), rise time (s), output mass (kg)


def _one_dof(tau: float, T: np.ndarray) -> tuple:
    """X, X', X'', H of (3.1) with the cycloidal rise, by SciPy's DOP853 at rtol 1e-12: the
    rise, then the dwell at H = 1."""
    w2 = (2 * math.pi / tau) ** 2

    def H(t):
        return np.where(t < 1.0, t - np.sin(2 * np.pi * t) / (2 * np.pi), 1.0)

    def f(t, y):
        return [y[1], w2 * (float(H(t)) - y[0])]
    rise = solve_ivp(f, (0, 1), [0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14,
                     dense_output=True)
    dwell = solve_ivp(f, (1, T[-1]), rise.y[:, -1], method="DOP853", rtol=1e-12, atol=1e-14,
                      dense_output=True)
    Y = np.where(T < 1.0, rise.sol(np.minimum(T, 1.0)), dwell.sol(np.maximum(T, 1.0)))
    return Y[0], Y[1], w2 * (H(T) - Y[0]), H(T)


def _design(tau, **kw):
    return design(stroke=H_M, rise_time=T_M, mass=MASS, tau=tau, Fa=0.0, **kw)


@pytest.mark.parametrize("rate", [None, 2000.0])
def test_least_spring_against_an_independent_integration(rate):
    """tau 0.15, margin 0.3: the inertia force, the least preload (for k = 2000 N/m, and with
    no rate), the least rate without preload and the least contact force match the same
    figures from SciPy's integration of (3.1) on 60,001 points to 1e-4 relative, within
    the errors the answer states and a sampling allowance."""
    d = _design(0.15, spring_margin=0.3, spring_rate=rate)
    sp = d["spring"]
    T = np.linspace(0.0, 3.0, 60001)
    X, _, Xdd, _ = _one_dof(0.15, T)
    x, need = X * H_M, 1.3 * (-MASS * Xdd * H_M / T_M**2)
    k = rate or 0.0
    F0 = max(0.0, float(np.max(need - k * x)))
    assert sp["inertia_force_max"] == pytest.approx(np.max(need) / 1.3, rel=1e-4)
    assert sp["preload_min"] == pytest.approx(F0, rel=1e-4)
    assert abs(sp["preload_min"] - F0) <= sp["preload_min_error"] + 1e-4 * F0
    pos = x > 1e-3 * H_M
    assert sp["rate_min_without_preload"] == pytest.approx(np.max(need[pos] / x[pos]), rel=1e-4)
    contact = MASS * Xdd * H_M / T_M**2 + F0 + k * x
    assert sp["contact_force_min"] == pytest.approx(np.min(contact), rel=1e-3, abs=1e-3)
    # the margin holds everywhere: the contact force never falls below mu/(1 + mu) of the need
    assert np.all(contact >= 0.3 / 1.3 * np.maximum(need, 0) - 1e-3 * F0)


def test_spring_surge_is_the_one_dof_follower_of_its_own():
    """f_s = (1/2)(k/m_s)^(1/2): k = 3000 N/m, m_s = 0.04 kg gives f_s = 136.9 Hz, tau_s =
    1/(f_s t_m), and the coils' residual vibration U0(tau_s) equals SciPy's one-DOF run at
    tau_s to 1e-8 (the rise's end state, U0 = |u + i u'/w|)."""
    d = _design(0.15, spring_margin=0.2, spring_rate=3000.0, spring_mass=0.04)
    s = d["spring"]["surge"]
    f_s = 0.5 * math.sqrt(3000.0 / 0.04)
    assert s["f_surge"] == pytest.approx(f_s, rel=1e-15)
    assert s["tau_surge"] == pytest.approx(1 / (f_s * T_M), rel=1e-15)
    X, Xd, _, _ = _one_dof(s["tau_surge"], np.array([1.0 - 1e-15, 1.0]))
    w = 2 * math.pi / s["tau_surge"]
    U0 = math.hypot(X[-1] - 1.0, Xd[-1] / w)
    assert s["U0"] == pytest.approx(U0, abs=1e-8)


def test_flywheel_of_a_stiff_follower_is_the_rigid_closed_form():
    """tau 0.02 (nearly rigid), no spring: the energy swing tends to the follower's largest
    kinetic energy m (h_m' H'max/t_m)^2/2, H'max = 2 for the cycloid, so J = dE/(C_s w_s^2) and
    Fv = m h_m'^2/(J beta_m^2) = 2 C_s/H'max^2 = C_s/2 (5.14b), to 1e-3 (the follower's
    elasticity at tau 0.02)."""
    d = design(stroke=H_M, cam_angle_rad=math.radians(120), speed=200.0, mass=MASS, tau=0.02,
               Fa=0.0, speed_fluctuation=0.04)
    f = d["flywheel"]
    assert f["Fv"] == pytest.approx(0.02, rel=1e-3)
    t_m = math.radians(120) / (200 * 2 * math.pi / 60)
    dE = 0.5 * MASS * (2 * H_M / t_m) ** 2
    assert f["energy_swing"] == pytest.approx(dE, rel=1e-3)
    assert f["J"] == pytest.approx(dE / (0.04 * (200 * 2 * math.pi / 60) ** 2), rel=1e-3)


def test_flywheel_with_a_spring_against_an_independent_integration():
    """tau 0.15, spring k = 2000 N/m at its least preload: the swing of
    m x'^2/2 + c_c (h H - x)^2/2 + F0 x + k x^2/2 over SciPy's run to 1e-5 relative."""
    d = design(stroke=H_M, cam_angle_rad=math.radians(90), speed=150.0, mass=MASS, tau=0.15,
               Fa=0.0, spring_margin=0.3, spring_rate=2000.0, speed_fluctuation=0.05)
    t_m = math.radians(90) / (150 * 2 * math.pi / 60)
    F0 = d["spring"]["preload_min"]
    T = np.linspace(0.0, 3.0, 60001)
    X, Xd, _, H = _one_dof(0.15, T)
    c_c = MASS * (2 * math.pi / (0.15 * t_m)) ** 2
    x, v = X * H_M, Xd * H_M / t_m
    E = 0.5 * MASS * v**2 + 0.5 * c_c * (H * H_M - x) ** 2 + F0 * x + 0.5 * 2000.0 * x**2
    assert d["flywheel"]["energy_swing"] == pytest.approx(np.ptp(E), rel=1e-5)
    assert d["flywheel"]["with_spring"]


@pytest.mark.parametrize("kw, msg", [
    ({"spring_rate": 1000.0}, "--spring-rate: goes with --spring-margin"),
    ({"spring_margin": 0.2, "spring_mass": 0.1}, "--spring-mass: the surge frequency needs"),
    ({"spring_margin": -0.1}, "--spring-margin: -0.1 is out of range: 0 <= margin <= 10"),
    ({"spring_margin": 0.2, "check": False}, "--spring-margin: is read off the check run"),
    ({"speed_fluctuation": 1.5}, "--speed-fluctuation: 1.5 is out of range: 0 < C_s < 1"),
    ({"speed_fluctuation": 0.05}, "--speed-fluctuation: needs the camshaft's speed"),
])
def test_spring_and_flywheel_inputs_are_refused_in_one_line(kw, msg):
    with pytest.raises(CamdynInputError, match=msg.replace("(", r"\(")):
        _design(0.15, **kw)


def test_refused_without_the_mass():
    with pytest.raises(CamdynInputError, match=r"--spring-margin: needs the output's mass"):
        design(stroke=H_M, rise_time=T_M, tau=0.15, Fa=0.0, spring_margin=0.2)


def test_a_rate_that_needs_no_preload_is_said(capsys):
    """k = 3000 N/m at tau 0.12: k x exceeds 1.3 times the inertia force wherever the
    follower decelerates (checked on SciPy's run), so the least preload is 0, and the text
    says what that leaves: no force at rest on the base circle."""
    T = np.linspace(0.0, 3.0, 30001)
    X, _, Xdd, _ = _one_dof(0.12, T)
    assert np.all(3000.0 * X * H_M >= 1.3 * (-MASS * Xdd * H_M / T_M**2) - 1e-9)
    code = main(["design", "--stroke", str(H_M), "--rise-time", str(T_M), "--mass", str(MASS),
                 "--tau", "0.12", "--fa", "0", "--spring-margin", "0.3", "--spring-rate", "3000",
                 "--quiet"])
    out = capsys.readouterr().out
    assert code == 0 and "least preload F0 = 0 " in out
    assert "without a preload the follower rests on the base circle with no force" in out


def test_the_command_prints_spring_and_flywheel_with_errors(capsys):
    code = main(["design", "--stroke", "0.05", "--cam-angle", "90deg", "--speed", "150",
                 "--mass", "2", "--tau", "0.15", "--fa", "0", "--spring-margin", "0.3",
                 "--spring-rate", "2000", "--spring-mass", "0.05", "--speed-fluctuation",
                 "0.05", "--json"])
    assert code == 0
    d = json.loads(capsys.readouterr().out)
    for key in ("preload_min", "inertia_force_max", "peak_spring_force", "contact_force_min"):
        assert d["spring"][f"{key}_error"] >= 0.0
    assert d["spring"]["surge"]["harmonic"] == pytest.approx(
        0.5 * math.sqrt(2000 / 0.05) / 2.5, rel=1e-12)
    assert d["flywheel"]["J_error"] >= 0 and d["flywheel"]["Fv_error"] >= 0
