"""The dry backlash laws of DYNACAM against hand-computable answers.

Two force elements of the generated ``dynacam_axial_ideal_backlash_groove_shafty_shaftz`` (axial cam, constant input speed,
gear="backlash", roller="groove"; the thesis's indexing mechanism, scenes/indexing.toml):

* the reduction gear, backlash s_g (6.1): shaft torque M = k (phi_r - beta) + d_b (phi' - beta')
  (6.10) with the gear output phi_r = phi on the driving flank, phi + s_g on the back flank,
  and M = 0 in between (the wheel is massless);
* the roller in its groove, backlash s_r (6.27): the linkage c_x, d_x (6.42) is compressed by
  the lower wall (h_c - x > 0) or the upper one (x - h_c - s_r > 0), and carries nothing in
  between.

Dry contact law (the dynacam docstring): the spring-damper engages when the gap closes and
releases when the spring's deflection is zero again.  The squeeze film of (6.5)-(6.9),
(6.37)-(6.41) is the other variant (axial_ideal_gearsqueeze_groovesqueeze_shafty_shaftz, tests/test_nonsmooth.py); here it is absent
(the limit eta -> 0 of (6.6), (6.38)).

The mechanisms are tiny: the cam stays in the dwell before its rise (beta < beta_0, so H = H'
= H'' = 0, tan(alpha) = 0 (6.20) and h_c = -z (6.22)).  Then the contact force does no work
on beta or y, and the rotation (beta, the gear) and the translation (x, z, the groove) are
two independent systems, each solved by hand below.  The element not under test is parked
in the middle of its backlash, where nothing acts.  Every run starts in mode "free" with
explicit initial states, so the answers are exact up to the integration.

Each answer is checked at two tolerances of the integrator: rtol = 1e-8 with large steps
over the force-free flights (these once hid a located contact at the end of a long step, the
event search returning the far end of its bracket when the secant hit the root exactly) and
rtol = 1e-12.
"""
import math

import numpy as np
import pytest

from camdyn.runtime.core.compiled import load
from camdyn.runtime.core.simulator import Simulator

MODEL = "dynacam_axial_ideal_backlash_groove_shafty_shaftz"

# rtol -> relative tolerances on event times and on the closed forms (speeds, forces, gaps,
# relative to their scale).  Measured: rtol 1e-8, event times within 4.1e-9 and closed forms
# within 3.3e-8; rtol 1e-12, within 6e-13 and 3.5e-12.
TOLERANCES = {1e-8: (2e-8, 2e-7), 1e-12: (5e-12, 2e-11)}

# gear test: omega_s = 2 rad/s, s_g = 0.01 rad, J = 0.01 kg m^2, k = 100 N m/rad:
# w = (k/J)^(1/2) = 100 rad/s, (k J)^(1/2) = 1 N m s/rad
W_S, S_G, J, K = 2.0, 0.01, 0.01, 100.0
# groove test: s_r = 0.1 mm, m_x = 1 kg, m_z = 3 kg, c_x = 7500 N/m: mu = m_x m_z/(m_x + m_z)
# = 0.75 kg, w = (c_x/mu)^(1/2) = 100 rad/s; approach velocity v = 0.02 m/s
S_R, M_X, M_Z, C_X, V = 1e-4, 1.0, 3.0, 7500.0, 0.02
# the shaft's stiffness along the follower made negligible (c_z > 0 is required): the cam body
# is then a free mass m_z in z; its restoring force c_z z < 1e-12 N against forces of 1 N
C_Z_FREE = 1e-9


def _params(**extra):
    p = dict(beta_0=10.0, omega_s=W_S, J=J, k=K, q_b=0.0, m_x=M_X, c_x=C_X, q_x=0.0,
             m_z=M_Z, c_z=C_Z_FREE, q_z=0.0, q_y=0.0, s_g=S_G, s_r=S_R)
    p.update(extra)
    return p


def _run(y0: dict, t_end: float, rtol: float, **params):
    m = load(MODEL)
    y = np.zeros(len(m.state_names))
    for name, value in y0.items():
        y[m.state_names.index(name)] = value
    sim = Simulator(m, t_end, "dp54", rtol=rtol, y0=y, modes={"gear": "free", "roller": "free"})
    return sim.run(_params(**params))


