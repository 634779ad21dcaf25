"""Design charts of issue 14 (items 2-6): the envelopes of the response graphs, the cam-law
selection chart, the cam profile; and the places for the charts still to come.

To add a chart: one Figure below with a builder ``(out_dir, quick) -> [png paths]`` that calls
the command's own function (as the three here do), or, until it exists, ``build=None`` with
``not_reproduced`` saying what is missing."""
from __future__ import annotations

import shutil
from pathlib import Path

from ..checks import Check
from . import Claim, Figure


def _envelopes(out_dir, quick):
    from .ch4 import study

    data = study(str(out_dir), quick)
    path = Path(out_dir) / "envelopes.png"
    shutil.copyfile(Path(data["folder"]) / "graphs.png", path)
    return [str(path)]


def _laws(out_dir, quick):
    from .. import selection

    rows = selection.table(0.15, 0.5)
    return [selection.chart(rows, Path(out_dir) / "laws_selection.png")]


def _profile(out_dir, quick):
    from camdyn.runtime.cam_profile import CamProfile

    cam = CamProfile(stroke=0.015, base_radius=0.026, roller_radius=0.005)
    return [str(cam.write_png(Path(out_dir) / "cam_profile.png"))]


def _least_model_choice(scene_name: str) -> dict:
    """`camdyn simulate SCENE --model auto` on a built-in scene (pre-generated variants only,
    so the answer does not depend on what an earlier run left in the build cache)."""
    from camdyn.runtime import least_model, scene

    return least_model.choose(scene.load(scene_name), build=False)


_CHOICES: dict = {}


def _choice(name: str) -> dict:
    if name not in _CHOICES:
        _CHOICES[name] = _least_model_choice(name)
    return _CHOICES[name]


def _least_model(out_dir, quick):
    """Predicted error of every reduction of sec. 8.2's chain on fig8_1a (c_z' << c_x) and
    fig8_1b (c_z' >> c_x), the largest over the requested figures, against the tolerance."""
    from ._plot import plt, save

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
    from .. import design as ds

    if "result" not in _DESIGN or out_dir is not None:
        chart = None if out_dir is None else Path(out_dir) / "design.png"
        _DESIGN["result"] = ds.design(**_INDEXING, check=False, chart_path=chart)
    return _DESIGN["result"]


def _design(out_dir, quick):
    return [_design_result(out_dir)["chart"]]


DESIGN_TAU = Check("design.A7_2.tau", "indexing mechanism through `camdyn design`: tau = T_e/t_m",
                   "App. 7.2 (9)", "0.08", lambda: _design_result()["machine"]["tau"])
DESIGN_FA = Check("design.A7_2.Fa", "indexing mechanism through `camdyn design`: Fa",
                  "App. 7.2 (11)", "3.34", lambda: _design_result()["machine"]["Fa"])


def figures() -> list[Figure]:
    later = "to be added with its command (issue 14, item {}); the lead fills this entry"
    return [
        Figure("envelopes", "design", "CAMSHAFT-1 response graphs with the envelopes through "
               "the maxima, as a designer reads them (item 2; `camdyn run`)", _envelopes,
               note="the graphs.png of `camdyn run`; data in camshaft1_study/envelopes.csv"),
        Figure("laws", "design", "Cam-law selection at tau = 0.15, Fa = 0.5: envelopes, impact "
               "sensitivity and peaks of every law (item 4; `camdyn laws --tau 0.15 --fa 0.5`)",
               _laws),
        Figure("profile", "design", "Disk cam for a translating roller follower: cycloidal rise "
               "15 mm, base circle 26 mm, roller 5 mm (item 6; `camdyn profile`)", _profile),
        Figure("sweep", "design", "Parameter sweep chart (item 1)", None,
               not_reproduced=later.format(1)),
        Figure("design", "design", "`camdyn design` on App. 7.2's indexing mechanism with "
               "u0 <= 0.5 mm: the envelope at the design's Fa, at the largest Fa that meets it "
               "and at Fa = 0, and the smallest t_m (item 3)", _design,
               claims=(Claim(DESIGN_TAU), Claim(DESIGN_FA))),
        Figure("least model", "design", "Least model of sec. 8.2's chain within 5 % on U0, U0'' "
               "and the least deceleration, on the scenes of fig. 8.1a and 8.1b (item 5; "
               "`camdyn simulate fig8_1a --model auto`)", _least_model,
               claims=(Claim(LEAST_8_3A), Claim(LEAST_8_3B)),
               note="green: chosen; grey: accepted; red: rejected. Variants that are not "
                    "pre-generated are not probed (--build-variants builds them)"),
    ]
