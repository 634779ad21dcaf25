"""Cam-law selection: the criteria of thesis sec. 9.2.2 for every law of the library at a given
tau and Fa, and the nominal characteristics of App. 2 they start from.

Per law:
    U0_envelope, U0dd_envelope   the residual amplitudes a designer reads at (tau, Fa): the
                                 envelope through the maxima of the CAMSHAFT-1 graphs (4.15)
                                 around tau (runtime/measure/envelope.py; runs over 1.5 tuning
                                 dips either side of tau, DP54 rtol 1e-9), not the value at tau
                                 itself, which may sit in a tuning dip (secs 3.5, 8.2.6), with
                                 their errors
    impact_T0, _T05, _T1         impact sensitivity after backlash at T = 0, 1/2, 1: the
                                 relative impact speed per S^(2/3), r_e/S^(2/3) =
                                 1/2 |H'''|^(1/3) 6^(2/3), from (3.15) made dimensionless as
                                 (3.16) is read (thesis/theory/impact.py); infinite where H'' jumps
                                 (an impact without backlash)
    H1_max, H2_max, torque_max   peak velocity, peak |acceleration|, peak torque factor H' H''
                                 (A.2.7), from the App. 2 table (thesis/theory/lawtable.py)
    rho_min, alpha_max           with a cam geometry: the least radius of curvature of the
                                 profile where it is convex and the largest pressure angle
                                 (runtime/cam/profile.py)
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field

import numpy as np

from camdyn.runtime.core.errors import CamdynInputError, SimulationError
from camdyn.runtime.core.outdir import out_folder, writing
from camdyn.runtime.measure.contract import chart_note
from camdyn.runtime.measure.envelope import envelope, envelope_error, tau_grid
from camdyn.runtime.targets.grid import run_grid
from camdyn.runtime.targets.model_target import ModelTarget
from camdyn.thesis.theory import lawtable

from .graphs import LATTICE_CAP, PER_DIP, phase_factor

SIX23 = 6 ** (2 / 3)

RTOL = 1e-9
"""Tolerance of the envelope runs (DP54), each with its own estimate (the run one notch
tighter), which the envelope's error carries."""


def impact_sensitivity(jerk) -> float:
    """r_e/S^(2/3) = 1/2 |H'''|^(1/3) 6^(2/3) at a reversal point (3.15), (3.16); inf for an
    impulsive jerk (None in the App. 2 table: H'' jumps there)."""
    if jerk is None or not math.isfinite(jerk):
        return math.inf
    return 0.5 * abs(jerk) ** (1 / 3) * SIX23


def window(key: str, tau: float, Fa: float, theta=None, spacings: float = 1.5) -> np.ndarray:
    """The tau grid the envelopes at tau are read from: ``spacings`` tuning-dip spacings either
    side of 1/tau (the dips of CAMSHAFT-1 lie about 1/phase_factor apart in 1/tau,
    graphs.py), so that maxima bracket tau on both sides (a window of 0.8 to 1.25 tau held
    one maximum at tau = 0.3 and read the envelope 15 % low there, held flat from tau =
    0.286), 2 PER_DIP samples a spacing, uniform in 1/tau (every other one of them is the
    grid of the envelope's sampling error); tau at most LATTICE_CAP."""
    w = spacings / phase_factor(key, theta, Fa)
    x_lo, x_hi = max(1.0 / tau - w, 1.0 / LATTICE_CAP), 1.0 / tau + w
    n = max(int(math.ceil(PER_DIP * (x_hi - x_lo))), 2)
    return tau_grid(1.0 / x_hi, 1.0 / x_lo, 2 * n + 1)


WIDEST = 4.5
"""The widest window, in dip spacings either side: a law whose dips lie further apart than
CAMSHAFT-1's cycloid (the parabolic law's) is read from a wider one, up to this."""


