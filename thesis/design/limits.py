"""The requirement and the limits it sets on the envelopes of :mod:`.graphs`: the largest Fa at
the design's tau (the least shaft stiffness c_tan = c_c tan^2 alpha_me/Fa) and the largest tau
at its Fa (the smallest t_m = T_e/tau, or the largest T_e = tau t_m at the given t_m, so the
least c_c = m (2 pi/T_e)^2); sec. 3.3 turns U0, U0'' into u0 = U0 h_m', u0'' = U0'' h_m'/t_m^2.

Solving on the envelope.  "Largest Fa that still meets the requirement" is taken as the
first crossing: the envelope ratio r(Fa) = max(u0_env/accuracy, u0''_env/acceleration) is
evaluated on the bracket Fa = 0, 0.1, 0.2, 0.4, ... (doubling, up to :data:`FA_CAP`) until
it exceeds 1, each Fa on a window of +-1.5 of its dip spacings around tau (in 1/tau), and
the root in the last interval is found by Brent's method, every Fa there on one window, that
of the interval's top (its dips lie furthest apart), so that r(Fa) is one function of Fa.
The largest tau is found the same way on one
envelope in tau (samples on a lattice in 1/tau, extended until the first crossing lies
inside them with a window to spare).  Both use 12 samples per dip; the root is then moved
by secant steps onto the envelope with 24 samples per dip, which is the answer, and the
step is its stated error (:func:`polish`).  Not counting on a later dip, the first
crossing is the limit even where a larger Fa or tau would meet the requirement again.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camdyn.runtime.core.errors import CamdynInputError, SimulationError

from .graphs import Graphs, phase_factor
from ..numerics import brentq

FA_CAP = 12.8
"""The largest Fa searched (fig. 4.11 stops at 2, App. 7's indexing mechanism has 3.34)."""
TAU_MIN, TAU_CAP = 0.02, 0.9
"""The tau range searched for the smallest t_m (tau < 1: the rise longer than a period)."""


@dataclass(frozen=True)
class Requirement:
    """u0 <= accuracy (m) and/or u0'' <= acceleration (m/s^2) for a stroke h_m' (m)."""

    stroke: float
    accuracy: float | None = None
    acceleration: float | None = None

    def ratio(self, U0, U0dd, t_m):
        """The largest of u0/accuracy and u0''/acceleration (sec. 3.3: u0 = U0 h_m',
        u0'' = U0'' h_m'/t_m^2); <= 1 meets the requirement.  Element by element for arrays
        of points."""
        r = 0.0
        if self.accuracy is not None:
            r = np.maximum(r, U0 * self.stroke / self.accuracy)
        if self.acceleration is not None:
            r = np.maximum(r, U0dd * self.stroke / t_m**2 / self.acceleration)
        return r

    def which(self, U0, U0dd, t_m) -> str:
        a = U0 * self.stroke / self.accuracy if self.accuracy is not None else -1
        b = U0dd * self.stroke / t_m**2 / self.acceleration if self.acceleration is not None else -1
        return "accuracy" if a >= b else "residual acceleration"


def largest_Fa(graphs: Graphs, tau: float, req: Requirement, t_m: float | None,
               width: float | None = None) -> dict:
    """The largest Fa at this tau whose envelope still meets ``req`` (module doc); with
    ``width`` every Fa on the one window of that half-width in 1/tau."""

    def r(Fa, w=None, per_dip=None):
        return req.ratio(*graphs.at(tau, Fa, per_dip=per_dip, width=w or width), t_m)

    prev, r_prev = 0.0, r(0.0)
    if r_prev > 1.0:
        return {"Fa_max": None, "reason": f"not met even by a rigid shaft: at Fa = 0 the envelope "
                f"is {r_prev:.3g} times the requirement"}
    Fa = 0.1
    while True:
        r_Fa = r(Fa)
        if r_Fa > 1.0:
            break
        prev, r_prev = Fa, r_Fa
        if Fa >= FA_CAP:
            return {"Fa_max": None, "reason": f"met for every Fa up to {FA_CAP:g} (the search "
                    f"range); ratio {r_Fa:.3g} there"}
        Fa = min(2 * Fa, FA_CAP)
    w = width or 1.5 / phase_factor(graphs.law, graphs.theta, Fa)
    if not r(prev, w) <= 1.0 < r(Fa, w):
        # the wider window moved the envelope across the requirement at an end of the
        # interval (a maximum it adds beyond those bracketing tau): search again, every Fa
        # on the window of the largest
        return largest_Fa(graphs, tau, req, t_m, 1.5 / phase_factor(graphs.law, graphs.theta,
                                                                    FA_CAP))
    Fa_c = brentq(lambda f: r(f, w) - 1.0, prev, Fa, xtol=1e-10, rtol=1e-9)
    r_beyond = r(Fa_c * (1 + 1e-3), w)
    slope = (r_beyond - r(Fa_c, w)) / (1e-3 * Fa_c)
    return polish("Fa_max", Fa_c, slope, lambda f: r(f, w, 2 * graphs.per_dip),
                  lambda f: graphs.at(tau, f, width=w, per_dip=2 * graphs.per_dip), req,
                  lambda f: t_m, r_beyond) | {"bracket": [prev, Fa]}


ERROR_FLOOR = 1e-9
"""The least relative error a limit is stated with; a secant step a tenth of it is not
taken (a step to a new Fa costs a window of runs)."""


def polish(name, x_c, slope, r_fine, envelopes_at, req, t_m_of, r_beyond=None) -> dict:
    """The answer x_c found on the envelope with PER_DIP samples per dip, moved by secant
    steps onto the envelope with twice as many: the answer reported; |the move| is its error
    estimate (the finer envelope's own error is some four times smaller, the parabolas through
    the maxima and the spline between samples being second order or better).  ``ratio_at``
    is the finer envelope's ratio at the answer, ``ratio_beyond`` its ratio 0.1 % beyond, or
    ``r_beyond`` where given (the coarser envelope's there, already read for its slope)."""
    if not slope > 0:
        raise SimulationError(f"the envelope does not grow through the crossing at {name} = "
                              f"{x_c:.6g}: no single limit to report")
    # secant steps on the finer envelope, the first with the coarse slope
    x, r = x_c, r_fine(x_c)
    step = -(r - 1.0) / slope
    for _ in range(8):
        if abs(r - 1.0) < 1e-10 or abs(step) <= 0.1 * ERROR_FLOOR * abs(x):
            break
        x_new = x + step
        r_new = r_fine(x_new)
        if r_new == r:
            x = x_new
            break
        step = -(r_new - 1.0) * step / (r_new - r)
        x, r = x_new, r_new
    U0, U2 = envelopes_at(x)
    return {name: x, f"{name}_error": max(abs(x - x_c), ERROR_FLOOR * x),
            "ratio_at": float(req.ratio(U0, U2, t_m_of(x))),
            "ratio_beyond": float(r_fine(x * (1 + 1e-3)) if r_beyond is None else r_beyond),
            "U0_envelope": U0, "U0dd_envelope": U2, "limited_by": req.which(U0, U2, t_m_of(x))}


def largest_tau(graphs: Graphs, Fa: float, tau0: float, req: Requirement,
                T_e: float | None = None, t_m: float | None = None) -> dict:
    """The largest tau at this Fa whose envelope meets ``req`` (module doc).  With T_e given
    the machine runs faster (t_m = T_e/tau: an acceleration requirement reads
    U0'' h_m' tau^2/T_e^2); with t_m given the follower gets softer (T_e = tau t_m)."""
    if req.acceleration is not None and T_e is None and t_m is None:
        raise CamdynInputError("--residual-acceleration needs the rise time (--rise-time, or "
                               "--cam-angle with --speed) to turn U0'' into m/s^2")

    def t_m_of(t):
        return t_m if T_e is None else T_e / np.asarray(t)
    w = 1.5 / phase_factor(graphs.law, graphs.theta, Fa)
    # a machine below TAU_MIN starts the search at TAU_MIN (an empty bracket otherwise)
    lo, hi = max(tau0 / 1.5, TAU_MIN), min(max(tau0, TAU_MIN) * 1.5, TAU_CAP)

    def ratio_on(taus, e0, e2):
        taus = np.asarray(taus, float)
        return req.ratio(e0(taus), e2(taus), t_m_of(taus))

    while True:
        x_hi_samples = 1.0 / lo + w
        x_lo_samples = 1.0 / hi - w
        e0, e2 = graphs.envelopes(x_lo_samples, x_hi_samples, Fa)
        taus = 1.0 / np.linspace(1.0 / hi, 1.0 / lo, max(200, int(60 * (1 / lo - 1 / hi))))[::-1]
        rs = ratio_on(taus, e0, e2)
        if rs[0] > 1.0:
            if lo <= TAU_MIN:
                return {"tau_max": None, "reason": f"not met even at tau = {TAU_MIN:g} (ratio "
                        f"{rs[0]:.3g})"}
            lo = max(lo / 1.5, TAU_MIN)
            continue
        over = np.flatnonzero(rs > 1.0)
        if over.size == 0:
            if hi >= TAU_CAP:
                return {"tau_max": None, "reason": f"met up to tau = {TAU_CAP:g} (the search "
                        f"range; ratio {rs[-1]:.3g} there)"}
            hi = min(hi * 1.5, TAU_CAP)
            continue
        k = int(over[0])
        break

    def f(t):
        return ratio_on([t], e0, e2)[0] - 1.0

    tau_c = brentq(f, taus[k - 1], taus[k], xtol=1e-13, rtol=1e-11)
    slope = (f(tau_c * (1 + 1e-4)) - f(tau_c)) / (1e-4 * tau_c)
    # the window Graphs.at reads around tau, so that the answer and at(answer) agree
    fine = graphs.envelopes(1 / tau_c - w, 1 / tau_c + w, Fa, 2 * graphs.per_dip)

    def fine_at(t):
        return float(fine[0](t)), float(fine[1](t))

    out = polish("tau_max", tau_c, slope, lambda t: req.ratio(*fine_at(t), t_m_of(t)), fine_at,
                  req, t_m_of)
    out["beyond_last_maximum"] = fine[0].unbracketed(out["tau_max"]) or fine[1].unbracketed(
        out["tau_max"])
    return out
