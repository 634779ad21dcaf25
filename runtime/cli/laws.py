"""camdyn laws: the cam laws' characteristics (thesis App. 2), their selection by the criteria
of sec. 9.2.2 (--tau) and a law's shape parameter swept on a scene (--sweep, fig. 8.8); the
library is camdyn.thesis.design (selection, shape_sweep)."""
from __future__ import annotations

import json
import sys

from ..core.errors import SimulationError
from .common import add_out_option, fail, law_names, run_failed
from .residual import name_argument

HELP = "cam-law characteristics (thesis App. 2), derived symbolically"
"""The command's line in `camdyn --help`."""

PROG = "camdyn laws"


def add(sub):
    lw = sub.add_parser("laws", help=HELP)
    lw.add_argument("--theta", type=float, default=None,
                    help="modified sine's theta, 0 < theta < 0.5 (default 0.1; not with --sweep)")
    lw.add_argument("--json", action="store_true", help="one JSON array on stdout")
    lw.add_argument("--tau", type=float, default=None,
                    help="0 < tau < 0.99: the selection criteria of sec. 9.2.2 at this tau (envelope "
                         "U0 and U0'' of CAMSHAFT-1, impact sensitivity, peaks)")
    lw.add_argument("--fa", type=float, default=None,
                    help="Fa of the selection, 0 <= Fa <= 100 (default 0)")
    lw.add_argument("--stroke", type=float, default=None, metavar="M",
                    help="with --tau, --base-radius and --roller-radius: stroke in m, 0 <= h < 1000; "
                         "adds the cam's least radius of curvature and largest pressure angle, "
                         "at the cam's --angles")
    lw.add_argument("--base-radius", type=float, default=None, metavar="M",
                    help="with --stroke: base circle radius in m, 1e-6 <= r_b < 1000")
    lw.add_argument("--roller-radius", type=float, default=None, metavar="M",
                    help="with --stroke: roller radius in m, 1e-6 <= r_r < 1000")
    lw.add_argument("--angles", default=None, metavar="R,D,F,D",
                    help="with --stroke: the cam's rise, outer dwell, return and inner dwell in "
                         "deg, summing to 360, as camdyn profile takes them (default "
                         "90,90,90,90): the pressure angle and curvature are the real cam's")
    add_out_option(lw, default=None, help="folder for laws_selection.png/.csv "
                                          "(laws_sweep.png/.csv with --sweep)")
    lw.add_argument("--sweep", default=None, metavar="SCENE",
                    help="a DYNACAM scene (camdyn scenes): run it over a grid of the shape "
                         "parameter of --law and chart U0'' and the largest fictitious angular-"
                         "velocity variation against it (thesis fig. 8.8)")
    lw.add_argument("--law", default=None, choices=law_names(),
                    help="with --sweep: the law whose parameter is swept (default modified-sine)")
    lw.add_argument("--rise", default=None, metavar="FILE",
                    help="the characteristic values of a rise you shaped (a blend or B-spline "
                         ".toml, a table .csv/.txt/.dat, as --law of residual takes it)")
    lw.add_argument("--n", type=int, default=None, help="with --sweep: grid points, 2 to 200 (default 9)")
    lw.add_argument("--values", default=None, metavar="V1,V2,...",
                    help="with --sweep: these parameter values instead of the grid")
    lw.add_argument("--no-error-estimate", action="store_true",
                    help="with --sweep or --tau: skip the second run per point at rtol/10 "
                         "that estimates each figure's error (for speed)")
    return lw


def run(args) -> int:
    from camdyn.thesis.design import selection, shape_sweep

    stray = _stray_option(args)
    if stray:
        return fail(PROG, stray)
    if args.rise is not None:
        return _rise(args)
    sweep, chosen = args.sweep is not None, args.tau is not None or args.fa is not None
    try:
        if sweep:
            result = shape_sweep.sweep_scene(args.sweep, args.law, args.values, args.n,
                                             errors=not args.no_error_estimate, out=args.out,
                                             progress=None if args.json else sys.stderr)
        elif chosen:
            result = selection.select(args.tau, args.fa, args.theta, args.stroke,
                                      args.base_radius, args.roller_radius, out=args.out,
                                      angles=args.angles,
                                      progress=lambda msg: print(f"{PROG}: {msg}", file=sys.stderr,
                                                                 flush=True),
                                      estimate=not args.no_error_estimate)
        else:
            result = selection.characteristics(args.theta)
    except ValueError as exc:
        return fail(PROG, name_argument(str(exc)))
    except SimulationError as exc:
        return run_failed(PROG, f"a run of the {'sweep' if sweep else 'selection'}: {exc}")
    if args.json:
        data = [r.as_dict() for r in result] if not (sweep or chosen) else result.as_dict()
        print(json.dumps(data, indent=1))
    elif sweep:
        _print_sweep(result)
    elif chosen:
        _print_selection(result)
    else:
        _print_characteristics(result)
    return 0


def _print_characteristics(rows) -> None:
    head = ("law", "H'max", "H''max", "H''min", "jerk T=0", "jerk T=1/2", "jerk T=1",
            "max H'H''", "at T", "C", "p")
    table = [head] + [(r.key, _num(r.H1_max), _num(r.H2_max), _num(r.H2_min), _num(r.jerk_0),
                       _num(r.jerk_half), _num(r.jerk_1), _num(r.torque_max), _num(r.T_torque_max),
                       _num(r.residual_coeff), str(r.residual_order)) for r in rows]
    _print_table(table)
    print("\nNominal characteristics, thesis App. 2 (jerk = H''', 'impulse' where H'' jumps); "
          "torque M = m h_m^2/(w_s t_m^3) H' H'' (A.2.7); one-DOF residual envelope "
          "U0 <= C tau^p for tau << 1 (ch. 3). VDI 2143's characteristic values: C_v = H'max, "
          "C_a = H''max, C_j the largest jerk, C_Mdyn = max H'H''.")


