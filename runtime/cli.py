"""The ``camdyn`` command line.

    camdyn derive [--check] [--out DIR]     regenerate generated/ (or check it)
    camdyn residual --model M --tau T ...   residual vibration of one rise
    camdyn check [--json]                   every comparison with the thesis
    camdyn laws [--json]                    cam-law characteristics (App. 2)
    camdyn run [SCENE] [--out DIR]          any scene (default: the CAMSHAFT-1 study): report
    camdyn scenes [--json]                  the built-in scenes, their kinds and titles
    camdyn integrate MODEL --t-end T ...    any model: a model file (built on demand) or built-in
    camdyn simulate SCENE.toml [--json]     a DYNACAM scene (thesis ch. 6, 7): summary and diagrams
    camdyn beam-follower [--omega W] ...    the Rayleigh-beam follower (paper; issue 5)
    camdyn precision SCENE_OR_MODEL ...     work-precision chart: every method, SciPy's beside
    camdyn stability MODEL --param P=A:B:N  stability map: step/rtol x parameter, per method
    camdyn profile --law L --stroke H ...   the cam itself: pitch curve, profile(s), CSV/DXF/PNG
    camdyn figures [--out DIR] [--only IDS]  every thesis/paper figure the models determine + index
    camdyn design --stroke H ...            design by the thesis's rules (secs 8.3, 8.5, App. 7)

Bad arguments end in one line on stderr naming the argument, and status 2.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from dataclasses import replace
from pathlib import Path

from .accuracy import plus_minus
from .errors import CamdynInputError, SimulationError, out_folder


class _Parser(argparse.ArgumentParser):
    """argparse, but errors are one line (no usage block) with status 2."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message}\n")


def fail(prog: str, message: str) -> int:
    """Print a one-line error naming the command and return exit status 2."""
    print(f"{prog}: error: {message}", file=sys.stderr)
    return 2


# -- camdyn derive ------------------------------------------------------------------

def _cmd_derive(args) -> int:
    from camdyn.derive import generate

    try:
        out = Path(args.out) if args.out else generate.project_root() / "generated"
    except FileNotFoundError as exc:
        return fail("camdyn derive", str(exc))
    only = args.only or None
    try:
        if args.check:
            problems = generate.check(out, only, full=args.full)
        else:
            changed = generate.write(out, only, full=args.full)
    except KeyError as exc:
        return fail("camdyn derive", f"argument --only: {exc.args[0]}")
    if args.check:
        if problems:
            print("generated/ is stale; run `camdyn derive` and rebuild:", file=sys.stderr)
            print("\n".join(problems), file=sys.stderr)
            return 1
        print(f"{out}: up to date")
        return 0
    for name in changed:
        print(f"wrote {out / name}")
    if changed:
        print("rebuild the extensions: pip install -e . (or make build)")
    else:
        print(f"{out}: unchanged")
    return 0


# -- camdyn residual ----------------------------------------------------------------

_MODELS = {"one-dof": "one_dof", "camshaft1": "camshaft1", "camshaft2": "camshaft2"}


def residual_run(model: str, tau: float, fa: float | None, law: str, theta: float | None,
                 method: str, rtol: float | None, step: float | None, q: float = 0.0,
                 t_end: float = 3.0, fv: float | None = None) -> dict:
    """One rise and dwell; the residual figures with the run's settings, as a dict.

    camshaft2 (thesis ch. 5) needs both Fa (5.12b) and the flywheel factor Fv (5.14) and adds
    the cam's largest speed deviation max |B' - 1| and the largest wind-up max (T - B) over the
    run (sec. 5.5.5, fig. 5.6).
    """
    from . import closed_forms
    from .residual import extreme, residual
    from .simulate import simulate

    params = {"tau": tau}
    if fv is not None and model != "camshaft2":
        limit = {"one-dof": "Fv -> 0, a cam of infinite inertia", "camshaft1": "Fv -> oo, a massless cam"}
        raise CamdynInputError(f"Fv applies to camshaft2 only: {model} is its limit {limit[model]} "
                               "(thesis sec. 5.7); use --model camshaft2 for a cam with inertia")
    if model == "camshaft2":
        # Fa = 0 or Fv = 0 leave (5.16) without a shaft or without a cam mass: both limits
        # are other models (CAMSHAFT-1, one-dof), so neither has a default here
        if fv is None:
            raise CamdynInputError("argument --fv: required with --model camshaft2 "
                                   "(flywheel factor Fv > 0, thesis (5.14))")
        if fa is None:
            raise CamdynInputError("argument --fa: required with --model camshaft2 "
                                   "(shaft stiffness factor Fa > 0, thesis (5.12b))")
        params.update(Fa=fa, Fv=fv)
        if q:
            raise CamdynInputError("q applies to one-dof only: CAMSHAFT-2 (5.15), (5.16) has no "
                                   "damping")
    elif model == "camshaft1":
        params["Fa"] = 0.0 if fa is None else fa
        if q:
            raise CamdynInputError("q applies to one-dof only: CAMSHAFT-1 (4.15) has no damping "
                                   "(thesis sec. 4.2.4)")
    else:
        params["q"] = q
    if model == "one-dof" and fa not in (None, 0.0):
        raise CamdynInputError("Fa applies to camshaft1 and camshaft2 only: the one-dof model has "
                               "constant fictitious angular velocity (Fa = 0); use --model camshaft1 "
                               "for a flexible shaft")
    if method in ("rk4", "koster") and step is None:
        step = 0.01 * tau  # the thesis's fine step (sec. 4.4.2)
        if model == "camshaft2" and fa > 0 and fv > 0:
            # sec. 5.4: the step follows the smaller period, tau_b = tau (Fa/Fv)^(1/2) (5.19)
            step = 0.01 * min(tau, tau * (fa / fv) ** 0.5)
    from .methods import METHODS

    if method in METHODS and METHODS[method].adaptive and rtol is None and step is None:
        rtol = 1e-10
    if not t_end > 1.0:
        raise CamdynInputError(f"--t-end={t_end:g} must exceed the end of the rise, T = 1")
    c0 = time.process_time()
    res = simulate(_MODELS[model], params, t_end, method, rtol=rtol, step=step, law=law,
                   theta=theta)
    fig = residual(res)
    cpu = time.process_time() - c0
    out = {"model": model, **res.params, "law": law, "method": method, "t_end": t_end}
    if theta is not None or law == "modified-sine":
        out["theta"] = res.laws["H"].par
    out.update(rtol=rtol, step=step)
    out.update(fig.as_dict())
    if model == "camshaft2":
        t0, t1 = float(res.t[0]), float(res.t[-1])
        out["Bdot_dev_max"] = extreme(res, "Bdot_dev", t0, t1, absolute=True, minimum=False)[0]
        out["windup_max"] = extreme(res, "windup", t0, t1, absolute=False, minimum=False)[0]
    out.update({k: res.stats[k] for k in ("n_steps", "n_rejected", "n_rhs")})
    out.update(run_health(res))
    out["cpu_seconds"] = cpu  # integration and post-processing
    if law == "cycloidal" and params.get("Fa", 0.0) == 0.0 and q == 0.0:
        out["U0_closed_form"] = closed_forms.U0(tau)
        out["U0dd_closed_form"] = closed_forms.U0dd(tau)
    return out


def run_health(res) -> dict:
    """What a run says about its own reliability, for the JSON: ``warnings`` (a fixed step near
    the stability boundary) and ``stiff_from_T`` (DP54: where the problem became stiff, else
    None)."""
    return {"warnings": list(res.warnings), "stiff_from_T": res.stiff_from_T}


# the implicit method the stiffness note names (runtime/methods.py RODAS4)
IMPLICIT_HINT = "the implicit (L-stable) method rodas4 (--method rodas4)"


def report_health(prog: str, out: dict, tname: str = "T") -> None:
    """One stderr line per warning, and one for a run that became stiff."""
    for w in out.get("warnings") or ():
        print(f"{prog}: warning: {w}", file=sys.stderr)
    if out.get("stiff_from_T") is not None:
        print(f"{prog}: note: the problem became stiff at {tname} = {out['stiff_from_T']:.6g}; "
              f"{IMPLICIT_HINT} would take larger steps", file=sys.stderr)


