"""Sweeps: the headline figures of a target over a grid of its parameters, as tables and charts.

``sweep(target, {"Fa": [...], "tau": [...]})`` runs every combination of the grid's values (the
first axis slowest) and returns a :class:`SweepResult`: a column per axis, per figure and its
error estimate (``<figure>_error``), the runs' ``warnings`` and their steps, written as CSV
(and Parquet with pyarrow) with a chart per figure.  Given a folder, it writes the CSV as the
grid runs, every chunk's rows as soon as both passes of the chunk (the runs and their tighter
twins) are in, so that a sweep stopped midway keeps whole rows with their estimates and
warnings, and ``resume`` runs only the points the table lacks.  The target is whatever
runtime/targets/resolve.py makes of the name: a model or a model file (the residual-vibration
figures, fig. 4.11), the CAMSHAFT-1 study, a DYNACAM scene (its summary's figures; the grid's
names are its [parameters]) or the beam follower (the tip's largest deflection; the names are
the fields of its case).

The runs go through runtime/targets/grid.py (compiled chunks on every core for a model, the
answer contract on every point); with ``dask`` (a ``distributed.Client``, a cluster, or a
scheduler's address) the chunks go to a Dask cluster instead; every worker must import camdyn.
"""
from __future__ import annotations

import csv
import hashlib
import math
import os
import sys
from contextlib import contextmanager
from dataclasses import dataclass, field
from itertools import product
from pathlib import Path

import numpy as np

from ..core import display
from ..core.errors import CamdynInputError, OutFolderError
from ..core.methods import ADAPTIVE
from ..core.outdir import Growing, entry, note, out_folder, writing
from ..core.signals import held as signals_held
from ..measure.contract import chart_note
from ..targets.grid import default_jobs, plan_grid, run_chunk, whole_steps

__all__ = ["parse_axis", "parse_grid", "sweep", "SweepResult", "default_jobs"]


# -- the grid ---------------------------------------------------------------------------------

def parse_axis(text: str) -> tuple[str, np.ndarray]:
    """``NAME=START:STOP:N[:lin|log|inv]`` (N values; log: geometric; inv: uniform in 1/value,
    as the tau grid of fig. 4.11, runtime/measure/envelope.py) or ``NAME=a,b,c``."""
    name, sep, rng = text.partition("=")
    name = name.strip()
    if not sep or not name:
        raise CamdynInputError(f"argument --grid: {text!r} is not NAME=START:STOP:N[:lin|log|inv] "
                               "or NAME=a,b,c")
    parts = rng.split(":")
    syntax = CamdynInputError(f"argument --grid: {text!r} is not NAME=START:STOP:N[:lin|log|inv] "
                              "or NAME=a,b,c")
    if len(parts) == 1 and any(not v.strip() for v in rng.split(",")):
        raise CamdynInputError(f"argument --grid: {name}: {rng!r} has an empty item; give "
                               "NAME=a,b,c, a number between every two commas")
    try:
        if len(parts) == 1:
            values = np.array([float(v) for v in rng.split(",")])
        elif len(parts) in (3, 4):
            a, b, n = float(parts[0]), float(parts[1]), int(parts[2])
            spacing = parts[3] if len(parts) == 4 else "lin"
        else:
            raise syntax
    except ValueError:
        raise syntax from None
    if len(parts) > 1:
        if spacing not in ("lin", "log", "inv"):
            raise syntax
        if not (np.isfinite(a) and np.isfinite(b)):
            # before linspace, which warns on inf and nan
            raise CamdynInputError(f"argument --grid: {name}: {rng!r} must give finite numbers")
        if not 1 <= n <= 1_000_000:
            raise CamdynInputError(f"argument --grid: {name}: N={n} is out of range: "
                                   "1 <= N <= 1000000")
        if spacing != "lin" and not (a > 0 and b > 0):
            raise CamdynInputError(f"argument --grid: {name}: a {spacing} grid needs "
                                   "START, STOP > 0")
        if spacing == "log":
            values = np.geomspace(a, b, n)
        elif spacing == "inv":
            values = 1.0 / np.linspace(1.0 / a, 1.0 / b, n)
        else:
            values = np.linspace(a, b, n)
    if values.size == 0 or not np.all(np.isfinite(values)):
        raise CamdynInputError(f"argument --grid: {name}: {rng!r} must give finite numbers")
    twice = repeated(values)
    if twice is not None:
        raise CamdynInputError(f"argument --grid: {name}: {rng!r} gives {twice:g} more than "
                               "once; give each value once")
    return name, values


