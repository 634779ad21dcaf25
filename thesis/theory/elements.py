"""Element energies of thesis sec. 2.2.2 with the thesis's displacement functions.

Each component of a mechanism is described by the displacements of its two
nodal points, x_j and x_{j+1}.  Its displacement field is a rigid-body
displacement plus an elastic one that is taken equal to the *static*
deflection under forces at the nodes (2.2): "the dynamic displacement will
conform to the elastic displacement".  The energies below are not typed in:
every constructor writes down the field and integrates over the element
length with :func:`sympy.integrate`,

    V = 1/2 (stiffness) * integral of (strain measure)^2 dz     (2.5), (2.11), (2.21)
    T = 1/2 (mass per length) * integral of (field rate)^2 dz   (2.7), (2.13), (2.23)

so that what the thesis prints, (2.6), (2.22), the coefficients of (2.32),
(2.33), (2.39) and of the matrices (2.40), can be compared with the result
(thesis/checks/elements_checks.py).

Every element also fits the generic forms (2.25)-(2.26),

    V = 1/2 c (x_{j+1} - x_j)^2,
    T = 1/2 m (a1 x_j'^2 + a2 x_j' x_{j+1}' + a3 x_{j+1}'^2),

where x_j is the displacement that the *rigid* motion of the first node
produces at the second node's radius (for a shaft or lever with transmission
i, x_j = i times the first node's coordinate: that is what "i is introduced for
greater ease of coupling" after (2.9) is for).  :func:`generic_form` reads c
and a1..a3 back out of an element.

Rigid kinetic energy (sec. 2.2.2.2): with ``kinetic="rigid"`` the kinetic
energy is integrated over the rigid-body field that carries the second node's
displacement, while V keeps the elastic field; this is (2.41)-(2.44) and
leaves a mass matrix without dynamic coupling.

Contents: the uniform components :func:`bar`, :func:`shaft`, :func:`beam`
and the roller lever :func:`overhung_lever` (component 4 of fig. 2.4); the
discrete :func:`lumped_mass`, :func:`spring`, :func:`torsion_spring` and the
rigid :class:`Lever` (2.51); the generic forms :func:`generic`,
:func:`generic_form`, Lagrange's equations (2.27)-(2.29)
:func:`lagrange_equations`; the accuracy test of sec. 2.2.2.1
:func:`clamped_beam_omega_squared`.

Symbols: node coordinates are plain real symbols, their rates are
``rate(x)`` (name + "d") and accelerations ``accel(x)`` (name + "dd"),
following the project's H, Hd, Hdd convention.  Stiffness products are single
parameters, as the thesis writes them: EA, EI, GIp.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp

z = sp.Symbol("z", nonnegative=True)
"""Position along an element, 0 at the first node (A), l at the second (B)."""

_u = sp.Symbol("u", nonnegative=True)     # dummy integration variable
_F = sp.Symbol("F", real=True)            # nodal force while solving for a static deflection


def rate(x: sp.Symbol) -> sp.Symbol:
    """The velocity symbol x' of a node coordinate x."""
    return sp.Symbol(x.name + "d", real=True)


def accel(x: sp.Symbol) -> sp.Symbol:
    """The acceleration symbol x'' of a node coordinate x."""
    return sp.Symbol(x.name + "dd", real=True)


def _rates(field: sp.Expr, nodes) -> sp.Expr:
    # the fields are linear in the node coordinates with z-dependent shape
    # functions, so the time derivative just swaps each node for its rate
    # (a node given as a number, e.g. 0 for a clamp, does not move)
    return field.xreplace({x: rate(x) for x in _symbols(nodes)})


def _symbols(nodes) -> tuple:
    return tuple(x for x in nodes if isinstance(x, sp.Symbol))


def _integral(expr, lo, hi) -> sp.Expr:
    return sp.integrate(sp.expand(expr), (z, lo, hi))


