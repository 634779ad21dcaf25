"""The machine over its band (thesis/design/band/residual.py, kinematics.py): the worst
residual over the speed band against independent computations (the closed form (3.5) and SciPy
solve_ivp, maximised over the band by a dense grid and minimize_scalar), the least model and
the shaft's numbers (4.1)-(4.14), (5.51)-(5.52) by hand, and the rigid follower's motion
against the cycloid's hand formulas."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import minimize_scalar

from camdyn.runtime.core.errors import CamdynInputError
from camdyn.thesis.design.band import kinematics, residual, spec

H = 0.025


def machine(**changes):
    """A translating roller follower: 25 mm in 120 deg, 0.8 kg at 2e6 N/m (T_e = 3.97 ms),
    500-1000 rpm: tau from 0.0994 to 0.199, five periods of U0 in 1/tau."""
    data = {"kind": "machine",
            "follower": {"type": "translating-roller", "roller_radius": 0.01},
            "motion": {"stroke": H, "angles": [120, 60, 150, 30]},
            "speed": {"band": "500:1000 rpm"},
            "train": {"mass": 0.8, "stiffness": 2e6},
            "cam": {"base_radius": 0.04}}
    for key, value in changes.items():
        table, name = key.split("__")
        if value is None:
            data.get(table, {}).pop(name, None)
        else:
            data.setdefault(table, {})[name] = value
    return spec.from_dict(data, "test")


def worst_over(U0, taus, grid_values=None, n=4001):
    """(largest U0, its tau) over the band: a dense grid (``grid_values(grid)``, or U0 at
    every point), its best point refined by SciPy's bounded Brent between its neighbours."""
    grid = np.linspace(taus[0], taus[1], n)
    values = grid_values(grid) if grid_values is not None else U0(grid)
    k = int(np.argmax(values))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, n - 1)]
    opt = minimize_scalar(lambda t: -U0(t), bounds=(lo, hi), method="bounded",
                          options={"xatol": 1e-13})
    best = (-float(opt.fun), float(opt.x))
    ends = [(float(U0(t)), float(t)) for t in (lo, hi) if t in (taus[0], taus[1])]
    return max([best, *ends])


def cycloid_U0(tau):
    """(3.5) by hand: tau^3 |sin(pi/tau)| / (pi |1 - tau^2|)."""
    return tau**3 * np.abs(np.sin(np.pi / tau)) / (np.pi * np.abs(1 - tau**2))


# -- the worst residual ---------------------------------------------------------------------

def test_worst_residual_of_the_cycloid_is_the_closed_forms_largest():
    """Undamped one-DOF model, cycloidal rise: the worst u0 over 500-1000 rpm is (3.5)'s
    largest value over the band times the stroke, within the stated error, which is below
    1e-4 of it; found where (3.5) peaks, within the stated place error; and every point of
    the curve for the chart is (3.5) within its own error."""
    m = machine()
    w = residual.worst_residual(m, "cycloidal", residual.ladder(m))
    ref, tau_ref = worst_over(cycloid_U0, m.taus)
    assert w.model == "one_dof"
    assert abs(w.value - ref * H) <= w.error
    assert w.error <= 1e-4 * w.value
    assert abs(w.speed - m.speed_of(tau_ref)) <= w.speed_error + 1e-9 * w.speed
    curve_taus = np.array([m.tau(s) for s in w.curve_speeds])
    assert np.all(np.diff(w.curve_speeds) > 0)
    assert np.all(np.abs(w.curve_values - cycloid_U0(curve_taus) * H) <= w.curve_errors)
    assert curve_taus[0] == pytest.approx(m.taus[0], rel=1e-12)
    assert curve_taus[-1] == pytest.approx(m.taus[1], rel=1e-12)


def _three_four_five(T):
    """H'' of the 3-4-5 rise by hand: H = 10 T^3 - 15 T^4 + 6 T^5."""
    return 60 * T - 180 * T**2 + 120 * T**3


