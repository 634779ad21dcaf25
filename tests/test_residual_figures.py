"""The residual-vibration figures' building blocks (runtime/measure/residual.py) against closed forms:
``crossing_time`` (the first time a state or output reaches a level), ``extreme`` (a refined
extreme on a window, including one that lies inside the first or last interval of the scan
grid) and ``residual``'s window checks (runs starting before T = 0, after it, ending one step
after the rise; CAMSHAFT-2, whose rise ends when the cam angle B reaches 1).

The reference is the closed-form u = X - H of the damped one-DOF model (3.1) with the damper
(6.47) under the cycloidal rise H = T - sin(2 pi T)/(2 pi) (A.2.11), ``DampedOneDof`` of
test_damped.py: X = H + u during the rise, X = 1 + u in the dwell, where u is the damped free
vibration e^(-q w s) (c cos w_d s + d sin w_d s), s = T - 1, whose extrema and zeros are in
closed form; for CAMSHAFT-2 (5.15)-(5.18) it is SciPy's DOP853 at rtol 1e-12.
"""
import dataclasses
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.measure.residual import residual
from camdyn.runtime.measure.extremes import crossing_time, extreme
from camdyn.runtime.core.simulator import simulate

from .test_damped import DampedOneDof, damped_sinusoid_max, derivative

TAU, Q = 0.2, 0.05     # away from the zero points 1/n of (3.5): a residual vibration to measure
RTOL = 1e-12


@pytest.fixture(scope="module")
def ref():
    return DampedOneDof(TAU, Q)


@pytest.fixture(scope="module")
def run():
    return simulate("one_dof", {"tau": TAU, "q": Q}, 2.0, "dp54", rtol=RTOL)


def u_dwell(ref, T):
    c, d = ref.dwell()
    s = np.asarray(T) - 1.0
    return np.exp(-ref.alpha * s) * (c * np.cos(ref.beta * s) + d * np.sin(ref.beta * s))


def x_closed(ref, T):
    """X = H + u during the rise (cycloid H = T - sin(2 pi T)/(2 pi)), 1 + u in the dwell."""
    T = np.asarray(T, dtype=float)
    rise = T - np.sin(2 * np.pi * T) / (2 * np.pi) + ref.u(T)
    return np.where(T <= 1.0, rise, 1.0 + u_dwell(ref, T))


def dwell_times(ref, psi, t_end):
    """Times 1 + s in (1, t_end) where cos(w_d s - psi) = 0: the extrema of u for
    psi = atan2(d', c') of its derivative, the zeros of u for psi = atan2(d, c)."""
    k = np.arange(-2, math.ceil(ref.beta * (t_end - 1) / math.pi) + 3)
    s = (psi + math.pi / 2 + k * math.pi) / ref.beta
    return 1.0 + s[(s > 0) & (s < t_end - 1)]


# -- crossing_time ---------------------------------------------------------------------------
@pytest.mark.parametrize("level", [0.05, 0.3, 0.5, 0.8, 0.97, 1.0004])
def test_crossing_time_is_the_closed_form_root(run, ref, level):
    """First T with X(T) = level, against the first root of the closed-form X = H + u (rise)
    or 1 + u (dwell), bracketed on a 1e-4 grid and found by brentq to 1e-15; level 1.0004 is
    first reached in the overshoot at the end of the rise (X up to 1.0011 at T = 0.955, where
    X' is small).  Measured: within 8e-13 (dense output of DP54 at rtol 1e-12); asserted
    1e-9.  Either end of the bracketing step is 4.5e-6 to 1.2e-3 from the root."""
    grid = np.linspace(0.0, 2.0, 20001)
    first = int(np.flatnonzero(x_closed(ref, grid) >= level)[0])
    t_ref = brentq(lambda T: float(x_closed(ref, T)) - level, grid[first - 1], grid[first],
                   xtol=1e-15)
    assert crossing_time(run, "X", level) == pytest.approx(t_ref, abs=1e-9)


@pytest.mark.parametrize("level", [0.0, -0.1])
def test_crossing_time_at_or_below_the_start_is_the_start(level):
    """A level X already reaches at the start of the run (X = 0 at rest before the rise,
    level 0 reached with equality) is reached at the run's first time, T = -0.5 exactly,
    not at the start of the rise or at any later recorded point."""
    res = simulate("one_dof", {"tau": TAU, "q": Q}, 1.5, "dp54", rtol=1e-10, t0=-0.5)
    assert crossing_time(res, "X", level) == -0.5


