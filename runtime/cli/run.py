"""camdyn run: any scene (the CAMSHAFT-1 study by default), as report and charts."""
from __future__ import annotations

from pathlib import Path

from ..core.errors import CamdynInputError, SimulationError
from ..core.outdir import out_folder
from .common import (add_estimate_option, add_out_option, add_tolerance_options, fail,
                     method_names, report_health, run_failed, say_on_stderr, tolerance_argument,
                     tolerances)

HELP = "any scene: the CAMSHAFT-1 study (default), a DYNACAM mechanism, the beam follower"
"""The command's line in `camdyn --help`."""


def add(sub):
    _, adaptive = method_names()
    m = sub.add_parser("run", help=HELP)
    m.add_argument("scene", nargs="?", default=None,
                   help="scene TOML or a built-in scene name (camdyn scenes); default: the "
                        "embedded CAMSHAFT-1 study")
    add_out_option(m, default="out", help="folder for report and charts (default out/)")
    m.add_argument("--method", default=None, choices=adaptive,
                   help="integration method instead of the scene's [run] method; rodas4 is the "
                        "stiff solver")
    add_tolerance_options(m)
    m.add_argument("--quiet", action="store_true", help="no progress lines")
    add_estimate_option(m)
    return m


def run(args) -> int:
    """Any scene, through its target's main job: the CAMSHAFT-1 study (report and charts), a
    DYNACAM mechanism (summary and diagrams) or the beam follower (tip response), each
    writing report.json into --out, every figure with its error estimate."""
    from ..targets.resolve import scene

    prog = "camdyn run"
    try:
        target = scene(args.scene or "default")
        if args.method is not None:
            target = target.with_settings(method=args.method)
        tol = tolerances(args)
        if tol:
            target = target.with_settings(**tol)
        out_dir = Path(out_folder(args.out, create=False))       # checked before the runs
        record = target.job(out_dir, estimate=not args.no_error_estimate,
                            progress=say_on_stderr(args.quiet))
    except CamdynInputError as exc:
        return fail(prog, tolerance_argument(str(exc)))
    except SimulationError as exc:
        return run_failed(prog, exc)
    report_health(prog, record, target.time_name)
    print("\n".join(record["lines"]))
    return 0