def solve_ivp_U0(tau, q, Hdd):
    """U0 of the one-DOF model (3.1) by SciPy: m x'' + c (x - h) + d (x' - h') = 0 (the
    model's damper acts on x' - h', derive/models/one_dof.py), written in the error u = x - h
    of the stroke, time in t_m: u'' + 2 q w u' + w^2 u = -H''(T), w = 2 pi/tau; DOP853 at
    rtol 1e-11 over the rise and on into the dwell; U0 the largest |u| there (the model reads
    it over [1, 3]; the free vibration's envelope only decays, so its first 1.25 periods hold
    the largest), the dense output sampled 64 times a period and its best sample refined by
    Brent."""
    w = 2 * np.pi / tau
    end = 1.0 + 1.25 * tau

    def rhs(H_dd):
        return lambda T, y: [y[1], -H_dd(T) - 2 * q * w * y[1] - w**2 * y[0]]

    opts = dict(method="DOP853", rtol=1e-11, atol=1e-16)
    rise = solve_ivp(rhs(Hdd), (0.0, 1.0), [0.0, 0.0], **opts)
    dwell = solve_ivp(rhs(lambda T: 0.0), (1.0, end), rise.y[:, -1], dense_output=True, **opts)
    T = np.linspace(1.0, end, 81)
    u = np.abs(dwell.sol(T)[0])
    k = int(np.argmax(u))
    if k in (0, len(T) - 1):
        return float(u[k])
    opt = minimize_scalar(lambda t: -abs(dwell.sol(t)[0]), bounds=(T[k - 1], T[k + 1]),
                          method="bounded", options={"xatol": 1e-13})
    return max(float(u[k]), -opt.fun)


def solve_ivp_grid(taus, q, Hdd, t_end=3.0):
    """:func:`solve_ivp_U0` of many taus in one solve_ivp (each oscillator its own pair of
    states), the dwell's largest |u| over [1, 3] read from 64 samples a period: the grid that
    finds the worst hump, whose top Brent then refines on single runs."""
    w = 2 * np.pi / np.asarray(taus)
    n = len(w)

    def rhs(H_dd):
        def f(T, y):
            u, v = y[:n], y[n:]
            return np.concatenate([v, -H_dd(T) - 2 * q * w * v - w**2 * u])
        return f

    opts = dict(method="DOP853", rtol=1e-11, atol=1e-16)
    rise = solve_ivp(rhs(Hdd), (0.0, 1.0), np.zeros(2 * n), **opts)
    T = np.linspace(1.0, t_end, int(64 * (t_end - 1.0) / min(taus)) + 1)
    dwell = solve_ivp(rhs(lambda T: 0.0), (1.0, t_end), rise.y[:, -1], t_eval=T, **opts)
    return np.abs(dwell.y[:n]).max(axis=1)


@pytest.mark.parametrize("zeta", [0.0, 0.05])
def test_worst_residual_of_the_3_4_5_rise_against_solve_ivp(zeta):
    """The 3-4-5 rise, undamped and at damping ratio 0.05 (q, (6.47)): the worst u0 over the
    band against SciPy's solve_ivp of the model's equation maximised over the band (a grid
    of 161 speeds and Brent), within the stated error, which is below 1e-4 of it."""
    m = machine(train__damping_ratio=zeta)
    ladder = residual.ladder(m)
    assert ladder.model == "one_dof" and ladder.params == {"q": zeta}
    w = residual.worst_residual(m, "3-4-5", ladder)

    def U0(tau):
        return solve_ivp_U0(tau, zeta, _three_four_five)

    def grid_values(taus):
        return solve_ivp_grid(taus, zeta, _three_four_five)

    ref, tau_ref = worst_over(U0, m.taus, grid_values, n=161)
    assert abs(w.value - ref * H) <= w.error
    assert w.error <= 1e-4 * w.value
    assert abs(w.speed - m.speed_of(tau_ref)) <= w.speed_error + 1e-6 * w.speed


def test_a_band_that_is_one_speed_and_a_band_whose_worst_is_its_end():
    """One speed: the residual there by (3.5), placed exactly.  A band (390-435 rpm, 1/tau
    from 12.9 to 11.57, just past a hump's top at 11.5) whose largest U0 by (3.5) lies at its
    top end: the worst is that end's."""
    m = machine(speed__band="700 rpm")
    w = residual.worst_residual(m, "cycloidal", residual.ladder(m))
    assert abs(w.value - cycloid_U0(m.taus[0]) * H) <= w.error
    assert w.speed_error == 0.0 and w.speed == m.speeds[0]
    m = machine(speed__band="390:435 rpm")
    ref, tau_ref = worst_over(cycloid_U0, m.taus)
    w = residual.worst_residual(m, "cycloidal", residual.ladder(m))
    assert tau_ref == pytest.approx(m.taus[1], rel=1e-12)
    assert abs(w.value - ref * H) <= w.error and w.speed == pytest.approx(m.speeds[1], rel=1e-12)


