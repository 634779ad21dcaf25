"""camdyn precision: work-precision chart of one problem, SciPy's integrators beside camdyn's."""
from __future__ import annotations

import json
import sys
from pathlib import Path

from ..core.errors import CamdynInputError, SimulationError
from ..core.outdir import out_folder
from .common import add_out_option, assignments, fail, method_names, run_failed

HELP = ("work-precision chart: error against CPU time of every method over a ladder of "
        "tolerances, SciPy's beside")
"""The command's line in `camdyn --help`."""


def add(sub):
    all_methods, _ = method_names()
    pr = sub.add_parser("precision", help=HELP)
    pr.add_argument("target", metavar="SCENE_OR_MODEL",
                    help="a scene (.toml or built-in), a model file (.py) or a built-in model")
    pr.add_argument("--set", action="append", metavar="NAME=VALUE", help="a parameter (repeatable)")
    pr.add_argument("--t-end", type=float, default=None, metavar="T",
                    help="end of the run, models only (default 3 for a model with a rise)")
    pr.add_argument("--methods", nargs="+", choices=all_methods, default=None,
                    help="camdyn's methods (default: all)")
    pr.add_argument("--peers", nargs="+", default=None, metavar="PEER",
                    help="SciPy peers: RK45 DOP853 Radau BDF LSODA odeint (default: all)")
    pr.add_argument("--no-peers", action="store_true", help="camdyn's methods only")
    add_out_option(pr, default="out", help="folder for the chart, CSV and JSON (default out/)")
    pr.add_argument("--json", action="store_true", help="one JSON object on stdout")
    pr.add_argument("--quick", action="store_true", help="every other rung of the ladders")
    return pr


def run(args) -> int:
    """Work-precision study (runtime/studies/precision.py): chart, CSV and JSON into --out."""
    from ..studies import precision

    prog = "camdyn precision"
    say = (lambda msg: print(msg, file=sys.stderr, flush=True))
    try:
        params = assignments(args.set, "--set")
        if args.no_peers and args.peers:
            raise CamdynInputError("arguments --peers and --no-peers: give one")
        pr = precision.problem(args.target, params, args.t_end, say)
        # the folder and the three files, checked before the runs
        csv, js, png = names = [f"{Path(args.target).stem}_precision.{ext}"
                                for ext in ("csv", "json", "png")]
        out = out_folder(args.out, files=names)
        st = precision.study(pr, args.methods, () if args.no_peers else args.peers,
                             quick=args.quick, progress=say)
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    except SimulationError as exc:
        return run_failed(prog, exc)
    files = [st.write_csv(out / csv), st.write_json(out / js), st.chart(out / png)]
    if args.json:
        print(json.dumps({**precision.finite(st.as_dict()), "files": files}, indent=1))
        return 0
    ref = st.reference
    print(f"{st.label}: reference dp54 rtol={ref['rtol']:g}, error bound {ref['error_estimate']:.2g}")
    print(f"{'method':8s} {'setting':>14s} {'error':>10s} {'CPU s':>10s} {'rhs':>9s}  status")
    for r in st.rows:
        setting = "" if r.setting is None else f"{r.setting_name}={r.setting:.3g}"
        err = "" if r.error is None else f"{r.error:.3g}"
        cpu = "" if r.cpu_seconds is None else f"{r.cpu_seconds:.3g}"
        rhs = "" if r.n_rhs is None else str(r.n_rhs)
        note = r.status if r.status == "ok" else f"{r.status}: {r.message.split(';')[0][:100]}"
        print(f"{r.method:8s} {setting:>14s} {err:>10s} {cpu:>10s} {rhs:>9s}  {note}")
    for f in files:
        print(f"wrote {f}")
    return 0
