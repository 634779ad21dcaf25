"""Design by the rules: what a designer knows in, the thesis's answer out.

Secs 8.3, 8.5, 8.6 and App. 7 describe one method, which :func:`design` follows:

1. the machine's figures: T_e = 2 pi (m/c_c)^(1/2) (4.39), t_m = beta_m/w_s (App. 7 (8)),
   tau = T_e/t_m (4.12), tan alpha_me = h_m'/(i R_1/2 beta_m) (4.13), Fa = (c_c/c_tan)
   tan^2 alpha_me (4.14), the stiffness dip 1 + H'max^2 Fa (4.18), (4.19) (:mod:`.machine`);
2. the response at (tau, Fa) read from the graphs U0(tau, Fa), U0''(tau, Fa) of fig. 4.11, i.e.
   from the envelopes through their maxima (secs 3.5, 8.2.6): a designer never counts on a
   tuning dip (:mod:`.graphs`);
3. the requirement (positional accuracy u0 = U0 h_m', residual acceleration
   u0'' = U0'' h_m'/t_m^2, sec. 3.3) turned into limits: the largest Fa at the given tau
   and the largest tau at the given Fa (:mod:`.limits`);
4. the rules of sec. 8.5 the input breaks (and the remedies (8.5) suggests) (:mod:`.rules`);
5. the motor by sec. 8.3 (:mod:`.motor_sizing`);
6. a check run of the design point with the least model that is adequate, its U0, U0'' with
   error estimates beside the envelope values (:mod:`.check_run`).
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from camdyn.runtime.core import laws
from camdyn.runtime.core.errors import CamdynInputError, SimulationError
from camdyn.runtime.core.outdir import write_text, writing
from camdyn.runtime.measure.contract import chart_note, quotient
from camdyn.thesis.theory import examples as ex

from .check_run import check_answer, check_run, least_model, turn_runs
from .graphs import PER_DIP, Graphs, Upper, phase_factor, run_errors
from .limits import Requirement, largest_Fa, largest_tau
from .machine import Machine, machine, positive
from .motor_sizing import motor
from .rules import rules
from .spring_flywheel import (LawMotion, Motions, RunMotion, check_fluctuation, check_margin,
                              flywheel, spring)
from .turn import CamTurn, angles_argument, rise_angle


def design(*, stroke, rise_time=None, cam_angle_rad=None, speed=None, mass=None, stiffness=None,
           tau=None, Fa=None, c_tan=None, pitch_radius=None, ratio=None, tan_alpha_me=None,
           accuracy=None, residual_acceleration=None, law="cycloidal", theta=None,
           common_shaft=False, motor_args: dict | None = None, check: bool = True,
           per_dip: int = PER_DIP, progress=None, chart_path=None, spring_margin=None,
           spring_rate=None, spring_mass=None, speed_fluctuation=None, angles=None,
           arm_length=None) -> dict:
    """The thesis's design method (module doc) as one dict (the JSON of `camdyn design`);
    with ``spring_margin`` also the least follower spring and with ``speed_fluctuation`` the
    camshaft's flywheel, both over the rise alone or, with ``angles`` (rise, outer dwell,
    return, inner dwell in deg, or the text 'R,D,F,D'), over the whole turn, kinetostatic and
    with the check run's model (:mod:`.spring_flywheel`, :mod:`.turn`); ``arm_length`` (a
    rocker's) adds the spring at the pivot."""
    say = progress or (lambda msg: None)
    angles = angles_argument(angles) if isinstance(angles, str) or angles is None else \
        angles_argument(",".join(str(a) for a in angles))
    cam_angle_rad = rise_angle(angles, cam_angle_rad, rise_time, speed)
    M = machine(stroke=stroke, rise_time=rise_time, cam_angle_rad=cam_angle_rad, speed=speed,
                mass=mass, stiffness=stiffness, tau=tau, Fa=Fa, c_tan=c_tan,
                pitch_radius=pitch_radius, ratio=ratio, tan_alpha_me=tan_alpha_me)
    spring_rate = positive("spring rate", "--spring-rate", spring_rate, "N/m")
    spring_mass = positive("spring mass", "--spring-mass", spring_mass, "kg, the active coils'")
    _spring_inputs(M, check, spring_margin, spring_rate, spring_mass, speed_fluctuation)
    acc = positive("accuracy", "--accuracy", accuracy, "m, largest positional error u0")
    a_req = positive("acceleration", "--residual-acceleration", residual_acceleration,
                      "m/s^2, largest residual acceleration u0''")
    if a_req is not None and M.t_m is None:
        raise CamdynInputError("argument --residual-acceleration: needs the rise time "
                               "(--rise-time, or --cam-angle with --speed): u0'' = U0'' h_m'/t_m^2")
    choice = laws.choose(law, theta)
    if motor_args is not None:
        if law != "cycloidal":
            raise CamdynInputError("argument --law: the motor rules (8.1)-(8.4) and fig. 8.6 are "
                                   "the cycloid's (its torque H' H'', (A.2.14)); use --law cycloidal "
                                   "with a motor")
        if M.t_m is None:
            raise CamdynInputError("the motor (sec. 8.3) needs the rise time: tau_m = T_m/t_m")
    turn = CamTurn.of(law, theta, angles,
                      math.radians(angles[0]) if angles is not None else M.beta_m)
    graphs = Graphs(law, theta, per_dip)
    H1 = float(np.max(np.abs(choice.evaluate(np.linspace(0, 1, 2001))[:, 1])))
    out = {"law": law, "theta": choice.par if theta is not None or law == "modified-sine" else None,
           "machine": {"stroke": M.stroke, "t_m": M.t_m, "T_e": M.T_e, "tau": M.tau,
                       "tan_alpha_me": M.tan_alpha_me, "Fa": M.Fa, "mass": M.mass,
                       "stiffness": M.stiffness, "c_tan": M.c_tan, "beta_m": M.beta_m,
                       "w_s": M.w_s, "ratio": M.ratio, "pitch_radius": M.pitch_radius,
                       "dip": ex.stiffness_dip(M.Fa, H1),
                       "c_min": None if M.stiffness is None else M.stiffness / ex.stiffness_dip(M.Fa, H1),
                       "freq_factor": ex.frequency_factor(M.Fa, H1),
                       "sources": M.sources}}
    say(f"envelope at tau = {M.tau:.4g}, Fa = {M.Fa:.4g}")
    U0e, U2e = graphs.at(M.tau, M.Fa)
    U0f, U2f = graphs.at(M.tau, M.Fa, per_dip=2 * per_dip)      # reported; U0e for its error
    U00, U20 = graphs.at(M.tau, 0.0)
    # the envelope's accuracy: twice the samples per dip; no less than the graph runs' own
    # error (graphs.RUN_ERROR)
    e0, e2 = run_errors(U0f, U2f)
    env = {"U0": U0f, "U0_error": max(abs(U0f - U0e), e0), "U0dd": U2f,
           "U0dd_error": max(abs(U2f - U2e), e2),
           "U0_Fa0": U00, "U0dd_Fa0": U20, "u0": U0f * M.stroke,
           "u0dd": None if M.t_m is None else U2f * M.stroke / M.t_m**2,
           # (8.5) is (3.5)'s envelope for small tau: the cycloid's only
           "eq_8_5_u0": M.stroke * M.tau**3 / math.pi if law == "cycloidal" else None}
    env.update(_scaled(env, M))
    out["envelope"] = env
    req = Requirement(M.stroke, acc, a_req)
    ratio_design = None
    if acc is not None or a_req is not None:
        ratio_design = req.ratio(U0f, U2f, M.t_m)
        out["requirement"] = {"accuracy": acc, "residual_acceleration": a_req,
                              "ratio": float(ratio_design),
                              "ratio_error": _ratio_error(req, env, M.t_m),
                              "met": bool(ratio_design <= 1.0)}
        say("largest Fa at this tau")
        lf = largest_Fa(graphs, M.tau, req, M.t_m)
        if lf.get("Fa_max") is not None and M.tan_alpha_me is not None and M.stiffness is not None:
            lf["c_tan_min"], lf["c_tan_min_error"] = quotient(
                M.stiffness * M.tan_alpha_me**2, 0.0, lf["Fa_max"], lf.get("Fa_max_error") or 0.0)
        if lf.get("Fa_max") and M.Fa > 0:
            # torsion-dominated shaft: c_tan ~ d^4 (sec. 8.2.8, "2^(1/4) = 1.19")
            lf["shaft_diameter_factor"] = (M.Fa / lf["Fa_max"]) ** 0.25
            lo = lf["Fa_max"] - (lf.get("Fa_max_error") or 0.0)
            lf["shaft_diameter_factor_error"] = ((M.Fa / lo) ** 0.25 - lf["shaft_diameter_factor"]
                                                 if lo > 0 else math.inf)
        out["largest_Fa"] = lf
        say("largest tau (smallest t_m) at this Fa")
        lt = largest_tau(graphs, M.Fa, M.tau, req, T_e=M.T_e)
        if lt.get("tau_max") is not None and M.T_e is not None:
            lt["t_m_min"] = M.T_e / lt["tau_max"]
            if lt.get("tau_max_error") is not None:
                lt["t_m_min_error"] = lt["t_m_min"] * lt["tau_max_error"] / lt["tau_max"]
            lt["speed_factor"] = lt["tau_max"] / M.tau
            lt["speed_factor_error"] = (None if lt.get("tau_max_error") is None
                                        else lt["tau_max_error"] / M.tau)
        out["largest_tau"] = lt
        if M.t_m is not None:
            # the same question at this t_m: the softest follower, T_e = tau t_m (sec. 8.6)
            say("largest T_e (least c_c/m) at this t_m")
            le = lt if req.acceleration is None else largest_tau(graphs, M.Fa, M.tau, req, t_m=M.t_m)
            le = {"tau_max": le.get("tau_max"), "tau_max_error": le.get("tau_max_error"),
                  "limited_by": le.get("limited_by"), "reason": le.get("reason")}
            if le["tau_max"] is not None:
                le["T_e_max"] = le["tau_max"] * M.t_m
                if le["tau_max_error"] is not None:
                    le["T_e_max_error"] = le["tau_max_error"] * M.t_m
                if M.mass is not None:
                    le["c_c_min"] = M.mass * (2 * math.pi / le["T_e_max"]) ** 2
                    e = le.get("T_e_max_error")
                    le["c_c_min_error"] = (None if e is None else math.inf if e >= le["T_e_max"]
                                           else M.mass * (2 * math.pi / (le["T_e_max"] - e)) ** 2
                                           - le["c_c_min"])
            out["largest_T_e"] = le
    motor_out = None
    if motor_args is not None:
        say("motor (sec. 8.3)")
        motor_out = motor(t_m=M.t_m, mass=M.mass, stroke=M.stroke, w_s=M.w_s, **motor_args)
        out["motor"] = motor_out
    out["rules"] = rules(M, ratio_design or 0.0, common_shaft, motor_out,
                         req.which(U0f, U2f, M.t_m) if ratio_design else "accuracy", law)
    extra_warnings = []
    if check:
        model, why = least_model(U0f, U00, M.Fa)
        say(f"check run: {model}")
        a = None
        try:
            a = check_answer(model, M.tau, M.Fa, law, theta)
            run = check_run(model, M.tau, M.Fa, law, theta, a)
        except SimulationError as exc:
            run = {"failed": str(exc)}
        run.update(model=model, why=why)
        if "U0" in run:
            run.update(_check_figures(run, M, req if ratio_design is not None else None))
        out["check_run"] = run
        if a is not None and (spring_margin is not None or speed_fluctuation is not None):
            extra_warnings = _spring_and_flywheel(
                out, model, a, M, turn, law, theta, spring_margin, spring_rate, spring_mass,
                speed_fluctuation, run["U0"], arm_length, say)
    # the answer's warnings, on every road (text, --json, design.json)
    out["warnings"] = ([f"check run: {w}" for w in out.get("check_run", {}).get("warnings", ())]
                       + ([f"check run failed: {out['check_run']['failed']}"]
                          if "failed" in out.get("check_run", {}) else [])
                       + extra_warnings)
    if chart_path is not None:
        say("chart")
        out["chart"] = chart(out, graphs, M, chart_path)
    out["graph_runs"] = graphs.runs
    return out


