"""DYNACAM: the cam mechanism with four degrees of freedom and its drive, thesis ch. 6.

Degrees of freedom (figs 6.1, 6.2, all reduced to the output member, SI units):
the cam angle beta, the shaft's tangential deflection y (6.12), (6.16), its
deflection z along the follower (6.11), (6.15), and the follower output x
(6.42), (6.44); plus, as first-order states, the asynchronous motor
(A.5.6)-(A.5.9), and the massless gear wheel or roller in a squeeze film
(6.9), (6.41).

Smooth mechanics from energies:

    kinetic energy     1/2 J beta'^2 + 1/2 m_y y'^2 + 1/2 m_z z'^2 + 1/2 m_x x'^2
    potential energy   1/2 c_y y^2 + 1/2 c_z z^2 [+ F_0 x + 1/2 c_s x^2, follower spring (6.45)]
    dissipation        1/2 d_y y'^2 + 1/2 d_z z'^2,   d = 2 q sqrt(m c) (6.47)

The nonsmooth laws are force elements with modes and events:

* the roller: the cam contact point moves by h_c = h(beta) - y tan(alpha) - z
  (6.22), tan(alpha) = (dh/dbeta)/R(beta) (6.20), R = R_b + h (radial cam) or
  R_b (axial) (6.21).  On a rocker (option ``rocker``, a radial cam) h is the roller
  centre's arc l_a psi and the same first-order reasoning gives h_c = h - y i_y - z i_z
  with ratios of the rocker's geometry (:func:`_rocker`); for the translating follower
  they are tan(alpha) and 1, (6.22) again.  A flat face square to the follower's motion
  (option ``flat_face``) is not moved by a sideways shift of the cam: i_y = 0, i_z = 1, and
  the angle it sees is beta itself.  A flat face on the rocker's arm (both options) swings
  with the arm; h is its swing reduced to the arc at l_a, and its ratios come from the
  face's support distance (:func:`_rocker_flat`).  The linkage spring-damper (c_x, d_x) carries
  F_x = c_x delta + d_x delta', delta = h_c - x, while the roller touches
  (6.42).  Contact law taken here, with zero viscosity: the roller is massless
  and the spring-damper engages when the roller reaches a wall (delta = 0 or
  the far groove wall delta = -s_r) and releases when it leaves it again;
  these crossings are events.  So a spring-loaded follower can jump (mode
  "free"), a positive-drive cam traverses its groove backlash s_r, and the
  "impact" is the sudden engagement of the linkage stiffness, the ramp input
  of sec. 3.6.  With the squeeze film (A.4.11) instead the roller position is
  a state, h_r' = h_c' - F_x/(V_R gap^(-3/2)) on the compressed side (6.41);
* the reduction gear: the shaft torque M = k (phi_r - beta) + d_b (phi_r' - beta')
  (6.10) with the gear output phi_r either the input phi (rigid), within the
  backlash s_g with the same contact law (dry), or in a squeeze film (6.9);
* Coulomb friction on the cam (6.13) and in the linkage (6.43): modes slip
  forward, stick, slip backward; sticking holds the velocity at zero while
  the other forces stay within the friction limit;
* the worm gear passes the torque with efficiency tan(a)/tan(a + mu) when the
  motor drives and tan(a - mu)/tan(a) when it is driven (6.71), (6.72).

The option set of a variant (which of these elements and degrees of freedom
it has) is in its manifest; a scene generates only what it asks for.
"""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, field, fields

import sympy as sp

from ..model import Branch, Coordinate, Event, FirstOrder, Mode, Model, Output, Parameter, Residual, \
    cam_input, time

t = time("t")
H = cam_input("H")


def _opt(default, doc):
    return field(default=default, metadata={"doc": doc})