def _switches(res, mode: str) -> list:
    """(t, new value, index of the right limit) at every switch of ``mode``."""
    v = res.element_mode(mode)
    return [(float(res.t[i + 1]), v[i + 1], i + 1) for i in np.flatnonzero(v[1:] != v[:-1])]


def _gear_deflection(r):
    """phi - beta = omega_s t - beta from the states (a run's record or a dense sample): the
    torsion spring's deflection on the driving flank, the gap while free."""
    return W_S * r["t"] - r["beta"]


def _roller_position(r):
    """x - h_c = x + z from the states (h_c = -z in the dwell, (6.22)): the follower over the
    lower wall, s_r + the upper spring's compression while on the upper wall."""
    return r["x"] + r["z"]


def _gear_run(rtol, t_end, **params):
    """Cam at rest on the back flank (phi - beta = -s_g at t = 0, phi = omega_s t), the roller
    parked mid-groove."""
    return _run({"beta": S_G, "x": S_R / 2}, t_end, rtol, **params)


def _groove_run(rtol, t_end, **params):
    """Follower leaving the lower wall (x = h_c = 0) upwards at v, cam body at rest; the gear
    parked mid-backlash with the cam turning at the input speed (phi - beta = -s_g/2)."""
    return _run({"beta": S_G / 2, "betad": W_S, "xd": V}, t_end, rtol, **params)


# ---------------------------------------------------------------------------------------------
# reduction gear, dry backlash s_g


@pytest.mark.parametrize("rtol", sorted(TOLERANCES))
def test_gear_backlash_traverse_then_ramp_into_the_shaft_spring(rtol):
    """Traverse, then the sudden engagement of the torsion spring (6.10), (sec. 3.6 ramp).

    Free (M = 0): the cam rests, the gap phi - beta = omega_s t - s_g closes at
    t_1 = s_g/omega_s = 5 ms.  Drive (q_b = 0): with tau = t - t_1 and r = phi - beta,
    J r'' = -k r, r(0) = 0, r'(0) = omega_s, so
        r = (omega_s/w) sin(w tau),  beta' = omega_s (1 - cos w tau),
        M = k r = omega_s (k J)^(1/2) sin(w tau),  w = (k/J)^(1/2),
    the ramp response: peak torque omega_s (kJ)^(1/2) = 2 N m at w tau = pi/2, and the spring
    unloads (r = 0) at w tau = pi with the cam at twice the input speed, 2 omega_s = 4 rad/s.
    """
    tol_t, tol_y = TOLERANCES[rtol]
    w = math.sqrt(K / J)
    t1, t2 = S_G / W_S, S_G / W_S + math.pi / w
    res = _gear_run(rtol, 0.04)
    sw = _switches(res, "gear")
    assert [v for _, v, _ in sw[:2]] == ["drive", "free"]
    assert sw[0][0] == pytest.approx(t1, rel=tol_t)
    assert sw[1][0] == pytest.approx(t2, rel=tol_t)
    # the free flight: no torque, the cam at rest
    before = res.t < t1
    assert np.all(res["torque"][before] == 0.0) and np.all(res["betad"][before] == 0.0)
    # the engaged phase against the closed form, through the dense output
    tau = np.linspace(0.0, math.pi / w, 41)[1:-1]
    s = res.sample(t1 + tau)
    scale = W_S * math.sqrt(K * J)
    assert np.allclose(s["betad"], W_S * (1 - np.cos(w * tau)), rtol=0, atol=tol_y * 2 * W_S)
    assert np.allclose(s["torque"], scale * np.sin(w * tau), rtol=0, atol=tol_y * scale)
    assert np.allclose(_gear_deflection(s), W_S / w * np.sin(w * tau), rtol=0, atol=tol_y * W_S / w)
    # the peak torque and the release speed
    assert res.sample([t1 + math.pi / (2 * w)])["torque"][0] == pytest.approx(scale, rel=tol_y)
    k2 = sw[1][2]
    assert res["betad"][k2] == pytest.approx(2 * W_S, rel=tol_y)
    assert abs(_gear_deflection(res)[k2]) < tol_y * W_S / w


