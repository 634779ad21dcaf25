"""One registry for the thesis's comparisons and its figures.

Both are lists gathered from topic modules: the checks that `camdyn check` runs
(:mod:`camdyn.thesis.checks`) and the figures that `camdyn figures` draws
(:mod:`camdyn.thesis.figures`).  What differs between the two is data, held by one
:class:`Registry` each: where the topic modules live and how they are named, which function of
a topic module lists its entries, and which attribute names an entry.  A name used twice is
refused: `-k` and `--only` could not tell the two apart, nor a reader of the table or the index.
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass


@dataclass(frozen=True)
class Registry:
    package: str            # the package of the topic modules
    topics: tuple           # the topics, in the order their entries are listed
    module: str             # a topic's module name, "{}" standing for the topic
    lists: str              # the function of a topic module that returns its entries
    key: str                # the attribute that names an entry
    kind: str               # what that name is called, in messages

    def entries(self, topics=None) -> list:
        """The entries of ``topics`` (default: all), in topic order, each name once."""
        out, seen = [], set()
        for topic in self.topics if topics is None else topics:
            module = importlib.import_module(f"{self.package}.{self.module.format(topic)}")
            for entry in getattr(module, self.lists)():
                name = getattr(entry, self.key)
                if name in seen:
                    raise ValueError(f"{self.kind} {name!r} used twice")
                seen.add(name)
                out.append(entry)
        return out


CHECKS = Registry(
    package="camdyn.thesis.checks",
    topics=("spine", "app2", "elements", "chains", "rayleigh", "impact", "foundation",
            "examples", "camshaft2", "motor", "dynacam"),
    module="{}_checks", lists="checks", key="key", kind="check key")
"""The comparisons with the thesis; the topics are those `camdyn check --topic` selects."""

FIGURES = Registry(
    package="camdyn.thesis.figures",
    topics=("ch3", "ch4", "ch5", "ch7", "ch8", "app2", "measured", "paper", "charts"),
    module="{}", lists="figures", key="id", kind="figure id")
"""The figures the models determine; the index orders the thesis's by their numbers."""
