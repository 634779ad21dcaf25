"""The live design page of `camdyn serve`: Panel widgets on Bokeh charts.

A designer picks a mechanism (the one-DOF model (3.1), CAMSHAFT-1 (4.15), CAMSHAFT-2
(5.15), (5.16), or a DYNACAM scene: built-in or a file), a follower and a cam law, and sets
the parameters; every change answers with

* the response X'' against T of one run, its figures each with its error estimate and the
  run's warnings (runtime/measure/contract.py, the answer contract);
* the residual acceleration U0'' against tau (a compiled sweep, each point ± its estimate)
  with its envelope through the maxima (secs 3.5, 8.2.6) and the design point marked;
* the cam profile (the envelope of the follower's positions), its pressure angle and the
  Hertz contact stress along the cam (runtime/cam/profile.py, stress.py), each extreme ± its
  sampling error: the page's fields for a model, the scene's own cam for a DYNACAM scene (its
  follower, R_b, h_m, beta_m, law and turn, under the largest force F_x (6.42) of its run);
* the verdict of the design rules of secs 8.2-8.5 (camdyn design), made on the next tick so
  that the charts answer first.

:func:`evaluate` is the page without the page: the inputs in, every figure out, so that it
can be tested and timed alone; bad input raises the CamdynInputError the command line
prints, and the page shows its one line above the charts of the last inputs that ran, greyed
out as stale.  Its ``inputs`` are the inputs that ran (a scene's law, follower and cam in
place of the page's fields), which the page's widgets then show.

The page changes its Bokeh models (the charts' data) only on its own turn of the server's loop,
holding the document's lock (:func:`app`, ``answer_later``): Panel runs a widget's callback
without that lock when the change comes with a browser event (a text box's Enter), and Bokeh
refuses a change of a served document made without it.
"""
from __future__ import annotations

import io
import time
from collections import OrderedDict
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field, replace

import numpy as np

from ..core.errors import CamdynInputError, SimulationError

MODELS = {"one_dof": "one-DOF (3.1): tau", "camshaft1": "CAMSHAFT-1 (4.15): tau, Fa",
          "camshaft2": "CAMSHAFT-2 (5.15), (5.16): tau, Fa, Fv"}
"""The lumped models the page runs through the compiled sweeps."""

LAWS = ("cycloidal", "modified-sine", "3-4-5", "4-5-6-7", "5-6-7-8-9", "modified-trapezoid",
        "simple-harmonic")
"""The rise laws offered (App. 2); the others need a shape parameter or a table."""

FOLLOWERS = ("translating-roller", "oscillating-roller", "translating-flat", "oscillating-flat")

N_TAU = 80
"""tau points of the residual chart, uniform in 1/tau (fig. 4.11's grid)."""

SCENE_RTOL = 1e-6
"""The tolerance the page runs a DYNACAM scene at, whatever its file asks: a live answer in
about 0.1 s for the slowest built-in scene (indexing: 115 ms, against 314 ms at its file's
1e-8), each figure with its estimate at this tolerance (there: X''_min -44.7411 ± 2.4e-4);
`camdyn simulate` runs the file's own."""

CHART = {"one_dof": (80, 1e-8), "camshaft1": (80, 1e-8), "camshaft2": (40, 1e-6)}
"""(tau points, rtol) of each model's residual chart, run with DOP853: within the page's
200 ms on two cores (CAMSHAFT-2's fast shaft mode costs it eight times CAMSHAFT-1's steps);
every point carries its estimate, so a looser rtol shows as a wider band, not as a wrong one."""


@dataclass
class Inputs:
    """What the page's widgets hold (SI units, angles in degrees)."""

    mechanism: str = "camshaft1"          # a model of MODELS, a built-in scene or a scene file
    law: str = "cycloidal"
    tau: float = 0.15
    Fa: float = 0.5
    Fv: float = 10.0
    scene_parameters: dict = field(default_factory=dict)
    follower: str = "translating-roller"
    base_radius: float = 0.04
    roller_radius: float = 0.008
    stroke: float = 0.02
    swing_deg: float = 18.0
    pivot_distance: float = 0.1
    arm_length: float = 0.08
    face_offset: float = 0.0
    rise_deg: float = 120.0
    contact_force: float = 500.0
    width: float = 0.01
    rise_time: float = 0.1
    accuracy: float = 1e-4
    tau_min: float = 0.05
    tau_max: float = 0.8


def is_model(mechanism: str) -> bool:
    return mechanism in MODELS


def scene_target(name: str):
    """The target of a DYNACAM scene, built-in or a file, at the page's SCENE_RTOL.  A file
    that is missing, unreadable, broken or of another kind is refused in one line that
    starts with the cause (the command line's resolver names every model first: a scene
    name is also tried as a model there, never here)."""
    from ..targets import scene_files
    from ..targets.dynacam_scene import DynacamTarget
    from ..targets.resolve import load_scene

    try:
        kind, sc = load_scene(name)
    except CamdynInputError as exc:
        cause = str(exc).splitlines()[0] if str(exc) else "cannot be read"
        raise CamdynInputError(cause if name in cause else f"{cause} (scene {name})") from None
    if kind != scene_files.DYNACAM:
        raise CamdynInputError(f"{name} is a {kind} scene; the page runs DYNACAM scenes (kind = "
                               f"\"dynacam\"); camdyn run runs any kind")
    return DynacamTarget.from_scene(sc, name).with_settings(rtol=SCENE_RTOL)


