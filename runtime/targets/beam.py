"""Running the Rayleigh-beam follower of the paper: the case, its checks, one compiled run, the
frozen natural frequency at the outer dwell, and the paper's figures 4-9.

A :class:`Case` holds what a user varies (SI units, defaults from the paper, sec. 4);
:func:`run` integrates the generated ``beam<N>`` module for whole cam revolutions from the
rigid follower's state at theta = 0 (zero deflection, the constraints (6), (7) and their
rates satisfied), and :func:`summarize` reports the tip response and the constraint residual.
"""
from __future__ import annotations

import math
import time
from dataclasses import asdict, replace
from functools import lru_cache

import numpy as np

from ..core.errors import CamdynInputError
from ..core.laws import choose
from ..core.compiled import load
from .beam_case import FORMULATIONS, N_MAX, Case, check  # noqa: F401  (the case, re-exported)
from ..measure.batch import Wanted
from ..measure.extremes import extreme
from ..core.simulator import Simulator

# summary keys, in the order printed
KEYS = ("model", "formulation", "omega", "modes", "revolutions", "max_abs_tip_deflection",
        "max_constraint_residual", "dwell_frequency_hz", "n_steps", "cpu_seconds")


def parameters(case: Case) -> dict:
    """The generated model's parameter values (manifest names) for a case."""
    return {"Omega": case.omega, "d": case.distance, "r_b": case.base_radius,
            "r_r": case.roller_radius, "S_T": case.rise, "a_rod": case.rod_radius, "E": case.E,
            "rho": case.rho, "m_r": case.roller_mass, "J_r": case.J_r,
            "rayleigh": 1.0 if case.rayleigh else 0.0, "w_B": case.w_B,
            "formulation": FORMULATIONS[case.formulation]}


def _law_arrays(case: Case) -> tuple[np.ndarray, np.ndarray]:
    """The cam law as the compiled one-off evaluations (eval_rhs, eval_outputs) take it."""
    law = choose(case.law)
    return np.array([law.code], dtype=np.intc), np.array([law.par])


def initial_state(case: Case, model, b=None, b_rate=None) -> np.ndarray:
    """A consistent state at t = 0 for the mode amplitudes ``b`` and their rates ``b_rate``
    (default: the rod straight and at rest transversally, as the paper starts).

    The dependent coordinates come from the generated constraints themselves: x_E and theta
    by Newton's method on Phi(Q, 0) = 0 (6), (7), started from the rigid follower at theta = 0;
    their rates from the partitioned right-hand side, which solves Phi_Q Q' = -dPhi/dt for
    them.  For b = 0 this is x_E = d - r(0), theta = 0, theta' = Omega, x_E' = -S'(0) Omega."""
    from ..engine import driver

    n = case.modes
    names = model.state_names
    # the model's declared start (x_E = d - r_b - r_r, theta' = Omega): the rigid follower at
    # theta = 0 (every law starts its rise at S = 0), the first guess for the solve below
    p_aug = model.parameter_vector({**parameters(case), "formulation": 0.0})
    y = model.initial_state(p_aug)
    if b is not None:
        y[[names.index(f"b{i}") for i in range(1, n + 1)]] = np.asarray(b, dtype=float)
    if b_rate is not None:
        y[[names.index(f"b{i}d") for i in range(1, n + 1)]] = np.asarray(b_rate, dtype=float)
    codes, pars = _law_arrays(case)
    t0 = np.zeros(1)
    dep = [names.index("xE"), names.index("theta")]
    phis = [model.output_names.index("Phi1"), model.output_names.index("Phi2")]

    def residual(p, yy):
        return driver.eval_outputs(model.capsule, p, codes, pars, t0, yy[None, :])[0][phis]

    for _ in range(30):
        g = residual(p_aug, y)
        if np.abs(g).max() < 1e-15:
            break
        J = np.empty((2, 2))
        for j, k in enumerate(dep):
            h = 1e-7 * (1.0 + abs(y[k]))
            yp = y.copy()
            yp[k] += h
            J[:, j] = (residual(p_aug, yp) - g) / h
        y[dep] -= np.linalg.solve(J, g)
    else:
        raise CamdynInputError(f"no consistent initial state: the constraints (6), (7) keep a "
                               f"residual of {np.abs(g).max():.3g} m")
    p_part = model.parameter_vector({**parameters(case), "formulation": 1.0})
    f = driver.eval_rhs(model.capsule, p_part, codes, pars, t0, y[None, :])[0]
    y[[names.index("xEd"), names.index("thetad")]] = f[dep]
    return y


def deflection_scale(case: Case) -> float:
    """S_T Omega^2/w_1^2, m: the static deflection of the lowest mode under the cam's
    acceleration (w_1 the lowest transverse frequency at the outer dwell)."""
    w1 = 2 * math.pi * dwell_frequency(case)
    return case.rise * case.omega**2 / w1**2


