"""Tight tests behind the wide ones.

Comparisons with numbers read from the thesis's diagrams need wide tolerances (sec. 7.4.7:
errors up to 20 % are satisfactory), and a wrong formula can hide inside them: dropping the
square on the torsion term of m_tan (5.51) makes Fv 11 % low and moves the sec. 8.2.4 factor
only from 2.44 to 2.40 against the thesis's 2.45 +- 10 %.  So each quantity those tests read
is also pinned here to an independent reference:

* tau, Fa, Fv and the sums behind them, for every built-in DYNACAM scene, computed by hand
  from the scene file with the thesis's formulas, and against the digits App. 7 and fig. 8.1
  print;
* exact members of the model ladder: the two-DOF DYNACAM variant is CAMSHAFT-2 (5.15),
  (5.16); a cam of huge inertia gives the one-DOF model (3.1); a massless, tangentially
  flexible shaft with rigid torsion under an axial cam gives CAMSHAFT-1 (4.15);
* the sec. 8.2 model comparison (fig. 8.3 curves (4)-(6)) against SciPy integrations of the
  4-DOF equations, (5.15)-(5.16) and (4.15) written out here.

Units: SI, reduced to the output member (sec. 2.4); X = x/h_m', T = t/t_m, tau = T_e/t_m.
"""
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import minimize_scalar

import camdyn.runtime
from camdyn.derive.models.dynacam import Options
from camdyn.runtime.targets import dynacam, scene_files as scenes
from camdyn.runtime.core.methods import DP54
from camdyn.runtime.measure.extremes import extreme
from camdyn.runtime.core.simulator import simulate

SCENE_DIR = Path(camdyn.runtime.__file__).parent / "scenes"
# the DYNACAM mechanisms with a translating roller (default.toml is the CAMSHAFT-1 study,
# beam_paper.toml the beam follower; the rocker's numbers take its ratios to the contact and are
# held in tests/test_dynacam_followers.py)
SCENES = sorted(p.stem for p in SCENE_DIR.glob("*.toml")
                if tomllib.loads(p.read_text()).get("kind") == "dynacam"
                and not any(tomllib.loads(p.read_text())["options"].get(k) for k in ("rocker", "flat_face")))
KEYS = ("tau", "Fa", "Fv", "t_m", "c_c", "m", "tan_alpha_me", "c_tan", "m_tan")
ODE = dict(method="DOP853", rtol=1e-12, atol=1e-15)


def _raw(name: str) -> dict:
    """The scene file as TOML, read without camdyn."""
    with open(SCENE_DIR / f"{name}.toml", "rb") as f:
        return tomllib.load(f)


def _by_hand(options: dict, p: dict) -> dict:
    """App. 7's chain from the mechanism's data to tau, Fa, Fv, written out from the thesis.

    Compliances add in series: 1/c_c = 1/c_x + 1/c_z' (4.3), 1/c_tan = 1/c_beta' + 1/c_y' (4.4),
    the torsion reduced to the pitch circle as c_beta' = k/R_1/2^2 with inertia J/R_1/2^2
    (sec. 2.4).  R_1/2 = R_b + h_m/2 on a radial cam (4.1); an axial cam turns the roller at
    its constant pitch radius R_b (sec. 4.2.5).  Masses by the static deflection shape:
    m = m_x + m_z' ((1/c_z')/(1/c_c))^2 (4.39), (5.50); m_tan = m_beta' ((1/c_beta')/(1/c_tan))^2
    + m_y' ((1/c_y')/(1/c_tan))^2 (5.51).  tan alpha_me = h_m/(R_1/2 beta_m) (4.13);
    Fa = (c_c/c_tan) tan^2 alpha_me (4.14); Fv = (m/m_tan) tan^2 alpha_me (5.52);
    T_e = 2 pi (m/c_c)^(1/2) (4.11), t_m = beta_m/w_s, tau = T_e/t_m (4.12).
    """
    shaft_y, shaft_z = options.get("shaft_y", True), options.get("shaft_z", True)
    radius = p["R_b"] + p["h_m"] / 2 if options.get("cam", "radial") == "radial" else p["R_b"]
    flex_c = 1 / p["c_x"] + (1 / p["c_z"] if shaft_z else 0.0)
    m = p["m_x"] + (p["m_z"] * (1 / p["c_z"] / flex_c) ** 2 if shaft_z else 0.0)
    flex_beta = radius**2 / p["k"]
    flex_tan = flex_beta + (1 / p["c_y"] if shaft_y else 0.0)
    m_tan = p["J"] / radius**2 * (flex_beta / flex_tan) ** 2
    if shaft_y:
        m_tan += p["m_y"] * (1 / p["c_y"] / flex_tan) ** 2
    slope = p["h_m"] / (radius * p["beta_m"])
    t_m = p["beta_m"] / p["omega_s"]
    return {"tau": 2 * math.pi * math.sqrt(m * flex_c) / t_m, "Fa": flex_tan / flex_c * slope**2,
            "Fv": m / m_tan * slope**2, "t_m": t_m, "c_c": 1 / flex_c, "m": m,
            "tan_alpha_me": slope, "c_tan": 1 / flex_tan, "m_tan": m_tan}


