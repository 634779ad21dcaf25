"""A model is a declaration: coordinates, energies, forces, constraints, inputs.

Nothing here derives anything; :mod:`camdyn.derive.lagrange` turns a
:class:`Model` into equations of motion and :mod:`camdyn.derive.render` into
Cython.  Names follow the thesis (tau, Fa, Fv, H, X, ...), so a declaration
reads next to the cited equations.
"""
from __future__ import annotations

import keyword
import math
import re
from dataclasses import dataclass, field
from typing import ClassVar

import sympy as sp

from .printer import MATH_FUNCTIONS

_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
# names the generated code itself uses (its own locals start with "_"), C and
# Cython keywords, and the libc math functions it imports
_RESERVED = set(keyword.kwlist) | {
    "ctx", "p", "t", "json", "MODEL", "MANIFEST",
    "int", "double", "float", "char", "long", "short", "signed", "unsigned", "const",
    "static", "extern", "register", "volatile", "auto", "restrict", "struct", "union",
    "enum", "typedef", "sizeof", "goto", "switch", "case", "default", "void", "inline",
    "cdef", "cpdef", "ctypedef", "cimport", "include", "nogil", "gil", "public", "api",
    "readonly", "NULL", "DEF", "IF", "ELIF", "ELSE", "M_PI", *MATH_FUNCTIONS,
}


def _check_name(name: str, what: str) -> str:
    if not _NAME.match(name) or name in _RESERVED:
        raise ValueError(f"{what} name {name!r} is not usable in generated code")
    return name


def time(name: str = "T") -> sp.Symbol:
    """The independent variable (dimensionless T = t/t_m in the thesis models)."""
    return sp.Symbol(name, real=True)


@dataclass(frozen=True)
class Parameter:
    """A model parameter with unit, default and admissible range.

    ``low``/``high`` bound the range; ``open_low``/``open_high`` say whether
    the bound itself is excluded.  ``math.inf`` means unbounded.
    """

    name: str
    default: float
    unit: str
    doc: str
    low: float = -math.inf
    high: float = math.inf
    open_low: bool = False
    open_high: bool = False

    def __post_init__(self):
        _check_name(self.name, "parameter")
        if not self.admits(self.default):
            raise ValueError(f"default of {self.name} is outside its own range")

    @property
    def symbol(self) -> sp.Symbol:
        if self.low >= 0 and self.open_low:
            return sp.Symbol(self.name, positive=True)
        if self.low >= 0:
            return sp.Symbol(self.name, nonnegative=True)
        return sp.Symbol(self.name, real=True)

    def admits(self, value: float) -> bool:
        if not math.isfinite(value):
            return False
        lo_ok = value > self.low if self.open_low else value >= self.low
        hi_ok = value < self.high if self.open_high else value <= self.high
        return lo_ok and hi_ok

    def range_text(self) -> str:
        lo = "" if self.low == -math.inf else f"{self.low:g} {'<' if self.open_low else '<='} "
        hi = "" if self.high == math.inf else f" {'<' if self.open_high else '<='} {self.high:g}"
        if not lo and not hi:
            return f"{self.name} finite"
        return f"{lo}{self.name}{hi}"


@dataclass(frozen=True)
class Coordinate:
    """A generalized coordinate q(t); its velocity is a state too.

    ``scale`` is a typical magnitude of q (and of q' per unit time), used for
    the absolute tolerance of adaptive integrators.
    """

    name: str
    unit: str
    doc: str
    scale: float = 1.0
    initial: float | sp.Expr = 0
    initial_rate: float | sp.Expr = 0

    def __post_init__(self):
        _check_name(self.name, "coordinate")

    def __call__(self, t: sp.Symbol) -> sp.Expr:
        return sp.Function(self.name, real=True)(t)


@dataclass(frozen=True)
class Output:
    """A named quantity computed from t, q, q' and q'' (e.g. X'')."""

    name: str
    expr: sp.Expr
    unit: str
    doc: str

    def __post_init__(self):
        _check_name(self.name, "output")


