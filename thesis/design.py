"""Design by the rules: what a designer knows in, the thesis's answer out (issue 14, item 3).

Secs 8.3, 8.5, 8.6 and App. 7 describe one method:

1. the machine's figures: T_e = 2 pi (m/c_c)^(1/2) (4.39), t_m = beta_m/w_s (App. 7 (8)),
   tau = T_e/t_m (4.12), tan alpha_me = h_m'/(i R_1/2 beta_m) (4.13), Fa = (c_c/c_tan)
   tan^2 alpha_me (4.14), the stiffness dip 1 + H'max^2 Fa (4.18), (4.19)
   (thesis/examples.py holds the formulas);
2. the response at (tau, Fa) read from the graphs U0(tau, Fa), U0''(tau, Fa) of fig. 4.11, i.e.
   from the envelopes through their maxima (secs 3.5, 8.2.6): a designer never counts on a
   tuning dip.  Here the graphs are computed with CAMSHAFT-1 (4.15) for the chosen law on a
   grid uniform in 1/tau (runtime/envelope.py), so any law and any Fa can be read, also
   beyond the printed graphs (tau 0.06-0.7, Fa 0-2);
3. the requirement (positional accuracy u0 = U0 h_m', residual acceleration
   u0'' = U0'' h_m'/t_m^2, sec. 3.3) turned into limits: the largest Fa at the given tau
   (the least shaft stiffness c_tan = c_c tan^2 alpha_me/Fa) and the largest tau at the
   given Fa (the smallest t_m = T_e/tau, the fastest machine, and the largest T_e = tau t_m
   at the given t_m, so the least c_c = m (2 pi/T_e)^2);
4. the rules of sec. 8.5 the input breaks (and the remedies (8.5) suggests);
5. the motor by sec. 8.3: tau_m = T_m/t_m, the peak slip of fig. 8.6, the overdimensioning
   P (8.1), the torque (8.2), the rated power (8.3), and (8.4) (thesis/motor_theory.py);
6. a check run of the design point with the least model that is adequate (one-DOF when Fa
   changes the envelope by less than :data:`ONE_DOF_TOLERANCE`, else CAMSHAFT-1), its U0,
   U0'' with error estimates beside the envelope values.

Solving on the envelope.  "Largest Fa that still meets the requirement" is taken as the
first crossing: the envelope ratio r(Fa) = max(u0_env/accuracy, u0''_env/acceleration) is
evaluated on the bracket Fa = 0, 0.1, 0.2, 0.4, ... (doubling, up to :data:`FA_CAP`) until
it exceeds 1, and the root in the last interval is found by Brent's method.  Every Fa uses
the same tau samples (a window of +-1.5 dip spacings of the largest Fa around tau, in
1/tau), so r(Fa) is one function of Fa.  The largest tau is found the same way on one
envelope in tau (samples on a lattice in 1/tau, extended until the first crossing lies
inside them with a window to spare).  Both use 12 samples per dip; the root is then moved
by secant steps onto the envelope with 24 samples per dip, which is the answer, and the
step is its stated error (:func:`_polish`).  Not counting on a later dip, the first
crossing is the limit even where a larger Fa or tau would meet the requirement again.
The envelope itself: :class:`Upper`.
"""
from __future__ import annotations

import math
from pathlib import Path
from dataclasses import dataclass, field

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq

from camdyn.runtime import laws as _laws
from camdyn.runtime.envelope import dips, maxima, through_maxima
from camdyn.runtime.errors import CamdynInputError, SimulationError
from camdyn.runtime.residual import residual
from camdyn.runtime.simulate import Simulator

from . import examples as ex

PER_DIP = 12
"""Samples per unit of 1/tau (one tuning dip of (3.5) at Fa = 0; wider at Fa > 0)."""
FA_CAP = 12.8
"""The largest Fa searched (fig. 4.11 stops at 2, App. 7's indexing mechanism has 3.34)."""
TAU_MIN, TAU_CAP = 0.02, 0.9
"""The tau range searched for the smallest t_m (tau < 1: the rise longer than a period)."""
LATTICE_CAP = 0.95
"""The largest tau sampled (windows around tau up to TAU_CAP reach beyond it)."""
RTOL = 1e-9
"""Tolerance of the graph runs (DP54); their error is far below the envelope's."""
ONE_DOF_TOLERANCE = 0.02
"""The one-DOF model (3.1) stands in for CAMSHAFT-1 when the envelopes at Fa and at 0 differ
by less than this, relatively (the check run's least adequate model)."""
COMMON_SHAFT_FA = 0.3
"""Sec. 8.5 rule (3): Fa <= 0.3 on a shaft that drives several mechanisms (interaction)."""
TAN_ALPHA_MAX = 0.5
"""Sec. 8.2.7 (3): tan alpha_me = 1/2 'is considered to be a maximum for practical design
reasons' (the scan prints the fraction as '-!'; 0.13/(0.178 1.47) = 0.497 there)."""
GRAPH_TAU = (0.06, 0.7)
GRAPH_FA = 2.0
"""The range of the printed graphs of fig. 4.11 (tau axis, largest Fa curve)."""


# -- the graphs of fig. 4.11 and their envelopes -----------------------------------------------
def phase_factor(law: str, theta, Fa: float) -> float:
    """Mean of (1 + H'^2 Fa)^(-1/2) over the rise: the natural frequency of CAMSHAFT-1 falls
    by this on average (4.32), so its tuning dips lie 1/phase_factor apart in 1/tau."""
    T = np.linspace(0.0, 1.0, 2001)
    hd = _laws.choose(law, theta).evaluate(T)[:, 1]
    return float(np.mean((1.0 + hd**2 * Fa) ** -0.5))


