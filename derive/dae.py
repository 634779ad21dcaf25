"""Code generation for constrained models: M Q'' + Phi_Q^T lambda = f, Phi(Q, t) = 0.

The generated module has the same C interface as every other model (runtime/engine/abi.pxd), so
the compiled integrators of runtime/engine/loops.pxi run it unchanged; what differs is how its
right-hand side finds Q'' (template ``constrained.pyx.j2``), in one of three formulations
chosen at run time by the parameter the model's :class:`~camdyn.derive.model.ConstraintSolver`
names as ``formulation``:

0. augmented: the index-1 system [[M, Phi_Q^T], [Phi_Q, 0]] [Q''; lambda] = [f; gamma_B],
   gamma_B = gamma - 2 w Phi' - w^2 Phi (Baumgarte stabilization with the critically
   damped rate w, the solver's ``baumgarte_rate``), one dense LU with partial pivoting per
   evaluation;
1. partitioned: the solver's ``dependent`` coordinates (by default the last n_c) are
   recovered from the independent ones at every evaluation by Newton's method on Phi = 0
   (started from the values carried in the state), their rates from Phi_Q Q' = -Phi_t,
   and the same augmented system then gives Q'' (eliminating lambda and the dependent
   accelerations from it gives the ODE in the independent coordinates);
2. projection: the augmented system without Baumgarte's terms, and after every accepted step
   the integration loops call the module's ``project`` (ModelC.project), which moves the
   state back onto Phi = 0 and Phi_Q Q' = -Phi_t in the mass metric: no rate to tune.

The Jacobian d(dy/dt)/dy (and df/dt) is exact in each: A^-1 d(b - A x)/dy at fixed
x = [Q''; lambda] (:func:`_jacobian_parts`), with the chain rule through the recovery when
partitioned, so the implicit methods keep their order and pay no right-hand-side calls for it.

Everything model-specific comes from the declaration: the multipliers are outputs named by
the :class:`~camdyn.derive.model.Constraint` s, after the model's own outputs; a model with a
cam declares its profile (``Model.profile``), whose template prints ``_profile`` and whose
rise angle the call passes; a model without one has no cam input.  The profile's segment
ends are the model's events, pure breakpoints: nothing switches, the step just ends there.
"""
from __future__ import annotations

import json
import re

import sympy as sp

from .emit import (doc_lines, manifest_common, math_imports, option_entries, plainer,
                   render as render_template, state_entries, with_source_hash)
from .lagrange import Equations, derive, generic_rank
from .model import Model
from .optimize import ConstantTable
from .printer import CythonPrinter, cse_block


