"""Cam laws as symbolic piecewise functions that know their breakpoints.

A cam law is the dimensionless rise H(T) of thesis App. 2: H(0) = 0, H(1) = 1,
dwell H = 0 before the rise and H = 1 after it, T = t/t_m (A.2.1)-(A.2.3).

Every law is declared the way App. 2 presents it, by its acceleration H''(T)
on each segment of the rise, e.g. the cycloid (A.2.8) or the three segments
OA, AB, BC of the modified sine (A.2.17).  Velocity and displacement follow by
symbolic integration from rest (H(0) = H'(0) = 0) with continuity at the
breakpoints; the amplitude of the acceleration follows from H(1) = 1.  So the
peak accelerations the thesis prints, 2 pi for the cycloid and
pi^2/(2 - 8 theta + 2 pi theta) for the modified sine (A.2.17), are derived,
not typed in, and the tests compare them with the printed forms.

Two families are built rather than typed: :func:`polynomial_law` solves for the
polynomial of least degree that meets given boundary conditions (3-4-5 and 4-5-6-7 are
its members with the derivatives up to H'' or H''' zero at both ends,
:func:`polynomial_2n1`), and :func:`scca_pieces` gives the sine-constant-cosine
acceleration family (Norton's b, c, d), whose one-parameter member with b = 1/4 is the law
``sine-constant-cosine``.  A full cam turn (rise, dwell, return, dwell) is not a law of
this table: the generated library composes it at run time from two of them (law code
:data:`TURN_CODE`).

Segments are numbered for the generated code: 0 is the dwell before the rise
(T < 0), 1..K the pieces of the rise and K + 1 the dwell after it (T >= 1).
Segments are closed on the left, so a breakpoint belongs to the segment that
starts there, which is what forward integration restarting at a breakpoint
needs.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from . import symbolic

T = sp.Symbol("T", real=True)
"""Dimensionless time T = t/t_m (or cam angle B = beta/beta_m, App. 2)."""

theta = sp.Symbol("theta", positive=True)
"""Peak position of the modified sine (A.2.17), fig. A.2.3."""

c_scca = sp.Symbol("c", positive=True)
"""Constant-acceleration fraction c of the sine-constant-cosine law (Norton's b, c, d with
b = 1/4, d = 3/4 - c): see :func:`scca_pieces`."""

tau_d = sp.Symbol("tau_d", positive=True)
"""Design tau of the polydyne law: T_e/t_m (3.3) at the speed the cam is compensated for."""

_A = sp.Symbol("A", real=True)  # unknown acceleration amplitude while building


@dataclass(frozen=True)
class LawParameter:
    """The one shape parameter a law may have, with its admissible open range."""

    symbol: sp.Symbol
    default: float
    low: float
    high: float
    doc: str

    def check(self, value: float, law: str) -> float:
        value = float(value)
        if not (self.low < value < self.high):
            raise ValueError(
                f"{self.symbol.name}={value!r} is outside the range "
                f"{self.low} < {self.symbol.name} < {self.high} of the {law} law"
            )
        return value


@dataclass(frozen=True)
class CamLaw:
    """A rise law: its acceleration pieces and what follows from them."""

    key: str
    """Name used on the command line, e.g. ``modified-sine``."""
    code: int
    """Integer that selects the law in generated code (stable, never reused)."""
    title: str
    reference: str
    bounds: tuple
    """Breakpoints 0 = b0 < b1 < ... < bK = 1 of the rise (may contain theta)."""
    acceleration: tuple
    """H''(T) on each piece, written with the amplitude symbol ``A``; empty when the law is
    declared by its displacement (laws with impulsive acceleration)."""
    parameter: LawParameter | None = None
    displacement: tuple = ()
    """H(T) on each piece, for laws whose acceleration is impulsive (uniform motion)."""
    simplify_pieces: bool = True
    """False: tidy H by collecting on its sines and cosines and factoring their coefficients
    instead of sympy's simplify(), which takes ~30 s on the SCCA's cosine piece."""

    # -- derived symbolically -------------------------------------------------
    @cached_property
    def _derived(self):
        if self.displacement:
            return self.displacement, None
        pieces, v0, h0 = [], sp.Integer(0), sp.Integer(0)
        for k, acc in enumerate(self.acceleration):
            lo, hi = self.bounds[k], self.bounds[k + 1]
            # antiderivatives, not definite integrals: much faster in sympy
            va = sp.integrate(sp.expand(acc), T)
            v = v0 + va - va.subs(T, lo)
            ha = sp.integrate(sp.expand(v), T)
            h = h0 + ha - ha.subs(T, lo)
            pieces.append(h)
            v0, h0 = v.subs(T, hi), h.subs(T, hi)
        amp = sp.solve(sp.Eq(h0, 1), _A)
        if len(amp) != 1:
            raise ValueError(f"{self.key}: H(1) = 1 does not fix the amplitude")
        amp = symbolic.simplify(amp[0])
        tidy = symbolic.simplify if self.simplify_pieces else _collect_trig
        return tuple(tidy(h.subs(_A, amp)) for h in pieces), amp

    @property
    def amplitude(self) -> sp.Expr | None:
        """Acceleration amplitude fixed by H(1) = 1 (e.g. H''max, (A.2.17)); None when the
        acceleration is impulsive."""
        return self._derived[1]

    @property
    def rise(self) -> tuple:
        """H(T) on each piece of the rise."""
        return self._derived[0]

    @property
    def n_segments(self) -> int:
        """Segments including the dwell before (0) and after (K + 1)."""
        return len(self.rise) + 2

    def segment_exprs(self, order: int) -> tuple:
        """d^order H / dT^order on every segment, dwells included.

        The acceleration and the jerk come from the declared acceleration itself, not from
        differentiating the simplified H: simplify() expands factors such as (1 - 2 theta)^2
        of the modified sine, which then cancel against the denominator and lose every digit
        as theta -> 1/2."""
        before = sp.Integer(0)
        after = sp.Integer(1) if order == 0 else sp.Integer(0)
        if order >= 2 and self.acceleration:
            acc = [a.subs(_A, self.amplitude) for a in self.acceleration]
            inner = tuple(sp.diff(a, T, order - 2) for a in acc)
        else:
            inner = tuple(sp.diff(h, T, order) for h in self.rise)
        return (before,) + inner + (after,)

    def piecewise(self, order: int = 0, arg: sp.Expr = T) -> sp.Piecewise:
        """The whole law on the real line as one sympy Piecewise."""
        exprs = self.segment_exprs(order)
        conds = [(exprs[0], arg < 0)]
        for k, e in enumerate(exprs[1:-1]):
            conds.append((e.subs(T, arg), arg < self.bounds[k + 1]))
        conds.append((exprs[-1].subs(T, arg), True))
        return sp.Piecewise(*conds)

    def breakpoints(self, value: float | None = None) -> list[float]:
        """Numerical breakpoints of the rise for a parameter value."""
        subs = self._subs(value)
        return [float(sp.sympify(b).subs(subs)) for b in self.bounds]

    def _subs(self, value):
        if self.parameter is None:
            return {}
        v = self.parameter.default if value is None else self.parameter.check(value, self.key)
        return {self.parameter.symbol: v}

    def numeric(self, order: int = 0, value: float | None = None):
        """A NumPy function T -> d^order H/dT^order (for plots and checks)."""
        import numpy as np

        f = sp.lambdify(T, self.piecewise(order).subs(self._subs(value)), "numpy")
        return lambda t: np.broadcast_to(f(np.asarray(t, dtype=float)), np.shape(t)) * 1.0


def _collect_trig(h: sp.Expr) -> sp.Expr:
    """h as a sum of its sines and cosines times factored coefficients (and a factored rest)."""
    parts = sp.collect(sp.expand(h), sorted(h.atoms(sp.sin, sp.cos), key=sp.default_sort_key),
                       evaluate=False)
    return sp.Add(*(k * symbolic.factor(v) for k, v in parts.items()))


def _law(key, code, title, reference, bounds, acceleration, parameter=None, displacement=()):
    return CamLaw(key, code, title, reference, tuple(sp.sympify(b) for b in bounds),
                  tuple(sp.sympify(a) for a in acceleration), parameter,
                  tuple(sp.sympify(h) for h in displacement))


_pi = sp.pi
_half = sp.Rational(1, 2)


# -- builders of law families -----------------------------------------------------------


def polynomial_rise(at0: dict | None = None, at1: dict | None = None) -> sp.Expr:
    """The polynomial H(T) of least degree with H(0) = 0, H(1) = 1 and the given derivative
    values, ``{order: value}`` at T = 0 and at T = 1 (polynomial by boundary conditions).

    Every condition is one linear equation in the coefficients, so N conditions fix a
    polynomial of degree N - 1; e.g. H', H'' zero at both ends give 10 T^3 - 15 T^4 + 6 T^5."""
    at0, at1 = dict(at0 or {}), dict(at1 or {})
    for side in (at0, at1):
        if any(int(k) != k or k < 1 for k in side):
            raise ValueError(f"boundary conditions are on derivatives of order >= 1, got {sorted(side)}")
    conds = [(0, 0, 0), (1, 0, 1)] + [(0, k, v) for k, v in at0.items()] \
        + [(1, k, v) for k, v in at1.items()]
    coeffs = sp.symbols(f"a0:{len(conds)}")
    H = sum(a * T**i for i, a in enumerate(coeffs))
    eqs = [sp.Eq(sp.diff(H, T, k).subs(T, t), v) for t, k, v in conds]
    sol = sp.solve(eqs, coeffs, dict=True)
    if len(sol) != 1 or len(sol[0]) != len(coeffs):
        raise ValueError("the boundary conditions do not fix one polynomial")
    return sp.expand(H.subs(sol[0]))


