"""The spring over the whole turn and the band, the cam's contact and the drive of a machine
(thesis/design/band/spring.py, contact.py, drive.py), against computations typed in here:
the cycloid's closed forms (its rise H'' = 2 pi sin 2 pi T and the mirrored return), the
one-DOF follower (3.1) integrated by SciPy over the whole turn, Hertz's line contact (Johnson,
Contact Mechanics, sec. 4.3), the translating roller's pressure angle and the drive torque by
virtual work."""
from __future__ import annotations

import math
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

from camdyn.thesis.design.band import contact, drive, residual, spec, spring

H, MASS, STIFF, RATE, MU = 0.025, 0.8, 2e6, 1000.0, 0.3
RB, RR, WIDTH = 0.04, 0.01, 0.012
ANGLES = (100.0, 60.0, 130.0, 70.0)       # rise, outer dwell, return, inner dwell (deg)
LO, HI = 300 * math.pi / 30, 600 * math.pi / 30


def machine(**changes) -> spec.Machine:
    tables = {"follower": {"type": "translating-roller", "roller_radius": RR,
                           "roller_width": WIDTH},
              "motion": {"stroke": H, "angles": list(ANGLES)},
              "speed": {"band": [LO, HI]},
              "train": {"mass": MASS, "stiffness": STIFF},
              "spring": {"rate": RATE, "margin": MU},
              "cam": {"base_radius": RB, "materials": "steel, steel",
                      "allowable_stress": 1.2e9}}
    for key, value in changes.items():
        table, name = key.split("__")
        tables.setdefault(table, {})[name] = value
    return spec.from_dict(tables, "test")


# -- the cycloid over the whole turn, by hand ------------------------------------------------------

def cycloid_turn(T, angles=ANGLES):
    """H, H', H'' of the cycloidal rise and its mirrored return at T (units of the rise):
    H = T - sin(2 pi T)/(2 pi), H' = 1 - cos 2 pi T, H'' = 2 pi sin 2 pi T; the return over
    r = return/rise, H = 1 - H_c(u), H^(n) = -H_c^(n)(u)/r^n."""
    T = np.asarray(T, dtype=float)
    up, r = angles[1] / angles[0], angles[2] / angles[0]
    out = np.zeros((3,) + T.shape)
    rise = (T >= 0) & (T < 1)
    out[0, rise] = T[rise] - np.sin(2 * np.pi * T[rise]) / (2 * np.pi)
    out[1, rise] = 1 - np.cos(2 * np.pi * T[rise])
    out[2, rise] = 2 * np.pi * np.sin(2 * np.pi * T[rise])
    out[0, (T >= 1) & (T < 1 + up)] = 1.0
    ret = (T >= 1 + up) & (T < 1 + up + r)
    u = (T[ret] - 1 - up) / r
    out[0, ret] = 1 - (u - np.sin(2 * np.pi * u) / (2 * np.pi))
    out[1, ret] = -(1 - np.cos(2 * np.pi * u)) / r
    out[2, ret] = -2 * np.pi * np.sin(2 * np.pi * u) / r**2
    return out


def pieces(angles=ANGLES):
    up, r = angles[1] / angles[0], angles[2] / angles[0]
    return [(0.0, 1.0), (1.0 + up, 1.0 + up + r)]


def largest_by_hand(f, angles=ANGLES) -> tuple[float, float]:
    """max f over the rise and the return: a grid of 20001 points a piece, then SciPy's bounded
    Brent between the best point's neighbours to 1e-13."""
    best = (-math.inf, math.nan)
    for a, b in pieces(angles):
        T = np.linspace(a, b, 20001)
        v = f(T)
        i = int(np.argmax(v))
        lo, hi = T[max(i - 1, 0)], T[min(i + 1, T.size - 1)]
        r = minimize_scalar(lambda t: -float(f(np.array([t]))[0]), bounds=(lo, hi),
                            method="bounded", options={"xatol": 1e-13})
        for val, at in ((v[i], T[i]), (-r.fun, r.x)):
            if val > best[0]:
                best = (float(val), float(at))
    return best


