"""DYNACAM runs of the two measured mechanisms against what thesis ch. 7 reports.

The scenes (camdyn/runtime/scenes/*.toml) carry App. 7's data; the splits the scan
lost are taken as the scene files say, so the tolerances here are those of reading a
measured diagram (the thesis itself calls errors up to 20 % satisfactory, sec. 7.4.7).
"""
import math

import numpy as np
import pytest

from camdyn.runtime.targets import dynacam, scene_files as scenes
from camdyn.runtime.core.methods import DP54

NOMINAL_MAX = 2 * math.pi      # cycloid: max |H''| = 2 pi (A.2.10)


@pytest.fixture(scope="module")
def spring_loaded():
    sc = scenes.load("spring_loaded")
    return sc, *dynacam.run(sc)


def _at_tau(sc, tau):
    """The scene at another tau, by the cam speed (tau = T_e w_s/beta_m)."""
    ch = dynacam.characteristics(sc.options, sc.parameters)
    return scenes.replace(sc, parameters={"omega_s": sc.parameters["omega_s"] * tau / ch["tau"]})


def test_spring_loaded_deceleration_sec_7_4_2(spring_loaded):
    """Sec. 7.4.2 (fig. 7.12): 'the maximum deceleration at T = 0.8 exceeds the maximum nominal
    deceleration by a factor of 2.2', and the residual amplitude exceeds the maximum nominal
    acceleration.  Tolerance: the factor within 2.2 +- 25 %, its T within 0.8 +- 0.15."""
    _, s, _ = spring_loaded
    factor = -s["Xdd_min_rise"] / NOMINAL_MAX
    assert factor == pytest.approx(2.2, rel=0.25)
    assert s["T_at_Xdd_min"] == pytest.approx(0.8, abs=0.15)
    assert s["U0dd"] > NOMINAL_MAX
    assert not s["jump"]["occurs"]


def test_spring_loaded_fictitious_speed_fig_7_12(spring_loaded):
    """Sec. 7.6 (fig. 7.12): the fictitious angular velocity varies 'up to a maximum of 40 %';
    tolerance +- 25 % of that."""
    _, s, _ = spring_loaded
    assert s["speed_variation_max"] == pytest.approx(0.40, rel=0.25)


def test_motor_speed_varies_under_2_percent(spring_loaded):
    """Sec. A.5.4.3: the asynchronous motor's speed varies by under 2 % (1.6 % measured, 1.8 %
    simulated, for the mechanism of fig. A.5.7)."""
    _, s, _ = spring_loaded
    assert 0 < s["motor_speed_variation_max"] < 0.02


def test_follower_jump_at_tau_0_16_sec_7_5(spring_loaded):
    """Sec. 7.5 (figs 7.21, 7.22): with the spring of fig. 7.21 the follower jumps at tau = 0.16,
    Fa = 2.04.  The spring is not legible; the scene's F_0, c_s hold the roller at the
    scene's tau = 0.141 (no jump there) and the same spring lets it jump at 0.16."""
    sc, s, _ = spring_loaded
    fast = _at_tau(sc, 0.16)
    s16, res = dynacam.run(fast)
    assert s16["tau"] == pytest.approx(0.16, rel=1e-9)
    assert s16["Fa"] == pytest.approx(s["Fa"], rel=1e-12)
    assert s16["jump"]["occurs"]
    assert 0.0 < s16["jump"]["T"] < 1.0   # within the rise; fig. 7.22 is not legible enough for T
    # the roller leaves the cam exactly where the contact force reaches zero (event located)
    free = res.element_mode("roller") == "free"
    k = np.flatnonzero(free)[0]
    assert abs(res["roller_gap"][k]) < 1e-9


# -- indexing mechanism, sec. 7.4.4 -----------------------------------------------------------
@pytest.fixture(scope="module")
def indexing():
    sc = scenes.load("indexing")
    return sc, *dynacam.run(sc)


def test_indexing_gear_impact_at_T_0_58(indexing):
    """Sec. 7.4.4: the gear teeth lift off after T = 0.5, where the torque reverses, and 'the
    impact of the gear teeth at T = 0.58' follows.  Tolerance +- 0.03 in T."""
    sc, s, res = indexing
    changes = [c for c in dynacam.mode_changes(sc, res, "gear") if c[0] > 0.3]
    lift, impact = changes[0], changes[1]
    assert lift[1] == "free" and lift[0] == pytest.approx(0.5, abs=0.03)
    assert impact[1] == "back" and impact[0] == pytest.approx(0.58, abs=0.03)