def repeated(values) -> float | None:
    """A value that occurs more than once in ``values``, or None: a grid's axis is a
    coordinate, one row per value (a Dataset with a repeated coordinate cannot be selected
    by it, and the table would hold the same run twice)."""
    v = np.sort(np.asarray(values, dtype=float))
    same = np.flatnonzero(v[1:] == v[:-1])
    return float(v[same[0]]) if same.size else None


MAX_POINTS = 1_000_000
"""The most grid points of one sweep, all axes combined (as N of one axis)."""


def parse_grid(texts) -> dict:
    """{name: values} of repeated ``--grid`` texts (:func:`parse_axis`); a name given twice
    is refused (a dict would keep the last one without a word)."""
    grid: dict = {}
    for text in texts:
        name, values = parse_axis(text)
        if name in grid:
            raise CamdynInputError(f"argument --grid: {name} is given twice; give each "
                                   "parameter one axis")
        grid[name] = values
    return grid


def _axes(grid: dict) -> dict:
    if not isinstance(grid, dict) or not grid:
        raise CamdynInputError("a sweep needs a grid: {parameter name: values}")
    out = {}
    for name, values in grid.items():
        v = np.atleast_1d(np.asarray(values, dtype=float)).ravel()
        if v.size == 0 or not np.all(np.isfinite(v)):
            raise CamdynInputError(f"grid {name}: give finite numbers, got {values!r}")
        twice = repeated(v)
        if twice is not None:
            raise CamdynInputError(f"grid {name}: {twice:g} is given more than once; give "
                                   "each value once")
        out[str(name)] = v
    total = math.prod(v.size for v in out.values())
    if total > MAX_POINTS:
        # the table of every combination would not fit in memory (1e5 x 1e5 needed 75 GiB)
        raise CamdynInputError(f"grid {' x '.join(f'{k} ({v.size})' for k, v in out.items())}: "
                               f"{total:.3g} points; at most {MAX_POINTS:,} in one sweep")
    return out


def _points(axes: dict) -> np.ndarray:
    """Every combination, the first axis slowest: shape (n_points, n_axes)."""
    mesh = np.meshgrid(*axes.values(), indexing="ij")
    return np.stack([m.ravel() for m in mesh], axis=1)


# -- the result -------------------------------------------------------------------------------