# -- 1. characteristic numbers of the built-in scenes ------------------------------------------

def test_every_dynacam_scene_is_covered():
    """The parametrized tests below take the scene list from the folder: it must hold the five
    DYNACAM scenes the docs name (so the parametrization cannot run empty)."""
    assert {"fig8_1a", "fig8_1b", "indexing", "indexing_squeeze", "spring_loaded"} <= set(SCENES)


@pytest.mark.parametrize("name", SCENES)
def test_the_contact_form_is_the_thesis_s_for_a_translating_roller(name):
    """dynacam.contact_form, which rockers and flat faces use, at the translating roller's
    ratios (tan alpha_me, 1) gives (4.3)-(5.52) of the scene: all nine numbers to 1e-12."""
    sc = scenes.load(name)
    want = dynacam.characteristics(sc.options, sc.parameters)
    got = dynacam.contact_form(sc.options, sc.parameters, *dynacam.mean_ratios(sc.options, sc.parameters))
    for key in KEYS:
        assert got[key] == pytest.approx(want[key], rel=1e-12), key


@pytest.mark.parametrize("name", SCENES)
def test_characteristics_of_every_scene_by_hand(name):
    """camdyn's dynacam.characteristics of the loaded scene against _by_hand from the TOML
    (App. 7, (4.3), (4.4), (4.11)-(4.14), (4.39), (5.50)-(5.52)), all nine numbers to 1e-12
    relative; measured: equal to rounding (<= 3e-16).  The reviewer's mutation, m_tan without
    the square on the torsion term, puts Fv 11 % low in fig8_1a, 27 % in indexing, 1.6 % in
    spring_loaded, 0.9 % in fig8_1b: all caught."""
    raw = _raw(name)
    sc = scenes.load(name)
    got = dynacam.characteristics(sc.options, sc.parameters)
    want = _by_hand(raw["options"], raw["parameters"])
    for key in KEYS:
        assert got[key] == pytest.approx(want[key], rel=1e-12), key


@pytest.mark.parametrize("options", [dict(shaft_y=False, shaft_z=False), dict(shaft_y=False),
                                     dict(shaft_z=False), dict(cam="axial"),
                                     dict(cam="axial", shaft_z=False)])
def test_characteristics_of_other_option_sets_by_hand(options):
    """The branches the scenes do not take (no y' or no z' deflection, axial cam), on
    fig8_1a's numbers, against _by_hand to 1e-12 relative (measured: rounding)."""
    p = _raw("fig8_1a")["parameters"]
    got = dynacam.characteristics(Options(**options), p)
    want = _by_hand(options, p)
    for key in KEYS:
        assert got[key] == pytest.approx(want[key], rel=1e-12), key


