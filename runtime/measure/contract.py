"""The answer contract: a figure leaves camdyn only with its error estimate and the run's
warnings, or the run is refused with one line saying why and what to do.

Every command that prints, writes or tabulates a figure goes through :func:`answer` (one
run) or :func:`grid_columns` (a grid of runs), so a safeguard added here is on every road.
The estimate of a figure v covers every error it has:

* discretisation: the same target one notch tighter (rtol/100 or half the step,
  runtime/core/methods.py) gives v'; |v - v'| times the method's factor (1.5 for the adaptive
  methods, 3 for radau5, Richardson's 2^p/(2^p - 1) for the fixed steps) estimates v's error;
* sampling: an extreme carries the error the scan that found it leaves, and the place of an
  extreme how well the refinement places it (runtime/measure/extremes.py);
* the window: a residual amplitude read from a dwell shorter than one period of the slowest
  mode its output sees (runtime/measure/modes.py) is too small.  Where the run's end was
  left to camdyn the run is extended; where the user gave it, the run is refused, naming
  the setting and the end it needs; where the dwell ends at the cam's next motion (a full
  turn's upper dwell) the figure carries an estimate of that error and a warning.

The total is the sum of the three (each a bound of its own error to the accuracy the
estimate has), with the parts in ``sources``.  With ``estimate=False`` (the command's
``--no-error-estimate``, for speed) the figures come back with their estimate as None.

A second run that fails where the first succeeded (a step budget the tighter run exhausts, a
step that collapses at rtol/10) takes the estimate away, not the answer: the figures keep
their values, their estimates are None ("estimate unavailable" in text, null in JSON, NaN in a
grid's table), and a warning "estimate unavailable: <why>" says what happened, on every road
(:func:`answer`, :class:`Twin` for a grid's chunks).
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
    tight_result: object = None     # the run one notch tighter (None without an estimate)
    factor: float = 1.0             # the method's factor of |v - v'| (Richardson's for rk4)
    unavailable: str | None = None  # why the estimate was asked for and could not be made
    about: dict = field(default_factory=dict)   # figure -> (unit, description), the target's

    def as_dict(self) -> dict:
        """The command's record with ``<figure>_error`` beside it, the warnings and the
        parts of every estimate: the JSON every command prints."""
        out = dict(self.record)
        for name, e in self.errors.items():
            out[f"{name}_error"] = e
        out["warnings"] = list(self.warnings)
        if self.sources:
            out["error_sources"] = self.sources
        if self.unavailable is not None:
            out["estimate_unavailable"] = self.unavailable
        return out

    def to_pandas(self):
        """The figures as a pandas DataFrame: one row per figure, its value, its error
        estimate and the estimate's parts; ``.attrs`` holds the warnings and the target."""
        from ..core import display

        pd = display.need("pandas", "Answer.to_pandas()")
        rows = {name: {"value": v, "error": self.errors.get(name),
                       **{f"error_{k}": e for k, e in (self.sources.get(name) or {}).items()}}
                for name, v in self.figures.items()}
        frame = pd.DataFrame.from_dict(rows, orient="index")
        frame.index.name = "figure"
        frame.attrs.update(target=self.target, warnings=list(self.warnings),
                           estimate_unavailable=self.unavailable)
        return frame

    def to_xarray(self):
        """The figures as an xarray Dataset, as :meth:`Result.to_xarray` and
        :meth:`SweepResult.to_xarray` hold theirs: every figure a variable without a
        dimension, its estimate the variable ``<figure>_error`` beside it (NaN where there is
        none: not asked for, or unavailable), the estimate's parts its attributes; units and
        descriptions as attributes (the target's); the warnings ("none" without), the
        target and why an estimate is unavailable as the Dataset's attributes."""
        from ..core import display

        xr = display.need("xarray", "Answer.to_xarray()")
        data = {}
        for name, value in self.figures.items():
            unit, doc = self.about.get(name, ("", ""))
            data[name] = ((), _scalar(value), {"units": unit, "description": doc})
            if name in self.errors:
                parts = {k: _scalar(e) for k, e in (self.sources.get(name) or {}).items()}
                data[f"{name}_error"] = ((), _scalar(self.errors[name]), {
                    "units": unit, "description": f"error estimate of {name}",
                    **{f"error_{k}": e for k, e in parts.items()}})
        attrs = {"target": self.target, "kind": self.kind,
                 "warnings": "; ".join(self.warnings) or "none",
                 "estimated": int(self.estimated)}
        if self.unavailable is not None:
            attrs["estimate_unavailable"] = self.unavailable
        return xr.Dataset(data, attrs=attrs)

    def _repr_html_(self) -> str:
        from ..core import display

        rows = [[name, display.plus_minus(v, self.errors.get(name)),
                 ", ".join(f"{k} {display.text(e)}" for k, e in (self.sources.get(name) or {}).items())]
                for name, v in self.figures.items()]
        extra = ([f"estimate unavailable: {self.unavailable}"] if self.unavailable else [])
        chart = ""
        if getattr(self.result, "chart", None) is not None:
            est = [e for e in self.errors.values() if e is not None]
            chart = display.picture(self.result.chart(note=(
                f"the run the figures are read from; largest estimate {max(est):.2g}" if est
                else "the run the figures are read from; no estimates")))
        return display.page(f"{self.target}: {len(self.figures)} figures",
                            display.table(["figure", "value \u00b1 error", "error's parts"], rows),
                            display.warnings_block([*self.warnings, *extra]), chart)

    def at_end(self) -> tuple[dict, dict]:
        """(values, estimates) of every output of the run at its end, a constrained model's
        multipliers among them (named after its constraints, following its own outputs): the
        estimate is |v - v'| times the method's factor, v' the output at the end of the run
        one notch tighter; None without that run (not asked for, or unavailable)."""
        res, tight = self.result, self.tight_result
        names = list(res.output_names)
        # the last recorded point is the run's end (its right limit where a breakpoint is there)
        values = {n: float(res.outputs[n][-1]) for n in names}
        errors = {n: None if tight is None else abs(values[n] - float(tight.outputs[n][-1]))
                  * self.factor for n in names}
        return values, errors


