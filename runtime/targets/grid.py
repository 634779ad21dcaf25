"""A target over a grid of its parameters: the runs in chunks, on threads (or any mapper, a
Dask cluster's), with the answer contract applied to every point.

A chunk is ``target.run_points(names, points)``: with an adaptive method a target's chunk
runs in compiled code holding no GIL (runtime/engine/finder.pyx, runtime/measure/batch.py),
what each point needs of Python (a consistent initial state, a scene's equilibrium, the times
a full turn's short dwells are sampled at) made beforehand, so threads run chunks side by
side on as many cores (threads rather than processes: no pickling, no start-up, one copy of
the model); fixed-step methods run point by point (their stability check lives in
Simulator.run).  With the error estimate, every point runs again one notch tighter; the two
passes of a chunk go out side by side, so that its rows are whole as soon as both are in, and
the rows come back in the grid's order (a sweep writes its table as they come).
"""
from __future__ import annotations

import math
import os
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

import numpy as np

from ..core.errors import CamdynInputError, SimulationError
from ..measure.contract import grid_columns, unavailable
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


@dataclass(frozen=True)
class Twin:
    """The tighter twin of a grid's target, as the chunks run it: a point whose run one notch
    tighter fails (a step budget it exhausts, a step that collapses) keeps its figures and
    loses only its estimate (NaN), with the warning that says why (runtime/measure/contract.py
    unavailable), instead of failing the grid."""

    target: object

    def run_points(self, names: tuple, points: np.ndarray) -> Batch:
        try:
            return self.target.run_points(names, points)
        except (SimulationError, CamdynInputError):
            pass
        # the chunk stopped at a point that failed: each point alone, so that only those lose
        parts = []
        for j in range(len(points)):
            try:
                parts.append(self.target.run_points(names, points[j:j + 1]))
            except (SimulationError, CamdynInputError) as exc:
                k = len(self.target.figure_names())
                parts.append(Batch(np.full((1, k), np.nan), np.zeros((1, k)),
                                   [[unavailable(f"the run one notch tighter failed ({exc})")]],
                                   np.full(1, np.nan)))
        return Batch(np.concatenate([b.figures for b in parts]),
                     np.concatenate([b.sampling for b in parts]),
                     [w for b in parts for w in b.warnings],
                     np.concatenate([np.asarray(b.steps, dtype=float) for b in parts]))


class _Threads:
    """Run chunks on ``jobs`` threads, their results yielded in order, a progress bar updated
    as they finish.  Stopped early (Ctrl-C, a run that failed), the chunks not yet started
    are dropped and those running finish."""

    def __init__(self, jobs: int):
        self.jobs = jobs
        self.where = f"local, {jobs} thread{'s' if jobs > 1 else ''}"

    def __call__(self, todo, names, bar):
        if self.jobs == 1 or len(todo) == 1:
            for tgt, piece in todo:
                out = run_chunk(tgt, names, piece)
                bar.update(len(piece))
                yield out
            return
        pool = ThreadPoolExecutor(max_workers=self.jobs)
        try:
            futures = [pool.submit(run_chunk, tgt, names, piece) for tgt, piece in todo]
            for fut, (_, piece) in zip(futures, todo):
                out = fut.result()
                bar.update(len(piece))
                yield out
        finally:
            pool.shutdown(wait=True, cancel_futures=True)


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


def whole_steps(steps) -> np.ndarray:
    """The step counts of a grid's runs as whole numbers (int64), as a run counts them; as
    floats only where a target did not count some (NaN there)."""
    a = np.asarray(steps, dtype=float)
    return a.astype(np.int64) if np.all(np.isfinite(a)) else a