@dataclass
class SweepResult:
    """A sweep's table: ``columns[name]`` for every axis, figure and statistic, one row per
    grid point (the first axis slowest)."""

    target: str
    axes: dict                   # name -> the axis's values
    figures: tuple               # every figure and its <figure>_error, in the table's order
    columns: dict
    seconds: float = 0.0         # wall time of the runs
    where: str = "local"         # "local, K threads" or "dask <address>"
    stats: tuple = ("warnings", "n_steps")
    meta: dict = field(default_factory=dict)
    files: list = field(default_factory=list)      # what sweep(..., out=) wrote
    held: dict = field(default_factory=dict)       # the model's other inputs -> their value

    def __len__(self) -> int:
        return len(next(iter(self.columns.values())))

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            return self.columns[name]
        except KeyError:
            raise KeyError(f"no column {name!r}; columns: {', '.join(self.columns)}") from None

    @property
    def names(self) -> list:
        """The table's columns: the axes, every figure and its error, the model's other
        inputs at the value every run had (:func:`held`), the warnings and the steps."""
        return [*self.axes, *self.figures, *self.held, *self.stats]

    def rows(self) -> list[dict]:
        return [{k: _item(self.columns[k][i]) for k in self.names} for i in range(len(self))]

    @property
    def warned(self) -> int:
        """How many grid points have a warning (the warnings column)."""
        return int(sum(1 for w in self.columns["warnings"] if w))

    def summary(self) -> str:
        """One line: how many runs, where, the figures, how many points warned."""
        warned = (f"; {self.warned} of {len(self)} points warned (the warnings column)"
                  if self.warned else "; no warnings")
        est = "" if self.meta.get("estimated", True) else "; no error estimates"
        figs = [f for f in self.figures if not f.endswith("_error")]
        kept = self.meta.get("kept", 0)
        runs = (f"{len(self)} runs" if not kept else
                f"{len(self)} points ({kept} kept from the table, {len(self) - kept} run now)")
        return (f"{runs} of {self.target} in {self.seconds:.2f} s ({self.where}); "
                f"figures: {', '.join(figs)}{self._held_text()}{est}{warned}")

    def _held_text(self) -> str:
        """The inputs off the grid, in words: those the model's defaults gave and those the
        target was given."""
        defaults = set(self.meta.get("defaults", ()))
        parts = []
        for words, names in (("at the model's defaults", [k for k in self.held if k in defaults]),
                             ("as given", [k for k in self.held if k not in defaults])):
            if names:
                parts.append(", ".join(f"{k} = {self.held[k]:g}" for k in names) + f" {words}")
        return f"; held: {'; '.join(parts)}" if parts else ""

    def to_csv(self, path) -> Path:
        with writing(path) as path:
            path.write_text(_head(self.names) + _lines(self.columns, self.names))
        return path

    def to_parquet(self, path) -> Path:
        try:
            import pyarrow as pa
            import pyarrow.parquet as pq
        except ImportError:
            raise CamdynInputError("Parquet needs pyarrow: pip install pyarrow") from None
        with writing(path) as path:
            pq.write_table(pa.table({k: (self.columns[k].astype(str) if k == "warnings"
                                         else self.columns[k]) for k in self.names}), path)
        return path

    def charts(self, out_dir) -> list[Path]:
        """One PNG per figure (:meth:`chart`)."""
        out_dir = out_folder(out_dir)
        written = []
        for fig_name in [f for f in self.figures if not f.endswith("_error")]:
            with writing(chart_file(out_dir, fig_name)) as path:
                self.chart(fig_name).savefig(path, dpi=110)
            written.append(path)
        return written

    @property
    def units(self) -> dict:
        """name -> unit of every axis and figure the target declares one for."""
        return dict(self.meta.get("units", {}))

    def _shape(self) -> tuple:
        return tuple(len(v) for v in self.axes.values())

    def to_pandas(self):
        """The table as a pandas DataFrame, one row per grid point (the first axis slowest),
        every figure beside its ``<figure>_error``; ``.attrs`` holds the units, the target
        and the summary line."""
        pd = display.need("pandas", "SweepResult.to_pandas()")
        frame = pd.DataFrame({k: self.columns[k] for k in self.names})
        frame.attrs.update(units=self.units, target=self.target, summary=self.summary())
        return frame

    def to_xarray(self):
        """The sweep as an xarray Dataset on its grid: the axes are its coordinates (and
        dimensions, in the grid's order), every figure, its ``<figure>_error``, the warnings
        and the step counts (integers) are variables over them; the model's inputs off the
        grid are coordinates without a dimension, at their value; units and descriptions are
        attributes."""
        xr = display.need("xarray", "SweepResult.to_xarray()")
        dims = list(self.axes)
        shape = self._shape()
        units = self.units
        data = {}
        for k in [*self.figures, *self.stats]:
            values = np.asarray(self.columns[k], dtype=object if k == "warnings" else None)
            attrs = {"units": units.get(k.removesuffix("_error"), "")}
            if k.endswith("_error"):
                attrs["description"] = f"error estimate of {k.removesuffix('_error')}"
            data[k] = (dims, values.reshape(shape), attrs)
        coords = {k: (k, np.asarray(v), {"units": units.get(k, "")}) for k, v in self.axes.items()}
        defaults = set(self.meta.get("defaults", ()))
        for k, v in self.held.items():      # off the grid: a coordinate without a dimension
            coords[k] = ((), v, {"units": units.get(k, ""), "description": (
                "held at the model's default" if k in defaults else "held as given")})
        return xr.Dataset(data, coords=coords, attrs={"target": self.target,
                                                     "summary": self.summary()})

    def _repr_html_(self) -> str:
        figs = [f for f in self.figures if not f.endswith("_error")]
        head = [*self.axes, *[f"{f} ± error" for f in figs], "warnings"]
        rows = []
        for i in range(len(self)):
            row = [_item(self.columns[k][i]) for k in self.axes]
            for f in figs:
                e = self.columns.get(f"{f}_error")
                row.append(display.plus_minus(_item(self.columns[f][i]),
                                              None if e is None else _item(e[i])))
            row.append(self.columns["warnings"][i] or "")
            rows.append(row)
        chart = display.picture(self.chart(figs[0])) if figs and len(self) > 1 else ""
        return display.page(self.summary(), display.table(head, rows), chart)

    def chart(self, fig_name: str):
        """The figure ``fig_name`` against the last axis with more than one value, a line for
        every combination of the other axes (up to 12, evenly picked), its error estimate
        shaded about it, the points that warned marked, and a footnote with the largest
        estimate and how many points warned (the answer contract on a chart): a matplotlib
        Figure, made without pyplot so that a notebook's backend stays as it is."""
        from matplotlib.figure import Figure

        names = list(self.axes)
        shape = self._shape()
        multi = [k for k, n in enumerate(shape) if n > 1]
        x_ax = multi[-1] if multi else len(names) - 1
        others = [k for k in range(len(names)) if k != x_ax]
        combos = list(product(*[range(shape[k]) for k in others]))
        if len(combos) > 12:
            combos = [combos[int(round(j))] for j in np.linspace(0, len(combos) - 1, 12)]
        x = self.axes[names[x_ax]]
        warned = np.array([bool(w) for w in self.columns["warnings"]]).reshape(shape)
        data = np.asarray(self.columns[fig_name], dtype=float).reshape(shape)
        err = self.columns.get(f"{fig_name}_error")
        err = None if err is None else np.asarray(err, dtype=float).reshape(shape)
        fig = Figure(figsize=(7, 4.6))
        ax = fig.subplots()
        for c in combos:
            idx = [0] * len(names)
            for k, j in zip(others, c):
                idx[k] = j
            idx[x_ax] = slice(None)
            label = ", ".join(f"{names[k]} = {self.axes[names[k]][j]:g}"
                              for k, j in zip(others, c))
            y = data[tuple(idx)]
            # a marker where the x axis has one value: a line of one point draws nothing
            line, = ax.plot(x, y, lw=1.0, label=label or None,
                            marker="o" if len(x) == 1 else None)
            if err is not None and np.any(np.isfinite(err[tuple(idx)])):
                e = err[tuple(idx)]
                ax.fill_between(x, y - e, y + e, color=line.get_color(), alpha=0.25, lw=0)
            w = warned[tuple(idx)]
            if w.any():
                ax.plot(np.asarray(x)[w], y[w], "x", color="#e53935", ms=5)
        finite = data[np.isfinite(data)]
        if finite.size and finite.min() > 0 and finite.max() > 100 * finite.min():
            ax.set_yscale("log")     # U0 and U0'' span decades between the dips of (3.5)
        ax.set_xlabel(names[x_ax])
        ax.set_ylabel(fig_name)
        ax.set_title(f"{self.target}: {fig_name}", fontsize=10)
        ax.grid(alpha=0.3)
        if combos and combos[0]:
            ax.legend(fontsize=7)
        note = chart_note({fig_name: (data, err if err is not None else
                                      np.full(data.shape, np.nan))},
                          self.columns["warnings"], points=len(self))
        fig.text(0.01, 0.01, note + ("; x: a point that warned" if warned.any() else "")
                 + ("; shaded: ± the estimate" if err is not None
                    and np.any(np.isfinite(err)) else ""), fontsize=7)
        fig.tight_layout(rect=(0, 0.07, 1, 1))
        return fig

    def write(self, out_dir) -> list[Path]:
        """sweep.csv, sweep.parquet (with pyarrow) and the charts into ``out_dir``."""
        out_dir = out_folder(out_dir)
        return [self.to_csv(out_dir / TABLE)] + self._beside(out_dir)

    def _beside(self, out_dir) -> list[Path]:
        """What goes beside the table: sweep.parquet (with pyarrow) and the charts."""
        files = []
        try:
            files.append(self.to_parquet(out_dir / "sweep.parquet"))
        except OutFolderError:
            raise
        except CamdynInputError:          # no pyarrow: the CSV is the table
            pass
        return files + self.charts(out_dir)


