"""What runtime/targets/dynacam.py makes of a run: initial state, time axis, mode switches, summary, figures.

Each quantity is checked against a hand computation on a scene small enough to have one:

* a one-DOF scene: the DYNACAM variant without shaft deflections (radial_ideal_rigidgear_bilateral) with a cam of huge
  inertia on a stiff shaft and a huge base radius, so that it is the thesis's one-DOF model at
  constant fictitious speed (sec. 3.3) with its closed forms (3.4a), (3.4b), (3.5), (3.6);
* a stiff spring-loaded follower at constant speed (radial_ideal_rigidgear_contact_shafty_shaftz_spring) whose roller lifts off where the
  nominal inertia force first overcomes the spring preload (sec. 7.5);
* the static equilibrium (6.49)-(6.68) of preloaded springs in series, with cam friction
  (6.13) and linkage friction (6.43), and with the second-order motor (App. 5);
* the indexing mechanism, whose roller crosses its groove backlash (fig. 7.16) without a jump.

Units SI, reduced to the output member (sec. 2.4); T = t/t_m + T_start, t_m = beta_m/w_s.
"""
import math
import time
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from camdyn.runtime.targets import dynacam, dynacam_diagrams, scene_files as scenes

T_START = -0.1
# t_m = beta_m/w_s = 0.25 s, and beta_m w_s = 4: a time axis built with the product, or
# without t_m, is off by a factor 16 or 4
BETA_M, OMEGA_S = 1.0, 4.0
T_M = BETA_M / OMEGA_S


def _scene(name, options, parameters, T_end, rtol=1e-8):
    # the path only names the figure files (<stem>_<key>.png)
    data = {"title": name, "law": "cycloidal", "options": options, "parameters": parameters,
            "run": {"T_start": T_START, "T_end": T_end, "rtol": rtol}}
    return scenes.from_dict(data, f"/nonexistent/{name}.toml")


# -- one DOF: radial_ideal_rigidgear_bilateral as the model of sec. 3.3 --------------------------------------------------
TAU = 0.15          # sin(pi/tau) = 0.87: U0 well away from a zero of (3.5)
H_M, M_X = 0.01, 1.0
C_X = M_X * (2 * math.pi / (TAU * T_M)) ** 2      # tau = 2 pi (m/c)^(1/2)/t_m (4.11), (4.12)


def _one_dof(T_end):
    # J = 1e6 kg m^2 keeps the cam at w_s (speed variation 3e-10), R_b = 10 m makes
    # tan alpha_me = 1e-3 (Fa = 3e-9, Fv = 1e-10): the coupling to the cam is negligible
    return _scene("one_dof", {"shaft_y": False, "shaft_z": False},
                  {"h_m": H_M, "beta_m": BETA_M, "R_b": 10.0, "omega_s": OMEGA_S, "J": 1e6,
                   "k": 1e9, "q_b": 0.0, "m_x": M_X, "c_x": C_X, "q_x": 0.0}, T_end, rtol=1e-10)


@lru_cache(maxsize=None)
def one_dof_run():
    """(scene, summary, result, process time spent in dynacam.run)."""
    sc = _one_dof(1.6)
    before = time.process_time()
    s, res = dynacam.run(sc)
    return sc, s, res, time.process_time() - before


def xdd_closed_form(T):
    """X'' of the one-DOF follower, undamped, cycloid (3.2), from rest: the second derivative of
    (3.4a) for 0 <= T <= 1 and of (3.4b) for T >= 1; zero in the dwell before the rise."""
    T = np.asarray(T, dtype=float)
    w = 2 * math.pi / TAU
    rise = 2 * math.pi * (np.sin(2 * math.pi * T) - TAU * np.sin(w * T)) / (1 - TAU**2)
    dwell = (-4 * math.pi * TAU / (1 - TAU**2) * math.sin(math.pi / TAU)
             * np.cos(math.pi / TAU * (2 * T - 1)))
    return np.where(T < 0, 0.0, np.where(T <= 1, rise, dwell))


