"""Geometry of the grooved disk cam with a translating roller follower.

Source: *Transverse Vibration Analysis of a Translating Roller-Follower Cam Using
Cycloidal Profile for RDFD Motion*, cited as "paper (n)".

Frame and symbols (paper (3), (4)): the cam frame is fixed to the cam,
polar angle ``theta`` (the cam parameter).  The roller centre, i.e. the pitch-curve
point at ``theta``, is r(theta) (cos theta, sin theta) with r = r_b + r_r + S(theta):
r_b base-circle radius, r_r roller radius, S the follower displacement.  The
follower is radial (its axis passes through the cam centre).  SI units.

Motion, paper (1) and fig. 2.  RDFD: rise, outer dwell, fall, inner dwell.  The
paper sets the rise and the fall to pi/2 each and shows the two dwells in fig. 2
without printing their lengths; the reading taken here (the natural one for the
figure) is rise on [0, pi/2], outer dwell on [pi/2, pi], fall on [pi, 3 pi/2],
inner dwell on [3 pi/2, 2 pi].  All three first lengths are arguments, the inner
dwell takes what is left of the revolution.  The rise is S_T H(theta/beta_rise),
H a normalized law of ``camdyn.derive.camlaws`` (cycloidal by default, which is
paper (1) exactly); the fall is "S_T minus the rise shape", S_T (1 - H).

Profile, paper (2)-(4), by the theory of envelopes.  The groove walls are the
envelope of the family of roller circles F(X, Y, theta) = 0 centred on the pitch
curve; the envelope condition dF/dtheta = 0 is solved by SymPy here (nothing is
typed in from the paper, whose scan of (2), (3) is garbled).  Everything is derived
once for a generic pitch radius r(theta) (an undefined function) and then bound to
a concrete r by :func:`bind`, which keeps the symbolic forms short and lets the
tests check them with ``simplify``.

Why the envelope is solved in the pitch curve's own frame: solving F = 0,
dF/dtheta = 0 directly for (X, Y) returns sqrt(P^2) = |P| (P = r sin theta -
r' cos theta) and divides by P, so its two roots swap walls wherever P changes
sign.  Writing the unknown point as p + a t + b m, with t the pitch tangent and m
the tangent turned by -90 degrees (a valid coordinate change wherever t != 0),
turns the system into (a^2 + b^2)|t|^2 = r_r^2, a |t|^2 = 0, whose roots
a = 0, b = -/+ r_r/|t| are the inner and the outer wall for every theta.

Sign conventions.  Curvature is signed for the parametrization in increasing
theta (counter-clockwise): positive where the pitch curve is convex (bulges away
from the cam centre), negative where it is concave.  Radii of curvature are the
reciprocals, signed the same way.  The inner wall is the pitch curve offset by
-r_r along the outward normal, the outer wall by +r_r.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cache, cached_property

import numpy as np
import sympy as sp

from camdyn.derive import camlaws, symbolic

theta = sp.Symbol("theta", real=True)
"""Cam parameter: polar angle of the pitch-curve point in the cam frame (paper (4))."""

X, Y = sp.symbols("X Y", real=True)
"""Cam-frame coordinates of a point of the roller circle (paper (2))."""

S_T, r_b, r_r = sp.symbols("S_T r_b r_r", positive=True)
"""Total lift, base-circle radius, roller radius (paper (1), (3))."""

r = sp.Function("r", positive=True)(theta)
"""Generic pitch radius r(theta) = r_b + r_r + S(theta); bind it with :func:`bind`."""

PAPER = {"S_T": 0.015, "r_b": 0.026, "r_r": 0.005}
"""Paper data (sec. 4), m."""

SIDES = ("inner", "outer")

_jet = sp.symbols("r0:4", real=True)  # r, r', r'', r''' as plain symbols for lambdify


# -- motion, paper (1) -----------------------------------------------------------

def law_pieces(law="cycloidal") -> tuple:
    """The normalized rise H(T), T in [0, 1], as pieces ``(H_k(T), T_k)``, T_k the right end.

    ``law`` is a name of the cam-law library (``"cycloidal"``, ``"modified-sine"``,
    ...), a :class:`camlaws.CamLaw`, a pair ``(name, parameter)`` for a law with a
    shape parameter, or a SymPy expression in ``camlaws.T`` with H(0) = 0, H(1) = 1.
    The parameter is made exact (0.1 -> 1/10) so continuity checks stay exact.
    """
    value = None
    if isinstance(law, tuple):
        law, value = law
    if isinstance(law, str):
        law = camlaws.get(law)
    if isinstance(law, camlaws.CamLaw):
        subs = {}
        if law.parameter is not None:
            v = law.parameter.default if value is None else law.parameter.check(value, law.key)
            subs = {law.parameter.symbol: sp.Rational(repr(float(v)))}
        elif value is not None:
            raise ValueError(f"the {law.key} law has no shape parameter; drop {value!r}")
        return tuple((h.subs(subs), sp.sympify(hi).subs(subs))
                     for h, hi in zip(law.rise, law.bounds[1:]))
    H = sp.sympify(law)
    if not H.free_symbols <= {camlaws.T}:
        raise ValueError(f"a rise law must be an expression in T only, got {H}")
    for at, want in ((0, 0), (1, 1)):
        got = complex(H.subs(camlaws.T, at))
        if abs(got - want) > 1e-12:
            raise ValueError(f"a rise law needs H({at}) = {want}, got {got}")
    return ((H, sp.Integer(1)),)


@dataclass(frozen=True)
class Segment:
    """One piece of S(theta): ``name`` is rise, outer dwell, fall or inner dwell."""

    name: str
    lo: sp.Expr
    hi: sp.Expr
    S: sp.Expr


def rdfd_segments(S_T=S_T, rise_law="cycloidal", fall_law=None, *,
                  beta_rise=sp.pi / 2, dwell_outer=sp.pi / 2, beta_fall=sp.pi / 2) -> tuple:
    """RDFD displacement pieces over one revolution, paper (1) and fig. 2.

    Rise S_T H_rise(theta/beta_rise) on [0, beta_rise], outer dwell S_T, fall
    S_T (1 - H_fall(T)) (paper: "subtract the rise displacement from S_T"), inner
    dwell 0 up to 2 pi.  ``fall_law`` defaults to the rise law.  A law with several
    pieces (e.g. modified sine) gives several rise or fall segments.
    """
    fall_law = rise_law if fall_law is None else fall_law
    beta_rise, dwell_outer, beta_fall = map(sp.sympify, (beta_rise, dwell_outer, beta_fall))
    fall_start = beta_rise + dwell_outer
    fall_end = fall_start + beta_fall
    inner = 2 * sp.pi - fall_end
    for name, length in (("beta_rise", beta_rise), ("dwell_outer", dwell_outer),
                         ("beta_fall", beta_fall), ("inner dwell", inner)):
        # no inner dwell (fall straight into the rise) is allowed; no empty rise, dwell, fall
        short = length < 0 if name == "inner dwell" else length <= 0
        if length.is_number and bool(short):
            raise ValueError(f"{name} = {float(length):g} rad: rise, outer dwell and fall "
                             "must be positive and fit in one revolution")
    T = camlaws.T
    segs, lo = [], sp.Integer(0)
    for H, hi in law_pieces(rise_law):
        segs.append(Segment("rise", lo, beta_rise * hi, S_T * H.subs(T, theta / beta_rise)))
        lo = beta_rise * hi
    segs.append(Segment("outer dwell", beta_rise, fall_start, S_T))
    lo = fall_start
    for H, hi in law_pieces(fall_law):
        shape = H.subs(T, (theta - fall_start) / beta_fall)
        segs.append(Segment("fall", lo, fall_start + beta_fall * hi, S_T * (1 - shape)))
        lo = fall_start + beta_fall * hi
    if not (inner.is_number and inner == 0):
        segs.append(Segment("inner dwell", fall_end, 2 * sp.pi, sp.Integer(0)))
    return tuple(segs)


def displacement(segments, order: int = 0) -> sp.Piecewise:
    """d^order S / dtheta^order as one Piecewise on [0, 2 pi] (0 before theta = 0).

    Conditions are ``theta < hi``, so a breakpoint belongs to the segment starting
    there; beyond 2 pi the last segment continues (wrap theta first for that).
    """
    pieces = [(sp.Integer(0), theta < 0)]
    pieces += [(sp.diff(s.S, theta, order), theta < s.hi) for s in segments[:-1]]
    pieces.append((sp.diff(segments[-1].S, theta, order), True))
    return sp.Piecewise(*pieces)


def rdfd_displacement(S_T=S_T, rise_law="cycloidal", fall_law=None, *, order: int = 0,
                      **angles) -> sp.Piecewise:
    """S(theta) (or its derivative of ``order``) of the RDFD motion, paper (1)."""
    return displacement(rdfd_segments(S_T, rise_law, fall_law, **angles), order)


def pitch_radius(S, r_b=r_b, r_r=r_r):
    """r = r_b + r_r + S (paper (3))."""
    return r_b + r_r + S


def bind(expr, r_expr):
    """Replace the generic r(theta) and its derivatives in ``expr`` by ``r_expr``."""
    orders = [d.derivative_count for d in expr.atoms(sp.Derivative) if d.expr == r]
    table = {sp.Derivative(r, (theta, k)): sp.diff(r_expr, theta, k)
             for k in range(1, max(orders, default=0) + 1)}
    table[r] = r_expr
    return expr.xreplace(table)  # top-down: derivatives are matched whole before r


def _to_jet(expr):
    """r, r', r'', r''' -> plain symbols r0..r3, for lambdify."""
    table = {sp.Derivative(r, (theta, k)): _jet[k] for k in range(1, 4)}
    table[r] = _jet[0]
    return expr.xreplace(table)


# -- pitch curve and the envelope, paper (2)-(4) -----------------------------------

def pitch_curve() -> sp.Matrix:
    """Roller-centre path in the cam frame, r (cos theta, sin theta) (paper (4))."""
    return sp.Matrix([r * sp.cos(theta), r * sp.sin(theta)])


def roller_family() -> sp.Expr:
    """The family of roller circles F(X, Y, theta) = |(X, Y) - p(theta)|^2 - r_r^2."""
    p = pitch_curve()
    return (X - p[0]) ** 2 + (Y - p[1]) ** 2 - r_r ** 2


def envelope_condition() -> sp.Expr:
    """dF/dtheta at fixed (X, Y): with F = 0 it defines the envelope (paper (2))."""
    return sp.diff(roller_family(), theta)


def groove_walls() -> dict:
    """The two envelope branches of the roller circles: the inner and the outer wall.

    Returns ``{"inner": Matrix([X, Y]), "outer": ...}`` in terms of r(theta), r'(theta)
    and r_r; the result equals p -/+ r_r (Q, P)/sqrt(r^2 + r'^2) with P, Q of paper (3).
    """
    return dict(_groove_walls())


@cache
def _groove_walls() -> dict:
    """Derivation behind :func:`groove_walls`.

    Solves F = 0, dF/dtheta = 0 (paper (2)) for the point p + a t + b m in the
    pitch curve's tangent frame (see the module docstring for why not in X, Y
    directly) and sorts the roots by the sign of b: b < 0 lies towards the cam
    centre (inner wall), b > 0 away from it (outer wall).
    """
    p = pitch_curve()
    t = p.diff(theta)
    m = sp.Matrix([t[1], -t[0]])
    a, b = sp.symbols("a b", real=True)
    point = p + a * t + b * m
    on = {X: point[0], Y: point[1]}
    eqs = [symbolic.trigsimp(sp.expand(e.xreplace(on))) for e in (roller_family(), envelope_condition())]
    roots = sp.solve(eqs, [a, b], dict=True)
    if len(roots) != 2 or any(sol[a] != 0 for sol in roots):
        raise RuntimeError(f"unexpected envelope roots {roots}")
    # sign of b at a sample state (r = 1, r' = 0, r_r = 1); the roots are -/+ r_r/|t|
    probe = {sp.Derivative(r, theta): 0, r: 1, r_r: 1}
    walls = {}
    for sol in roots:
        side = "inner" if float(sol[b].xreplace(probe)) < 0 else "outer"
        walls[side] = p + sol[b] * m
    return walls


@cache
def outward_normal() -> sp.Matrix:
    """Unit common normal of the roller and both walls, pointing away from the cam centre.

    Taken from the derived envelope itself, (outer wall - p)/r_r, not from a
    formula for the normal.
    """
    return symbolic.simplify((groove_walls()["outer"] - pitch_curve()) / r_r)


def _cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


@cache
def tan_pressure_angle() -> sp.Expr:
    """tan phi, phi the angle from the follower axis (radial) to the common normal.

    Signed so that phi > 0 while the follower rises (the normal leans back against
    increasing theta); simplifies to r'/r = S'/r for the radial follower.
    """
    n = outward_normal()
    e_r = sp.Matrix([sp.cos(theta), sp.sin(theta)])
    return symbolic.simplify(_cross(n, e_r) / n.dot(e_r))


@cache
def pressure_angle() -> sp.Expr:
    """phi = atan2(n x e_r, n . e_r), see :func:`tan_pressure_angle`."""
    n = outward_normal()
    e_r = sp.Matrix([sp.cos(theta), sp.sin(theta)])
    return sp.atan2(symbolic.simplify(_cross(n, e_r)), symbolic.simplify(n.dot(e_r)))


def signed_curvature(curve: sp.Matrix) -> sp.Expr:
    """kappa = (x' y'' - y' x'') / (x'^2 + y'^2)^(3/2) of a curve parametrized by theta."""
    d1, d2 = curve.diff(theta), curve.diff(theta, 2)
    return _cross(d1, d2) / (d1.dot(d1)) ** sp.Rational(3, 2)


@cache
def pitch_curvature() -> sp.Expr:
    """Signed curvature of the pitch curve, from :func:`signed_curvature` (simplified)."""
    return symbolic.simplify(signed_curvature(pitch_curve()))


@cache
def wall_curvature(side: str) -> sp.Expr:
    """Signed curvature of a groove wall from its derived parametrization.

    Left unsimplified (its r''' terms cancel, but simplify is slow); for the
    offset by d = -/+ r_r it equals kappa_p / |1 + d kappa_p|, so the wall's radius
    of curvature is rho_p -/+ r_r wherever the wall is not undercut (the undercut test on
    the pitch curve's curvature is :mod:`camdyn.runtime.cam.motion`, in NumPy).
    """
    return signed_curvature(groove_walls()[_side(side)])


def _side(side):
    if side not in SIDES:
        raise ValueError(f"side must be 'inner' or 'outer', got {side!r}")
    return side


# -- numbers -----------------------------------------------------------------------

@cache
def _compiled(name, side=None):
    """The generic expressions as NumPy functions of (theta, r, r', r'', r''', r_r)."""
    expr = {"pitch": lambda: pitch_curve(),
            "wall": lambda: groove_walls()[side],
            "normal": lambda: outward_normal(),
            "phi": lambda: pressure_angle(),
            "kappa_p": lambda: pitch_curvature(),
            "kappa_w": lambda: wall_curvature(side)}[name]()
    expr = _to_jet(expr)
    if isinstance(expr, sp.MatrixBase):
        expr = list(expr)  # a list lambdifies to a list, whatever the shapes of its entries
    return sp.lambdify((theta, *_jet, r_r), expr, "numpy", cse=True)


@dataclass(frozen=True)
class CamGeometry:
    """A numerical cam design: the symbolic geometry evaluated on theta grids (SI units).

    Laws as in :func:`law_pieces`; angles as in :func:`rdfd_segments`.  Every method
    takes theta in rad (any real, wrapped to [0, 2 pi)) and returns arrays.
    """

    S_T: float = PAPER["S_T"]
    r_b: float = PAPER["r_b"]
    r_r: float = PAPER["r_r"]
    rise_law: object = "cycloidal"
    fall_law: object = None
    beta_rise: object = sp.pi / 2
    dwell_outer: object = sp.pi / 2
    beta_fall: object = sp.pi / 2

    def __post_init__(self):
        for name in ("S_T", "r_b", "r_r"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and np.isfinite(value) and value > 0):
                raise ValueError(f"{name} must be a positive length in m, got {value!r}")

    @cached_property
    def segments(self) -> tuple:
        return rdfd_segments(sp.Float(self.S_T), self.rise_law, self.fall_law,
                             beta_rise=self.beta_rise, dwell_outer=self.dwell_outer,
                             beta_fall=self.beta_fall)

    @cached_property
    def breakpoints(self) -> np.ndarray:
        """Segment ends in rad, 0 ... 2 pi."""
        ends = {float(s.lo) for s in self.segments} | {float(s.hi) for s in self.segments}
        return np.array(sorted(ends))

    @cached_property
    def _S(self):
        return [sp.lambdify(theta, displacement(self.segments, k), "numpy") for k in range(4)]

    def displacement(self, th, order: int = 0) -> np.ndarray:
        """d^order S / dtheta^order, order 0..3."""
        th = np.mod(np.asarray(th, dtype=float), 2 * np.pi)
        return np.broadcast_to(self._S[order](th), th.shape) * 1.0

    def _args(self, th):
        th = np.mod(np.asarray(th, dtype=float), 2 * np.pi)
        S = [self.displacement(th, k) for k in range(4)]
        return th, S[0] + self.r_b + self.r_r, S[1], S[2], S[3], self.r_r

    def _vector(self, name, th, side=None):
        args = self._args(th)
        x, y = _compiled(name, side)(*args)
        return np.array([np.broadcast_to(x, args[0].shape), np.broadcast_to(y, args[0].shape)],
                        dtype=float)

    def radius(self, th) -> np.ndarray:
        """Pitch radius r(theta) (paper (3))."""
        return self._args(th)[1]

    def pitch(self, th) -> np.ndarray:
        """Pitch-curve points, shape (2, n) (paper (4))."""
        return self._vector("pitch", th)

    def wall(self, th, side: str) -> np.ndarray:
        """Points of the inner or outer groove wall, shape (2, n) (paper (2))."""
        return self._vector("wall", th, _side(side))

    def normal(self, th) -> np.ndarray:
        """Unit common normal pointing away from the cam centre, shape (2, n)."""
        return self._vector("normal", th)

    def pressure_angle(self, th) -> np.ndarray:
        """Pressure angle phi in rad, > 0 during the rise."""
        args = self._args(th)
        return np.broadcast_to(_compiled("phi")(*args), args[0].shape) * 1.0

    def pitch_curvature(self, th) -> np.ndarray:
        args = self._args(th)
        return np.broadcast_to(_compiled("kappa_p")(*args), args[0].shape) * 1.0

    def wall_curvature(self, th, side: str) -> np.ndarray:
        args = self._args(th)
        return np.broadcast_to(_compiled("kappa_w", _side(side))(*args), args[0].shape) * 1.0

    def pitch_radius_of_curvature(self, th) -> np.ndarray:
        """Signed rho_p = 1/kappa_p (inf at an inflection)."""
        with np.errstate(divide="ignore"):
            return 1.0 / self.pitch_curvature(th)

    def wall_radius_of_curvature(self, th, side: str) -> np.ndarray:
        """Signed radius of curvature of a wall, from its own parametrization."""
        with np.errstate(divide="ignore"):
            return 1.0 / self.wall_curvature(th, side)

    def sample(self, n: int = 721) -> dict:
        """Everything on an even grid of n points over [0, 2 pi]."""
        th = np.linspace(0.0, 2 * np.pi, n)
        return {"theta": th, "S": self.displacement(th), "r": self.radius(th),
                "pitch": self.pitch(th), "inner": self.wall(th, "inner"),
                "outer": self.wall(th, "outer"), "pressure_angle": self.pressure_angle(th),
                "rho_pitch": self.pitch_radius_of_curvature(th),
                "rho_inner": self.wall_radius_of_curvature(th, "inner"),
                "rho_outer": self.wall_radius_of_curvature(th, "outer")}
