"""The chosen design into --out: its machine file (the sized preload written in, the law
chosen), its cam as `camdyn profile` writes it (CSV in SI, DXF in mm; a STEP plate with
--step) and the answer as JSON.  Every file through runtime/core/outdir.py, whose names the
command claims before any run (:func:`files`)."""
from __future__ import annotations

import json
from dataclasses import replace

from camdyn.runtime.core.outdir import write_text

from . import spec

BASE = ("machine.toml", "cam.csv", "cam.dxf", "design.json")

POINTS_PER_DEGREE = 10
"""The written profile's samples per degree, `camdyn profile`'s default."""


def files(step: bool = False) -> tuple:
    """The names :func:`write` writes (cam.step with ``step``)."""
    return BASE + (("cam.step",) if step else ())


def chosen_machine(a) -> spec.Machine:
    """The machine as designed: the chosen law alone, its spring's preload as used (the
    least that holds where it was sized)."""
    best = a.chosen
    m = replace(a.machine, laws=(best.law,))
    if best.spring is not None and a.machine.spring_preload is None:
        m = spec.with_preload(m, best.spring.preload_used)
    return m


def write(a, folder, d: dict, step: bool = False) -> dict:
    """Write the chosen design into ``folder`` (:func:`files`); ``d`` is the answer's JSON.
    Returns {what: path}.  A cam whose profile bounds no solid (a cusp, an undercut) has no
    STEP plate: the reason joins the answer's warnings."""
    from . import contact

    best = a.chosen
    out = {"machine": str(write_text(folder / "machine.toml", spec.as_toml(chosen_machine(a))))}
    # the cam the checks judged, sampled as `camdyn profile` writes it by default
    cam = contact.profile(a.machine, best.law, best.theta, points_per_degree=POINTS_PER_DEGREE)
    out["csv"] = str(cam.write_csv(folder / "cam.csv"))
    out["dxf"] = str(cam.write_dxf(folder / "cam.dxf"))
    if step:
        why = _step(cam, a.machine.cam_width, folder / "cam.step")
        if why is None:
            out["step"] = str(folder / "cam.step")
        else:
            d["warnings"].append(f"cam.step not written: {why}")
    out["json"] = str(folder / "design.json")
    write_text(folder / "design.json", json.dumps({**d, "files": out}, indent=1))
    return out


def _step(cam, thickness: float, path) -> str | None:
    """The STEP plate, or why it is not written (`camdyn profile --step`'s rules)."""
    from camdyn.runtime.cam.step import StepError, profile_refusal, write_step

    why = profile_refusal(cam)
    if why is not None:
        return why
    try:
        write_step(cam, path, thickness, 0.0)
    except StepError as exc:
        return str(exc)
    return None
