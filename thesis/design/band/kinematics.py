"""The rigid follower's motion over the whole turn: lift, velocity, acceleration and jerk (SVAJ)
at a camshaft speed, and their largest values with error estimates.

The turn is :func:`camdyn.runtime.core.laws.compose`'s: the rise law over the rise angle
beta_m, the outer dwell, the same law mirrored over the return angle, the inner dwell; in
units of the rise T = phi/beta_m it gives H, H', H'', H''' in closed form (the generated
library; the return's H^(n) = -H_ret^(n)/r^n, r its angle over the rise's).  At the speed w
the rise lasts t_m = beta_m/w (App. 7 (8)), and at the output

    s = h H,   v = h H'/t_m,   a = h H''/t_m^2,   j = h H'''/t_m^3,

h the output's stroke: a translating follower's, a rocker's roller arc l Phi (2.55) (a
flat-faced rocker's at its pivot distance), whose arm turns by s/l (:meth:`SVAJ.arm`).

The largest |a| and |j| over the turn (:func:`peaks`) are found on the closed forms, segment
by segment of the law (each piece between its breakpoints sampled, the best sample refined by
Brent's method); their error is what the refinement leaves, c XATOL^2/2 with c the next
derivative's size there, plus the rounding, plus a law file's own estimate (a table's spline,
runtime/core/shaped.py).  Where H' jumps (the uniform law against its dwells) the acceleration
is an impulse and where H'' jumps the jerk is: the largest value is then infinite, and the
warnings give the jump's finite size and where it is.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camdyn.runtime.core import laws

from .residual import maximize, theta_of
from .spec import Machine

SAMPLES = 257
"""Samples of each piece of the law before the best is refined."""

XATOL = 1e-9
"""Brent's tolerance in T: at a maximum it costs c XATOL^2/2, far below the rounding."""

ROUNDING = 1e-13
"""The closed forms' rounding, relative to the largest value (polynomials of degree <= 9 and
sines evaluated in double precision)."""

JUMP = 1e-9
"""A derivative jumps where its two sides differ by more than this times its largest value
over the turn (runtime/core/shaped.py's rule)."""


@dataclass(frozen=True)
class SVAJ:
    """The rigid follower's motion over the full turn at the camshaft speed ``w`` (rad/s):
    theta_deg the cam angle from the rise's start, s (m), v (m/s), a (m/s^2), j (m/s^3) at the
    output (a rocker's along its roller's arc), ``lever`` the output's radius about a rocker's
    pivot (1 for a translating follower)."""

    theta_deg: np.ndarray
    s: np.ndarray
    v: np.ndarray
    a: np.ndarray
    j: np.ndarray
    law: str
    w: float
    lever: float = 1.0
    rocker: bool = False

    def arm(self) -> dict | None:
        """A rocker's arm angle psi (rad, from its rest), psi', psi'', psi''' (rad/s^n): the
        arc over the lever; None for a translating follower."""
        if not self.rocker:
            return None
        L = self.lever
        return {"psi": self.s / L, "psi_d": self.v / L, "psi_dd": self.a / L,
                "psi_ddd": self.j / L}


def turn_of(m: Machine, law: str, theta=None) -> laws.Turn:
    """The full turn of ``law`` on ``m``'s angles (the polydyne designed at the band's
    centre, :func:`.residual.theta_of`)."""
    return laws.compose(law, None, m.angles, theta=theta_of(m, law, theta))


def scales(m: Machine, w: float) -> tuple[float, float, float, float]:
    """h, h/t_m, h/t_m^2, h/t_m^3 at the speed w: the factors of H, H', H'', H'''."""
    h, k = m.output_stroke, w / m.rise_angle
    return h, h * k, h * k**2, h * k**3


def svaj(m: Machine, law: str, w: float, n: int = 3601, theta=None) -> SVAJ:
    """s, v, a, j over the full turn at ``w`` on ``n`` cam angles from 0 to 360 deg (module
    doc)."""
    turn = turn_of(m, law, theta)
    theta_deg = np.linspace(0.0, 360.0, int(n))
    E = turn.evaluate(theta_deg / m.angles[0])
    f = scales(m, w)
    return SVAJ(theta_deg, f[0] * E[:, 0], f[1] * E[:, 1], f[2] * E[:, 2], f[3] * E[:, 3],
                law, float(w), float(m.lever), m.rocker)


@dataclass(frozen=True)
class Peaks:
    """The largest |a| and |j| over the turn at the speed ``w``, with their errors.

    acceleration_max, _error   m/s^2 (inf where the velocity jumps: an impulse)
    jerk_max, _error           m/s^3 (inf where the acceleration jumps)
    acceleration_at_deg, jerk_at_deg
                               the cam angle where each is reached (where the jump is, for inf)
    velocity_jump, acceleration_jump
                               the largest jump of v (m/s) and of a (m/s^2) over the turn, 0
                               where there is none
    warnings                   the jumps, in words
    """

    acceleration_max: float
    acceleration_max_error: float
    jerk_max: float
    jerk_max_error: float
    w: float = 0.0
    law: str = ""
    acceleration_at_deg: float = 0.0
    jerk_at_deg: float = 0.0
    velocity_jump: float = 0.0
    acceleration_jump: float = 0.0
    warnings: tuple = ()


