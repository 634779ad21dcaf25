"""The statements beside a figure, computed now against the printed values, each with its error.

A statement's value v comes from runs of the compiled models, or is a closed form or a
parameter and then exact.  Its error estimate is |v - v'|, v' the same value computed again
inside :func:`camdyn.runtime.core.methods.tightened`, where every run is one notch tighter:
rtol/10, or half the step with Richardson's factor 2^p/(2^p - 1)
(runtime/core/methods.py).  Whether the statement is reproduced is judged on v alone, as
`camdyn check` judges it; an estimate larger than the band the rule accepts is flagged, for
then the runs do not resolve the agreement.  A statement read from figures that carry their
own estimates (the answer contract's, a sweep's) states its estimate from them instead.
"""
from __future__ import annotations

from dataclasses import replace

from camdyn.runtime.core.methods import estimate_factor, tightened
from camdyn.thesis.checks import check as checks

from .figure import Claim, ClaimResult, plus_minus


def evaluate(claim: Claim, checks_by_key: dict) -> ClaimResult:
    """Compute the claim's value now, compare it with the printed one and estimate its error."""
    if claim.trend is not None:
        return _trend(claim)
    c = claim.check if isinstance(claim.check, checks.Check) else checks_by_key[claim.check]
    o = checks.run(c, estimate=True)
    derived = o.error or fmt(o.derived)
    result = ClaimResult(c.item, c.reference, c.printed or "(symbolic)", derived, c.rule,
                         o.status, o.passed, c.note, shown=derived,
                         tolerance=checks.tolerance(c))
    if o.error:
        return result
    if checks.is_exact(c):
        return replace(result, shown=f"{derived} (exact)", exact=True)
    return replace(result, shown=derived + plus_minus(o.estimate, o.estimate_why),
                   estimates=(o.estimate,))


def _trend(claim: Claim) -> ClaimResult:
    try:
        t = claim.trend()
    except Exception as exc:     # reported in the index, not a crash of the whole build
        error = f"{type(exc).__name__}: {exc}"
        return ClaimResult(claim.text, claim.reference, "(trend)", error, "trend", "ERROR",
                           False, shown=error)
    try:
        with tightened():
            tight = claim.trend()
        es = tuple(abs(a - b) * estimate_factor(t.method)
                   for a, b in zip(t.values, tight.values))
        why = ""
    except Exception as exc:     # the values stand, without estimates, saying why
        es = (None,) * len(t.values)
        why = checks.failure_reason(exc)
    return ClaimResult(claim.text, claim.reference, "(trend)", t.shown(), "trend",
                       "pass" if t.holds else "FAIL", t.holds, shown=t.shown(es, why),
                       estimates=es)


def fmt(v) -> str:
    """A computed value as the index shows it: four significant digits."""
    if isinstance(v, bool) or v is None:
        return str(v)
    try:
        return f"{float(v):.4g}"
    except (TypeError, ValueError):
        return str(v)