def envelopes_at(key: str, tau: float, Fa: float, theta=None, estimate: bool = True) -> dict:
    """The (U0, U0'') envelopes through the maxima of the CAMSHAFT-1 graphs of law ``key`` at
    tau, from one compiled grid of runs over :func:`window` (DP54, rtol RTOL), each with its
    error (runtime/measure/envelope.py's envelope_error: the sampling and the runs' own
    estimates) and the runs' warnings."""
    target = ModelTarget.of("camshaft1", {"tau": tau, "Fa": Fa}, rtol=RTOL, law=key,
                            theta=theta)
    spacings = 1.5
    while True:
        # widened a spacing at a time until maxima bracket tau (the estimate exists) on both
        # graphs, or the window reaches WIDEST or the largest tau
        taus = window(key, tau, Fa, theta, spacings)
        cols = run_grid(target, ("tau",), taus[:, None], estimate=True, jobs=1).columns
        errs = {f: float(envelope_error(taus, cols[f], cols[f"{f}_error"])(tau))
                for f in ("U0", "U0dd")}
        if all(map(math.isfinite, errs.values())) or spacings >= WIDEST \
                or taus[-1] >= LATTICE_CAP * (1 - 1e-12) and taus[0] <= 1.0 / (1.0 / tau + WIDEST):
            break
        spacings += 1.0
    out = {}
    for fig in ("U0", "U0dd"):
        out[f"{fig}_envelope"] = float(envelope(taus, cols[fig])(tau))
        e = errs[fig]
        out[f"{fig}_envelope_error"] = e if estimate and math.isfinite(e) else None
    warned = [w for w in cols["warnings"] if w]
    out["warnings"] = ([f"{len(warned)} of {len(taus)} runs of the envelope warned; the first: "
                        f"{warned[0]}"] if warned else [])
    unbracketed = [f for f in ("U0", "U0dd") if not math.isfinite(errs[f])]
    if estimate and unbracketed:
        out["warnings"].append(
            f"no estimate of the {' and '.join(unbracketed)} envelope at tau = {tau:g}: no "
            f"maximum of the graph brackets it within {spacings:g} dip spacings (or below tau = "
            f"{LATTICE_CAP:g}), so the envelope there holds the nearest maximum")
    return out


FA_MAX = 100.0
"""The largest Fa that CAMSHAFT-1, whose envelopes the selection reads, accepts."""


def check(tau: float, Fa: float) -> None:
    if not 0 < tau < 0.99:
        raise CamdynInputError(f"tau={tau:g} is out of range: 0 < tau < 0.99")
    if not 0 <= Fa <= FA_MAX:
        # inf passed here and failed in the first run, after its progress line
        raise CamdynInputError(f"Fa={Fa:g} is out of range: 0 <= Fa <= {FA_MAX:g} (CAMSHAFT-1's "
                               "declared range, (4.14))")


def criteria(key: str, tau: float, Fa: float, theta=None, geometry: dict | None = None,
             estimate: bool = True) -> dict:
    """The criteria of sec. 9.2.2 for law ``key`` (module doc), each figure a run gives with
    its error (``<figure>_error``; the closed forms of App. 2 are exact) and the runs'
    ``warnings``; ``geometry``: stroke, base_radius, roller_radius (m), optionally offset and
    angles_deg, for rho_min and alpha_max."""
    check(tau, Fa)
    p = lawtable.properties(key, theta)
    out = {"law": key, "tau": tau, "Fa": Fa, "warnings": []}
    try:
        out.update(envelopes_at(key, tau, Fa, theta, estimate=estimate))
    except SimulationError as exc:       # an impulsive law the run cannot follow
        out["U0_envelope"] = out["U0dd_envelope"] = None
        out["note"] = str(exc)
    out["impact_T0"] = impact_sensitivity(p.jerk_0)
    out["impact_T05"] = impact_sensitivity(p.jerk_half)
    out["impact_T1"] = impact_sensitivity(p.jerk_1)
    out["H1_max"] = p.H1_max
    out["H2_max"] = max(abs(p.H2_max), abs(p.H2_min))
    out["torque_max"] = p.torque_max
    if geometry:
        from camdyn.runtime.cam.profile import CamProfile

        cam = CamProfile(law=key, law_parameter=theta, **geometry)
        checks = {c.name: c for c in cam.checks}
        # the profile's radius where the pitch curve is convex (below zero it is undercut):
        # the smallest convex |rho_p| less the roller, refined between the samples
        under = checks["undercut"]
        finite = math.isfinite(under.value)
        out["rho_min"] = under.value - cam.roller_radius if finite else None
        out["rho_min_error"] = under.error if finite else None
        if not under.ok and "jumps" in under.message:
            # a velocity that jumps cuts a corner into the profile: its radius there is 0
            out["rho_min"], out["rho_min_error"] = 0.0, 0.0
            out["warnings"].append(under.message)
        alpha = checks["pressure angle"]
        out["alpha_max_deg"], out["alpha_max_deg_error"] = alpha.value, alpha.error
    return out


