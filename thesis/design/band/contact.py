"""The cam of one law under the spring's contact force: its profile, pressure angle, radius of
curvature and Hertz's contact pressure, as `camdyn profile` computes them for every follower
(runtime/cam/profile.py, follower.py, stress.py, load.py).

The force is the one the spring answer gives over the turn (:mod:`.spring`): the dynamic
contact force of the Ladder's model, the larger of the band's lowest and top speed's at each
cam angle (the inertia force grows as w^2 at each angle, so over the band it is largest at one
of the ends; the residual vibration's worst speed inside the band loads the cam less than the
top speed does wherever the top speed's force is the larger, and the top speed's dynamic force
is taken as the conservative one).  It is a force along the follower's motion at its output (a
rocker's roller arc), which `camdyn profile`'s load turns into the normal force through the
follower's lever (a translating roller's 1/cos alpha, a rocker's arm); a rocker's is given to it
as the torque at the pivot, F l.

Errors: each extreme's as `camdyn profile` states it (how far the sampled extreme lay from the
refined one); the Hertz pressure's adds the force's error, its estimate from the runs and its
linear interpolation between the cam angles it is given at (h^2/8 |F''|, from the second
differences), through p0 ~ F^(1/2): p0 ((1 + e_F/F)^(1/2) - 1) (runtime/cli/page.py's rule).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camdyn.runtime.cam.load import ContactLoad, ForceHistory
from camdyn.runtime.cam.profile import CamProfile
from camdyn.runtime.cam.stress import ContactSpec
from camdyn.runtime.core.errors import CamdynInputError

from .spec import Machine

POINTS_PER_DEGREE = 2
"""The profile's samples a degree: every extreme is refined between them on the closed-form
profile (CamProfile._worst), so two a degree give its figures to the refinement's accuracy, as
the design page takes it."""


@dataclass(frozen=True)
class ContactAnswer:
    """The cam of one law (module doc), SI (angles in deg), each figure's estimate in
    ``*_error``; ``ok`` flags of each check; arrays over the cam angle for the chart."""

    law: str
    pressure_angle_max_deg: float
    pressure_angle_max_deg_error: float
    pressure_angle_max_at_deg: float
    pressure_angle_ok: bool
    rho_min: float
    """The profile's least radius of curvature where it is convex (m; below 0 it is undercut
    or cusps, 0 at the corners of a law whose velocity jumps)."""
    rho_min_error: float
    rho_min_at_deg: float
    rho_min_pitch: float | None
    """A roller's pitch curve's least convex radius (m; inf where it is nowhere convex),
    undercut below the roller's."""
    rho_min_pitch_error: float | None
    undercut: bool
    hertz_stress_max: float | None
    hertz_stress_max_error: float | None
    hertz_stress_max_at_deg: float | None
    hertz_allowed: float | None
    hertz_ok: bool | None
    contact_kept: bool | None
    ok: bool
    theta_deg: np.ndarray
    x: np.ndarray
    y: np.ndarray
    pressure_angle_deg: np.ndarray
    stress: np.ndarray | None
    force: np.ndarray | None
    """The normal force (N) over theta_deg, the force the stress was computed from."""
    summary: dict
    """`camdyn profile`'s checks of the cam ("checks", "ok") and its stress summary
    ("stress")."""
    warnings: tuple


def profile(m: Machine, law, theta=None, points_per_degree: int = POINTS_PER_DEGREE
            ) -> CamProfile:
    """The machine's cam for ``law`` (its return the rise's law mirrored), `camdyn profile`'s."""
    kw = dict(base_radius=m.base_radius, angles_deg=tuple(m.angles), law=law,
              law_parameter=theta, follower=m.follower, points_per_degree=points_per_degree,
              max_pressure_angle_deg=m.max_pressure_angle)
    if m.roller:
        kw["roller_radius"] = m.roller_radius
    if m.rocker:
        kw.update(pivot_distance=m.pivot_distance, swing_deg=m.swing)
        if m.roller:
            kw["arm_length"] = m.arm_length
        else:
            kw["face_offset"] = m.face_offset
    else:
        kw.update(stroke=m.stroke, offset=m.offset)
    return CamProfile(**kw)


def _periodic(theta_deg, values):
    """phi (rad) -> values linearly interpolated over the turn (periodic in 360 deg)."""
    th = np.asarray(theta_deg, dtype=float)
    v = np.asarray(values, dtype=float)

    def at(phi):
        return np.interp(np.mod(np.degrees(np.asarray(phi, dtype=float)), 360.0), th, v,
                         period=360.0)
    return at


def interpolation_error(theta_deg, force) -> float:
    """The largest error of the force's linear interpolation between the angles it is given
    at: h^2/8 |F''| per interval, |F''| h^2 the second difference about its ends."""
    F = np.asarray(force, dtype=float)
    if F.size < 3:
        return 0.0
    dd = np.abs(F[2:] - 2 * F[1:-1] + F[:-2])
    spacing = np.diff(np.asarray(theta_deg, dtype=float))
    # uneven spacing: the second difference over the larger neighbour's square
    ratio = (np.maximum(spacing[1:], spacing[:-1]) / np.minimum(spacing[1:], spacing[:-1]))**2
    return float(np.max(dd * ratio)) / 8.0


