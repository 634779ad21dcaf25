"""The follower's spring over the whole turn, across the speed band and beyond it (secs 4.5.5,
7.5).

The follower stays on the cam while the contact force, the output's inertia force plus the
spring's,

    F(T) = F0 + k x(T) + m x''(T),        x = h_m' X,  x'' = h_m' X'' w^2/beta_m^2,

stays positive (load.py's Q = M omega^2 m'' + k m + Q_0 at the output); where the output
decelerates faster than the spring pulls it back the follower jumps (sec. 7.5, fig. 7.22).

* The least preload at the top speed, kinetostatic (the rigid follower X = H of the law's closed
  form) and dynamic (the Ladder's model driven by the whole turn from rest over one turn, its
  follower elasticity included), with the margin mu: F0 + k x >= (1 + mu)(-m x'') at every T.
  That is `camdyn design`'s sizing over the whole turn (:func:`..spring_flywheel.spring`, its
  errors and binding places; its least preload alone, :func:`..spring_flywheel.least_preload`),
  here at the band's top speed with the machine's spring.
* The preload used: the designer's, or the larger of the two least preloads (the dynamic one
  but where the elastic follower happens to decelerate less than the rigid one, so that
  `camdyn profile`'s kinetostatic check of the cam holds with it too).
* The jump speed, the lowest speed at which the spring as used lets the follower leave the
  cam (its least contact force over the turn reaches 0).  Kinetostatic it is a closed form:
  F = A(T) + B(T) w^2 with A = F0 + k h_m' H, B = m h_m' H''/beta_m^2, so the force first
  reaches zero at w_j^2 = min over H'' < 0 of A/(-B), found by refining that minimum over the
  turn (exact to the refinement; the least force against w^2 is concave, so this crossing is
  the only one).  Dynamic the follower's vibration depends on tau, proportional to w: the
  least force is scanned against the speed (the jump margin chart, points evenly spaced in
  1/tau, SCAN_PER_TAU to a unit, which is about the spacing of the residual vibration's
  lobes; runs at SCAN_RTOL) and its first sign change refined by Brent's method (bisection
  safeguarded) on the speed to JUMP_XTOL (runs at JUMP_RTOL).  A dip below zero narrower than
  the chart's spacing could escape the scan; the chart is dense enough in 1/tau that each lobe
  of the residual vibration has two points or more.  ``dynamic_jump=False`` leaves the dynamic
  chart and search out (the kinetostatic ones alone), for an answer that must be quick.
* The contact force over the turn at the band's lowest and top speed (the Ladder's model),
  and the jump margin chart (the least contact force over the turn against the speed, from
  the lowest speed to BEYOND times the top speed), kinetostatic and dynamic.

Errors: the runs' as the answer contract states them (the run one notch tighter, its
difference times the method's factor; for a chart's point the largest difference of the two
runs' forces over the turn, which bounds that of their least values), plus what the
refinement of each extreme leaves (:func:`..extremes.largest`, :func:`least`); a chart's
point is its run's least recorded value, its error adding how far below it the curvature lets
the force reach between the points.  The jump speed's adds the search's bracket and the
contact force's error over its slope in the speed.  The spring acts on the output mass without
changing the follower's own frequency (as `camdyn design`'s sizing: its rate is small beside
the train's stiffness, which the warnings check).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from camdyn.runtime.core.errors import CamdynInputError, SimulationError
from camdyn.runtime.targets.model_target import ModelTarget
from camdyn.thesis.numerics import EPS

from ..check_run import RTOL
from ..extremes import XATOL, ZOOM, largest
from ..spring_flywheel import LawMotion, Motions, RunMotion, least_preload
from ..turn import CamTurn
from . import units
from .spec import Machine

SCAN_RTOL = 1e-5
"""The tolerance of the jump margin chart's runs (DP54; its estimate from the run one notch
tighter): the contact force to some 1e-4 of itself, below what a chart shows, at a tenth of
the sizing runs' cost."""

JUMP_RTOL = 1e-7
"""The tolerance of the jump speed's search (DP54): the contact force to some 1e-6 of itself,
the speed to some 1e-5 of itself."""

SCAN_PER_TAU = 2.0
"""Speeds of the jump margin chart per unit of 1/tau: the residual vibration's lobes lie about
one unit of 1/tau apart (the cycloid's zeros at tau = 1/n, (3.5)), so each has two points."""