def test_a_law_file_works_as_the_law_it_is(tmp_path):
    """A blend file that is the 3-4-5 rise gives the 3-4-5 law's worst residual, within the
    two errors."""
    f = tmp_path / "b345.toml"
    f.write_text('[[point]]\nT = 0\nH = 0\n"H\'" = 0\n"H\'\'" = 0\n'
                 '[[point]]\nT = 1\nH = 1\n"H\'" = 0\n"H\'\'" = 0\n')
    m = machine()
    ladder = residual.ladder(m)
    a = residual.worst_residual(m, str(f), ladder)
    b = residual.worst_residual(m, "3-4-5", ladder)
    assert abs(a.value - b.value) <= a.error + b.error


def test_the_polydyne_is_designed_at_the_bands_centre():
    """Its design tau is the centre speed's, T_e w_c/beta_m (4.12); its residual vanishes
    there (the one-DOF output follows the degree-9 rise exactly), so the curve dips to the
    runs' accuracy near the centre.  A band whose centre reaches tau >= 1 is refused by name."""
    m = machine()
    w_c = 750 * 2 * math.pi / 60
    tau_c = 2 * math.pi * math.sqrt(0.8 / 2e6) * w_c / math.radians(120)
    assert residual.theta_of(m, "polydyne") == pytest.approx(tau_c, rel=1e-12)
    L = residual.ladder(m)
    w = residual.worst_residual(m, "polydyne", L)
    near = np.abs(w.curve_speeds - w_c) < 0.02 * w_c
    assert near.any() and np.min(w.curve_values[near]) < 1e-2 * w.value
    same = residual.worst_residual(m, "polydyne", L, theta=tau_c)
    assert abs(same.value - w.value) <= same.error + w.error
    other = residual.worst_residual(m, "polydyne", L, theta=0.5 * tau_c)
    assert abs(other.value - w.value) > other.error + w.error
    slow = machine(train__mass=2000.0)
    with pytest.raises(CamdynInputError, match="polydyne"):
        residual.theta_of(slow, "polydyne")


def test_brents_maximum_inside_and_at_an_end():
    """Brent's method finds the top of a parabola inside the interval and the end where the
    function rises to it, each within its tolerance (against the hand answer)."""
    x, v = residual.maximize(lambda t: 2.0 - (t - 0.3) ** 2, 0.0, 1.0, 1e-8)
    assert abs(x - 0.3) <= 1e-8 and v == pytest.approx(2.0, abs=1e-15)
    x, v = residual.maximize(lambda t: math.exp(t), 0.0, 1.0, 1e-8)
    assert 1.0 - x <= 1e-8


# -- the ladder of models -------------------------------------------------------------------

def test_without_camshaft_data_the_one_dof_model_and_above_tau_1_camshaft1():
    """No camshaft: the one-DOF model (3.1) with the damping ratio as q.  A band reaching
    tau >= 1 (a slow train, 400 kg at 2e6 N/m) takes CAMSHAFT-1 at Fa = 0, the same model,
    saying so, and warning that the damping is left out; and its worst residual is (3.5)'s
    largest (the cycloid, |1 - tau^2| through resonance) within the stated error."""
    m = machine(train__damping_ratio=0.02)
    L = residual.ladder(m)
    assert (L.model, L.params) == ("one_dof", {"q": 0.02}) and "(3.1)" in L.why
    slow = machine(train__mass=400.0, train__damping_ratio=0.02)
    assert slow.taus[1] > 1
    L = residual.ladder(slow)
    assert (L.model, L.params) == ("camshaft1", {"Fa": 0.0}) and "tau = " in L.why
    assert any("damping ratio 0.02 is left out" in x for x in L.warnings)
    w = residual.worst_residual(slow, "cycloidal", L)
    ref, _ = worst_over(cycloid_U0, slow.taus)
    assert abs(w.value - ref * H) <= w.error <= 1e-4 * w.value
    assert w.warnings[0] == L.warnings[0]


