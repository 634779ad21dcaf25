"""The thesis room's commands, `camdyn check` and `camdyn laws` (the entry point,
camdyn.runtime.cli, hands them over here).

They live beside what they run: the comparisons with the thesis (:mod:`camdyn.thesis.checks`)
and the App. 2 law table (:mod:`camdyn.thesis.lawtable`), both of which need SymPy, which the
runtime's own commands never load.
"""
from __future__ import annotations

import json
from pathlib import Path
import sys

from camdyn.runtime.cli import fail, fmt, name_argument, run_failed
from camdyn.runtime.errors import out_folder


def check(args) -> int:
    """`camdyn check`: run the comparisons with the thesis (thesis/checks/) and print the table."""
    from . import checks

    try:
        topics = checks.TOPICS if not args.topic else tuple(args.topic)
        unknown = sorted(set(topics) - set(checks.TOPICS))
        if unknown:
            return fail("camdyn check", f"argument --topic: unknown topic {unknown[0]!r}; "
                                         f"choose from {', '.join(checks.TOPICS)}")
        todo = [c for c in checks.registry(topics) if not args.k or args.k in c.key]
    except Exception as exc:
        return fail("camdyn check", f"cannot load the checks: {exc}")
    outcomes = []
    for i, c in enumerate(todo, 1):
        if not args.json and not args.quiet:
            print(f"  [{i}/{len(todo)}] {c.key}", file=sys.stderr, flush=True)
        outcomes.append(checks.run(c))
    if args.json:
        print(json.dumps({"passed": all(o.passed for o in outcomes),
                          "checks": [o.as_dict() for o in outcomes]}, indent=1))
    else:
        _print_check_table(outcomes)
    return 0 if all(o.passed for o in outcomes) else 1


def _print_check_table(outcomes) -> None:
    rows = [("item", "reference", "printed", "derived", "rel. diff", "status")]
    for o in outcomes:
        c = o.check
        rel = "-" if o.rel_diff is None else f"{o.rel_diff:.2g}"
        derived = o.error if o.error else fmt(o.derived)
        rows.append((c.item, c.reference, c.printed or "(symbolic)", derived, rel, o.status))
    widths = [min(max(len(r[i]) for r in rows), 60) for i in range(len(rows[0]))]
    for k, r in enumerate(rows):
        print("  ".join(cell[:60].ljust(widths[i]) for i, cell in enumerate(r)).rstrip())
        if k == 0:
            print("  ".join("-" * w for w in widths))
    n_fail = sum(not o.passed for o in outcomes)
    n_err = sum(o.check.errata for o in outcomes)
    print(f"\n{len(outcomes)} checks: {len(outcomes) - n_fail} passed ({n_err} of them printed "
          f"values shown to be misprints), {n_fail} failed, "
          f"{sum(o.seconds for o in outcomes):.1f} s")
    for o in outcomes:
        if o.check.errata and o.check.note:
            print(f"  errata {o.check.key}: {o.check.note}")


def laws(args) -> int:
    """`camdyn laws`: the App. 2 characteristics of every cam law, derived symbolically; with
    --tau, the selection criteria of sec. 9.2.2 (thesis/selection.py)."""
    from . import lawtable

    stray = _stray_laws_option(args)
    if stray:
        return fail("camdyn laws", stray)
    if getattr(args, "sweep", None) is not None:
        return _sweep(args)
    if getattr(args, "tau", None) is not None or getattr(args, "fa", None) is not None:
        return _selection(args)

    try:
        rows = [lawtable.properties(k, args.theta if k == "modified-sine" else None)
                for k in lawtable.LAWS]
    except ValueError as exc:
        return fail("camdyn laws", name_argument(str(exc)))
    if args.json:
        print(json.dumps([r.as_dict() for r in rows], indent=1))
        return 0
    head = ("law", "H'max", "H''max", "H''min", "jerk T=0", "jerk T=1/2", "jerk T=1",
            "max H'H''", "at T", "C", "p")
    table = [head] + [(r.key, _num(r.H1_max), _num(r.H2_max), _num(r.H2_min), _num(r.jerk_0),
                       _num(r.jerk_half), _num(r.jerk_1), _num(r.torque_max), _num(r.T_torque_max),
                       _num(r.residual_coeff), str(r.residual_order)) for r in rows]
    _print_table(table)
    print("\nNominal characteristics, thesis App. 2 (jerk = H''', 'impulse' where H'' jumps); "
          "torque M = m h_m^2/(w_s t_m^3) H' H'' (A.2.7); one-DOF residual envelope "
          "U0 <= C tau^p for tau << 1 (ch. 3).")
    return 0