def _scalar(v):
    """A figure or estimate as a Dataset holds it: a number (NaN for None), a yes or no as
    such."""
    if v is None:
        return math.nan
    return v if isinstance(v, (bool, np.bool_)) else float(v)


def _number(v) -> bool:
    return isinstance(v, (int, float, np.floating)) and not isinstance(v, bool) and math.isfinite(v)


def fit_window(target, window=None, at: str = ""):
    """``target`` itself, or extended to the dwell its figures need, or a refusal
    (CamdynInputError) naming the setting that ends the run and the least value it needs.
    ``window``: the target's (None: ``target.window()``), or a grid's worst point's, which
    ``at`` names ("tau = 0.9")."""
    w = target.window() if window is None else window
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
    where = f" at {at}" if at else ""
    raise CamdynInputError(
        f"{w.setting}={w.end:g} leaves {w.available:.4g}{unit} of dwell after the rise, less "
        f"than one period of the slowest mode {worst} sees there{where} ({short[worst]:.4g}"
        f"{unit}): {worst} would come out too small; give {w.setting} >= "
        f"{w.end_for(need):.4g}")


UNAVAILABLE = "estimate unavailable"
"""The words of a warning, and of a text table, where an estimate was asked for and the run
one notch tighter could not give it."""


def unavailable(why: str) -> str:
    """The warning of an estimate that could not be made, saying why."""
    return f"{UNAVAILABLE}: {why}; the figures are the run's, without an error estimate"


def tighter_run(target):
    """(the run of ``target`` one notch tighter, None) or (None, why it could not be made):
    the second run of every error estimate.  A failure of it (a budget of steps it exhausts, a
    step that collapses, a tolerance with no tighter notch) leaves the answer standing."""
    tighter = target.tighter()
    if tighter is None:
        return None, (f"rtol={target.method().rtol:g} is the tightest tolerance there is, no "
                      "run one notch tighter (give a larger rtol)")
    try:
        return tighter.run(), None
    except (SimulationError, CamdynInputError) as exc:
        return None, f"the run one notch tighter failed ({exc})"