def test_indexing_backlash_Xdd_at_T_0_68_fig_7_16(indexing):
    """Fig. 7.16 (zero damping and viscosity): X''_0.68 = -16; sec. 7.4.4's estimate by (3.12),
    (3.16) gives -16.2.  Tolerance 10 %."""
    sc, s, res = indexing
    assert dynacam.sample_at(sc, res, 0.68) == pytest.approx(-16.0, rel=0.10)


def test_indexing_without_backlash_fig_7_15_and_impact_estimate(indexing):
    """Fig. 7.15: without backlash X'' = -7.4 at T = 0.68 (tolerance 5 %); Van der Hoek's
    estimate X''_(s=0) - U_sn'' (3.12), (3.16), (4.32) from that simulated value agrees with
    the simulation with backlash to 10 %, as the thesis concludes (sec. 7.4.4)."""
    from camdyn.thesis.theory import examples

    sc, s, res = indexing
    sc0 = scenes.without_backlash(sc)
    assert sc0.variant == "dynacam_axial_ideal_rigidgear_bilateral_shafty_shaftz"
    s0, res0 = dynacam.run(sc0)
    x0 = dynacam.sample_at(sc0, res0, 0.68)
    assert x0 == pytest.approx(-7.4, rel=0.05)
    estimate = examples.indexing_impact(Xdd_s0=x0).Xdd
    assert dynacam.sample_at(sc, res, 0.68) == pytest.approx(estimate, rel=0.10)


def test_indexing_amplitude_grows_towards_T_1_without_damping(indexing):
    """Sec. 7.4.4: 'Figure 7.16 ... shows that the amplitude increases towards T = 1, because of
    the increasing stiffness in the absence of damping': the largest |X''| over 0.85 <= T <= 1
    exceeds the one right after the impact (0.6 <= T <= 0.75)."""
    sc, s, res = indexing
    T = dynacam.nominal_T(sc, res)
    late = np.abs(res["Xdd"][(T >= 0.85) & (T <= 1.0)]).max()
    early = np.abs(res["Xdd"][(T >= 0.6) & (T <= 0.75)]).max()
    assert late > early


# -- a reduced variant agrees with the full one with the dropped element made ideal ----
def test_constant_speed_variant_is_the_stiff_motor_limit(spring_loaded):
    """radial_ideal_rigidgear_contact_shafty_shaftz_spring (no motor states) against radial_motor2_rigidgear_contact_shafty_shaftz_spring with a motor of huge inertia and torque
    slope (J_ma = 1e6 kg m^2, G_a = 1e9 N m s/rad: speed deviation M/G_a ~ 1e-8 rad/s): the
    follower accelerations agree to 1e-5 of their peak over the whole run."""
    sc, _, _ = spring_loaded
    full = scenes.replace(sc, parameters={"J_ma": 1e6, "G_a": 1e9})
    reduced = scenes.replace(sc, {"motor": "constant"}, drop=("J_ma", "G_a", "T_el", "alpha_w", "mu_w"))
    assert (full.variant, reduced.variant) == ("dynacam_radial_motor2_rigidgear_contact_shafty_shaftz_spring", "dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring")
    sf, rf = dynacam.run(full)
    sr, rr = dynacam.run(reduced)
    t = np.linspace(0.0, rr.t[-1], 400)
    a, b = rf.sample(t)["Xdd"], rr.sample(t)["Xdd"]
    assert np.max(np.abs(a - b)) < 1e-5 * np.max(np.abs(b))
    assert sf["motor_speed_variation_max"] < 1e-7


def test_backlash_variant_tends_to_the_backlash_free_one(indexing):
    """axial_ideal_backlash_groove_shafty_shaftz (gear and groove backlash) with the backlash shrunk towards zero against axial_ideal_rigidgear_bilateral_shafty_shaftz
    (rigid gear, bilateral roller), zero damping: the largest X'' difference over the run falls
    from 10 % of the peak at s_g = 1e-4 rad to under 1 % at s_g = 1e-6 rad (s_r = s_g/100 m).
    It levels off near 0.3 % (event location at rtol 1e-8 with undamped contacts)."""
    sc, _, _ = indexing
    sr, rr = dynacam.run(scenes.without_backlash(sc))
    t = np.linspace(0.0, rr.t[-1], 400)
    ref = rr.sample(t)["Xdd"]
    diffs = []
    for s_g in (1e-4, 1e-6):
        s, r = dynacam.run(scenes.replace(sc, parameters={"s_g": s_g, "s_r": s_g / 100}))
        diffs.append(np.max(np.abs(r.sample(t)["Xdd"] - ref)) / np.max(np.abs(ref)))
    assert diffs[1] < 0.01 < diffs[0]


