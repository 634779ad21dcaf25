"""Nominal characteristics of the cam laws, derived symbolically (thesis App. 2).

For every law of :mod:`camdyn.derive.camlaws`:

* peak velocity H'max, peak acceleration H''max and most negative H''min
  (A.2.1)-(A.2.3);
* jerk H''' at T = 0 (right limit), 1/2 and 1 (left limit), (A.2.16),
  (A.2.21)-(A.2.22); None where the acceleration itself jumps (the jerk is an
  impulse there);
* peak torque factor max(H' H'') and its instant: the driving torque of the
  nominal motion is M = m h_m'^2/(w_s t_m^3) H' H'' (A.2.5)-(A.2.7), so
  max(H' H'') is its dimensionless peak (the cycloid: (3 sqrt 3/2) pi at
  T = 1/3, (A.2.12)-(A.2.14));
* the residual-vibration envelope of the one-DOF model (ch. 3): for tau << 1
  the residual amplitude is governed by the lowest derivative of H that jumps
  (order p, counting the dwells): U0 <= C tau^p with C = sum|jumps|/(2 pi)^p.
  Reason: u = X - H obeys u'' + w^2 u = -H'', and integrating the free
  vibration left after the rise by parts p - 1 times leaves the jumps of
  H^(p) divided by w^p, largest when their phases add.  For the cycloid the
  jerk jumps by 4 pi^2 at both ends, C = 8 pi^2/(2 pi)^3 = 1/pi: the envelope
  tau^3/pi of (3.5).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from functools import lru_cache

import sympy as sp

from camdyn.derive.camlaws import LAWS, T, CamLaw

HALF = sp.Rational(1, 2)


@dataclass(frozen=True)
class LawProperties:
    key: str
    H1_max: float                 # peak velocity H'max
    H2_max: float                 # peak acceleration
    H2_min: float                 # most negative acceleration
    jerk_0: float | None          # H''' at T = 0+
    jerk_half: float | None       # H''' at T = 1/2 (None: H'' jumps there)
    jerk_1: float | None          # H''' at T = 1-
    torque_max: float | None      # max of H' H'' (None: impulsive)
    T_torque_max: float | None
    residual_order: int           # p: lowest derivative of H that jumps
    residual_coeff: float         # C in U0 <= C tau^p

    def as_dict(self) -> dict:
        """The fields for JSON: an infinite peak (the uniform law's H'' impulses) is None, as
        the impulsive jerks are, since JSON has no infinity."""
        return {k: (None if isinstance(v, float) and not math.isfinite(v) else v)
                for k, v in asdict(self).items()}


def _pieces(law: CamLaw, theta):
    sub = {law.parameter.symbol: theta} if law.parameter else {}
    bounds = [sp.nsimplify(sp.sympify(b).subs(sub)) for b in law.bounds]
    exprs = [sp.sympify(h).subs(sub) for h in law.rise]
    return bounds, exprs


def _real_roots(poly: sp.Poly, lo, hi) -> list:
    """The real roots of ``poly`` in [lo, hi] to 30 digits, found on its square-free factors
    (the rest of a dwell makes multiple roots at the ends, where the root finder converges
    slowly)."""
    out = []
    for factor, _ in sp.sqf_list(poly)[1]:
        if factor.degree() >= 1:
            out += [sp.re(r) for r in factor.nroots(n=30, maxsteps=500)
                    if abs(sp.im(r)) < 1e-25 and lo <= sp.re(r) <= hi]
    return out


def _extreme(exprs, bounds, order: int, sign: int):
    """Largest value of sign * d^order H over the rise, and where (exact candidates)."""
    best, where = None, None
    for k, h in enumerate(exprs):
        lo, hi = bounds[k], bounds[k + 1]
        f = sp.diff(h, T, order)
        cands = [lo, hi]
        df = sp.diff(f, T)
        poly = sp.Poly(df, T) if df.is_polynomial(T) and df.free_symbols <= {T} else None
        if poly is not None and poly.degree() > 4:
            # beyond quartics solveset answers in CRootOf, which took a minute for the
            # polydyne's degree-8 jerk; its real roots to 30 digits serve as well
            cands += _real_roots(poly, lo, hi)
        else:
            sol = sp.solveset(df, T, sp.Interval(lo, hi))
            if isinstance(sol, sp.FiniteSet):
                cands += list(sol)
            else:  # fall back to a fine scan refined by nsolve when solveset cannot say
                fn = sp.lambdify(T, df)
                import numpy as np
                grid = np.linspace(float(lo), float(hi), 2001)
                vals = fn(grid) * np.ones_like(grid)
                for i in np.flatnonzero(np.sign(vals[:-1]) != np.sign(vals[1:])):
                    cands.append(sp.Float(sp.nsolve(df, T, (grid[i] + grid[i + 1]) / 2)))
        for c in cands:
            v = sign * f.subs(T, c)
            if best is None or float(v) > float(best):
                best, where = v, c
    return sign * best, where


def _value(exprs, bounds, order: int, t, side: int):
    """d^order H at t, from the left (side = -1) or the right (+1); dwells outside [0, 1]."""
    if (t <= 0 and side < 0) or (t >= 1 and side > 0):
        return sp.Integer(1 if (order == 0 and t >= 1) else 0)
    for k, h in enumerate(exprs):
        lo, hi = bounds[k], bounds[k + 1]
        if (lo < t < hi) or (side > 0 and t == lo) or (side < 0 and t == hi):
            return sp.diff(h, T, order).subs(T, t)
    raise ValueError(t)


def _jumps(exprs, bounds, order: int):
    return [sp.simplify(_value(exprs, bounds, order, b, +1) - _value(exprs, bounds, order, b, -1))
            for b in bounds]


@lru_cache(maxsize=None)
def properties(key: str, theta: float | None = None) -> LawProperties:
    """The App. 2 characteristics of one law (theta: the modified sine's parameter)."""
    law = LAWS[key]
    th = None
    if law.parameter is not None:
        th = sp.nsimplify(law.parameter.default if theta is None else law.parameter.check(theta, key))
    elif theta is not None:
        raise ValueError(f"the {key} law has no shape parameter")
    bounds, exprs = _pieces(law, th)
    v_max, _ = _extreme(exprs, bounds, 1, +1)
    if law.amplitude is None:   # impulsive acceleration
        a_max, a_min = float("inf"), float("-inf")
    else:
        a_max = float(_extreme(exprs, bounds, 2, +1)[0])
        a_min = float(_extreme(exprs, bounds, 2, -1)[0])

    def jerk(t, side):
        # where the acceleration itself jumps (dwell to rise included) the jerk is an impulse
        jump = _value(exprs, bounds, 2, t, +1) - _value(exprs, bounds, 2, t, -1)
        if law.amplitude is None or (t in bounds and sp.simplify(jump) != 0):
            return None
        return float(_value(exprs, bounds, 3, t, side))

    torque = [sp.diff(h, T) * sp.diff(h, T, 2) for h in exprs]
    if law.amplitude is None:   # H'' and so the torque are impulses at the ends
        t_max, T_t = None, None
    else:
        tq, where = None, None
        for k, f in enumerate(torque):
            # H' H'' is smooth inside a piece; search its stationary points numerically
            import numpy as np
            fn = sp.lambdify(T, f)
            grid = np.linspace(float(bounds[k]), float(bounds[k + 1]), 4001)
            vals = fn(grid) * np.ones_like(grid)
            i = int(np.argmax(vals))
            t0 = grid[i]
            if 0 < i < len(grid) - 1:
                t0 = float(sp.nsolve(sp.diff(f, T), T, t0))
            v = float(f.subs(T, t0))
            if tq is None or v > tq:
                tq, where = v, t0
        t_max, T_t = tq, where
    for p in (1, 2, 3, 4):
        jumps = _jumps(exprs, bounds, p)
        if any(j != 0 for j in jumps):
            break
    coeff = float(sum(abs(j) for j in jumps) / (2 * sp.pi) ** p)
    return LawProperties(key, float(v_max), a_max, a_min, jerk(sp.Integer(0), +1),
                         jerk(HALF, +1), jerk(sp.Integer(1), -1), t_max and float(t_max),
                         T_t and float(T_t), p, coeff)


def table() -> list[LawProperties]:
    """Characteristics of every law (modified sine at its default theta)."""
    return [properties(key) for key in LAWS]
