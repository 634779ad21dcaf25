"""Runs of generated models: ``simulate(...)`` for one run, ``Simulator`` for many.

A :class:`Simulator` fixes the model, method, cam law and time span and
checks them once; ``Simulator.run(params)`` then only checks the parameters
and calls the compiled loops.  ``simulate`` keeps a few recently used
simulators, so repeated calls with the same settings cost little more.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ..engine import driver
from . import diagnosis, laws as _laws, methods as _methods, stability as _stability
from .errors import CamdynInputError, SimulationError, UnstableStep
from .compiled import CompiledModel, load
from .result import Result


def _flag(name: str, value) -> bool:
    if not isinstance(value, bool):
        raise CamdynInputError(f"{name} must be True or False, got {value!r}")
    return value


def law_choices(model: CompiledModel, law, theta):
    """The cam law of each input family of a model: (chosen per family, their codes, their
    shape parameters), from a law name (every input), {family: name}, or a composed turn."""
    fams = model.families
    if isinstance(law, dict):
        missing = set(fams) - set(law)
        if missing:
            raise CamdynInputError(f"no cam law given for input {', '.join(sorted(missing))}")
        chosen = {f: law[f] if isinstance(law[f], _laws.CHOSEN)
                  else _laws.choose(law[f], theta)
                  for f in fams}
    else:
        choice = law if isinstance(law, _laws.CHOSEN) else _laws.choose(law, theta)
        chosen = {f: choice for f in fams}
    order = _laws.orders_used(model.manifest)
    for c in set(chosen.values()):
        if isinstance(c, _laws.Shaped):
            c.check_for(model.name, order)
    codes = np.array([chosen[f].code for f in fams] or [0], dtype=np.intc)
    pars = np.array([chosen[f].par for f in fams] or [0.0], dtype=float)
    return chosen, codes, pars


def stop_times(model: CompiledModel, p, chosen: dict, t0: float, t_end: float) -> np.ndarray:
    """Cam-law breakpoints in time inside (t0, t_end), then t_end.

    A cam input whose argument is a t + b has its law breakpoints at
    (bp - b)/a; inputs driven by a state (H(B)) need events instead.
    """
    stops = {float(t_end)}
    affine = model.cam_time_affine(p)
    for inst, ab in zip(model.manifest["cam_instances"], affine):
        if ab is None:
            continue
        a, b = ab
        if a == 0:
            continue
        lo, hi = sorted((a * t0 + b, a * t_end + b))
        for bp in chosen[inst["family"]].breakpoints_between(lo, hi):
            tb = (bp - b) / a
            if t0 < tb < t_end:
                stops.add(float(tb))
    return np.array(sorted(stops))


def initial_modes(model: CompiledModel, modes: dict | None) -> list[int]:
    """Initial value index of every force-element mode: the manifest's, overridden by ``modes``."""
    specs = model.manifest.get("modes", [])
    given = dict(modes or {})
    unknown = sorted(set(given) - {m["name"] for m in specs})
    if unknown:
        raise CamdynInputError(f"model {model.name} has no mode {unknown[0]!r}; its modes are "
                               f"{', '.join(m['name'] for m in specs) or 'none'}")
    out = []
    for spec in specs:
        value = given.get(spec["name"], spec["initial"])
        if value not in spec["values"]:
            raise CamdynInputError(f"mode {spec['name']}={value!r} is not one of {spec['values']}")
        out.append(spec["values"].index(value))
    return out


def drive_rate(model: CompiledModel, p: np.ndarray, y0: np.ndarray) -> float:
    """The rate the mechanism is driven at, per unit of the model's time: the fastest of a cam
    input's rises per time unit (its argument a t + b: |a|) and a coordinate's initial rate in
    its scales per time unit (a cam turning at Omega from the start: Omega/1 rad), never below
    1.  It is 1 for the thesis's models, whose time T = t/t_m counts rises (the follower moves
    its scale in about one unit of T), and the cam's speed for the models in seconds (the
    beam follower, DYNACAM), whose coordinates move their scales in about 1/Omega."""
    rate = 1.0
    for ab in model.cam_time_affine(p):
        if ab is not None:
            rate = max(rate, abs(float(ab[0])))
    n_q = int(model.manifest.get("n_q", 0))
    scales = model.state_scales()
    for k in range(n_q):
        v = abs(float(y0[n_q + k])) / scales[k]
        if math.isfinite(v):
            rate = max(rate, v)
    return rate


