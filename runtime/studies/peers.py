"""SciPy's integrators as peers of camdyn's, on the same generated model.

``run_peer(name, model, params, t_end, rtol, atol)`` integrates a CompiledModel with one of
``scipy.integrate.solve_ivp``'s RK45, DOP853, Radau, BDF, LSODA or with ``odeint`` (LSODA of
ODEPACK), on the model's generated right-hand side (``driver.eval_rhs``, one point per call,
into preallocated arrays) and, for the implicit ones (Radau, BDF, LSODA, odeint), its generated
Jacobian (``driver.eval_jacobian``).  Like camdyn's loops, a peer restarts at every cam-law
breakpoint in time (``simulate.stop_times``): the right-hand side is smooth inside each interval
only.  A cam input driven by a state (H(B) on a turning camshaft) switches segment where an event
function of the model crosses zero; the solve_ivp peers stop there (terminal events through
``driver.eval_events``) and restart, odeint cannot locate events and is skipped on such
models.  Force-element modes (contact, backlash, friction) switch through the model's event
actions, which the peers do not apply: every peer is skipped on such models, with that reason.

The result, a :class:`PeerRun`, has the status ("ok", "failed" with SciPy's message, or
"skipped" with the reason), the final state, the right-hand-side and Jacobian calls, the CPU
time of the integration alone, and dense output (``sample``, ``t``, ``model``, ``params``, like
camdyn's Result) so that the same headline figures can be read from it.  atol is a vector of
state tolerances, camdyn's default when not given: 1e-3 rtol times the manifest's state scales.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import odeint, solve_ivp
from scipy.interpolate import CubicHermiteSpline

from ..engine import driver
from ..core.errors import CamdynInputError
from ..core.compiled import CompiledModel, load
from ..core.simulator import law_choices, stop_times, tolerance_scales

PEERS = ("RK45", "DOP853", "Radau", "BDF", "LSODA", "odeint")
"""The peers, as named on the command line and in charts."""

IMPLICIT = ("Radau", "BDF", "LSODA", "odeint")
"""The peers given the generated Jacobian."""

MAX_RHS = 2_000_000
"""Right-hand-side calls a peer may make before it is stopped and reported as failed."""


MAX_RESTARTS = 10_000
"""Restarts at events a peer may make before it is stopped and reported as failed."""


class _Budget(Exception):
    """Raised inside the right-hand side when a peer exceeds its call budget."""


class _Calls:
    """The generated right-hand side and Jacobian at one point, as SciPy calls them.

    One preallocated time array and a (1, n) view of the state per call: the Python cost is a
    counter, a comparison and the call into compiled code.  ``t_right`` is the end of the current
    interval; a time at (or beyond) it is taken just inside, so that the cam segment looked up is
    the interval's own (eval_rhs takes the segment that starts at a breakpoint)."""

    def __init__(self, model: CompiledModel, p, codes, pars, max_rhs: int):
        self.capsule, self.p, self.codes, self.pars = model.capsule, p, codes, pars
        self.n_states = len(model.state_names)
        self.tb = np.empty(1)
        self.n_rhs = self.n_jac = 0
        self.max_rhs = max_rhs
        self.t_right = math.inf
        self.t_inside = math.inf

    def interval(self, a: float, b: float) -> None:
        self.t_right, self.t_inside = b, float(np.nextafter(b, a))

    def f(self, t, y):
        self.n_rhs += 1
        if self.n_rhs > self.max_rhs:
            raise _Budget(f"more than {self.max_rhs} right-hand-side calls")
        self.tb[0] = t if t < self.t_right else self.t_inside
        return driver.eval_rhs(self.capsule, self.p, self.codes, self.pars, self.tb,
                                   y.reshape(1, self.n_states))[0]

    def jac(self, t, y):
        self.n_jac += 1
        tt = t if t < self.t_right else self.t_inside
        return driver.eval_jacobian(self.capsule, self.p, self.codes, self.pars, tt,
                                        np.ascontiguousarray(y, dtype=float))


