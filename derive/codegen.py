"""Generate one Cython module per model, plus the cam-law library, from templates.

The templates live in ``templates/`` and are rendered with StrictUndefined, so
a missing value is an error, never an empty string.  Output is deterministic:
the same model and the same SymPy version give byte-identical files (sympy is
pinned in pyproject.toml for that reason), and every file carries the hash of
the symbolic equations it was generated from.
"""
from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from pathlib import Path

import jinja2
import sympy as sp

from . import camlaws
from .lagrange import Equations, derive
from .model import CamFunction, Model
from .optimize import ConstantTable, dwell_variants
from .printer import MATH_FUNCTIONS, CythonPrinter, cse_block

TEMPLATES = Path(__file__).parent / "templates"


def _env() -> jinja2.Environment:
    return jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(TEMPLATES)),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
    )


def _num(value) -> float:
    return float(sp.sympify(value))


# -- model modules --------------------------------------------------------------


@dataclass
class _Symbols:
    """Plain symbols for q, q', q'' and the cam inputs, and how to print them."""

    subs: list  # (function-of-time expression, plain symbol), highest derivative first
    names: dict  # symbol -> code
    instances: list  # (family, arg expression with plain symbols)
    orders: list  # highest derivative order used per instance


def _symbols(eq: Equations, exprs) -> _Symbols:
    m = eq.model
    t = m.time
    subs, names = [], {}
    n = len(m.coordinates)
    for i, c in enumerate(m.coordinates):
        x = c(t)
        for order, suffix, code in ((2, "dd", f"qdd[{i}]"), (1, "d", f"y[{n + i}]"), (0, "", f"y[{i}]")):
            s = sp.Symbol(c.name + suffix, real=True)
            subs.append((x.diff(t, order) if order else x, s))
    subs.sort(key=lambda pair: -(pair[0].derivative_count if isinstance(pair[0], sp.Derivative) else 0))
    for p in m.parameters:
        names[p.symbol] = p.name
    names[t] = "t"

    # cam inputs: one instance per distinct (family, argument)
    found = set()
    for e in exprs:
        found |= {a for a in sp.sympify(e).atoms(CamFunction)}
    keyed = {}
    for a in found:
        arg = a.args[0]
        for old, new in subs:
            arg = arg.subs(old, new)
        key = (a.family, sp.srepr(arg))
        keyed.setdefault(key, [arg, 0])
        keyed[key][1] = max(keyed[key][1], a.order)
    instances, orders = [], []
    for idx, key in enumerate(sorted(keyed)):
        arg, order = keyed[key]
        instances.append((key[0], arg))
        orders.append(order)
    inst_index = {key: i for i, key in enumerate(sorted(keyed))}
    cam_subs = []
    for a in sorted(found, key=sp.srepr):
        arg = a.args[0]
        for old, new in subs:
            arg = arg.subs(old, new)
        i = inst_index[(a.family, sp.srepr(arg))]
        s = sp.Symbol(f"_cam{i}_{a.order}", real=True)
        names[s] = f"_cam{i}[{a.order}]"
        cam_subs.append((a, s))
    # cam functions are replaced first: their arguments contain coordinates
    return _Symbols(cam_subs + subs, names, instances, orders)


def _plain(expr, sy: _Symbols):
    expr = sp.sympify(expr)
    for old, new in sy.subs:
        expr = expr.subs(old, new)
    return expr


def _time_affine(arg, t, states: set):
    """(a, b) with arg = a t + b when the cam argument is affine in time, else None.

    Breakpoints of such an input are known times; others (H(B), CAMSHAFT-2)
    need events.
    """
    if arg.free_symbols & states:
        return None
    a = sp.diff(arg, t)
    if a.has(t):
        return None
    return a, arg.subs(t, 0)


MAX_VARIANT_INSTANCES = 3  # 2^3 dwell variants at most; beyond that, one general rhs


