"""Drawing the figures of the registry (:data:`camdyn.thesis.registry.FIGURES`; the topic
modules ch3.py ... charts.py each define ``figures() -> list[Figure]``, and adding a figure is
one entry there): :func:`build` draws the chosen figures and evaluates the statements beside
them, :mod:`.index` writes the HTML page."""
from __future__ import annotations

import re
import sys
import time
from dataclasses import dataclass
from pathlib import Path

from camdyn.runtime.core.errors import CamdynInputError, OutFolderError
from camdyn.runtime.core.outdir import note, out_folder
from camdyn.runtime.core.signals import held
from camdyn.thesis.checks import suite
from camdyn.thesis.registry import FIGURES

from . import index
from .figure import Built, Figure
from .statements import evaluate

TOPICS = FIGURES.topics
"""The topic modules, in the order the index lists their figures."""


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
    return sorted(FIGURES.entries(topics), key=_order)


def select(figures: list[Figure], only) -> list[Figure]:
    """The figures whose id is in ``only`` (ids as listed; "4.11" also picks 4.11a-c,
    "paper" every paper figure), in registry order; every name must match something.  None
    selects all; an empty selection (--only "" or ",") is refused rather than drawing all."""
    if only is None:
        return list(figures)
    if not only:
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
        raise CamdynInputError(f"argument --only: unknown figure {unknown[0]!r}; choose from "
                               f"{', '.join(f.id for f in figures)}, or thesis, paper, design")
    keep = {id(f) for f in chosen}
    return [f for f in figures if id(f) in keep]


def checks_by_key(figures: list[Figure]) -> dict:
    """The thesis checks by key; every key a figure names must exist."""
    by_key = {c.key: c for c in suite.registry()}
    for fig in figures:
        for cl in fig.claims:
            if isinstance(cl.check, str) and cl.check not in by_key:
                raise ValueError(f"figure {fig.id}: no check {cl.check!r} in thesis/checks")
    return by_key


def build_one(fig: Figure, out_dir, quick: bool, by_key: dict) -> Built:
    """Draw one figure and evaluate its claims; a builder that fails is reported in
    Built.error (the index shows it), not raised, so the other figures are still built; but
    an --out that cannot take its pictures ends the build."""
    b = Built(fig)
    t0 = time.perf_counter()
    if fig.build is not None:
        try:
            b.pngs = [str(p) for p in fig.build(Path(out_dir), quick)]
        except OutFolderError:
            raise
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


@dataclass
class Drawing:
    """What `camdyn figures` made: every figure built, the time it took and the index page."""

    built: list
    seconds: float
    index: str

    @property
    def passed(self) -> bool:
        return all(b.passed for b in self.built)

    @property
    def claims(self) -> list:
        return [c for b in self.built for c in b.claims]


def make(only, out, quick: bool = False, progress: bool = True) -> Drawing:
    """`camdyn figures`: the figures whose ids are in ``only`` (None: all; see :func:`select`)
    drawn into the folder ``out`` with the index page beside them, written again after each
    figure, so that a build stopped midway leaves the index of what it drew; ``progress``: a
    bar on stderr."""
    from tqdm import tqdm

    todo = select(registry(), only)
    by_key = checks_by_key(todo)
    out = out_folder(out)
    t0 = time.perf_counter()
    built = []

    def page() -> str:
        with held():            # the index and the line saying what it lists: both, or neither
            path = index.write(built, out, time.perf_counter() - t0, quick, len(todo))
            note(f"{len(built)} of {len(todo)} figures drawn, listed in {path}")
        return path

    last = page()
    with tqdm(todo, file=sys.stderr, unit="fig", desc="figures", disable=not progress) as bar:
        for fig in bar:
            bar.set_postfix_str(fig.id)
            built.append(build_one(fig, out, quick, by_key))
            last = page()
    return Drawing(built, time.perf_counter() - t0, last)