def _cell(v) -> str:
    """A table cell that reads back to the last bit: 17 digits, a whole number as such,
    empty for NaN and for no warnings."""
    if isinstance(v, str):
        return '"' + v.replace('"', '""') + '"' if v else ""
    v = float(v)
    if math.isnan(v):
        return ""
    if math.isinf(v) or v != int(v) or abs(v) >= 1e15:
        return f"{v:.17g}"
    return str(int(v)) if v or math.copysign(1.0, v) > 0 else "-0"


def _head(names) -> str:
    return ",".join(names) + "\n"


def _lines(columns: dict, names) -> str:
    """The table's rows of ``columns`` as CSV text."""
    n = len(columns[names[0]])
    return "".join(",".join(_cell(columns[k][i]) for k in names) + "\n" for i in range(n))


def _item(v):
    return v if isinstance(v, str) else v.item()


MODEL_RTOL = 1e-9
"""A model's sweep runs at this rtol unless told otherwise (fig. 4.11's grid)."""


# -- the sweep ------------------------------------------------------------------------------------

DASK_CHUNK = 512
"""Grid points per Dask task at most (and at least the target's chunk; 16 tasks or more where
the grid allows): each task costs the cluster about a millisecond and a pickled target, which at
32 points of CAMSHAFT-1 (6 ms of work) made a 20,000-point sweep on 2 workers twice as slow as
on 2 threads; at 512 they take the same time."""


