"""CAMSHAFT-2 (thesis ch. 5): the generated model against (5.43), (5.46), sec. 5.5.5, sec. 5.4,
its limits Fv -> 0 (ch. 3) and Fv -> oo (CAMSHAFT-1, ch. 4), and conclusion (2) of sec. 5.7."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from camdyn.thesis.theory import equivalent as eq
from camdyn.thesis.theory import numeric as cf
from camdyn.thesis.checks import camshaft2_checks as c2
from camdyn.thesis.checks.check import matches_printed
from camdyn.runtime.measure.residual import residual
from camdyn.runtime.core.simulator import simulate


# -- the frozen system (sec. 5.5.7) ----------------------------------------------------------------
@pytest.mark.parametrize("Fa,Fv", [(0.3, 0.64), (1.5, 10.0), (2.0, 2.0), (3.35, 7.5), (1.5, 0.1)])
@pytest.mark.parametrize("B0", [0.0, 0.1, 0.25, 0.4, 0.5, 0.7])
def test_generated_eigenvalues_are_5_43(B0, Fa, Fv):
    """scipy.linalg.eigh of the generated M and K at X = H(B0), B = T = B0 equals (5.43) with
    dH/dB = 1 - cos 2 pi B0 (slopes 0 .. 2); Fa, Fv from fig. 5.6, sec. 5.6 and table 5-I."""
    lam = c2.frozen_eigenvalues(B0, Fa, Fv, tau=0.16)
    ref = eq.eigenvalues(c2.cycloid(B0)[1], Fa, Fv)
    np.testing.assert_allclose(lam, ref, rtol=1e-12, atol=0)


def test_generated_frozen_matrices_are_those_of_5_36():
    """M = diag(1, 1/Fv) and K = w_ex^2 [[1, -s], [-s, s^2 + 1/Fa]] at the equilibrium: the
    dimensionless (5.36) with c_beta'' = c_beta'/tan^2 a, m_beta'' = m_beta'/tan^2 a (fig. 5.3)."""
    tau, Fa, Fv, B0 = 0.16, 1.5, 10.0, 0.3
    M, K = c2.frozen_matrices(B0, Fa, Fv, tau)
    s, w2 = c2.cycloid(B0)[1], (2 * math.pi / tau) ** 2
    np.testing.assert_allclose(M, np.diag([1.0, 1.0 / Fv]), rtol=1e-14, atol=0)
    np.testing.assert_allclose(K, w2 * np.array([[1.0, -s], [-s, s * s + 1 / Fa]]), rtol=1e-12, atol=0)


@pytest.mark.parametrize("Fa,Fv", [(1.5, 10.0), (2.0, 2.0), (0.4, 1.14)])
def test_generated_eigenvalue_product_is_independent_of_the_slope_5_46(Fa, Fv):
    """w_el^2 w_eh^2 = w_ex^2 w_eb^2 = w_ex^4 Fv/Fa (5.46) at every cam position, while each
    eigenvalue moves (the lowest one down to its minimum at B = 1/2, sec. 5.5.7.2)."""
    B = np.linspace(0.0, 1.0, 11)
    lam = np.array([c2.frozen_eigenvalues(b, Fa, Fv) for b in B])
    np.testing.assert_allclose(lam[:, 0] * lam[:, 1], Fv / Fa, rtol=1e-12)
    assert np.argmin(lam[:, 0]) == 5 and np.argmax(lam[:, 1]) == 5
    assert lam[5, 0] < 0.5 * lam[0, 0]


def test_sec_5_6_lowest_eigenvalue_at_maximum_slope():
    """Fa = Fv = 2, dH/dB = 2 (B0 = 1/2): 0.1 w_ex^2 exact (5.43), 0.101 by (5.53), 0.111 by (4.32)
    (sec. 5.6).  The first from the generated CAMSHAFT-2, the last from the generated CAMSHAFT-1
    at T = 1/2, the middle from the closed form (5.53)."""
    exact = c2.frozen_eigenvalues(0.5, 2.0, 2.0)[0]
    rayleigh = eq.lowest_eigenvalue_rayleigh(2.0, 2.0, 2.0)
    one_dof = c2.frozen_eigenvalues(0.5, 2.0, 0.0, model="camshaft1")[0]
    assert matches_printed(exact, "0.1") and exact == pytest.approx(5 - 24**0.5, rel=1e-12)
    assert matches_printed(rayleigh, "0.101")
    assert matches_printed(one_dof, "0.111")
    assert exact < rayleigh < one_dof
    # "w_el^2 = w_ex^2 at zero slope", both methods
    assert c2.frozen_eigenvalues(0.0, 2.0, 2.0)[0] == pytest.approx(1.0, rel=1e-12)


# -- an independent integration of (5.15), (5.16) ---------------------------------------------
def _scipy_run(tau, Fa, Fv, T):
    """(5.15)-(5.18) with the cycloid (A.2.10), (A.2.11) typed in, tau_b^2 = tau^2 Fa/Fv, DOP853."""
    w2, wb2 = (2 * math.pi / tau) ** 2, (2 * math.pi / tau) ** 2 * Fv / Fa

    def f(t, y):
        X, B, Xd, Bd = y
        b = min(max(B, 0.0), 1.0)
        H, Hd = c2.cycloid(b)
        Xdd = w2 * (H - X)
        return [Xd, Bd, Xdd, wb2 * (t - B) - Fv * Xdd * Hd]

    return solve_ivp(f, (0.0, T[-1]), [0.0, 0.0, 0.0, 1.0], t_eval=T, method="DOP853",
                     rtol=1e-11, atol=1e-13, max_step=1e-3).y


@pytest.mark.parametrize("params", [c2.FIG_5_6, c2.FIG_5_6_HEAVY, {"tau": 0.16, "Fa": 0.15, "Fv": 10.0}])
def test_agrees_with_an_independent_integration(params):
    """The three cases of fig. 5.6: X, B, B' of camdyn (DP54, rtol 1e-10) against scipy's DOP853 on
    the equations typed in from (5.15), (5.16), to 1e-6 over the rise and a dwell."""
    T = np.linspace(0.0, 1.5, 301)
    ref = _scipy_run(params["tau"], params["Fa"], params["Fv"], T)
    got = c2.run(params["tau"], params["Fa"], params["Fv"]).sample(T)
    for k, name in enumerate(("X", "B", "Xd", "Bd")):
        np.testing.assert_allclose(got[name], ref[k], rtol=0, atol=1e-6 * max(1.0, np.abs(ref[k]).max()))


# -- sec. 5.5.5, fig. 5.6 ---------------------------------------------------------------------
def test_sec_5_5_5_angular_velocity_error_30_percent():
    """"The error in the angular velocity reaches a maximum of 30 %" at tau = 0.16, Fa = 1.5, Fv = 10
    (curves (2)); camdyn: 28.9 % at T = 0.76, in the deceleration phase where the stored wind-up is
    released (sec. 5.5.3).  With the heavy cam (curves (3), Fv = 0.1) "Delta B' up to 30 %": 26.8 %."""
    light, t_light = c2.speed_deviation(**c2.FIG_5_6)
    assert light == pytest.approx(0.30, rel=0.10)
    assert 0.5 < t_light < 1.0
    heavy, _ = c2.speed_deviation(**c2.FIG_5_6_HEAVY)
    assert heavy == pytest.approx(0.30, rel=0.15)


def test_sec_5_5_5_wind_up_at_T_0_68():
    """"The amount of shaft wind-up ... appear[s] to be 17 % (at T = 0.68, Delta B-curve (2))".
    camdyn puts the largest |T - B| of the rise at T = 0.682, the instant printed, but its size is
    0.0174 beta_m (1.7 %), a tenth of the printed 17 %; the independent scipy integration gives the
    same 0.0174.  Perhaps the scan lost a decimal point ("1.7 %"); the size is not asserted against
    the thesis (see thesis/checks/camshaft2_checks.py, ch5.sec5_5_5.windup_time)."""
    size, instant = c2.windup_extreme(**c2.FIG_5_6)
    assert matches_printed(instant, "0.68")
    T = np.linspace(0.6, 0.76, 16001)
    ref = _scipy_run(c2.FIG_5_6["tau"], c2.FIG_5_6["Fa"], c2.FIG_5_6["Fv"], T)
    ref_windup = T - ref[1]
    k = int(np.argmax(np.abs(ref_windup)))
    assert size == pytest.approx(abs(ref_windup[k]), rel=1e-5)
    assert instant == pytest.approx(T[k], abs=2e-5)
    assert ref_windup[k] < 0  # the cam leads the input: the released wind-up (sec. 5.5.3)


# -- limits (sec. 5.7 (2)) ----------------------------------------------------------------------
@pytest.mark.parametrize("k", [9, 4, 3, 2, 1])
def test_fv_to_zero_is_the_one_dof_model(k):
    """Fv -> 0 is the cam of infinite inertia at constant speed, ch. 3: at Fv = 1e-6 U0 agrees with
    (3.5) within 1e-4 at the tau of Table 3-I (maxima 2/(2k + 1)); the difference shrinks with Fv."""
    tau = 2 / (2 * k + 1)
    u = c2.residual2(tau, 1.0, c2.FV_ZERO).U0
    assert u == pytest.approx(cf.U0(tau), rel=1e-4)
    coarse = c2.residual2(tau, 1.0, 1e-4).U0
    assert abs(u / cf.U0(tau) - 1) < 0.05 * abs(coarse / cf.U0(tau) - 1) + 1e-9


def test_fv_to_zero_table_3_I():
    """Sec. 5.7 (2): "the characteristic Fv = 0 agrees with table 3-I", to the printed digits, for
    the rows whose printed values are not misprints (thesis/checks/spine_checks.py)."""
    for k, name, printed in ((9, "U0", "3.75e-4"), (9, "U0dd", "1.34"), (3, "U0dd", "3.91"),
                             (2, "U0", "2.43e-2"), (2, "U0dd", "5.98")):
        value = getattr(c2.residual2(2 / (2 * k + 1), 1.0, c2.FV_ZERO), name)
        assert matches_printed(value, printed), (k, name, value)


def test_fv_to_zero_follows_the_one_dof_trajectory():
    """The whole follower motion, not only U0: X(T) at Fv = 1e-6 stays within 1e-5 of the one-DOF
    model (the gap is 1.1e-6) and the gap falls in proportion to Fv: by (5.16) with the shaft
    as soft as (2 pi/tau_b)^2 = (2 pi/tau)^2 Fv/Fa, the cam's angle error is about Fv times the
    double integral of X'' dH/dB."""
    T = np.linspace(0.0, 3.0, 601)
    b = simulate("one_dof", {"tau": 0.15}, 3.0, "dp54", rtol=1e-10).sample(T)["X"]
    gap = [np.max(np.abs(c2.run(0.15, 1.5, Fv).sample(T)["X"] - b)) for Fv in (1e-6, 1e-7)]
    assert gap[0] < 1e-5
    assert gap[1] < gap[0] / 5


def test_fv_to_infinity_converges():
    """Fv = 1e4 already is the massless-cam limit: U0 moves by < 0.2 % up to Fv = 1e6 (the shaft
    mode gets fast, tau_b = tau (Fa/Fv)^(1/2); DP54 adapts its step)."""
    for tau, Fa in ((0.1, 2.0), (0.2, 0.8)):
        u4 = c2.residual2(tau, Fa, 1e4, 1e-8).U0
        u6 = c2.residual2(tau, Fa, 1e6, 1e-8).U0
        assert u4 == pytest.approx(u6, rel=2e-3)


def test_fv_to_infinity_is_close_to_camshaft1():
    """Sec. 5.7 (2): "the characteristics Fv = oo agree with those of the CAMSHAFT-1 model".  Over
    tau = 0.07 .. 0.25 and Fa = 0.5, 0.8, 1.5, 2 (fig. 4.11), U0(Fv = 1e4)/U0(CAMSHAFT-1) has
    median 0.99 and spans 0.87 .. 1.31 (median |difference| 4 %); the extremes sit next to zero
    points, where a small shift of the curve changes U0 a lot.  The difference is the assumption
    (4.8) dh'/dbeta ~ h'/w_s, which CAMSHAFT-2 does not make (sec. 5.1): the thesis calls the
    CAMSHAFT-1 calculations justified (sec. 5.5.5), and within these bounds they are."""
    r = c2.limit_ratios()
    assert np.median(r) == pytest.approx(1.0, abs=0.03)
    assert np.median(np.abs(r - 1)) < 0.06
    assert 0.8 < r.min() and r.max() < 1.4


def _window_max(model, window, n, **params):
    return max(residual(simulate(model, {"tau": float(t), **params}, 3.0, "dp54", rtol=1e-8)).U0
               for t in np.linspace(*window, n))


def test_fig_5_7_envelopes_lie_between_the_limits():
    """Sec. 5.7 (2): the envelope curves U0(tau, Fa) with constant Fv lie between Fv = 0 and
    Fv = oo.  Envelope = largest U0 over a tau window (41 points); at Fa = 1 (fig. 5.7a) for
    Fv = 0.3, 1, 3, 10 each window maximum lies in the band spanned by Fv = 0 (one-DOF) and
    Fv = 1e4, within 10 % (camdyn exceeds the upper limit by up to 6 %, at Fv = 3).
    Not asserted, found on the way (window maxima, 81 points): at Fa = 0.3 a heavy cam
    (Fv = 0.1, 0.3) lies up to 2 times above both limits in tau = 0.15 .. 0.2 and Fv = 1 26 % above
    in 0.1 .. 0.15; at Fa = 2, Fv = 0.1 lies up to 29 % below Fv = 0.  Those are cams heavier than
    the shaft is stiff (Fv < Fa: w_eb < w_ex, the case sec. 5.5.7 calls unusual in practice)."""
    for window in ((0.1, 0.15), (0.15, 0.2), (0.2, 0.25)):
        e0 = _window_max("one_dof", window, 41)
        einf = _window_max("camshaft2", window, 41, Fa=1.0, Fv=c2.FV_INFINITE)
        lo, hi = min(e0, einf), max(e0, einf)
        for Fv in (0.3, 1.0, 3.0, 10.0):
            e = _window_max("camshaft2", window, 41, Fa=1.0, Fv=Fv)
            assert lo / 1.1 <= e <= hi * 1.1, (window, Fv, e, lo, hi)


# -- the thesis's scheme (sec. 5.4) -------------------------------------------------------------
def test_thesis_scheme_step_change_sec_5_4():
    """"Changing of dT from 0.1 tau to 0.01 tau causes a variation of the residual amplitude of
    1.9 %" (sec. 5.4).  The thesis does not say where; camdyn's "koster" method (mid-step
    acceleration held constant) with dT = 0.1 and 0.01 min(tau, tau_b) over tau = 0.07 .. 0.25,
    Fa = 0.5 .. 2, Fv = 0.7 .. 7.5 (table 5-I) changes U0 by 1.4 % (median): within a factor 2."""
    median, error = c2.step_change_median()
    assert 0.019 / 2 <= median <= 0.019 * 2
    # its error: what the scans of the U0 leave, far below the factor-2 band
    assert 0.0 <= error < 1e-3 * median


def test_thesis_scheme_agrees_with_dp54_at_fine_step():
    """At dT = 0.01 min(tau, tau_b) the thesis scheme gives U0 within 0.5 % of DP54 (rtol 1e-10)
    for the curves of fig. 5.6 with a flexible shaft."""
    for params in (c2.FIG_5_6, c2.FIG_5_6_HEAVY):
        tau, Fa, Fv = params["tau"], params["Fa"], params["Fv"]
        h = 0.01 * min(tau, tau * math.sqrt(Fa / Fv))
        fine = residual(simulate("camshaft2", params, 3.0, "koster", step=h)).U0
        assert fine == pytest.approx(c2.residual2(tau, Fa, Fv).U0, rel=5e-3)