class Upper:
    """The envelope through the maxima of a sampled graph, as runtime/envelope.py's Envelope
    draws it (log-linear between the maxima, held flat beyond the outermost one where the
    graph dips on that side, never below the graph), with two refinements the design solver needs: the answer
    is flagged where it rests on a held maximum (the top of the tau range at small Fa,
    :meth:`unbracketed`), and the graph between samples is a spline, not a line.
    Extrapolating the maxima instead (a power law through the outermost two) fails where
    the dips fade out: at Fa = 0.8 the last two
    maxima below tau = 0.15 rise as tau^11.  Between samples the graph is a cubic spline in 1/tau, on whose uniform grid the
    samples lie: near the top of a lobe, where the graph rises above the line through the
    maxima, straight lines would cut the lobe short by ~(pi h)^2/8 (0.9 % at 12 samples per
    dip), the spline by some 1e-5.  The kinks at the dips ring in the spline only over a
    sample or two, where the line through the maxima lies far above the graph anyway."""

    def __init__(self, tau, value):
        t = np.asarray(tau, float)
        v = np.asarray(value, float)
        if t.size < 3 or np.any(v < 0) or np.any(np.diff(t) <= 0):
            raise CamdynInputError("an envelope needs at least 3 samples, tau ascending, values >= 0")
        self.t, self.v = t, v
        self.mt, self.mv = maxima(t, v)
        self._spline = CubicSpline(1.0 / t[::-1], v[::-1])

    def graph(self, tau):
        return np.maximum(self._spline(1.0 / np.asarray(tau, float)), 0.0)

    def through(self, x):
        """runtime/envelope.py's curve through the maxima at x (NaN where the graph is its own
        envelope)."""
        return through_maxima(x, self.mt, self.mv, dips(self.t, self.v))

    def unbracketed(self, tau) -> bool:
        """Is tau beyond the last maximum with a dip in between, the held value above the
        graph there (so that it sets the envelope)?  There the flat hold may lie
        below the curve the maxima to come would draw (at Fa = 0 beyond tau = 0.4: (3.5) dips
        to zero at tau = 1/2 and then rises without a maximum)."""
        if self.mt.size == 0:
            return False
        d = dips(self.t, self.v)
        return bool(tau > self.mt[-1] and np.any((d > self.mt[-1]) & (d <= tau))
                    and self.mv[-1] > self.graph(tau))

    def __call__(self, tau):
        x = np.atleast_1d(np.asarray(tau, float))
        if np.any(x < self.t[0]) or np.any(x > self.t[-1]):
            raise CamdynInputError(f"tau outside the samples {self.t[0]:g}..{self.t[-1]:g}")
        out = self.graph(x)
        through = self.through(x)
        out = np.where(np.isnan(through), out, np.maximum(out, np.nan_to_num(through)))
        return float(out[0]) if np.ndim(tau) == 0 else out


class Graphs:
    """U0 and U0'' of CAMSHAFT-1 (4.15) for one law, run once per (tau, Fa) and kept.

    tau is always taken on the lattice 1/tau = k/per_dip, so windows around different tau
    share their runs."""

    def __init__(self, law: str = "cycloidal", theta=None, per_dip: int = PER_DIP):
        _laws.choose(law, theta)
        self.law, self.theta, self.per_dip = law, theta, per_dip
        self._cache: dict = {}
        self._sims: dict = {}
        self.runs = 0

    def _sim(self, t_end: float) -> Simulator:
        if t_end not in self._sims:
            self._sims[t_end] = Simulator("camshaft1", t_end, "dp54", rtol=RTOL, law=self.law,
                                          theta=self.theta)
        return self._sims[t_end]

    def point(self, k: int, Fa: float, per_dip: int) -> tuple[float, float, float]:
        """(tau, U0, U0'') at 1/tau = k/per_dip."""
        tau = per_dip / k              # correctly rounded: equal for k/n and 2k/2n
        key = (tau, Fa)
        if key not in self._cache:
            # two periods of the dwell or more (its period is tau in T whatever Fa: H' = 0
            # there), in steps of 0.1 so that few simulators are prepared
            t_end = 1.0 + 0.1 * math.ceil((2.0 * tau + 0.05) / 0.1)
            r = residual(self._sim(t_end).run({"tau": tau, "Fa": Fa}))
            self.runs += 1
            self._cache[key] = (tau, r.U0, r.U0dd)
        return self._cache[key]

    def samples(self, x_lo: float, x_hi: float, Fa: float, per_dip: int | None = None):
        """(tau, U0, U0'') arrays on the lattice points with x_lo <= 1/tau <= x_hi."""
        n = per_dip or self.per_dip
        ks = range(max(math.ceil(x_lo * n), math.ceil(n / LATTICE_CAP)), math.floor(x_hi * n) + 1)
        pts = np.array([self.point(k, Fa, n) for k in ks])
        order = np.argsort(pts[:, 0])
        return pts[order, 0], pts[order, 1], pts[order, 2]

    def envelopes(self, x_lo, x_hi, Fa, per_dip=None):
        t, u0, u2 = self.samples(x_lo, x_hi, Fa, per_dip)
        return Upper(t, u0), Upper(t, u2)

    def at(self, tau: float, Fa: float, per_dip: int | None = None, width: float | None = None):
        """(U0_env, U0''_env) at tau: the envelopes of a window of +-1.5 dip spacings around
        tau (``width`` in 1/tau to fix the window, so that it does not move with Fa)."""
        w = 1.5 / phase_factor(self.law, self.theta, Fa) if width is None else width
        x = 1.0 / tau
        e0, e2 = self.envelopes(x - w, x + w, Fa, per_dip)
        return float(e0(tau)), float(e2(tau))


# -- the requirement -----------------------------------------------------------------------------
@dataclass(frozen=True)
class Requirement:
    """u0 <= accuracy (m) and/or u0'' <= acceleration (m/s^2) for a stroke h_m' (m)."""

    stroke: float
    accuracy: float | None = None
    acceleration: float | None = None

    def ratio(self, U0: float, U0dd: float, t_m: float | None) -> float:
        """The largest of u0/accuracy and u0''/acceleration (sec. 3.3: u0 = U0 h_m',
        u0'' = U0'' h_m'/t_m^2); <= 1 meets the requirement."""
        r = 0.0
        if self.accuracy is not None:
            r = max(r, U0 * self.stroke / self.accuracy)
        if self.acceleration is not None:
            r = max(r, U0dd * self.stroke / t_m**2 / self.acceleration)
        return r

    def which(self, U0, U0dd, t_m) -> str:
        a = U0 * self.stroke / self.accuracy if self.accuracy is not None else -1
        b = U0dd * self.stroke / t_m**2 / self.acceleration if self.acceleration is not None else -1
        return "accuracy" if a >= b else "residual acceleration"


