"""Integration methods: one small class each, checked options, one compiled loop.

The loops themselves are in :mod:`camdyn.runtime.engine.driver`; these classes
only validate what the user asked for and say which loop to run with which
step control.

Each method also knows its one-notch-tighter self, the second run of an error estimate: a
figure v is computed again as v' and |v - v'| times the method's factor estimates v's global
error.  For the adaptive methods (dp54, dop853, rodas4, radau5, rkn12) the second run is at
rtol/100 and atol/100 (rtol/10 near the tightest rtol), with a factor 1.5 (3 for RADAU5) that
covers what v' leaves and the runs whose error does not follow their tolerance
(:meth:`DP54.tighter`).  For the fixed-step methods (rk4, and the thesis's
scheme, whose acceleration is held at its mid-step value (4.23)-(4.31)) it is at half the step,
with Richardson's factor 2^p/(2^p - 1), p the method's order.  The estimate needs the error to
be in its asymptotic range; near a stability limit, or for a figure that jumps (an event in one
run and not in the other), it is as large as the change between the runs, which flags it.
tests/test_accuracy.py checks on CAMSHAFT-1 that the estimates bound the true error within a
factor of 10, and on random one-DOF, CAMSHAFT-1 and CAMSHAFT-2 runs that they cover it.
"""
from __future__ import annotations

import math
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, replace

from ..engine import driver
from .errors import CamdynInputError


def _positive(name: str, value, upper: float | None = None) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise CamdynInputError(f"{name} must be a number, got {value!r}") from None
    if not (math.isfinite(v) and v > 0 and (upper is None or v < upper)):
        rng = f"0 < {name}" + (f" < {upper:g}" if upper is not None else "")
        raise CamdynInputError(f"{name}={value} is out of range: {rng}")
    return v


DEFAULT_RTOL = 1e-8
"""The tolerance of an adaptive method (dp54, dop853, rodas4, radau5) when none is given."""

RTOL_MIN = 1e-14
"""The tightest rtol an adaptive method accepts: a run there has no tighter neighbour."""

ORDER = {"rk4": 4, "koster": 2}
"""Order of the fixed-step methods, for Richardson's factor 2^p/(2^p - 1)."""


def estimate_factor(name: str) -> float:
    """The multiplier of |v - v'| for the method called ``name``: Richardson's 2^p/(2^p - 1)
    for a fixed-step method of order p, 1 for an adaptive one."""
    p = ORDER.get(name)
    return 1.0 if p is None else 2.0 ** p / (2.0 ** p - 1.0)


class _FixedStep:
    adaptive = False

    def __post_init__(self):
        object.__setattr__(self, "step", _positive("step", self.step))

    def tighter(self):
        """The same method one notch more accurate, for an error estimate: half the step."""
        return replace(self, step=self.step / 2)

    @property
    def estimate_factor(self) -> float:
        """Richardson's 2^p/(2^p - 1): |v - v'| times this estimates the error of v when v'
        took half the step (p the method's order)."""
        return estimate_factor(self.name)


@dataclass(frozen=True)
class RK4(_FixedStep):
    """Classical fourth-order Runge-Kutta with a fixed step.

    ``step`` is the largest step; each interval between breakpoints is cut
    into equal steps no longer than it, so that steps land on breakpoints.
    """

    step: float
    code = driver.RK4
    name = "rk4"


@dataclass(frozen=True)
class Koster(_FixedStep):
    """The thesis's CAMSHAFT-1 scheme (4.23)-(4.31), fixed step.

    The acceleration is held constant over a step at its value at mid-step,
    evaluated at the mid-step position X + dX, dX = X' theta + X'' theta^2/2
    (4.23), (4.24) with theta = dT/2; the thesis eliminates dX by hand (4.25),
    here the mid-step equation is solved to rounding error by fixed-point
    iteration while that contracts fast, else by Newton's method with the
    model's Jacobian (one step for the linear equation (4.15): the same as the
    elimination), so the run is usable up to the scheme's stability boundary
    dT omega = 2 sqrt(2) (runtime/core/stability.py).  Then
    dX' = X'' dT, dX = (X' + dX'/2) dT (4.28)-(4.31).  The thesis finds it
    stable for dT <= 0.1 tau.  Second-order models only.
    """

    step: float
    code = driver.KOSTER
    name = "koster"


