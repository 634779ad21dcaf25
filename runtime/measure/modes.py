"""The modes a figure sees in the dwell, and the window a figure read there needs.

A residual amplitude (U0 (3.5), U0'' (3.6)) is the largest |U| or |X''| in the dwell after
the rise; read from a window shorter than one period of the slowest oscillation the output
carries, it comes out too small (the thesis's one-DOF model at tau = 0.9 read over 0.2 of a
dwell: 6 % low).  Which oscillations an output carries follows from the frozen linear system
of the dwell: the eigenvalues lambda_k of df/dy with a positive imaginary part are its
oscillatory modes, of period 2 pi/Im(lambda_k), and output g sees mode k when its gradient
has a component along the mode's shape v_k, |dg/dy . v_k| > SEEN |dg/dy| |v_k| (both
measured in the states' own scales).  For the thesis's models this gives back the theory:
the one-DOF model and CAMSHAFT-1 see tau (3.3), (4.12); in CAMSHAFT-2's dwell the cam's
slope H' is zero, so U sees tau only, while the cam's speed deviation sees the flywheel
mode tau (Fa/Fv)^(1/2) (5.19); a DYNACAM scene's U sees the follower's tau of (4.3), (4.39).
tests/test_window.py holds these.
"""
from __future__ import annotations

import math

import numpy as np

from ..engine import driver

SEEN = 1e-10
"""Relative component of a mode along an output's gradient below which the output does not
see it (rounding of the difference Jacobian is ~1e-13; real couplings are 1e-9 and more)."""


def slowest_periods(model, P, law_codes, law_pars, t, Y, outputs, element_modes=None) -> np.ndarray:
    """Period of the slowest oscillatory mode each output sees, at each point: shape
    (len(P), len(outputs)), 0 where an output sees none.  ``P`` one parameter vector per
    point, ``t``, ``Y`` the time and state to linearize at (a dwell), ``outputs`` names of
    states or outputs."""
    P = np.ascontiguousarray(np.atleast_2d(P), dtype=float)
    n = len(P)
    Y = np.ascontiguousarray(np.broadcast_to(np.atleast_2d(Y), (n, len(model.state_names))),
                             dtype=float)
    t = np.ascontiguousarray(np.broadcast_to(np.atleast_1d(np.asarray(t, float)), (n,)))
    scale = np.ascontiguousarray(model.state_scales(), dtype=float)
    ns = len(model.state_names)
    out_idx, state_idx = [], []
    for name in outputs:
        if name in model.state_names:
            state_idx.append(model.state_names.index(name))
            out_idx.append(0 if model.output_names else -1)
        else:
            state_idx.append(-1)
            out_idx.append(model.output_names.index(name))
    idx = np.array([max(i, 0) for i in out_idx], dtype=np.intc) if model.output_names else \
        np.zeros(0, dtype=np.intc)
    J, G = driver.linearize(model.capsule, P, law_codes, law_pars, t, Y, scale,
                                idx if model.output_names else np.zeros(0, dtype=np.intc),
                                element_modes)
    if not model.output_names:
        G = np.zeros((n, len(outputs), ns))
    for i, s in enumerate(state_idx):
        if s >= 0:                      # a state: its gradient is the unit vector
            G[:, i, :] = 0.0
            G[:, i, s] = 1.0
    out = np.zeros((n, len(outputs)))
    finite = np.all(np.isfinite(J), axis=(1, 2)) & np.all(np.isfinite(G), axis=(1, 2))
    if not finite.any():
        return out
    lam, V = np.linalg.eig(J[finite])
    mag = np.abs(lam)
    oscillating = (lam.imag > 1e-9 * mag) & (mag > 0)
    Gs = G[finite] * scale[None, None, :]
    Vs = V / scale[None, :, None]
    along = np.abs(np.einsum("nis,nsk->nik", G[finite], V))
    size = (np.linalg.norm(Gs, axis=2)[:, :, None] * np.linalg.norm(Vs, axis=1)[:, None, :])
    seen = oscillating[:, None, :] & (along > SEEN * size)
    with np.errstate(divide="ignore"):
        periods = np.where(seen, 2 * math.pi / np.where(oscillating, lam.imag, 1.0)[:, None, :],
                           0.0)
    out[finite] = periods.max(axis=2)
    return out


def amplitude_bound(result, name: str, a: float, b: float, period: float,
                    samples_per_period: int = 64) -> float:
    """The amplitude of ``name`` on [a, b] as one oscillation of the given period shows it:
    max over the window of (v^2 + (v'/omega)^2)^(1/2), omega = 2 pi/period, v' by central
    differences of the dense output.  For a single sinusoid it is the amplitude wherever the
    window lies, however short: what the largest |v| over a full period would have been."""
    T = amplitude_times(a, b, period, samples_per_period)
    if T is None:
        return 0.0
    return amplitude_from(T, result.sample(T)[name], period)


def amplitude_times(a: float, b: float, period: float,
                    samples_per_period: int = 64) -> np.ndarray | None:
    """The times :func:`amplitude_bound` samples on [a, b] (None: an empty window or no
    period), so that a grid's compiled runs can sample them on each record."""
    if not (b > a and period > 0):
        return None
    n = max(8, int(math.ceil(samples_per_period * (b - a) / period)) + 1)
    return np.linspace(a, b, n)


def amplitude_from(T: np.ndarray, v: np.ndarray, period: float) -> float:
    """:func:`amplitude_bound` from the values ``v`` at its times ``T``."""
    dv = np.gradient(v, T)
    w = 2 * math.pi / period
    return float(np.max(np.sqrt(v * v + (dv / w) ** 2)))