def test_crossing_time_of_a_plateau_reached_with_equality(run):
    """The cycloid H = T - sin(2 pi T)/(2 pi) (A.2.11) is below 1 during the rise and exactly
    1 in the dwell: it reaches the level 1 at T = 1.  The level is met with equality only,
    never exceeded.  Asserted 1e-5: in floating point H rounds to 1 already where its
    deficit (2 pi)^2 (1 - T)^3/6 is below half an ulp, 2e-6 before the end (measured: exactly
    1)."""
    assert crossing_time(run, "H", 1.0) == pytest.approx(1.0, abs=1e-5)


def test_crossing_time_at_a_jump_between_the_limits_of_a_breakpoint():
    """The simple-harmonic law's H'' = (pi^2/2) cos(pi T) jumps at T = 0 from 0 (dwell) to
    pi^2/2 = 4.93: the recorded left and right limits share T = 0, and the level 2 is first
    reached there, at T = 0 exactly (not found by a root search, which needs a sign change
    on an interval)."""
    res = simulate("one_dof", {"tau": TAU, "q": Q}, 1.5, "dp54", rtol=1e-10,
                   law="simple-harmonic", t0=-0.5)
    assert crossing_time(res, "Hdd", 2.0) == 0.0


def test_crossing_time_refuses_a_level_never_reached(run):
    """X stays below 1.0011 (largest overshoot, near the end of the rise, in closed form):
    the level 1.01 is refused with a named error."""
    with pytest.raises(CamdynInputError, match="X never reaches 1.01 in this run"):
        crossing_time(run, "X", 1.01)


# -- extreme ---------------------------------------------------------------------------------
def _window_at_an_end(run, T, end, period):
    """A window [a, b] with the extremum at T inside its first (end "a") or last (end "b")
    scan interval, a twelfth of a recorded step: the end is placed 1/30 of the distance from T
    to the far end of T's step away from T, so the end itself is the best sample of the scan
    and only refining in the neighbouring interval finds T.  None if T is too close to a
    recorded point for that."""
    i = int(np.searchsorted(run.t, T, side="right"))
    lo, hi = run.t[i - 1], run.t[i]
    frac = (T - lo) / (hi - lo)
    if end == "a" and 0.1 < frac < 0.6:
        return T - (hi - T) / 30, T + 0.3 * period
    if end == "b" and 0.4 < frac < 0.9:
        return T - 0.3 * period, T + (T - lo) / 30
    return None


CASES = [  # name, absolute, minimum, what is sought
    ("crest", False, False, "extremum", 1),
    ("trough", False, True, "extremum", -1),
    ("|trough|", True, False, "extremum", -1),
    ("|crest|", True, False, "extremum", 1),
    ("zero of u", True, True, "zero", 0),
]


@pytest.mark.parametrize("end", ["a", "b"])
@pytest.mark.parametrize("name,absolute,minimum,kind,sign", CASES)
def test_extreme_inside_the_first_or_last_scan_interval(run, ref, name, absolute, minimum,
                                                        kind, sign, end):
    """Signed and absolute maxima and minima of u in the dwell on windows whose extremum lies
    just inside one end (5e-6 to 1.6e-5 from it, a fraction of a scan interval), against the
    closed form: crests and troughs of e^(-q w s)(c cos w_d s + d sin w_d s) where its
    derivative vanishes, zeros of u for the smallest |u|.  The first such extremum whose
    position in its recorded step allows the window is taken.

    Measured: values within 5e-11 of |u| (the dense output's own error), |u| at the zero below
    1e-10 (Brent's location of the kink, 4e-9); times within 2e-8.  Asserted: value 2e-9 of
    |u| (the value at the window's end is 1.2e-8 to 2.8e-8 of it worse), 1e-9 at the zero
    (2.5e-7 to 5.3e-7 at the end), times 5e-7 (the end is 5e-6 to 1.6e-5 away)."""
    c, d = ref.dwell()
    cd, dd = derivative(c, d, ref.alpha, ref.beta)
    psi = math.atan2(dd, cd) if kind == "extremum" else math.atan2(d, c)
    period = 2 * math.pi / ref.beta
    for T in dwell_times(ref, psi, run.t[-1] - period):
        if kind == "extremum" and np.sign(u_dwell(ref, T)) != sign:
            continue
        window = _window_at_an_end(run, T, end, period)
        if window is not None:
            break
    else:
        pytest.fail("no extremum with a suitable position in its step")
    value, t = extreme(run, "U", *window, absolute=absolute, minimum=minimum)
    u_T = float(u_dwell(ref, T))
    assert t == pytest.approx(T, abs=5e-7)
    if kind == "zero":
        assert abs(value) < 1e-9
    else:
        assert value == pytest.approx(abs(u_T) if absolute else u_T, rel=2e-9)
        # the window's end is measurably worse, or the test could not see the refinement
        u_end = abs(float(u_dwell(ref, window[0] if end == "a" else window[1])))
        assert abs(u_T) - u_end > 5e-9 * abs(u_T)


