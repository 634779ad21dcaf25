"""camdyn simulate: a DYNACAM scene (thesis ch. 6, 7), summary and diagrams."""
from __future__ import annotations

import json

from ..core.errors import CamdynInputError, SimulationError
from ..core.outdir import out_folder
from .common import (add_estimate_option, add_out_option, add_tolerance_options, fail, fmt,
                     method_names, report_health, run_failed, tolerance_argument, tolerances)
from .common import say_on_stderr

HELP = "a DYNACAM scene (thesis ch. 6, 7): summary and diagrams"
"""The command's line in `camdyn --help`."""


def add(sub):
    _, adaptive = method_names()
    sm = sub.add_parser("simulate", help=HELP)
    sm.add_argument("scene", help="scene TOML, or a built-in DYNACAM scene: indexing, "
                                   "indexing_squeeze, spring_loaded, fig8_1a, fig8_1b")
    sm.add_argument("--json", action="store_true", help="one JSON object on stdout")
    add_estimate_option(sm)
    add_out_option(sm, default=None, help="folder for the diagrams (PNG)")
    sm.add_argument("--method", default=None, choices=adaptive,
                    help="integration method instead of the scene's (dp54 unless it sets "
                         "run.method); rodas4 is the stiff solver")
    add_tolerance_options(sm)
    sm.add_argument("--model", default="scene", choices=("scene", "auto"),
                    help="auto: the least model of the chain of sec. 8.2 (ideal drive, no "
                         "backlash, spring, shaft directions, CAMSHAFT-2, -1, one DOF) that keeps "
                         "--figures within --tolerance of the full model, with error bounds")
    sm.add_argument("--tolerance", type=float, default=None,
                    help="with --model auto: relative tolerance on every figure (default 0.05)")
    sm.add_argument("--figures", default=None, metavar="F1,F2",
                    help="with --model auto: figures to keep (default U0,U0dd,Xdd_min_rise; also "
                         "T_at_Xdd_min, Xdd_max_rise, speed_variation_max)")
    sm.add_argument("--build-variants", action="store_true",
                    help="with --model auto: build DYNACAM variants of the chain that are not "
                         "compiled yet (seconds each, once)")
    return sm


def run(args) -> int:
    from ..measure.contract import answer, missing_estimate, plus_minus
    from ..targets.dynacam_scene import DynacamTarget
    from ..targets import scene_files

    prog = "camdyn simulate"
    progress = say_on_stderr(args.json)
    try:
        target = DynacamTarget.from_scene(scene_files.load(args.scene), args.scene)
        if args.method is not None:
            target = target.with_settings(method=args.method)
        tol = tolerances(args)
        if tol:
            target = target.with_settings(**tol)
        if args.model == "auto":
            if args.out:
                raise CamdynInputError("--out does not go with --model auto (no diagrams of the "
                                       "least model yet)")
            if args.no_error_estimate:
                raise CamdynInputError("--no-error-estimate does not go with --model auto (the "
                                       "error bounds are part of the choice)")
            return _least_model(target.scene, args, progress)
        if args.tolerance is not None or args.figures is not None or args.build_variants:
            raise CamdynInputError("--tolerance, --figures and --build-variants go with --model auto")
        if args.out:       # made and its files claimed before the run: a bad --out costs none
            out_folder(args.out, files=target.main_files())
        a = answer(target, estimate=not args.no_error_estimate, progress=progress)
        out = a.as_dict()
        out["outputs"], errors = a.at_end()
        if a.estimated:
            out["outputs_error"] = errors
        if args.out:
            out["figures"] = target.main_job(args.out, a)
    except CamdynInputError as exc:
        return fail(prog, tolerance_argument(str(exc)))
    except SimulationError as exc:
        return run_failed(prog, exc)
    report_health(prog, out)
    if args.json:
        print(json.dumps(out, indent=1))
        return 0
    print("\n".join(target.table(out)))
    none = missing_estimate(out)
    print(f"  outputs at the end of the run (T = {target.scene.T_end:g}):")
    for name, value in out["outputs"].items():
        e = out.get("outputs_error", {}).get(name)
        print(f"    {name:24s} {value:.6g}{plus_minus(e) if e is not None else none}")
    return 0


def _least_model(sc, args, progress) -> int:
    """camdyn simulate SCENE --model auto: the least model of the chain of sec. 8.2 that keeps
    the requested figures within the tolerance (runtime/studies/least_model.py)."""
    from ..studies import least_model

    figures = least_model.DEFAULT_FIGURES if args.figures is None else tuple(
        f.strip() for f in args.figures.split(",") if f.strip())
    tol = least_model.TOLERANCE if args.tolerance is None else args.tolerance
    out = least_model.choose(sc, figures, tol, build=args.build_variants, progress=progress)
    if out["summary"] is not None:
        report_health("camdyn simulate", out["summary"])
    if args.json:
        print(json.dumps(out, indent=1, default=float))
        return 0
    print(f"{sc.title}: least model within {100 * tol:g} % on {', '.join(figures)}")
    print(f"  {'candidate':12s} {'states':>6s}  predicted error (probes)")
    for c in out["candidates"]:
        if c["note"] and not c["predicted"]:
            text = f"not probed: {c['note']}"
        else:
            text = ", ".join(f"{f} {100 * c['predicted'][f]:.3g} %" for f in figures
                             if f in c["predicted"])
            text += "  accepted" if c["accepted"] else (f"  ({c['note']})" if c["note"] else "")
        mark = "*" if c["key"] == out["chosen"] else " "
        print(f"{mark} {c['key']:12s} {c['states'] or '':>6}  {text}")
    print(f"chosen: {out['chosen']}, {out['chosen_label']}")
    print(f"why: {out['why']}")
    for f in figures:
        print(f"  {f:22s} {fmt(out['result'][f])} ± {out['bound'][f]:.2g} (against the full model)")
    t = out["time"]
    full = "measured" if t["full_measured"] else "estimated from the probes"
    saved = (f"saved {t['saved_cpu_seconds'] * 1e3:.3g} ms" if t["saved_cpu_seconds"] > 0
             else "no time saved")
    print(f"time: {t['chosen_cpu_seconds'] * 1e3:.3g} ms CPU against {t['full_cpu_seconds'] * 1e3:.3g} ms "
          f"for the full model ({full}), {saved}; the probes took "
          f"{t['probes_cpu_seconds'] * 1e3:.3g} ms")
    return 0