def run_failed(prog: str, exc: Exception) -> int:
    """A run that failed (SimulationError): one line on stderr, exit status 1."""
    print(f"{prog}: run failed: {exc}", file=sys.stderr)
    return 1


def _cmd_residual(args) -> int:
    prog = "camdyn residual"
    if args.rtol is not None and args.step is not None:
        return fail(prog, "argument --step: not allowed with argument --rtol")
    try:
        out = residual_run(args.model, args.tau, args.fa, args.law, args.theta, args.method,
                           args.rtol, args.step, args.q, args.t_end, fv=args.fv)
    except CamdynInputError as exc:
        return fail(prog, name_argument(str(exc)))
    except SimulationError as exc:
        return run_failed(prog, exc)
    report_health(prog, out)
    if not args.no_error_estimate:
        try:
            out.update(residual_errors(args, out))
        except SimulationError as exc:
            return run_failed(prog, f"the error estimate's second run failed: {exc}")
    if args.json:
        print(json.dumps(out))
    else:
        from .accuracy import with_errors

        print("\n".join(with_errors({k: v for k, v in out.items() if k != "warnings"})))
    return 0


RESIDUAL_FIGURES = ("U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min", "Bdot_dev_max", "windup_max")
"""The headline figures of `camdyn residual` that get an error estimate."""


def residual_errors(args, out: dict) -> dict:
    """``<figure>_error`` for the residual figures of ``out`` (runtime/accuracy.py): the same
    run at rtol/10 or half the step."""
    from . import accuracy

    settings = accuracy.tighter_settings(args.method, out["rtol"], out["step"])
    tight = None if settings is None else residual_run(
        args.model, args.tau, args.fa, args.law, args.theta, args.method, settings[0],
        settings[1], args.q, args.t_end, fv=args.fv)
    return accuracy.errors(out, tight, RESIDUAL_FIGURES, args.method)


def name_argument(message: str) -> str:
    """Prefix the command-line spelling of the parameter a message is about."""
    flags = {"tau": "--tau", "Fa": "--fa", "Fv": "--fv", "q": "--q", "theta": "--theta", "rtol": "--rtol",
             "step": "--step", "t_end": "--t-end"}
    head = message.split("=", 1)[0].split(" ", 1)[0]
    if head in flags and not message.startswith("--"):
        return f"argument {flags[head]}: {message}"
    return message


def fmt(value) -> str:
    """A value for a text table: 4 significant digits, '-' for None, words for booleans."""
    if isinstance(value, bool):
        return "identical" if value else "differs"
    if value is None:
        return "-"
    try:
        return f"{float(value):.4g}"
    except (TypeError, ValueError):
        return str(value)


# -- camdyn check, camdyn laws: the thesis room's commands ----------------------------
# The comparisons with the thesis and App. 2's law table live in camdyn.thesis, which may import
# SymPy and both sides of the pipeline; the command line is the one place that reaches into it,
# and only when one of these commands runs.

def _cmd_check(args) -> int:
    from camdyn.thesis import commands

    return commands.check(args)


def _cmd_laws(args) -> int:
    from camdyn.thesis import commands

    return commands.laws(args)


def _cmd_design(args) -> int:
    from camdyn.thesis import commands

    return commands.design(args)


# -- camdyn integrate ------------------------------------------------------------------

def _assignments(items, flag: str) -> dict:
    out = {}
    for item in items or ():
        name, sep, value = item.partition("=")
        if not sep or not name:
            raise CamdynInputError(f"argument {flag}: {item!r} is not NAME=VALUE")
        try:
            out[name] = float(value)
        except ValueError:
            raise CamdynInputError(f"argument {flag}: {name}={value!r} is not a number") from None
    return out


def integrate_run(model_arg: str, params: dict, initial: dict, t_end: float, method: str,
                  rtol, step, law: str, theta, progress=None) -> tuple[dict, object]:
    """One run of a model file (built on demand) or a built-in model: (summary, result)."""
    from .models import available, load
    from .simulate import Simulator

    if model_arg.endswith(".py") or Path(model_arg).is_file():
        from . import ondemand

        model = ondemand.model_file(model_arg, progress)
    elif model_arg in available():
        model = load(model_arg)
    else:
        raise CamdynInputError(f"MODEL {model_arg!r} is neither a model file (.py) nor a built-in "
                               f"model; built-in models: {', '.join(available())}")
    if not isinstance(law, str) and not model.manifest.get("cam_instances"):
        # a Turn (--turn) drives the cam inputs; without one it would be dropped unread
        raise CamdynInputError(f"argument --turn: {model.name} has no cam input to drive")
    p = model.parameter_vector(params)
    y0 = model.initial_state(p)
    for name, value in initial.items():
        if name not in model.state_names:
            raise CamdynInputError(f"argument --initial: {model.name} has no state {name}; its "
                                   f"states are {', '.join(model.state_names)}")
        y0[model.state_names.index(name)] = value
    sim = Simulator(model, t_end, method, rtol=rtol, step=step, law=law, theta=theta, y0=y0)
    c0 = time.process_time()
    res = sim.run(params)
    cpu = time.process_time() - c0
    final = res.sample([res.t[-1]])
    summary = {"model": model.name, "method": method, "t_end": t_end,
               "time_unit": model.manifest["time"]["unit"],
               "state": {n: float(final[n][0]) for n in model.state_names},
               "n_steps": int(res.stats["n_steps"]), "n_rhs": int(res.stats["n_rhs"]),
               "cpu_seconds": cpu, "status": "ok", **run_health(res)}
    return summary, res


def _law_arg(args) -> tuple:
    """(law, theta) of a run: --law and --theta, or with --turn the dwell-rise-dwell-return
    turn of --law (rise) and --return-law (runtime.laws.compose)."""
    if getattr(args, "turn", None) is None:
        for flag in ("return_law", "return_theta"):
            if getattr(args, flag, None) is not None:
                raise CamdynInputError(f"argument --{flag.replace('_', '-')}: only with --turn")
        return args.law, args.theta
    from .laws import compose

    try:
        angles = [float(a) for a in args.turn.split(",")]
    except ValueError:
        raise CamdynInputError(f"argument --turn: {args.turn!r} is not four comma-separated "
                               "angles in deg (rise,upper dwell,return,lower dwell)") from None
    return compose(args.law, args.return_law, angles, args.theta,
                   getattr(args, "return_theta", None)), None


def integrate_errors(args, params: dict, initial: dict, summary: dict) -> dict:
    """State name -> estimate of its error at t_end (runtime/accuracy.py): the same run at
    rtol/10 (an adaptive method; rtol 1e-8 when not given) or half the step."""
    from . import accuracy

    settings = accuracy.tighter_settings(args.method, args.rtol, args.step)
    tight = None
    if settings is not None:
        law, theta = _law_arg(args)
        tight, _ = integrate_run(args.model, params, initial, args.t_end, args.method,
                                 settings[0], settings[1], law, theta)
    errs = accuracy.errors(summary["state"], None if tight is None else tight["state"],
                           summary["state"], args.method)
    return {name: errs.get(f"{name}_error") for name in summary["state"]}


