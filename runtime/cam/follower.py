"""The follower of a disk cam: where it touches the cam, seen from the cam.

Four followers, as the cam-design texts class them (e.g. Norton, *Cam Design and
Manufacturing Handbook*, ch. 7; Chen, *Mechanics and Design of Cam Mechanisms*, ch. 5):

* ``translating-roller``  a roller on a slide, the slide's axis offset by e;
* ``translating-flat``    a flat face square to the slide;
* ``oscillating-roller``  a roller on an arm of length l pivoted at distance a from the cam
  centre (a rocker);
* ``oscillating-flat``    a flat face on an arm pivoted at distance a, the face's line at
  distance f from the pivot.

Each takes the cam angle phi and the rows M = (m, m', m'') of its motion, derivatives in phi:
the lift s (m) of a translating follower, the swing psi (rad, from the arm's start angle
psi_0) of an oscillating one; and returns a :class:`Contact`, everything in the cam frame.

Conventions (those of :mod:`camdyn.runtime.cam.profile`): the cam centre O is the origin, the
cam turns clockwise by phi, so a point g fixed in the ground lies at R(phi) g in the cam frame
(kinematic inversion), R the rotation by +phi.  A translating follower moves along +x on the
line y = e.  An oscillating follower's pivot is A = (a, 0); its arm leaves A towards the cam
at the angle psi from AO, on the side y > 0, along u(psi) = (-cos psi, sin psi), and the
motion rises as psi grows.

Roller followers: the roller centre traces the pitch curve P(phi) = R(phi) G(phi), G its
ground position; with J the rotation by +90 deg, P' = R (G' + J G) and P'' = R (G'' + 2 J G'
- G), so the pitch curve's signed curvature kappa_p = (P' x P'')/|P'|^3 (positive where
convex) needs no difference quotient.  The profile is P - r_r n (n the outward normal), of
radius of curvature rho_p - r_r; it cusps where 1 - r_r kappa_p < 0.

Flat-faced followers: the face is the line x . m(theta) = k in the cam frame, m = (cos theta,
sin theta); the profile is the envelope of these lines, touched at

    X = k m + (dk/dtheta) m_perp,     radius of curvature  rho = k + d^2k/dtheta^2,

(the support function of a convex curve: its radius of curvature is p + p''), with
dk/dtheta = k'/theta' and d^2k/dtheta^2 = (k'' theta' - k' theta'')/theta'^3 from the
derivatives in phi.  Where rho < 0 the envelope cusps: no flat face can follow that motion
(for a translating face rho = r_b + s + s'').

Pressure angle: the angle between the common normal at the contact and the velocity of the
follower's point there (for a roller, of the roller centre), signed atan2(n x v, n . v).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .names import KINDS  # noqa: F401  (the followers by name)


@dataclass(frozen=True)
class Contact:
    """The cam-frame geometry of one follower along the cam angles asked for (arrays)."""

    x: np.ndarray
    """Profile point (contact point), x (m)."""
    y: np.ndarray
    kappa_profile: np.ndarray
    """Signed curvature of the profile (1/m), positive where convex."""
    pressure_angle: np.ndarray
    """rad."""
    normal: tuple | None = None
    """(nx, ny): the profile's outward unit normal in the cam frame."""
    pitch: tuple | None = None
    """(x, y) of the roller centre (roller followers)."""
    kappa_pitch: np.ndarray | None = None
    """Signed curvature of the pitch curve (roller followers)."""
    face_position: np.ndarray | None = None
    """Where the contact lies on the flat face (m): from the slide's axis (translating), from
    the pivot along the arm (oscillating)."""
    lever: np.ndarray | None = None
    """n . dX/dm: the common normal (from the cam to the follower) against the velocity of
    the follower's point of contact per unit of motion m (1 for a translating face, cos alpha
    for a translating roller, m for a rocker): by virtual work the normal force F_n drives the
    motion with the generalised force F_n * lever."""


def _cross(a0, a1, b0, b1):
    return a0 * b1 - a1 * b0


