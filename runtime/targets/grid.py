"""A target over a grid of its parameters: the runs in chunks, on threads (or any mapper, a
Dask cluster's), with the answer contract applied to every point.

A chunk is ``target.run_points(names, points)``: a model's chunk with an adaptive method runs
in compiled code holding no GIL (runtime/engine/finder.pyx), so threads run chunks side by
side on as many cores (threads rather than processes: no pickling, no start-up, one copy of
the model); a scene's chunk runs point by point, its threads overlapping only in the compiled
integration.  With the error estimate, every point runs again one notch tighter.
"""
from __future__ import annotations

import os
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

import numpy as np

from ..core.errors import CamdynInputError
from ..measure.contract import grid_columns
from .base import Batch

def default_jobs() -> int:
    """All cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


def run_chunk(target, names: tuple, points: np.ndarray) -> Batch:
    """One chunk of a grid (a module-level function, so that a Dask worker can call it)."""
    return target.run_points(names, points)


def _concat(batches: list) -> Batch:
    return Batch(np.concatenate([b.figures for b in batches]),
                 np.concatenate([b.sampling for b in batches]),
                 [w for b in batches for w in b.warnings],
                 np.concatenate([b.steps for b in batches]))


class _Threads:
    """Run chunks on ``jobs`` threads, in order, a progress bar updated as they finish."""

    def __init__(self, jobs: int):
        self.jobs = jobs
        self.where = f"local, {jobs} thread{'s' if jobs > 1 else ''}"

    def __call__(self, todo, names, bar) -> list:
        if self.jobs == 1 or len(todo) == 1:
            out = []
            for tgt, piece in todo:
                out.append(run_chunk(tgt, names, piece))
                bar.update(len(piece))
            return out
        with ThreadPoolExecutor(max_workers=self.jobs) as pool:
            futures = [pool.submit(run_chunk, tgt, names, piece) for tgt, piece in todo]
            out = []
            for fut, (_, piece) in zip(futures, todo):
                out.append(fut.result())
                bar.update(len(piece))
        return out


class NoBar:
    def update(self, n=1):
        pass

    def close(self):
        pass


@dataclass
class GridRun:
    """Every point of a grid: ``columns[name]`` per axis, figure, ``<figure>_error``,
    ``warnings`` and ``n_steps``, one row per point (the first axis slowest)."""

    target: object
    tight: object
    names: tuple
    figures: tuple
    columns: dict
    seconds: float
    where: str
    meta: dict = field(default_factory=dict)

    @property
    def warned(self) -> int:
        """How many points have a warning."""
        return int(sum(1 for w in self.columns["warnings"] if w))


def run_grid(target, names: tuple, points: np.ndarray, *, estimate: bool = True,
             jobs: int | None = None, chunk: int | None = None, bar=None,
             mapper=None) -> GridRun:
    """Run ``target`` at every row of ``points`` (columns ``names``) and apply the answer
    contract: the figures, their error estimates (NaN without ``estimate``) and warnings.
    ``mapper(todo, names, bar) -> [Batch]`` runs the chunks (default: ``jobs`` threads)."""
    points = np.atleast_2d(np.asarray(points, dtype=float))
    target = target.fit_points(tuple(names), points)
    jobs = default_jobs() if jobs is None else jobs
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise CamdynInputError(f"jobs={jobs!r}: give a positive whole number of threads")
    size = chunk or target.chunk
    if isinstance(size, bool) or not isinstance(size, int) or size < 1:
        raise CamdynInputError(f"chunk={size!r}: give a positive whole number of grid points")
    tight = None
    if estimate:
        tight = target.tighter()
        if tight is None:
            raise CamdynInputError(f"rtol={target.method().rtol:g} is the tightest there is: no "
                                   "error estimate (give a larger rtol)")
    pieces = [points[i:i + size] for i in range(0, len(points), size)]
    todo = [(t, p) for t in ([target] if tight is None else [target, tight]) for p in pieces]
    mapper = mapper or _Threads(jobs)
    bar = bar or NoBar()
    start = time.perf_counter()
    results = mapper(todo, tuple(names), bar)
    seconds = time.perf_counter() - start
    base = _concat(results[:len(pieces)])
    tight_batch = _concat(results[len(pieces):]) if tight is not None else None
    columns = {k: points[:, i].copy() for i, k in enumerate(names)}
    order = []
    errors = grid_columns(target, base, tight_batch)
    for k, f in enumerate(target.figure_names()):
        columns[f] = base.figures[:, k]
        order.append(f)
        if f"{f}_error" in errors:
            columns[f"{f}_error"] = errors[f"{f}_error"]
            order.append(f"{f}_error")
    columns["warnings"] = errors["warnings"]
    columns["n_steps"] = base.steps
    return GridRun(target, tight, tuple(names), tuple(order), columns, seconds,
                   getattr(mapper, "where", "local"))
