"""One check for the numbers a cam design takes: a finite value within a stated range, else
one line naming the input and the range."""
from __future__ import annotations

import math

from ..core.errors import CamdynInputError


MIN_WIDTH = 1e-6
"""The thinnest contact line and plate (m) a cam takes, the widths of roller and cam and the
STEP plate's thickness: a micrometre, as the least radius (profile.py MIN_RADIUS); a
force per length over a thinner line overflows a double in Hertz's pressure, and the CAD
kernel finds no solid in a thinner plate."""


def in_range(name: str, value, low: float = 0.0, *, strict: bool = False,
             high: float | None = None, high_open: bool = False) -> float:
    """``value`` as a float, finite and >= low (> low with ``strict``) and <= high (< high with
    ``high_open``); otherwise CamdynInputError naming ``name`` and the range."""
    try:
        value = float(value)
    except (TypeError, ValueError):
        raise CamdynInputError(f"{name} must be a number, got {value!r}") from None
    above = value > low if strict else value >= low
    below = high is None or (value < high if high_open else value <= high)
    if not (math.isfinite(value) and above and below):
        rng = f"{'>' if strict else '>='} {low:g}"
        if high is not None:
            rng += f" and {'<' if high_open else '<='} {high:g}"
        raise CamdynInputError(f"{name}={value:g} is out of range: it must be finite and {rng}")
    return value