def table(tau: float, Fa: float, theta=None, geometry=None, progress=None,
          estimate: bool = True) -> list[dict]:
    """The criteria of every law of the library (modified sine at ``theta``)."""
    check(tau, Fa)                      # before the first run: one error, no progress lines
    if theta is not None:
        lawtable.properties("modified-sine", theta)     # its range, before the first law runs
    if geometry:
        from camdyn.runtime.cam.profile import CamProfile

        CamProfile(**geometry)          # the geometry's ranges, checked once
    rows = []
    for key in lawtable.LAWS:
        if progress:
            progress(f"law {key}")
        rows.append(criteria(key, tau, Fa, theta if key == "modified-sine" else None, geometry,
                             estimate))
    return rows


ESTIMATED = ("U0_envelope", "U0dd_envelope", "rho_min", "alpha_max_deg")
"""The columns a run or a sampled profile gives, each with its ``<column>_error``; the others
are App. 2's closed forms, exact."""

COLUMNS = (("U0_envelope", "U0 env."), ("U0dd_envelope", "U0'' env."),
           ("impact_T0", "impact T=0"), ("impact_T05", "impact T=1/2"),
           ("impact_T1", "impact T=1"), ("H1_max", "H'max"), ("H2_max", "|H''|max"),
           ("torque_max", "(H'H'')max"), ("rho_min", "rho_min m"), ("alpha_max_deg", "alpha_max"))


def chart(rows: list[dict], path) -> str:
    """One panel per criterion, a bar per law (lower is better for every one of them)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cols = [(k, t) for k, t in COLUMNS if any(r.get(k) is not None for r in rows)]
    fig, axes = plt.subplots(2, (len(cols) + 1) // 2, figsize=(3.2 * ((len(cols) + 1) // 2), 6.4))
    names = [r["law"] for r in rows]
    for ax, (k, title) in zip(axes.ravel(), cols):
        vals = [r.get(k) for r in rows]
        finite = [v for v in vals if v is not None and math.isfinite(v)]
        top = 1.15 * max(finite) if finite else 1.0
        bars = [top if v is not None and not math.isfinite(v) else (v or 0.0) for v in vals]
        ax.barh(names, bars, color=["#e53935" if v is not None and not math.isfinite(v)
                                    else "#1e88e5" for v in vals])
        ax.set_title(title, fontsize=9)
        ax.tick_params(labelsize=7)
    for ax in axes.ravel()[len(cols):]:
        ax.axis("off")
    r0 = rows[0]
    fig.suptitle(f"Cam-law selection at tau = {r0['tau']:g}, Fa = {r0['Fa']:g} "
                 "(thesis sec. 9.2.2; red: infinite)", fontsize=10)
    shown = {t: ([r[k] for r in rows if r.get(k) is not None],
                 [r.get(f"{k}_error") for r in rows if r.get(k) is not None])
             for k, t in cols if k in ESTIMATED}
    fig.text(0.01, 0.01, chart_note(shown, [f"{r['law']}: {w}" for r in rows
                                            for w in r.get("warnings", ())])
             + "; the other columns: App. 2's closed forms", fontsize=7)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    with writing(path):
        fig.savefig(path, dpi=110)
    plt.close(fig)
    return str(path)


def characteristics(theta=None) -> list:
    """App. 2's nominal characteristics of every law of the library (modified sine at
    ``theta``), as thesis/theory/lawtable.py derives them: `camdyn laws`."""
    try:
        return [lawtable.properties(k, theta if k == "modified-sine" else None)
                for k in lawtable.LAWS]
    except ValueError as exc:
        raise CamdynInputError(str(exc)) from None


@dataclass
class Selection:
    """The criteria of every law at (tau, Fa): the rows of :func:`table`, the columns any row
    has a value in, and the files written."""

    tau: float
    Fa: float
    rows: list
    columns: list               # (key, title) of COLUMNS
    files: list = field(default_factory=list)
    angles_deg: tuple | None = None     # the cam's, with a geometry

    @property
    def warnings(self) -> list:
        """The runs' warnings, each naming its law."""
        return [f"{r['law']}: {w}" for r in self.rows for w in r.get("warnings", ())]

    def as_dict(self) -> dict:
        """The rows with infinities as None (JSON has none), the warnings and the files."""
        clean = [{k: (None if isinstance(v, float) and math.isinf(v) else v) for k, v in r.items()}
                 for r in self.rows]
        return {"rows": clean, "warnings": self.warnings, "files": self.files,
                "angles_deg": None if self.angles_deg is None else list(self.angles_deg)}


