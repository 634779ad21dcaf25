"""Compiled models: loading a generated module and checking what is passed to it."""
from __future__ import annotations

import importlib
import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .errors import CamdynInputError


@dataclass(frozen=True)
class CompiledModel:
    """A generated model module with its manifest."""

    name: str
    module: object

    @property
    def manifest(self) -> dict:
        return self.module.MANIFEST

    @property
    def capsule(self):
        return self.module.MODEL

    @property
    def state_names(self) -> list[str]:
        return [s["name"] for s in self.manifest["states"]]

    @property
    def output_names(self) -> list[str]:
        return [o["name"] for o in self.manifest["outputs"]]

    @property
    def parameter_names(self) -> list[str]:
        return [p["name"] for p in self.manifest["parameters"]]

    @property
    def families(self) -> list[str]:
        return self.manifest["cam_families"]

    def parameter_vector(self, values: dict | None = None) -> np.ndarray:
        """Parameters in manifest order: defaults, overridden by ``values``, checked."""
        values = dict(values or {})
        unknown = sorted(set(values) - set(self.parameter_names))
        if unknown:
            raise CamdynInputError(
                f"model {self.name} has no parameter {', '.join(unknown)}; "
                f"its parameters are {', '.join(self.parameter_names)}")
        vec = []
        for spec in self.manifest["parameters"]:
            name = spec["name"]
            raw = values.get(name, spec["default"])
            if isinstance(raw, bool) or not isinstance(raw, (int, float, np.floating, np.integer)):
                raise CamdynInputError(f"{name} must be a number, got {raw!r}")
            v = float(raw)
            if not _admits(spec, v):
                raise CamdynInputError(
                    f"{name}={v:g} is out of range: {spec['range']} ({spec['doc']})")
            vec.append(v)
        return np.array(vec, dtype=float)

    def initial_state(self) -> np.ndarray:
        return np.array([s["initial"] for s in self.manifest["states"]], dtype=float)

    def state_scales(self) -> np.ndarray:
        return np.array([s["scale"] for s in self.manifest["states"]], dtype=float)

    def cam_time_affine(self, p: np.ndarray):
        return self.module.cam_time_affine(p)


def _admits(spec: dict, v: float) -> bool:
    if not math.isfinite(v):
        return False
    lo, hi = spec["low"], spec["high"]
    if lo is not None and (v <= lo if spec["open_low"] else v < lo):
        return False
    if hi is not None and (v >= hi if spec["open_high"] else v > hi):
        return False
    return True


def available() -> list[str]:
    """Names of the models in the registry (the generated modules)."""
    from importlib import resources

    names = []
    for entry in resources.files("camdyn.generated").iterdir():
        name = entry.name
        if name.endswith(".pyx") and name != "camlaws.pyx":
            names.append(name[:-4])
    return sorted(names)


@lru_cache(maxsize=None)
def load(name: str) -> CompiledModel:
    """The compiled model ``name`` (``one-dof`` and ``one_dof`` both work)."""
    mod_name = name.replace("-", "_")
    if mod_name == "camlaws" or not mod_name.isidentifier():
        raise CamdynInputError(f"unknown model {name!r}; choose one of {', '.join(available())}")
    try:
        module = importlib.import_module(f"camdyn.generated.{mod_name}")
    except ModuleNotFoundError:
        known = available()
        if mod_name in known:
            raise CamdynInputError(
                f"model {name!r} is generated but not compiled; reinstall camdyn (pip install -e .)"
            ) from None
        raise CamdynInputError(f"unknown model {name!r}; choose one of {', '.join(known)}") from None
    return CompiledModel(mod_name, module)