def sweep(target, grid: dict, *, jobs: int | None = None, dask=None, progress: bool = True,
          t_end: float | None = None, method: str | None = None, rtol: float | None = None,
          law: str | None = None, step: float | None = None, chunk: int | None = None,
          estimate: bool = True, out=None, resume: bool = False, atol: float | None = None,
          state_atol: dict | None = None, dependent=None) -> SweepResult:
    """Run ``target`` (a name, or a target of runtime/targets) at every point of ``grid``
    ({name: values}); ``jobs`` threads (default: every core), or the Dask cluster ``dask``;
    a progress bar on stderr.  Every figure comes with its error estimate (the grid again
    one notch tighter: twice the time) unless ``estimate`` is False, and every point with
    its run's warnings (runtime/measure/contract.py).

    With ``out`` (a folder) the table is written there as the grid runs: sweep.csv, each
    chunk's rows appended once both its passes are in, then sweep.parquet and the charts
    (``.files``).  ``resume`` continues the table a stopped sweep of the same target, grid
    and settings left there: its rows are kept, the others run, and the table ends as an
    uninterrupted sweep's, to the last bit.  ``dependent``: a constrained model's dependent
    coordinates (Simulator's ``dependent``) when ``target`` is a model's name."""
    from ..targets.resolve import is_model, resolve

    if dask is not None and jobs is not None:
        raise CamdynInputError("--jobs and --dask: give one (threads here, or the Dask "
                               "cluster's workers)")
    if resume and out is None:
        raise CamdynInputError("--resume continues the table in --out: give the folder")
    if isinstance(target, str):
        if rtol is None and (method or "dp54") in ADAPTIVE and is_model(target):
            rtol = MODEL_RTOL
        # a model that declares no rise: its states at t_end (runtime/targets/resolve.py)
        tgt = resolve(target, model_class=None, t_end=t_end, method=method, rtol=rtol, law=law,
                      step=step, atol=atol, state_atol=state_atol or None, dependent=dependent)
    else:
        tgt = target
    axes = _axes(grid)
    points = _points(axes)
    fixed, defaults = held(tgt, axes)
    if dask is not None and chunk is None:
        chunk = max(tgt.chunk, min(DASK_CHUNK, math.ceil(len(points) / 16)))
    plan = plan_grid(tgt, tuple(axes), points, estimate=estimate,
                     jobs=jobs if dask is None else 1, chunk=chunk)
    with _on_dask(dask) as mapper:
        table = None if out is None else _Table(plan, out, resume, fixed)
        kept = 0 if table is None else table.kept
        bar = _bar((len(plan.points) - kept) * (2 if estimate else 1), progress, tgt.name)
        try:
            run = plan.run(kept, bar=bar, mapper=mapper,
                           each=None if table is None else table.add)
        finally:
            bar.close()
            if table is not None:
                table.close()
    columns = {**run.columns, **_constant(fixed, len(run.columns["n_steps"]))}
    if kept:
        columns = {k: np.concatenate([table.rows[k], v]) for k, v in columns.items()}
    res = SweepResult(tgt.name, axes, run.figures, columns, run.seconds, run.where,
                      meta={"target": run.target, "tight": run.tight, "estimated": estimate,
                            "kept": kept, "units": _units(tgt, {**axes, **fixed}),
                            "defaults": defaults},
                      held=fixed)
    if table is not None:
        res.files = [table.path] + res._beside(table.path.parent)
    return res


