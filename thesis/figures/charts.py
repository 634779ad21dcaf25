"""Design charts, the design tools of thesis ch. 8 and sec. 9.2.2 at work: the envelopes of the
response graphs (secs 3.5, 8.2.6), the compiled sweep, the design of App. 7.2's indexing
mechanism, the cam-law selection chart, the least model of sec. 8.2's chain and the cam
profile.

To add a chart: one Figure below with a builder ``(out_dir, quick) -> [png paths]`` that calls
the command's own function (as the ones here do), or, until it exists, ``build=None`` with
``not_reproduced`` saying what is missing."""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np

from camdyn.thesis.runcache import cached_runs

from ..checks.check import Check
from .figure import Claim, Figure
from .plotting import copy


def _envelopes(out_dir, quick):
    from .ch4 import study

    data = study(str(out_dir), quick)
    return [copy(Path(data["folder"]) / "graphs.png", Path(out_dir) / "envelopes.png")]


def _laws(out_dir, quick):
    from ..design import selection

    rows = selection.table(0.15, 0.5)
    return [selection.chart(rows, Path(out_dir) / "laws_selection.png")]


def _profile(out_dir, quick):
    from camdyn.runtime.cam.profile import CamProfile

    cam = CamProfile(stroke=0.015, base_radius=0.026, roller_radius=0.005)
    return [str(cam.write_png(Path(out_dir) / "cam_profile.png"))]


@cached_runs
def _choice(scene_name: str) -> dict:
    """`camdyn simulate SCENE --model auto` on a built-in scene (pre-generated variants only,
    so the answer does not depend on what an earlier run left in the build cache)."""
    from camdyn.runtime.studies import least_model
    from camdyn.runtime.targets import scene_files as scene

    return least_model.choose(scene.load(scene_name), build=False)


def _least_model(out_dir, quick):
    """Predicted error of every reduction of sec. 8.2's chain on fig8_1a (c_z' << c_x) and
    fig8_1b (c_z' >> c_x), the largest over the requested figures, against the tolerance."""
    from .plotting import plt, save

    pyplot = plt()
    fig, axes = pyplot.subplots(1, 2, figsize=(10, 3.8), sharey=True)
    for ax, name in zip(axes, ("fig8_1a", "fig8_1b")):
        out = _choice(name)
        cands = [c for c in out["candidates"] if c["predicted"]]
        worst = [max(c["predicted"].values()) * 100 for c in cands]
        colors = ["tab:green" if c["key"] == out["chosen"] else
                  ("0.6" if c["accepted"] else "tab:red") for c in cands]
        ax.bar(range(len(cands)), worst, color=colors)
        ax.axhline(out["tolerance"] * 100, color="k", ls="--", lw=1, label="tolerance")
        ax.set_xticks(range(len(cands)), [c["key"] for c in cands], rotation=30, ha="right")
        ax.set_yscale("log")
        ax.set_title(f"{name}: chosen {out['chosen']}", fontsize=10)
        ax.grid(alpha=0.3, axis="y")
    axes[0].set_ylabel("predicted error, largest figure [%]")
    axes[0].legend(fontsize=8)
    return [save(fig, out_dir, "least_model")]


def _two_dof_factor(name: str) -> float:
    """U0'' of CAMSHAFT-2 (the 2-DOF reduction) over the full model's, from the probes."""
    out = _choice(name)
    by_key = {c["key"]: c for c in out["candidates"]}
    return by_key["camshaft2"]["probe"]["U0dd"] / by_key["full"]["probe"]["U0dd"]


LEAST_8_3A = Check("least.fig8_3a", "fig8_1a (c_z' << c_x): U0'' of the 2-DOF model over the "
                   "4-DOF model's, from the least-model probes", "sec. 8.2.4, fig. 8.3a", "2.45",
                   lambda: _two_dof_factor("fig8_1a"), rule="rel:0.10",
                   note="the 2-DOF reduction is rejected on this scene")
LEAST_8_3B = Check("least.fig8_3b", "fig8_1b (c_z' >> c_x): U0'' of the 2-DOF model over the "
                   "4-DOF model's, from the least-model probes", "sec. 8.2.4, fig. 8.3b", "1.08",
                   lambda: _two_dof_factor("fig8_1b"), rule="rel:0.10",
                   note="the 2-DOF reduction (CAMSHAFT-2) is chosen on this scene")


_INDEXING = dict(stroke=0.0981, cam_angle_rad=1.745, speed=60.0, mass=45.0, stiffness=3.65e6,
                 c_tan=157109.0, pitch_radius=0.085, ratio=1.745, accuracy=0.5e-3)
"""App. 7.2's indexing mechanism as `camdyn design` takes it (README), with u0 <= 0.5 mm."""

_DESIGN: dict = {}


def _design_result(out_dir=None) -> dict:
    from ..design import method as ds

    if "result" not in _DESIGN or out_dir is not None:
        chart = None if out_dir is None else ds.chart_file(out_dir)
        _DESIGN["result"] = ds.design(**_INDEXING, check=False, chart_path=chart)
    return _DESIGN["result"]


def _design(out_dir, quick):
    return [_design_result(out_dir)["chart"]]


