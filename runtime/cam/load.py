"""The normal force between cam and follower along the cam angle, for the contact stress.

Three sources:

* constant: a force F (N) given outright, e.g. the largest a dynamic run reports;
* kinetostatic: the follower driven rigidly through its motion m(phi) (lift s, or swing psi)
  at a constant cam speed omega, against its mass (or moment of inertia about the pivot), a
  return spring of rate k and a preload Q_0 at the bottom of the stroke: the generalised
  force along m is Q = M omega^2 m'' + k m + Q_0 (derivatives in phi; friction and gravity
  left out), and by virtual work the normal force is F_n = Q / lever, lever = n . dX/dm of
  :class:`camdyn.runtime.cam.follower.Contact` (1 for a translating face, cos alpha for a
  translating roller, the moment arm for a rocker).  Where F_n < 0 the spring cannot hold the
  follower on the cam at that speed: it leaves the cam (thesis sec. 7.5);
* a history: the generalised force Q along the cam angle from a dynamic run (a
  :class:`ForceHistory`, e.g. the force F_x (6.42) of a DYNACAM scene over its last full turn,
  runtime/targets/scene_force.py), turned into F_n = Q / lever as above.  Where Q <= 0 the
  follower has left the cam in that run.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ..core.errors import CamdynInputError
from .checks import in_range


@dataclass(frozen=True)
class ForceHistory:
    """The generalised force Q along the follower's motion (N; a rocker's N m) at the cam
    angles phi (rad, the rise starting at 0, periodic in 2 pi), as a dynamic run gave it."""

    label: str
    """What run it is, for the reports."""
    force: Callable
    """phi (array, rad) -> Q (array)."""


@dataclass(frozen=True)
class ContactLoad:
    """A constant ``force`` (N), the kinetostatic force at ``speed_rpm`` of a follower of
    ``mass`` (kg; a rocker's moment of inertia about its pivot, kg m^2) held by a spring of
    ``spring_rate`` (N/m; a rocker's N m/rad) with ``preload`` (N; N m) at the bottom, or the
    ``history`` of a dynamic run."""

    force: float | None = None
    speed_rpm: float | None = None
    mass: float = 0.0
    spring_rate: float = 0.0
    preload: float = 0.0
    history: ForceHistory | None = None

    def __post_init__(self):
        if sum(v is not None for v in (self.force, self.speed_rpm, self.history)) != 1:
            raise CamdynInputError("give the contact force one way: as a constant "
                                   "(contact-force), through the cam speed (speed, with "
                                   "follower-mass, spring-rate, spring-preload), or from a "
                                   "dynamic run (contact-force-from)")
        if self.force is not None:
            in_range("contact-force", self.force, strict=True, high=1e9)
        elif self.speed_rpm is not None:
            in_range("speed", self.speed_rpm, strict=True, high=1e6)
            in_range("follower-mass", self.mass, high=1e6)
            in_range("spring-rate", self.spring_rate, high=1e12)
            in_range("spring-preload", self.preload, high=1e9)

    @property
    def constant(self) -> bool:
        return self.force is not None

    @property
    def omega(self) -> float:
        """Cam speed, rad/s."""
        return 2.0 * math.pi * self.speed_rpm / 60.0

    def generalised(self, M) -> np.ndarray:
        """Q = M omega^2 m'' + k m + Q_0 along the motion rows M = (m, m', m'')."""
        return self.mass * self.omega**2 * M[2] + self.spring_rate * M[0] + self.preload

    def normal_force(self, M, lever, phi) -> np.ndarray:
        """F_n (N) at the cam angles phi (motion rows M = (m, m', m'') there): constant, or
        Q / lever."""
        if self.constant:
            return np.full(np.shape(M[0]), float(self.force))
        if self.history is not None:
            return self.history.force(np.asarray(phi, dtype=float)) / lever
        return self.generalised(M) / lever

    def leaves_where(self) -> str:
        """Where a force that falls to zero says the follower leaves the cam (the checks)."""
        if self.history is not None:
            return f"in {self.history.label}"
        return f"at {self.speed_rpm:g} rpm"

    def describe(self) -> str:
        if self.constant:
            return f"constant contact force {self.force:g} N"
        if self.history is not None:
            return f"contact force of {self.history.label}"
        return (f"kinetostatic contact force at {self.speed_rpm:g} rpm (follower mass "
                f"{self.mass:g}, spring rate {self.spring_rate:g}, preload {self.preload:g})")
