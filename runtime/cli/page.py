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
  sampling error;
* the verdict of the design rules of secs 8.2-8.5 (camdyn design), made on the next tick so
  that the charts answer first.

:func:`evaluate` is the page without the page: the inputs in, every figure out, so that it
can be tested and timed alone; bad input raises the CamdynInputError the command line
prints, and the page shows its one line.
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


def _target(inp: Inputs):
    from ..targets.resolve import resolve

    if is_model(inp.mechanism):
        values = {"tau": inp.tau, "Fa": inp.Fa, "Fv": inp.Fv}
        tgt = resolve(inp.mechanism, law=inp.law)
        names = tgt.parameters()
        return tgt.with_parameters({k: v for k, v in values.items() if k in names})
    tgt = resolve(inp.mechanism).with_settings(rtol=SCENE_RTOL)
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


def _profile(inp: Inputs):
    from ..cam.profile import CamProfile

    oscillating, roller = inp.follower.startswith("oscillating"), inp.follower.endswith("roller")
    dwell = (360.0 - 2 * inp.rise_deg) / 2
    if not 0 < inp.rise_deg < 180:
        raise CamdynInputError(f"rise={inp.rise_deg:g} deg is out of range: 0 < rise < 180 (the "
                               "return takes as long, the dwells share the rest)")
    return CamProfile(
        follower=inp.follower, base_radius=inp.base_radius,
        roller_radius=inp.roller_radius if roller else None,
        stroke=None if oscillating else inp.stroke,
        swing_deg=inp.swing_deg if oscillating else None,
        pivot_distance=inp.pivot_distance if oscillating else None,
        arm_length=inp.arm_length if oscillating and roller else None,
        face_offset=inp.face_offset if oscillating and not roller else 0.0,
        angles_deg=(inp.rise_deg, dwell, inp.rise_deg, dwell), law=inp.law, points_per_degree=2)


def _stress(prof, inp: Inputs):
    from ..cam.load import ContactLoad
    from ..cam.stress import ContactSpec

    roller = inp.follower.endswith("roller")
    spec = ContactSpec(ContactLoad(force=inp.contact_force),
                       roller_width=inp.width if roller else None,
                       cam_width=None if roller else inp.width)
    _, p0 = prof.contact_stress(prof.phi, spec)
    return p0, prof.stress_summary(spec)


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


def _cam(inp: Inputs) -> tuple:
    prof = _profile(inp)
    table = prof.table
    p0, stress = _stress(prof, inp)
    return prof, table, p0, stress, prof.extremes(), prof.summary()["warnings"]


