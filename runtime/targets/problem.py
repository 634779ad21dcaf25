"""A target's run as the studies of many methods take it: the model, its parameter values,
span, cam law, initial state and modes, and how to read the headline figures from a run of
any integrator (camdyn's, or a SciPy peer's that only offers ``sample``)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from ..core.simulator import Simulator


@dataclass
class Problem:
    """What a work-precision study or a stability map integrates, and the figures it scores."""

    label: str
    model: object
    params: dict
    t_end: float
    read: Callable
    kind: str = ""
    law: object = "cycloidal"
    theta: float | None = None
    y0: np.ndarray | None = None
    modes: dict = field(default_factory=dict)

    def simulator(self, method, **options) -> Simulator:
        # the figures read the dense output: made as the run goes, and timed with it
        return Simulator(self.model, self.t_end, method, law=self.law, theta=self.theta,
                         y0=self.y0, modes=self.modes or None, dense_output=True,
                         max_steps=options.pop("max_steps", 5_000_000), **options)

    def figures(self, run) -> dict:
        """The headline figures of a run (a camdyn Result or a SciPy peer's run)."""
        return self.read(run)