def _model_target(mechanism: str, law, theta, values: dict):
    from ..targets.resolve import resolve

    tgt = resolve(mechanism, law=law, theta=theta)
    names = tgt.parameters()
    return tgt.with_parameters({k: v for k, v in values.items() if k in names})


def _target(inp: Inputs):
    if is_model(inp.mechanism):
        return _model_target(inp.mechanism, inp.law, None, {"tau": inp.tau, "Fa": inp.Fa, "Fv": inp.Fv})
    tgt = scene_target(inp.mechanism)
    return tgt.with_parameters(inp.scene_parameters) if inp.scene_parameters else tgt


def _characteristics(inp: Inputs, tgt) -> tuple[float, float, float, float]:
    """(tau, Fa, stroke h_m', rise time t_m) of the design point: the sliders' for a model
    (the stroke and rise time of the page's fields), a scene's (4.3)-(5.52) and its own."""
    if is_model(inp.mechanism):
        Fa = inp.Fa if inp.mechanism != "one_dof" else 0.0
        return inp.tau, Fa, inp.stroke, inp.rise_time
    from ..targets import dynacam

    sc = tgt.scene
    params, ch, _ = dynacam.placed(sc)
    return ch["tau"], ch["Fa"], params["h_m"], ch["t_m"]


def _rise_angles(rise_deg: float) -> tuple:
    """The page's turn: the rise, a dwell, the return over as many degrees, a dwell as long."""
    if not 0 < rise_deg < 180:
        raise CamdynInputError(f"rise={rise_deg:g} deg is out of range: 0 < rise < 180 (the "
                               "return takes as long, the dwells share the rest)")
    dwell = (360.0 - 2 * rise_deg) / 2
    return (rise_deg, dwell, rise_deg, dwell)


def _geometry(inp: Inputs) -> dict:
    """The page's cam as CamProfile's keyword arguments (a model's page: its fields)."""
    oscillating, roller = inp.follower.startswith("oscillating"), inp.follower.endswith("roller")
    return dict(
        follower=inp.follower, base_radius=inp.base_radius,
        roller_radius=inp.roller_radius if roller else None,
        stroke=None if oscillating else inp.stroke,
        swing_deg=inp.swing_deg if oscillating else None,
        pivot_distance=inp.pivot_distance if oscillating else None,
        arm_length=inp.arm_length if oscillating and roller else None,
        face_offset=inp.face_offset if oscillating and not roller else 0.0,
        angles_deg=_rise_angles(inp.rise_deg), law=inp.law)


class NotDrawn(CamdynInputError):
    """A scene whose cam the page cannot draw as a disk cam: its run answers, its cam panels
    are greyed out with this message (the DXF is refused with it)."""


def scene_geometry(sc, roller_radius: float) -> dict:
    """The cam a DYNACAM scene runs, as CamProfile's keyword arguments; NotDrawn for an axial
    (globoidal) cam, which is no disk cam, a rise of 180 deg or more without a [turn], a
    rocker swinging 90 deg or more.  A radial cam lifts the follower by h = h_m H(B)
    on the pitch radius R_b + h (6.20)-(6.22): a roller of the page's radius r_r (the scene
    has none) rolls on a profile of base radius R_b - r_r, a flat face on the base circle R_b
    itself (camdyn profile --contact-force-from reads a scene so); a rocker pivoted at d_p
    swings h_m/l_a, the stroke being its arc at l_a (sec. 2.4), a roller at l_a, a flat face
    at f_f from the pivot.  The law is the scene's, over its [turn] if it has one, else the
    rise mirrored after a dwell as the page's own cam."""
    import math

    from ..targets import scene_files

    o, p = sc.options, sc.parameters
    if o.cam != "radial":
        raise NotDrawn(f"{sc.title}: an axial (globoidal) cam; the cam panels draw radial disk "
                       "cams only")
    rocker, flat = bool(getattr(o, "rocker", False)), bool(getattr(o, "flat_face", False))
    R_b = float(p["R_b"])
    if not flat and not 0 < roller_radius < R_b:
        raise CamdynInputError(f"roller radius={roller_radius:g} m is out of range: 0 < roller "
                               f"radius < the scene's base pitch radius R_b = {R_b:g} m")
    rise = math.degrees(p["beta_m"])
    if sc.turn is not None:
        angles = scene_files.turn_angles(sc)
    elif not rise < 180:
        raise NotDrawn(f"beta_m={p['beta_m']:g} rad ({rise:g} deg): the cam drawn for a "
                               f"scene without a [turn] returns as it rises and needs beta_m < "
                               f"180 deg; give the scene a [turn] (upper_dwell, return in deg)")
    else:
        angles = _rise_angles(rise)
    if rocker and not 0 < math.degrees(p["h_m"] / p["l_a"]) < 90:
        raise NotDrawn(f"h_m={p['h_m']:g} m on the arm l_a={p['l_a']:g} m swings the "
                               f"rocker {math.degrees(p['h_m'] / p['l_a']):g} deg: the cam "
                               f"drawn needs 0 < h_m/l_a < 90 deg")
    g = dict(follower=f"{'oscillating' if rocker else 'translating'}-{'flat' if flat else 'roller'}",
             base_radius=R_b if flat else R_b - roller_radius,
             roller_radius=None if flat else roller_radius, stroke=None, swing_deg=None,
             pivot_distance=None, arm_length=None, face_offset=0.0, angles_deg=tuple(angles),
             law=sc.law, law_parameter=sc.theta,
             return_law=(sc.turn or {}).get("return_law"),
             return_law_parameter=(sc.turn or {}).get("return_theta"))
    if rocker:
        g.update(pivot_distance=float(p["d_p"]), swing_deg=math.degrees(p["h_m"] / p["l_a"]),
                 arm_length=None if flat else float(p["l_a"]),
                 face_offset=float(p.get("f_f", 0.0)) if flat else 0.0)
    else:
        g.update(stroke=float(p["h_m"]))
    return g


