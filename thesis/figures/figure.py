"""The records of the figure registry: a :class:`Figure` names the figure as the thesis (or the
paper) numbers it, says in a short title of our own what it shows, lists the statements it
reproduces (:class:`Claim`, each a comparison of a live computed value with the printed one,
mostly the checks of :mod:`camdyn.thesis.checks`) and has a builder
``build(out_dir, quick) -> [png paths]``.  Figures the models cannot determine stay in the
registry with ``build=None`` and the reason in ``not_reproduced``, so the index says why they
are missing."""
from __future__ import annotations

import re
import string
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from camdyn.runtime.measure.contract import UNAVAILABLE
from camdyn.thesis.checks.check import Check

GROUPS = (("thesis", "Thesis figures (Koster, Vibrations of cam mechanisms)"),
          ("paper", "Paper: Rayleigh-beam follower of a roller cam (figs 4-9)"),
          ("design", "Design charts (thesis ch. 8, sec. 9.2.2; README, Designing a cam mechanism)"))
"""Sections of the index, in order: key, heading."""


@dataclass(frozen=True)
class Trend:
    """What a qualitative statement computed: its numbers, the words around them (``text``,
    one format field such as ``{:.3g}`` per number) and whether the statement holds."""

    text: str
    values: tuple
    holds: bool
    method: str = "dp54"    # the method of the runs behind the values, for their estimates

    def shown(self, estimates=None, why: str = "") -> str:
        """The text with the numbers filled in, each followed by "± its estimate" when
        ``estimates`` (one per number) are given."""
        out = []
        fields = iter(range(len(self.values)))
        for literal, name, spec, _ in string.Formatter().parse(self.text):
            out.append(literal)
            if name is None:
                continue
            i = next(fields)
            out.append(format(self.values[i], spec))
            if estimates is not None:
                out.append(plus_minus(estimates[i], why))
        return "".join(out)


def plus_minus(estimate, why: str = "") -> str:
    """" ± e" for an estimate, " (estimate unavailable: why)" without one."""
    if estimate is not None:
        return f" ± {estimate:.2g}"
    return f" ({UNAVAILABLE}: {why})" if why else f" ({UNAVAILABLE})"


@dataclass(frozen=True)
class Claim:
    """One statement a figure reproduces: a check of thesis/checks by key, or an ad-hoc
    :class:`~camdyn.thesis.checks.check.Check` (same rules), or a qualitative statement
    (``trend() -> Trend``, for the paper's "larger response for ...")."""

    check: str | Check | None = None
    trend: Callable[[], Trend] | None = None
    text: str = ""                    # the statement, for a trend (a check brings its own)
    reference: str = ""


@dataclass(frozen=True)
class ClaimResult:
    """A statement computed now: ``derived`` the value as compared with the printed one,
    ``shown`` the same with its error estimate (or "exact"), ``estimates`` the estimates,
    ``wide`` when one of them exceeds the half-width of the band the rule accepts
    (``tolerance``): then the agreement is not resolved by the runs."""

    text: str
    reference: str
    printed: str
    derived: str
    rule: str
    status: str
    passed: bool
    note: str = ""
    shown: str = ""
    estimates: tuple = ()
    exact: bool = False
    tolerance: float | None = None

    @property
    def wide(self) -> bool:
        return self.tolerance is not None and any(
            e is not None and e > self.tolerance for e in self.estimates)


@dataclass(frozen=True)
class Figure:
    id: str                 # as the source numbers it: "3.3", "4.11a", "paper 5", "laws"
    group: str              # a key of GROUPS
    caption: str            # a short title in our own words
    build: Callable[[Path, bool], list] | None
    claims: tuple = ()
    note: str = ""          # what is drawn differently from the source, readings taken
    not_reproduced: str = ""  # why, when build is None

    def __post_init__(self):
        if self.group not in dict(GROUPS):
            raise ValueError(f"figure {self.id}: unknown group {self.group!r}")
        if (self.build is None) != bool(self.not_reproduced):
            raise ValueError(f"figure {self.id}: a figure either has a builder or says why not")

    @property
    def slug(self) -> str:
        """File-name form of the id: "4.11a" -> "fig4_11a", "paper 5" -> "paper5"."""
        s = re.sub(r"[^0-9A-Za-z]+", "_", self.id).strip("_")
        if self.group == "thesis":
            return f"fig{s}"
        return s.replace("_", "") if self.group == "paper" else s


@dataclass
class Built:
    figure: Figure
    pngs: list = field(default_factory=list)
    pics: list = field(default_factory=list)      # the pngs relative to the index page
    claims: list = field(default_factory=list)
    seconds: float = 0.0
    error: str = ""

    @property
    def passed(self) -> bool:
        return not self.error and all(c.passed for c in self.claims)
