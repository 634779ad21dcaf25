"""The nonsmooth force elements of DYNACAM against hand-computable answers.

Each test puts a generated variant into a configuration small enough to solve by hand.
"""
import math

import numpy as np
import pytest

from camdyn.runtime.engine import driver
from camdyn.runtime.core import laws
from camdyn.runtime.core.compiled import load
from camdyn.runtime.core.simulator import Simulator


def _p(model, **values):
    return model.parameter_vector(values)


def test_squeeze_film_approach_velocity_A_4_11():
    """(A.4.11), (6.41): with no linkage damping (q_x = 0) and the cam in its dwell, the roller
    approaches the lower groove wall at h_r' = -N gap^(3/2)/V_R, N = c_x (h_r - x) the load it
    carries.  Checked on the generated axial_ideal_gearsqueeze_groovesqueeze_shafty_shaftz at several gaps and loads, to 1e-12."""
    m = load("dynacam_axial_ideal_gearsqueeze_groovesqueeze_shafty_shaftz")
    p = _p(m, q_x=0.0, V_R=2e-5, c_x=1e6, beta_0=0.5)
    choice = laws.choose("cycloidal")
    codes, pars = np.array([choice.code], dtype=np.intc), np.array([choice.par])
    names = m.state_names
    for gap, load_N in ((1e-5, 50.0), (4e-5, 200.0), (1e-4, 10.0)):
        y = np.zeros(len(names))
        y[names.index("betad")] = 1.0            # turning, still in the dwell before beta_0
        y[names.index("hr")] = gap                # h_c = 0 in the dwell: the gap is h_r
        y[names.index("x")] = gap - load_N / 1e6  # linkage compressed by N/c_x
        f = driver.eval_rhs(m.capsule, p, codes, pars, np.zeros(1), y[None, :])[0]
        expected = -load_N * gap**1.5 / 2e-5
        assert f[names.index("hr")] == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("flank", ["driving", "back"])
def test_gear_squeeze_film_closes_on_the_loaded_flank_6_9(flank):
    """(6.5)-(6.9): the output wheel phi_r lies between the driving flank phi (film AA =
    (phi_r - phi)^(-3/2), (6.7)) and the back flank phi + s_g (BB, (6.8)); with no shaft
    damping (q_b = 0) the massless wheel moves at phi_r' = phi' - N gap^(3/2)/V_T, N = k (phi_r -
    beta) the torque it passes on, so the loaded film closes: driving torque (N > 0) on the
    driving flank, reversed torque on the back flank.  Generated axial_ideal_gearsqueeze_groovesqueeze_shafty_shaftz at t = 0 (phi = 0),
    to 1e-12."""
    m = load("dynacam_axial_ideal_gearsqueeze_groovesqueeze_shafty_shaftz")
    V_T, k, s_g, w_s = 2e-4, 5e3, 1e-2, 3.0
    p = _p(m, q_b=0.0, V_T=V_T, k=k, s_g=s_g, omega_s=w_s, beta_0=0.5)
    choice = laws.choose("cycloidal")
    codes, pars = np.array([choice.code], dtype=np.intc), np.array([choice.par])
    names = m.state_names
    for gap, torque in ((1e-5, 20.0), (3e-4, 5.0)):
        y = np.zeros(len(names))
        y[names.index("betad")] = w_s
        if flank == "driving":
            y[names.index("phir")] = gap
            N = torque
        else:
            y[names.index("phir")] = s_g - gap
            N = -torque
        y[names.index("beta")] = y[names.index("phir")] - N / k
        f = driver.eval_rhs(m.capsule, p, codes, pars, np.zeros(1), y[None, :])[0]
        rate = f[names.index("phir")] - w_s       # d(phi_r - phi)/dt
        assert rate == pytest.approx(-N * gap**1.5 / V_T, rel=1e-12)
        closing = -rate if flank == "driving" else rate
        assert closing > 0


