"""One place that turns what a user names (a command-line argument, a scene file) into a
target: a built-in model or a model file, or a scene of any kind.  Every command resolves
its argument here.

A scene's ``kind`` picks its target class by the class's ``scene_kind``; adding a kind of
mechanism is adding its target class to SCENE_TARGETS.
"""
from __future__ import annotations

import os
from pathlib import Path

from ..core.errors import CamdynInputError
from ..core.methods import ADAPTIVE
from ..core.compiled import available
from . import scene_files
from .beam_scene import BeamTarget
from .camshaft1_study import StudyTarget
from .dynacam_scene import DynacamTarget
from .model_target import (ModelTarget, StateTarget, built_in_names, load_ref, model_file,
                           model_ref)

SCENE_TARGETS = {cls.scene_kind: cls for cls in (DynacamTarget, StudyTarget, BeamTarget)}
"""Scene kind -> the target class that runs it (its ``parse`` checks the scene file's tables,
its ``scene_doc`` says what a run of it gives)."""

KINDS = {kind: cls.scene_doc for kind, cls in SCENE_TARGETS.items()}
"""The kinds of scene, with what a run of each gives."""


def load_scene(name: str) -> tuple[str, object]:
    """(kind, checked scene) of any scene file or built-in scene: read, its kind, its tables
    checked by its target class, before anything runs."""
    data, where = scene_files.read(name)
    kind = scene_files.kind_of(data, where, KINDS)
    return kind, SCENE_TARGETS[kind].parse(data, where)


def is_model(name: str) -> bool:
    """Whether ``name`` names a model (a model file, or a built-in model) rather than a scene;
    a path that is neither a readable model file nor a scene file is refused here, naming it
    (model_target.model_file)."""
    return model_file(name, scenes=True) is not None or name.replace("-", "_") in available()


def scene(name: str, *, label: str = ""):
    """The target of a scene file or built-in scene (any kind)."""
    kind, sc = load_scene(name)
    return SCENE_TARGETS[kind].from_scene(sc, label or name)


def model(name: str, cls=None, progress=None, **settings):
    """The target of a model: ``cls`` ModelTarget (the residual vibration after a rise),
    StateTarget (the state at t_end), or None for ModelTarget where the model declares a
    rise and StateTarget otherwise."""
    if cls is None:
        declared = load_ref(model_ref(name), progress).manifest.get("residual")
        cls = ModelTarget if declared else StateTarget
    return cls.of(name, progress=progress, **settings)


def resolve(name: str, *, model_class=ModelTarget, progress=None, **settings):
    """The target ``name`` names, with the run's settings (method, rtol, step, t_end, law,
    theta, ...; None: the target's own).  A scene takes a method and rtol; its span, law
    and step come from its file (but for the CAMSHAFT-1 study, which is a model's)."""
    name = str(name)
    settings = {k: v for k, v in settings.items() if v is not None}
    if settings.get("rtol") is not None and settings.get("method") in ("rk4", "koster"):
        raise CamdynInputError(f"rtol applies to the adaptive methods {', '.join(ADAPTIVE)}; "
                               f"{settings['method']} takes step")
    if is_model(name):
        return model(name, model_class, progress, **settings)
    try:
        target = scene(name)
    except CamdynInputError as exc:
        if Path(name).suffix in (".toml", ".py") or os.sep in name:
            raise                  # a file the user named: what is wrong with it comes first
        raise CamdynInputError(f"{name!r} is neither a model ({built_in_names()}), a model "
                               f"file (.py) nor a scene: {exc}") from None
    if isinstance(target, ModelTarget):
        if "t_end" in settings and not settings["t_end"] > 1.0:
            raise CamdynInputError(f"t_end={settings['t_end']:g} must exceed the end of the "
                                   "rise, T = 1")
        method = settings.get("method", target.method_name)
        if method in ("rk4", "koster"):
            settings["rtol"] = None
        return target.with_settings(**settings)
    if "dependent" in settings:
        raise CamdynInputError(f"dependent: the scene {name} sets its model's formulation; "
                               "dependent coordinates are chosen for a constrained model run "
                               "by name (camdyn integrate MODEL --dependent NAMES)")
    given = [k for k in ("t_end", "law", "step") if k in settings]
    if given:
        raise CamdynInputError(f"{', '.join(given)}: t_end, law and step of a scene come from the "
                               "scene file")
    return target.with_settings(**settings)