def u_closed_form(T):
    """U = (x - h)/h_m: 0 at rest before the rise, (3.4a) during it, (3.4b) after it."""
    if T < 0:
        return 0.0
    rise = (-TAU**2 / (1 - TAU**2) * math.sin(2 * math.pi * T) / (2 * math.pi)
            + TAU**3 / (1 - TAU**2) * math.sin(2 * math.pi * T / TAU) / (2 * math.pi))
    dwell = TAU**3 / (1 - TAU**2) / math.pi * math.sin(math.pi / TAU) * math.cos(math.pi / TAU * (2 * T - 1))
    return rise if T <= 1 else dwell


def test_time_axis_runs_from_T_start_to_T_end():
    """nominal_T = t/t_m + T_start with t_m = beta_m/w_s = 0.25 s from the scene data: the
    first recorded point is at T_start = -0.1, the last at T_end = 1.6, and every recorded t
    maps so (1e-12 relative; measured: rounding)."""
    sc, _, res, _ = one_dof_run()
    T = dynacam.nominal_T(sc, res)
    assert T[0] == pytest.approx(T_START, abs=1e-12)
    assert T[-1] == pytest.approx(1.6, rel=1e-12)
    assert np.allclose(T, res.t / T_M + T_START, rtol=0, atol=1e-12)


@pytest.mark.parametrize("T", [-0.05, 0.25, 0.7, 0.9, 1.3])
def test_sample_at_nominal_time_against_3_4(T):
    """sample_at(T) of X'' and U against the one-DOF closed forms (3.4a), (3.4b) and their
    second derivatives at the same T (before the rise: at rest, X'' = U = 0).  Tolerance
    1e-6 absolute on X'' (amplitude 2 pi), 1e-9 on U (amplitude 4e-3); measured 1.7e-8 and 1e-11.
    A time axis off by 2 T_start samples 0.2 earlier (X'' differs by ~5 at T = 0.25)."""
    sc, _, res, _ = one_dof_run()
    assert dynacam.sample_at(sc, res, T) == pytest.approx(float(xdd_closed_form(T)), abs=1e-6)
    assert dynacam.sample_at(sc, res, T, "U") == pytest.approx(u_closed_form(T), abs=1e-9)


def test_summary_residual_amplitudes_3_5_3_6():
    """Summary U0 (largest |U| in the dwell after the rise) and U0dd against (3.5)
    U0 = tau^3 |sin(pi/tau)|/(pi (1 - tau^2)) and (3.6) U0dd = 4 pi tau |sin(pi/tau)|/(1 - tau^2),
    tau = 0.15 from the scene's c_x, m_x, beta_m, w_s; relative tolerance 1e-6, measured 1.1e-8.
    The largest X'' deceleration of the rise and its T against the minimum of the closed form
    (second derivative of (3.4a)), found here by bounded Brent on the closed form: 1e-6 in X''
    and 1e-6 in T (measured 2e-9, 1.1e-8).  tau is App. 7's (4.11), (4.12) to 1e-12."""
    _, s, _, _ = one_dof_run()
    assert s["tau"] == pytest.approx(TAU, rel=1e-12)
    U0 = TAU**3 * abs(math.sin(math.pi / TAU)) / (math.pi * (1 - TAU**2))
    assert s["U0"] == pytest.approx(U0, rel=1e-6)
    assert s["U0dd"] == pytest.approx(4 * math.pi * TAU * abs(math.sin(math.pi / TAU)) / (1 - TAU**2), rel=1e-6)
    grid = np.linspace(0.0, 1.0, 20001)
    k = int(np.argmin(xdd_closed_form(grid)))
    opt = minimize_scalar(lambda T: float(xdd_closed_form(T)), bounds=(grid[k - 1], grid[k + 1]),
                          method="bounded", options={"xatol": 1e-12})
    assert s["Xdd_min_rise"] == pytest.approx(opt.fun, abs=1e-6)
    assert s["T_at_Xdd_min"] == pytest.approx(opt.x, abs=1e-6)
    assert not s["jump"]["occurs"] and s["jump"]["T"] is None