def write_series(res, out_dir) -> list:
    """states and outputs against time: <model>.csv and <model>.png in ``out_dir``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    out = out_folder(out_dir)
    m = res.model
    names = m.state_names + m.output_names
    units = {s["name"]: s.get("unit", "") for s in m.manifest["states"] + m.manifest["outputs"]}
    tname = m.manifest["time"]["name"]
    T = np.unique(np.concatenate([res.t, np.linspace(res.t[0], res.t[-1], 1001)]))
    smp = res.sample(T)
    csv = out / f"{m.name}.csv"
    np.savetxt(csv, np.column_stack([T] + [smp[n] for n in names]), delimiter=",",
               header=",".join([tname] + names), comments="")
    fig, axes = plt.subplots(len(names), 1, figsize=(7, 1.8 * len(names) + 0.6), sharex=True,
                             squeeze=False)
    for ax, n in zip(axes[:, 0], names):
        ax.plot(T, smp[n], lw=0.9)
        ax.set_ylabel(f"{n} [{units.get(n, '')}]", fontsize=8)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel(f"{tname} [{m.manifest['time']['unit']}]")
    axes[0, 0].set_title(m.manifest.get("title", m.name), fontsize=9)
    fig.tight_layout()
    png = out / f"{m.name}.png"
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return [str(csv), str(png)]


def _cmd_integrate(args) -> int:
    prog = "camdyn integrate"
    say = (lambda msg: print(msg, file=sys.stderr, flush=True))
    try:
        params = _assignments(args.set, "--set")
        initial = _assignments(args.initial, "--initial")
        if args.rtol is not None and args.step is not None:
            raise CamdynInputError("arguments --rtol and --step: give one (rtol for dp54 and "
                                   "rodas4, step for rk4 and koster)")
        law, theta = _law_arg(args)
        summary, res = integrate_run(args.model, params, initial, args.t_end, args.method,
                                     args.rtol, args.step, law, theta, say)
        if not args.no_error_estimate:
            summary["state_error"] = integrate_errors(args, params, initial, summary)
        if args.out:
            summary["files"] = write_series(res, args.out)
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    except SimulationError as exc:
        return run_failed(prog, exc)
    report_health(prog, summary, res.model.manifest["time"]["name"])
    if args.json:
        print(json.dumps(summary, indent=1))
        return 0
    print(f"{summary['model']}: {summary['method']} to {summary['t_end']:g} "
          f"{summary['time_unit']}, {summary['n_steps']} steps, {summary['n_rhs']} rhs calls, "
          f"{summary['cpu_seconds']:.3g} s CPU")
    errs = summary.get("state_error", {})
    for name, value in summary["state"].items():
        print(f"  {name:12s} {value:.10g}{plus_minus(errs.get(name))}")
    for f in summary.get("files", []):
        print(f"wrote {f}")
    return 0


# -- camdyn run, camdyn scenes --------------------------------------------------------

def _cmd_run(args) -> int:
    """Any scene: the CAMSHAFT-1 study (report and charts), a DYNACAM mechanism (summary and
    diagrams) or the beam follower (tip response), each writing report.json into --out."""
    from . import report, scene as scenes

    say = (lambda msg: None) if args.quiet else (lambda msg: print(msg, file=sys.stderr, flush=True))
    try:
        kind, sc = scenes.load_any(args.scene or "default")
        if args.method is not None:
            sc = _with_method(kind, sc, args.method)
        out_dir = out_folder(args.out, create=False)       # checked before the runs
        if kind == "camshaft1-study":
            path = report.main_job(sc, out_dir, progress=not args.quiet)
            print(f"report: {path}")
            return 0
        if kind == "dynacam":
            from . import dynacam

            summary, res = dynacam.run(sc, progress=say)
            summary["figures"] = dynacam.plot(sc, res, summary, out_dir)
            report_health("camdyn run", summary)
            _print_dynacam(sc, summary)
        else:
            summary = beam_follower_run(sc.case, None, say)
            report_health("camdyn run", summary, "t")
            _print_beam("camdyn run", summary)
    except CamdynInputError as exc:
        return fail("camdyn run", str(exc))
    except SimulationError as exc:
        print(f"camdyn run: run failed: {exc}", file=sys.stderr)
        return 1
    out_folder(out_dir)
    (out_dir / "report.json").write_text(json.dumps({"kind": kind, "scene": sc.path,
                                                     "title": sc.title, **summary}, indent=1))
    print(f"report: {out_dir / 'report.json'}")
    return 0


def _with_method(kind: str, sc, method: str):
    """The scene with its [run] method replaced (--method of run and simulate)."""
    from dataclasses import replace

    if kind == "dynacam":
        return replace(sc, method=method)
    if kind == "beam-follower":
        return replace(sc, case=replace(sc.case, method=method))
    return {**sc, "run": {**sc["run"], "method": method}}


def _cmd_scenes(args) -> int:
    from . import scene as scenes

    rows = scenes.builtins()
    if args.json:
        print(json.dumps([{"name": n, "kind": k, "title": t} for n, k, t in rows], indent=1))
        return 0
    w = max(len(n) for n, _, _ in rows)
    wk = max(len(k) for _, k, _ in rows)
    for name, kind, title in rows:
        print(f"{name:<{w}}  {kind:<{wk}}  {title}")
    print("\nrun one with `camdyn run NAME`; kinds: "
          + "; ".join(f"{k}: {what}" for k, what in scenes.KINDS.items()))
    return 0


# -- camdyn simulate ----------------------------------------------------------------

def _cmd_simulate(args) -> int:
    from . import dynacam, scene as scenes

    def progress(msg):
        if not args.json:
            print(msg, file=sys.stderr)

    try:
        sc = scenes.load(args.scene)
        if args.method is not None:
            sc = _with_method("dynacam", sc, args.method)
        if args.model == "auto":
            if args.out:
                raise CamdynInputError("--out does not go with --model auto (no diagrams of the "
                                       "least model yet)")
            if args.no_error_estimate:
                raise CamdynInputError("--no-error-estimate does not go with --model auto (the "
                                       "error bounds are part of the choice)")
            return _least_model(sc, args, progress)
        if args.tolerance is not None or args.figures is not None or args.build_variants:
            raise CamdynInputError("--tolerance, --figures and --build-variants go with --model auto")
        if args.out:                 # made before the run, so that a bad --out costs no run
            out_folder(args.out)
        summary, res = dynacam.run(sc, progress=progress)
        if not args.no_error_estimate:
            summary.update(dynacam.errors(sc, summary))
        if args.out:
            summary["figures"] = dynacam.plot(sc, res, summary, args.out)
    except CamdynInputError as exc:
        return fail("camdyn simulate", str(exc))
    except SimulationError as exc:
        return run_failed("camdyn simulate", exc)
    report_health("camdyn simulate", summary)
    if args.json:
        print(json.dumps(summary, indent=1))
        return 0
    _print_dynacam(sc, summary)
    return 0


def _least_model(sc, args, progress) -> int:
    """camdyn simulate SCENE --model auto: the least model of the chain of sec. 8.2 that keeps
    the requested figures within the tolerance (runtime/least_model.py)."""
    from . import least_model

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


def _print_dynacam(sc, summary) -> None:
    from . import dynacam

    print(sc.title)
    for key in dynacam.KEYS:
        v = summary.get(key)
        if key == "jump":
            v = summary["jump"]
            v = f"from T = {v['T']:.4g}" if v["occurs"] else "no"
        print(f"  {key:26s} {v if isinstance(v, str) else fmt(v)}"
              f"{plus_minus(summary.get(f'{key}_error'))}")
    if "turn" in summary:
        t = summary["turn"]
        print(f"  full turn: rise, upper dwell, return, lower dwell "
              f"{', '.join(f'{a:.4g}' for a in t['angles_deg'])} deg; return law {t['return_law']}")
        for key in ("Xdd_absmax_return", "U0dd_return", "U0_return"):
            v = summary.get(key)
            print(f"  {key:26s} {'not reached' if v is None else fmt(v)}"
                  f"{plus_minus(summary.get(f'{key}_error'))}")
    for f in summary.get("figures", []):
        print(f"wrote {f}")


# -- camdyn beam-follower ----------------------------------------------------------

# Case field -> command-line spelling, in the order of the usage line
_BEAM_FLAGS = {"omega": "--omega", "modes": "--modes", "rod_radius": "--rod-radius",
               "distance": "--distance", "base_radius": "--base-radius", "rise": "--rise",
               "revolutions": "--revolutions", "rayleigh": "--rayleigh",
               "roller_inertia": "--roller-inertia", "formulation": "--formulation",
               "method": "--method"}
# summary key -> unit, for the table
_BEAM_UNITS = {"omega": "rad/s", "rod_radius": "m", "distance": "m", "base_radius": "m",
               "rise": "m", "roller_inertia": "kg m^2", "roller_radius": "m", "roller_mass": "kg",
               "E": "Pa", "rho": "kg/m^3", "w_B": "rad/s", "max_abs_tip_deflection": "m",
               "max_constraint_residual": "m", "dwell_frequency_hz": "Hz", "cpu_seconds": "s",
               "figures_cpu_seconds": "s"}


def _beam_argument(message: str) -> str:
    """Prefix the flag a :func:`camdyn.runtime.beam.check` message is about (``name=value ...``)."""
    head = message.split("=", 1)[0].split(" ", 1)[0]
    if head in _BEAM_FLAGS and not message.startswith("argument "):
        return f"argument {_BEAM_FLAGS[head]}: {message}"
    return message


def beam_follower_run(case, out_dir=None, progress=None, announce_run=True) -> dict:
    """Check ``case``, run it, report the undercut of its cam profile and, with ``out_dir``,
    write figs 4-9; returns one flat dict: the inputs used, then the results.  ``progress``
    gets one line per run (the main run's only with ``announce_run``).

    An undercut profile is reported (``"undercut"``: the message, else None), not refused:
    the model holds the roller centre on the pitch curve, which stays smooth, so the run is
    that of the designed motion, which a cam cut for this roller could not give."""
    from dataclasses import replace

    from . import beam
    from .profile import RDFD

    beam.check(case)
    planned = []
    if out_dir is not None:
        # every figure run varies one field of this case: refuse before anything runs
        for name, (field, values, _) in beam.FIGURES.items():
            for v in values:
                try:
                    beam.check(replace(case, **{field: v}))
                except CamdynInputError as exc:
                    raise CamdynInputError(
                        f"argument --out: {name} sets {field}={v:g}, which this case does not "
                        f"allow: {exc}") from None
                planned.append(f"{name}, {field} = {v:g}")
        out_folder(out_dir)
    cut = RDFD.of(case.rise, case.base_radius, case.roller_radius, case.law).undercut()
    summary, _ = beam.run(case, progress if announce_run else None)
    out = {key: getattr(case, key) for key in _BEAM_FLAGS}
    out["roller_inertia"] = case.J_r
    out["roller_inertia_default"] = case.roller_inertia is None
    for key in ("law", "roller_radius", "roller_mass", "E", "rho", "rtol", "w_B"):
        out[key] = getattr(case, key)
    out["model"] = summary["model"]
    for key in ("max_abs_tip_deflection", "max_constraint_residual", "dwell_frequency_hz"):
        out[key] = summary[key]
    out["undercut"] = cut.message if cut else None
    out["n_steps"] = summary["n_steps"]
    out["stiff_from_T"] = summary["stiff_from_T"]   # model time t, s
    out["warnings"] = summary["warnings"]
    out["cpu_seconds"] = summary["cpu_seconds"]
    if out_dir is not None:
        done = iter(range(1, len(planned) + 1))

        def figure_progress(msg):
            k = next(done, None)
            if progress and k is not None:
                progress(f"  [{k}/{len(planned)}] {planned[k - 1]}: {msg}")
            elif progress:
                progress(f"  {msg}")

        c0 = time.process_time()
        out["figures"] = beam.plot_figures(case, out_dir, progress=figure_progress)
        out["figures_cpu_seconds"] = time.process_time() - c0
    return out


def _cmd_beam_follower(args) -> int:
    from . import beam

    prog = "camdyn beam-follower"

    def progress(msg):
        print(msg, file=sys.stderr, flush=True)

    given = {key: getattr(args, key) for key in _BEAM_FLAGS}
    case = beam.Case(**{key: v for key, v in given.items() if v is not None})
    try:
        # the main run's line only without --json; the 18 figure runs report in any case
        out = beam_follower_run(case, args.out, progress, announce_run=not args.json)
        if not args.no_error_estimate:
            out.update(beam.errors(case, out))
    except CamdynInputError as exc:
        return fail(prog, _beam_argument(str(exc)))
    except SimulationError as exc:
        return run_failed(prog, exc)
    report_health(prog, out, "t")
    if args.json:
        _warn_undercut(prog, out)
        print(json.dumps(out, indent=1))
        return 0
    _print_beam(prog, out)
    return 0


def _warn_undercut(prog, out) -> None:
    if out["undercut"]:
        print(f"{prog}: warning: {out['undercut']} The run follows the pitch curve all the same.",
              file=sys.stderr)


def _print_beam(prog, out) -> None:
    _warn_undercut(prog, out)
    rows = [(k, v) for k, v in out.items()
            if k not in ("figures", "warnings") and not k.endswith("_error")]
    rows = [(k, ("yes, see the warning" if v else "no") if k == "undercut" else v) for k, v in rows]
    width = max(len(k) for k, _ in rows)
    for k, v in rows:
        text = f"{v:.6g}" if isinstance(v, float) else str(v)
        unit = _BEAM_UNITS.get(k, "")
        text += plus_minus(out.get(f"{k}_error"))
        print(f"{k:<{width}}  {text} {unit}".rstrip())
    for f in out.get("figures", []):
        print(f"wrote {f}")


# -- camdyn precision ----------------------------------------------------------------

def _cmd_precision(args) -> int:
    """Work-precision study (runtime/precision.py): chart, CSV and JSON into --out."""
    from . import precision

    prog = "camdyn precision"
    say = (lambda msg: print(msg, file=sys.stderr, flush=True))
    try:
        params = _assignments(args.set, "--set")
        if args.no_peers and args.peers:
            raise CamdynInputError("arguments --peers and --no-peers: give one")
        pr = precision.problem(args.target, params, args.t_end, say)
        out = out_folder(args.out)
        st = precision.study(pr, args.methods, () if args.no_peers else args.peers,
                             quick=args.quick, progress=say)
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    except SimulationError as exc:
        return run_failed(prog, exc)
    stem = Path(args.target).stem
    files = [st.write_csv(out / f"{stem}_precision.csv"), st.write_json(out / f"{stem}_precision.json"),
             st.chart(out / f"{stem}_precision.png")]
    if args.json:
        print(json.dumps({**precision._finite(st.as_dict()), "files": files}, indent=1))
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


# -- camdyn stability ------------------------------------------------------------------

# default grids: tau at the maxima 2/(2k + 1) of |sin(pi/tau)| in U0 (3.5), k = 13, 9, 6, 4, 2:
# near a zero of U0 (tau = 1/n) a relative error means nothing
_TAU_MAXIMA = "tau=" + ",".join(f"{2 / (2 * k + 1):.6g}" for k in (13, 9, 6, 4, 2))
_STABILITY_DEFAULTS = {"one_dof": _TAU_MAXIMA, "camshaft1": _TAU_MAXIMA,
                       "roller": "kappa=100:10000:3:log"}


def _grid(text: str, flag: str, positive: bool = True) -> list:
    """'A:B:N' (N values from A to B; ':log' for geometric spacing) or 'a,b,c'."""
    import numpy as np

    parts = text.split(":")
    try:
        if len(parts) == 1:
            vals = [float(v) for v in text.split(",") if v.strip()]
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
    return [float(v) for v in vals]


def stability_run(args, say) -> tuple:
    """The map of `camdyn stability` (runtime/stability_map.py): (StabilityMap, model)."""
    import numpy as np

    from . import stability_map as smap
    from .methods import METHODS
    from .models import available, load

    if args.model.replace("_", "-") in BEAM_NAMES:
        return _beam_stability_run(args, say)
    if args.model.endswith(".py") or Path(args.model).is_file():
        from . import ondemand

        model = ondemand.model_file(args.model, say)
    elif args.model.replace("-", "_") in available():
        model = load(args.model)
    else:
        raise CamdynInputError(f"MODEL {args.model!r} is neither a model file (.py) nor a built-in "
                               f"model; built-in models: {', '.join(available())}")
    spec = args.param or _STABILITY_DEFAULTS.get(model.name)
    if spec is None:
        raise CamdynInputError(f"argument --param: required for {model.name} (NAME=START:STOP:N, "
                               f"e.g. one of {', '.join(model.parameter_names)})")
    name, sep, rng = spec.partition("=")
    if not sep or not name:
        raise CamdynInputError(f"argument --param: {spec!r} is not NAME=START:STOP:N[:log]")
    values = _grid(rng, "--param", positive=False)
    methods = args.methods or [k for k in ("rk4", "koster", "dp54", "rodas4")
                               if not (k == "koster" and len(model.state_names) != 2 * model.manifest["n_q"])]
    for k in methods:
        if k not in METHODS:
            raise CamdynInputError(f"argument --methods: unknown method {k!r}; choose from "
                                   f"{', '.join(METHODS)}")
    fixed = _assignments(args.set, "--set")
    rtols = _grid(args.rtols, "--rtols") if args.rtols else list(np.geomspace(1e-3, 1e-10, 8))
    if any(not r < 1 for r in rtols):
        raise CamdynInputError("argument --rtols: every rtol must be < 1")
    if args.steps:
        steps = _grid(args.steps, "--steps")
    else:   # around the theory's boundary over the grid: 1/50 of the smallest to 1.6 x the largest
        lims = []
        for v in values:
            p = {**fixed, name: v}
            model.parameter_vector(p)
            ref = smap.reference(model, p, args.t_end, args.law)
            lims.append(smap.step_limit(model, "rk4", ref))
        steps = list(np.geomspace(min(lims) / 50, max(lims) * 1.6, 10))
    return smap.run_map(model, name, values, methods, steps=steps, rtols=rtols, fixed=fixed,
                        threshold=args.threshold, t_end=args.t_end, law=args.law,
                        check_stability=not args.run_refused, progress=say), model


BEAM_NAMES = ("beam-follower", "beam")


def _beam_stability_run(args, say) -> tuple:
    """The beam follower's map (runtime/stability_beam.py) over E or N: dp54 and rodas4 over
    rtol, the paper's case otherwise (--set modes=N with E, --set E=... with N)."""
    from types import SimpleNamespace

    from . import stability_beam as sb
    from .beam_case import Case

    name, values = "N", None
    if args.param:
        name, sep, rng = args.param.partition("=")
        if not sep or name not in sb.PARAMS:
            raise CamdynInputError(f"argument --param: {args.param!r}: the beam follower's map "
                                   f"takes E=START:STOP:N[:log] or N=a,b,c")
        values = _grid(rng, "--param")
    methods = args.methods or ["dp54", "rodas4"]
    rtols = _grid(args.rtols, "--rtols") if args.rtols else [1e-4, 1e-5, 1e-6, 1e-7, 1e-8]
    if args.steps:
        raise CamdynInputError("argument --steps: the beam follower's map takes --rtols "
                               "(dp54, rodas4)")
    base = Case()
    for k, v in _assignments(args.set, "--set").items():
        if k == "modes":
            base = replace(base, modes=int(v))
        elif k == "E":
            base = replace(base, E=float(v))
        else:
            raise CamdynInputError(f"argument --set: the beam follower's map takes modes=N or "
                                   f"E=PA besides its --param, not {k}")
    smap = sb.run_map(name, values or sb.default_values(name), methods, rtols,
                      threshold=args.threshold, base=base, progress=say)
    return smap, SimpleNamespace(name="beam_follower")


def _cmd_stability(args) -> int:
    prog = "camdyn stability"
    say = (lambda msg: None) if args.quiet else (lambda msg: print(f"{prog}: {msg}", file=sys.stderr, flush=True))
    from . import stability_map as smap

    try:
        if not 0 < args.threshold < 1:
            raise CamdynInputError(f"argument --threshold: {args.threshold:g} is out of range: "
                                   f"0 < threshold < 1")
        if not args.t_end > 0:
            raise CamdynInputError(f"argument --t-end: {args.t_end:g} must be positive")
        out = out_folder(args.out, create=False)       # checked before the runs
        m, model = stability_run(args, say)
        out_folder(out)
        stem = out / f"stability_{model.name}_{m.param}"
        files = [m.plot(f"{stem}.png"), m.write_csv(f"{stem}.csv"), m.write_json(f"{stem}.json")]
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    except SimulationError as exc:   # the reference run itself failed
        return run_failed(prog, f"the reference run (dp54, rtol {smap.REF_RTOL:g}) failed: {exc}")
    summary = {"model": m.model, "param": m.param, "values": m.values, "counts": m.counts(),
               "largest_fine": {k: smap.largest_fine(m, k) for k in m.settings},
               "step_limit": m.step_limit, "files": files}
    if args.json:
        print(json.dumps(summary, indent=1))
        return 0
    print(f"{m.model}: stability map over {m.param} = {', '.join(f'{v:.4g}' for v in m.values)} "
          f"({m.figure} within {m.threshold:g} counts as fine)")
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

# -- parser -------------------------------------------------------------------------

def _method_names() -> tuple[list, list]:
    """(every method, the adaptive ones) for the --method choices.  A compiled runtime older
    than its sources (a loop added, not yet rebuilt) must not stop `camdyn derive`, which
    regenerates what the rebuild then compiles: its names are then the known ones."""
    try:
        from . import methods
    except (ImportError, AttributeError):
        return ["dp54", "koster", "rk4", "rodas4"], ["dp54", "rodas4"]
    return sorted(methods.METHODS), list(methods.ADAPTIVE)


def build_parser() -> argparse.ArgumentParser:
    from . import laws

    all_methods, adaptive = _method_names()

    top = _Parser(prog="camdyn", description="Cam-mechanism dynamics: derive, generate, simulate, check.")
    sub = top.add_subparsers(dest="command", required=True, parser_class=_Parser)

    d = sub.add_parser("derive", help="regenerate generated/ from the model declarations")
    d.add_argument("--check", action="store_true", help="exit 1 when generated/ is stale")
    d.add_argument("--out", help="target folder (default: generated/ of this checkout)")
    d.add_argument("--only", nargs="+", metavar="MODEL", help="only these registered models")
    d.add_argument("--full", action="store_true",
                   help="derive every file again, also those whose recorded derivation key is current")
    d.set_defaults(func=_cmd_derive)

    r = sub.add_parser("residual", help="residual vibration after one rise (thesis ch. 3-5)")
    r.add_argument("--model", required=True, choices=sorted(_MODELS))
    r.add_argument("--tau", required=True, type=float, help="T_e/t_m (3.3), (4.12)")
    r.add_argument("--fa", type=float, default=None,
                   help="shaft stiffness factor Fa (4.14), (5.12b): camshaft1, camshaft2")
    r.add_argument("--fv", type=float, default=None,
                   help="flywheel factor Fv (5.14): camshaft2 only, required there")
    r.add_argument("--q", type=float, default=0.0, help="relative damping q (6.47), one-dof only; default 0")
    r.add_argument("--law", default="cycloidal", choices=laws.NAMES)
    r.add_argument("--theta", type=float, default=None, help="shape parameter of the modified sine")
    r.add_argument("--method", default="dp54", choices=all_methods)
    r.add_argument("--rtol", type=float, default=None,
                   help="dp54/rodas4 tolerance (default 1e-10)")
    r.add_argument("--step", type=float, default=None, help="rk4/koster step in T (default tau/100)")
    r.add_argument("--t-end", type=float, default=3.0, help="end of the dwell, in T (default 3)")
    r.add_argument("--json", action="store_true", help="one JSON object on stdout")
    r.add_argument("--no-error-estimate", action="store_true",
                    help="skip the second, more accurate run that estimates each headline figure's error (sweeps)")
    r.set_defaults(func=_cmd_residual)

    c = sub.add_parser("check", help="every comparison with the thesis, as a table")
    c.add_argument("--json", action="store_true", help="one JSON object on stdout")
    c.add_argument("-k", default=None, help="only checks whose key contains this text")
    c.add_argument("--topic", action="append", help="only this topic (repeatable)")
    c.add_argument("--quiet", action="store_true", help="no progress lines")
    c.set_defaults(func=_cmd_check)

    lw = sub.add_parser("laws", help="cam-law characteristics (thesis App. 2), derived symbolically")
    lw.add_argument("--theta", type=float, default=None,
                    help="modified sine's theta, 0 < theta < 0.5 (default 0.1; not with --sweep)")
    lw.add_argument("--json", action="store_true", help="one JSON array on stdout")
    lw.add_argument("--tau", type=float, default=None,
                    help="0 < tau < 0.99: the selection criteria of sec. 9.2.2 at this tau (envelope "
                         "U0 and U0'' of CAMSHAFT-1, impact sensitivity, peaks)")
    lw.add_argument("--fa", type=float, default=None,
                    help="Fa of the selection, 0 <= Fa <= 100 (default 0)")
    lw.add_argument("--stroke", type=float, default=None, metavar="M",
                    help="with --tau, --base-radius and --roller-radius: stroke in m, >= 0; "
                         "adds the cam's least radius of curvature and largest pressure angle "
                         "(90/90/90/90 deg cam)")
    lw.add_argument("--base-radius", type=float, default=None, metavar="M",
                    help="with --stroke: base circle radius in m, > 0")
    lw.add_argument("--roller-radius", type=float, default=None, metavar="M",
                    help="with --stroke: roller radius in m, > 0")
    lw.add_argument("--out", default=None, help="folder for laws_selection.png/.csv "
                    "(laws_sweep.png/.csv with --sweep)")
    lw.add_argument("--sweep", default=None, metavar="SCENE",
                    help="a DYNACAM scene (camdyn scenes): run it over a grid of the shape "
                         "parameter of --law and chart U0'' and the largest fictitious angular-"
                         "velocity variation against it (thesis fig. 8.8)")
    lw.add_argument("--law", default=None, choices=laws.NAMES,
                    help="with --sweep: the law whose parameter is swept (default modified-sine)")
    lw.add_argument("--n", type=int, default=None, help="with --sweep: grid points, 2 to 200 (default 9)")
    lw.add_argument("--values", default=None, metavar="V1,V2,...",
                    help="with --sweep: these parameter values instead of the grid")
    lw.add_argument("--no-error-estimate", action="store_true",
                    help="with --sweep: skip the second run per point at rtol/10")
    lw.set_defaults(func=_cmd_laws)

    _add_design(sub, laws.NAMES)

    m = sub.add_parser("run", help="any scene: the CAMSHAFT-1 study (default), a DYNACAM mechanism, "
                                   "the beam follower")
    m.add_argument("scene", nargs="?", default=None,
                   help="scene TOML or a built-in scene name (camdyn scenes); default: the "
                        "embedded CAMSHAFT-1 study")
    m.add_argument("--out", default="out", help="folder for report and charts (default out/)")
    m.add_argument("--method", default=None, choices=adaptive,
                   help="integration method instead of the scene's [run] method; rodas4 is the "
                        "stiff solver")
    m.add_argument("--quiet", action="store_true", help="no progress lines")
    m.set_defaults(func=_cmd_run)

    ls = sub.add_parser("scenes", help="the built-in scenes with their kinds and titles")
    ls.add_argument("--json", action="store_true", help="one JSON array on stdout")
    ls.set_defaults(func=_cmd_scenes)

    ig = sub.add_parser("integrate", help="any model: a model file (built on first use) or a "
                                          "built-in model, to t_end")
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
                    help="dp54/rodas4 tolerance (default 1e-8)")
    ig.add_argument("--step", type=float, default=None, help="rk4/koster step")
    ig.add_argument("--law", default="cycloidal", choices=laws.NAMES, help="cam law of the inputs")
    ig.add_argument("--theta", type=float, default=None, help="shape parameter of the law")
    ig.add_argument("--turn", default=None, metavar="RISE,UP,RETURN,LOW",
                    help="a full cam turn, repeated: rise by --law, upper dwell, return by "
                         "--return-law, lower dwell, in deg summing to 360 (the input's "
                         "argument counts rises: one turn is 360/RISE)")
    ig.add_argument("--return-law", default=None, choices=laws.NAMES,
                    help="with --turn: the law of the return (default: --law)")
    ig.add_argument("--return-theta", type=float, default=None,
                    help="with --return-law: its shape parameter (default: the law's own)")
    ig.add_argument("--json", action="store_true", help="one JSON object on stdout")
    ig.add_argument("--no-error-estimate", action="store_true",
                     help="skip the second, more accurate run that estimates each headline figure's error (sweeps)")
    ig.add_argument("--out", default=None, help="folder for <model>.csv and <model>.png")
    ig.set_defaults(func=_cmd_integrate)

    sm = sub.add_parser("simulate", help="a DYNACAM scene (thesis ch. 6, 7): summary and diagrams")
    sm.add_argument("scene", help="scene TOML, or a built-in DYNACAM scene: indexing, "
                                   "indexing_squeeze, spring_loaded, fig8_1a, fig8_1b")
    sm.add_argument("--json", action="store_true", help="one JSON object on stdout")
    sm.add_argument("--no-error-estimate", action="store_true",
                     help="skip the second, more accurate run that estimates each headline figure's error (sweeps)")
    sm.add_argument("--out", default=None, help="folder for the diagrams (PNG)")
    sm.add_argument("--method", default=None, choices=adaptive,
                    help="integration method instead of the scene's (dp54 unless it sets "
                         "run.method); rodas4 is the stiff solver")
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
    sm.set_defaults(func=_cmd_simulate)

    _add_beam_follower(sub)
    st = sub.add_parser("stability", help="stability map: each method over a grid of step (or "
                                          "rtol) x a stiffness parameter")
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
                    help="tolerances of dp54/rodas4 (default 1e-3 .. 1e-10, 8)")
    st.add_argument("--threshold", type=float, default=1e-3,
                    help="relative error of the headline figure above which a run is "
                         "inaccurate (default 1e-3)")
    st.add_argument("--t-end", type=float, default=3.0, help="end of each run (default 3)")
    st.add_argument("--law", default="cycloidal", choices=laws.NAMES)
    st.add_argument("--run-refused", action="store_true",
                    help="run refused steps anyway and show what they do (stability check off)")
    st.add_argument("--out", default="out", help="folder for PNG, CSV, JSON (default out/)")
    st.add_argument("--json", action="store_true", help="the summary as JSON on stdout")
    st.add_argument("--quiet", action="store_true", help="no progress lines")
    st.set_defaults(func=_cmd_stability)

    _add_precision(sub, all_methods)
    _add_profile(sub, laws.NAMES)
    _add_figures(sub)
    _add_sweep(sub, all_methods, laws.NAMES)
    return top


