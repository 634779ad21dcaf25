"""Checks of topic 'dynacam': the DYNACAM runs of the two measured mechanisms (thesis ch. 7).

Each runs a built-in scene (runtime/scenes/*.toml) through the generated code; the values
the thesis prints are read from simulated or measured diagrams, so the rules are relative
(the thesis calls errors up to 20 % satisfactory, sec. 7.4.7).
"""
from __future__ import annotations

import math

from camdyn.thesis.runcache import cached_runs

from .check import Check


@cached_runs
def scene_run(name: str, backlash: bool = True):
    """(scene, summary, result) of a built-in scene's run, with or without its backlash; the
    figures of chs 7, 8 draw from the same runs."""
    from camdyn.runtime.targets import dynacam, scene_files as scenes

    sc = scenes.load(name)
    if not backlash:
        sc = scenes.without_backlash(sc)
    summary, res = dynacam.run(sc)
    return sc, summary, res


def _Xdd(name: str, T: float, backlash: bool = True) -> float:
    from camdyn.runtime.targets import dynacam

    sc, _, res = scene_run(name, backlash)
    return dynacam.sample_at(sc, res, T)


def _gear_impact_T() -> float:
    from camdyn.runtime.targets import dynacam

    sc, _, res = scene_run("indexing")
    return next(T for T, value in dynacam.mode_changes(sc, res, "gear") if value == "back")


def _impact_estimate() -> float:
    from camdyn.thesis.theory import examples

    return examples.indexing_impact(Xdd_s0=_Xdd("indexing", 0.68, backlash=False)).Xdd


@cached_runs
def _ladder(case: str) -> dict:
    from camdyn.runtime.targets import dynacam

    sc, summary, _ = scene_run(f"fig8_1{case}")
    return dynacam.reduced_models(sc, summary)


def _factor(case: str, num: str, den: str) -> float:
    u = _ladder(case)
    return u[num] / u[den]


def checks() -> list:
    return [
        Check("sec7_4_4.gear_impact_T", "indexing: T of the gear-teeth impact after the torque reversal",
              "sec. 7.4.4, fig. 7.11b", "0.58", _gear_impact_T, rule="abs:0.03",
              note="scene indexing.toml, zero damping"),
        Check("fig7_16.Xdd_068", "indexing with backlash, zero damping and viscosity: X'' at T = 0.68",
              "fig. 7.16, sec. 7.4.4", "-16", lambda: _Xdd("indexing", 0.68), rule="rel:0.10"),
        Check("fig7_15.Xdd_068", "indexing without backlash: X'' at T = 0.68", "fig. 7.15, sec. 7.4.4",
              "-7.4", lambda: _Xdd("indexing", 0.68, backlash=False), rule="rel:0.05"),
        Check("sec7_4_4.estimate", "Van der Hoek's estimate (3.12), (3.16) from the simulated X''_(s=0)",
              "sec. 7.4.4", "-16.2", _impact_estimate, rule="rel:0.05",
              note="the thesis's chain from the printed -7.4 gives -16.2"),
        Check("sec7_4_2.decel_factor", "spring-loaded: largest deceleration during the rise over 2 pi",
              "sec. 7.4.2, fig. 7.12", "2.2", lambda: -scene_run("spring_loaded")[1]["Xdd_min_rise"] / (2 * math.pi),
              rule="rel:0.25", note="the thesis reads it at T = 0.8 from the measurement"),
        Check("fig7_12.speed_variation", "spring-loaded: largest fictitious angular velocity variation",
              "sec. 7.6, fig. 7.12", "0.40", lambda: scene_run("spring_loaded")[1]["speed_variation_max"],
              rule="rel:0.25"),
            Check("sec8_2_4.factor_a", "c_z' << c_x: U0dd of CAMSHAFT-2 over the 4-DOF model's",
              "sec. 8.2.4, fig. 8.3a", "2.45", lambda: _factor("a", "2dof", "4dof"), rule="rel:0.10",
              note="scene fig8_1a.toml; m_z' = 0.5 kg taken (0.2 kg gives 1.35)"),
        Check("sec8_2_4.factor_b", "c_z' >> c_x: U0dd of CAMSHAFT-2 over the 4-DOF model's",
              "sec. 8.2.4, fig. 8.3b", "1.08", lambda: _factor("b", "2dof", "4dof"), rule="abs:0.10",
              note="scene fig8_1b.toml"),
        Check("sec8_2_5.one_vs_two_a", "c_z' << c_x: U0dd of CAMSHAFT-1 over CAMSHAFT-2's",
              "sec. 8.2.5, fig. 8.3a", "1", lambda: _factor("a", "1dof", "2dof"),
              rule="abs:0.10", note="'hardly any differences'"),
        Check("sec8_2_5.one_vs_two_b", "c_z' >> c_x: U0dd of CAMSHAFT-1 over CAMSHAFT-2's",
              "sec. 8.2.5, fig. 8.3b", "1", lambda: _factor("b", "1dof", "2dof"),
              rule="abs:0.10", note="'hardly any differences'"),
    ]
