"""The Rayleigh-beam follower's physics checked from outside its derivation.

Everything on the reference side is NumPy typed from the physics in ``tests/beam_reference.py``
(no SymPy, no generated code): the energies the model declares (derive/models/beam.py, paper
(8)-(12)), integrated over the free rod by Gauss-Legendre from the recorded states; Phi_t of
the constraints (6), (7) with the cycloidal RDFD motion of paper (1); a finite-element
Rayleigh cantilever; a Ritz model in the model's polynomials (13).

The energy balance.  The model's Lagrangian L(Q, Q') = T - U (T = T_rod + T_roller +
T_guide) has no explicit t; the constraints Phi(Q, t) do.  With the sign of the generated code,
M Q'' + Phi_Q^T lambda = f, i.e. d/dt L_Q' - L_Q = -Phi_Q^T lambda, Jacobi's function
h = Q' . L_Q' - L changes at the rate -lambda^T Phi_Q Q' = lambda^T Phi_t (Phi_Q Q' + Phi_t
= 0).  T is quadratic in Q' but for J_r w_n^2/2, w_n = Omega - theta' (1 - phi'(theta)),
which makes h = E - Omega J_r w_n, E = T + U.  So

    E(t) - E(0) = W(t) = int_0^t lambda^T Phi_t dt + Omega J_r (w_n(t) - w_n(0)).       (*)

Phi = (pitch point of the cam) - (pin E), so (lambda1, lambda2) is the cam's contact force on
the pin in (X, Y), and Phi_t = (r Omega cos u, -r Omega sin u) the velocity of the cam's
material point at the pin: lambda^T Phi_t is the power the cam delivers through the contact.
The roller's orientation is tied to the common normal, alpha = Omega t - theta + phi(theta)
+ const: through its explicit Omega t the torque J_r w_n' that enforces the tie works at the
rate Omega J_r w_n'.  The rod inside the guide, L_g > 0, moves with x_E' and is part of E.

Nothing crosses the guide exit in the model: (*) has no term at x = 0, since Hamilton's
principle is applied to the free part as if it were closed (the docstring of the model).  The
open system would add there, besides the work of the guide's reactions on the rod sliding
through it, the kinetic energy carried in by the rod, rho A x_E'^3/2 per unit time, and the
convected strain energy E I v_xx(0, t)^2 x_E'/2; over the half revolutions below,
max |int rho A x_E'^3/2 dt| = 0.062 J (5.8 % of the energy scale) and
max |int E I v_xx(0)^2 x_E'/2 dt| up to 2.3e-3 J, while (*) closes to < 1e-10 without them.
(For information: leaving out the roller's torque term Omega J_r (w_n - w_n(0)) leaves 3.6e-2
of the scale unbalanced, and lambda with the opposite sign 2.0.)
"""
import math
from dataclasses import replace
from functools import lru_cache

import numpy as np
import pytest
from scipy.optimize import brentq

from camdyn.runtime.targets import beam
from camdyn.runtime.core.compiled import load
from camdyn.runtime.core.simulator import Simulator

from . import beam_reference as ref

HALF = beam.Case(revolutions=0.5)      # the paper's case (N = 3, 240 rad/s), rtol 1e-9
BALANCE_TOL = 1e-9                     # of the energy scale, at rtol 1e-9
L_GUIDE = 0.03                         # m of rod inside the guide, for the guide term


def simulate(case, L_g=0.0):
    sim, _ = beam.simulator(case)
    return sim.run({**beam.parameters(case), "L_g": L_g})


run = lru_cache(maxsize=None)(simulate)     # the fast runs, shared between tests


def balance(res, n, p=None):
    """E(t_k) - E(0) - W(t_k) of (*) at every recorded step end t_k, and the energy scale
    max |W|.  lambda^T Phi_t is integrated by 3-point Gauss-Legendre on each step through the
    dense output; ``p`` (default: the run's parameters) gives the energies' parameters."""
    p = res.params if p is None else p
    nodes, weights, ends = ref.step_quadrature(res.t, 3)
    W = ref.cumulative_integral(ref.contact_power(p, res.sample(nodes), n), weights)
    e = ref.energies(p, {name: res[name][ends] for name in res.state_names}, n)
    W = W + p["Omega"] * p["J_r"] * (e["w_n"] - e["w_n"][0])
    return e["total"] - e["total"][0] - W, np.abs(W).max()


