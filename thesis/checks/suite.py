"""The suite of comparisons with the thesis: every check of the topic modules
(``<topic>_checks.py``, each with ``checks() -> list[Check]``), chosen by topic and key.
``camdyn check`` runs it and prints a table; the test suite runs the same registry
(tests/test_checks.py), so the command and the tests cannot drift apart."""
from __future__ import annotations

from camdyn.runtime.core.errors import CamdynInputError
from camdyn.thesis.registry import CHECKS

from . import check
from .check import Check, Outcome

TOPICS = CHECKS.topics
"""The topics, in the order the table lists them."""


def registry(topics=TOPICS) -> list[Check]:
    """All checks of the given topics, keys unique."""
    return CHECKS.entries(topics)


def select(topics=None, k: str | None = None) -> list[Check]:
    """The checks of ``topics`` (default: all) whose key contains ``k``; an unknown topic is a
    CamdynInputError naming --topic."""
    topics = TOPICS if not topics else tuple(topics)
    unknown = sorted(set(topics) - set(TOPICS))
    if unknown:
        raise CamdynInputError(f"argument --topic: unknown topic {unknown[0]!r}; choose from "
                               f"{', '.join(TOPICS)}")
    return [c for c in registry(topics) if not k or k in c.key]


def run(checks: list[Check], progress=None, estimate: bool = True) -> list[Outcome]:
    """The outcome of every check, in order, each derived value with its error estimate
    (``estimate``); ``progress(i, n, check)`` is called before the i-th of n."""
    outcomes = []
    for i, c in enumerate(checks, 1):
        if progress:
            progress(i, len(checks), c)
        outcomes.append(check.run(c, estimate))
    return outcomes
