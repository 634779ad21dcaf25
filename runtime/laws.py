"""Cam laws at run time: names, codes, parameters and breakpoints.

Reads the table written into the generated cam-law library, so simulating
never imports SymPy.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camdyn.generated import camlaws as _lib

from .errors import CamdynInputError

NAMES = [law["key"] for law in sorted(_lib.LAWS, key=lambda l: l["code"])]
_BY_KEY = {law["key"]: law for law in _lib.LAWS}


@dataclass(frozen=True)
class LawChoice:
    """A cam law with its shape parameter fixed."""

    key: str
    code: int
    par: float

    def breakpoints(self) -> list[float]:
        return list(_lib.breakpoints(self.code, self.par))

    def evaluate(self, T) -> np.ndarray:
        """Columns H, H', H'', H''' at the times T."""
        return _lib.evaluate(self.code, self.par, T)


def choose(key: str, theta: float | None = None) -> LawChoice:
    """Check a law name and its parameter; errors name the argument and the range."""
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
