"""Measured stability boundaries of the fixed-step methods, and the thesis's step criterion.

``measure_boundary`` bisects the largest step h at which a compiled fixed-step run (the
stability check off, ``Simulator(check_stability=False)``) stays bounded, and returns h omega
with omega the spectral radius of the Jacobian at the start.  "Bounded": two runs from
initial states a small perturbation apart (a free vibration, e.g. in the dwell after the rise)
are compared over ``n_steps`` equal steps; their difference, which a linear(ised) system
carries by the method's amplification alone, must not be more than ``GROWTH`` times larger
in the last tenth of the run than in the first.  A run that fails (non-finite state, the thesis scheme's mid-step
iteration not converging) is unbounded.  Near the boundary |R| = 1 + d grows the difference
by (1 + d)^n_steps, so 2000 steps place it to ~1e-4 relative.

Measured (tests/test_stability_map.py):

* RK4 on the undamped one-DOF model (3.1) in the dwell, lambda = +-i omega: h omega = 2.8284,
  the imaginary-axis limit 2 sqrt(2).  On the first-order motor model (thesis sec. A.5.4.2,
  lambda = -G_a/J_ma, real) 2.7853, the negative-real-axis limit; on the one-DOF model with
  q = 0.9999 (lambda = omega (-q +- i (1 - q^2)^(1/2)), nearly real) 2.7855.
* The thesis scheme ("koster", (4.23)-(4.31)) with its mid-step equation eliminated as the
  thesis does it by hand (4.25) (``koster_scheme_step``, NumPy): 2.8284 = 2 sqrt(2).  The
  compiled scheme solves that equation by fixed-point iteration while it contracts fast and
  by Newton's method with the model's Jacobian beyond (one step on a linear model: the
  elimination (4.25)); compiled, on the dwell of the one-DOF model: 2.8284 = 2 sqrt(2) as
  well.  (With the fixed-point iteration alone, contraction factor (h omega)^2/8 and at most
  100 iterations, it failed with "did not converge" from h omega = 2.39, 2.35 for a full
  stroke.)

The thesis (sec. 4.4.2): "stable if Delta T <= 0.1 tau", i.e. h omega <= 0.2 pi = 0.628 with
omega = 2 pi/tau; the measured limit is 2.828 (Delta T <= 0.450 tau, compiled as well): the
thesis's criterion is 4.5 times inside the stability limit, an accuracy criterion rather than
a stability one (``thesis_step_comparison``).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Callable

import numpy as np

from ..core import stability as _stability
from ..core.errors import CamdynInputError, SimulationError
from ..core.compiled import CompiledModel, load
from ..core.simulator import Simulator

GROWTH = 2.0        # a difference grown by more than this over the run is unbounded
N_STEPS = 2000      # steps per trial run
PERTURBATION = 1e-2  # of the first state, in its scale, between the two runs
THESIS_STEP = 0.1   # sec. 4.4.2: stable if Delta T <= 0.1 tau
THESIS_FINE = 0.01  # and 0.01 tau, the step of its results
THESIS_CHANGE = 0.015  # "the residual amplitude changes by only 1.5 %"


@dataclass(frozen=True)
class Boundary:
    """A measured boundary: the largest bounded step ``h`` and ``x = h * omega``."""

    model: str
    method: str
    params: dict
    omega: float
    h: float
    x: float

    def as_dict(self) -> dict:
        return asdict(self)


def bisect(stable: Callable[[float], bool], lo: float, hi: float, rel: float = 1e-5) -> float:
    """The largest x in [lo, hi] with ``stable(x)``, given stable(lo) and not stable(hi)."""
    if not stable(lo):
        raise CamdynInputError(f"lo={lo:g} is not stable: start the bisection lower")
    if stable(hi):
        raise CamdynInputError(f"hi={hi:g} is stable: start the bisection higher")
    while hi - lo > rel * lo:
        mid = 0.5 * (lo + hi)
        if stable(mid):
            lo = mid
        else:
            hi = mid
    return lo


def spectral_radius(model: CompiledModel, params: dict | None, t0: float, y0) -> float:
    """|lambda|max of the difference Jacobian at (t0, y0), the cycloidal law's segments."""
    sim = Simulator(model, t0 + 1.0, "rk4", step=1.0, t0=t0, y0=y0)
    ev = _stability.spectra(model, model.parameter_vector(params), sim.law_codes, sim.law_pars,
                            [t0], [np.asarray(y0, float)], None,
                            np.array(sim.modes0, dtype=np.intc))[0]
    return float(np.abs(ev).max())