@dataclass(frozen=True)
class Options:
    """What a DYNACAM variant contains (each field names the thesis section)."""

    cam: str = _opt("radial", "cam: radial disk or axial (globoidal) (6.21)")
    motor: str = _opt("constant", "drive: constant speed, first- or second-order motor (App. 5, sec. 6.7)")
    gear: str = _opt("rigid", "gear between motor and camshaft: rigid, with backlash, or with backlash "
                              "and a squeeze film (6.1)-(6.9)")
    roller: str = _opt("bilateral", "roller: held on both sides, in contact held by a spring, in a groove "
                                    "with backlash, or in a groove with a squeeze film (6.27)-(6.41)")
    shaft_y: bool = _opt(True, "tangential shaft deflection y' (6.12), (6.16)")
    shaft_z: bool = _opt(True, "shaft deflection z' along the follower (6.11), (6.15)")
    cam_friction: bool = _opt(False, "Coulomb friction between roller and cam (6.13)")
    linkage_friction: bool = _opt(False, "Coulomb friction in the follower linkage (6.43)")
    spring: bool = _opt(False, "follower spring with preload (6.45)")
    external: bool = _opt(False, "constant external force on the output (6.46)")
    flat_face: bool = _opt(False, "flat-faced follower: square to its motion, or with rocker on the "
                                  "arm, at f_f from the pivot (radial cam)")
    rocker: bool = _opt(False, "oscillating follower on an arm pivoted at d_p from the cam centre: "
                               "a roller at l_a, or with flat_face a flat face, reduced to the arc "
                               "at l_a (sec. 2.4; radial cam)")

    CHOICES = {"cam": ("radial", "axial"), "motor": ("constant", "first", "second"),
               "gear": ("rigid", "backlash", "squeeze"),
               "roller": ("bilateral", "contact", "groove", "groove-squeeze")}

    def __post_init__(self):
        for key, allowed in self.CHOICES.items():
            if getattr(self, key) not in allowed:
                raise ValueError(f"option {key}={getattr(self, key)!r}: choose one of {', '.join(allowed)}")
        for key, value, other, other_value, why in EXCLUDES:
            if getattr(self, key) == value and getattr(self, other) == other_value:
                raise ValueError(f"option {key}={_toml(value)} with {other}={_toml(other_value)}: {why}")

    @property
    def name(self) -> str:
        """Module name: ``dynacam_`` and the words of NAME_WORDS for the four choices, then those
        of NAME_FLAGS for the elements switched on, joined by underscores."""
        words = [NAME_WORDS[key][getattr(self, key)] for key in NAME_WORDS]
        words += [word for word, key in NAME_FLAGS if getattr(self, key)]
        return "dynacam_" + "_".join(words)

    def description(self) -> tuple:
        """What this variant contains, one line per option, in words (its generated header)."""
        lines = [f"{key} = {getattr(self, key)}: {DESCRIPTIONS[key][getattr(self, key)]}"
                 for key in NAME_WORDS]
        lines += [f"{key} = {'yes' if getattr(self, key) else 'no'}: "
                  f"{DESCRIPTIONS[key][getattr(self, key)]}" for _, key in NAME_FLAGS]
        return tuple(lines)

    def items(self) -> tuple:
        return tuple(sorted(asdict(self).items()))


EXCLUDES = (
    ("rocker", True, "cam", "axial", "a rocker is derived for a radial cam; an axial cam drives a "
                                     "translating follower"),
    ("flat_face", True, "cam", "axial", "a flat face is derived for a radial cam"),
    ("flat_face", True, "roller", "groove", "a flat face cannot run in a groove"),
    ("flat_face", True, "roller", "groove-squeeze", "a flat face cannot run in a groove"),
    ("flat_face", True, "cam_friction", True, "the friction on the cam (6.13) is written for a "
                                              "roller"),
    ("rocker", True, "cam_friction", True, "the friction on the cam (6.13) is written for the "
                                           "translating follower only"),
)
"""Option pairs no variant has: (option, value, other option, its value, why)."""


def _toml(value) -> str:
    return json.dumps(value)       # as a scene file writes it: true, "axial"


NAME_WORDS = {"cam": {"radial": "radial", "axial": "axial"},
              "motor": {"constant": "ideal", "first": "motor1", "second": "motor2"},
              "gear": {"rigid": "rigidgear", "backlash": "backlash", "squeeze": "gearsqueeze"},
              "roller": {"bilateral": "bilateral", "contact": "contact", "groove": "groove",
                         "groove-squeeze": "groovesqueeze"}}
"""One word per choice, in this order, make the first part of a variant's name; no word
stands for two things (tests/test_dynacam.py checks)."""
NAME_FLAGS = (("shafty", "shaft_y"), ("shaftz", "shaft_z"), ("camfriction", "cam_friction"),
              ("linkfriction", "linkage_friction"), ("spring", "spring"), ("force", "external"),
              ("flat", "flat_face"), ("rocker", "rocker"))
"""The words of the elements switched on make the rest of the name."""

DESCRIPTIONS = {
    "cam": {"radial": "radial disk cam, pitch radius R_b + h (6.21)",
            "axial": "axial (globoidal) cam, constant pitch radius R_b (6.21)"},
    "motor": {"constant": "camshaft input turning at the constant speed omega_s (ideal drive)",
              "first": "asynchronous motor without electrical lag (T_el -> 0, App. 5), worm gear (6.71), (6.72)",
              "second": "asynchronous motor with electrical lag T_el (A.5.6)-(A.5.9), worm gear (6.71), (6.72)"},
    "gear": {"rigid": "reduction gear without backlash: the shaft torsion k, d_b alone (6.10)",
             "backlash": "reduction gear with backlash s_g, dry contact (6.1), fig. 6.3",
             "squeeze": "reduction gear with backlash s_g and a squeeze film between the teeth (6.5)-(6.9)"},
    "roller": {"bilateral": "roller held on both sides: the linkage spring always carries (6.42)",
               "contact": "roller held on the cam by the follower spring; it may lift off (6.42)",
               "groove": "roller in a groove with backlash s_r, dry contact (6.27), fig. 6.10",
               "groove-squeeze": "roller in a groove with backlash s_r and a squeeze film (6.37)-(6.41)"},
    "shaft_y": {True: "tangential shaft deflection y (6.12), (6.16)", False: "shaft rigid tangentially"},
    "shaft_z": {True: "shaft deflection z along the follower (6.11), (6.15)",
                False: "shaft rigid along the follower"},
    "cam_friction": {True: "Coulomb friction between roller and cam (6.13)", False: "no friction on the cam"},
    "linkage_friction": {True: "Coulomb friction in the follower linkage (6.43)",
                         False: "no friction in the linkage"},
    "spring": {True: "follower spring with preload F_0 (6.45)", False: "no follower spring"},
    "external": {True: "constant external force F_ex on the output (6.46)", False: "no external force"},
    "flat_face": {True: "flat-faced follower: square to its motion, or on the rocker's arm",
                  False: "a roller on the cam"},
    "rocker": {True: "oscillating follower (rocker), reduced to the arc at l_a",
               False: "translating follower"},
}
"""Each option's value in words, for the header of the generated file."""