class CamFunction(sp.Function):
    """Base of the symbolic cam input H and its derivatives.

    ``H(arg).diff(t)`` gives ``Hd(arg) * d(arg)/dt`` by the chain rule, so a
    model may drive the follower with H(T) (constant fictitious angular
    velocity) or with H(B) of a cam angle coordinate B (CAMSHAFT-2, (5.15)).
    The generated code replaces each H(arg) by a call of the cam-law library.
    """

    family: str = ""
    order: int = 0
    max_order = 3

    @classmethod
    def eval(cls, arg):
        return None

    def fdiff(self, argindex=1):
        if self.order >= self.max_order:
            raise ValueError(f"cam input {self.family}: derivative of order > {self.max_order}")
        return cam_input(self.family, self.order + 1)(self.args[0])

    def _sympystr(self, printer):
        return f"{self.family}{'d' * self.order}({printer.doprint(self.args[0])})"


_CAM_CLASSES: dict = {}


def cam_input(family: str = "H", order: int = 0) -> type:
    """The function class d^order H/darg^order of the cam input ``family``."""
    key = (family, order)
    if key not in _CAM_CLASSES:
        _check_name(family, "cam input")
        name = family + "d" * order
        _CAM_CLASSES[key] = type(name, (CamFunction,), {"family": family, "order": order})
    return _CAM_CLASSES[key]


@dataclass(frozen=True)
class FirstOrder:
    """A state z(t) given by an explicit first-order equation z' = rate.

    For what Lagrange's equations do not produce: the electrical lag of the
    motor (A.5.6), a massless gear or roller in a squeeze film (6.9), (6.41).
    ``rate`` may contain t, the coordinates, their rates, other first-order
    states and modes.  States come after q and q' in the state vector.
    """

    name: str
    unit: str
    doc: str
    rate: sp.Expr
    scale: float = 1.0
    initial: float | sp.Expr = 0

    def __post_init__(self):
        _check_name(self.name, "first-order state")

    def __call__(self, t: sp.Symbol) -> sp.Expr:
        return sp.Function(self.name, real=True)(t)


@dataclass(frozen=True)
class Mode:
    """A discrete state of a nonsmooth force element: which wall a roller touches,
    whether friction sticks or slips in which direction.

    Expressions depend on it through :meth:`select`; it changes only at
    :class:`Event` s, which the integrators locate.
    """

    name: str
    values: tuple
    doc: str
    initial: str = ""

    def __post_init__(self):
        _check_name(self.name, "mode")
        if len(set(self.values)) != len(self.values) or len(self.values) < 2:
            raise ValueError(f"mode {self.name}: at least two distinct values")
        if self.initial and self.initial not in self.values:
            raise ValueError(f"mode {self.name}: initial value {self.initial!r} not among its values")

    @property
    def symbol(self) -> sp.Symbol:
        return sp.Symbol(f"mode_{self.name}", integer=True)

    def index(self, value: str) -> int:
        try:
            return self.values.index(value)
        except ValueError:
            raise ValueError(f"mode {self.name} has no value {value!r}; it has {self.values}") from None

    def select(self, **by_value) -> sp.Expr:
        """The expression of the current value: ``mode.select(lower=..., free=0, upper=...)``."""
        missing = set(self.values) - set(by_value)
        if missing:
            raise ValueError(f"mode {self.name}: no expression for {sorted(missing)}")
        pieces = [(sp.sympify(by_value[v]), sp.Eq(self.symbol, k)) for k, v in enumerate(self.values[:-1])]
        return sp.Piecewise(*pieces, (sp.sympify(by_value[self.values[-1]]), True))


@dataclass(frozen=True)
class Branch:
    """What an event does when ``condition`` holds: new mode values, state resets."""

    modes: dict
    condition: object = True
    resets: dict = field(default_factory=dict)


@dataclass(frozen=True)
class Event:
    """A zero crossing of ``g`` in ``direction`` (+1 upward, -1 downward), armed while
    the modes have the values in ``armed`` ({mode name: (values, ...)}); at the
    crossing the first branch whose condition holds is applied."""

    name: str
    g: sp.Expr
    direction: int
    armed: dict
    branches: tuple

    def __post_init__(self):
        _check_name(self.name, "event")
        if self.direction not in (-1, 1):
            raise ValueError(f"event {self.name}: direction must be +1 or -1")


@dataclass(frozen=True)
class Residual:
    """What residual-vibration post-processing reads (thesis sec. 3.3).

    ``error`` is the positional-error output u = X - H, ``acceleration`` the
    follower acceleration output X'', ``rise_end`` the end of the rise in
    model time (T = 1 in the dimensionless models).
    """

    error: str
    acceleration: str
    rise_end: float = 1.0
    rise_state: str = ""
    """When set, the rise ends where this state reaches ``rise_end`` (the cam angle B of
    CAMSHAFT-2), not at that time."""


