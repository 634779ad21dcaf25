"""The Cython module of a model without constraints: M(q, t) q'' = f, first-order states z.

What ``model.pyx.j2`` prints from the model's equations (:mod:`camdyn.derive.lagrange`): the
right-hand side (q'' solved symbolically for a diagonal M, else M and f for a dense solve), its
dwell variants and parameter constants (:mod:`camdyn.derive.optimize`), the Jacobian and df/dT,
the outputs, the frozen M and K of the stability check, the events and the cam inputs, and the
manifest.  Output is deterministic: the same model and the same SymPy version give
byte-identical files (SymPy is pinned in pyproject.toml for that reason), and every file
carries the hash of the symbolic equations it was generated from.  Constrained models are
printed by :mod:`camdyn.derive.dae`; what both share is in :mod:`camdyn.derive.emit`.
"""
from __future__ import annotations

import json

import sympy as sp

from . import symbolic
from .emit import (Plain, doc_lines, manifest_common, math_imports, number, option_entries,
                   plainer, render as render_template, state_entries, time_functions,
                   with_source_hash)
from .lagrange import Equations, derive
from .model import CamFunction, Model
from .optimize import ConstantTable, dwell_variants, dwell_zeros
from .printer import CythonPrinter, cse_block


def _time_affine(arg, t, states: set):
    """(a, b) with arg = a t + b when the cam argument is affine in time, else None.

    Breakpoints of such an input are known times; others (H(B), CAMSHAFT-2)
    are located as events.
    """
    if arg.free_symbols & states:
        return None
    a = sp.diff(arg, t)
    if a.has(t):
        return None
    return a, arg.subs(t, 0)


def _armed(event, modes: dict):
    conds = []
    for name, values in sorted(event.armed.items()):
        mode = modes[name]
        conds.append(sp.Or(*[sp.Eq(mode.symbol, mode.index(v)) for v in values]))
    return sp.And(*conds) if conds else sp.true


def _stiffness(m: Model, f: sp.Matrix) -> sp.Matrix:
    """K = -df/dq, the coordinates and their rates held as plain symbols while differentiating.

    The same matrix as ``-f.jacobian(m.q)`` (SymPy treats q' as independent of q there too),
    but SymPy differentiates with respect to a function q(t) by swapping it for a dummy
    symbol in every term, which takes more than half of the time on the large squeeze-film
    equations of DYNACAM."""
    tf = time_functions(m)
    back = {v: k for k, v in tf.items()}
    return (-f.xreplace(tf).jacobian([tf[q] for q in m.q])).xreplace(back)


MAX_VARIANT_INSTANCES = 3  # 2^3 dwell variants at most; beyond that, one general rhs


def _rhs_expressions(m: Model, eq: Equations, plain: Plain):
    """(expressions of the right-hand side, whether M is diagonal): q'' divided out
    symbolically for a diagonal M, else the entries of M and f for a solve, then z'."""
    n = len(m.coordinates)
    M = eq.M.applyfunc(plain)
    f = eq.f.applyfunc(plain)
    rates = [plain(z.rate) for z in m.first_order]
    if M.is_diagonal():
        acc = [f[i] / M[i, i] for i in range(n)]
        # a model that keeps its forces unexpanded (a rocker's long geometric ratios) is not
        # simplified either: the rocker held on both sides, whose force has no Piecewise to
        # pass over, ran in simplify() for more than 25 minutes
        acc = [symbolic.simplify(e) if M[i, i] != 1 and not e.has(sp.Piecewise)
               and m.expand_forces else e for i, e in enumerate(acc)]
        return acc + rates, True
    return list(M) + list(f) + rates, False