@dataclass
class PeerRun:
    """One run of a peer: status, final state, costs and dense output."""

    name: str
    model: CompiledModel
    p: np.ndarray
    rtol: float
    status: str = "ok"               # "ok", "failed" or "skipped"
    message: str = ""
    y_end: np.ndarray | None = None
    n_rhs: int = 0
    n_jac: int = 0
    n_steps: int = 0
    cpu_seconds: float = math.nan
    law_codes: np.ndarray | None = None
    law_pars: np.ndarray | None = None
    pieces: list = field(default_factory=list)   # (a, b, callable t -> (n_states, len(t)), t knots)

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    @property
    def params(self) -> dict:
        return dict(zip(self.model.parameter_names, self.p.tolist()))

    @property
    def state_names(self) -> list[str]:
        return self.model.state_names

    @property
    def t(self) -> np.ndarray:
        """The points the peer stepped to (interval ends included once per interval)."""
        if not self.pieces:
            return np.empty(0)
        return np.concatenate([knots for *_, knots in self.pieces])

    def sample(self, times) -> dict:
        """States and outputs at ``times`` (the solver's dense output; at a breakpoint, the
        interval that ends there)."""
        if not self.ok:
            raise CamdynInputError(f"peer {self.name} has no trajectory: {self.status}")
        tq = np.atleast_1d(np.asarray(times, dtype=float))
        a0, b1 = self.pieces[0][0], self.pieces[-1][1]
        if tq.size and (tq.min() < a0 or tq.max() > b1):
            raise CamdynInputError(f"sample times must lie in [{a0:g}, {b1:g}]")
        ends = np.array([piece[1] for piece in self.pieces])
        which = np.minimum(np.searchsorted(ends, tq, side="left"), len(self.pieces) - 1)
        Y = np.empty((tq.size, len(self.state_names)))
        for k in np.unique(which):
            sel = which == k
            Y[sel] = np.asarray(self.pieces[k][2](tq[sel])).T
        out = driver.eval_outputs(self.model.capsule, self.p, self.law_codes, self.law_pars,
                                      np.ascontiguousarray(tq), Y)
        res = {"t": tq}
        res.update({n: Y[:, k] for k, n in enumerate(self.state_names)})
        res.update({n: out[:, k] for k, n in enumerate(self.model.output_names)})
        return res

    def __getitem__(self, name: str) -> np.ndarray:
        """A state or output at the points :attr:`t`."""
        return self.sample(self.t)[name] if name not in ("t",) else self.t


def skip_reason(name: str, model: CompiledModel) -> str | None:
    """Why peer ``name`` cannot run ``model`` faithfully, or None when it can."""
    if name not in PEERS:
        raise CamdynInputError(f"unknown peer {name!r}; choose from {', '.join(PEERS)}")
    modes = model.manifest.get("modes", [])
    if modes:
        return (f"{model.name} switches force-element modes ({', '.join(m['name'] for m in modes)}) "
                "at events through its event actions, which the SciPy peers do not apply")
    if name == "odeint" and _state_driven(model):
        return (f"{model.name}'s cam segments switch at events (a cam driven by a state); odeint "
                "locates no events")
    return None


def _state_driven(model: CompiledModel) -> bool:
    return any(not inst.get("time_affine", True) for inst in model.manifest["cam_instances"])


def default_atol(model: CompiledModel, rtol: float, y0=None) -> np.ndarray:
    """camdyn's default absolute tolerances: 1e-3 rtol times the tolerance scales of the states
    (runtime/core/simulator.py tolerance_scales), as a Simulator starting at ``y0`` (default:
    the declared start) takes them."""
    p = model.parameter_vector()
    y = model.initial_state(p) if y0 is None else np.asarray(y0, dtype=float).ravel()
    return 1e-3 * rtol * tolerance_scales(model, p, y)


def run_peer(name: str, model, params: dict | None, t_end: float, rtol: float, atol=None, *,
             law="cycloidal", theta: float | None = None, y0=None, t0: float = 0.0,
             sample_times=None, max_rhs: int = MAX_RHS) -> PeerRun:
    """Integrate ``model`` from t0 to t_end with peer ``name`` (one of :data:`PEERS`).

    rtol     relative tolerance, 1e-14 <= rtol < 1
    atol     absolute tolerance, a number or one per state (default: :func:`default_atol`)
    y0       initial state (default: the model's)
    sample_times  odeint only: the times it reports (it has no dense output; a cubic Hermite
             interpolant of the states and generated slopes there serves as one); default 2000
             points per interval.  The breakpoints are always among them.
    max_rhs  the right-hand-side calls allowed before the run is stopped as failed

    Returns a :class:`PeerRun`; a solver failure or an exhausted budget is status "failed",
    a model the peer cannot run (see :func:`skip_reason`) status "skipped".
    """
    m = model if isinstance(model, CompiledModel) else load(model)
    p = m.parameter_vector(params)
    if not (isinstance(rtol, (int, float)) and 1e-14 <= rtol < 1):
        raise CamdynInputError(f"rtol={rtol!r} is out of range: 1e-14 <= rtol < 1")
    if not (math.isfinite(t0) and math.isfinite(t_end) and t_end > t0):
        raise CamdynInputError(f"t_end={t_end:g} must be finite and greater than t0={t0:g}")
    ns = len(m.state_names)
    atol_v = default_atol(m, rtol, y0) if atol is None else np.broadcast_to(
        np.asarray(atol, dtype=float), (ns,)).copy()
    if not np.all(atol_v > 0):
        raise CamdynInputError("atol must be positive")
    chosen, codes, pars = law_choices(m, law, theta)
    run = PeerRun(name, m, p, float(rtol), law_codes=codes, law_pars=pars)
    reason = skip_reason(name, m)
    if reason:
        run.status, run.message = "skipped", reason
        return run
    y = (m.initial_state(p) if y0 is None else np.array(y0, dtype=float).ravel()).copy()
    if y.shape != (ns,):
        raise CamdynInputError(f"y0 must be {ns} numbers ({', '.join(m.state_names)})")
    stops = stop_times(m, p, chosen, t0, t_end)
    calls = _Calls(m, p, codes, pars, max_rhs)
    c0 = time.process_time()
    try:
        if name == "odeint":
            _odeint(run, calls, y, t0, stops, atol_v, sample_times)
        else:
            _ivp(run, calls, y, t0, stops, atol_v)
    except _Budget as exc:
        run.status, run.message = "failed", str(exc)
    run.cpu_seconds = time.process_time() - c0
    run.n_rhs, run.n_jac = calls.n_rhs, calls.n_jac
    if name == "odeint" and run.ok:
        _hermite(run, calls)
    if run.ok and not np.all(np.isfinite(run.y_end)):
        run.status, run.message = "failed", "the state became non-finite"
    return run


