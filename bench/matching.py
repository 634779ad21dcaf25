"""Error-vs-time sweeps and the choice of settings at matched error.

Error = |U0 - U0_ref|, absolute, U0 from the state at T = 1 (problem.u0).

Matched error.  For a target E a method's setting is the loosest setting of
its sweep such that it and every tighter setting measured have error <= E.
Demanding it of the tighter ones too keeps a lucky cancellation (the error of
RK4 changes sign near h = 1/800) from passing for accuracy.  With four grid
points per decade of error the chosen error lies within about a factor 2
below E; no interpolation is done.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

from problem import u0
from timing import median_seconds_side_by_side

TARGETS = (1e-6, 1e-8, 1e-10)
FLOOR = min(TARGETS) / 10   # a sweep stops after two settings in a row below this error
ERR_ZERO = 1e-16            # errors are shown no smaller than this (log axes)


@dataclass(frozen=True)
class Point:
    setting: float
    error: float
    seconds: float
    n_rhs: int


class Bench:
    """Measurements, each taken once and reused (the tables share points with the sweeps)."""

    def __init__(self, u0_ref: float, repeat: int):
        self.u0_ref = u0_ref
        self.repeat = repeat
        self._memo: dict = {}

    def points(self, comps, x: float) -> list[Point]:
        """The competitors at setting x; the ones not measured yet are timed side by side."""
        todo = [c for c in comps if (c.key, x) not in self._memo]
        if todo:
            infos = {c.key: c.info(x) for c in todo}
            secs = median_seconds_side_by_side({c.key: c.runner(x) for c in todo}, self.repeat)
            for c in todo:
                x1, v1, n_rhs = infos[c.key]
                err = max(abs(u0(x1, v1) - self.u0_ref), ERR_ZERO)
                self._memo[(c.key, x)] = Point(x, err, secs[c.key], n_rhs)
        return [self._memo[(c.key, x)] for c in comps]

    def sweep(self, comps) -> dict:
        """Competitors sharing a grid, loose to tight, until the error is well below every target.

        Returns {key: [Point, ...]}; the first competitor's error decides when to stop.
        """
        grid = comps[0].grid
        if any(c.grid != grid for c in comps):
            raise ValueError("a sweep group must share its grid")
        out: dict = {c.key: [] for c in comps}
        below = 0
        for x in sorted(grid, reverse=True):
            for c, p in zip(comps, self.points(comps, x)):
                out[c.key].append(p)
            below = below + 1 if out[comps[0].key][-1].error < FLOOR else 0
            if below == 2:
                break
        return out


def final_times(bench: Bench, comps: dict, settings: dict, repeat: int) -> dict:
    """Re-time the matched settings of one target side by side: {key: Point with new seconds}.

    settings maps a competitor key to its matched Point.  Interleaving every
    competitor within each repeat puts them all under the same machine
    conditions, which matters for ratios of 100 between runs seconds apart.
    """
    fns = {k: comps[k].runner(p.setting) for k, p in settings.items()}
    secs = median_seconds_side_by_side(fns, repeat)
    return {k: replace(p, seconds=secs[k]) for k, p in settings.items()}


def matched(points: list[Point], target: float) -> Point | None:
    """The loosest point whose error, and that of every tighter point, is <= target."""
    chosen = None
    for p in reversed(points):   # tight to loose
        if p.error > target:
            break
        chosen = p
    return chosen