SCAN_POINTS = (9, 41)
"""The fewest and the most speeds of the chart."""

BEYOND = 2.0
"""How far beyond the top speed the jump speed is sought: None beyond BEYOND times it."""

JUMP_XTOL = 1e-5
"""The bracket of the jump speed's search, relative to the speed."""

THETA_POINTS = 2881
"""Cam angles of the contact force over the turn (0 to 360 deg, every eighth of a degree: the
stress takes the force interpolated between them, which errs by h^2/8 |F''|)."""

SCAN_XATOL = 1e-6
"""The bracket in T to which a least contact force is refined: it leaves |F''| 5e-13, some
1e-9 N of a follower's force, below the runs' own error by orders of magnitude."""

LAW_SAMPLES = 400
"""Points per unit of T on which the rigid follower's least contact force is sought between
the law's segment ends (then refined)."""

SPRING_STIFFNESS = 0.05
"""A spring rate above this fraction of the train's stiffness is warned of: the models leave
the spring out of the follower's own frequency."""


@dataclass(frozen=True)
class SpringAnswer:
    """The spring of one law (module doc), SI at the output (a rocker's roller), angles in deg;
    each figure's estimate beside it in ``*_error`` (None: no estimate could be made, said in
    ``warnings``)."""

    law: str
    model: str
    speed: float
    """The top speed (rad/s) the least preloads are sized at."""
    margin: float
    rate: float
    preload_min_kinetostatic: float
    preload_min_kinetostatic_error: float
    binding_part_kinetostatic: str
    binding_angle_deg_kinetostatic: float
    binding_angle_deg_kinetostatic_error: float
    preload_min: float
    preload_min_error: float | None
    binding_part: str
    binding_angle_deg: float
    binding_angle_deg_error: float | None
    preload_used: float
    preload_used_error: float | None
    preload_given: bool
    torque_at_pivot: float | None
    torque_at_pivot_error: float | None
    rate_at_pivot: float | None
    contact_force_min: float
    """The least contact force over the turn at the top speed with the preload used (dynamic)."""
    contact_force_min_error: float | None
    jump_speed: float | None
    jump_speed_error: float | None
    jump_speed_kinetostatic: float | None
    jump_speed_kinetostatic_error: float | None
    jump_speed_dynamic: float | None
    jump_speed_dynamic_error: float | None
    jump_speed_how: str
    theta_deg: np.ndarray
    contact_force_lo: np.ndarray
    contact_force_lo_error: np.ndarray
    contact_force_hi: np.ndarray
    contact_force_hi_error: np.ndarray
    contact_force_lo_kinetostatic: np.ndarray
    contact_force_hi_kinetostatic: np.ndarray
    jump_margin_speeds: np.ndarray
    jump_margin: np.ndarray
    jump_margin_error: np.ndarray
    jump_margin_kinetostatic: np.ndarray
    jump_margin_kinetostatic_error: np.ndarray
    warnings: tuple


# -- the turn and the Ladder's model driven by it -------------------------------------------------

def cam_turn(m: Machine, law, theta=None) -> CamTurn:
    """The machine's whole turn with ``law`` rising and (mirrored) returning."""
    return CamTurn.of(law, theta, m.angles, m.rise_angle)


def model_at(ladder, tau: float) -> tuple[str, dict] | None:
    """(model, parameters) of the Ladder's model at ``tau``, or None where it does not take
    tau: the one-DOF model's tau < 1 (beyond it, undamped, it is CAMSHAFT-1 at Fa = 0, the same
    equations (4.15) with a range to 10); CAMSHAFT-1 and -2 take tau <= 10."""
    params = {**dict(ladder.params), "tau": float(tau)}
    if ladder.model == "one_dof":
        if tau < 1.0:
            return "one_dof", params
        if not params.get("q"):
            return "camshaft1", {"tau": float(tau), "Fa": 0.0}
        return None
    return (ladder.model, params) if tau <= 10.0 else None


@dataclass(frozen=True)
class TurnRun:
    """One turn from rest of the Ladder's model at the speed ``w`` (rad/s), and the run one
    notch tighter (None: no estimate, ``why``), with the contract's factor on their
    difference."""

    w: float
    tau: float
    t_m: float
    model: str
    result: object
    tight: object
    factor: float
    why: str | None
    warnings: tuple