def need_by_hand(w, k=RATE, mass=MASS, h=H, angles=ANGLES):
    """(1 + mu) m (-x'') - k x of the rigid follower at w: x = h H, x'' = h H'' w^2/beta^2."""
    beta = math.radians(angles[0])

    def f(T):
        Hs = cycloid_turn(T, angles)
        return (1 + MU) * mass * (-h * Hs[2] * w**2 / beta**2) - k * h * Hs[0]
    return f


@pytest.mark.parametrize("rate", [0.0, 1000.0, 5000.0])
def test_whole_turn_least_preload_kinetostatic_by_hand(rate):
    """F0 + k x >= (1 + mu) m (-x'') everywhere over the turn at the top speed: the least F0 is
    the largest (1 + mu) m (-x'') - k x over the cycloid's rise and its longer mirrored return
    (typed in here), to 1e-9 and within the stated error; the rise binds (its deceleration is
    (130/100)^2 times the return's), past its middle, where the stiffer spring shifts it."""
    m = machine(spring__rate=rate)
    a = spring.spring(m, "cycloidal", residual.ladder(m), dynamic_jump=False)
    need, T = largest_by_hand(need_by_hand(HI, k=rate))
    assert a.preload_min_kinetostatic == pytest.approx(need, rel=1e-9)
    assert abs(a.preload_min_kinetostatic - need) <= a.preload_min_kinetostatic_error + 1e-9 * need
    assert a.binding_part_kinetostatic == "rise"
    assert a.binding_angle_deg_kinetostatic == pytest.approx(T * ANGLES[0], abs=1e-5)


def test_kinetostatic_jump_speed_of_the_cycloid_in_closed_form():
    """Without a rate the rigid follower leaves the cam where the inertia force at its worst
    place, 2 pi m h w^2/beta^2 (H'' = -2 pi at T = 3/4 of the rise), equals the preload:
    w_j = beta (F0/(2 pi m h))^(1/2), to 1e-9 and within the stated error."""
    F0 = 60.0
    m = machine(spring__rate=0.0, spring__preload=F0)
    a = spring.spring(m, "cycloidal", residual.ladder(m), dynamic_jump=False)
    beta = math.radians(ANGLES[0])
    w_j = beta * math.sqrt(F0 / (2 * math.pi * MASS * H))
    assert LO < w_j < HI
    assert a.jump_speed_kinetostatic == pytest.approx(w_j, rel=1e-9)
    assert abs(a.jump_speed_kinetostatic - w_j) <= a.jump_speed_kinetostatic_error + 1e-9 * w_j
    assert a.preload_used == F0 and a.preload_given
    assert any("leaves the cam within the band" in w for w in a.warnings)


def test_kinetostatic_jump_speed_with_a_rate_by_root_finding():
    """With a rate the place shifts with the speed: the speed at which the least over the turn
    of F0 + k h H + m h H'' w^2/beta^2 reaches 0, by SciPy's brentq on w over the hand-made
    maximum of the need (:func:`largest_by_hand`), to 1e-8."""
    F0, k = 40.0, 5000.0
    m = machine(spring__rate=k, spring__preload=F0)
    a = spring.spring(m, "cycloidal", residual.ladder(m), dynamic_jump=False)
    beta = math.radians(ANGLES[0])

    def least(w):
        def pull(T):
            Hs = cycloid_turn(T)
            return -(F0 + k * H * Hs[0] + MASS * H * Hs[2] * w**2 / beta**2)
        return -largest_by_hand(pull)[0]
    w_j = brentq(least, LO / 2, 2 * HI, xtol=1e-12)
    assert a.jump_speed_kinetostatic == pytest.approx(w_j, rel=1e-8)


# -- the dynamic figures against SciPy -----------------------------------------------------------

def _H(t: float, a: float, b: float) -> float:
    """The turn's H at t inside the piece [a, b) (scalar: SciPy's right-hand side)."""
    up, r = ANGLES[1] / ANGLES[0], ANGLES[2] / ANGLES[0]
    t = min(max(t, a), b)
    if a == 0.0:
        return t - math.sin(2 * math.pi * t) / (2 * math.pi)
    if a == 1.0 + up:
        u = (t - a) / r
        return 1.0 - (u - math.sin(2 * math.pi * u) / (2 * math.pi))
    return 1.0 if a == 1.0 else 0.0