def test_extreme_at_the_window_end_of_a_monotone_output(run):
    """H increases through the rise (A.2.11): its maximum on [0.2, 0.6] is at T = 0.6, its
    minimum at T = 0.2, the closed form there to 1e-14 (measured 0)."""
    h = lambda T: T - math.sin(2 * math.pi * T) / (2 * math.pi)  # noqa: E731
    assert tuple(extreme(run, "H", 0.2, 0.6, absolute=False, minimum=False)) == \
        pytest.approx((h(0.6), 0.6), abs=1e-14)
    assert tuple(extreme(run, "H", 0.2, 0.6, absolute=False, minimum=True)) == \
        pytest.approx((h(0.2), 0.2), abs=1e-14)


def test_extreme_flags_are_keyword_only(run):
    """``absolute`` and ``minimum`` are two booleans side by side: given by position they
    could be swapped unnoticed, so they are keyword-only."""
    with pytest.raises(TypeError):
        extreme(run, "U", 1.0, 1.5, True, False)


# -- residual: which runs it accepts ----------------------------------------------------------
def test_residual_of_a_run_starting_before_the_rise(ref):
    """A run from T = -0.5 (at rest in the dwell before the rise) covers the rise: accepted,
    and its figures are those of the closed form on [1, 2] (U0, U0'' the largest |u|, |X''|;
    Xdd_min_rise the most negative X'' on [0, 1] and its T, a root of the analytic X''').
    Measured: 1e-10 relative, T within 1.2e-8; asserted 1e-7, T 1e-7 (as test_damped)."""
    fig = residual(simulate("one_dof", {"tau": TAU, "q": Q}, 2.0, "dp54", rtol=RTOL, t0=-0.5))
    U0, U0dd, xmin, tmin = ref.figures(2.0)
    assert fig.U0 == pytest.approx(U0, rel=1e-7)
    assert fig.U0dd == pytest.approx(U0dd, rel=1e-7)
    assert fig.Xdd_min_rise == pytest.approx(xmin, rel=1e-7)
    assert fig.T_at_Xdd_min == pytest.approx(tmin, abs=1e-7)


def test_residual_refuses_a_run_starting_after_the_rise_start():
    """A run from T = 0.5 misses the first half of the rise: refused, naming the windows."""
    res = simulate("one_dof", {"tau": TAU, "q": Q}, 2.0, "dp54", rtol=1e-8, t0=0.5)
    with pytest.raises(CamdynInputError,
                       match=r"must cover the rise \[0, 1\] .*it covers \[0.5, 2\]"):
        residual(res)


def test_residual_of_a_run_ending_one_step_after_the_rise(ref):
    """RK4 with step h = tau/1000, ending one step after the rise (T = 1 is a stop, recorded
    twice, then one step to 1 + h): accepted, U0 and U0'' are the largest |u|, |X''| over that
    one step, against the closed-form damped sinusoid on [0, h]; Xdd_min_rise against the
    closed form.  Measured: U0 1.2e-9, U0'' 8.8e-9, Xdd_min_rise 4e-11 relative (RK4's
    fourth-order error), T 1.0e-8; asserted 1e-7 relative and 1e-7 in T."""
    h = TAU / 1000
    res = simulate("one_dof", {"tau": TAU, "q": Q}, 1.0 + h, "rk4", step=h)
    fig = residual(res)
    c, d = ref.dwell()
    cd, dd = derivative(c, d, ref.alpha, ref.beta)
    w2, qw2 = ref.w**2, 2 * Q * ref.w
    U0 = damped_sinusoid_max(c, d, ref.alpha, ref.beta, h)
    U0dd = damped_sinusoid_max(-w2 * c - qw2 * cd, -w2 * d - qw2 * dd, ref.alpha, ref.beta, h)
    _, _, xmin, tmin = ref.figures(1.0 + h)
    assert fig.U0 == pytest.approx(U0, rel=1e-7)
    assert fig.U0dd == pytest.approx(U0dd, rel=1e-7)
    assert fig.Xdd_min_rise == pytest.approx(xmin, rel=1e-7)
    assert fig.T_at_Xdd_min == pytest.approx(tmin, abs=1e-7)


