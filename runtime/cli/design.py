"""camdyn design: design by the thesis's rules (secs 8.3, 8.5, App. 7) from SI inputs at one
speed; or a machine over its band of speeds (a machine file, or --speed LO:HI with the
machine's options): every candidate law's worst residual vibration, spring, cam and drive, a
ranking and the recommended law.  The libraries are camdyn.thesis.design and
camdyn.thesis.design.band."""
from __future__ import annotations

import json
import sys
from types import SimpleNamespace

from ..core.errors import CamdynInputError, SimulationError
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
    a("machine", nargs="?", default=None, metavar="MACHINE.toml",
      help="a machine file (camdyn scenes --template machine): the band design of every "
           "candidate law over the machine's speed band; with it only --laws, --out, --json, "
           "--quiet and --step")
    a("--stroke", default=None, metavar="M",
      help="h_m', stroke of the output member (m, or with a unit: '25mm'); for a rocker, "
           "--swing and --arm-length instead")
    a("--swing", default=None, metavar="DEG",
      help="a rocker's swing Phi (deg): the design is made at its roller centre's arc, the "
           "stroke l Phi, as sec. 2.4 reduces a linkage (with --arm-length)")
    a("--arm-length", default=None, metavar="M",
      help="a rocker's arm l, pivot to roller centre (m)")
    a("--arm-inertia", default=None, metavar="KG_M2",
      help="a rocker's inertia about its pivot (kg m^2): the mass J/l^2 at the roller (2.56)")
    a("--arm-stiffness", default=None, metavar="NM_RAD",
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
    a("--speed", default=None, metavar="RPM",
      help="camshaft speed (r.p.m. unless a unit is given: '450rpm', '47rad/s', '7.5Hz' in "
           "revolutions per second); a band LO:HI ('300:600rpm') designs the machine over the "
           "band (the options below from --follower on)")
    a("--mass", default=None, metavar="KG", help="m, equivalent mass at the output (4.39)")
    a("--stiffness", default=None, metavar="N/M",
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
    a("--law", default=None, type=law_argument, metavar="LAW",
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
    a("--spring-margin", default=None, metavar="MU",
      help="size the follower spring: its force at least (1 + MU) times the inertia force "
           "pulling the follower off the cam (secs 4.5.5, 7.5), kinetostatically (as camdyn "
           "profile checks) and along the check run's model, over the rise or with --angles the "
           "whole turn, 0 <= MU <= 10; a rocker's also as a torque at its pivot")
    a("--spring-rate", default=None, metavar="N/M",
      help="the spring's rate k: the least preload for it (default: both ends of the family)")
    a("--spring-mass", type=float, default=None, metavar="KG",
      help="the spring's active coils' mass: its surge frequency (1/2)(k/m_s)^(1/2) and the "
           "vibration the rise leaves in it (needs --spring-rate)")
    a("--speed-fluctuation", default=None, metavar="CS",
      help="size the flywheel: the camshaft inertia J keeping (w_max - w_min)/w_s <= CS over "
           "the check run, and its Fv (5.14b), 0 < CS < 1")
    a("--no-check", action="store_true", help="skip the check run")
    a("--json", action="store_true", help="one JSON object on stdout")
    add_out_option(ds, default=None, help="folder for design.json and design.png (the envelope "
                                          "u0 over tau at the design's Fa, the largest Fa and "
                                          "Fa = 0, with the requirement); the band design's: "
                                          "design.json, report.md and report.html with its "
                                          "charts, the recommended design's machine.toml and "
                                          "cam.csv, cam.dxf (cam.step with --step)")
    a("--quiet", action="store_true", help="no progress lines")
    _band_options(ds)
    return ds


def _band_options(ds) -> None:
    """The band design's own options: the machine as a machine file gives it (each value a
    number in SI, an angle in degrees, or a string with its unit, '25mm')."""
    from camdyn.runtime.cam.names import KINDS

    g = ds.add_argument_group(
        "the machine over its speed band (with a machine file, or --speed LO:HI; a number is "
        "SI, an angle deg, a string carries its unit: '25mm', '2e6N/m', '1200MPa'; the exit "
        "status is 1 when no law passes every check, the answer and files written all the same)")
    a = g.add_argument
    a("--laws", default=None, metavar="all|LAW,...",
      help="the candidate laws: all (every law of camdyn laws, the polydyne designed at the "
           "band's centre tau) or a comma list of laws and law files (default all)")
    a("--follower", default=None, choices=KINDS,
      help="the follower (default translating-roller)")
    a("--base-radius", default=None, metavar="M", help="the cam's base circle r_b")
    a("--roller-radius", default=None, metavar="M", help="a roller's radius r_r")
    a("--roller-width", default=None, metavar="M",
      help="a roller's width, the contact's length for the Hertz stress")
    a("--offset", default=None, metavar="M", help="a translating follower's axis off the cam "
                                                  "centre (default 0)")
    a("--pivot-distance", default=None, metavar="M", help="a rocker's pivot from the cam centre")
    a("--face-offset", default=None, metavar="M",
      help="an oscillating flat face's line from the pivot (default 0)")
    a("--crown-radius", default=None, metavar="M", help="a crowned roller's crown radius")
    a("--cam-width", default=None, metavar="M",
      help="the cam plate's width: a flat face's contact length and the STEP solid's "
           "thickness")
    a("--damping-ratio", default=None, metavar="Q",
      help="the train's damping ratio, 0 to 0.99 (default 0)")
    a("--spring-preload", default=None, metavar="N",
      help="the spring's preload (N, a rocker's N m at its pivot), or 'size' (default): the "
           "least that holds over the whole turn at the top speed with --spring-margin")
    a("--materials", default=None, metavar="CAM,FOLLOWER",
      help="the cam's and the follower's materials (camdyn profile's names, or E:nu; default "
           "steel,steel)")
    a("--allowable-stress", default=None, metavar="PA",
      help="the allowable Hertz contact pressure (a law beyond it fails its check)")
    a("--max-pressure-angle", default=None, metavar="DEG",
      help="the pressure-angle limit (default 30 deg)")
    a("--camshaft-torsion", default=None, metavar="NM_RAD",
      help="the camshaft's torsional stiffness: Fa (4.14) and the thesis's larger models")
    a("--camshaft-bending", default=None, metavar="N/M",
      help="the camshaft's bending stiffness at the cam")
    a("--camshaft-inertia", default=None, metavar="KG_M2",
      help="the camshaft's inertia: Fv (5.52) with CAMSHAFT-2")
    a("--step", action="store_true",
      help="with --out, also the recommended cam as a STEP plate (needs --cam-width)")


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
    # the thesis room is imported here, the command line's one door into it (tests/test_rooms.py)
    from camdyn.thesis.design import machine, method, motor_sizing
    from camdyn.thesis.design.band import answer, charts, export, report, spec, units

    lib = SimpleNamespace(machine=machine, method=method, motor_sizing=motor_sizing,
                          answer=answer, charts=charts, export=export, report=report, spec=spec,
                          units=units)
    if _band_mode(args):
        return _band(args, lib)
    try:
        _single_numbers(args, lib.units)
    except ValueError as exc:
        return fail(PROG, str(exc))
    return _single(args, lib)


# -- one speed: the thesis's method ------------------------------------------------------------

SINGLE_QUANTITIES = {"stroke": "length", "swing": "angle", "arm_length": "length",
                     "arm_inertia": "inertia", "arm_stiffness": "torsional stiffness",
                     "speed": "speed", "mass": "mass", "stiffness": "stiffness",
                     "spring_margin": "ratio", "spring_rate": "stiffness",
                     "speed_fluctuation": "ratio"}
"""The options both designs take, read as numbers (argparse's float) for the single-speed
design, or with a unit ('25mm', '450rpm'); a speed is then in r.p.m."""


def _single_numbers(args, units) -> None:
    """Each option of :data:`SINGLE_QUANTITIES` as the float the single-speed design takes:
    a plain number as argparse's float read it, a value with a unit in SI (a speed in
    r.p.m.)."""
    for dest, kind in SINGLE_QUANTITIES.items():
        raw = getattr(args, dest)
        if raw is None:
            continue
        flag = "--" + dest.replace("_", "-")
        try:
            value = float(raw)
        except ValueError:
            if not any(c.isalpha() for c in raw):
                raise CamdynInputError(f"argument {flag}: invalid float value: {raw!r}") from None
            value = units.value(raw, kind, f"argument {flag}")
            if kind == "speed":
                value = units.speed_in(value, "rpm")
        setattr(args, dest, value)


def _single(args, lib) -> int:
    machine, method, motor_sizing = lib.machine, lib.method, lib.motor_sizing
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
            law=args.law or "cycloidal", theta=args.theta, common_shaft=args.common_shaft,
            motor_args=motor, check=not args.no_check,
            progress=None if args.json or args.quiet else say,
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


# -- the machine over its band -----------------------------------------------------------------

BAND_ONLY = ("laws", "follower", "base_radius", "roller_radius", "roller_width", "offset",
             "pivot_distance", "face_offset", "crown_radius", "cam_width", "damping_ratio",
             "spring_preload", "materials", "allowable_stress", "max_pressure_angle",
             "camshaft_torsion", "camshaft_bending", "camshaft_inertia", "step")
"""The options only the band design takes: any of them asks for it."""

SINGLE_ONLY = ("rise_time", "cam_angle", "tau", "fa", "c_tan", "pitch_radius", "ratio",
               "tan_alpha_me", "accuracy", "residual_acceleration", "law", "theta",
               "common_shaft", "motor_rpm", "motor_tm", "motor_tel", "rated_slip",
               "slip_limit", "spring", "gear_efficiency", "worm", "spring_mass", "no_check")
"""The single-speed design's own options, refused by the band design (not dropped unread)."""

WITH_FILE = ("laws", "step")
"""What a machine file leaves to the options (beside --out, --json, --quiet)."""

MACHINE_OPTIONS = {
    # option dest: (Machine field, the quantity; a rocker's where it differs)
    "stroke": ("stroke", "length"), "swing": ("swing", "angle"),
    "base_radius": ("base_radius", "length"), "roller_radius": ("roller_radius", "length"),
    "roller_width": ("roller_width", "length"), "offset": ("offset", "length"),
    "pivot_distance": ("pivot_distance", "length"), "arm_length": ("arm_length", "length"),
    "face_offset": ("face_offset", "length"), "crown_radius": ("crown_radius", "length"),
    "mass": ("mass", "mass"), "arm_inertia": ("inertia", "inertia"),
    "stiffness": ("stiffness", "stiffness"),
    "arm_stiffness": ("torsional_stiffness", "torsional stiffness"),
    "damping_ratio": ("damping_ratio", "ratio"),
    "spring_rate": ("spring_rate", ("stiffness", "torsional stiffness")),
    "spring_preload": ("spring_preload", ("force", "torque")),
    "spring_margin": ("spring_margin", "ratio"), "cam_width": ("cam_width", "length"),
    "allowable_stress": ("allowable_stress", "stress"),
    "max_pressure_angle": ("max_pressure_angle", "angle"),
    "camshaft_torsion": ("camshaft_torsional_stiffness", "torsional stiffness"),
    "camshaft_bending": ("camshaft_bending_stiffness", "stiffness"),
    "camshaft_inertia": ("camshaft_inertia", "inertia"),
    "speed_fluctuation": ("speed_fluctuation", "ratio")}
"""The machine's options: the field each gives and the quantity its unit is of."""

DEFAULTS = {"offset": 0.0, "face_offset": 0.0, "damping_ratio": 0.0}


def _flag(dest: str) -> str:
    return "--" + dest.replace("_", "-")


def _given(args, dest: str) -> bool:
    return getattr(args, dest, None) not in (None, False)


def _band_mode(args) -> bool:
    """A machine file, a band of speeds, or any of the band design's own options."""
    return (args.machine is not None or (args.speed is not None and ":" in str(args.speed))
            or any(_given(args, d) for d in BAND_ONLY))


def _refuse_single_options(args) -> None:
    for dest in SINGLE_ONLY:
        if _given(args, dest):
            hint = " (the band design takes --laws)" if dest in ("law", "theta") else ""
            raise CamdynInputError(
                f"argument {_flag(dest)}: the single-speed design's; the band design (a machine "
                f"file or --speed LO:HI) does not take it{hint}")


def machine_of(args, spec, units):
    """The machine of the command line (``spec``, ``units``: the band's modules): its file
    (only --laws beside it) or its options, every missing value named at once (spec.check)."""
    from dataclasses import replace

    _refuse_single_options(args)
    if args.machine is None:
        return from_options(args, spec, units)
    others = [d for d in (*MACHINE_OPTIONS, "speed", "angles", "follower", "materials")
              if _given(args, d)]
    if others:
        raise CamdynInputError(f"argument {_flag(others[0])}: the machine file "
                               f"{args.machine} gives the machine; change it there, or give "
                               f"every value as options without the file")
    m = spec.load(args.machine)
    if args.laws is not None:
        m = replace(m, laws=spec.laws_of(args.laws, "--laws"))
    return m


def from_options(args, spec, units):
    """The machine from the options alone, as a machine file would give it (spec.from_dict):
    each value by the units rule, a speed without a unit in r.p.m."""
    kind = args.follower or "translating-roller"
    rocker = kind.startswith("oscillating")
    values = {"follower": kind, "title": "machine", "source": "",
              "angles": spec.angles_of(args.angles, "--angles"),
              "laws": spec.laws_of(args.laws or "all", "--laws"),
              "materials": spec.materials_of(args.materials or "steel,steel", "--materials")}
    values["speeds"], values["speed_unit"] = (None, "rpm") if args.speed is None else \
        units.band(_rpm_unless_given(args.speed), "--speed")
    for dest, (name, kind_of) in MACHINE_OPTIONS.items():
        raw = getattr(args, dest)
        if isinstance(kind_of, tuple):
            kind_of = kind_of[1] if rocker else kind_of[0]
        if raw is None:
            values[name] = DEFAULTS.get(dest)
        elif dest == "spring_preload" and str(raw).strip().lower() == "size":
            values[name] = None
        else:
            values[name] = units.value(raw, kind_of, _flag(dest))
    if values["spring_margin"] is None:
        values["spring_margin"] = spec.MARGIN
    if values["max_pressure_angle"] is None:
        values["max_pressure_angle"] = spec.MAX_PRESSURE_ANGLE
    return spec.check(values, spec.OPTION_KEYS)


def _rpm_unless_given(raw: str) -> str:
    """--speed of plain numbers (LO:HI or one) is in r.p.m., as the single-speed design's
    --speed is; anything else goes to the units rule as it is."""
    text = str(raw).strip()
    try:
        [float(x) for x in text.split(":")]
    except ValueError:
        return text
    return f"{text} rpm"


def _band(args, lib) -> int:
    answer, charts, export, report = lib.answer, lib.charts, lib.export, lib.report
    say = (lambda msg: None) if args.json or args.quiet else \
        (lambda msg: print(f"{PROG}: {msg}", file=sys.stderr, flush=True))
    try:
        m = machine_of(args, lib.spec, lib.units)
        if args.step and m.cam_width is None:
            raise CamdynInputError("argument --step: the STEP plate needs its thickness: "
                                   + ("--cam-width" if args.machine is None else
                                      f"cam.width in {args.machine}"))
        if args.step and args.out is None:
            raise CamdynInputError("argument --step: goes with --out DIR")
        names = (*export.files(args.step), *report.FILES, *charts.FILES)
        folder = out_folder(args.out, files=names)    # the user's own: refused before the runs
        a = answer.design_band(m, progress=say)
        d = answer.as_json(a)
        if folder is not None:
            figures = charts.draw(a, folder)
            d["files"] = {**export.write(a, folder, d, step=args.step),
                          **report.write(a, folder, figures), **figures}
    except ValueError as exc:
        return fail(PROG, str(exc))
    except SimulationError as exc:
        return run_failed(PROG, exc)
    for w in d["warnings"]:
        print(f"{PROG}: warning: {w}", file=sys.stderr)
    if args.json:
        print(json.dumps(d, indent=1))
    else:
        print(answer.text(a, warnings=False))       # they are on stderr
        for f in d.get("files", {}).values():
            print(f"wrote {f}")
    # no law passing every check is status 1, as camdyn profile's failed checks are
    return 0 if a.recommended is not None else 1
