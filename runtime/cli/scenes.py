"""camdyn scenes: the built-in scenes with their kinds and titles; a commented template of a
scene kind to fill in (--template machine)."""
from __future__ import annotations

import json
import sys

from ..core.errors import CamdynInputError
from .common import add_out_option, fail

HELP = "the built-in scenes with their kinds and titles, or a template to fill in"
"""The command's line in `camdyn --help`."""

TEMPLATES = ("machine",)
"""The kinds a template is written of: a machine for `camdyn design MACHINE.toml`."""


def add(sub):
    ls = sub.add_parser("scenes", help=HELP)
    ls.add_argument("--json", action="store_true", help="one JSON array on stdout")
    ls.add_argument("--template", default=None, choices=TEMPLATES,
                    help="write a commented template of this kind to stdout, or with --out "
                         "into DIR/machine.toml: a machine for `camdyn design MACHINE.toml "
                         "--laws all`")
    add_out_option(ls, default=None, metavar="DIR",
                   help="with --template: the folder to write the template into")
    return ls


def run(args) -> int:
    if args.template is not None:
        # the machine's template is the thesis room's (camdyn.thesis.design.band.spec): the
        # command line's door into it is run() (tests/test_rooms.py)
        from camdyn.thesis.design.band import spec

        return _template(args, spec.TEMPLATE)
    if args.out is not None:
        return fail("camdyn scenes", "argument --out: goes with --template")
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
          + "; ".join(f"{k}: {what}" for k, what in KINDS.items())
          + "; a template to fill in: `camdyn scenes --template machine`")
    return 0


def _template(args, text: str) -> int:
    """The template ``text`` on stdout, or into --out as <kind>.toml, a file of the user's
    there refused (runtime/core/outdir.py)."""
    from ..core.outdir import out_folder, write_text

    prog = "camdyn scenes"
    if args.json:
        return fail(prog, "argument --json: a template is TOML; leave --json out")
    if args.out is None:
        sys.stdout.write(text)
        return 0
    name = f"{args.template}.toml"
    try:
        folder = out_folder(args.out, files=[name])
        path = write_text(folder / name, text)
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    print(f"wrote {path}")
    return 0
