"""camdyn design: design by the thesis's rules (secs 8.3, 8.5, App. 7) from SI inputs; the
library is camdyn.thesis.design."""
from __future__ import annotations

import json
import sys

from ..core.errors import SimulationError
from ..core.outdir import out_folder
from .common import LAW_HELP, add_out_option, fail, law_argument, run_failed
from .residual import name_argument

HELP = ("design by the thesis's rules: tau, Fa, the envelope, the largest Fa and smallest t_m "
        "meeting a requirement, sec. 8.5's rules, the motor (sec. 8.3), a check run, the "
        "follower spring and the flywheel")
"""The command's line in `camdyn --help`."""

PROG = "camdyn design"


def add(sub):
    ds = sub.add_parser("design", help=HELP)
    a = ds.add_argument
    a("--stroke", type=float, default=None, metavar="M",
      help="h_m', stroke of the output member (m); for a rocker, --swing and --arm-length instead")
    a("--swing", type=float, default=None, metavar="DEG",
      help="a rocker's swing Phi (deg): the design is made at its roller centre's arc, the "
           "stroke l Phi, as sec. 2.4 reduces a linkage (with --arm-length)")
    a("--arm-length", type=float, default=None, metavar="M",
      help="a rocker's arm l, pivot to roller centre (m)")
    a("--arm-inertia", type=float, default=None, metavar="KG_M2",
      help="a rocker's inertia about its pivot (kg m^2): the mass J/l^2 at the roller (2.56)")
    a("--arm-stiffness", type=float, default=None, metavar="NM_RAD",
      help="a rocker's torsional stiffness at its pivot (N m/rad): c_c = k_t/l^2 at the roller (2.57)")
    a("--rise-time", type=float, default=None, metavar="S", help="t_m, cam rise time (s)")
    a("--cam-angle", default=None, metavar="RAD",
      help="beta_m, cam angle of the rise: rad, or degrees as '100deg' (with --speed); the "
           "follower spring and the flywheel are then sized over the rise alone")
    a("--angles", default=None, metavar="R,D,F,D",
      help="the whole turn: rise, outer dwell, return, inner dwell in deg, summing to 360, as "
           "camdyn profile takes them (the return the rise's law mirrored); the rise sets "
           "beta_m (with --speed; --cam-angle, if given too, must equal it) and the follower "
           "spring and the flywheel are sized over the whole turn")
    a("--speed", type=float, default=None, metavar="RPM", help="camshaft speed (r.p.m.)")
    a("--mass", type=float, default=None, metavar="KG", help="m, equivalent mass at the output (4.39)")
    a("--stiffness", type=float, default=None, metavar="N/M",
      help="c_c, stiffness of the uncoupled follower system at the output (4.3)")
    a("--tau", type=float, default=None,
      help="tau = T_e/t_m directly, 0 < tau < 0.9 (dimensionless; instead of m and c_c)")
    a("--fa", type=float, default=None,
      help="Fa directly, 0 <= Fa <= 12.8 (dimensionless; instead of --c-tan)")
    a("--c-tan", type=float, default=None, metavar="N/M",
      help="c_tan, tangential stiffness of the shaft at the output (4.4); Fa = (c_c/c_tan) tan^2 alpha_me")
    a("--pitch-radius", type=float, default=None, metavar="M", help="R_1/2 at the cam (4.1)")
    a("--ratio", type=float, default=None, metavar="I",
      help="transmission ratio i, h_m' = i h_m at the cam (default 1)")
    a("--tan-alpha-me", type=float, default=None,
      help="tan alpha_me, the mean slope (4.13) directly (dimensionless; instead of --pitch-radius)")
    a("--accuracy", type=float, default=None, metavar="M", help="largest positional error u0 (m)")
    a("--residual-acceleration", type=float, default=None, metavar="M/S2",
      help="largest residual acceleration u0'' after the rise (m/s^2)")
    a("--law", default="cycloidal", type=law_argument, metavar="LAW",
      help=f"cam law of the rise: {LAW_HELP} (default cycloidal)")
    a("--theta", type=float, default=None,
      help="the law's shape parameter, for laws that have one (default: the law's own)")
    a("--common-shaft", action="store_true", help="the shaft drives other mechanisms (Fa <= 0.3, sec. 8.5)")
    a("--motor-rpm", type=float, default=None, help="a thesis motor by synchronous speed: "
      "3000/1500/1000/750 (T_m of fig. A.5.3)")
    a("--motor-tm", type=float, default=None, metavar="S", help="the motor's mechanical time "
      "constant T_m = J_m/G (A.5.11)")
    a("--motor-tel", type=float, default=None, metavar="S",
      help="electrical time constant T_el (A.5.3): second-order slip (A.5.25) instead of (A.5.33)")
    a("--rated-slip", type=float, default=None, help="delta_n, the motor's rated slip, 0 < delta_n < 1 "
      "(default 0.085, fig. A.5.3)")
    a("--slip-limit", type=float, default=None,
      help="delta_lim, the largest slip allowed, 0 < delta_lim < 1 (8.1); required with a motor")
    a("--spring", action="store_true", help="a follower spring: v_v = 5 in (8.1) (with a motor)")
    a("--gear-efficiency", type=float, default=None,
      help="eta_g of the reduction gear, 0 < eta_g <= 1 (8.1) (with a motor; default 1)")
    a("--worm", type=float, nargs=2, default=None, metavar=("ALPHA", "MU"),
      help="worm gear lead angle and friction angle (rad): eta_g by (6.72)")
    a("--spring-margin", type=float, default=None, metavar="MU",
      help="size the follower spring: its force at least (1 + MU) times the inertia force "
           "pulling the follower off the cam (secs 4.5.5, 7.5), kinetostatically (as camdyn "
           "profile checks) and along the check run's model, over the rise or with --angles the "
           "whole turn, 0 <= MU <= 10; a rocker's also as a torque at its pivot")
    a("--spring-rate", type=float, default=None, metavar="N/M",
      help="the spring's rate k: the least preload for it (default: both ends of the family)")
    a("--spring-mass", type=float, default=None, metavar="KG",
      help="the spring's active coils' mass: its surge frequency (1/2)(k/m_s)^(1/2) and the "
           "vibration the rise leaves in it (needs --spring-rate)")
    a("--speed-fluctuation", type=float, default=None, metavar="CS",
      help="size the flywheel: the camshaft inertia J keeping (w_max - w_min)/w_s <= CS over "
           "the check run, and its Fv (5.14b), 0 < CS < 1")
    a("--no-check", action="store_true", help="skip the check run")
    a("--json", action="store_true", help="one JSON object on stdout")
    add_out_option(ds, default=None, help="folder for design.json and design.png (the envelope "
                                          "u0 over tau at the design's Fa, the largest Fa and "
                                          "Fa = 0, with the requirement)")
    a("--quiet", action="store_true", help="no progress lines")
    return ds


