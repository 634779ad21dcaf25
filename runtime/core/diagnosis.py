"""Why a run failed, in the model's own terms.

The compiled loops stop with a status (runtime/engine/driver.pyx STATUS_TEXT) that says what
the integrator saw, not why: a mass matrix that is not positive definite, or a right-hand side
that is not finite, makes the step size collapse under DP54 ("the step size fell below the
resolution of the time axis") or the state non-finite under RK4.  After a failure, and only
then (a successful run pays nothing), :func:`explain` looks at the last state the run
accepted and names the cause:

* the mass matrix M (the model's ``mass_stiffness``) there, and at the time the loop gave up
  with that state: its Cholesky factorization fails
  at the first coordinate whose leading block is not positive definite (a negative or zero
  mass or inertia, a declared range that admits one);
* else the right-hand side there: the first component that is not finite, with the state
  that made it;
* else the integrator's own words.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..engine import driver


SINGULAR = 1e-10
"""A pivot below this fraction of its value at the run's start makes the mass matrix singular
for the integrator: q'' grows without bound and the step collapses before it reaches zero."""


def pivots(M: np.ndarray) -> np.ndarray:
    """The pivots (squared diagonal of L) of M's Cholesky factorization, up to and including
    the first that is not positive."""
    n = M.shape[0]
    L = np.zeros_like(M)
    out = []
    for k in range(n):
        v = M[k, k] - L[k, :k] @ L[k, :k]
        out.append(v)
        if not v > 0.0:
            break
        L[k, k] = np.sqrt(v)
        L[k + 1:, k] = (M[k + 1:, k] - L[k + 1:, :k] @ L[k, :k]) / L[k, k]
    return np.array(out)


def not_positive_definite(M: np.ndarray, start: np.ndarray | None = None) -> int | None:
    """The index of the first pivot of M's Cholesky factorization that is not positive (its
    leading (k+1) x (k+1) block is not positive definite), or that has fallen below SINGULAR of
    its value in ``start`` (the pivots at the run's start); None if M is positive definite."""
    piv = pivots(M)
    for k, v in enumerate(piv):
        if not v > 0.0 or (start is not None and k < len(start) and start[k] > 0
                           and v < SINGULAR * start[k]):
            return k
    return None


def _mass(model, p, law_codes, law_pars, t, y, modes):
    M, _ = driver.eval_mass_stiffness(model.capsule, p, law_codes, law_pars, float(t),
                                      np.ascontiguousarray(y, dtype=float), element_modes=modes)
    return M


def mass_fault(model, p, law_codes, law_pars, t: float, y: np.ndarray, modes=None,
               start=None) -> str | None:
    """What is wrong with the mass matrix at (t, y), in words, or None if nothing is;
    ``start``: the mass matrix at the run's first state, against which a pivot that has all
    but vanished counts as singular."""
    if not model.state_names or not model.manifest.get("n_q") or model.manifest.get("constraints"):
        # with constraints M need only be positive definite where they let the model move (a
        # prescribed coordinate may have none): the augmented solve is what fails there
        return None
    M = _mass(model, p, law_codes, law_pars, t, y, modes)
    k = not_positive_definite(M, None if start is None else pivots(start))
    if k is None:
        return None
    name = model.state_names[k]
    if M[k, k] > 0 and np.allclose(M[k, :k], 0.0):
        return (f"the mass matrix becomes singular at {_tname(model)} = {t:.6g}: M[{name}, "
                f"{name}] = {M[k, k]:.3g}, against {start[k, k]:.3g} at the start; check the "
                "masses and inertias the model declares (and their ranges)")
    if k == 0 or np.allclose(M[k, :k], 0.0):
        entry = f"M[{name}, {name}] = {M[k, k]:.6g}"
        why = ": the coordinate has no inertia" if M[k, k] == 0 else " is not positive"
        return (f"the mass matrix is not positive definite at {_tname(model)} = {t:.6g}: "
                f"{entry}{why}; check the masses and inertias the model declares (and their "
                "ranges)")
    return (f"the mass matrix is not positive definite at {_tname(model)} = {t:.6g}: its "
            f"block up to coordinate {name} has a pivot <= 0; check the masses and inertias "
            "the model declares (and their ranges)")


def rhs_fault(model, p, law_codes, law_pars, t: float, y: np.ndarray, modes=None,
              part=None) -> str | None:
    """The first right-hand side component that is not finite at (t, y), or along the path the
    next step would take from there (Euler steps of 1e-12 to 1e-3 of the time scale: the
    state the rejected steps tried), in words, or None.  ``part``: a constrained model's
    coordinate partition of the run (Simulator.part)."""
    y = np.ascontiguousarray(y, dtype=float)
    if not np.all(np.isfinite(y)):
        return None

    def rhs(tt, yy):
        return driver.eval_rhs(model.capsule, p, law_codes, law_pars, np.array([float(tt)]),
                               yy[None, :], element_modes=modes, part=part)[0]

    f = rhs(t, y)
    if np.all(np.isfinite(f)):
        for dt in (1.0 + abs(t)) * np.logspace(-12, -3, 10):
            ahead = y + dt * f
            fa = rhs(t + dt, ahead)
            if not np.all(np.isfinite(fa)):
                t, y, f = t + dt, ahead, fa
                break
    bad = np.flatnonzero(~np.isfinite(f))
    if not bad.size:
        return None
    names = model.state_names
    state = ", ".join(f"{n} = {v:.15g}" for n, v in zip(names, y))
    return (f"the right-hand side is not finite at {_tname(model)} = {t:.6g}: d{names[bad[0]]}/d"
            f"{_tname(model)} = {f[bad[0]]} with the state {state}; check the forces and "
            "potentials the model declares where the state goes there")


@dataclass(frozen=True)
class Fault:
    """The cause of a failed run: ``text`` in words, ``at_start`` when the run's first state
    already has it (then the input is at fault, not the run)."""

    text: str
    at_start: bool


def explain(model, p, law_codes, law_pars, out, modes=None, part=None,
            start=None) -> Fault | None:
    """The cause of the failed run ``out`` (driver.Integrator.run's record), found at the last
    state it accepted, or None when neither the mass matrix nor the right-hand side shows one;
    ``part`` as :func:`rhs_fault` takes it.  ``start``: (t0, y0) the run started from, where
    the cause is looked for when the run recorded no point (its first slope not finite)."""
    ns = len(model.state_names)
    if out.n < 1:
        if start is None:
            return None
        row = np.concatenate([[float(start[0])], np.asarray(start[1], dtype=float)])
        out = _Started(row[None, :], 1, out.t_fail, None)
    row = out.rows[out.n - 1]
    t, y = float(row[0]), np.array(row[1:1 + ns])
    element = None
    if modes is not None:
        element = modes
    elif out.modes is not None and len(out.modes) >= out.n and model.manifest.get("modes"):
        element = np.ascontiguousarray(out.modes[out.n - 1][-len(model.manifest["modes"]):],
                                       dtype=np.intc)
    # at the last accepted state, and at the time the loop gave up with that state (the
    # cause may lie in the step that failed: a mass that vanishes at t_fail)
    times = [t] + ([float(out.t_fail)] if np.isfinite(out.t_fail) and out.t_fail != t else [])
    text = None
    try:
        first = out.rows[0]
        start = (_mass(model, p, law_codes, law_pars, first[0], first[1:1 + ns], element)
                 if model.manifest.get("n_q") and not model.manifest.get("constraints")
                 else None)
        for tt in times:
            text = (mass_fault(model, p, law_codes, law_pars, tt, y, element, start)
                    or rhs_fault(model, p, law_codes, law_pars, tt, y, element, part))
            if text:
                break
    except (ValueError, ArithmeticError):       # a diagnosis must never hide the failure
        return None
    return None if text is None else Fault(text, out.n == 1)


@dataclass
class _Started:
    """The record :func:`explain` reads, of a run that recorded nothing: its start alone."""

    rows: np.ndarray
    n: int
    t_fail: float
    modes: object


def _tname(model) -> str:
    return model.manifest["time"]["name"]