def integrator(case: Case):
    """The method object of the case's run: method, rtol and absolute tolerances, the mode
    amplitudes' from ``case.mode_atol`` (beam_case.MODE_ATOL) unless the user's atol or
    state_atol say otherwise.

    An amplitude b_i is held to tol = mode_atol S_T Omega^2/w_1^2, its rate to tol w_N, w_N the
    highest frozen frequency (:func:`fastest_frequency`): a mode ringing at w with amplitude a
    has the rate a w, so the rate's tolerance is the amplitude's for the fastest mode too.
    Held to tol Omega instead, the rates kept that mode's ringing to tol Omega/w_N (1/6300 of
    tol at N = 6), which every method then resolved: DOP853 at a third of its stable step, the
    implicit methods at a few percent of it (README "Rayleigh-beam follower")."""
    from ..core.methods import METHODS

    pairs = dict(case.state_atol)
    if case.mode_atol is not None and case.atol is None:
        tol = case.mode_atol * deflection_scale(case)
        rate = tol * 2 * math.pi * fastest_frequency(case)
        for i in range(1, case.modes + 1):
            pairs.setdefault(f"b{i}", tol)
            pairs.setdefault(f"b{i}d", rate)
    return METHODS[case.method](rtol=case.rtol, atol=case.atol, state_atol=tuple(pairs.items()))


def simulator(case: Case, t_end: float | None = None,
              max_steps: int = 20_000_000) -> tuple[Simulator, object]:
    check(case)
    model = load(case.model)
    t_end = case.revolutions * case.period if t_end is None else t_end
    sim = Simulator(model, t_end, integrator(case), law=case.law,
                    y0=initial_state(case, model), max_steps=max_steps)
    return sim, model


def run(case: Case, progress=None) -> tuple[dict, object]:
    """Integrate ``case``; returns (summary, result)."""
    sim, model = simulator(case)
    if progress:
        progress(f"beam follower: N = {case.modes}, Omega = {case.omega:g} rad/s, "
                 f"{case.revolutions:g} revolution(s), {case.formulation}")
    start = time.process_time()
    res = sim.run(parameters(case))
    cpu = time.process_time() - start
    return summarize(case, res, cpu), res


def tip_max(res) -> float:
    """max |v_E| over the run (the paper's headline figure), refined on the dense output."""
    return tip_extreme(res).value


def tip_extreme(res):
    """The largest |v_E| over the run with the sampling error of the scan that found it
    (4 samples a recorded step, the peaks checked; runtime/measure/extremes.py)."""
    return extreme(res, TIP.name, float(res.t[0]), float(res.t[-1]), absolute=TIP.absolute,
                   minimum=TIP.minimum, per_step=TIP.per_step, candidates=TIP.candidates)


TIP = Wanted("vE", absolute=True, minimum=False, per_step=4, candidates=4)
"""How the largest tip deflection is found: 4 samples a recorded step, the peaks checked."""
RESIDUALS = tuple(Wanted(k, absolute=True, minimum=False, per_step=4, hermite_tol=1e-12)
                  for k in ("Phi1", "Phi2"))
"""How the largest constraint residuals |Phi1|, |Phi2| are found: to 1e-12 m (Baumgarte's
terms hold them near 1e-13 m, where 1e-9 of them is rounding), so the scan may read the
cubic Hermite interpolant in steps whose dense output the run left out."""


def summarize(case: Case, res, cpu: float) -> dict:
    """The run's summary; ``sampling`` in it: the sampling error of each largest value."""
    t0, t1 = float(res.t[0]), float(res.t[-1])
    tip = tip_extreme(res)
    phi = [extreme(res, w.name, t0, t1, absolute=w.absolute, minimum=w.minimum,
                   per_step=w.per_step, candidates=w.candidates, hermite_tol=w.hermite_tol)
           for w in RESIDUALS]
    worst, sampling = largest(tip, phi)
    return {"model": case.model, "formulation": case.formulation, "omega": case.omega,
            "modes": case.modes, "revolutions": case.revolutions,
            "max_abs_tip_deflection": tip.value, "max_constraint_residual": worst,
            "dwell_frequency_hz": dwell_frequency(case), "n_steps": int(res.stats["n_steps"]),
            # DP54's stiffness test (Hairer): where it fired, in the model's time t (s)
            "stiff_from_T": res.stiff_from_T, "warnings": list(res.warnings),
            "cpu_seconds": cpu, "case": asdict(case), "sampling": sampling}


def largest(tip, phi) -> tuple[float, dict]:
    """(the largest constraint residual, the sampling errors of the summary's figures) from
    the extremes of |v_E| and of every |Phi| (runtime/measure/extremes.py)."""
    return max(phi, key=lambda e: e.value).value, {
        "max_abs_tip_deflection": tip.sampling_error,
        "max_constraint_residual": max(e.sampling_error for e in phi)}