def catalog() -> dict:
    """The option set as data, for the runtime (generated/catalog.json): every option with its
    default, its choices (or false/true) and what it is, and the rule that names a variant's
    module."""
    options = []
    for f in fields(Options):
        choices = list(Options.CHOICES[f.name]) if f.name in Options.CHOICES else [False, True]
        options.append({"name": f.name, "default": f.default, "choices": choices,
                        "doc": f.metadata["doc"]})
    return {"options": options, "name": {"prefix": "dynacam", "words": NAME_WORDS,
                                         "flags": [list(f) for f in NAME_FLAGS], "separator": "_"},
            "excludes": [list(e) for e in EXCLUDES]}


def _p(name, default, unit, doc, low=0.0, open_low=True, high=float("inf")):
    return Parameter(name, default, unit, doc, low=low, open_low=open_low, high=high)


# parameters, SI; defaults roughly those of the spring-loaded follower of fig. 7.2 (App. 7)
h_m = _p("h_m", 0.015, "m", "stroke of the output member (reduced)")
beta_m = _p("beta_m", 0.436, "rad", "cam angle of the rise (within one turn)", high=2 * math.pi)
beta_0 = _p("beta_0", 0.0, "rad", "cam angle where the rise starts", low=-100.0, open_low=False)
R_b = _p("R_b", 0.0675, "m", "base pitch radius (reduced) (6.21)")
omega_s = _p("omega_s", 4.95, "rad/s", "nominal angular velocity of the camshaft")
J = _p("J", 0.01, "kg m^2", "polar moment of inertia of the cam, reduced to the output member")
k = _p("k", 1.0e3, "N m/rad", "torsional stiffness between gear and cam (6.10)")
q_b = _p("q_b", 0.05, "1", "relative damping of the torsion (6.47)", open_low=False, high=1.0)
m_x = _p("m_x", 1.46, "kg", "equivalent follower mass")
c_x = _p("c_x", 0.376e6, "N/m", "linkage stiffness at the roller (6.42)")
q_x = _p("q_x", 0.023, "1", "relative damping of the linkage (6.47)", open_low=False, high=1.0)
m_y = _p("m_y", 0.1, "kg", "cam mass in the tangential direction (6.16)")
c_y = _p("c_y", 1.0e6, "N/m", "tangential shaft stiffness (6.12)")
q_y = _p("q_y", 0.05, "1", "relative damping, tangential (6.47)", open_low=False, high=1.0)
m_z = _p("m_z", 0.1, "kg", "cam mass along the follower (6.15)")
c_z = _p("c_z", 1.0e6, "N/m", "shaft stiffness along the follower (6.11)")
q_z = _p("q_z", 0.05, "1", "relative damping along the follower (6.47)", open_low=False, high=1.0)
J_ma = _p("J_ma", 0.05, "kg m^2", "motor inertia reduced to the camshaft (A.5.7)")
G_a = _p("G_a", 5.0, "N m s/rad", "slope of the motor's torque-speed line, reduced (A.5.4b)")
T_el = _p("T_el", 8.6e-3, "s", "electrical time constant of the motor (A.5.3)")
alpha_w = _p("alpha_w", 0.36, "rad", "lead angle of the worm (6.71)", high=1.5)
mu_w = _p("mu_w", 0.05, "1", "friction coefficient of the worm gear (6.71)", open_low=False, high=1.0)
s_g = _p("s_g", 1.0e-2, "rad", "backlash of the reduction gear, reduced to the camshaft (6.1)")
V_T = _p("V_T", 1.0e-3, "N m s rad^(1/2)", "squeeze coefficient of the gear teeth (6.6), with R_b^(1/2)")
s_r = _p("s_r", 1.3e-4, "m", "backlash of the roller in its groove (6.27)")
V_R = _p("V_R", 1.0e-5, "N s m^(1/2)", "squeeze coefficient of the roller (6.38)")
nu_b = _p("nu_b", 0.01, "1", "friction coefficient on the cam (6.13)", open_low=False, high=1.0)
nu_x = _p("nu_x", 0.01, "1", "friction coefficient of the follower linkage (6.43)", open_low=False, high=1.0)
F_0 = _p("F_0", 100.0, "N", "follower spring preload at x = 0 (6.45)", open_low=False)
c_s = _p("c_s", 1.0e4, "N/m", "follower spring stiffness (6.45)", open_low=False)
F_ex = _p("F_ex", 0.0, "N", "constant external force on the output, positive along x (6.46)",
          low=-1e9, open_low=False)
