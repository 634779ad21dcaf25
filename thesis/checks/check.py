"""One comparison of camdyn with what the thesis prints, and how it is judged.

A :class:`Check` names the item, the thesis reference, the printed value (as
printed), how to compute camdyn's value and how to compare the two; :func:`run`
computes it and returns an :class:`Outcome`.

Comparison rules
    "digits"     derived value agrees with the printed one to its printed
                 digits (rounded or truncated, see :func:`matches_printed`)
    "rel:X"      relative difference at most X (values read from graphs,
                 "about" statements, ...)
    "abs:X"      absolute difference at most X
    "factor:X"   derived within a factor X of the printed value either way
    "identity"   a symbolic identity: compute() returns True when
                 sympy.simplify(derived - printed) == 0
Printed values the thesis gets wrong (misprints, scan errors that cannot be
read another way) are kept with ``errata=True``, an explanation, and the
value the thesis's own formulas give instead (``expected``, worked out from
the cited equations and stated in the note, with its tolerance
``expected_rule``).  Such a check passes only when camdyn's value agrees with
that derived value *and* does not reproduce the misprint under ``rule``: a
NaN, a zero, a wild value or the misprint itself all fail.

A value computed from runs of the compiled models carries the error of those runs; one that
is a closed form, a parameter or an identity says so (``exact``).  With ``estimate=True``
:func:`run` estimates it (:func:`error_estimate`): |v - v'|, v' the same value computed again
inside :func:`camdyn.runtime.core.methods.tightened`, where every run is one notch tighter
(rtol/10, or half the step with Richardson's factor 2^p/(2^p - 1)), unless the check's runs
carry estimates of their own (``estimate``).  Whether a check passes is judged on v alone;
:func:`tolerance` is the half-width of the band it accepts, and an estimate wider than that
band means the runs do not resolve the agreement (``Outcome.wide``).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass
from decimal import Decimal
from typing import Callable

from camdyn.runtime.core.methods import estimate_factor, tightened

@dataclass(frozen=True)
class Check:
    key: str
    item: str
    reference: str
    printed: str | None
    compute: Callable[[], object]
    rule: str = "digits"
    note: str = ""
    errata: bool = False
    expected: str | None = None
    expected_rule: str = ""
    exact: bool = False     # the value is a closed form or a parameter: no run, no run's error
    method: str = "dp54"    # the method of the runs behind the value, for its error estimate
    # the value's error estimate where its runs carry their own (the answer contract's);
    # else the value is computed again one notch tighter
    estimate: Callable[[], float] | None = None

    def __post_init__(self):
        if self.errata and (self.expected is None or not self.expected_rule):
            raise ValueError(f"{self.key}: an errata check states the value the thesis's own "
                             "formulas give (expected) and its tolerance (expected_rule)")
        if self.errata and _agrees(self.rule, float(self.expected), self.printed)[0]:
            raise ValueError(f"{self.key}: the derived value {self.expected} would reproduce the "
                             f"misprint {self.printed} under rule {self.rule}")


@dataclass(frozen=True)
class Outcome:
    check: Check
    derived: object
    rel_diff: float | None
    agrees: bool
    seconds: float
    error: str = ""
    expected_agrees: bool = True
    estimate: float | None = None   # the derived value's error estimate (0 where exact)
    estimated: bool = False         # whether one was asked for (run(..., estimate=True))
    estimate_why: str = ""          # why an estimate asked for could not be made

    @property
    def exact(self) -> bool:
        return is_exact(self.check)

    @property
    def wide(self) -> bool:
        """The estimate exceeds the half-width of the band the rule accepts: the runs do not
        resolve whether the value agrees."""
        tol = tolerance(self.check) if self.estimate is not None else None
        return tol is not None and self.estimate > tol

    @property
    def passed(self) -> bool:
        if self.error:
            return False
        if self.check.errata:
            return self.expected_agrees and not self.agrees
        return self.agrees

    @property
    def status(self) -> str:
        if self.error:
            return "ERROR"
        if self.check.errata:
            if self.passed:
                return "errata"
            return ("FAIL (misprint reproduced)" if self.agrees
                    else f"FAIL (not the derived {self.check.expected})")
        return "pass" if self.passed else "FAIL"

    def as_dict(self) -> dict:
        c = self.check
        return {"key": c.key, "item": c.item, "reference": c.reference, "printed": c.printed,
                "derived": _plain(self.derived), "rel_diff": self.rel_diff, "rule": c.rule,
                "status": self.status, "passed": self.passed, "note": c.note,
                "errata": c.errata, "expected": c.expected, "expected_rule": c.expected_rule or None,
                "derived_error": self.estimate, "error": self.error, "seconds": self.seconds,
                **({"estimate_unavailable": self.estimate_why} if self.estimate_why else {})}


def _plain(value):
    if isinstance(value, bool) or value is None:
        return value
    try:
        return float(value)
    except (TypeError, ValueError):
        return str(value)


def matches_printed(value: float, printed: str) -> bool:
    """Does ``value`` agree with a number printed in the thesis, to its printed digits?

    Accepts rounding and truncation at the last printed digit (the thesis
    truncates some values, e.g. 4 pi^2 = 39.478 printed as 39.4).  ``printed``
    may carry an exponent: "3.75e-4".
    """
    p = Decimal(printed)
    ulp = Decimal(1).scaleb(p.as_tuple().exponent)
    v = Decimal(repr(float(value)))
    rounded = abs(v - p) <= ulp / 2
    away = (v - p) if p > 0 else (p - v)  # how far |v| exceeds |p|
    truncated = p != 0 and Decimal(0) <= away < ulp
    return bool(rounded or truncated)


def _agrees(rule: str, value: float, reference: str | None) -> tuple[bool, float]:
    """(agrees, relative difference) of ``value`` with the number ``reference`` under ``rule``;
    a value that is not finite never agrees."""
    if reference is None:
        raise ValueError(f"rule {rule} needs a printed value")
    ref = float(reference)
    rel = abs(value - ref) / abs(ref) if ref != 0 else abs(value)
    if not math.isfinite(value):
        return False, rel
    if rule == "digits":
        return matches_printed(value, reference), rel
    kind, _, tol = rule.partition(":")
    if kind == "rel":
        return rel <= float(tol), rel
    if kind == "abs":
        return abs(value - ref) <= float(tol), rel
    if kind == "factor":
        ratio = value / ref
        return 1 / float(tol) <= ratio <= float(tol), rel
    raise ValueError(f"unknown rule {rule!r}")


def compare(check: Check, derived) -> tuple[bool, float | None]:
    """(agrees, relative difference) of a derived value with the printed one."""
    if check.rule == "identity":
        return bool(derived), None
    try:
        return _agrees(check.rule, float(derived), check.printed)
    except ValueError as exc:
        raise ValueError(f"{check.key}: {exc}") from None


def run(check: Check, estimate: bool = False) -> Outcome:
    """The check computed and judged; with ``estimate`` the derived value's error estimate
    too (:func:`error_estimate`)."""
    t0 = time.perf_counter()
    try:
        derived = check.compute()
        agrees, rel = compare(check, derived)
        expected_agrees = True
        if check.errata:
            expected_agrees = _agrees(check.expected_rule, float(derived), check.expected)[0]
    except Exception as exc:  # a check that cannot run is a failure, reported, not a crash
        return Outcome(check, None, None, False, time.perf_counter() - t0,
                       error=f"{type(exc).__name__}: {exc}")
    e, why = error_estimate(check, derived) if estimate else (None, "")
    return Outcome(check, derived, rel, agrees, time.perf_counter() - t0,
                   expected_agrees=expected_agrees, estimate=e, estimated=estimate,
                   estimate_why=why)


def is_exact(check: Check) -> bool:
    """The value is a closed form, a parameter or a symbolic identity: no run, no run's error."""
    return check.exact or check.rule == "identity"