def constrained_context(eq: Equations) -> dict:
    """Everything ``constrained.pyx.j2`` needs, printed as Cython strings.

    The model's events must be pure breakpoints (no mode changes, no resets): the profile's
    segment ends.  Its cam inputs must be those of its profile: one family, one argument.
    """
    m = eq.model
    t = m.time
    n, nc = len(m.coordinates), eq.Phi.rows
    if m.first_order or m.modes:
        raise NotImplementedError(f"{m.name}: constrained models take no first-order states or "
                                  "modes here")
    for e in m.events:
        if any(b.modes or b.resets for b in e.branches):
            raise NotImplementedError(f"{m.name}: event {e.name} must be a pure breakpoint")
    # the partial dPhi/dt: the total derivative with the coordinate rates set to zero
    rates = {q.diff(t): 0 for q in m.q}
    Phi_t = eq.Phi.diff(t).xreplace(rates)
    exprs = (list(eq.M) + list(eq.f) + list(eq.Phi) + list(eq.Phi_q) + list(eq.gamma)
             + list(Phi_t) + [o.expr for o in m.outputs] + [e.g for e in m.events])
    plain = plainer(m, exprs)
    if m.profile is None and plain.instances:
        raise ValueError(f"{m.name}: cam input {plain.instances[0][0]} is used but no profile "
                         "is declared (Model.profile)")
    if m.profile is not None and [fam for fam, _ in plain.instances] != [m.profile.family]:
        raise NotImplementedError(f"{m.name}: one cam input, the profile's "
                                  f"{m.profile.family}, of one argument; found "
                                  f"{[str(fam) for fam, _ in plain.instances] or 'none'}")
    consts = ConstantTable({p.symbol for p in m.parameters})

    def prep(es):
        return [consts.hoist(plain(e)) for e in es]

    system = prep(list(eq.M) + list(eq.Phi_q) + list(eq.f) + list(eq.gamma) + list(eq.Phi)
                  + list(Phi_t))
    phi_part = prep(list(eq.Phi) + list(eq.Phi_q) + list(Phi_t))
    qdd = {sp.Symbol(c.name + "dd", real=True): f"_acc[{i}]" for i, c in enumerate(m.coordinates)}
    outs = prep([o.expr for o in m.outputs])
    gs = prep([e.g for e in m.events])
    jac = _jacobian_parts(eq, plain, Phi_t)
    jac_exprs = prep(jac["exprs"])
    names = dict(plain.names)
    names.update(jac["names"])
    # a profile is evaluated into _cam0[k] by _profile() (see the template)
    names.update({k: k.name for k, _ in consts.items})
    used = set()
    sys_lines, sys_code, u = cse_block(system, names, prefix="_s")
    used |= u
    phi_lines, phi_code, u = cse_block(phi_part, names, prefix="_p")
    used |= u
    out_lines, out_code, u = cse_block(outs, names | qdd, prefix="_o")
    used |= u
    jac_lines, jac_code, u = cse_block(jac_exprs, names | qdd, prefix="_j")
    used |= u
    const_lines, const_code, u = cse_block([e for _, e in consts.items], names, prefix="_c")
    used |= u
    printer = CythonPrinter(names)
    events = [{"name": e.name, "direction": e.direction, "g": printer.doprint(g)}
              for e, g in zip(m.events, gs)]
    # the initial state may call math functions the equations do not: cimport those too
    initial = [c.initial for c in m.coordinates] + [c.initial_rate for c in m.coordinates]
    initial_code = [printer.doprint(sp.sympify(v)) for v in initial]
    used |= printer.used
    used = math_imports(used)
    profile, cam_profile = None, None
    if m.profile is not None:
        family, arg = plain.instances[0]
        profile = {"template": m.profile.template,
                   "arg": CythonPrinter(names).doprint(arg),
                   "rise": CythonPrinter(names).doprint(plain(m.profile.rise))}
        cam_profile = {"family": family, "argument": str(arg), "kind": m.profile.kind}
    params = [p.name for p in m.parameters]
    solver = {role: params.index(getattr(m.solver, role).name)
              for role in ("baumgarte_rate", "formulation")}
    dependent = m.solver.dependent_indices(m)
    independent = [j for j in range(n) if j not in dependent]
    if generic_rank(eq.Phi_q.extract(list(range(nc)), dependent)) < nc:
        chosen = ", ".join(m.coordinates[j].name for j in dependent)
        raise ValueError(f"{m.name}: the constraints cannot be solved for the dependent "
                         f"coordinates {chosen} (Phi_Q restricted to them is singular at a "
                         "generic point); name others in ConstraintSolver(dependent=...)")

    outputs = [{"name": o.name, "unit": o.unit, "doc": o.doc} for o in m.outputs]
    outputs += [{"name": c.multiplier, "unit": c.unit, "doc": c.doc} for c in m.constraints]
    manifest = {
        **manifest_common(m),
        "n_constraints": nc,
        "dependent": [m.coordinates[j].name for j in dependent],
        "states": state_entries(m),
        "outputs": outputs,
        "constraints": [{"name": c.name, "multiplier": c.multiplier} for c in m.constraints],
        "solver": {role: params[k] for role, k in solver.items()},
        "cam_families": [] if cam_profile is None else [cam_profile["family"]],
        "cam_instances": [],
        "cam_profile": cam_profile,
        "modes": [],
        "events": [e.name for e in m.events],
        # a rise and its residual vibration, declared as for an unconstrained model
        "residual": None if m.residual is None else {
            "error": m.residual.error, "acceleration": m.residual.acceleration,
            "rise_end": m.residual.rise_end, "rise_state": m.residual.rise_state},
        "options": option_entries(m),
        # d(dy/dt)/dy and df/dt (ModelC.jac): A^-1 d(b - A x)/dy at fixed x (template)
        "jacobian": "symbolic",
        "time_derivative": "symbolic",
    }
    with_source_hash(manifest, {"M": sp.srepr(eq.M), "f": sp.srepr(eq.f), "Phi": sp.srepr(eq.Phi),
                                "events": [sp.srepr(e.g) for e in m.events],
                                "outputs": [sp.srepr(o.expr) for o in m.outputs]})
    return {
        "name": m.name,
        "title": m.title,
        "reference": m.reference,
        "doc_lines": doc_lines(m),
        "n": n,
        "nc": nc,
        "na": n + nc,
        "n_states": 2 * n,
        "params": params,
        "coords": [c.name for c in m.coordinates],
        "outputs": [o["name"] for o in outputs],
        "n_model_outputs": len(m.outputs),
        "consts": [k.name for k, _ in consts.items],
        "const_lines": const_lines,
        "const_code": const_code,
        "sys_lines": sys_lines,
        "sys_code": sys_code,
        "phi_lines": phi_lines,
        "phi_code": phi_code,
        "out_lines": out_lines,
        "jac_lines": jac_lines,
        "jac_code": jac_code,
        "fourth": jac["fourth"],
        "dependent": dependent,
        "independent": independent,
        "out_code": out_code,
        "events": events,
        "profile": profile,
        "solver": solver,
        "math": used,
        "initial_code": initial_code,
        "scales": [repr(float(c.scale)) for c in m.coordinates] * 2,
        "manifest_json": json.dumps(manifest, indent=1, sort_keys=True),
        "source_hash": manifest["source_hash"],
    }