def evaluate(inp: Inputs) -> dict:
    """Every figure of the page for ``inp`` (see the module doc), with the seconds each part
    took; the design rules' verdict is :func:`verdict`."""
    from ..measure.contract import answer
    from ..measure.envelope import envelope, tau_grid
    from ..studies.sweep import sweep

    clock = {}
    t0 = time.perf_counter()
    tgt = _target(inp)
    given = ((inp.tau, inp.Fa, inp.Fv) if is_model(inp.mechanism)
             else tuple(sorted(inp.scene_parameters.items())))
    ans = _memo(("response", inp.mechanism, _stamp(inp.mechanism), inp.law, given),
                lambda: answer(tgt))
    res = ans.result
    acc = res.model.manifest.get("residual", {}).get("acceleration") or res.state_names[0]
    clock["response"] = time.perf_counter() - t0
    tau, Fa, h, t_m = _characteristics(inp, tgt)
    t0 = time.perf_counter()
    if not 0 < inp.tau_min < inp.tau_max:
        raise CamdynInputError(f"tau range {inp.tau_min:g} to {inp.tau_max:g}: needs "
                               "0 < tau min < tau max")
    model = inp.mechanism if is_model(inp.mechanism) else "camshaft1"
    n_tau, rtol = CHART[model]
    graph = _target(replace(inp, mechanism=model, Fa=Fa)).with_settings(method="dop853", rtol=rtol)
    taus = tau_grid(inp.tau_min, inp.tau_max, n_tau)
    sw = _memo(("residual", model, inp.law, Fa, inp.Fv if model == "camshaft2" else None,
                inp.tau_min, inp.tau_max),
               lambda: sweep(graph, {"tau": taus}, progress=False, jobs=1))
    env = envelope(sw.axes["tau"], sw["U0dd"])
    at = float(np.interp(tau, env.tau, env.value)) if env.tau[0] <= tau <= env.tau[-1] else None
    clock["residual"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    key = ("cam", inp.follower, inp.base_radius, inp.roller_radius, inp.stroke, inp.swing_deg,
           inp.pivot_distance, inp.arm_length, inp.face_offset, inp.rise_deg, inp.law,
           inp.contact_force, inp.width)
    prof, table, p0, stress, extremes, cam_warnings = _memo(key, lambda: _cam(inp))
    clock["profile"] = time.perf_counter() - t0
    return {
        "answer": ans, "sweep": sw, "T": res.t, "Xdd": res[acc], "acceleration": acc,
        "tau_axis": sw.axes["tau"], "U0dd": sw["U0dd"], "U0dd_error": sw.columns.get("U0dd_error"),
        "sweep_warned": sw.warned, "env_tau": env.tau, "env_value": env.value,
        "design": {"tau": tau, "Fa": Fa, "stroke": h, "rise_time": t_m, "envelope": at},
        "profile": prof, "x": table["x_profile"], "y": table["y_profile"],
        "phi_deg": table["phi_deg"], "alpha_deg": table["alpha_deg"], "p0": p0,
        "stress": stress, "extremes": extremes, "profile_warnings": cam_warnings,
        "seconds": clock,
    }


def page_warnings(out: dict) -> list:
    """Every warning of the page's answer: the run's, the cam's, the stress's, and how many
    points of the residual chart warned."""
    warnings = [*out["answer"].warnings, *out["profile_warnings"],
                *out["stress"].get("warnings", [])]
    if out["sweep_warned"]:
        warnings.append(f"{out['sweep_warned']} of {len(out['tau_axis'])} tau points warned "
                        "(their estimates exceed half the figure)")
    return warnings


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
    ex, st = out["extremes"], out["stress"]
    lines += ["## Cam", "", f"- largest |pressure angle|: "
              f"{plus_minus(ex['max_abs_pressure_angle_deg'], ex['max_abs_pressure_angle_deg_error'])} deg",
              f"- least radius of curvature of the profile: "
              f"{plus_minus(ex['min_rho_profile'], ex['min_rho_profile_error'])} m",
              f"- Hertz stress max: {plus_minus(st['hertz_stress_max'], st['hertz_stress_max_error'])} Pa "
              f"at {st['hertz_stress_max_angle_deg']:.1f} deg ({st['contact_force']})", ""]
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


def app():
    """One session's page (Panel calls it per browser tab)."""
    import panel as pn
    from bokeh.models import ColumnDataSource, Span
    from bokeh.plotting import figure

    from ..core import display
    from ..targets import scene_files

    inp = Inputs()
    scenes = [n for n, kind, _ in scene_files.builtins() if kind == "dynacam"]
    mech = pn.widgets.Select(name="mechanism", options={**{v: k for k, v in MODELS.items()},
                                                         **{f"scene: {n}": n for n in scenes}},
                             value=inp.mechanism)
    scene_file = pn.widgets.TextInput(name="or a scene file (path)", placeholder="my_scene.toml")
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
    src_prof = ColumnDataSource({"x": [], "y": []})
    f_prof = figure(height=300, width=300, title="cam profile", match_aspect=True)
    f_prof.line("x", "y", source=src_prof)
    src_alpha = ColumnDataSource({"phi": [], "alpha": [], "p0": []}, name="cam")
    f_alpha = figure(height=150, width=420, title="pressure angle (deg)",
                     x_axis_label="cam angle (deg)")
    f_alpha.line("phi", "alpha", source=src_alpha)
    f_p0 = figure(height=150, width=420, title="Hertz contact stress p0 (MPa)",
                  x_axis_label="cam angle (deg)", x_range=f_alpha.x_range)
    f_p0.line("phi", "p0", source=src_alpha, color="darkorange")
    last = {}

    def read() -> Inputs:
        values = {k: w.value for k, w in fields.items()}
        values.update({k: w.value for k, w in sliders.items()})
        mechanism = scene_file.value.strip() or mech.value
        params = {k: w.value for k, w in scene_fields.items()}
        return replace(inp, mechanism=mechanism, law=law.value, follower=follower.value,
                       scene_parameters=params, **values)

    def show(out: dict, now: Inputs) -> None:
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
        if out["profile"] is not before.get("profile"):
            src_prof.data = {"x": out["x"], "y": out["y"]}
            p0 = np.where(np.isfinite(out["p0"]), out["p0"] / 1e6, np.nan)
            src_alpha.data = {"phi": out["phi_deg"], "alpha": out["alpha_deg"], "p0": p0}
        ex, st = out["extremes"], out["stress"]
        rows = [[k, display.plus_minus(v, ans.errors.get(k))] for k, v in ans.figures.items()]
        rows += [["max |pressure angle| (deg)", display.plus_minus(
                     ex["max_abs_pressure_angle_deg"], ex["max_abs_pressure_angle_deg_error"])],
                 ["min rho profile (m)", display.plus_minus(ex["min_rho_profile"],
                                                            ex["min_rho_profile_error"])],
                 ["Hertz stress max (Pa)", display.plus_minus(st["hertz_stress_max"],
                                                              st["hertz_stress_max_error"])]]
        figures_md.object = display.table(["figure", "value ± error"], rows) \
            + display.warnings_block(page_warnings(out))

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

    def update(*_):
        start = time.perf_counter()
        now = read()
        try:
            out = evaluate(now)
        except (CamdynInputError, SimulationError, ValueError) as exc:
            alert.object = str(exc).splitlines()[0]
            alert.visible = True
            return
        alert.visible = False
        show(out, now)
        last.update(inputs=now, out=out, rules=None)
        timing.object = (f"answered in {1e3 * (time.perf_counter() - start):.0f} ms"
                         + ("" if is_model(now.mechanism) else
                            f" (the scene at rtol {SCENE_RTOL:g}; its file's in camdyn simulate)"))
        verdict_md.object = "design rules: ..."
        rules_later(now, out["design"])

    def scene_changed(*_):
        scene_fields.clear()
        name = scene_file.value.strip() or mech.value
        takes = {"one_dof": ("tau",), "camshaft1": ("tau", "Fa")}.get(name, ("tau", "Fa", "Fv"))
        for key, w in sliders.items():
            w.visible = is_model(name) and key in takes
        if not is_model(name):
            try:
                tgt = _target(replace(inp, mechanism=name))
                specs = scene_files.declared_parameters(tgt.scene.options)
                for k, p in tgt.scene.parameters.items():
                    unit = specs[k].unit if k in specs else ""
                    scene_fields[k] = pn.widgets.FloatInput(
                        name=f"{k} ({unit})" if unit and unit != "1" else k, value=float(p),
                        description=specs[k].doc if k in specs else None)
            except CamdynInputError as exc:
                alert.object, alert.visible = str(exc).splitlines()[0], True
        scene_box.objects = list(scene_fields.values())
        for w in scene_fields.values():
            w.param.watch(update, "value")
        update()

    for w in [law, follower, *sliders.values(), *fields.values()]:
        w.param.watch(update, "value")
    mech.param.watch(scene_changed, "value")
    scene_file.param.watch(scene_changed, "value")

    downloads = pn.Row(
        pn.widgets.FileDownload(callback=lambda: io.BytesIO(scene_toml(last["inputs"]).encode()),
                                filename="scene.toml", label="scene TOML", css_classes=["export-toml"]),
        pn.widgets.FileDownload(callback=lambda: io.BytesIO(dxf_bytes(last["inputs"])),
                                filename="cam.dxf", label="cam DXF", css_classes=["export-dxf"]),
        pn.widgets.FileDownload(callback=lambda: io.BytesIO(report(last["inputs"], last["out"],
                                                                   last.get("rules")).encode()),
                                filename="report.md", label="report", css_classes=["export-report"]))
    controls = pn.Column("## Mechanism", mech, scene_file, law, *sliders.values(), scene_box,
                         "## Design", fields["stroke"], fields["rise_time"], fields["accuracy"],
                         "## Follower", follower,
                         *[fields[k] for k in ("base_radius", "roller_radius", "swing_deg",
                                               "pivot_distance", "arm_length", "face_offset",
                                               "rise_deg", "contact_force", "width")],
                         width=320)
    charts = pn.Column(alert, timing, pn.Row(pn.pane.Bokeh(f_resp), pn.pane.Bokeh(f_env)),
                       pn.Row(pn.pane.Bokeh(f_prof),
                              pn.Column(pn.pane.Bokeh(f_alpha), pn.pane.Bokeh(f_p0))),
                       pn.Row(figures_md, verdict_md), downloads)
    scene_changed()
    return pn.Row(controls, charts)