def largest_Fa(graphs: Graphs, tau: float, req: Requirement, t_m: float | None) -> dict:
    """The largest Fa at this tau whose envelope still meets ``req`` (module doc)."""
    width = 1.5 / phase_factor(graphs.law, graphs.theta, FA_CAP)

    def r(Fa):
        return req.ratio(*graphs.at(tau, Fa, width=width), t_m)

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
    Fa_c = brentq(lambda f: r(f) - 1.0, prev, Fa, xtol=1e-10, rtol=1e-9)
    slope = (r(Fa_c * (1 + 1e-3)) - r(Fa_c)) / (1e-3 * Fa_c)

    def r_fine(f):
        return req.ratio(*graphs.at(tau, f, per_dip=2 * graphs.per_dip, width=width), t_m)

    return _polish("Fa_max", Fa_c, slope, r_fine, lambda f: graphs.at(tau, f, width=width,
                   per_dip=2 * graphs.per_dip), req, lambda f: t_m) | {"bracket": [prev, Fa]}


def _polish(name, x_c, slope, r_fine, envelopes_at, req, t_m_of) -> dict:
    """The answer x_c found on the envelope with PER_DIP samples per dip, moved by secant
    steps onto the envelope with twice as many: the answer reported; |the move| is its error
    estimate (the finer envelope's own error is some four times smaller, the parabolas through
    the maxima and the spline between samples being second order or better).  ``ratio_at``
    and ``ratio_beyond`` are the finer envelope's ratio at the answer and 0.1 % beyond."""
    if not slope > 0:
        raise SimulationError(f"the envelope does not grow through the crossing at {name} = "
                              f"{x_c:.6g}: no single limit to report")
    # secant steps on the finer envelope, the first with the coarse slope
    x0, r0 = x_c, r_fine(x_c)
    x = x0 - (r0 - 1.0) / slope
    for _ in range(8):
        r1 = r_fine(x)
        if abs(r1 - 1.0) < 1e-10 or r1 == r0:
            break
        x0, r0, x = x, r1, x - (r1 - 1.0) * (x - x0) / (r1 - r0)
    U0, U2 = envelopes_at(x)
    return {name: x, f"{name}_error": max(abs(x - x_c), 1e-9 * x),
            "ratio_at": float(req.ratio(U0, U2, t_m_of(x))),
            "ratio_beyond": float(r_fine(x * (1 + 1e-3))), "U0_envelope": U0, "U0dd_envelope": U2,
            "limited_by": req.which(U0, U2, t_m_of(x))}


def largest_tau(graphs: Graphs, Fa: float, tau0: float, req: Requirement,
                T_e: float | None = None, t_m: float | None = None) -> dict:
    """The largest tau at this Fa whose envelope meets ``req`` (module doc).  With T_e given
    the machine runs faster (t_m = T_e/tau: an acceleration requirement reads
    U0'' h_m' tau^2/T_e^2); with t_m given the follower gets softer (T_e = tau t_m)."""
    if req.acceleration is not None and T_e is None and t_m is None:
        raise CamdynInputError("--residual-acceleration needs the rise time (--rise-time, or "
                               "--cam-angle with --speed) to turn U0'' into m/s^2")

    def t_m_of(t):
        return t_m if T_e is None else T_e / t
    w = 1.5 / phase_factor(graphs.law, graphs.theta, Fa)
    # a machine below TAU_MIN starts the search at TAU_MIN (an empty bracket otherwise)
    lo, hi = max(tau0 / 1.5, TAU_MIN), min(max(tau0, TAU_MIN) * 1.5, TAU_CAP)

    def ratio_on(taus, e0, e2):
        return np.array([req.ratio(e0(t), e2(t), t_m_of(t)) for t in taus])

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

    out = _polish("tau_max", tau_c, slope, lambda t: req.ratio(*fine_at(t), t_m_of(t)), fine_at,
                  req, t_m_of)
    out["beyond_last_maximum"] = fine[0].unbracketed(out["tau_max"]) or fine[1].unbracketed(
        out["tau_max"])
    return out


# -- the check run -------------------------------------------------------------------------------
def least_model(U0_env_Fa: float, U0_env_0: float, Fa: float,
                tolerance: float = ONE_DOF_TOLERANCE) -> tuple[str, str]:
    """(model, why): the one-DOF model (3.1) when the envelope at Fa and at Fa = 0 differ by
    less than ``tolerance`` (the shaft's flexibility does not show), else CAMSHAFT-1 (4.15).

    Kept small so that a general chooser of the least adequate model can take its place."""
    if Fa == 0:
        return "one-dof", "Fa = 0: a rigid shaft, constant fictitious angular velocity (ch. 3)"
    change = abs(U0_env_Fa / U0_env_0 - 1.0)
    if change < tolerance:
        return "one-dof", (f"Fa = {Fa:.3g} changes the U0 envelope by {100 * change:.2g} % "
                           f"(< {100 * tolerance:g} %) against Fa = 0: the shaft's flexibility "
                           "does not show (ch. 3)")
    return "camshaft1", (f"Fa = {Fa:.3g} changes the U0 envelope by {100 * change:.3g} % against "
                         "Fa = 0: the variable fictitious angular velocity of CAMSHAFT-1 (4.15) is "
                         "needed; the flywheel effect is left out (Fv -> oo, sec. 8.2.5)")


def check_run(model: str, tau: float, Fa: float, law: str, theta) -> dict:
    """U0, U0'', X''min of the run at (tau, Fa), with error estimates from a run at rtol/10
    (runtime/accuracy.py)."""
    from camdyn.runtime import accuracy
    from camdyn.runtime.cli import RESIDUAL_FIGURES, residual_run

    fa = None if model == "one-dof" else Fa
    base = residual_run(model, tau, fa, law, theta, "dp54", 1e-10, None)
    tight = residual_run(model, tau, fa, law, theta, "dp54", 1e-11, None)
    out = {k: base[k] for k in ("U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min")}
    out.update(accuracy.errors(base, tight, [k for k in RESIDUAL_FIGURES if k in out], "dp54"))
    return out


# -- the motor, sec. 8.3 -------------------------------------------------------------------------
MOTOR_T_M = {3000: 0.113, 1500: 0.0398, 1000: 0.0392, 750: 0.0321}
"""Mechanical time constants T_m (s) of the thesis's motors by synchronous speed (fig. A.5.3)."""


