"""Print SymPy expressions as Cython (C-level, nogil) code.

Based on SymPy's C99 printer, with two changes that matter for speed and for
Cython syntax: small integer powers become products (gcc only turns pow(x, 2)
into x*x by itself), and every symbol is printed through a name map, so states
read ``y[0]`` through locals named as in the thesis.
"""
from __future__ import annotations

import sympy as sp
from sympy.printing.c import C99CodePrinter

# libc.math names the printed code may call
MATH_FUNCTIONS = ("sin", "cos", "tan", "sqrt", "exp", "log", "fabs", "pow", "tanh",
                  "sinh", "cosh", "atan", "atan2", "asin", "acos", "copysign", "fmin", "fmax")


MAX_SQUARING = 32
"""Integer powers up to this one of a symbol are printed as products of its repeated squares
(x^14 = x^8 x^4 x^2): one libm pow costs some twenty multiplications, and gcc computes the
squares x^2, x^4, ... once for every power of the same symbol in a function, as they are the
same expressions.  Within a few units in the last place of pow."""


def _squarings(b: str, n: int) -> str:
    """x^n as the product of the squares x^(2^k) of n's binary digits, each written out from
    x so that every power of x shares them."""
    squares, factors, k = [b], [], 0
    while n >> k:
        if k:
            squares.append(f"({squares[-1]}*{squares[-1]})")
        if (n >> k) & 1:
            factors.append(squares[k])
        k += 1
    return "(" + "*".join(reversed(factors)) + ")"


class CythonPrinter(C99CodePrinter):
    """C99 expressions that are also valid Cython expressions."""

    def __init__(self, names: dict | None = None, functions: dict | None = None):
        super().__init__()
        self.names = names or {}
        self.functions = functions or {}
        """Functions printed under another name (``{"sin": "camlaw_sin"}``)."""
        self.used = set()

    def _print(self, expr, **kwargs):
        # record every libc.math function printed, whichever printing method handles it
        name = type(expr).__name__
        if name in self.functions:
            return f"{self.functions[name]}({', '.join(self._print(a) for a in expr.args)})"
        if name in MATH_FUNCTIONS:
            self.used.add(name)
        elif name == "Abs":
            self.used.add("fabs")
        return super()._print(expr, **kwargs)

    def _print_Symbol(self, expr):
        return self.names.get(expr, expr.name)

    def _print_Pi(self, expr):
        self.used.add("M_PI")
        return "M_PI"

    def _print_Pow(self, expr):
        base, exp = expr.as_base_exp()
        if exp.is_Integer and 1 < abs(int(exp)) <= 4:
            b = self.parenthesize(base, sp.printing.precedence.PRECEDENCE["Mul"] + 1)
            prod = "(" + "*".join([b] * abs(int(exp))) + ")"
            return prod if exp > 0 else f"(1.0/{prod})"
        if exp.is_Integer and abs(int(exp)) <= MAX_SQUARING and base.is_Atom:
            prod = _squarings(self._print(base), abs(int(exp)))
            return prod if exp > 0 else f"(1.0/{prod})"
        if exp == -1:
            return f"(1.0/{self.parenthesize(base, sp.printing.precedence.PRECEDENCE['Mul'] + 1)})"
        if exp == sp.S.Half:
            self.used.add("sqrt")
            return f"sqrt({self._print(base)})"
        if exp == -sp.S.Half:
            self.used.add("sqrt")
            return f"(1.0/sqrt({self._print(base)}))"
        self.used.add("pow")
        return f"pow({self._print(base)}, {self._print(exp)})"

    def _print_Mul(self, expr):
        # fold the numeric factors (1/2, pi, sqrt(3), ...) into one literal: C may not
        # turn x/M_PI into a multiplication itself (it would change the rounding)
        numeric = [a for a in expr.args if a.is_number]
        others = [a for a in expr.args if not a.is_number]
        if not numeric or (len(numeric) == 1 and (numeric[0].is_Integer or numeric[0] == -1)):
            return super()._print_Mul(expr)
        c = float(sp.Mul(*numeric).evalf(20))
        if not others:
            return repr(c)
        rest = super()._print_Mul(sp.Mul(*others)) if len(others) > 1 else \
            self.parenthesize(others[0], sp.printing.precedence.PRECEDENCE["Mul"])
        if c == 1.0:
            return rest
        if c == -1.0:
            return f"-{rest}"
        return f"{c!r}*{rest}"

    def _print_Function(self, expr):
        name = type(expr).__name__
        if name in MATH_FUNCTIONS:
            self.used.add(name)
        return super()._print_Function(expr)

    def _print_Abs(self, expr):
        self.used.add("fabs")
        return f"fabs({self._print(expr.args[0])})"

    def _print_sign(self, expr):
        self.used.add("copysign")
        a = self._print(expr.args[0])
        return f"(0.0 if {a} == 0.0 else copysign(1.0, {a}))"

    def _print_Piecewise(self, expr):
        # Cython conditional expression, nested right to left
        *pairs, last = expr.args
        if last.cond != sp.true:
            raise ValueError("Piecewise without a default branch cannot be printed")
        code = self._print(last.expr)
        for e, c in reversed(pairs):
            code = f"(({self._print(e)}) if ({self._print(c)}) else ({code}))"
        return code

    def _print_Relational(self, expr):
        op = {"==": "==", "!=": "!="}.get(expr.rel_op, expr.rel_op)
        return f"({self._print(expr.lhs)} {op} {self._print(expr.rhs)})"

    def _print_And(self, expr):
        return "(" + " and ".join(self._print(a) for a in expr.args) + ")"

    def _print_Or(self, expr):
        return "(" + " or ".join(self._print(a) for a in expr.args) + ")"

    def _print_Not(self, expr):
        return f"(not {self._print(expr.args[0])})"

    def _print_BooleanTrue(self, expr):
        return "True"

    def _print_BooleanFalse(self, expr):
        return "False"

    def _print_Float(self, expr):
        return repr(float(expr))

    def _print_Rational(self, expr):
        return f"{float(expr.p)!r}/{float(expr.q)!r}"

    def _print_Integer(self, expr):
        return f"{int(expr)}.0" if abs(int(expr)) < 2**53 else repr(float(expr))


def cse_block(exprs, names: dict, prefix: str = "s", functions: dict | None = None):
    """Common subexpressions of ``exprs``: (lines of local definitions, printed exprs);
    ``functions`` as CythonPrinter's."""
    exprs = list(exprs)
    # the "basic" pre-optimizations (factoring) pay on small systems and take minutes on
    # the large mode-dependent ones
    small = sum(sp.count_ops(e) for e in exprs) < 1500
    replacements, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix),
                                   optimizations="basic" if small else None, order="canonical")
    printer = CythonPrinter(names, functions)
    lines = [(str(sym), printer.doprint(e)) for sym, e in replacements]
    return lines, [printer.doprint(e) for e in reduced], printer.used