def _key(ladder) -> tuple:
    return ladder.model, tuple(sorted(dict(ladder.params).items()))


def turn_run(m: Machine, law, theta, ladder, w: float, rtol: float = RTOL,
             twin: bool = True) -> TurnRun:
    """The Ladder's model driven by the whole turn from rest over one turn at ``w`` (DP54 at
    ``rtol``), as `camdyn design`'s whole-turn run (check_run.turn_runs) for any model of the
    ladder, and with ``twin`` the run one notch tighter as the answer contract makes it; the
    runs are kept for the figures that share them (the spring's, the drive's)."""
    return _turn_run(m, law, theta, _key(ladder), float(w), float(rtol), bool(twin))


@lru_cache(maxsize=128)
def _turn_run(m, law, theta, ladder_key, w, rtol, twin) -> TurnRun:
    tau = m.tau(w)
    chosen = model_at(_Ladder(ladder_key[0], dict(ladder_key[1])), tau)
    if chosen is None:
        raise CamdynInputError(f"the {ladder_key[0]} model does not take tau = {tau:.4g} (at "
                               f"{w:.4g} rad/s)")
    model, params = chosen
    sim, tight_sim, factor, why = _simulators(m, law, theta, model, rtol)
    base = sim.run(params)
    tight = None
    if twin and tight_sim is not None:
        try:
            tight = tight_sim.run(params)
        except (SimulationError, CamdynInputError) as exc:
            why = f"the run one notch tighter failed ({exc})"
    return TurnRun(w, tau, m.rise_angle / w, model, base, tight, factor,
                   why if twin else None, tuple(getattr(base, "warnings", ()) or ()))


@lru_cache(maxsize=32)
def _simulators(m, law, theta, model, rtol) -> tuple:
    """(simulator, the one a notch tighter or None, the contract's factor, why there is none) of
    ``model`` driven by the machine's turn over one turn: made once, run at every speed."""
    turn = cam_turn(m, law, theta)
    target = ModelTarget.of(model, None, method="dp54", rtol=rtol, law=turn.drive,
                            t_end=turn.end)
    tighter = target.tighter()
    why = None if tighter is not None else f"rtol={rtol:g} has no tighter notch"
    return (target.simulator, None if tighter is None else tighter.simulator,
            target.method().estimate_factor, why)


@dataclass(frozen=True)
class _Ladder:
    model: str
    params: dict


# -- contact forces over the turn ------------------------------------------------------------------

def force_of(m: Machine, F0: float, x, a):
    """F = F0 + k x + m x'' (N at the output): the contact force of the output at x with the
    acceleration x'' (load.py's Q = M omega^2 m'' + k m + Q_0), shared with the drive's torque."""
    return F0 + m.output_spring_rate * x + m.output_mass * a


def run_force(m: Machine, result, t_m: float, F0: float, T) -> np.ndarray:
    """The contact force (N) of a run at T (units of the rise)."""
    s = result.sample(np.clip(T, result.t[0], result.t[-1]))
    h = m.output_stroke
    return force_of(m, F0, s["X"] * h, s["Xdd"] * h / t_m**2)


def at_cam(result, B) -> np.ndarray:
    """The times (units of the rise) at which a run's cam stands at the angles B (units of the
    rise): B itself where the cam turns evenly, and where the model turns it by a state B of
    its own (CAMSHAFT-2's variable speed, (5.15)) the times its recorded B passes them, linear
    between the recorded points (which lie a fraction of its vibration's period apart; past
    the run's last B, its end)."""
    B = np.asarray(B, dtype=float)
    if "B" not in result.state_names:
        return B
    return np.interp(B, result["B"], result.t)


def law_force(m: Machine, turn: CamTurn, w: float, F0: float, T) -> np.ndarray:
    """The kinetostatic contact force (N) of the rigid follower at T and the speed w."""
    H = turn.motion(T)
    h = m.output_stroke
    return force_of(m, F0, H[0] * h, H[2] * h * w**2 / m.rise_angle**2)


def _run_grid(result) -> np.ndarray:
    """The run's recorded points (every accepted step), where its states and outputs are known
    without the dense output's cost."""
    return np.asarray(result.t, dtype=float)


