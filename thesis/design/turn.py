"""The cam's motion the follower spring is sized over: the rise alone (then the dwell, the
check run's span), or the whole turn (rise, outer dwell, return, inner dwell) at the angles
`camdyn profile` takes.

The turn is the runtime's :class:`camdyn.runtime.core.laws.Turn` (``compose``), the motion
`camdyn profile` draws the cam from and every model takes as its cam input: in units of the
rise, T = phi/beta_m, the rise over [0, 1), the outer dwell to 1 + up, the return (the rise's
law mirrored) over a length r, the inner dwell to the period P = 360 deg/beta_m.  Its H,
H', H'' are the law's closed forms, so the kinetostatic motion of a rigid follower,
x = h_m' H, x'' = h_m' H''/t_m^2, is exact at every T, and the check run's model driven by
the turn gives the same motion with the follower's elasticity (:mod:`.spring_flywheel`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camdyn.runtime.core import laws
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.targets.model_target import DEFAULT_T_END

PARTS = ("rise", "outer dwell", "return", "inner dwell")
"""The parts of a turn, in the order the cam meets them."""

RISE_ONLY_END = DEFAULT_T_END
"""The end of the rise alone's span: the check run's, the rise and two rise times of dwell."""

ANGLES_HELP = ("rise,outer dwell,return,inner dwell in deg, summing to 360, as camdyn profile "
               "takes them")


def angles_argument(text) -> tuple | None:
    """--angles 'R,D,F,D' (deg) as four floats, None for None; the refusal names the option."""
    if text is None:
        return None
    try:
        ang = tuple(float(a) for a in str(text).split(","))
    except ValueError:
        raise CamdynInputError(f"argument --angles: must be four numbers, {ANGLES_HELP}; got "
                               f"{text!r}") from None
    if len(ang) != 4:
        raise CamdynInputError(f"argument --angles: must be four numbers, {ANGLES_HELP}; got "
                               f"{len(ang)} in {text!r}")
    try:                # the turn's own checks (runtime/core/laws.py compose), before any other
        laws.compose("cycloidal", None, ang)
    except CamdynInputError as exc:
        raise CamdynInputError(f"argument --angles: {exc}") from None
    return ang


def rise_angle(angles_deg, cam_angle_rad, rise_time, speed_rpm) -> float | None:
    """beta_m (rad) for the machine (App. 7 (8)): --cam-angle's, or with a speed and no rise
    time --angles' rise; one line where --angles' rise differs from --cam-angle (or from
    t_m w_s of a rise time and a speed)."""
    if angles_deg is None:
        return cam_angle_rad
    rise = math.radians(angles_deg[0])
    given, flag = cam_angle_rad, "--cam-angle"
    if given is None and rise_time is not None and speed_rpm is not None:
        given, flag = rise_time * 2 * math.pi * speed_rpm / 60.0, "--rise-time with --speed"
    if given is not None and not math.isclose(given, rise, rel_tol=1e-9, abs_tol=0.0):
        raise CamdynInputError(f"argument --angles: its rise, {angles_deg[0]:g} deg, differs from "
                               f"{flag} ({math.degrees(given):.6g} deg): give the rise once "
                               "(--angles alone sets the cam angle of the rise)")
    if cam_angle_rad is not None or (speed_rpm is not None and rise_time is None):
        return rise
    return None         # t_m given (or none): the machine forms beta_m, or needs none


@dataclass(frozen=True)
class CamTurn:
    """The span the spring is sized over and the law driving it: the rise alone (``turn``
    None: the law, then the dwell at H = 1 to T = 3) or one whole ``turn`` from rest."""

    law: object
    """The rise's LawChoice (or a shaped rise)."""
    turn: laws.Turn | None = None
    beta_m: float | None = None
    """The cam angle of the rise (rad), for the cam angles of the answer; None if unknown."""

    @classmethod
    def of(cls, law: str, theta, angles_deg=None, beta_m=None) -> "CamTurn":
        """The rise alone, or the whole turn at ``angles_deg`` (the rise's law mirrored for the
        return); refusals name --angles."""
        rise = laws.choose(law, theta)
        if angles_deg is None:
            return cls(rise, None, beta_m)
        try:
            turn = laws.compose(law, None, angles_deg, theta)
        except CamdynInputError as exc:
            raise CamdynInputError(f"argument --angles: {exc}") from None
        return cls(rise, turn, beta_m)

    @property
    def whole(self) -> bool:
        return self.turn is not None

    @property
    def end(self) -> float:
        """The span's end, T: one period P for the turn, else RISE_ONLY_END."""
        return self.turn.period if self.whole else RISE_ONLY_END

    @property
    def drive(self):
        """What drives the models' cam input over the span: the turn, or the rise's law."""
        return self.turn if self.whole else self.law

    def starts(self) -> tuple:
        """T where each part of PARTS starts (the rise alone: its dwell is the outer one)."""
        if not self.whole:
            return (0.0, 1.0, math.inf, math.inf)
        t = self.turn
        return (0.0, 1.0, 1.0 + t.up, 1.0 + t.up + t.r)

    def part(self, T: float) -> str:
        """The part of the turn T lies in."""
        starts = self.starts()
        k = max(i for i, s in enumerate(starts) if T >= s) if T >= 0 else 0
        return PARTS[k] if self.whole or k else "rise"

    def pieces(self) -> list:
        """(lo, hi) spans of T between the law's segment ends over the span: within each, H''
        is smooth (the law's closed form); it may jump from one to the next."""
        ends = set(self.drive.breakpoints()) | {0.0, 1.0, self.end}
        ends = sorted(b for b in ends if 0.0 <= b <= self.end)
        return [(a, b) for a, b in zip(ends[:-1], ends[1:]) if b > a]

    def motion(self, T) -> np.ndarray:
        """Rows H, H', H'' of the cam at T (units of the rise), the law's closed forms."""
        T = np.asarray(T, dtype=float)
        if self.whole:
            return self.turn.evaluate(T)[:, :3].T
        H = self.law.evaluate(np.minimum(T, 1.0))[:, :3].T.copy()
        H[:, T >= 1.0] = [[1.0], [0.0], [0.0]]
        return H

    def where(self, T: float, t_m: float | None) -> dict:
        """Where T lies: its part, the cam angle (rad) and the time (s), where known."""
        return {"part": self.part(T), "T": T,
                "cam_angle": None if self.beta_m is None else T * self.beta_m,
                "time": None if t_m is None else T * t_m}

    def describe(self) -> dict:
        """The span for the answer: whole turn or the rise alone, its angles (rad)."""
        if not self.whole:
            return {"whole_turn": False, "angles": None, "T_end": self.end}
        return {"whole_turn": True, "angles": [math.radians(a) for a in self.turn.angles_deg],
                "T_end": self.end}