def linearized(case: Case) -> np.ndarray:
    """State matrix A of the transverse motion d[b, b']/dt = A [b, b'] at the outer dwell with
    the length frozen there: numerical derivatives of the generated right-hand side in its
    partitioned form (x_E, theta recovered from b by the constraints), at mid-dwell.  In the
    dwell the pitch curve is a circle, so the linearization does not depend on the time."""
    from ..engine import driver

    c = replace(case, formulation="partitioned")
    check(c)
    model = load(c.model)
    p = model.parameter_vector(parameters(c))
    codes, pars = _law_arrays(c)
    names = model.state_names
    n = c.modes
    theta0 = 3 * math.pi / 4
    t0 = theta0 / c.omega
    y0 = np.zeros(len(names))
    y0[names.index("theta")] = theta0
    y0[names.index("thetad")] = c.omega
    y0[names.index("xE")] = c.free_length_raised
    idx = [names.index(f"b{i}") for i in range(1, n + 1)]
    idx += [names.index(f"b{i}d") for i in range(1, n + 1)]
    acc = [names.index(f"b{i}d") for i in range(1, n + 1)]
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    for j, k in enumerate(idx):
        h = 1e-9 if j < n else 1e-9 * c.omega
        ys = np.repeat(y0[None, :], 2, axis=0)
        ys[0, k] += h
        ys[1, k] -= h
        f = driver.eval_rhs(model.capsule, p, codes, pars, np.full(2, t0), ys)
        A[n:, j] = (f[0, acc] - f[1, acc]) / (2 * h)
    return A


def dwell_frequencies(case: Case) -> np.ndarray:
    """Transverse natural frequencies [Hz], ascending, at the outer dwell (length frozen)."""
    lam = np.linalg.eigvals(linearized(case))
    w = np.sort(np.abs(lam.imag[lam.imag > 0]))
    return w / (2 * math.pi)


@lru_cache(maxsize=64)
def _dwell_spectrum(case: Case) -> tuple:
    return tuple(float(f) for f in dwell_frequencies(case))


def dwell_frequency(case: Case) -> float:
    """The lowest transverse natural frequency [Hz] at the outer dwell (follower raised)."""
    return _dwell_spectrum(case)[0]


def fastest_frequency(case: Case) -> float:
    """The highest transverse natural frequency [Hz] of the N-mode model at the outer dwell,
    where the free rod is shortest and every frozen frequency highest over the revolution
    (242.1 kHz at N = 6 for the paper's data, against 674.2 Hz for the lowest): the step an
    explicit method is stable at is a fixed multiple of its inverse."""
    return _dwell_spectrum(case)[-1]


def cantilever_tip_mass_frequency(E: float, I: float, rho_A: float, L: float, m_tip: float) -> float:
    """Lowest natural frequency [Hz] of an Euler-Bernoulli cantilever with a tip point mass:
    the first root of 1 + cos(bL) cosh(bL) + r bL (cos(bL) sinh(bL) - sin(bL) cosh(bL)) = 0,
    r = m_tip/(rho A L), and w = b^2 (E I/(rho A))^(1/2)."""
    from scipy.optimize import brentq

    r = m_tip / (rho_A * L)

    def g(z):
        return 1 + math.cos(z) * math.cosh(z) + r * z * (math.cos(z) * math.sinh(z) - math.sin(z) * math.cosh(z))

    grid = np.linspace(1e-3, 2.0, 2001)
    vals = [g(z) for z in grid]
    k = next(i for i in range(len(grid) - 1) if vals[i] * vals[i + 1] < 0)
    z = brentq(g, grid[k], grid[k + 1], xtol=1e-15)
    return (z / L) ** 2 * math.sqrt(E * I / rho_A) / (2 * math.pi)


# -- the paper's figures 4-9: the tip response against the cam angle, one parameter varied ---------

FIGURES = {
    "fig4_modes": ("modes", (2, 3, 4), "N"),
    "fig5_omega": ("omega", (120.0, 240.0, 360.0), "Omega [rad/s]"),
    "fig6_distance": ("distance", (0.102, 0.112, 0.122), "d [m]"),
    "fig7_rod_radius": ("rod_radius", (0.007, 0.005, 0.003), "rod radius [m]"),
    # the paper does not print its three base radii: 22, 26 and 30 mm taken
    "fig8_base_radius": ("base_radius", (0.030, 0.026, 0.022), "r_b [m]"),
    "fig9_rise": ("rise", (0.008, 0.015, 0.022), "S_T [m]"),
}


def sweep(case: Case, field: str, values, progress=None) -> list:
    """(value, summary, result) for each value of one field of the case."""
    out = []
    for v in values:
        c = replace(case, **{field: v})
        s, res = run(c, progress)
        out.append((v, s, res))
    return out
