"""Extremes of a state or output of a finished run, found on its dense output.

A scan samples the dense output in every recorded step; the best peaks are refined by Brent's
bounded minimizer on the interpolant, so a figure does not depend on where the integrator
happened to step; a peak the scan left that could still be higher is refined too, and what
is left is the extreme's sampling error (runtime/engine/finder.pyx).  The same recipe in
Python and SciPy, without the sampling check, is :func:`extreme_reference`, which
tests/test_figures_compiled.py compares the compiled one with.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.errors import CamdynInputError
from ..core.result import Result
from ..engine import finder


@dataclass(frozen=True)
class Extreme:
    """An extreme: its value, where it is, and the error the scan that found it leaves.

    It unpacks and indexes as (value, at), the pair most callers want."""

    value: float
    at: float
    sampling_error: float = 0.0

    def __iter__(self):
        return iter((self.value, self.at))

    def __getitem__(self, k):
        return (self.value, self.at)[k]


SQRT_EPS = 1.4901161193847656e-08


def place_error(at: float) -> float:
    """How well the refinement places an extreme at time ``at`` (the run's time): Brent stops
    within twice its tolerance, sqrt(eps)|t| + xatol/3 (runtime/engine/finder.pyx,
    _brent_min, xatol 1e-12 max(1, |t|)), of the best point it saw, and on a flat top the
    rounding of the values moves the best point as far again (a top where g changes by
    eps |g| over sqrt(eps)|t|): 4 times the tolerance.  A place found one notch tighter lands
    within this of the first, so |T - T'| alone left it out (measured 0.1 to 346 times the
    true error of T_at_Xdd_min at rtol 1e-9)."""
    return 4.0 * (SQRT_EPS * abs(at) + 1e-12 * max(1.0, abs(at)) / 3.0)


def scan_grid(t_rec: np.ndarray, a: float, b: float, per_step: int) -> np.ndarray:
    """``per_step`` evenly spaced times in every recorded step inside [a, b], and b: where the
    dense output is sampled before an extreme is refined."""
    knots = np.unique(np.concatenate([[a, b], t_rec[(t_rec > a) & (t_rec < b)]]))
    s = np.linspace(0.0, 1.0, per_step, endpoint=False)
    grid = (knots[:-1, None] + np.diff(knots)[:, None] * s[None, :]).ravel()
    return np.append(grid, b)


def column(result, name: str) -> int:
    """Index of a state, or of an output after the states, as the compiled finder takes it
    (of a Result's model, or of a model)."""
    if name in result.state_names:
        return result.state_names.index(name)
    if name in result.output_names:
        return len(result.state_names) + result.output_names.index(name)
    model = getattr(result, "model", result)       # a Result, or the model itself
    raise KeyError(f"{name!r} is neither a state nor an output of {model.name}; known: "
                   f"{', '.join([*result.state_names, *result.output_names])}")


def record(result: Result) -> tuple:
    """The arguments the compiled finder reads a run's record from: a DOP853 run's rows as
    they are, the finder making the dense output the run left out where it needs it."""
    rows = result._rows if result._fills else result.record
    return (result.model.capsule, result.p, result.law_codes, result.law_pars, rows,
            result.mode, len(result.state_names), result.n_extra)


def extreme(result, name: str, a: float, b: float, *, absolute: bool, minimum: bool,
            per_step: int = 12, candidates: int = 1, hermite_tol: float = 0.0) -> Extreme:
    """Refined extreme of state or output ``name`` on [a, b], in compiled code.

    ``per_step`` samples in every recorded step, then the best sample (``candidates`` = 1,
    as :func:`extreme_reference`) or the best ``candidates`` peaks are refined by Brent's
    bounded minimizer on the dense output, then the sampling check (module doc); where a
    DOP853 run left its dense output out, the scan reads the cubic Hermite interpolant
    there while that is off by at most ``hermite_tol`` at the peaks (0: 1e-9 of the
    extreme), and else makes it (runtime/engine/finder.pyx, _extreme).  A run of
    another integrator that only offers ``sample`` (SciPy's, runtime/studies/peers.py) goes
    through :func:`extreme_reference`."""
    if not isinstance(result, Result):
        return extreme_reference(result, name, a, b, absolute=absolute, minimum=minimum,
                                 per_step=per_step)
    if not (result.t[0] <= a <= b <= result.t[-1]):
        raise CamdynInputError(f"extreme of {name} on [{a:g}, {b:g}]: the span must lie in the "
                               f"run [{result.t[0]:g}, {result.t[-1]:g}]")
    if per_step < 1 or not 1 <= candidates <= 16:
        raise CamdynInputError(f"per_step={per_step} must be >= 1 and candidates={candidates} "
                               "in 1..16")
    value, at, sampling, calls = finder.extreme(*record(result), column(result, name), float(a),
                                                  float(b), absolute, minimum, per_step,
                                                  candidates, part=result.part,
                                                  hermite_tol=float(hermite_tol))
    result.count_dense_calls(calls)
    return Extreme(float(value), float(at), float(sampling))


def dwell_closed_form(result, spec: dict, t1: float) -> tuple | None:
    """(U0, U0'') as two :class:`Extreme` s, in closed form from the state at the end of the
    rise t1, for a camdyn run whose dwell [t1, end] was stepped over exactly (linear and time
    invariant there, runtime/engine/finder.pyx: _dwell_closed_form) and whose model has two
    states; None otherwise (the scan then finds them).  Where the extreme lies is not kept:
    U0 and U0'' are amplitudes."""
    if not isinstance(result, Result) or not result.exact_segments:
        return None
    t_end = float(result.t[-1])
    got = finder.dwell_figures(*record(result), float(t1), t_end,
                               column(result, spec["error"]), column(result, spec["acceleration"]),
                               part=result.part)
    if got is None:
        return None
    return Extreme(float(got[0]), float("nan")), Extreme(float(got[1]), float("nan"))


def extreme_reference(result, name: str, a: float, b: float, *, absolute: bool,
                      minimum: bool, per_step: int = 12) -> Extreme:
    """Refined extreme of ``name`` on [a, b] in Python and SciPy: the best sample refined (the
    reference the compiled :func:`extreme` is tested against; no sampling check, so its
    sampling error is unknown and given as NaN)."""
    grid = scan_grid(result.t, a, b, per_step)
    vals = result.sample(grid)[name]
    score = np.abs(vals) if absolute else vals
    k = int(np.argmin(score) if minimum else np.argmax(score))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]

    def f(t):
        v = result.sample([t])[name][0]
        v = abs(v) if absolute else v
        return v if minimum else -v

    best_t, best = grid[k], score[k]
    if hi > lo:
        from scipy.optimize import minimize_scalar

        opt = minimize_scalar(f, bounds=(lo, hi), method="bounded",
                              options={"xatol": 1e-12 * max(1.0, abs(hi))})
        val = opt.fun if minimum else -opt.fun
        if (val < best) if minimum else (val > best):
            best_t, best = float(opt.x), float(val)
    return Extreme(float(best), float(best_t), float("nan"))


def crossing_time(result, name: str, level: float) -> float:
    """First time the state or output ``name`` reaches ``level`` (dense output, Brent)."""
    v = result[name] - level
    hit = np.flatnonzero(v >= 0)
    if not hit.size:
        raise CamdynInputError(f"{name} never reaches {level:g} in this run; run longer")
    k = int(hit[0])
    if k == 0:
        return float(result.t[0])
    a, b = result.t[k - 1], result.t[k]
    if a == b:
        return float(a)
    from scipy.optimize import brentq

    return float(brentq(lambda t: result.sample([t])[name][0] - level, a, b, xtol=1e-14))


def first_crossing(result, name: str, level: float) -> float:
    """First time the state or output ``name`` reaches ``level``: compiled for a camdyn run
    (the crossing a grid's compiled chunk finds, runtime/engine/finder.pyx, so that a chunk's
    rise ends where a single run's does, bit for bit), through :func:`crossing_time` for
    another integrator's."""
    if not isinstance(result, Result):
        return crossing_time(result, name, level)
    t = finder.crossing(*record(result), column(result, name), float(level), part=result.part)
    if t != t:
        raise CamdynInputError(f"{name} never reaches {level:g} in this run; run longer")
    return float(t)