# -- the model comparison of sec. 8.2 (fig. 8.1a/b, 8.3a/b curves (4), (5), (6)) -----------
@pytest.fixture(scope="module")
def comparison():
    """fig8_1a.toml (c_z' << c_x) and fig8_1b.toml (c_z' >> c_x): the 4-DOF run and the U0dd of
    the 4-, 2- and 1-DOF models at the same tau, Fa, Fv."""
    out = {}
    for case in ("a", "b"):
        sc = scenes.load(f"fig8_1{case}")
        s, _ = dynacam.run(sc)
        out[case] = (s, dynacam.reduced_models(sc, s))
    return out


@pytest.mark.parametrize("case, printed", [("a", (0.161, 1.64, 2.42)), ("b", (0.141, 2.04, 2.68))])
def test_comparison_scenes_have_the_printed_characteristics(comparison, case, printed):
    """Fig. 8.1a/b print tau, Fa, Fv; the scene files split them over the degrees of freedom
    (their header says how) and must give them back by (4.14), (4.39), (5.52) to 1e-4.  The
    formulas themselves are checked by hand in tests/test_sensitivity.py."""
    s, _ = comparison[case]
    assert (s["tau"], s["Fa"], s["Fv"]) == pytest.approx(printed, rel=1e-4)


def test_two_dof_model_overestimates_when_c_z_is_low_sec_8_2_4(comparison):
    """Sec. 8.2.4, fig. 8.3a: with c_z' << c_x 'the X-curve (5) [2 DOF] deviates from curve (4)
    [4 DOF] by a factor of 2.45'; replacing the 4-DOF model by CAMSHAFT-2 'is not permissible'.
    Ratio of the residual acceleration amplitudes U0dd (1 < T < 1.5), tolerance 10 %.  The
    factor depends on the cam's mass along z, which fig. 8.1a does not show legibly: with the
    taken m_z' = 0.5 kg it is 2.44, with 0.2 kg (m_x' raised to keep m = 1.46 kg) it would be
    1.35 (still far from 1).  The tight counterpart, against independent integrations of the
    4-, 2- and 1-DOF models: tests/test_sensitivity.py::test_sec_8_2_4_factor_moves_with_the_model."""
    _, u = comparison["a"]
    assert u["2dof"] / u["4dof"] == pytest.approx(2.45, rel=0.10)


def test_two_dof_model_holds_when_c_z_is_high_sec_8_2_4(comparison):
    """Sec. 8.2.4, fig. 8.3b: with c_z' >> c_x the curves (4) and (5) 'differ only by a factor of
    1.08', the 4-DOF model 'resembles that with two degrees of freedom'.  Ours: 1.01; asserted
    within 0.1 of the thesis's 1.08 (read from the diagram).  Pinned to 2e-4 by
    tests/test_sensitivity.py::test_sec_8_2_4_factor_moves_with_the_model."""
    _, u = comparison["b"]
    assert abs(u["2dof"] / u["4dof"] - 1.08) <= 0.1


@pytest.mark.parametrize("case", ["a", "b"])
def test_one_dof_model_close_to_two_dof_at_high_Fv_sec_8_2_5(comparison, case):
    """Sec. 8.2.5: 'the curves (6) of the single-degree-of-freedom model and those of the
    two-degrees-of-freedom model (5) show hardly any differences, due to the high Fv-numbers'
    (2.42, 2.68): CAMSHAFT-1 and CAMSHAFT-2 U0dd within 10 % (ours: 3 % and 8 %).  Both U0dd
    are pinned to 1e-8 by test_reduced_models_at_the_hand_computed_characteristics
    (tests/test_sensitivity.py)."""
    _, u = comparison[case]
    assert u["1dof"] / u["2dof"] == pytest.approx(1.0, abs=0.10)


# -- squeeze, sec. 7.4.6 (fig. 7.11b against fig. 7.20) --------------------------------------
@pytest.fixture(scope="module")
def squeeze():
    """indexing_squeeze.toml (squeeze films in gear and groove, fig. 7.19b damping) and the same
    scene at zero viscosity (dry backlash), each sampled at 2e5 points over the run."""
    wet = scenes.load("indexing_squeeze")
    dry = scenes.replace(wet, {"gear": "backlash", "roller": "groove"}, drop=("V_T", "V_R"))
    out = {}
    for name, sc in (("wet", wet), ("dry", dry)):
        s, res = dynacam.run(sc)
        t = np.linspace(0.0, res.t[-1], 200_001)
        out[name] = (sc, s, res, t, res.sample(t))
    return out


def test_squeeze_coefficients_of_the_scene_are_the_derived_ones():
    """The scene file's V_T, V_R are camdyn.thesis.theory.examples.indexing_squeeze's (6.6), (6.38), to
    the six digits written."""
    from camdyn.thesis.theory import examples

    p = scenes.load("indexing_squeeze").parameters
    sq = examples.indexing_squeeze()
    assert (p["V_T"], p["V_R"]) == pytest.approx((sq["V_T"], sq["V_R"]), rel=1e-5)