def _spring_inputs(M: Machine, check: bool, margin, rate, spring_mass, fluctuation) -> None:
    """Refuse, before any run, a spring or flywheel question the inputs cannot answer."""
    if margin is not None:
        check_margin(margin)
    if fluctuation is not None:
        check_fluctuation(fluctuation)
    if margin is None:
        for flag, v in (("--spring-rate", rate), ("--spring-mass", spring_mass)):
            if v is not None:
                raise CamdynInputError(f"argument {flag}: goes with --spring-margin MU (the "
                                       "follower spring is sized for that margin)")
    for flag, v in (("--spring-margin", margin), ("--speed-fluctuation", fluctuation)):
        if v is None:
            continue
        if not check:
            raise CamdynInputError(f"argument {flag}: is read off the check run; drop --no-check")
        if M.mass is None or M.t_m is None:
            raise CamdynInputError(f"argument {flag}: needs the output's mass (--mass) and the "
                                   "rise time (--rise-time, or --cam-angle with --speed)")
    if fluctuation is not None and (M.w_s is None or M.beta_m is None):
        raise CamdynInputError("argument --speed-fluctuation: needs the camshaft's speed and the "
                               "cam angle of the rise (--speed with --cam-angle or --rise-time)")


def _times(e, factor):
    return None if e is None else abs(factor) * e