def held(tgt, axes: dict) -> tuple[dict, list]:
    """({name: value} of every input the model of ``tgt`` declares that is not an axis, at
    the value every run of the sweep has, [the names of those at the model's default]): a
    sweep of CAMSHAFT-2 over tau runs at some Fa and Fv, and its table says which.  A scene
    (DYNACAM, the beam follower) states its parameters in its file: none here."""
    model = getattr(tgt, "model", None)
    values = getattr(tgt, "values", None)
    if model is None or not isinstance(values, dict) \
            or not hasattr(model, "parameter_vector"):
        return {}, []
    vector = model.parameter_vector(values)
    fixed = {k: float(v) for k, v in zip(model.parameter_names, vector) if k not in axes}
    return fixed, [k for k in fixed if k not in values]


def _constant(fixed: dict, n: int) -> dict:
    """The columns of the inputs off the grid: each its value in every row."""
    return {k: np.full(n, v) for k, v in fixed.items()}


def _units(tgt, axes: dict) -> dict:
    """The units the target declares for the sweep's axes and figures (a blank one left out)."""
    params = tgt.parameters()
    units = {k: params[k].unit for k in axes if k in params and params[k].unit}
    units.update({f.name: f.unit for f in tgt.figures() if f.unit})
    return units


TABLE = "sweep.csv"
"""The sweep's table in its folder."""


def chart_file(out_dir, figure: str) -> Path:
    """Where the chart of ``figure`` goes."""
    return Path(out_dir) / f"{figure}.png"


class _Table:
    """sweep.csv written as the grid runs: the head, then every chunk's rows in the grid's
    order (runtime/core/outdir.py Growing: each chunk whole, flushed and recorded as
    camdyn's, under a key of the sweep's target, settings and grid, which --resume must
    find again); and what it holds so far, for the line a stopped sweep ends with."""

    def __init__(self, plan, out, resume: bool, fixed: dict):
        charts = [chart_file("", f).name for f in plan.figures if not f.endswith("_error")]
        folder = out_folder(out, files=["sweep.parquet", *charts])    # before the runs
        self.path = folder / TABLE
        self.fixed = fixed
        self.names = [*plan.names, *plan.figures, *fixed, "warnings", "n_steps"]
        self.total = len(plan.points)
        key = _key(plan)
        self.rows = None
        if resume and os.path.lexists(self.path):
            self.rows = _kept(self.path, self.names, key, plan)
        self.kept = 0 if self.rows is None else len(self.rows[self.names[0]])
        with signals_held():
            self.file = Growing(self.path, "" if self.rows is not None else _head(self.names),
                                append=self.rows is not None, about=key)
            self._note()

    def add(self, columns: dict) -> None:
        columns = {**columns, **_constant(self.fixed, len(columns[self.names[0]]))}
        with signals_held():    # the rows and the line saying how many: both, or neither
            self.file.add(_lines(columns, self.names))
            self.kept += len(columns[self.names[0]])
            self._note()

    def _note(self) -> None:
        note(f"{self.kept} of {self.total} points kept in {self.path}"
             + (" (--resume continues)" if self.kept < self.total else ""))

    def close(self) -> None:
        self.file.close()