def _recorded_force(m: Machine, result, t_m: float, F0: float) -> np.ndarray:
    h = m.output_stroke
    return force_of(m, F0, result["X"] * h, result["Xdd"] * h / t_m**2)


def _zoom(g, lo: float, hi: float) -> tuple[float, float]:
    """(T, g(T)) at the least value of g on [lo, hi], g unimodal there: grids of ZOOM points
    each over the two steps around the best of the one before, down to SCAN_XATOL
    (:func:`..extremes.zoom`'s passes, stopped where the value no longer moves)."""
    x, fx = lo, math.inf
    while True:
        T = np.linspace(lo, hi, ZOOM)
        v = np.asarray(g(T), dtype=float)
        j = int(np.argmin(v))
        if v[j] < fx:
            x, fx = float(T[j]), float(v[j])
        step = T[1] - T[0]
        if 2 * step <= SCAN_XATOL:
            return x, fx
        lo, hi = max(lo, x - step), min(hi, x + step)


def least(g, grid: np.ndarray, values=None, refine: bool = True) -> tuple[float, float, float]:
    """(least value of g over the grid's span, what the refinement leaves of it, T there): the
    grid's least point, and every local minimum of the grid that its curvature lets reach
    below it (|g''| h^2/2, the second difference), refined by :func:`_zoom` to SCAN_XATOL;
    its error is the refinement's |g''| SCAN_XATOL^2/2 and the rounding, 8 eps |g|.  One
    refinement where :func:`..extremes.largest` makes three and a check of the rounding around
    it: the scan's many runs afford no more, and their estimate (the runs' difference over the
    whole turn) is far larger than what either leaves.  Without ``refine`` (a chart's point)
    it is the grid's least value, its error how far below it the curvature lets the function
    reach between the points."""
    v = np.asarray(g(grid) if values is None else values, dtype=float)
    n = v.size
    left = np.r_[True, v[1:] <= v[:-1]]
    right = np.r_[v[:-1] <= v[1:], True]
    idx = np.flatnonzero(left & right)
    lo, hi = np.maximum(idx - 1, 0), np.minimum(idx + 1, n - 1)
    h1, h2 = grid[idx] - grid[lo], grid[hi] - grid[idx]
    inner = (idx > 0) & (idx < n - 1)
    with np.errstate(divide="ignore", invalid="ignore"):
        curv = np.where(inner, 2 * ((v[hi] - v[idx]) / h2 - (v[idx] - v[lo]) / h1) / (h1 + h2),
                        0.0)
    curv = np.where(np.isfinite(curv), np.abs(curv), 0.0)
    reach = v[idx] - 0.5 * curv * np.maximum(h1, h2) ** 2
    best = float(v[idx].min())
    T, value, c_at = float(grid[idx[int(np.argmin(v[idx]))]]), best, 0.0
    first = int(np.argmin(v[idx]))
    if not refine:
        return best, best - min(best, float(reach.min())) + 8 * EPS * abs(best), T
    for j in sorted(set(np.flatnonzero(reach < best).tolist()) | {first}):
        i = idx[j]
        x, fx = float(grid[i]), float(v[i])
        if grid[hi[j]] - grid[lo[j]] > SCAN_XATOL:
            xr, fr = _zoom(g, grid[lo[j]], grid[hi[j]])
            if fr < fx:
                x, fx = xr, fr
        if fx < value or (fx == value and x == T):
            T, value, c_at = x, fx, curv[j]
    return value, 0.5 * c_at * SCAN_XATOL**2 + 8 * EPS * abs(value), T


def _least_run_force(m, result, t_m, F0, refine=True) -> tuple[float, float, float]:
    """(least contact force, its refinement's error, T there) of one run over the turn: on its
    recorded points, refined on its dense output."""
    return least(lambda T: run_force(m, result, t_m, F0, T), _run_grid(result),
                 _recorded_force(m, result, t_m, F0), refine)