def _scaled(env: dict, M: Machine) -> dict:
    """The envelope's u0 = U0 h_m' and u0'' = U0'' h_m'/t_m^2 with their errors (sec. 3.3)."""
    out = {"u0_error": _times(env["U0_error"], M.stroke)}
    if M.t_m is not None:
        out["u0dd_error"] = _times(env["U0dd_error"], M.stroke / M.t_m**2)
    return out


def _ratio_error(req: Requirement, fig: dict, t_m) -> float | None:
    """How far the requirement's ratio moves with U0 and U0'' at the far ends of their errors
    (it grows with both)."""
    e0, e2 = fig.get("U0_error"), fig.get("U0dd_error")
    if e0 is None or e2 is None:
        return None
    return float(req.ratio(fig["U0"] + e0, fig["U0dd"] + e2, t_m)
                 - req.ratio(fig["U0"], fig["U0dd"], t_m))


def _check_figures(run: dict, M: Machine, req: Requirement | None) -> dict:
    """The check run's figures in SI at the output, each with its error: u0 = U0 h_m',
    u0'' = U0'' h_m'/t_m^2, x''min = X''min h_m'/t_m^2, the inertia force m |x''min| and the
    ratio to the requirement."""
    out = {"u0": run["U0"] * M.stroke, "u0_error": _times(run.get("U0_error"), M.stroke)}
    if req is not None:
        out["ratio"] = float(req.ratio(run["U0"], run["U0dd"], M.t_m))
        out["ratio_error"] = _ratio_error(req, run, M.t_m)
    if M.t_m is not None:
        acc = M.stroke / M.t_m**2
        out.update(u0dd=run["U0dd"] * acc, u0dd_error=_times(run.get("U0dd_error"), acc),
                   xdd_min_rise=run["Xdd_min_rise"] * acc,
                   xdd_min_rise_error=_times(run.get("Xdd_min_rise_error"), acc))
        if M.mass is not None:
            out["inertia_force_max"] = M.mass * abs(out["xdd_min_rise"])
            out["inertia_force_max_error"] = _times(out["xdd_min_rise_error"], M.mass)
    return out