def _linear_in_dwell(m: Model, checked: list, cam_syms: list, events: list,
                     n_mass: int) -> bool:
    """Whether the right-hand side is linear and time invariant, y' = A y + c with A and c
    constant, while every cam input sits in a dwell (every one of them: a model without cam
    inputs, always): its expressions there (the cam's derivatives zero, its value a
    constant) are affine in the states and free of time, and nothing switches (no force
    element modes, no events).  ``n_mass``: the leading expressions that are the entries of
    a mass matrix solved at run time (it must be constant there).  The loops then step over
    such an interval exactly (runtime/engine/loops.pxi, _loop_exact): the free vibration
    after a rise, whose amplitude is the residual vibration of thesis sec. 4.4."""
    if m.modes or events:
        return False
    states = set(_state_symbols(m))
    dwell = dwell_zeros(cam_syms, 2 ** len(cam_syms) - 1)
    seen: dict = {}
    for k, e in enumerate(checked):
        e = sp.sympify(e).xreplace(dwell)
        if m.time in e.free_symbols:
            return False
        if _state_degree(e, states, seen) > (0 if k < n_mass else 1):
            return False
    return True


def _state_degree(e, states: set, seen: dict) -> int:
    """The degree of ``e`` in the ``states``: 0 free of them, 1 affine, 2 anything else (a
    product of two, a power, a function of one, a Piecewise on one); read off the expression
    tree once (``seen`` keeps its subtrees), not by differentiation, which takes minutes on the
    largest DYNACAM models.  Conservative: x**2 - x**2 counts as 2."""
    hit = seen.get(e)
    if hit is not None:
        return hit
    if e.is_Symbol:
        d = 1 if e in states else 0
    elif e.is_Number or not e.args:
        d = 0
    elif e.is_Add:
        d = max(_state_degree(a, states, seen) for a in e.args)
    elif e.is_Mul:
        d = min(2, sum(_state_degree(a, states, seen) for a in e.args))
    elif e.is_Pow:
        base, ex = (_state_degree(a, states, seen) for a in e.args)
        d = 0 if base == ex == 0 else (
            base if ex == 0 and e.exp.is_Integer and e.exp == 1 else 2)
    else:       # a function, a Piecewise, ...: linear only when free of the states
        d = 0 if all(_state_degree(a, states, seen) == 0 for a in e.args) else 2
    seen[e] = d
    return d


def _state_symbols(m: Model) -> list:
    """Plain symbols of the states in their order y = [q, q', z]."""
    return ([sp.Symbol(c.name, real=True) for c in m.coordinates]
            + [sp.Symbol(c.name + "d", real=True) for c in m.coordinates]
            + [sp.Symbol(z.name, real=True) for z in m.first_order])


def _cam_symbol(i: int, k: int) -> sp.Symbol:
    return sp.Symbol(f"_cam{i}_{k}", real=True)


def jacobian_plain(exprs, plain: Plain, ys: list) -> list:
    """Rows d e/d y of the plain expressions ``exprs`` with respect to the plain states ``ys``.

    A cam input value ``_cam{i}_{k}`` = d^k H/darg^k at the instance's argument a_i depends on a
    state through a_i: its derivative is ``_cam{i}_{k+1}`` * d a_i/d y (the chain rule the
    plain symbols hide), so the rows may use one derivative order more than the expressions;
    its name is added to ``plain.names``.  The cam-law library evaluates H up to H''': an
    order above that is refused.  Piecewise expressions (modes, squeeze gaps, friction)
    differentiate branch by branch: the Jacobian of the current mode, modes being switched by
    events.  d sign(x)/dx (a Dirac delta at the switching surface) is 0: the Jacobian away
    from it."""
    cams = [[_cam_symbol(i, k) for k in range(CamFunction.max_order + 1)]
            for i in range(len(plain.instances))]
    dargs = [[sp.diff(arg, y) for y in ys] for _, arg in plain.instances]
    rows = []
    for e in exprs:
        e = sp.sympify(e)
        free = e.free_symbols
        chain = []   # (d e/d cam_ik, i, k) for the cam values e uses
        for i, syms in enumerate(cams):
            for k, s in enumerate(syms):
                if s in free:
                    chain.append((sp.diff(e, s), i, k))
        row = []
        for j, y in enumerate(ys):
            d = sp.diff(e, y) if y in free else sp.S.Zero
            for de, i, k in chain:
                if dargs[i][j] == 0 or de == 0:
                    continue
                if k + 1 > CamFunction.max_order:
                    raise NotImplementedError(
                        f"{plain.model.name}: the Jacobian needs d^{k + 1}H/darg^{k + 1} of cam "
                        f"input {i}, above the order {CamFunction.max_order} the cam-law "
                        "library evaluates")
                up = cams[i][k + 1]
                plain.names.setdefault(up, f"_cam{i}[{k + 1}]")
                d += de * up * dargs[i][j]
            if d.has(sp.DiracDelta):
                d = d.replace(sp.DiracDelta, lambda *a: sp.S.Zero)
            if d.has(sp.Derivative, sp.Subs):
                raise NotImplementedError(f"{plain.model.name}: an unevaluated derivative in "
                                          f"the Jacobian: {d}")
            row.append(d)
        rows.append(row)
    return rows


