"""Shape-parameter sweep of a cam law on a DYNACAM scene: thesis fig. 8.8 (sec. 8.2).

Fig. 8.8 plots, for the spring-loaded mechanism of fig. A.7.6 driven by the modified sine,
the residual acceleration amplitude U0'' and the variation of the fictitious angular velocity
(Delta Omega_nc) against theta, the instant of the nominal acceleration peak: "the optimum is
found at about theta = 0.1", "an improvement by a factor of 2.9 in the residual amplitude",
and for the speed variation "an improvement by a factor of 2.7 ..., almost coinciding with the
positional-error optimum" (theta = 0.25 is the cycloid (A.2.17)).

:func:`sweep` runs the scene once per value of the law's shape parameter (modified sine's
theta, or the constant-acceleration fraction c of the sine-constant-cosine law) and keeps the
summary's U0dd, U0 and speed_variation_max (runtime/targets/dynacam_scene.py), each with the
error estimate of the answer contract (a second run at rtol/10, the sampling and the window)
unless asked not to, and the run's warnings.
"""
from __future__ import annotations

import csv
import dataclasses
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from camdyn.generated import camlaws
from camdyn.runtime.core import laws
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.core.outdir import out_folder, writing
from camdyn.runtime.measure.contract import answer, chart_note
from camdyn.runtime.targets import scene_files
from camdyn.runtime.targets.dynacam_scene import DynacamTarget

FIELDS = ("U0dd", "speed_variation_max", "U0")
"""The summary figures kept per grid point."""

DEFAULT_SPAN = {"modified-sine": (0.05, 0.25)}
"""Default grid ends per law: fig. 8.8 runs from the peak near the start to the cycloid."""


def shape_parameter(law: str) -> dict:
    """The law's shape parameter (name, low, high, default) or a CamdynInputError."""
    laws.choose(law, None)  # checks the name
    spec = next(l for l in camlaws.LAWS if l["key"] == law)["parameter"]
    if spec is None:
        with_par = [l["key"] for l in camlaws.LAWS if l["parameter"] is not None]
        raise CamdynInputError(f"argument --law: the {law} law has no shape parameter to "
                               f"sweep; laws with one: {', '.join(with_par)}")
    return spec


def grid(law: str, n: int) -> np.ndarray:
    """n values of the shape parameter: fig. 8.8's span for the modified sine, else the open
    range shrunk by a tenth at each end."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 2 <= n <= 200:
        raise CamdynInputError(f"argument --n: {n!r} is out of range: an integer from 2 to 200")
    spec = shape_parameter(law)
    lo, hi = DEFAULT_SPAN.get(law, (None, None))
    if lo is None:
        pad = 0.1 * (spec["high"] - spec["low"])
        lo, hi = spec["low"] + pad, spec["high"] - pad
    return np.linspace(lo, hi, n)


def sweep(scene, law: str = "modified-sine", values=None, n: int = 9, errors: bool = True,
          progress=None) -> list[dict]:
    """One row per shape-parameter value: the value and the scene's U0dd, speed variation and
    U0 (with ``<figure>_error`` when ``errors``: the answer contract's, runtime/measure/
    contract.py) and the run's warnings, joined by "; "."""
    spec = shape_parameter(law)
    values = grid(law, n) if values is None else np.asarray(values, dtype=float).ravel()
    for v in values:
        laws.choose(law, float(v))   # range check before any run
    rows = []
    it = values
    if progress:
        from tqdm import tqdm

        it = tqdm(values, desc=f"sweep {spec['name']}", unit="run", file=progress)
    for v in it:
        target = DynacamTarget.from_scene(dataclasses.replace(scene, law=law, theta=float(v)))
        a = answer(target, estimate=errors)
        row = {spec["name"]: float(v)}
        row.update({k: a.figures[k] for k in FIELDS})
        if errors:
            row.update({f"{k}_error": a.errors.get(k) for k in FIELDS})
        row["warnings"] = "; ".join(a.warnings)
        rows.append(row)
    return rows


def best(rows: list[dict], figure: str = "U0dd") -> dict:
    """The row where ``figure`` is least."""
    return min(rows, key=lambda r: r[figure])