def test_the_shafts_numbers_by_hand():
    """A translating roller: R_1/2 = r_b + r_r + h/2 (4.1), tan alpha_me = h/(R_1/2 beta_m)
    (4.13), 1/c_tan = R_1/2^2/k + 1/c_y (4.4), Fa = (c_c/c_tan) tan^2 alpha_me (4.14),
    m_tan = (J/R_1/2^2)(c_tan R_1/2^2/k)^2 (5.51), Fv = (m/m_tan) tan^2 alpha_me (5.52).  A
    flat face winds the shaft only: Fa = c_c h^2/(k beta_m^2) (5.12b), Fv = m h^2/(J beta_m^2)
    (5.14b)."""
    k, c_y, J = 2000.0, 5e6, 0.0015
    m = machine(camshaft__torsional_stiffness=k, camshaft__bending_stiffness=c_y,
                camshaft__inertia=J)
    beta, c, mass = math.radians(120), 2e6, 0.8
    R = 0.04 + 0.01 + H / 2
    tan = H / (R * beta)
    c_tan = 1 / (R**2 / k + 1 / c_y)
    m_tan = J / R**2 * (c_tan * R**2 / k) ** 2
    s = residual.shaft(m)
    assert s["pitch_radius"] == pytest.approx(R, rel=1e-14)
    assert s["c_tan"] == pytest.approx(c_tan, rel=1e-12)
    assert s["Fa"] == pytest.approx(c / c_tan * tan**2, rel=1e-12)
    assert s["Fv"] == pytest.approx(mass / m_tan * tan**2, rel=1e-12)
    flat = machine(follower__type="translating-flat", camshaft__torsional_stiffness=k,
                   camshaft__bending_stiffness=c_y, camshaft__inertia=J)
    s = residual.shaft(flat)
    assert s["Fa"] == pytest.approx(c * H**2 / (k * beta**2), rel=1e-12)
    assert s["Fv"] == pytest.approx(mass * H**2 / (J * beta**2), rel=1e-12)
    assert residual.shaft(machine()) is None


def test_a_rockers_pitch_radius_from_its_triangle():
    """An oscillating roller (pivot 0.1 m away, arm 0.08 m, r_b + r_r = 0.05 m, swing 20 deg):
    the roller centre's distance from the cam centre at half the swing, by the law of
    cosines from the arm's angle at rest."""
    m = machine(follower__type="oscillating-roller", follower__pivot_distance=0.1,
                follower__arm_length=0.08, motion__stroke=None, motion__swing=20.0,
                train__mass=None, train__inertia=0.0039, train__stiffness=None,
                train__torsional_stiffness=12800.0)
    a, arm, r0 = 0.1, 0.08, 0.05
    psi0 = math.acos((a * a + arm * arm - r0 * r0) / (2 * a * arm))
    psi = psi0 + math.radians(10)
    assert residual.pitch_radius(m) == pytest.approx(
        math.sqrt(a * a + arm * arm - 2 * a * arm * math.cos(psi)), rel=1e-14)


@pytest.mark.parametrize("k, J, model, words", [
    (2e6, None, "one_dof", "does not show"),
    (300.0, None, "camshaft1", "(4.15)"),
    (300.0, 0.0015, "camshaft2", "sec. 8.2.5")])
def test_the_least_model_by_chapter_8(k, J, model, words):
    """A stiff shaft leaves the one-DOF model (Fa changes the worst U0 by < 2 %); a soft one
    needs CAMSHAFT-1 (4.15); with a cam whose inertia gives a small Fv (the cam's speed
    varies) CAMSHAFT-2, sec. 8.2.5."""
    m = machine(camshaft__torsional_stiffness=k, camshaft__inertia=J)
    L = residual.ladder(m)
    assert L.model == model and words in L.why
    if model == "one_dof":
        assert L.params == {"q": 0.0}
    else:
        assert L.params["Fa"] == residual.shaft(m)["Fa"]


def test_a_shaft_beyond_the_models_is_refused_by_name():
    with pytest.raises(CamdynInputError, match="Fa = .*camshaft.torsional_stiffness"):
        residual.ladder(machine(camshaft__torsional_stiffness=1e-3))


# -- the rigid follower's motion ------------------------------------------------------------