PRINTED = [
    # scene, key, printed value, unit of its last digit, where printed
    ("fig8_1a", "tau", 0.161, 1e-3, "fig. 8.1a, 8.3a"),
    ("fig8_1a", "Fa", 1.64, 1e-2, "fig. 8.1a, 8.3a"),
    ("fig8_1a", "Fv", 2.42, 1e-2, "fig. 8.1a, 8.3a"),
    ("fig8_1a", "m", 1.46, 1e-2, "fig. 8.1b, A.7.3 (6)"),
    ("fig8_1b", "tau", 0.141, 1e-3, "fig. 8.1b, 8.3b"),
    ("fig8_1b", "Fa", 2.04, 1e-2, "fig. 8.1b, 8.3b"),
    ("fig8_1b", "Fv", 2.68, 1e-2, "fig. 8.1b, 8.3b"),
    ("fig8_1b", "m", 1.46, 1e-2, "fig. 8.1b, A.7.3 (6)"),
    ("spring_loaded", "c_c", 0.37e6, 0.01e6, "fig. A.7.7, table 7-I"),
    ("spring_loaded", "m", 1.46, 1e-2, "A.7.3 (6)"),
    ("spring_loaded", "t_m", 0.088, 1e-3, "A.7.3 (8)"),
    ("spring_loaded", "flex_tan", 26.14e-6, 0.01e-6, "A.7.3 (10)"),
    ("spring_loaded", "Fa", 2.04, 1e-2, "A.7.3 (12)"),
    ("spring_loaded", "m_tan", 0.116, 1e-3, "A.7.3.2"),
] + [(name, *row) for name in ("indexing", "indexing_squeeze") for row in (
    ("c_c", 3.65e6, 0.01e6, "A.7.2 (5)"),
    ("m", 45.0, 1.0, "fig. 7.14"),
    ("T_e", 2.2e-2, 0.1e-2, "A.7.2 (7)"),
    ("t_m", 0.278, 1e-3, "A.7.2 (8)"),
    ("tau", 0.08, 1e-2, "A.7.2 (9), fig. 7.14"),
    ("flex_tan", 6.365e-6, 0.001e-6, "A.7.2 (10)"),
    ("tan_alpha_me", 0.379, 1e-3, "A.7.2 (11)"),
    ("Fa", 3.34, 1e-2, "A.7.2 (12), fig. 7.14"),
    ("Fv", 7.5, 0.1, "fig. A.7.3, table 5-I"),
)]


@pytest.mark.parametrize("name, key, printed, unit, where", PRINTED)
def test_scene_gives_the_printed_value(name, key, printed, unit, where):
    """The scene's numbers (camdyn's characteristics) against what the thesis prints, to the
    printed digits: within half a unit of the last printed digit.  flex_tan is 1/c_tan,
    T_e = tau t_m.  Closest calls: indexing Fa 3.3353 (printed 3.34), spring_loaded Fa 2.0351
    (printed 2.04)."""
    sc = scenes.load(name)
    ch = dynacam.characteristics(sc.options, sc.parameters)
    ch = {**ch, "flex_tan": 1 / ch["c_tan"], "T_e": ch["tau"] * ch["t_m"]}
    assert abs(ch[key] - printed) <= 0.5 * unit, f"{key} of {name}: {ch[key]:.6g}, {where} prints {printed}"


@pytest.mark.parametrize("name", ["fig8_1a", "fig8_1b", "spring_loaded"])
def test_mean_slope_of_the_spring_loaded_follower(name):
    """tan alpha_me = 15 mm/(75 mm 0.436) = 0.4587 (A.7.3 (11), fig. 8.1), printed 0.458: the
    thesis cuts the digits off here, so the bound is one unit of the last printed digit."""
    sc = scenes.load(name)
    ch = dynacam.characteristics(sc.options, sc.parameters)
    assert 0.458 <= ch["tan_alpha_me"] < 0.459
    assert ch["tan_alpha_me"] == pytest.approx(15 / (75 * 0.436), rel=1e-3)


def test_spring_loaded_tau_and_Fv_where_the_thesis_disagrees_with_itself():
    """A.7.3 prints T_e = 1.24e-2 s and tau = 0.141 from c_c = 0.376e6 N/m (A.7.3 (5)), but
    Fa = 2.04 and fig. A.7.7 from c_c = 0.37e6 N/m; and Fv = 2.68 although its own m = 1.46 kg,
    tan alpha_me and m_tan = 0.116 kg give m tan^2/m_tan = 2.65 (5.52).  The scene keeps
    c_c = 0.37e6 and m_tan = 0.116, so its tau and Fv are those of the printed inputs
    (to 1e-6: the scene rounds m_x to 7 digits), 1.0 % and 1.2 % off the printed results;
    asserted within 1.5 % of them."""
    sc = scenes.load("spring_loaded")
    ch = dynacam.characteristics(sc.options, sc.parameters)
    slope = 15 / (75 * 0.436)
    assert ch["tau"] == pytest.approx(2 * math.pi * math.sqrt(1.46 / 0.37e6) / ch["t_m"], rel=1e-6)
    assert ch["Fv"] == pytest.approx(1.46 * slope**2 / 0.116, rel=1e-6)
    assert ch["tau"] == pytest.approx(0.141, rel=0.015)
    assert ch["Fv"] == pytest.approx(2.68, rel=0.015)


# -- 2. exact members of the model ladder ------------------------------------------------------