def _motions(model: str, a, M: Machine, turn: CamTurn, say) -> Motions:
    """The kinetostatic motion over the span and the check run's model over it: the check run
    itself for the rise alone, or one whole turn from rest (check_run.turn_runs)."""
    kin = LawMotion(turn, stroke=M.stroke, t_m=M.t_m)
    if turn.whole:
        say("the whole turn: the check run's model over one turn from rest")
        base, tight, warnings = turn_runs(model, M.tau, M.Fa, turn.drive, turn.end)
        covers = ("one turn from rest: the rise, the outer dwell, the return and the inner "
                  "dwell with the residual vibration each leaves; the vibration left at the "
                  "turn's end rides into the next rise (carried)")
    else:
        base, tight, warnings = a.result, a.tight_result, []
        covers = (f"the rise and the dwell after it to T = {a.result.t[-1]:.4g} (the check "
                  "run); the return is not in it: give --angles for the whole turn")
    dyn = RunMotion(base, stroke=M.stroke, t_m=M.t_m)
    twin = None if tight is None else RunMotion(tight, stroke=M.stroke, t_m=M.t_m)
    return Motions(turn, kin, dyn, twin, covers, [f"whole-turn run: {w}" for w in warnings])


def _spring_and_flywheel(out: dict, model: str, a, M: Machine, turn: CamTurn, law, theta,
                         margin, rate, spring_mass, fluctuation, U0_run: float, arm_length,
                         say) -> list:
    """out["spring"] and out["flywheel"] over the motions (:func:`_motions`); their warnings."""
    try:
        motions = _motions(model, a, M, turn, say)
    except SimulationError as exc:
        return [f"follower spring and flywheel not sized: the whole-turn run failed ({exc})"]
    warnings = []
    preload, preload_error = 0.0, 0.0
    if margin is not None:
        say("follower spring (secs 4.5.5, 7.5)")
        sp = spring(motions, mass=M.mass, stroke=M.stroke, t_m=M.t_m, margin=margin, rate=rate,
                    spring_mass=spring_mass,
                    speed_rpm=None if M.w_s is None else M.w_s * 60.0 / (2 * math.pi),
                    law=law, theta=theta, U0_design=U0_run, tau=M.tau, arm_length=arm_length)
        out["spring"] = sp
        warnings += sp["warnings"]
        preload, preload_error = sp["preload_min"], sp["preload_min_error"]
    if fluctuation is not None:
        say("flywheel (ch. 5)")
        # the follower's stiffness: given, else from T_e = 2 pi (m/c_c)^(1/2) (4.39)
        c_c = M.stiffness if M.stiffness is not None else M.mass * (2 * math.pi / (M.tau * M.t_m)) ** 2
        out["flywheel"] = flywheel(motions, mass=M.mass, stroke=M.stroke, t_m=M.t_m, w_s=M.w_s,
                                   beta_m=M.beta_m, stiffness=c_c, fluctuation=fluctuation,
                                   preload=preload, preload_error=preload_error,
                                   rate=rate or 0.0)
        if margin is None:
            warnings += motions.warnings
    return warnings


