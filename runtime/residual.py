"""Residual-vibration figures of a run (thesis sec. 3.3, fig. 4.11).

U0     amplitude of the positional error u = X - H after the rise (3.5)
U0dd   amplitude of the residual acceleration after the rise (3.6)
Xdd_min_rise, T_at_Xdd_min
       the most negative acceleration during the rise and its instant (fig. 4.11b)

Extremes are found on the dense output: a fine scan of every step, then the
best sample is refined by bounded Brent minimization of the interpolant, so
the figures do not depend on where the integrator happened to step.  The work is
done in compiled code (runtime/_figures.pyx, 3-20x faster); the same recipe in
Python and SciPy is kept as :func:`extreme_reference` and :func:`residual_reference`,
which tests/test_figures_compiled.py compares it with.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np
from scipy.optimize import minimize_scalar

from . import _figures
from .errors import CamdynInputError
from .result import Result


@dataclass(frozen=True)
class ResidualVibration:
    U0: float
    U0dd: float
    Xdd_min_rise: float
    T_at_Xdd_min: float

    def as_dict(self) -> dict:
        return asdict(self)


def scan_grid(t_rec: np.ndarray, a: float, b: float, per_step: int) -> np.ndarray:
    """``per_step`` evenly spaced times in every recorded step inside [a, b], and b: where the
    dense output is sampled before an extreme is refined."""
    knots = np.unique(np.concatenate([[a, b], t_rec[(t_rec > a) & (t_rec < b)]]))
    s = np.linspace(0.0, 1.0, per_step, endpoint=False)
    grid = (knots[:-1, None] + np.diff(knots)[:, None] * s[None, :]).ravel()
    return np.append(grid, b)


def _index(result: Result, name: str) -> int:
    """Index of a state, or of an output after the states, as runtime/_figures.pyx takes it."""
    if name in result.state_names:
        return result.state_names.index(name)
    if name in result.output_names:
        return len(result.state_names) + result.output_names.index(name)
    raise KeyError(f"{name!r} is neither a state nor an output of {result.model.name}; "
                   f"known: {', '.join(result.names)}")


def _record(result: Result) -> tuple:
    """The arguments runtime/_figures.pyx reads a run's record from."""
    return (result.model.capsule, result.p, result.law_codes, result.law_pars, result._rows,
            result.mode, len(result.state_names), bool(result._extra.shape[0]))


def extreme(result: Result, name: str, a: float, b: float, *, absolute: bool, minimum: bool,
            per_step: int = 12, candidates: int = 1) -> tuple[float, float]:
    """Refined extreme of state or output ``name`` on [a, b]: (value, time), in compiled code.

    ``per_step`` samples in every recorded step, then the best sample (``candidates`` = 1,
    as :func:`extreme_reference`) or the best ``candidates`` peaks are refined by Brent's
    bounded minimizer on the dense output.  A run of another integrator that only offers
    ``sample`` (runtime/peers.py) goes through :func:`extreme_reference`."""
    if not isinstance(result, Result):
        return extreme_reference(result, name, a, b, absolute=absolute, minimum=minimum,
                                 per_step=per_step)
    if not (result.t[0] <= a <= b <= result.t[-1]):
        raise CamdynInputError(f"extreme of {name} on [{a:g}, {b:g}]: the span must lie in the "
                               f"run [{result.t[0]:g}, {result.t[-1]:g}]")
    if per_step < 1 or not 1 <= candidates <= 16:
        raise CamdynInputError(f"per_step={per_step} must be >= 1 and candidates={candidates} "
                               "in 1..16")
    value, at = _figures.extreme(*_record(result), _index(result, name), float(a), float(b),
                                 absolute, minimum, per_step, candidates)
    return float(value), float(at)


def extreme_reference(result: Result, name: str, a: float, b: float, *, absolute: bool,
                      minimum: bool, per_step: int = 12) -> tuple[float, float]:
    """Refined extreme of output ``name`` on [a, b]: (value, time), in Python and SciPy (the
    reference the compiled :func:`extreme` is tested against)."""
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
        opt = minimize_scalar(f, bounds=(lo, hi), method="bounded",
                              options={"xatol": 1e-12 * max(1.0, abs(hi))})
        val = opt.fun if minimum else -opt.fun
        if (val < best) if minimum else (val > best):
            best_t, best = float(opt.x), float(val)
    return float(best), float(best_t)


def crossing_time(result: Result, name: str, level: float) -> float:
    """First time the state or output ``name`` reaches ``level`` (dense output, Brent)."""
    from scipy.optimize import brentq

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
    return float(brentq(lambda t: result.sample([t])[name][0] - level, a, b, xtol=1e-14))


def rise_end(result: Result, spec: dict) -> float:
    """End of the rise: spec's rise_end, or the time its rise_state reaches it (compiled)."""
    if not spec.get("rise_state"):
        return spec["rise_end"]
    name = spec["rise_state"]
    if not isinstance(result, Result) or name not in result.state_names:
        return crossing_time(result, name, spec["rise_end"])
    t = _figures.crossing(*_record(result), result.state_names.index(name),
                          float(spec["rise_end"]))
    if t != t:
        raise CamdynInputError(f"{name} never reaches {spec['rise_end']:g} in this run; run longer")
    return float(t)


def residual(result: Result) -> ResidualVibration:
    """U0, U0dd, Xdd_min_rise, T_at_Xdd_min of a run that covers the rise and a dwell."""
    return _residual(result, extreme, rise_end)


def residual_reference(result: Result) -> ResidualVibration:
    """:func:`residual` through the Python and SciPy reference of the extremes."""
    def end(res, spec):
        if spec.get("rise_state"):
            return crossing_time(res, spec["rise_state"], spec["rise_end"])
        return spec["rise_end"]

    return _residual(result, extreme_reference, end)


def _residual(result: Result, extreme, rise_end) -> ResidualVibration:
    spec = result.model.manifest.get("residual")
    if not spec:
        raise CamdynInputError(f"model {result.model.name} declares no residual-vibration outputs")
    t0, t_end = result.t[0], result.t[-1]
    t1 = rise_end(result, spec)
    if not (t0 <= 0.0 and t_end > t1):
        raise CamdynInputError(
            f"the run must cover the rise [0, {t1:g}] and part of the dwell after it "
            f"(it covers [{t0:g}, {t_end:g}])")
    U0, _ = extreme(result, spec["error"], t1, t_end, absolute=True, minimum=False)
    U0dd, _ = extreme(result, spec["acceleration"], t1, t_end, absolute=True, minimum=False)
    xmin, tmin = extreme(result, spec["acceleration"], max(t0, 0.0), t1, absolute=False, minimum=True)
    return ResidualVibration(U0=U0, U0dd=U0dd, Xdd_min_rise=xmin, T_at_Xdd_min=tmin)