def _rise(args) -> int:
    """camdyn laws --rise FILE: VDI 2143's characteristic values of a shaped rise, each with
    its error and where it is reached."""
    from ..core import shaped
    from ..core.errors import CamdynInputError

    try:
        if not shaped.is_law_file(args.rise):
            raise CamdynInputError(f"--rise {args.rise!r}: a blend or B-spline (.toml) or a "
                                   f"table (.csv, .txt, .dat)")
        rise = shaped.load(args.rise)
        values = rise.characteristics()
    except CamdynInputError as exc:
        return fail(PROG, str(exc))
    warnings = rise.warnings()
    for w in warnings:
        print(f"{PROG}: warning: {w}", file=sys.stderr)
    if args.json:
        print(json.dumps({"rise": rise.name, "segment_ends": rise.breakpoints()[1:],
                          "continuity": rise.continuity, **values, "warnings": warnings},
                         indent=1))
        return 0
    names = {"C_v": "C_v = H'max", "C_a": "C_a = |H''|max", "C_j": "C_j = |H'''|max",
             "C_Mdyn": "C_Mdyn = max H'H''"}
    table = [("characteristic", "value", "+-", "at T")]
    for key, v in values.items():
        table.append((names[key], "impulse" if v["value"] is None else _num(v["value"]),
                      "" if v["error"] is None else f"{v['error']:.2g}",
                      "" if v["at_T"] is None else f"{v['at_T']:.4g}"))
    smooth = "H" + "'" * max(rise.continuity, 0)
    print(f"{rise.name}: segments end at T = "
          f"{', '.join(f'{b:g}' for b in rise.breakpoints()[1:])}; {smooth} continuous over "
          f"the cam motion, dwells included")
    _print_table(table)
    return 0


def _stray_option(args) -> str | None:
    """An option of one mode of `camdyn laws` given in another would be dropped unread: the
    message naming it, or None."""
    # given: anything but the default None (or a flag's False); a number 0 is given (0.0 ==
    # False, so `in (None, False)` took --tau 0 and --fa 0 for options not given)
    given = lambda name: getattr(args, name, None) is not None and \
        getattr(args, name) is not False                                    # noqa: E731
    sweep_only = ("law", "n", "values")
    selection_only = ("tau", "fa", "stroke", "base_radius", "roller_radius", "angles")
    flag = lambda name: "--" + name.replace("_", "-")                       # noqa: E731
    if given("rise"):
        bad = [n for n in ("sweep", *sweep_only, *selection_only, "theta", "out",
                           "no_error_estimate") if given(n)]
        return f"argument {flag(bad[0])}: not with --rise" if bad else None
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
    if given("no_error_estimate") and not (given("tau") or given("fa")):
        return ("argument --no-error-estimate: only with --sweep or --tau (App. 2's "
                "characteristics are closed forms, exact)")
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


def _cell(row: dict, key: str) -> str:
    """A selection cell: the value, "± e" beside it where it has an estimate."""
    from ..measure.contract import note

    v = row.get(key)
    if v is None:
        return "-"
    return _num(v) + note(row, key)


def _print_sweep(s) -> None:
    """U0'' and the largest fictitious angular-velocity variation against the law's shape
    parameter (fig. 8.8), each with its error estimate."""
    name = s.parameter
    head = (name, "U0''", "+-", "max speed var", "+-", "U0", "+-")
    table = [head] + [(f"{r[name]:.4g}",) + tuple(
        _num(r.get(k)) if r.get(k) is not None else "-"
        for f in s.figures for k in (f, f"{f}_error")) for r in s.rows]
    _print_table(table)
    b, v = s.best("U0dd"), s.best("speed_variation_max")
    note = (" (thesis fig. 8.8, the spring-loaded mechanism: both near theta = 0.1)"
            if s.law == "modified-sine" else "")
    print(f"\n{s.scene}, {s.law}: least U0'' at {name} = {b[name]:.4g}, least speed variation "
          f"at {name} = {v[name]:.4g}{note}")
    warned = s.warnings
    if warned:
        print(f"{PROG}: warning: {len(warned)} of {len(s.rows)} points warned (the warnings "
              f"column of laws_sweep.csv); the first: {warned[0]}", file=sys.stderr)
    for f in s.files:
        print(f"wrote {f}")


def _print_selection(s) -> None:
    """The criteria of sec. 9.2.2 for every law."""
    head = ("law",) + tuple(t for _, t in s.columns)
    table = [head] + [(r["law"],) + tuple(_cell(r, k) for k, _ in s.columns) for r in s.rows]
    _print_table(table)
    if s.angles_deg is not None:
        print(f"\nThe cam's curvature and pressure angle at rise, outer dwell, return, inner "
              f"dwell {', '.join(f'{a:g}' for a in s.angles_deg)} deg.", end="")
    print(f"\nSelection criteria of thesis sec. 9.2.2 at tau = {s.tau:g}, Fa = {s.Fa:g}: "
          "envelopes through the maxima of CAMSHAFT-1's U0 and U0'' around tau; impact = "
          "r_e/S^(2/3) after backlash (3.15)-(3.16), inf where H'' jumps; lower is better in "
          "every column. ± the error estimate of what runs (the runs one notch tighter, and the "
          "envelope's sampling) or a sampled profile give; the other columns are App. 2's "
          "closed forms.")
    for w in s.warnings:
        print(f"{PROG}: warning: {w}", file=sys.stderr)
    for f in s.files:
        print(f"wrote {f}")