# the spring-loaded follower's geometry (scenes/*.toml), undamped, cycloidal rise
GEOMETRY = dict(h_m=0.0309, beta_m=0.436, R_b=0.13905, omega_s=4.974188, q_b=0.0, q_x=0.0)
T_M = GEOMETRY["beta_m"] / GEOMETRY["omega_s"]
M = 1.46
TAU = 0.161
C = M * (2 * math.pi / (TAU * T_M)) ** 2       # tau = 2 pi (m/c)^(1/2)/t_m (4.11), (4.12)
T_GRID = np.linspace(0.0, 1.5, 601)


def _dynacam(options: dict, params: dict):
    """A DYNACAM run from T = -0.1 (dwell) to 1.5 at rtol 1e-12; returns the scene and result."""
    sc = scenes.from_dict({"law": "cycloidal", "options": options,
                           "parameters": {**GEOMETRY, **params},
                           "run": {"T_start": -0.1, "T_end": 1.5, "rtol": 1e-12}})
    _, res = dynacam.run(sc, method=DP54(rtol=1e-12))
    return sc, res


def _on_grid(sc, res) -> dict:
    """X = x/h_m, X'' and B of a DYNACAM run at T_GRID (nominal T, dense output)."""
    smp = res.sample((T_GRID - sc.T_start) * T_M)
    return {"X": smp["x"] / GEOMETRY["h_m"], "Xdd": smp["Xdd"], "B": smp["B"]}


def _rel(a, b):
    return np.max(np.abs(a - b)) / np.max(np.abs(b))


@pytest.fixture(scope="module")
def one_dof():
    return simulate("one_dof", {"tau": TAU}, 1.5, "dp54", rtol=1e-12).sample(T_GRID)


def test_two_dof_variant_is_camshaft2():
    """Without the shaft deflections (variant radial_ideal_rigidgear_bilateral) DYNACAM is J beta'' = k (w_s t - beta) -
    F_x dh/dbeta, m_x x'' = c_x (h(beta) - x); with B = beta/beta_m, T = t/t_m this is (5.15),
    (5.16) exactly, at Fv = m_x h_m^2/(J beta_m^2) (5.14), Fa = c_x h_m^2/(k beta_m^2)
    (5.12b) and tau_b^2 = tau^2 Fa/Fv, and characteristics gives those numbers (R_1/2 cancels).
    J, k are set from fig. 8.1a's printed tau = 0.161, Fa = 1.64, Fv = 2.42.  X, B to 1e-9
    and X'' to 1e-9 of its peak against camshaft2 over 0 <= T <= 1.5, both at rtol 1e-12;
    measured 4e-14, 9e-14, 4e-12."""
    Fa, Fv = 1.64, 2.42
    k = C * GEOMETRY["h_m"] ** 2 / (Fa * GEOMETRY["beta_m"] ** 2)
    J = M * GEOMETRY["h_m"] ** 2 / (Fv * GEOMETRY["beta_m"] ** 2)
    sc, res = _dynacam(dict(shaft_y=False, shaft_z=False), dict(m_x=M, c_x=C, k=k, J=J))
    assert sc.variant == "dynacam_radial_ideal_rigidgear_bilateral"
    ch = dynacam.characteristics(sc.options, sc.parameters)
    assert (ch["tau"], ch["Fa"], ch["Fv"]) == pytest.approx((TAU, Fa, Fv), rel=1e-12)
    got = _on_grid(sc, res)
    want = simulate("camshaft2", {"tau": TAU, "Fa": Fa, "Fv": Fv}, 1.5, "dp54", rtol=1e-12)
    want = want.sample(T_GRID)
    assert np.max(np.abs(got["X"] - want["X"])) < 1e-9
    assert np.max(np.abs(got["B"] - want["B"])) < 1e-9
    assert _rel(got["Xdd"], want["Xdd"]) < 1e-9