@dataclass(frozen=True)
class Constraint:
    """A holonomic constraint Phi(Q, t) = 0 and the output of its Lagrange multiplier.

    The equations are M Q'' + Phi_Q^T lambda = f, so the multiplier's sign and unit follow
    from how ``expr`` is written: lambda times dPhi/dq is a generalized force, and its unit
    is (force of q) / (unit of Phi).  ``name`` labels the constraint in the manifest and in
    messages (it may equal an output that reports the residual); ``multiplier``, ``unit``
    and ``doc`` declare the output through which the generated code reports lambda.
    """

    name: str
    expr: sp.Expr
    multiplier: str
    unit: str
    doc: str

    def __post_init__(self):
        _check_name(self.name, "constraint")
        _check_name(self.multiplier, "multiplier")


@dataclass(frozen=True)
class RDFDProfile:
    """The cam input of a constrained model: a rise-dwell-fall-dwell profile, periodic in 2 pi.

    The normalized displacement R(theta) of cam input ``family`` rises by the chosen cam law
    over [0, rise), dwells at 1 to pi, falls by the same law over [pi, pi + rise) and dwells
    at 0 to 2 pi.  ``rise`` is an expression of the parameters (usually one parameter's
    symbol); the model uses R(theta) and its derivatives through ``cam_input(family, k)``.
    The segment ends are breakpoints the model declares as events.
    """

    family: str
    rise: sp.Expr
    kind: ClassVar[str] = "RDFD, periodic in 2 pi"
    """What the manifest says the profile is."""
    template: ClassVar[str] = "profile_rdfd.j2"
    """The template that prints ``_profile(ctx, theta, rise, out)`` for the generated module."""

    def __post_init__(self):
        _check_name(self.family, "cam input")


@dataclass(frozen=True)
class ConstraintSolver:
    """How the generated code solves a constrained model: two of its parameters, read at run
    time, and which coordinates are dependent.

    ``formulation`` (a parameter, so a run chooses without regenerating; README "Constrained
    models"):

    0. augmented: the index-1 system [[M, Phi_Q^T], [Phi_Q, 0]] [Q''; lambda] =
       [f; gamma - 2 w Phi' - w^2 Phi], stabilized by Baumgarte's terms with the critically
       damped rate w = ``baumgarte_rate`` (w = 0: no stabilization, the residual drifts);
    1. partitioned: the ``dependent`` coordinates are recovered from the others by Newton's
       method on Phi = 0 at every evaluation, their rates from Phi_Q Q' = -Phi_t; the same
       augmented system (without Baumgarte's terms) then gives Q'';
    2. projection: the augmented system without Baumgarte's terms, and after every accepted
       step the state projected back onto Phi = 0 and Phi_Q Q' = -Phi_t (the template's
       ``project``): no rate to tune.

    ``dependent`` names the n_c dependent coordinates (partitioning, and the consistent
    initial values of every formulation: they are computed from the others); empty means
    the last n_c declared.  Phi_Q restricted to them must be invertible along the motion.
    """

    baumgarte_rate: sp.Symbol
    formulation: sp.Symbol
    dependent: tuple = ()

    def dependent_indices(self, model: "Model") -> list:
        """Indices of the dependent coordinates of ``model``, in the order named."""
        names = [c.name for c in model.coordinates]
        nc = len(model.constraints)
        if not self.dependent:
            return list(range(len(names) - nc, len(names)))
        return [names.index(d) for d in self.dependent]


