"""camdyn scenes: the built-in scenes with their kinds and titles."""
from __future__ import annotations

import json

HELP = "the built-in scenes with their kinds and titles"
"""The command's line in `camdyn --help`."""


def add(sub):
    ls = sub.add_parser("scenes", help=HELP)
    ls.add_argument("--json", action="store_true", help="one JSON array on stdout")
    return ls


def run(args) -> int:
    from ..targets import scene_files
    from ..targets.resolve import KINDS

    rows = scene_files.builtins()
    if args.json:
        print(json.dumps([{"name": n, "kind": k, "title": t} for n, k, t in rows], indent=1))
        return 0
    w = max(len(n) for n, _, _ in rows)
    wk = max(len(k) for _, k, _ in rows)
    for name, kind, title in rows:
        print(f"{name:<{w}}  {kind:<{wk}}  {title}")
    print("\nrun one with `camdyn run NAME`; kinds: "
          + "; ".join(f"{k}: {what}" for k, what in KINDS.items()))
    return 0