# -- camdyn figures: the thesis room's figure registry (thesis/figures/) -------------------

def _cmd_figures(args) -> int:
    from camdyn.thesis import commands

    return commands.figures(args)


def _add_figures(sub) -> None:
    f = sub.add_parser(
        "figures", help="every thesis and paper figure the models determine, with an index page",
        description="Draw the thesis's figures (3.3 ... 8.6, A.5.7), the paper's figs 4-9 and "
                    "the design charts into --out, and write index.html showing each picture "
                    "beside its number, caption and the printed statements it reproduces, "
                    "computed now. Exit 1 if a figure fails or a statement is not reproduced.")
    f.add_argument("--out", default="out/figures", metavar="DIR",
                   help="folder for the PNG files and index.html (default out/figures)")
    f.add_argument("--only", default=None, metavar="IDS",
                   help="comma-separated figure ids (3.3,4.11a,paper 5; 4.11 = 4.11a-c; "
                        "thesis, paper or design = the whole group)")
    f.add_argument("--quick", action="store_true",
                   help="coarser tau grids for the response graphs (4.11, 5.7): a draft in "
                        "a fraction of the time")
    f.add_argument("--quiet", action="store_true", help="no progress bar")
    f.set_defaults(func=_cmd_figures)


# -- camdyn profile ------------------------------------------------------------------