def relative_imbalance(case, p_change=None, L_g=0.0):
    res = run(case, L_g)
    gap, scale = balance(res, case.modes, {**res.params, **(p_change or {})})
    return np.abs(gap).max() / scale


def grid_case(modes, rayleigh, roller, revolutions=0.5, rtol=1e-9):
    return beam.Case(modes=modes, rayleigh=rayleigh, roller_inertia=None if roller else 0.0,
                     revolutions=revolutions, rtol=rtol)


def rigid_peak_kinetic(case):
    """(rho A x_E + m_r) x_E'^2/2 of the rigid follower at mid-rise, where the cycloid's speed
    peaks at x_E' = 2 S_T Omega/beta_r (paper (1)), x_E = d - r_b - r_r - S_T/2: ~1.00 J."""
    rho_A = case.rho * math.pi * case.rod_radius**2
    x = case.distance - case.base_radius - case.roller_radius - case.rise / 2
    return (rho_A * x + case.roller_mass) * (2 * case.rise * case.omega / (math.pi / 2)) ** 2 / 2


# N = 1, 2 with both switches each way; N = 3, 4 one way each (their other two in the slow grid)
FAST = [(1, True, True), (1, True, False), (1, False, True), (1, False, False),
        (2, True, True), (2, True, False), (2, False, True), (2, False, False),
        (3, True, True), (3, False, False), (4, True, False), (4, False, True)]


@pytest.mark.parametrize("modes, rayleigh, roller", FAST,
                         ids=[f"N{n}-{'R' if r else 'EB'}-{'Jr' if j else 'noJr'}"
                              for n, r, j in FAST])
def test_energy_balance(modes, rayleigh, roller):
    """(*) of the module docstring at every recorded step end (1.1e3 .. 1.1e5 of them) over
    half a revolution (rise and outer dwell, Omega = 240 rad/s, rtol 1e-9), for N = 1..4 with
    the Rayleigh term on/off and J_r = m_r r_r^2/2 or 0: E from the recorded states, W from the
    multipliers lambda1, lambda2 and w_n.  Energy scale max |W| = 1.03 .. 1.07 J, the rising
    follower's kinetic energy (rigid_peak_kinetic 1.00 J, asserted within 10 %).  Measured
    max |E - E(0) - W| / scale: N = 1 5.0e-11 .. 6.8e-11, N = 2 1.3e-12 .. 5.4e-11, N = 3
    2.6e-14 .. 1.4e-12, N = 4 1.6e-14 .. 1.9e-13; asserted 1e-9.  The rod's vibration energy
    is ~1 % of the scale (peak strain energy 6e-3 .. 1e-2 J), its Rayleigh term ~3e-6 of the
    scale (see test_balance_rejects_wrong_energies)."""
    case = grid_case(modes, rayleigh, roller)
    res = run(case)
    assert res.t[-1] == pytest.approx(case.period / 2, rel=1e-12)
    gap, scale = balance(res, modes)
    assert len(gap) > 1000
    assert scale == pytest.approx(rigid_peak_kinetic(case), rel=0.1)
    assert np.abs(gap).max() < BALANCE_TOL * scale


@pytest.mark.slow
@pytest.mark.parametrize("modes", [1, 2, 3, 4])
def test_energy_balance_full_grid(modes):
    """(*) over one whole revolution (rise, outer dwell, fall, inner dwell) at rtol 1e-10 for
    all four combinations of the Rayleigh term and J_r at each N = 1..4 (16 runs, ~30 s).
    Measured max |E - E(0) - W| / scale: N = 1 4.9e-12 .. 6.5e-12, N = 2 7.8e-13 .. 1.1e-11,
    N = 3 6.1e-14 .. 8.1e-13, N = 4 6.5e-14 .. 1.9e-13; asserted 1e-10."""
    for rayleigh in (True, False):
        for roller in (True, False):
            case = grid_case(modes, rayleigh, roller, revolutions=1.0, rtol=1e-10)
            res = simulate(case)
            assert res.t[-1] == pytest.approx(case.period, rel=1e-12)
            gap, scale = balance(res, modes)
            assert np.abs(gap).max() < 1e-10 * scale, (rayleigh, roller)


