"""The result of a simulation: named states and outputs, dense output, statistics."""
from __future__ import annotations

from functools import cached_property

import numpy as np

from . import _integrate
from .errors import CamdynInputError


class Result:
    """Trajectory of one run.

    ``t`` and ``y`` hold the recorded points (every accepted step; a breakpoint
    appears twice, as left and right limit).  ``result["X"]`` gives a state or
    an output at those points; ``result.sample(times)`` evaluates everything
    at arbitrary times through the method's dense output.
    """

    def __init__(self, model, params: dict, p, law, laws, method, raw: dict, cpu_seconds: float):
        self.model = model
        self.params = params
        self.p = p
        self.law_codes = law[0]
        self.law_pars = law[1]
        self.laws = laws
        self.method = method
        self.t = raw["t"]
        self.y = raw["y"]
        self.dense = raw["dense"]
        self.mode = raw["mode"]
        self.stats = {k: raw[k] for k in ("n_steps", "n_rejected", "n_rhs")}
        self.stats["cpu_seconds"] = cpu_seconds

    @property
    def state_names(self) -> list[str]:
        return self.model.state_names

    @property
    def output_names(self) -> list[str]:
        return self.model.output_names

    @property
    def names(self) -> list[str]:
        return self.state_names + self.output_names

    @cached_property
    def outputs(self) -> dict:
        """Outputs at the recorded points (computed on first use, in C)."""
        out = _integrate.eval_outputs(self.model.capsule, self.p, self.law_codes, self.law_pars,
                                      self.t, self.y, self.mode)
        return {name: out[:, k] for k, name in enumerate(self.output_names)}

    def __getitem__(self, name: str) -> np.ndarray:
        if name in ("t", self.model.manifest["time"]["name"]):
            return self.t
        if name in self.state_names:
            return self.y[:, self.state_names.index(name)]
        if name in self.output_names:
            return self.outputs[name]
        raise KeyError(f"{name!r} is neither a state nor an output of {self.model.name}; "
                       f"known: {', '.join(self.names)}")

    def sample(self, times) -> dict:
        """States and outputs at ``times`` (dense output), as a dict of arrays."""
        tq = np.ascontiguousarray(np.atleast_1d(np.asarray(times, dtype=float)))
        if tq.size and (tq.min() < self.t[0] or tq.max() > self.t[-1]):
            raise CamdynInputError(
                f"sample times must lie in [{self.t[0]:g}, {self.t[-1]:g}]")
        Y, idx = _integrate.dense_eval(self.t, self.y, self.dense, tq)
        modes = np.ascontiguousarray(self.mode[idx]) if self.mode.shape[1] else None
        out = _integrate.eval_outputs(self.model.capsule, self.p, self.law_codes, self.law_pars,
                                      tq, Y, modes)
        res = {"t": tq}
        res.update({name: Y[:, k] for k, name in enumerate(self.state_names)})
        res.update({name: out[:, k] for k, name in enumerate(self.output_names)})
        return res
