"""camdyn figures: every thesis and paper figure the models determine, with an index page
(the library is camdyn.thesis.figures)."""
from __future__ import annotations

from ..core.errors import CamdynInputError
from .common import add_out_option, fail

HELP = "every thesis and paper figure the models determine, with an index page"
"""The command's line in `camdyn --help`."""

PROG = "camdyn figures"


def add(sub):
    f = sub.add_parser(
        "figures", help=HELP,
        description="Draw the thesis's figures (3.3 ... 8.6, A.5.7), the paper's figs 4-9 and "
                    "the design charts into --out, and write index.html showing each picture "
                    "beside its number, caption and the printed statements it reproduces, "
                    "computed now. Exit 1 if a figure fails or a statement is not reproduced.")
    add_out_option(f, default="out/figures", metavar="DIR",
                   help="folder for the PNG files and index.html (default out/figures)")
    f.add_argument("--only", default=None, metavar="IDS",
                   help="comma-separated figure ids (3.3,4.11a,paper 5; 4.11 = 4.11a-c; "
                        "thesis, paper or design = the whole group)")
    f.add_argument("--quick", action="store_true",
                   help="coarser tau grids for the response graphs (4.11, 5.7): a draft in "
                        "a fraction of the time")
    f.add_argument("--quiet", action="store_true", help="no progress bar")
    return f


def run(args) -> int:
    from camdyn.thesis.figures import build

    only = ([s.strip() for s in args.only.split(",") if s.strip()]
            if args.only is not None else None)
    try:
        drawing = build.make(only, args.out, args.quick, progress=not args.quiet)
    except CamdynInputError as exc:
        return fail(PROG, str(exc))
    for b in drawing.built:
        agree = (f"{sum(c.passed for c in b.claims)}/{len(b.claims)} statements agree"
                 if b.claims else "")
        status = ("not reproduced" + (f"; {agree}" if agree else "") if b.figure.build is None
                  else "FAILED: " + b.error if b.error else agree or "drawn")
        print(f"{b.figure.id:<12} {b.seconds:6.1f} s  {status}")
    claims = drawing.claims
    print(f"\n{sum(bool(b.pngs) for b in drawing.built)} figures drawn, "
          f"{sum(b.figure.build is None for b in drawing.built)} listed as not reproducible; "
          f"{len(claims)} printed statements computed, {sum(c.passed for c in claims)} agree; "
          f"{drawing.seconds:.0f} s")
    print(f"index: {drawing.index}")
    return 0 if drawing.passed else 1