def test_run_ending_at_the_rise_end_has_no_dwell():
    """T_end = 1: the run stops where the rise ends, there is no dwell to take U0, U0dd from
    (None), while the rise's deceleration is still the closed form's (1e-6; the 20001-point
    grid's minimum is 7e-8 above the true one)."""
    s, _ = dynacam.run(_one_dof(1.0))
    assert s["U0"] is None and s["U0dd"] is None
    grid = np.linspace(0.0, 1.0, 20001)
    assert s["Xdd_min_rise"] == pytest.approx(xdd_closed_form(grid).min(), abs=1e-6)


def test_cpu_time_is_that_of_the_integration():
    """cpu_seconds is process time spent inside the run: positive and at most the process
    time the whole dynacam.run call took (its setup, equilibrium and summary included)."""
    _, s, _, spent = one_dof_run()
    assert 0.0 < s["cpu_seconds"] <= spent


# -- figures -----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def figures(tmp_path_factory):
    """plot() of the one-DOF run, its figures kept open (plot closes them) for inspection."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    sc, s, res, _ = one_dof_run()
    out = tmp_path_factory.mktemp("figures")
    kept, close = [], plt.close
    mp = pytest.MonkeyPatch()
    mp.setattr(plt, "close", lambda fig=None: kept.append(fig))
    try:
        written = dynacam_diagrams.plot(sc, res, s, out)
    finally:
        mp.undo()
    yield out, written, dict(zip((Path(p).stem.split("one_dof_", 1)[1] for p in written), kept)), res
    for fig in kept:
        close(fig)


def test_plot_writes_one_png_per_diagram_of_the_variant(figures):
    """radial_ideal_rigidgear_bilateral (rigid gear, bilateral roller, constant speed) has the diagrams X'', B'', the
    shaft torque and the fictitious speed variation (figs 7.11, 7.12), no gap or motor one:
    exactly those four files, named <scene stem>_<key>.png in the output folder, PNG each,
    beside the folder's record of what camdyn wrote there (runtime/core/outdir.py)."""
    from camdyn.runtime.core.outdir import RECORD, entry

    out, written, _, _ = figures
    want = {out / f"one_dof_{key}.png" for key in ("Xdd", "Bdd", "torque", "speed_var")}
    assert {Path(p) for p in written} == want
    assert set(out.iterdir()) == want | {out / RECORD}
    assert all(entry(p) is not None for p in want)
    for p in want:
        assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_acceleration_figure_shows_X_and_the_nominal_H_dd(figures):
    """The X'' diagram (fig. 7.12): its solid curve is X'' against T, equal to the closed form
    (3.4a), (3.4b) differentiated twice (1e-6, measured 2.5e-8); the dashed curve labelled
    "nominal H''" is the cycloid's H''(T) = 2 pi sin 2 pi T inside the rise and 0 outside
    (A.2.10; 1e-12); the marker sits at the summary's deceleration extreme; the bottom axes
    carries the T label.  No other diagram carries the nominal curve."""
    _, _, figs, res = figures
    fig = figs["Xdd"]
    ax = fig.axes[0]
    T = res.t / T_M + T_START
    curve = ax.lines[0]
    assert np.allclose(curve.get_xdata(), T, rtol=0, atol=1e-12)
    assert np.allclose(curve.get_ydata(), xdd_closed_form(T), rtol=0, atol=1e-6)
    nominal = [ln for ln in ax.lines if ln.get_label() == "nominal H''"]
    assert len(nominal) == 1
    Tn = np.asarray(nominal[0].get_xdata())
    assert np.allclose(Tn, T, rtol=0, atol=1e-12)
    want = np.where((Tn > 0) & (Tn < 1), 2 * math.pi * np.sin(2 * math.pi * Tn), 0.0)
    assert np.allclose(nominal[0].get_ydata(), want, rtol=0, atol=1e-12)
    assert ax.get_legend() is not None
    grid = np.linspace(0.0, 1.0, 20001)
    marker = [ln for ln in ax.lines if ln.get_marker() == "v"]
    assert len(marker) == 1
    assert marker[0].get_ydata()[0] == pytest.approx(xdd_closed_form(grid).min(), abs=1e-6)
    for key, f in figs.items():
        assert f.axes[-1].get_xlabel() == "T = t/t_m", key
        if key != "Xdd":
            assert not [ln for a in f.axes for ln in a.lines if ln.get_label() == "nominal H''"], key