@dataclass(frozen=True)
class DP54:
    """Dormand-Prince 5(4), local extrapolation, PI step-size control, dense output.

    Error per step is measured in the RMS norm against atol + rtol |y|.  ``atol`` is in
    units of each state's tolerance scale (runtime/core/simulator.py tolerance_scales: a
    coordinate's scale from the model's manifest, its rate's that scale times the rate the
    mechanism is driven at), default 1e-3 rtol.  ``state_atol``, pairs (state name, absolute tolerance), sets the
    tolerance of single states: a large one takes a state out of the error control
    (it is then as accurate as the others' accuracy makes it, no more), so that an
    L-stable method can step over a fast mode that only rings (the roller on its
    contact spring) while the follower's error stays controlled.  The consequence:
    that state's own history (the contact force, a ringing roller) is then not
    resolved and must not be read from the run.
    """

    rtol: float = DEFAULT_RTOL
    atol: float | None = None
    first_step: float | None = None
    max_step: float = math.inf
    state_atol: tuple = ()
    code = driver.DP54
    name = "dp54"
    adaptive = True

    def __post_init__(self):
        object.__setattr__(self, "rtol", _positive("rtol", self.rtol, 1.0))
        if self.rtol < RTOL_MIN:
            raise CamdynInputError(f"rtol={self.rtol:g} is out of range: {RTOL_MIN:g} <= rtol < 1")
        if self.atol is not None:
            object.__setattr__(self, "atol", _positive("atol", self.atol))
        if self.first_step is not None:
            object.__setattr__(self, "first_step", _positive("first_step", self.first_step))
        if self.max_step != math.inf:
            object.__setattr__(self, "max_step", _positive("max_step", self.max_step))
        pairs = tuple(dict(self.state_atol).items())
        object.__setattr__(self, "state_atol", tuple(
            (name, _positive(f"state_atol[{name}]", value)) for name, value in pairs))

    @property
    def notch(self) -> float:
        """How much tighter the run of the error estimate is (:meth:`tighter`): 100, or 10
        where rtol/100 would pass the tightest rtol there is."""
        return 100.0 if self.rtol / 100 >= RTOL_MIN else 10.0

    def tighter(self):
        """The same method one notch more accurate, for an error estimate: rtol and every
        absolute tolerance divided by :attr:`notch` (100), or None at the tightest rtol there
        is.  A run at rtol/10 was the notch once; its error, a tenth of the run's where the
        error follows the tolerance, is left out of |v - v'| (0.88 of the true error on
        smooth problems), and where it does not follow it (steps that happen to fall well
        at rtol, badly at rtol/10) |v - v'| missed the error by up to 14 times, measured
        over 96 random one-DOF, CAMSHAFT-1 and CAMSHAFT-2 runs a method (rtol 1e-10 to 1e-5,
        against DOP853 at 3e-14).  At rtol/100 the largest miss was 1.25 times for DP54,
        DOP853 and RODAS4 and 2.7 for RADAU5 (the median 1.01), which :attr:`estimate_factor`
        covers; the estimate's run costs 2.5 times the run with DP54 (steps as rtol^(-1/5))
        instead of 1.6."""
        if self.rtol / 10 < RTOL_MIN:
            return None
        k = self.notch
        return replace(self, rtol=self.rtol / k,
                       atol=None if self.atol is None else self.atol / k,
                       state_atol=tuple((name, v / k) for name, v in self.state_atol))

    notch_factor = 1.5
    """The multiplier of |v - v'| with v' at rtol/100: what v' leaves and the misses
    measured there (see :meth:`tighter`)."""

    @property
    def estimate_factor(self) -> float:
        """The multiplier of |v - v'| (see :meth:`tighter`): :attr:`notch_factor` with v' at
        rtol/100; 4 where only rtol/10 is left (rtol below 1e-12), where |v - v'| was 1.1
        times the error at its median and up to 14 at its worst."""
        return self.notch_factor if self.notch == 100.0 else 4.0


