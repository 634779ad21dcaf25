"""One rule for the units of a machine's values: a number is in SI units (m, kg, N/m, N, Pa,
N m/rad, kg m^2, rad/s), but an angle, which is in degrees; a string carries its own unit
("25 mm", "2e6 N/m", "1200 MPa", "120 deg", "300:600 rpm").  Strings are read by Pint, a
well-kept units library (loaded only when a string with a unit is given: it takes about half a
second to import).  A speed in Hz (or any unit of 1/time) is revolutions per second, as a
designer means it, not radians per second.
"""
from __future__ import annotations

import math
from functools import lru_cache

from camdyn.runtime.core.errors import CamdynInputError

SI = {"length": ("m", "[length]"), "mass": ("kg", "[mass]"),
      "stiffness": ("N/m", "[mass] / [time] ** 2"), "force": ("N", "[length] * [mass] / [time] ** 2"),
      "stress": ("Pa", "[mass] / [length] / [time] ** 2"),
      "torque": ("N*m", "[length] ** 2 * [mass] / [time] ** 2"),
      "torsional stiffness": ("N*m/rad", "[length] ** 2 * [mass] / [time] ** 2"),
      "inertia": ("kg*m**2", "[length] ** 2 * [mass]"),
      "angle": ("deg", ""), "speed": ("rad/s", "1 / [time]"), "ratio": ("", "")}
"""Each kind of quantity: the unit a bare number is in, and Pint's dimensionality."""


@lru_cache(maxsize=1)
def registry():
    import pint

    return pint.UnitRegistry(cache_folder=":auto:")


def _number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def value(raw, kind: str, key: str) -> float:
    """``raw`` (a number, or a string with or without a unit) in SI (an angle in degrees, a
    speed in rad/s), finite; a CamdynInputError naming ``key`` otherwise."""
    unit, _ = SI[kind]
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise CamdynInputError(f"{key} must be a number or a value with its unit "
                               f"(e.g. '{_example(kind)}'), got {raw!r}")
    if isinstance(raw, str):
        bare = _number(raw.strip())
        v = bare if bare is not None else _parse(raw, kind, key)
    else:
        v = float(raw)
    if not math.isfinite(v):
        raise CamdynInputError(f"{key}={raw!r} is not a finite number")
    return v


def _example(kind: str) -> str:
    return {"length": "25 mm", "mass": "0.8 kg", "stiffness": "2e6 N/m", "force": "50 N",
            "stress": "1200 MPa", "torque": "0.8 N m", "torsional stiffness": "2000 N m/rad",
            "inertia": "0.0039 kg m^2", "angle": "120 deg", "speed": "300 rpm",
            "ratio": "0.05"}[kind]


def _parse(text: str, kind: str, key: str) -> float:
    import pint

    unit, _ = SI[kind]
    u = registry()
    try:
        q = u.Quantity(text.strip())
    except (pint.errors.PintError, ValueError, TypeError, AttributeError, SyntaxError,
            KeyError, ZeroDivisionError, AssertionError):    # ":" fails an assertion of Pint's
        raise CamdynInputError(f"{key}={text!r}: not a number with a unit (e.g. "
                               f"'{_example(kind)}')") from None
    try:
        if kind == "speed":
            return _speed(q)
        if kind == "ratio":
            return float(q.to("dimensionless").magnitude)
        return float(q.to(unit).magnitude)
    except pint.errors.DimensionalityError:
        raise CamdynInputError(f"{key}={text!r}: {q.units:~} is no unit of {kind} (e.g. "
                               f"'{_example(kind)}')") from None


def _speed(q) -> float:
    """rad/s of a speed: rpm, rad/s, deg/s as they are, Hz and 1/s as revolutions per second."""
    names = str(q.units)
    if any(a in names for a in ("radian", "degree", "revolution", "turn")):
        return float(q.to("rad/s").magnitude)
    return float(q.to("1/s").magnitude) * 2 * math.pi


def band(raw, key: str = "speed") -> tuple[float, float, str]:
    """A speed band 'LO:HI UNIT' (or one speed 'V UNIT', or [LO, HI] in rad/s) as (lo, hi)
    rad/s and the unit to print them in (rpm unless rad/s or Hz were given)."""
    if isinstance(raw, (list, tuple)) and len(raw) == 2:
        lo, hi = (value(x, "speed", key) for x in raw)
        return _ordered(lo, hi, key, raw), "rad/s"
    if not isinstance(raw, (str, int, float)) or isinstance(raw, bool):
        raise CamdynInputError(f"{key} must be a speed or a band LO:HI with its unit "
                               f"(e.g. '300:600 rpm'), got {raw!r}")
    text = str(raw).strip()
    shown = ("rad/s" if "rad" in text else "Hz" if text.lower().endswith("hz") else "rpm")
    if ":" not in text:
        v = value(text if _number(text) is None else text, "speed", key)
        return (_ordered(v, v, key, raw), shown if _number(text) is None else "rad/s")
    lo_text, _, hi_text = text.partition(":")
    unit = "".join(c for c in hi_text if not (c.isdigit() or c in ".eE+-")).strip() \
        if _number(hi_text.strip()) is None else ""
    number = hi_text.strip()[:len(hi_text.strip()) - len(unit)].strip() if unit else hi_text
    if _number(lo_text.strip()) is None or _number(str(number).strip()) is None:
        raise CamdynInputError(f"{key}={raw!r}: a band is LO:HI with one unit after it "
                               f"(e.g. '300:600 rpm')")
    try:
        lo = value(f"{lo_text.strip()} {unit}" if unit else lo_text.strip(), "speed", key)
        hi = value(f"{str(number).strip()} {unit}" if unit else str(number).strip(), "speed",
                   key)
    except CamdynInputError:
        raise CamdynInputError(f"{key}={raw!r}: {unit!r} is no unit of speed (rpm, rad/s, Hz; "
                               f"e.g. '300:600 rpm')") from None
    return _ordered(lo, hi, key, raw), (shown if unit else "rad/s")


def _ordered(lo: float, hi: float, key: str, raw) -> tuple[float, float]:
    if not (0 < lo <= hi):
        raise CamdynInputError(f"{key}={raw!r}: the speeds must be positive, the lowest first")
    return lo, hi


def speed_in(w: float, unit: str) -> float:
    """A speed w (rad/s) in ``unit`` (rpm, rad/s, Hz: revolutions per second)."""
    return {"rpm": w * 60 / (2 * math.pi), "rad/s": w, "Hz": w / (2 * math.pi)}[unit]