# -- roller lift-off (sec. 7.5) ----------------------------------------------------------------
LIFT = {"h_m": 0.01, "F_0": 0.5, "m_x": 1.0, "c_x": 1e6, "c_z": 1e8}


@lru_cache(maxsize=None)
def lift_run():
    # stiff (tau = 0.025), damped, at constant speed; c_s = 0 so the preload is F_0 throughout
    sc = _scene("lift", {"roller": "contact", "spring": True},
                {"h_m": LIFT["h_m"], "beta_m": BETA_M, "R_b": 10.0, "omega_s": OMEGA_S, "J": 1e6,
                 "k": 1e9, "q_b": 0.05, "m_x": LIFT["m_x"], "c_x": LIFT["c_x"], "q_x": 0.05,
                 "m_y": 100.0, "c_y": 1e8, "q_y": 0.05, "m_z": 100.0, "c_z": LIFT["c_z"], "q_z": 0.05,
                 "F_0": LIFT["F_0"], "c_s": 0.0}, 1.0)
    return sc, *dynacam.run(sc)


def test_roller_lifts_off_where_the_preload_no_longer_holds_the_follower():
    """Sec. 7.5: following the nominal cycloid, the roller leaves the cam where the inertia
    force m_x x'' first reaches -F_0: 2 pi (h_m/t_m^2) m_x sin 2 pi T = -F_0, i.e.
    T = 1/2 + asin(F_0 t_m^2/(2 pi m_x h_m))/(2 pi) = 0.5828.  mode_changes lists that switch
    to "free" first, each entry a real change of value; the summary reports the jump there.
    Tolerance 1e-3 in T: the dynamic deviation of order tau^2 and the linkage damper
    (2 q tau) the hand formula leaves out; measured 3.4e-4."""
    sc, s, res = lift_run()
    ratio = LIFT["F_0"] * T_M**2 / (2 * math.pi * LIFT["m_x"] * LIFT["h_m"])
    T_lift = 0.5 + math.asin(ratio) / (2 * math.pi)
    changes = dynacam.mode_changes(sc, res, "roller")
    assert changes, "the roller never left the cam"
    assert changes[0][1] == "free"
    assert changes[0][0] == pytest.approx(T_lift, abs=1e-3)
    values = ["contact"] + [v for _, v in changes]
    assert all(a != b for a, b in zip(values, values[1:]))
    assert all(a[0] < b[0] for a, b in zip(changes, changes[1:]))
    assert s["jump"]["occurs"]
    assert s["jump"]["T"] == pytest.approx(T_lift, abs=1e-3)


def test_lift_scene_starts_in_the_preload_equilibrium():
    """(6.49)-(6.68): at rest in the dwell, the preload F_0 compresses the linkage c_x and the
    shaft c_z in series: z = F_0/c_z, x = -F_0 (1/c_x + 1/c_z), beta = y = 0 (no torque in the
    dwell, tan alpha = 0), cam at w_s.  1e-9 relative (measured 2e-16)."""
    _, _, res = lift_run()
    y0 = dict(zip(res.state_names, res.y[0]))
    F_0, c_x, c_z = LIFT["F_0"], LIFT["c_x"], LIFT["c_z"]
    assert y0["z"] == pytest.approx(F_0 / c_z, rel=1e-9)
    assert y0["x"] == pytest.approx(-F_0 * (1 / c_x + 1 / c_z), rel=1e-9)
    assert abs(y0["beta"]) < 1e-15 and abs(y0["y"]) < 1e-15
    assert y0["betad"] == OMEGA_S


