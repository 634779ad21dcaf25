"""Every figure the models determine, in one registry: ``camdyn figures`` (issue 14, item 7).

A :class:`Figure` names the figure as the thesis (or the paper) numbers it, says in a short
title of our own what it shows, lists the statements it reproduces (:class:`Claim`, each a
comparison of a live computed value with the printed one, mostly the checks of
:mod:`camdyn.thesis.checks`) and has a builder ``build(out_dir, quick) -> [png paths]``.
Figures the models cannot determine stay in the registry with ``build=None`` and the reason
in ``not_reproduced``, so the index says why they are missing.

The topic modules (ch3.py ... design.py) each define ``figures() -> list[Figure]``; adding a
figure is one entry there.  :func:`build` draws the chosen figures and evaluates their claims,
:mod:`.index` writes the HTML page.
"""
from __future__ import annotations

import importlib
import re
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from ..checks import Check

GROUPS = (("thesis", "Thesis figures (Koster, Vibrations of cam mechanisms)"),
          ("paper", "Paper: Rayleigh-beam follower of a roller cam (figs 4-9)"),
          ("design", "Design charts (issue 14, items 1-6)"))
"""Sections of the index, in order: key, heading."""

TOPICS = ("ch3", "ch4", "ch5", "ch7", "ch8", "app2", "measured", "paper", "design")
"""Topic modules of this package, in the order the index lists them."""


@dataclass(frozen=True)
class Claim:
    """One statement a figure reproduces: a check of thesis/checks by key, or an ad-hoc
    :class:`~camdyn.thesis.checks.Check` (same rules), or a qualitative statement
    (``trend() -> (what was computed, holds)``, for the paper's "larger response for ...")."""

    check: str | Check | None = None
    trend: Callable[[], tuple[str, bool]] | None = None
    text: str = ""                    # the statement, for a trend (a check brings its own)
    reference: str = ""


@dataclass(frozen=True)
class ClaimResult:
    text: str
    reference: str
    printed: str
    derived: str
    rule: str
    status: str
    passed: bool
    note: str = ""


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


def _order(fig: Figure) -> tuple:
    """Thesis figures by chapter and number (appendices after the chapters), the rest as
    listed: "8.10" after "8.9", "A.5.7" after "8.10", "4.11a" after "4.10"."""
    if fig.group != "thesis":
        return (1,)
    parts = re.findall(r"[A-Z]|\d+|[a-z]", fig.id)
    appendix = parts[0] == "A"
    return (0, appendix) + tuple((int(p), "") if p.isdigit() else (0, p) for p in parts[appendix:])


def registry(topics=TOPICS) -> list[Figure]:
    """All figures of the given topic modules, ids unique; thesis figures in the thesis's
    order, the others as their modules list them."""
    out, seen = [], set()
    for topic in topics:
        module = importlib.import_module(f"{__name__}.{topic}")
        for fig in module.figures():
            if fig.id in seen:
                raise ValueError(f"figure id {fig.id!r} used twice")
            seen.add(fig.id)
            out.append(fig)
    return sorted(out, key=_order)


def select(figures: list[Figure], only) -> list[Figure]:
    """The figures whose id is in ``only`` (ids as listed; "4.11" also picks 4.11a-c,
    "paper" every paper figure), in registry order; every name must match something.  None
    selects all; an empty selection (--only "" or ",") is refused rather than drawing all."""
    if only is None:
        return list(figures)
    if not only:
        from camdyn.runtime.errors import CamdynInputError

        raise CamdynInputError("argument --only: no figure id given; give ids such as 3.3,4.11 "
                               "or thesis, paper, design (or leave --only out for all)")
    chosen, unknown = [], []
    for name in only:
        hits = [f for f in figures if f.id == name or f.group == name
                or (f.id.startswith(name) and f.id[len(name):].isalpha())]
        if not hits:
            unknown.append(name)
        chosen += hits
    if unknown:
        from camdyn.runtime.errors import CamdynInputError

        raise CamdynInputError(f"argument --only: unknown figure {unknown[0]!r}; choose from "
                               f"{', '.join(f.id for f in figures)}, or thesis, paper, design")
    keep = {id(f) for f in chosen}
    return [f for f in figures if id(f) in keep]


def evaluate(claim: Claim, checks_by_key: dict) -> ClaimResult:
    """Compute the claim's value now and compare it with the printed one."""
    from .. import checks

    if claim.trend is not None:
        try:
            shown, holds = claim.trend()
        except Exception as exc:   # reported in the index, not a crash of the whole build
            return ClaimResult(claim.text, claim.reference, "(trend)", f"{type(exc).__name__}: "
                               f"{exc}", "trend", "ERROR", False)
        return ClaimResult(claim.text, claim.reference, "(trend)", shown, "trend",
                           "pass" if holds else "FAIL", holds)
    c = claim.check if isinstance(claim.check, Check) else checks_by_key[claim.check]
    o = checks.run(c)
    derived = o.error or _fmt(o.derived)
    return ClaimResult(c.item, c.reference, c.printed or "(symbolic)", derived, c.rule,
                       o.status, o.passed, c.note)


def _fmt(v) -> str:
    if isinstance(v, bool) or v is None:
        return str(v)
    try:
        return f"{float(v):.4g}"
    except (TypeError, ValueError):
        return str(v)


def checks_by_key(figures: list[Figure]) -> dict:
    """The thesis checks by key; every key a figure names must exist."""
    from .. import checks

    by_key = {c.key: c for c in checks.registry(checks.TOPICS)}
    for fig in figures:
        for cl in fig.claims:
            if isinstance(cl.check, str) and cl.check not in by_key:
                raise ValueError(f"figure {fig.id}: no check {cl.check!r} in thesis/checks")
    return by_key


def build_one(fig: Figure, out_dir, quick: bool, by_key: dict) -> Built:
    """Draw one figure and evaluate its claims; a builder that fails is reported in
    Built.error (the index shows it), not raised, so the other figures are still built."""
    b = Built(fig)
    t0 = time.perf_counter()
    if fig.build is not None:
        try:
            b.pngs = [str(p) for p in fig.build(Path(out_dir), quick)]
        except Exception as exc:
            b.error = f"{type(exc).__name__}: {exc}"
    b.claims = [evaluate(cl, by_key) for cl in fig.claims]
    b.seconds = time.perf_counter() - t0
    return b


def build(figures: list[Figure], out_dir, quick: bool = False) -> list[Built]:
    """Draw each figure into ``out_dir`` and evaluate its claims."""
    Path(out_dir).mkdir(parents=True, exist_ok=True)
    by_key = checks_by_key(figures)
    return [build_one(fig, out_dir, quick, by_key) for fig in figures]