def motor(*, t_m, T_m, delta_n, delta_lim, eta_g=1.0, spring=False, T_el=None, mass=None,
          stroke=None, w_s=None) -> dict:
    """Sec. 8.3: tau_m = T_m/t_m, delta_max/delta_n from fig. 8.6 (first order (A.5.33), as
    sec. 8.3 says; second order (A.5.25) with T_el), P (8.1), M_ena (8.2), N_n (8.3), (8.4);
    the torque and power need the mass (at the output member, with the stroke h_m' there),
    the torque also the shaft speed."""
    from . import motor_theory as mt

    tau_m = T_m / t_m
    tau_el = None if T_el is None else T_el / t_m
    rel, T_peak = mt.relative_slip_peak(tau_m, tau_el)
    P = mt.required_overdimensioning(tau_m, delta_n, delta_lim, eta_g=eta_g, spring=spring,
                                     tau_el=tau_el)
    out = {"T_m": T_m, "tau_m": tau_m, "tau_el": tau_el, "delta_n": delta_n,
           "delta_lim": delta_lim, "eta_g": eta_g, "v_v": 5 if spring else 1,
           "slip_peak_rel": rel, "T_slip_peak": T_peak, "P": P,
           "M_ena": None, "N_n": None, "rule_8_4": bool(mt.slip_within_rated(delta_lim, delta_n))}
    if mass is not None:
        out["N_n"] = mt.required_power(mass, stroke, t_m, P)
        if w_s is not None:
            out["M_ena"] = mt.required_torque(mass, stroke, w_s, t_m, P)
    return out


# -- input ---------------------------------------------------------------------------------------
def _positive(name: str, flag: str, value, unit: str, upper: float | None = None):
    if value is None:
        return None
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise CamdynInputError(f"argument {flag}: {name} must be a number, got {value!r}") from None
    if not (math.isfinite(v) and v > 0 and (upper is None or v < upper)):
        rng = f"0 < {name} < {upper:g}" if upper is not None else f"{name} > 0"
        raise CamdynInputError(f"argument {flag}: {name}={v:g} is out of range: {rng} ({unit})")
    return v


def cam_angle(text) -> float:
    """beta_m in rad from '1.745' (rad) or '100deg' (degrees)."""
    if text is None:
        return None
    s = str(text).strip().lower()
    deg = s.endswith("deg")
    v = _positive("beta_m", "--cam-angle", s[:-3] if deg else s, "rad, or degrees as '100deg'")
    v = math.radians(v) if deg else v
    if v >= 2 * math.pi:
        raise CamdynInputError(f"argument --cam-angle: beta_m={v:g} rad is out of range: "
                               "0 < beta_m < 2 pi (rad, or degrees as '100deg')")
    return v


@dataclass
class Machine:
    """The machine's figures (App. 7 (5)-(12)) and where each came from."""

    stroke: float
    t_m: float | None = None
    T_e: float | None = None
    tau: float = 0.0
    Fa: float = 0.0
    mass: float | None = None
    stiffness: float | None = None
    c_tan: float | None = None
    tan_alpha_me: float | None = None
    beta_m: float | None = None
    w_s: float | None = None
    ratio: float | None = None
    pitch_radius: float | None = None
    sources: dict = field(default_factory=dict)


def machine(*, stroke, rise_time=None, cam_angle_rad=None, speed=None, mass=None, stiffness=None,
            tau=None, Fa=None, c_tan=None, pitch_radius=None, ratio=None,
            tan_alpha_me=None) -> Machine:
    """tau and Fa from what the designer gives (App. 7 (5)-(12)); every input checked."""
    h = _positive("h_m'", "--stroke", stroke, "m, stroke of the output member")
    if h is None:
        raise CamdynInputError("argument --stroke: required (h_m' > 0, m, stroke of the output "
                               "member)")
    t_m = _positive("t_m", "--rise-time", rise_time, "s")
    beta = cam_angle_rad
    rpm = _positive("speed", "--speed", speed, "r.p.m. of the camshaft")
    m = _positive("m", "--mass", mass, "kg, equivalent mass (4.39) at the output member")
    c = _positive("c_c", "--stiffness", stiffness, "N/m, stiffness of the uncoupled follower (4.3)")
    tau = _positive("tau", "--tau", tau, "T_e/t_m (4.12)", upper=TAU_CAP)
    c_t = _positive("c_tan", "--c-tan", c_tan, "N/m, tangential stiffness (4.4)")
    R = _positive("R_1/2", "--pitch-radius", pitch_radius, "m, pitch radius at half the stroke "
                  "(4.1), at the cam")
    i = _positive("i", "--ratio", ratio, "transmission ratio output/cam, h_m' = i h_m")
    tan_me = _positive("tan alpha_me", "--tan-alpha-me", tan_alpha_me, "mean slope (4.13)")
    if Fa is not None:
        try:
            Fa = float(Fa)
        except (TypeError, ValueError):
            raise CamdynInputError(f"argument --fa: Fa must be a number, got {Fa!r}") from None
        if not (math.isfinite(Fa) and 0 <= Fa <= FA_CAP):
            raise CamdynInputError(f"argument --fa: Fa={Fa:g} is out of range: 0 <= Fa <= "
                                   f"{FA_CAP:g} (shaft stiffness factor (4.14))")
    src = {}
    M = Machine(stroke=h, mass=m, stiffness=c, c_tan=c_t, beta_m=beta, ratio=i, pitch_radius=R)
    # the rise time: given, or beta_m/w_s (App. 7 (8))
    if t_m is not None and (rpm is not None and beta is not None):
        raise CamdynInputError("argument --rise-time: not allowed with both --cam-angle and "
                               "--speed (t_m = beta_m/w_s, App. 7 (8)); give one or the other")
    if rpm is not None:
        M.w_s = rpm * 2 * math.pi / 60
        if beta is not None:
            t_m = ex.rise_time(beta, M.w_s)
            src["t_m"] = "beta_m/w_s (App. 7 (8))"
        elif t_m is not None:
            M.beta_m = beta = t_m * M.w_s
            src["beta_m"] = "t_m w_s"
        else:
            raise CamdynInputError("argument --speed: needs --cam-angle (t_m = beta_m/w_s) or "
                                   "--rise-time")
    elif beta is not None and t_m is None:
        raise CamdynInputError("argument --cam-angle: needs --speed (t_m = beta_m/w_s, App. 7 (8))")
    elif t_m is not None:
        src["t_m"] = "given"
    M.t_m = t_m
    # T_e and tau: m and c_c (4.39), or tau given
    if tau is not None:
        if m is not None and c is not None:
            raise CamdynInputError("argument --tau: not allowed with both --mass and --stiffness "
                                   "(tau = 2 pi (m/c_c)^(1/2)/t_m, (4.39), (4.12)); give tau or m "
                                   "and c_c")
        M.tau = tau
        src["tau"] = "given"
        if t_m is not None:
            M.T_e = tau * t_m
            src["T_e"] = "tau t_m"
            w2 = (2 * math.pi / M.T_e) ** 2
            if m is not None:
                M.stiffness = m * w2
                src["stiffness"] = "m (2 pi/T_e)^2 (4.39)"
            elif c is not None:
                M.mass = c / w2
                src["mass"] = "c_c (T_e/2 pi)^2 (4.39)"
    else:
        if m is None or c is None:
            raise CamdynInputError("arguments --mass, --stiffness: give both (T_e = 2 pi "
                                   "(m/c_c)^(1/2), (4.39)) or give --tau")
        if t_m is None:
            raise CamdynInputError("argument --rise-time: required with --mass and --stiffness "
                                   "(tau = T_e/t_m, (4.12)); or --cam-angle with --speed")
        M.T_e = ex.natural_period(m, c)
        M.tau = M.T_e / t_m
        src["T_e"] = "2 pi (m/c_c)^(1/2) (4.39)"
        src["tau"] = "T_e/t_m (4.12)"
        if not M.tau < TAU_CAP:
            raise CamdynInputError(f"arguments --mass, --stiffness, --rise-time: they give tau = "
                                   f"T_e/t_m = {M.tau:.3g}, out of range: 0 < tau < {TAU_CAP:g} "
                                   "(the rise must outlast the natural period)")
    # tan alpha_me (4.13) and Fa (4.14)
    if tan_me is not None:
        if R is not None:
            raise CamdynInputError("argument --tan-alpha-me: not allowed with --pitch-radius "
                                   "(tan alpha_me = h_m'/(i R_1/2 beta_m), (4.13)); give one")
        M.tan_alpha_me = tan_me
        src["tan_alpha_me"] = "given"
    elif R is not None:
        if beta is None:
            raise CamdynInputError("argument --pitch-radius: needs the cam angle (--cam-angle, "
                                   "or --rise-time with --speed) for tan alpha_me = h_m'/(i "
                                   "R_1/2 beta_m) (4.13)")
        M.tan_alpha_me = ex.mean_slope(h / (i or 1.0), R, beta)
        src["tan_alpha_me"] = "h_m'/(i R_1/2 beta_m) (4.13)"
    if Fa is not None:
        if c_t is not None:
            raise CamdynInputError("argument --fa: not allowed with --c-tan (Fa = (c_c/c_tan) "
                                   "tan^2 alpha_me, (4.14)); give one")
        M.Fa = Fa
        src["Fa"] = "given"
    elif c_t is not None:
        if M.tan_alpha_me is None or M.stiffness is None:
            raise CamdynInputError("argument --c-tan: Fa = (c_c/c_tan) tan^2 alpha_me (4.14) needs "
                                   "c_c (--stiffness, or --mass with --tau and t_m) and tan alpha_me "
                                   "(--pitch-radius with the cam angle, or --tan-alpha-me)")
        M.Fa = ex.shaft_factor(M.stiffness, c_t, M.tan_alpha_me)
        src["Fa"] = "(c_c/c_tan) tan^2 alpha_me (4.14)"
        if not M.Fa <= FA_CAP:
            raise CamdynInputError(f"argument --c-tan: it gives Fa = (c_c/c_tan) tan^2 alpha_me = "
                                   f"{M.Fa:.3g}, out of range: 0 <= Fa <= {FA_CAP:g}")
    else:
        raise CamdynInputError("argument --fa: give --fa, or --c-tan with the pitch radius "
                               "(Fa = (c_c/c_tan) tan^2 alpha_me, (4.14)); --fa 0 for a rigid shaft")
    M.sources = src
    return M