def test_huge_cam_inertia_gives_the_one_dof_model(one_dof):
    """Fv -> 0 (J -> infinity): the cam turns at w_s and radial_ideal_rigidgear_bilateral is (3.1), X'' = (2 pi/tau)^2 (H - X)
    (sec. 5.7 (2): 'Fv = 0 means that the mass of the cam is infinite ... the starting point of
    the model of chapter 3').  No variant has beta fixed, so this is a limit: beta lags w_s t
    by the contact torque's double integral over J, and the error in X is proportional to Fv,
    measured max|X - X_1dof| = 1.08 Fv (0 <= T <= 1.5).  Asserted: the error at Fv = 1e-5 is 10 times
    that at 1e-6 (+- 2 %; measured 9.998), and at Fv = 1e-10 X is within 1e-8 and X'' within
    1e-8 of its peak of one_dof at rtol 1e-12 (measured 1e-10 and 9e-10)."""
    k = C * GEOMETRY["h_m"] ** 2 / (1.64 * GEOMETRY["beta_m"] ** 2)
    J_unit = M * GEOMETRY["h_m"] ** 2 / GEOMETRY["beta_m"] ** 2       # J at Fv = 1

    def error(Fv):
        sc, res = _dynacam(dict(shaft_y=False, shaft_z=False), dict(m_x=M, c_x=C, k=k, J=J_unit / Fv))
        got = _on_grid(sc, res)
        return np.max(np.abs(got["X"] - one_dof["X"])), _rel(got["Xdd"], one_dof["Xdd"])

    assert error(1e-5)[0] / error(1e-6)[0] == pytest.approx(10.0, rel=0.02)
    dX, dXdd = error(1e-10)
    assert dX < 1e-8 and dXdd < 1e-8


def test_four_dof_with_rigid_heavy_shaft_and_cam_is_the_one_dof_model(one_dof):
    """The 4-DOF variant radial_ideal_rigidgear_bilateral_shafty_shaftz with the shaft's y', z' stiffness 1e15 N/m and mass 1e9 kg
    (deflection F/c ~ 1e-13 m, natural frequency 1e3 rad/s, so not stiff) and J = 1e9 kg m^2
    (Fv ~ 1e-11): (3.1) at the characteristics' tau, which is 0.161 to 1e-9 (c_c, m of (4.3),
    (4.39) move by 3e-10).  X to 1e-8, X'' to 1e-8 of its peak; measured 1.1e-11, 1.7e-9."""
    big = 1e9
    sc, res = _dynacam({}, dict(m_x=M, c_x=C, k=1000.0, J=big, m_y=big, c_y=1e6 * big, m_z=big,
                                c_z=1e6 * big, q_y=0.0, q_z=0.0))
    assert sc.variant == "dynacam_radial_ideal_rigidgear_bilateral_shafty_shaftz"
    assert dynacam.characteristics(sc.options, sc.parameters)["tau"] == pytest.approx(TAU, rel=1e-9)
    got = _on_grid(sc, res)
    assert np.max(np.abs(got["X"] - one_dof["X"])) < 1e-8
    assert _rel(got["Xdd"], one_dof["Xdd"]) < 1e-8


def test_massless_tangential_shaft_under_an_axial_cam_is_camshaft1():
    """CAMSHAFT-1 (4.15) as a limit of DYNACAM.  Sec. 4.2-4.3.1 derive it with the cam masses
    m_beta', m_y' small against m_x (sec. 4.2.2), so y' and beta follow the contact force
    statically, and need (4.8), dh'/dbeta = h'/w_s, only because the torsion turns the cam off
    w_s t; (4.10) puts R_1/2 for R(beta) (sec. 4.2.5).  All three are exact when the torsion
    is rigid (k = 1e12 N m/rad; J = 1e9 kg m^2 only keeps the torsion mode slow, so not stiff:
    beta = w_s t to 1e-11), the tangential compliance is the bending 1/c_y' alone, the cam
    axial (R = R_b) and m_y' -> 0: then c_y' y = F_x tan alpha with tan alpha = tan alpha_me H'
    (6.20), (6.22), so F_x = c_x (h - x)/(1 + Fa H'^2), Fa = c_x tan^2 alpha_me/c_y' (4.14).
    m_tan (5.51) -> 0 with m_y', so this is sec. 5.7's 'Fv = oo means that there is no cam mass
    at all ... the characteristics Fv = oo agree with those of the CAMSHAFT-1' (Fv = 8400 at
    the eps below).  z' is held by m_z' = 1e9 kg, c_z' = 1e15 N/m, so c_c = c_x.
    The variant axial_ideal_rigidgear_bilateral_shafty_shaftz keeps m_y' > 0 and the limit is singular (stiff), so it is taken by
    extrapolation: the error in X is proportional to eps = m_y'/m_x (0.17 eps measured;
    doubling eps doubles it, asserted within 5 %, measured 2.0001) and the Richardson value
    2 X(eps) - X(2 eps) at eps = 2.5e-5 is within 1e-8 of camshaft1 (measured 1.1e-9; X''
    within 2e-7 of its peak, measured 5.5e-8).  characteristics gives tau = 0.161 and Fa = 2
    to 1e-8 (measured 4e-10).  A radial cam in the same limit misses by 9e-3 (R varies)."""
    Fa = 2.0
    radius = GEOMETRY["R_b"] + GEOMETRY["h_m"] / 2
    slope = GEOMETRY["h_m"] / (radius * GEOMETRY["beta_m"])
    want = simulate("camshaft1", {"tau": TAU, "Fa": Fa}, 1.5, "dp54", rtol=1e-12).sample(T_GRID)

    def run(eps):
        sc, res = _dynacam(dict(cam="axial"), dict(
            R_b=radius, m_x=M, c_x=C, k=1e12, J=1e9, m_y=eps * M, c_y=C * slope**2 / Fa,
            m_z=1e9, c_z=1e15, q_y=0.0, q_z=0.0))
        assert sc.variant == "dynacam_axial_ideal_rigidgear_bilateral_shafty_shaftz"
        ch = dynacam.characteristics(sc.options, sc.parameters)
        assert (ch["tau"], ch["Fa"]) == pytest.approx((TAU, Fa), rel=1e-8)
        return _on_grid(sc, res)

    eps = 2.5e-5
    fine, coarse = run(eps), run(2 * eps)
    e_fine = np.max(np.abs(fine["X"] - want["X"]))
    e_coarse = np.max(np.abs(coarse["X"] - want["X"]))
    assert e_coarse / e_fine == pytest.approx(2.0, rel=0.05)
    assert np.max(np.abs(2 * fine["X"] - coarse["X"] - want["X"])) < 1e-8
    assert _rel(2 * fine["Xdd"] - coarse["Xdd"], want["Xdd"]) < 2e-7