def least_dynamic(m: Machine, run: TurnRun, F0: float, refine: bool = True,
                  twin_least: bool = False) -> tuple:
    """(least contact force over the turn, its error or None, T there) of a TurnRun.  The error:
    the contract's factor times the largest difference of the two runs' contact forces over
    the turn (on the run's grid; it bounds the difference of their least values), and what the
    refinement leaves; with ``twin_least`` the contract's own rule, the factor times the
    difference of the two runs' least values (each refined)."""
    v, ev, T = _least_run_force(m, run.result, run.t_m, F0, refine)
    if run.tight is None:
        return v, None, T
    if twin_least:
        vt, evt, _ = _least_run_force(m, run.tight, run.t_m, F0, True)
        return v, run.factor * abs(v - vt) + ev + evt, T
    grid = _run_grid(run.result)
    diff = np.max(np.abs(run_force(m, run.tight, run.t_m, F0, grid)
                         - _recorded_force(m, run.result, run.t_m, F0)))
    return v, run.factor * float(diff) + ev, T


class _LawForce:
    """The rigid follower's contact force A(T) + B(T) w^2 (module doc) on the law's grids
    between its segment ends, A and B kept for every speed."""

    def __init__(self, m: Machine, turn: CamTurn, F0: float):
        self.m, self.turn, self.F0 = m, turn, F0
        self.grid = np.concatenate([np.linspace(a + XATOL / 10, b - XATOL / 10,
                                                max(3, int(LAW_SAMPLES * (b - a)) + 1))
                                    for a, b in turn.pieces()])
        self.A, self.B = self.parts(self.grid)

    def parts(self, T):
        m = self.m
        H = self.turn.motion(T)
        h = m.output_stroke
        return (self.F0 + m.output_spring_rate * h * H[0],
                m.output_mass * h * H[2] / m.rise_angle**2)

    def least(self, w: float, refine: bool = True) -> tuple[float, float, float]:
        def g(T):
            A, B = self.parts(T)
            return A + B * w * w
        return least(g, self.grid, self.A + self.B * w * w, refine)


def least_kinetostatic(m: Machine, turn: CamTurn, w: float, F0: float) -> tuple:
    """(least contact force over the turn, its refinement's error, T there) of the rigid
    follower at w, refined on the law's closed form between its segment ends."""
    return _LawForce(m, turn, F0).least(w)


# -- the jump speed ------------------------------------------------------------------------------

def jump_kinetostatic(m: Machine, turn: CamTurn, F0: float) -> tuple:
    """(w_j, its error, T there): the speed at which the rigid follower's least contact force
    over the turn first reaches 0, w_j^2 = beta_m^2 min over H'' < 0 of (F0 + k h H)/(m h
    (-H'')) (module doc); (inf, 0, nan) where H'' < 0 nowhere."""
    h, k, mass, beta = m.output_stroke, m.output_spring_rate, m.output_mass, m.rise_angle

    def neg_w2(T):
        H = turn.motion(T)
        with np.errstate(divide="ignore", invalid="ignore"):
            w2 = beta**2 * (F0 + k * h * H[0]) / (mass * h * -H[2])
        return np.where(H[2] < 0, -w2, -np.inf)
    grids = LawMotion(turn, stroke=h, t_m=1.0).grids
    e = largest(neg_w2, grids)
    if not math.isfinite(e.value):
        return math.inf, 0.0, math.nan
    w2, ew2 = max(0.0, -e.value), e.error
    w = math.sqrt(w2)
    # dw = dw2/(2 w); where w2 is not told from zero, w is known to sqrt(error)
    err = ew2 / (2 * w) if w2 > ew2 else math.sqrt(ew2 + w2)
    return w, err, e.T


def scan_speeds(m: Machine, ladder) -> np.ndarray:
    """The jump margin chart's speeds, lowest of the band to BEYOND times the top, evenly
    spaced in 1/tau (SCAN_PER_TAU a unit, SCAN_POINTS), the band's ends among them; cut where
    the Ladder's model takes no larger tau."""
    lo, hi = m.speeds
    top = BEYOND * hi
    while model_at(ladder, m.tau(top)) is None and top > hi:
        top = max(hi, 0.9 * top)
    span = 1.0 / m.tau(lo) - 1.0 / m.tau(top)
    n = int(np.clip(math.ceil(SCAN_PER_TAU * span) + 1, *SCAN_POINTS))
    inv = np.linspace(1.0 / lo, 1.0 / top, n)
    return np.unique(np.append(1.0 / inv, [lo, hi, top]))


