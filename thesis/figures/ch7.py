"""Chapter 7, the DYNACAM simulations of the two measured mechanisms: figs 7.12-7.16.

The runs are those of the checks (thesis/checks/dynacam_checks.py, cached there), so a figure and the
statement beside it come from one simulation; the diagrams are drawn by
:func:`camdyn.runtime.targets.dynacam.plot`, as `camdyn simulate SCENE --out` draws them."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from .figure import Claim, Figure
from .plotting import dwell_shade, dynacam_diagrams, plt, save


def _diagrams(scene: str, backlash: bool, slug: str, keys):
    """Builder: DYNACAM's diagrams ``keys`` (of dynacam.DIAGRAMS) of a built-in scene into
    out_dir/slug/ (the diagrams not asked for are removed)."""
    def build(out_dir, quick):
        from ..checks.dynacam_checks import scene_run   # the checks' cached run: one simulation for both

        return dynacam_diagrams(*scene_run(scene, backlash), Path(out_dir) / slug, keys)
    return build


def _fig7_14(out_dir, quick):
    """CAMSHAFT-1 with the numbers of fig. 7.14 (tau = 0.08, Fa = 3.34)."""
    from camdyn.runtime.core.simulator import simulate

    T = np.linspace(0.0, 1.5, 1501 if quick else 3001)
    s = simulate("camshaft1", {"tau": 0.08, "Fa": 3.34}, 1.5, "dp54", rtol=1e-10).sample(T)
    p = plt()
    fig, ax = p.subplots(figsize=(7.5, 3.8))
    ax.plot(T, s["Xdd"], lw=0.8, label="X'', one DOF (fig. 7.14)")
    ax.plot(T, s["Hdd"], "k--", lw=0.7, label="nominal H''")
    x68 = float(np.interp(0.68, T, s["Xdd"]))
    ax.plot([0.68], [x68], "rv", label=f"X''(0.68) = {x68:.2f}")
    ax.set_xlabel("T = t/t_m")
    ax.set_ylabel("X''")
    ax.set_title("indexing mechanism reduced to one DOF: m = 45 kg, tau = 0.08, Fa = 3.34",
                 fontsize=9)
    dwell_shade(ax)
    ax.legend(fontsize=7)
    return [save(fig, out_dir, "fig7_14")]


def figures() -> list[Figure]:
    return [
        Figure("7.12", "thesis", "Spring-loaded cam follower mechanism without backlash (DYNACAM, "
               "4 DOF and motor): output and cam acceleration, torque, speed variations",
               _diagrams("spring_loaded", True, "fig7_12",
                         ("Xdd", "Bdd", "torque", "speed_var", "motor_speed_var")),
               claims=(Claim("sec7_4_2.decel_factor"), Claim("fig7_12.speed_variation")),
               note="scene runtime/scenes/spring_loaded.toml; the printed diagrams also show "
                    "the shaft speed at the gear side and the tangential deflection velocity, "
                    "which the diagrams here leave out."),
        Figure("7.13", "thesis", "Backlash in dimensionless form: roller in its groove and gear "
               "teeth (here: the gaps as the indexing run traverses them)",
               _diagrams("indexing", True, "fig7_13", ("gaps",)),
               claims=(Claim("app7.sec7_4_4.S"), Claim("sec7_4_4.gear_impact_T")),
               note="The thesis's figure is a sketch of the symbols; what the models determine "
                    "is where the backlash is traversed, drawn from the run of fig. 7.16."),
        Figure("7.14", "thesis", "One-DOF model of the indexing mechanism (m = 45 kg, tau = 0.08, "
               "Fa = 3.34) and its acceleration response", _fig7_14,
               claims=(Claim("app7.indexing.m"), Claim("app7.indexing.tau"),
                       Claim("app7.indexing.Fa"), Claim("app7.sec7_4_4.Xdd_s0.camshaft1")),
               note="The thesis draws the model; its numbers are reproduced, and the response "
                    "of CAMSHAFT-1 with them is drawn."),
        Figure("7.15", "thesis", "Indexing mechanism without backlash (DYNACAM): output and cam "
               "acceleration and camshaft torque",
               _diagrams("indexing", False, "fig7_15", ("Xdd", "Bdd", "torque")),
               claims=(Claim("fig7_15.Xdd_068"),),
               note="scene indexing.toml with the backlash removed (scene.without_backlash)."),
        Figure("7.16", "thesis", "Indexing mechanism with backlash, no damping and no viscosity "
               "(DYNACAM): output and cam acceleration and camshaft torque",
               _diagrams("indexing", True, "fig7_16", ("Xdd", "Bdd", "torque")),
               claims=(Claim("fig7_16.Xdd_068"), Claim("sec7_4_4.estimate")),
               note="scene runtime/scenes/indexing.toml."),
    ]