def peaks(m: Machine, law: str, w: float, theta=None) -> Peaks:
    """The largest |a| and |j| of ``law`` over ``m``'s turn at ``w`` (module doc)."""
    turn = turn_of(m, law, theta)
    f = scales(m, w)
    rise = m.angles[0]
    table = _table_errors(turn)
    a_T, a_val, a_err = _largest(turn, 2)
    j_T, j_val, j_err = _largest(turn, 3)
    v_jump = _jumps(turn, 1)
    a_jump = _jumps(turn, 2)
    warnings = []
    acc = (f[2] * a_val, f[2] * (a_err + table[2] * a_val), a_T * rise)
    jerk = (f[3] * j_val, f[3] * (j_err + table[3] * j_val), j_T * rise)
    if v_jump[1] > 0:
        dv = f[1] * v_jump[1]
        warnings.append(f"{law}: the velocity jumps by {dv:.4g} m/s at {v_jump[0] * rise:.4g} "
                        "deg: the acceleration is an impulse there (infinite), and so is the "
                        "inertia force on the cam")
        acc = (math.inf, 0.0, v_jump[0] * rise)
    if a_jump[1] > 0 or v_jump[1] > 0:
        da = f[2] * a_jump[1]
        if a_jump[1] > 0:
            warnings.append(f"{law}: the acceleration jumps by {da:.4g} m/s^2 at "
                            f"{a_jump[0] * rise:.4g} deg: the jerk is infinite there")
        where = (a_jump if a_jump[1] > 0 else v_jump)[0] * rise
        jerk = (math.inf, 0.0, where)
    return Peaks(acc[0], acc[1], jerk[0], jerk[1], float(w), law, acc[2], jerk[2],
                 f[1] * v_jump[1], f[2] * a_jump[1], tuple(warnings))


def _table_errors(turn) -> tuple:
    """A law file's estimated error of H .. H''' relative to their largest values (0 for a
    law of the library or a rise given exactly)."""
    errs = [getattr(turn.rise, "errors", (0.0,) * 4), getattr(turn.ret, "errors", (0.0,) * 4)]
    return tuple(max(a, b) for a, b in zip(*errs))


def _pieces(turn) -> list[tuple[float, float]]:
    """The turn's pieces in T, 0 to its period, each where its closed form is smooth."""
    b = [0.0, *turn.breakpoints()]
    b = sorted(set(x for x in b if 0.0 <= x <= turn.period))
    return [(lo, hi) for lo, hi in zip(b[:-1], b[1:]) if hi > lo]


def _inside(lo: float, hi: float, n: int) -> np.ndarray:
    """n points on [lo, hi], the ends moved inward by one rounding step (each piece's own
    side of a breakpoint)."""
    T = np.linspace(lo, hi, n)
    T[0], T[-1] = np.nextafter(lo, hi), np.nextafter(hi, lo)
    return T


def _largest(turn, order: int) -> tuple[float, float, float]:
    """(T, value, error) of the largest |H^(order)| over the turn: every piece sampled, the
    best sample of each refined by Brent on the closed form; the error what the refinement
    leaves (the next derivative's size c there, c XATOL^2/2) and the rounding."""
    best = (0.0, 0.0, 0.0)
    for lo, hi in _pieces(turn):
        T = _inside(lo, hi, SAMPLES)
        g = np.abs(turn.evaluate(T)[:, order])
        k = int(np.argmax(g))
        if not g[k] > best[1]:
            continue
        a, b = T[max(k - 1, 0)], T[min(k + 1, len(T) - 1)]
        x, v = maximize(lambda t: abs(float(turn.evaluate(np.array([t]))[0, order])), a, b,
                        XATOL)
        if g[k] >= v:
            x, v = float(T[k]), float(g[k])
        c = _curvature(turn, order, x, T[1] - T[0])
        best = (x, v, c * XATOL**2 / 2 + ROUNDING * v)
    return best


def _curvature(turn, order: int, x: float, d: float) -> float:
    """|d^2/dT^2 H^(order)| near x, twice its estimate from differences of the closed forms
    over d (H'''s differences for H'', second differences for H''')."""
    E = turn.evaluate(np.array([x - d, x, x + d]))
    if order == 2:
        return 2 * abs(E[2, 3] - E[0, 3]) / (2 * d)
    return 2 * abs(E[2, 3] - 2 * E[1, 3] + E[0, 3]) / d**2


def _jumps(turn, order: int) -> tuple[float, float]:
    """(T, size) of the largest jump of H^(order) at the turn's breakpoints (the turn
    repeating: the left side of T = 0 is the end of the inner dwell or the return), (0, 0)
    where it is continuous."""
    P = turn.period
    pts = sorted(set([0.0, *[b for b in turn.breakpoints() if 0.0 < b < P]]))
    left = np.array([np.nextafter(P, 0.0) if b == 0.0 else np.nextafter(b, -1.0) for b in pts])
    right = np.array([np.nextafter(b, P) for b in pts])
    jumps = np.abs(turn.evaluate(right)[:, order] - turn.evaluate(left)[:, order])
    scale = max(float(np.abs(turn.evaluate(_inside(0.0, P, 4 * SAMPLES))[:, order]).max()),
                float(jumps.max()), 1.0)
    k = int(np.argmax(jumps))
    if jumps[k] > JUMP * scale:
        return float(pts[k]), float(jumps[k])
    return 0.0, 0.0