def _events(calls: _Calls, model: CompiledModel, t, y):
    """A terminal event where a state-driven cam input changes segment, or None.

    The model's event functions g = argument - bound are relative to the segment looked up at
    the point, so they jump rather than cross zero where the segment changes.  What stays
    constant inside a segment is the difference of each input's pair (cam<i>_hi - cam<i>_lo =
    lower - upper bound); the event is +1 while those equal the start's, -1 after, and SciPy's
    root finder (Brent on the dense output) locates the jump to rounding.  A change between
    two adjacent segments of equal width goes unnoticed (the run then continues across it)."""
    names = model.manifest["events"]
    pairs = [(names.index(f"cam{i}_hi"), names.index(f"cam{i}_lo"))
             for i, inst in enumerate(model.manifest["cam_instances"])
             if not inst.get("time_affine", True)
             and f"cam{i}_hi" in names and f"cam{i}_lo" in names]
    if not pairs:
        return None

    def ident(tt, yy):
        g = driver.eval_events(model.capsule, calls.p, calls.codes, calls.pars, float(tt),
                                   np.ascontiguousarray(yy, dtype=float))
        return tuple(round(float(g[h] - g[lo]), 9) for h, lo in pairs)

    start = ident(t, y)

    def changed(tt, yy):
        return 1.0 if ident(tt, yy) == start else -1.0

    changed.terminal = True
    changed.direction = -1
    return [changed]


def _ivp(run: PeerRun, calls: _Calls, y, t, stops, atol) -> None:
    jac = {"jac": calls.jac} if run.name in IMPLICIT else {}
    restarts = 0
    for b in stops:
        calls.interval(t, b)
        while t < b:
            restarts += 1
            if restarts > MAX_RESTARTS:
                run.status, run.message = "failed", f"more than {MAX_RESTARTS} event restarts"
                return
            events = _events(calls, run.model, t, y)
            sol = solve_ivp(calls.f, (t, b), y, method=run.name, rtol=run.rtol, atol=atol,
                            dense_output=True, events=events, **jac)
            if sol.status < 0:
                run.status, run.message = "failed", f"{sol.message} (at t = {sol.t[-1]:.6g})"
                return
            run.n_steps += len(sol.t) - 1
            t_new, y = float(sol.t[-1]), sol.y[:, -1].copy()
            if sol.status == 1 and t_new <= t:   # an event at the start: cannot make progress
                run.status, run.message = "failed", f"event at t = {t:.6g} repeats at its start"
                return
            # a piece a few ulps long is the last event found again: its root left the state
            # on the old side of the segment's bound by rounding; it joins the next piece
            if not (sol.status == 1 and t_new - t <= 1e-12 * max(1.0, abs(t))):
                run.pieces.append((float(t), t_new, sol.sol, sol.t))
            elif run.pieces:
                a, _, s_prev, ts_prev = run.pieces[-1]
                run.pieces[-1] = (a, t_new, s_prev, ts_prev)
            t = t_new
    run.y_end = y


def _odeint(run: PeerRun, calls: _Calls, y, t, stops, atol, sample_times) -> None:
    for b in stops:
        calls.interval(t, b)
        if sample_times is None:
            inner = np.linspace(t, b, 2001)[1:-1]
        else:
            st = np.asarray(sample_times, dtype=float)
            inner = st[(st > t) & (st < b)]
        tt = np.concatenate([[t], np.sort(inner), [b]])
        Y, info = odeint(calls.f, y, tt, Dfun=calls.jac, tfirst=True, rtol=run.rtol, atol=atol,
                         mxstep=max(500, calls.max_rhs // 4), full_output=True)
        if info["message"] != "Integration successful.":
            run.status, run.message = "failed", f"odeint: {info['message']}"
            return
        run.n_steps += int(info["nst"][-1])
        run.pieces.append((float(t), float(b), Y, tt))
        t, y = float(b), Y[-1].copy()
    run.y_end = y


def _hermite(run: PeerRun, calls: _Calls) -> None:
    """odeint's dense output, made after the timed run: the cubic Hermite interpolant of the
    reported states and the generated slopes there (left limits at an interval's end)."""
    pieces = []
    for a, b, Y, knots in run.pieces:
        tk = knots.copy()
        tk[-1] = np.nextafter(b, a)
        F = driver.eval_rhs(calls.capsule, calls.p, calls.codes, calls.pars, tk,
                                np.ascontiguousarray(Y))
        spline = CubicHermiteSpline(knots, Y, F, axis=0)
        pieces.append((a, b, lambda q, s=spline: s(q).T, knots))
    run.pieces = pieces