def model_context(eq: Equations) -> dict:
    """Everything the model template needs, printed as Cython strings."""
    m = eq.model
    t = m.time
    if eq.Phi.rows:
        raise NotImplementedError(f"{m.name}: constrained models are not generated yet")
    n = len(m.coordinates)
    qdd_syms = [sp.Symbol(c.name + "dd", real=True) for c in m.coordinates]
    all_exprs = list(eq.M) + list(eq.f) + [o.expr for o in m.outputs]
    sy = _symbols(eq, all_exprs)
    state_syms = {c.name for c in m.coordinates} | {c.name + "d" for c in m.coordinates}

    M = eq.M.applyfunc(lambda e: _plain(e, sy))
    f = eq.f.applyfunc(lambda e: _plain(e, sy))
    diagonal = M.is_diagonal()

    # right-hand side: q'' from M q'' = f (diagonal M: divided out symbolically)
    if diagonal:
        rhs_exprs = [f[i] / M[i, i] for i in range(n)]
        rhs_exprs = [sp.simplify(e) if M[i, i] != 1 else e for i, e in enumerate(rhs_exprs)]
    else:
        rhs_exprs = list(M) + list(f)
    cam_syms = [[sp.Symbol(f"_cam{i}_{k}", real=True) for k in range(order + 1)]
                for i, order in enumerate(sy.orders)]
    specialise = 0 < len(sy.instances) <= MAX_VARIANT_INSTANCES
    variants = dwell_variants(rhs_exprs, cam_syms) if specialise else [rhs_exprs]

    # parameter-only subexpressions: computed once per run by prepare()
    consts = ConstantTable({p.symbol for p in m.parameters})
    variants = [[consts.hoist(e) for e in v] for v in variants]
    if all(v == variants[0] for v in variants[1:]):   # the dwell changes nothing here
        specialise, variants = False, variants[:1]
    out_exprs = [consts.hoist(_plain(o.expr, sy)) for o in m.outputs]
    names = dict(sy.names)
    names.update({k: k.name for k, _ in consts.items})

    rhs_variants, used_rhs = [], set()
    for v, exprs in enumerate(variants):
        lines, code, used = cse_block(exprs, names, prefix=f"_s{v}_")
        rhs_variants.append({"index": v, "lines": lines, "code": code,
                             "dwell": [i for i in range(len(sy.instances)) if v >> i & 1]})
        used_rhs |= used
    # outputs: q'' is taken from dy, computed first by rhs()
    out_lines, out_code, used_out = cse_block(
        out_exprs, names | {s: f"dy[{n + i}]" for i, s in enumerate(qdd_syms)}, prefix="_o")
    const_lines, const_code, used_const = cse_block([e for _, e in consts.items], names, prefix="_c")

    printer = CythonPrinter(sy.names)
    instances = []
    for i, ((family, arg), order) in enumerate(zip(sy.instances, sy.orders)):
        affine = _time_affine(arg, t, {sp.Symbol(s, real=True) for s in state_syms})
        instances.append({
            "index": i,
            "bit": 1 << i,
            "family": family,
            "family_index": sorted({fam for fam, _ in sy.instances}).index(family),
            "arg": printer.doprint(arg),
            "arg_text": str(arg),
            "order": order,
            "affine": None if affine is None else [printer.doprint(affine[0]), printer.doprint(affine[1])],
        })
    used = sorted((used_rhs | used_out | used_const | printer.used) & (set(MATH_FUNCTIONS) | {"M_PI"}))
    families = sorted({fam for fam, _ in sy.instances})

    manifest = {
        "name": m.name,
        "title": m.title,
        "reference": m.reference,
        "time": {"name": t.name, "unit": m.time_unit},
        "n_q": n,
        "states": [{"name": c.name, "unit": c.unit, "scale": c.scale, "doc": c.doc,
                    "initial": _num(c.initial)} for c in m.coordinates]
        + [{"name": c.name + "d", "unit": f"{c.unit}/{m.time_unit}", "scale": c.scale,
            "doc": f"rate of {c.name}", "initial": _num(c.initial_rate)} for c in m.coordinates],
        "parameters": [{"name": p.name, "default": p.default, "unit": p.unit, "doc": p.doc,
                        "low": p.low if p.low != -float("inf") else None,
                        "high": p.high if p.high != float("inf") else None,
                        "open_low": p.open_low, "open_high": p.open_high,
                        "range": p.range_text()} for p in m.parameters],
        "outputs": [{"name": o.name, "unit": o.unit, "doc": o.doc} for o in m.outputs],
        "cam_families": families,
        "cam_instances": [{"family": d["family"], "argument": d["arg_text"],
                           "time_affine": d["affine"] is not None} for d in instances],
        "residual": None if m.residual is None else {
            "error": m.residual.error, "acceleration": m.residual.acceleration,
            "rise_end": m.residual.rise_end},
        "options": list(m.options),
    }
    canonical = json.dumps({"M": sp.srepr(eq.M), "f": sp.srepr(eq.f), "Phi": sp.srepr(eq.Phi),
                            "outputs": [sp.srepr(o.expr) for o in m.outputs],
                            "manifest": manifest}, sort_keys=True)
    manifest["source_hash"] = "sha256:" + hashlib.sha256(canonical.encode()).hexdigest()

    return {
        "model": m,
        "name": m.name,
        "title": m.title,
        "reference": m.reference,
        "doc_lines": [line.rstrip() for line in m.doc.strip().splitlines()],
        "n": n,
        "n_states": 2 * n,
        "params": [p.name for p in m.parameters],
        "coords": [c.name for c in m.coordinates],
        "outputs": [o.name for o in m.outputs],
        "instances": instances,
        "n_families": len(families),
        "diagonal": diagonal,
        "specialise": specialise,
        "variants": rhs_variants,
        "temporaries": [name for v in rhs_variants for name, _ in v["lines"]],
        "consts": [k.name for k, _ in consts.items],
        "const_lines": const_lines,
        "const_code": const_code,
        "out_lines": out_lines,
        "out_code": out_code,
        "math": used,
        "manifest_json": json.dumps(manifest, indent=1, sort_keys=True),
        "source_hash": manifest["source_hash"],
    }