@pytest.mark.parametrize("rtol", sorted(TOLERANCES))
def test_gear_backlash_cycle_of_the_unloaded_cam(rtol):
    """With nothing loading the cam (the dwell) and no damping, the motion is periodic.

    After the release at 2 omega_s (previous test) the cam runs ahead of the gear at the
    relative speed omega_s, crosses the backlash in s_g/omega_s and hits the back flank
    (M = k (phi + s_g - beta), the cam ahead by s_g); that half-wave of pi/w brings it back
    to rest (beta' = 2 omega_s - omega_s (1 - cos w tau) = 0 at w tau = pi) with the gap at
    -s_g, the start.  With a = s_g/omega_s, b = pi/w the switches are
        drive a, free a+b, back 2a+b, free 2a+2b, drive 3a+2b, ... (period 2a + 2b),
    the cam speed after them 0, 2 omega_s, 2 omega_s, 0, and the back flank's torque
    -omega_s (kJ)^(1/2) at its extreme.
    """
    tol_t, tol_y = TOLERANCES[rtol]
    w = math.sqrt(K / J)
    a, b = S_G / W_S, math.pi / w
    res = _gear_run(rtol, 2 * (2 * a + 2 * b) + 0.006)
    sw = _switches(res, "gear")
    expected = []
    for n in range(2):
        t0 = n * (2 * a + 2 * b)
        expected += [(t0 + a, "drive", 0.0), (t0 + a + b, "free", 2 * W_S),
                     (t0 + 2 * a + b, "back", 2 * W_S), (t0 + 2 * a + 2 * b, "free", 0.0)]
    assert [v for _, v, _ in sw] == [v for _, v, _ in expected] + ["drive"]
    for (t, v, k), (te, ve, wde) in zip(sw, expected):
        assert t == pytest.approx(te, rel=tol_t), v
        assert res["betad"][k] == pytest.approx(wde, abs=tol_y * 2 * W_S), v
    # the back flank: the torque reverses, -omega_s (kJ)^(1/2) at mid-contact
    t_back = expected[2][0] + b / 2
    assert res.sample([t_back])["torque"][0] == pytest.approx(-W_S * math.sqrt(K * J), rel=tol_y)
    # while free, phi - beta stays within the backlash [-s_g, 0]
    free = res.element_mode("gear") == "free"
    r = _gear_deflection(res)[free]
    assert np.all(r <= tol_y * S_G) and np.all(r >= -S_G * (1 + tol_y))


@pytest.mark.parametrize("rtol", sorted(TOLERANCES))
def test_gear_backlash_damped_engagement_releases_on_the_deflection(rtol):
    """Damped shaft, q_b = 0.1: d_b = 2 q_b (kJ)^(1/2) (6.47) makes the relative motion
    J r'' + d_b r' + k r = 0 underdamped with zeta = q_b exactly, so, from r(0) = 0,
    r'(0) = omega_s at the engagement t_1 = s_g/omega_s,
        r = (omega_s/w_d) exp(-zeta w tau) sin(w_d tau),  w_d = w (1 - zeta^2)^(1/2).
    The damper takes the load at once: M(t_1+) = d_b omega_s = 0.4 N m.  The spring releases
    at r = 0, tau = pi/w_d, not where M = 0: there r' = -omega_s e with the restitution
    e = exp(-zeta pi/(1 - zeta^2)^(1/2)) = 0.72925, so the cam leaves at omega_s (1 + e) and
    the damper pulls, M(release-) = -d_b omega_s e.  The cam then runs ahead at omega_s e and
    hits the back flank s_g/(omega_s e) later.
    """
    tol_t, tol_y = TOLERANCES[rtol]
    q = 0.1
    w = math.sqrt(K / J)
    wd = w * math.sqrt(1 - q * q)
    d_b = 2 * q * math.sqrt(K * J)
    e = math.exp(-q * math.pi / math.sqrt(1 - q * q))
    t1 = S_G / W_S
    t2 = t1 + math.pi / wd
    t3 = t2 + S_G / (W_S * e)
    res = _gear_run(rtol, t3 + 0.002, q_b=q)
    sw = _switches(res, "gear")
    assert [v for _, v, _ in sw[:3]] == ["drive", "free", "back"]
    (ta, _, ka), (tb, _, kb), (tc, _, _) = sw[:3]
    assert ta == pytest.approx(t1, rel=tol_t)
    assert res["torque"][ka] == pytest.approx(d_b * W_S, rel=tol_y)
    assert tb == pytest.approx(t2, rel=tol_t)
    assert res["torque"][kb - 1] == pytest.approx(-d_b * W_S * e, rel=tol_y)
    assert res["betad"][kb] == pytest.approx(W_S * (1 + e), rel=tol_y)
    assert tc == pytest.approx(t3, rel=tol_t)
    tau = np.linspace(0.0, math.pi / wd, 41)[1:-1]
    r = W_S / wd * np.exp(-q * w * tau) * np.sin(wd * tau)
    assert np.allclose(_gear_deflection(res.sample(t1 + tau)), r, rtol=0, atol=tol_y * W_S / w)


