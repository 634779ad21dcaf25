"""Contact stress between cam and follower: Hertz's solution for two elastic bodies pressed
together (K. L. Johnson, *Contact Mechanics*, 1985, sec. 4.2 and 4.3).

Line contact (a cylindrical roller, or a flat face, on the cam over a length L): with the
load per length P' = F/L, the effective radius 1/R = 1/rho_cam + 1/r_r (1/r_r = 0 for a
flat face; rho_cam < 0 where the cam is concave) and the contact modulus
1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2, the strip's half-width and peak pressure are

    b = sqrt(4 P' R / (pi E*)),        p0 = sqrt(P' E* / (pi R)) = 2 P' / (pi b).

Point contact (a crowned roller, crown radius R_c across the cam): the gap is A x^2 + B y^2
with the relative curvatures 1/2 (1/r_r + 1/rho_cam) in the rolling plane and 1/(2 R_c)
across it; the contact ellipse (semi-axes a >= b, along the smaller curvature A) and its
peak pressure follow from

    B/A = ((a/b)^2 E(e) - K(e)) / (K(e) - E(e)),      e^2 = 1 - (b/a)^2,
    a^3 = 3 F (K(e) - E(e)) / (2 pi E* e^2 A),        p0 = 3 F / (2 pi a b),

K and E the complete elliptic integrals (Johnson (4.37)-(4.39)); the first is solved for
b/a by root finding.  At A = B it is a sphere's contact, p0 = (6 F E*^2/(pi^3 R^2))^(1/3).
Both are written in Carlson's symmetric integral R_D (DLMF 19.25.1: K - E = (e^2/3)
R_D(0, k'^2, 1), E - k'^2 K = (e^2 k'^2/3) R_D(0, 1, k'^2), k' = b/a), which takes the
differences K - E and E - k'^2 K without cancelling digits at either end of the range:

    B/A = R_D(0, 1, k'^2) / R_D(0, k'^2, 1),      a^3 = F R_D(0, k'^2, 1) / (2 pi E* A),

so the ellipse is found for every ratio B/A >= 1, from a sphere's contact (k' = 1) to a
nearly line-like one (k' ~ (B/A ln(4 a/b))^(-1/2) as B/A grows without bound).

Materials: Young's modulus and Poisson's ratio of common cam and follower materials, typical
handbook values (Shigley's Mechanical Engineering Design, table A-5).
"""
from __future__ import annotations

import math

import numpy as np

from ..core.errors import CamdynInputError
from .checks import MIN_WIDTH, in_range
from .names import MATERIALS

def material(text: str) -> tuple[float, float]:
    """A material by name (:data:`MATERIALS`) or as E:nu (Pa, 1), e.g. ``210e9:0.3``."""
    key = text.strip().lower()
    if key in MATERIALS:
        return MATERIALS[key]
    try:
        E, nu = (float(v) for v in key.split(":"))
    except ValueError:
        raise CamdynInputError(f"material {text!r} is neither one of {', '.join(MATERIALS)} "
                               f"nor E:nu (Pa and Poisson's ratio, e.g. 210e9:0.3)") from None
    if not (math.isfinite(E) and 1e6 <= E <= 1e13):
        raise CamdynInputError(f"material {text!r}: E={E:g} Pa is out of range 1e6 to 1e13")
    if not (math.isfinite(nu) and 0.0 <= nu < 0.5):
        raise CamdynInputError(f"material {text!r}: Poisson's ratio {nu:g} is out of range "
                               f"0 <= nu < 0.5")
    return E, nu


def contact_modulus(cam: tuple[float, float], follower: tuple[float, float]) -> float:
    """E* of the pair: 1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2."""
    return 1.0 / sum((1.0 - nu * nu) / E for E, nu in (cam, follower))


def line_contact(force, length: float, curvature, e_star: float):
    """(p0, b): peak pressure (Pa) and half-width (m) of a line contact under ``force`` (N)
    over ``length`` (m), ``curvature`` = 1/R = 1/rho_cam + 1/r_r (1/m, > 0).  Arrays
    broadcast; a force <= 0 gives p0 = b = 0."""
    per_length = np.maximum(np.asarray(force, dtype=float), 0.0) / length
    curvature = np.asarray(curvature, dtype=float)
    p0 = np.sqrt(per_length * e_star * curvature / math.pi)
    b = np.sqrt(4.0 * per_length / (math.pi * e_star * curvature))
    return p0, b


def _ratio_of(k: float) -> float:
    """B/A of the contact ellipse with b/a = k (0 < k <= 1): R_D(0, 1, k^2)/R_D(0, k^2, 1)."""
    from scipy.special import elliprd

    q = k * k
    return float(elliprd(0.0, 1.0, q) / elliprd(0.0, q, 1.0))


