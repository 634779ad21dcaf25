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

from ..core.errors import CamdynInputError, SimulationError
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


STEP_BUDGET = 2_000_000
"""The most steps a beam follower's run may be predicted to need (:func:`feasible`); its
Simulator may take twice as many, for the run one notch tighter of the error estimate.  At
N = 3 a step costs about 15 us on this kind of machine, so a refused case is one that would
run for a minute or more."""

SMALL_DEFLECTION = 0.1
"""The largest deflection scale S_T Omega^2/w_1^2 (:func:`deflection_scale`), as a fraction
of the rod's shortest free length, for which the paper's small-deflection beam theory is
taken to hold: the paper's data give 7e-4 of it (a largest tip deflection 4.6 times the
scale), so at the limit the rod's tip moves about half its free length."""

SLENDER = 0.2
"""The thickest rod, as a fraction of its shortest free length, that passes as a Rayleigh
beam without a warning: a beam without shear deformation wants a length of ten radii of
gyration or more (a/2 for a solid round rod, so a <= L/5); the paper's thickest rod, 7 mm,
has 66 mm, L/a = 9.4.  A rod thicker than its free length is refused."""

STEPS_PER_REVOLUTION = 20
"""A lower bound of the steps any method takes over one revolution of the four-segment
cam (rise, dwell, fall, dwell; each segment's start is a step's end, and every method takes
several steps through a segment's motion): the paper's data take 969 (DOP853, N = 3)."""

EXPLICIT_STABLE = 4.2
"""h w_N of DOP853 and DP54 stepping at their stability limit on the rod's fastest mode (w_N,
rad/s): N = 6 with the mode tolerance takes 9,700 steps a revolution of 26.2 ms, w_N = 1.52e6
rad/s, h w_N = 4.1.  A run of length t needs at least t w_N / 4.2 steps of an explicit
method."""


def _frozen(case: Case) -> Case:
    """The case whose frozen spectrum :func:`feasible` reads: the case at the paper's cam
    speed.  The rod frozen in a dwell, where the pitch curve is a circle, does not feel the
    speed (674.2293 Hz at 1 rad/s and at 1e4 rad/s); at absurd speeds the linearization's
    difference steps, which scale with Omega, would no longer be small."""
    return replace(case, omega=_D_OMEGA)


def least_frequency(case: Case) -> float:
    """The lowest transverse natural frequency [Hz] over the revolution: the rod frozen at the
    inner dwell, where its free length is longest (as the outer dwell of a cam whose rise is
    1e-9 of the case's, tests/test_beam_energy.py)."""
    return dwell_frequency(replace(_frozen(case), rise=case.rise * 1e-9))


def least_revolutions(case: Case) -> float:
    """The revolutions that cover one period of the rod's slowest mode, so that the largest
    tip deflection is not read from a run too short for the rod to answer the cam (the window
    rule of runtime/measure/contract.py); a fraction of one at the paper's speeds (0.079)."""
    return case.omega / (2 * math.pi * least_frequency(case))


def predicted_steps(case: Case) -> float:
    """A lower bound of the steps the case's run takes: STEPS_PER_REVOLUTION a revolution,
    and for an explicit method its stable step on the fastest mode (EXPLICIT_STABLE)."""
    t_end = case.revolutions * case.period
    floor = case.revolutions * STEPS_PER_REVOLUTION
    if case.method in ("dp54", "dop853", "rkn12"):
        floor = max(floor, t_end * 2 * math.pi * fastest_frequency(_frozen(case))
                    / EXPLICIT_STABLE)
    return floor


