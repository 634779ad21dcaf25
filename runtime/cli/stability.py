"""camdyn stability: stability maps, each method over a grid of step (or rtol) x a stiffness parameter."""
from __future__ import annotations

import json
import sys

from ..core.errors import CamdynInputError, SimulationError
from ..core.outdir import out_folder
from .common import (LAW_HELP, add_out_option, assignments, fail, law_argument, method_names,
                     run_failed)

HELP = "stability map: each method over a grid of step (or rtol) x a stiffness parameter"
"""The command's line in `camdyn --help`."""


def add(sub):
    all_methods, _ = method_names()
    st = sub.add_parser("stability", help=HELP)
    st.add_argument("model", metavar="MODEL", help="a built-in model (one_dof, camshaft1, roller, "
                    "motor1, ...), a model file, or beam-follower (--param E=... or N=...)")
    st.add_argument("--param", metavar="NAME=START:STOP:N[:log]",
                    help="the stiffness parameter's grid, or NAME=a,b,c (default for one_dof and "
                         "camshaft1: tau = 2/(2k + 1), k = 13, 9, 6, 4, 2, maxima of U0 (3.5); "
                         "kappa=100:10000:3:log for roller)")
    st.add_argument("--set", action="append", metavar="NAME=VALUE",
                    help="another parameter's value (repeatable)")
    st.add_argument("--methods", nargs="+", metavar="METHOD",
                    help=f"methods to map (default: {', '.join(all_methods)}; koster only for "
                         "second-order models)")
    st.add_argument("--steps", metavar="START:STOP:N[:log] | a,b,c",
                    help="fixed steps (default: 10 on a log grid around the theory's boundary)")
    st.add_argument("--rtols", metavar="START:STOP:N[:log] | a,b,c",
                    help="tolerances of dp54/dop853/rodas4 (default 1e-3 .. 1e-10, 8)")
    st.add_argument("--threshold", type=float, default=1e-3,
                    help="relative error of the headline figure above which a run is "
                         "inaccurate (default 1e-3)")
    st.add_argument("--t-end", type=float, default=None,
                    help="end of each run (default: for a model with a rise, 3 or one period of "
                         "the slowest mode its U0 sees past the rise if longer; else 3)")
    st.add_argument("--law", default="cycloidal", type=law_argument, metavar="LAW",
                    help=f"cam law: {LAW_HELP} (default cycloidal)")
    st.add_argument("--run-refused", action="store_true",
                    help="run refused steps anyway and show what they do (stability check off)")
    add_out_option(st, default="out", help="folder for PNG, CSV, JSON (default out/)")
    st.add_argument("--json", action="store_true", help="the summary as JSON on stdout")
    st.add_argument("--quiet", action="store_true", help="no progress lines")
    return st


def _grid(text: str, flag: str, positive: bool = True) -> list:
    """'A:B:N' (N values from A to B; ':log' for geometric spacing) or 'a,b,c', each value
    once (a map has one column per value)."""
    import numpy as np

    from ..studies.sweep import repeated

    parts = text.split(":")
    if len(parts) == 1 and any(not v.strip() for v in text.split(",")):
        raise CamdynInputError(f"argument {flag}: {text!r} has an empty item; give a,b,c, a "
                               "number between every two commas")
    try:
        if len(parts) == 1:
            vals = [float(v) for v in text.split(",")]
        elif len(parts) in (3, 4) and (len(parts) == 3 or parts[3] in ("log", "lin")):
            a, b, n = float(parts[0]), float(parts[1]), int(parts[2])
            if not 1 <= n <= 200:
                raise CamdynInputError(f"argument {flag}: N={n} is out of range: 1 <= N <= 200")
            log = len(parts) == 4 and parts[3] == "log"
            if log and not (a > 0 and b > 0):
                raise CamdynInputError(f"argument {flag}: a log grid needs START, STOP > 0")
            vals = list(np.geomspace(a, b, n) if log else np.linspace(a, b, n))
        else:
            raise ValueError
    except ValueError:
        raise CamdynInputError(f"argument {flag}: {text!r} is not START:STOP:N[:log] or a "
                               f"comma-separated list of numbers") from None
    if not vals or not all(np.isfinite(vals)) or (positive and min(vals) <= 0):
        raise CamdynInputError(f"argument {flag}: {text!r} must give finite"
                               f"{' positive' if positive else ''} numbers")
    twice = repeated(vals)
    if twice is not None:
        raise CamdynInputError(f"argument {flag}: {text!r} gives {twice:g} more than once; "
                               "give each value once")
    return [float(v) for v in vals]


