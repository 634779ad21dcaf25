"""The cam's drive over the speed band: the peak torque the camshaft delivers at the top speed
and the flywheel that keeps its speed within the machine's fluctuation (ch. 5).

Torque.  By virtual work (friction left out) the cam delivers the follower's force along its
motion times the cam's slope, whatever the follower,

    M(theta) = F(T) dx/dtheta = F(T) h_m' H'(T)/beta_m,     F = F0 + k x + m x''

(T = theta/beta_m; a rocker's force and motion at its roller's arc give its torque about the
pivot times dpsi/dtheta, the same product).  Kinetostatic: the rigid follower, x = h_m' H,
x'' = h_m' H'' w^2/beta_m^2, exact at every angle; dynamic: the Ladder's model over one turn
from rest at the top speed (:func:`.spring.turn_run`, its cam slope H' read off the run).  The
peak is the larger |M| of the two; a negative M is the follower driving the cam back (the
return).

Flywheel (ch. 5).  The energy the cam gives and takes back over a turn swings by dE
(:func:`..spring_flywheel.flywheel`: the output's kinetic energy, the train's elastic energy
and the spring's); a camshaft of inertia J at w keeps within C_s = (w_max - w_min)/w = dE/(J
w^2).  Kinetostatic, dE/w^2 = swing of (m (h_m' H'/beta_m)^2/2 + (F0 x + k x^2/2)/w^2), a swing of
functions linear in 1/w^2 and so convex in it: over the band the largest J lies at one of its
ends.  Both ends are sized kinetostatically (the law's closed form), and the binding one again
with the Ladder's model (the vibration's energy too); the flywheel is the larger of the two
there.

Errors: the runs' (the run one notch tighter, times the contract's factor: the largest
difference of the two runs' torques over the turn bounds their peaks' difference) and what the
refinement leaves; the preload's error moves M by at most e_F0 max |h_m' H'/beta_m| and the
energy swing by e_F0 (max x - min x) (flywheel()'s).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..spring_flywheel import LawMotion, Motions, RunMotion, flywheel
from . import spring as band_spring
from .spec import Machine


@dataclass(frozen=True)
class DriveAnswer:
    """The drive of one law (module doc), SI, each figure's estimate in ``*_error`` (None: no
    estimate, said in ``warnings``)."""

    law: str
    speed: float
    torque_max: float
    """The peak |M| (N m) at the top speed, the larger of the kinetostatic and dynamic ones."""
    torque_max_error: float | None
    torque_max_at_deg: float
    torque_max_kinetostatic: float
    torque_max_kinetostatic_error: float
    torque_max_dynamic: float
    torque_max_dynamic_error: float | None
    flywheel_inertia: float | None
    """J (kg m^2) for the machine's speed fluctuation (None without it)."""
    flywheel_inertia_error: float | None
    flywheel_inertia_kinetostatic: float | None
    flywheel_inertia_kinetostatic_error: float | None
    flywheel_speed: float | None
    """The band's end (rad/s) the flywheel is sized at."""
    energy_swing: float | None
    energy_swing_error: float | None
    theta_deg: np.ndarray
    torque: np.ndarray
    """M (N m) over theta_deg at the top speed, dynamic."""
    torque_kinetostatic: np.ndarray
    warnings: tuple


def drive(m: Machine, law, ladder, spring_preload_N: float, theta=None,
          spring_preload_error: float | None = 0.0) -> DriveAnswer:
    """The drive of ``law`` on the machine ``m`` with the spring's preload ``spring_preload_N``
    (N at the output; its estimate ``spring_preload_error``) (module doc)."""
    w_lo, w_hi = m.speeds
    turn = band_spring.cam_turn(m, law, theta)
    F0 = float(spring_preload_N)
    eF0 = spring_preload_error
    warnings = []
    top = band_spring.turn_run(m, law, theta, ladder, w_hi)
    slope_max = _slope_max(m, turn)
    kin, kin_e, kin_T = _torque_kinetostatic(m, turn, w_hi, F0)
    dyn, dyn_e, dyn_T = _torque_dynamic(m, top, F0)
    if eF0 is None:
        warnings.append("drive torque: the preload has no error estimate")
    else:
        kin_e += eF0 * slope_max
        dyn_e = None if dyn_e is None else dyn_e + eF0 * slope_max
    if dyn_e is None:
        warnings.append(f"drive torque: no error estimate of the dynamic torque ({top.why})")
    use_dyn = dyn >= kin
    theta_deg = np.linspace(0.0, 360.0, band_spring.THETA_POINTS)
    T = theta_deg / m.angles[0]
    fly = (_flywheel(m, law, theta, ladder, turn, F0, eF0, warnings)
           if m.speed_fluctuation is not None else {})
    return DriveAnswer(
        law=band_spring.law_name(law), speed=w_hi,
        torque_max=dyn if use_dyn else kin, torque_max_error=dyn_e if use_dyn else kin_e,
        torque_max_at_deg=(dyn_T if use_dyn else kin_T) * m.angles[0],
        torque_max_kinetostatic=kin, torque_max_kinetostatic_error=kin_e,
        torque_max_dynamic=dyn, torque_max_dynamic_error=dyn_e,
        flywheel_inertia=fly.get("J"), flywheel_inertia_error=fly.get("J_error"),
        flywheel_inertia_kinetostatic=fly.get("J_kinetostatic"),
        flywheel_inertia_kinetostatic_error=fly.get("J_kinetostatic_error"),
        flywheel_speed=fly.get("speed"), energy_swing=fly.get("energy_swing"),
        energy_swing_error=fly.get("energy_swing_error"), theta_deg=theta_deg,
        torque=_run_torque(m, top.result, top.t_m, F0, band_spring.at_cam(top.result, T)),
        torque_kinetostatic=_law_torque(m, turn, w_hi, F0, T), warnings=tuple(warnings))


