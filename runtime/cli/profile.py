"""camdyn profile: the cam itself, pitch curve and profile(s) as CSV, DXF and PNG."""
from __future__ import annotations

import json
import sys

from ..core.errors import CamdynInputError
from ..core.outdir import out_folder, write_text
from ..cam.names import KINDS, MATERIALS
from .common import LAW_HELP, add_out_option, fail, law_argument

HELP = ("the cam itself: profile(s) of a disk cam for a translating or oscillating, roller or "
        "flat-faced follower, as CSV, DXF and PNG")
"""The command's line in `camdyn --help`."""


def add(sub):
    p = sub.add_parser(
        "profile", help=HELP,
        description="A radial disk cam over a full turn (rise, upper dwell, return with the "
                    "same law mirrored, lower dwell) for a translating or oscillating (rocker), "
                    "roller or flat-faced follower: the profile as the envelope of the "
                    "follower's positions seen from the cam, the pitch curve of a roller "
                    "(both walls with --groove), the pressure angle and the radius of curvature "
                    "along the cam angle, and for a flat face where the contact travels on it "
                    "(the face width it needs); written as CSV (SI), DXF (mm, layers PITCH, "
                    "PROFILE, PROFILE_OUTER, BASE_CIRCLE) and PNG. The undercut (roller), cusp "
                    "(flat face) and pressure-angle checks that fail are warnings naming the "
                    "cam angle where they are worst (and in the JSON), and the exit status "
                    "is then 1, the files written all the same; a law whose velocity jumps "
                    "fails the undercut or cusp check where it jumps. SI units.")
    p.add_argument("--follower", default=None, choices=KINDS,
                   help="the follower (default translating-roller); a translating one takes "
                        "--stroke (and --offset), an oscillating one --pivot-distance and "
                        "--swing, a roller --roller-radius, an oscillating roller "
                        "--arm-length, an oscillating flat face --face-offset")
    p.add_argument("--law", default=None, type=law_argument, metavar="LAW",
                   help=f"cam law of the rise: {LAW_HELP} (the return is its mirror unless "
                        f"--return-law; default cycloidal)")
    p.add_argument("--law-parameter", type=float, default=None, metavar="X",
                   help="the law's shape parameter, for laws that have one")
    p.add_argument("--return-law", default=None, type=law_argument, metavar="LAW",
                   help="cam law of the return, S = h (1 - H(u)) (default: the rise's)")
    p.add_argument("--return-law-parameter", type=float, default=None, metavar="X",
                   help="the return law's shape parameter")
    p.add_argument("--stroke", type=float, default=None, metavar="M",
                   help="stroke h of a translating follower, m, 0 <= h < 1000")
    p.add_argument("--swing", type=float, default=None, metavar="DEG",
                   help="swing of an oscillating follower's arm over the rise, deg, 0 < DEG < 90")
    p.add_argument("--pivot-distance", type=float, default=None, metavar="M",
                   help="oscillating follower: cam centre to the arm's pivot a, m")
    p.add_argument("--arm-length", type=float, default=None, metavar="M",
                   help="oscillating roller: pivot to roller centre l, m, |a - l| < r_b + r_r < a + l")
    p.add_argument("--face-offset", type=float, default=0.0, metavar="M",
                   help="oscillating flat face: distance of the face's line from the pivot f, m "
                        "(default 0, the face through the pivot; |r_b - f| < a)")
    p.add_argument("--base-radius", type=float, default=None, metavar="M",
                   help="base circle of the cam profile r_b, m, 1e-6 <= r_b < 1000 (roller centre on the "
                        "prime circle r_b + r_r at the bottom of the stroke); required unless "
                        "--contact-force-from gives the cam")
    p.add_argument("--roller-radius", type=float, default=None, metavar="M",
                   help="roller radius r_r of a roller follower, m, 1e-6 <= r_r < 1000")
    p.add_argument("--offset", type=float, default=None, metavar="M",
                   help="translating follower: offset e of its axis, m, |e| < r_b + r_r "
                        "(default 0; e > 0 lowers a roller's pressure angle on the rise)")
    p.add_argument("--angles", default=None, metavar="R,D,F,D",
                   help="rise, upper dwell, return, lower dwell in deg, summing to 360 "
                        "(default 90,90,90,90)")
    p.add_argument("--groove", action="store_true", help="a groove cam: both walls")
    p.add_argument("--max-pressure-angle", type=float, default=30.0, metavar="DEG",
                   help="pressure-angle limit of the check, 0 < DEG < 90 (default 30)")
    p.add_argument("--points-per-degree", type=int, default=10, metavar="N",
                   help="samples per degree of cam angle, 1 to 1000 (default 10)")
    p.add_argument("--cutter-radius", type=float, default=None, metavar="M",
                   help="a milling cutter's radius, m: its centre path (the profile offset "
                        "outwards; CSV x_cutter, y_cutter; DXF layer CUTTER) and the check that "
                        "it does not gouge a concave part (open cams)")
    p.add_argument("--arcs", type=float, default=None, metavar="TOL",
                   help="write the DXF's curves as tangent arcs (bi-arcs) within TOL m of the "
                        "exact curves, 1e-9 <= TOL <= 1, instead of sampled polylines (a "
                        "profile failing its undercut or cusp check has no such arcs: its "
                        "DXF keeps the polylines, with a warning)")
    g = p.add_argument_group(
        "contact stress", "Hertz's peak contact pressure along the cam (line contact; a crowned "
        "roller's point contact), from a constant normal force, the kinetostatic one at a "
        "cam speed, or the force of a dynamic run")
    g.add_argument("--contact-force", type=float, default=None, metavar="N",
                   help="a constant normal force between cam and follower, N")
    g.add_argument("--contact-force-from", default=None, metavar="SCENE",
                   help="the force F_x (6.42) of a dynamic run of a DYNACAM scene (file or "
                        "built-in; a radial cam with a [turn]) over its last full turn; the cam "
                        "is the scene's (stroke h_m, a translating roller on the prime circle "
                        "R_b, its law and turn), the roller's radius --roller-radius")
    g.add_argument("--speed", type=float, default=None, metavar="RPM",
                   help="cam speed for the kinetostatic force: the follower driven through its "
                        "motion against its mass and spring")
    g.add_argument("--follower-mass", type=float, default=0.0, metavar="KG",
                   help="with --speed: the follower's mass, kg (a rocker's moment of inertia "
                        "about the pivot, kg m^2)")
    g.add_argument("--spring-rate", type=float, default=0.0, metavar="K",
                   help="with --speed: the return spring's rate, N/m (a rocker's N m/rad)")
    g.add_argument("--spring-preload", type=float, default=0.0, metavar="F0",
                   help="with --speed: the spring's force at the bottom of the stroke, N (a "
                        "rocker's N m)")
    g.add_argument("--roller-width", type=float, default=None, metavar="M",
                   help="the roller's width, m: the contact line's length")
    g.add_argument("--cam-width", type=float, default=None, metavar="M",
                   help="the cam's thickness, m: the contact line's length for a flat face (the "
                        "shorter of the two for a roller)")
    g.add_argument("--materials", default="steel,steel", metavar="CAM,FOLLOWER",
                   help="materials of cam and follower, each a name (" + ", ".join(MATERIALS)
                        + ") or E:nu in Pa, e.g. 210e9:0.3 (default steel,steel)")
    g.add_argument("--crown-radius", type=float, default=None, metavar="M",
                   help="a crowned roller's crown radius across the cam, m (point contact)")
    g.add_argument("--allowable-stress", type=float, default=None, metavar="PA",
                   help="the allowable peak contact pressure, Pa, for the check")
    g = p.add_argument_group(
        "solid", "the cam plate as a STEP solid (optional extra: pip install 'camdyn[cad]')")
    g.add_argument("--step", action="store_true",
                   help="also write cam.step: the profile (tangent arcs within --arcs, 1e-6 m "
                        "unless given) extruded to the plate's thickness --cam-width, less the "
                        "bore; an open cam")
    g.add_argument("--bore", type=float, default=0.0, metavar="M",
                   help="with --step: the bore's diameter, m, below twice the profile's least "
                        "radius (default 0, none)")
    add_out_option(p, default="out/cam", metavar="DIR",
                   help="folder for cam.csv, cam.dxf, cam.png, cam.json and cam.step (default "
                        "out/cam)")
    p.add_argument("--json", action="store_true", help="one JSON object on stdout")
    return p


