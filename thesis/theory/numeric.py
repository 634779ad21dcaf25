"""NumPy versions of the closed forms in :mod:`camdyn.thesis.theory.forms`, lambdified from SymPy.

The runtime has its own hand-written (3.5), (3.6) (:mod:`camdyn.runtime.measure.references`, no
SymPy); tests/test_one_dof.py holds the two equal.
"""
from functools import lru_cache

import numpy as np


@lru_cache(maxsize=None)
def _fn(name: str):
    import sympy as sp

    from camdyn.thesis.theory import forms as th

    expr = getattr(th, name)
    args = sorted(expr.free_symbols, key=lambda s: s.name)
    return sp.lambdify(args, expr, "numpy"), [a.name for a in args]


def evaluate(name: str, **values):
    """Closed form ``name`` of the theory module at the given symbol values."""
    f, args = _fn(name)
    missing = set(args) - set(values)
    if missing:
        raise TypeError(f"{name} needs {', '.join(sorted(missing))}")
    return f(*(np.asarray(values[a], dtype=float) for a in args))


def U0(tau: float) -> float:
    """(3.5)"""
    return float(evaluate("U0", tau=tau))


def U0dd(tau: float) -> float:
    """(3.6)"""
    return float(evaluate("U0dd", tau=tau))