# -- the rules of sec. 8.5 -----------------------------------------------------------------------
def rules(M: Machine, ratio_design: float, common_shaft: bool, motor_out: dict | None,
          limited_by: str = "accuracy", law: str = "cycloidal") -> list[dict]:
    """The rules of secs 8.2.6-8.5 the design breaks ("violated") or should mind ("note")."""
    out = []

    def add(kind, rule, text):
        out.append({"status": kind, "rule": rule, "text": text})

    if ratio_design > 1:
        k = ratio_design
        if law != "cycloidal":
            how = ("(8.5) and (3.6) are the cycloid's; the limits above say how far tau and Fa "
                   "must come down (rules 1, 3, 4: a shorter stroke, a longer t_m, a stiffer, "
                   "lighter follower)")
        elif limited_by == "accuracy":
            how = (f"By (8.5), u0 ~ h_m' (2 pi/t_m)^3 (m/c)^(3/2)/pi (Fa = 0): shorten the stroke "
                   f"by {k:.3g} (rule 1), or lengthen t_m by {k ** (1 / 3):.3g} (rule 3), or raise "
                   f"c/m by {k ** (2 / 3):.3g} (rule 4)")
        else:
            how = (f"By (3.6), u0'' ~ 4 pi h_m' T_e/t_m^3 (Fa = 0, small tau): shorten the stroke "
                   f"by {k:.3g}, or lengthen t_m by {k ** (1 / 3):.3g}, or raise c/m by {k ** 2:.3g}")
        add("violated", "sec. 8.5 (3), (8.5)",
            f"the envelope at tau = {M.tau:.3g}, Fa = {M.Fa:.3g} is {k:.3g} times the "
            f"requirement ({limited_by}).  {how}" + ("; with Fa > 0 see the limits above"
                                                      if law == "cycloidal" else ""))
    if M.Fa > COMMON_SHAFT_FA:
        if common_shaft:
            add("violated", "sec. 8.5 (3)", f"Fa = {M.Fa:.3g} > {COMMON_SHAFT_FA} on a common "
                "shaft: mechanisms driven from one shaft interact (ref. 35)")
        else:
            add("note", "sec. 8.5 (3)", f"Fa = {M.Fa:.3g} > {COMMON_SHAFT_FA}: allowed only if "
                "this shaft drives no other mechanism (--common-shaft checks it)")
    if M.tan_alpha_me is not None and M.tan_alpha_me > TAN_ALPHA_MAX:
        add("violated", "sec. 8.2.7 (3)", f"tan alpha_me = {M.tan_alpha_me:.3g} > 1/2, the "
            "practical maximum; Fa grows with its square (4.14): a larger beta_m or R_1/2 (rule 10)")
    if M.ratio is not None and M.ratio != 1:
        add("note", "sec. 8.5 (6), (7)", f"i = {M.ratio:.4g}: stiffnesses before the output "
            f"member count reduced by i^2 = {M.ratio ** 2:.3g}; rule (6) asks i about 1")
    if not GRAPH_TAU[0] <= M.tau <= GRAPH_TAU[1] or M.Fa > GRAPH_FA:
        add("note", "fig. 4.11", f"(tau, Fa) = ({M.tau:.3g}, {M.Fa:.3g}) lies beyond the printed "
            f"graphs (tau {GRAPH_TAU[0]}-{GRAPH_TAU[1]}, Fa <= {GRAPH_FA:g}); the envelope is "
            "computed here")
    if M.tau < 0.1:
        add("note", "sec. 8.2.6", "tau < 0.1: measured points lie far below the envelope there "
            "(tuning); the envelope is the safe reading")
    if motor_out is not None and not motor_out["rule_8_4"]:
        add("violated", "(8.4)", f"the slip limit {motor_out['delta_lim']:.3g} exceeds the rated "
            f"slip {motor_out['delta_n']:.3g}: the motor would be overloaded")
    add("note", "sec. 8.5 (2), sec. 8.2.8", "the graphs hold without backlash and without damping "
        "(the safe side); with backlash use sec. 3.6 ((3.11), (3.12), (3.16))")
    return out