def feasible(case: Case, window: bool = True, budget: int | None = STEP_BUDGET) -> Case:
    """Refuse, before any run and naming the parameter, a case whose answer could not be
    trusted or would not come in bounded time: a rod so slender or a cam so fast that the
    rod's deflection is not small (:data:`SMALL_DEFLECTION`), a run shorter than one period
    of the rod's slowest mode (:func:`least_revolutions`; with ``window``), or one predicted
    to need more than ``budget`` steps (None: not checked)."""
    check(case)
    length = case.free_length_raised
    if case.rod_radius > length:
        raise CamdynInputError(
            f"rod_radius={case.rod_radius:g} m: a rod thicker than its free length at the top "
            f"of the stroke ({length * 1e3:.3g} mm) is no beam; give rod_radius <= "
            f"{SLENDER * length:.3g} m, a fifth of it, for a Rayleigh beam")
    ratio = case.omega / (2 * math.pi * dwell_frequency(_frozen(case)))
    scale = case.rise * ratio * ratio          # inf, not OverflowError, for absurd speeds
    if not scale <= SMALL_DEFLECTION * length:         # NaN too: a rod with no stiffness left
        raise CamdynInputError(_not_small(case, scale, length))
    least = least_revolutions(case)
    if window and case.revolutions < least:
        raise CamdynInputError(
            f"revolutions={case.revolutions:g} covers {case.revolutions * case.period:.3g} s, "
            f"less than one period of the rod's slowest mode ({1 / least_frequency(case):.3g} "
            f"s at the inner dwell): its largest tip deflection would be read from a run too "
            f"short for the rod to answer the cam; give revolutions >= {least:.3g}")
    steps = predicted_steps(case)
    if budget is not None and steps > budget:
        raise CamdynInputError(_too_long(case, steps, least))
    return case


def _too_long(case: Case, steps: float, least: float) -> str:
    """The refusal of a run predicted to need more than STEP_BUDGET steps, with its cure: fewer
    revolutions where that suffices, an implicit method where an explicit one is held to the
    fastest mode's stable step, else a slower cam."""
    per = steps / case.revolutions
    fits = math.floor(STEP_BUDGET / per)
    head = (f"revolutions={case.revolutions:g} at omega={case.omega:g} rad/s needs at least "
            f"{steps:.3g} steps ({per:.3g} a revolution with {case.method}), more than the "
            f"{STEP_BUDGET:.3g} a run may take")
    if fits >= least:
        return f"{head}; give revolutions <= {fits:g}"
    if per > STEPS_PER_REVOLUTION:
        return (f"{head}: the explicit method steps at the stability limit of the rod's fastest "
                f"mode ({fastest_frequency(_frozen(case)):.4g} Hz); give --method radau5 or "
                f"rodas4, or fewer --modes")
    return f"{head}; give fewer revolutions or a lower omega"


def _not_small(case: Case, scale: float, length: float) -> str:
    """The refusal of a deflection that is not small: led by the rod's radius or by the cam's
    speed, whichever departs further from the paper's data, with the bound of each that
    would hold (the thinnest rod only where one exists that fits the cam)."""
    what = (f"the cam's acceleration would bend the rod by about S_T Omega^2/w_1^2 = "
            f"{scale:.3g} m, more than {SMALL_DEFLECTION:g} of its free length "
            f"({length * 1e3:.3g} mm), where the small-deflection beam theory of the model "
            f"does not hold")
    w1 = 2 * math.pi * dwell_frequency(_frozen(case))
    top = w1 * math.sqrt(SMALL_DEFLECTION * length / case.rise)
    speed = f"omega <= {top:.4g} rad/s" if top > 0 else None
    a = _least_radius(case)
    rod = (f"rod_radius >= {a:.3g} m" if a is not None and a > case.rod_radius else None)
    slender = _D_ROD / case.rod_radius >= case.omega / _D_OMEGA
    head = (f"rod_radius={case.rod_radius:g} m with omega={case.omega:g} rad/s" if slender
            else f"omega={case.omega:g} rad/s with rod_radius={case.rod_radius:g} m")
    cures = [c for c in ((rod, speed) if slender else (speed, rod)) if c]
    return f"{head}: {what}; give " + (" or ".join(cures) if cures else "the paper's data")


_D_ROD, _D_OMEGA = Case().rod_radius, Case().omega