@dataclass(frozen=True)
class Element:
    """One component: its energies in terms of its node coordinates.

    ``nodes`` are the coordinate symbols (x_j, x_{j+1}) (a lumped mass has
    one); ``generic`` are the displacements (x_j, x_{j+1}) of the generic
    forms (2.25)-(2.26) as expressions in the nodes (e.g. (i h, x4) for the
    roller lever of fig. 2.4); ``field`` is the displacement function (rigid
    plus elastic part) that V was integrated from, and T too unless the rigid
    kinetic energy was asked for (None for discrete elements).
    """

    name: str
    reference: str
    nodes: tuple
    T: sp.Expr
    V: sp.Expr
    generic: tuple = ()
    field: sp.Expr | None = None

    @property
    def rates(self) -> tuple:
        return tuple(rate(x) for x in self.nodes)

    def mass_matrix(self) -> sp.Matrix:
        """Hessian of T in the node rates (T = 1/2 x'^T M x')."""
        return sp.hessian(self.T, self.rates).applyfunc(sp.simplify)

    def stiffness_matrix(self) -> sp.Matrix:
        """Hessian of V in the node coordinates (V = 1/2 x^T C x)."""
        return sp.hessian(self.V, self.nodes).applyfunc(sp.simplify)


# -- uniform components, energies integrated from the displacement functions --------------

def bar(x1, x2, EA, l, m, kinetic: str = "elastic") -> Element:
    """Longitudinally moving bar, fig. 2.6, (2.3)-(2.8).

    Field: rigid displacement x1 (2.3) plus the elastic stretch under end
    forces, linear in z, (x2 - x1) z/l (2.4).  V from (2.5) gives (2.6),
    V = EA/(2l) (x2 - x1)^2; T from (2.7) with the mass m spread uniformly.
    (2.8) is lost in the scan; the equations (2.32)-(2.33), 1/2 m5 (2/3 x4'' +
    1/3 x5'') ..., show its coefficients: a1 = a2 = a3 = 1/3.
    Rigid kinetic energy: the whole bar moves with x2, T = 1/2 m x2'^2 (2.42).
    """
    x_r = x1 + 0 * z                              # (2.3)
    x_e = (x2 - x1) * z / l                       # (2.4)
    field = x_r + x_e
    V = EA / 2 * _integral(sp.diff(x_e, z) ** 2, 0, l)          # (2.5)
    moving = field if kinetic == "elastic" else x2 + 0 * z
    T = m / l / 2 * _integral(_rates(moving, (x1, x2)) ** 2, 0, l)   # (2.7)
    return Element("bar", "(2.3)-(2.8)" if kinetic == "elastic" else "(2.42)",
                   _symbols((x1, x2)), sp.expand(T), sp.factor(V), (x1, x2), field)


def shaft(x1, x2, GIp, l, J, r2, i=1, kinetic: str = "elastic") -> Element:
    """Rotating shaft, fig. 2.7, (2.9)-(2.14), node displacements at two radii.

    Nodes: x1 = phi1 r1 and x2 = phi2 r2, the rotations of the shaft ends
    expressed as displacements at radii r1 and r2 = i r1 (in fig. 2.4: psi6 l6
    and psi7 l8, i2 = l8/l6).  Field, measured at r2: rigid rotation
    phi1 r2 = i x1 (2.9) plus a twist linear in z, (x2 - i x1) z/l (2.10).
    V = GIp/2 integral (dphi/dz)^2 dz (2.11); T = 1/2 J/(l r2^2) integral
    (phi' r2)^2 dz (2.13), J the polar mass moment of inertia of the shaft.
    (2.12) and (2.14) are lost in the scan; by the analogy with (2.6), (2.8)
    the text states they are
        V = GIp/(2 l r2^2) (x2 - i x1)^2,
        T = 1/2 J/r2^2 (1/3 i^2 x1'^2 + 1/3 i x1' x2' + 1/3 x2'^2),
    which are the entries of (2.40) at psi6 l6, psi7 l8 (i2^2 (GIp)7/(l8^2 l7),
    i2^2 J7/(3 l8^2), i2 J7/(6 l8^2), J7/(3 l8^2)).
    Rigid kinetic energy: the shaft turns with phi2, T = 1/2 J/r2^2 (phi2' r2)^2 (2.43).
    """
    phi_r_r2 = i * x1 + 0 * z                     # (2.9), at radius r2
    phi_e_r2 = (x2 - i * x1) * z / l              # (2.10)
    field = phi_r_r2 + phi_e_r2                   # phi(z) r2
    V = GIp / 2 * _integral(sp.diff(field / r2, z) ** 2, 0, l)        # (2.11)
    moving = field if kinetic == "elastic" else x2 + 0 * z
    T = J / (l * r2**2) / 2 * _integral(_rates(moving, (x1, x2)) ** 2, 0, l)   # (2.13)
    return Element("shaft", "(2.9)-(2.14)" if kinetic == "elastic" else "(2.43)",
                   _symbols((x1, x2)), sp.expand(T), sp.factor(V), (i * x1, x2), field)