def _stray_laws_option(args) -> str | None:
    """An option of one mode of `camdyn laws` given in another would be dropped unread: the
    message naming it, or None."""
    given = lambda name: getattr(args, name, None) not in (None, False)   # noqa: E731
    sweep_only = ("law", "n", "values", "no_error_estimate")
    selection_only = ("tau", "fa", "stroke", "base_radius", "roller_radius")
    flag = lambda name: "--" + name.replace("_", "-")                       # noqa: E731
    if given("sweep"):
        bad = [n for n in selection_only + ("theta",) if given(n)]
        if bad:
            return f"argument {flag(bad[0])}: not with --sweep (it sweeps the law's parameter)"
        if given("n") and given("values"):
            return "argument --n: not with --values (the grid is either N points or the values)"
        return None
    bad = [n for n in sweep_only if given(n)]
    if bad:
        return f"argument {flag(bad[0])}: only with --sweep SCENE"
    if not (given("tau") or given("fa")):
        bad = [n for n in ("stroke", "base_radius", "roller_radius", "out") if given(n)]
        if bad:
            return f"argument {flag(bad[0])}: only with --tau (the selection) or --sweep"
    return None


def _print_table(table) -> None:
    """Rows of strings, the first the head: the name left, the numbers right, a rule under
    the head."""
    widths = [max(len(row[i]) for row in table) for i in range(len(table[0]))]
    for k, row in enumerate(table):
        print("  ".join(c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(row, widths))))
        if k == 0:
            print("  ".join("-" * w for w in widths))


def _num(v) -> str:
    if v is None:
        return "impulse"
    return {float("inf"): "inf", float("-inf"): "-inf"}.get(v, f"{v:.4g}")


def _sweep(args) -> int:
    """`camdyn laws --sweep SCENE`: a law's shape parameter over a grid on a DYNACAM scene,
    U0'' and the largest fictitious angular-velocity variation against it (fig. 8.8)."""
    from pathlib import Path

    from camdyn.runtime import laws as _laws
    from camdyn.runtime import scene as scenes
    from camdyn.runtime.errors import CamdynInputError, SimulationError

    from . import shape_sweep

    prog = "camdyn laws"
    law = args.law or "modified-sine"
    try:
        sc = scenes.load(args.sweep)
        out_folder(args.out)
        values = None
        if args.values:
            try:
                values = [float(v) for v in args.values.split(",")]
            except ValueError:
                raise CamdynInputError(f"argument --values: {args.values!r} is not a comma-"
                                       "separated list of numbers") from None
            shape_sweep.shape_parameter(law)     # --law first: has it a parameter at all
            for v in values:                     # named --values, not --theta
                try:
                    _laws.choose(law, v)
                except CamdynInputError as exc:
                    raise CamdynInputError(f"argument --values: {exc}") from None
        rows = shape_sweep.sweep(sc, law, values, 9 if args.n is None else args.n, errors=not args.no_error_estimate,
                                 progress=None if args.json else sys.stderr)
    except (CamdynInputError, ValueError) as exc:
        return fail(prog, name_argument(str(exc)))
    except SimulationError as exc:               # a failed run: status 1, as every command
        return run_failed(prog, f"a run of the sweep: {exc}")
    name = shape_sweep.shape_parameter(law)["name"]
    files = []
    if args.out:
        out = Path(args.out)
        own = sc.theta if sc.law == law else None
        files = [str(shape_sweep.write_csv(rows, out / "laws_sweep.csv")),
                 str(shape_sweep.write_png(rows, name, f"{sc.title}: {law}, {name} swept",
                                           out / "laws_sweep.png", own))]
    if args.json:
        print(json.dumps({"scene": sc.title, "law": law, "parameter": name, "rows": rows,
                          "files": files}, indent=1))
        return 0
    head = (name, "U0''", "+-", "max speed var", "+-", "U0", "+-")
    table = [head] + [(f"{r[name]:.4g}",) + tuple(
        _num(r.get(k)) if r.get(k) is not None else "-"
        for f in shape_sweep.FIELDS for k in (f, f"{f}_error")) for r in rows]
    _print_table(table)
    b = shape_sweep.best(rows, "U0dd")
    v = shape_sweep.best(rows, "speed_variation_max")
    note = (" (thesis fig. 8.8, the spring-loaded mechanism: both near theta = 0.1)"
            if law == "modified-sine" else "")
    print(f"\n{sc.title}, {law}: least U0'' at {name} = {b[name]:.4g}, least speed variation "
          f"at {name} = {v[name]:.4g}{note}")
    for f in files:
        print(f"wrote {f}")
    return 0


