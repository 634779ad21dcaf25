"""The polynomials of the cam laws' sine and cosine (templates/camlaws.pxd.j2, camlaw_trig_).

After the argument is reduced to |r| <= pi/4 the laws take

    sin r = r + r z P(z),   cos r = 1 - z/2 + z^2 Q(z),   z = r^2,

with P and Q of degree 5 in z (sin of degree 13, cos of degree 14).  Their coefficients are
the polynomials of least largest relative error on [0, pi/4], found here by Lawson's
iteration (a weighted least-squares fit whose weights grow where the error is largest, which
converges to the minimax fit) on 400 Chebyshev nodes, in 40-digit arithmetic (mpmath), then
rounded to doubles.  The Taylor series reaches the same accuracy only at degrees 17 and 18,
two more products and sums in a chain every stage of a step waits on.

    python -m camdyn.derive.trig_fit      prints the coefficients and their errors
"""
from __future__ import annotations

import mpmath as mp

N_NODES = 400
N_COEF = 6          # P, Q of degree 5 in z
ITERATIONS = 60


def _nodes(n: int = N_NODES) -> list:
    half = mp.pi / 8
    xs = [half * (1 + mp.cos(mp.pi * (2 * i + 1) / (2 * n))) for i in range(n)]
    return [x for x in xs if x > mp.mpf("1e-6")]     # r -> 0 adds nothing but rounding


def _value(kind: str, x, c):
    z = x * x
    p = sum(ci * z ** j for j, ci in enumerate(c))
    return x + x ** 3 * p if kind == "sin" else 1 - z / 2 + z * z * p


def _exact(kind: str, x):
    return mp.sin(x) if kind == "sin" else mp.cos(x)


def fit(kind: str) -> list[float]:
    """The N_COEF coefficients of P (kind "sin") or Q ("cos"), rounded to doubles."""
    with mp.workdps(40):
        xs = _nodes()
        # the unknowns enter linearly: relative error = (row . c - rhs) * scale / f(x)
        rows = [[(x * x) ** j for j in range(N_COEF)] for x in xs]
        if kind == "sin":
            rhs = [(mp.sin(x) - x) / x ** 3 for x in xs]
            scale = [x ** 3 / mp.sin(x) for x in xs]
        else:
            rhs = [(mp.cos(x) - 1 + x * x / 2) / x ** 4 for x in xs]
            scale = [x ** 4 / mp.cos(x) for x in xs]
        w = [mp.mpf(1)] * len(xs)
        for _ in range(ITERATIONS):
            a = mp.matrix([[r * mp.sqrt(wi) * s for r in row]
                           for row, wi, s in zip(rows, w, scale)])
            b = mp.matrix([y * mp.sqrt(wi) * s for y, wi, s in zip(rhs, w, scale)])
            c = mp.lu_solve(a.T * a, a.T * b)
            err = [abs(sum(ci * ri for ci, ri in zip(c, row)) - y) * s
                   for row, y, s in zip(rows, rhs, scale)]
            total = sum(wi * e for wi, e in zip(w, err))
            w = [wi * e / total for wi, e in zip(w, err)]
        return [float(c[j]) for j in range(N_COEF)]


def largest_error(kind: str, coefficients, n: int = 20000) -> float:
    """The largest relative error of the rounded polynomial on n points of (0, pi/4]."""
    with mp.workdps(40):
        c = [mp.mpf(x) for x in coefficients]
        worst = mp.mpf(0)
        for i in range(1, n + 1):
            x = mp.pi / 4 * i / n
            worst = max(worst, abs(_value(kind, x, c) / _exact(kind, x) - 1))
        return float(worst)


def main() -> None:
    for kind in ("sin", "cos"):
        c = fit(kind)
        print(kind, ", ".join(repr(x) for x in c),
              f"(largest relative error {largest_error(kind, c):.2e})")


if __name__ == "__main__":
    main()
