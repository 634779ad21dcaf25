"""Cam laws at run time: names, codes, parameters and breakpoints.

Reads the table written into the generated cam-law library, so simulating
never imports SymPy.  :func:`compose` strings a rise law, dwells and a return law into a
full cam turn (:class:`Turn`) that any model takes as its cam input, like a plain law.
"""
from __future__ import annotations

from dataclasses import dataclass

import math

import numpy as np

from camdyn.generated import camlaws as _lib

from . import shaped
from .errors import CamdynInputError
from .shaped import Shaped

LAWS = tuple(_lib.LAWS)
"""Every law of the generated library: key, code, its shape parameter (name, range, default)."""
NAMES = [law["key"] for law in sorted(LAWS, key=lambda l: l["code"])]
_BY_KEY = {law["key"]: law for law in _lib.LAWS}


@dataclass(frozen=True)
class LawChoice:
    """A cam law with its shape parameter fixed."""

    key: str
    code: int
    par: float

    def breakpoints(self) -> list[float]:
        return list(_lib.breakpoints(self.code, self.par))

    def breakpoints_between(self, lo: float, hi: float) -> list[float]:
        """Breakpoints b with lo < b < hi (the rise's, T in units of the rise)."""
        return [b for b in self.breakpoints() if lo < b < hi]

    def evaluate(self, T) -> np.ndarray:
        """Columns H, H', H'', H''' at the times T."""
        return _lib.evaluate(self.code, self.par, T)


def choose(key: str, theta: float | None = None) -> LawChoice:
    """Check a law name and its parameter; errors name the argument and the range.  A file
    name (.csv, .txt, .dat, .toml) is a rise shaped by the user (camdyn.runtime.core.shaped)."""
    if isinstance(key, Shaped):
        return key
    if isinstance(key, str) and shaped.is_law_file(key):
        if theta is not None:
            raise CamdynInputError(f"a shaped rise ({key}) has no shape parameter; drop theta")
        return shaped.load(key)
    if key not in _BY_KEY:
        raise CamdynInputError(f"unknown cam law {key!r}; choose one of {', '.join(NAMES)}")
    law = _BY_KEY[key]
    spec = law["parameter"]
    if spec is None:
        if theta is not None:
            raise CamdynInputError(f"the {key} law has no shape parameter; drop theta")
        return LawChoice(key, law["code"], 0.0)
    value = spec["default"] if theta is None else theta
    try:
        value = float(value)
    except (TypeError, ValueError, OverflowError):
        raise CamdynInputError(f"{spec['name']} must be a number, got {value!r}") from None
    if not spec["low"] < value < spec["high"]:
        raise CamdynInputError(
            f"{spec['name']}={value:g} is out of range: {spec['low']:g} < {spec['name']} < "
            f"{spec['high']:g} ({spec['doc']})")
    return LawChoice(key, law["code"], value)