def test_energy_balance_with_rod_in_the_guide():
    """L_g = 30 mm of rod inside the guide, moving with x_E' (the model's parameter L_g; N = 2,
    half a revolution): its kinetic energy rho A L_g x_E'^2/2 is part of E and (*) closes.
    Measured 2.8e-11 of the scale (1.29 J); asserted 1e-9.  Without the guide term in E the
    imbalance is 0.16 of the scale."""
    case = replace(HALF, modes=2)
    assert relative_imbalance(case, L_g=L_GUIDE) < BALANCE_TOL
    assert relative_imbalance(case, {"L_g": 0.0}, L_g=L_GUIDE) > 0.1


def test_balance_rejects_wrong_energies():
    """The balance notices a model whose energy differs from the declared one: on the N = 2
    runs of test_energy_balance, E with the Rayleigh term switched the other way (on for the
    run without it, off for the run with it) leaves 2.6e-6 of the scale unbalanced, 2600x the
    tolerance (asserted > 100x); J_r doubled (J_r = m_r r_r^2) 4.3e-2, J_r = 1e-6 kg m^2 where
    the run has none 7.0e-2 (asserted > 1e-2).  And the guide exit: adding the open system's
    kinetic-energy flux rho A x_E'^3/2 to W leaves 5.8e-2 of the scale (asserted > 1e-2): the
    model lets nothing cross there."""
    on, off = grid_case(2, True, True), grid_case(2, False, True)
    assert relative_imbalance(on, {"rayleigh": 0.0}) > 100 * BALANCE_TOL
    assert relative_imbalance(off, {"rayleigh": 1.0}) > 100 * BALANCE_TOL
    assert relative_imbalance(on, {"J_r": 2 * on.J_r}) > 1e-2
    assert relative_imbalance(grid_case(2, True, False), {"J_r": 1e-6}) > 1e-2
    res = run(on)
    p = res.params
    nodes, weights, _ = ref.step_quadrature(res.t, 3)
    rho_A, _, _ = ref.section(p)
    flux = ref.cumulative_integral(rho_A * res.sample(nodes)["xEd"] ** 3 / 2, weights)
    gap, scale = balance(res, 2)
    assert np.abs(gap - flux).max() > 1e-2 * scale


# -- the rod frozen in a dwell: finite elements ---------------------------------------------

def _tip_mass_root(ratio):
    """First root z = beta L of the Euler-Bernoulli cantilever with a tip mass ratio
    m/(rho A L): 1 + cos z cosh z + ratio z (cos z sinh z - sin z cosh z) = 0."""
    def g(z):
        return (1 + math.cos(z) * math.cosh(z)
                + ratio * z * (math.cos(z) * math.sinh(z) - math.sin(z) * math.cosh(z)))
    grid = np.linspace(0.5, 2.0, 301)
    k = next(i for i in range(300) if g(grid[i]) * g(grid[i + 1]) < 0)
    return brentq(g, grid[k], grid[k + 1], xtol=1e-15)


def test_fe_reference_converges():
    """The finite-element reference itself (40 Hermite elements).  Euler-Bernoulli (rho I = 0)
    cantilever of the outer dwell, L = 66 mm: without tip mass against beta L = 1.8751040687
    (the classical root, found here by brentq: 1.87510406871), with the tip mass m_r against
    the root of the tip-mass frequency equation (beta L = 1.1945290): measured 7.9e-9 and
    -4.3e-10, asserted 5e-8.  With the Rayleigh term and the dwell's tip mass m_r + J_r/r^2:
    20 against 40 elements, f1 1.7e-9, f2 9.7e-7 (asserted 1e-8, 2e-6), so by the h^4
    convergence of the cubic elements the 40-element f2 is good to 1/15 of that, ~7e-8; and
    against a Ritz model of 10 polynomials f1 1.5e-10, f2 6.5e-8 (asserted 1e-8, 2e-7)."""
    p = beam.parameters(beam.Case())
    rod = ref.dwell_cantilever(p)
    L, rho_A, EI = rod["L"], rod["rho_A"], rod["EI"]
    assert _tip_mass_root(0.0) == pytest.approx(1.8751040687, abs=1e-10)
    for m in (0.0, p["m_r"]):
        z = _tip_mass_root(m / (rho_A * L))
        exact = (z / L) ** 2 * math.sqrt(EI / rho_A) / (2 * math.pi)
        f = ref.frequencies_hz(*ref.fe_cantilever(L, rho_A, 0.0, EI, m, 40))[0]
        assert f == pytest.approx(exact, rel=5e-8)
    f20, f40 = (ref.dwell_frequencies_fe(p, elements=k) for k in (20, 40))
    ritz = ref.frequencies_hz(*ref.ritz_cantilever(d=p["d"], n=10, **rod))
    for other in (f20, ritz):
        assert f40[0] == pytest.approx(other[0], rel=1e-8)
    assert f40[1] == pytest.approx(f20[1], rel=2e-6)
    assert f40[1] == pytest.approx(ritz[1], rel=2e-7)