def test_squeeze_hardly_changes_the_follower_response_sec_7_4_6(squeeze):
    """Sec. 7.4.6: 'the squeeze effect has hardly any effect on the follower vibration (X)'.
    With and without viscosity, X'' at T = 0.68, the largest deceleration in the rise and the
    residual amplitude U0'' agree within 5 % (ours: 0.6 %, 2.5 %, 1 %)."""
    wet, dry = squeeze["wet"], squeeze["dry"]
    for key in ("Xdd_min_rise", "U0dd"):
        assert wet[1][key] == pytest.approx(dry[1][key], rel=0.05)
    x_wet, x_dry = (dynacam.sample_at(c[0], c[2], 0.68) for c in (wet, dry))
    assert x_wet == pytest.approx(x_dry, rel=0.05)


def test_squeeze_run_against_fig_7_11b():
    """Fig. 7.11b, sec. 7.4.4: X'' = -14 at T = 0.68 with backlash, damping and squeeze.  The
    scene damps as fig. 7.19b (constant q) where fig. 7.11b used a velocity-dependent q, so
    the tolerance is the thesis's own 20 % (sec. 7.4.7); ours -15.1."""
    sc = scenes.load("indexing_squeeze")
    _, res = dynacam.run(sc)
    assert dynacam.sample_at(sc, res, 0.68) == pytest.approx(-14.0, rel=0.20)


def test_squeeze_damps_the_impact_spikes_sec_7_4_6(squeeze):
    """Sec. 7.4.6: squeeze 'reduces considerably the high-frequency impact phenomena', seen in
    the cam's angular acceleration B'' and the traversals of backlash.  Measured on dense
    samples: the total variation of B'' over the run falls by more than a third (ours: to
    0.49), the B'' peak as the gear teeth first traverse their backlash (0.5 < T < 0.62) by
    more than a third (ours: 26.5 -> 11.8), and the jumps of X'' where a dry contact
    engages its damper vanish (ours: 4.0 -> 0.02 between samples 8e-6 t_m apart)."""
    wet, dry = squeeze["wet"], squeeze["dry"]

    def figures(case):
        sc, _, res, t, smp = case
        T = t / (res.params["beta_m"] / res.params["omega_s"]) + sc.T_start
        B, X = smp["Bdd"], smp["Xdd"]
        first = (T > 0.5) & (T < 0.62)
        return np.abs(np.diff(B)).sum(), np.abs(B[first]).max(), np.abs(np.diff(X)).max()

    tv_w, peak_w, jump_w = figures(wet)
    tv_d, peak_d, jump_d = figures(dry)
    assert tv_w < tv_d * 2 / 3
    assert peak_w < peak_d * 2 / 3
    assert jump_w < 0.1 * jump_d


# -- the rise start is an event on the cam angle: found however long the dwell step ---------------
@pytest.mark.parametrize("name", ["indexing", "spring_loaded"])
def test_rise_starts_on_its_breakpoint_without_a_step_limit(name, request):
    """The scenes run with no step limit.  The cam law's breakpoint T = 0 is a condition on the
    cam angle (a state), so an event: the first recorded point of the rise must lie on it, cam
    argument (beta - beta_0)/beta_m = 0 to 1e-12; and X'' over the whole run must agree with a
    run whose steps are no longer than t_m/20000 (where even an event put at its step's end
    would cost little) to 2e-6 of the peak |X''|.  Measured: 6e-7 (indexing: undamped contacts
    located at rtol 1e-8) and 4e-11 (spring-loaded).  When the event search returned the far
    end of its bracket after landing on g = 0, the indexing mechanism never left the dwell
    (X'' = 0, error 1.0) and the spring-loaded rise began at T = 0.0044 (error 1e-4)."""
    sc, s, res = request.getfixturevalue(name)
    p = res.params
    seg = res.mode[:, 0]                       # segment of the cam law (the only cam input)
    first = np.flatnonzero(seg == 1)
    assert first.size
    assert abs((res["beta"][first[0]] - p["beta_0"]) / p["beta_m"]) < 1e-12
    t_m = s["characteristics"]["t_m"]
    _, ref = dynacam.run(sc, method=DP54(rtol=sc.rtol, max_step=t_m / 20000))
    t = np.linspace(0.0, ref.t[-1], 801)
    a, b = res.sample(t)["Xdd"], ref.sample(t)["Xdd"]
    assert np.max(np.abs(a - b)) < 2e-6 * np.max(np.abs(b))