def _rotate(phi, v0, v1):
    c, s = np.cos(phi), np.sin(phi)
    return v0 * c - v1 * s, v0 * s + v1 * c


def _pressure(n0, n1, v0, v1):
    return np.arctan2(_cross(n0, n1, v0, v1), n0 * v0 + n1 * v1)


class _Roller:
    """A roller follower: subclasses give the roller centre's ground position G and its
    derivatives in phi, and the direction its centre moves in as the follower rises."""

    roller_radius: float

    def centre(self, M):
        """((G0, G1), (G0', G1'), (G0'', G1'')) in the ground frame."""
        raise NotImplementedError

    def direction(self, M):
        """Unit vector of the roller centre's velocity as the follower rises (ground)."""
        raise NotImplementedError

    def reach(self) -> float:
        """|dG/dm|: how far the roller centre moves per unit of motion."""
        raise NotImplementedError

    def contact(self, phi, M) -> Contact:
        (g0, g1), (d0, d1), (e0, e1) = self.centre(M)
        # P' and P'' expressed in the ground frame (R^T P', R^T P''): curvature and angles
        # do not depend on the frame they are written in
        a0, a1 = d0 - g1, d1 + g0                  # G' + J G
        b0, b1 = e0 - 2 * d1 - g0, e1 + 2 * d0 - g1  # G'' + 2 J G' - G
        speed = np.hypot(a0, a1)
        kappa = _cross(a0, a1, b0, b1) / speed**3
        n0, n1 = a1 / speed, -a0 / speed           # outward normal of a counter-clockwise curve
        v0, v1 = self.direction(M)
        rr = self.roller_radius
        px, py = _rotate(phi, g0, g1)
        q0, q1 = _rotate(phi, n0, n1)
        with np.errstate(divide="ignore"):
            rho_p = np.where(kappa == 0.0, np.inf, 1.0 / kappa)
            kappa_prof = np.where(np.isinf(rho_p), 0.0, 1.0 / (rho_p - rr))
        return Contact(px - rr * q0, py - rr * q1, kappa_prof, _pressure(n0, n1, v0, v1),
                       normal=(q0, q1), pitch=(px, py), kappa_pitch=kappa,
                       lever=(n0 * v0 + n1 * v1) * self.reach())


@dataclass(frozen=True)
class TranslatingRoller(_Roller):
    """Roller centre at (d0 + s, e), d0 = sqrt(r_p0^2 - e^2), r_p0 = r_b + r_r."""

    base_radius: float
    roller_radius: float
    offset: float = 0.0

    @property
    def d0(self) -> float:
        return math.sqrt((self.base_radius + self.roller_radius) ** 2 - self.offset**2)

    def centre(self, M):
        z = np.zeros_like(M[0])
        return (self.d0 + M[0], z + self.offset), (M[1], z), (M[2], z)

    def direction(self, M):
        return np.ones_like(M[0]), np.zeros_like(M[0])

    def reach(self) -> float:
        return 1.0


def arm_reaches(pivot_distance: float, arm_length: float, radius: float) -> bool:
    """Whether an arm pivoted at that distance from the cam centre puts its end on the circle
    of that radius: |a - l| < r < a + l, the triangle cam centre, pivot, arm's end."""
    return abs(pivot_distance - arm_length) < radius < pivot_distance + arm_length


@dataclass(frozen=True)
class OscillatingRoller(_Roller):
    """Roller centre at A + l u(psi_0 + psi); psi_0 puts it on the prime circle r_b + r_r:
    cos psi_0 = (a^2 + l^2 - r_p0^2)/(2 a l)."""

    base_radius: float
    roller_radius: float
    pivot_distance: float
    arm_length: float

    @property
    def psi0(self) -> float:
        a, l, rp = self.pivot_distance, self.arm_length, self.base_radius + self.roller_radius
        return math.acos((a * a + l * l - rp * rp) / (2 * a * l))

    def centre(self, M):
        a, l = self.pivot_distance, self.arm_length
        psi = self.psi0 + M[0]
        c, s = np.cos(psi), np.sin(psi)
        # d/dpsi of (-cos, sin) is (sin, cos); of that, (cos, -sin)
        return ((a - l * c, l * s), (l * s * M[1], l * c * M[1]),
                (l * (s * M[2] + c * M[1] ** 2), l * (c * M[2] - s * M[1] ** 2)))

    def direction(self, M):
        psi = self.psi0 + M[0]
        return np.sin(psi), np.cos(psi)

    def reach(self) -> float:
        return self.arm_length