def study_of(args, say) -> tuple:
    """The map `camdyn stability` asks for: the grids parsed here, the map made by
    runtime/studies/stability_map.py (a model) or stability_beam.py (the beam follower)."""
    from ..studies import stability_beam, stability_map

    param = None
    if args.param:
        name, sep, rng = args.param.partition("=")
        if not sep or not name:
            raise CamdynInputError(f"argument --param: {args.param!r} is not "
                                   "NAME=START:STOP:N[:log]")
        param = (name, _grid(rng, "--param",
                             positive=args.model.replace("_", "-") in stability_beam.NAMES))
    fixed = assignments(args.set, "--set")
    rtols = _grid(args.rtols, "--rtols") if args.rtols else None
    steps = _grid(args.steps, "--steps") if args.steps else None
    if args.model.replace("_", "-") in stability_beam.NAMES:
        return stability_beam.study(param, args.methods, fixed, rtols, steps,
                                    threshold=args.threshold, progress=say), "beam_follower"
    m = stability_map.study(args.model, param, args.methods, fixed, rtols, steps,
                            threshold=args.threshold, t_end=args.t_end, law=args.law,
                            check_stability=not args.run_refused, progress=say)
    return m, m.model


def stem_of(label: str, param: str) -> str:
    """The name the map's PNG, CSV and JSON share in --out."""
    return f"stability_{label}_{param}"


def output_files(args) -> list:
    """The files the map of ``args`` writes into --out, named before it runs (the model
    loaded, not run): its label (the model's name, or beam_follower) and its parameter (the
    one --param names, else the model's default).  A model without a default parameter
    writes nothing: study_of refuses it."""
    from ..studies import stability_beam, stability_map

    if args.model.replace("_", "-") in stability_beam.NAMES:
        label, default = "beam_follower", "N"
    else:
        model = stability_map.target_of(args.model, args.t_end, args.law).model
        label, default = model.name, (stability_map.DEFAULT_PARAMS.get(model.name) or (None,))[0]
    name, sep, _ = (args.param or "").partition("=")
    param = (name if sep else None) if args.param else default
    if not param:                   # no parameter, or a --param study_of refuses
        return []
    return [f"{stem_of(label, param)}.{ext}" for ext in ("png", "csv", "json")]


def run(args) -> int:
    prog = "camdyn stability"
    say = (lambda msg: None) if args.quiet else (lambda msg: print(f"{prog}: {msg}", file=sys.stderr, flush=True))
    from ..studies import stability_map as smap

    try:
        if not 0 < args.threshold < 1:
            raise CamdynInputError(f"argument --threshold: {args.threshold:g} is out of range: "
                                   f"0 < threshold < 1")
        if args.t_end is not None and not args.t_end > 0:
            raise CamdynInputError(f"argument --t-end: {args.t_end:g} must be positive")
        # the folder and every file the map writes, checked before its runs
        out = out_folder(args.out, create=False, files=output_files(args))
        m, label = study_of(args, say)
        out_folder(out)
        stem = out / stem_of(label, m.param)
        files = [m.plot(f"{stem}.png"), m.write_csv(f"{stem}.csv"), m.write_json(f"{stem}.json")]
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    except SimulationError as exc:   # the reference run itself failed
        return run_failed(prog, f"the reference run (dp54, rtol {smap.REF_RTOL:g}) failed: {exc}")
    summary = {"model": m.model, "param": m.param, "values": m.values, "counts": m.counts(),
               "largest_fine": {k: smap.largest_fine(m, k) for k in m.settings},
               "step_limit": m.step_limit, "reference_run": m.reference_run,
               "reference": m.reference, "reference_error": m.reference_error,
               "warnings": m.warnings, "files": files}
    for w in m.warnings:
        print(f"{prog}: warning: {w}", file=sys.stderr)
    if args.json:
        print(json.dumps(summary, indent=1))
        return 0
    print(f"{m.model}: stability map over {m.param} = {', '.join(f'{v:.4g}' for v in m.values)} "
          f"({m.figure} within {m.threshold:g} of {m.reference_run} counts as fine; that "
          f"reference good to {max(m.reference_error):.2g}, relative)")
    for k, c in summary["counts"].items():
        fine = ", ".join("-" if f is None else f"{f:.3g}" for f in summary["largest_fine"][k])
        line = f"  {k:7s} " + " ".join(f"{n} {c[n]}" for n in smap.CLASSES)
        line += f"; largest fine {'step' if k in m.step_limit else 'rtol'}: {fine}"
        if k in m.step_limit:
            line += "; theory's step limit: " + ", ".join(f"{v:.3g}" for v in m.step_limit[k])
        print(line)
    for f in files:
        print(f"wrote {f}")
    return 0