def one_dof_turn(tau, T):
    """X, X'' of (3.1), X'' = (2 pi/tau)^2 (H - X), driven by the cycloid's whole turn from
    rest (typed in here), by SciPy's DOP853 at rtol 1e-12, piece by piece."""
    w2 = (2 * math.pi / tau) ** 2
    up, r = ANGLES[1] / ANGLES[0], ANGLES[2] / ANGLES[0]
    ends = [0.0, 1.0, 1 + up, 1 + up + r, sum(ANGLES) / ANGLES[0]]
    y, sols = [0.0, 0.0], []
    for a, b in zip(ends[:-1], ends[1:]):
        s = solve_ivp(lambda t, z: [z[1], w2 * (_H(t, a, b) - z[0])], (a, b), y,
                      method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)
        y = s.y[:, -1]
        sols.append((a, b, s.sol))
    X = np.empty_like(T)
    for a, b, sol in sols:
        on = (T >= a) & (T <= b)
        X[on] = sol(T[on])[0]
    return X, w2 * (cycloid_turn(np.minimum(T, ends[-1] - 1e-15))[0] - X)


def test_dynamic_least_preload_and_contact_force_against_scipy():
    """At the top speed the Ladder's model (the one-DOF follower over the whole turn from rest)
    needs F0 >= max (1 + mu) m (-x'') - k x: SciPy's run on 150,001 points gives it to 1e-6,
    within the stated error and the grid's allowance; the contact force over the turn at the
    top speed with that preload, F0 + k x + m x'', agrees point by point to 1e-6 of its
    largest, and so does the peak drive torque |F h H'/beta| within its error."""
    m = machine()
    a = spring.spring(m, "cycloidal", residual.ladder(m), dynamic_jump=False)
    tau, t_m = m.tau(HI), math.radians(ANGLES[0]) / HI
    T = np.linspace(0.0, sum(ANGLES) / ANGLES[0], 150001)
    X, Xdd = one_dof_turn(tau, T)
    x, a_ = H * X, H * Xdd / t_m**2
    need = float(np.max((1 + MU) * MASS * (-a_) - RATE * x))
    assert a.preload_min == pytest.approx(need, rel=1e-6)
    assert abs(a.preload_min - need) <= a.preload_min_error + 1e-6 * need
    assert a.preload_used == max(a.preload_min, a.preload_min_kinetostatic)
    F = a.preload_used + RATE * x + MASS * a_
    mine = np.interp(T * ANGLES[0], a.theta_deg, a.contact_force_hi)
    # the answer's grid is every eighth of a degree: compare at its own angles
    at = a.theta_deg / ANGLES[0]
    Xa, Xdda = one_dof_turn(tau, at)
    Fa = a.preload_used + RATE * H * Xa + MASS * H * Xdda / t_m**2
    assert np.max(np.abs(a.contact_force_hi - Fa)) <= 1e-6 * np.max(np.abs(Fa))
    scale = np.max(np.abs(Fa))
    assert np.all(np.abs(a.contact_force_hi - Fa) <= a.contact_force_hi_error + 1e-6 * scale)
    assert a.contact_force_min == pytest.approx(float(np.min(F)), rel=1e-5)
    assert np.min(mine) >= a.contact_force_min - 1e-6 * a.preload_used
    # the dynamic drive torque F h H'/beta on the same run
    d = drive.drive(m, "cycloidal", residual.ladder(m), a.preload_used)
    M = np.abs(F * H * cycloid_turn(T)[1] / math.radians(ANGLES[0]))
    assert abs(d.torque_max_dynamic - np.max(M)) <= d.torque_max_dynamic_error + 1e-7 * np.max(M)