d_p = _p("d_p", 0.12, "m", "rocker: distance from the cam centre to the arm's pivot")
l_a = _p("l_a", 0.09, "m", "rocker: arm length from the pivot to the roller centre")
l_f = _p("l_a", 0.09, "m", "oscillating flat face: the radius its swing is reduced to, h = l_a psi "
                           "(sec. 2.4)")
f_f = _p("f_f", 0.0, "m", "oscillating flat face: distance from the pivot to the face's line, "
                          "positive towards the cam centre's side", low=-1e9, open_low=False)

GAP_MIN = sp.Rational(1, 10**12)
"""Smallest squeeze gap [m or rad]: the film never closes in exact arithmetic, but a step may
overshoot by rounding; the gap is clipped there instead of taking a negative power."""


STATIC = sp.Rational(1001, 1000)
"""Static over sliding friction: sticking breaks when the other forces exceed the sliding
limit by 0.1 %, so that a slip always starts with a positive acceleration."""


def _clipped(gap):
    return sp.Piecewise((gap, gap > GAP_MIN), (GAP_MIN, True))


def _coulomb(name: str, coordinate, rate, friction_force, other_force, doc, initial):
    """Mode, generalized force and events of Coulomb friction on one coordinate.

    Slip forward/backward: the friction force opposes the motion; stick: it balances the
    other forces exactly (the velocity stays zero) while they stay within the limit.
    """
    mode = Mode(name, ("forward", "stick", "backward"), doc, initial=initial)
    force = mode.select(forward=-friction_force, stick=-other_force, backward=friction_force)
    # sticking holds up to STATIC times the sliding friction: at exactly 1 a slip that starts
    # with zero acceleration turns back at once and the modes chatter at zero velocity
    static = STATIC * friction_force
    holds = sp.Abs(other_force) <= static
    events = (
        Event(f"{name}_stop_fwd", rate, -1, {name: ("forward",)},
              (Branch({name: "stick"}, holds, {coordinate.name + "d": 0}), Branch({name: "backward"}))),
        Event(f"{name}_stop_bwd", rate, 1, {name: ("backward",)},
              (Branch({name: "stick"}, holds, {coordinate.name + "d": 0}), Branch({name: "forward"}))),
        Event(f"{name}_break", sp.Abs(other_force) - static, 1, {name: ("stick",)},
              (Branch({name: "forward"}, other_force > 0), Branch({name: "backward"}))),
    )
    return mode, force, events


@dataclass
class _Parts:
    """What the elements of a variant declare, collected in the order they are added (the
    order of parameters, states, modes, events and outputs in the generated manifest)."""

    params: list
    P: dict = field(default_factory=dict)
    first_order: list = field(default_factory=list)
    modes: list = field(default_factory=list)
    events: list = field(default_factory=list)
    outputs: list = field(default_factory=list)

    def __post_init__(self):
        self.P = {p.name: p.symbol for p in self.params}

    def use(self, *params):
        self.params += params
        self.P.update({p.name: p.symbol for p in params})


@dataclass
class _Cam:
    """The cam and the contact point it drives (6.17)-(6.26)."""

    B: object        # cam angle over the rise angle (6.17)
    h: object        # cam law h(beta)
    R: object        # pitch radius (6.21)
    tan_a: object    # cam slope (6.20); a rocker's i_y
    i_z: object      # ratio of the contact's displacement to z: 1, or a rocker's
    h_c: object      # contact point displacement (6.22)
    dhc: list        # dh_c/dq per coordinate, for the contact force's work
    hc_rate: object  # h_c' (6.23), (6.26)


def _coordinates(opts: Options):
    """The coordinates beta, [y], [z], x (figs 6.1, 6.2) and their functions of time (0 for a
    deflection the variant leaves out)."""
    b_c = Coordinate("beta", "rad", "cam angle", scale=1.0, initial_rate=omega_s.symbol)
    x_c = Coordinate("x", "m", "follower output position", scale=0.01)
    y_c = Coordinate("y", "m", "tangential deflection of the camshaft", scale=1e-5)
    z_c = Coordinate("z", "m", "deflection of the camshaft along the follower", scale=1e-5)
    coords = [b_c] + ([y_c] if opts.shaft_y else []) + ([z_c] if opts.shaft_z else []) + [x_c]
    y = y_c(t) if opts.shaft_y else sp.Integer(0)
    z = z_c(t) if opts.shaft_z else sp.Integer(0)
    return coords, b_c(t), y, z, x_c(t)


def _cam(opts: Options, P: dict, coords, beta, y, z) -> _Cam:
    """Cam law, pitch radius, slope and the contact point's displacement (6.17)-(6.26)."""
    B = (beta - P["beta_0"]) / P["beta_m"]
    h = P["h_m"] * H(B)
    dh = sp.diff(h, beta)
    if opts.rocker and opts.flat_face:
        R, tan_a, i_z = _rocker_flat(P, h, dh)
    elif opts.rocker:
        R, tan_a, i_z = _rocker(P, h, dh)
    elif opts.flat_face:
        R, tan_a, i_z = P["R_b"] + h, sp.Integer(0), sp.Integer(1)
    else:
        R = P["R_b"] + h if opts.cam == "radial" else P["R_b"]
        tan_a, i_z = dh / R, sp.Integer(1)
    h_c = h - y * tan_a - z * i_z                 # (6.22)
    q_funcs = [c(t) for c in coords]
    dhc = [sp.diff(h_c, qq) for qq in q_funcs]
    hc_rate = sum(g * qq.diff(t) for g, qq in zip(dhc, q_funcs))   # (6.23), (6.26)
    return _Cam(B, h, R, tan_a, i_z, h_c, dhc, hc_rate)