def _selection(args) -> int:
    """`camdyn laws --tau T --fa F`: the criteria of sec. 9.2.2 for every law, table and chart."""
    import csv
    import math
    from pathlib import Path

    from camdyn.runtime.errors import CamdynInputError

    from . import selection

    prog = "camdyn laws"
    say = (lambda msg: print(f"{prog}: {msg}", file=sys.stderr, flush=True))
    try:
        if args.tau is None:
            raise CamdynInputError("argument --tau: required with --fa (0 < tau < 0.99)")
        out_folder(args.out)
        geo_args = (args.stroke, args.base_radius, args.roller_radius)
        if any(g is not None for g in geo_args) and not all(g is not None for g in geo_args):
            raise CamdynInputError("arguments --stroke, --base-radius, --roller-radius: give all "
                                   "three for the cam's curvature and pressure angle")
        geometry = None if args.stroke is None else {
            "stroke": args.stroke, "base_radius": args.base_radius,
            "roller_radius": args.roller_radius}
        rows = selection.table(args.tau, 0.0 if args.fa is None else args.fa, args.theta,
                               geometry, say)
    except (CamdynInputError, ValueError) as exc:
        return fail(prog, name_argument(str(exc)))
    cols = [(k, t) for k, t in selection.COLUMNS if any(r.get(k) is not None for r in rows)]
    files = []
    if args.out:
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        with open(out / "laws_selection.csv", "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["law"] + [k for k, _ in cols])
            for r in rows:
                w.writerow([r["law"]] + [r.get(k) for k, _ in cols])
        files = [str(out / "laws_selection.csv"),
                 selection.chart(rows, out / "laws_selection.png")]
    if args.json:
        clean = [{k: (None if isinstance(v, float) and math.isinf(v) else v) for k, v in r.items()}
                 for r in rows]
        print(json.dumps({"rows": clean, "files": files}, indent=1))
        return 0
    head = ("law",) + tuple(t for _, t in cols)
    table = [head] + [(r["law"],) + tuple(_num(r.get(k)) if r.get(k) is not None else "-"
                                          for k, _ in cols) for r in rows]
    _print_table(table)
    print(f"\nSelection criteria of thesis sec. 9.2.2 at tau = {args.tau:g}, Fa = "
          f"{0.0 if args.fa is None else args.fa:g}: envelopes through the maxima of CAMSHAFT-1's "
          "U0 and U0'' around tau; impact = r_e/S^(2/3) after backlash (3.15)-(3.16), inf where "
          "H'' jumps; lower is better in every column.")
    for f in files:
        print(f"wrote {f}")
    return 0


def figures(args) -> int:
    """`camdyn figures`: every figure the models determine, drawn into --out with index.html
    beside them (thesis/figures/, issue 14 item 7)."""
    import time

    from camdyn.runtime.errors import CamdynInputError

    from . import figures as figs
    from .figures import index

    prog = "camdyn figures"
    try:
        only = ([s.strip() for s in args.only.split(",") if s.strip()]
                if args.only is not None else None)
        todo = figs.select(figs.registry(), only)
        out = out_folder(args.out)
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    t0 = time.perf_counter()
    by_key = figs.checks_by_key(todo)
    built = []
    from tqdm import tqdm

    with tqdm(todo, file=sys.stderr, unit="fig", desc="figures", disable=args.quiet) as bar:
        for fig in bar:
            bar.set_postfix_str(fig.id)
            built.append(figs.build_one(fig, out, args.quick, by_key))
    seconds = time.perf_counter() - t0
    page = index.write(built, out, seconds, args.quick)
    for b in built:
        agree = (f"{sum(c.passed for c in b.claims)}/{len(b.claims)} statements agree"
                 if b.claims else "")
        status = ("not reproduced" + (f"; {agree}" if agree else "") if b.figure.build is None
                  else "FAILED: " + b.error if b.error else agree or "drawn")
        print(f"{b.figure.id:<12} {b.seconds:6.1f} s  {status}")
    bad = [b for b in built if not b.passed]
    claims = [c for b in built for c in b.claims]
    print(f"\n{sum(bool(b.pngs) for b in built)} figures drawn, "
          f"{sum(b.figure.build is None for b in built)} listed as not reproducible; "
          f"{len(claims)} printed statements computed, {sum(c.passed for c in claims)} agree; "
          f"{seconds:.0f} s")
    print(f"index: {page}")
    return 1 if bad else 0
def design(args) -> int:
    """`camdyn design`: the thesis's design method (secs 8.3, 8.5, App. 7) for what the designer
    gives (thesis/design.py)."""
    import math

    from camdyn.runtime.errors import CamdynInputError, SimulationError

    from . import design as ds

    prog = "camdyn design"
    say = (lambda msg: print(f"{prog}: {msg}", file=sys.stderr, flush=True))
    try:
        out_folder(args.out)
        motor_args = None
        motor_given = [args.motor_rpm, args.motor_tm, args.slip_limit]
        motor_only = {"--motor-tel": args.motor_tel, "--rated-slip": args.rated_slip,
                      "--gear-efficiency": args.gear_efficiency, "--worm": args.worm,
                      "--spring": args.spring or None}
        stray = [k for k, v in motor_only.items() if v is not None]
        if stray and all(v is None for v in motor_given):
            # they enter (8.1)-(8.3) only: without a motor they would be dropped unread
            raise CamdynInputError(f"argument {stray[0]}: applies to the motor (sec. 8.3) only; "
                                   "give --motor-rpm or --motor-tm and --slip-limit")
        if args.rated_slip is None:
            args.rated_slip = 0.085        # delta_n of the motors of fig. A.5.3
        if any(v is not None for v in motor_given):
            if args.slip_limit is None:
                raise CamdynInputError("argument --slip-limit: required with a motor (delta_lim, "
                                       "the largest slip allowed, 0 < delta_lim < 1; (8.1))")
            if (args.motor_rpm is None) == (args.motor_tm is None):
                raise CamdynInputError("arguments --motor-rpm, --motor-tm: give one (the motor's "
                                       "mechanical time constant T_m, fig. A.5.3, (A.5.11))")
            if args.motor_rpm is not None:
                if args.motor_rpm not in ds.MOTOR_T_M:
                    raise CamdynInputError(f"argument --motor-rpm: {args.motor_rpm:g} is not one of "
                                           f"{', '.join(str(k) for k in ds.MOTOR_T_M)} (fig. A.5.3)")
                T_m = ds.MOTOR_T_M[int(args.motor_rpm)]
            else:
                T_m = ds._positive("T_m", "--motor-tm", args.motor_tm, "s, motor's mechanical "
                                   "time constant (A.5.11)")
            for flag, v in (("--slip-limit", args.slip_limit), ("--rated-slip", args.rated_slip)):
                if not (math.isfinite(v) and 0 < v < 1):
                    raise CamdynInputError(f"argument {flag}: {v:g} is out of range: 0 < slip < 1")
            if args.worm is not None and args.gear_efficiency is not None:
                raise CamdynInputError("argument --worm: not allowed with --gear-efficiency; give one")
            eta = 1.0
            if args.gear_efficiency is not None:
                eta = args.gear_efficiency
                if not 0 < eta <= 1:
                    raise CamdynInputError(f"argument --gear-efficiency: eta_g={eta:g} is out of "
                                           "range: 0 < eta_g <= 1")
            if args.worm is not None:
                alpha, mu = args.worm
                if not (0 < alpha < math.pi / 2 and 0 <= mu and alpha + mu < math.pi / 2):
                    raise CamdynInputError(f"argument --worm: alpha={alpha:g}, mu={mu:g} rad out of "
                                           "range: 0 < alpha, 0 <= mu, alpha + mu < pi/2")
                from .motor_theory import worm_gear_efficiency

                eta = worm_gear_efficiency(alpha, mu)       # motor driving (6.72), (A.5.34)
            tel = ds._positive("T_el", "--motor-tel", args.motor_tel, "s, electrical time "
                               "constant (A.5.3)")
            motor_args = {"T_m": T_m, "delta_n": args.rated_slip, "delta_lim": args.slip_limit,
                          "eta_g": eta, "spring": args.spring, "T_el": tel}
        result = ds.design(
            stroke=args.stroke, rise_time=args.rise_time, cam_angle_rad=ds.cam_angle(args.cam_angle),
            speed=args.speed, mass=args.mass, stiffness=args.stiffness, tau=args.tau, Fa=args.fa,
            c_tan=args.c_tan, pitch_radius=args.pitch_radius, ratio=args.ratio,
            tan_alpha_me=args.tan_alpha_me, accuracy=args.accuracy,
            residual_acceleration=args.residual_acceleration, law=args.law, theta=args.theta,
            common_shaft=args.common_shaft, motor_args=motor_args, check=not args.no_check,
            progress=None if args.json or args.quiet else say,
            chart_path=None if args.out is None else Path(args.out) / "design.png")
        if args.out is not None:
            (Path(args.out) / "design.json").write_text(json.dumps(result, indent=1, default=float))
    except (CamdynInputError, ValueError) as exc:
        return fail(prog, name_argument(str(exc)))
    except SimulationError as exc:
        return run_failed(prog, f"a graph run: {exc}")
    if args.json:
        print(json.dumps(result, indent=1, default=float))
    else:
        print(ds.text(result))
    return 0
