"""The normal force between cam and follower along the cam angle, for the contact stress.

Two sources:

* constant: a force F (N) given outright, e.g. the largest a dynamic run reports;
* kinetostatic: the follower driven rigidly through its motion m(phi) (lift s, or swing psi)
  at a constant cam speed omega, against its mass (or moment of inertia about the pivot), a
  return spring of rate k and a preload Q_0 at the bottom of the stroke: the generalised
  force along m is Q = M omega^2 m'' + k m + Q_0 (derivatives in phi; friction and gravity
  left out), and by virtual work the normal force is F_n = Q / lever, lever = n . dX/dm of
  :class:`camdyn.runtime.cam.follower.Contact` (1 for a translating face, cos alpha for a
  translating roller, the moment arm for a rocker).  Where F_n < 0 the spring cannot hold the
  follower on the cam at that speed: it leaves the cam (thesis sec. 7.5).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..core.errors import CamdynInputError
from .checks import in_range


@dataclass(frozen=True)
class ContactLoad:
    """A constant ``force`` (N), or the kinetostatic force at ``speed_rpm`` of a follower of
    ``mass`` (kg; a rocker's moment of inertia about its pivot, kg m^2) held by a spring of
    ``spring_rate`` (N/m; a rocker's N m/rad) with ``preload`` (N; N m) at the bottom."""

    force: float | None = None
    speed_rpm: float | None = None
    mass: float = 0.0
    spring_rate: float = 0.0
    preload: float = 0.0

    def __post_init__(self):
        if (self.force is None) == (self.speed_rpm is None):
            raise CamdynInputError("give the contact force either as a constant (contact-force) "
                                   "or through the cam speed (speed, with follower-mass, "
                                   "spring-rate, spring-preload), not both")
        if self.force is not None:
            in_range("contact-force", self.force, strict=True, high=1e9)
        else:
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

    def normal_force(self, M, lever) -> np.ndarray:
        """F_n (N) along the cam angle: constant, or Q / lever."""
        if self.constant:
            return np.full(np.shape(M[0]), float(self.force))
        return self.generalised(M) / lever

    def describe(self) -> str:
        if self.constant:
            return f"constant contact force {self.force:g} N"
        return (f"kinetostatic contact force at {self.speed_rpm:g} rpm (follower mass "
                f"{self.mass:g}, spring rate {self.spring_rate:g}, preload {self.preload:g})")