def _jump_dynamic(m, law, theta, ladder, F0, speeds, margins) -> tuple:
    """(w_j, its error, how): the first sign change of the dynamic least contact force along
    ``speeds`` refined by Brent's method to JUMP_XTOL (module doc)."""
    from scipy.optimize import brentq

    def f(w):
        run = turn_run(m, law, theta, ladder, w, JUMP_RTOL, twin=False)
        return _least_run_force(m, run.result, run.t_m, F0)[0]

    below = np.flatnonzero(margins <= 0.0)
    if below.size == 0:
        return None, None, (f"the least contact force stays positive up to {BEYOND:g} times the "
                            "top speed")
    i = int(below[0])
    if i == 0:                       # below the band: halve the speed until it holds
        hi_w, lo_w = speeds[0], speeds[0] / 2
        while f(lo_w) <= 0.0:
            if lo_w < speeds[0] / 8:
                return lo_w / 2, lo_w / 2, (f"the follower leaves the cam below an eighth of "
                                            f"the lowest speed, {lo_w:.4g} rad/s")
            hi_w, lo_w = lo_w, lo_w / 2
    else:
        lo_w, hi_w = speeds[i - 1], speeds[i]
    spread = 0.0
    try:
        w = brentq(f, lo_w, hi_w, xtol=JUMP_XTOL * hi_w * 0.5, rtol=4 * np.finfo(float).eps)
    except ValueError:
        # the chart's runs and the search's differ in sign at an end (a force within their
        # errors of zero there): the crossing is somewhere in the bracket
        w, spread = (lo_w if f(lo_w) <= 0.0 else hi_w), hi_w - lo_w
    # the root's error: the bracket, and the contact force's error at the root over its slope
    dw = 1e-3 * w
    slope = (f(w + dw) - f(w - dw)) / (2 * dw)
    run = turn_run(m, law, theta, ladder, w, JUMP_RTOL)
    _, eF, _ = least_dynamic(m, run, F0, twin_least=True)
    if eF is None or slope == 0.0:
        return w, None, "Brent's method on the speed (no estimate of the force's error)"
    return w, spread + JUMP_XTOL * w + eF / abs(slope), (
        f"the least contact force's first sign change along the chart, between "
        f"{_speed(m, lo_w)} and {_speed(m, hi_w)}, refined by Brent's method to {JUMP_XTOL:g} "
        "of the speed")


# -- the answer ----------------------------------------------------------------------------------