# -- the torque ----------------------------------------------------------------------------------

def _law_torque(m: Machine, turn, w: float, F0: float, T) -> np.ndarray:
    """M = F h_m' H'/beta_m of the rigid follower at the speed w (N m)."""
    H = turn.motion(T)
    return (band_spring.law_force(m, turn, w, F0, T) * m.output_stroke * H[1]
            / m.rise_angle)


def _run_torque(m: Machine, result, t_m: float, F0: float, T) -> np.ndarray:
    """M = F h_m' H'/beta_m along a run, its cam slope H' (Hd) read off the run (N m)."""
    T = np.clip(T, result.t[0], result.t[-1])
    s = result.sample(T)
    h = m.output_stroke
    F = band_spring.force_of(m, F0, s["X"] * h, s["Xdd"] * h / t_m**2)
    return F * h * s["Hd"] / m.rise_angle


def _slope_max(m: Machine, turn) -> float:
    """max |dx/dtheta| = h_m' max |H'|/beta_m over the turn (the preload's lever on M)."""
    grid = np.concatenate([np.linspace(a, b, 401) for a, b in turn.pieces()])
    return float(np.max(np.abs(turn.motion(grid)[1]))) * m.output_stroke / m.rise_angle * 1.001


def _torque_kinetostatic(m: Machine, turn, w: float, F0: float) -> tuple:
    """(peak |M|, what its refinement leaves, T there) of the rigid follower at w."""
    grid = np.concatenate(LawMotion(turn, stroke=1.0, t_m=1.0).grids)
    v, e, T = band_spring.least(lambda t: -np.abs(_law_torque(m, turn, w, F0, t)), grid)
    return -v, e, T


def _torque_dynamic(m: Machine, run, F0: float) -> tuple:
    """(peak |M|, its error or None, T there) of a run of the Ladder's model: on its recorded
    points refined on its dense output; the error the contract's factor times the largest
    difference of the two runs' torques over the turn, and the refinement's."""
    grid = np.asarray(run.result.t, dtype=float)

    def g(t):
        return -np.abs(_run_torque(m, run.result, run.t_m, F0, t))
    v, e, T = band_spring.least(g, grid)
    if run.tight is None:
        return -v, None, T
    diff = np.max(np.abs(_run_torque(m, run.tight, run.t_m, F0, grid)
                         - _run_torque(m, run.result, run.t_m, F0, grid)))
    return -v, run.factor * float(diff) + e, T


# -- the flywheel --------------------------------------------------------------------------------

def _flywheel(m: Machine, law, theta, ladder, turn, F0, eF0, warnings) -> dict:
    """The flywheel for the machine's fluctuation (module doc): the binding end of the band
    kinetostatically, then the Ladder's model there; the larger J of the two."""
    h, mass, k = m.output_stroke, m.output_mass, m.output_spring_rate
    kw = dict(mass=mass, stroke=h, beta_m=m.rise_angle, stiffness=m.output_stiffness,
              fluctuation=m.speed_fluctuation, preload=F0,
              preload_error=0.0 if eF0 is None else eF0, rate=k)
    ends = {}
    for w in sorted(set(m.speeds)):
        law_motion = LawMotion(turn, stroke=h, t_m=m.rise_angle / w)
        rigid = Motions(turn, law_motion, law_motion, None, "", [])
        ends[w] = flywheel(rigid, t_m=m.rise_angle / w, w_s=w, **kw)
    w = max(ends, key=lambda x: ends[x]["J"])
    kin = ends[w]
    run = band_spring.turn_run(m, law, theta, ladder, w)
    motions = Motions(turn, None, RunMotion(run.result, stroke=h, t_m=run.t_m),
                      None if run.tight is None else RunMotion(run.tight, stroke=h, t_m=run.t_m),
                      "one turn from rest", [])
    dyn = flywheel(motions, t_m=run.t_m, w_s=w, **kw)
    pick = dyn if dyn["J"] >= kin["J"] else kin
    if pick["J_error"] is None:
        warnings.append("flywheel: no error estimate of the dynamic energy swing (no run one "
                        "notch tighter)")
    if m.has_camshaft:
        warnings.append("flywheel: the energy swing is the follower train's and its spring's; "
                        "the camshaft's own elastic energy is left out")
    return {"J": pick["J"], "J_error": pick["J_error"], "J_kinetostatic": kin["J"],
            "J_kinetostatic_error": kin["J_error"], "speed": w,
            "energy_swing": pick["energy_swing"], "energy_swing_error": pick["energy_swing_error"]}