def test_groove_backlash_traverse_is_not_a_jump():
    """The indexing mechanism (positive drive, roller in a groove with backlash s_r, fig. 7.16):
    the roller leaves the lower wall in the rise and crosses the groove ("free"), but a
    positive-drive follower cannot jump (sec. 7.5 concerns force closure): the summary reports
    no jump."""
    sc = scenes.load("indexing")
    s, res = dynacam.run(sc)
    assert "free" in [v for _, v in dynacam.mode_changes(sc, res, "roller")]
    assert s["jump"] == {"occurs": False, "T": None}


# -- static equilibrium with friction and with the motor ---------------------------------------
def _series_force(p):
    """Contact force of the preload F_0 through the follower spring c_s in series with the
    linkage c_x and the shaft c_z: F = F_0 + c_s x, x = -F (1/c_x + 1/c_z) (4.3), (6.45)."""
    return p["F_0"] / (1 + p["c_s"] * (1 / p["c_x"] + 1 / p["c_z"]))


def test_equilibrium_with_cam_and_linkage_friction_6_13_6_43():
    """radial_ideal_rigidgear_contact_shafty_shaftz_camfriction_linkfriction_spring at rest in the dwell, cam slipping forward under it: the contact force is the
    series-spring one, F = F_0/(1 + c_s/c_c); the linkage friction (sticking, nu_x) holds no
    force there; the cam friction torque nu_b F R_b (6.13) (tan alpha = 0, R = R_b) winds the
    shaft back, beta = -nu_b F R_b/k; z = F/c_z, x = -F/c_c, y = 0.  1e-9 relative (measured
    2e-16).  The first recorded slopes are the rest ones: accelerations zero (1e-9 m/s^2)."""
    p = {"h_m": 0.01, "beta_m": BETA_M, "R_b": 0.08, "omega_s": OMEGA_S, "J": 0.01, "k": 1000.0,
         "q_b": 0.05, "m_x": 1.0, "c_x": 1e6, "q_x": 0.05, "m_y": 1.0, "c_y": 1e7, "q_y": 0.05,
         "m_z": 1.0, "c_z": 2e6, "q_z": 0.05, "F_0": 50.0, "c_s": 2e4, "nu_b": 0.1, "nu_x": 0.1}
    sc = _scene("friction", {"roller": "contact", "spring": True, "cam_friction": True,
                             "linkage_friction": True}, p, 1.0)
    _, res = dynacam.run(sc)
    y0 = dict(zip(res.state_names, res.y[0]))
    F = _series_force(p)
    assert y0["beta"] == pytest.approx(-p["nu_b"] * F * p["R_b"] / p["k"], rel=1e-9)
    assert y0["z"] == pytest.approx(F / p["c_z"], rel=1e-9)
    assert y0["x"] == pytest.approx(-F * (1 / p["c_x"] + 1 / p["c_z"]), rel=1e-9)
    assert abs(y0["y"]) < 1e-15
    assert y0["betad"] == OMEGA_S
    f0 = dict(zip(res.state_names, res.f[0]))
    assert max(abs(f0[n]) for n in ("betad", "yd", "zd", "xd")) < 1e-9


def test_spring_loaded_scene_starts_in_equilibrium_with_the_motor_at_rest():
    """The spring-loaded follower of fig. 7.2 (motor of App. 5, second order): in the dwell the
    cam needs no torque, so the motor runs at w_s (dw = 0) with zero electromagnetic torque
    (Mea = 0, (A.5.6)), phi = beta = y = 0, and the preload sits in the series springs:
    F = F_0/(1 + c_s/c_c) = 59.84 N, z = F/c_z, x = -F/c_c.  1e-9 relative on x, z, 1e-12
    absolute on dw [rad/s] and Mea [N m] (measured 2e-16 relative; 4e-29, 6e-26)."""
    sc = scenes.load("spring_loaded")
    _, res = dynacam.run(sc)
    y0 = dict(zip(res.state_names, res.y[0]))
    p = sc.parameters
    F = _series_force(p)
    assert y0["z"] == pytest.approx(F / p["c_z"], rel=1e-9)
    assert y0["x"] == pytest.approx(-F * (1 / p["c_x"] + 1 / p["c_z"]), rel=1e-9)
    for name in ("dw", "Mea", "phi", "beta", "y"):
        assert abs(y0[name]) < 1e-12, name
    assert y0["betad"] == p["omega_s"]