def _cmd_profile(args) -> int:
    from .cam_profile import CamProfile

    prog = "camdyn profile"
    try:
        angles = [float(a) for a in args.angles.split(",")]
    except ValueError:
        return fail(prog, f"--angles must be four numbers in deg, rise,upper dwell,return,lower "
                          f"dwell summing to 360, got {args.angles!r}")
    try:
        cam = CamProfile(stroke=args.stroke, base_radius=args.base_radius,
                         roller_radius=args.roller_radius, offset=args.offset,
                         angles_deg=tuple(angles), law=args.law, law_parameter=args.law_parameter,
                         return_law=args.return_law,
                         return_law_parameter=args.return_law_parameter,
                         groove=args.groove, points_per_degree=args.points_per_degree,
                         max_pressure_angle_deg=args.max_pressure_angle)
        out = cam.summary()
        out_folder(args.out)
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    out["files"] = cam.write_all(args.out)
    for c in cam.failures:
        print(f"{prog}: warning: {c.message}", file=sys.stderr)
    out["files"]["json"] = str(Path(args.out) / "cam.json")
    Path(out["files"]["json"]).write_text(json.dumps(out, indent=1))
    if args.json:
        print(json.dumps(out, indent=1))
        return 0
    print(f"{out['kind']} cam, {cam.law}{'' if cam.return_law in (None, cam.law) else ' / ' + cam.return_law + ' return'} law, stroke {cam.stroke * 1e3:g} mm, base circle "
          f"{cam.base_radius * 1e3:g} mm, roller {cam.roller_radius * 1e3:g} mm, offset "
          f"{cam.offset * 1e3:g} mm, {out['points']} points")
    for c in cam.checks:
        print(f"{'ok  ' if c.ok else 'FAIL'} {c.message}")
    for f in out["files"].values():
        print(f"wrote {f}")
    return 0