def polynomial_law(key: str, code: int, at0: dict | None = None, at1: dict | None = None,
                   title: str | None = None) -> CamLaw:
    """A law whose rise is :func:`polynomial_rise`, declared by its acceleration H''(T).

    The library's laws start from rest (the dwell before the rise), so H'(0) must be 0;
    it is then derived again from H'' like every other law, which checks the solve."""
    at0 = dict(at0 or {})
    if at0.get(1, 0) != 0:
        raise ValueError("a rise starts from the dwell: H'(0) must be 0")
    at0.setdefault(1, 0)
    H = polynomial_rise(at0, at1)
    if sp.diff(H, T, 2) == 0:
        raise ValueError("the boundary conditions give no acceleration (H linear)")
    terms = " ".join(f"{'+' if c > 0 else '-'} {abs(c)} T^{m[0]}"
                     for (m, c) in sorted(sp.Poly(H, T).terms(), key=lambda mc: mc[0]))
    # written as A times H'' over its peak, so that the amplitude fixed by H(1) = 1 is
    # H''max like that of the other laws (10/sqrt 3 for 3-4-5)
    acc = sp.diff(H, T, 2)
    stat = sp.solveset(sp.diff(acc, T), T, sp.Interval(0, 1))
    if isinstance(stat, sp.FiniteSet):
        acc = acc / max((symbolic.simplify(acc.subs(T, x)) for x in stat | {0, 1}), key=float)
    return _law(key, code, title or f"{key} polynomial", f"H = {terms.lstrip('+ ')}", (0, 1),
                [_A * acc])