def test_dynamic_jump_speed_is_where_scipys_follower_first_leaves_the_cam():
    """A given preload of 120 N (below the dynamic least at 600 rpm): the dynamic jump speed is
    a sign change of the least contact force over the turn of SciPy's one-DOF run (positive
    twice its stated error below it, negative as far above), the chart's least contact force at the
    band's lowest speed agrees with SciPy's (on 300,001 points) within its error, and the
    kinetostatic jump speed lies above the dynamic one (the vibration adds to the pull)."""
    F0 = 120.0
    m = machine(spring__preload=F0)
    a = spring.spring(m, "cycloidal", residual.ladder(m))
    assert a.jump_speed is not None and a.jump_speed == a.jump_speed_dynamic
    assert a.jump_speed_error < 1e-4 * a.jump_speed
    beta = math.radians(ANGLES[0])
    def least(w, n=60001):
        T = np.linspace(0.0, sum(ANGLES) / ANGLES[0], n)
        X, Xdd = one_dof_turn(m.tau(w), T)
        return float(np.min(F0 + RATE * H * X + MASS * H * Xdd * w**2 / beta**2))
    step = 2 * a.jump_speed_error
    assert least(a.jump_speed - step) > 0.0 > least(a.jump_speed + step)
    # the chart's points below the jump speed hold (SciPy at the band's lowest speed)
    assert abs(a.jump_margin[0] - least(LO, 300001)) <= a.jump_margin_error[0] + 1e-6 * F0
    below = a.jump_margin_speeds < a.jump_speed
    assert np.all(a.jump_margin[below] > 0.0)
    assert a.jump_speed_kinetostatic > a.jump_speed


def test_a_rocker_is_sized_at_its_roller_and_its_spring_given_at_the_pivot():
    """An oscillating roller (arm 80 mm, swing 18 deg, J = 0.0039 kg m^2, k_t = 6.4 N m/rad):
    its spring is sized at the roller's arc as a translating follower with h = l Phi, m =
    J/l^2, k = k_t/l^2 (sec. 2.4, (2.55)-(2.57)), by hand; the preload used is its torque at
    the pivot divided by l, the torque F0 l."""
    l, swing, J, kt = 0.08, 18.0, 0.0039, 6.4
    m = spec.from_dict({
        "follower": {"type": "oscillating-roller", "roller_radius": RR, "roller_width": WIDTH,
                     "pivot_distance": 0.1, "arm_length": l},
        "motion": {"swing": swing, "angles": list(ANGLES)}, "speed": {"band": [LO, HI]},
        "train": {"inertia": J, "torsional_stiffness": 2e6 * l**2},
        "spring": {"rate": kt, "margin": MU},
        "cam": {"base_radius": RB}}, "rocker")
    a = spring.spring(m, "cycloidal", residual.ladder(m), dynamic_jump=False)
    need, _ = largest_by_hand(need_by_hand(HI, k=kt / l**2, mass=J / l**2,
                                           h=l * math.radians(swing)))
    assert a.preload_min_kinetostatic == pytest.approx(need, rel=1e-9)
    assert a.torque_at_pivot == pytest.approx(a.preload_used * l, rel=1e-15)
    assert a.rate_at_pivot == pytest.approx(kt, rel=1e-12)


# -- the cam's contact ---------------------------------------------------------------------------

def test_hertz_line_contact_in_the_outer_dwell_and_the_peak_by_hand():
    """A constant force of 300 N along the slide: in the outer dwell the cam is a circle of
    radius r_b + h and the force is normal (alpha = 0), so Hertz's line contact gives p0 =
    (P' E*/(pi R))^(1/2), 1/R = 1/(r_b + h) + 1/r_r, P' = F/L, 1/E* = 2 (1 - nu^2)/E (steel,
    207 GPa, 0.292; Johnson (4.45)), to 1e-12; the peak over the cam, with the normal force
    F/cos alpha and the profile's radius rho_p - r_r (the pitch curve's in polar form, rho_p =
    (r^2 + r'^2)^(3/2)/(r^2 + 2 r'^2 - r r''), r = r_b + r_r + s), by hand within the stated
    error."""
    m = machine()
    theta = np.linspace(0.0, 360.0, 2881)
    F = 300.0
    c = contact.contact(m, "cycloidal", theta, np.full(theta.shape, F))
    E, nu = 207e9, 0.292
    e_star = E / (2 * (1 - nu * nu))
    i = int(np.argmin(np.abs(c.theta_deg - 130.0)))          # in the outer dwell, 100-160 deg
    p_dwell = math.sqrt(F / WIDTH * e_star * (1 / (RB + H) + 1 / RR) / math.pi)
    assert c.stress[i] == pytest.approx(p_dwell, rel=1e-12)
    beta = math.radians(ANGLES[0])

    def p0(T):
        Hs = cycloid_turn(T)
        r, r1, r2 = RB + RR + H * Hs[0], H * Hs[1] / beta, H * Hs[2] / beta**2
        rho_p = (r * r + r1 * r1) ** 1.5 / (r * r + 2 * r1 * r1 - r * r2)
        normal = F * np.sqrt(r * r + r1 * r1) / r          # F / cos alpha
        return np.sqrt(normal / WIDTH * e_star * (1 / (rho_p - RR) + 1 / RR) / math.pi)
    peak, _ = largest_by_hand(p0)
    assert c.hertz_stress_max == pytest.approx(peak, rel=1e-6)
    assert abs(c.hertz_stress_max - peak) <= c.hertz_stress_max_error + 1e-9 * peak
    assert c.hertz_ok and c.contact_kept and not c.undercut