def _time_column(m: Model, plain: Plain, exprs: list):
    """d e/dT of the plain expressions (explicit time and the cam arguments a T + b, by the
    chain rule of jacobian_plain), or None when that needs a cam derivative above the order
    the cam-law library evaluates (the implicit loops then difference the rhs in time)."""
    try:
        return [row[0] for row in jacobian_plain(exprs, plain, [m.time])]
    except NotImplementedError:
        return None


def _jacobian_context(m: Model, plain: Plain, diagonal: bool, rhs_exprs: list,
                      consts: ConstantTable):
    """(sparse Jacobian entries (row, column, expr), the entries R of the non-diagonal
    correction, the time column: entries (row, expr) of df/dT and its correction R_t, or
    None) of the general (not dwell-specialised) right-hand side.

    df/dT is what a Rosenbrock method needs besides J (its gamma_i h f_t terms).  Derived,
    not differenced: a unilateral contact makes f kinked in T within a deflection's worth of
    cam travel of the trajectory (the roller, F_c = max(0, ...)), and a difference quotient
    straddling the kink turned RODAS4's local error from O(h^5) into O(h^2) (the step
    shrank with rtol^(1/2), 10^5 steps in a rise where 10^3 do).

    Diagonal M: rows n.. of d(dy/dt)/dy differentiate q'' = f/M and z' directly.  Else
    q'' = M^-1 f and d q''/dy_j = M^-1 (df/dy_j - dM/dy_j q''): the template solves M (the
    entries of ``rhs_exprs``) for q'', evaluates R_ij = df_i/dy_j - sum_k dM_ik/dy_j q''_k
    (row-major n x n_states) with q'' as the symbols ``Xdd`` and solves M X = R column by
    column.  Rows 0..n-1 (d q'/dy, the identity block) are written by the template.
    """
    n = len(m.coordinates)
    ys = _state_symbols(m)
    ns = len(ys)
    entries = []
    if diagonal:
        for i, row in enumerate(jacobian_plain(rhs_exprs, plain, ys)):
            for j, d in enumerate(row):
                if d != 0:
                    entries.append((n + i, j, consts.hoist(d)))
        col = _time_column(m, plain, rhs_exprs)
        time = None if col is None else (
            [(n + i, consts.hoist(d)) for i, d in enumerate(col) if d != 0], [])
        return entries, [], time
    qdd = [sp.Symbol(c.name + "dd", real=True) for c in m.coordinates]
    M = rhs_exprs[:n * n]
    f = rhs_exprs[n * n:n * n + n]
    rates = rhs_exprs[n * n + n:]
    dM = jacobian_plain(M, plain, ys)
    df = jacobian_plain(f, plain, ys)
    R = []
    for i in range(n):
        for j in range(ns):
            R.append(consts.hoist(df[i][j] - sum(dM[i * n + k][j] * qdd[k] for k in range(n))))
    for i, row in enumerate(jacobian_plain(rates, plain, ys)):
        for j, d in enumerate(row):
            if d != 0:
                entries.append((2 * n + i, j, consts.hoist(d)))
    time = None
    dMt, dft, ratest = (_time_column(m, plain, e) for e in (M, f, rates))
    if dMt is not None and dft is not None and ratest is not None:
        time = ([(2 * n + i, consts.hoist(d)) for i, d in enumerate(ratest) if d != 0],
                [consts.hoist(dft[i] - sum(dMt[i * n + k] * qdd[k] for k in range(n)))
                 for i in range(n)])
    return entries, R, time