@dataclass(frozen=True)
class Turn:
    """Dwell-rise-dwell-return over a full cam turn, repeated turn after turn.

    In units of the rise (the models' T = t/t_m, B = (beta - beta_0)/beta_m), the rise law
    runs over [0, 1), the upper dwell holds H = 1 to 1 + up, the return law runs backwards
    over a length r (H = 1 - H_ret((T - 1 - up)/r), so H^(n) = -H_ret^(n)/r^n), and the
    lower dwell holds H = 0 until the period P = 1 + up + r + low, where the next rise starts.
    For T < 0 the cam rests at H = 0 as before a plain rise.  The angles (deg) are those of
    :class:`camdyn.runtime.cam.profile.CamProfile`: rise, upper dwell, return, lower dwell,
    summing to 360.

    The generated library evaluates it (law code ``camlaws.TURN``); ``par`` is the slot that
    describes the turn in this process, registered on first use, so a Turn sent to another
    process registers itself there again."""

    rise: LawChoice
    ret: LawChoice
    angles_deg: tuple

    key = "turn"
    code = _lib.TURN

    @property
    def up(self) -> float:
        return self.angles_deg[1] / self.angles_deg[0]

    @property
    def r(self) -> float:
        return self.angles_deg[2] / self.angles_deg[0]

    @property
    def low(self) -> float:
        return self.angles_deg[3] / self.angles_deg[0]

    @property
    def period(self) -> float:
        """P = 360 deg over the rise angle, in units of the rise."""
        return 1.0 + self.up + self.r + self.low

    @property
    def par(self) -> float:
        return float(_lib.turn_slot(self.rise.code, self.rise.par, self.ret.code, self.ret.par,
                                    self.up, self.r, self.low))

    def breakpoints(self) -> list[float]:
        """Segment ends over the first turn, 0 to P: the rise's pieces, the start of the
        return and its pieces, the start of the lower dwell."""
        start = 1.0 + self.up
        pts = set(self.rise.breakpoints())
        pts |= {start + self.r * b for b in self.ret.breakpoints()}
        pts |= {start, self.period}
        return sorted(pts)

    def breakpoints_between(self, lo: float, hi: float) -> list[float]:
        """Every segment end b of the repeated turns with lo < b < hi."""
        one = self.breakpoints()
        P = self.period
        out = []
        for k in range(max(0, math.floor(lo / P)), math.floor(hi / P) + 1):
            out += [k * P + b for b in one if lo < k * P + b < hi]
        return sorted(set(out))

    def evaluate(self, T) -> np.ndarray:
        """Columns H, H', H'', H''' at the times T, from the generated library."""
        return _lib.evaluate(self.code, self.par, T)


def compose(rise: str = "cycloidal", ret: str | None = None, angles_deg=(90, 90, 90, 90),
            theta: float | None = None, ret_theta: float | None = None) -> Turn:
    """A :class:`Turn`: the rise law ``rise`` (shape parameter ``theta``), the return law
    ``ret`` (default: the rise law and its theta), angles rise, upper dwell, return, lower
    dwell in deg summing to 360 (dwells may be 0)."""
    if ret is None and ret_theta is not None:
        # the return is the rise law with the rise's theta: a ret_theta would be dropped
        raise CamdynInputError("return theta goes with a return law of its own (--return-law)")
    rise_law = choose(rise, theta)
    ret_law = rise_law if ret is None else choose(ret, ret_theta)
    try:
        ang = tuple(float(a) for a in angles_deg)
    except (TypeError, ValueError):
        raise CamdynInputError(f"turn angles must be numbers, got {angles_deg!r}") from None
    if len(ang) != 4:
        raise CamdynInputError(f"turn angles must be four values rise,upper dwell,return,lower "
                               f"dwell in deg, got {len(ang)}")
    names = ("rise", "upper dwell", "return", "lower dwell")
    for name, a in zip(names, ang):
        positive = name in ("rise", "return")
        if not math.isfinite(a) or (a <= 0 if positive else a < 0):
            raise CamdynInputError(f"turn angle ({name})={a:g} is out of range: it must be "
                                   f"{'> 0' if positive else '>= 0'} deg")
    if abs(sum(ang) - 360.0) > 1e-9:
        raise CamdynInputError(f"turn angles must sum to 360 deg (rise + upper dwell + return + "
                               f"lower dwell), got {sum(ang):g}")
    return Turn(rise_law, ret_law, ang)


CHOSEN = (LawChoice, Turn, Shaped)
"""What a model takes as the law of a cam input, chosen and checked."""


def orders_used(manifest: dict) -> int:
    """Highest derivative of H a model's equations use: from its cam inputs, H''' for a
    constrained model's cam profile (its curvature's rate), else H''."""
    orders = [inst.get("order", 2) for inst in manifest.get("cam_instances", [])]
    if orders:
        return max(orders)
    return 3 if manifest.get("cam_profile") else 2