def test_pressure_angle_of_the_cycloid_on_a_translating_roller():
    """tan alpha = s'/(r_b + r_r + s), s' = h H'/beta (offset 0): its largest |alpha| over the
    rise and the return by hand, to 1e-8 deg and within the stated error; the least radius of
    curvature is the convex pitch curve's less the roller's."""
    m = machine()
    theta = np.linspace(0.0, 360.0, 721)
    c = contact.contact(m, "cycloidal", theta, np.full(theta.shape, 100.0))

    def alpha(T):
        Hs = cycloid_turn(T)
        return np.degrees(np.abs(np.arctan(H * Hs[1] / math.radians(ANGLES[0])
                                           / (RB + RR + H * Hs[0]))))
    top, _ = largest_by_hand(alpha)
    assert c.pressure_angle_max_deg == pytest.approx(top, abs=1e-8)
    assert abs(c.pressure_angle_max_deg - top) <= c.pressure_angle_max_deg_error + 1e-9
    assert c.rho_min == pytest.approx(c.rho_min_pitch - RR, rel=1e-15)


# -- the drive -----------------------------------------------------------------------------------

def test_drive_torque_and_flywheel_by_hand():
    """M = (F0 + k h H + m h H'' w^2/beta^2) h H'/beta at the top speed, its largest |M| over the
    turn by hand, to 1e-9 and within the error; the kinetostatic flywheel for C_s = 0.05: the
    swing of m (h H' w/beta)^2/2 + F0 h H + k (h H)^2/2 over C_s w^2, the larger of the band's
    two ends (the lowest, where the spring's energy weighs most), to 1e-9."""
    F0 = 150.0
    m = machine(spring__preload=F0, drive__speed_fluctuation=0.05)
    d = drive.drive(m, "cycloidal", residual.ladder(m), F0)
    beta = math.radians(ANGLES[0])

    def torque(T):
        Hs = cycloid_turn(T)
        F = F0 + RATE * H * Hs[0] + MASS * H * Hs[2] * HI**2 / beta**2
        return np.abs(F * H * Hs[1] / beta)
    top, _ = largest_by_hand(torque)
    assert d.torque_max_kinetostatic == pytest.approx(top, rel=1e-9)
    assert abs(d.torque_max_kinetostatic - top) <= d.torque_max_kinetostatic_error + 1e-9 * top
    assert d.torque_max >= d.torque_max_kinetostatic

    def J(w):
        T = np.concatenate([np.linspace(a, b, 200001) for a, b in pieces()] + [np.array([1.2])])
        Hs = cycloid_turn(T)
        x = H * Hs[0]
        E = 0.5 * MASS * (H * Hs[1] * w / beta) ** 2 + F0 * x + 0.5 * RATE * x**2
        return np.ptp(E) / (0.05 * w**2)
    assert J(LO) > J(HI)
    assert d.flywheel_inertia_kinetostatic == pytest.approx(J(LO), rel=1e-9)
    assert d.flywheel_speed == LO
    assert d.flywheel_inertia >= d.flywheel_inertia_kinetostatic * (1 - 1e-6)
