"""The follower's spring and the camshaft's flywheel, read off the check run.

Spring (secs 4.5.5 and 7.5).  The follower stays on the cam while the contact force, the
output's inertia force m x'' plus the spring's force F0 + k x, stays positive; where the output
decelerates faster than the spring can pull it back, the follower jumps (sec. 7.5, fig. 7.22).
Sec. 4.5.5 sizes the spring by the largest deceleration; the check run gives it as it happens,
the rise and the residual vibration of the dwell alike.  With a margin mu the spring must meet

    F0 + k x(T) >= (1 + mu) (-m x''(T))   at every T of the run,        x = X h_m', x'' = X'' h_m'/t_m^2

so that for a rate k the least preload is F0_min(k) = max_T [(1 + mu)(-m x'') - k x]: a
piecewise-linear, falling curve whose ends are the least preload at k = 0 (a constant force)
and the least rate without preload.  Any spring on or above the curve holds the follower.

The spring's surge.  A helical spring between its seats has its first surge frequency at
f_s = (1/2) (k/m_s)^(1/2) (m_s the active coils' mass).  That mode is a follower of its own,
driven at one end by the lift: the thesis's one-DOF model (3.1) at tau_s = 1/(f_s t_m) gives
the residual vibration U0(tau_s) it is left with after the rise (ch. 3), beside the harmonic
of the camshaft's speed it sits at.

Flywheel (ch. 5).  The energy the cam gives and takes back over the run, the output's kinetic
energy, the follower's elastic energy and the spring's,

    E = m x'^2/2 + c_c (h_m' H - x)^2/2 + F0 x + k x^2/2,

swings by dE = max E - min E; a camshaft of polar inertia J at w_s then varies its speed by
the coefficient C_s = (w_max - w_min)/w_s = dE/(J w_s^2).  The J that keeps it within C_s gives
the flywheel factor Fv = m h_m'^2/(J beta_m^2) (5.14b).  The check run leaves the flywheel
effect out (Fv -> oo); its residual vibration bounds the one with the flywheel from above
(sec. 5.7, CAMSHAFT-2), which is not the way to quieten a follower: "cams are no substitutes
for flywheels".

Every figure comes with its error: the check run's against the run one notch tighter, and the
sampling's, the same figure from the run's dense output at half the spacing.
"""
from __future__ import annotations

import math
import weakref

import numpy as np

from camdyn.runtime.core.errors import CamdynInputError, SimulationError
from camdyn.runtime.measure.contract import answer
from camdyn.runtime.targets.model_target import ModelTarget

SAMPLES = 3000
"""Dense-output samples of the check run per unit of T (then twice as many, for the sampling
error)."""


_SAMPLED: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
"""The series of a run already sampled, per density: the spring and the flywheel read the
same three series of the same check run."""


def _series(result, per_unit: int) -> dict:
    """The run's dimensionless X, X', X'', H on an even grid, its recorded points added."""
    done = _SAMPLED.setdefault(result, {})
    if per_unit not in done:
        span = result.t[-1] - result.t[0]
        T = np.union1d(np.linspace(result.t[0], result.t[-1], int(per_unit * span) + 1), result.t)
        s = result.sample(T)
        done[per_unit] = {"T": T, "X": s["X"], "Xd": s["Xd"], "Xdd": s["Xdd"], "H": s["H"]}
    return done[per_unit]


def _spring_figures(S: dict, *, mass, stroke, t_m, margin, rate) -> dict:
    x = S["X"] * stroke
    need = (1.0 + margin) * (-mass * S["Xdd"] * stroke / t_m**2)   # the spring force needed
    pull = need > 0
    k = 0.0 if rate is None else rate
    i = int(np.argmax(need - k * x))
    preload = max(0.0, float(need[i] - k * x[i]))
    j = int(np.argmax(np.where(pull & (x > 0), need / np.where(x > 0, x, 1.0), -np.inf)))
    rate_min = float(need[j] / x[j]) if pull[j] and x[j] > 0 else 0.0
    contact = mass * S["Xdd"] * stroke / t_m**2 + preload + k * x
    return {"preload_min": preload, "T_binding": float(S["T"][i]),
            "rate_min_without_preload": rate_min, "T_binding_rate": float(S["T"][j]),
            "inertia_force_max": float(np.max(need) / (1.0 + margin)),
            "peak_spring_force": preload + k * float(np.max(x)),
            "contact_force_min": float(np.min(contact))}


def _energy_swing(S: dict, *, mass, stroke, t_m, stiffness, preload, rate) -> float:
    x, v = S["X"] * stroke, S["Xd"] * stroke / t_m
    E = (0.5 * mass * v**2 + 0.5 * stiffness * (S["H"] * stroke - x)**2
         + preload * x + 0.5 * rate * x**2)
    return float(np.max(E) - np.min(E))