# Ritz excess of the model's N polynomials over the converged finite elements, f1 and f2:
# measured N = 3 8.1e-6 (outer) 1.12e-5 (inner), 2.03e-3, 1.97e-3; N = 4 5.8e-8, 7.9e-8,
# 1.24e-3, 1.29e-3 (N = 5: ~1e-9, 2.1e-5): bounds 2x the worst measured
RITZ_EXCESS = {3: (2.5e-5, 4e-3), 4: (2e-7, 3e-3)}


@pytest.mark.parametrize("modes", [3, 4])
def test_dwell_frequencies_against_finite_elements(modes):
    """beam.dwell_frequencies (the linearized generated rhs, outer dwell; the inner dwell as
    the outer one of a cam with a 1 nm rise) against the rod frozen there in NumPy: a
    cantilever of length d - r with rotary inertia rho I and the tip mass m_r + J_r/r^2 (the
    roller's w_n = v_E'/r on the dwell circle of radius r, see beam_reference.dwell_tip_mass).
    (i) 40 Hermite finite elements: the model's f1 and f2 lie above (Ritz bounds from above)
    by no more than RITZ_EXCESS (the Ritz error of N polynomials, 2x the measured; FE good to
    1e-8), and not below by more than 2e-8; outer 674.224 Hz, inner 485.761 Hz (FE).  (ii)
    NumPy's Ritz model in the same polynomials gives all N frequencies: measured 7e-11,
    asserted 1e-9.  With the tip mass m_r alone the model's f1 would be 2.5e-3 (outer) and
    5.2e-3 (inner) below the FE value, without the FE's rotary inertia 5.7e-4 and 4.4e-4
    below: both fail (i)."""
    bound = RITZ_EXCESS[modes]
    for case in (beam.Case(modes=modes), beam.Case(modes=modes, rise=1e-9)):
        p = beam.parameters(case)
        rod = ref.dwell_cantilever(p)
        model = beam.dwell_frequencies(case)
        fe = ref.frequencies_hz(*ref.fe_cantilever(elements=40, **rod))
        excess = model[:2] / fe[:2] - 1
        assert np.all(excess > -2e-8) and np.all(excess < bound), excess
        ritz = ref.frequencies_hz(*ref.ritz_cantilever(d=p["d"], n=modes, **rod))
        np.testing.assert_allclose(model, ritz, rtol=1e-9)


V0 = 1e-6          # m, the initial tip deflection: geometric nonlinearity (V0/r)^2 ~ 5e-10
DWELL_OMEGA = 120.0   # rad/s: the outer dwell lasts 13 ms, 8.6 periods of the rod


