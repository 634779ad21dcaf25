"""Expression rewrites that make generated right-hand sides cheaper.

Two rewrites, both exact:

* parameter constants: every subexpression that depends on parameters only
  (e.g. (2 pi/tau)^2) is computed once per run by the generated
  ``prepare()`` and read from a table, instead of in every call;
* dwell variants: while a cam input sits in a dwell its derivatives are zero,
  so the equations are specialised with H' = H'' = H''' = 0 (the stiffness
  1/(1 + H'^2 Fa) of CAMSHAFT-1 becomes 1, with no division left).
"""
from __future__ import annotations

import sympy as sp


class ConstantTable:
    """Parameter-only subexpressions, each replaced by a symbol _k<j>, in first-seen order."""

    def __init__(self, params: set):
        self.params = set(params)
        self.entries: dict = {}

    def _symbol(self, expr):
        if not expr.free_symbols:   # a plain number: the printer writes it as a literal
            return expr
        if expr not in self.entries:
            self.entries[expr] = sp.Symbol(f"_k{len(self.entries)}", real=True)
        return self.entries[expr]

    def _const(self, expr) -> bool:
        return expr.free_symbols <= self.params

    def hoist(self, expr):
        """``expr`` with its maximal parameter-only parts replaced by table symbols."""
        expr = sp.sympify(expr)
        if expr.is_Atom:
            return expr
        if self._const(expr):
            return self._symbol(expr)
        if isinstance(expr, sp.Piecewise):
            # a piece (value, condition) is no expression of its own: hoist inside it
            return sp.Piecewise(*[(self.hoist(e), self.hoist(c)) for e, c in expr.args])
        if expr.is_Mul:
            const = [a for a in expr.args if self._const(a)]
            other = [a for a in expr.args if not self._const(a)]
            if const and len(other) == 1 and other[0].is_Add and all(
                    t.is_Mul and any(self._const(f) for f in t.args) for t in other[0].args):
                # c (a X + b Y) -> (c a) X + (c b) Y with a, b constant: one multiplication less
                c = sp.Mul(*const)
                return self.hoist(sp.Add(*[c * term for term in other[0].args], evaluate=False))
        if expr.is_Add:
            # a X + b X -> (a + b) X: terms that differ by a constant factor share one product
            groups: dict = {}
            for term in expr.args:
                c, rest = term.as_independent(*(term.free_symbols - self.params), as_Add=False)
                groups[rest] = groups.get(rest, 0) + c
            terms = [self.hoist(c * rest) if c != 1 else self.hoist(rest) for rest, c in groups.items()]
            return sp.Add(*terms)
        if expr.is_Add or expr.is_Mul:
            const = [a for a in expr.args if self._const(a)]
            rest = [self.hoist(a) for a in expr.args if not self._const(a)]
            if const:
                c = expr.func(*const)
                if not (c.is_Atom):
                    c = self._symbol(c)
                rest = [c] + rest
            return expr.func(*rest)
        return expr.func(*[self.hoist(a) for a in expr.args])

    @property
    def items(self) -> list:
        """(symbol, expression) pairs in table order."""
        return [(s, e) for e, s in self.entries.items()]


def dwell_variants(exprs, cam_symbols: list) -> list:
    """Specialisations of ``exprs`` for every pattern of cam inputs in a dwell.

    ``cam_symbols[i][k]`` is the symbol of d^k H/darg^k of cam instance i.
    Variant v has instance i in a dwell when bit i of v is set: there its
    derivatives (k >= 1) are zero; the value H stays a symbol (0 before the
    rise, 1 after it).
    """
    out = []
    for v in range(2 ** len(cam_symbols)):
        zero = dwell_zeros(cam_symbols, v)
        out.append([sp.sympify(e).xreplace(zero) if zero else sp.sympify(e) for e in exprs])
    return out


def dwell_zeros(cam_symbols: list, v: int) -> dict:
    """The substitution of variant ``v`` (see :func:`dwell_variants`): the derivatives of
    every cam instance i with bit i of v set are zero."""
    return {s: 0 for i, syms in enumerate(cam_symbols) if v >> i & 1 for s in syms[1:]}