def test_follower_jump_where_the_spring_can_no_longer_hold_the_follower():
    """Roller contact law (mode contact/free, sec. 7.5): a stiff mechanism (tau = 0.0063) at
    constant cam speed follows the nominal cycloid, so the roller lifts off where the nominal
    inertia force m x''(T) first overcomes the spring preload F_0 (c_s = 0):
    2 pi (h_m/t_m^2) m sin 2 pi T = -F_0, i.e. T = 1/2 + asin(F_0 t_m^2/(2 pi m h_m))/(2 pi).
    Tolerance 0.003 in T (the dynamic deviation is of order (2 pi tau)^2)."""
    m = load("dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring")
    h_m, F_0 = 0.01, 0.05
    p = _p(m, h_m=h_m, beta_m=1.0, beta_0=0.1, R_b=1.0, omega_s=1.0, J=1e6, k=1e9, q_b=0.05,
           m_x=1.0, c_x=1e6, q_x=0.05, m_y=1.0, c_y=1e9, q_y=0.05, m_z=1.0, c_z=1e9, q_z=0.05,
           F_0=F_0, c_s=0.0)
    y0 = np.zeros(len(m.state_names))
    y0[m.state_names.index("betad")] = 1.0
    y0[m.state_names.index("x")] = -F_0 / 1e6        # preload equilibrium, c_z, c_y >> c_x
    sim = Simulator(m, 1.2, "dp54", rtol=1e-9, y0=y0)
    res = sim.run(dict(zip(m.parameter_names, p)))
    free = res.element_mode("roller") == "free"
    assert free.any()
    T_lift = res.t[np.flatnonzero(free)[0]] - 0.1
    expected = 0.5 + math.asin(F_0 / (2 * math.pi * h_m)) / (2 * math.pi)
    assert T_lift == pytest.approx(expected, abs=0.003)
    # the roller leaves where the linkage is unloaded (delta = 0: the contact law is on the
    # spring's deflection, so its damper may pull briefly), located as an event, not stepped over
    k = np.flatnonzero(free)[0]
    assert np.all(res["roller_gap"][:k] <= 1e-12)
    assert abs(res["roller_gap"][k]) < 1e-12


def test_stick_slip_threshold_of_linkage_friction():
    """Coulomb friction in the linkage (6.43), initially sticking: with the follower held, the
    contact force grows by c h_m H(T) over the preload F_0 (c = c_x c_z/(c_x + c_z), the cam
    turning at constant speed); sticking breaks when that growth reaches the static limit
    1.001 nu (F_0 + growth), i.e. c h_m H(T) = 1.001 nu F_0/(1 - 1.001 nu).  The cycloid's
    H(T) = T - sin(2 pi T)/(2 pi) is inverted numerically.  Tolerance 1e-3 relative in H."""
    m = load("dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_camfriction_linkfriction_spring")
    h_m, F_0, nu, c_x, c_z = 0.01, 5.0, 0.1, 1e6, 1e9
    p = _p(m, h_m=h_m, beta_m=1.0, beta_0=0.1, R_b=1.0, omega_s=1.0, J=1e6, k=1e9, q_b=0.05,
           m_x=1.0, c_x=c_x, q_x=0.0, m_y=1.0, c_y=1e9, q_y=0.05, m_z=1.0, c_z=c_z, q_z=0.0,
           F_0=F_0, c_s=0.0, nu_b=0.0, nu_x=nu)
    c = c_x * c_z / (c_x + c_z)
    y0 = np.zeros(len(m.state_names))
    y0[m.state_names.index("betad")] = 1.0
    # preload equilibrium: the shaft yields by F_0/c_z, the linkage is compressed by F_0/c_x
    y0[m.state_names.index("z")] = F_0 / c_z
    y0[m.state_names.index("x")] = -F_0 / c_z - F_0 / c_x
    sim = Simulator(m, 0.4, "dp54", rtol=1e-10, y0=y0)
    res = sim.run(dict(zip(m.parameter_names, p)))
    fric = res.element_mode("linkfric")
    assert fric[0] == "stick"
    k = np.flatnonzero(fric != "stick")[0]
    T_break = res.t[k] - 0.1
    H = T_break - math.sin(2 * math.pi * T_break) / (2 * math.pi)
    s = 1.001 * nu
    assert c * h_m * H == pytest.approx(s * F_0 / (1 - s), rel=1e-3)
    assert fric[k] == "forward"


