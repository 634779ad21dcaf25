"""camdyn integrate: any model, a model file (built on first use) or a built-in one, to t_end."""
from __future__ import annotations

import json
import math

from ..core.errors import CamdynInputError, SimulationError
from .common import (LAW_HELP, add_dependent_option, add_estimate_option, add_out_option,
                     add_tolerance_options, assignments, fail, law_argument, law_names, method_names,
                     report_health, run_failed, say_on_stderr, tolerance_argument, tolerances)

HELP = "any model: a model file (built on first use) or a built-in model, to t_end"
"""The command's line in `camdyn --help`."""


def add(sub):
    all_methods, _ = method_names()
    ig = sub.add_parser("integrate", help=HELP)
    ig.add_argument("model", metavar="MODEL",
                    help="a Python file defining build() -> Model, or a built-in model name")
    ig.add_argument("--set", action="append", metavar="NAME=VALUE",
                    help="a parameter value, in the model's units (repeatable)")
    ig.add_argument("--initial", action="append", metavar="NAME=VALUE",
                    help="an initial state value (repeatable; default: the declared state)")
    ig.add_argument("--t-end", type=float, required=True, metavar="T",
                    help="end time, in the model's time unit")
    ig.add_argument("--method", default="dp54", choices=all_methods)
    ig.add_argument("--rtol", type=float, default=None,
                    help="dp54/dop853/rodas4 tolerance (default 1e-8)")
    ig.add_argument("--step", type=float, default=None, help="rk4/koster step")
    add_tolerance_options(ig)
    ig.add_argument("--max-steps", type=int, default=None, metavar="N",
                    help="the run's budget of steps, a whole number >= 1 (default 5,000,000); "
                         "the error estimate's run one notch tighter has the same budget")
    ig.add_argument("--exact-segments", default=None, choices=("on", "off"),
                    help="step over intervals where the model is linear and time invariant (a "
                         "dwell) with their exact propagator e^(A h), the record's points "
                         "spreading out as the vibration fades; default: on for rk4 and "
                         "dop853, off for the others (on pays for rodas4 and radau5 where a "
                         "stiff mode is damped, e.g. a contact with damping)")
    ig.add_argument("--law", default="cycloidal", type=law_argument, metavar="LAW",
                    help=f"cam law of the inputs: {LAW_HELP} (default cycloidal)")
    ig.add_argument("--theta", type=float, default=None, help="shape parameter of the law")
    ig.add_argument("--turn", default=None, metavar="RISE,UP,RETURN,LOW",
                    help="a full cam turn, repeated: rise by --law, upper dwell, return by "
                         "--return-law, lower dwell, in deg summing to 360 (the input's "
                         "argument counts rises: one turn is 360/RISE)")
    ig.add_argument("--return-law", default=None, choices=law_names(),
                    help="with --turn: the law of the return (default: --law)")
    ig.add_argument("--return-theta", type=float, default=None,
                    help="with --return-law: its shape parameter (default: the law's own)")
    add_dependent_option(ig)
    ig.add_argument("--json", action="store_true", help="one JSON object on stdout")
    add_estimate_option(ig)
    add_out_option(ig, default=None, help="folder for <model>.csv and <model>.png")
    return ig



def law_arg(args) -> tuple:
    """(law, theta) of a run: --law and --theta, or with --turn the dwell-rise-dwell-return
    turn of --law (rise) and --return-law (runtime.laws.compose)."""
    if getattr(args, "turn", None) is None:
        for flag in ("return_law", "return_theta"):
            if getattr(args, flag, None) is not None:
                raise CamdynInputError(f"argument --{flag.replace('_', '-')}: only with --turn")
        return args.law, args.theta
    from ..core.laws import compose

    try:
        angles = [float(a) for a in args.turn.split(",")]
    except ValueError:
        raise CamdynInputError(f"argument --turn: {args.turn!r} is not four comma-separated "
                               "angles in deg (rise,upper dwell,return,lower dwell)") from None
    return compose(args.law, args.return_law, angles, args.theta,
                   getattr(args, "return_theta", None)), None


INITIAL_LIMIT = 1e100
"""An initial value may be at most this many times its state's declared scale.  The error
control squares the scaled differences of the stages (a sum of squares, DP54's norm): from
about 1e140 on the one-DOF model at rtol 1e-8 that overflows at the first step, and the run
cannot take one ("the step budget was used up at T = 0").  1e100 leaves a margin of 1e30
for stiffer models and tighter tolerances, and is beyond any state a mechanism takes."""