def growth(model, method: str, params: dict | None, h: float, t0: float, y0,
           n_steps: int = N_STEPS, law: str = "cycloidal") -> float:
    """Growth of a perturbation of the first state over ``n_steps`` steps h (inf if a run
    fails): per state, max |difference| over the last tenth of the run over its max over the
    first tenth (so that a velocity, scaled by omega, is compared with itself); the largest."""
    m = model if isinstance(model, CompiledModel) else load(model)
    y0 = np.asarray(y0, dtype=float)
    d0 = PERTURBATION * m.state_scales()[0]
    ya = y0.copy()
    yb = y0.copy()
    yb[0] += d0
    t_end = t0 + n_steps * h
    runs = []
    for y in (ya, yb):
        sim = Simulator(m, t_end, method, step=h, t0=t0, y0=y, law=law,
                        max_steps=2 * n_steps + 10, check_stability=False,
                        exact_segments=False)     # the method's own growth, the dwell too
        try:
            runs.append(sim.run(params).y)
        except SimulationError:
            return math.inf
    d = np.abs(runs[1] - runs[0]) / m.state_scales()
    tenth = max(1, len(d) // 10)
    head, tail = d[:tenth].max(axis=0), d[-tenth:].max(axis=0)
    if not np.all(np.isfinite(tail)):
        return math.inf
    return float((tail / np.maximum(head, 1e-300)).max())


def measure_boundary(model, method: str, params: dict | None, t0: float, y0, *,
                     omega: float | None = None, lo: float = 0.5, hi: float = 4.0,
                     n_steps: int = N_STEPS, rel: float = 1e-5) -> Boundary:
    """The largest bounded h omega of ``method`` (rk4, koster) on ``model`` from (t0, y0),
    bisected in [lo, hi]; omega is the spectral radius of the Jacobian there unless given."""
    if method not in ("rk4", "koster"):
        raise CamdynInputError(f"method={method!r}: boundaries are measured for the fixed-step "
                               f"methods rk4 and koster")
    m = model if isinstance(model, CompiledModel) else load(model)
    w = spectral_radius(m, params, t0, y0) if omega is None else float(omega)
    if not (w > 0 and math.isfinite(w)):
        raise CamdynInputError(f"omega={w:g} must be positive: a system without dynamics has "
                               f"no stability boundary")
    x = bisect(lambda x: growth(m, method, params, x / w, t0, y0, n_steps) <= GROWTH, lo, hi, rel)
    return Boundary(m.name, method, dict(params or {}), w, x / w, x)


def koster_scheme_step(X: float, V: float, h: float, w: float) -> tuple[float, float]:
    """One step of the thesis scheme on X'' = -w^2 X with the mid-step equation eliminated by
    hand, as in (4.25): X''_m = -w^2 (X + V theta + X''_m theta^2/2), theta = h/2, solved for
    X''_m; then V += X''_m h (4.28), (4.29), X += (V_old + X''_m h/2) h (4.30), (4.31)."""
    th = 0.5 * h
    a = -w * w * (X + V * th) / (1.0 + 0.5 * w * w * th * th)
    return X + (V + 0.5 * a * h) * h, V + a * h


def koster_scheme_boundary(n_steps: int = N_STEPS, rel: float = 1e-5) -> float:
    """h omega at which the eliminated thesis scheme (``koster_scheme_step``) stops being
    bounded on the undamped test equation, measured by running it (theory: 2 sqrt(2)).

    Bounded as in ``growth``: the last tenth against the first, per component.  Below the
    boundary X^2 + (1 - (h omega)^2/8) X'^2/omega^2 is conserved exactly (the invariant of the
    step matrix, determinant 1), so the velocity's amplitude at the step points is the
    position's times (1 - (h omega)^2/8)^(-1/2): bounded, but 2.6 % high at the thesis's
    0.1 tau and unbounded as h omega -> 2 sqrt(2).
    """

    def stable(x: float) -> bool:
        y = np.empty((n_steps, 2))
        X, V = 1.0, 0.0
        for k in range(n_steps):
            X, V = koster_scheme_step(X, V, x, 1.0)
            y[k] = X, V
        tenth = n_steps // 10
        with np.errstate(invalid="ignore", over="ignore"):
            head, tail = np.abs(y[:tenth]).max(axis=0), np.abs(y[-tenth:]).max(axis=0)
            return bool(np.all(tail <= GROWTH * head))   # false for NaN too

    return bisect(stable, 0.5, 4.0, rel)


@dataclass(frozen=True)
class StepChange:
    """U0 of CAMSHAFT-1 with the thesis scheme at Delta T = 0.1 tau and 0.01 tau."""

    tau: float
    Fa: float
    U0_coarse: float
    U0_fine: float

    @property
    def change(self) -> float:
        return abs(self.U0_coarse - self.U0_fine) / self.U0_fine


def step_changes(cases, model: str = "camshaft1") -> list[StepChange]:
    """The thesis's comparison (sec. 4.4.2) for each (tau, Fa): koster at 0.1 and 0.01 tau."""
    from ..measure.residual import residual

    out = []
    for tau, Fa in cases:
        params = {"tau": tau, "Fa": Fa} if model == "camshaft1" else {"tau": tau}
        u = [residual(Simulator(model, 3.0, "koster", step=f * tau).run(params)).U0
             for f in (THESIS_STEP, THESIS_FINE)]
        out.append(StepChange(tau, Fa, *u))
    return out


def thesis_step_comparison(cases, koster_x: float) -> dict:
    """Sec. 4.4.2 set against the measurements: the thesis's stability criterion as h omega
    (0.628) against the measured boundary ``koster_x`` (with omega = 2 pi/tau the largest
    frequency of CAMSHAFT-1, in the dwell), and the U0 change from 0.1 tau to 0.01 tau."""
    ch = step_changes(cases)
    changes = np.array([c.change for c in ch])
    return {
        "thesis_h_omega": 2 * math.pi * THESIS_STEP,
        "measured_h_omega": koster_x,
        "measured_step_over_tau": koster_x / (2 * math.pi),
        "margin": koster_x / (2 * math.pi * THESIS_STEP),
        "thesis_change": THESIS_CHANGE,
        "change_median": float(np.median(changes)),
        "change_min": float(changes.min()),
        "change_max": float(changes.max()),
        "cases": [dict(tau=c.tau, Fa=c.Fa, U0_coarse=c.U0_coarse, U0_fine=c.U0_fine,
                       change=c.change) for c in ch],
    }