def _event_entries(m: Model, plain: Plain, printer: CythonPrinter) -> list:
    """The model's own events, with their arming condition and branches (modes, resets)."""
    modes = {mode.name: mode for mode in m.modes}
    events = []
    for e in m.events:
        branches = []
        for b in e.branches:
            branches.append({
                "condition": printer.doprint(plain(sp.sympify(b.condition))),
                "modes": [(len(plain.instances) + list(modes).index(k), modes[k].index(v), k, v)
                          for k, v in sorted(b.modes.items())],
                "resets": [(_state_index(m, k), printer.doprint(plain(v)), k)
                           for k, v in sorted(b.resets.items())],
            })
        events.append({"kind": "model", "name": e.name, "direction": e.direction,
                       "g": printer.doprint(plain(e.g)),
                       "armed": printer.doprint(_armed(e, modes)), "branches": branches})
    return events


def _cam_instances(m: Model, plain: Plain, printer: CythonPrinter) -> tuple[list, list]:
    """(cam-input instances, their breakpoint events): an instance whose argument is not
    affine in time is driven by a state, and its segment ends are located as events."""
    instances, events = [], []
    families = sorted({fam for fam, _ in plain.instances})
    for i, ((family, arg), order) in enumerate(zip(plain.instances, plain.orders)):
        affine = _time_affine(arg, m.time, plain.states)
        inst = {"index": i, "bit": 1 << i, "family": family, "family_index": families.index(family),
                "arg": printer.doprint(arg), "arg_text": str(arg), "order": order,
                "affine": None if affine is None else [printer.doprint(affine[0]),
                                                       printer.doprint(affine[1])]}
        instances.append(inst)
        if affine is None:
            for direction, side in ((1, "hi"), (-1, "lo")):
                events.append({"kind": "cam", "name": f"cam{i}_{side}", "direction": direction,
                               "instance": inst, "side": side})
    return instances, events


def _model_manifest(m: Model, eq: Equations, instances: list, events: list,
                    time_symbolic: bool) -> dict:
    """The manifest the runtime reads (states, parameters, outputs, cam inputs, modes,
    events, options) with the source hash of the equations it was generated from."""
    manifest = {
        **manifest_common(m),
        "states": state_entries(m) + [{"name": z.name, "unit": z.unit, "scale": z.scale, "doc": z.doc,
                                       "initial": number(z.initial)} for z in m.first_order],
        "outputs": [{"name": o.name, "unit": o.unit, "doc": o.doc} for o in m.outputs],
        "cam_families": sorted({d["family"] for d in instances}),
        "cam_instances": [{"family": d["family"], "argument": d["arg_text"],
                           "time_affine": d["affine"] is not None,
                           "order": d["order"]} for d in instances],
        "modes": [{"name": mode.name, "values": list(mode.values), "doc": mode.doc,
                   "initial": mode.initial or mode.values[0]} for mode in m.modes],
        "events": [e["name"] for e in events],
        "residual": None if m.residual is None else {
            "error": m.residual.error, "acceleration": m.residual.acceleration,
            "rise_end": m.residual.rise_end, "rise_state": m.residual.rise_state},
        "options": option_entries(m),
        # d(dy/dt)/dy (ModelC.jac): derived symbolically with the equations
        "jacobian": "symbolic",
        # df/dT with it (jacobian()'s ft), for the Rosenbrock method's f_t terms
        "time_derivative": "symbolic" if time_symbolic else "finite-difference",
    }
    return with_source_hash(manifest, {
        "M": sp.srepr(eq.M), "f": sp.srepr(eq.f), "Phi": sp.srepr(eq.Phi),
        "rates": [sp.srepr(z.rate) for z in m.first_order],
        "events": [sp.srepr(e.g) for e in m.events],
        "outputs": [sp.srepr(o.expr) for o in m.outputs]})


