"""camdyn beam-follower: the Rayleigh-beam follower of the paper, its tip response."""
from __future__ import annotations

import argparse
import json
import math
import time
from dataclasses import replace

from ..core.errors import CamdynInputError, SimulationError
from ..core.outdir import out_folder
from .common import (add_estimate_option, add_out_option, add_tolerance_options, fail,
                     report_health, run_failed, say_on_stderr, tolerance_argument, tolerances)

HELP = "the Rayleigh-beam follower of the paper: tip response"
"""The command's line in `camdyn --help`."""

FLAGS = {"omega": "--omega", "modes": "--modes", "rod_radius": "--rod-radius",
               "distance": "--distance", "base_radius": "--base-radius", "rise": "--rise",
               "revolutions": "--revolutions", "rayleigh": "--rayleigh",
               "roller_inertia": "--roller-inertia", "formulation": "--formulation",
               "method": "--method", "rtol": "--rtol", "mode_atol": "--mode-atol"}


def _beam_argument(message: str) -> str:
    """Prefix the flag a :func:`camdyn.runtime.targets.beam.check` message is about (``name=value ...``)."""
    head = message.split("=", 1)[0].split(" ", 1)[0]
    if head in FLAGS and not message.startswith("argument "):
        return f"argument {FLAGS[head]}: {message}"
    return message


def add(sub):
    # the defaults shown in the help are the case's own (beam_case loads no SciPy)
    from dataclasses import asdict

    from ..targets.beam_case import FORMULATIONS, MODE_ATOL, N_MAX, Case
    from ..core.methods import ADAPTIVE

    dflt = asdict(Case())
    disc = Case().J_r
    b = sub.add_parser(
        "beam-follower", help=HELP,
        description="Translating roller follower in the groove of a rigid disk cam (RDFD motion, "
                    "cycloidal rise and fall over 90 deg each), its rod a Rayleigh beam clamped in "
                    "the guide whose free length changes as the cam turns. Integrates whole cam "
                    "revolutions from the rigid follower's state at theta = 0 and reports the "
                    "largest tip deflection |v_E|, the largest constraint residual and the lowest "
                    "transverse natural frequency with the rod frozen at the outer dwell. SI "
                    "units; defaults are the paper's data (sec. 4). A cam profile whose groove "
                    "wall is undercut for this roller is reported with a warning (and in the JSON "
                    "as \"undercut\") but not refused: the model follows the pitch curve, so the "
                    "run shows the designed motion, which a cam cut for this roller could not "
                    "give. Progress lines go to stderr.")
    b.add_argument("--omega", type=float, metavar="RAD_S",
                   help=f"cam speed Omega, rad/s (default {dflt['omega']:g}; paper: 120, 240, 360)")
    b.add_argument("--modes", type=int, metavar="N",
                   help=f"assumed modes N, 1 to {N_MAX} (default {dflt['modes']})")
    b.add_argument("--rod-radius", type=float, metavar="M",
                   help=f"radius of the follower rod, m (default {dflt['rod_radius']:g})")
    b.add_argument("--distance", type=float, metavar="M",
                   help=f"cam centre to guide exit d, m (default {dflt['distance']:g})")
    b.add_argument("--base-radius", type=float, metavar="M",
                   help=f"base-circle radius r_b, m (default {dflt['base_radius']:g}); the "
                        f"roller must stay clear of the guide at the top of the stroke")
    b.add_argument("--rise", type=float, metavar="M",
                   help=f"total rise S_T, m (default {dflt['rise']:g})")
    b.add_argument("--revolutions", type=float, metavar="K",
                   help=f"cam revolutions to integrate, > 0 (default {dflt['revolutions']:g}, or as many as "
                        f"cover one period of the rod's slowest mode at a fast cam); a run too "
                        f"short for the rod to answer, or predicted to need more than "
                        f"2 million steps, is refused")
    b.add_argument("--rayleigh", action=argparse.BooleanOptionalAction,
                   help="keep the rotary inertia of the rod (default); --no-rayleigh gives the "
                        "Euler-Bernoulli rod")
    b.add_argument("--roller-inertia", type=float, metavar="KG_M2",
                   help=f"roller moment of inertia J_r, kg m^2, >= 0 (default: uniform disc "
                        f"m_r r_r^2/2 = {disc:g}); 0 ignores the roller's rotation")
    b.add_argument("--formulation", choices=tuple(FORMULATIONS),
                   help=f"augmented (multipliers, Baumgarte), partitioned (coordinate "
                        f"partitioning, paper (21)-(27)) or projection (multipliers, the "
                        f"state projected onto the constraints after every step); default "
                        f"{dflt['formulation']}")
    b.add_argument("--method", choices=ADAPTIVE, default="dop853",
                   help="integration method (default dop853, whose order 8 suits rtol 1e-9 and "
                        "the higher modes' stiffness); rodas4 or radau5, the stiff solvers, "
                        "suit stiff rods (large E)")
    b.add_argument("--rtol", type=float, metavar="RTOL",
                   help=f"relative tolerance of the method, 1e-14 <= rtol < 1 (default "
                        f"{dflt['rtol']:g}; the error estimate runs again at rtol/10)")
    add_tolerance_options(b)
    b.add_argument("--mode-atol", type=float, default=MODE_ATOL, metavar="F",
                   help=f"absolute tolerance of the mode amplitudes b_i as a fraction of the "
                        f"rod's deflection scale S_T Omega^2/w_1^2 (default {MODE_ATOL:g}: "
                        f"1.4e-9 m for the paper's data; their rates': times the highest frozen "
                        f"frequency w_N); not with --atol, and under --state-atol")
    b.add_argument("--json", action="store_true", help="one JSON object on stdout")
    add_estimate_option(b)
    add_out_option(b, default=None, metavar="DIR",
                   help="also write the paper's figs 4-9 (tip deflection against cam angle, one "
                        "parameter varied; 18 runs) as PNG into DIR")
    return b


