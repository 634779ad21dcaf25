"""camdyn polydyne: the compensated cam of the one-DOF follower against the uncompensated one,
residual vibration over the speed (runtime/studies/polydyne.py)."""
from __future__ import annotations

import json

from ..core.errors import CamdynInputError, SimulationError
from .common import add_out_option, fail, run_failed

HELP = "compensated cam (polydyne) of the one-DOF follower against the uncompensated one"
"""The command's line in `camdyn --help`."""

PROG = "camdyn polydyne"


def add(sub):
    p = sub.add_parser(
        "polydyne", help=HELP,
        description="The polydyne rise H = P + (tau_d/2 pi)^2 P'' makes the one-DOF output "
                    "(thesis (3.1)) follow the degree-9 rise P exactly at the design tau tau_d. "
                    "This runs the residual vibration U0 after the rise over a range of tau for "
                    "the polydyne and for P itself as the cam law (5-6-7-8-9), each with its "
                    "error estimate, and charts them (polydyne.png, polydyne.json). Use "
                    "--law polydyne --theta TD (or camdyn residual --design-tau TD) wherever a "
                    "law is taken.")
    p.add_argument("--design-tau", type=float, required=True, metavar="TD",
                   help="the tau the cam is compensated for, 0 < TD < 1")
    p.add_argument("--taus", default=None, metavar="A:B:N",
                   help="the tau range, N values from A to B (default TD/2:2TD:121, within "
                        "0 < tau < 1)")
    p.add_argument("--q", type=float, default=0.0, help="relative damping q (6.47), default 0")
    p.add_argument("--no-error-estimate", action="store_true",
                   help="skip the second, one notch tighter sweep that estimates each figure's "
                        "error (half the time; the figures then carry no estimate)")
    add_out_option(p, default="out/polydyne", metavar="DIR",
                   help="folder for polydyne.png and polydyne.json (default out/polydyne)")
    p.add_argument("--json", action="store_true", help="one JSON object on stdout")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    return p


def _range(text, td):
    import numpy as np

    if text is None:
        lo, hi, n = td / 2, min(2 * td, 0.99), 121
    else:
        try:
            a, b, c = text.split(":")
            lo, hi, n = float(a), float(b), int(c)
        except ValueError:
            raise CamdynInputError(f"--taus must be A:B:N (two taus and a count), got "
                                   f"{text!r}") from None
        if not (0 < lo < hi < 1 and 2 <= n <= 10000):
            raise CamdynInputError(f"--taus={text}: needs 0 < A < B < 1 and 2 <= N <= 10000")
    return np.linspace(lo, hi, n)


def run(args) -> int:
    from ..core.outdir import out_folder, write_text
    from ..studies.polydyne import chart, compensation

    try:
        td = float(args.design_tau)
        if not 0 < td < 1:
            raise CamdynInputError(f"--design-tau={td:g} is out of range: 0 < TD < 1")
        taus = _range(args.taus, td)
        # --out checked whole before the runs: a file of the user's there is refused first
        folder = out_folder(args.out, files=["polydyne.png", "polydyne.json"])
        res = compensation(td, taus, args.q, progress=not args.quiet,
                           estimate=not args.no_error_estimate)
        out = res.as_dict()
        chart(res, folder / "polydyne.png")
        out["files"] = [str(folder / "polydyne.png"), str(folder / "polydyne.json")]
        write_text(folder / "polydyne.json", json.dumps(out, indent=1))
    except CamdynInputError as exc:
        return fail(PROG, str(exc))
    except SimulationError as exc:
        return run_failed(PROG, exc)
    if args.json:
        print(json.dumps(out))
        return 0
    import numpy as np
    i = int(np.argmin(np.abs(taus - td)))
    pm = lambda key: (f" ± {out[key][i]:.1e}" if out.get(key) and out[key][i] is not None
                      else " (no error estimate)")
    print(f"polydyne designed for tau = {td:g} (q = {args.q:g}), {taus.size} taus from "
          f"{taus[0]:g} to {taus[-1]:g}")
    print(f"at tau = {taus[i]:g}: U0 = {out['polydyne:U0'][i]:.3e}{pm('polydyne:U0_error')} "
          f"compensated, {out['plain:U0'][i]:.3e}{pm('plain:U0_error')} uncompensated")
    for w in out["warnings"]:
        print(f"warning: {w}")
    for f in out["files"]:
        print(f"wrote {f}")
    return 0