# -- 3. the sec. 8.2 comparison against independent integrations ------------------------------

def _cycloid(B: float) -> tuple:
    """H, dH/dB, d2H/dB2 of the cycloidal rise (A.2.8)-(A.2.10), dwell before and after."""
    if B <= 0.0:
        return 0.0, 0.0, 0.0
    if B >= 1.0:
        return 1.0, 0.0, 0.0
    s = 2 * math.pi * B
    return B - math.sin(s) / (2 * math.pi), 1 - math.cos(s), 2 * math.pi * math.sin(s)


def _four_dof_Xdd(p: dict, T_start: float, T_end: float):
    """X''(T) of the undamped 4-DOF model (radial cam, constant input speed, rigid gear,
    roller held on the cam: fig. 8.3 curves (4)) by DOP853 at rtol 1e-12.

    Equations of ch. 6 from the energies 1/2 J beta'^2 + 1/2 m_y y'^2 + 1/2 m_z z'^2 +
    1/2 m_x x'^2 and 1/2 k (w_s t - beta)^2 + 1/2 c_y y^2 + 1/2 c_z z^2 + 1/2 c_x (h_c - x)^2,
    the contact point h_c = h(beta) - y tan alpha - z (6.22), tan alpha = (dh/dbeta)/R,
    R = R_b + h (6.20), (6.21).  The cam law's breakpoints B = 0, 1 end the pieces.
    """
    t_m = p["beta_m"] / p["omega_s"]
    beta_0 = -T_start * p["beta_m"]

    def contact(q):
        beta, y, z, x = q[:4]
        H, H1, H2 = _cycloid((beta - beta_0) / p["beta_m"])
        h, dh, d2h = p["h_m"] * H, p["h_m"] * H1 / p["beta_m"], p["h_m"] * H2 / p["beta_m"] ** 2
        R = p["R_b"] + h
        tan = dh / R
        F = p["c_x"] * (h - y * tan - z - x)
        return F, tan, dh - y * (d2h / R - dh**2 / R**2)     # F_x, tan alpha, dh_c/dbeta

    def rhs(t, q):
        beta, y, z, _ = q[:4]
        F, tan, dhc = contact(q)
        return [*q[4:], (p["k"] * (p["omega_s"] * t - beta) - F * dhc) / p["J"],
                (F * tan - p["c_y"] * y) / p["m_y"], (F - p["c_z"] * z) / p["m_z"], F / p["m_x"]]

    def reaches(level):
        def g(t, q):
            return (q[0] - beta_0) / p["beta_m"] - level
        g.terminal, g.direction = True, 1
        return g

    t_end = (T_end - T_start) * t_m
    q = np.array([0.0, 0.0, 0.0, 0.0, p["omega_s"], 0.0, 0.0, 0.0])   # at rest in the dwell
    t0, pieces = 0.0, []
    for event in (reaches(0.0), reaches(1.0), None):
        s = solve_ivp(rhs, (t0, t_end), q, dense_output=True, events=event, **ODE)
        pieces.append((s.t[-1], s.sol))
        t0, q = s.t[-1], s.y[:, -1]

    def Xdd(T):
        t = (T - T_start) * t_m
        sol = next(sol for end, sol in pieces if t <= end)
        return contact(sol(t))[0] / p["m_x"] * t_m**2 / p["h_m"]
    return Xdd