@pytest.mark.parametrize("name", ["spring_loaded", "indexing"])
def test_speed_variation_is_refined_on_the_dense_output(name):
    """The largest fictitious speed variation of the summary (fig. 7.12, 7.15) is the maximum of
    |speed_var| on the dense output, not at the recorded steps: against an independent scan of
    the interpolant at 400 points per step it is never lower (to 1e-12) and within 1e-8
    relative of it (the scan's own spacing error); the recorded points alone fell short by
    1.1e-5 relative on spring_loaded, 1.8e-6 on indexing."""
    sc = scenes.load(name)
    summary, res = dynacam.run(sc)
    t = res.t
    s = np.linspace(0.0, 1.0, 400, endpoint=False)
    grid = np.append((t[:-1, None] + np.diff(t)[:, None] * s[None, :]).ravel(), t[-1])
    dense = float(np.abs(res.sample(grid)["speed_var"]).max())
    got = summary["speed_variation_max"]
    assert got >= dense * (1 - 1e-12)
    assert got == pytest.approx(dense, rel=1e-8)
    assert got >= float(np.abs(res["speed_var"]).max())


# -- a full turn (scene [turn]) -----------------------------------------------------------------
TAU_TURN = 0.25      # sin(pi/tau) = 0: the rise leaves no residual vibration by (3.5)
R_TURN = 1.2         # the return takes 1.2 times the rise: tau/r = 0.2083, |sin(pi r/tau)| = 0.87


def _one_dof_turn(T_end, turn):
    c_x = M_X * (2 * math.pi / (TAU_TURN * T_M)) ** 2
    data = {"title": "one_dof_turn", "law": "cycloidal", **({"turn": turn} if turn else {}),
            "options": {"shaft_y": False, "shaft_z": False},
            "parameters": {"h_m": H_M, "beta_m": BETA_M, "R_b": 10.0, "omega_s": OMEGA_S,
                           "J": 1e6, "k": 1e9, "q_b": 0.0, "m_x": M_X, "c_x": c_x, "q_x": 0.0},
            "run": {"T_start": T_START, "T_end": T_end, "rtol": 1e-10}}
    return scenes.from_dict(data, "/nonexistent/one_dof_turn.toml")


def test_full_turn_return_residuals_3_5_3_6():
    """A full turn on the one-DOF scene (beta_m = 57.3 deg; upper dwell 30 deg, return 1.2 x
    57.3 deg): the return is the cycloid run backwards over r = 1.2 rise times, so after it the
    follower vibrates as after a rise at tau/r, (3.5) U0 = (tau/r)^3 |sin(pi r/tau)| /
    (pi (1 - (tau/r)^2)) in units of h_m, and (3.6) U0'' over r^2 in units of h_m/t_m^2 (the
    rise at tau = 1/4 leaves none to superpose); the largest |X''| of the return is at least
    the nominal 2 pi/r^2.  Tolerance 1e-6 relative; the rise's figures are those of the
    plain scene to 1e-12."""
    turn = {"upper_dwell": 30.0, "return": R_TURN * math.degrees(BETA_M)}
    s, _ = dynacam.run(_one_dof_turn(4.0, turn))
    t = TAU_TURN / R_TURN
    U0 = t**3 * abs(math.sin(math.pi / t)) / (math.pi * (1 - t**2))
    U0dd = 4 * math.pi * t * abs(math.sin(math.pi / t)) / (1 - t**2) / R_TURN**2
    assert s["U0"] < 1e-8 and s["U0dd"] < 1e-5          # the rise at a tuning dip of (3.5)
    assert s["U0_return"] == pytest.approx(U0, rel=1e-6)
    assert s["U0dd_return"] == pytest.approx(U0dd, rel=1e-6)
    assert s["Xdd_absmax_return"] >= 2 * math.pi / R_TURN**2
    assert s["turn"]["angles_deg"][2] == pytest.approx(R_TURN * math.degrees(BETA_M), rel=1e-12)
    plain, _ = dynacam.run(_one_dof_turn(1.5, None))
    for key in ("Xdd_min_rise", "T_at_Xdd_min", "Xdd_max_rise"):
        assert s[key] == pytest.approx(plain[key], rel=1e-12, abs=1e-12), key


