"""camdyn sweep: headline figures over a grid of parameters, as tables and charts."""
from __future__ import annotations

import sys

from ..core.errors import CamdynInputError, SimulationError
from ..core.outdir import out_folder
from .common import (LAW_HELP, add_dependent_option, add_estimate_option, add_out_option,
                     add_tolerance_options, fail, law_argument, method_names, run_failed,
                     tolerance_argument, tolerances)

HELP = ("headline figures over a grid of parameters: table (CSV, Parquet) and a chart per figure,"
        " on every core or a Dask cluster")
"""The command's line in `camdyn --help`."""


def add(sub):
    all_methods, _ = method_names()
    sw = sub.add_parser("sweep", help=HELP)
    sw.add_argument("target", metavar="SCENE_OR_MODEL",
                    help="a model (camshaft1, camshaft2, one_dof, ...), a model file (.py) or a "
                         "scene (built-in name or TOML: default, indexing, beam_paper, ...)")
    sw.add_argument("--grid", action="append", required=True, metavar="NAME=START:STOP:N",
                    help="a grid axis: NAME=START:STOP:N[:lin|log|inv] (inv: uniform in 1/NAME, "
                         "as fig. 4.11's tau) or NAME=a,b,c; repeat for more axes (the first "
                         "varies slowest)")
    sw.add_argument("--jobs", type=int, default=None,
                    help="threads, >= 1 (default: every core; not with --dask)")
    sw.add_argument("--dask", default=None, metavar="ADDRESS",
                    help="run on the Dask scheduler at ADDRESS (tcp://host:8786) instead")
    add_out_option(sw, default="out/sweep", help="folder for the table and charts "
                                                  "(default out/sweep)")
    sw.add_argument("--t-end", type=float, default=None,
                    help="end of each run of a model, in its time unit (T = t/t_m for the "
                         "thesis models), at least one period tau past the rise (default 3)")
    sw.add_argument("--method", choices=all_methods, default=None,
                    help="integration method (default: the scene's, dp54 for a model)")
    sw.add_argument("--rtol", type=float, default=None,
                    help="relative tolerance of dp54/dop853/rodas4, 1e-14 <= rtol < 1 (default: the "
                         "scene's, 1e-9 for a model)")
    sw.add_argument("--step", type=float, default=None,
                    help="step of a fixed-step method (rk4, koster; required there), in the "
                         "model's time unit; not with dp54/dop853/rodas4")
    add_tolerance_options(sw)
    add_dependent_option(sw)
    sw.add_argument("--law", type=law_argument, metavar="LAW", default=None,
                    help=f"cam law of a model: {LAW_HELP} (default: the scene's, cycloidal)")
    sw.add_argument("--error-estimate", action="store_true",
                    help="the default: every figure with its error estimate, a column "
                         "<figure>_error from the grid run again one notch tighter (rtol/10, "
                         "half the step), plus the scan's sampling error")
    add_estimate_option(sw)
    sw.add_argument("--resume", action="store_true",
                    help="continue the table a stopped sweep of the same target, grid and "
                         "settings left in --out: its rows are kept, the others run (the "
                         "table is written as the grid runs)")
    sw.add_argument("--quiet", action="store_true", help="no progress bar")
    return sw


def run(args) -> int:
    """The headline figures over a grid of parameters (runtime/studies/sweep.py): CSV (written
    as the grid runs; --resume continues it), Parquet with pyarrow, a chart per figure."""
    from ..studies import sweep as sw

    try:
        grid = sw.parse_grid(args.grid)
        out_folder(args.out, create=False)       # checked before the runs
        res = sw.sweep(args.target, grid, jobs=args.jobs, dask=args.dask,
                       progress=not args.quiet, t_end=args.t_end, method=args.method,
                       rtol=args.rtol, law=args.law, step=args.step,
                       estimate=not args.no_error_estimate, out=args.out, resume=args.resume,
                       dependent=args.dependent, **tolerances(args))
    except CamdynInputError as exc:
        return fail("camdyn sweep", tolerance_argument(str(exc)))
    except SimulationError as exc:
        return run_failed("camdyn sweep", exc)
    if args.error_estimate and args.no_error_estimate:
        return fail("camdyn sweep", "arguments --error-estimate and --no-error-estimate: give one")
    if res.warned:
        first = next(w for w in res.columns["warnings"] if w)
        print(f"camdyn sweep: warning: {res.warned} of {len(res)} points warned (the warnings "
              f"column of the table); the first: {first}", file=sys.stderr)
    print(res.summary())
    for path in res.files:
        print(f"  {path}")
    return 0