def cantilever_deflection(x1, x2, EI, l) -> tuple[sp.Expr, sp.Expr]:
    """Static deflection of a beam clamped at A under an end force F at B, (2.17)-(2.20).

    Returns (x_e(z), F).  Bending moment at section z from the end force is
    F (l - z) (equal to the thesis's M - F z with the clamp moment M = F l),
    so x_e'' = F (l - z)/EI (2.17), integrated twice from x_e = x_e' = 0 at
    z = 0 (2.18); the deflection at B is the elastic part x2 - x1, which
    fixes F = 3 EI (x2 - x1)/l^3 (2.19) and
    x_e = 3 (x2 - x1)/(2 l^3) (l z^2 - z^3/3) (2.20).
    Reading of (2.20): the scan shows "3 (x2 - x1)/(2 l^3) ( . l z^2 - . z^3)";
    the derived form above is the one consistent with (2.19).
    """
    curvature = _F * (l - _u) / EI                                 # (2.17)
    slope = sp.integrate(curvature, (_u, 0, z)).subs(z, _u)        # x_e'(0) = 0
    deflection = sp.integrate(slope, (_u, 0, z))                    # x_e(0) = 0
    F = sp.solve(sp.Eq(deflection.subs(z, l), x2 - x1), _F)[0]     # (2.19)
    return sp.factor(deflection.subs(_F, F)), sp.factor(F)


def beam(x1, x2, EI, l, m, kinetic: str = "elastic") -> Element:
    """Transversely moving beam pivoting about A, fig. 2.8, (2.16)-(2.24).

    Nodes: x1 is the displacement of B that the rigid rotation about A
    produces (the rotation at A times l; in fig. 2.4 psi6 l6 or psi7 l8), x2
    the actual displacement of B.  Field: rigid x1 z/l (2.16) plus the
    cantilever deflection under an end force (2.20), see
    :func:`cantilever_deflection`.  V = EI/2 integral (x_e'')^2 dz (2.21)
    gives (2.22), V = 3 EI/(2 l^3) (x2 - x1)^2.  T = 1/2 m/l integral x'^2 dz
    (2.23) gives
        T = 1/2 m (2/105 x1'^2 + 11/140 x1' x2' + 33/140 x2'^2);
    (2.24) itself is lost in the scan, its coefficients are readable in
    (2.39) (11/140, 33/70) and in the mass matrix (2.40) (2/105, 11/280, 33/140).
    Rigid kinetic energy: the beam turns about A as a rigid body carrying B's
    displacement, x = x2 z/l, T = 1/2 (1/3 m) x2'^2 (2.44).
    """
    x_r = x1 * z / l                                               # (2.16)
    x_e, _ = cantilever_deflection(x1, x2, EI, l)                  # (2.20)
    field = x_r + x_e
    V = EI / 2 * _integral(sp.diff(x_e, z, 2) ** 2, 0, l)          # (2.21)
    moving = field if kinetic == "elastic" else x2 * z / l
    T = m / l / 2 * _integral(_rates(moving, (x1, x2)) ** 2, 0, l)   # (2.23)
    return Element("beam", "(2.16)-(2.24)" if kinetic == "elastic" else "(2.44)",
                   _symbols((x1, x2)), sp.expand(T), sp.factor(V), (x1, x2), field)


