"""Error estimates of headline figures (issue 13, item 4).

A figure without its accuracy is half an answer.  Every command that prints headline figures
(``residual``, ``simulate``, ``beam-follower``, ``integrate``) runs the same problem a second
time one notch more accurately and reports, next to each figure v, the estimate of its global
error from the difference with the second run's v':

* adaptive methods (dp54, rodas4): the second run at rtol/10 and atol/10.  With the error of a run
  roughly proportional to its tolerance, v' carries a tenth of v's error, and |v - v'|
  estimates v's error to within about 10 %;
* fixed-step methods (rk4, the thesis's scheme): the second run at half the step, and
  Richardson's estimate |v - v'| 2^p/(2^p - 1) with the method's order p (4 for RK4, 2 for
  the thesis's scheme, whose acceleration is held at its mid-step value (4.23)-(4.31)).

The estimate needs the error to be in the asymptotic range (smooth dependence on the
tolerance or step); a run near a stability limit or a figure that jumps (an event that
appears in one run and not in the other) gives an estimate that means little, and such a
figure's estimate is as large as its change between the runs, which flags it.
tests/test_accuracy.py checks on CAMSHAFT-1 that the estimates bound the true error, against
a tight reference, within a factor of 10.  ``--no-error-estimate`` skips the second run
(sweeps).
"""
from __future__ import annotations

import math
from dataclasses import replace

ORDER = {"rk4": 4, "koster": 2}
"""Order of the fixed-step methods, for Richardson's factor 2^p/(2^p - 1)."""

RTOL_MIN = 1e-14
"""The tightest rtol a method accepts: a run there has no tighter neighbour to compare with."""


RTOL_DEFAULT = 1e-8
"""The adaptive methods' rtol when none is given (runtime/methods.py)."""


def tighter_settings(method: str, rtol: float | None, step: float | None) -> tuple:
    """(rtol, step) of the second run: rtol/10 for an adaptive method (dp54, rodas4; its
    default rtol when None), step/2 for a fixed one.  None when rtol is already the tightest
    allowed."""
    if method in ORDER:
        return None, step / 2
    rtol = RTOL_DEFAULT if rtol is None else rtol
    if rtol / 10 < RTOL_MIN:
        return None
    return rtol / 10, None


def tighter_method(method):
    """The method object of the second run (see :func:`tighter_settings`), or None."""
    settings = tighter_settings(method.name, getattr(method, "rtol", None),
                                getattr(method, "step", None))
    if settings is None:
        return None
    rtol, step = settings
    if method.adaptive:
        return replace(method, rtol=rtol, atol=None if method.atol is None else method.atol / 10)
    return replace(method, step=step)


def plus_minus(e) -> str:
    """" ± e" for a text table, or "" without a number."""
    return f" ± {e:.2g}" if _number(e) else ""


def factor(method_name: str) -> float:
    """Multiplier of |v - v'|: Richardson's 2^p/(2^p - 1) for fixed steps, 1 otherwise."""
    p = ORDER.get(method_name)
    return 1.0 if p is None else 2.0**p / (2.0**p - 1.0)


def _number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def errors(base: dict, tight: dict | None, keys, method_name: str) -> dict:
    """``{key + "_error": estimate}`` for every key of ``keys`` that is a number in ``base``;
    None where the second run could not be made or lacks the figure."""
    f = factor(method_name)
    out = {}
    for key in keys:
        if key not in base or not _number(base[key]):
            continue
        if tight is None or not _number(tight.get(key)):
            out[f"{key}_error"] = None
        else:
            out[f"{key}_error"] = abs(base[key] - tight[key]) * f
    return out


def with_errors(figures: dict) -> list:
    """Lines "name  value ± e" for a text table, the *_error keys folded into the line of
    their figure."""
    rows = []
    keys = [k for k in figures if not (k.endswith("_error") and k[:-6] in figures)]
    width = max((len(k) for k in keys), default=0)
    for k in keys:
        v = figures[k]
        text = f"{v:.6g}" if isinstance(v, float) else f"{v}"
        e = figures.get(f"{k}_error")
        if _number(e):
            text += plus_minus(e)
        elif f"{k}_error" in figures:
            text += " (no error estimate)"
        rows.append(f"{k:<{width}}  {text}")
    return rows