def contact(m: Machine, law, force_theta_deg, force_N, theta=None,
            force_error_N=None) -> ContactAnswer:
    """The cam of ``law`` (module doc) under the contact force ``force_N`` (N, at the output,
    along the follower's motion) at the cam angles ``force_theta_deg`` (0 to 360 deg), with
    its estimate ``force_error_N`` (array or number) where known."""
    prof = profile(m, law, theta)
    checks = {c.name: c for c in prof.checks}
    summary = {"checks": [c.as_dict() for c in prof.checks], "ok": not prof.failures}
    warnings = [c.message for c in prof.failures] + prof.law_warnings()
    alpha = checks["pressure angle"]
    shape = checks["undercut" if m.roller else "cusp"]
    rho, rho_e = _least_radius(prof, shape)
    out = dict(law=law if isinstance(law, str) else getattr(law, "key", str(law)),
               pressure_angle_max_deg=alpha.value,
               pressure_angle_max_deg_error=alpha.error,
               pressure_angle_max_at_deg=alpha.worst_deg, pressure_angle_ok=alpha.ok,
               rho_min=rho, rho_min_error=rho_e, rho_min_at_deg=shape.worst_deg,
               rho_min_pitch=shape.value if m.roller else None,
               rho_min_pitch_error=shape.error if m.roller else None,
               undercut=not shape.ok)
    table = prof.table
    out.update(theta_deg=table["phi_deg"], x=table["x_profile"], y=table["y_profile"],
               pressure_angle_deg=table["alpha_deg"])
    stress = _hertz(m, prof, summary, force_theta_deg, force_N, force_error_N, warnings)
    out.update(stress)
    out["ok"] = bool(out["pressure_angle_ok"] and not out["undercut"]
                     and out["hertz_ok"] is not False and out["contact_kept"] is not False)
    return ContactAnswer(**out, warnings=tuple(dict.fromkeys(warnings)))


def _least_radius(prof: CamProfile, check) -> tuple[float, float]:
    """The profile's least convex radius (m) and its error: a roller's pitch curve's less the
    roller's radius (the undercut check's), a flat face's own (the cusp check's); 0 at the
    corners of a law whose velocity jumps (as `camdyn laws` gives it)."""
    if prof.velocity_jumps:
        return 0.0, 0.0
    if not math.isfinite(check.value):
        return math.inf, 0.0
    if prof.roller:
        return check.value - prof.roller_radius, check.error
    return check.value, check.error


def _hertz(m: Machine, prof: CamProfile, summary: dict, theta_deg, force, force_error,
           warnings) -> dict:
    """The Hertz pressure under the force over the turn (module doc), or None with a warning
    where the contact's length is not given."""
    none = dict(hertz_stress_max=None, hertz_stress_max_error=None, hertz_stress_max_at_deg=None,
                hertz_allowed=m.allowable_stress, hertz_ok=None, contact_kept=None, stress=None,
                force=None, summary=summary)
    if (m.roller and m.roller_width is None and m.cam_width is None) or \
            (not m.roller and m.cam_width is None):
        warnings.append("contact stress not computed: it needs the contact's length, "
                        + ("follower.roller_width (or cam.width)" if m.roller else "cam.width"))
        return none
    F = np.asarray(force, dtype=float)
    if F.shape != np.shape(theta_deg) or not np.all(np.isfinite(F)):
        raise CamdynInputError("the contact force must be finite and given at every cam angle")
    scale = m.lever if m.rocker else 1.0         # a rocker's load is its torque at the pivot
    Q = _periodic(theta_deg, F * scale)
    label = "the dynamic contact force over the turn (the larger of the band's ends)"
    spec = ContactSpec(ContactLoad(history=ForceHistory(label, Q)),
                       roller_width=m.roller_width if m.roller else None,
                       cam_width=m.cam_width, materials=tuple(m.materials),
                       crown_radius=m.crown_radius if m.roller else None,
                       allowable=m.allowable_stress)
    ss = prof.stress_summary(spec)
    warnings += [w for w in ss["warnings"]]
    normal, p0 = prof.contact_stress(prof.phi, spec)
    checks = {c["check"]: c for c in ss["checks"]}
    kept = checks.get("contact kept", {}).get("ok")
    p, at = ss["hertz_stress_max"], ss["hertz_stress_max_angle_deg"]
    out = dict(none, hertz_stress_max_at_deg=at, stress=p0, force=normal, contact_kept=kept,
               summary={**summary, "stress": ss})
    if p is None:
        return out
    e_force = interpolation_error(theta_deg, F)
    if force_error is not None:
        e_given = np.broadcast_to(np.asarray(force_error, dtype=float), F.shape)
        if not np.all(np.isfinite(e_given)):
            warnings.append("contact stress: the contact force has no error estimate (no run "
                            "one notch tighter): the stress's is the sampling's only")
            e_given = np.zeros(F.shape)
        e_force += float(_periodic(theta_deg, e_given)(np.radians([at]))[0])
    F_at = float(_periodic(theta_deg, F)(np.radians([at]))[0])
    grow = e_force / F_at if F_at > 0 else math.inf
    error = ss["hertz_stress_max_error"] + p * (math.sqrt(1.0 + grow) - 1.0)
    ok = None if m.allowable_stress is None else bool(p <= m.allowable_stress)
    out.update(hertz_stress_max=p, hertz_stress_max_error=error, hertz_ok=ok)
    return out
