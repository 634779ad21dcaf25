"""What every command shares: one-line errors, warnings on stderr, small parsers and formats."""
from __future__ import annotations

import argparse
import sys

from ..core.errors import CamdynInputError


class Parser(argparse.ArgumentParser):
    """argparse, but errors are one line (no usage block) with status 2."""

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {message}\n")


def fail(prog: str, message: str) -> int:
    """Print a one-line error naming the command and return exit status 2."""
    print(f"{prog}: error: {message}", file=sys.stderr)
    return 2


# the implicit method the stiffness note names (runtime/core/methods.py RODAS4)
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


def assignments(items, flag: str) -> dict:
    """{NAME: number} of a repeatable NAME=VALUE option (--set, --initial, --state-atol); a
    NAME given twice is refused (a dict would keep the last without a word)."""
    out = {}
    for item in items or ():
        name, sep, value = item.partition("=")
        name = name.strip()
        if not sep or not name:
            raise CamdynInputError(f"argument {flag}: {item!r} is not NAME=VALUE")
        if name in out:
            raise CamdynInputError(f"argument {flag}: {name} is given twice; give each name "
                                   "once")
        try:
            out[name] = float(value)
        except ValueError:
            raise CamdynInputError(f"argument {flag}: {name}={value!r} is not a number") from None
    return out


def method_names() -> tuple[list, list]:
    """(every method, the adaptive ones) for the --method choices.  A compiled runtime older
    than its sources (a loop added, not yet rebuilt) must not stop `camdyn derive`, which
    regenerates what the rebuild then compiles: its names are then the known ones."""
    try:
        from ..core import methods
    except (ImportError, AttributeError):
        return (["dop853", "dp54", "koster", "radau5", "rk4", "rkn12", "rodas4"],
                ["dp54", "dop853", "rodas4", "radau5", "rkn12"])
    return sorted(methods.METHODS), list(methods.ADAPTIVE)


def law_names() -> list:
    from ..core import laws

    return laws.NAMES


LAW_HELP = ("a law of the library (camdyn laws) or a file: a table of angle and lift (.csv, "
            ".txt, .dat) or a blend or B-spline (.toml)")


def law_argument(text: str) -> str:
    """--law: a law's name or a shaped rise's file (checked when the run is set up)."""
    import argparse

    from ..core import laws, shaped

    if text in laws.NAMES or shaped.is_law_file(text):
        return text
    raise argparse.ArgumentTypeError(f"unknown cam law {text!r}; choose one of "
                                     f"{', '.join(laws.NAMES)}, or a file: a table of angle "
                                     f"and lift (.csv, .txt, .dat) or a blend or B-spline (.toml)")


def say_on_stderr(quiet: bool = False):
    """A progress callback: one line on stderr per message (nothing when quiet)."""
    if quiet:
        return lambda msg: None
    return lambda msg: print(msg, file=sys.stderr, flush=True)


def add_out_option(parser, **kwargs) -> None:
    """--out (``kwargs`` as add_argument's) and --overwrite: every command that writes files
    takes both, and writes them through runtime/core/outdir.py."""
    parser.add_argument("--out", **kwargs)
    parser.add_argument("--overwrite", action="store_true",
                        help="replace files in --out that camdyn did not write there, or that "
                             "were changed since it wrote them (refused otherwise, naming the "
                             "file; camdyn's own files are replaced anyway)")


def add_estimate_option(parser) -> None:
    parser.add_argument("--no-error-estimate", action="store_true",
                        help="skip the second, one notch tighter run that estimates each "
                             "figure's error (for speed; the figures then say so)")


ATOL_HELP = ("absolute tolerance of dp54/dop853/rodas4, > 0, in units of each state's tolerance "
             "scale: a coordinate's declared scale, its rate's that scale times the rate the "
             "mechanism is driven at (1 per unit of T for the thesis's models, the cam speed "
             "for models in seconds); default 1e-3 rtol (README \"Tolerances\")")
STATE_ATOL_HELP = ("absolute tolerance of one state, in its own units, > 0 (repeatable); a "
                   "large one takes the state out of the error control (its own history is then "
                   "not resolved)")


def add_tolerance_options(parser) -> None:
    """--atol and --state-atol: the absolute tolerances of an adaptive method (runtime/core/
    methods.py DP54), tightened with rtol for the error estimate's second run."""
    parser.add_argument("--atol", type=float, default=None, metavar="A", help=ATOL_HELP)
    parser.add_argument("--state-atol", action="append", default=None, metavar="NAME=VALUE",
                        help=STATE_ATOL_HELP)


def tolerances(args) -> dict:
    """{"atol": ..., "state_atol": {...}} from --atol and --state-atol, checked: finite and
    > 0; unknown state names are refused when the model is known, naming its states."""
    import math

    out = {}
    if args.atol is not None:
        if not (math.isfinite(args.atol) and args.atol > 0):
            raise CamdynInputError(f"argument --atol: {args.atol:g} is out of range: a finite "
                                   "atol > 0 (in units of each state's tolerance scale)")
        out["atol"] = args.atol
    pairs = assignments(args.state_atol, "--state-atol")
    for name, value in pairs.items():
        if not (math.isfinite(value) and value > 0):
            raise CamdynInputError(f"argument --state-atol: {name}={value:g} is out of range: a "
                                   "finite absolute tolerance > 0 in the state's units")
    if pairs:
        out["state_atol"] = pairs
    return out


DEPENDENT_HELP = ("a constrained model's dependent coordinates for this run, comma-separated, "
                  "exactly as many as it has constraints (default: the ones its "
                  "ConstraintSolver declares). Coordinate partitioning (Wehage and Haug 1982; "
                  "formulation 1) solves them from Phi = 0 and Phi_Q Q' = -Phi_t at every "
                  "evaluation and integrates the others; every formulation starts from the "
                  "consistent state they are solved for from the others' values. Phi_Q "
                  "restricted to them must stay invertible along the run")


def add_dependent_option(parser) -> None:
    """--dependent: a constrained model's dependent coordinates (Simulator's ``dependent``)."""
    parser.add_argument("--dependent", default=None, metavar="NAMES", help=DEPENDENT_HELP)


def tolerance_argument(message: str) -> str:
    """A library message about the tolerances (atol=..., state_atol...) with the flag it came
    from in front, as every other bad argument is named."""
    if message.startswith("atol="):
        return f"argument --atol: {message}"
    if message.startswith("state_atol"):
        return f"argument --state-atol: {message.removeprefix('state_atol: ')}"
    if message.startswith("dependent"):
        return f"argument --dependent: {message}"
    return message
