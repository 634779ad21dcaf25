"""A cache for computations built on runs that knows how tight the runs are.

An error estimate computes a value again inside :func:`camdyn.runtime.core.methods.tightened`,
where every run is one notch tighter; a plain cache would hand back the first value and the
estimate would be zero.  :func:`cached_runs` keeps one value per notch count instead."""
from __future__ import annotations

import functools

from camdyn.runtime.core import methods


def cached_runs(fn):
    """``fn`` cached on its arguments and on how many notches tighter runs are made now."""
    @functools.lru_cache(maxsize=None)
    def at(notches, *args, **kwargs):
        return fn(*args, **kwargs)

    @functools.wraps(fn)
    def cached(*args, **kwargs):
        return at(methods.notches(), *args, **kwargs)

    cached.cache_clear = at.cache_clear
    return cached