def _with_error(fn, a) -> tuple[dict, dict]:
    """fn(series) on the base run at SAMPLES, then at 2 SAMPLES (sampling) and on the tighter
    run (discretisation): the figures and their errors."""
    fine = fn(_series(a.result, 2 * SAMPLES))
    coarse = fn(_series(a.result, SAMPLES))
    tight = fn(_series(a.tight_result, 2 * SAMPLES)) if a.tight_result is not None else None
    err = {}
    for key, v in fine.items():
        if key.startswith("T_"):
            continue
        e = abs(v - coarse[key])
        e += a.factor * abs(v - tight[key]) if tight is not None else 0.0
        err[key] = e
    return fine, err


def check_margin(margin) -> float:
    """The spring's margin mu as a float in [0, 10], else one line naming the option."""
    try:
        mu = float(margin)
    except (TypeError, ValueError):
        raise CamdynInputError(f"argument --spring-margin: must be a number, got {margin!r}") from None
    if not (math.isfinite(mu) and 0.0 <= mu <= 10.0):
        raise CamdynInputError(f"argument --spring-margin: {mu:g} is out of range: 0 <= margin <= 10 "
                               "(the spring's force over the inertia force, less 1)")
    return mu


def spring(a, *, mass, stroke, t_m, margin, rate=None, spring_mass=None, speed_rpm=None,
           law="cycloidal", theta=None, U0_design=None) -> dict:
    """The least spring that holds the follower on the cam along the check run ``a`` (an
    Answer with its tighter run) with the margin; with ``spring_mass`` also its surge."""
    mu = check_margin(margin)
    figs, errs = _with_error(lambda S: _spring_figures(S, mass=mass, stroke=stroke, t_m=t_m,
                                                       margin=mu, rate=rate), a)
    out = {"margin": mu, "rate": rate, **figs, **{f"{k}_error": e for k, e in errs.items()}}
    warnings = []
    if spring_mass is not None:
        if rate is None:
            raise CamdynInputError("argument --spring-mass: the surge frequency needs the spring's "
                                   "rate, --spring-rate N/M")
        f_s = 0.5 * math.sqrt(rate / spring_mass)
        tau_s = 1.0 / (f_s * t_m)
        surge = {"spring_mass": spring_mass, "f_surge": f_s, "tau_surge": tau_s,
                 "harmonic": None if speed_rpm is None else f_s / (speed_rpm / 60.0)}
        if tau_s >= 1.0:
            warnings.append(f"spring surge: its period 1/f_s = {1 / f_s:.4g} s is not shorter than "
                            f"the rise t_m = {t_m:.4g} s (tau_s = {tau_s:.3g}): the coils cannot "
                            "follow the lift. Use a stiffer or lighter spring.")
            surge.update(U0=None, U0_error=None)
        else:
            try:
                s = answer(ModelTarget.of("one_dof", {"tau": tau_s}, method="dp54", rtol=1e-10,
                                          law=law, theta=theta))
                surge.update(U0=s.figures["U0"], U0_error=s.errors.get("U0"))
                warnings += [f"spring surge run: {w}" for w in s.warnings]
            except SimulationError as exc:
                surge.update(U0=None, U0_error=None)
                warnings.append(f"spring surge run failed: {exc}")
            if surge["U0"] is not None and U0_design is not None and surge["U0"] > U0_design:
                warnings.append(f"spring surge: the coils ring after the rise with U0(tau_s = "
                                f"{tau_s:.3g}) = {surge['U0']:.3g}, more than the follower itself "
                                f"({U0_design:.3g}). Use a stiffer or lighter spring.")
        out["surge"] = surge
    out["warnings"] = warnings
    return out


def check_fluctuation(fluctuation) -> float:
    """The coefficient of speed fluctuation C_s as a float in (0, 1), else one line."""
    try:
        cs = float(fluctuation)
    except (TypeError, ValueError):
        raise CamdynInputError(f"argument --speed-fluctuation: must be a number, got "
                               f"{fluctuation!r}") from None
    if not (math.isfinite(cs) and 0.0 < cs < 1.0):
        raise CamdynInputError(f"argument --speed-fluctuation: {cs:g} is out of range: 0 < C_s < 1 "
                               "((w_max - w_min)/w_s)")
    return cs


def flywheel(a, *, mass, stroke, t_m, w_s, beta_m, stiffness, fluctuation, preload=0.0,
             rate=0.0) -> dict:
    """The camshaft inertia that keeps its speed within the coefficient ``fluctuation`` over
    the check run ``a``, and the flywheel factor Fv (5.14b) it gives."""
    cs = check_fluctuation(fluctuation)
    figs, errs = _with_error(lambda S: {"energy_swing": _energy_swing(
        S, mass=mass, stroke=stroke, t_m=t_m, stiffness=stiffness, preload=preload, rate=rate)}, a)
    dE, e_dE = figs["energy_swing"], errs["energy_swing"]
    J = dE / (cs * w_s**2)
    Fv = mass * stroke**2 / (J * beta_m**2) if J > 0 else math.inf
    return {"speed_fluctuation": cs, "energy_swing": dE, "energy_swing_error": e_dE,
            "J": J, "J_error": J * e_dE / dE if dE > 0 else 0.0,
            "Fv": Fv, "Fv_error": Fv * e_dE / dE if dE > 0 else 0.0,
            "with_spring": bool(preload or rate)}
