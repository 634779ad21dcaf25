"""Code generation for constrained models: M Q'' + Phi_Q^T lambda = f, Phi(Q, t) = 0.

The generated module has the same C interface as every other model (runtime/abi.pxd), so
the compiled integrators of runtime/loops.pxi run it unchanged; what differs is how its
right-hand side finds Q'' (template ``constrained.pyx.j2``), in one of two formulations
chosen by the model's parameter ``formulation``:

0. augmented: the index-1 system [[M, Phi_Q^T], [Phi_Q, 0]] [Q''; lambda] = [f; gamma_B],
   gamma_B = gamma - 2 w_B Phi' - w_B^2 Phi (Baumgarte stabilization with the critically
   damped rate w_B), one dense LU with partial pivoting per evaluation (paper (20));
1. partitioned: the last n_c coordinates are dependent; at every evaluation they are
   recovered from the independent ones by Newton's method on Phi = 0 (started from the
   values carried in the state), their rates from Phi_Q Q' = -Phi_t, and the same
   augmented system then gives Q'' (the ODE of paper (25)-(27) in the independent
   coordinates: eliminating lambda and the dependent accelerations gives exactly this).

The cam input of such a model is the periodic profile R(theta) of its cam parameter (a
state), evaluated by ``_profile`` in the template; its segment ends are the model's events,
pure breakpoints: nothing switches, the step just ends there.
"""
from __future__ import annotations

import hashlib
import json

import sympy as sp

from .codegen import _env, _num, _plainer, _state_entries, manifest_common
from .lagrange import Equations, derive
from .model import Model
from .optimize import ConstantTable
from .printer import MATH_FUNCTIONS, CythonPrinter, cse_block

EXTRA_OUTPUTS = (("lambda1", "N", "multiplier of the first constraint (transverse, (6))"),
                 ("lambda2", "N", "multiplier of the second constraint (axial, (7))"))


def constrained_context(eq: Equations) -> dict:
    """Everything ``constrained.pyx.j2`` needs, printed as Cython strings.

    The model's events must be pure breakpoints (no mode changes, no resets): the profile's
    segment ends.
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
    plain = _plainer(m, exprs)
    if len({fam for fam, _ in plain.instances}) > 1 or len(plain.instances) > 1:
        raise NotImplementedError(f"{m.name}: one cam profile of one argument")
    consts = ConstantTable({p.symbol for p in m.parameters})

    def prep(es):
        return [consts.hoist(plain(e)) for e in es]

    system = prep(list(eq.M) + list(eq.Phi_q) + list(eq.f) + list(eq.gamma) + list(eq.Phi)
                  + list(Phi_t))
    phi_part = prep(list(eq.Phi) + list(eq.Phi_q) + list(Phi_t))
    qdd = {sp.Symbol(c.name + "dd", real=True): f"_acc[{i}]" for i, c in enumerate(m.coordinates)}
    outs = prep([o.expr for o in m.outputs])
    gs = prep([e.g for e in m.events])
    names = dict(plain.names)
    # the profile is evaluated into _cam0[k] by _profile() (see the template)
    names.update({k: k.name for k, _ in consts.items})
    used = set()
    sys_lines, sys_code, u = cse_block(system, names, prefix="_s")
    used |= u
    phi_lines, phi_code, u = cse_block(phi_part, names, prefix="_p")
    used |= u
    out_lines, out_code, u = cse_block(outs, names | qdd, prefix="_o")
    used |= u
    const_lines, const_code, u = cse_block([e for _, e in consts.items], names, prefix="_c")
    used |= u
    printer = CythonPrinter(names)
    events = [{"name": e.name, "direction": e.direction, "g": printer.doprint(g)}
              for e, g in zip(m.events, gs)]
    used |= printer.used
    used = sorted(used & (set(MATH_FUNCTIONS) | {"M_PI"}))
    family, arg = plain.instances[0]
    arg_code = CythonPrinter(names).doprint(arg)

    outputs = [{"name": o.name, "unit": o.unit, "doc": o.doc} for o in m.outputs]
    outputs += [{"name": nme, "unit": unit, "doc": doc} for nme, unit, doc in EXTRA_OUTPUTS[:nc]]
    manifest = {
        **manifest_common(m),
        "n_constraints": nc,
        "dependent": [c.name for c in m.coordinates[n - nc:]],
        "states": _state_entries(m),
        "outputs": outputs,
        "cam_families": [family],
        "cam_instances": [],
        "cam_profile": {"family": family, "argument": str(arg), "kind": "RDFD, periodic in 2 pi"},
        "modes": [],
        "events": [e.name for e in m.events],
        "residual": None,
        "options": [list(o) if isinstance(o, tuple) else o for o in m.options],
    }
    canonical = json.dumps({"M": sp.srepr(eq.M), "f": sp.srepr(eq.f), "Phi": sp.srepr(eq.Phi),
                            "events": [sp.srepr(e.g) for e in m.events],
                            "outputs": [sp.srepr(o.expr) for o in m.outputs],
                            "manifest": manifest}, sort_keys=True)
    manifest["source_hash"] = "sha256:" + hashlib.sha256(canonical.encode()).hexdigest()
    initial = [c.initial for c in m.coordinates] + [c.initial_rate for c in m.coordinates]
    return {
        "name": m.name,
        "title": m.title,
        "reference": m.reference,
        "doc_lines": [line.rstrip() for line in m.doc.strip().splitlines()],
        "n": n,
        "nc": nc,
        "na": n + nc,
        "n_states": 2 * n,
        "params": [p.name for p in m.parameters],
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
        "out_code": out_code,
        "events": events,
        "arg_code": arg_code,
        "math": used,
        "initial_code": [CythonPrinter(names).doprint(sp.sympify(v)) for v in initial],
        "manifest_json": json.dumps(manifest, indent=1, sort_keys=True),
        "source_hash": manifest["source_hash"],
    }


def render_constrained(model: Model, source: str) -> str:
    ctx = constrained_context(derive(model))
    return _env().get_template("constrained.pyx.j2").render(**ctx, source=source)