def _key(plan) -> str:
    """The sweep a table belongs to: its target as fitted to the grid (model or scene,
    method, tolerance or step, law, the runs' end), the tighter twin (or none), the axes and
    every point."""
    h = hashlib.sha256(repr((plan.target, plan.tight, plan.names)).encode())
    h.update(np.ascontiguousarray(plan.points).tobytes())
    return f"sweep {h.hexdigest()}"


def _kept(path: Path, names: list, key: str, plan) -> dict:
    """The columns of the rows a stopped sweep left in ``path``, for --resume: only from a
    table camdyn wrote for this very sweep and nobody changed since."""
    found = entry(path)
    if found is None:
        raise CamdynInputError(f"argument --resume: {path} was not written by camdyn, or was "
                               "changed since; drop --resume to start afresh (--overwrite "
                               "replaces it)")
    other = CamdynInputError(f"argument --resume: {path} is the table of another sweep "
                             "(target, grid, method, tolerance, t_end or error estimate); give "
                             "the command that wrote it, or drop --resume to start afresh")
    if found.get("about") != key:
        raise other
    with open(path, newline="") as fh:
        rows = list(csv.reader(fh))
    body = rows[1:]
    if not rows or rows[0] != names or len(body) > len(plan.points) \
            or any(len(r) != len(names) for r in body):
        raise other
    cols = {k: (np.array([r[j] for r in body], dtype=object) if k == "warnings" else
                np.array([float(r[j]) if r[j] else math.nan for r in body]))
            for j, k in enumerate(names)}
    cols["n_steps"] = whole_steps(cols["n_steps"])      # whole numbers, as the runs count
    done = np.column_stack([cols[k] for k in plan.names]) if body else plan.points[:0]
    if not np.array_equal(done, plan.points[:len(body)]):
        raise other
    return cols


class _NoBar:
    def update(self, n=1):
        pass

    def close(self):
        pass


def _bar(total: int, progress: bool, label: str):
    if not progress:
        return _NoBar()
    from tqdm import tqdm

    return tqdm(total=total, desc=f"sweep {label}", unit="run", file=sys.stderr, leave=False,
                mininterval=0.2)


@contextmanager
def _on_dask(dask):
    """The chunks' mapper on the Dask cluster ``dask`` (a Client, a cluster, or a
    scheduler's address), connected before anything is written; None without one."""
    if dask is None:
        yield None
        return
    try:
        from distributed import Client
    except ImportError:
        raise CamdynInputError("--dask needs dask.distributed: pip install 'camdyn[dask]'") from None
    own = False
    if isinstance(dask, Client):
        client = dask
    elif isinstance(dask, str):
        try:
            client = Client(dask, timeout=10)
        except (OSError, TimeoutError, ValueError) as exc:     # ValueError: no port in it
            raise CamdynInputError(f"argument --dask: no Dask scheduler at {dask}: {exc}") from None
        own = True
    else:                          # a cluster object (LocalCluster, ...)
        client = Client(dask)
        own = True
    try:
        yield _Dask(client)
    finally:
        if own:
            client.close()


class _Dask:
    """Run the chunks on a Dask cluster (runtime/targets/grid.py's mapper), their results
    yielded in order; stopped early, the chunks not gathered yet are cancelled."""

    def __init__(self, client):
        self.client = client
        self.where = f"dask {client.scheduler.address}"

    def __call__(self, todo, names, bar):
        futures = self.client.map(run_chunk, [t for t, _ in todo], [names] * len(todo),
                                  [p for _, p in todo], pure=False)
        finished = False
        try:
            for fut, (_, piece) in zip(futures, todo):
                out = fut.result()
                bar.update(len(piece))
                yield out
            finished = True
        finally:
            if not finished:
                self.client.cancel(futures)
