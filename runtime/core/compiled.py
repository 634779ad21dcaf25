"""Compiled models: loading a generated module and checking what is passed to it."""
from __future__ import annotations

import importlib
import math
from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from ..engine import driver
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

    @cached_property
    def _param_index(self) -> dict:
        """name -> (position, low, high, open_low, open_high, spec) for fast checks."""
        inf = math.inf
        return {spec["name"]: (k, -inf if spec["low"] is None else spec["low"],
                               inf if spec["high"] is None else spec["high"],
                               spec["open_low"], spec["open_high"], spec)
                for k, spec in enumerate(self.manifest["parameters"])}

    @cached_property
    def _defaults(self) -> np.ndarray:
        return np.array([spec["default"] for spec in self.manifest["parameters"]], dtype=float)

    @cached_property
    def _param_table(self):
        """The parameters' defaults and ranges for the checks in C (driver.ParameterTable)."""
        entries = sorted(self._param_index.values(), key=lambda e: e[0])
        return driver.ParameterTable(self.parameter_names, self._defaults,
                                     [e[1] for e in entries], [e[2] for e in entries],
                                     [e[3] for e in entries], [e[4] for e in entries])

    def parameter_vector(self, values: dict | None = None) -> np.ndarray:
        """Parameters in manifest order: defaults, overridden by ``values``, checked."""
        if values:
            # the common case (a dict of floats, every one in range) is checked in C; what that
            # declines comes here, where ints and NumPy numbers are taken and a refusal says why
            vec = self._param_table.vector(values)
            if vec is not None:
                return vec
        vec = self._defaults.copy()
        if not values:
            return vec
        index = self._param_index
        for name, raw in values.items():
            entry = index.get(name)
            if entry is None:
                raise CamdynInputError(
                    f"model {self.name} has no parameter {name}; "
                    f"its parameters are {', '.join(self.parameter_names)}")
            k, lo, hi, open_lo, open_hi, spec = entry
            if raw.__class__ is not float:
                if isinstance(raw, bool) or not isinstance(raw, (int, float, np.floating, np.integer)):
                    raise CamdynInputError(f"{name} must be a number, got {raw!r}")
                raw = float(raw)
            if not (-math.inf < raw < math.inf and (lo < raw if open_lo else lo <= raw)
                    and (raw < hi if open_hi else raw <= hi)):
                raise CamdynInputError(
                    f"{name}={raw:g} is out of range: {spec['range']} ({spec['doc']})")
            vec[k] = raw
        return vec

    def initial_state(self, p: np.ndarray | None = None) -> np.ndarray:
        """Default initial state; it may depend on the parameters (a cam turning at w_s)."""
        if p is None:
            p = self.parameter_vector()
        return np.array(self.module.initial_state(p), dtype=float)

    def state_scales(self) -> np.ndarray:
        return np.array([s["scale"] for s in self.manifest["states"]], dtype=float)

    def cam_time_affine(self, p: np.ndarray):
        return self.module.cam_time_affine(p)


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