@pytest.mark.parametrize("mode, sign", [("forward", -1.0), ("backward", 1.0)])
def test_cam_friction_torque_6_13(mode, sign):
    """(6.13): slipping, the friction on the cam opposes its rotation with the torque
    nu_b |F_x| R (1 + tan^2 alpha)^(1/2).  In the dwell before the rise tan alpha = 0 and
    R = R_b (+ h = 0), so turning the friction on changes the cam's angular acceleration by
    -/+ nu_b |F_x| R_b/J.  F_x is read from the generated outputs, the rest by hand; generated
    radial_ideal_rigidgear_contact_shafty_shaftz_camfriction_linkfriction_spring at a state with the linkage compressed, to 1e-12 relative."""
    m = load("dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_camfriction_linkfriction_spring")
    nu, R_b, J = 0.2, 0.08, 0.003
    base = dict(R_b=R_b, J=J, beta_0=0.5, F_0=20.0, c_s=100.0, nu_x=0.0, q_x=0.0)
    choice = laws.choose("cycloidal")
    codes, pars = np.array([choice.code], dtype=np.intc), np.array([choice.par])
    names = m.state_names
    y = np.zeros(len(names))
    y[names.index("betad")] = 4.0
    y[names.index("x")] = -3e-5                 # roller pressed onto the cam
    modes = np.array([m.manifest["modes"][j]["values"].index(v) for j, v in
                      enumerate(("contact", mode, "forward"))], dtype=np.intc)
    assert [s["name"] for s in m.manifest["modes"]] == ["roller", "camfric", "linkfric"]
    acc = {}
    for key, nu_b in (("with", nu), ("without", 0.0)):
        p = _p(m, **base, nu_b=nu_b)
        f = driver.eval_rhs(m.capsule, p, codes, pars, np.zeros(1), y[None, :], element_modes=modes)[0]
        out = driver.eval_outputs(m.capsule, p, codes, pars, np.zeros(1), y[None, :],
                                      element_modes=modes)[0]
        acc[key] = f[names.index("betad")]
        Fx = out[m.output_names.index("Fx")]
    assert abs(Fx) > 1.0
    assert acc["with"] - acc["without"] == pytest.approx(sign * nu * abs(Fx) * R_b / J, rel=1e-12)


@pytest.mark.parametrize("mode", ["drive", "driven"])
def test_worm_gear_passes_the_shaft_torque_with_its_efficiency_6_71(mode):
    """(6.71), (6.72): driving, the motor supplies the shaft torque M over the worm gear's
    efficiency eta = tan(a)/tan(a + mu) (0.87 at a = 0.36 rad, mu = 0.05, App. 5); driven back,
    it receives M eta' with eta' = tan(a - mu)/tan(a).  On the generated radial_motor2_rigidgear_contact_shafty_shaftz_spring the motor's
    speed deviation then changes at (M_ea - M_ma)/J_ma (A.5.8): checked with M and M_ea read
    from the outputs, to 1e-12 relative."""
    m = load("dynacam_radial_motor2_rigidgear_contact_shafty_shaftz_spring")
    a, mu, J_ma = 0.36, 0.05, 2.0
    p = _p(m, alpha_w=a, mu_w=mu, J_ma=J_ma, beta_0=0.5)
    choice = laws.choose("cycloidal")
    codes, pars = np.array([choice.code], dtype=np.intc), np.array([choice.par])
    names = m.state_names
    y = np.zeros(len(names))
    y[names.index("betad")] = 4.0
    y[names.index("phi")] = 0.02                 # shaft wound up: M = k (phi - beta) > 0
    y[names.index("Mea")] = 3.0
    modes = np.zeros(len(m.manifest["modes"]), dtype=np.intc)
    specs = m.manifest["modes"]
    w = [s["name"] for s in specs].index("worm")
    modes[w] = specs[w]["values"].index(mode)
    f = driver.eval_rhs(m.capsule, p, codes, pars, np.zeros(1), y[None, :], element_modes=modes)[0]
    out = driver.eval_outputs(m.capsule, p, codes, pars, np.zeros(1), y[None, :], element_modes=modes)[0]
    M = out[m.output_names.index("torque")]
    assert M > 1.0
    eta = math.tan(a) / math.tan(a + mu)
    assert eta == pytest.approx(0.87, abs=0.005)
    M_ma = M / eta if mode == "drive" else M * math.tan(a - mu) / math.tan(a)
    assert f[names.index("dw")] == pytest.approx((3.0 - M_ma) / J_ma, rel=1e-12)
