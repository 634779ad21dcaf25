"""The text of each unit of generated/: a model's module, the cam-law library, the catalog.

A model's module is printed by one of two printers, chosen by its declaration: a model with
holonomic constraints in the multiplier form M q'' + Phi_q^T lambda = f, Phi = 0
(:mod:`camdyn.derive.dae`), any other as M q'' = f (:mod:`camdyn.derive.codegen`).  The two
share :mod:`camdyn.derive.emit` and do not import each other; this module, above both, is the
one place that knows there are two.  `camdyn derive` (:mod:`camdyn.derive.generate`) and the
on-demand builder (:mod:`camdyn.derive.build`) print through it.
"""
from __future__ import annotations

import json

from . import codegen, dae
from .camlaws_code import render_camlaws
from .model import Model
from .models import dynacam

__all__ = ["render_camlaws", "render_catalog", "render_model", "source_of"]


def render_model(model: Model, source: str) -> str:
    """The generated module of ``model``; ``source`` is the file its declaration comes from
    (the provenance line of the preamble)."""
    return (dae.render if model.constraints else codegen.render)(model, source)


def source_of(build) -> str:
    """The source file of a model's build function, as the provenance line of its generated
    file names it (``camdyn/derive/models/dynacam.py`` for every DYNACAM variant)."""
    module = getattr(build, "func", build).__module__
    return module.replace(".", "/") + ".py"


def render_catalog() -> dict[str, str]:
    """``catalog.json``: what the runtime needs of the declarations without SymPy (the DYNACAM
    option set and how a variant is named), so that checking a scene loads no derive code."""
    head = ("written by `camdyn derive` from camdyn/derive/models/dynacam.py; do not edit, "
            "edit the declaration and regenerate")
    return {"catalog.json": json.dumps({"generated": head, "dynacam": dynacam.catalog()},
                                       indent=1) + "\n"}