def _profile(inp: Inputs, tgt=None):
    """The cam of ``inp`` (a scene's: its own, ``tgt`` its target if already made)."""
    from ..cam.profile import CamProfile

    if is_model(inp.mechanism):
        geometry = _geometry(inp)
    else:
        geometry = scene_geometry((tgt or _target(inp)).scene, inp.roller_radius)
    return CamProfile(**geometry, points_per_degree=2)


def run_force(ans) -> tuple[float, float | None]:
    """(Q, its estimate): the largest |F_x| (6.42), the force the follower takes from the cam
    along its motion, over a scene's run, found on the dense output; the estimate is the
    difference the run one notch tighter makes (times the method's factor) plus both scans'
    sampling errors (None without a tighter run)."""
    from ..measure.extremes import extreme

    def largest(res):
        e = extreme(res, "Fx", float(res.t[0]), float(res.t[-1]), absolute=True, minimum=False)
        return abs(e.value), e.sampling_error

    Q, s = largest(ans.result)
    if ans.tight_result is None:
        return Q, None
    Q2, s2 = largest(ans.tight_result)
    return Q, abs(Q - Q2) * ans.factor + s + s2


def _stress(prof, follower: str, width: float, force: float, generalised: bool):
    from ..cam.load import ContactLoad, ForceHistory
    from ..cam.stress import ContactSpec

    roller = follower.endswith("roller")
    if generalised:
        # the run's largest F_x along the whole cam: a force along the follower's motion,
        # which the cam's lever turns into the normal force (runtime/cam/load.py)
        load = ContactLoad(history=ForceHistory(
            f"the scene's run (its largest |F_x| (6.42), {force:.6g} N, all along the cam)",
            lambda phi: np.full(np.shape(phi), force)))
    else:
        load = ContactLoad(force=force)
    spec = ContactSpec(load, roller_width=width if roller else None,
                       cam_width=None if roller else width)
    _, p0 = prof.contact_stress(prof.phi, spec)
    return p0, prof.stress_summary(spec)


def with_force_error(stress: dict, Q: float, eQ: float | None) -> dict:
    """The stress summary with the error of the force it was computed from: Hertz's peak
    pressure of a line contact is p0 = (P' E*/(pi R))^(1/2), P' = F/L (stress.py), so a force
    known to F +- e_F gives p0 within p0 ((1 + e_F/F)^(1/2) - 1) more, and the normal force
    within F e_F/F."""
    out = dict(stress)
    if eQ is None:
        out["warnings"] = [*out.get("warnings", []), "the contact force has no error estimate "
                           "(no run one notch tighter): the stress's is the sampling's only"]
        return out
    grow = eQ / Q if Q > 0 else 0.0
    if out.get("hertz_stress_max") is not None:
        out["hertz_stress_max_error"] += out["hertz_stress_max"] * (np.sqrt(1.0 + grow) - 1.0)
    for key in ("contact_force_max", "contact_force_min"):
        if out.get(key) is not None:
            out[key + "_error"] += abs(out[key]) * grow
    return out


_MEMO: "OrderedDict[tuple, object]" = OrderedDict()
"""The page's latest answers by what they depend on: a change of the follower does not run the
mechanism again, nor a change of tau the cam (the 32 latest of each part kept)."""


def _memo(key: tuple, make):
    if key in _MEMO:
        _MEMO.move_to_end(key)
        return _MEMO[key]
    value = _MEMO[key] = make()
    while len(_MEMO) > 96:
        _MEMO.popitem(last=False)
    return value


def _stamp(mechanism: str):
    """A scene file's modification time and size (a built-in's: None), so that an edited
    file is run again."""
    from pathlib import Path

    path = Path(mechanism)
    if is_model(mechanism) or not path.is_file():
        return None
    st = path.stat()
    return st.st_mtime_ns, st.st_size


def _cam(geometry: dict, follower: str, width: float, force: float, force_error,
         generalised: bool) -> tuple:
    from ..cam.profile import CamProfile

    prof = CamProfile(**geometry, points_per_degree=2)
    table = prof.table
    p0, stress = _stress(prof, follower, width, force, generalised)
    if generalised:
        stress = with_force_error(stress, force, force_error)
    return prof, table, p0, stress, prof.extremes(), prof.summary()["warnings"]


def _ran(inp: Inputs, tgt, geometry: dict | None, force: tuple, h: float, t_m: float) -> Inputs:
    """The inputs a scene ran with: its law, its follower and cam in place of the page's
    fields, the largest force of its run as the contact force, its stroke and rise time."""
    import math

    sc = tgt.scene
    ran = replace(inp, law=sc.law, stroke=h, rise_time=t_m, contact_force=force[0],
                  rise_deg=math.degrees(sc.parameters["beta_m"]))
    if geometry is None:
        return ran
    g = {k: v for k, v in geometry.items() if v is not None and k in (
        "follower", "base_radius", "swing_deg", "pivot_distance", "arm_length", "face_offset")}
    return replace(ran, **g)


def _nominal_T(tgt, res) -> np.ndarray:
    """The response chart's abscissa T = t/t_m: a model's time already; a scene's run is in
    seconds from run.T_start (runtime/targets/dynacam.py, nominal_T)."""
    if getattr(tgt, "scene", None) is None:
        return res.t
    from ..targets import dynacam

    return dynacam.nominal_T(tgt.scene, res)


