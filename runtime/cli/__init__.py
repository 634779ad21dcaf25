"""The ``camdyn`` command line: one module per command, each with add(sub) (its arguments) and
run(args) (parse, call the library, print).  Nothing imports the command line.

    camdyn derive [--check] [--out DIR]     regenerate generated/ (or check it)
    camdyn residual --model M --tau T ...   residual vibration of one rise
    camdyn check [--json]                   every comparison with the thesis
    camdyn laws [--json]                    cam-law characteristics (App. 2)
    camdyn run [SCENE] [--out DIR]          any scene (default: the CAMSHAFT-1 study): report
    camdyn scenes [--json]                  the built-in scenes, their kinds and titles
    camdyn integrate MODEL --t-end T ...    any model: a model file (built on demand) or built-in
    camdyn simulate SCENE.toml [--json]     a DYNACAM scene (thesis ch. 6, 7): summary and diagrams
    camdyn beam-follower [--omega W] ...    the Rayleigh-beam follower of the paper
    camdyn precision SCENE_OR_MODEL ...     work-precision chart: every method, SciPy's beside
    camdyn stability MODEL --param P=A:B:N  stability map: step/rtol x parameter, per method
    camdyn profile --law L --stroke H ...   the cam itself: pitch curve, profile(s), CSV/DXF/PNG
    camdyn figures [--out DIR] [--only IDS]  every thesis/paper figure the models determine + index
    camdyn design --stroke H ...            design by the thesis's rules (secs 8.3, 8.5, App. 7)
    camdyn serve [--port N] [--no-browser]  the live design page in the browser

Bad arguments end in one line on stderr naming the argument, and status 2.  Every command
that writes files takes --out and --overwrite and writes through runtime/core/outdir.py (it
never replaces a file camdyn did not write there); Ctrl-C and SIGTERM end any command in one
line saying what it kept, with status 130 and 143 (README "Where commands write").
"""
from __future__ import annotations

import importlib
import os
import sys
from pathlib import Path

from ..core import outdir, signals
from ..core.errors import CamdynInputError
from .common import Parser, fail, run_failed

COMMANDS = ("derive", "residual", "check", "laws", "design", "run", "scenes", "integrate", "simulate",
            "beam_follower", "stability", "precision", "profile", "figures", "sweep", "polydyne",
            "serve")
"""The command modules, in the order of `camdyn --help`."""


def build_parser(only: str | None = None) -> Parser:
    """The parser of every command, or with ``only`` (a command's name, or "" for none) that
    command's in full and the others' names and lines of help, which is all `camdyn --help`
    and a mistyped command show: a command's arguments load what their choices and defaults
    come from (the cam laws, the methods, the beam's case, so NumPy and compiled modules),
    which a command that does not need them should not wait for."""
    top = Parser(prog="camdyn", description="Cam-mechanism dynamics: derive, generate, simulate, check.")
    sub = top.add_subparsers(dest="command", required=True, parser_class=Parser)
    for name in COMMANDS:
        module = importlib.import_module(f"{__name__}.{name}")
        command = name.replace("_", "-")
        if only is None or only == command:
            module.add(sub).set_defaults(func=module.run)
        else:
            sub.add_parser(command, help=module.HELP)
    return top


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    # the command is the first word that is no option (camdyn itself takes only --help)
    args = build_parser(only=next((a for a in argv if not a.startswith("-")), "")).parse_args(argv)
    prog = f"camdyn {args.command}" if getattr(args, "command", None) else "camdyn"
    out = getattr(args, "out", None)
    # every --out names a folder: a file in its place is refused here, in one line, rather
    # than by a FileExistsError deep inside a command after its runs
    if out is not None and Path(out).exists() and not Path(out).is_dir():
        return fail(prog, f"argument --out: {out} is a file; --out names a folder")
    with signals.handled(), outdir.session(getattr(args, "overwrite", False)) as written:
        try:
            rc = args.func(args)
            sys.stdout.flush()           # here, so that a closed pipe is caught below
            return rc
        except BrokenPipeError:
            # the reader of stdout left (`camdyn ... | head`): stop quietly, not with a
            # traceback, and keep the interpreter's final flush from raising it again
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            return 1
        except KeyboardInterrupt as exc:
            # Ctrl-C or SIGTERM, wherever the command was: one line with what it kept (every
            # file it wrote is whole, runtime/core/signals.py), the shell's status for it
            print(f"{prog}: interrupted; {written.kept()}", file=sys.stderr)
            return exc.status if isinstance(exc, signals.Interrupted) else 130
        except CamdynInputError as exc:
            # an --out refused while a command writes, past its own handling of bad input
            return fail(prog, str(exc))
        except OSError as exc:
            # a file a library wrote on its own, or one camdyn read, failed: named, one line
            where = f": {exc.filename}" if exc.filename else ""
            return run_failed(prog, f"{exc.strerror or exc}{where}"
                                    + (f" (--out {out})" if out else ""))