FILES = ("design.json", "design.png")
"""What a design writes into its folder: the answer and the chart."""


def chart_file(out) -> Path:
    """Where the chart of a design goes in the folder ``out``."""
    return Path(out) / FILES[1]


def write(result: dict, out) -> Path:
    """design.json in the folder ``out``: the answer as `camdyn design --json` prints it."""
    return write_text(Path(out) / FILES[0], json.dumps(result, indent=1, default=float))


def chart_window(tau: float, tau_max: float | None) -> tuple[float, float]:
    """(1/tau_hi, 1/tau_lo) of the chart: the design's tau and the largest tau, with room
    on both sides.  An unmet requirement puts tau_max below tau (the window started at
    0.8 tau and left the largest tau's line beside no envelope)."""
    taus = [tau] + ([tau_max] if tau_max is not None else [])
    return 1.0 / (1.5 * max(taus)), 1.0 / (0.8 * min(taus))


def chart(d: dict, graphs: Graphs, M: Machine, path) -> str:
    """The design on fig. 4.11a's axes: the envelope u0 = U0 h_m' over tau at the design's Fa
    (with its graph), at the largest Fa that meets the requirement and at Fa = 0, the required
    accuracy, the design point and the smallest t_m (largest tau)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lf, lt = d.get("largest_Fa") or {}, d.get("largest_tau") or {}
    x_lo, x_hi = chart_window(M.tau, lt.get("tau_max"))
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    curves = [(M.Fa, f"Fa = {M.Fa:.3g} (design)", "tab:blue")]
    if lf.get("Fa_max") is not None:
        curves.append((lf["Fa_max"], f"Fa = {lf['Fa_max']:.3g} (largest meeting the requirement)",
                       "tab:orange"))
    if M.Fa > 0:
        curves.append((0.0, "Fa = 0 (rigid camshaft)", "0.4"))
    for Fa, label, color in curves:
        # two dip spacings more on either side, so that the drawn part lies between maxima
        w = 2.0 / phase_factor(graphs.law, graphs.theta, Fa)
        t, u0, _ = graphs.samples(max(x_lo - w, 1.0), x_hi + w, Fa)
        env = Upper(t, u0)
        shown = (t >= 1.0 / x_hi) & (t <= 1.0 / x_lo)
        ax.plot(t[shown], env(t[shown]) * M.stroke, color=color, lw=1.8, label=label)
        if Fa == M.Fa:
            ax.plot(t[shown], u0[shown] * M.stroke, color=color, lw=0.6, alpha=0.6)
    req = (d.get("requirement") or {}).get("accuracy")
    if req is not None:
        ax.axhline(req, color="k", ls="--", lw=1, label=f"required u0 <= {req:.3g} m")
    ax.plot([M.tau], [d["envelope"]["u0"]], "o", color="tab:blue", label="design point")
    if lt.get("tau_max") is not None:
        ax.axvline(lt["tau_max"], color="tab:green", ls=":", lw=1.2,
                   label=f"largest tau {lt['tau_max']:.4g}"
                         + (f" (t_m >= {lt['t_m_min']:.4g} s)" if lt.get("t_m_min") else ""))
    ax.set_yscale("log")
    ax.set_xlabel("tau = T_e / t_m")
    ax.set_ylabel("u0 = U0 h_m'  [m]  (envelope through the maxima)")
    ax.set_title(f"camdyn design: {d['law']} law, stroke {M.stroke:g} m", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7.5, loc="lower right")
    env = d["envelope"]
    shown = {"U0 (envelope)": (env["U0"], env["U0_error"])}
    if lf.get("Fa_max") is not None:
        shown["largest Fa"] = (lf["Fa_max"], lf.get("Fa_max_error"))
    if lt.get("tau_max") is not None:
        shown["largest tau"] = (lt["tau_max"], lt.get("tau_max_error"))
    fig.text(0.01, 0.01, chart_note(shown, d.get("warnings", [])), fontsize=7)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
    with writing(path) as path:
        fig.savefig(path, dpi=110)
    plt.close(fig)
    return str(path)


# -- text ----------------------------------------------------------------------------------------
def _g(v, digits=4) -> str:
    if v is None:
        return "-"
    if isinstance(v, bool):
        return "yes" if v else "no"
    return f"{v:.{digits}g}"


def _pm(v, e, digits=4) -> str:
    """A figure and its estimate; "(estimate unavailable)" where it could not be made."""
    if v is None:
        return "-"
    return _g(v, digits) + (f" ± {e:.2g}" if e is not None else " (estimate unavailable)")


def text(d: dict) -> str:
    """The answer of `camdyn design` as lines of text."""
    M = d["machine"]
    L = [f"camdyn design: {d['law']} rise" + (f" (theta {d['theta']:g})" if d.get("theta") else "")]
    L.append("machine (App. 7 (5)-(12))")
    for key, label, unit in (("stroke", "h_m'", "m"), ("beta_m", "beta_m", "rad"),
                             ("w_s", "w_s", "rad/s"), ("t_m", "t_m", "s"), ("mass", "m", "kg"),
                             ("stiffness", "c_c", "N/m"), ("T_e", "T_e", "s"), ("tau", "tau", ""),
                             ("tan_alpha_me", "tan alpha_me", ""), ("c_tan", "c_tan", "N/m"),
                             ("Fa", "Fa", ""), ("dip", "c_max/c_min", ""), ("c_min", "c_min", "N/m")):
        if M.get(key) is not None:
            src = M["sources"].get(key, "")
            L.append(f"  {label:<14}{_g(M[key]):>12} {unit:<6}{src}")
    e = d["envelope"]
    L.append("envelope through the maxima of fig. 4.11 (CAMSHAFT-1), at the design point")
    eq85 = f"; (8.5): u0 ~ {_g(e['eq_8_5_u0'])} m" if e["eq_8_5_u0"] is not None else ""
    L.append(f"  U0   = {_pm(e['U0'], e['U0_error'])}   u0 = U0 h_m' = {_pm(e['u0'], e['u0_error'])} m"
             f"   (Fa = 0: {_g(e['U0_Fa0'])}{eq85})")
    L.append(f"  U0'' = {_pm(e['U0dd'], e['U0dd_error'])}" +
             (f"   u0'' = U0'' h_m'/t_m^2 = {_pm(e['u0dd'], e['u0dd_error'])} m/s^2"
              if e["u0dd"] is not None else ""))
    if "requirement" in d:
        r = d["requirement"]
        want = " and ".join(s for s in (
            f"u0 <= {_g(r['accuracy'])} m" if r["accuracy"] is not None else "",
            f"u0'' <= {_g(r['residual_acceleration'])} m/s^2"
            if r["residual_acceleration"] is not None else "") if s)
        L.append(f"requirement {want}: {'met' if r['met'] else 'NOT met'} "
                 f"(envelope/requirement = {_pm(r['ratio'], r['ratio_error'])})")
        lf = d["largest_Fa"]
        if lf.get("Fa_max") is None:
            L.append(f"  largest Fa at tau = {_g(M['tau'])}: none ({lf['reason']})")
        else:
            extra = ""
            if lf.get("c_tan_min") is not None:
                extra += f", least c_tan = {_pm(lf['c_tan_min'], lf['c_tan_min_error'])} N/m"
            if lf.get("shaft_diameter_factor") is not None:
                extra += (f", shaft diameter x {_pm(lf['shaft_diameter_factor'], lf['shaft_diameter_factor_error'], 3)} if torsion "
                          "sets c_tan (~ d^4, sec. 8.2.8)")
            L.append(f"  largest Fa at tau = {_g(M['tau'])}: {_pm(lf['Fa_max'], lf['Fa_max_error'])}"
                     f" (limited by {lf['limited_by']}){extra}")
        lt = d["largest_tau"]
        if lt.get("tau_max") is None:
            L.append(f"  largest tau at Fa = {_g(M['Fa'])}: none ({lt['reason']})")
        else:
            extra = ""
            if lt.get("t_m_min") is not None:
                extra += (f"; smallest t_m = {_pm(lt['t_m_min'], lt.get('t_m_min_error'))} s "
                          f"(speed x {_pm(lt['speed_factor'], lt.get('speed_factor_error'), 3)})")
            if lt.get("beyond_last_maximum"):
                extra += ("; NB past the graph's last maximum, where it dips again: the envelope "
                          "is held flat there and may read low")
            L.append(f"  largest tau at Fa = {_g(M['Fa'])}, this T_e: "
                     f"{_pm(lt['tau_max'], lt['tau_max_error'])} (limited by {lt['limited_by']}){extra}")
        le = d.get("largest_T_e")
        if le is not None and le.get("T_e_max") is not None:
            extra = (f", c_c >= {_pm(le['c_c_min'], le.get('c_c_min_error'))} N/m at this m"
                     if le.get("c_c_min") else "")
            L.append(f"  largest T_e at this t_m: {_pm(le['T_e_max'], le.get('T_e_max_error'))} s "
                     f"(tau {_g(le['tau_max'])}, limited by {le['limited_by']}){extra}")
    if "motor" in d:
        m = d["motor"]
        L.append("motor (sec. 8.3)")
        L.append(f"  tau_m = T_m/t_m = {_g(m['tau_m'])}; peak slip delta_max/delta_n = "
                 f"{_g(m['slip_peak_rel'])} at P = 1 (fig. 8.6, at T = {_g(m['T_slip_peak'], 3)})")
        L.append(f"  P = {_g(m['P'])} (8.1) with v_v = {m['v_v']}, eta_g = {_g(m['eta_g'])}, "
                 f"delta_n = {_g(m['delta_n'])}, delta_lim = {_g(m['delta_lim'])}")
        if m["M_ena"] is not None:
            L.append(f"  rated torque at the camshaft M_ena = {_g(m['M_ena'])} N m (8.2)")
        if m["N_n"] is not None:
            L.append(f"  rated power N_n = {_g(m['N_n'])} W (8.3)")
        L.append(f"  (8.4) delta_lim <= delta_n: {_g(m['rule_8_4'])}")
    L.append("rules (secs 8.2-8.5)")
    for r in d["rules"]:
        L.append(f"  {r['status']:<9}{r['rule']}: {r['text']}")
    if "check_run" in d:
        c = d["check_run"]
        L.append(f"check run: {c['model']} ({c['why']})")
        if "failed" in c:
            L.append(f"  failed: {c['failed']}")
        else:
            L.append(f"  U0   = {_pm(c['U0'], c.get('U0_error'), 6)}  (envelope {_g(e['U0'])})")
            L.append(f"  U0'' = {_pm(c['U0dd'], c.get('U0dd_error'), 6)}  (envelope {_g(e['U0dd'])})")
            if c.get("u0") is not None:
                L.append(f"  u0 = U0 h_m' = {_pm(c['u0'], c.get('u0_error'))} m" +
                         (f", u0'' = U0'' h_m'/t_m^2 = {_pm(c['u0dd'], c.get('u0dd_error'))} m/s^2"
                          if c.get("u0dd") is not None else ""))
            L.append(f"  X''min during the rise = {_pm(c['Xdd_min_rise'], c.get('Xdd_min_rise_error'), 6)}"
                     f" at T = {_pm(c['T_at_Xdd_min'], c.get('T_at_Xdd_min_error'), 6)}" +
                     (f"; x''min = {_pm(c['xdd_min_rise'], c.get('xdd_min_rise_error'))} m/s^2"
                      if c.get("xdd_min_rise") is not None else "") +
                     (f", inertia force {_pm(c['inertia_force_max'], c.get('inertia_force_max_error'))} N"
                      if c.get("inertia_force_max") is not None else ""))
            if c.get("ratio") is not None:
                L.append(f"  the run against the requirement: {_pm(c['ratio'], c.get('ratio_error'))} "
                         f"({'met' if c['ratio'] <= 1 else 'NOT met'}; at a tuning dip the run "
                         "may meet what the envelope does not)")
    if "spring" in d:
        L += _spring_text(d["spring"])
    if "flywheel" in d:
        f = d["flywheel"]
        L.append(f"flywheel (ch. 5) for a speed fluctuation C_s = {_g(f['speed_fluctuation'])}")
        over = "one turn from rest" if f["whole_turn"] else "the check run (the rise and its dwell)"
        L.append(f"  energy swing over {over} {_pm(f['energy_swing'], f['energy_swing_error'])} J"
                 + (" (spring included, its preload's error too)" if f["with_spring"] else ""))
        L.append(f"  camshaft inertia J >= {_pm(f['J'], f['J_error'])} kg m^2, flywheel factor "
                 f"Fv = {_pm(f['Fv'], f['Fv_error'])} (5.14b); the check run (Fv -> oo) bounds "
                 "U0 from above (sec. 5.7)")
    return "\n".join(L)


def _deg(v) -> str:
    return "-" if v is None else f"{math.degrees(v):.6g}"


def _where(b: dict) -> str:
    """Where an extreme lies: the part of the turn, the cam angle (deg), the time (s) and T,
    each with its error."""
    parts = [f"in the {b['part']}"]
    if b.get("cam_angle") is not None:
        e = b.get("cam_angle_error")
        parts.append(f"at cam angle {_deg(b['cam_angle'])}"
                     + (f" ± {math.degrees(e):.2g}" if e is not None else "") + " deg")
    if b.get("time") is not None:
        parts.append(f"t = {_pm(b['time'], b.get('time_error'), 6)} s")
    parts.append(f"T = {_pm(b['T'], b.get('T_error'), 6)}")
    return ", ".join(parts)


def _spring_text(sp: dict) -> list:
    if sp.get("whole_turn"):
        names = ("rise", "outer dwell", "return", "inner dwell")
        over = "over the whole turn (" + ", ".join(
            f"{n} {math.degrees(a):.6g}" for n, a in zip(names, sp["angles"])) + " deg)"
    else:
        over = "over the rise alone"
    L = [f"follower spring (secs 4.5.5, 7.5), margin {_g(sp['margin'])} over the inertia force, "
         f"{over}"]
    L.append(f"  held kinetostatically (the rigid follower, as camdyn profile checks the cam) and "
             f"along the check run's model: {sp['covers']}")
    L.append(f"  largest inertia force pulling the follower off the cam "
             f"{_pm(sp['inertia_force_max'], sp['inertia_force_max_error'])} N (kinetostatic "
             f"{_g(sp['kinetostatic']['inertia_force_max'])}, dynamic "
             f"{_g(sp['dynamic']['inertia_force_max'])})")
    b = sp["binding"]
    if sp["rate"] is not None:
        L.append(f"  at the rate k = {_g(sp['rate'])} N/m: least preload F0 = "
                 f"{_pm(sp['preload_min'], sp['preload_min_error'])} N, peak spring force "
                 f"{_pm(sp['peak_spring_force'], sp['peak_spring_force_error'])} N")
    else:
        rate = (f"least rate with no preload k = "
                f"{_pm(sp['rate_min_without_preload'], sp['rate_min_without_preload_error'])} N/m "
                f"({_where(sp['rate_binding'])}); any spring on or above the line between holds "
                "the follower" if sp["rate_min_without_preload"] is not None
                else sp["rate_min_without_preload_reason"])
        L.append(f"  least preload with no rate F0 = "
                 f"{_pm(sp['preload_min'], sp['preload_min_error'])} N; {rate}")
    L.append(f"  binding: the {b['by']} motion {_where(b)}")
    other = "kinetostatic" if b["by"] == "dynamic" else "dynamic"
    o = sp[other]
    L.append(f"  ({other}: F0 = {_pm(o['preload_min'], o['preload_min_error'])} N "
             f"{_where(o['binding'])})")
    r = sp.get("rocker")
    if r is not None:
        rate = (f", rate k l^2 = {_g(r['rate_torsional'])} N m/rad" if "rate_torsional" in r
                else "")
        L.append(f"  at the rocker's pivot (arm l = {_g(r['arm_length'] * 1e3)} mm): preload "
                 f"F0 l = {_pm(r['preload_torque'], r['preload_torque_error'])} N m{rate}, arm "
                 f"inertia {_g(r['inertia_about_pivot'])} kg m^2 (camdyn profile's "
                 "--spring-preload, --spring-rate, --follower-mass)")
    L.append(f"  least contact force with it {_pm(sp['contact_force_min'], sp['contact_force_min_error'])} N")
    c = sp.get("carried")
    if c is not None and c.get("force") is not None:
        L.append(f"  carried into the next turn: the vibration left at the turn's end, "
                 f"amplitude {_pm(c['x'] * 1e3, _times(c['x_error'], 1e3))} mm, x'' "
                 f"{_pm(c['xdd'], c['xdd_error'])} m/s^2; each later turn may add up to "
                 f"{_pm(c['force'], c['force_error'])} N to the least preload (the model is "
                 "undamped)")
    if sp["rate"] is not None and sp["preload_min"] <= (sp["preload_min_error"] or 0.0):
        L.append("  the rate alone meets the margin; without a preload the follower rests on the "
                 "base circle with no force: give it one for the loads the run leaves out")
    s = sp.get("surge")
    if s is not None:
        harm = f", {_g(s['harmonic'], 4)} times the camshaft's speed" if s["harmonic"] else ""
        U0 = (f"; the coils' residual vibration U0(tau_s) = {_pm(s['U0'], s['U0_error'])} (3.1)"
              if s.get("U0") is not None else "")
        L.append(f"  surge frequency f_s = {_g(s['f_surge'])} Hz{harm}; tau_s = "
                 f"{_g(s['tau_surge'])}{U0}")
    return L