def _rocker(P: dict, h, dh):
    """A rocker's pitch radius R and the ratios i_y, i_z that (6.22) takes for tan(alpha) and 1.

    Frame: the cam centre at the origin, z towards the roller centre at the rise start (on
    the base pitch circle R_b), y square to it, the cam turning counter-clockwise in (y, z)
    (its surface at that point moving towards -y).  The pivot lies at distance d_p from the
    cam centre and l_a from that roller centre, on the side y < 0 that the cam's surface
    moves towards (the rocker of runtime/cam/follower.py, whose pressure angle this one's
    equals); the roller centre is C(h) = pivot + l_a (cos phi, sin phi), phi = phi_0 + h/l_a,
    so that h, the output reduced to the roller's arc (sec. 2.4), rises as the roller moves
    out; e_t = dC/dh.  The pitch curve's normal there is n = J (e_t h' - J C) (J: +90 deg),
    its tangent being the roller centre's velocity relative to the cam per unit beta.  A shaft deflection moves the
    cam by y e_y - z e_z (the signs of (6.22)); the roller stays on the pitch curve if it
    moves along its arc by -(y e_y.n - z e_z.n)/(e_t.n) to first order, so

        i_y = -(e_y.n)/(e_t.n),    i_z = (e_z.n)/(e_t.n),

    tan(alpha) = h'/R and 1 for the translating follower (C = (0, R_b + h), e_t = e_z)."""
    Rb, d, l = P["R_b"], P["d_p"], P["l_a"]
    pz = (d**2 - l**2 + Rb**2) / (2 * Rb)
    py = -sp.sqrt(d**2 - pz**2)
    c0, s0 = -py / l, (Rb - pz) / l               # cos, sin of phi_0
    cph = c0 * sp.cos(h / l) - s0 * sp.sin(h / l)
    sph = s0 * sp.cos(h / l) + c0 * sp.sin(h / l)
    # e_t = (-sin phi, cos phi), C = pivot + l (cos phi, sin phi), n = (C_y - h' cos phi,
    # C_z - h' sin phi); e_t.n = p_z cos phi - p_y sin phi, the h' terms cancelling
    den = pz * cph - py * sph
    i_y = (cph * (dh - l) - py) / den
    i_z = (pz + sph * (l - dh)) / den
    return sp.sqrt((py + l * cph)**2 + (pz + l * sph)**2), i_y, i_z


def _rocker_flat(P: dict, h, dh):
    """A flat face on a rocker's arm: its support distance R from the cam centre and the
    ratios i_y, i_z that (6.22) takes for tan(alpha) and 1.

    Frame and signs as in :func:`_rocker`.  The face's line keeps the distance f_f from the
    pivot p, on the cam centre's side; at the rise start it is the line z = R_b, touching the
    base circle, so p_z = R_b - f_f and p_y = -(d_p^2 - p_z^2)^(1/2).  The arm turns by
    phi = h/l_a, the face's normal m = (-sin phi, cos phi) turning with it, and its support
    k(phi) = p.m + f_f rises with phi.  The cam's own support function s(theta) (theta the
    normal's angle in the cam frame, theta = pi/2 + phi - beta) holds the face where
    k(phi) = s(theta) + D.m, D the shift of the cam centre.  Along the rise (D = 0) the
    derivative in beta gives s' = k' phi_b/(phi_b - 1); a shift D then turns the arm by
    D.m (1 - phi_b)/k' to first order, k' = dk/dphi, phi_b = h'/l_a.  With D = y e_y - z e_z:

        i_y = (l_a - h') sin(phi)/k',    i_z = (l_a - h') cos(phi)/k',

    and the translating flat face's 0 and 1 where the pivot goes to infinity along -y."""
    Rb, d, l, f = P["R_b"], P["d_p"], P["l_a"], P["f_f"]
    pz = Rb - f
    py = -sp.sqrt(d**2 - pz**2)
    c, s = sp.cos(h / l), sp.sin(h / l)
    dk = -py * c - pz * s
    return -py * s + pz * c + f, (l - dh) * s / dk, (l - dh) * c / dk


def _drive(opts: Options, parts: _Parts):
    """The input angle phi, its rate and the motor's speed deviation dw (None at constant
    speed); the motor's states are declared with their rates by :func:`_motor`."""
    P = parts.P
    if opts.motor == "constant":
        return P["omega_s"] * t, P["omega_s"], None
    parts.use(J_ma, G_a, alpha_w, mu_w, *([T_el] if opts.motor == "second" else []))
    phi = FirstOrder("phi", "rad", "input angle of the camshaft (motor side of the shaft)", 0)(t)
    dw = FirstOrder("dw", "rad/s", "speed deviation of the motor, reduced (A.5.8)", 0)(t)
    return phi, P["omega_s"] + dw, dw


