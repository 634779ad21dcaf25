"""The beam follower's grooved cam at run time: RDFD motion, pitch curve and the undercut test
(paper (1), (3), (4)), in NumPy on the compiled cam-law library (no SymPy).

The symbolic geometry, the groove walls as envelopes of the roller circles and their
curvatures, is :mod:`camdyn.derive.beam.geometry`; tests/test_beam_geometry.py holds the two
equal.  Conventions are that module's: theta is the polar angle of the pitch-curve point in
the cam frame; the pitch radius is r = r_b + r_r + S(theta); RDFD is a rise
S_T H(theta/beta_rise) on [0, beta_rise], an outer dwell S_T, a fall S_T (1 - H) over
beta_fall and an inner dwell 0 to 2 pi; curvature is signed for increasing theta, positive
where the pitch curve is convex.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..core.laws import LawChoice, choose

TWO_PI = 2 * math.pi


JUMP_RTOL = 1e-6
"""A derivative of the motion jumps at a segment end when its two one-sided limits differ by
more than this times its largest value over the turn (:meth:`RDFD.jumps`)."""


class UndercutError(ValueError):
    """A cam design whose groove wall is undercut (see :func:`undercut`)."""


@dataclass(frozen=True)
class RDFD:
    """A rise-dwell-fall-dwell cam (paper (1), fig. 2) with its roller, SI units."""

    S_T: float
    r_b: float
    r_r: float
    law: LawChoice
    beta_rise: float = math.pi / 2
    dwell_outer: float = math.pi / 2
    beta_fall: float = math.pi / 2
    fall_law: LawChoice | None = None
    """The return's law (S = S_T (1 - H(u)) over the return); None: the rise's law."""

    @property
    def return_law(self) -> LawChoice:
        return self.law if self.fall_law is None else self.fall_law

    @classmethod
    def of(cls, S_T: float, r_b: float, r_r: float, law: str = "cycloidal",
           theta: float | None = None, **angles) -> "RDFD":
        return cls(S_T, r_b, r_r, choose(law, theta), **angles)

    @property
    def fall_start(self) -> float:
        return self.beta_rise + self.dwell_outer

    @cached_property
    def breakpoints(self) -> np.ndarray:
        """Segment ends in rad, the law's own breakpoints inside the rise and the fall included."""
        inside = [b for b in self.law.breakpoints() if 0.0 < b < 1.0]
        inside_fall = [b for b in self.return_law.breakpoints() if 0.0 < b < 1.0]
        ends = {0.0, self.beta_rise, self.fall_start, self.fall_start + self.beta_fall, TWO_PI}
        ends |= {self.beta_rise * b for b in inside}
        ends |= {self.fall_start + self.beta_fall * b for b in inside_fall}
        return np.array(sorted(ends))

    def displacement(self, th) -> np.ndarray:
        """Rows S, S', S'', S''' (derivatives in theta) at the angles ``th`` (wrapped to 2 pi)."""
        th = np.mod(np.atleast_1d(np.asarray(th, dtype=float)), TWO_PI)
        out = np.zeros((4, th.size))
        rise = th < self.beta_rise
        fall = (th >= self.fall_start) & (th < self.fall_start + self.beta_fall)
        out[0, (th >= self.beta_rise) & (th < self.fall_start)] = self.S_T
        if rise.any():
            H = self.law.evaluate(th[rise] / self.beta_rise)
            for k in range(4):
                out[k, rise] = self.S_T * H[:, k] / self.beta_rise**k
        if fall.any():
            H = self.return_law.evaluate((th[fall] - self.fall_start) / self.beta_fall)
            out[0, fall] = self.S_T * (1.0 - H[:, 0])
            for k in range(1, 4):
                out[k, fall] = -self.S_T * H[:, k] / self.beta_fall**k
        return out

    def jumps(self, order: int, rtol: float = JUMP_RTOL) -> tuple:
        """Where S^(order) (1: the velocity ds/dtheta, 2: the acceleration) jumps: the segment
        ends (the rise's and the return's ends against the dwells, and the laws' own
        breakpoints inside) whose one-sided limits differ by more than ``rtol`` times the
        largest |S^(order)| over the two segments that meet there, as (theta, left limit,
        right limit) rows.  The scale is the segments' own, not the turn's: a short rise's
        acceleration may be a hundred thousand times a long return's, whose jumps count too.

        Each limit is the values at theta -+ d, 2 d, 3 d extrapolated to theta by the parabola
        through them (3 f(d) - 3 f(2 d) + f(3 d), error d^3 S^(order+3)): with d at most
        1e-7 rad and a ten-thousandth of the shortest segment, a smooth law's two limits agree
        to below 1e-8 of that scale (every law of the library, its shape parameter at either
        end of its range, over rises of 0.01 to 170 deg), a hundredth of ``rtol``."""
        ends = self.breakpoints
        d = min(1e-7, float(np.diff(ends).min()) * 1e-4)
        at = ends[:-1]                                  # 2 pi is 0 again
        row = lambda x: self.displacement(x)[order]   # noqa: E731

        def limit(side):
            return (3.0 * row(at + side * d) - 3.0 * row(at + 2.0 * side * d)
                    + row(at + 3.0 * side * d))
        left, right = limit(-1.0), limit(1.0)
        # each segment's largest |S^(order)|: 65 points inside it and its two limits
        u = np.linspace(0.0, 1.0, 65)[:, None]
        inside = np.abs(row((ends[:-1] + d + u * (np.diff(ends) - 2 * d)).ravel()))
        seg = np.maximum(inside.reshape(u.size, -1).max(axis=0),
                         np.maximum(np.abs(right), np.abs(np.roll(left, -1))))
        scale = np.maximum(seg, np.roll(seg, 1))       # the segment after and the one before
        bad = np.abs(right - left) > rtol * scale
        return tuple((float(t), float(lv), float(rv))
                     for t, lv, rv in zip(at[bad], left[bad], right[bad]))

    def radius(self, th) -> np.ndarray:
        """Pitch radius r = r_b + r_r + S (paper (3))."""
        return self.r_b + self.r_r + self.displacement(th)[0]

    def pitch_curvature(self, th) -> np.ndarray:
        """Signed curvature of the pitch curve r (cos theta, sin theta) (paper (4)):
        (r^2 + 2 r'^2 - r r'') / (r^2 + r'^2)^(3/2), the plane curvature in polar form."""
        S = self.displacement(th)
        r, r1, r2 = self.r_b + self.r_r + S[0], S[1], S[2]
        return (r * r + 2 * r1 * r1 - r * r2) / (r * r + r1 * r1) ** 1.5

    def undercut(self, samples: int = 4001) -> "Undercut":
        return undercut(self, samples)