@dataclass(frozen=True)
class Model:
    """A cam-mechanism model as the thesis sets one up (energies and forces).

    The layer derives M(q, t) q'' + Phi_q^T lambda = f(q, q', t) by Lagrange's
    equations from kinetic energy ``kinetic``, potential energy ``potential``,
    Rayleigh dissipation ``dissipation`` and generalized forces ``forces``
    (one per coordinate, not derivable from a potential).  ``constraints``
    are holonomic, Phi(q, t) = 0 (:class:`Constraint`); a model with constraints declares
    its ``solver`` (:class:`ConstraintSolver`) and, when a cam drives it, its ``profile``
    (:class:`RDFDProfile`); without a profile it has no cam input.
    """

    name: str
    title: str
    reference: str
    doc: str
    time: sp.Symbol
    time_unit: str
    coordinates: tuple
    kinetic: sp.Expr
    potential: sp.Expr
    parameters: tuple
    outputs: tuple
    dissipation: sp.Expr = sp.Integer(0)
    forces: tuple = ()
    constraints: tuple = ()
    residual: Residual | None = None
    options: tuple = field(default_factory=tuple)
    first_order: tuple = ()
    modes: tuple = ()
    events: tuple = ()
    profile: RDFDProfile | None = None
    solver: ConstraintSolver | None = None
    variant: tuple = ()
    """Lines saying in words what this member of a model family contains (the options of a
    DYNACAM variant), printed in the generated file's header."""
    expand_forces: bool = True
    """Whether Lagrange's equations multiply the generalized forces out with the rest; False
    keeps forces free of accelerations as written, for forces of long geometric factors (a
    rocker's ratios, derive/models/dynacam.py) that expanding would blow up."""

    def __post_init__(self):
        _check_name(self.name, "model")
        names = [c.name for c in self.coordinates]
        names += [c.name + "d" for c in self.coordinates]
        names += [z.name for z in self.first_order] + [m.name for m in self.modes]
        names += [p.name for p in self.parameters] + [o.name for o in self.outputs]
        names += [e.name for e in self.events]
        names += [c.multiplier for c in self.constraints if isinstance(c, Constraint)]
        dup = {n for n in names if names.count(n) > 1}
        if dup:
            raise ValueError(f"model {self.name}: names used twice: {sorted(dup)}")
        if self.forces and len(self.forces) != len(self.coordinates):
            raise ValueError(f"model {self.name}: one generalized force per coordinate")

        self._check_constraints()

        modes = {m.name: m for m in self.modes}
        for e in self.events:
            for name, values in list(e.armed.items()) + [(k, (v,)) for b in e.branches for k, v in b.modes.items()]:
                if name not in modes:
                    raise ValueError(f"event {e.name}: unknown mode {name!r}")
                for v in values:
                    modes[name].index(v)

    def _check_constraints(self):
        for k, c in enumerate(self.constraints):
            if not isinstance(c, Constraint):
                raise ValueError(f"model {self.name}: constraint {k + 1} is a {type(c).__name__}; "
                                 "declare it as Constraint(name, expr, multiplier, unit, doc)")
        if not self.constraints:
            if self.profile is not None or self.solver is not None:
                raise ValueError(f"model {self.name}: a profile or a constraint solver is "
                                 "declared but no constraints")
            return
        if self.solver is None:
            raise ValueError(f"model {self.name}: constrained, but no solver declared; give "
                             "solver=ConstraintSolver(baumgarte_rate=..., formulation=...) "
                             "with two of its parameters")
        if len(self.constraints) >= len(self.coordinates):
            raise ValueError(f"model {self.name}: {len(self.constraints)} constraints on "
                             f"{len(self.coordinates)} coordinates leave no motion")
        params = {p.name for p in self.parameters}
        for role in ("baumgarte_rate", "formulation"):
            sym = getattr(self.solver, role)
            if not isinstance(sym, sp.Symbol) or sym.name not in params:
                raise ValueError(f"model {self.name}: solver {role}={sym!r} is not one of its "
                                 f"parameters ({', '.join(sorted(params))})")
        coords = [c.name for c in self.coordinates]
        dep = list(self.solver.dependent)
        if dep and (len(dep) != len(self.constraints) or len(set(dep)) != len(dep)
                    or not set(dep) <= set(coords)):
            raise ValueError(f"model {self.name}: solver dependent={tuple(dep)} must name "
                             f"{len(self.constraints)} distinct coordinates among "
                             f"{', '.join(coords)} (one per constraint)")
        if self.profile is not None and not sp.sympify(self.profile.rise).free_symbols <= {
                p.symbol for p in self.parameters}:
            raise ValueError(f"model {self.name}: profile rise {self.profile.rise} is not an "
                             "expression of its parameters")

    @property
    def q(self) -> list:
        return [c(self.time) for c in self.coordinates]

    @property
    def z(self) -> list:
        return [s(self.time) for s in self.first_order]

    def parameter(self, name: str) -> Parameter:
        for p in self.parameters:
            if p.name == name:
                return p
        raise KeyError(name)
