"""Reduction of a dynamic model to a point of interest, thesis sec. 2.4, (2.55)-(2.59).

A lever with transmission i = b/a (2.51) connects point A (arm a) to point B
(arm b).  Reduction replaces a magnitude at A by one at B such that the
model's behaviour does not change.  The thesis argues each rule the same way:
a force F at B is balanced by i F at A (virtual work, or the lever's moment
balance); whatever A does in response (acceleration, displacement, velocity)
appears at B multiplied by i; the reduced magnitude at B must give that same
response to F.  :func:`derive_rules` repeats these arguments symbolically, so
the printed rules below are checked, not just typed in:

    linear dimension   s'   = i s          (2.55)
    mass               m'   = m / i^2      (2.56)
    stiffness          c'   = c / i^2      (2.57)
    viscous damper     d'   = d / i^2      (2.58)
    viscosity          eta' = eta / i^3    (2.59)
    frame at pivot M   c'   = c / ((a + b)/a)^2   (sec. 2.4.3)

The rules assume a frame that is rigid with respect to the mechanism (text
after (2.57)).  :func:`reduce_system` applies them to a whole linear system:
scaling each coordinate to the point of interest, x' = i x.
"""
from __future__ import annotations

import sympy as sp

from .assembly import System

i = sp.Symbol("i", positive=True)
"""Transmission ratio from A to B, i = b/a (2.51)."""


def length(s, i):
    """Linear dimension at A seen at B, e.g. backlash: s' = i s (2.55)."""
    return i * s


def mass(m, i):
    """Mass at A replaced at B: m' = m/i^2 (2.56)."""
    return m / i**2


def stiffness(c, i):
    """Stiffness at A replaced at B: c' = c/i^2 (2.57)."""
    return c / i**2


def damper(d, i):
    """Linear viscous damper at A replaced at B: d' = d/i^2 (2.58)."""
    return d / i**2


def viscosity(eta, i):
    """Lubricant viscosity of a squeeze film at A replaced at B: eta' = eta/i^3 (2.59)."""
    return eta / i**3


def frame_stiffness(c_M, a, b):
    """Pivot (frame) stiffness c_M at M of a lever A-M-B, seen at B: c_M/((a + b)/a)^2 (sec. 2.4.3).

    The lever's pivot M sits between A (arm a) and B (arm b); with A held by
    the mechanism, a deflection of the pivot turns the lever about A, so B
    moves (a + b)/a times as far: the rule (2.57) with i = (a + b)/a.
    """
    return c_M / ((a + b) / a) ** 2


def squeeze_force(eta, w, b, R_e, s):
    """Squeeze-film force F = 12 pi eta w b (R_e/(2 s))^(3/2) (A.4.11), as the text of sec. 2.4.5 uses it.

    w the approach velocity, b the width of the film, R_e the equivalent
    radius, s the gap.  App. 4 is partly lost in the scan; this is the form
    quoted in sec. 2.4.5 and in the model guide.
    """
    return 12 * sp.pi * eta * w * b * (R_e / (2 * s)) ** sp.Rational(3, 2)


def derive_rules() -> dict[str, sp.Expr]:
    """Each reduction rule derived from the equivalence argument of sec. 2.4.

    Returns the reduced magnitude at B for a magnitude at A, keyed "length",
    "mass", "stiffness", "damper", "viscosity", and "frame" for a pivot
    stiffness c at M (lever arms a, b: symbols a, b).  For the viscosity the
    squeeze law (A.4.11) gives the velocity at A under the force i F; the
    linear dimensions of the film (b, s and, reading taken, R_e as well: the
    text writes R_e' in the reduced law and calls the rule "valid for all
    linear dimensions") are reduced by (2.55), so (R_e/(2s)) is unchanged and
    only b' = i b enters; equal velocity at B then gives eta' = eta/i^3.
    """
    F, ii = sp.Symbol("F", positive=True), i
    arm_a, arm_b = sp.symbols("a b", positive=True)
    s, m, c, d, eta = sp.symbols("s m c d eta", positive=True)
    b, R_e, gap = sp.symbols("b R_e s_g", positive=True)
    lever = {arm_b: ii * arm_a}                                   # i = b/a (2.51)
    # moment balance about the pivot: F_A a = F b
    F_A = sp.solve(sp.Eq(sp.Symbol("F_A") * arm_a, F * arm_b), sp.Symbol("F_A"))[0].subs(lever)
    unknown = sp.Symbol("reduced", positive=True)
    rules = {}
    # a displacement s at A turns the lever through s/a, which moves B through b s/a
    rules["length"] = (arm_b * (s / arm_a)).subs(lever)
    # B's response (i times A's) must equal the response of the reduced magnitude to F
    for name, at_A, law in (("mass", m, lambda F, k: F / k),       # acceleration F/m
                            ("stiffness", c, lambda F, k: F / k),  # deflection F/c
                            ("damper", d, lambda F, k: F / k)):    # velocity F/d
        at_B = ii * law(F_A, at_A)
        rules[name] = sp.solve(sp.Eq(law(F, unknown), at_B), unknown)[0]
    # frame rigidity (sec. 2.4.3): F at B, A held; moments about A give the pivot load
    # F_M a = F (a + b); the pivot yields F_M/c and B follows (a + b)/a times that
    F_M = F * (arm_a + arm_b) / arm_a
    f_B = (arm_a + arm_b) / arm_a * F_M / c
    rules["frame"] = sp.solve(sp.Eq(F / unknown, f_B), unknown)[0]
    w = sp.Symbol("w", positive=True)
    w_A = sp.solve(sp.Eq(squeeze_force(eta, w, b, R_e, gap), F_A), w)[0]
    w_B = ii * w_A
    w_reduced = sp.solve(sp.Eq(squeeze_force(unknown, w, length(b, ii), length(R_e, ii),
                                             length(gap, ii)), F), w)[0]
    rules["viscosity"] = sp.solve(sp.Eq(w_reduced, w_B), unknown)[0]
    return {k: sp.simplify(v) for k, v in rules.items()}


def reduce_system(system: System, ratios) -> System:
    """Reduce every coordinate of a linear system to the point of interest.

    ``ratios[k]`` is the transmission from coordinate k to the point of
    interest, so the reduced coordinate is x_k' = i_k x_k (2.55).  With
    S = diag(i_k), M' = S^-1 M S^-1 and C' = S^-1 C S^-1: on the diagonal of
    a lumped model this is m/i^2 (2.56) and c/i^2 (2.57), and a spring
    between two coordinates with different ratios loses its transmission.
    The inputs keep their own scale (K' = S^-1 K, B' = S^-1 B).  The natural
    frequencies, roots of (2.50), do not change.
    """
    S_inv = sp.diag(*[1 / sp.sympify(r) for r in ratios])
    f = lambda A: A.applyfunc(sp.factor)  # noqa: E731
    return System(system.coords, system.inputs, f(S_inv * system.M * S_inv),
                  f(S_inv * system.C * S_inv), f(S_inv * system.B), f(S_inv * system.K))
