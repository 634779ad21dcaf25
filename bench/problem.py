"""The benchmark problem: CAMSHAFT-1, thesis (4.15), and its error measure U0.

    X'' = (2 pi/tau)^2 (H - X) / (1 + Fa H'^2),   X(0) = X'(0) = 0,

cycloidal rise H = T - sin(2 pi T)/(2 pi), H' = 1 - cos(2 pi T) on [0, 1),
dwell H = 1, H' = 0 for T >= 1; tau = 0.15, Fa = 2, T in [0, 3].  Every
integration restarts at the breakpoint T = 1.

Error measure.  In the dwell (4.15) is X'' = omega^2 (1 - X), omega = 2 pi/tau,
an undamped harmonic oscillation about X = 1, so the residual amplitude U0
(thesis sec. 3.3, (3.5)) follows exactly from the state at T = 1:

    U0 = sqrt((X(1) - 1)^2 + (X'(1)/omega)^2).

Every method is scored with this formula on its own state at T = 1, so the
score does not depend on any method's dense output or post-processing.
"""
from __future__ import annotations

import math

import numpy as np

TAU = 0.15
FA = 2.0
T_BREAK = 1.0
T_END = 3.0
OMEGA = 2.0 * math.pi / TAU
PARAMS = {"tau": TAU, "Fa": FA}
MODEL = "camshaft1"


def u0(x1: float, v1: float) -> float:
    """Residual amplitude after the rise from the state (X, X') at T = 1 (see module doc)."""
    return math.hypot(x1 - 1.0, v1 / OMEGA)


def state_at_break(t: np.ndarray, y: np.ndarray) -> tuple[float, float]:
    """(X, X') at T = 1 from a camdyn record, where the breakpoint appears twice."""
    k = int(np.searchsorted(t, T_BREAK))
    if k >= len(t) or t[k] != T_BREAK:
        raise ValueError("the record has no point at the breakpoint T = 1")
    return float(y[k, 0]), float(y[k, 1])


def rhs_rise(t, y):
    """(4.15) during the cycloidal rise, NumPy version for SciPy."""
    c = 2.0 * np.pi * t
    h = t - np.sin(c) / (2.0 * np.pi)
    hd = 1.0 - np.cos(c)
    return np.array([y[1], OMEGA ** 2 * (h - y[0]) / (1.0 + FA * hd * hd)])


def rhs_dwell(t, y):
    """(4.15) in the dwell, H = 1 and H' = 0, NumPy version for SciPy."""
    return np.array([y[1], OMEGA ** 2 * (1.0 - y[0])])

