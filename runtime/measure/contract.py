"""The answer contract: a figure leaves camdyn only with its error estimate and the run's
warnings, or the run is refused with one line saying why and what to do.

Every command that prints, writes or tabulates a figure goes through :func:`answer` (one
run) or :func:`grid_columns` (a grid of runs), so a safeguard added here is on every road.
The estimate of a figure v covers every error it has:

* discretisation: the same target one notch tighter (rtol/10 or half the step,
  runtime/core/methods.py) gives v'; |v - v'| times the method's factor (1 for dp54 and
  rodas4, Richardson's 2^p/(2^p - 1) for the fixed steps) estimates v's error;
* sampling: an extreme carries the error the scan that found it leaves
  (runtime/measure/extremes.py);
* the window: a residual amplitude read from a dwell shorter than one period of the slowest
  mode its output sees (runtime/measure/modes.py) is too small.  Where the run's end was
  left to camdyn the run is extended; where the user gave it, the run is refused, naming
  the setting and the end it needs; where the dwell ends at the cam's next motion (a full
  turn's upper dwell) the figure carries an estimate of that error and a warning.

The total is the sum of the three (each a bound of its own error to the accuracy the
estimate has), with the parts in ``sources``.  With ``estimate=False`` (the command's
``--no-error-estimate``, for speed) the figures come back with their estimate as None.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..core.errors import CamdynInputError, SimulationError


@dataclass
class Answer:
    """Figures of one run of a target with their error estimates and the run's warnings."""

    target: str
    kind: str
    figures: dict
    errors: dict
    sources: dict
    warnings: list
    record: dict = field(default_factory=dict)
    stats: dict = field(default_factory=dict)
    estimated: bool = True
    result: object = None

    def as_dict(self) -> dict:
        """The command's record with ``<figure>_error`` beside it, the warnings and the
        parts of every estimate: the JSON every command prints."""
        out = dict(self.record)
        for name, e in self.errors.items():
            out[f"{name}_error"] = e
        out["warnings"] = list(self.warnings)
        if self.sources:
            out["error_sources"] = self.sources
        return out


def _number(v) -> bool:
    return isinstance(v, (int, float, np.floating)) and not isinstance(v, bool) and math.isfinite(v)


def fit_window(target):
    """``target`` itself, or extended to the dwell its figures need, or a refusal
    (CamdynInputError) naming the setting that ends the run and the least value it needs."""
    w = target.window()
    if w is None:
        return target
    short = w.short()
    if not short or w.fixed:
        return target
    need = max(short.values())
    if not w.given:
        return target.extended(need)
    worst = max(short, key=short.get)
    unit = f" {w.unit}" if w.unit else ""
    raise CamdynInputError(
        f"{w.setting}={w.end:g} leaves {w.available:.4g}{unit} of dwell after the rise, less "
        f"than one period of the slowest mode {worst} sees there ({short[worst]:.4g}{unit}): "
        f"{worst} would come out too small; give {w.setting} >= {w.end_for(need):.4g}")


def answer(target, *, estimate: bool = True, progress=None) -> Answer:
    """One run of ``target`` with every figure's error estimate (module doc)."""
    target = fit_window(target)
    base = target.run(progress)
    tight = None
    warnings = list(base.warnings)
    if estimate:
        tighter = target.tighter()
        if tighter is None:
            warnings.append("no error estimate: the run is at the tightest tolerance there is "
                            "(give a larger rtol)")
        else:
            try:
                tight = tighter.run()
            except SimulationError as exc:
                raise SimulationError(f"the error estimate's second run failed: {exc}") from None
    errors, sources, missing = combine(target, base, tight, estimate)
    for name in missing:
        warnings.append(f"no error estimate for {name}: the tighter run does not give it")
    return Answer(target.name, target.kind, dict(base.figures), errors, sources, warnings,
                  base.record, base.stats, estimate, base.result)


def combine(target, base, tight, estimate: bool) -> tuple[dict, dict, list]:
    """(errors, sources, figures the tighter run lacks) of a run and its tighter twin."""
    factor = target.method().estimate_factor
    errors, sources, missing = {}, {}, []
    for fig in target.figures():
        name = fig.name
        v = base.figures.get(name)
        if fig.estimate == "none" or v is None:
            continue
        if fig.estimate == "exact":
            errors[name] = 0.0
            continue
        if not estimate:
            errors[name] = None
            continue
        w = tight.figures.get(name) if tight is not None else None
        if tight is not None and not _number(w):
            errors[name] = None
            missing.append(name)
            continue
        parts = {"discretisation": None if w is None else abs(float(v) - float(w)) * factor,
                 "sampling": float(base.sampling.get(name, 0.0)),
                 "window": float(base.window.get(name, 0.0))}
        sources[name] = parts
        errors[name] = (None if parts["discretisation"] is None
                        else parts["discretisation"] + parts["sampling"] + parts["window"])
    return errors, sources, missing


def grid_columns(target, base, tight) -> dict:
    """The error columns of a grid of runs: ``<figure>_error`` per figure that has one
    (discretisation from the tighter batch, plus sampling and window), 0 for exact figures;
    and ``warnings``, the run's warnings joined by "; " per point ("" for none)."""
    factor = target.method().estimate_factor
    names = target.figure_names()
    cols = {}
    for k, fig in enumerate(target.figures()):
        if fig.estimate == "none":
            continue
        if fig.estimate == "exact":
            cols[f"{fig.name}_error"] = np.zeros(len(base.figures))
            continue
        est = np.full(len(base.figures), np.nan)
        if tight is not None:
            est = np.abs(base.figures[:, k] - tight.figures[:, k]) * factor + base.sampling[:, k]
        cols[f"{names[k]}_error"] = est
    cols["warnings"] = np.array(["; ".join(w) for w in base.warnings], dtype=object)
    return cols


# -- the contract in text: a figure and its estimate on one line ------------------------
def plus_minus(e) -> str:
    """" ± e" for a text table, or "" without a number."""
    return f" ± {e:.2g}" if _number(e) else ""


def with_errors(figures: dict) -> list:
    """Lines "name  value ± e" for a text table, the *_error keys folded into the line of
    their figure; a figure whose estimate is None says so."""
    rows = []
    keys = [k for k in figures if not (k.endswith("_error") and k[:-6] in figures)
            and k not in ("warnings", "error_sources")]
    width = max((len(k) for k in keys), default=0)
    for k in keys:
        v = figures[k]
        text = f"{v:.6g}" if isinstance(v, float) else f"{v}"
        e = figures.get(f"{k}_error")
        if _number(e):
            text += plus_minus(e)
        elif f"{k}_error" in figures:
            text += " (no error estimate)"
        rows.append(f"{k:<{width}}  {text}")
    return rows