# the machine's figures are closed forms of the inputs (App. 7 (5)-(12)): exact, although the
# design they are read from also runs the graphs
DESIGN_TAU = Check("design.A7_2.tau", "indexing mechanism through `camdyn design`: tau = T_e/t_m",
                   "App. 7.2 (9)", "0.08", lambda: _design_result()["machine"]["tau"], exact=True)
DESIGN_FA = Check("design.A7_2.Fa", "indexing mechanism through `camdyn design`: Fa",
                  "App. 7.2 (11)", "3.34", lambda: _design_result()["machine"]["Fa"], exact=True)


@lru_cache(maxsize=None)
def _sweep_result(quick: bool = True):
    """`camdyn sweep camshaft1 --grid Fa=0,0.3,1,3 --grid tau=0.06:0.7:N:inv` (the fig. 4.11
    grid, fewer Fa), with every figure's error estimate (the answer contract), kept for the
    claim."""
    from camdyn.runtime.studies import sweep as sw

    n = 160 if quick else 400
    grid = {"Fa": np.array([0.0, 0.3, 1.0, 3.0]), "tau": sw.parse_axis(f"tau=0.06:0.7:{n}:inv")[1]}
    return sw.sweep("camshaft1", grid, progress=False)


def _sweep(out_dir, quick):
    res = _sweep_result(quick)
    paths = res.charts(Path(out_dir) / "sweep")
    keep = []
    for p in paths:                       # the index shows U0 and the least deceleration
        if p.stem in ("U0", "Xdd_min_rise"):
            keep.append(copy(p, Path(out_dir) / f"sweep_{p.stem}.png"))
    return keep


def _fa0_against_3_5() -> tuple:
    """The sweep's U0 at Fa = 0 (CAMSHAFT-1 at Fa = 0 is the one-DOF model), its error
    estimates and (3.5), away from the tuning dips where (3.5) vanishes."""
    from camdyn.runtime.measure import references as closed_forms

    res = _sweep_result()
    at0 = res["Fa"] == 0.0
    tau, u0, err = res["tau"][at0], res["U0"][at0], res["U0_error"][at0]
    ref = closed_forms.U0(tau)
    keep = ref > 0.05 * np.max(ref)
    return u0[keep], err[keep], ref[keep]


def _sweep_vs_3_5() -> float:
    """Largest relative difference of the sweep's U0 at Fa = 0 from (3.5)."""
    u0, _, ref = _fa0_against_3_5()
    return float(np.max(np.abs(u0 / ref - 1.0)))


def _sweep_vs_3_5_error() -> float:
    """The error of :func:`_sweep_vs_3_5` from the sweep's own estimates: no point's relative
    difference moves by more than its U0's estimate over (3.5), so neither does the largest."""
    _, err, ref = _fa0_against_3_5()
    return float(np.max(err / ref))


SWEEP_3_5 = Check("sweep.camshaft1.U0_Fa0", "compiled sweep of CAMSHAFT-1 at Fa = 0: largest "
                  "relative difference of U0 from (3.5) over tau 0.06-0.7 (away from the dips)",
                  "(3.5), fig. 4.11a curve Fa = 0", "0", _sweep_vs_3_5, rule="abs:1e-6",
                  estimate=_sweep_vs_3_5_error)


def figures() -> list[Figure]:
    return [
        Figure("envelopes", "design", "CAMSHAFT-1 response graphs with the envelopes through "
               "the maxima, as a designer reads them (secs 3.5, 8.2.6; `camdyn run`)", _envelopes,
               note="the graphs.png of `camdyn run`; data in camshaft1_study/envelopes.csv"),
        Figure("laws", "design", "Cam-law selection at tau = 0.15, Fa = 0.5: envelopes, impact "
               "sensitivity and peaks of every law (sec. 9.2.2; `camdyn laws --tau 0.15 --fa 0.5`)",
               _laws),
        Figure("profile", "design", "Disk cam for a translating roller follower: cycloidal rise "
               "15 mm, base circle 26 mm, roller 5 mm (README, The cam itself; `camdyn profile`)",
               _profile),
        Figure("sweep", "design", "Compiled sweep of CAMSHAFT-1 over tau (uniform in 1/tau) and "
               "Fa: U0 and the least acceleration in the rise, fig. 4.11a/b's grid ("
               "`camdyn sweep camshaft1 --grid Fa=0,0.3,1,3 --grid tau=0.06:0.7:400:inv`)",
               _sweep, claims=(Claim(SWEEP_3_5),)),
        Figure("design", "design", "`camdyn design` on App. 7.2's indexing mechanism with "
               "u0 <= 0.5 mm: the envelope at the design's Fa, at the largest Fa that meets it "
               "and at Fa = 0, and the smallest t_m (secs 8.3, 8.5, App. 7)", _design,
               claims=(Claim(DESIGN_TAU), Claim(DESIGN_FA))),
        Figure("least model", "design", "Least model of sec. 8.2's chain within 5 % on U0, U0'' "
               "and the least deceleration, on the scenes of fig. 8.1a and 8.1b (sec. 8.2; "
               "`camdyn simulate fig8_1a --model auto`)", _least_model,
               claims=(Claim(LEAST_8_3A), Claim(LEAST_8_3B)),
               note="green: chosen; grey: accepted; red: rejected. Variants that are not "
                    "pre-generated are not probed (--build-variants builds them)"),
    ]
