"""The cam itself: a radial disk cam for a translating roller follower.

Pitch curve, profile (open cam) or both groove walls (groove cam), pressure angle and radius
of curvature along the cam angle, the undercut and pressure-angle checks, and writers for
CSV, DXF (through ezdxf) and a PNG sheet.  NumPy on the compiled cam-law library; no SymPy.

The motion is :class:`camdyn.runtime.cam.motion.RDFD` (rise, upper dwell, return with the same
law mirrored or a law of its own, lower dwell to 360 deg), and the walls are the envelopes of the roller circles
tested as in :func:`camdyn.runtime.cam.motion.undercut` (the wall offset by d has tangent
p'(1 + d kappa_p)); here the follower axis may be offset.

Conventions (SI throughout, angles in rad unless named *_deg):

* r_b is the base circle of the cam *profile* (its smallest radius); the roller centre at
  the lowest point of the stroke lies on the prime circle r_p0 = r_b + r_r.
* Ground frame: cam centre at the origin, the follower translates along the line y = e,
  moving in +x as it rises; its roller centre is (d0 + s, e) with d0 = sqrt(r_p0^2 - e^2).
  The cam turns clockwise by phi, so in the cam frame the pitch point is
  p(phi) = R(phi) (d0 + s, e), traced counter-clockwise; with e = 0 the pitch point's polar
  angle is phi and p = (r_p0 + s)(cos phi, sin phi), the convention of profile.RDFD.
  e > 0 puts the axis on the side the cam surface comes from (it lowers the pressure angle
  on the rise).
* Pressure angle: tan alpha = (s' - e) / (d0 + s), s' = ds/dphi, the angle between the
  follower's axis and the common normal; positive on the rise.
* Curvature kappa_p of the pitch curve is signed, positive where it is convex; rho_p = 1/kappa_p.
  The profile of an open cam (and the groove's inner wall) is p - r_r n with n the outward
  normal, radius of curvature rho_p - r_r; the groove's outer wall is p + r_r n, rho_p + r_r.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from ..core.errors import CamdynInputError
from ..measure.contract import chart_note
from ..core.laws import choose
from ..core.outdir import out_folder, writing
from .checks import in_range
from .follower import (KINDS, Contact, OscillatingFlat, OscillatingRoller, TranslatingFlat,
                       TranslatingRoller, arm_reaches)
from .motion import RDFD, failing_spans

TWO_PI = 2 * math.pi


@dataclass(frozen=True)
class Check:
    """One design check: ``ok``, where it is worst, the worst value with its sampling error
    (how far the sampled worst lay from the refined one) and the intervals where it fails
    (deg)."""

    name: str
    ok: bool
    worst_deg: float
    value: float
    limit: float
    intervals_deg: tuple
    message: str
    error: float = 0.0

    def as_dict(self) -> dict:
        # strict JSON: no curvature of that sign at all (rho infinite) is null
        finite = math.isfinite(self.value)
        return {"check": self.name, "ok": self.ok, "worst_angle_deg": self.worst_deg,
                "value": self.value if finite else None,
                "value_error": self.error if finite else None, "limit": self.limit,
                "intervals_deg": [list(iv) for iv in self.intervals_deg],
                "message": self.message}


def _law(flag: str, key: str, parameter):
    """choose(key, parameter), its refusal naming the option (laws.choose says theta, the
    option is --law-parameter or --return-law-parameter)."""
    try:
        law = choose(key, parameter)
    except CamdynInputError as exc:
        which = f"{flag}-parameter" if parameter is not None else flag
        raise CamdynInputError(f"{which} ({key}): {exc}") from None
    if hasattr(law, "check_for"):       # a rise from a table: its curvature takes H''
        law.check_for("the cam profile", 2)
    return law


MAX_LENGTH = 1000.0
"""The largest stroke and radius (m) a cam takes: a kilometre is beyond any cam, and far
enough below the square root of the largest float for every formula of the profile."""
MIN_RADIUS = 1e-6
"""The smallest base and roller radius (m): a micrometre is below any cam, and far enough
above the smallest float that curvatures (1/radius, squared) stay finite."""
HERTZ_SIZE = 0.1
"""The largest contact size over the radius of curvature it lies across (a/R) before the
stress figures are warned of: Hertz's half-spaces ask a << R (Johnson sec. 4.1); at a tenth
the surfaces within the contact stray from the parabolas of his gap by a quarter of a
percent, and beyond it the contact soon wraps round the body."""
CUSP_ARCS = 2000
"""The most tangent arcs a layer of a profile that fails its undercut or cusp check is fitted
with (a smooth one: biarc.MAX_ARCS): a small cusp's loop within 1 um takes a few hundred
(tests/test_followers.py), a large one hundreds of thousands, a second a thousand."""
ARC_TOLERANCE = 1e-6
"""How far (m) the tangent arcs of a curve may stray from it where the cam states no
``arc_tolerance`` of its own (the STEP plate's profile): a micrometre, a tenth of what a
milling machine holds."""


def _a(kind: str) -> str:
    return ("an " if kind[0] in "aeiou" else "a ") + kind


def _span_degrees(runs) -> tuple:
    """Failing spans of cam angle (rad) in degrees."""
    return tuple((math.degrees(a), math.degrees(b)) for a, b in runs)


def _span_text(runs) -> str:
    """Failing spans of cam angle (rad) as the messages print them: [a, b], [c, d] (deg)."""
    return ", ".join(f"[{a:.2f}, {b:.2f}]" for a, b in _span_degrees(runs))


@dataclass(frozen=True)
class CamProfile:
    """A radial disk cam and its follower (see the module's conventions and
    :mod:`camdyn.runtime.cam.follower`): a translating follower rises by ``stroke`` (m), an
    oscillating one swings by ``swing_deg``."""

    stroke: float | None = None
    base_radius: float | None = None
    roller_radius: float | None = None
    offset: float = 0.0
    angles_deg: tuple = (90.0, 90.0, 90.0, 90.0)
    law: str = "cycloidal"
    law_parameter: float | None = None
    return_law: str | None = None
    """The return's law (None: the rise's law and parameter, mirrored)."""
    return_law_parameter: float | None = None
    groove: bool = False
    points_per_degree: int = 10
    max_pressure_angle_deg: float = 30.0
    follower: str = "translating-roller"
    """One of :data:`camdyn.runtime.cam.follower.KINDS`."""
    pivot_distance: float | None = None
    """Oscillating followers: cam centre to pivot a (m)."""
    arm_length: float | None = None
    """Oscillating roller: pivot to roller centre l (m)."""
    swing_deg: float | None = None
    """Oscillating followers: the arm's swing over the rise (deg)."""
    face_offset: float = 0.0
    """Oscillating flat face: distance f of the face's line from the pivot (m)."""
    cutter_radius: float | None = None
    """The milling cutter's radius (m): its centre path is the profile offset outwards."""
    arc_tolerance: float | None = None
    """Write the DXF's curves as tangent arcs within this distance (m) of the exact curves
    (runtime/cam/biarc.py) instead of the sampled polylines."""
    cam: RDFD = field(init=False, repr=False, compare=False)
    geometry: object = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        kind = self.follower
        if kind not in KINDS:
            raise CamdynInputError(f"follower={kind!r} is not one of {', '.join(KINDS)}")
        oscillating, roller = kind.startswith("oscillating"), kind.endswith("roller")
        needs = ["base-radius"] + (["roller-radius"] if roller else [])
        needs += (["pivot-distance", "swing"] + (["arm-length"] if roller else [])
                  if oscillating else ["stroke"])
        given = {"base-radius": self.base_radius, "roller-radius": self.roller_radius,
                 "pivot-distance": self.pivot_distance, "swing": self.swing_deg,
                 "arm-length": self.arm_length, "stroke": self.stroke}
        missing = [n for n in needs if given[n] is None]
        if missing:
            raise CamdynInputError(f"{_a(kind)} follower needs {', '.join(missing)}")
        rb = in_range("base-radius", self.base_radius, low=MIN_RADIUS, high=MAX_LENGTH,
                      high_open=True)
        self._only_with(oscillating, roller)
        rr = (in_range("roller-radius", self.roller_radius, low=MIN_RADIUS, high=MAX_LENGTH,
                       high_open=True) if roller else None)
        if oscillating:
            rise = math.radians(in_range("swing", self.swing_deg, strict=True, high=90.0, high_open=True))
        else:
            rise = in_range("stroke", self.stroke, high=MAX_LENGTH, high_open=True)
        try:
            e = float(self.offset)
        except (TypeError, ValueError):
            raise CamdynInputError(f"offset must be a number, got {self.offset!r}") from None
        if not math.isfinite(e):
            raise CamdynInputError(f"offset={e:g} is out of range: it must be finite")
        reach = rb + (rr or 0.0)
        if roller and abs(e) >= reach:
            raise CamdynInputError(f"offset={e:g} is out of range: |offset| < base-radius + "
                                   f"roller-radius = {reach:g}")
        ang = tuple(self.angles_deg)
        if len(ang) != 4:
            raise CamdynInputError(f"angles must be four values rise,upper dwell,return,lower "
                                   f"dwell in deg, got {len(ang)}")
        names = ("rise", "upper dwell", "return", "lower dwell")
        ang = tuple(in_range(f"angles ({n})", a, strict=n in ("rise", "return"))
                    for n, a in zip(names, ang))
        if abs(sum(ang) - 360.0) > 1e-9:
            raise CamdynInputError(f"angles must sum to 360 deg (rise + upper dwell + return + "
                                   f"lower dwell), got {sum(ang):g}")
        ppd = self.points_per_degree
        if not isinstance(ppd, (int, np.integer)) or not 1 <= ppd <= 1000:
            raise CamdynInputError(f"points-per-degree={ppd!r} is out of range: an integer "
                                   f"from 1 to 1000")
        in_range("max-pressure-angle", self.max_pressure_angle_deg, strict=True, high=90.0,
                 high_open=True)
        if self.cutter_radius is not None:
            in_range("cutter-radius", self.cutter_radius, low=MIN_RADIUS, high=MAX_LENGTH,
                     high_open=True)
            if self.groove:
                raise CamdynInputError("cutter-radius goes with an open cam: a groove is cut by "
                                       "a cutter of the roller's size along the pitch curve")
        if self.arc_tolerance is not None:
            in_range("arcs", self.arc_tolerance, low=1e-9, high=1.0, high_open=True)
        if self.groove and not roller:
            raise CamdynInputError("groove goes with a roller follower: a flat face has one "
                                   "side to push on")
        r = np.radians(ang)
        if self.return_law is None and self.return_law_parameter is not None:
            raise CamdynInputError("return-law-parameter goes with --return-law")
        fall = (None if self.return_law is None
                else _law("return-law", self.return_law, self.return_law_parameter))
        cam = RDFD(rise, rb, rr or 0.0, _law("law", self.law, self.law_parameter),
                   beta_rise=float(r[0]), dwell_outer=float(r[1]), beta_fall=float(r[2]),
                   fall_law=fall)
        object.__setattr__(self, "offset", e)
        object.__setattr__(self, "angles_deg", ang)
        object.__setattr__(self, "cam", cam)
        object.__setattr__(self, "geometry", self._geometry(rb, rr, e, rise))
        if kind == "oscillating-flat":
            self._face_keeps_turning()

    def _face_keeps_turning(self) -> None:
        """Refuse an oscillating flat face whose arm turns as fast as the cam somewhere.

        The face's normal turns in the cam frame at theta' = 1 - psi' (follower.py: theta =
        phi + pi/2 - psi): where the arm's speed psi' reaches the cam's, the face stands still
        against the cam, its contact dk/dtheta = k'/theta' runs off to infinity along it, and
        beyond that the face turns back, so no profile has these lines for its envelope.  psi'
        is the swing times H'/beta, so the largest swing that keeps psi' < 1 is the swing over
        the largest psi'; no length of the arm or the cam changes it."""
        at, top, _ = self._worst(lambda x: self.cam.displacement(x)[1], self._grid())
        if top < 1.0:
            return
        rise = at <= self.cam.beta_rise
        law = self.law if rise or self.return_law is None else self.return_law
        span = self.angles_deg[0 if rise else 2]
        raise CamdynInputError(
            f"swing={self.swing_deg:g} deg is out of range for an oscillating flat face: the "
            f"{law} {'rise' if rise else 'return'} over {span:g} deg turns the arm at up to "
            f"{top:.4g} times the cam's speed (at cam angle {math.degrees(at):.2f} deg), and "
            f"where the arm turns as fast as the cam the face stands still against it and the "
            f"contact runs off to infinity along the face: no cam has that profile. It needs "
            f"swing < {self.swing_deg / top:.4g} deg with these laws and angles (whatever the "
            f"pivot distance and base radius), or a longer rise/return angle")

    @cached_property
    def velocity_jumps(self) -> tuple:
        """(cam angle in rad, left, right limit) where the motion's velocity ds/dphi
        (dpsi/dphi) jumps: the law's H' against the dwells' zero at the rise's or return's
        ends, or inside a law (:meth:`camdyn.runtime.cam.motion.RDFD.jumps`)."""
        return self.cam.jumps(1)

    @cached_property
    def acceleration_jumps(self) -> tuple:
        """(cam angle in rad, left, right limit) where the motion's acceleration d2s/dphi2
        jumps (an infinite jerk)."""
        return self.cam.jumps(2)

    def _velocity_jump_text(self, wall: str | None = None, convex: bool = True) -> str:
        """What a velocity jump does to the profile: for a roller the pitch curve turns a
        corner, which the wall ``wall`` follows with a sharp edge where the corner is
        ``convex`` (the velocity falls across it: the pitch tangent R (s' - e, d0 + s), a
        rocker's too, turns left by (d0 + s)(s'_left - s'_right)) and the other wall with an
        arc of the roller's radius; for a flat face the contact jumps across the face, over a
        flat of the profile."""
        rate = "dpsi/dphi" if self.oscillating else "ds/dphi"
        where = ", ".join(f"{math.degrees(t):.2f}" for t, _, _ in self.velocity_jumps)
        head = (f"the motion's velocity {rate} jumps at cam angle {where} deg (the law's H' "
                f"against the dwells' zero or inside the law)")
        if self.roller:
            edges = [math.degrees(t) for t, lv, rv in self.velocity_jumps
                     if (rv < lv) == convex]
            what = (f"the {wall} a sharp edge at "
                    f"{', '.join(f'{a:.2f}' for a in edges)} deg" if edges else
                    f"the {wall} an arc of the roller's radius round each")
            shape = (f"the pitch curve has a corner there (its radius of curvature changes "
                     f"without bound), {what}")
        else:
            shape = ("the contact jumps across the face there, over a flat of the profile "
                     "(its radius of curvature jumps to infinity and back)")
        return (f"{head}: {shape}, and the follower's acceleration is an impulse, an unbounded "
                f"contact force. Use a law whose velocity is continuous and zero at the dwells")

    def _only_with(self, oscillating: bool, roller: bool) -> None:
        """Refuse the dimensions another follower takes, naming them."""
        stray = []
        if oscillating:
            stray += [n for n, v in (("stroke", self.stroke), ("offset", self.offset or None))
                      if v is not None]
        else:
            stray += [n for n, v in (("pivot-distance", self.pivot_distance),
                                     ("arm-length", self.arm_length), ("swing", self.swing_deg))
                      if v is not None]
        if not roller and self.roller_radius is not None:
            stray.append("roller-radius")
        if (self.follower != "oscillating-flat") and self.face_offset:
            stray.append("face-offset")
        if self.follower == "oscillating-flat" and self.arm_length is not None:
            stray.append("arm-length")
        if stray:
            raise CamdynInputError(f"{', '.join(stray)} {'does' if len(stray) == 1 else 'do'} "
                                   f"not apply to {_a(self.follower)} follower")

    def _geometry(self, rb, rr, e, swing):
        kind = self.follower
        if kind == "translating-roller":
            return TranslatingRoller(rb, rr, e)
        if kind == "translating-flat":
            return TranslatingFlat(rb, e)
        a = in_range("pivot-distance", self.pivot_distance, low=MIN_RADIUS, high=MAX_LENGTH,
                     high_open=True)
        if kind == "oscillating-roller":
            l = in_range("arm-length", self.arm_length, low=MIN_RADIUS, high=MAX_LENGTH,
                         high_open=True)
            rp = rb + rr
            if not arm_reaches(a, l, rp):
                raise CamdynInputError(
                    f"arm-length={l:g} with pivot-distance={a:g} cannot put the roller on the "
                    f"prime circle r_b + r_r = {rp:g}: it needs |pivot-distance - arm-length| "
                    f"< {rp:g} < pivot-distance + arm-length")
            geo = OscillatingRoller(rb, rr, a, l)
        else:
            try:
                f = float(self.face_offset)
            except (TypeError, ValueError):
                raise CamdynInputError(f"face-offset must be a number, got "
                                       f"{self.face_offset!r}") from None
            if not (math.isfinite(f) and abs(rb - f) < a):
                raise CamdynInputError(
                    f"face-offset={f:g} is out of range: the face must reach the base circle, "
                    f"|base-radius - face-offset| < pivot-distance = {a:g}")
            geo = OscillatingFlat(rb, a, f)
        if geo.psi0 + swing >= math.pi:
            raise CamdynInputError(
                f"swing={math.degrees(swing):g} deg is out of range: from the arm's start "
                f"angle {math.degrees(geo.psi0):.4g} deg it must stay below 180 deg, swing < "
                f"{180 - math.degrees(geo.psi0):.4g} deg")
        return geo

    @property
    def roller(self) -> bool:
        return self.follower.endswith("roller")

    @property
    def oscillating(self) -> bool:
        return self.follower.startswith("oscillating")

    @property
    def turn(self):
        """This cam's motion as a model input: the :class:`camdyn.runtime.core.laws.Turn` with the
        same law and angles (in units of the rise, T = phi/beta_rise; its H^(k) times
        stroke/beta_rise^k is this cam's S^(k)(phi))."""
        from ..core.laws import compose

        return compose(self.law, self.return_law, self.angles_deg, self.law_parameter,
                       self.return_law_parameter)

    # -- geometry at any angles --------------------------------------------------------
    @property
    def prime_radius(self) -> float:
        return self.base_radius + (self.roller_radius or 0.0)

    @property
    def d0(self) -> float:
        return math.sqrt(self.prime_radius**2 - self.offset**2)

    def contact(self, phi) -> Contact:
        """The follower's contact geometry at the cam angles phi (rad)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        return self.geometry.contact(phi, self.cam.displacement(phi)[:3])

    def pitch(self, phi) -> np.ndarray:
        """Pitch points (roller centre), shape (2, n)."""
        return np.array(self.contact(phi).pitch)

    def tangent(self, phi) -> np.ndarray:
        """dP/dphi of a translating roller's pitch curve, shape (2, n): R(phi) (s' - e, d0 + s)."""
        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        S = self.cam.displacement(phi)
        a, b = S[1] - self.offset, self.d0 + S[0]
        c, s = np.cos(phi), np.sin(phi)
        return np.array([a * c - b * s, a * s + b * c])

    def pressure_angle(self, phi) -> np.ndarray:
        """alpha in rad (translating roller: atan2(s' - e, d0 + s))."""
        return self.contact(phi).pressure_angle

    def curvature(self, phi) -> np.ndarray:
        """Signed curvature of the pitch curve (roller followers), of the profile (flat
        faces)."""
        c = self.contact(phi)
        return c.kappa_pitch if self.roller else c.kappa_profile

    def profile_curvature(self, phi) -> np.ndarray:
        """Signed curvature of the profile itself, positive where convex."""
        return self.contact(phi).kappa_profile

    # -- contact force and stress (runtime/cam/load.py, runtime/cam/stress.py) ----------
    def contact_stress(self, phi, spec) -> tuple[np.ndarray, np.ndarray]:
        """(F_n, p0): the normal force (N) and Hertz's peak contact pressure (Pa) at the cam
        angles phi.  The relative curvature is the profile's plus the roller's (line
        contact; a crowned roller's crown across it, point contact); where it is not
        positive (a cusp, or a concave part tighter than the roller) p0 is infinite."""
        force, p0, _ = self._hertz(phi, spec)
        return force, p0

    def _hertz(self, phi, spec):
        """(F_n, p0, size): as :meth:`contact_stress`, and the contact's size over the
        relative radius of curvature it lies across, b/R of a line contact (1/R = 1/rho +
        1/r_r), the larger of a/R_A and b/R_B of an ellipse (R_A = 1/(2 A)), which Hertz's
        theory takes to be small (Johnson sec. 4.1); NaN where there is no contact."""
        from .stress import line_contact, point_contact

        phi = np.atleast_1d(np.asarray(phi, dtype=float))
        M = self.cam.displacement(phi)[:3]
        c = self.geometry.contact(phi, M)
        force = spec.load.normal_force(M, c.lever, phi)
        curv = c.kappa_profile + (1.0 / self.roller_radius if self.roller else 0.0)
        ok = curv > 0
        p0 = np.full(phi.shape, np.inf)
        size = np.full(phi.shape, np.nan)
        if spec.crown_radius is not None and self.roller:
            across = 0.5 / spec.crown_radius
            ellipses = [point_contact(f, 0.5 * k, across, spec.e_star)
                        for f, k in zip(force[ok], curv[ok])]
            p0[ok] = [e[0] for e in ellipses]
            size[ok] = [max(2.0 * e[1] * min(0.5 * k, across), 2.0 * e[2] * max(0.5 * k, across))
                        for e, k in zip(ellipses, curv[ok])]
        else:
            p0[ok], b = line_contact(force[ok], spec.length(self.roller), curv[ok], spec.e_star)
            size[ok] = b * curv[ok]
        return force, p0, size

    def _stress_notes(self, spec, th, size) -> list:
        """Warnings on the stress figures that are not failed checks: a contact too large for
        Hertz's theory, and a force from a speed or a run where the motion's velocity or
        acceleration jumps."""
        notes = []
        if np.any(size > HERTZ_SIZE):
            i = int(np.nanargmax(size))
            crown = (f" (crown radius {spec.crown_radius * 1e3:.4g} mm)"
                     if spec.crown_radius is not None and self.roller else "")
            notes.append(
                f"contact stress: the contact is not small beside the radii of curvature it "
                f"lies across, its semi-axis reaching {size[i]:.3g} of that radius at cam angle "
                f"{math.degrees(th[i]):.2f} deg{crown}, where Hertz's theory takes it to be small "
                f"(here below {HERTZ_SIZE:g}): the peak pressure is beyond its reach there")
        if spec.load.constant:
            return notes
        rate = "psi" if self.oscillating else "s"
        if spec.load.history is not None:       # a compliant linkage's run: finite, struck
            velocity = ("the run's contact force there is its linkage's answer to a kink in "
                        "the lift, which a rigid follower would meet with an impulse")
            acceleration = ("the run's contact force is struck there by a step of "
                            "acceleration (an infinite jerk), and the peak pressure with it")
        else:
            velocity = ("the follower's acceleration is an impulse there, which the "
                        "kinetostatic contact force leaves out: its figures hold between "
                        "those angles only")
            acceleration = ("the kinetostatic contact force jumps there with it (an infinite "
                            "jerk), and the peak pressure with it; a real follower adds the "
                            "vibration the step excites. A law with continuous acceleration "
                            "avoids it")
        for rows, what, effect in ((self.velocity_jumps, f"velocity d{rate}/dphi", velocity),
                                   (self.acceleration_jumps, f"acceleration d2{rate}/dphi2",
                                    acceleration)):
            if rows:
                where = ", ".join(f"{math.degrees(t):.2f}" for t, _, _ in rows)
                notes.append(f"contact force: the motion's {what} jumps at cam angle {where} "
                             f"deg: {effect}")
        return notes

    def stress_summary(self, spec) -> dict:
        """The peak contact pressure along the cam (refined between the samples, with the
        sampling error), where it is, the force's range, and the checks: the allowable
        pressure, and for a kinetostatic force whether the follower stays on the cam; ``ok``
        whether every check holds, ``warnings`` those that fail and what the figures should
        be read with (:meth:`_stress_notes`)."""
        th = self._grid()
        if spec.crown_radius is not None and not self.roller:
            raise CamdynInputError("crown-radius goes with a roller follower")
        spec.length(self.roller)            # refuses a missing length before any work

        def f(x):
            return self.contact_stress(x, spec)[0]

        def p(x):
            return self.contact_stress(x, spec)[1]
        f_grid, p_grid, size = self._hertz(th, spec)
        _, fmax, fmax_s = self._worst(f, th, f_grid)
        lo_at, neg, neg_s = self._worst(lambda x: -f(x), th, -f_grid)
        out = {"contact_force": spec.load.describe(),
               "contact_force_max": fmax, "contact_force_max_error": abs(fmax - fmax_s),
               "contact_force_min": -neg, "contact_force_min_error": abs(neg - neg_s),
               "materials": list(spec.materials), "contact_modulus": spec.e_star,
               "contact": "point (crowned roller)" if spec.crown_radius is not None else "line"}
        checks = []
        if not np.all(np.isfinite(p_grid)):
            at = float(th[np.argmax(~np.isfinite(p_grid))])
            out.update(hertz_stress_max=None, hertz_stress_max_error=None,
                       hertz_stress_max_angle_deg=math.degrees(at))
            checks.append(Check("contact stress", False, math.degrees(at), math.inf,
                                spec.allowable or 0.0, (), (
                                    f"contact stress: no Hertz contact from cam angle "
                                    f"{math.degrees(at):.2f} deg on, where the profile is not "
                                    f"convex enough for the follower (see the undercut or cusp "
                                    f"check)")))
        else:
            at, pmax, sampled = self._worst(p, th, p_grid)
            out.update(hertz_stress_max=pmax, hertz_stress_max_error=abs(pmax - sampled),
                       hertz_stress_max_angle_deg=math.degrees(at))
            if spec.allowable is not None:
                bad = pmax > spec.allowable
                msg = (f"contact stress: Hertz's peak pressure reaches {pmax / 1e6:.4g} MPa at "
                       f"cam angle {math.degrees(at):.2f} deg, "
                       + (f"beyond the allowable {spec.allowable / 1e6:.4g} MPa. Use a wider "
                          f"contact, a larger roller or base circle, or a stronger material "
                          f"pair." if bad else
                          f"within the allowable {spec.allowable / 1e6:.4g} MPa"))
                checks.append(Check("contact stress", not bad, math.degrees(at), pmax,
                                    spec.allowable, (), msg, abs(pmax - sampled)))
        if not spec.load.constant:
            # a run's force is zero, not negative, where the roller has left the cam: the
            # spans end where it falls below a billionth of its largest
            eps = 1e-9 * fmax if spec.load.history is not None else 0.0
            runs = failing_spans(th, f_grid < eps,
                                 lambda x: float(f(np.array([x]))[0]) - eps)
            if runs:
                spans = _span_text(runs)
                msg = (f"follower leaves the cam: {spec.load.leaves_where()} the contact "
                       f"force falls to {-neg:.4g} N at cam angle {math.degrees(lo_at):.2f} deg "
                       f"(not positive for phi in {spans} deg): the spring cannot hold the "
                       f"follower there. Raise the spring's preload or rate, or lower the speed.")
            else:
                msg = (f"follower stays on the cam: least contact force {-neg:.4g} N at "
                       f"{math.degrees(lo_at):.2f} deg")
            checks.append(Check("contact kept", not runs, math.degrees(lo_at), -neg, 0.0,
                                _span_degrees(runs),
                                msg, abs(neg - neg_s)))
        out["checks"] = [c.as_dict() for c in checks]
        out["ok"] = all(c.ok for c in checks)
        out["warnings"] = [c.message for c in checks if not c.ok] + self._stress_notes(spec, th,
                                                                                      size)
        return out

    # -- the sampled cam ---------------------------------------------------------------
    @cached_property
    def phi(self) -> np.ndarray:
        n = 360 * int(self.points_per_degree)
        return np.arange(n) * (TWO_PI / n)

    @cached_property
    def table(self) -> dict:
        """Every column along the sampled cam angle (SI, angles in deg)."""
        phi = self.phi
        S = self.cam.displacement(phi)
        c = self.contact(phi)
        out = {"phi_deg": np.degrees(phi)}
        if self.oscillating:
            out["psi_deg"] = np.degrees(self.geometry.psi0 + S[0])
        else:
            out["s"] = S[0]
        if self.roller:
            rr = self.roller_radius
            out["x_pitch"], out["y_pitch"] = c.pitch
        out["x_profile"], out["y_profile"] = c.x, c.y
        if self.groove:
            # the outer wall lies a roller diameter beyond the inner one along the normal
            out["x_outer"] = 2 * c.pitch[0] - c.x
            out["y_outer"] = 2 * c.pitch[1] - c.y
        if self.cutter_radius is not None:
            out["x_cutter"] = c.x + self.cutter_radius * c.normal[0]
            out["y_cutter"] = c.y + self.cutter_radius * c.normal[1]
        out["alpha_deg"] = np.degrees(c.pressure_angle)
        with np.errstate(divide="ignore"):
            if self.roller:
                rho = np.where(c.kappa_pitch == 0.0, np.inf, 1.0 / c.kappa_pitch)
                out["rho_pitch"] = rho
                out["rho_profile"] = rho - rr
                if self.groove:
                    out["rho_outer"] = rho + rr
            else:
                out["rho_profile"] = np.where(c.kappa_profile == 0.0, np.inf,
                                              1.0 / c.kappa_profile)
                out["face_position"] = c.face_position
        return out

    # -- checks ------------------------------------------------------------------------
    def _grid(self):
        """The sample angles with every segment end (the law's own breakpoints too)."""
        return np.union1d(np.append(self.phi, TWO_PI), self.cam.breakpoints)

    def _worst(self, f, th, v=None):
        """(where, value, sampled value) of the largest value of f: sampled on th (or its
        samples v, given), then refined between the grid neighbours of the largest sample.
        How far the refinement moved it from the sample bounds what it could still be off by,
        choosing among near-equal peaks: the extreme's sampling error."""
        v = f(th) if v is None else v
        i = int(np.argmax(v))
        lo, hi = th[max(i - 1, 0)], th[min(i + 1, th.size - 1)]
        if hi > lo:
            from scipy.optimize import minimize_scalar

            r = minimize_scalar(lambda x: -float(f(np.array([x]))[0]), bounds=(lo, hi),
                                method="bounded", options={"xatol": 1e-12})
            if -r.fun > v[i]:
                return float(r.x), float(-r.fun), float(v[i])
        return float(th[i]), float(v[i]), float(v[i])

    @cached_property
    def checks(self) -> tuple:
        th = self._grid()
        out = list(self._undercut_checks(th) if self.roller else self._cusp_checks(th))
        if self.cutter_radius is not None:
            out.append(self._cutter_check(th))
        lim = math.radians(self.max_pressure_angle_deg)

        def fa(x):
            return np.abs(self.pressure_angle(x))
        at, amax, sampled = self._worst(fa, th)
        bad = fa(th) > lim
        runs = failing_spans(th, bad, lambda x: float(fa(x)[0]) - lim)
        if runs:
            spans = _span_text(runs)
            msg = (f"pressure angle: |alpha| reaches {math.degrees(amax):.2f} deg at cam angle "
                   f"{math.degrees(at):.2f} deg, beyond the limit {self.max_pressure_angle_deg:g} "
                   f"deg for phi in {spans} deg. Use a larger base circle or a longer "
                   f"rise/return angle" + (" (or move the pivot: the arm's start angle sets "
                   f"it)." if self.oscillating else " (an offset lowers it on one stroke, "
                   f"raises it on the other)."))
        else:
            msg = (f"pressure angle within {self.max_pressure_angle_deg:g} deg: largest "
                   f"|alpha| = {math.degrees(amax):.2f} deg at {math.degrees(at):.2f} deg")
        out.append(Check("pressure angle", not runs, math.degrees(at), math.degrees(amax),
                         self.max_pressure_angle_deg,
                         _span_degrees(runs), msg,
                         math.degrees(amax - sampled)))
        return tuple(out)

    def _undercut_checks(self, th):
        """A roller's walls: each cusps where 1 + d kappa_p < 0 (d = -r_r the profile or
        inner wall, +r_r the outer wall)."""
        rr = self.roller_radius
        walls = [("undercut", "profile" if not self.groove else "inner wall", -1.0)]
        if self.groove:
            walls.append(("undercut outer", "outer wall", +1.0))
        for name, wall, d in walls:
            # the wall p + d n runs backwards (a cusp) where 1 + d kappa_p < 0
            def g(x, d=d):
                return 1.0 + d * rr * self.curvature(x)
            bad = g(th) < 0
            runs = failing_spans(th, bad, lambda x: float(g(x)[0]))
            # worst: the largest curvature of that sign, i.e. the smallest |rho_p|
            at, k, k_sampled = self._worst(lambda x: -d * self.curvature(x), th)
            rho = 1.0 / k if k > 0 else math.inf
            rho_error = abs(rho - 1.0 / k_sampled) if k_sampled > 0 and k > 0 else 0.0
            shape = "convex" if d < 0 else "concave"
            if runs:
                spans = _span_text(runs)
                msg = (f"undercut: the {wall} cusps at cam angle {math.degrees(at):.2f} deg "
                       f"(fails for phi in {spans} deg): the pitch curve's radius of curvature "
                       f"on this {shape} part, down to {rho * 1e3:.4g} mm, is below the roller "
                       f"radius {rr * 1e3:.4g} mm. Use a larger base circle, a longer rise/return "
                       f"angle, a smaller stroke or a smaller roller.")
            elif math.isfinite(rho):
                msg = (f"no undercut of the {wall}: smallest {shape} |rho_p| = {rho * 1e3:.4g} mm "
                       f"at {math.degrees(at):.2f} deg > roller radius {rr * 1e3:.4g} mm")
            else:           # no part of that shape (a groove's outer wall on a convex pitch)
                msg = f"no undercut of the {wall}: the pitch curve has no {shape} part"
            yield self._with_velocity_jumps(
                Check(name, not runs, math.degrees(at), rho, rr, _span_degrees(runs), msg,
                      rho_error),
                "undercut: " + self._velocity_jump_text(wall, convex=d < 0))

    def _with_velocity_jumps(self, check: Check, text: str) -> Check:
        """The profile's check failed where the motion's velocity jumps (whatever its smooth
        parts give): the jumps join its intervals as points, the text leads its message."""
        if not self.velocity_jumps:
            return check
        at = [math.degrees(t) for t, _, _ in self.velocity_jumps]
        spans = tuple(sorted(check.intervals_deg + tuple((a, a) for a in at)))
        msg = text + (f". Besides, {check.message}" if not check.ok else "")
        return Check(check.name, False, check.worst_deg if not check.ok else at[0],
                     check.value, check.limit, spans, msg, check.error)

    def _cutter_check(self, th):
        """The cutter's centre, offset outwards by r_c, runs backwards (the cutter gouges the
        profile) where 1 + r_c kappa < 0: a concave part tighter than the cutter."""
        rc = self.cutter_radius

        def g(x):
            return 1.0 + rc * self.profile_curvature(x)
        runs = failing_spans(th, g(th) < 0, lambda x: float(g(x)[0]))
        at, k, k_sampled = self._worst(lambda x: -self.profile_curvature(x), th)
        rho = 1.0 / k if k > 0 else math.inf
        err = abs(rho - 1.0 / k_sampled) if k > 0 and k_sampled > 0 else 0.0
        if runs:
            spans = _span_text(runs)
            msg = (f"cutter: a cutter of radius {rc * 1e3:.4g} mm gouges the profile at cam "
                   f"angle {math.degrees(at):.2f} deg (for phi in {spans} deg), where the "
                   f"concave profile's radius of curvature is down to {rho * 1e3:.4g} mm. Use a "
                   f"smaller cutter.")
        else:
            msg = (f"cutter of radius {rc * 1e3:.4g} mm fits: "
                   + (f"smallest concave |rho| = {rho * 1e3:.4g} mm at {math.degrees(at):.2f} deg"
                      if math.isfinite(rho) else "the profile is convex throughout"))
        return Check("cutter", not runs, math.degrees(at), rho if math.isfinite(rho) else math.inf,
                     rc, _span_degrees(runs), msg, err)

    def _cusp_checks(self, th):
        """A flat face follows the profile only where the profile is convex: it cusps where
        its radius of curvature rho = k + d^2k/dtheta^2 is negative (translating face:
        r_b + s + s'')."""
        def rho(x):
            return 1.0 / self.profile_curvature(x)
        runs = failing_spans(th, rho(th) < 0, lambda x: float(rho(x)[0]))
        # worst: the least rho, most negative where it cusps
        at, neg, sampled = self._worst(lambda x: -rho(x), th)
        value, err = -neg, abs(neg - sampled)
        if runs:
            spans = _span_text(runs)
            msg = (f"cusp: the flat face cannot follow this motion, the profile cusps at cam "
                   f"angle {math.degrees(at):.2f} deg (its radius of curvature "
                   f"{'' if self.oscillating else 'r_b + s + s'' '}reaches {value * 1e3:.4g} mm; "
                   f"negative for phi in {spans} deg). Use a larger base circle, a longer "
                   f"rise/return angle or a smaller {'swing' if self.oscillating else 'stroke'}.")
        else:
            msg = (f"no cusp: the profile's smallest radius of curvature is {value * 1e3:.4g} mm "
                   f"at {math.degrees(at):.2f} deg")
        yield self._with_velocity_jumps(
            Check("cusp", not runs, math.degrees(at), value, 0.0, _span_degrees(runs), msg, err),
            "cusp: " + self._velocity_jump_text())

    @property
    def failures(self) -> list:
        return [c for c in self.checks if not c.ok]

    def extremes(self) -> dict:
        """The largest |alpha| (deg), the smallest |rho| of the pitch curve (rollers) and of
        the profile (m), and for a flat face where the contact travels on it (m), each
        refined on the closed-form profile between the samples around the sampled extreme,
        with its sampling error: how far the sampled extreme lay from the refined one, a
        bound of what the refinement could still be off by choosing among near-equal
        peaks."""
        th = self._grid()
        alpha = next(c for c in self.checks if c.name == "pressure angle")
        out = {"max_abs_pressure_angle_deg": alpha.value,
               "max_abs_pressure_angle_deg_error": alpha.error}

        def least_rho(curvature):
            _, kmax, sampled_k = self._worst(lambda x: np.abs(curvature(x)), th)
            rho = 1.0 / kmax if kmax > 0 else math.inf
            rho_sampled = 1.0 / sampled_k if sampled_k > 0 else math.inf
            return rho, abs(rho - rho_sampled) if math.isfinite(rho) else 0.0

        if self.roller:
            out["min_rho_pitch"], out["min_rho_pitch_error"] = least_rho(self.curvature)
        out["min_rho_profile"], out["min_rho_profile_error"] = least_rho(self.profile_curvature)
        if not self.roller:
            def w(x):
                return self.contact(x).face_position
            _, hi, hi_s = self._worst(w, th)
            _, lo, lo_s = self._worst(lambda x: -w(x), th)
            out["face_travel"] = [-lo, hi]
            out["face_width"] = hi + lo
            out["face_width_error"] = abs(hi - hi_s) + abs(lo - lo_s)
        return out

    def summary(self) -> dict:
        return {"law": self.law, "law_parameter": self.cam.law.par if self.law_parameter is not None else None,
                "return_law": self.return_law or self.law,
                "return_law_parameter": (self.cam.return_law.par if self.return_law_parameter
                                         is not None else None),
                "kind": "groove" if self.groove else "open",
                "follower": self.follower,
                "stroke": self.stroke, "base_radius": self.base_radius,
                "roller_radius": self.roller_radius, "offset": self.offset,
                "prime_radius": self.prime_radius,
                **({"pivot_distance": self.pivot_distance, "swing_deg": self.swing_deg,
                    "start_angle_deg": math.degrees(self.geometry.psi0),
                    **({"arm_length": self.arm_length} if self.roller
                       else {"face_offset": self.face_offset})}
                   if self.oscillating else {}),
                "angles_deg": dict(zip(("rise", "upper_dwell", "return", "lower_dwell"),
                                       self.angles_deg)),
                "points": int(self.phi.size),
                "cutter_radius": self.cutter_radius,
                **({"arc_tolerance": self.arc_tolerance,
                    "arcs": {layer: len(self.arcs(layer)) for layer in self._layers()}}
                   if self.arc_tolerance is not None else {}),
                **self.extremes(),
                "checks": [c.as_dict() for c in self.checks],
                "ok": not self.failures,
                "warnings": [c.message for c in self.failures] + self.law_warnings()}

    def law_warnings(self) -> list:
        """What the laws say of themselves (a rise from a table: how well it is known)."""
        from ..core.laws import Shaped

        laws = {_law("law", self.law, self.law_parameter)}
        if self.return_law is not None:
            laws.add(_law("return-law", self.return_law, self.return_law_parameter))
        return [w for law in laws if isinstance(law, Shaped) for w in law.warnings()]

    # -- writers -----------------------------------------------------------------------
    def write_csv(self, path) -> Path:
        path = Path(path)
        tab = self.table
        cols = list(tab)
        with writing(path), path.open("w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(cols)
            for row in zip(*(tab[c] for c in cols)):
                w.writerow([repr(float(v)) for v in row])
        return path

    def write_dxf(self, path) -> Path:
        """Closed LWPOLYLINEs in mm on layers PITCH, PROFILE (, PROFILE_OUTER), the base
        circle on BASE_CIRCLE.  Written by ezdxf."""
        import ezdxf
        from ezdxf import units

        path = Path(path)
        doc = ezdxf.new("R2010")
        doc.units = units.MM
        doc.header["$MEASUREMENT"] = 1
        colours = {"PITCH": 3, "PROFILE": 7, "PROFILE_OUTER": 5, "BASE_CIRCLE": 8, "CUTTER": 1}
        for name, colour in colours.items():
            if ((name == "PROFILE_OUTER" and not self.groove) or (name == "PITCH" and not self.roller)
                    or (name == "CUTTER" and self.cutter_radius is None)):
                continue
            doc.layers.add(name, color=colour)
        msp = doc.modelspace()
        tab = self.table
        curves = [("PROFILE", "x_profile", "y_profile")]
        if self.roller:
            curves.insert(0, ("PITCH", "x_pitch", "y_pitch"))
        if self.cutter_radius is not None:
            curves.append(("CUTTER", "x_cutter", "y_cutter"))
        if self.groove:
            curves.append(("PROFILE_OUTER", "x_outer", "y_outer"))
        for layer, x, y in curves:
            # the vertices set in one array (x, y, start width, end width, bulge): ezdxf's
            # add_lwpolyline appends them one by one, copying the array each time, which took
            # 38 s at 200 points a degree and would take minutes at the allowed 1000
            line = msp.add_lwpolyline([], close=True, dxfattribs={"layer": layer})
            if self.arc_tolerance is None:
                n = len(tab[x])
                line.lwpoints.set(np.column_stack([tab[x] * 1e3, tab[y] * 1e3, np.zeros((n, 3))]))
            else:
                arcs = self.arcs(layer)
                line.lwpoints.set(np.array([[a.start[0] * 1e3, a.start[1] * 1e3, 0.0, 0.0, a.bulge]
                                            for a in arcs]))
        msp.add_circle((0.0, 0.0), self.base_radius * 1e3, dxfattribs={"layer": "BASE_CIRCLE"})
        with writing(path):
            doc.saveas(path)
        return path

    def _layers(self) -> list:
        return ((["PITCH"] if self.roller else []) + ["PROFILE"]
                + (["CUTTER"] if self.cutter_radius is not None else [])
                + (["PROFILE_OUTER"] if self.groove else []))

    @cached_property
    def _fitted_arcs(self) -> dict:
        return {}

    def arcs(self, layer: str = "PROFILE") -> list:
        """The curve of a DXF layer (PROFILE, PITCH, CUTTER, PROFILE_OUTER) as tangent arcs
        within ``arc_tolerance`` of it (:func:`camdyn.runtime.cam.biarc.fit`), split at the
        motion's segment ends.  Every offset curve shares the profile's tangent.  Fitted once
        a layer (the JSON counts them, the DXF writes them)."""
        if layer not in self._fitted_arcs:
            self._fitted_arcs[layer] = self._fit_arcs(layer)
        return self._fitted_arcs[layer]

    @property
    def arc_tolerance_used(self) -> float:
        """How far (m) the arcs of :meth:`arcs` may stray from their curves."""
        return self.arc_tolerance if self.arc_tolerance is not None else ARC_TOLERANCE

    def _fit_arcs(self, layer: str) -> list:
        from .biarc import fit

        tol = self.arc_tolerance_used
        rr, rc = self.roller_radius or 0.0, self.cutter_radius or 0.0
        shift = {"PROFILE": 0.0, "PITCH": rr, "CUTTER": rc, "PROFILE_OUTER": 2 * rr}[layer]

        def curve(u):
            c = self.contact(u)
            n0, n1 = c.normal
            return np.array([c.x + shift * n0, c.y + shift * n1]), np.array([-n1, n0])
        # round a cusp (or a loop, a corner) the arcs shrink with the tolerance: 1934 arcs at
        # 0.1 mm, 18584 at 10 um round a flat face's cusp, past 200000 at 1 um, where the fit
        # ran for minutes; a profile that fails its undercut or cusp check gets CUSP_ARCS
        from .step import PROFILE_CHECKS

        failed = [c for c in self.checks if c.name in PROFILE_CHECKS and not c.ok]
        if not failed:
            return fit(curve, self.cam.breakpoints, tol)
        try:
            return fit(curve, self.cam.breakpoints, tol, max_arcs=CUSP_ARCS)
        except CamdynInputError:
            raise CamdynInputError(
                f"arcs={tol:g} m: the {layer} layer would take more than {CUSP_ARCS} tangent "
                f"arcs round the {failed[0].name} its check finds (cam angle "
                f"{failed[0].worst_deg:.2f} deg); give a coarser --arcs, or leave it out for "
                f"the sampled polylines") from None

    def write_png(self, path) -> Path:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        path = Path(path)
        tab = self.table
        fig = plt.figure(figsize=(12, 6))
        ax = fig.add_subplot(1, 2, 1)
        close = np.r_[np.arange(self.phi.size), 0]
        if self.roller:
            ax.plot(tab["x_pitch"][close] * 1e3, tab["y_pitch"][close] * 1e3, "g--", lw=0.8,
                    label="pitch curve")
        ax.plot(tab["x_profile"][close] * 1e3, tab["y_profile"][close] * 1e3, "k-", lw=1.2,
                label="profile" if not self.groove else "inner wall")
        if self.groove:
            ax.plot(tab["x_outer"][close] * 1e3, tab["y_outer"][close] * 1e3, "b-", lw=1.2,
                    label="outer wall")
        a = np.linspace(0, TWO_PI, 361)
        ax.plot(self.base_radius * 1e3 * np.cos(a), self.base_radius * 1e3 * np.sin(a), ":",
                color="0.5", lw=0.8, label="base circle")
        self._draw_follower(ax)
        for c in self.failures:
            w = math.radians(c.worst_deg)
            p = np.array(self.contact(w).pitch if self.roller else
                         (self.contact(w).x, self.contact(w).y))[:, 0] * 1e3
            ax.plot(p[0], p[1], "rx", ms=10)
        ax.set_aspect("equal")
        ax.set_xlabel("x, mm")
        ax.set_ylabel("y, mm")
        laws = self.law if self.return_law in (None, self.law) else f"{self.law}/{self.return_law}"
        ax.set_title(f"{laws}, {'groove' if self.groove else 'open'} cam, {self.follower}"
                     + ("" if self.oscillating else f", e = {self.offset * 1e3:g} mm"))
        ax.legend(fontsize=7, loc="upper right")
        phi = tab["phi_deg"]
        a1 = fig.add_subplot(2, 2, 2)
        a1.plot(phi, tab["alpha_deg"], "k-")
        for sgn in (1, -1):
            a1.axhline(sgn * self.max_pressure_angle_deg, color="r", ls="--", lw=0.8)
        a1.set_ylabel("pressure angle, deg")
        a1.grid(True, lw=0.3)
        a2 = fig.add_subplot(2, 2, 4, sharex=a1)
        reach = np.hypot(tab["x_pitch" if self.roller else "x_profile"],
                         tab["y_pitch" if self.roller else "y_profile"])
        span = 4 * float(np.max(reach)) * 1e3
        for key, style, lab in (("rho_pitch", "g--", "pitch"), ("rho_profile", "k-", "profile"),
                                ("rho_outer", "b-", "outer wall")):
            if key in tab:
                y = np.clip(tab[key] * 1e3, -span, span)
                y[1:][np.sign(tab[key][1:]) != np.sign(tab[key][:-1])] = np.nan  # through infinity
                a2.plot(phi, y, style, lw=1, label=lab)
        a2.axhline(0, color="0.5", lw=0.5)
        a2.set_ylim(-span, span)
        a2.set_ylabel("radius of curvature, mm (clipped)")
        a2.set_xlabel("cam angle phi, deg")
        a2.legend(fontsize=7)
        a2.grid(True, lw=0.3)
        ex = self.extremes()
        figures = {"largest |alpha| (deg)": (ex["max_abs_pressure_angle_deg"],
                                             ex["max_abs_pressure_angle_deg_error"]),
                   "smallest |rho_profile| (m)": (ex["min_rho_profile"],
                                                  ex["min_rho_profile_error"])}
        if self.roller:
            figures["smallest |rho_pitch| (m)"] = (ex["min_rho_pitch"], ex["min_rho_pitch_error"])
        else:
            figures["face width (m)"] = (ex["face_width"], ex["face_width_error"])
        fig.text(0.01, 0.01, chart_note(
            figures,
            [c.message for c in self.failures]) + " (the estimates: what the sampling leaves)",
            fontsize=7)
        fig.tight_layout(rect=(0, 0.04, 1, 1))
        with writing(path):
            fig.savefig(path, dpi=110)
        plt.close(fig)
        return path

    def _draw_follower(self, ax) -> None:
        """The follower at phi = 0 (cam frame = ground frame there): the roller, or the face
        over the width the contact travels, and an oscillating follower's arm and pivot."""
        a = np.linspace(0, TWO_PI, 361)
        c = self.contact(0.0)
        if self.roller:
            x0, y0 = c.pitch[0][0] * 1e3, c.pitch[1][0] * 1e3
            r = self.roller_radius * 1e3
            ax.plot(x0 + r * np.cos(a), y0 + r * np.sin(a), "r-", lw=0.8, label="roller at phi = 0")
            centre = (x0, y0)
        else:
            lo, hi = self.extremes()["face_travel"]
            x0, y0 = c.x[0] * 1e3, c.y[0] * 1e3
            w0 = c.face_position[0]
            # the face's direction at phi = 0: along the arm u (rocker) or +y (slide)
            if self.oscillating:
                psi = self.geometry.psi0
                d = np.array([-math.cos(psi), math.sin(psi)])
            else:
                d = np.array([0.0, 1.0])
            ends = np.array([(lo - w0) * 1e3, (hi - w0) * 1e3])
            ax.plot(x0 + ends * d[0], y0 + ends * d[1], "r-", lw=1.5, label="face at phi = 0")
            centre = (x0, y0)
        if self.oscillating:
            A = self.pivot_distance * 1e3
            ax.plot([A, centre[0]], [0.0, centre[1]], "r:", lw=0.8)
            ax.plot([A], [0.0], "r^", ms=6, label="pivot")

    def write_all(self, out_dir, stem: str = "cam") -> dict:
        out = out_folder(out_dir)
        return {"csv": str(self.write_csv(out / f"{stem}.csv")),
                "dxf": str(self.write_dxf(out / f"{stem}.dxf")),
                "png": str(self.write_png(out / f"{stem}.png"))}