def _largest(f, a: float, b: float) -> float:
    """max |f| on [a, b]: a scan of 2001 points, refined by bounded Brent."""
    T = np.linspace(a, b, 2001)
    v = np.abs([f(x) for x in T])
    k = int(np.argmax(v))
    bounds = (T[max(k - 1, 0)], T[min(k + 1, len(T) - 1)])
    r = minimize_scalar(lambda x: -abs(f(x)), bounds=bounds, method="bounded", options={"xatol": 1e-12})
    return max(-r.fun, v[k])


def _dwell_amplitude(X, Xd, w):
    """U0'' of the free vibration X'' = w^2 (1 - X) that follows the rise: exact amplitude."""
    return w**2 * math.hypot(X - 1, Xd / w)


def _camshaft2_U0dd(tau, Fa, Fv, T_end=1.5):
    """(5.15), (5.16) with B(0) = 0, B'(0) = 1 up to B = 1, then the dwell amplitude.

    After B = 1, H = 1 and dH/dB = 0, so X is a free undamped vibration; the dwell window
    (from B = 1 to T_end, as camdyn.runtime.measure.residual takes it) holds a peak of |X''| when it
    is longer than tau/2, so U0'' is the amplitude.
    """
    w = 2 * math.pi / tau

    def rhs(T, y):
        X, B, Xd, Bd = y
        H, H1, _ = _cycloid(B)
        Xdd = w**2 * (H - X)
        return [Xd, Bd, Xdd, w**2 * Fv / Fa * (T - B) - Fv * Xdd * H1]

    def rise_end(T, y):
        return y[1] - 1.0
    rise_end.terminal, rise_end.direction = True, 1
    s = solve_ivp(rhs, (0.0, T_end), [0.0, 0.0, 0.0, 1.0], events=rise_end, **ODE)
    assert s.status == 1 and T_end - s.t[-1] > tau
    return _dwell_amplitude(s.y[0, -1], s.y[2, -1], w)


def _camshaft1_U0dd(tau, Fa):
    """(4.15) over the rise, then the dwell amplitude (H' = 0 there: the one-DOF vibration)."""
    w = 2 * math.pi / tau

    def rhs(T, y):
        H, H1, _ = _cycloid(T)
        return [y[1], w**2 * (H - y[0]) / (1 + Fa * H1**2)]
    s = solve_ivp(rhs, (0.0, 1.0), [0.0, 0.0], **ODE)
    return _dwell_amplitude(s.y[0, -1], s.y[1, -1], w)


def _m_z_0_2(p: dict) -> dict:
    """m_z' = 0.2 kg with m_x' raised to keep m = 1.46 kg (4.39): the same tau, Fa, Fv."""
    share = (1 / (1 + p["c_z"] / p["c_x"])) ** 2        # (c_c/c_z)^2
    return {"m_z": 0.2, "m_x": p["m_x"] + (p["m_z"] - 0.2) * share}


CASES = {   # case: (scene, parameter changes from its file)
    "fig8_1a": ("fig8_1a", lambda p: {}),
    "fig8_1b": ("fig8_1b", lambda p: {}),
    "fig8_1a_m_z_0.2": ("fig8_1a", _m_z_0_2),
    "fig8_1a_half_J": ("fig8_1a", lambda p: {"J": p["J"] / 2}),
}