@dataclass(frozen=True)
class Undercut:
    """Where the groove walls are undercut: theta intervals (rad) per wall."""

    r_r: float
    inner: tuple
    outer: tuple
    min_rho_convex: float
    """Smallest pitch-curve radius of curvature on convex parts (inner wall needs > r_r)."""
    min_rho_concave: float
    """Smallest |rho_p| on concave parts (outer wall needs > r_r); inf if none."""

    def __bool__(self):
        return bool(self.inner or self.outer)

    @property
    def message(self) -> str:
        if not self:
            return (f"no undercut: pitch-curve radius of curvature >= {self.min_rho_convex * 1e3:.3g} mm "
                    f"on convex parts, |rho_p| >= {self.min_rho_concave * 1e3:.3g} mm on concave "
                    f"parts, roller radius r_r = {self.r_r * 1e3:.3g} mm")
        parts = []
        for side, where, rho, shape in (("inner", self.inner, self.min_rho_convex, "convex"),
                                        ("outer", self.outer, self.min_rho_concave, "concave")):
            if where:
                spans = ", ".join(f"[{np.degrees(lo):.2f}, {np.degrees(hi):.2f}] deg"
                                  for lo, hi in where)
                parts.append(f"the {side} wall is undercut for theta in {spans}: on this {shape} "
                             f"part the pitch curve's radius of curvature (down to "
                             f"{rho * 1e3:.3g} mm) is below the roller radius "
                             f"r_r = {self.r_r * 1e3:.3g} mm")
        return ("undercut: " + "; ".join(parts) + ". Use a larger base circle, a longer "
                "rise/fall angle, a smaller lift or a smaller roller.")

    def check(self):
        """Raise :class:`UndercutError` with :attr:`message` if a wall is undercut."""
        if self:
            raise UndercutError(self.message)


def failing_spans(th, bad, g):
    """theta intervals where bad is True, ends refined to the roots of g."""
    from scipy.optimize import brentq

    out, i, n = [], 0, len(th)
    while i < n:
        if not bad[i]:
            i += 1
            continue
        j = i
        while j + 1 < n and bad[j + 1]:
            j += 1
        lo = th[i] if i == 0 else brentq(g, th[i - 1], th[i], xtol=1e-13)
        hi = th[j] if j == n - 1 else brentq(g, th[j], th[j + 1], xtol=1e-13)
        out.append((float(lo), float(hi)))
        i = j + 1
    return tuple(out)


def undercut(cam: RDFD, samples: int = 4001) -> Undercut:
    """Where a groove wall is undercut (local test on the pitch curve's curvature).

    The wall offset by d (-r_r inner, +r_r outer) has tangent p'(1 + d kappa_p): where
    1 + d kappa_p < 0 it runs backwards, a cusp and a swallowtail the roller cannot follow.
    For the inner wall that is a convex part with rho_p < r_r, for the outer wall a concave
    part with |rho_p| < r_r.  The curvature is sampled on ``samples`` points plus the segment
    ends, and the interval ends are refined by root finding; an excursion narrower than the
    grid may be missed.
    """
    # the segment ends are sampled too: a law's curvature may peak or jump there
    th = np.union1d(np.linspace(0.0, TWO_PI, samples), cam.breakpoints)
    kappa = cam.pitch_curvature(th)
    rr = cam.r_r

    def k(x):
        return float(cam.pitch_curvature(x)[0])

    inner = failing_spans(th, 1.0 - rr * kappa < 0, lambda x: 1.0 - rr * k(x))
    outer = failing_spans(th, 1.0 + rr * kappa < 0, lambda x: 1.0 + rr * k(x))
    convex, concave = kappa[kappa > 0], kappa[kappa < 0]
    return Undercut(rr, inner, outer,
                    float(1.0 / convex.max()) if convex.size else float("inf"),
                    float(1.0 / -concave.min()) if concave.size else float("inf"))