def answer(target, *, estimate: bool = True, progress=None) -> Answer:
    """One run of ``target`` with every figure's error estimate (module doc)."""
    target = fit_window(target)
    base = target.run(progress)
    tight, why = None, None
    warnings = list(base.warnings)
    if estimate:
        tight, why = tighter_run(target)
        if why is not None:
            warnings.append(unavailable(why))
    errors, sources, missing = combine(target, base, tight, estimate)
    for name in missing:
        warnings.append(f"no error estimate for {name}: the tighter run does not give it")
    warnings += unresolved(base.figures, errors, _scales(target))
    return Answer(target.name, target.kind, dict(base.figures), errors, sources, warnings,
                  base.record, base.stats, estimate, base.result,
                  None if tight is None else tight.result, target.method().estimate_factor, why,
                  {f.name: (f.unit, f.doc) for f in target.figures()})


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
    # the points with a figure that its estimate does not resolve, found on the whole arrays
    # (a grid has thousands of points), then worded as a single run words them
    shown = [(k, f) for k, f in enumerate(names) if f"{f}_error" in cols]
    scales = _scales(target)
    flagged = np.zeros(len(base.figures), dtype=bool)
    for k, f in shown:
        e, v = cols[f"{f}_error"], base.figures[:, k]
        with np.errstate(invalid="ignore"):
            flagged |= (np.isfinite(e) & np.isfinite(v)
                        & (e > UNRESOLVED * (np.abs(v) + scales.get(f, 0.0))))
    # what the run's inputs say of every point (a rise from a table: how well it is known)
    notes = list(getattr(getattr(target, "simulator", None), "law_notes", ()))
    warnings = [notes + list(w) for w in base.warnings]
    if tight is not None:       # a chunk whose tighter runs failed says so (Twin)
        for j, w in enumerate(tight.warnings):
            warnings[j] += [x for x in w if x.startswith(UNAVAILABLE)]
    for j in np.flatnonzero(flagged):
        warnings[j] += unresolved({f: float(base.figures[j, k]) for k, f in shown},
                                  {f: float(cols[f"{f}_error"][j]) for _, f in shown}, scales)
    cols["warnings"] = np.array(["; ".join(w) for w in warnings], dtype=object)
    return cols


def quotient(a: float, ea: float, b: float, eb: float) -> tuple[float, float]:
    """(a/b, its error) where a and b carry errors ea and eb: the largest distance from a/b
    to the quotients over the box [a - ea, a + ea] x [b - eb, b + eb] (exact, where adding
    relative errors holds only while they are small); infinite where the box holds b = 0, for
    then the quotient is not bounded."""
    r = a / b
    if eb >= abs(b):
        return r, math.inf
    corners = [(a + sa * ea) / (b + sb * eb) for sa in (-1, 1) for sb in (-1, 1)]
    return r, max(abs(c - r) for c in corners)


UNRESOLVED = 0.5
"""An estimate above this fraction of its figure leaves the figure unknown to within a factor
of two or worse: the run does not resolve it, and says so."""


def _scales(target) -> dict:
    """Figure -> the size below which it counts as zero (targets/base.py Figure.scale)."""
    return {f.name: f.scale for f in target.figures() if f.scale}


def unresolved(figures: dict, errors: dict, scales: dict | None = None) -> list:
    """A warning for every figure whose estimate exceeds UNRESOLVED of |figure| + its scale
    (``scales``, 0 where not given): the run does not resolve it (its tolerance or step is too
    coarse for it, or it lies at a zero of the response, which the run cannot tell from a
    small value)."""
    out = []
    for name, e in errors.items():
        v = figures.get(name)
        if _number(e) and _number(v) and e > UNRESOLVED * (abs(v) + (scales or {}).get(name, 0.0)):
            out.append(f"{name} = {v:.4g} ± {e:.2g}: the estimate exceeds half the figure"
                       f"{' (and its scale)' if (scales or {}).get(name) else ''}, which the run "
                       "does not resolve; tighten rtol (or the step)")
    return out


