"""Impact after backlash (thesis sec. 3.6, (3.8)-(3.16)) and damping over a dwell ((3.7), (7.10)),
beyond the registry checks of camdyn/thesis/checks/impact_checks.py."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from camdyn.thesis.theory import impact as im
from camdyn.thesis.checks.check import matches_printed
from camdyn.runtime.measure.extremes import extreme
from camdyn.runtime.core.simulator import simulate


def _ramp_run(tau, y0=None):
    return simulate("one_dof", {"tau": tau}, 1.0, "dp54", rtol=1e-11, law="uniform", y0=y0)


@pytest.mark.parametrize("tau", [0.06, 0.1, 0.2, 0.37])
def test_ramp_response_pointwise(tau):
    """The compiled one-DOF model under the ramp (3.8) (law 'uniform', r_e = 1 on 0 <= T < 1)
    follows u = -(tau/(2 pi)) sin(2 pi T/tau), the solution of (3.1) from rest, everywhere."""
    res = _ramp_run(tau)
    T = np.linspace(0.0, 1.0, 2001)
    st = res.sample(T)
    w = 2 * math.pi / tau
    amp = tau / (2 * math.pi)
    np.testing.assert_allclose(st["U"], -amp * np.sin(w * T), rtol=0, atol=1e-8 * amp)
    np.testing.assert_allclose(st["Xdd"], w * np.sin(w * T), rtol=0, atol=1e-8 * w)


@pytest.mark.parametrize("tau", [0.06, 0.1, 0.2, 0.37])
def test_ramp_amplitudes_3_11_3_12(tau):
    """Refined extremes of U and X'' on the dense output equal (3.11) and (3.12) with r_e = 1:
    U_sn proportional, U_sn'' inversely proportional to tau (sec. 3.6)."""
    res = _ramp_run(tau)
    u, _ = extreme(res, "U", 0.0, 1.0, absolute=True, minimum=False)
    a, _ = extreme(res, "Xdd", 0.0, 1.0, absolute=True, minimum=False)
    assert u == pytest.approx(im.U_sn(1.0, tau), rel=1e-8)
    assert a == pytest.approx(im.Udd_sn(1.0, tau), rel=1e-8)


@pytest.mark.parametrize("r_e", [0.31, 0.75])
def test_impact_amplitude_depends_on_velocity_difference(r_e):
    """The amplitudes depend on the velocity difference at impact, not on the speed itself
    (the argument of sec. 3.6 and of the first 'stelling' against Rothbart): a follower already
    moving at 1 - r_e when the input jumps to speed 1 vibrates with (3.11), (3.12) for r_e."""
    tau = 0.13
    res = _ramp_run(tau, y0=[0.0, 1.0 - r_e])
    u, _ = extreme(res, "U", 0.0, 1.0, absolute=True, minimum=False)
    a, _ = extreme(res, "Xdd", 0.0, 1.0, absolute=True, minimum=False)
    assert u == pytest.approx(im.U_sn(r_e, tau), rel=1e-8)
    assert a == pytest.approx(im.Udd_sn(r_e, tau), rel=1e-8)


@pytest.mark.parametrize("k,s", [(1.0, 1e-3), (39.48, 1.27e-2), (850.0, 2e-5)])
def test_impact_speed_3_15_by_numerical_integration(k, s):
    """Integrating delta h''' = k numerically from the force reversal, with an event at
    delta h = s', gives the impact speed (3.15) (independent of the SymPy derivation)."""
    def rhs(t, y):
        return [y[1], y[2], k]

    def used_up(t, y):
        return y[0] - s

    used_up.terminal = True
    sol = solve_ivp(rhs, (0.0, 10.0), [0.0, 0.0, 0.0], events=used_up, rtol=1e-12, atol=1e-16)
    v = sol.y_events[0][0][1]
    assert v == pytest.approx(im.impact_speed(k, s), rel=1e-8)


@pytest.mark.parametrize("S", [1e-5, 1e-4, 1e-3, 1.27e-2, 3e-2])
def test_3_16_linear_jerk_against_the_exact_cycloid(S):
    """(3.13)-(3.16) take the acceleration difference as growing linearly, k = H'''.  At the
    reversal T = 1/2 of the cycloid the free member keeps the speed it had and the cam
    decelerates with -2 pi sin 2 pi u (u = T - 1/2), so the exact relative position is
    u - sin(2 pi u)/(2 pi) = S at impact and r_e = 1 - cos 2 pi u_b.  Expanding both to the
    next order gives r_e(3.16)/r_e(exact) - 1 = r_e/10 + O(r_e^2): the linear estimate is a
    little high (safe), 3 % at the backlash of the indexing mechanism, S = 1.27e-2."""
    u_b = brentq(lambda u: u - math.sin(2 * math.pi * u) / (2 * math.pi) - S, 1e-9, 0.5, xtol=1e-15)
    exact = 1 - math.cos(2 * math.pi * u_b)
    linear = im.r_e_from_backlash(S)
    excess = linear / exact - 1
    assert excess > 0
    assert abs(excess / (linear / 10) - 1) < linear
    if S == 1.27e-2:
        assert 0.03 < excess < 0.035


def test_dimensionless_3_16_coefficient():
    """r_e = (18 pi^2)^(1/3) S^(2/3) = 5.62 S^(2/3): the numeric (3.16) and the reading agree."""
    for S in (1e-4, 1.27e-2, 0.1):
        assert im.r_e_from_backlash(S) == pytest.approx((18 * math.pi**2 * S**2) ** (1 / 3), rel=1e-14)
    assert im.r_e_from_backlash(1.0) == pytest.approx(5.6216, abs=1e-4)


def _dwell_envelope(tau, q, td):
    res = simulate("one_dof", {"tau": tau, "q": q}, 1.0 + td, "dp54", rtol=1e-11)
    w = 2 * math.pi / tau
    s, wd = q * w, w * math.sqrt(1 - q * q)
    st = res.sample([1.0, 1.0 + td])
    amp = np.sqrt(st["U"] ** 2 + ((st["Xd"] + s * st["U"]) / wd) ** 2)
    return amp[1] / amp[0]


@pytest.mark.parametrize("tau,q,td", [(0.15, 0.06, 1.5), (0.1, 0.02, 1.0), (0.25, 0.2, 0.8)])
def test_dwell_decay_3_7_damped_periods(tau, q, td):
    """Over a dwell t_d the damped model's envelope falls by exp(-q w_e t_d); that is (3.7)
    exactly when n counts damped periods, n = t_d (1 - q^2)^(1/2)/(tau t_m)."""
    ratio = _dwell_envelope(tau, q, td)
    assert ratio == pytest.approx(im.envelope_decay(td, tau, q), rel=1e-7)
    n_damped = td * math.sqrt(1 - q * q) / tau
    assert ratio == pytest.approx(im.decay_ratio(n_damped, q), rel=1e-7)


def test_dwell_decay_thesis_n_convention():
    """Sec. 3.4 counts n = t_d/(tau t_m) = 10 undamped periods; (3.7) with it is lower than the
    simulated decay by exp(-2 pi q n ((1 - q^2)^(-1/2) - 1)) = 0.9932 at q = 0.06.  Both are the
    printed 2 %."""
    tau, q, td = 0.15, 0.06, 1.5
    sim = _dwell_envelope(tau, q, td)
    formula = im.decay_ratio(im.dwell_vibrations(td, tau), q)
    factor = math.exp(-2 * math.pi * q * 10 * (1 / math.sqrt(1 - q * q) - 1))
    assert formula / sim == pytest.approx(factor, rel=1e-7)
    assert 0.993 < factor < 0.994
    assert matches_printed(sim, "0.02") and matches_printed(formula, "0.02")


@pytest.mark.parametrize("q", [0.01, 0.023, 0.06, 0.11, 0.4])
def test_q_from_decrement_inverts_3_7(q):
    """The exact inverse of (3.7) recovers q; (7.10) returns q/(1 - q^2)^(1/2), i.e. it is high by
    about q^2/2 (0.6 % at the 11 % of the camshaft, sec. 7.4.5)."""
    for n in (2, 9):
        ratio = 1 / im.decay_ratio(n, q)
        assert im.q_from_decrement(ratio, n, exact=True) == pytest.approx(q, rel=1e-12)
        assert im.q_from_decrement(ratio, n) == pytest.approx(q / math.sqrt(1 - q * q), rel=1e-12)


def test_impact_amplitudes_of_the_indexing_example():
    """(3.11), (3.12) at the printed r_e = 0.31, tau_0.68 = 0.222 (sec. 7.4.4): the impact
    acceleration 8.77 is larger than the nominal maximum 2 pi of the cycloid, the positional
    error 1.1 % of the stroke."""
    assert im.Udd_sn(0.31, 0.222) == pytest.approx(8.774, abs=1e-3)
    assert im.Udd_sn(0.31, 0.222) > 2 * math.pi
    assert im.U_sn(0.31, 0.222) == pytest.approx(0.01095, abs=1e-5)
