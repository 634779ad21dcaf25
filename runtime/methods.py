"""Integration methods: one small class each, checked options, one compiled loop.

The loops themselves are in :mod:`camdyn.runtime._integrate`; these classes
only validate what the user asked for and say which loop to run with which
step control.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from . import _integrate
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


@dataclass(frozen=True)
class RK4:
    """Classical fourth-order Runge-Kutta with a fixed step.

    ``step`` is the largest step; each interval between breakpoints is cut
    into equal steps no longer than it, so that steps land on breakpoints.
    """

    step: float
    code = _integrate.RK4
    name = "rk4"
    adaptive = False

    def __post_init__(self):
        object.__setattr__(self, "step", _positive("step", self.step))


@dataclass(frozen=True)
class Koster:
    """The thesis's CAMSHAFT-1 scheme (4.23)-(4.31), fixed step.

    The acceleration is held constant over a step at its value at mid-step,
    evaluated at the mid-step position X + dX, dX = X' theta + X'' theta^2/2
    (4.23), (4.24) with theta = dT/2; the thesis eliminates dX by hand (4.25),
    here the mid-step equation is solved to rounding error by fixed-point
    iteration while that contracts fast, else by Newton's method with the
    model's Jacobian (one step for the linear equation (4.15): the same as the
    elimination), so the run is usable up to the scheme's stability boundary
    dT omega = 2 sqrt(2) (runtime/stability.py).  Then
    dX' = X'' dT, dX = (X' + dX'/2) dT (4.28)-(4.31).  The thesis finds it
    stable for dT <= 0.1 tau.  Second-order models only.
    """

    step: float
    code = _integrate.KOSTER
    name = "koster"
    adaptive = False

    def __post_init__(self):
        object.__setattr__(self, "step", _positive("step", self.step))


@dataclass(frozen=True)
class DP54:
    """Dormand-Prince 5(4), local extrapolation, PI step-size control, dense output.

    Error per step is measured in the RMS norm against atol + rtol |y|;
    ``atol`` defaults to rtol times the state scales of the model's manifest
    times 1e-3.  ``state_atol``, pairs (state name, absolute tolerance), sets the
    tolerance of single states: a large one takes a state out of the error control
    (it is then as accurate as the others' accuracy makes it, no more), so that an
    L-stable method can step over a fast mode that only rings (the roller on its
    contact spring) while the follower's error stays controlled.  The consequence:
    that state's own history (the contact force, a ringing roller) is then not
    resolved and must not be read from the run.
    """

    rtol: float = 1e-8
    atol: float | None = None
    first_step: float | None = None
    max_step: float = math.inf
    state_atol: tuple = ()
    code = _integrate.DP54
    name = "dp54"
    adaptive = True

    def __post_init__(self):
        object.__setattr__(self, "rtol", _positive("rtol", self.rtol, 1.0))
        if self.rtol < 1e-14:
            raise CamdynInputError(f"rtol={self.rtol:g} is out of range: 1e-14 <= rtol < 1")
        if self.atol is not None:
            object.__setattr__(self, "atol", _positive("atol", self.atol))
        if self.first_step is not None:
            object.__setattr__(self, "first_step", _positive("first_step", self.first_step))
        if self.max_step != math.inf:
            object.__setattr__(self, "max_step", _positive("max_step", self.max_step))
        pairs = tuple(dict(self.state_atol).items())
        for name, value in pairs:
            _positive(f"state_atol[{name}]", value)
        object.__setattr__(self, "state_atol", pairs)


@dataclass(frozen=True)
class RODAS4(DP54):
    """RODAS4, the stiff solver: a linearly implicit (Rosenbrock) method of order 4 with an
    embedded order-3 estimate, stiffly accurate and L-stable (Hairer & Wanner, Solving
    Ordinary Differential Equations II, sec. IV.7, the method of their code RODAS).

    Chosen over Radau IIA of order 5 (RADAU5) because a step is one LU of
    (I/(h gamma) - J) and six triangular solves: there is no Newton iteration that could
    fail to converge or need a complex transformation of the stage system, the cost of a
    step is fixed, and order 4 suits the moderate tolerances of design runs.  Stiffly
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

    code = _integrate.RODAS
    name = "rodas4"


METHODS = {"rk4": RK4, "dp54": DP54, "koster": Koster, "rodas4": RODAS4}
ADAPTIVE = tuple(name for name, cls in METHODS.items() if cls.adaptive)
"""The methods with error control and dense output: those scenes and the beam follower take."""


def make(name: str, *, rtol=None, atol=None, step=None):
    """A method from its name and the options given on a command line or API call."""
    if name not in METHODS:
        raise CamdynInputError(f"unknown method {name!r}; choose one of {', '.join(METHODS)}")
    cls = METHODS[name]
    if cls.adaptive:
        if step is not None:
            raise CamdynInputError("step applies to the fixed-step methods rk4 and koster; "
                                   f"{name} takes rtol")
        return cls(rtol=1e-8 if rtol is None else rtol, atol=atol)
    if rtol is not None or atol is not None:
        raise CamdynInputError(f"rtol/atol apply to dp54 and rodas4; {name} takes step")
    if step is None:
        raise CamdynInputError(f"method {name} needs step")
    return cls(step=step)
