"""Residual-vibration figures of a run (thesis sec. 3.3, fig. 4.11).

U0     amplitude of the positional error u = X - H after the rise (3.5)
U0dd   amplitude of the residual acceleration after the rise (3.6)
Xdd_min_rise, T_at_Xdd_min
       the most negative acceleration during the rise and its instant (fig. 4.11b)

Extremes are found on the dense output: a fine scan of every step, then the
best sample is refined by bounded Brent minimization of the interpolant, so
the figures do not depend on where the integrator happened to step.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np
from scipy.optimize import minimize_scalar

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


def extreme(result: Result, name: str, a: float, b: float, *, absolute: bool, minimum: bool,
            per_step: int = 12) -> tuple[float, float]:
    """Refined extreme of output ``name`` on [a, b]: (value, time)."""
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


def residual(result: Result) -> ResidualVibration:
    """U0, U0dd, Xdd_min_rise, T_at_Xdd_min of a run that covers the rise and a dwell."""
    spec = result.model.manifest.get("residual")
    if not spec:
        raise CamdynInputError(f"model {result.model.name} declares no residual-vibration outputs")
    t0, t1, t_end = result.t[0], spec["rise_end"], result.t[-1]
    if spec.get("rise_state"):
        t1 = crossing_time(result, spec["rise_state"], spec["rise_end"])
    if not (t0 <= 0.0 and t_end > t1):
        raise CamdynInputError(
            f"the run must cover the rise [0, {t1:g}] and part of the dwell after it "
            f"(it covers [{t0:g}, {t_end:g}])")
    U0, _ = extreme(result, spec["error"], t1, t_end, absolute=True, minimum=False)
    U0dd, _ = extreme(result, spec["acceleration"], t1, t_end, absolute=True, minimum=False)
    xmin, tmin = extreme(result, spec["acceleration"], max(t0, 0.0), t1, absolute=False, minimum=True)
    return ResidualVibration(U0=U0, U0dd=U0dd, Xdd_min_rise=xmin, T_at_Xdd_min=tmin)
