"""Residual-vibration figures of a run (thesis sec. 3.3, fig. 4.11).

U0     amplitude of the positional error u = X - H after the rise (3.5)
U0dd   amplitude of the residual acceleration after the rise (3.6)
Xdd_min_rise, T_at_Xdd_min
       the most negative acceleration during the rise and its instant (fig. 4.11b)

Each is an extreme on the dense output (runtime/measure/extremes.py) and carries the sampling
error of the scan that found it; where the dwell was stepped over exactly and the model has
two states (one-DOF, CAMSHAFT-1), U0 and U0'' come in closed form from the state at the end
of the rise instead, with no sampling error.  The model's manifest names the outputs ("error",
"acceleration") and where the rise ends ("rise_end", or the time its "rise_state" reaches it).
"""
from __future__ import annotations

from dataclasses import dataclass, field

from ..core.errors import CamdynInputError
from .extremes import (crossing_time, dwell_closed_form, extreme, extreme_reference, place_error,
                       first_crossing)

FIGURES = ("U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min")
"""The residual-vibration figures, in the order every table gives them."""


@dataclass(frozen=True)
class ResidualVibration:
    U0: float
    U0dd: float
    Xdd_min_rise: float
    T_at_Xdd_min: float
    sampling: dict = field(default_factory=dict, compare=False)
    """The sampling error of each figure found by a scan (runtime/measure/extremes.py)."""

    def as_dict(self) -> dict:
        return {k: getattr(self, k) for k in FIGURES}


def rise_end(result, spec: dict) -> float:
    """End of the rise: the spec's rise_end, or the time its rise_state reaches it."""
    if not spec.get("rise_state"):
        return spec["rise_end"]
    return first_crossing(result, spec["rise_state"], spec["rise_end"])


def residual(result) -> ResidualVibration:
    """U0, U0dd, Xdd_min_rise, T_at_Xdd_min of a run that covers the rise and a dwell."""
    return _residual(result, extreme, rise_end)


def residual_reference(result) -> ResidualVibration:
    """:func:`residual` through the Python and SciPy reference of the extremes."""
    def end(res, spec):
        if spec.get("rise_state"):
            return crossing_time(res, spec["rise_state"], spec["rise_end"])
        return spec["rise_end"]

    return _residual(result, extreme_reference, end)


def _residual(result, extreme, rise_end) -> ResidualVibration:
    spec = result.model.manifest.get("residual")
    if not spec:
        raise CamdynInputError(f"model {result.model.name} declares no residual-vibration outputs")
    t0, t_end = result.t[0], result.t[-1]
    t1 = rise_end(result, spec)
    if not (t0 <= 0.0 and t_end > t1):
        raise CamdynInputError(
            f"the run must cover the rise [0, {t1:g}] and part of the dwell after it "
            f"(it covers [{t0:g}, {t_end:g}])")
    closed = dwell_closed_form(result, spec, t1) if extreme is not extreme_reference else None
    if closed is not None:
        U0, U0dd = closed
    else:
        U0 = extreme(result, spec["error"], t1, t_end, absolute=True, minimum=False)
        U0dd = extreme(result, spec["acceleration"], t1, t_end, absolute=True, minimum=False)
    xmin = extreme(result, spec["acceleration"], max(t0, 0.0), t1, absolute=False, minimum=True)
    return ResidualVibration(U0=U0.value, U0dd=U0dd.value, Xdd_min_rise=xmin.value,
                             T_at_Xdd_min=xmin.at,
                             sampling={"U0": U0.sampling_error, "U0dd": U0dd.sampling_error,
                                       "Xdd_min_rise": xmin.sampling_error,
                                       "T_at_Xdd_min": place_error(xmin.at)})