def spring(m: Machine, law, ladder, theta=None, dynamic_jump: bool = True) -> SpringAnswer:
    """The spring of ``law`` on the machine ``m`` with the Ladder's model (module doc); with
    ``dynamic_jump`` False the jump margin and jump speed are the kinetostatic ones only
    (the designer's quick answer)."""
    w_lo, w_hi = m.speeds
    turn = cam_turn(m, law, theta)
    h, k, mass = m.output_stroke, m.output_spring_rate, m.output_mass
    warnings = _law_warnings(m, turn)
    # the least preloads at the top speed: camdyn design's sizing over the whole turn
    top = turn_run(m, law, theta, ladder, w_hi)
    motions = Motions(turn, LawMotion(turn, stroke=h, t_m=top.t_m),
                      RunMotion(top.result, stroke=h, t_m=top.t_m),
                      None if top.tight is None else RunMotion(top.tight, stroke=h, t_m=top.t_m),
                      "one turn from rest at the top speed", [])
    sp = least_preload(motions, mass=mass, stroke=h, t_m=top.t_m, margin=m.spring_margin,
                       rate=None if m.spring_rate is None else k, tau=top.tau)
    warnings += sp["warnings"]
    if top.why is not None:
        warnings.append(f"no error estimate of the dynamic figures: {top.why}")
    kin, dyn = sp["kinetostatic"], sp["dynamic"]
    given = m.output_spring_preload is not None
    if given:
        used, used_error = m.output_spring_preload, 0.0
    else:
        pick = dyn if dyn["preload_min"] >= kin["preload_min"] else kin
        used, used_error = pick["preload_min"], pick["preload_min_error"]
    # contact forces over the turn at the band's ends, with the preload used
    theta_deg = np.linspace(0.0, 360.0, THETA_POINTS)
    T = theta_deg / m.angles[0]
    lo = turn_run(m, law, theta, ladder, w_lo) if w_lo != w_hi else top
    arrays = {}
    for name, run in (("lo", lo), ("hi", top)):
        F = run_force(m, run.result, run.t_m, used, at_cam(run.result, T))
        eF = (np.full_like(F, np.nan) if run.tight is None else run.factor * np.abs(
            F - run_force(m, run.tight, run.t_m, used, at_cam(run.tight, T))))
        arrays[name] = (F, eF, law_force(m, turn, run.w, used, T))
    least, least_e, _ = least_dynamic(m, top, used)
    # the jump margin and the jump speed
    speeds = scan_speeds(m, ladder)
    kin_margin = _margin(_LawForce(m, turn, used).least, speeds)
    wk, ewk, _ = jump_kinetostatic(m, turn, used)
    kin_jump = (None, None) if wk > BEYOND * w_hi else (wk, ewk)
    if dynamic_jump:
        dyn_margin = _margin(lambda w, refine: _or_nan(least_dynamic(
            m, turn_run(m, law, theta, ladder, w, SCAN_RTOL), used, refine)[:2]), speeds)
        wd, ewd, how = _jump_dynamic(m, law, theta, ladder, used, speeds, dyn_margin[:, 0])
        jump, jump_e = wd, ewd
    else:
        dyn_margin = np.full((speeds.size, 2), np.nan)
        wd, ewd = None, None
        jump, jump_e = kin_jump
        how = "kinetostatic only: the rigid follower's closed form (module doc)"
    need = max(kin["preload_min"], dyn["preload_min"])
    warnings += _spring_warnings(m, need, used, given, least, jump, speeds,
                                 dyn_margin[:, 0] if dynamic_jump else kin_margin[:, 0],
                                 dynamic_jump)
    l = m.lever if m.rocker else None
    return SpringAnswer(
        law=law_name(law), model=top.model, speed=w_hi, margin=m.spring_margin, rate=k,
        preload_min_kinetostatic=kin["preload_min"],
        preload_min_kinetostatic_error=kin["preload_min_error"],
        binding_part_kinetostatic=kin["binding"]["part"],
        binding_angle_deg_kinetostatic=_deg(kin["binding"]["cam_angle"]),
        binding_angle_deg_kinetostatic_error=_deg(kin["binding"]["cam_angle_error"]),
        preload_min=dyn["preload_min"], preload_min_error=dyn["preload_min_error"],
        binding_part=dyn["binding"]["part"],
        binding_angle_deg=_deg(dyn["binding"]["cam_angle"]),
        binding_angle_deg_error=_plus(_deg(dyn["binding"]["cam_angle_error"]),
                                      _lag(top.result) * m.angles[0]),
        preload_used=used, preload_used_error=used_error, preload_given=given,
        torque_at_pivot=None if l is None else used * l,
        torque_at_pivot_error=None if l is None or used_error is None else used_error * l,
        rate_at_pivot=None if l is None else k * l**2,
        contact_force_min=least, contact_force_min_error=least_e,
        jump_speed=jump, jump_speed_error=jump_e,
        jump_speed_kinetostatic=kin_jump[0], jump_speed_kinetostatic_error=kin_jump[1],
        jump_speed_dynamic=wd, jump_speed_dynamic_error=ewd, jump_speed_how=how,
        theta_deg=theta_deg,
        contact_force_lo=arrays["lo"][0], contact_force_lo_error=arrays["lo"][1],
        contact_force_hi=arrays["hi"][0], contact_force_hi_error=arrays["hi"][1],
        contact_force_lo_kinetostatic=arrays["lo"][2],
        contact_force_hi_kinetostatic=arrays["hi"][2],
        jump_margin_speeds=speeds, jump_margin=dyn_margin[:, 0],
        jump_margin_error=dyn_margin[:, 1], jump_margin_kinetostatic=kin_margin[:, 0],
        jump_margin_kinetostatic_error=kin_margin[:, 1], warnings=tuple(warnings))


def _margin(least_at, speeds) -> np.ndarray:
    """Rows (least contact force, its error) at each speed: the grid's least (a chart's point),
    refined where its error does not tell its sign (the jump speed's bracket is read off it)."""
    out = np.array([least_at(w, False)[:2] for w in speeds], dtype=float)
    for i in np.flatnonzero(out[:, 0] - out[:, 1] <= 0.0):
        if out[i, 0] > 0.0:
            out[i] = least_at(speeds[i], True)[:2]
    return out