def run(args) -> int:
    from ..measure.contract import answer
    from ..targets import beam
    from ..targets.beam_scene import BeamTarget

    prog = "camdyn beam-follower"
    say = say_on_stderr()
    given = {key: getattr(args, key) for key in FLAGS}
    try:
        tol = tolerances(args)
        case = beam.Case(**{k: v for k, v in given.items() if v is not None},
                         **{k: tuple(v.items()) if k == "state_atol" else v
                            for k, v in tol.items()})
        if args.revolutions is None:
            # the run's end left to camdyn: as many revolutions as one period of the rod's
            # slowest mode needs (the window rule of the answer contract)
            need = beam.least_revolutions(beam.check(case))
            if need > case.revolutions:
                case = replace(case, revolutions=float(math.ceil(need)))
        target = BeamTarget.of(beam.feasible(case))
        planned = target.figure_runs() if args.out else []     # refused before anything runs
        if args.out:                   # a picture of the user's is refused before the runs
            out_folder(args.out, files=target.figure_files())
        # the main run's line only without --json; the 18 figure runs report in any case
        a = answer(target, estimate=not args.no_error_estimate,
                   progress=None if args.json else say)
        out = a.as_dict()
        if args.out:
            done = iter(range(1, len(planned) + 1))

            def figure_progress(msg):
                k = next(done, None)
                if k is not None:
                    name, field, v = planned[k - 1]
                    say(f"  [{k}/{len(planned)}] {name}, {field} = {v:g}: {msg}")
                else:
                    say(f"  {msg}")

            c0 = time.process_time()
            out["figures"] = target.paper_figures(args.out, progress=figure_progress,
                                                  estimate=not args.no_error_estimate, known=a)
            out["figures_cpu_seconds"] = time.process_time() - c0
    except CamdynInputError as exc:
        return fail(prog, tolerance_argument(_beam_argument(str(exc))))
    except SimulationError as exc:
        return run_failed(prog, exc)
    report_health(prog, out, "t")
    if args.json:
        print(json.dumps(out, indent=1))
        return 0
    print("\n".join(target.table(out)))
    return 0