def tolerance_scales(model: CompiledModel, p: np.ndarray, y0: np.ndarray) -> np.ndarray:
    """What an absolute tolerance of 1 means for each state: a coordinate's declared scale; its
    rate's that scale times :func:`drive_rate` (a coordinate that moves its scale over a rise
    of length 1/rate moves at about scale x rate: with the scale alone, a beam mode's rate in
    m/s would have been held to the tolerance of its amplitude in m, 240 times too tight at
    the paper's 240 rad/s); a first-order state its declared scale."""
    scales = model.state_scales().copy()
    n_q = int(model.manifest.get("n_q", 0))
    scales[n_q:2 * n_q] *= drive_rate(model, p, y0)
    return scales


def absolute_tolerances(model: CompiledModel, method, y0=None) -> np.ndarray:
    """The absolute tolerance of every state of an adaptive ``method``'s run of ``model`` from
    ``y0`` (None: the declared start): atol (default 1e-3 rtol) times the tolerance scales of
    that start at the default parameters, so that a grid over the parameters keeps one
    absolute tolerance for all its points, then ``state_atol``'s values."""
    p_scale = model.parameter_vector()
    y_scale = model.initial_state(p_scale) if y0 is None else y0
    base = method.atol if method.atol is not None else 1e-3 * method.rtol
    atol = np.ascontiguousarray(base * tolerance_scales(model, p_scale, y_scale), dtype=float)
    for name, value in method.state_atol:
        if name not in model.state_names:
            raise CamdynInputError(f"state_atol: {model.name} has no state {name}; its states "
                                   f"are {', '.join(model.state_names)}")
        atol[model.state_names.index(name)] = value
    return atol


def partition(model: CompiledModel, dependent) -> tuple[tuple, np.ndarray | None]:
    """(the dependent coordinates' names in force, the coordinate partition the compiled code
    takes: their indices, then the independent ones' in declared order, or None for the
    declared partition) of a constrained ``model`` run with ``dependent``: None (the model's
    ConstraintSolver(dependent=...), the manifest's "dependent"), names of exactly n_c
    distinct coordinates, or one string of them separated by commas (coordinate
    partitioning: the dependent coordinates are solved from Phi = 0 and Phi_Q Q' = -Phi_t,
    the independent ones integrated)."""
    declared = tuple(model.manifest.get("dependent", ()))
    if dependent is None:
        return declared, None
    nc = int(model.manifest.get("n_constraints", 0))
    if not nc:
        raise CamdynInputError(f"dependent: model {model.name} has no constraints; dependent "
                               "coordinates are chosen for constrained models only")
    coords = model.state_names[:int(model.manifest["n_q"])]
    names = dependent.split(",") if isinstance(dependent, str) else dependent
    try:
        names = tuple(n.strip() if isinstance(n, str) else n for n in names)
    except TypeError:
        names = (dependent,)
    if (len(names) != nc or len(set(names)) != nc
            or not all(isinstance(n, str) and n in coords for n in names)):
        shown = ",".join(str(n) for n in names)
        raise CamdynInputError(
            f"dependent={shown!r}: {model.name} takes {nc} distinct name{'s' * (nc > 1)} of "
            f"its coordinates {', '.join(coords)} (declared: {','.join(declared)})")
    if set(names) == set(declared):
        return declared, None
    dep = [coords.index(n) for n in names]
    return names, np.array(dep + [j for j in range(len(coords)) if j not in dep],
                           dtype=np.intc)


@dataclass(frozen=True)
class BatchInputs:
    """What the compiled loops take to run many parameter sets of one Simulator (its
    :meth:`Simulator.batch_inputs`): per run a parameter vector, an initial state and a stop
    table; for all, the method's code and step control, the cam laws and the modes."""

    P: np.ndarray
    Y0: np.ndarray
    stops: np.ndarray
    n_stops: np.ndarray
    method: int
    law_codes: np.ndarray
    law_pars: np.ndarray
    t0: float
    first_step: float
    h_max: float
    rtol: float
    atol: np.ndarray
    max_steps: int
    modes0: np.ndarray
    max_events: int
    part: np.ndarray | None = None     # a constrained model's coordinate partition (partition)