@dataclass(frozen=True)
class RODAS4(DP54):
    """RODAS4, the stiff solver: a linearly implicit (Rosenbrock) method of order 4 with an
    embedded order-3 estimate, stiffly accurate and L-stable (Hairer & Wanner, Solving
    Ordinary Differential Equations II, sec. IV.7, the method of their code RODAS).

    Beside Radau IIA of order 5 (RADAU5, radau5) its step is one LU of (I/(h gamma) - J)
    and six triangular solves: there is no Newton iteration that could fail to converge or
    need a complex transformation of the stage system, the cost of a step is fixed, and
    order 4 suits the moderate tolerances of design runs; but it needs a fresh Jacobian and
    LU every step, where RADAU5 keeps them over many.  Stiffly
    accurate and L-stable, it damps the parasitic high frequencies (a stiff shaft, a beam's
    higher modes, a penalty contact) in one step instead of resolving them, as DP54 must to
    stay stable.  The Jacobian is the model's generated one where it is symbolic, else
    central differences of the right-hand side (a Rosenbrock method needs an accurate
    Jacobian for its order; forward differences were not accurate enough on the beam
    follower), and df/dt central differences; afresh at every accepted point and kept
    through rejections: 2 right-hand-side calls per step with the generated Jacobian,
    2 n_states + 2 without, counted in n_rhs.  Error control, breakpoints and events
    are those of DP54 (rtol, atol the same way); dense output is the cubic Hermite
    interpolant of the recorded points and slopes, O(h^4) like the method.
    """

    code = driver.RODAS
    name = "rodas4"


@dataclass(frozen=True)
class DOP853(DP54):
    """Dormand-Prince 8(5,3), the explicit pair of order 8 of Hairer, Norsett & Wanner (Solving
    Ordinary Differential Equations I, sec. II.10, their code DOP853), for tight tolerances.

    Twelve stages a step (the slope at the new point serves the next one) and three more for
    its dense output of order 7, so that sampled figures and located events keep the method's
    accuracy.  The step is controlled by DOP853's combination of a fifth- and a third-order
    error estimate; options, error estimates, events and the stiffness note are DP54's.  Below
    rtol of about 1e-7 it needs several times fewer right-hand-side calls than DP54 for the
    same error; at loose tolerances DP54 is the cheaper one.

    Chosen over Verner's pairs because it comes whole: its error estimate, its dense output of
    matching order and its stiffness test are published and proven together in one code,
    while an order-9 pair needs 16 stages a step and more for its dense output, and pays off
    only below rtol of about 1e-12, where rounding in double precision sets the limit anyway.
    On CAMSHAFT-1 at U0 error 1e-10 it needs a third of DP54's right-hand-side calls
    integrating the dwell, a seventeenth stepping over it exactly (bench/results).
    """

    code = driver.DOP853
    name = "dop853"


@dataclass(frozen=True)
class RKN12(DP54):
    """The Runge-Kutta-Nystrom pair of order 12 with an embedded order 10 of Dormand,
    El-Mikkawy & Prince (High-order embedded Runge-Kutta-Nystrom formulae, IMA J. Numer. Anal.
    7 (1987) 423-430), for models whose accelerations do not depend on the velocities and
    that have no first-order states: q'' = g(t, q), as CAMSHAFT-1 (4.15), the undamped one-DOF
    follower (3.1) and the chain.  Its stages take positions only, so order 12 costs 17 calls a
    step; on CAMSHAFT-1 at U0 error 1e-10 it needs about half of DOP853's calls (bench/results).

    Its dense output (degree 11, through the state at eight interior nodes of each step, made
    by steps of the method itself) costs 128 more calls a step and is made when first used,
    by a second run taking the same steps (Simulator's ``dense_output``).  Models with
    events (CAMSHAFT-2's, a contact's) are refused: events are located on the dense output as
    the run goes.  Options and error estimates are DP54's.
    """

    code = driver.RKN12
    name = "rkn12"