def release_in_the_dwell(modes):
    """The model released from rest in the outer dwell with the tip-load shape of tip
    deflection V0, run to the end of the dwell: (result, t0, case parameters).

    A consistent state built from the constraints (6), (7): on the dwell circle of radius r,
    r sin u = v_E = V0 gives u0 = asin(V0/r) and x_E = d - r cos u0 (the shape is taken on this
    x_E); theta0 = beta_r + 0.02, t0 = (theta0 + u0)/Omega.  At rest (b' = 0) the rates
    x_E' = 0, theta' = Omega satisfy Phi_Q Q' = -Phi_t: Phi_t = (r Omega cos u, -r Omega sin u)
    and the theta column of Phi_Q is (-r cos u, r sin u) where r' = 0."""
    case = beam.Case(modes=modes, omega=DWELL_OMEGA)
    p = beam.parameters(case)
    model = load(case.model)
    names = model.state_names
    r = p["r_b"] + p["r_r"] + p["S_T"]
    u0 = math.asin(V0 / r)
    xE = p["d"] - r * math.cos(u0)
    theta0 = math.pi / 2 + 0.02
    t0, t1 = (theta0 + u0) / DWELL_OMEGA, (math.pi - 0.02) / DWELL_OMEGA
    y = np.zeros(len(names))
    for i, b in enumerate(ref.tip_load_amplitudes(xE, V0, p["d"], modes), start=1):
        y[names.index(f"b{i}")] = b
    y[names.index("xE")], y[names.index("theta")] = xE, theta0
    y[names.index("thetad")] = DWELL_OMEGA
    sim = Simulator(model, t1, "dp54", rtol=case.rtol, law=case.law, y0=y, t0=t0)
    return sim.run(p), t0, p


# model against FE modal superposition, as a fraction of V0: measured N = 3 1.23e-3, N = 4
# 5.4e-4, the same as NumPy's Ritz model in the model's polynomials against FE (the Ritz error:
# the second mode, 7e-4 of V0 at the tip, runs 2.0e-3 (N = 3), 1.2e-3 (N = 4) fast and
# dephases by 1.2 and 0.75 rad over the dwell); bounds 2x
FE_RESPONSE_TOL = {3: 2.5e-3, 4: 1.1e-3}


@pytest.mark.parametrize("modes", [3, 4])
def test_free_vibration_in_the_outer_dwell(modes):
    """Free vibration in the outer dwell (Omega = 120 rad/s, 8.6 periods of 674 Hz): the
    model released from rest with the static tip-load shape v = V0 (3 s^2 - s^3)/2, s = x/x_E,
    V0 = 1 um (in the span of (x/d)^2, (x/d)^3 and of the Hermite cubics: the same initial
    shape in every model), v_E(t) at 3000 times (dense output) against the modal
    superposition of (i) the 40-element FE cantilever of test_dwell_frequencies_against_
    finite_elements: difference below FE_RESPONSE_TOL of V0 (measured 1.23e-3 for N = 3,
    5.4e-4 for N = 4, the Ritz error); (ii) NumPy's Ritz model in the model's N polynomials:
    measured 2.9e-8 of V0 (the geometric nonlinearity (V0/r)^2 and the integration),
    asserted 1e-6.  The generated constraints hold at the constructed start (1.6e-18 m,
    asserted 1e-15 m).  Without J_r/r^2 in the references' tip mass the differences would be
    0.13 of V0, without their rotary inertia 3.1e-2 (fail (i) and (ii))."""
    res, t0, p = release_in_the_dwell(modes)
    start = res.sample([t0])
    assert abs(start["Phi1"][0]) < 1e-15 and abs(start["Phi2"][0]) < 1e-15
    assert abs(start["vE"][0] - V0) < 1e-12 * V0
    assert res["theta"].max() < math.pi        # still in the dwell
    t = np.linspace(t0, res.t[-1], 3000)
    v = res.sample(t)["vE"]
    rod = ref.dwell_cantilever(p)
    L, elements = rod["L"], 40
    M, K = ref.fe_cantilever(elements=elements, **rod)
    w, slope = ref.tip_load_shape(ref.fe_nodes(L, elements), L, V0)
    u0 = np.column_stack([w, slope]).ravel()
    tip = np.zeros(len(u0))
    tip[-2] = 1.0
    v_fe = ref.modal_response(M, K, u0, tip, t - t0)
    assert np.abs(v - v_fe).max() < FE_RESPONSE_TOL[modes] * V0
    M, K = ref.ritz_cantilever(d=p["d"], n=modes, **rod)
    b0 = ref.tip_load_amplitudes(L, V0, p["d"], modes)
    v_ritz = ref.modal_response(M, K, b0, (L / p["d"]) ** np.arange(2, modes + 2), t - t0)
    assert np.abs(v - v_ritz).max() < 1e-6 * V0