def _model(model) -> CompiledModel:
    """A compiled model, a built-in model's name, or a model file (a path ending in ``.py``
    with a ``build()``), derived and compiled on its first use and loaded from the cache
    after (runtime/core/ondemand.py; an edited file is built again)."""
    if isinstance(model, CompiledModel):
        return model
    if str(model).endswith(".py"):
        from .ondemand import model_file

        return model_file(model)
    return load(model)


class Simulator:
    """A prepared simulation: everything but the parameter values is fixed and checked.

    model   name of a generated model ("camshaft1") or a CompiledModel
    t_end   end of the run (model time)
    method  "dp54", "dop853", "rodas4", "radau5" (rtol, atol), "rk4" or "koster" (step), or a
            method object (runtime/core/methods.py)
    law     cam-law name, or {family: name} for models with several inputs;
            theta is the law's shape parameter (modified sine)
    check_stability
            True (the default): a fixed step beyond the method's stability boundary is
            refused (UnstableStep).  False runs it anyway, for the stability map
            (runtime/studies/stability_map.py), which must see what the step does: the loop
            still checks and the largest h |lambda| it saw is in ``result.stability``; a run
            that becomes non-finite still raises SimulationError.
    consistent
            True (the default): a constrained model starts on its constraints, its dependent
            coordinates and rates recovered from the independent ones, with a note when that
            moved them.  False starts from the state as given, off the constraints, to study
            how the formulation pulls it back (Baumgarte's terms, tests/test_pendulum_xy.py).
    exact_segments
            Where the model is linear and time invariant (every cam input in a dwell, no
            contact or friction: the free vibration after a rise of one-DOF, CAMSHAFT-1, the
            chain, a roller held on its contact spring), step over the interval with its exact
            propagator e^(A h) instead of the method (runtime/engine/loops.pxi, _loop_exact).
            RK4's record takes its own steps there, each a matrix-vector product without
            error.  An adaptive method's record there holds a degree-7 extension through the
            exact state whose steps lengthen as the content fades (each checked against the
            exact state at rtol and atol), so a stiff mode that has rung out no longer sets
            them.  Default: True for RK4, DOP853 and RKN12.  False for DP54 (the thesis's figures and
            their estimates are read off DP54's own record), for the thesis scheme, which is
            run as the thesis ran it, and for RODAS4 and RADAU5, whose own steps damp a stiff
            mode that does not decay (a stiff spring without damping) where the exact record
            must follow it; give True to them where the stiff mode is damped (a contact
            with damping: the roller's dwell then costs a few dozen points instead of
            hundreds of steps).  False with check_stability=False too, whose runs are made to
            see what the method's step does, the dwell included (the stability map).
    dependent
            A constrained model's dependent coordinates for these runs, instead of the ones
            its ConstraintSolver declares (the manifest's "dependent"): exactly n_c distinct
            coordinate names, as a sequence or one comma-separated string.  Coordinate
            partitioning (formulation 1) solves them from the constraints at every
            evaluation and integrates the others; every formulation starts from the
            consistent state they are solved for (``consistent``).  Phi_Q restricted to
            them must be invertible along the run.
    dense_output
            DOP853's dense output (its three extra stages a step, a sixth of the run's
            right-hand-side calls) and RKN12's (eight interior steps, 128 calls a step): True
            computes it as the run goes; False, the default, leaves it out until it is used.
            DOP853 then makes it step by step where it is wanted (the steps ``Result.sample``
            reads, the peaks a figure's extreme refines; each step made again from its
            recorded start, bit for bit, 16 calls), and has it as the run goes on the steps
            where an event crossed, since events are located on it; RKN12 runs again with
            it, taking the same steps.  Other methods' dense output costs no extra call and
            is always there.
    """

    def __init__(self, model, t_end: float = 3.0, method="dp54", *, rtol: float | None = None,
                 atol: float | None = None, step: float | None = None, law="cycloidal",
                 theta: float | None = None, y0=None, t0: float = 0.0, max_steps: int = 5_000_000,
                 modes: dict | None = None, max_events: int = 1_000_000,
                 check_stability: bool = True, consistent: bool = True,
                 exact_segments: bool | None = None, dependent=None,
                 dense_output: bool = False):
        m = _model(model)
        self.dependent, self.part = partition(m, dependent)
        if isinstance(method, str):
            method = _methods.make(method, rtol=rtol, atol=atol, step=step)
        elif rtol is not None or atol is not None or step is not None:
            raise CamdynInputError("give rtol/atol/step inside the method object, not beside it")
        # inside methods.tightened(): the run one notch tighter of an error estimate
        method = _methods.apply_notches(method)
        try:
            t0, t_end = float(t0), float(t_end)
        except (TypeError, ValueError):
            raise CamdynInputError("t0 and t_end must be numbers") from None
        if not (math.isfinite(t0) and math.isfinite(t_end) and t_end > t0):
            raise CamdynInputError(f"t_end={t_end:g} must be finite and greater than t0={t0:g}")
        if isinstance(max_steps, bool) or not isinstance(max_steps, int) or max_steps < 1:
            raise CamdynInputError(f"max_steps must be a positive integer, got {max_steps!r}")
        self.model, self.method, self.t0, self.t_end, self.max_steps = m, method, t0, t_end, max_steps
        self.check_stability = _flag("check_stability", check_stability)
        self.consistent = bool(consistent)
        self._project = self.consistent and hasattr(m.module, "consistent_state")
        self.laws, self.law_codes, self.law_pars = law_choices(m, law, theta)
        # what a run with a rise from a table says about the table's accuracy
        self.law_notes = [w for c in dict.fromkeys(self.laws.values())
                           if isinstance(c, _laws.Shaped) for w in c.warnings()]
        n = len(m.state_names)
        # a default initial state that depends on the parameters is worked out per run
        self._y0_given = y0 is not None or all(
            isinstance(st["initial"], float) for st in m.manifest["states"])
        y_init = m.initial_state() if y0 is None else np.array(y0, dtype=float).ravel()
        if y_init.shape != (n,) or not np.all(np.isfinite(y_init)):
            raise CamdynInputError(f"y0 must be {n} finite numbers ({', '.join(m.state_names)})")
        self._y_init = y_init
        if method.adaptive:
            atol = absolute_tolerances(m, method, y_init if self._y0_given else None)
            h, h_max, rtol = method.first_step or 0.0, min(method.max_step, t_end - t0), method.rtol
        else:
            if (t_end - t0) / method.step > max_steps:
                raise CamdynInputError(
                    f"step={method.step:g} needs more than max_steps={max_steps} steps over "
                    f"[{t0:g}, {t_end:g}]")
            atol, h, h_max, rtol = np.ones(n), method.step, method.step, 0.0
        self.modes0 = initial_modes(m, modes)
        # what the compiled loops take, kept for the batch entry (batch_inputs)
        self.atol, self.first_step, self.h_max, self.loop_rtol = atol, h, h_max, rtol
        self.max_events = int(max_events)
        stab = (driver.CHECK_OFF if method.adaptive else
                driver.CHECK_STOP if check_stability else driver.CHECK_ESTIMATE)
        if exact_segments is None:
            exact_segments = method.name in ("rk4", "dop853", "rkn12") and check_stability
        self.exact_segments = _flag("exact_segments", exact_segments)
        if method.name == "rkn12":
            self._nystrom_model()
        self.integrator = driver.Integrator(
            m.capsule, method.code, self.law_codes, self.law_pars, y_init, t0, h, h_max, rtol, atol,
            max_steps, np.array(self.modes0, dtype=np.intc), int(max_events), stab,
            None if method.adaptive else _stability.loop_boundary(method.name), exact_segments,
            self.part, dense=_flag("dense_output", dense_output))
        self._stops: dict = {}
        self._cap = 256
        # what run() reads on every call, looked up once here
        self._tname = m.manifest["time"]["name"]
        self._fixed_step = None if method.adaptive else method.step
        self._warn_level = None if method.adaptive else _stability.warn_level(method.name)

    def initial_state(self, p: np.ndarray) -> np.ndarray:
        """The initial state of a run with parameters p: the one given, else the model's
        declared one (which may depend on p)."""
        return self._y_init.copy() if self._y0_given else self.model.initial_state(p)

    def batch_inputs(self, P: np.ndarray) -> "BatchInputs":
        """Everything the compiled loops need to run the parameter sets P (one row each)
        without a Python call per run: initial states, stop tables (breakpoints in time, then
        t_end, padded with t_end) and the loop's settings, as this Simulator runs them."""
        P = np.ascontiguousarray(np.atleast_2d(P), dtype=float)
        n = len(P)
        # stop times depend on the parameters only through the cam inputs' affine arguments
        stops, seen = [], {}
        for p in P:
            key = repr(self.model.cam_time_affine(p))
            s = seen.get(key)
            if s is None:
                s = seen[key] = stop_times(self.model, p, self.laws, self.t0, self.t_end)
            stops.append(s)
        width = max(len(s) for s in stops)
        S = np.full((n, width), self.t_end)
        for j, s in enumerate(stops):
            S[j, :len(s)] = s
        Y0 = (np.tile(self._y_init, (n, 1)) if self._y0_given
              else np.array([self.model.initial_state(p) for p in P]))
        return BatchInputs(P=P, Y0=np.ascontiguousarray(Y0, dtype=float), stops=S,
                           n_stops=np.array([len(s) for s in stops], dtype=np.intc),
                           method=self.method.code, law_codes=self.law_codes,
                           law_pars=self.law_pars, t0=self.t0, first_step=self.first_step,
                           h_max=self.h_max, rtol=self.loop_rtol,
                           atol=np.ascontiguousarray(self.atol, dtype=float),
                           max_steps=self.max_steps,
                           modes0=np.array(self.modes0, dtype=np.intc),
                           max_events=self.max_events, part=self.part)

    def start(self, p: np.ndarray, y0=None) -> tuple[np.ndarray, str | None]:
        """(the state a run with parameters p starts from, the note that the constraints
        moved it or None): ``y0``, else the initial values given, else the model's own for p,
        for a constrained model projected onto its constraints (see ``consistent``)."""
        if y0 is None:
            y0 = self._y_init if self._y0_given else self.model.initial_state(p)
        if self._project:
            return self._consistent(p, y0)
        return y0, None

    def stops(self, p: np.ndarray) -> np.ndarray:
        """Stop times for parameters p (cached: they depend on p only through the cam inputs)."""
        return self.stops_and_capacity(p)[0]

    def stops_and_capacity(self, p: np.ndarray):
        """(stop times, record capacity: 0 for adaptive methods) for parameters p, cached."""
        hit = self._stops.get(p.tobytes())
        return self._new_stops(p) if hit is None else hit

    def _new_stops(self, p: np.ndarray):
        if len(self._stops) > 256:
            self._stops.clear()
        if self.method.name == "rkn12":
            self._velocity_free(p)
        stops = stop_times(self.model, p, self.laws, self.t0, self.t_end)
        cap = 0 if self.method.adaptive else driver.fixed_step_points(self.t0, stops, self.method.step)
        hit = self._stops[p.tobytes()] = (stops, cap)
        return hit

    def _nystrom_model(self) -> None:
        """Refuse a model RKN12 cannot integrate: first-order states, events, constraints, or a
        Jacobian by differences (whose zeros are not exact, see _velocity_free)."""
        m, why = self.model, None
        mf = m.manifest
        if len(m.state_names) != 2 * mf["n_q"]:
            why = "it has first-order states"
        elif mf.get("events"):
            why = "it has events (located on a dense output made as the run goes)"
        elif self._project or hasattr(m.module, "consistent_state"):
            why = "it is constrained"
        elif mf.get("jacobian") != "symbolic":
            why = "its Jacobian is not symbolic, so q''s freedom from q' cannot be checked"
        if why:
            raise CamdynInputError(f"{m.name}: {why}, and rkn12 integrates q'' = g(t, q) "
                                   "alone. Use dop853")

    def _velocity_free(self, p: np.ndarray) -> None:
        """Refuse parameters p for which q'' depends on q': the generated Jacobian's block
        d q''/d q' must be exactly zero, checked at three states and times (a symbolic entry
        that does not vanish identically is not exactly zero at such points)."""
        m, nq = self.model, self.model.manifest["n_q"]
        rng = np.random.default_rng(12)
        for t in np.linspace(self.t0, self.t_end, 5)[1:4]:
            y = self.initial_state(p) + rng.uniform(-0.5, 0.5, 2 * nq)
            J = driver.eval_jacobian(m.capsule, p, self.law_codes, self.law_pars, float(t), y,
                                     np.array(self.modes0, dtype=np.intc) if self.modes0 else None)
            dep = np.argwhere(J[nq:, nq:] != 0.0)
            if dep.size:
                i, j = dep[0]
                raise CamdynInputError(
                    f"{m.name}: the acceleration {m.state_names[i]}'' depends on the velocity "
                    f"{m.state_names[nq + j]} with these parameters (damping?), and rkn12 "
                    "integrates q'' = g(t, q) alone. Use dop853")

    def run(self, params: dict | None = None) -> Result:
        """One run with these parameter values (defaults for the ones not given).

        A failed run raises SimulationError; so does a fixed-step run whose step lies beyond
        the method's stability boundary, which the compiled loop checks as it goes and stops
        at, where h |lambda| first exceeds the boundary (camdyn.runtime.core.stability;
        UnstableStep, unless the simulator was made with check_stability=False).  A step near
        the boundary leaves a warning in ``result.warnings``, from the largest h |lambda| the
        loop saw; DP54 records where Hairer's stiffness test fired in ``result.stiff_from_T``.
        """
        # the fixed cost of a call is a good part of a short run's (a CAMSHAFT-1 run in RK4
        # steps takes a few microseconds): what does not depend on params was looked up in
        # __init__, and the common path makes no call it can do without
        m = self.model
        p = m.parameter_vector(params)
        hit = self._stops.get(p.tobytes())
        stops, cap = self._new_stops(p) if hit is None else hit
        y0 = note = None
        if self._project or not self._y0_given:
            y0, note = self.start(p)
        out = self.integrator.run(p, stops, cap or self._cap, y0)
        if out.status != 0:
            self._failed(p, out, y0)
        if not cap:
            self._cap = max(256, out.n + out.n // 4)
        res = Result(self, p, out)
        if note:
            res.warnings.append(note)
        if self.law_notes:
            res.warnings.extend(self.law_notes)
        # near the boundary (the warning) or beyond it, read off the loop's check without
        # building the estimate: far inside, the common case, this costs two comparisons
        h = self._fixed_step
        if h is not None and out.n_checks > 0 and (out.stab_ratio > 1.0
                                                   or h * out.stab_rho > self._warn_level):
            est = res.stability
            if est.stable:
                res.warnings.append(_stability.warning(self._tname, est))
            else:   # run anyway (check_stability=False)
                res.warnings.append("run with the stability check off: "
                                    + _stability.refusal(m.name, self._tname, est))
        return res

    def _failed(self, p, out, y0=None):
        """Raise what a run that stopped early (out.status) calls for; ``y0``: the state it
        started from (None: its own), which is where the diagnosis looks when the run
        could not record even its first point (a slope not finite there)."""
        m, tname = self.model, self._tname
        if out.status == driver.UNSTABLE:
            est = _stability.from_loop(self.method.name, self.method.step, out)
            raise UnstableStep(_stability.refusal(m.name, tname, est), est)
        # the integrator's words say what it saw; the model's state says why
        fault = diagnosis.explain(m, p, self.law_codes, self.law_pars, out, part=self.part,
                                  start=(self.t0, self.start(p, y0)[0] if y0 is None else y0))
        if fault is not None and fault.at_start:     # the input, not the run
            raise CamdynInputError(f"{m.name}: {fault.text}")
        why = (driver.PROJECTION_TEXT if out.status == driver.NO_CONVERGENCE
               and self.method.name != "koster" else driver.STATUS_TEXT[out.status])
        raise SimulationError(f"{m.name} with {self.method.name}: " + (
            fault.text if fault else f"{why} at {tname} = {out.t_fail:.6g}"))

    def _consistent(self, p, y):
        """A constrained model's initial state on its constraints: the dependent coordinates
        (``dependent``, else as the model's ConstraintSolver names them) and their rates
        recovered from the independent ones, in every formulation, with a note when that
        moved them (the run starts, and its record reports, the consistent state); a
        CamdynInputError naming the dependent coordinates when no consistent state is found
        or they cannot be solved for there."""
        m = self.model
        y = np.ascontiguousarray(y, dtype=float)
        dep = self.dependent
        try:
            yc, phi, phid = driver.consistent_state(
                m.capsule, m.module, p, self.law_codes, self.law_pars, self.t0, y,
                np.array(self.modes0, dtype=np.intc) if self.modes0 else None, self.part)
        except ValueError as e:
            skip = set(dep) | {n + "d" for n in dep}
            given = ", ".join(f"{n} = {v:.6g}" for n, v in zip(m.state_names, y)
                              if n not in skip)
            if str(e) == "singular":
                raise CamdynInputError(
                    f"{m.name}: the constraints cannot be solved for the dependent coordinates "
                    f"{', '.join(dep)} at the initial state (Phi_Q restricted to them is "
                    "singular there); give other initial values or choose other dependent "
                    "coordinates (dependent=..., --dependent NAMES)") from None
            raise CamdynInputError(
                f"{m.name}: Newton's method found no {', '.join(dep)} on the constraints from "
                f"the independent coordinates ({given}); give initial values closer to "
                "them") from None
        moved = np.abs(yc - y) > 1e-10 * (np.abs(y) + m.state_scales())
        if not moved.any():
            return y, None
        names = [n for n, k in zip(m.state_names, moved) if k]
        return yc, (f"the initial state violated the constraints (|Phi| = {phi:.3g}, "
                    f"|Phi'| = {phid:.3g}): {', '.join(names)} recovered from the independent "
                    "coordinates (" + ", ".join(f"{n} = {v:.6g}" for n, v
                                                in zip(m.state_names, yc) if n in names) + ")")


@lru_cache(maxsize=32)
def _prepared(model, t_end, method, rtol, atol, step, law, theta, y0, t0, max_steps, modes,
              exact_segments, dependent, notches, dense_output) -> Simulator:
    return Simulator(model, t_end, method, rtol=rtol, atol=atol, step=step,
                     law=dict(law) if isinstance(law, tuple) else law,
                     theta=theta, y0=y0, t0=t0, max_steps=max_steps,
                     modes=dict(modes) if modes else None, exact_segments=exact_segments,
                     dependent=dependent, dense_output=dense_output)


def simulate(model, params: dict | None = None, t_end: float = 3.0, method="dp54", *,
             rtol: float | None = None, atol: float | None = None, step: float | None = None,
             law="cycloidal", theta: float | None = None, y0=None, t0: float = 0.0,
             max_steps: int = 5_000_000, modes: dict | None = None,
             exact_segments: bool | None = None, dependent=None,
             dense_output: bool = False) -> Result:
    """Integrate ``model`` from t0 to t_end with ``params`` (see :class:`Simulator`).

    The prepared Simulator is kept for the next call with the same settings.
    """
    key_law = tuple(sorted(law.items())) if isinstance(law, dict) else law
    key_y0 = None if y0 is None else tuple(np.asarray(y0, dtype=float).ravel().tolist())
    key_modes = tuple(sorted(modes.items())) if modes else None
    # the names as given, in order: a list is keyed as its tuple, a string as itself
    key_dep = dependent if dependent is None or isinstance(dependent, str) else tuple(dependent)
    try:
        sim = _prepared(model, t_end, method, rtol, atol, step, key_law, theta, key_y0, t0,
                        max_steps, key_modes, exact_segments, key_dep, _methods.notches(),
                        dense_output)
    except TypeError:  # unhashable settings: prepare without the cache
        sim = Simulator(model, t_end, method, rtol=rtol, atol=atol, step=step, law=law,
                        theta=theta, y0=y0, t0=t0, max_steps=max_steps, modes=modes,
                        exact_segments=exact_segments, dependent=dependent,
                        dense_output=dense_output)
    return sim.run(params)
