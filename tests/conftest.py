"""Shared helpers for the test suite."""
import functools

import numpy as np
import pytest

from camdyn.runtime.residual import residual
from camdyn.runtime.simulate import simulate


@functools.lru_cache(maxsize=None)
def residual_of(model: str, tau: float, Fa: float = 0.0, rtol: float = 1e-10,
                law: str = "cycloidal", t_end: float = 3.0):
    """Residual figures of one run (cached: many tests ask for the same runs)."""
    params = {"tau": tau} if model == "one_dof" else {"tau": tau, "Fa": Fa}
    return residual(simulate(model, params, t_end, "dp54", rtol=rtol, law=law))


@pytest.fixture
def rng():
    return np.random.default_rng(20261122)


def matches_printed(value: float, printed: str) -> bool:
    """Does ``value`` agree with a number printed in the thesis, to its printed digits?

    Accepts rounding and truncation at the last printed digit (the thesis
    truncates some values, e.g. 4 pi^2 = 39.478 printed as 39.4).  ``printed``
    may carry an exponent: "3.75e-4".
    """
    from decimal import Decimal

    p = Decimal(printed)
    ulp = Decimal(1).scaleb(p.as_tuple().exponent)
    v = Decimal(repr(float(value)))
    rounded = abs(v - p) <= ulp / 2
    away = (v - p) if p > 0 else (p - v)  # how far |v| exceeds |p|
    truncated = p != 0 and Decimal(0) <= away < ulp
    return bool(rounded or truncated)