def _add_profile(sub, law_names) -> None:
    p = sub.add_parser(
        "profile", help="the cam itself: pitch curve and profile(s) of a disk cam for a "
                        "translating roller follower, as CSV, DXF and PNG",
        description="A radial disk cam for a translating roller follower over a full turn "
                    "(rise, upper dwell, return with the same law mirrored, lower dwell): the "
                    "pitch curve and the profile (open cam) or both walls (--groove), with the "
                    "pressure angle and the radius of curvature along the cam angle, written as "
                    "CSV (SI), DXF (mm, layers PITCH, PROFILE, PROFILE_OUTER, BASE_CIRCLE) and "
                    "PNG. The undercut and pressure-angle checks that fail are warnings naming "
                    "the cam angle where they are worst (and in the JSON). SI units.")
    p.add_argument("--law", default="cycloidal", choices=law_names,
                   help="cam law of the rise (the return is its mirror unless --return-law; "
                        "default cycloidal)")
    p.add_argument("--law-parameter", type=float, default=None, metavar="X",
                   help="the law's shape parameter, for laws that have one")
    p.add_argument("--return-law", default=None, choices=law_names,
                   help="cam law of the return, S = h (1 - H(u)) (default: the rise's)")
    p.add_argument("--return-law-parameter", type=float, default=None, metavar="X",
                   help="the return law's shape parameter")
    p.add_argument("--stroke", type=float, required=True, metavar="M", help="stroke h, m, >= 0")
    p.add_argument("--base-radius", type=float, required=True, metavar="M",
                   help="base circle of the cam profile r_b, m, > 0 (roller centre on the "
                        "prime circle r_b + r_r at the bottom of the stroke)")
    p.add_argument("--roller-radius", type=float, required=True, metavar="M",
                   help="roller radius r_r, m, > 0")
    p.add_argument("--offset", type=float, default=0.0, metavar="M",
                   help="follower offset e, m, |e| < r_b + r_r (default 0; e > 0 lowers the "
                        "pressure angle on the rise)")
    p.add_argument("--angles", default="90,90,90,90", metavar="R,D,F,D",
                   help="rise, upper dwell, return, lower dwell in deg, summing to 360 "
                        "(default 90,90,90,90)")
    p.add_argument("--groove", action="store_true", help="a groove cam: both walls")
    p.add_argument("--max-pressure-angle", type=float, default=30.0, metavar="DEG",
                   help="pressure-angle limit of the check, 0 < DEG < 90 (default 30)")
    p.add_argument("--points-per-degree", type=int, default=10, metavar="N",
                   help="samples per degree of cam angle, 1 to 1000 (default 10)")
    p.add_argument("--out", default="out/cam", metavar="DIR",
                   help="folder for cam.csv, cam.dxf, cam.png, cam.json (default out/cam)")
    p.add_argument("--json", action="store_true", help="one JSON object on stdout")
    p.set_defaults(func=_cmd_profile)