@lru_cache(maxsize=None)  # half a second of algebra; fig. 2.4 and the checks ask for it repeatedly
def overhung_lever(h, x, EI, a, i, m, kinetic: str = "elastic") -> Element:
    """The roller lever (component 4 of fig. 2.4) as a flexible beam, (2.30)-(2.31).

    Geometry read from fig. 2.9 and the printed c4: a uniform lever of
    length b = i a and mass m, pivoted at its end (z = 0), the cam roller at
    z = a (input h), the output node x at z = b, i = b/a (2.51).  Field:
    rigid rotation h/a, i.e. (i h) z/b, plus the static deflection under an
    end force F at b with the pivot and the roller held (a beam on two
    supports with an overhang b - a).  This is "the method of (2.22)" for c4
    and "the method of (2.24)" for a14, a24, a34.  Integrating gives
        V = 1/2 c4 (x - i h)^2,  c4 = 3 EI/(a^3 i (i - 1)^2)   (as printed after (2.31)),
    and coefficients a14, a24, a34 that depend on i only (the printed values
    after "from which it appears that" are lost in the scan); their sum is
    1/3, the rigid lever of (2.45).
    Generic displacements (2.25): x_j = i h, x_{j+1} = x, which makes the
    component's equations (2.28)-(2.29) the printed (2.30)
    1/2 m4 (2 a14 i1^2 h'' + a24 i1 x4'') - c4 (i1 x4 - i1^2 h) = Qh.
    """
    # worked in zeta = z/a (roller at zeta = 1, output at zeta = i): the shape
    # functions are then polynomials in zeta with coefficients rational in i only,
    # which keeps the integrals small (in z the same algebra takes a minute)
    zeta, s_ = sp.Symbol("zeta", nonnegative=True), sp.Symbol("s", nonnegative=True)
    # curvature d2w/dzeta2 = a^2 M/EI of a unit end force: M = (b - a) z/a between
    # the supports, M = b - z on the overhang
    k1 = a**2 * a * (i - 1) * s_ / EI
    k2 = a**2 * a * (i - s_) / EI
    # w(0) = w'(0) = 0, then the rotation about the pivot that puts the roller back at w(1) = 0
    w1 = sp.integrate(sp.integrate(k1, (s_, 0, s_)), (s_, 0, zeta))
    w1 = w1 - w1.subs(zeta, 1) * zeta
    w2 = (w1.subs(zeta, 1) + sp.diff(w1, zeta).subs(zeta, 1) * (zeta - 1)
          + sp.integrate(sp.integrate(k2, (s_, 1, s_)), (s_, 1, zeta)))
    compliance = sp.cancel(w2.subs(zeta, i))          # deflection at b per unit force
    phi1, phi2 = (sp.Poly(sp.cancel(w / compliance), zeta) for w in (w1, w2))
    stretch = x - i * h                               # elastic displacement at b
    dd = lambda p: p.diff(zeta).diff(zeta)            # noqa: E731
    V = EI / (2 * a**3) * (dd(phi1) ** 2).integrate().as_expr().subs(zeta, 1)
    V += EI / (2 * a**3) * ((dd(phi2) ** 2).integrate().as_expr().subs(zeta, i)
                            - (dd(phi2) ** 2).integrate().as_expr().subs(zeta, 1))
    V = sp.factor(V) * stretch**2
    # rigid rotation h/a: (i h) z/b = h zeta
    zp = sp.Poly(zeta, zeta)
    if kinetic == "elastic":
        pieces = (((zp - i * phi1), phi1, 0, 1), ((zp - i * phi2), phi2, 1, i))
    else:
        pieces = ((sp.Poly(0, zeta), sp.Poly(zeta / i, zeta), 0, i),)
    hd, xd = rate(h), rate(x)
    coeff = {}
    for key, (f, g) in {"hh": (0, 0), "hx": (0, 1), "xx": (1, 1)}.items():
        total = 0
        for piece in pieces:
            P = (piece[f] * piece[g]).integrate()
            total += P.as_expr().subs(zeta, piece[3]) - P.as_expr().subs(zeta, piece[2])
        coeff[key] = sp.factor(sp.cancel(total))
    # T = 1/2 (m/b) integral over z = 1/2 (m/i) integral over zeta
    T = m / (2 * i) * (coeff["hh"] * hd**2 + 2 * coeff["hx"] * hd * xd + coeff["xx"] * xd**2)
    w1 = phi1.as_expr().subs(zeta, z / a) * stretch
    w2 = phi2.as_expr().subs(zeta, z / a) * stretch
    x_r = h * z / a
    field = sp.Piecewise((x_r + w1, z <= a), (x_r + w2, True))
    return Element("lever", "(2.30)-(2.31)" if kinetic == "elastic" else "(2.41), (2.45)",
                   _symbols((h, x)), T, V, (i * h, x), field)