def write_csv(rows: list[dict], path) -> Path:
    with writing(path) as path, path.open("w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    return path


def write_png(rows: list[dict], name: str, title: str, path, own=None) -> Path:
    """U0'' and the largest fictitious angular-velocity variation against the parameter
    (the two curves of fig. 8.8), the scene's own value marked."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x = np.array([r[name] for r in rows])
    fig, axes = plt.subplots(2, 1, figsize=(6.4, 6.0), sharex=True)
    for ax, figure, label in ((axes[0], "U0dd", "residual acceleration U0''"),
                              (axes[1], "speed_variation_max", "max |dOmega_nc|/w_s")):
        y = np.array([r[figure] for r in rows])
        err = np.array([r.get(f"{figure}_error") or 0.0 for r in rows])
        ax.errorbar(x, y, yerr=err if err.any() else None, marker="o", ms=4, capsize=2)
        i = int(np.argmin(y))
        ax.plot(x[i], y[i], "rv", label=f"least at {name} = {x[i]:.3g}")
        if own is not None:
            ax.axvline(own, color="0.6", ls="--", lw=0.8, label=f"scene's {name} = {own:g}")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axes[1].set_xlabel(name)
    axes[0].set_title(title, fontsize=9)
    fig.text(0.01, 0.01, chart_note(
        {f: ([r[f] for r in rows], [r.get(f"{f}_error") for r in rows])
         for f in ("U0dd", "speed_variation_max")},
        [r.get("warnings", "") for r in rows], points=len(rows)), fontsize=7)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
    with writing(path) as path:
        fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


@dataclass
class Sweep:
    """A law's shape parameter swept on a scene: the rows of :func:`sweep` and the files
    written."""

    scene: str                  # the scene's title
    law: str
    parameter: str              # the swept parameter's name (theta, c)
    rows: list
    files: list = field(default_factory=list)
    figures = FIELDS

    def best(self, figure: str) -> dict:
        return best(self.rows, figure)

    @property
    def warnings(self) -> list:
        """The runs' warnings, each naming its parameter value."""
        return [f"{self.parameter} = {r[self.parameter]:.4g}: {r['warnings']}"
                for r in self.rows if r["warnings"]]

    def as_dict(self) -> dict:
        return {"scene": self.scene, "law": self.law, "parameter": self.parameter,
                "rows": self.rows, "warnings": self.warnings, "files": self.files}


def parse_values(law: str, text: str) -> list:
    """The values of the comma-separated ``text`` (the option --values), each in the law's
    range, or a CamdynInputError naming --values."""
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        raise CamdynInputError(f"argument --values: {text!r} is not a comma-separated list of "
                               "numbers") from None
    shape_parameter(law)                 # first: has the law a parameter at all
    for v in values:                     # named --values, not --theta
        try:
            laws.choose(law, v)
        except CamdynInputError as exc:
            raise CamdynInputError(f"argument --values: {exc}") from None
    return values


FILES = ("laws_sweep.csv", "laws_sweep.png")
"""What a shape sweep writes into its folder."""


def sweep_scene(scene: str, law: str | None = None, values: str | None = None,
                n: int | None = None, errors: bool = True, out=None, progress=None) -> Sweep:
    """`camdyn laws --sweep SCENE`: the built-in or TOML scene ``scene`` run over ``values``
    (comma-separated) or an ``n``-point grid (default 9) of the shape parameter of ``law``
    (default the modified sine); with ``out``, laws_sweep.csv and laws_sweep.png there."""
    law = law or "modified-sine"
    sc = scene_files.load(scene)
    out_folder(out, files=FILES)
    grid_values = None if values is None else parse_values(law, values)
    rows = sweep(sc, law, grid_values, 9 if n is None else n, errors=errors, progress=progress)
    name = shape_parameter(law)["name"]
    result = Sweep(sc.title, law, name, rows)
    if out:
        folder = Path(out)
        own = sc.theta if sc.law == law else None
        result.files = [str(write_csv(rows, folder / FILES[0])),
                        str(write_png(rows, name, f"{sc.title}: {law}, {name} swept",
                                      folder / FILES[1], own))]
    return result