# -- the contract on a chart: a footnote with the estimates and the warnings -------------
WIDTH = 130
"""The longest line of a chart's footnote, in characters."""


def chart_note(estimates: dict, warnings, points: int | None = None) -> str:
    """The footnote a chart carries (the answer contract on a picture): for each figure drawn,
    ``estimates[name] = (values, errors)`` (numbers or arrays), its largest estimate, absolute
    and relative to the figure (to the largest |value| of an array); and the warnings: ``warnings`` a list of lines, or of one
    string per point of a grid ("" for none; ``points`` of them)."""
    parts = []
    for name, (values, errors) in estimates.items():
        v = np.abs(np.ravel(np.asarray(values, dtype=float)))
        e = np.atleast_1d(np.asarray([np.nan if x is None else x for x in np.ravel(errors)],
                                     dtype=float))
        if not np.all(np.isfinite(e)):
            parts.append(f"{name}: no error estimate"
                         + ("" if not np.any(np.isfinite(e)) else " at some points"))
            continue
        big, top = float(e.max()), float(v.max()) if v.size else 0.0
        if e.size == 1:
            text = f"{name} ± {big:.2g}" + (f" ({big / top:.2g} relative)" if top > 0 else "")
        else:    # against the largest value drawn: a curve through zero has no relative error
            text = f"{name} ± up to {big:.2g}" + (f" ({big / top:.2g} of its largest |value|)"
                                                  if top > 0 else "")
        parts.append(text)
    lines = []
    if parts:        # a line of at most about WIDTH characters, so that no part is cut off
        line = "error estimates: " + parts[0]
        for part in parts[1:]:
            if len(line) + len(part) + 2 > WIDTH:
                lines.append(line + ";")
                line = "  " + part
            else:
                line += "; " + part
        lines.append(line)
    warned = [w for w in warnings if w]
    if points is not None:
        lines.append(f"{len(warned)} of {points} points warned" if warned else "no warnings")
    elif warned:
        first = warned[0] if len(warned[0]) <= 110 else warned[0][:107] + "..."
        lines.append(f"{len(warned)} warning{'s' if len(warned) > 1 else ''}: {first}")
    else:
        lines.append("no warnings")
    return "\n".join(lines)


# -- the contract in text: a figure and its estimate on one line ------------------------
def plus_minus(e) -> str:
    """" ± e" for a text table, or "" without a number."""
    return f" ± {e:.2g}" if _number(e) else ""


def note(out: dict, key: str, exact=()) -> str:
    """What follows figure ``key``'s value in a text table: " (exact)" for a figure in
    ``exact`` (it follows from the parameters), " ± e" with its estimate, " (estimate
    unavailable)" where it was asked for and could not be made, " (no error estimate)" where
    the record has none for it, "" for what is no figure."""
    if key in exact:
        return " (exact)"
    e = out.get(f"{key}_error")
    if _number(e):
        return plus_minus(e)
    return missing_estimate(out) if f"{key}_error" in out else ""


def missing_estimate(out: dict) -> str:
    """What a text table shows for a number without an estimate: " (estimate unavailable)"
    where it was asked for and could not be made, " (no error estimate)" otherwise."""
    return f" ({UNAVAILABLE})" if out.get("estimate_unavailable") else " (no error estimate)"


def exact_figures(target) -> set:
    """The names of ``target``'s figures that follow from its parameters (no run's error)."""
    return {f.name for f in target.figures() if f.estimate == "exact"}


def with_errors(figures: dict, exact=()) -> list:
    """Lines "name  value ± e" for a text table, the *_error keys folded into the line of
    their figure (:func:`note`)."""
    rows = []
    keys = [k for k in figures if not (k.endswith("_error") and k[:-6] in figures)
            and k not in ("warnings", "error_sources", "estimate_unavailable")]
    width = max((len(k) for k in keys), default=0)
    for k in keys:
        v = figures[k]
        text = f"{v:.6g}" if isinstance(v, float) else f"{v}"
        rows.append(f"{k:<{width}}  {text}{note(figures, k, exact)}")
    return rows
