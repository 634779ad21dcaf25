"""camdyn derive: regenerate generated/ from the model declarations (or check it)."""
from __future__ import annotations

import sys
from pathlib import Path

from .common import fail

HELP = "regenerate generated/ from the model declarations"
"""The command's line in `camdyn --help`."""


def add(sub):
    d = sub.add_parser("derive", help=HELP)
    d.add_argument("--check", action="store_true", help="exit 1 when generated/ is stale")
    d.add_argument("--out", help="target folder (default: generated/ of this checkout)")
    d.add_argument("--only", nargs="+", metavar="MODEL", help="only these registered models")
    d.add_argument("--full", action="store_true",
                   help="derive every file again, also those whose recorded derivation key is current")
    return d


def run(args) -> int:
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