def _follower(args, machine) -> tuple:
    """(stroke, mass, stiffness) at the output: as given, or a rocker's at its roller."""
    rocker = (args.swing, args.arm_length, args.arm_inertia, args.arm_stiffness)
    if all(v is None for v in rocker):
        if args.stroke is None:
            raise ValueError("argument --stroke: the stroke of the output member is required "
                             "(m), or a rocker's --swing and --arm-length")
        return args.stroke, args.mass, args.stiffness
    return machine.rocker(swing_deg=args.swing, arm_length=args.arm_length, stroke=args.stroke,
                          inertia=args.arm_inertia, mass=args.mass,
                          torsional_stiffness=args.arm_stiffness, stiffness=args.stiffness)


def run(args) -> int:
    from camdyn.thesis.design import machine, method, motor_sizing

    say = (lambda msg: print(f"{PROG}: {msg}", file=sys.stderr, flush=True))
    try:
        stroke, mass, stiffness = _follower(args, machine)
        out_folder(args.out, files=method.FILES)       # the user's own: refused before the runs
        motor = motor_sizing.settings(
            motor_rpm=args.motor_rpm, motor_tm=args.motor_tm, slip_limit=args.slip_limit,
            rated_slip=args.rated_slip, motor_tel=args.motor_tel,
            gear_efficiency=args.gear_efficiency, worm=args.worm, spring=args.spring)
        result = method.design(
            stroke=stroke, rise_time=args.rise_time,
            cam_angle_rad=machine.cam_angle(args.cam_angle), speed=args.speed, mass=mass,
            stiffness=stiffness, tau=args.tau, Fa=args.fa, c_tan=args.c_tan,
            pitch_radius=args.pitch_radius, ratio=args.ratio, tan_alpha_me=args.tan_alpha_me,
            accuracy=args.accuracy, residual_acceleration=args.residual_acceleration,
            law=args.law, theta=args.theta, common_shaft=args.common_shaft, motor_args=motor,
            check=not args.no_check, progress=None if args.json or args.quiet else say,
            chart_path=None if args.out is None else method.chart_file(args.out),
            spring_margin=args.spring_margin, spring_rate=args.spring_rate,
            spring_mass=args.spring_mass, speed_fluctuation=args.speed_fluctuation,
            angles=args.angles, arm_length=args.arm_length)
        if args.out is not None:
            method.write(result, args.out)
    except ValueError as exc:
        return fail(PROG, name_argument(str(exc)))
    except SimulationError as exc:
        return run_failed(PROG, f"a graph run: {exc}")
    for w in result["warnings"]:
        print(f"{PROG}: warning: {w}", file=sys.stderr)
    if args.json:
        print(json.dumps(result, indent=1, default=float))
    else:
        print(method.text(result))
    return 0