def evaluate(inp: Inputs) -> dict:
    """Every figure of the page for ``inp`` (see the module doc), with the seconds each part
    took and the inputs that ran; the design rules' verdict is :func:`verdict`."""
    from ..measure.contract import answer
    from ..measure.envelope import envelope, tau_grid
    from ..studies.sweep import sweep

    clock = {}
    t0 = time.perf_counter()
    model_page = is_model(inp.mechanism)
    tgt = _target(inp)
    given = ((inp.tau, inp.Fa, inp.Fv) if model_page
             else tuple(sorted(inp.scene_parameters.items())))
    run_key = ("response", inp.mechanism, _stamp(inp.mechanism),
               inp.law if model_page else None, given)
    ans = _memo(run_key, lambda: answer(tgt))
    res = ans.result
    acc = res.model.manifest.get("residual", {}).get("acceleration") or res.state_names[0]
    force = None if model_page else _memo(run_key + ("force",), lambda: run_force(ans))
    clock["response"] = time.perf_counter() - t0
    tau, Fa, h, t_m = _characteristics(inp, tgt)
    cam_note = None
    try:
        geometry = _geometry(inp) if model_page else scene_geometry(tgt.scene, inp.roller_radius)
    except NotDrawn as exc:
        geometry, cam_note = None, str(exc)
    ran = inp if model_page else _ran(inp, tgt, geometry, force, h, t_m)
    t0 = time.perf_counter()
    if not 0 < inp.tau_min < inp.tau_max < np.inf:
        raise CamdynInputError(f"tau range {inp.tau_min:g} to {inp.tau_max:g}: needs "
                               "0 < tau min < tau max, both finite")
    model = inp.mechanism if model_page else "camshaft1"
    theta = None if model_page else tgt.scene.theta
    n_tau, rtol = CHART[model]
    Fv = inp.Fv if model == "camshaft2" else None
    graph = _model_target(model, ran.law, theta, {"Fa": Fa, "Fv": inp.Fv}).with_settings(
        method="dop853", rtol=rtol)
    taus = tau_grid(inp.tau_min, inp.tau_max, n_tau)
    sw = _memo(("residual", model, ran.law, theta, Fa, Fv, inp.tau_min, inp.tau_max),
               lambda: sweep(graph, {"tau": taus}, progress=False, jobs=1))
    env = envelope(sw.axes["tau"], sw["U0dd"])
    at = float(np.interp(tau, env.tau, env.value)) if env.tau[0] <= tau <= env.tau[-1] else None
    clock["residual"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    cam = dict.fromkeys(("profile", "x", "y", "phi_deg", "alpha_deg", "p0", "stress",
                         "extremes"))
    cam_warnings = []
    if geometry is not None:
        load = (inp.contact_force, None) if model_page else force
        key = ("cam", tuple(sorted(geometry.items())), ran.follower, inp.width, *load,
               not model_page)
        prof, table, p0, stress, extremes, cam_warnings = _memo(
            key, lambda: _cam(geometry, ran.follower, inp.width, *load, not model_page))
        cam.update(profile=prof, x=table["x_profile"], y=table["y_profile"],
                   phi_deg=table["phi_deg"], alpha_deg=table["alpha_deg"], p0=p0,
                   stress=stress, extremes=extremes)
    clock["profile"] = time.perf_counter() - t0
    return {
        "inputs": ran, "answer": ans, "sweep": sw, "T": _nominal_T(tgt, res), "Xdd": res[acc],
        "acceleration": acc, "tau_axis": sw.axes["tau"], "U0dd": sw["U0dd"],
        "U0dd_error": sw.columns.get("U0dd_error"), "sweep_warned": sw.warned,
        "env_tau": env.tau, "env_value": env.value,
        "design": {"tau": tau, "Fa": Fa, "stroke": h, "rise_time": t_m, "envelope": at},
        **cam, "profile_warnings": cam_warnings, "cam_note": cam_note,
        "contact_force": force, "seconds": clock,
    }


def page_warnings(out: dict) -> list:
    """Every warning of the page's answer: the run's, the cam's, the stress's, and how many
    points of the residual chart warned."""
    warnings = [*out["answer"].warnings, *out["profile_warnings"],
                *(out["stress"] or {}).get("warnings", [])]
    if out["sweep_warned"]:
        warnings.append(f"{out['sweep_warned']} of {len(out['tau_axis'])} tau points warned "
                        "(their estimates exceed half the figure)")
    return warnings


def cam_lines(out: dict) -> list:
    """The cam's figures as the report lists them, each ± its estimate (or why there are
    none)."""
    from ..core.display import plus_minus

    lines = []
    if out["contact_force"] is not None:
        lines.append(f"- contact force: the scene run's largest |F_x| (6.42), "
                     f"{plus_minus(*out['contact_force'])} N, all along the cam")
    if out["profile"] is None:
        return lines + [f"- not drawn: {out['cam_note']}"]
    ex, st = out["extremes"], out["stress"]
    return lines + [
        f"- largest |pressure angle|: "
        f"{plus_minus(ex['max_abs_pressure_angle_deg'], ex['max_abs_pressure_angle_deg_error'])} deg",
        f"- least radius of curvature of the profile: "
        f"{plus_minus(ex['min_rho_profile'], ex['min_rho_profile_error'])} m",
        f"- Hertz stress max: {plus_minus(st['hertz_stress_max'], st['hertz_stress_max_error'])} Pa "
        f"at {st['hertz_stress_max_angle_deg']:.1f} deg ({st['contact_force']})"]


def verdict(inp: Inputs, design_point: dict) -> dict:
    """The design rules' verdict (camdyn design, secs 8.2-8.5) at the design point: the
    requirement u0 <= accuracy met or not, and the rules with their status."""
    from camdyn.thesis.design.method import design

    return design(stroke=design_point["stroke"], rise_time=design_point["rise_time"],
                  tau=design_point["tau"], Fa=design_point["Fa"], accuracy=inp.accuracy,
                  law=inp.law, check=False)


# -- what the buttons export ------------------------------------------------------------------

def scene_toml(inp: Inputs) -> str:
    """The page's mechanism as a scene file: a DYNACAM scene with the page's parameters, or
    for a model the CAMSHAFT-1 study at its design point (its Fv, for CAMSHAFT-2, in a note:
    the study has none)."""
    import tomli_w

    from ..targets import scene_files

    if not is_model(inp.mechanism):
        data, _ = scene_files.read(inp.mechanism)
        data = dict(data)
        data["parameters"] = {**data.get("parameters", {}), **inp.scene_parameters}
        data["law"] = data.get("law", inp.law)
        return tomli_w.dumps(data)
    Fa = inp.Fa if inp.mechanism != "one_dof" else 0.0
    data = {"kind": "camshaft1-study",
            "title": f"{MODELS[inp.mechanism].split(':')[0]} at tau = {inp.tau:g} (camdyn serve)",
            "law": inp.law,
            "study": {"response": {"tau": inp.tau, "Fa": sorted({0.0, Fa})},
                      "graphs": {"tau_min": inp.tau_min, "tau_max": inp.tau_max, "n_tau": 240,
                                 "Fa": sorted({0.0, Fa})}},
            "run": {"method": "dp54", "rtol": 1e-9}}
    if inp.mechanism == "camshaft2":
        data["note"] = f"designed on CAMSHAFT-2 with Fv = {inp.Fv:g}; the study runs CAMSHAFT-1"
    return tomli_w.dumps(data)


def dxf_bytes(inp: Inputs) -> bytes:
    """The cam profile as DXF (camdyn profile's writer)."""
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        path = _profile(inp).write_dxf(Path(tmp) / "cam.dxf")
        return Path(path).read_bytes()


def report(inp: Inputs, out: dict, rules: dict | None) -> str:
    """The page's answer as Markdown: the inputs, every figure ± its estimate, the warnings,
    the profile's extremes and stress, the verdict."""
    from ..core.display import plus_minus

    ans = out["answer"]
    lines = [f"# camdyn design page: {inp.mechanism}, {inp.law} law", ""]
    if not is_model(inp.mechanism):
        lines += [f"The scene ran at rtol {SCENE_RTOL:g}, the page's tolerance; `camdyn simulate` "
                  "runs the tolerance of its file.", ""]
    lines += ["## Inputs", "", "| input | value |", "|---|---|"]
    lines += [f"| {k} | {v} |" for k, v in asdict(inp).items()]
    lines += ["", "## Figures (value ± error estimate)", "", "| figure | value |", "|---|---|"]
    lines += [f"| {k} | {plus_minus(v, ans.errors.get(k))} |" for k, v in ans.figures.items()]
    d = out["design"]
    lines += ["", f"Design point: tau = {d['tau']:.4g}, Fa = {d['Fa']:.4g}; U0'' envelope there "
              + (f"{d['envelope']:.4g}" if d["envelope"] is not None else "outside the chart"), ""]
    lines += ["## Cam", ""] + cam_lines(out) + [""]
    warnings = page_warnings(out)
    lines += ["## Warnings", ""] + ([f"- {w}" for w in warnings] or ["no warnings"]) + [""]
    if rules is not None:
        req = rules["requirement"]
        lines += ["## Design rules (secs 8.2-8.5)", "",
                  f"requirement u0 <= {inp.accuracy:g} m: {'met' if req['met'] else 'NOT met'} "
                  f"(envelope/requirement = {req['ratio']:.4g})", ""]
        lines += [f"- {r['status']} {r['rule']}: {r['text']}" for r in rules["rules"]]
    return "\n".join(lines) + "\n"


# -- the page ---------------------------------------------------------------------------------

_RULES = ThreadPoolExecutor(max_workers=1, thread_name_prefix="camdyn-rules")
"""The design rules' verdict runs here, beside the page's loop."""


def _range(key: str) -> str:
    """The range the models' manifests declare for ``key`` (the widest), as a label says it:
    the slider spans the usual values, its box takes any, and a value outside this range is
    refused with the manifest's own message."""
    from ..core.compiled import load

    for name in ("camshaft2", "camshaft1", "one_dof"):
        spec = {p["name"]: p for p in load(name).manifest["parameters"]}.get(key)
        if spec is not None:
            low = "<" if spec.get("open_low") else "<="
            high = "<" if spec.get("open_high") else "<="
            return f"{spec['low']:g} {low} {key} {high} {spec['high']:g}"
    return ""


SCENE_GIVES = ("base_radius", "stroke", "swing_deg", "pivot_distance", "arm_length",
               "face_offset", "rise_deg", "contact_force", "rise_time")
"""The fields a DYNACAM scene fills from its file and its run: shown, not edited."""

STALE = {"opacity": "0.35", "filter": "grayscale(100%)"}
"""How charts that no longer answer the inputs look."""

SCENE_NOTE = (
    "From the scene, not edited here: the law, the follower, the base radius (R_b less the "
    "roller's radius; a flat face's R_b), the stroke h_m (a rocker's swing h_m/l_a, pivot "
    "d_p, arm l_a), the rise angle beta_m (and its [turn]), the rise time beta_m/omega_s and "
    "the contact force: the largest |F_x| (6.42) of its run, all along the cam.  Its "
    "parameters are the fields above.")

NOT_DRAWN_NOTE = "The scene's cam is not drawn ({}): its panels are greyed out, its fields left out."

CAM_FIELDS = ("base_radius", "roller_radius", "swing_deg", "pivot_distance", "arm_length",
              "face_offset", "rise_deg", "contact_force", "width")
"""The fields of the follower and its cam, in the order the page lists them."""


def app():
    """One session's page (Panel calls it per browser tab)."""
    from contextlib import contextmanager

    import panel as pn
    from bokeh.models import ColumnDataSource, Span
    from bokeh.plotting import figure

    from ..core import display
    from ..targets import scene_files

    inp = Inputs()
    scenes = [n for n, kind, _ in scene_files.builtins() if kind == "dynacam"]
    menu = {**{v: k for k, v in MODELS.items()}, **{f"scene: {n}": n for n in scenes}}
    files: dict = {}           # "scene file: <path>" -> path, for the files opened in this tab
    mech = pn.widgets.Select(name="mechanism", options=dict(menu), value=inp.mechanism)
    scene_file = pn.widgets.TextInput(name="or a scene file (path, then Enter)",
                                      placeholder="my_scene.toml")
    law = pn.widgets.Select(name="law", options=list(LAWS), value=inp.law)
    sliders = {key: pn.widgets.EditableFloatSlider(
        name=f"{label}, {_range(key)}", start=start, end=end, step=step,
        value=getattr(inp, key), format="0.000", css_classes=[key])
        for key, label, start, end, step in (
            ("tau", "tau = T_e/t_m (4.12)", 0.02, 1.0, 0.001),
            ("Fa", "Fa, shaft stiffness (4.14)", 0.0, 5.0, 0.01),
            ("Fv", "Fv, cam mass (5.52)", 0.1, 100.0, 0.1))}
    fields = {k: pn.widgets.FloatInput(name=label, value=getattr(inp, k))
              for k, label in (("stroke", "stroke h_m' (m)"), ("rise_time", "rise time t_m (s)"),
                               ("accuracy", "requirement u0 <= (m)"),
                               ("base_radius", "base radius (m)"),
                               ("roller_radius", "roller radius (m)"),
                               ("swing_deg", "swing (deg)"), ("pivot_distance", "pivot distance (m)"),
                               ("arm_length", "arm length (m)"), ("face_offset", "face offset (m)"),
                               ("rise_deg", "rise angle (deg)"),
                               ("contact_force", "contact force (N)"),
                               ("width", "roller (or face) width (m)"))}
    follower = pn.widgets.Select(name="follower", options=list(FOLLOWERS), value=inp.follower)
    scene_box = pn.Column()
    scene_fields: dict = {}
    scene_note = pn.pane.Markdown(SCENE_NOTE, visible=False, css_classes=["camdyn-scene-note"])
    alert = pn.pane.Alert("", alert_type="danger", visible=False, css_classes=["camdyn-error"])
    figures_md = pn.pane.HTML("", css_classes=["camdyn-figures"])
    verdict_md = pn.pane.Markdown("", css_classes=["camdyn-verdict"])
    timing = pn.pane.Markdown("", css_classes=["camdyn-timing"])

    src_resp = ColumnDataSource({"T": [], "y": []}, name="response")
    f_resp = figure(height=260, width=520, title="response", x_axis_label="T = t/t_m",
                    y_axis_label="X''")
    f_resp.line("T", "y", source=src_resp)
    src_sw = ColumnDataSource({"tau": [], "v": [], "lo": [], "hi": []})
    src_env = ColumnDataSource({"tau": [], "v": []})
    f_env = figure(height=260, width=520, title="residual U0'' against tau", x_axis_label="tau",
                   y_axis_label="U0''", y_axis_type="log")
    f_env.varea("tau", "lo", "hi", source=src_sw, alpha=0.3)
    f_env.line("tau", "v", source=src_sw, legend_label="U0'' ± estimate")
    f_env.line("tau", "v", source=src_env, color="firebrick", legend_label="envelope")
    mark = Span(location=inp.tau, dimension="height", line_color="green", line_dash="dashed")
    f_env.add_layout(mark)
    src_prof = ColumnDataSource({"x": [], "y": []}, name="profile")
    f_prof = figure(height=300, width=300, title="cam profile", match_aspect=True)
    f_prof.line("x", "y", source=src_prof)
    src_alpha = ColumnDataSource({"phi": [], "alpha": [], "p0": []}, name="cam")
    f_alpha = figure(height=150, width=420, title="pressure angle (deg)",
                     x_axis_label="cam angle (deg)")
    f_alpha.line("phi", "alpha", source=src_alpha)
    f_p0 = figure(height=150, width=420, title="Hertz contact stress p0 (MPa)",
                  x_axis_label="cam angle (deg)", x_range=f_alpha.x_range)
    f_p0.line("phi", "p0", source=src_alpha, color="darkorange")
    cam_box = pn.Row(pn.pane.Bokeh(f_prof), pn.Column(pn.pane.Bokeh(f_alpha), pn.pane.Bokeh(f_p0)),
                     css_classes=["camdyn-cam"])
    body = pn.Column(pn.Row(pn.pane.Bokeh(f_resp), pn.pane.Bokeh(f_env)), cam_box,
                     pn.Row(figures_md, verdict_md), css_classes=["camdyn-charts"])
    last: dict = {}
    designer: dict = {}        # a model's own fields and law, kept while a scene fills them
    asked: dict = {}           # what the next turn of the loop answers (answer_later)
    hush = [False]

    @contextmanager
    def quietly():
        # the page setting a widget to show what ran: not a change of the designer's
        hush[0] = True
        try:
            yield
        finally:
            hush[0] = False

    def read() -> Inputs:
        values = {k: w.value for k, w in fields.items()}
        values.update({k: w.value for k, w in sliders.items()})
        params = {k: w.value for k, w in scene_fields.items()}
        return replace(inp, mechanism=mech.value, law=law.value, follower=follower.value,
                       scene_parameters=params, **values)

    def show_law(name: str) -> None:
        with quietly():
            if name not in law.options:
                law.options = [*LAWS, name]
            law.value = name

    def shown(ran: Inputs) -> None:
        """Every widget shows what ran: a scene's law, follower and cam fields."""
        show_law(ran.law)
        with quietly():
            follower.value = ran.follower
            for k, w in fields.items():
                if w.value != getattr(ran, k):
                    w.value = getattr(ran, k)

    def show(out: dict) -> None:
        # a chart whose answer came from the memo unchanged is not sent again: less to carry
        # over the websocket and to draw
        ans, before = out["answer"], last.get("out") or {}
        if ans is not before.get("answer"):
            src_resp.data = {"T": out["T"], "y": out["Xdd"]}
            f_resp.yaxis.axis_label = out["acceleration"]
        if out["sweep"] is not before.get("sweep"):
            e = out["U0dd_error"]
            e = np.zeros_like(out["U0dd"]) if e is None else np.nan_to_num(e)
            v = np.maximum(out["U0dd"], 1e-12)
            src_sw.data = {"tau": out["tau_axis"], "v": v, "lo": np.maximum(v - e, 1e-12),
                           "hi": v + e}
            src_env.data = {"tau": out["env_tau"], "v": np.maximum(out["env_value"], 1e-12)}
        mark.location = out["design"]["tau"]
        drawn = out["profile"] is not None
        if not drawn:
            src_prof.data = {"x": [], "y": []}
            src_alpha.data = {"phi": [], "alpha": [], "p0": []}
            f_prof.title.text = "cam profile: not drawn (see the figures)"
        elif out["profile"] is not before.get("profile"):
            src_prof.data = {"x": out["x"], "y": out["y"]}
            p0 = np.where(np.isfinite(out["p0"]), out["p0"] / 1e6, np.nan)
            src_alpha.data = {"phi": out["phi_deg"], "alpha": out["alpha_deg"], "p0": p0}
            f_prof.title.text = "cam profile"
        cam_box.styles = {} if drawn else STALE
        # a cam not drawn leaves the follower's fields out: they would show a cam that never ran
        for w in (follower, *(fields[k] for k in CAM_FIELDS)):
            w.visible = drawn
        scene_note.object = SCENE_NOTE if drawn else NOT_DRAWN_NOTE.format(out["cam_note"])
        dxf.disabled = not drawn
        figures_md.object = display.table(["figure", "value ± error"], figure_rows(out)) \
            + display.warnings_block(page_warnings(out))

    def figure_rows(out: dict) -> list:
        ans = out["answer"]
        rows = [[k, display.plus_minus(v, ans.errors.get(k))] for k, v in ans.figures.items()]
        if out["contact_force"] is not None:
            rows.append(["contact force: largest |F_x| of the run (N)",
                         display.plus_minus(*out["contact_force"])])
        if out["profile"] is None:
            return rows + [["cam", f"not drawn: {out['cam_note']}"]]
        ex, st = out["extremes"], out["stress"]
        return rows + [
            ["max |pressure angle| (deg)", display.plus_minus(
                ex["max_abs_pressure_angle_deg"], ex["max_abs_pressure_angle_deg_error"])],
            ["min rho profile (m)", display.plus_minus(ex["min_rho_profile"],
                                                       ex["min_rho_profile_error"])],
            ["Hertz stress max (Pa)", display.plus_minus(st["hertz_stress_max"],
                                                         st["hertz_stress_max_error"])]]

    doc = pn.state.curdoc

    def rules_text(now: Inputs, point: dict) -> str:
        try:
            d = verdict(now, point)
        except CamdynInputError as exc:
            return f"design rules: {exc}"
        if last.get("inputs") is now:
            last["rules"] = d
        req = d["requirement"]
        return (f"**requirement u0 <= {now.accuracy:g} m: {'met' if req['met'] else 'NOT met'}** "
                f"(envelope/requirement {req['ratio']:.3g})\n\n"
                + "\n".join(f"- {r['status']} {r['rule']}: {r['text']}" for r in d["rules"]))

    def rules_later(now: Inputs, point: dict) -> None:
        # in a thread, so that the charts' update leaves first; the page takes the text back
        # on its own loop, and only if no later change came meanwhile
        def done(future):
            if last.get("inputs") is now:
                doc.add_next_tick_callback(lambda: setattr(verdict_md, "object", future.result()))
        _RULES.submit(rules_text, now, point).add_done_callback(done)

    def refuse(exc: Exception) -> None:
        """A refused input: its one line above the charts, which still answer the last
        inputs that ran and are greyed out as stale."""
        alert.object = (str(exc).splitlines() or [type(exc).__name__])[0]
        alert.visible = True
        if last:
            body.styles = STALE
            body.css_classes = ["camdyn-charts", "camdyn-stale"]
            timing.object = (f"**stale**: the charts and figures below answer the last inputs "
                             f"that ran ({last['inputs'].mechanism}), not the refused one")

    def fresh() -> None:
        alert.visible = False
        body.styles = {}
        body.css_classes = ["camdyn-charts"]

    def update() -> None:
        start = time.perf_counter()
        now = read()
        try:
            out = evaluate(now)
        except (CamdynInputError, SimulationError, ValueError) as exc:
            refuse(exc)
            return
        fresh()
        ran = out["inputs"]
        with quietly():     # a refused path typed earlier is not what runs now
            scene_file.value = ran.mechanism if ran.mechanism in files.values() else ""
        shown(ran)
        show(out)
        last.update(inputs=ran, out=out, rules=None)
        timing.object = (f"answered in {1e3 * (time.perf_counter() - start):.0f} ms"
                         + ("" if is_model(now.mechanism) else
                            f" (the scene at rtol {SCENE_RTOL:g}; its file's in camdyn simulate)"))
        verdict_md.object = "design rules: ..."
        rules_later(ran, out["design"])

    def arrange(name: str, tgt) -> None:
        """The controls of the mechanism ``name``: a model's sliders and fields, or a
        scene's parameters as fields beside its law, follower and cam, shown, not edited
        (a model's own values come back when a model is picked again)."""
        scene = tgt is not None
        takes = {"one_dof": ("tau",), "camshaft1": ("tau", "Fa")}.get(name, ("tau", "Fa", "Fv"))
        for key, w in sliders.items():
            w.visible = not scene and key in takes
        with quietly():
            if scene and not designer:
                designer.update({k: w.value for k, w in fields.items()}, law=law.value,
                                follower=follower.value)
            elif not scene and designer:
                for k, w in fields.items():
                    w.value = designer[k]
                law.options = list(LAWS)
                law.value, follower.value = designer["law"], designer["follower"]
                designer.clear()
            scene_file.value = name if name in files.values() else ""
        if scene:
            show_law(tgt.scene.law)
        law.disabled = follower.disabled = scene
        for k in SCENE_GIVES:
            fields[k].disabled = scene
        scene_fields.clear()
        if scene:
            specs = scene_files.declared_parameters(tgt.scene.options)
            for k, v in tgt.scene.parameters.items():
                unit = specs[k].unit if k in specs else ""
                scene_fields[k] = pn.widgets.FloatInput(
                    name=f"{k} ({unit})" if unit and unit != "1" else k, value=float(v),
                    description=specs[k].doc if k in specs else None)
        scene_box.objects = list(scene_fields.values())
        for w in scene_fields.values():
            w.param.watch(changed, "value")
        scene_note.visible = scene

    def open_mechanism(name: str, from_file: bool) -> bool:
        """Switch to the mechanism ``name`` (a model, a built-in scene, a scene file); a scene
        that cannot be read is refused and the page stays on what ran."""
        try:
            tgt = None if is_model(name) else scene_target(name)
        except CamdynInputError as exc:
            refuse(exc)
            return False
        if from_file:
            files[f"scene file: {name}"] = name
            with quietly():
                mech.options = {**menu, **files}
                mech.value = name
        arrange(name, tgt)
        return True

    served = doc is not None and doc.session_context is not None

    def answer_later(**what) -> None:
        """Answer a change on the page's next turn of the server's loop, which holds the
        document's lock: Panel calls a watcher without it when the change comes with a
        browser event (a text box's Enter), and Bokeh refuses a chart's change made so
        (module doc).  Changes that come before that turn are answered together, with the
        widgets' latest values."""
        if hush[0]:
            return
        queued = bool(asked)
        asked.update(what, update=True)
        if queued:
            return
        if served:
            pn.state.execute(answer_now, schedule=True)
        else:
            answer_now()

    def answer_now() -> None:
        what = dict(asked)
        asked.clear()
        name = what.get("mechanism")
        if name is not None and not open_mechanism(name, what.get("from_file", False)):
            return
        update()

    def changed(*_) -> None:
        answer_later()

    def mechanism_picked(event) -> None:
        answer_later(mechanism=event.new, from_file=False)

    def file_entered(event) -> None:
        if event.new.strip():
            answer_later(mechanism=event.new.strip(), from_file=True)

    for w in [law, follower, *sliders.values(), *fields.values()]:
        w.param.watch(changed, "value")
    mech.param.watch(mechanism_picked, "value")
    scene_file.param.watch(file_entered, "value")

    dxf = pn.widgets.FileDownload(callback=lambda: io.BytesIO(dxf_bytes(last["inputs"])),
                                  filename="cam.dxf", label="cam DXF", css_classes=["export-dxf"])
    downloads = pn.Row(
        pn.widgets.FileDownload(callback=lambda: io.BytesIO(scene_toml(last["inputs"]).encode()),
                                filename="scene.toml", label="scene TOML", css_classes=["export-toml"]),
        dxf,
        pn.widgets.FileDownload(callback=lambda: io.BytesIO(report(last["inputs"], last["out"],
                                                                   last.get("rules")).encode()),
                                filename="report.md", label="report", css_classes=["export-report"]))
    controls = pn.Column("## Mechanism", mech, scene_file, law, *sliders.values(), scene_box,
                         "## Design", fields["stroke"], fields["rise_time"], fields["accuracy"],
                         "## Follower", follower, scene_note, *[fields[k] for k in CAM_FIELDS],
                         width=320)
    charts = pn.Column(alert, timing, body, downloads)
    arrange(inp.mechanism, None)
    update()
    return pn.Row(controls, charts)
