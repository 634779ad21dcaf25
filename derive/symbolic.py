"""SymPy's simplification made to take the same path on every call.

simplify() factors multivariate polynomials by Wang's algorithm, which tries random
evaluation points drawn from SymPy's own generator (seeded once, at import, from the system).
The factors it finds are the same whatever the points, but the time is not: for one seed in
about twenty-five, the Hensel lifting of beam2's mass matrix ran for minutes instead of the
usual 2.5 s.  Seeding that generator before every call gives every derivation one path, so
that `camdyn derive` and the tests take the time they took when they were measured.
"""
from __future__ import annotations

import sympy as sp
from sympy.core import random as sympy_random

SEED = 0
"""The seed of SymPy's generator before each call (beam2: 2.5 s, as most seeds)."""


def simplify(expr, **kwargs):
    """``sympy.simplify(expr)`` with SymPy's generator seeded first (module doc)."""
    sympy_random.seed(SEED)
    return sp.simplify(expr, **kwargs)


def trigsimp(expr, **kwargs):
    """``sympy.trigsimp(expr)`` with SymPy's generator seeded first (module doc)."""
    sympy_random.seed(SEED)
    return sp.trigsimp(expr, **kwargs)


def factor(expr, **kwargs):
    """``sympy.factor(expr)`` with SymPy's generator seeded first (module doc)."""
    sympy_random.seed(SEED)
    return sp.factor(expr, **kwargs)