# -- the whole answer ----------------------------------------------------------------------------
def design(*, stroke, rise_time=None, cam_angle_rad=None, speed=None, mass=None, stiffness=None,
           tau=None, Fa=None, c_tan=None, pitch_radius=None, ratio=None, tan_alpha_me=None,
           accuracy=None, residual_acceleration=None, law="cycloidal", theta=None,
           common_shaft=False, motor_args: dict | None = None, check: bool = True,
           per_dip: int = PER_DIP, progress=None, chart_path=None) -> dict:
    """The thesis's design method (module doc) as one dict (the JSON of `camdyn design`)."""
    say = progress or (lambda msg: None)
    M = machine(stroke=stroke, rise_time=rise_time, cam_angle_rad=cam_angle_rad, speed=speed,
                mass=mass, stiffness=stiffness, tau=tau, Fa=Fa, c_tan=c_tan,
                pitch_radius=pitch_radius, ratio=ratio, tan_alpha_me=tan_alpha_me)
    acc = _positive("accuracy", "--accuracy", accuracy, "m, largest positional error u0")
    a_req = _positive("acceleration", "--residual-acceleration", residual_acceleration,
                      "m/s^2, largest residual acceleration u0''")
    if a_req is not None and M.t_m is None:
        raise CamdynInputError("argument --residual-acceleration: needs the rise time "
                               "(--rise-time, or --cam-angle with --speed): u0'' = U0'' h_m'/t_m^2")
    choice = _laws.choose(law, theta)
    if motor_args is not None:
        if law != "cycloidal":
            raise CamdynInputError("argument --law: the motor rules (8.1)-(8.4) and fig. 8.6 are "
                                   "the cycloid's (its torque H' H'', (A.2.14)); use --law cycloidal "
                                   "with a motor")
        if M.t_m is None:
            raise CamdynInputError("the motor (sec. 8.3) needs the rise time: tau_m = T_m/t_m")
    graphs = Graphs(law, theta, per_dip)
    H1 = float(np.max(np.abs(choice.evaluate(np.linspace(0, 1, 2001))[:, 1])))
    out = {"law": law, "theta": choice.par if theta is not None or law == "modified-sine" else None,
           "machine": {"stroke": M.stroke, "t_m": M.t_m, "T_e": M.T_e, "tau": M.tau,
                       "tan_alpha_me": M.tan_alpha_me, "Fa": M.Fa, "mass": M.mass,
                       "stiffness": M.stiffness, "c_tan": M.c_tan, "beta_m": M.beta_m,
                       "w_s": M.w_s, "ratio": M.ratio, "pitch_radius": M.pitch_radius,
                       "dip": ex.stiffness_dip(M.Fa, H1),
                       "c_min": None if M.stiffness is None else M.stiffness / ex.stiffness_dip(M.Fa, H1),
                       "freq_factor": ex.frequency_factor(M.Fa, H1),
                       "sources": M.sources}}
    say(f"envelope at tau = {M.tau:.4g}, Fa = {M.Fa:.4g}")
    U0e, U2e = graphs.at(M.tau, M.Fa)
    U0f, U2f = graphs.at(M.tau, M.Fa, per_dip=2 * per_dip)      # reported; U0e for its error
    U00, U20 = graphs.at(M.tau, 0.0)
    # the envelope's accuracy: twice the samples per dip; no less than the graph runs' own
    # error (rtol 1e-9: about 1e-8 relative, measured against rtol 1e-11)
    env = {"U0": U0f, "U0_error": max(abs(U0f - U0e), 1e-8 * U0f), "U0dd": U2f,
           "U0dd_error": max(abs(U2f - U2e), 1e-8 * U2f),
           "U0_Fa0": U00, "U0dd_Fa0": U20, "u0": U0f * M.stroke,
           "u0dd": None if M.t_m is None else U2f * M.stroke / M.t_m**2,
           # (8.5) is (3.5)'s envelope for small tau: the cycloid's only
           "eq_8_5_u0": M.stroke * M.tau**3 / math.pi if law == "cycloidal" else None}
    out["envelope"] = env
    req = Requirement(M.stroke, acc, a_req)
    ratio_design = None
    if acc is not None or a_req is not None:
        ratio_design = req.ratio(U0f, U2f, M.t_m)
        out["requirement"] = {"accuracy": acc, "residual_acceleration": a_req,
                              "ratio": float(ratio_design), "met": bool(ratio_design <= 1.0)}
        say("largest Fa at this tau")
        lf = largest_Fa(graphs, M.tau, req, M.t_m)
        if lf.get("Fa_max") is not None and M.tan_alpha_me is not None and M.stiffness is not None:
            lf["c_tan_min"] = M.stiffness * M.tan_alpha_me**2 / lf["Fa_max"]
        if lf.get("Fa_max") and M.Fa > 0:
            # torsion-dominated shaft: c_tan ~ d^4 (sec. 8.2.8, "2^(1/4) = 1.19")
            lf["shaft_diameter_factor"] = (M.Fa / lf["Fa_max"]) ** 0.25
        out["largest_Fa"] = lf
        say("largest tau (smallest t_m) at this Fa")
        lt = largest_tau(graphs, M.Fa, M.tau, req, T_e=M.T_e)
        if lt.get("tau_max") is not None and M.T_e is not None:
            lt["t_m_min"] = M.T_e / lt["tau_max"]
            if lt.get("tau_max_error") is not None:
                lt["t_m_min_error"] = lt["t_m_min"] * lt["tau_max_error"] / lt["tau_max"]
            lt["speed_factor"] = lt["tau_max"] / M.tau
        out["largest_tau"] = lt
        if M.t_m is not None:
            # the same question at this t_m: the softest follower, T_e = tau t_m (sec. 8.6)
            say("largest T_e (least c_c/m) at this t_m")
            le = lt if req.acceleration is None else largest_tau(graphs, M.Fa, M.tau, req, t_m=M.t_m)
            le = {"tau_max": le.get("tau_max"), "tau_max_error": le.get("tau_max_error"),
                  "limited_by": le.get("limited_by"), "reason": le.get("reason")}
            if le["tau_max"] is not None:
                le["T_e_max"] = le["tau_max"] * M.t_m
                if le["tau_max_error"] is not None:
                    le["T_e_max_error"] = le["tau_max_error"] * M.t_m
                if M.mass is not None:
                    le["c_c_min"] = M.mass * (2 * math.pi / le["T_e_max"]) ** 2
            out["largest_T_e"] = le
    motor_out = None
    if motor_args is not None:
        say("motor (sec. 8.3)")
        motor_out = motor(t_m=M.t_m, mass=M.mass, stroke=M.stroke, w_s=M.w_s, **motor_args)
        out["motor"] = motor_out
    out["rules"] = rules(M, ratio_design or 0.0, common_shaft, motor_out,
                         req.which(U0f, U2f, M.t_m) if ratio_design else "accuracy", law)
    if check:
        model, why = least_model(U0f, U00, M.Fa)
        say(f"check run: {model}")
        try:
            run = check_run(model, M.tau, M.Fa, law, theta)
        except SimulationError as exc:
            run = {"failed": str(exc)}
        run.update(model=model, why=why)
        if "U0" in run:
            run["u0"] = run["U0"] * M.stroke
            if ratio_design is not None:
                run["ratio"] = req.ratio(run["U0"], run["U0dd"], M.t_m)
            if M.t_m is not None:
                run["u0dd"] = run["U0dd"] * M.stroke / M.t_m**2
                run["xdd_min_rise"] = run["Xdd_min_rise"] * M.stroke / M.t_m**2
                if M.mass is not None:
                    run["inertia_force_max"] = M.mass * abs(run["xdd_min_rise"])
        out["check_run"] = run
    if chart_path is not None:
        say("chart")
        out["chart"] = chart(out, graphs, M, chart_path)
    out["graph_runs"] = graphs.runs
    return out


