"""camdyn residual: the residual vibration after one rise (thesis ch. 3-5)."""
from __future__ import annotations

import json

from ..core.errors import CamdynInputError, SimulationError
from .common import (LAW_HELP, add_estimate_option, add_tolerance_options, fail, law_argument,
                     method_names,
                     report_health, run_failed, tolerance_argument, tolerances)

HELP = "residual vibration after one rise (thesis ch. 3-5)"
"""The command's line in `camdyn --help`."""

MODELS = {"one-dof": "one_dof", "camshaft1": "camshaft1", "camshaft2": "camshaft2"}
"""The thesis's residual-vibration models by their command-line names (chs 3, 4, 5)."""

LIMITS = {"one-dof": "Fv -> 0, a cam of infinite inertia", "camshaft1": "Fv -> oo, a massless cam"}
"""What the flywheel factor is in the models without a cam inertia (thesis sec. 5.7)."""


RESIDUAL_RTOL = 1e-10
"""The tolerance of `camdyn residual` when none is given: one run, so a tight one."""


def add(sub):
    all_methods, _ = method_names()
    r = sub.add_parser("residual", help=HELP)
    r.add_argument("--model", required=True, choices=sorted(MODELS))
    r.add_argument("--tau", required=True, type=float, help="T_e/t_m (3.3), (4.12)")
    r.add_argument("--fa", type=float, default=None,
                   help="shaft stiffness factor Fa (4.14), (5.12b): camshaft1, camshaft2")
    r.add_argument("--fv", type=float, default=None,
                   help="flywheel factor Fv (5.14): camshaft2 only, required there")
    r.add_argument("--q", type=float, default=0.0,
                   help="relative damping q (6.47), one-dof only; default 0")
    r.add_argument("--law", default="cycloidal", type=law_argument, metavar="LAW",
                   help=f"cam law of the rise: {LAW_HELP} (default cycloidal)")
    r.add_argument("--theta", type=float, default=None,
                   help="the law's shape parameter (modified sine: peak position; "
                        "sine-constant-cosine: c; polydyne: the design tau)")
    r.add_argument("--design-tau", type=float, default=None, metavar="TD",
                   help="polydyne: the tau the cam is compensated for (its shape parameter): "
                        "at tau = TD the one-DOF output follows the degree-9 rise exactly")
    r.add_argument("--method", default="dp54", choices=all_methods)
    r.add_argument("--rtol", type=float, default=None,
                   help="dp54/dop853/rodas4 tolerance (default 1e-10)")
    r.add_argument("--step", type=float, default=None,
                   help="rk4/koster step in T (default: 1/100 of the shortest period of the "
                        "dwell's modes: tau/100 (sec. 4.4.2), for CAMSHAFT-2 also its flywheel "
                        "period (5.19))")
    add_tolerance_options(r)
    r.add_argument("--t-end", type=float, default=None,
                   help="end of the dwell, in T (default 3, longer where one period of the "
                        "slowest mode a figure sees needs it; a shorter one given is refused)")
    r.add_argument("--json", action="store_true", help="one JSON object on stdout")
    add_estimate_option(r)
    return r


def parameters(model: str, tau: float, fa, fv, q) -> dict:
    """The parameters of the thesis's model ``model`` from the command line, with what each
    model cannot take named (the limits of sec. 5.7)."""
    params = {"tau": tau}
    if fv is not None and model != "camshaft2":
        raise CamdynInputError(f"Fv applies to camshaft2 only: {model} is its limit "
                               f"{LIMITS[model]} (thesis sec. 5.7); use --model camshaft2 for a "
                               "cam with inertia")
    if model == "camshaft2":
        # Fa = 0 or Fv = 0 leave (5.16) without a shaft or without a cam mass: both limits
        # are other models (CAMSHAFT-1, one-dof), so neither has a default here
        if fv is None:
            raise CamdynInputError("argument --fv: required with --model camshaft2 "
                                   "(flywheel factor Fv > 0, thesis (5.14))")
        if fa is None:
            raise CamdynInputError("argument --fa: required with --model camshaft2 "
                                   "(shaft stiffness factor Fa > 0, thesis (5.12b))")
        if q:
            raise CamdynInputError("q applies to one-dof only: CAMSHAFT-2 (5.15), (5.16) has no "
                                   "damping")
        params.update(Fa=fa, Fv=fv)
    elif model == "camshaft1":
        if q:
            raise CamdynInputError("q applies to one-dof only: CAMSHAFT-1 (4.15) has no damping "
                                   "(thesis sec. 4.2.4)")
        params["Fa"] = 0.0 if fa is None else fa
    else:
        if fa not in (None, 0.0):
            raise CamdynInputError("Fa applies to camshaft1 and camshaft2 only: the one-dof model "
                                   "has constant fictitious angular velocity (Fa = 0); use "
                                   "--model camshaft1 for a flexible shaft")
        params["q"] = q
    return params


def target(args):
    """The run `camdyn residual` asks for, as a target."""
    from ..core.methods import METHODS
    from ..targets.model_target import ModelTarget

    if args.rtol is not None and args.step is not None:
        raise CamdynInputError("argument --step: not allowed with argument --rtol")
    if args.t_end is not None and not args.t_end > 1.0:
        raise CamdynInputError(f"--t-end={args.t_end:g} must exceed the end of the rise, T = 1")
    rtol = args.rtol
    if METHODS[args.method].adaptive and rtol is None and args.step is None:
        rtol = RESIDUAL_RTOL
    step = args.step
    params = parameters(args.model, args.tau, args.fa, args.fv, args.q)
    if getattr(args, "design_tau", None) is not None:
        if args.law != "polydyne":
            raise CamdynInputError(f"--design-tau goes with --law polydyne, not {args.law}")
        if args.theta is not None:
            raise CamdynInputError("--design-tau is the polydyne's --theta: give one of them")
        args.theta = args.design_tau
    if not METHODS[args.method].adaptive and step is None:
        step = ModelTarget.of(MODELS[args.model], params, law=args.law,
                              theta=args.theta).default_step()
    return ModelTarget.of(MODELS[args.model], params, method=args.method, rtol=rtol, step=step,
                          t_end=args.t_end, law=args.law, theta=args.theta, **tolerances(args))


def run(args) -> int:
    from ..measure.contract import answer, with_errors

    prog = "camdyn residual"
    try:
        t = target(args)
        a = answer(t, estimate=not args.no_error_estimate)
    except CamdynInputError as exc:
        return fail(prog, tolerance_argument(name_argument(str(exc))))
    except SimulationError as exc:
        return run_failed(prog, exc)
    out = {**a.as_dict(), "model": args.model, **t.references()}
    report_health(prog, out)
    if args.json:
        print(json.dumps(out))
    else:
        print("\n".join(with_errors(out)))
    return 0


FLAGS = {"tau": "--tau", "Fa": "--fa", "Fv": "--fv", "q": "--q", "theta": "--theta",
         "rtol": "--rtol", "step": "--step", "t_end": "--t-end"}


def name_argument(message: str) -> str:
    """Prefix the command-line spelling of the parameter a message is about."""
    head = message.split("=", 1)[0].split(" ", 1)[0]
    if head in FLAGS and not message.startswith("--"):
        return f"argument {FLAGS[head]}: {message}"
    return message
