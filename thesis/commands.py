"""The thesis room's commands, `camdyn check` and `camdyn laws` (the entry point,
camdyn.runtime.cli, hands them over here).

They live beside what they run: the comparisons with the thesis (:mod:`camdyn.thesis.checks`)
and the App. 2 law table (:mod:`camdyn.thesis.lawtable`), both of which need SymPy, which the
runtime's own commands never load.
"""
from __future__ import annotations

import json
import sys

from camdyn.runtime.cli import fail, fmt, name_argument


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

    from camdyn.runtime import scene as scenes
    from camdyn.runtime.errors import CamdynInputError, SimulationError

    from . import shape_sweep

    prog = "camdyn laws"
    law = args.law or "modified-sine"
    try:
        sc = scenes.load(args.sweep)
        values = None
        if args.values:
            try:
                values = [float(v) for v in args.values.split(",")]
            except ValueError:
                raise CamdynInputError(f"argument --values: {args.values!r} is not a comma-"
                                       "separated list of numbers") from None
        rows = shape_sweep.sweep(sc, law, values, args.n, errors=not args.no_error_estimate,
                                 progress=None if args.json else sys.stderr)
    except (CamdynInputError, ValueError) as exc:
        return fail(prog, name_argument(str(exc)))
    except SimulationError as exc:
        return fail(prog, f"a run of the sweep failed: {exc}")
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