class _Flat:
    """A flat-faced follower: subclasses give the face's normal angle theta_g and support k
    in the ground frame with their derivatives in phi, and the face's point velocity."""

    def face(self, M):
        """(theta_g, theta_g', theta_g''), (k, k', k'') in the ground frame."""
        raise NotImplementedError

    def along(self, M, dk):
        """Where on the face the contact lies, from the ground-frame contact coordinates."""
        raise NotImplementedError

    def velocity(self, M, w):
        """Velocity (ground) of the face's point at face position w per unit of motion."""
        raise NotImplementedError

    def contact(self, phi, M) -> Contact:
        (th, th1, th2), (k, k1, k2) = self.face(M)
        t1 = 1.0 + th1                              # theta = phi + theta_g in the cam frame
        dk = k1 / t1
        d2k = (k2 * t1 - k1 * th2) / t1**3
        rho = k + d2k
        m0, m1 = np.cos(th), np.sin(th)
        # the contact point in the ground frame: k m + dk m_perp
        g0, g1 = k * m0 - dk * m1, k * m1 + dk * m0
        x, y = _rotate(phi, g0, g1)
        w = self.along(M, dk)
        v0, v1 = self.velocity(M, w)
        with np.errstate(divide="ignore"):
            kappa = np.where(rho == 0.0, np.inf, 1.0 / rho)
        # where theta runs backwards (t1 < 0) the envelope is traced backwards: a cusp too
        kappa = np.where(t1 > 0, kappa, -np.abs(kappa))
        return Contact(x, y, kappa, _pressure(m0, m1, v0, v1), normal=_rotate(phi, m0, m1),
                       face_position=w,
                       lever=m0 * v0 + m1 * v1)


@dataclass(frozen=True)
class TranslatingFlat(_Flat):
    """Face x = r_b + s square to the slide: m_g = (1, 0), k = r_b + s, contact at y = s'."""

    base_radius: float
    offset: float = 0.0

    def face(self, M):
        z = np.zeros_like(M[0])
        return (z, z, z), (self.base_radius + M[0], M[1], M[2])

    def along(self, M, dk):
        return dk - self.offset

    def velocity(self, M, w):
        return np.ones_like(w), np.zeros_like(w)


@dataclass(frozen=True)
class OscillatingFlat(_Flat):
    """Face through the point at distance f from the pivot along m_g = (sin psi, cos psi),
    along the arm u(psi): support k = a sin psi + f; psi_0 makes it touch the base circle,
    sin psi_0 = (r_b - f)/a."""

    base_radius: float
    pivot_distance: float
    face_offset: float = 0.0

    @property
    def psi0(self) -> float:
        return math.asin((self.base_radius - self.face_offset) / self.pivot_distance)

    def face(self, M):
        a = self.pivot_distance
        psi = self.psi0 + M[0]
        c, s = np.cos(psi), np.sin(psi)
        # m_g = (sin psi, cos psi) = (cos theta_g, sin theta_g): theta_g = pi/2 - psi
        return ((np.pi / 2 - psi, -M[1], -M[2]),
                (a * s + self.face_offset, a * c * M[1], a * (c * M[2] - s * M[1] ** 2)))

    def along(self, M, dk):
        # the contact minus A, along u = m_perp: dk - A . u = dk + a cos psi
        return dk + self.pivot_distance * np.cos(self.psi0 + M[0])

    def velocity(self, M, w):
        # a face point A + w u + f m_g turns about A: d/dpsi = w m_g - f u
        psi = self.psi0 + M[0]
        s, c = np.sin(psi), np.cos(psi)
        f = self.face_offset
        return w * s + f * c, w * c - f * s