def write_csv(rows: list[dict], columns, path) -> str:
    """One row per law: every column, ``<column>_error`` beside those a run gives, and the
    law's warnings."""
    keys = [x for k, _ in columns for x in ((k, f"{k}_error") if k in ESTIMATED else (k,))]
    with writing(path), open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["law"] + keys + ["warnings"])
        for r in rows:
            w.writerow([r["law"]] + [r.get(k) for k in keys] + ["; ".join(r.get("warnings", ()))])
    return str(path)


FILES = ("laws_selection.csv", "laws_selection.png")
"""What a selection writes into its folder."""


def select(tau, Fa=None, theta=None, stroke=None, base_radius=None, roller_radius=None,
           out=None, progress=None, estimate: bool = True, angles=None) -> Selection:
    """`camdyn laws --tau T [--fa F]`: the criteria of sec. 9.2.2 for every law (Fa = 0 when
    not given), with a cam geometry when all three of stroke, base and roller radius are
    given, at the cam's ``angles`` ('R,D,F,D' in deg, default 90,90,90,90); with ``out``,
    laws_selection.csv and laws_selection.png there."""
    from .turn import angles_argument

    if tau is None:
        raise CamdynInputError("argument --tau: required with --fa (0 < tau < 0.99)")
    out_folder(out, files=FILES)
    geo = (stroke, base_radius, roller_radius)
    if any(g is not None for g in geo) and not all(g is not None for g in geo):
        raise CamdynInputError("arguments --stroke, --base-radius, --roller-radius: give all "
                               "three for the cam's curvature and pressure angle")
    angles_deg = angles_argument(angles)
    if angles_deg is not None and stroke is None:
        raise CamdynInputError("argument --angles: goes with --stroke, --base-radius and "
                               "--roller-radius (the cam's curvature and pressure angle)")
    geometry = None if stroke is None else {
        "stroke": stroke, "base_radius": base_radius, "roller_radius": roller_radius,
        **({} if angles_deg is None else {"angles_deg": angles_deg})}
    Fa = 0.0 if Fa is None else Fa
    rows = table(tau, Fa, theta, geometry, progress, estimate)
    cols = [(k, t) for k, t in COLUMNS if any(r.get(k) is not None for r in rows)]
    result = Selection(tau, Fa, rows, cols, angles_deg=None if geometry is None
                       else tuple(angles_deg or (90.0, 90.0, 90.0, 90.0)))
    if out:
        folder = out_folder(out)
        result.files = [write_csv(rows, cols, folder / FILES[0]), chart(rows, folder / FILES[1])]
    return result
