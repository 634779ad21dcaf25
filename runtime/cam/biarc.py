"""A smooth closed curve as a chain of circular arcs, tangent to one another (bi-arcs), within
a stated tolerance: what a CNC controller and most CAD programs take as G2/G3 moves and arcs.

Between two points P0, P1 of the curve with unit tangents t0, t1 a bi-arc is two arcs meeting
at a joint J with a common tangent there: with Q0 = P0 + d t0 and Q1 = P1 - d t1 the joint is
their midpoint, and d solves |Q1 - Q0| = 2 d (the two arcs' tangent lengths equal):

    2 (1 - t0.t1) d^2 + 2 (v.(t0 + t1)) d - v.v = 0,     v = P1 - P0.

Each arc leaves its start point along the given tangent; as a DXF bulge (tan of a quarter
of the included angle) it is tan(a/2), a the signed angle from the tangent to the chord.
The curve is split at the given knots and each span halved until the bi-arc lies within the
tolerance of the curve at ``checks`` points inside the span (the curve evaluated there, not
interpolated), with a margin for what lies between them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..core.errors import CamdynInputError


@dataclass(frozen=True)
class Arc:
    """From ``start`` to ``end`` leaving ``start`` along ``tangent``: a DXF bulge."""

    start: tuple
    end: tuple
    bulge: float

    def centre_radius(self):
        """(centre, radius); None for a straight segment (bulge 0)."""
        if self.bulge == 0.0:
            return None
        (x0, y0), (x1, y1) = self.start, self.end
        chord = math.hypot(x1 - x0, y1 - y0)
        theta = 4.0 * math.atan(self.bulge)          # included angle, signed (CCW > 0)
        r = chord / (2.0 * math.sin(theta / 2.0))     # signed
        # the centre lies on the chord's perpendicular bisector, at r cos(theta/2) from it
        mx, my = (x0 + x1) / 2.0, (y0 + y1) / 2.0
        nx, ny = -(y1 - y0) / chord, (x1 - x0) / chord
        off = r * math.cos(theta / 2.0)
        return (mx + off * nx, my + off * ny), abs(r)


def _arc(p, t, q) -> Arc:
    chord = q - p
    a = math.atan2(t[0] * chord[1] - t[1] * chord[0], t[0] * chord[0] + t[1] * chord[1])
    return Arc((float(p[0]), float(p[1])), (float(q[0]), float(q[1])), math.tan(a / 2.0))


def biarc(p0, t0, p1, t1) -> tuple[Arc, Arc]:
    """The two arcs from p0 (tangent t0) to p1 (tangent t1), equal tangent lengths."""
    v = p1 - p0
    tt = t0 + t1
    a = 2.0 * (1.0 - float(t0 @ t1))
    b = 2.0 * float(v @ tt)
    c = -float(v @ v)
    if a < 1e-12:                                   # parallel tangents: the root of b d + c
        d = -c / b
    else:
        d = (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)
    j = (p0 + d * t0 + p1 - d * t1) / 2.0
    tj = (p1 - d * t1) - (p0 + d * t0)
    tj = tj / np.hypot(*tj)
    return _arc(p0, t0, j), _arc(j, tj, p1)


def distance(arc: Arc, pts) -> np.ndarray:
    """Distance of points (2, n) from the arc: from its circle where a point lies in the
    arc's angular span, from the nearer end otherwise (a straight segment likewise)."""
    (x0, y0), (x1, y1) = arc.start, arc.end
    ends = np.minimum(np.hypot(pts[0] - x0, pts[1] - y0), np.hypot(pts[0] - x1, pts[1] - y1))
    cr = arc.centre_radius()
    if cr is None:
        dx, dy = x1 - x0, y1 - y0
        L2 = dx * dx + dy * dy
        s = ((pts[0] - x0) * dx + (pts[1] - y0) * dy) / L2
        line = np.abs((pts[0] - x0) * dy - (pts[1] - y0) * dx) / math.sqrt(L2)
        return np.where((s >= 0) & (s <= 1), line, ends)
    (cx, cy), r = cr
    # the span as the angle swept from the start, in the arc's own sense
    sense = 1.0 if arc.bulge > 0 else -1.0
    a0 = math.atan2(y0 - cy, x0 - cx)
    span = abs(4.0 * math.atan(arc.bulge))
    ang = np.mod(sense * (np.arctan2(pts[1] - cy, pts[0] - cx) - a0), 2 * math.pi)
    circle = np.abs(np.hypot(pts[0] - cx, pts[1] - cy) - r)
    return np.where(ang <= span, circle, ends)


MAX_ARCS = 20000
"""The most arcs a fit makes before it gives up: a smooth cam's profile at the finest
tolerance, 1 nm, takes under a thousand; each arc costs about half a millisecond, so a curve
that cannot be followed (a corner, a cusp) is refused within seconds."""


def fit(curve, knots, tol: float, checks: int = 32, max_arcs: int = MAX_ARCS) -> list[Arc]:
    """Arcs through the closed curve ``curve(u) -> (points (2, n), unit tangents (2, n))``,
    split at ``knots`` (increasing, the first and last the same point of the curve), each
    span halved until its bi-arc is within 0.9 ``tol`` of the curve at ``checks`` interior
    points: the margin covers what lies between the points checked (the deviation is smooth
    along a span; tests/test_followers.py checks the chain at 60 points a degree).  More
    than ``max_arcs`` is a CamdynInputError."""
    out: list[Arc] = []
    stack = [(float(a), float(b)) for a, b in zip(knots[:-1], knots[1:])][::-1]
    while stack:
        a, b = stack.pop()
        (p, t) = curve(np.array([a, b]))
        arcs = biarc(p[:, 0], t[:, 0], p[:, 1], t[:, 1])
        inner = np.linspace(a, b, checks + 2)[1:-1]
        q, _ = curve(inner)
        dev = np.minimum(distance(arcs[0], q), distance(arcs[1], q))
        if float(np.max(dev)) > 0.9 * tol and b - a > 1e-9 * (knots[-1] - knots[0]):
            m = (a + b) / 2.0
            stack += [(m, b), (a, m)]
            if len(out) + len(stack) > max_arcs:
                raise CamdynInputError(f"arc-tolerance={tol:g} m would take more than "
                                       f"{max_arcs} arcs: the curve has corners or cusps "
                                       f"there, or the tolerance is too fine")
            continue
        out += arcs
    return out