def polynomial_2n1(n: int) -> sp.Expr:
    """The (2n+1)-degree member: H', ..., H^(n) zero at both ends (3-4-5 for n = 2,
    4-5-6-7 for n = 3).  H' is proportional to T^n (1 - T)^n."""
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ValueError(f"n={n!r}: the 2n+1 family needs a whole n >= 1 (n = 1: 3-2, the cubic)")
    zero = {k: 0 for k in range(1, n + 1)}
    return polynomial_rise(zero, zero)


def scca_pieces(b, c, d):
    """Breakpoints and acceleration pieces of the sine-constant-cosine acceleration (SCCA)
    family, Norton, *Cam Design and Manufacturing Handbook*, sec. 3 (b + c + d = 1):

    =================  ==================================  =========================
    0 .. b/2           A sin(pi T/b)                       sine ramp up
    b/2 .. (1-d)/2     A                                   constant
    (1-d)/2 .. (1+d)/2 A cos(pi (T - (1-d)/2)/d)           cosine from +A to -A
    (1+d)/2 .. 1-b/2   -A                                  constant
    1-b/2 .. 1         -A cos(pi (T - 1 + b/2)/b)          cosine ramp back to 0
    =================  ==================================  =========================

    Pieces of zero length (b, c or d = 0) are left out.  Members: b = d = 1/2 the cycloid,
    d = 1 simple harmonic, c = 1 constant acceleration, (1/4, 1/2, 1/4) the modified
    trapezoid, (1/4, 0, 3/4) the modified sine (thesis (A.2.17) with theta = 1/8)."""
    b, c, d = (sp.sympify(x) for x in (b, c, d))
    if symbolic.simplify(b + c + d - 1) != 0:
        raise ValueError(f"SCCA needs b + c + d = 1, got {b + c + d}")
    ends = [0, b / 2, (1 - d) / 2, (1 + d) / 2, 1 - b / 2, 1]
    accs = [_A * sp.sin(_pi * T / b) if b != 0 else None,
            _A,
            _A * sp.cos(_pi * (T - (1 - d) / 2) / d) if d != 0 else None,
            -_A,
            -_A * sp.cos(_pi * (T - 1 + b / 2) / b) if b != 0 else None]
    width = [b / 2, c / 2, d, c / 2, b / 2]
    bounds, pieces = [sp.Integer(0)], []
    for k in range(5):
        if width[k] != 0:
            bounds.append(sp.sympify(ends[k + 1]))
            pieces.append(accs[k])
    return tuple(bounds), tuple(pieces)