# ---------------------------------------------------------------------------------------------
# roller in the cam groove, dry backlash s_r


@pytest.mark.parametrize("rtol", sorted(TOLERANCES))
def test_groove_backlash_traverse_and_impact_on_the_upper_wall(rtol):
    """Traverse of the groove, then the linkage spring as a two-body impact.

    Free: x = v t, the walls at rest (h_c = -z = 0, upper wall at s_r): the roller reaches
    the upper wall at t_1 = s_r/v = 5 ms.  Upper (q_x = 0): the compression
    r = x - h_c - s_r = x + z - s_r of c_x between the follower m_x and the cam body m_z
    (m_x x'' = -c_x r, m_z z'' = F_x = -c_x r (6.15)) obeys mu r'' = -c_x r,
    mu = m_x m_z/(m_x + m_z), r'(0) = v:
        r = (v/w) sin(w tau),  F_x = -v (c_x mu)^(1/2) sin(w tau),  w = (c_x/mu)^(1/2),
    and releases at tau = pi/w with the relative velocity reversed (an elastic impact):
    momentum m_x v conserved, x' = v (m_x - m_z)/(m_x + m_z) = -v/2 and the cam wall
    h_c' = -z' = 2 m_x v/(m_x + m_z) = +v/2.
    """
    tol_t, tol_y = TOLERANCES[rtol]
    mu = M_X * M_Z / (M_X + M_Z)
    w = math.sqrt(C_X / mu)
    t1, t2 = S_R / V, S_R / V + math.pi / w
    res = _groove_run(rtol, t2 + 0.002)
    sw = _switches(res, "roller")
    assert [v for _, v, _ in sw[:2]] == ["upper", "free"]
    assert sw[0][0] == pytest.approx(t1, rel=tol_t)
    assert sw[1][0] == pytest.approx(t2, rel=tol_t)
    before = res.t < t1
    assert np.all(res["Fx"][before] == 0.0)
    tau = np.linspace(0.0, math.pi / w, 41)[1:-1]
    s = res.sample(t1 + tau)
    F = V * math.sqrt(C_X * mu)
    assert np.allclose(s["Fx"], -F * np.sin(w * tau), rtol=0, atol=tol_y * F)
    assert np.allclose(_roller_position(s), S_R + V / w * np.sin(w * tau), rtol=0, atol=tol_y * V / w)
    assert res.sample([t1 + math.pi / (2 * w)])["Fx"][0] == pytest.approx(-F, rel=tol_y)
    k2 = sw[1][2]
    assert res["xd"][k2] == pytest.approx(V * (M_X - M_Z) / (M_X + M_Z), rel=tol_y)
    assert -res["zd"][k2] == pytest.approx(2 * M_X * V / (M_X + M_Z), rel=tol_y)
    assert _roller_position(res)[k2] == pytest.approx(S_R, rel=tol_y)
    # the gear, parked, never switched; the tangential shaft saw no force (tan alpha = 0)
    assert set(res.element_mode("gear")) == {"free"}
    assert np.all(res["y"] == 0.0)


