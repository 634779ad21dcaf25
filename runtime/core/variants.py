"""DYNACAM option sets at run time, read from the generated catalog (no SymPy).

``camdyn derive`` writes ``generated/catalog.json`` from the declaration
(:mod:`camdyn.derive.models.dynacam`): every option with its default, its choices and what it
is, and the rule that names a variant's module.  :class:`Options` here is built from it, so a
scene's options are checked and its variant named without loading the derivation; the
variant's parameters come from its compiled manifest (pre-generated, or built on demand).
tests/test_scene.py holds this class equal to the declaration's.
"""
from __future__ import annotations

import json
from dataclasses import asdict, field, make_dataclass
from importlib import resources

from .errors import CamdynInputError

CATALOG = json.loads(resources.files("camdyn.generated").joinpath("catalog.json").read_text())
_DYN = CATALOG["dynacam"]
CHOICES = {o["name"]: tuple(o["choices"]) for o in _DYN["options"] if o["choices"] != [False, True]}
"""Options with named choices; the others are switches (true/false)."""
DOCS = {o["name"]: o["doc"] for o in _DYN["options"]}


def _name(self) -> str:
    """Module name of the variant these options select (the catalog's naming rule)."""
    rule = _DYN["name"]
    words = [rule["prefix"]] + [rule["words"][key][getattr(self, key)] for key in rule["words"]]
    words += [word for word, key in rule["flags"] if getattr(self, key)]
    return rule["separator"].join(words)


def _items(self) -> tuple:
    return tuple(sorted(asdict(self).items()))


def _toml(value) -> str:
    return json.dumps(value)       # as a scene file writes it: true, "axial"


def _post_init(self):
    # CamdynInputError (a ValueError, as the declaration raises): a scene's options that no
    # variant has are bad input, one line on every road
    for key, allowed in CHOICES.items():
        if getattr(self, key) not in allowed:
            raise CamdynInputError(f"option {key}={getattr(self, key)!r}: choose one of "
                                   f"{', '.join(allowed)}")
    for key, value, other, other_value, why in _DYN.get("excludes", ()):
        if getattr(self, key) == value and getattr(self, other) == other_value:
            raise CamdynInputError(f"option {key}={_toml(value)} with {other}="
                                   f"{_toml(other_value)}: {why}")


Options = make_dataclass(
    "Options",
    [(o["name"], type(o["default"]), field(default=o["default"], metadata={"doc": o["doc"]}))
     for o in _DYN["options"]],
    frozen=True,
    namespace={"name": property(_name), "items": _items, "__post_init__": _post_init,
               "CHOICES": CHOICES,
               "__doc__": "What a DYNACAM variant contains (the declaration's option set)."})
Options.__module__ = __name__


def options_model(options, progress=None):
    """The compiled variant of an option set: pre-generated, or else derived, generated and
    compiled on first use into the user cache (:mod:`camdyn.runtime.core.ondemand`)."""
    from .compiled import available, load

    if options.name in available():
        return load(options.name)
    from . import ondemand

    return ondemand.dynacam_variant(asdict(options), options.name, progress)


def variant_manifest(options, progress=None) -> dict:
    return options_model(options, progress).manifest


def is_compiled(options) -> bool:
    """Whether the variant of an option set loads without a build: pre-generated, or already in
    the on-demand cache (:mod:`camdyn.runtime.core.ondemand`)."""
    from .compiled import available

    if options.name in available():
        return True
    from . import ondemand

    return ondemand.has_variant(asdict(options), options.name)
