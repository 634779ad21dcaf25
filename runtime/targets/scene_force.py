"""The contact force along a cam from a dynamic run of a DYNACAM scene, for the contact
stress of `camdyn profile --contact-force-from SCENE`.

A DYNACAM radial cam (thesis ch. 6) lifts the roller's centre by h = h_m H(B) on the pitch
radius R = R_b + h with tan(alpha) = (dh/dbeta)/R (6.20), (6.21): the translating roller
follower without offset whose prime circle is R_b, so the profile is that of stroke h_m, base
circle R_b - r_r for a roller of radius r_r, and the scene's law over its full turn ([turn]).
The force the linkage takes from the cam along the follower, F_x (6.42), is the generalised
force Q of runtime/cam/load.py; the normal force is F_x / cos(alpha).  A reduced scene (sec.
2.4) gives the reduced cam and force.

The roller must be spring-held (a roller held on both sides, bilateral or in a groove, is
refused: its negative F_x loads the other wall).  Where its mode is "free" (it has lifted, sec.
7.5) the force is zero, and it is never below zero (the linkage damper's share makes F_x
negative for an instant as the roller leaves; a cam cannot pull).

The run's last full turn of the cam is used (the start's transient left behind): its cam angle
phi = beta_m B, B = (beta - beta_0)/beta_m the output "B" (6.17), taken modulo one turn, and
each phi found on the dense output by Newton's method on B(t) (B' = beta'/beta_m).  The same is
done on the run one notch tighter (the scene's error estimate): the figures' errors add the
difference it makes.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..cam.load import ForceHistory
from ..core.errors import CamdynInputError
from . import scene_files
from .dynacam import run_scene
from .resolve import load_scene, scene as scene_target


@dataclass(frozen=True)
class SceneForce:
    """The cam of a scene (CamProfile's keyword arguments), the force history of its run and,
    for the error estimate, that of its run one notch tighter (None if it has none)."""

    cam: dict
    history: ForceHistory
    tighter: ForceHistory | None


def load(name: str, roller_radius: float | None) -> SceneForce:
    """Check the scene ``name`` (a DYNACAM scene with a radial cam and a [turn]), run it and
    its tighter twin, and return its cam and force histories."""
    kind, sc = load_scene(name)
    if kind != scene_files.DYNACAM:
        raise CamdynInputError(f"contact-force-from takes a DYNACAM scene (kind \"dynacam\"); "
                               f"{name} is of kind {kind!r}")
    if sc.options.cam != "radial":
        raise CamdynInputError(f"contact-force-from: {name} has an {sc.options.cam} cam; the "
                               f"profile is that of a radial disk cam (options.cam = \"radial\")")
    if sc.options.roller != "contact":
        raise CamdynInputError(f"contact-force-from: the roller of {name} is held on both sides "
                               f"(options.roller = \"{sc.options.roller}\"), where a negative "
                               f"F_x loads the other wall; the stress along one profile needs a "
                               f"spring-held roller (options.roller = \"contact\")")
    if sc.turn is None:
        raise CamdynInputError(f"contact-force-from: {name} runs one rise and dwell; the force "
                               f"along the whole cam needs a full turn: add a [turn] table "
                               f"(upper_dwell, return in deg)")
    if roller_radius is None:
        raise CamdynInputError("contact-force-from needs the roller's radius: --roller-radius M")
    target = scene_target(name)
    p = target.prepared.params
    R_b = float(p["R_b"])
    if not 0.0 < roller_radius < R_b:
        raise CamdynInputError(f"roller-radius={roller_radius:g} is out of range: 0 < "
                               f"roller-radius < the scene's pitch radius R_b = {R_b:g} m")
    turn = sc.turn
    cam = dict(follower="translating-roller", stroke=float(p["h_m"]),
               base_radius=R_b - roller_radius, roller_radius=roller_radius, offset=0.0,
               angles_deg=scene_files.turn_angles(sc), law=sc.law, law_parameter=sc.theta,
               return_law=turn.get("return_law"),
               return_law_parameter=turn.get("return_theta"))
    first = _history(name, sc, target)
    tight = target.tighter()
    second = None if tight is None else _history(name, sc, tight)
    return SceneForce(cam, first, second)


def _history(name: str, sc, target) -> ForceHistory:
    res = run_scene(sc, prepared=target.prepared).result
    beta_m = float(res.params["beta_m"])
    period = 2.0 * math.pi / beta_m                 # one turn in units of B
    t, B = res.t, res["B"]
    if np.any(np.diff(B) < 0):
        raise CamdynInputError(f"contact-force-from: the cam of {name} turns backwards in its "
                               f"run; the force along the cam angle is not defined")
    if B[-1] - B[0] < period:
        need = sc.T_start + period + (sc.T_start - B[0])
        raise CamdynInputError(
            f"contact-force-from: the run of {name} covers {math.degrees((B[-1] - B[0]) * beta_m):.1f} "
            f"deg of the cam; the force along the whole profile needs a full turn: set run.T_end "
            f">= {need:.4g}")
    b0 = B[-1] - period
    where = (f"a run of {sc.title} (its last full turn, B {b0:.4g} to {B[-1]:.4g}, "
             f"method {target.method().name} at rtol {target.method().rtol:g})")
    free = res.element_mode("roller") == "free"

    def force(phi):
        phi = np.asarray(phi, dtype=float)
        b = b0 + np.mod(phi / beta_m - b0, period)
        tt = np.interp(b, B, t)
        for _ in range(4):                   # Newton on B(t) = b, B' = beta'/beta_m
            s = res.sample(tt)
            tt = np.clip(tt - (s["B"] - b) * beta_m / s["betad"], t[0], t[-1])
        # F_x (6.42) is the linkage's spring-damper force while the roller touches; where
        # the run's roller mode is "free" it has left the cam and carries nothing, and a cam
        # cannot pull (the damper's share makes F_x negative as the roller leaves)
        q = np.maximum(res.sample(tt)["Fx"], 0.0)
        return np.where(free[np.clip(np.searchsorted(t, tt, side="right") - 1, 0, len(t) - 1)],
                        0.0, q)

    return ForceHistory(where, force)


def with_run_error(stress: dict, tighter: dict | None) -> dict:
    """The stress summary of the run with each figure's error grown by the difference the
    tighter run makes (or a warning that there is none to compare with)."""
    out = dict(stress)
    if tighter is None:
        out["warnings"] = out["warnings"] + [
            "the contact force's run has no tighter twin: the figures' errors are the "
            "sampling's only"]
        return out
    for key in ("hertz_stress_max", "contact_force_max", "contact_force_min"):
        a, b = out.get(key), tighter.get(key)
        if a is not None and b is not None:
            out[key + "_error"] = out[key + "_error"] + abs(a - b)
    return out