def _cam_order(symbol: sp.Symbol):
    """(instance, order) of a plain cam symbol ``_cam<i>_<k>``, or None."""
    m = _CAM_SYMBOL.fullmatch(symbol.name)
    return None if m is None else tuple(int(g) for g in m.groups())


def _jacobian_parts(eq: Equations, plain, Phi_t: sp.Matrix) -> dict:
    """What the exact Jacobian of the generated right-hand side is computed from.

    The right-hand side solves A(y) x = b(y) for x = [Q''; lambda] (y = [Q, Q']); so
    dx/dy = A^-1 d(b - A x)/dy with x held fixed, and dx/dt likewise: no symbolic inverse,
    the LU of A is the one the right-hand side factors.  Printed here, in plain symbols with
    x as the symbols Q''_j (``_acc[j]``) and ``_lam<k>`` (``_acc[n + k]``): d(b - A x)/dy
    (row-major, (n + n_c) x 2n), d(b - A x)/dt, and of the velocity constraint
    C = Phi_Q Q' + Phi_t its dC/dQ (n_c x n) and dC/dt, from which the template adds
    Baumgarte's terms and the chain rule of coordinate partitioning.  Cam inputs enter
    through the chain rule dH^(k)(a)/dv = H^(k+1)(a) da/dv; the fourth derivative this may
    ask of a cam profile comes from the cam-law library's ``camlaw_d4``.
    """
    m = eq.model
    t = m.time
    n, nc = len(m.coordinates), eq.Phi.rows
    Q = [sp.Symbol(c.name, real=True) for c in m.coordinates]
    V = [sp.Symbol(c.name + "d", real=True) for c in m.coordinates]
    acc = sp.Matrix([sp.Symbol(c.name + "dd", real=True) for c in m.coordinates])
    lam = sp.Matrix([sp.Symbol(f"_lam{k}", real=True) for k in range(nc)])
    M, f, Phi_q, gamma = (plain(x) for x in (eq.M, eq.f, eq.Phi_q, eq.gamma))
    r = list(f - M * acc - Phi_q.T * lam) + list(gamma - Phi_q * acc)
    C = list(Phi_q * sp.Matrix(V) + plain(Phi_t))
    args = [a for _, a in plain.instances]
    fourth = False

    def d(e, v):
        nonlocal fourth
        out = sp.diff(e, v)
        for s in sorted(e.free_symbols, key=sp.default_sort_key):
            io = _cam_order(s)
            if io is None:
                continue
            da = sp.diff(args[io[0]], v)
            if da != 0:
                fourth |= io[1] + 1 >= 4
                out += sp.diff(e, s) * sp.Symbol(f"_cam{io[0]}_{io[1] + 1}", real=True) * da
        return out

    exprs = [d(e, v) for e in r for v in Q + V] + [d(e, t) for e in r]
    exprs += [d(e, v) for e in C for v in Q] + [d(e, t) for e in C]
    names = {sp.Symbol(f"_lam{k}", real=True): f"_acc[{n + k}]" for k in range(nc)}
    names.update({sp.Symbol(f"_cam{i}_4", real=True): f"_cam{i}[4]" for i in range(len(args))})
    return {"exprs": exprs, "names": names, "fourth": fourth}


_CAM_SYMBOL = re.compile(r"_cam(\d+)_(\d+)")


def render(model: Model, source: str) -> str:
    """The generated module of the constrained ``model``; ``source`` is the file its
    declaration comes from (the provenance line of the preamble)."""
    return render_template("constrained.pyx.j2", **constrained_context(derive(model)),
                           source=source)
