"""`camdyn design`'s follower spring over the whole turn, and estimates that cover their errors.

Every number here is computed independently of camdyn: the kinetostatic motion from the
cycloid's closed form, the dynamic one from the closed-form solution of the one-DOF follower
(3.1), X'' = w^2 (H - X), w = 2 pi/tau, driven by the cycloidal rise and return of the turn:
on a segment where H = a + b s - c sin(2 pi s)/(2 pi), s = (T - T0)/L, a particular solution
is X_p = a + b s - K sin(Omega (T - T0)), Omega = 2 pi/L, K = c w^2/(2 pi (w^2 - Omega^2)), and
the free part C1 cos(w (T - T0)) + C2 sin(w (T - T0)) carries the state over from the segment
before (rest at T = 0).  Extremes are found on a fine grid and refined by SciPy's bounded
Brent search to 1e-13 in T.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from camdyn.runtime.cli import main
from camdyn.thesis.design import machine as mach
from camdyn.thesis.design.method import design

TWO_PI = 2 * math.pi

# the README's rocker: 18 deg of swing on an 80 mm arm, 0.0039 kg m^2, 12800 N m/rad, 300 rpm
ROCKER = ["--swing", "18", "--arm-length", "0.08", "--arm-inertia", "0.0039",
          "--arm-stiffness", "12800", "--speed", "300", "--fa", "0", "--accuracy", "20e-6",
          "--spring-margin", "0.3", "--spring-rate", "1000"]
FINDING = ROCKER + ["--cam-angle", "120deg", "--spring-mass", "0.02", "--speed-fluctuation", "0.05"]
TURN = (120.0, 60.0, 100.0, 80.0)
MU = 0.3


def _rocker(**kw):
    h, m, c = mach.rocker(swing_deg=18, arm_length=0.08, inertia=0.0039, torsional_stiffness=12800)
    return design(stroke=h, speed=300, mass=m, stiffness=c, Fa=0, accuracy=20e-6, spring_margin=MU,
                  spring_rate=1000.0, arm_length=0.08, **kw)


def _translating(**kw):
    return design(stroke=0.05, speed=150, mass=2.0, tau=0.15, Fa=0, accuracy=1e-4,
                  spring_margin=MU, spring_rate=2000.0, speed_fluctuation=0.05, **kw)


@pytest.fixture(scope="module")
def finding():
    """The command of the finding (a rocker, the rise alone), as design() takes it."""
    return _rocker(cam_angle_rad=math.radians(120), spring_mass=0.02, speed_fluctuation=0.05)


@pytest.fixture(scope="module")
def rocker_turn():
    return _rocker(angles=TURN, speed_fluctuation=0.05)


@pytest.fixture(scope="module")
def translating_rise():
    return _translating(cam_angle_rad=math.radians(90))


@pytest.fixture(scope="module")
def translating_turn():
    return _translating(angles=(90.0, 60.0, 120.0, 90.0))


# -- the motion, typed in ----------------------------------------------------------------------
def _segments(angles):
    """(T0, L, a, b, c) of each segment of the turn, H = a + b s - c sin(2 pi s)/(2 pi): the
    cycloidal rise, the outer dwell, the return S = 1 - H(s), the inner dwell (units of the
    rise); None: the rise and a long dwell (the check run's span)."""
    if angles is None:
        return [(0.0, 1.0, 0.0, 1.0, 1.0), (1.0, 10.0, 1.0, 0.0, 0.0)], 3.0
    r0 = angles[0]
    up, r, low = angles[1] / r0, angles[2] / r0, angles[3] / r0
    return [(0.0, 1.0, 0.0, 1.0, 1.0), (1.0, up, 1.0, 0.0, 0.0),
            (1.0 + up, r, 1.0, -1.0, -1.0), (1.0 + up + r, low, 0.0, 0.0, 0.0)], 360.0 / r0


def _in(T, T0, L, last):
    return (T >= T0) & ((T <= T0 + L) if last else (T < T0 + L))


def _one_dof(tau, segs, T):
    """X, X', X'' of (3.1) from rest at T = 0 (module doc), X'' without cancellation."""
    w = TWO_PI / tau
    T = np.atleast_1d(np.asarray(T, dtype=float))
    X, V, A = (np.zeros_like(T) for _ in range(3))
    x0 = v0 = 0.0
    for n, (T0, L, a, b, c) in enumerate(segs):
        Om = TWO_PI / L
        K = c * w**2 / (TWO_PI * (w**2 - Om**2))
        C1, C2 = x0 - a, (v0 - (b / L - K * Om)) / w

        def at(t):
            u = t - T0
            free = C1 * np.cos(w * u) + C2 * np.sin(w * u)
            return (a + b * u / L - K * np.sin(Om * u) + free,
                    b / L - K * Om * np.cos(Om * u) + w * (-C1 * np.sin(w * u) + C2 * np.cos(w * u)),
                    K * Om**2 * np.sin(Om * u) - w**2 * free)
        m = _in(T, T0, L, n == len(segs) - 1)
        if m.any():
            X[m], V[m], A[m] = at(T[m])
        x0, v0, _ = (float(q) for q in at(np.array(T0 + L)))
    return X, V, A


def _cam(segs, T):
    """H and H'' of the designed motion (the cycloid H = s - sin(2 pi s)/(2 pi),
    H'' = 2 pi sin(2 pi s)/L^2 on a segment of length L; the return mirrored)."""
    T = np.atleast_1d(np.asarray(T, dtype=float))
    H, H2 = np.zeros_like(T), np.zeros_like(T)
    for n, (T0, L, a, b, c) in enumerate(segs):
        m = _in(T, T0, L, n == len(segs) - 1)
        s = (T[m] - T0) / L
        H[m] = a + b * s - c * np.sin(TWO_PI * s) / TWO_PI
        H2[m] = c * TWO_PI * np.sin(TWO_PI * s) / L**2
    return H, H2


def _largest(g, lo, hi, n=60001, top=4):
    """(max, where) of g on [lo, hi]: the grid's best points refined by bounded Brent."""
    T = np.linspace(lo, hi, n)
    v = g(T)
    best = (float(np.max(v)), float(T[np.argmax(v)]))
    for i in np.argsort(-v)[:top]:
        a, b = T[max(i - 1, 0)], T[min(i + 1, n - 1)]
        r = minimize_scalar(lambda t: -float(g(np.array([t]))[0]), bounds=(a, b),
                            method="bounded", options={"xatol": 1e-13})
        if -r.fun > best[0]:
            best = (-r.fun, float(r.x))
    return best


def _covers(value, true, estimate, floor, what):
    """The estimate covers the true error and is not absurd: at most 100 times it, or the
    stated floor."""
    err = abs(value - true)
    assert estimate is not None, what
    assert err <= estimate, f"{what}: error {err:.3g} > estimate {estimate:.3g}"
    assert estimate <= max(100 * err, floor), f"{what}: estimate {estimate:.3g} vs error {err:.3g}"


REL = 1e-7
"""The stated floor of an estimate, relative to its figure: the check run runs at rtol 1e-10,
and an estimate up to 1e-7 of the figure is small however lucky the true error."""


# -- A: the spring over the whole turn ---------------------------------------------------------
def test_the_whole_turns_kinetostatic_preload_is_the_hand_computation(rocker_turn):
    """The rigid rocker through rise 120, dwell 60, return 100, dwell 80 deg at 300 rpm:
    F0 >= (1 + mu)(-m x'') - k x with x = h H, x'' = h H''/t_m^2 from the cycloid's closed form,
    the largest over a grid of 3e6 + 1 points on the turn, within the grid's bound
    |g''|max (dT/2)^2/2 (|g''| <= (1 + mu) m h (2 pi)^3/(L^4 t_m^2) + k h 2 pi/L^2 on the
    return, the shorter segment, L = 100/120); it binds in the return, where the rise alone
    did not see it (the README's 0.56 N m pulled the arm off at 207 deg)."""
    d = rocker_turn
    M, kin = d["machine"], d["spring"]["kinetostatic"]
    h, m, t_m, k = M["stroke"], M["mass"], M["t_m"], 1000.0
    segs, P = _segments(TURN)

    def g(T):
        H, H2 = _cam(segs, T)
        return (1 + MU) * (-m * h * H2 / t_m**2) - k * h * H

    T = np.linspace(0.0, P, 3_000_001)
    v = g(T)
    dT = T[1] - T[0]
    L = TURN[2] / TURN[0]
    bound = 0.5 * ((1 + MU) * m * h * TWO_PI**3 / (L**4 * t_m**2) + k * h * TWO_PI / L**2) * (dT / 2)**2
    F0_grid = float(v.max())
    assert F0_grid <= kin["preload_min"] + kin["preload_min_error"]
    assert kin["preload_min"] <= F0_grid + bound + kin["preload_min_error"]
    F0, T0 = _largest(g, 0.0, P)
    _covers(kin["preload_min"], F0, kin["preload_min_error"], 1e-12 * F0, "kinetostatic F0")
    b = kin["binding"]
    assert b["part"] == "return" and abs(b["T"] - T0) <= b["T_error"]
    assert b["cam_angle"] == pytest.approx(math.radians(120) * T0, abs=b["cam_angle_error"] + 1e-12)
    assert b["time"] == pytest.approx(t_m * T0, abs=b["time_error"] + 1e-15)
    # the answer holds both the kinetostatic turn and the model's; the rise alone asked less
    sp = d["spring"]
    assert sp["preload_min"] >= kin["preload_min"] and sp["preload_min"] >= sp["dynamic"]["preload_min"]
    assert sp["rocker"]["preload_torque"] == pytest.approx(0.08 * sp["preload_min"], rel=1e-15)
    assert sp["rocker"]["rate_torsional"] == pytest.approx(1000.0 * 0.08**2, rel=1e-15)


def test_the_whole_turns_dynamic_figures_against_the_closed_form(rocker_turn):
    """The one-DOF rocker over one turn from rest: its least preload, where it binds, the
    largest inertia force, the least contact force, the energy swing, J, Fv and the vibration
    carried into the next turn, each within its estimate of the closed form (module doc)."""
    d = rocker_turn
    M, sp, fw = d["machine"], d["spring"], d["flywheel"]
    h, m, c, t_m, tau, k = M["stroke"], M["mass"], M["stiffness"], M["t_m"], M["tau"], 1000.0
    segs, P = _segments(TURN)

    def xa(T):
        X, V, A = _one_dof(tau, segs, T)
        return X * h, V * h / t_m, A * h / t_m**2

    F0_dyn, T_dyn = _largest(lambda T: (1 + MU) * (-m * xa(T)[2]) - k * xa(T)[0], 0.0, P)
    dyn = sp["dynamic"]
    _covers(dyn["preload_min"], F0_dyn, dyn["preload_min_error"], REL * F0_dyn, "dynamic F0")
    assert sp["binding"]["by"] == "dynamic" and sp["binding"]["part"] == "return"
    _covers(sp["T_binding"], T_dyn, sp["T_binding_error"], 1e-6, "T_binding")
    kin_F = sp["kinetostatic"]["inertia_force_max"]
    inertia = max(_largest(lambda T: -m * xa(T)[2], 0.0, P)[0], kin_F)
    _covers(sp["inertia_force_max"], inertia, sp["inertia_force_max_error"], REL * inertia,
            "inertia force")
    F0 = max(F0_dyn, sp["kinetostatic"]["preload_min"])
    H_of = (lambda T: _cam(segs, T)[0])
    hold = max(_largest(lambda T: -(m * xa(T)[2] + k * xa(T)[0]), 0.0, P)[0],
               _largest(lambda T: -(m * h * _cam(segs, T)[1] / t_m**2 + k * h * H_of(T)),
                        0.0, P)[0])
    _covers(sp["contact_force_min"], F0 - hold, sp["contact_force_min_error"], REL * F0,
            "contact force")

    def E(T):
        x, v, _ = xa(T)
        return 0.5 * m * v**2 + 0.5 * c * (h * H_of(T) - x)**2 + F0 * x + 0.5 * k * x**2
    dE = _largest(E, 0.0, P)[0] + _largest(lambda T: -E(T), 0.0, P)[0]
    _covers(fw["energy_swing"], dE, fw["energy_swing_error"], REL * dE, "energy swing")
    J = dE / (0.05 * M["w_s"]**2)
    _covers(fw["J"], J, fw["J_error"], REL * J, "J")
    Fv = m * h**2 / (J * M["beta_m"]**2)
    _covers(fw["Fv"], Fv, fw["Fv_error"], REL * Fv, "Fv")
    X, V, _ = _one_dof(tau, segs, np.array([P]))
    U = math.hypot(X[0], V[0] / (TWO_PI / tau))
    _covers(sp["carried"]["U"], U, sp["carried"]["U_error"], REL * U, "carried U")


def _profile_holds(preload_torque: float) -> bool:
    """Step 2 of the README's walk-through at that preload (`camdyn profile`'s cam and its
    kinetostatic contact force over the turn, runtime/cam): does the arm stay on the cam?"""
    from camdyn.runtime.cam.load import ContactLoad
    from camdyn.runtime.cam.profile import CamProfile
    from camdyn.runtime.cam.stress import ContactSpec

    cam = CamProfile(follower="oscillating-roller", law="cycloidal", swing_deg=18.0,
                     pivot_distance=0.10, arm_length=0.08, base_radius=0.04, roller_radius=0.008,
                     angles_deg=TURN)
    load = ContactLoad(speed_rpm=300.0, mass=0.0039, spring_rate=6.4, preload=preload_torque)
    stress = cam.stress_summary(ContactSpec(load, roller_width=0.01))
    (kept,) = [c for c in stress["checks"] if c["check"] == "contact kept"]
    return kept["ok"]


def test_the_walk_throughs_two_steps_agree(rocker_turn, finding):
    """Step 1 (`camdyn design` of the rocker over the turn 120, 60, 100, 80 deg) gives the
    preload as a torque at the pivot; step 2 (`camdyn profile` at that preload, its
    kinetostatic check over the turn) keeps the arm on the cam.  The rise alone's answer
    (--cam-angle 120deg, the finding's) does not: the return pulls the arm off."""
    assert rocker_turn["spring"]["rocker"]["rate_torsional"] == pytest.approx(6.4, rel=1e-12)
    assert _profile_holds(rocker_turn["spring"]["rocker"]["preload_torque"])
    assert not _profile_holds(finding["spring"]["rocker"]["preload_torque"])


def test_the_text_says_where_the_spring_binds(capsys):
    assert main(["design", *ROCKER, "--angles", "120,60,100,80", "--quiet"]) == 0
    out = capsys.readouterr().out
    assert "over the whole turn (rise 120, outer dwell 60, return 100, inner dwell 80 deg)" in out
    assert "binding: the dynamic motion in the return, at cam angle 208." in out
    assert "at the rocker's pivot (arm l = 80 mm): preload F0 l = " in out
    assert "carried into the next turn" in out


@pytest.mark.parametrize("argv, words", [
    (["--cam-angle", "110deg", "--angles", "120,60,100,80"],
     "argument --angles: its rise, 120 deg, differs from --cam-angle (110 deg)"),
    (["--rise-time", "0.05", "--angles", "120,60,100,80"],
     "argument --angles: its rise, 120 deg, differs from --rise-time with --speed (90 deg)"),
    (["--angles", "120,60,100"], "argument --angles: must be four numbers"),
    (["--angles", "a,b,c,d"], "argument --angles: must be four numbers"),
    (["--angles", "120,60,100,90"], "argument --angles: turn angles must sum to 360 deg"),
    (["--angles", "0,120,140,100"], "argument --angles: turn angle (rise)=0 is out of range"),
    (["--angles", "120,60,0,180"], "argument --angles: turn angle (return)=0 is out of range"),
    (["--angles", "120,-10,150,100"], "argument --angles: turn angle (upper dwell)=-10 is out"),
    (["--angles", "nan,120,120,120"], "argument --angles: turn angle (rise)=nan is out of range"),
])
def test_clashing_and_bad_angles_are_refused_in_one_line(capsys, argv, words):
    code = main(["design", *ROCKER, *argv, "--quiet"])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    (line,) = err.strip().splitlines()
    assert line.startswith("camdyn design: error: ") and words in line


# -- B: every estimate covers its error --------------------------------------------------------
def _check_run_truth(tau):
    """U0, U0'', X''min and its T of (3.1) for the cycloidal rise, from the closed form."""
    segs, _ = _segments(None)
    A_min, T_at = _largest(lambda T: -_one_dof(tau, segs, T)[2], 0.0, 1.0)
    X, V, _ = _one_dof(tau, segs, np.array([1.0]))
    w = TWO_PI / tau
    U0 = math.hypot(X[0] - 1.0, V[0] / w)
    return U0, w * w * U0, -A_min, T_at


@pytest.mark.parametrize("case", ["finding", "translating_rise", "translating_turn"])
def test_every_figure_covers_its_error(case, request):
    """The finding's command (a rocker, the rise alone), and a translating follower over the
    rise and over a turn whose inner dwell rings evenly (its preload binds at any of equal
    peaks): the check run's figures (U0, U0'', X''min and its T, u0, u0'', x''min, the inertia
    force, the ratio to the requirement), the spring's (the least preload, where it binds,
    the inertia force, the least contact force) and the flywheel's (the energy swing with the
    preload's error in it, J, Fv) against the closed form of (3.1)."""
    d = request.getfixturevalue(case)
    M, cr, sp, fw = d["machine"], d["check_run"], d["spring"], d["flywheel"]
    h, m, c, t_m, tau = M["stroke"], M["mass"], M["stiffness"], M["t_m"], M["tau"]
    k = sp["rate"]
    U0, U2, A_min, T_at = _check_run_truth(tau)
    acc = h / t_m**2
    accuracy = d["requirement"]["accuracy"]
    for key, true in (("U0", U0), ("U0dd", U2), ("Xdd_min_rise", A_min), ("T_at_Xdd_min", T_at),
                      ("u0", U0 * h), ("u0dd", U2 * acc), ("xdd_min_rise", A_min * acc),
                      ("inertia_force_max", -m * A_min * acc), ("ratio", U0 * h / accuracy)):
        _covers(cr[key], true, cr[f"{key}_error"], REL * abs(true), f"check run {key}")
    angles = d["spring"]["angles"]
    segs, P = _segments(None if angles is None else tuple(math.degrees(a) for a in angles))

    def xa(T):
        X, V, A = _one_dof(tau, segs, T)
        return X * h, V * h / t_m, A * h / t_m**2

    F_dyn, T_dyn = _largest(lambda T: (1 + MU) * (-m * xa(T)[2]) - k * xa(T)[0], 0.0, P)
    F0 = max(0.0, F_dyn, sp["kinetostatic"]["preload_min"])
    _covers(sp["preload_min"], F0, sp["preload_min_error"], REL * F0, "least preload")
    if sp["binding"]["by"] == "dynamic":
        # any peak within the estimate of the largest is where it binds: the truth's is one
        _covers(sp["T_binding"], T_dyn, sp["T_binding_error"], 1e-6, "T_binding")
    H_of = (lambda T: _cam(segs, T)[0])

    def E(T):
        x, v, _ = xa(T)
        return 0.5 * m * v**2 + 0.5 * c * (h * H_of(T) - x)**2 + F0 * x + 0.5 * k * x**2
    dE = _largest(E, 0.0, P)[0] + _largest(lambda T: -E(T), 0.0, P)[0]
    _covers(fw["energy_swing"], dE, fw["energy_swing_error"], REL * dE, "energy swing")
    J = dE / (0.05 * M["w_s"]**2)
    _covers(fw["J"], J, fw["J_error"], REL * J, "J")
    Fv = m * h**2 / (J * M["beta_m"]**2)
    _covers(fw["Fv"], Fv, fw["Fv_error"], REL * Fv, "Fv")


def test_the_finding_command_prints_every_figure_with_its_estimate(capsys, finding):
    """The finding's command: the check run's and the spring's lines carry "±" on every
    figure, and the JSON has an ``_error`` beside each."""
    assert main(["design", *FINDING, "--quiet"]) == 0
    out = capsys.readouterr().out
    for line in out.splitlines():
        if line.startswith(("  u0 = ", "  X''min", "  the run against", "  at the rate",
                            "  binding", "  least contact", "  energy swing", "  camshaft inertia")):
            assert line.count("±") >= line.count("=") - line.count("= U0"), line
    d = finding
    for key in ("u0", "u0dd", "xdd_min_rise", "inertia_force_max", "ratio"):
        assert d["check_run"][f"{key}_error"] > 0, key
    assert d["spring"]["T_binding_error"] > 0 and d["spring"]["binding"]["time_error"] > 0
    assert d["envelope"]["u0_error"] > 0 and d["requirement"]["ratio_error"] > 0


def test_the_surge_run_covers_its_error(finding):
    """The coils' U0(tau_s) against the closed form of (3.1) at tau_s."""
    s = finding["spring"]["surge"]
    U0, _, _, _ = _check_run_truth(s["tau_surge"])
    _covers(s["U0"], U0, s["U0_error"], REL * U0, "surge U0")
