"""What every generated model module is printed with, whatever its formulation.

Both printers of model modules build on this module: :mod:`camdyn.derive.codegen` (the
ordinary differential equations M q'' = f) and :mod:`camdyn.derive.dae` (the multiplier form
M q'' + Phi_q^T lambda = f, Phi = 0).  Neither imports the other; :mod:`camdyn.derive.render`
chooses between them.  Here:

* the template environment: one, cached, with StrictUndefined, so a value a template asks
  for and the context lacks is an error, never an empty string;
* the plain symbols: how a model's expressions (functions of time, cam inputs H(arg), modes)
  become symbols the Cython printer names (``X``, ``Xd``, ``_cam0[1]``, ``ctx.mode[2]``);
* the manifest's entries every model has (names, time, coordinates and their rates,
  parameters with units and ranges, options) and its source hash, the hash of the equations
  the file was printed from.
"""
from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import jinja2
import sympy as sp

from .model import CamFunction, Model
from .printer import MATH_FUNCTIONS

TEMPLATES = Path(__file__).parent / "templates"


# -- templates ------------------------------------------------------------------------


@cache
def environment() -> jinja2.Environment:
    """The Jinja2 environment of every generated file (templates/), built once per process."""
    return jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(TEMPLATES)),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
    )


def render(template: str, **context) -> str:
    """The text of ``template`` filled in with ``context``."""
    return environment().get_template(template).render(**context)


# -- plain symbols ----------------------------------------------------------------------


@dataclass
class Plain:
    """How model expressions become plain symbols, and how those are printed."""

    model: Model
    names: dict       # plain symbol -> code
    instances: list   # (family, plain argument) per cam input instance
    orders: list      # highest derivative order used per instance
    cam: dict         # cam function atom -> plain symbol
    states: set       # plain symbols of q, q', z (state dependence of cam arguments)
    time_functions: dict  # q'' -> Xdd, q' -> Xd, q -> X, z -> z (built once: costly on many q)

    def __call__(self, expr):
        m, t = self.model, self.model.time
        expr = sp.sympify(expr)
        # xreplace, not subs: exact subtrees (derivatives before the functions inside them,
        # as xreplace replaces the largest match first) without subs' costly rewriting
        if m.first_order:
            expr = expr.xreplace({z(t).diff(t): z.rate for z in m.first_order})
        expr = expr.xreplace(self.cam) if self.cam else expr
        return expr.xreplace(self.time_functions)


def time_functions(m: Model) -> dict:
    """Derivatives first: q'' -> Xdd, q' -> Xd, q -> X, z -> z."""
    t = m.time
    out = {}
    for c in m.coordinates:
        out[c(t).diff(t, 2)] = sp.Symbol(c.name + "dd", real=True)
    for c in m.coordinates:
        out[c(t).diff(t)] = sp.Symbol(c.name + "d", real=True)
    for c in m.coordinates:
        out[c(t)] = sp.Symbol(c.name, real=True)
    for z in m.first_order:
        out[z(t)] = sp.Symbol(z.name, real=True)
    return out


def plainer(m: Model, exprs) -> Plain:
    """The plain symbols of the model's expressions ``exprs``: every cam input instance they
    use (one per family and argument, with the highest derivative order used), the
    parameters, time and the modes, each with the code that reads it."""
    t = m.time
    tf = time_functions(m)
    rates = {z(t).diff(t): z.rate for z in m.first_order}
    found = set()
    for e in exprs:
        e = sp.sympify(e)
        if rates:
            e = e.xreplace(rates)
        found |= e.atoms(CamFunction)
    # one instance per family and argument; arguments are compared expanded, because
    # Lagrange's equations may have expanded (beta - beta_0)/beta_m in some terms only
    def key_of(a):
        return (a.family, sp.srepr(sp.expand(a.args[0].xreplace(tf))))

    keyed = {}
    for a in sorted(found, key=sp.srepr):
        key = key_of(a)
        keyed.setdefault(key, [a.args[0].xreplace(tf), 0])
        keyed[key][1] = max(keyed[key][1], a.order)
    order = sorted(keyed)
    index = {key: i for i, key in enumerate(order)}
    names = {p.symbol: p.name for p in m.parameters}
    names[t] = "t"
    cam = {}
    for a in sorted(found, key=sp.srepr):
        i = index[key_of(a)]
        sym = sp.Symbol(f"_cam{i}_{a.order}", real=True)
        names[sym] = f"_cam{i}[{a.order}]"
        cam[a] = sym
    ncam = len(order)
    for j, mode in enumerate(m.modes):
        names[mode.symbol] = f"ctx.mode[{ncam + j}]"
    states = {v for k, v in tf.items() if not (isinstance(k, sp.Derivative) and k.derivative_count == 2)}
    return Plain(m, names, [(key[0], keyed[key][0]) for key in order],
                 [keyed[key][1] for key in order], cam, states, tf)


def math_imports(used: set) -> list:
    """The libc.math names among those the printed code ``used``, sorted, for its cimport."""
    return sorted(used & (set(MATH_FUNCTIONS) | {"M_PI"}))


# -- the manifest -------------------------------------------------------------------------


def number(value):
    """A number for the manifest; an expression of the parameters as its text."""
    value = sp.sympify(value)
    return float(value) if value.is_number else str(value)


def state_entries(m: Model) -> list:
    """Manifest entries of q and q'."""
    return ([{"name": c.name, "unit": c.unit, "scale": c.scale, "doc": c.doc,
              "initial": number(c.initial)} for c in m.coordinates]
            + [{"name": c.name + "d", "unit": f"{c.unit}/{m.time_unit}", "scale": c.scale,
                "doc": f"rate of {c.name}", "initial": number(c.initial_rate)} for c in m.coordinates])


def manifest_common(m: Model) -> dict:
    """The manifest entries every generated model has: names, time, coordinates, parameters."""
    return {
        "name": m.name,
        "title": m.title,
        "reference": m.reference,
        "time": {"name": m.time.name, "unit": m.time_unit},
        "n_q": len(m.coordinates),
        "parameters": [{"name": p.name, "default": p.default, "unit": p.unit, "doc": p.doc,
                        "low": p.low if p.low != -float("inf") else None,
                        "high": p.high if p.high != float("inf") else None,
                        "open_low": p.open_low, "open_high": p.open_high,
                        "range": p.range_text()} for p in m.parameters],
    }


def option_entries(m: Model) -> list:
    """The model's options as JSON (a tuple becomes a list)."""
    return [list(o) if isinstance(o, tuple) else o for o in m.options]


def doc_lines(m: Model) -> list:
    """The model's docstring as comment lines of its generated file."""
    return [line.rstrip() for line in m.doc.strip().splitlines()]


def with_source_hash(manifest: dict, equations: dict) -> dict:
    """``manifest`` with its ``source_hash``: SHA-256 of the equations (``equations``: name ->
    srepr text or list of them) and of the manifest itself.  srepr and sorted keys make it
    independent of the hash seed."""
    canonical = json.dumps({**equations, "manifest": manifest}, sort_keys=True)
    manifest["source_hash"] = "sha256:" + hashlib.sha256(canonical.encode()).hexdigest()
    return manifest