def _gear(opts: Options, parts: _Parts, phi, phi_rate, beta):
    """The torque M reaching the cam through the reduction gear and the shaft torsion
    (6.1)-(6.10): rigid, dry backlash, or backlash with a squeeze film."""
    P = parts.P
    d_b = 2 * P["q_b"] * sp.sqrt(P["J"] * P["k"])
    if opts.gear == "rigid":
        return P["k"] * (phi - beta) + d_b * (phi_rate - beta.diff(t))
    if opts.gear == "backlash":
        parts.use(s_g)
        gear = Mode("gear", ("drive", "free", "back"), "flank of the reduction gear in contact",
                    initial="drive")
        parts.modes.append(gear)
        M_drive = P["k"] * (phi - beta) + d_b * (phi_rate - beta.diff(t))
        # the cam runs ahead of the gear by s_g when the back flank is hit
        M_back = P["k"] * (phi + P["s_g"] - beta) + d_b * (phi_rate - beta.diff(t))
        parts.events += [
            Event("gear_lift_drive", phi - beta, -1, {"gear": ("drive",)}, (Branch({"gear": "free"}),)),
            Event("gear_hit_drive", phi - beta, 1, {"gear": ("free",)}, (Branch({"gear": "drive"}),)),
            Event("gear_hit_back", phi + P["s_g"] - beta, -1, {"gear": ("free",)}, (Branch({"gear": "back"}),)),
            Event("gear_lift_back", phi + P["s_g"] - beta, 1, {"gear": ("back",)}, (Branch({"gear": "free"}),)),
        ]
        # the massless wheel sits on a flank, or where the unloaded shaft leaves it (at beta)
        parts.outputs.append(Output("gear_gap", gear.select(drive=0, free=phi - beta, back=-P["s_g"]), "rad",
                                    "input minus gear output angle (6.1): 0 on the driving flank, -s_g on the other"))
        return gear.select(drive=M_drive, free=0, back=M_back)
    # squeeze film between the teeth (6.5)-(6.9)
    parts.use(s_g, V_T)
    phir_s = FirstOrder("phir", "rad", "angle of the gear output wheel (6.1)", 0, scale=1.0)
    phir = phir_s(t)
    N = P["k"] * (phir - beta) + d_b * (phi_rate - beta.diff(t))
    # as with the dry gear, the wheel lies in [phi, phi + s_g]: the film on the driving
    # flank is phir - phi (AA, (6.7)), on the back flank phi + s_g - phir (BB, (6.8)),
    # and either closes while it carries the torque N
    gap_d = _clipped(phir - phi)
    gap_b = _clipped(phi + P["s_g"] - phir)
    W = P["V_T"] * sp.Piecewise((gap_d ** sp.Rational(-3, 2), N > 0), (gap_b ** sp.Rational(-3, 2), True))
    parts.first_order.append(FirstOrder("phir", phir_s.unit, phir_s.doc, phi_rate - N / (W + d_b),
                                        scale=1.0))
    parts.outputs.append(Output("gear_gap", phi - phir, "rad", "input minus gear output angle (6.1): 0 on the driving flank, -s_g on the other"))
    return N * W / (W + d_b)


def _roller(opts: Options, parts: _Parts, cam: _Cam, x):
    """The force F_x between cam and follower linkage (6.42) through the roller: held on both
    sides, in spring-held contact, in a groove with backlash, or with a squeeze film
    (6.27)-(6.41)."""
    P = parts.P
    d_x = 2 * P["q_x"] * sp.sqrt(P["m_x"] * P["c_x"])
    delta = cam.h_c - x
    delta_rate = cam.hc_rate - x.diff(t)
    if opts.roller == "bilateral":
        return P["c_x"] * delta + d_x * delta_rate
    if opts.roller == "contact":
        roller = Mode("roller", ("contact", "free"), "roller on the cam or lifted off (follower jump)",
                      initial="contact")
        parts.modes.append(roller)
        parts.events += [
            Event("roller_lift", delta, -1, {"roller": ("contact",)}, (Branch({"roller": "free"}),)),
            Event("roller_land", delta, 1, {"roller": ("free",)}, (Branch({"roller": "contact"}),)),
        ]
        parts.outputs.append(Output("roller_gap", -delta, "m", "gap between roller and cam (negative: pressed)"))
        return roller.select(contact=P["c_x"] * delta + d_x * delta_rate, free=0)
    if opts.roller == "groove":
        parts.use(s_r)
        roller = Mode("roller", ("lower", "free", "upper"), "groove wall the roller touches",
                      initial="lower")
        parts.modes.append(roller)
        delta_u = x - cam.h_c - P["s_r"]
        parts.events += [
            Event("roller_leave_lower", delta, -1, {"roller": ("lower",)}, (Branch({"roller": "free"}),)),
            Event("roller_hit_lower", delta, 1, {"roller": ("free",)}, (Branch({"roller": "lower"}),)),
            Event("roller_hit_upper", delta_u, 1, {"roller": ("free",)}, (Branch({"roller": "upper"}),)),
            Event("roller_leave_upper", delta_u, -1, {"roller": ("upper",)}, (Branch({"roller": "free"}),)),
        ]
        # the massless roller sits on a wall, or where the unloaded linkage leaves it (at x)
        parts.outputs.append(Output("roller_gap", roller.select(lower=0, free=-delta, upper=P["s_r"]), "m",
                                    "roller position in the groove over the cam wall: 0 lower wall, s_r upper"))
        return roller.select(lower=P["c_x"] * delta + d_x * delta_rate, free=0,
                             upper=-(P["c_x"] * delta_u - d_x * delta_rate))
    # groove with the squeeze film (6.37)-(6.41)
    parts.use(s_r, V_R)
    hr_s = FirstOrder("hr", "m", "roller position (6.41)", 0, scale=0.01)
    hr = hr_s(t)
    N = P["c_x"] * (hr - x) + d_x * (cam.hc_rate - x.diff(t))
    gap_l = _clipped(hr - cam.h_c)
    gap_u = _clipped(cam.h_c + P["s_r"] - hr)
    W = P["V_R"] * sp.Piecewise((gap_l ** sp.Rational(-3, 2), N > 0), (gap_u ** sp.Rational(-3, 2), True))
    parts.first_order.append(FirstOrder("hr", "m", hr_s.doc, cam.hc_rate - N / (W + d_x), scale=0.01))
    parts.outputs.append(Output("roller_gap", hr - cam.h_c, "m", "roller over the cam wall: 0 lower wall, s_r upper"))
    return N * W / (W + d_x)