LAWS: dict[str, CamLaw] = {}
for _l in (
    _law("cycloidal", 0, "Cycloidal", "(A.2.8)-(A.2.11)", (0, 1),
         [_A * sp.sin(2 * _pi * T)]),
    _law("modified-sine", 1, "Modified sine", "(A.2.17)-(A.2.20)",
         (0, theta, 1 - theta, 1),
         [_A * sp.sin(_pi * T / (2 * theta)),                    # OA
          _A * sp.cos(_pi * (T - theta) / (1 - 2 * theta)),     # AB
          -_A * sp.sin(_pi * (2 * theta - 1 + T) / (2 * theta))],  # BC
         LawParameter(theta, 0.1, 0.0, 0.5,
                      "fraction of the rise to the acceleration peak (thesis fig. A.2.3: 0.1)")),
    polynomial_law("3-4-5", 2, {2: 0}, {1: 0, 2: 0}, "3-4-5 polynomial"),
    _law("simple-harmonic", 3, "Simple harmonic", "H = (1 - cos pi T)/2", (0, 1),
         [_A * sp.cos(_pi * T)]),
    _law("parabolic", 4, "Parabolic (constant acceleration)", "H'' = +-4", (0, _half, 1),
         [_A, -_A]),
    polynomial_law("4-5-6-7", 5, {2: 0, 3: 0}, {1: 0, 2: 0, 3: 0}, "4-5-6-7 polynomial"),
    # the degree-9 member (derivatives 1 to 4 zero at both ends): the polydyne's output
    # motion, and the cam it is compensated against
    polynomial_law("5-6-7-8-9", 10, {2: 0, 3: 0, 4: 0}, {1: 0, 2: 0, 3: 0, 4: 0},
                   "5-6-7-8-9 polynomial"),
    _law("modified-trapezoid", 6, "Modified trapezoid", "jerk-limited, eighths of the rise",
         (0, sp.Rational(1, 8), sp.Rational(3, 8), sp.Rational(5, 8), sp.Rational(7, 8), 1),
         [_A * sp.sin(4 * _pi * T), _A, _A * sp.cos(4 * _pi * (T - sp.Rational(3, 8))), -_A,
          -_A * sp.cos(4 * _pi * (T - sp.Rational(7, 8)))]),
    # uniform motion: H' jumps from 0 to 1 at T = 0, the ramp input of the impact model (3.8)
    _law("uniform", 7, "Uniform motion (constant velocity)", "H = T; ramp input (3.8)", (0, 1),
         [], displacement=[T]),
    # SCCA with Norton's b = 1/4 fixed: c -> 0 is the modified sine (theta = 1/8), c = 1/2 the
    # modified trapezoid, c -> 3/4 the jerk-unbounded trapezoid; c trades peak acceleration
    # (lower with more constant part) against peak velocity
    CamLaw("sine-constant-cosine", 8, "Sine-constant-cosine acceleration (SCCA, b = 1/4)",
           "Norton SCCA, b = 1/4, d = 3/4 - c", *scca_pieces(sp.Rational(1, 4), c_scca,
                                                           sp.Rational(3, 4) - c_scca),
           LawParameter(c_scca, 0.25, 0.0, 0.75,
                        "fraction of the rise at constant acceleration, b = 1/4, d = 3/4 - c"),
           simplify_pieces=False),
    # the compensated cam (polydyne) of the one-DOF follower (3.1): the rise that makes the
    # output X follow the degree-9 polynomial P (its derivatives 1 to 4 zero at both ends)
    # exactly at the design tau: X'' = (2 pi/tau)^2 (H - X) inverted, H = P + (tau_d/2 pi)^2 P''.
    # P's fourth derivative zero at the ends keeps the cam's acceleration
    # H'' = P'' + (tau_d/2 pi)^2 P^(4) continuous into the dwells.  Declared by H'' with
    # H(0) = H'(0) = 0, the amplitude comes out 1.
    CamLaw("polydyne", 9, "Polydyne (one-DOF compensated degree-9 rise)",
           "H = P9 + (tau_d/2 pi)^2 P9'', P9 with P' to P^(4) zero at both ends",
           (sp.Integer(0), sp.Integer(1)),
           (_A * (sp.diff(polynomial_2n1(4), T, 2)
                  + (tau_d / (2 * _pi))**2 * sp.diff(polynomial_2n1(4), T, 4)),),
           LawParameter(tau_d, 0.15, 0.0, 1.0,
                        "design tau T_e/t_m (3.3) at which the one-DOF output follows the "
                        "degree-9 rise exactly")),
):
    LAWS[_l.key] = _l

LAW_BY_CODE = {law.code: law for law in LAWS.values()}

TURN_CODE = 1000
"""Law code of the dwell-rise-dwell-return composition over a full cam turn, which the
generated library evaluates from a rise law and a return law of this table (its par is the
index of the turn's description, written at run time: camdyn.runtime.core.laws.compose)."""
TURN_SLOTS = 256
"""Different turns one process can hold at once."""
assert TURN_CODE not in LAW_BY_CODE

SHAPED_CODE = 1001
"""Law code of a rise shaped by the user: a piecewise polynomial H(T) on [0, 1] (blend
segments, a B-spline, a spline through a table), built at run time
(camdyn.runtime.core.shaped); its par is the index of its description in the library."""
SHAPED_SLOTS = 64
"""Different shaped rises one process can hold at once."""
SHAPED_POOL = 1 << 18
"""Doubles for all their breakpoints and coefficients (2 MB)."""
assert SHAPED_CODE not in LAW_BY_CODE


def get(key: str) -> CamLaw:
    """The law named ``key``; a clear error listing the known names otherwise."""
    try:
        return LAWS[key]
    except KeyError:
        raise ValueError(f"unknown cam law {key!r}; choose one of {', '.join(LAWS)}") from None