@pytest.mark.parametrize("turn, words", [
    ({"upper_dwell": 200.0, "return": 150.0}, "exceeds 360 deg"),
    ({"upper_dwell": 30.0}, "turn.return is missing"),
    ({"upper_dwell": 30.0, "return": 0.0}, "turn.return=0 is out of range"),
    ({"upper_dwell": 30.0, "return": 40.0, "lower": 1.0}, "turn.lower is not a turn setting"),
    ({"upper_dwell": 30.0, "return": 40.0, "return_law": "sine"}, "unknown cam law"),
    ({"upper_dwell": 30.0, "return": 40.0, "return_theta": 0.1}, "return_theta goes with"),
])
def test_bad_turn_is_refused_naming_it(turn, words):
    from camdyn.runtime.core.errors import CamdynInputError

    with pytest.raises(CamdynInputError, match=words):
        _one_dof_turn(4.0, turn)


def test_turn_scene_file_through_the_command(tmp_path, capsys):
    """A scene file with [turn] through `camdyn simulate`: the return's figures are printed
    with their error estimates; `--model auto` refuses it in one line (the sec. 8.2 chain
    compares one rise and dwell)."""
    from camdyn.runtime.cli import main

    text = (Path(scenes.builtin("spring_loaded")).read_text().replace("T_end = 1.5", "T_end = 5.0")
            + "\n[turn]\nupper_dwell = 50\nreturn = 40\n")
    path = tmp_path / "turn.toml"
    path.write_text(text)
    assert main(["simulate", str(path)]) == 0
    out = capsys.readouterr().out
    assert "full turn: rise, upper dwell, return, lower dwell 24.98, 50, 40, 245 deg" in out
    assert "U0dd_return" in out and "±" in out.split("U0dd_return")[1].splitlines()[0]
    assert main(["simulate", str(path), "--model", "auto"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "[turn]" in err


# -- the residual vibration about the dwell's static equilibrium -------------------------------

HELD = {"h_m": 0.01, "beta_m": BETA_M, "R_b": 0.08, "omega_s": OMEGA_S, "J": 1e6, "k": 1e9,
        "q_b": 0.05, "m_x": 1.0, "c_x": 1e6, "q_x": 0.05, "m_y": 1.0, "c_y": 1e7, "q_y": 0.05,
        "m_z": 1.0, "c_z": 2e6, "q_z": 0.05, "F_0": 50.0, "c_s": 2e4}
"""A spring-held follower whose roller stays on the cam (the preload beats the inertia force
of the rise, 2 pi m_x h_m/t_m^2 = 1 N, by far) on a camshaft that turns at w_s whatever the
torque (J, k huge, as the lift scene's): its motion is linear in the forces throughout.  On a
shaft that twists, the preload's torque F tan(alpha) R in the rise turns the cam, and U0
moves with the preload (2.4e-4 of it between F_0 = 50 and 150 N with J = 0.01, k = 1000)."""


def _held(F_0, T_end=2.0):
    sc = _scene(f"held{F_0:g}", {"roller": "contact", "spring": True}, {**HELD, "F_0": F_0},
                T_end)
    return sc, *dynacam.run(sc)


def test_static_level_of_the_dwell_is_the_series_springs():
    """In the dwell after the rise the follower settles where the spring, at the lift h_m,
    presses the linkage c_x and the shaft c_z in series (4.3), (6.45): F = F_0 + c_s x with
    x = h_m - F/c_c, so F = (F_0 + c_s h_m)/(1 + c_s/c_c) and U = (x - h_m)/h_m = -F/(c_c h_m);
    y = 0 (no torque in the dwell).  1e-9 relative (the equilibrium is solved to rounding)."""
    _, s, _ = _held(50.0)
    c_c = 1 / (1 / HELD["c_x"] + 1 / HELD["c_z"])
    F = (HELD["F_0"] + HELD["c_s"] * HELD["h_m"]) / (1 + HELD["c_s"] / c_c)
    assert s["U_static"] == pytest.approx(-F / (c_c * HELD["h_m"]), rel=1e-9)


def test_preload_shifts_the_dwell_not_the_vibration():
    """The follower never leaves the cam, so the motion is linear and a larger preload only
    moves the static level: U0, measured about it, stays (the U0 that included the static
    deflection grew exactly as (F_0 + c_s h)/(c_x h_m) with the preload), while U_static moves
    by -dF_0/((1 + c_s/c_c) c_c h_m).  U0 (4.2e-6 of the stroke against levels of 0.04 and
    0.05) equal to 1e-5 relative: the runs at rtol 1e-8 differ by 1.4e-6 of it, 6e-12 of the
    stroke; and the largest |U| of the dwell, the old figure, exceeds U0 by the static level,
    to U0's own size."""
    (sa, a, ra), (_, b, rb) = _held(50.0), _held(150.0)
    assert not a["jump"]["occurs"] and not b["jump"]["occurs"]
    assert b["U0"] == pytest.approx(a["U0"], rel=1e-5)
    c_c = 1 / (1 / HELD["c_x"] + 1 / HELD["c_z"])
    shift = -100.0 / ((1 + HELD["c_s"] / c_c) * c_c * HELD["h_m"])
    assert b["U_static"] - a["U_static"] == pytest.approx(shift, rel=1e-9)
    for s, res in ((a, ra), (b, rb)):
        T = dynacam.nominal_T(sa, res)
        U = res["U"][(T > 1.0)]
        # the recorded points alone: the largest |U| lies within U0 + |U_static| of them
        assert np.abs(U).max() <= s["U0"] + abs(s["U_static"]) + 1e-12
        assert np.abs(U).max() > abs(s["U_static"])


def test_static_level_is_where_the_dwell_settles():
    """Independently of the solve: run on through a long dwell (T to 40, the damped follower's
    oscillation about its level decays by e^-60 there) and read U at the end: the static level
    to 1e-9 of the stroke."""
    _, s, res = _held(50.0, T_end=40.0)
    assert res["U"][-1] == pytest.approx(s["U_static"], abs=1e-9)


def test_options_no_variant_has_are_one_line(tmp_path):
    """A rocker or a flat face on an axial cam: one line naming both options, status 2 (the
    declaration's own words; it was a ValueError traceback)."""
    import contextlib
    import io

    from camdyn.runtime.cli import main

    text = scenes.builtin("rocker").read_text()
    for swap, words in ((('cam = "radial"', 'cam = "axial"'), 'option rocker=true with cam="axial"'),
                        (('rocker = true', 'flat_face = true\ncam = "axial"'), None)):
        f = tmp_path / "s.toml"
        body = text.replace(*swap)
        if words is None:                                  # flat face instead of the rocker
            body = text.replace('cam = "radial"', 'cam = "axial"').replace(
                "rocker = true", "flat_face = true")
            words = 'option flat_face=true with cam="axial"'
        f.write_text(body)
        err = io.StringIO()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            rc = main(["simulate", str(f)])
        assert rc == 2
        assert err.getvalue().count("\n") == 1 and "Traceback" not in err.getvalue()
        assert err.getvalue().startswith(f"camdyn simulate: error: {words}")