@dataclass(frozen=True)
class RADAU5(DP54):
    """Radau IIA of order 5, the implicit Runge-Kutta method of three stages of Hairer & Wanner's
    code RADAU5 (Solving Ordinary Differential Equations II, sec. IV.8), for stiff problems.

    A collocation method at the right Radau points: stiffly accurate (the last stage is the new
    state, so a fast damped mode sits on its slow manifold after every step) and L-stable
    (a mode far beyond the step is damped to nothing, not reflected as by the trapezoidal rule),
    of order 5 (stage order 3), and it keeps its order 5 in the positions of an index-1
    differential-algebraic system (sec. VI.1): a stiff contact spring or a penalty constraint in
    its rigid limit does not lower it, where RODAS4's order 4 needs a new, accurate Jacobian
    every step to hold.  Its stage equations are solved by a simplified Newton iteration with
    the Jacobian kept over many steps while the iteration converges fast (Hairer's contraction
    test, theta <= 0.001 with the model's generated Jacobian, 0.1 with a difference one) and
    the LU factors kept while the step stays within 1.0-1.2 times the factored one; an
    iteration that would not converge shortens the step at once.  Error estimate: RADAU5's
    embedded one of order 3 (one more solve with the factors, refined after a first or rejected
    step); Gustafsson's predictive step control.  The real and complex transformed systems of
    the three stages (one real n x n, one complex n x n) are factored, the complex one in
    complex arithmetic (half the flops of its real form of size 2n).  Dense output and event location: the cubic Hermite interpolant of
    the recorded points and slopes, O(h^4) like the collocation polynomial (which RADAU5's
    CONTR5 interpolates), to which it is equal in order.  rtol is used as given (RADAU5 itself
    maps it to 0.1 rtol^(2/3)); options, breakpoints, events, state_atol and error estimates
    are DP54's.  The Jacobian is the model's generated one where it has one, else central
    differences of the right-hand side (2 n_states calls, counted in n_rhs).
    """

    notch_factor = 3.0
    """RADAU5's |v - v'| with v' at rtol/100 missed the error by up to 2.7 times over the runs
    :meth:`DP54.tighter` measured (its cubic Hermite dense output, whose error the step
    control does not see, sets its figures' error on some of them)."""

    code = driver.RADAU
    name = "radau5"


METHODS = {"rk4": RK4, "dp54": DP54, "dop853": DOP853, "koster": Koster, "rodas4": RODAS4,
           "radau5": RADAU5, "rkn12": RKN12}
ADAPTIVE = tuple(name for name, cls in METHODS.items() if cls.adaptive)
"""The methods with error control and dense output: those scenes and the beam follower take."""


_NOTCHES: ContextVar[int] = ContextVar("camdyn_tighter_notches", default=0)


@contextmanager
def tightened(notches: int = 1):
    """Every method made inside (by :func:`make` or a Simulator) one (or ``notches``) notch
    tighter: an error estimate of any computation built on runs, however composite, is its
    value's change when computed again inside ``with tightened():``."""
    token = _NOTCHES.set(_NOTCHES.get() + notches)
    try:
        yield
    finally:
        _NOTCHES.reset(token)


def notches() -> int:
    """How many notches tighter methods are made here (see :func:`tightened`)."""
    return _NOTCHES.get()


def apply_notches(method):
    """``method`` tightened by the notches in force (:func:`tightened`); a CamdynInputError
    when it cannot be tightened that far."""
    for _ in range(_NOTCHES.get()):
        tighter = method.tighter()
        if tighter is None:
            raise CamdynInputError(f"rtol={method.rtol:g} is the tightest there is: no run one "
                                   "notch tighter for an error estimate (give a larger rtol)")
        method = tighter
    return method


def make(name: str, *, rtol=None, atol=None, step=None, state_atol=()):
    """A method from its name and the options given on a command line or API call
    (``state_atol``: pairs or a dict, state name -> absolute tolerance)."""
    if name not in METHODS:
        raise CamdynInputError(f"unknown method {name!r}; choose one of {', '.join(METHODS)}")
    cls = METHODS[name]
    if cls.adaptive:
        if step is not None:
            raise CamdynInputError("step applies to the fixed-step methods rk4 and koster; "
                                   f"{name} takes rtol")
        return cls(rtol=DEFAULT_RTOL if rtol is None else rtol, atol=atol,
                   state_atol=tuple(dict(state_atol or ()).items()))
    if rtol is not None or atol is not None or state_atol:
        raise CamdynInputError(f"rtol/atol apply to {', '.join(ADAPTIVE)}; {name} takes step")
    if step is None:
        raise CamdynInputError(f"method {name} needs step")
    return cls(step=step)
