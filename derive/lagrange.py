"""Lagrange's equations for a declared :class:`~camdyn.derive.model.Model`.

For each coordinate q_i

    d/dt dT/dq'_i - dT/dq_i + dV/dq_i + dD/dq'_i = Q_i - sum_j lambda_j dPhi_j/dq_i

(D the Rayleigh dissipation function, Q_i the generalized forces, Phi the
holonomic constraints).  Collecting the q'' terms gives

    M(q, t) q'' + Phi_q^T lambda = f(q, q', t),     Phi_q q'' = gamma,

the multiplier form of the paper's (15) and (19); without constraints it is
M q'' = f.

Why an own implementation and not ``sympy.physics.mechanics.LagrangesMethod``:
the thesis models are stated as energies plus a *Rayleigh dissipation
function* and *generalized forces per coordinate* (not forces on points of
reference frames), and their inputs are cam laws that enter as functions of
time or of a coordinate.  LagrangesMethod wants forces as (Point, Vector)
pairs and has no dissipation function; wrapping that costs more lines than
the dozen below, and we need M, f, Phi_q and gamma as separate matrices for
code generation anyway.  The result is checked against hand-derived closed
forms in the tests.
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import sympy as sp

from . import symbolic
from .model import Model


@dataclass(frozen=True)
class Equations:
    """M q'' + Phi_q^T lambda = f and Phi_q q'' = gamma of one model."""

    model: Model
    M: sp.Matrix
    f: sp.Matrix
    Phi: sp.Matrix
    Phi_q: sp.Matrix
    gamma: sp.Matrix

    @property
    def q(self):
        return self.model.q

    @property
    def qd(self):
        return [x.diff(self.model.time) for x in self.q]

    @property
    def qdd(self):
        return [x.diff(self.model.time, 2) for x in self.q]

    @cached_property
    def accelerations(self) -> sp.Matrix:
        """q'' = M^-1 f for unconstrained models (symbolic; small M only)."""
        if self.Phi.rows:
            raise ValueError("constrained model: solve the multiplier form instead")
        return symbolic.simplify(self.M.LUsolve(self.f))


def _tidy(e):
    """simplify() where it is cheap; large or mode-dependent (Piecewise) expressions are left
    as derived: simplify would take long and CSE shares their parts anyway."""
    if e.has(sp.Piecewise) or sp.count_ops(e) > 150:
        return e
    return symbolic.simplify(e)


def generic_rank(A: sp.Matrix, seed: int = 0) -> int:
    """The rank of A at a generic point: every symbol, coordinate and applied function (and
    its derivatives) replaced by a pseudo-random number in [0.5, 1.5) from a seeded generator,
    so that the answer does not change from one derivation to the next."""
    rng = random.Random(seed)
    values = {}
    for d in sorted(A.atoms(sp.Subs, sp.Derivative), key=sp.default_sort_key):
        values[d] = sp.Float(0.5 + rng.random())
    for f in sorted(A.atoms(sp.core.function.AppliedUndef), key=sp.default_sort_key):
        values[f] = sp.Float(0.5 + rng.random())
    for x in sorted(A.free_symbols, key=sp.default_sort_key):
        values.setdefault(x, sp.Float(0.5 + rng.random()))
    try:
        numeric = np.array(A.xreplace(values).evalf(), dtype=float)
    except (TypeError, ValueError):     # something left that has no number: no verdict
        return min(A.shape)
    return int(np.linalg.matrix_rank(numeric)) if numeric.size else 0


def derive(model: Model) -> Equations:
    """Equations of motion of ``model`` by Lagrange's equations."""
    t = model.time
    q = model.q
    qd = [x.diff(t) for x in q]
    qdd = [x.diff(t, 2) for x in q]
    n = len(q)
    forces = model.forces or (0,) * n

    lhs, given = [], []
    for i in range(n):
        kin = model.kinetic.diff(qd[i]).diff(t) - model.kinetic.diff(q[i])
        e = kin + model.potential.diff(q[i]) + model.dissipation.diff(qd[i])
        # a generalized force free of accelerations may be kept as written (Model's
        # expand_forces): expanding a force of a long geometric ratio (a rocker's,
        # derive/models/dynacam.py) multiplies it out into more terms than anything needs
        if model.expand_forces or sp.sympify(forces[i]).has(*qdd):
            e -= forces[i]
            given.append(sp.Integer(0))
        else:
            given.append(sp.sympify(forces[i]))
        lhs.append(sp.expand(e))

    M = sp.Matrix(n, n, lambda i, j: lhs[i].coeff(qdd[j]))
    zero = {a: 0 for a in qdd}
    # xreplace, not subs: the accelerations are exact subtrees, and subs is slow on large
    # mode-dependent (Piecewise) expressions
    f = sp.Matrix([-lhs[i].xreplace(zero) + given[i] for i in range(n)])
    # the equations must be linear in q'': check that nothing was left over
    for i in range(n):
        rest = sp.expand(lhs[i] - sum(M[i, j] * qdd[j] for j in range(n)) + f[i] - given[i])
        if rest != 0:
            raise ValueError(f"{model.name}: equation {i} is not linear in the accelerations")
    # first-order states enter f through their rates (damping on a motor angle, ...)
    rates = {z(t).diff(t): z.rate for z in model.first_order}
    if rates:
        f = f.xreplace(rates)
    M = M.applyfunc(_tidy)
    f = f.applyfunc(_tidy)
    if not model.constraints:
        # a coordinate without inertia makes M singular: its equation would divide by zero
        for i in range(n):
            if all(M[i, j] == 0 for j in range(n)):
                raise ValueError(f"{model.name}: coordinate {q[i].func} has no inertia (the "
                                 f"kinetic energy has no term in its rate), so M is singular")

    Phi = sp.Matrix([c.expr for c in model.constraints])
    if Phi.rows:
        Phi_q = Phi.jacobian(q)
        rank = generic_rank(Phi_q)
        if rank < Phi.rows:
            raise ValueError(
                f"{model.name}: the {Phi.rows} constraints are dependent or contradict each "
                f"other (their Jacobian Phi_q has rank {rank} at a generic point): each "
                "constraint must remove a degree of freedom of its own")
        # d2Phi/dt2 = Phi_q q'' - gamma: gamma is minus the part free of q''
        gamma = (-sp.expand(Phi.diff(t, 2)).xreplace(zero)).applyfunc(_tidy)
    else:
        Phi_q = sp.zeros(0, n)
        gamma = sp.zeros(0, 1)
    return Equations(model, M, f, Phi, Phi_q, gamma)