# -- discrete elements -------------------------------------------------------------------

def lumped_mass(x, m) -> Element:
    """A rigid mass at a node: T = 1/2 m x'^2 (the end mass m2 of fig. 2.10)."""
    return Element("mass", "sec. 2.2.2.1", (x,), m * rate(x) ** 2 / 2, sp.Integer(0))


def spring(x1, x2, c) -> Element:
    """A massless linear spring, V = 1/2 c (x2 - x1)^2 (2.25) with m = 0.

    ``x1`` may be an expression (x_{i-1} + h_i in the chain of fig. 2.12), or
    0 for a spring to the frame (the follower spring c_g, (2.38)-(2.39)).
    """
    nodes = tuple(sorted(sp.sympify(x2 - x1).free_symbols, key=str))
    return Element("spring", "(2.25)", nodes, sp.Integer(0), c * (x2 - x1) ** 2 / 2, (x1, x2))


def torsion_spring(x1, x2, k, r2, i=1) -> Element:
    """A massless torsion spring k (torque per radian) between two shaft ends.

    Nodes as for :func:`shaft`: x1 = phi1 r1, x2 = phi2 r2 = phi2 i r1, so
    V = 1/2 k (phi2 - phi1)^2 = 1/2 (k/r2^2) (x2 - i x1)^2: seen at radius r2
    the stiffness is k/r2^2 (the massless shaft of (2.12)).
    """
    phi1, phi2 = i * x1 / r2, x2 / r2
    return Element("torsion spring", "(2.12)", (x1, x2), sp.Integer(0),
                   sp.factor(k * (phi2 - phi1) ** 2 / 2), (i * x1, x2))


@dataclass(frozen=True)
class Lever:
    """A rigid massless lever with arms a (input) and b (output), fig. 2.13.

    The linearised transmission ratio (2.51) is i = h_out/h_in = b/a: both
    ends turn through the same small angle, so their strokes are in the ratio
    of the arm lengths.  A lever is a constraint, not an energy: it maps the
    input displacement to the output one.
    """

    a: sp.Expr
    b: sp.Expr

    @property
    def i(self) -> sp.Expr:
        return self.b / self.a                                          # (2.51)

    def output(self, x_in: sp.Expr) -> sp.Expr:
        return self.i * x_in

    def input_force(self, F_out: sp.Expr) -> sp.Expr:
        """Force at the input that balances F_out at the output (virtual work)."""
        return self.i * F_out


# -- the generic forms (2.25)-(2.29) -----------------------------------------------------

xj, xj1 = sp.symbols("xj xj1", real=True)
m_, c_ = sp.symbols("m c", positive=True)
a1, a2, a3 = sp.symbols("a1 a2 a3", real=True)


def generic(x_j=xj, x_j1=xj1, m=m_, c=c_, coeffs=(a1, a2, a3)) -> Element:
    """The generic component (2.25)-(2.26) as the thesis states it (not integrated)."""
    A1, A2, A3 = coeffs
    T = m / 2 * (A1 * rate(x_j) ** 2 + A2 * rate(x_j) * rate(x_j1) + A3 * rate(x_j1) ** 2)
    V = c / 2 * (x_j1 - x_j) ** 2
    return Element("generic", "(2.25)-(2.26)", (x_j, x_j1), T, V, (x_j, x_j1))