@pytest.fixture(scope="module")
def ladder():
    """Per case: camdyn's run and reduced_models (as thesis/checks/dynacam_checks.py forms them),
    the refined U0'' of its dense output, and the independent U0'' of the 4-, 2- and 1-DOF
    models at the hand-computed tau, Fa, Fv."""
    out = {}
    for case, (name, change) in CASES.items():
        raw = _raw(name)
        p = {**raw["parameters"], **change(raw["parameters"])}
        hand = _by_hand(raw["options"], p)
        sc = scenes.replace(scenes.load(name), parameters=p)
        summary, res = dynacam.run(sc)
        t_dwell = (1 - sc.T_start) * summary["characteristics"]["t_m"]
        Xdd = _four_dof_Xdd(p, sc.T_start, sc.T_end)
        out[case] = dict(
            sc=sc, res=res, camdyn=dynacam.reduced_models(sc, summary),
            refined_4dof=extreme(res, "Xdd", t_dwell, res.t[-1], absolute=True, minimum=False)[0],
            ref={"4dof": _largest(Xdd, 1.0, sc.T_end),
                 "2dof": _camshaft2_U0dd(hand["tau"], hand["Fa"], hand["Fv"], sc.T_end),
                 "1dof": _camshaft1_U0dd(hand["tau"], hand["Fa"])},
            Xdd=Xdd)
    return out


@pytest.mark.parametrize("case", CASES)
def test_reduced_models_at_the_hand_computed_characteristics(ladder, case):
    """dynacam.reduced_models (the 2- and 1-DOF U0'' of sec. 8.2.4, 8.2.5, fig. 8.3 curves (5),
    (6)) against (5.15)-(5.16) and (4.15) integrated here at the tau, Fa, Fv computed by hand
    from the scene, to 1e-8 relative (measured <= 3e-9).  With m_tan missing the square on its
    torsion term (Fv 11 % low) CAMSHAFT-2's U0'' on fig8_1a moves 1.7 %, a million times the
    tolerance."""
    got, ref = ladder[case]["camdyn"], ladder[case]["ref"]
    assert got["2dof"] == pytest.approx(ref["2dof"], rel=1e-8)
    assert got["1dof"] == pytest.approx(ref["1dof"], rel=1e-8)


@pytest.mark.parametrize("case", CASES)
def test_four_dof_run_against_an_independent_integration(ladder, case):
    """The scene's DYNACAM run (DP54 at the scene's rtol 1e-8, as test_dynacam.py and the
    checks run it) against _four_dof_Xdd at rtol 1e-12: X'' over -0.1 <= T <= 1.5 within 2e-6
    of its peak (measured <= 6e-7; 6e-10 with camdyn at rtol 1e-12), and U0'' refined on the
    dense output (1 < T < 1.5) to 3e-6 relative (measured 9e-8, 4e-10, 8e-7, 1.4e-7: camdyn's
    error at rtol 1e-8)."""
    c = ladder[case]
    sc, res = c["sc"], c["res"]
    T = np.linspace(sc.T_start, sc.T_end, 801)
    t_m = sc.parameters["beta_m"] / sc.parameters["omega_s"]
    got = res.sample((T - sc.T_start) * t_m)["Xdd"]
    want = np.array([c["Xdd"](x) for x in T])
    assert _rel(got, want) < 2e-6
    assert c["refined_4dof"] == pytest.approx(c["ref"]["4dof"], rel=3e-6)


@pytest.mark.parametrize("case, near", [("fig8_1a", 2.44), ("fig8_1b", 1.01), ("fig8_1a_m_z_0.2", 1.35),
                                        ("fig8_1a_half_J", None)])
def test_sec_8_2_4_factor_moves_with_the_model(ladder, case, near):
    """The factor U0''(2 DOF)/U0''(4 DOF) that test_dynacam.py and the checks compare with the
    thesis's 2.45 and 1.08 at +-10 %, formed as they form it (summary U0'' over the recorded
    steps, reduced_models), against the independent one to 2e-4 (the summary's U0'' is the
    largest recorded value, not refined: 7.4e-5 low on fig8_1a; measured agreement 7.4e-5,
    1.2e-6, 2.9e-5, 2.5e-5).  The independent factor itself moves: 2.441 (fig. 8.1a), 1.012
    (fig. 8.1b), 1.349 with m_z' = 0.2 kg at the same tau, Fa, Fv (the 1.35 test_dynacam.py's
    docstring quotes), and 2.476 with J halved (Fv doubled; asserted: it moves by over 1 %).
    The reviewer's m_tan mutation moves camdyn's factor on fig8_1a by 1.7 %."""
    c = ladder[case]
    mine = c["ref"]["2dof"] / c["ref"]["4dof"]
    theirs = c["camdyn"]["2dof"] / c["camdyn"]["4dof"]
    assert theirs == pytest.approx(mine, rel=2e-4)
    if near is not None:
        assert mine == pytest.approx(near, abs=0.005)
    else:
        base = ladder["fig8_1a"]["ref"]
        assert abs(mine / (base["2dof"] / base["4dof"]) - 1) > 0.01