def check_initial(model, initial: dict) -> None:
    """--initial's values: at most INITIAL_LIMIT times each state's scale, else a refusal
    naming the value and the range."""
    scales = dict(zip(model.state_names, model.state_scales()))
    units = {s["name"]: s.get("unit", "") for s in model.manifest["states"]}
    for name, value in initial.items():
        if name not in scales:         # an unknown name: the target names the states
            continue
        limit = INITIAL_LIMIT * scales[name]
        if not abs(value) <= limit:
            unit = f" {units[name]}" if units[name] and units[name] != "1" else ""
            raise CamdynInputError(
                f"argument --initial: {name}={value:g} is out of range: |{name}| <= {limit:g}"
                f"{unit} ({INITIAL_LIMIT:g} times the state's scale); beyond it the "
                "integrator's error control overflows at the first step")


def run(args) -> int:
    from ..measure.contract import answer, missing_estimate, plus_minus
    from ..targets import resolve
    from ..targets.model_target import StateTarget

    prog = "camdyn integrate"
    say = say_on_stderr()
    initial = {}
    try:
        params = assignments(args.set, "--set")
        initial = assignments(args.initial, "--initial")
        for name, value in initial.items():      # before the model is built with them
            if not math.isfinite(value):
                raise CamdynInputError(f"argument --initial: {name}={value:g} is not a finite "
                                       "number")
        if args.rtol is not None and args.step is not None:
            raise CamdynInputError("arguments --rtol and --step: give one (rtol for dp54 and "
                                   "rodas4, step for rk4 and koster)")
        law, theta = law_arg(args)
        t = resolve.model(args.model, StateTarget, say, params=params, method=args.method,
                          rtol=args.rtol, step=args.step, t_end=args.t_end, law=law,
                          theta=theta, initial=initial, max_steps=args.max_steps,
                          dependent=args.dependent, **tolerances(args),
                          exact=None if args.exact_segments is None
                          else args.exact_segments == "on")
        check_initial(t.model, initial)
        if args.out:
            from ..core.outdir import out_folder

            # the folder and the two files write_series makes, checked before the run
            out_folder(args.out, create=False,
                       files=[f"{t.model.name}.csv", f"{t.model.name}.png"])
        a = answer(t, estimate=not args.no_error_estimate)
        files = []
        if args.out:
            from ..targets.series import write_series

            files = write_series(a, args.out)
    except CamdynInputError as exc:
        message = str(exc)
        if message.startswith("max_steps"):
            message = f"argument --max-steps: {message}"
        return fail(prog, tolerance_argument(message))
    except SimulationError as exc:
        # a run from states the user gave says so: they are the first suspect
        given = ", ".join(f"{k}={v:g}" for k, v in initial.items())
        return run_failed(prog, f"{exc}; the run started from --initial {given}" if initial
                          else exc)
    summary = {**a.record, "cpu_seconds": a.stats["cpu_seconds"], "status": "ok",
               "warnings": list(a.warnings), "stiff_from_T": a.stats["stiff_from_T"]}
    outputs, output_errors = a.at_end()
    summary["outputs"] = outputs
    if a.estimated:
        summary["state_error"] = dict(a.errors)
        summary["outputs_error"] = output_errors
        summary["error_sources"] = a.sources
    else:       # every number beside its estimate, null where none was made (as residual's)
        summary["state_error"] = dict.fromkeys(summary["state"])
        summary["outputs_error"] = dict.fromkeys(outputs)
    if a.unavailable is not None:
        summary["estimate_unavailable"] = a.unavailable
    if files:
        summary["files"] = files
    report_health(prog, summary, t.model.manifest["time"]["name"])
    if args.json:
        print(json.dumps(summary, indent=1))
        return 0
    print(f"{summary['model']}: {summary['method']} to {summary['t_end']:g} "
          f"{summary['time_unit']}, {summary['n_steps']} steps, {summary['n_rhs']} rhs calls, "
          f"{summary['cpu_seconds']:.3g} s CPU")
    none = missing_estimate(summary)
    for what, errs in (("state", summary.get("state_error", {})),
                       ("outputs", summary.get("outputs_error", {}))):
        if what == "outputs" and summary["outputs"]:
            print(f"  outputs at {summary['t_end']:g} {summary['time_unit']}:")
        for name, value in summary[what].items():
            e = errs.get(name)
            print(f"  {name:12s} {value:.10g}{plus_minus(e) if e is not None else none}")
    for f in files:
        print(f"wrote {f}")
    return 0