def chart_window(tau: float, tau_max: float | None) -> tuple[float, float]:
    """(1/tau_hi, 1/tau_lo) of the chart: the design's tau and the largest tau, with room
    on both sides.  An unmet requirement puts tau_max below tau (the window started at
    0.8 tau and left the largest tau's line beside no envelope)."""
    taus = [tau] + ([tau_max] if tau_max is not None else [])
    return 1.0 / (1.5 * max(taus)), 1.0 / (0.8 * min(taus))


def chart(d: dict, graphs: Graphs, M: Machine, path) -> str:
    """The design on fig. 4.11a's axes: the envelope u0 = U0 h_m' over tau at the design's Fa
    (with its graph), at the largest Fa that meets the requirement and at Fa = 0, the required
    accuracy, the design point and the smallest t_m (largest tau)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lf, lt = d.get("largest_Fa") or {}, d.get("largest_tau") or {}
    x_lo, x_hi = chart_window(M.tau, lt.get("tau_max"))
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    curves = [(M.Fa, f"Fa = {M.Fa:.3g} (design)", "tab:blue")]
    if lf.get("Fa_max") is not None:
        curves.append((lf["Fa_max"], f"Fa = {lf['Fa_max']:.3g} (largest meeting the requirement)",
                       "tab:orange"))
    if M.Fa > 0:
        curves.append((0.0, "Fa = 0 (rigid camshaft)", "0.4"))
    for Fa, label, color in curves:
        # two dip spacings more on either side, so that the drawn part lies between maxima
        w = 2.0 / phase_factor(graphs.law, graphs.theta, Fa)
        t, u0, _ = graphs.samples(max(x_lo - w, 1.0), x_hi + w, Fa)
        env = Upper(t, u0)
        shown = (t >= 1.0 / x_hi) & (t <= 1.0 / x_lo)
        ax.plot(t[shown], env(t[shown]) * M.stroke, color=color, lw=1.8, label=label)
        if Fa == M.Fa:
            ax.plot(t[shown], u0[shown] * M.stroke, color=color, lw=0.6, alpha=0.6)
    req = (d.get("requirement") or {}).get("accuracy")
    if req is not None:
        ax.axhline(req, color="k", ls="--", lw=1, label=f"required u0 <= {req:.3g} m")
    ax.plot([M.tau], [d["envelope"]["u0"]], "o", color="tab:blue", label="design point")
    if lt.get("tau_max") is not None:
        ax.axvline(lt["tau_max"], color="tab:green", ls=":", lw=1.2,
                   label=f"largest tau {lt['tau_max']:.4g}"
                         + (f" (t_m >= {lt['t_m_min']:.4g} s)" if lt.get("t_m_min") else ""))
    ax.set_yscale("log")
    ax.set_xlabel("tau = T_e / t_m")
    ax.set_ylabel("u0 = U0 h_m'  [m]  (envelope through the maxima)")
    ax.set_title(f"camdyn design: {d['law']} law, stroke {M.stroke:g} m", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7.5, loc="lower right")
    fig.tight_layout()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return str(path)


# -- text ----------------------------------------------------------------------------------------
def _g(v, digits=4) -> str:
    if v is None:
        return "-"
    if isinstance(v, bool):
        return "yes" if v else "no"
    return f"{v:.{digits}g}"


def _pm(v, e, digits=4) -> str:
    return _g(v, digits) + (f" ± {e:.2g}" if e is not None else "")


def text(d: dict) -> str:
    """The answer of `camdyn design` as lines of text."""
    M = d["machine"]
    L = [f"camdyn design: {d['law']} rise" + (f" (theta {d['theta']:g})" if d.get("theta") else "")]
    L.append("machine (App. 7 (5)-(12))")
    for key, label, unit in (("stroke", "h_m'", "m"), ("beta_m", "beta_m", "rad"),
                             ("w_s", "w_s", "rad/s"), ("t_m", "t_m", "s"), ("mass", "m", "kg"),
                             ("stiffness", "c_c", "N/m"), ("T_e", "T_e", "s"), ("tau", "tau", ""),
                             ("tan_alpha_me", "tan alpha_me", ""), ("c_tan", "c_tan", "N/m"),
                             ("Fa", "Fa", ""), ("dip", "c_max/c_min", ""), ("c_min", "c_min", "N/m")):
        if M.get(key) is not None:
            src = M["sources"].get(key, "")
            L.append(f"  {label:<14}{_g(M[key]):>12} {unit:<6}{src}")
    e = d["envelope"]
    L.append("envelope through the maxima of fig. 4.11 (CAMSHAFT-1), at the design point")
    eq85 = f"; (8.5): u0 ~ {_g(e['eq_8_5_u0'])} m" if e["eq_8_5_u0"] is not None else ""
    L.append(f"  U0   = {_pm(e['U0'], e['U0_error'])}   u0 = U0 h_m' = {_g(e['u0'])} m"
             f"   (Fa = 0: {_g(e['U0_Fa0'])}{eq85})")
    L.append(f"  U0'' = {_pm(e['U0dd'], e['U0dd_error'])}" +
             (f"   u0'' = U0'' h_m'/t_m^2 = {_g(e['u0dd'])} m/s^2" if e["u0dd"] is not None else ""))
    if "requirement" in d:
        r = d["requirement"]
        want = " and ".join(s for s in (
            f"u0 <= {_g(r['accuracy'])} m" if r["accuracy"] is not None else "",
            f"u0'' <= {_g(r['residual_acceleration'])} m/s^2"
            if r["residual_acceleration"] is not None else "") if s)
        L.append(f"requirement {want}: {'met' if r['met'] else 'NOT met'} "
                 f"(envelope/requirement = {_g(r['ratio'])})")
        lf = d["largest_Fa"]
        if lf.get("Fa_max") is None:
            L.append(f"  largest Fa at tau = {_g(M['tau'])}: none ({lf['reason']})")
        else:
            extra = ""
            if lf.get("c_tan_min") is not None:
                extra += f", least c_tan = {_g(lf['c_tan_min'])} N/m"
            if lf.get("shaft_diameter_factor") is not None:
                extra += (f", shaft diameter x {_g(lf['shaft_diameter_factor'], 3)} if torsion "
                          "sets c_tan (~ d^4, sec. 8.2.8)")
            L.append(f"  largest Fa at tau = {_g(M['tau'])}: {_pm(lf['Fa_max'], lf['Fa_max_error'])}"
                     f" (limited by {lf['limited_by']}){extra}")
        lt = d["largest_tau"]
        if lt.get("tau_max") is None:
            L.append(f"  largest tau at Fa = {_g(M['Fa'])}: none ({lt['reason']})")
        else:
            extra = ""
            if lt.get("t_m_min") is not None:
                extra += (f"; smallest t_m = {_pm(lt['t_m_min'], lt.get('t_m_min_error'))} s "
                          f"(speed x {_g(lt['speed_factor'], 3)})")
            if lt.get("beyond_last_maximum"):
                extra += ("; NB past the graph's last maximum, where it dips again: the envelope "
                          "is held flat there and may read low")
            L.append(f"  largest tau at Fa = {_g(M['Fa'])}, this T_e: "
                     f"{_pm(lt['tau_max'], lt['tau_max_error'])} (limited by {lt['limited_by']}){extra}")
        le = d.get("largest_T_e")
        if le is not None and le.get("T_e_max") is not None:
            extra = f", c_c >= {_g(le['c_c_min'])} N/m at this m" if le.get("c_c_min") else ""
            L.append(f"  largest T_e at this t_m: {_pm(le['T_e_max'], le.get('T_e_max_error'))} s "
                     f"(tau {_g(le['tau_max'])}, limited by {le['limited_by']}){extra}")
    if "motor" in d:
        m = d["motor"]
        L.append("motor (sec. 8.3)")
        L.append(f"  tau_m = T_m/t_m = {_g(m['tau_m'])}; peak slip delta_max/delta_n = "
                 f"{_g(m['slip_peak_rel'])} at P = 1 (fig. 8.6, at T = {_g(m['T_slip_peak'], 3)})")
        L.append(f"  P = {_g(m['P'])} (8.1) with v_v = {m['v_v']}, eta_g = {_g(m['eta_g'])}, "
                 f"delta_n = {_g(m['delta_n'])}, delta_lim = {_g(m['delta_lim'])}")
        if m["M_ena"] is not None:
            L.append(f"  rated torque at the camshaft M_ena = {_g(m['M_ena'])} N m (8.2)")
        if m["N_n"] is not None:
            L.append(f"  rated power N_n = {_g(m['N_n'])} W (8.3)")
        L.append(f"  (8.4) delta_lim <= delta_n: {_g(m['rule_8_4'])}")
    L.append("rules (secs 8.2-8.5)")
    for r in d["rules"]:
        L.append(f"  {r['status']:<9}{r['rule']}: {r['text']}")
    if "check_run" in d:
        c = d["check_run"]
        L.append(f"check run: {c['model']} ({c['why']})")
        if "failed" in c:
            L.append(f"  failed: {c['failed']}")
        else:
            L.append(f"  U0   = {_pm(c['U0'], c.get('U0_error'), 6)}  (envelope {_g(e['U0'])})")
            L.append(f"  U0'' = {_pm(c['U0dd'], c.get('U0dd_error'), 6)}  (envelope {_g(e['U0dd'])})")
            L.append(f"  X''min during the rise = {_pm(c['Xdd_min_rise'], c.get('Xdd_min_rise_error'), 6)}"
                     f" at T = {_g(c['T_at_Xdd_min'], 4)}" +
                     (f"; x''min = {_g(c['xdd_min_rise'])} m/s^2" if c.get("xdd_min_rise") else "") +
                     (f", inertia force {_g(c['inertia_force_max'])} N" if c.get("inertia_force_max")
                      else ""))
            if c.get("ratio") is not None:
                L.append(f"  the run against the requirement: {_g(c['ratio'])} "
                         f"({'met' if c['ratio'] <= 1 else 'NOT met'}; at a tuning dip the run "
                         "may meet what the envelope does not)")
    return "\n".join(L)