def generic_form(element: Element, m) -> tuple[sp.Expr, sp.Expr, sp.Expr, sp.Expr]:
    """(c, a1, a2, a3) of an element written in the generic forms (2.25)-(2.26).

    x_j is element.generic[0] = k n1 for the first node n1, so n1' = x_j'/k;
    raises ValueError when V is not 1/2 c (x_{j+1} - x_j)^2.
    """
    n1, n2 = element.nodes
    gj, gj1 = element.generic
    k = sp.simplify(gj / n1)
    c = sp.simplify(2 * element.V / (gj1 - gj) ** 2)
    if c.free_symbols & set(element.nodes):
        raise ValueError(f"{element.name}: V is not of the form (2.25)")
    H = sp.hessian(element.T, element.rates)
    a = (sp.factor(H[0, 0] / (k**2 * m)), sp.factor(2 * H[0, 1] / (k * m)),
         sp.factor(H[1, 1] / m))
    return (c, *a)


def lagrange_equations(T, V, nodes, name: str = "element") -> list[sp.Expr]:
    """Left-hand sides of Lagrange's equation (2.27) for each node coordinate.

    d/dt dT/dx_k' - dT/dx_k + dV/dx_k = Q_k: the returned expressions equal
    the generalized forces Q_k.  Derived with the project's own
    :func:`camdyn.derive.lagrange.derive`, in plain symbols (x, rate(x),
    accel(x)) on return.
    """
    from camdyn.derive.lagrange import derive
    from camdyn.derive.model import Coordinate, Model, time

    t = time("t_")
    coords = tuple(Coordinate(x.name, "m", "node coordinate") for x in nodes)
    q = [cc(t) for cc in coords]
    to_fun = {}
    for x, qq in zip(nodes, q):
        to_fun[rate(x)] = qq.diff(t)
        to_fun[x] = qq
    model = Model(name=name.replace(" ", "_"), title=name, reference="(2.27)", doc="",
                  time=t, time_unit="s", coordinates=coords,
                  kinetic=T.xreplace(to_fun), potential=V.xreplace(to_fun),
                  parameters=(), outputs=())
    eq = derive(model)
    back = {}
    for x, qq in zip(nodes, q):
        back[qq.diff(t, 2)] = accel(x)
        back[qq.diff(t)] = rate(x)
    lhs = eq.M * sp.Matrix(eq.qdd) - eq.f
    out = []
    for e in lhs:
        e = e.subs(back)
        out.append(sp.expand(e.subs({qq: x for x, qq in zip(nodes, q)})))
    return out


# -- the accuracy test of sec. 2.2.2.1 ---------------------------------------------------

def clamped_beam_omega_squared(mass_ratio=0, kinetic: str = "elastic") -> sp.Expr:
    """omega^2 of a clamped beam with end mass m2 = mass_ratio m1, fig. 2.10.

    In units of EI/(m1 l^3).  The beam element with x1 = 0 (clamped: no rigid
    rotation) plus a lumped mass at B; the one equation of motion (2.28) with
    Q = 0 gives omega^2 = c/m_eq with c = 3 EI/l^3 (2.22) and
    m_eq = 33/140 m1 + m2 (2.24); at m2 = 0 omega = (140/11)^(1/2) = 3.57.
    With ``kinetic="rigid"`` (sec. 2.2.2.2, (2.44)) m_eq = m1/3 + m2 and
    omega = 3 at m2 = 0.
    """
    EI, l, m1 = sp.symbols("EI l m1", positive=True)
    x2 = sp.Symbol("x2", real=True)
    e = beam(sp.Integer(0), x2, EI, l, m1, kinetic=kinetic)
    T = e.T + lumped_mass(x2, mass_ratio * m1).T
    M = sp.diff(T, rate(x2), 2)
    C = sp.diff(e.V, x2, 2)
    return sp.simplify(C / M * m1 * l**3 / EI)