MAX_RATIO = 1e100
"""The largest ratio of relative curvatures B/A the point contact takes (b/a is then some
1e-51): the root finder's lower bracket, b/a squared once more, stays a normal double up to
about 1e148 (B/A ~ a^2/(b^2 ln(4 a/b)))."""


def _ellipticity(ratio: float) -> float:
    """b/a <= 1 of the contact ellipse whose relative curvatures have B/A = ratio >= 1.

    B/A falls monotonically from infinity at b/a -> 0 to 1 at b/a = 1; the root is bracketed
    in ln(b/a) from the expansions at either end, b/a ~ 1 - 2 (B/A - 1)/3 near a circle and
    b/a ~ (B/A ln(4 a/b))^(-1/2) for a long ellipse (each within a factor of 2 of the root in
    ln(b/a)), widened until it changes sign, and found by Brent's method to a relative 1e-15
    in b/a."""
    from scipy.optimize import brentq

    if not (math.isfinite(ratio) and 1.0 <= ratio <= MAX_RATIO):
        raise CamdynInputError(
            f"the contact ellipse's ratio of relative curvatures B/A = {ratio:g} is out of "
            f"range 1 to {MAX_RATIO:g}: the crown radius and the rolling radius are too far "
            f"apart for Hertz's point contact; give a crown radius nearer the roller's")
    if ratio == 1.0:
        return 1.0

    def g(x):                     # x = ln(b/a) <= 0
        return math.log(_ratio_of(math.exp(x))) - math.log(ratio)
    x = (-2.0 * (ratio - 1.0) / 3.0 if ratio < 2.0 else
         -0.5 * math.log(ratio * math.log(4.0 * math.sqrt(ratio))))
    lo = 2.0 * x
    while g(lo) < 0.0:            # the ratio at lo is still below: a longer ellipse
        lo *= 2.0
    return math.exp(brentq(g, lo, 0.0, xtol=1e-16, rtol=1e-15))


def point_contact(force: float, A: float, B: float, e_star: float):
    """(p0, a, b) of Hertz's elliptical contact under ``force`` (N) with relative curvatures
    A and B (1/m, > 0; a lies along the smaller of the two): a^3 = F R_D(0, k'^2, 1)/(2 pi
    E* A), b = k' a, p0 = 3 F/(2 pi a b) (Johnson (4.37)-(4.39) in Carlson's form)."""
    from scipy.special import elliprd

    if force <= 0.0:
        return 0.0, 0.0, 0.0
    A, B = min(A, B), max(A, B)
    k = _ellipticity(B / A)
    a = (force * float(elliprd(0.0, k * k, 1.0)) / (2.0 * math.pi * e_star * A)) ** (1.0 / 3.0)
    b = k * a
    return 3.0 * force / (2.0 * math.pi * a * b), a, b


class ContactSpec:
    """What the contact stress along a cam needs beside the profile: the normal force
    (:class:`camdyn.runtime.cam.load.ContactLoad`), the contact's length (the roller's width,
    the cam's, the shorter of the two when both are given), the materials of cam and
    follower (names of :data:`MATERIALS` or E:nu), a crowned roller's crown radius (point
    contact) and the allowable peak pressure (Pa) of the check."""

    def __init__(self, load, roller_width=None, cam_width=None, materials=("steel", "steel"),
                 crown_radius=None, allowable=None):
        self.load = load
        widths = {}
        for name, w in (("roller-width", roller_width), ("cam-width", cam_width)):
            if w is not None:
                widths[name] = in_range(name, w, MIN_WIDTH, high=1000.0)
        self.widths = widths
        if len(materials) != 2:
            raise CamdynInputError(f"materials must be two, the cam's and the follower's, got "
                                   f"{len(materials)}")
        self.materials = tuple(materials)
        self.e_star = contact_modulus(material(materials[0]), material(materials[1]))
        self.crown_radius = (None if crown_radius is None else
                             in_range("crown-radius", crown_radius, strict=True, high=1000.0))
        self.allowable = (None if allowable is None else
                          in_range("allowable-stress", allowable, strict=True, high=1e12))

    def length(self, roller: bool) -> float:
        """The contact line's length (m) for a roller or a flat face."""
        usable = self.widths if roller else {k: v for k, v in self.widths.items()
                                             if k == "cam-width"}
        if not usable:
            raise CamdynInputError("the contact stress needs the contact's length: "
                                   + ("roller-width (or cam-width)" if roller else "cam-width"))
        return min(usable.values())