def _least_radius(case: Case) -> float | None:
    """The thinnest rod whose deflection scale stays within SMALL_DEFLECTION of its free
    length, to 0.1 %, or None where even the thickest slender rod (SLENDER) bends more: the
    scale falls as the rod thickens (as 1/a^2 where the rod's own mass rules, 1/a^4 where the
    roller's does), so bisection in log a on the model's own frequency."""
    limit, speed = SMALL_DEFLECTION * case.free_length_raised, case.omega / _D_OMEGA

    def bends(a: float) -> bool:
        scale = deflection_scale(replace(_frozen(case), rod_radius=a)) * speed * speed
        return not scale <= limit

    lo, hi = case.rod_radius, SLENDER * case.free_length_raised
    if bends(hi):
        return None
    while hi > 1.001 * lo:
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if bends(mid) else (lo, mid)
    return hi


def simulator(case: Case, t_end: float | None = None,
              max_steps: int | None = None) -> tuple[Simulator, object]:
    """The Simulator of ``case`` and its model, the case refused first where it cannot be
    answered (:func:`feasible`).  A caller's own ``t_end`` (a part of a revolution) or step
    budget (a study of where methods fail) takes the window rule and the step prediction out
    of the refusal; a run predicted beyond a caller's budget fails as the run would, at once
    (a SimulationError)."""
    own = t_end is not None or max_steps is not None
    feasible(case, window=not own, budget=None if own else STEP_BUDGET)
    if max_steps is not None:
        steps = predicted_steps(case if t_end is None else replace(
            case, revolutions=t_end / case.period))
        if steps > max_steps:
            raise SimulationError(f"{case.model} with {case.method}: the run needs at least "
                                  f"{steps:.3g} steps, more than its budget of {max_steps}")
    model = load(case.model)
    t_end = case.revolutions * case.period if t_end is None else t_end
    sim = Simulator(model, t_end, integrator(case), law=case.law,
                    y0=initial_state(case, model),
                    max_steps=2 * STEP_BUDGET if max_steps is None else max_steps)
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
    warnings = list(res.warnings) + large_deflection(case, tip.value)
    return {"model": case.model, "formulation": case.formulation, "omega": case.omega,
            "modes": case.modes, "revolutions": case.revolutions,
            "max_abs_tip_deflection": tip.value, "max_constraint_residual": worst,
            "dwell_frequency_hz": dwell_frequency(case), "n_steps": int(res.stats["n_steps"]),
            # DP54's stiffness test (Hairer): where it fired, in the model's time t (s)
            "stiff_from_T": res.stiff_from_T, "warnings": warnings,
            "cpu_seconds": cpu, "case": asdict(case), "sampling": sampling}


LARGE_DEFLECTION = 0.05
"""The largest tip deflection, as a fraction of the rod's shortest free length, that passes
without a warning: beyond it the rod's slope reaches about 0.1 rad (a cantilever's tip slope
is 1.5 v/L), where the model's linear curvature and the rod's shortening, which it leaves
out, are no longer small."""


def large_deflection(case: Case, tip: float) -> list:
    """Warnings where the rod is not slender (:data:`SLENDER`) or the largest tip deflection
    is not small (:data:`LARGE_DEFLECTION`)."""
    length = case.free_length_raised
    out = []
    if case.rod_radius > SLENDER * length:
        out.append(f"the rod ({case.rod_radius * 1e3:.3g} mm radius) is short for its "
                   f"thickness: {length * 1e3:.3g} mm of free length at the top of the "
                   f"stroke, less than ten radii of gyration; a Rayleigh beam leaves out the "
                   f"shear deformation, which such a rod has")
    if not tip > LARGE_DEFLECTION * length:
        return out
    return out + [f"the rod's tip deflects up to {tip * 1e3:.3g} mm, {tip / length:.0%} of its "
            f"free length at the top of the stroke ({length * 1e3:.3g} mm): beyond small "
            f"deflections the model's linear beam, which leaves out the rod's shortening, "
            f"does not hold; take a thicker rod or a lower omega"]


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
    A = linearized(case)
    if not np.isfinite(A).all():
        raise CamdynInputError(
            f"rod_radius={case.rod_radius:g} m: the rod frozen at the dwell has no finite "
            f"stiffness and mass matrices for these data (distance={case.distance:g} m, "
            f"roller_mass={case.roller_mass:g} kg, E={case.E:g} Pa, rho={case.rho:g} kg/m^3): "
            f"give values of a real rod, near the paper's (sec. 4)")
    lam = np.linalg.eigvals(A)
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
