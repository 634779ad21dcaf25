"""Shape-parameter sweep of a cam law on a DYNACAM scene: thesis fig. 8.8 (sec. 8.2).

Fig. 8.8 plots, for the spring-loaded mechanism of fig. A.7.6 driven by the modified sine,
the residual acceleration amplitude U0'' and the variation of the fictitious angular velocity
(Delta Omega_nc) against theta, the instant of the nominal acceleration peak: "the optimum is
found at about theta = 0.1", "an improvement by a factor of 2.9 in the residual amplitude",
and for the speed variation "an improvement by a factor of 2.7 ..., almost coinciding with the
positional-error optimum" (theta = 0.25 is the cycloid (A.2.17)).

:func:`sweep` runs the scene once per value of the law's shape parameter (modified sine's
theta, or the constant-acceleration fraction c of the sine-constant-cosine law) and keeps the
summary's U0dd, U0 and speed_variation_max (runtime/dynacam.py), each with the error estimate
of a second run at rtol/10 unless asked not to.
"""
from __future__ import annotations

import csv
import dataclasses
from pathlib import Path

import numpy as np

from camdyn.runtime import dynacam, laws
from camdyn.runtime.errors import CamdynInputError

FIELDS = ("U0dd", "speed_variation_max", "U0")
"""The summary figures kept per grid point."""

_DEFAULT_SPAN = {"modified-sine": (0.05, 0.25)}
"""Default grid ends per law: fig. 8.8 runs from the peak near the start to the cycloid."""


def shape_parameter(law: str) -> dict:
    """The law's shape parameter (name, low, high, default) or a CamdynInputError."""
    laws.choose(law, None)  # checks the name
    spec = next(l for l in laws._lib.LAWS if l["key"] == law)["parameter"]
    if spec is None:
        with_par = [l["key"] for l in laws._lib.LAWS if l["parameter"] is not None]
        raise CamdynInputError(f"argument --law: the {law} law has no shape parameter to "
                               f"sweep; laws with one: {', '.join(with_par)}")
    return spec


def grid(law: str, n: int) -> np.ndarray:
    """n values of the shape parameter: fig. 8.8's span for the modified sine, else the open
    range shrunk by a tenth at each end."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 2 <= n <= 200:
        raise CamdynInputError(f"argument --n: {n!r} is out of range: an integer from 2 to 200")
    spec = shape_parameter(law)
    lo, hi = _DEFAULT_SPAN.get(law, (None, None))
    if lo is None:
        pad = 0.1 * (spec["high"] - spec["low"])
        lo, hi = spec["low"] + pad, spec["high"] - pad
    return np.linspace(lo, hi, n)


def sweep(scene, law: str = "modified-sine", values=None, n: int = 9, errors: bool = True,
          progress=None) -> list[dict]:
    """One row per shape-parameter value: the value and the scene's U0dd, speed variation and
    U0 (with ``<figure>_error`` when ``errors``)."""
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
        sc = dataclasses.replace(scene, law=law, theta=float(v))
        summary, _ = dynacam.run(sc)
        row = {spec["name"]: float(v)}
        row.update({k: summary[k] for k in FIELDS})
        if errors:
            err = dynacam.errors(sc, summary)
            row.update({f"{k}_error": err.get(f"{k}_error") for k in FIELDS})
        rows.append(row)
    return rows


def best(rows: list[dict], field: str = "U0dd") -> dict:
    """The row where ``field`` is least."""
    return min(rows, key=lambda r: r[field])


def write_csv(rows: list[dict], path) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="") as fh:
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
    for ax, field, label in ((axes[0], "U0dd", "residual acceleration U0''"),
                             (axes[1], "speed_variation_max", "max |dOmega_nc|/w_s")):
        y = np.array([r[field] for r in rows])
        err = np.array([r.get(f"{field}_error") or 0.0 for r in rows])
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
    fig.tight_layout()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