@pytest.mark.parametrize("rtol", sorted(TOLERANCES))
def test_groove_backlash_cycle_between_the_walls(rtol):
    """After the upper impact (previous test) the follower falls at v/2 and the lower wall
    rises at v/2: the backlash closes at the relative speed v, after s_r/v.  The elastic
    impact on the lower wall (compression h_c - x, same mu and w) reverses the relative
    velocity again: with the centre of mass at v m_x/(m_x + m_z) = v/4, x' = v and h_c' = 0,
    the start.  With a = s_r/v, b = pi/w the switches are
        upper a, free a+b, lower 2a+b, free 2a+2b, upper 3a+2b, ...,
    the follower speed after them v, -v/2, -v/2, v.  The linkage force is +v (c_x mu)^(1/2)
    at mid-contact on the lower wall.
    """
    tol_t, tol_y = TOLERANCES[rtol]
    mu = M_X * M_Z / (M_X + M_Z)
    w = math.sqrt(C_X / mu)
    a, b = S_R / V, math.pi / w
    res = _groove_run(rtol, 2 * (2 * a + 2 * b) + 0.006)
    sw = _switches(res, "roller")
    expected = []
    for n in range(2):
        t0 = n * (2 * a + 2 * b)
        expected += [(t0 + a, "upper", V), (t0 + a + b, "free", -V / 2),
                     (t0 + 2 * a + b, "lower", -V / 2), (t0 + 2 * a + 2 * b, "free", V)]
    assert [v for _, v, _ in sw] == [v for _, v, _ in expected] + ["upper"]
    for (t, v, k), (te, ve, xde) in zip(sw, expected):
        assert t == pytest.approx(te, rel=tol_t), v
        assert res["xd"][k] == pytest.approx(xde, rel=tol_y), v
    F = V * math.sqrt(C_X * mu)
    assert res.sample([expected[2][0] + b / 2])["Fx"][0] == pytest.approx(F, rel=tol_y)
    # momentum m_x x' + m_z h_c' = m_x v throughout (only the linkage acts between them)
    assert np.allclose(M_X * res["xd"] - M_Z * res["zd"], M_X * V, rtol=0, atol=tol_y * M_X * V)


@pytest.mark.parametrize("rtol", sorted(TOLERANCES))
def test_groove_backlash_damped_impact_restitution(rtol):
    """Damped linkage, q_x = 0.1: d_x = 2 q_x (m_x c_x)^(1/2) (6.47) on the compression r
    gives mu r'' + d_x r' + c_x r = 0 with zeta = d_x/(2 (mu c_x)^(1/2)) = q_x (m_x/mu)^(1/2)
    = 0.11547.  The contact releases at r = 0, tau = pi/w_d, w_d = w (1 - zeta^2)^(1/2), with
    the relative velocity -v e, e = exp(-zeta pi/(1 - zeta^2)^(1/2)); from momentum
    conservation x' = v (m_x - e m_z)/(m_x + m_z) and h_c' = v m_x (1 + e)/(m_x + m_z).  At
    the engagement the damper alone carries F_x = -d_x v.  The lower wall then closes the
    backlash at the relative speed v e, after s_r/(v e).
    """
    tol_t, tol_y = TOLERANCES[rtol]
    q = 0.1
    mu = M_X * M_Z / (M_X + M_Z)
    w = math.sqrt(C_X / mu)
    zeta = q * math.sqrt(M_X / mu)
    wd = w * math.sqrt(1 - zeta**2)
    e = math.exp(-zeta * math.pi / math.sqrt(1 - zeta**2))
    d_x = 2 * q * math.sqrt(M_X * C_X)
    t1 = S_R / V
    t2 = t1 + math.pi / wd
    t3 = t2 + S_R / (V * e)
    res = _groove_run(rtol, t3 + 0.002, q_x=q)
    sw = _switches(res, "roller")
    assert [v for _, v, _ in sw[:3]] == ["upper", "free", "lower"]
    (ta, _, ka), (tb, _, kb), (tc, _, _) = sw[:3]
    assert ta == pytest.approx(t1, rel=tol_t)
    assert res["Fx"][ka] == pytest.approx(-d_x * V, rel=tol_y)
    assert tb == pytest.approx(t2, rel=tol_t)
    assert res["xd"][kb] == pytest.approx(V * (M_X - e * M_Z) / (M_X + M_Z), rel=tol_y)
    assert -res["zd"][kb] == pytest.approx(V * M_X * (1 + e) / (M_X + M_Z), rel=tol_y)
    assert tc == pytest.approx(t3, rel=tol_t)