def _add_beam_follower(sub) -> None:
    # the defaults shown in the help are the case's own (beam_case loads no SciPy)
    from dataclasses import asdict

    from .beam_case import FORMULATIONS, N_MAX, Case
    from .methods import ADAPTIVE

    dflt = asdict(Case())
    disc = Case().J_r
    b = sub.add_parser(
        "beam-follower", help="the Rayleigh-beam follower of the paper (issue 5): tip response",
        description="Translating roller follower in the groove of a rigid disk cam (RDFD motion, "
                    "cycloidal rise and fall over 90 deg each), its rod a Rayleigh beam clamped in "
                    "the guide whose free length changes as the cam turns. Integrates whole cam "
                    "revolutions from the rigid follower's state at theta = 0 and reports the "
                    "largest tip deflection |v_E|, the largest constraint residual and the lowest "
                    "transverse natural frequency with the rod frozen at the outer dwell. SI "
                    "units; defaults are the paper's data (sec. 4). A cam profile whose groove "
                    "wall is undercut for this roller is reported with a warning (and in the JSON "
                    "as \"undercut\") but not refused: the model follows the pitch curve, so the "
                    "run shows the designed motion, which a cam cut for this roller could not "
                    "give. Progress lines go to stderr.")
    b.add_argument("--omega", type=float, metavar="RAD_S",
                   help=f"cam speed Omega, rad/s (default {dflt['omega']:g}; paper: 120, 240, 360)")
    b.add_argument("--modes", type=int, metavar="N",
                   help=f"assumed modes N, 1 to {N_MAX} (default {dflt['modes']})")
    b.add_argument("--rod-radius", type=float, metavar="M",
                   help=f"radius of the follower rod, m (default {dflt['rod_radius']:g})")
    b.add_argument("--distance", type=float, metavar="M",
                   help=f"cam centre to guide exit d, m (default {dflt['distance']:g})")
    b.add_argument("--base-radius", type=float, metavar="M",
                   help=f"base-circle radius r_b, m (default {dflt['base_radius']:g}); the "
                        f"roller must stay clear of the guide at the top of the stroke")
    b.add_argument("--rise", type=float, metavar="M",
                   help=f"total rise S_T, m (default {dflt['rise']:g})")
    b.add_argument("--revolutions", type=float, metavar="K",
                   help=f"cam revolutions to integrate, > 0 (default {dflt['revolutions']:g})")
    b.add_argument("--rayleigh", action=argparse.BooleanOptionalAction,
                   help="keep the rotary inertia of the rod (default); --no-rayleigh gives the "
                        "Euler-Bernoulli rod")
    b.add_argument("--roller-inertia", type=float, metavar="KG_M2",
                   help=f"roller moment of inertia J_r, kg m^2, >= 0 (default: uniform disc "
                        f"m_r r_r^2/2 = {disc:g}); 0 ignores the roller's rotation")
    b.add_argument("--formulation", choices=tuple(FORMULATIONS),
                   help=f"augmented (multipliers, Baumgarte) or partitioned (coordinate "
                        f"partitioning, paper (21)-(27)); default {dflt['formulation']}")
    b.add_argument("--method", choices=ADAPTIVE,
                   help=f"integration method (default {dflt['method']}); rodas4, the stiff "
                        f"solver, suits stiff rods (large E, many modes)")
    b.add_argument("--json", action="store_true", help="one JSON object on stdout")
    b.add_argument("--no-error-estimate", action="store_true",
                    help="skip the second, more accurate run that estimates each headline figure's error (sweeps)")
    b.add_argument("--out", default=None, metavar="DIR",
                   help="also write the paper's figs 4-9 (tip deflection against cam angle, one "
                        "parameter varied; 18 runs) as PNG into DIR")
    b.set_defaults(func=_cmd_beam_follower)