def error_estimate(check: Check, derived) -> tuple[float | None, str]:
    """(the error estimate of ``derived`` (module doc), ""): 0 for an exact value; the check's
    own estimate where its runs carry one; else |derived - derived one notch tighter| times
    the method's factor.  (None, why) where no estimate can be made (a run already at the
    tightest rtol, a tighter run that fails): shown as such beside the value, the reason in a
    warning."""
    if is_exact(check):
        return 0.0, ""
    try:
        if check.estimate is not None:
            return float(check.estimate()), ""
        with tightened():
            tight = check.compute()
        return abs(float(derived) - float(tight)) * estimate_factor(check.method), ""
    except Exception as exc:     # no estimate is shown as such, beside the value
        return None, failure_reason(exc)


def failure_reason(exc: Exception) -> str:
    """Why a computation failed, in one line: the first line of its message, else the kind of
    failure."""
    return (str(exc).splitlines() or [type(exc).__name__])[0]


def tolerance(check: Check) -> float | None:
    """Half the width of the band of values ``check`` accepts around the printed value (around
    the value the thesis's formulas give, for an errata check): half the last printed digit
    for "digits", else what the rule allows on the tighter side; None for an identity."""
    rule, ref = ((check.expected_rule, check.expected) if check.errata
                 else (check.rule, check.printed))
    if rule == "identity" or ref is None:
        return None
    if rule == "digits":
        return float(Decimal(1).scaleb(Decimal(ref).as_tuple().exponent)) / 2
    kind, _, tol = rule.partition(":")
    x, r = float(tol), abs(float(ref))
    if kind == "rel":
        return x * r if r else x
    if kind == "abs":
        return x
    if kind == "factor":
        return r * (1 - 1 / x)
    raise ValueError(f"unknown rule {rule!r}")