def render_model(model: Model) -> str:
    return _env().get_template("model.pyx.j2").render(**model_context(derive(model)))


# -- cam-law library ------------------------------------------------------------


def camlaws_context() -> dict:
    laws = []
    par = camlaws.theta
    for law in sorted(camlaws.LAWS.values(), key=lambda l: l.code):
        names = {par: "par", camlaws.T: "T"}
        printer = CythonPrinter(names)
        segs = []
        for k in range(law.n_segments):
            exprs = [law.segment_exprs(order)[k] for order in range(4)]
            lines, code, _ = cse_block(exprs, names, prefix="c")
            segs.append({"index": k, "lines": lines, "code": code})
        laws.append({
            "key": law.key,
            "code": law.code,
            "title": law.title,
            "reference": law.reference,
            "bounds": [printer.doprint(b) for b in law.bounds],
            "segments": segs,
            "parameter": None if law.parameter is None else {
                "name": law.parameter.symbol.name, "default": law.parameter.default,
                "low": law.parameter.low, "high": law.parameter.high,
                "doc": law.parameter.doc},
            "amplitude": str(law.amplitude),
        })
    info = [{k: v for k, v in law.items() if k not in ("segments",)} for law in laws]
    return {"laws": laws, "laws_json": json.dumps(info, indent=1, sort_keys=True)}


def render_camlaws() -> dict[str, str]:
    env, ctx = _env(), camlaws_context()
    return {"camlaws.pxd": env.get_template("camlaws.pxd.j2").render(**ctx),
            "camlaws.pyx": env.get_template("camlaws.pyx.j2").render(**ctx)}


# -- all files ----------------------------------------------------------------------


def render_all() -> dict[str, str]:
    """File name -> text of everything that belongs in ``generated/``."""
    from .models import REGISTRY

    files = render_camlaws()
    for name, build in REGISTRY.items():
        model = build()
        if model.name != name:
            raise ValueError(f"registry key {name!r} differs from model name {model.name!r}")
        files[f"{name}.pyx"] = render_model(model)
    return files