def _add_precision(sub, all_methods) -> None:
    pr = sub.add_parser("precision", help="work-precision chart: error against CPU time of every "
                                          "method over a ladder of tolerances, SciPy's beside")
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
    pr.add_argument("--out", default="out", help="folder for the chart, CSV and JSON (default out/)")
    pr.add_argument("--json", action="store_true", help="one JSON object on stdout")
    pr.add_argument("--quick", action="store_true", help="every other rung of the ladders")
    pr.set_defaults(func=_cmd_precision)


def _add_design(sub, law_names) -> None:
    """`camdyn design`: SI inputs, the thesis's answer (camdyn/thesis/design.py)."""
    ds = sub.add_parser("design", help="design by the thesis's rules: tau, Fa, the envelope, the "
                                       "largest Fa and smallest t_m meeting a requirement, sec. 8.5's "
                                       "rules, the motor (sec. 8.3), a check run")
    a = ds.add_argument
    a("--stroke", type=float, required=True, metavar="M", help="h_m', stroke of the output member (m)")
    a("--rise-time", type=float, default=None, metavar="S", help="t_m, cam rise time (s)")
    a("--cam-angle", default=None, metavar="RAD",
      help="beta_m, cam angle of the rise: rad, or degrees as '100deg' (with --speed)")
    a("--speed", type=float, default=None, metavar="RPM", help="camshaft speed (r.p.m.)")
    a("--mass", type=float, default=None, metavar="KG", help="m, equivalent mass at the output (4.39)")
    a("--stiffness", type=float, default=None, metavar="N/M",
      help="c_c, stiffness of the uncoupled follower system at the output (4.3)")
    a("--tau", type=float, default=None,
      help="tau = T_e/t_m directly, 0 < tau < 0.9 (dimensionless; instead of m and c_c)")
    a("--fa", type=float, default=None,
      help="Fa directly, 0 <= Fa <= 12.8 (dimensionless; instead of --c-tan)")
    a("--c-tan", type=float, default=None, metavar="N/M",
      help="c_tan, tangential stiffness of the shaft at the output (4.4); Fa = (c_c/c_tan) tan^2 alpha_me")
    a("--pitch-radius", type=float, default=None, metavar="M", help="R_1/2 at the cam (4.1)")
    a("--ratio", type=float, default=None, metavar="I",
      help="transmission ratio i, h_m' = i h_m at the cam (default 1)")
    a("--tan-alpha-me", type=float, default=None,
      help="tan alpha_me, the mean slope (4.13) directly (dimensionless; instead of --pitch-radius)")
    a("--accuracy", type=float, default=None, metavar="M", help="largest positional error u0 (m)")
    a("--residual-acceleration", type=float, default=None, metavar="M/S2",
      help="largest residual acceleration u0'' after the rise (m/s^2)")
    a("--law", default="cycloidal", choices=law_names, help="cam law of the rise (default cycloidal)")
    a("--theta", type=float, default=None,
      help="the law's shape parameter, for laws that have one (default: the law's own)")
    a("--common-shaft", action="store_true", help="the shaft drives other mechanisms (Fa <= 0.3, sec. 8.5)")
    a("--motor-rpm", type=float, default=None, help="a thesis motor by synchronous speed: "
      "3000/1500/1000/750 (T_m of fig. A.5.3)")
    a("--motor-tm", type=float, default=None, metavar="S", help="the motor's mechanical time "
      "constant T_m = J_m/G (A.5.11)")
    a("--motor-tel", type=float, default=None, metavar="S",
      help="electrical time constant T_el (A.5.3): second-order slip (A.5.25) instead of (A.5.33)")
    a("--rated-slip", type=float, default=None, help="delta_n, the motor's rated slip, 0 < delta_n < 1 "
      "(default 0.085, fig. A.5.3)")
    a("--slip-limit", type=float, default=None,
      help="delta_lim, the largest slip allowed, 0 < delta_lim < 1 (8.1); required with a motor")
    a("--spring", action="store_true", help="a follower spring: v_v = 5 in (8.1) (with a motor)")
    a("--gear-efficiency", type=float, default=None,
      help="eta_g of the reduction gear, 0 < eta_g <= 1 (8.1) (with a motor; default 1)")
    a("--worm", type=float, nargs=2, default=None, metavar=("ALPHA", "MU"),
      help="worm gear lead angle and friction angle (rad): eta_g by (6.72)")
    a("--no-check", action="store_true", help="skip the check run")
    a("--json", action="store_true", help="one JSON object on stdout")
    a("--out", default=None, help="folder for design.json and design.png (the envelope u0 over "
                                   "tau at the design's Fa, the largest Fa and Fa = 0, with the "
                                   "requirement)")
    a("--quiet", action="store_true", help="no progress lines")
    ds.set_defaults(func=_cmd_design)
# -- camdyn sweep ----------------------------------------------------------------------

def _cmd_sweep(args) -> int:
    """The headline figures over a grid of parameters (runtime/sweep.py): CSV, Parquet with
    pyarrow, a chart per figure."""
    from . import sweep as sw

    try:
        grid = sw.parse_grid(args.grid)
        out_folder(args.out, create=False)       # checked before the runs
        res = sw.sweep(args.target, grid, jobs=args.jobs, dask=args.dask,
                       progress=not args.quiet, t_end=args.t_end, method=args.method,
                       rtol=args.rtol, law=args.law, step=args.step,
                       errors=args.error_estimate)
        files = res.write(args.out)
    except CamdynInputError as exc:
        return fail("camdyn sweep", str(exc))
    except SimulationError as exc:
        print(f"camdyn sweep: run failed: {exc}", file=sys.stderr)
        return 1
    print(f"{len(res)} runs of {args.target} in {res.seconds:.2f} s ({res.where}); "
          f"figures: {', '.join(res.figures)}")
    for path in files:
        print(f"  {path}")
    return 0


def _add_sweep(sub, all_methods, law_names) -> None:
    sw = sub.add_parser("sweep", help="headline figures over a grid of parameters: table (CSV, "
                        "Parquet) and a chart per figure, on every core or a Dask cluster")
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
    sw.add_argument("--out", default="out/sweep", help="folder for the table and charts "
                                                       "(default out/sweep)")
    sw.add_argument("--t-end", type=float, default=None,
                    help="end of each run of a model, in its time unit (T = t/t_m for the "
                         "thesis models), at least one period tau past the rise (default 3)")
    sw.add_argument("--method", choices=all_methods, default=None,
                    help="integration method (default: the scene's, dp54 for a model)")
    sw.add_argument("--rtol", type=float, default=None,
                    help="relative tolerance of dp54/rodas4, 1e-14 <= rtol < 1 (default: the "
                         "scene's, 1e-9 for a model)")
    sw.add_argument("--step", type=float, default=None,
                    help="step of a fixed-step method (rk4, koster; required there), in the "
                         "model's time unit; not with dp54/rodas4")
    sw.add_argument("--law", choices=law_names, default=None,
                    help="cam law of a model (default: the scene's, cycloidal)")
    sw.add_argument("--error-estimate", action="store_true",
                    help="run the grid again at rtol/10 (half the step) and add a column "
                         "<figure>_error per figure (twice the time)")
    sw.add_argument("--quiet", action="store_true", help="no progress bar")
    sw.set_defaults(func=_cmd_sweep)


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    out = getattr(args, "out", None)
    # every --out names a folder: a file in its place is refused here, in one line, rather
    # than by a FileExistsError deep inside a command after its runs
    if out is not None and Path(out).exists() and not Path(out).is_dir():
        return fail(f"camdyn {args.command}" if getattr(args, "command", None) else "camdyn",
                    f"argument --out: {out} is a file; --out names a folder")
    try:
        rc = args.func(args)
        sys.stdout.flush()           # here, so that a closed pipe is caught below
        return rc
    except BrokenPipeError:
        # the reader of stdout left (`camdyn ... | head`): stop quietly, not with a traceback,
        # and keep the interpreter's final flush from raising it again
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1


if __name__ == "__main__":
    sys.exit(main())