def test_residual_figures_are_immutable(run):
    """residual_of (checks/spine_checks.py) caches the figures and hands the same object to every
    caller: it must be frozen (and so hashable), or one caller could change another's."""
    fig = residual(run)
    with pytest.raises(dataclasses.FrozenInstanceError):
        fig.U0 = 0.0
    assert hash(fig) == hash(dataclasses.replace(fig))


# -- CAMSHAFT-2: the rise ends when the cam has turned through it ------------------------------
FA, FV = 3.0, 0.5      # a soft shaft and a heavy cam: the cam lags 0.037 t_m behind the input


def _camshaft2_scipy(t_end):
    """(5.15)-(5.18) with the cycloid typed in, tau_b^2 = tau^2 Fa/Fv, DOP853 at rtol 1e-12:
    up to the event B = 1 (the end of the cam's rise), then on in the dwell (H = 1)."""
    tau = 0.16
    w2 = (2 * math.pi / tau) ** 2
    wb2 = w2 * FV / FA

    def f(t, y):
        X, B, Xd, Bd = y
        b = min(max(B, 0.0), 1.0)
        H, Hd = b - math.sin(2 * math.pi * b) / (2 * math.pi), 1 - math.cos(2 * math.pi * b)
        Xdd = w2 * (H - X)
        return [Xd, Bd, Xdd, wb2 * (t - B) - FV * Xdd * Hd]

    event = lambda t, y: y[1] - 1.0  # noqa: E731
    event.terminal, event.direction = True, 1
    opts = dict(method="DOP853", rtol=1e-12, atol=1e-14)
    rise = solve_ivp(f, (0.0, 2.0), [0.0, 0.0, 0.0, 1.0], events=event, **opts)
    t1 = float(rise.t_events[0][0])
    dwell = solve_ivp(f, (t1, t_end), rise.y_events[0][0], dense_output=True, **opts)
    return t1, dwell.sol


def test_camshaft2_rise_ends_when_the_cam_angle_reaches_1():
    """CAMSHAFT-2 (Fa = 3, Fv = 0.5, tau = 0.16): the rise ends where B = 1, T1 = 1.0368 in
    SciPy's DOP853 event location, not at T = 1.  A run to 1.02 ends after T = 1 but inside
    the cam's rise: refused (B never reaches 1).  A run to 1.1: U0 = max |X - 1| on [T1, 1.1]
    (its first extreme, T = 1.063) against the SciPy solution's dense output, scanned on 2000
    points and refined by bounded Brent to 1e-14.  Measured: T1 within 7e-15, U0 within
    1.4e-10 relative; asserted 1e-10 and 1e-8."""
    params = {"tau": 0.16, "Fa": FA, "Fv": FV}
    t_end = 1.1
    t1_ref, sol = _camshaft2_scipy(t_end)
    assert 1.02 < t1_ref < t_end
    res = simulate("camshaft2", params, t_end, "dp54", rtol=RTOL)
    assert crossing_time(res, "B", 1.0) == pytest.approx(t1_ref, abs=1e-10)

    grid = np.linspace(t1_ref, t_end, 2001)
    err = np.abs(sol(grid)[0] - 1.0)
    k = int(np.argmax(err))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    opt = minimize_scalar(lambda t: -abs(sol(t)[0] - 1.0), bounds=(lo, hi), method="bounded",
                          options={"xatol": 1e-14})
    U0_ref = max(err[k], -opt.fun)
    assert residual(res).U0 == pytest.approx(U0_ref, rel=1e-8)

    short = simulate("camshaft2", params, 1.02, "dp54", rtol=1e-8)
    with pytest.raises(CamdynInputError, match="B never reaches 1 in this run"):
        residual(short)
