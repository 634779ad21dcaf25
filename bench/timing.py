"""Median wall-clock time of one call, timeit-style (GC off while timing)."""
from __future__ import annotations

import statistics
import time
import timeit

REPEAT = 7            # repeats per measurement; the median is reported
MIN_REPEAT_S = 0.01   # each repeat runs the call often enough to last about this long
MAX_NUMBER = 2000


def calls_per_repeat(fn) -> int:
    """How many calls make one repeat last MIN_REPEAT_S (after one warm-up call)."""
    fn()
    t0 = time.perf_counter()
    fn()
    one = time.perf_counter() - t0
    return max(1, min(MAX_NUMBER, int(MIN_REPEAT_S / max(one, 1e-9))))


def median_seconds_side_by_side(fns: dict, repeat: int = REPEAT) -> dict:
    """Median over `repeat` repeats of the mean time of one call, per callable.

    The callables take turns within each repeat, so they share whatever drift
    the machine goes through and their ratios are steadier than from separate runs.
    """
    numbers = {k: calls_per_repeat(fn) for k, fn in fns.items()}
    runs: dict = {k: [] for k in fns}
    for _ in range(repeat):
        for k, fn in fns.items():
            runs[k].append(timeit.Timer(fn).timeit(numbers[k]) / numbers[k])
    return {k: statistics.median(v) for k, v in runs.items()}


def median_seconds(fn, repeat: int = REPEAT) -> float:
    """Median over `repeat` repeats of the mean time of one call of fn()."""
    return median_seconds_side_by_side({0: fn}, repeat)[0]