_GIVEN_BY_SCENE = ("stroke", "base-radius", "law", "law-parameter", "return-law",
                   "return-law-parameter", "angles", "offset", "follower", "swing",
                   "pivot-distance", "arm-length", "face-offset")
"""The cam's settings a scene gives with --contact-force-from (refused beside it)."""


def run(args) -> int:
    from ..cam.load import ContactLoad
    from ..cam.profile import CamProfile
    from ..cam.stress import ContactSpec
    from ..measure.contract import plus_minus

    prog = "camdyn profile"
    scene = None
    if args.contact_force_from is not None:
        given = [n for n in _GIVEN_BY_SCENE if getattr(args, n.replace("-", "_")) not in
                 (None, 0.0)]
        if given:
            return fail(prog, f"--{given[0]} comes from the scene with --contact-force-from "
                              f"(its h_m, R_b, law and turn): leave it out")
        if args.contact_force is not None or args.speed is not None:
            return fail(prog, "give the contact force one way: --contact-force, --speed, or "
                              "--contact-force-from")
    elif args.base_radius is None:
        return fail(prog, "--base-radius M is required (or --contact-force-from SCENE, whose "
                          "R_b gives the cam)")
    if args.step and args.cam_width is None:
        return fail(prog, "--step needs the plate's thickness: --cam-width M")
    if args.bore and not args.step:
        return fail(prog, "--bore goes with --step")
    angles_text = args.angles or "90,90,90,90"
    try:
        angles = [float(a) for a in angles_text.split(",")]
    except ValueError:
        return fail(prog, f"--angles must be four numbers in deg, rise,upper dwell,return,lower "
                          f"dwell summing to 360, got {angles_text!r}")
    try:
        if args.contact_force_from is not None:
            from ..targets import scene_force

            scene = scene_force.load(args.contact_force_from, args.roller_radius)
            geometry = dict(scene.cam)
        else:
            geometry = dict(stroke=args.stroke, base_radius=args.base_radius,
                            roller_radius=args.roller_radius,
                            offset=0.0 if args.offset is None else args.offset,
                            follower=args.follower or "translating-roller",
                            pivot_distance=args.pivot_distance, arm_length=args.arm_length,
                            swing_deg=args.swing, face_offset=args.face_offset,
                            angles_deg=tuple(angles), law=args.law or "cycloidal",
                            law_parameter=args.law_parameter, return_law=args.return_law,
                            return_law_parameter=args.return_law_parameter)
        cam = CamProfile(**geometry, cutter_radius=args.cutter_radius, arc_tolerance=args.arcs,
                         groove=args.groove, points_per_degree=args.points_per_degree,
                         max_pressure_angle_deg=args.max_pressure_angle)
        out = cam.summary()
        if scene is not None:
            out["contact_force_from"] = args.contact_force_from
        if args.contact_force is not None or args.speed is not None or scene is not None:
            def spec(history=None):
                load = (ContactLoad(history=history) if history is not None else
                        ContactLoad(force=args.contact_force, speed_rpm=args.speed,
                                    mass=args.follower_mass, spring_rate=args.spring_rate,
                                    preload=args.spring_preload))
                return ContactSpec(load, roller_width=args.roller_width,
                                   cam_width=args.cam_width,
                                   materials=tuple(args.materials.split(",")),
                                   crown_radius=args.crown_radius,
                                   allowable=args.allowable_stress)
            if scene is None:
                stress = cam.stress_summary(spec())
            else:
                stress = scene_force.with_run_error(
                    cam.stress_summary(spec(scene.history)),
                    None if scene.tighter is None else cam.stress_summary(spec(scene.tighter)))
            out["contact_stress"] = stress
            out["hertz_stress_max"] = stress["hertz_stress_max"]
            out["hertz_stress_max_error"] = stress["hertz_stress_max_error"]
            out["warnings"] = out["warnings"] + stress["warnings"]
            out["ok"] = out["ok"] and stress["ok"]
        elif any(v is not None for v in (args.roller_width, args.crown_radius,
                                          args.allowable_stress,
                                          None if args.step else args.cam_width)):
            return fail(prog, "the contact stress needs its force: --contact-force N, "
                              "--speed RPM with --follower-mass, --spring-rate, "
                              "--spring-preload, or --contact-force-from SCENE")
        if args.step:
            from ..cam.step import plate_checks
            plate_checks(cam, args.cam_width, args.bore, "cam-width")   # before any file
        kinds = ("csv", "dxf", "png", "json") + (("step",) if args.step else ())
        folder = out_folder(args.out, files=[f"cam.{x}" for x in kinds])
        out["files"] = cam.write_all(folder)
        if args.step:
            _step(cam, args, folder, out)
        out["files"]["json"] = str(folder / "cam.json")
        write_text(folder / "cam.json", json.dumps(out, indent=1))
    except CamdynInputError as exc:
        return fail(prog, str(exc))
    for w in out["warnings"]:
        print(f"{prog}: warning: {w}", file=sys.stderr)
    # a failed check (undercut, cusp, pressure angle, contact stress, a STEP plate not
    # written) is status 1, the files and the report written all the same
    status = 0 if out["ok"] else 1
    if args.json:
        print(json.dumps(out, indent=1))
        return status
    laws = cam.law + ("" if cam.return_law in (None, cam.law) else f" / {cam.return_law} return")
    if cam.oscillating:
        motion = (f"swing {cam.swing_deg:g} deg, pivot at {cam.pivot_distance * 1e3:g} mm"
                  + (f", arm {cam.arm_length * 1e3:g} mm" if cam.roller
                     else f", face offset {cam.face_offset * 1e3:g} mm"))
    else:
        motion = f"stroke {cam.stroke * 1e3:g} mm, offset {cam.offset * 1e3:g} mm"
    roller = f", roller {cam.roller_radius * 1e3:g} mm" if cam.roller else ""
    print(f"{out['kind']} cam, {cam.follower} follower, {laws} law, {motion}, base circle "
          f"{cam.base_radius * 1e3:g} mm{roller}, {out['points']} points")
    for c in cam.checks:
        print(f"{'ok  ' if c.ok else 'FAIL'} {c.message}")
    pitch = (f", smallest |rho_pitch| = {out['min_rho_pitch'] * 1e3:.6g}"
             f"{plus_minus(out['min_rho_pitch_error'] * 1e3)} mm" if cam.roller else "")
    print(f"     largest |alpha| = {out['max_abs_pressure_angle_deg']:.6g}"
          f"{plus_minus(out['max_abs_pressure_angle_deg_error'])} deg{pitch}, smallest "
          f"|rho_profile| = {out['min_rho_profile'] * 1e3:.6g}"
          f"{plus_minus(out['min_rho_profile_error'] * 1e3)} mm")
    if not cam.roller:
        lo, hi = out["face_travel"]
        print(f"     the contact travels on the face from {lo * 1e3:.6g} to {hi * 1e3:.6g} mm "
              f"({'from the pivot' if cam.oscillating else 'from the slide axis'}): face width "
              f">= {out['face_width'] * 1e3:.6g}{plus_minus(out['face_width_error'] * 1e3)} mm")
    if "contact_stress" in out:
        st = out["contact_stress"]
        print(f"     {st['contact_force']}: {st['contact_force_min']:.6g} to "
              f"{st['contact_force_max']:.6g} N, {st['contact']} contact, E* = "
              f"{st['contact_modulus'] / 1e9:.4g} GPa")
        if st["hertz_stress_max"] is not None:
            print(f"     Hertz's peak contact pressure {st['hertz_stress_max'] / 1e6:.6g}"
                  f"{plus_minus(st['hertz_stress_max_error'] / 1e6)} MPa at cam angle "
                  f"{st['hertz_stress_max_angle_deg']:.2f} deg")
        for c in st["checks"]:
            print(f"{'ok  ' if c['ok'] else 'FAIL'} {c['message']}")
    if out.get("step", {}).get("written"):
        st = out["step"]
        print(f"     STEP plate {st['thickness'] * 1e3:g} mm thick"
              + (f", bore {st['bore'] * 1e3:g} mm" if st["bore"] else "")
              + f": {st['arcs']} arcs within {st['tolerance'] * 1e3:g} mm of the profile, "
              f"volume {st['volume'] * 1e6:.6g}{plus_minus(st['volume_error'] * 1e6)} cm^3")
    print("     (refined between the samples; ± what the sampling leaves)")
    for f in out["files"].values():
        print(f"wrote {f}")
    return status


def _step(cam, args, folder, out) -> None:
    """cam.step, or the reason it is not written among the warnings (and ``ok`` false): a
    profile its checks find is no closed simple curve (a cusp, an undercut, a velocity
    jump's corner) never reaches the CAD kernel, and what the kernel refuses is one line."""
    from ..cam.step import StepError, profile_refusal, write_step

    why = profile_refusal(cam)
    if why is None:
        try:
            out["step"] = {"written": True,
                           **write_step(cam, folder / "cam.step", args.cam_width, args.bore)}
            out["files"]["step"] = str(folder / "cam.step")
            return
        except StepError as exc:
            why = str(exc)
    out["step"] = {"written": False, "reason": why}
    out["warnings"].append(f"cam.step not written: {why}")
    out["ok"] = False