def _forces(opts: Options, parts: _Parts, coords, cam: _Cam, Fx, M, beta, x) -> dict:
    """Generalized forces per coordinate: the contact force's work, the shaft torque, the
    external force and Coulomb friction on the cam (6.13) and in the linkage (6.43)."""
    P = parts.P
    Q = {c.name: sp.Integer(0) for c in coords}
    for c, g in zip(coords, cam.dhc):
        Q[c.name] += -Fx * g
    Q["x"] += Fx
    Q["beta"] += M
    F_s = 0
    if opts.spring:
        parts.use(F_0, c_s)
        F_s = P["F_0"] + P["c_s"] * x
    if opts.external:
        parts.use(F_ex)
        Q["x"] += P["F_ex"]
    if opts.cam_friction:
        parts.use(nu_b)
        limit = sp.Abs(Fx) * P["nu_b"] * cam.R * sp.sqrt(1 + cam.tan_a**2)     # (6.13)
        mode, force, evs = _coulomb("camfric", coords[0], beta.diff(t), limit, Q["beta"],
                                    "friction on the cam: slipping forward, sticking, backward", "forward")
        parts.modes.append(mode)
        parts.events += evs
        Q["beta"] += force
    if opts.linkage_friction:
        parts.use(nu_x)
        limit = sp.Abs(Fx) * P["nu_x"]                                           # (6.43)
        mode, force, evs = _coulomb("linkfric", coords[-1], x.diff(t), limit, Q["x"] - F_s,
                                    "friction in the follower linkage: forward, sticking, backward", "stick")
        parts.modes.append(mode)
        parts.events += evs
        Q["x"] += force
    return Q


def _motor(opts: Options, parts: _Parts, M, phi_rate, dw) -> None:
    """The asynchronous motor's states: its torque drives phi through the worm gear
    (6.71), (6.72), (A.5.6)-(A.5.9).  Nothing at constant speed."""
    if opts.motor == "constant":
        return
    P = parts.P
    worm = Mode("worm", ("drive", "driven"), "worm gear: motor driving or driven", initial="drive")
    parts.modes.append(worm)
    ta = sp.tan(P["alpha_w"])
    M_ma = worm.select(drive=M * sp.tan(P["alpha_w"] + P["mu_w"]) / ta,
                       driven=M * sp.tan(P["alpha_w"] - P["mu_w"]) / ta)
    parts.events += [Event("worm_reverse", M, -1, {"worm": ("drive",)}, (Branch({"worm": "driven"}),)),
                     Event("worm_forward", M, 1, {"worm": ("driven",)}, (Branch({"worm": "drive"}),))]
    if opts.motor == "second":
        Mea_s = FirstOrder("Mea", "N m", "electromagnetic torque, reduced (A.5.6)", 0, scale=1.0)
        Mea = Mea_s(t)
        parts.first_order.append(FirstOrder("Mea", "N m", Mea_s.doc, (-P["G_a"] * dw - Mea) / P["T_el"]))
    else:
        Mea = -P["G_a"] * dw                                                       # T_el -> 0
    # the drive's own states come first, before those of the squeeze films
    parts.first_order[:0] = [
        FirstOrder("phi", "rad", "input angle of the camshaft (motor side)", phi_rate),
        FirstOrder("dw", "rad/s", "speed deviation of the motor, reduced (A.5.8)",
                   (Mea - M_ma) / P["J_ma"], scale=0.1)]
    parts.outputs += [Output("motor_speed_var", dw / P["omega_s"], "1", "motor speed deviation over w_s"),
                      Output("M_motor", Mea, "N m", "electromagnetic torque of the motor, reduced")]


