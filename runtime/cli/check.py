"""camdyn check: every comparison with the thesis (camdyn.thesis.checks), as a table."""
from __future__ import annotations

import json
import sys

from ..core.errors import CamdynInputError
from .common import add_estimate_option, fail, fmt

HELP = "every comparison with the thesis, as a table"
"""The command's line in `camdyn --help`."""


def add(sub):
    c = sub.add_parser("check", help=HELP)
    c.add_argument("--json", action="store_true", help="one JSON object on stdout")
    c.add_argument("-k", default=None, help="only checks whose key contains this text")
    c.add_argument("--topic", action="append", help="only this topic (repeatable)")
    c.add_argument("--quiet", action="store_true", help="no progress lines")
    c.add_argument("--list", action="store_true",
                   help="the keys of the checks selected (every one without -k and --topic), "
                        "one a line, without running them")
    add_estimate_option(c)
    return c


def run(args) -> int:
    from camdyn.thesis.checks import suite

    prog = "camdyn check"
    try:
        todo = suite.select(args.topic, args.k)
        if not todo:
            # nothing to run is no pass: a mistyped key would otherwise exit 0
            where = f" in --topic {', '.join(args.topic)}" if args.topic else ""
            what = (f"argument -k: no check's key contains {args.k!r}{where}" if args.k
                    else f"argument --topic: no checks{where}")
            raise CamdynInputError(f"{what}; camdyn check --list shows the keys")
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    except Exception as exc:         # a topic module that does not load: named, not a traceback
        return fail(prog, f"cannot load the checks: {exc}")
    if args.list:
        keys = [c.key for c in todo]
        print(json.dumps(keys, indent=1) if args.json else "\n".join(keys))
        return 0
    quiet = args.json or args.quiet
    outcomes = suite.run(todo, progress=None if quiet else (
        lambda i, n, c: print(f"  [{i}/{n}] {c.key}", file=sys.stderr, flush=True)),
        estimate=not args.no_error_estimate)
    passed = all(o.passed for o in outcomes)
    if args.json:
        print(json.dumps({"passed": passed, "checks": [o.as_dict() for o in outcomes]}, indent=1))
    else:
        _print_table(outcomes)
    return 0 if passed else 1


def _print_table(outcomes) -> None:
    rows = [("item", "reference", "printed", "derived", "rel. diff", "status")]
    for o in outcomes:
        c = o.check
        rel = "-" if o.rel_diff is None else f"{o.rel_diff:.2g}"
        derived = o.error if o.error else fmt(o.derived) + _estimate(o)
        rows.append((c.item, c.reference, c.printed or "(symbolic)", derived, rel, o.status))
    widths = [min(max(len(r[i]) for r in rows), 60) for i in range(len(rows[0]))]
    for k, r in enumerate(rows):
        print("  ".join(cell[:60].ljust(widths[i]) for i, cell in enumerate(r)).rstrip())
        if k == 0:
            print("  ".join("-" * w for w in widths))
    n_fail = sum(not o.passed for o in outcomes)
    wide = [o for o in outcomes if o.wide]
    n_err = sum(o.check.errata for o in outcomes)
    print(f"\n{len(outcomes)} checks: {len(outcomes) - n_fail} passed ({n_err} of them printed "
          f"values shown to be misprints), {n_fail} failed, "
          f"{sum(o.seconds for o in outcomes):.1f} s")
    if outcomes and outcomes[0].estimated:
        print("derived values: value ± the error estimate of the runs behind it (the value "
              "again with every run one notch tighter), or (exact)")
    for o in wide:
        print(f"  warning {o.check.key}: the estimate {o.estimate:.2g} exceeds the band the "
              f"rule accepts ({o.check.rule}): the runs do not resolve the agreement")
    from ..measure.contract import unavailable

    for o in outcomes:
        if o.estimate_why:
            print(f"  warning {o.check.key}: {unavailable(o.estimate_why)}")
    for o in outcomes:
        if o.check.errata and o.check.note:
            print(f"  errata {o.check.key}: {o.check.note}")


def _estimate(o) -> str:
    """" ± e", " (exact)", " (estimate unavailable)" (the reason in a warning below the table)
    beside a derived value, or "" when none was asked for."""
    from ..measure.contract import UNAVAILABLE

    if not o.estimated or o.check.rule == "identity":
        return ""
    if o.exact:
        return " (exact)"
    return f" ({UNAVAILABLE})" if o.estimate is None else f" ± {o.estimate:.2g}"