def _lag(result) -> float:
    """How far a run's cam angle B strays from T (units of the rise) over the run: 0 where the
    cam turns evenly; the places the sizing gives in T are cam angles within it."""
    if "B" not in result.state_names:
        return 0.0
    return float(np.max(np.abs(result["B"] - result.t)))


def _plus(a, b):
    return None if a is None else a + b


def _or_nan(pair):
    v, e = pair
    return v, (math.nan if e is None else e)


def _deg(rad):
    return None if rad is None else math.degrees(rad)


def law_name(law) -> str:
    """A law's name: its own where it is one, a shaped law's key (a law file's)."""
    return law if isinstance(law, str) else getattr(law, "key", str(law))


def _law_warnings(m: Machine, turn: CamTurn) -> list:
    """A law whose velocity jumps: its acceleration is an impulse there, which no spring holds
    (the figures are those between the jumps); a spring stiff beside the train."""
    out = []
    b = np.array([x for x in turn.drive.breakpoints() if 0.0 < x < turn.end] + [0.0, turn.end])
    d = 1e-9
    left = turn.motion(np.clip(b - d, 0.0, turn.end))[1]
    right = turn.motion(np.clip(b + d, 0.0, turn.end))[1]
    scale = np.max(np.abs(turn.motion(np.linspace(0.0, turn.end, 2001))[1]))
    jumps = np.abs(right - left) > 1e-6 * scale
    jumps |= (b == 0.0) & (np.abs(right) > 1e-6 * scale)
    if jumps.any():
        at = ", ".join(f"{x * m.angles[0]:.4g}" for x in sorted(set(b[jumps] % turn.end)))
        out.append(f"spring: the law's velocity jumps at cam angle {at} deg, where the "
                   "follower's acceleration is an impulse that no spring holds (sec. 7.5); the "
                   "spring's figures are those between the jumps")
    if m.output_spring_rate > SPRING_STIFFNESS * m.output_stiffness:
        out.append(f"spring: its rate {m.output_spring_rate:.4g} N/m is "
                   f"{m.output_spring_rate / m.output_stiffness:.2g} of the train's stiffness "
                   f"{m.output_stiffness:.4g} N/m, more than {SPRING_STIFFNESS:g}: the models "
                   "leave it out of the follower's own frequency (4.39), which it raises by "
                   f"{100 * (math.sqrt(1 + m.output_spring_rate / m.output_stiffness) - 1):.2g} %")
    return out


def _speed(m: Machine, w: float) -> str:
    return f"{units.speed_in(w, m.speed_unit):.4g} {m.speed_unit}"


def _spring_warnings(m, need, used, given, least, jump, speeds, margin, dynamic) -> list:
    """What the spring used leaves: a given preload below the least, the follower leaving the
    cam at the top speed or within the band (with the preload that would hold it over the
    band's speeds of the chart, where the residual vibration at a lower speed pulls harder
    than at the top), a chart cut short by the model's range."""
    out = []
    w_lo, w_hi = m.speeds
    if given and used < need:
        out.append(f"spring: the preload given, {used:.4g} N at the follower, is below the "
                   f"least that holds with the margin {m.spring_margin:g} at the top speed, "
                   f"{need:.4g} N")
    band = (speeds >= w_lo) & (speeds <= w_hi) & np.isfinite(margin)
    hold = used - float(np.min(margin[band])) if band.any() else None
    if least <= 0.0 and (jump is None or jump > w_hi):
        out.append(f"spring: the follower leaves the cam at the top speed (least contact force "
                   f"{least:.4g} N over the turn)")
    elif jump is not None and jump <= w_hi:
        out.append(f"spring: the follower leaves the cam within the band, from "
                   f"{_speed(m, jump)} on (the top speed is {_speed(m, w_hi)}): the residual "
                   "vibration pulls harder there than at the top speed"
                   + (f"; a preload of {hold:.4g} N at the follower keeps a contact force at "
                      "every speed of the jump margin chart in the band (without the margin)"
                      if hold is not None and hold > used else ""))
    if dynamic and speeds[-1] < BEYOND * w_hi:
        out.append(f"spring: the jump margin stops at {_speed(m, speeds[-1])}, the largest "
                   "speed the model takes (tau < 1 for the damped one-DOF model)")
    return out