def model_context(eq: Equations) -> dict:
    """Everything the model template needs, printed as Cython strings."""
    m = eq.model
    if eq.Phi.rows:
        raise NotImplementedError(f"{m.name}: constrained models are generated by the DAE layer")
    n, nz = len(m.coordinates), len(m.first_order)
    qdd_syms = [sp.Symbol(c.name + "dd", real=True) for c in m.coordinates]
    # the frozen stiffness K = -df/dq serves smooth models; with modes (contact, friction)
    # there is no single linearization, and K is left undefined (NaN)
    smooth = not m.modes
    K_raw = _stiffness(m, eq.f) if n and smooth else sp.zeros(0, 0)
    event_exprs = []
    for e in m.events:
        event_exprs.append(e.g)
        for b in e.branches:
            event_exprs += [sp.sympify(b.condition)] + list(b.resets.values())
    all_exprs = (list(eq.M) + list(eq.f) + list(K_raw) + [z.rate for z in m.first_order]
                 + [o.expr for o in m.outputs] + event_exprs)
    plain = plainer(m, all_exprs)

    rhs_exprs, diagonal = _rhs_expressions(m, eq, plain)
    # a diagonal M is divided out symbolically, so its entries are checked where they are not
    # positive by construction (a positive number, or a parameter whose declared range is
    # positive): a negative or zero mass makes q'' NaN, which stops the run, and the runtime
    # names the coordinate (runtime/core/diagnosis.py); a dense M is checked by its Cholesky
    # factorization
    mass_checks = [i for i in range(n) if not eq.M[i, i].is_positive] if diagonal else []
    checked = rhs_exprs + [plain(eq.M[i, i]) for i in mass_checks]
    cam_syms = [[sp.Symbol(f"_cam{i}_{k}", real=True) for k in range(order + 1)]
                for i, order in enumerate(plain.orders)]
    specialise = 0 < len(plain.instances) <= MAX_VARIANT_INSTANCES
    variants = dwell_variants(checked, cam_syms) if specialise else [checked]

    # parameter-only subexpressions: computed once per run by prepare()
    consts = ConstantTable({p.symbol for p in m.parameters})
    variants = [[consts.hoist(e) for e in v] for v in variants]
    if all(v == variants[0] for v in variants[1:]):   # the dwell changes nothing here
        specialise, variants = False, variants[:1]
    out_exprs = [consts.hoist(plain(o.expr)) for o in m.outputs]
    # the Jacobian of the general right-hand side (it may add cam derivative names)
    jac_entries, jac_R, jac_time = _jacobian_context(m, plain, diagonal, rhs_exprs, consts)
    t_entries, t_R = jac_time if jac_time is not None else ([], [])
    names = dict(plain.names)
    names.update({k: k.name for k, _ in consts.items})

    rhs_variants, used = [], set()
    for v, exprs in enumerate(variants):
        lines, code, u = cse_block(exprs, names, prefix=f"_s{v}_")
        rhs_variants.append({"index": v, "lines": lines, "code": code,
                             "dwell": [i for i in range(len(plain.instances)) if v >> i & 1]})
        used |= u
    qdd_names = {s: f"_dy[{n + i}]" for i, s in enumerate(qdd_syms)}
    out_lines, out_code, u = cse_block(out_exprs, names | qdd_names, prefix="_o")
    used |= u
    if diagonal:
        jac_sys_lines, jac_sys_code = [], []
    else:   # M and f, solved for q'' before the correction R is evaluated
        jac_sys_lines, jac_sys_code, u = cse_block(
            [consts.hoist(e) for e in rhs_exprs[:n * n + n]], names, prefix="_a")
        used |= u
    nR, nE, nRt = len(jac_R), len(jac_entries), len(t_R)
    jac_lines, jac_code, u = cse_block(jac_R + [e for _, _, e in jac_entries] + t_R
                                       + [e for _, e in t_entries],
                                       names | {s: f"_qdd[{i}]" for i, s in enumerate(qdd_syms)},
                                       prefix="_j")
    used |= u
    jac = {"sys_lines": jac_sys_lines, "sys_code": jac_sys_code, "lines": jac_lines,
           "R": jac_code[:nR],
           "entries": [(r * (2 * n + nz) + c, code)
                       for (r, c, _), code in zip(jac_entries, jac_code[nR:nR + nE])],
           # df/dT (Rosenbrock's f_t): derived unless it needs a cam derivative above the third
           "time": jac_time is not None,
           "R_t": jac_code[nR + nE:nR + nE + nRt],
           "t_entries": [(r, code) for (r, _), code in zip(t_entries, jac_code[nR + nE + nRt:])]}
    const_lines, const_code, u = cse_block([e for _, e in consts.items], names, prefix="_c")
    used |= u
    ms_lines, ms_code, u = cse_block(list(eq.M.applyfunc(plain)) + list(K_raw.applyfunc(plain)),
                                     names, prefix="_m")
    if not smooth:
        ms_code += ["0.0 / 0.0"] * (n * n)
    used |= u

    # events: the model's own, then the breakpoints of cam inputs driven by a state
    printer = CythonPrinter(names)
    events = _event_entries(m, plain, printer)
    instances, cam_events = _cam_instances(m, plain, printer)
    events += cam_events
    used |= printer.used
    used = math_imports(used)
    manifest = _model_manifest(m, eq, instances, events, jac_time is not None)
    lti = _linear_in_dwell(m, checked, cam_syms, events, 0 if diagonal else n * n)

    initial = ([c.initial for c in m.coordinates] + [c.initial_rate for c in m.coordinates]
               + [z.initial for z in m.first_order])
    initial_code = [CythonPrinter(names).doprint(sp.sympify(v)) for v in initial]
    return {
        "model": m,
        "initial_code": initial_code,
        "name": m.name,
        "title": m.title,
        "reference": m.reference,
        "doc_lines": doc_lines(m),
        "variant_lines": list(m.variant),
        "n": n,
        "nz": nz,
        "n_states": 2 * n + nz,
        "params": [p.name for p in m.parameters],
        "coords": [c.name for c in m.coordinates],
        "zs": [z.name for z in m.first_order],
        "outputs": [o.name for o in m.outputs],
        "instances": instances,
        "n_families": len(manifest["cam_families"]),
        "n_modes": len(m.modes),
        "diagonal": diagonal,
        "mass_checks": mass_checks,
        "specialise": specialise,
        "lti": lti,
        "variants": rhs_variants,
        "temporaries": [name for v in rhs_variants for name, _ in v["lines"]],
        "consts": [k.name for k, _ in consts.items],
        "const_lines": const_lines,
        "const_code": const_code,
        "out_lines": out_lines,
        "out_code": out_code,
        "ms_lines": ms_lines,
        "ms_code": ms_code,
        "jac": jac,
        "events": events,
        "math": used,
        "manifest_json": json.dumps(manifest, indent=1, sort_keys=True),
        "source_hash": manifest["source_hash"],
    }


def _state_index(m: Model, name: str) -> int:
    names = ([c.name for c in m.coordinates] + [c.name + "d" for c in m.coordinates]
             + [z.name for z in m.first_order])
    if name not in names:
        raise ValueError(f"{m.name}: an event resets unknown state {name!r}")
    return names.index(name)


def render(model: Model, source: str) -> str:
    """The generated module of the unconstrained ``model``; ``source`` is the file its
    declaration comes from (the provenance line of the preamble)."""
    return render_template("model.pyx.j2", **model_context(derive(model)), source=source)