def test_svaj_of_the_cycloid_and_its_mirrored_return_by_hand():
    """s = h (T - sin(2 pi T)/(2 pi)) over the rise, T = phi/beta_m; v, a, j with 1/t_m,
    t_m = beta_m/w; over the return the mirror, s = h (1 - H(T_r)) with its own t_r."""
    m = machine()
    w = 60.0
    S = kinematics.svaj(m, "cycloidal", w, n=3601)
    th = S.theta_deg
    for lo, width, sign, base in ((0.0, 120.0, 1, 0.0), (180.0, 150.0, -1, H)):
        inside = (th > lo) & (th < lo + width)
        T = (th[inside] - lo) / width
        t = math.radians(width) / w
        x = 2 * np.pi * T
        hand = {"s": base + sign * H * (T - np.sin(x) / (2 * np.pi)),
                "v": sign * H / t * (1 - np.cos(x)), "a": sign * H / t**2 * 2 * np.pi * np.sin(x),
                "j": sign * H / t**3 * 4 * np.pi**2 * np.cos(x)}
        for key, ref in hand.items():
            got = getattr(S, key)[inside]
            assert np.abs(got - ref).max() <= 1e-12 * np.abs(ref).max()
    dwell = (th > 120) & (th < 180)
    assert np.all(S.s[dwell] == pytest.approx(H, rel=1e-15)) and np.all(S.a[dwell] == 0)


def test_peaks_of_the_cycloid_by_hand():
    """a_max = 2 pi h/t^2 and j_max = 4 pi^2 h/t^3 (t the rise's or the return's, the
    shorter), within the stated error; a return faster than the rise sets them."""
    for angles, width in (([120, 60, 150, 30], 120.0), ([150, 30, 90, 90], 90.0)):
        m = machine(motion__angles=angles)
        w = 50.0
        p = kinematics.peaks(m, "cycloidal", w)
        t = math.radians(width) / w
        assert abs(p.acceleration_max - 2 * math.pi * H / t**2) <= p.acceleration_max_error
        assert abs(p.jerk_max - 4 * math.pi**2 * H / t**3) <= p.jerk_max_error
        assert p.acceleration_max_error <= 1e-12 * p.acceleration_max
        assert p.warnings == () and p.velocity_jump == 0 and p.acceleration_jump == 0


def test_jumps_give_infinite_peaks_and_their_size_in_the_warnings():
    """The simple-harmonic rise starts with H'' = pi^2/2 against the dwell's 0: an infinite
    jerk, the jump h (w/beta_m)^2 pi^2/2 named; the uniform rise starts with H' = 1 against 0:
    an infinite acceleration, the velocity jump h w/beta_m named."""
    m = machine()
    w = 50.0
    k = w / math.radians(120)
    p = kinematics.peaks(m, "simple-harmonic", w)
    jump = H * k**2 * math.pi**2 / 2
    assert p.jerk_max == math.inf and p.acceleration_jump == pytest.approx(jump, rel=1e-9)
    assert p.acceleration_max == pytest.approx(jump, rel=1e-12)
    assert any(f"jumps by {jump:.4g} m/s^2" in x for x in p.warnings)
    p = kinematics.peaks(m, "uniform", w)
    assert p.acceleration_max == math.inf and p.jerk_max == math.inf
    assert p.velocity_jump == pytest.approx(H * k, rel=1e-12)
    assert any(f"jumps by {H * k:.4g} m/s" in x for x in p.warnings)


def test_a_rockers_motion_is_along_its_arc_and_its_arm_turns_by_the_swing():
    """An oscillating roller's SVAJ is its roller's arc (l Phi at the top, (2.55)); the arm's
    angle over it is s/l and reaches the swing."""
    m = machine(follower__type="oscillating-roller", follower__pivot_distance=0.1,
                follower__arm_length=0.08, motion__stroke=None, motion__swing=20.0,
                train__mass=None, train__inertia=0.0039, train__stiffness=None,
                train__torsional_stiffness=12800.0)
    S = kinematics.svaj(m, "cycloidal", 50.0)
    assert S.s.max() == pytest.approx(0.08 * math.radians(20), rel=1e-14)
    arm = S.arm()
    assert arm["psi"].max() == pytest.approx(math.radians(20), rel=1e-14)
    assert kinematics.svaj(machine(), "cycloidal", 50.0).arm() is None