@dataclass
class GridPlan:
    """A grid checked and ready to run: the target fitted to every point (a run long enough
    for the dwell every point needs, so that a part of the grid runs exactly as in the whole),
    its twin one notch tighter (None without the estimate), the chunks' size and threads."""

    target: object
    tight: object
    names: tuple
    points: np.ndarray
    size: int
    jobs: int

    @property
    def figures(self) -> tuple:
        """Every figure and its ``<figure>_error`` column, in the table's order."""
        return tuple(k for k in self._no_rows() if k not in self.names
                     and k not in ("warnings", "n_steps"))

    def _no_rows(self) -> dict:
        empty = np.empty((0, len(self.target.figure_names())))
        none = Batch(empty, empty, [], np.empty(0))
        return self.columns(self.points[:0], none, none if self.tight is not None else None)

    def columns(self, points: np.ndarray, base: Batch, tight: Batch | None) -> dict:
        """The table's columns for ``points`` from their runs (the answer contract row by
        row, runtime/measure/contract.py grid_columns)."""
        columns = {k: points[:, i].copy() for i, k in enumerate(self.names)}
        errors = grid_columns(self.target, base, tight)
        for k, f in enumerate(self.target.figure_names()):
            columns[f] = base.figures[:, k]
            if f"{f}_error" in errors:
                columns[f"{f}_error"] = errors[f"{f}_error"]
        columns["warnings"] = errors["warnings"]
        columns["n_steps"] = whole_steps(base.steps)
        return columns

    def run(self, start: int = 0, *, bar=None, mapper=None, each=None) -> GridRun:
        """Run the points from ``start`` on; both passes of a chunk (the runs and their
        tighter twins) go out together, and ``each(columns)`` gets every chunk's rows in the
        grid's order as soon as they are in (a sweep writes its table so)."""
        rest = self.points[start:]
        pieces = [rest[i:i + self.size] for i in range(0, len(rest), self.size)]
        twins = [self.target] if self.tight is None else [self.target, Twin(self.tight)]
        todo = [(t, p) for p in pieces for t in twins]
        mapper = mapper or _Threads(self.jobs)
        started = time.perf_counter()
        results = iter(mapper(todo, tuple(self.names), bar or NoBar()))
        parts = []
        try:
            for piece in pieces:
                base = next(results)
                tight = next(results) if self.tight is not None else None
                parts.append(self.columns(piece, base, tight))
                if each is not None:
                    each(parts[-1])
        finally:
            close = getattr(results, "close", None)
            if close is not None:        # stopped early: the mapper drops what is not run
                close()
        seconds = time.perf_counter() - started
        if not parts:
            parts = [self._no_rows()]
        columns = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
        return GridRun(self.target, self.tight, tuple(self.names), self.figures, columns,
                       seconds, getattr(mapper, "where", "local"))


CHUNKS_PER_JOB = 8
"""Chunks a thread gets at least, where the grid is large enough: even shares and a live
progress bar."""
MAX_CHUNK = 512
"""Grid points per chunk at most by default: a Ctrl-C or a progress update waits for one."""


def default_chunk(target, n: int, jobs: int) -> int:
    """Points per chunk: the target's own (the least that pays for a call) or more, about
    CHUNKS_PER_JOB chunks a thread, at most MAX_CHUNK.  Larger chunks cost less Python
    around the compiled calls: 8 % of the fig. 4.11 grid's time on one core with 32 points
    a chunk (bench/sweep.py)."""
    return max(target.chunk, min(MAX_CHUNK, math.ceil(n / (CHUNKS_PER_JOB * jobs))))


def plan_grid(target, names: tuple, points: np.ndarray, *, estimate: bool = True,
              jobs: int | None = None, chunk: int | None = None) -> GridPlan:
    """Check a grid before any run (names, ranges, the window every point needs) and plan
    it: ``target`` at every row of ``points`` (columns ``names``), in chunks of ``chunk``
    points (default: :func:`default_chunk`) on ``jobs`` threads (default: every core)."""
    points = np.atleast_2d(np.asarray(points, dtype=float))
    target = target.fit_points(tuple(names), points)
    jobs = default_jobs() if jobs is None else jobs
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise CamdynInputError(f"jobs={jobs!r}: give a positive whole number of threads")
    size = chunk or default_chunk(target, len(points), jobs)
    if isinstance(size, bool) or not isinstance(size, int) or size < 1:
        raise CamdynInputError(f"chunk={size!r}: give a positive whole number of grid points")
    tight = None
    if estimate:
        tight = target.tighter()
        if tight is None:
            raise CamdynInputError(f"rtol={target.method().rtol:g} is the tightest there is: no "
                                   "error estimate (give a larger rtol)")
    return GridPlan(target, tight, tuple(names), points, size, jobs)


def run_grid(target, names: tuple, points: np.ndarray, *, estimate: bool = True,
             jobs: int | None = None, chunk: int | None = None, bar=None,
             mapper=None) -> GridRun:
    """Run ``target`` at every row of ``points`` (columns ``names``) and apply the answer
    contract: the figures, their error estimates (NaN without ``estimate``) and warnings.
    ``mapper(todo, names, bar)`` runs the chunks and yields their batches in order (default:
    ``jobs`` threads)."""
    return plan_grid(target, names, points, estimate=estimate, jobs=jobs,
                     chunk=chunk).run(bar=bar, mapper=mapper)