def _energies(opts: Options, P: dict, beta, y, z, x):
    """Kinetic and potential energy and Rayleigh's dissipation function (sec. 6.5, (6.45),
    (6.47))."""
    kinetic = P["J"] * beta.diff(t) ** 2 / 2 + P["m_x"] * x.diff(t) ** 2 / 2
    potential = sp.Integer(0)
    dissipation = sp.Integer(0)
    if opts.shaft_y:
        kinetic += P["m_y"] * y.diff(t) ** 2 / 2
        potential += P["c_y"] * y**2 / 2
        dissipation += 2 * P["q_y"] * sp.sqrt(P["m_y"] * P["c_y"]) * y.diff(t) ** 2 / 2
    if opts.shaft_z:
        kinetic += P["m_z"] * z.diff(t) ** 2 / 2
        potential += P["c_z"] * z**2 / 2
        dissipation += 2 * P["q_z"] * sp.sqrt(P["m_z"] * P["c_z"]) * z.diff(t) ** 2 / 2
    if opts.spring:
        potential += P["F_0"] * x + P["c_s"] * x**2 / 2
    return kinetic, potential, dissipation


def _common_outputs(opts: Options, P: dict, cam: _Cam, M, Fx, beta, y, x) -> list:
    """The outputs every variant has: dimensionless accelerations and error (sec. 8.2),
    torque, contact force, speed variation (2.54) and slope."""
    t_m = P["beta_m"] / P["omega_s"]
    return [
        Output("B", cam.B, "1", "cam angle over the rise angle (6.17)"),
        Output("Xdd", x.diff(t, 2) * t_m**2 / P["h_m"], "1", "follower acceleration x'' t_m^2/h_m"),
        Output("Bdd", beta.diff(t, 2) * t_m**2 / P["beta_m"], "1", "cam angular acceleration beta'' t_m^2/beta_m"),
        Output("U", (x - cam.h) / P["h_m"], "1", "positional error over the stroke, (x - h(beta))/h_m"),
        Output("xdd", x.diff(t, 2), "m/s^2", "follower acceleration"),
        Output("torque", M, "N m", "shaft torque driving the cam (6.10)"),
        Output("Fx", Fx, "N", "force between cam and follower linkage (6.42)"),
        Output("speed_var", (beta.diff(t) - (y.diff(t) / cam.R if opts.shaft_y and not opts.flat_face
                                             else 0)) / P["omega_s"] - 1,
               "1", "variation of the fictitious angular velocity seen by the roller (2.54)"),
        Output("tan_alpha", cam.tan_a, "1", "cam slope (6.20); a rocker's ratio i_y (_rocker, "
                                            "_rocker_flat), 0 for a translating flat face"),
    ] + ([Output("i_z", cam.i_z, "1", "a rocker's ratio of the contact's displacement to z (_rocker, "
                                      "_rocker_flat)"),
          Output("R_c", cam.R, "m", "a rocker's pitch radius (roller) or the face's support "
                                    "distance (flat face) from the cam centre")]
         if opts.rocker else [])


def build(opts: Options = Options()) -> Model:
    """The DYNACAM variant with the elements ``opts`` selects (thesis ch. 6)."""
    coords, beta, y, z, x = _coordinates(opts)
    parts = _Parts([h_m, beta_m, beta_0, R_b, omega_s, J, k, q_b, m_x, c_x, q_x]
                   + ([m_y, c_y, q_y] if opts.shaft_y else []) + ([m_z, c_z, q_z] if opts.shaft_z else [])
                   + ([d_p, l_f, f_f] if opts.rocker and opts.flat_face
                      else [d_p, l_a] if opts.rocker else []))
    cam = _cam(opts, parts.P, coords, beta, y, z)
    phi, phi_rate, dw = _drive(opts, parts)
    M = _gear(opts, parts, phi, phi_rate, beta)
    Fx = _roller(opts, parts, cam, x)
    Q = _forces(opts, parts, coords, cam, Fx, M, beta, x)
    _motor(opts, parts, M, phi_rate, dw)
    kinetic, potential, dissipation = _energies(opts, parts.P, beta, y, z, x)
    return Model(
        name=opts.name,
        title="DYNACAM, cam mechanism with four degrees of freedom and drive",
        reference="thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18",
        doc=__doc__,
        time=t,
        time_unit="s",
        coordinates=tuple(coords),
        kinetic=kinetic,
        potential=potential,
        dissipation=dissipation,
        forces=tuple(Q[c.name] for c in coords),
        parameters=tuple(parts.params),
        outputs=tuple(_common_outputs(opts, parts.P, cam, M, Fx, beta, y, x) + parts.outputs),
        first_order=tuple(parts.first_order),
        modes=tuple(parts.modes),
        events=tuple(parts.events),
        residual=Residual(error="U", acceleration="Xdd", rise_end=1.0, rise_state="B"),
        options=opts.items(),
        variant=opts.description(),
        expand_forces=not opts.rocker,
    )
