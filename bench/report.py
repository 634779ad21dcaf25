"""Tables (stdout and bench/results/BENCHMARKS-camshaft1.md), the goal verdicts and the
error-vs-time chart of bench/run.py."""
from __future__ import annotations

import platform
import subprocess
import time
from dataclasses import dataclass, field
from pathlib import Path

from matching import TARGETS
from problem import FA, OMEGA, T_END, TAU
from where import commit

GOAL_IVP = 300.0     # camdyn at least this many times faster than solve_ivp at equal error
GOAL_ODEINT = 100.0  # ... than odeint
GOAL_YARD = 1.5      # camdyn RK4 at most this many times slower than the yardstick, same steps
                     # (the dwell integrated, as the yardstick does)
CAMDYN_PUBLIC = ("camdyn-rk4", "camdyn-dp54", "camdyn-dop853", "camdyn-rkn12")
IVP = ("ivp-DOP853", "ivp-RK45")


# -- formatting -------------------------------------------------------------------

def t_fmt(seconds: float | None) -> str:
    if seconds is None:
        return "-"
    if seconds < 1e-3:
        return f"{seconds * 1e6:.3g} us"
    return f"{seconds * 1e3:.3g} ms"


def e_fmt(err: float | None) -> str:
    return "-" if err is None else f"{err:.2e}"


def r_fmt(ratio: float | None) -> str:
    return "-" if ratio is None else f"{ratio:.3g}"


@dataclass
class Section:
    title: str
    headers: list
    rows: list
    notes: list = field(default_factory=list)


def _text_table(headers, rows) -> list[str]:
    cells = [list(map(str, headers))] + [list(map(str, r)) for r in rows]
    widths = [max(len(r[i]) for r in cells) for i in range(len(headers))]
    line = lambda r: "  ".join(c.rjust(w) for c, w in zip(r, widths))
    return [line(cells[0]), "  ".join("-" * w for w in widths)] + [line(r) for r in cells[1:]]


def _md_table(headers, rows) -> list[str]:
    out = ["| " + " | ".join(map(str, headers)) + " |",
           "|:---|" + "".join("---:|" for _ in headers[1:])]
    return out + ["| " + " | ".join(map(str, r)) + " |" for r in rows]


# -- machine ----------------------------------------------------------------------

def _cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def _first_line(cmd, cwd=None) -> str:
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd, check=True).stdout
        return out.splitlines()[0].strip()
    except (OSError, subprocess.CalledProcessError, IndexError):
        return "unknown"


def machine_info() -> dict:
    import os

    import Cython
    import numpy
    import scipy

    return {
        "date": time.strftime("%Y-%m-%d %H:%M %Z"),
        "CPU": f"{_cpu_model()} ({os.cpu_count()} logical CPUs)",
        "OS": platform.platform(),
        "Python": platform.python_version(),
        "NumPy / SciPy / Cython": f"{numpy.__version__} / {scipy.__version__} / {Cython.__version__}",
        "C compiler": _first_line(["gcc", "--version"]),
        "camdyn commit": commit(),
        "OPENBLAS_NUM_THREADS": os.environ.get("OPENBLAS_NUM_THREADS", "unset"),
    }


# -- the sections -----------------------------------------------------------------------

def _label(res, key):
    return res["comps"][key].label


def _setting(key_setting: str, x: float) -> str:
    return f"h = 1/{round(1 / x)}" if key_setting == "h" else f"rtol = {x:.3g}"


def sec_reference(res) -> Section:
    ref = res["reference"]
    rows = [[f"camdyn DP54, rtol = {ref['rtol']:g} (reference)", f"{ref['u0']:.15f}", "0"]]
    rows += [[name, "", f"{d:+.1e}"] for name, d in ref["checks"].items()]
    ss = ref["same_steps"]
    same = (f"Same steps: at h = {ss['h']:g} camdyn's RK4 and the yardstick record the same {ss['points']} "
            f"times, states agreeing to {ss['max_dy']:.1e}." if ss["same_t"] else
            f"WARNING: at h = {ss['h']:g} camdyn's RK4 and the yardstick record different times.")
    return Section("Reference value of U0", ["run", "U0", "U0 - U0_ref"], rows,
                   ["U0 = sqrt((X(1) - 1)^2 + (X'(1)/omega)^2), omega = 2 pi/tau: exact for the "
                    "undamped dwell of (4.15); the same formula scores every method.", same])


def sec_rhs(res) -> Section:
    rows = [[name, f"{ns:.1f}"] for name, ns in res["rhs"].items()]
    return Section("Cost of one right-hand-side call of (4.15)", ["right-hand side", "ns per call"], rows,
                   ["camdyn's: driver.rhs_cost_ns (a C loop through the model's function pointer, "
                    "a new time at every call, so the cam law is evaluated every time); the yardstick's: "
                    "the same loop over its inlined function; NumPy's: timeit.  The calls in these loops "
                    "do not depend on each other (throughput); in an integrator each stage waits for the "
                    "one before.  Inside camdyn's own loops the rhs is inlined and cam values are reused "
                    "between stages at the same time (see the breakdown below)."])


def sec_rk4(res) -> Section:
    rows = []
    for r in res["rk4_table"]:
        c, st = r["camdyn-rk4"], r["camdyn-rk4-steps"]
        b, y = r["camdyn-rk4-bare"], r["yardstick"]
        rows.append([f"{c.setting:g}", st.n_rhs, e_fmt(st.error), t_fmt(st.seconds),
                     t_fmt(b.seconds), t_fmt(y.seconds), r_fmt(st.seconds / y.seconds),
                     r_fmt(b.seconds / y.seconds), c.n_rhs, t_fmt(c.seconds),
                     r_fmt(c.seconds / y.seconds)])
    return Section("camdyn RK4 (fixed step) against the yardstick on the same steps",
                   ["h", "rhs calls", "U0 error", "simulate(), dwell integrated", "compiled loop",
                    "yardstick", "simulate/yard", "bare/yard", "rhs calls, exact dwell",
                    "simulate(), exact dwell", "exact/yard"], rows,
                   ["Median time per simulation over [0, 3]; equal steps <= h in [0, 1] and [1, 3].  "
                    "'dwell integrated': RK4 over both intervals, as the yardstick does "
                    "(simulate(..., exact_segments=False)); the compiled loop likewise.  'exact "
                    "dwell': simulate() as a user calls it, the dwell [1, 3], where (4.15) is "
                    "linear and time invariant, stepped over with its propagator e^(A h) "
                    "(runtime/engine/loops.pxi, _loop_exact) at the same recorded steps; the "
                    "U0 error is the same (U0 is read at T = 1)."])


def sec_dp54(res) -> Section:
    rows = []
    for r in res["dp54_table"]:
        c, b = r["camdyn-dp54"], r["camdyn-dp54-bare"]
        rows.append([f"{c.setting:.0e}", c.n_rhs, e_fmt(c.error), t_fmt(c.seconds), t_fmt(b.seconds),
                     t_fmt(c.seconds - b.seconds)])
    return Section("camdyn DP54 (adaptive)",
                   ["rtol", "rhs calls", "U0 error", "simulate()", "compiled loop",
                    "simulate() - bare"], rows,
                   ["atol = 1e-3 rtol (camdyn's default for this model)."])


def sec_matched(res) -> Section:
    rows = []
    for target in TARGETS:
        pts = res["matched"][target]
        best = _best(pts, CAMDYN_PUBLIC)
        for key, comp in res["comps"].items():
            p = pts.get(key)
            if p is None:
                rows.append([f"{target:.0e}", comp.label, "not reached", "-", "-", "-", "-"])
                continue
            ratio = p.seconds / best[1].seconds if best else None
            rows.append([f"{target:.0e}", comp.label, _setting(comp.setting, p.setting), e_fmt(p.error),
                         p.n_rhs, t_fmt(p.seconds), r_fmt(ratio)])
    return Section("All methods at matched error",
                   ["target", "method", "setting", "U0 error", "rhs calls", "time", "time / camdyn best"],
                   rows,
                   ["Error: |U0 - U0_ref|, absolute (U0_ref ~ 0.016).  Setting: the loosest one of the "
                    "sweep whose error and the error of every tighter setting is <= target (no "
                    "interpolation); the bare loop and the yardstick run the steps of camdyn's "
                    "simulate() run.  Times: per target all methods re-timed side by side "
                    f"(interleaved repeats, {res['final_repeat']} of them).  "
                    "camdyn best: the fastest of RK4, DP54, DOP853 and RKN12 through simulate() as a "
                    "user calls it (RK4, DOP853 and RKN12 step over the dwell exactly, their "
                    "default; DOP853 and RKN12 make their dense output when it is first used)."])


SHORT = {"camdyn-rk4": "RK4", "camdyn-dp54": "DP54", "camdyn-dop853": "DOP853",
         "camdyn-rkn12": "RKN12",
         "ivp-DOP853": "DOP853", "ivp-RK45": "RK45"}


def _best(pts: dict, keys) -> tuple | None:
    """(short name, Point) of the fastest of `keys` at a target."""
    found = [(SHORT[k], pts[k]) for k in keys if pts.get(k) is not None]
    return min(found, key=lambda kp: kp[1].seconds) if found else None


def _ratio(num, den) -> float | None:
    return num.seconds / den.seconds if num is not None and den is not None else None


def goal_rows(res) -> list[dict]:
    """Per target: the three goal ratios and their verdicts."""
    out = []
    for target in TARGETS:
        pts = res["matched"][target]
        cam, ivp = _best(pts, CAMDYN_PUBLIC), _best(pts, IVP)
        cam_p, ivp_p = (cam[1] if cam else None), (ivp[1] if ivp else None)
        out.append({"target": target, "cam": cam, "ivp": ivp, "ode": pts.get("odeint"),
                    "r_ivp": _ratio(ivp_p, cam_p), "r_ode": _ratio(pts.get("odeint"), cam_p),
                    "r_yard": _ratio(pts.get("camdyn-rk4-steps"), pts.get("yardstick")),
                    "r_best_yard": _ratio(cam_p, pts.get("yardstick")),
                    "r_yard_bare": _ratio(pts.get("camdyn-rk4-bare"), pts.get("yardstick")),
                    "y_ivp": _ratio(ivp_p, pts.get("yardstick")),
                    "y_ode": _ratio(pts.get("odeint"), pts.get("yardstick"))})
    return out


def _verdict(ratio, goal, at_least: bool) -> str:
    if ratio is None:
        return "n/a"
    return "met" if (ratio >= goal if at_least else ratio <= goal) else "NOT met"


def _named(best) -> str:
    return f"{best[0]} {t_fmt(best[1].seconds)}" if best else "-"


def sec_goals(res) -> Section:
    rows = []
    for g in goal_rows(res):
        rows.append([f"{g['target']:.0e}", _named(g["cam"]), _named(g["ivp"]),
                     f"{r_fmt(g['r_ivp'])} ({_verdict(g['r_ivp'], GOAL_IVP, True)})",
                     t_fmt(g["ode"].seconds) if g["ode"] else "-",
                     f"{r_fmt(g['r_ode'])} ({_verdict(g['r_ode'], GOAL_ODEINT, True)})",
                     f"{r_fmt(g['r_yard'])} ({_verdict(g['r_yard'], GOAL_YARD, False)})",
                     r_fmt(g["r_yard_bare"]), r_fmt(g["r_best_yard"])])
    return Section("Speed ratios at equal error against the goals",
                   ["target", "camdyn best", "solve_ivp best", f"solve_ivp/camdyn (goal >= {GOAL_IVP:g})",
                    "odeint", f"odeint/camdyn (goal >= {GOAL_ODEINT:g})",
                    f"RK4 simulate()/yardstick, same steps (goal <= {GOAL_YARD:g})",
                    "RK4 bare/yardstick", "camdyn best/yardstick"], rows,
                   verdict_lines(res))


def verdict_lines(res) -> list[str]:
    rows = goal_rows(res)
    goals = [(f"camdyn >= {GOAL_IVP:g}x faster than solve_ivp", "r_ivp", GOAL_IVP, True),
             (f"camdyn >= {GOAL_ODEINT:g}x faster than odeint", "r_ode", GOAL_ODEINT, True),
             (f"camdyn RK4 simulate() within {GOAL_YARD:g}x of the hand-written RK4 loop on the "
              "same steps (the dwell integrated)", "r_yard", GOAL_YARD, False)]
    out = []
    for text, key, goal, at_least in goals:
        verdicts = [_verdict(g[key], goal, at_least) for g in rows]
        per_target = [f"{g['target']:.0e}: {r_fmt(g[key])}" for g in rows]
        status = "MET at every target" if all(v == "met" for v in verdicts) else (
            "NOT MET at any target" if all(v != "met" for v in verdicts) else "met only at some targets")
        out.append(f"Goal '{text}': {status} ({'; '.join(per_target)}).")
    out.append("For orientation, the yardstick against SciPy at the same targets: " + "; ".join(
        f"{g['target']:.0e}: solve_ivp/yardstick {r_fmt(g['y_ivp'])}, odeint/yardstick {r_fmt(g['y_ode'])}"
        for g in rows) + ".")
    return out


def overhead_facts(res) -> dict:
    """Per-call costs from the trivial run, per-step costs from the slope to the finest run."""
    ov = res["overheads"]
    h0, h1 = max(ov), min(ov)
    triv, fine = ov[h0], ov[h1]
    steps = lambda h: round(1 / h) + round((T_END - 1) / h)
    dn = steps(h1) - steps(h0)
    slope = lambda a, b: ((fine[a] - fine[b]) - (triv[a] - triv[b])) / dn
    probe = "probe: yardstick loop + camdyn rhs"
    return {
        "python_per_call": triv["simulate()"] - triv["compiled loop"],
        "bare_fixed": triv["compiled loop"] - triv["yardstick"],
        "fine_h": h1,
        "loop_per_step": slope("compiled loop", "yardstick"),
        "pointer_per_call": slope(probe, "yardstick") / 4,
        "record_per_step": slope("yardstick", "yardstick, no record"),
    }


def _ns(seconds: float) -> str:
    ns = seconds * 1e9
    return "less than 1 ns (within the noise)" if abs(ns) < 1.0 else f"{ns:.1f} ns"


def sec_overheads(res) -> Section:
    ov = res["overheads"]
    names = list(next(iter(ov.values())))
    rows = [[f"1/{round(1 / h)}"] + [t_fmt(ov[h][n]) for n in names] for h in sorted(ov, reverse=True)]
    f = overhead_facts(res)
    notes = [
        f"Python overhead of simulate() (simulate() - compiled loop, h = {max(ov):g}): "
        f"{t_fmt(f['python_per_call'])} per call.",
        f"Fixed cost of the compiled loop beyond the yardstick's (h = {max(ov):g}): "
        f"{t_fmt(f['bare_fixed'])} per call.",
        f"Per step, from h = {max(ov):g} to h = 1/{round(1 / f['fine_h'])}: camdyn's compiled loop "
        f"costs {f['loop_per_step'] * 1e9:.1f} ns more than the yardstick's (it also records slopes "
        f"and cam segments for dense output, and evaluates the general model: damping term, "
        f"cam-law dispatch); recording t, y costs the yardstick {_ns(f['record_per_step'])} per step.",
        f"The probe calls camdyn's generated rhs through its function pointer from the yardstick's "
        f"loop: {f['pointer_per_call'] * 1e9:.1f} ns per call more than the inlined hand-written "
        f"rhs.  camdyn's loops avoid that cost: runtime/engine/loops.pxi is compiled into every generated "
        f"model with the rhs inlined, and cam-law values are reused between stages at the same "
        f"time (RK4: two cam evaluations per step instead of four).",
        "These runs are timed side by side on their own, so their times differ a little from the "
        "tables above.",
    ]
    return Section("Where camdyn's time goes (RK4, median time per simulation)",
                   ["h"] + names, rows, notes)


def sec_malloc(res) -> Section:
    m = res["malloc"]
    names = list(m)
    hs = sorted(next(iter(m.values())), reverse=True)
    rows = [[f"{h:g}", round(1 / h) * 3 + 2] + [t_fmt(m[n][h]) for n in names] for h in hs]
    return Section("camdyn's compiled loop and glibc's trajectory buffers (compiled loop, RK4)",
                   ["h", "points recorded"] + names, rows,
                   ["Each configuration in a fresh process.  'buffers kept': MALLOC_MMAP_THRESHOLD_ and "
                    "MALLOC_TRIM_THRESHOLD_ = 1e9, so the record's malloc/realloc buffers are reused "
                    "instead of mmap'ed, page-faulted and unmapped on every call.  (A record of up "
                    "to 256 KiB, about 5900 points here, is not allocated again at all: the Integrator "
                    "refills the last run's once nothing refers to it.)"])


def findings(res) -> list[str]:
    """Plain-language summary of where camdyn's time goes, numbers from this run."""
    ov, out = res["overheads"], []
    mid = res["matched"][TARGETS[len(TARGETS) // 2]].get("camdyn-rk4")
    if mid is not None and mid.setting in ov:
        o = ov[mid.setting]
        sim, bare = o["simulate()"], o["compiled loop"]
        probe, yard = o["probe: yardstick loop + camdyn rhs"], o["yardstick"]
        part = lambda x: f"{t_fmt(x)} ({100 * x / sim:.0f} %)"
        out.append(
            f"At h = 1/{round(1 / mid.setting)} (U0 error {mid.error:.1e}) one RK4 simulate() takes "
            f"{t_fmt(sim)}: the compiled loop {part(bare)} (the yardstick takes {t_fmt(yard)}; the "
            f"yardstick's loop calling camdyn's rhs through a function pointer {t_fmt(probe)}), "
            f"Python around the compiled loop {part(sim - bare)}.")
    h0 = max(ov)
    triv, n0 = ov[h0], round(1 / h0) + round((T_END - 1) / h0)
    out.append(f"Fixed cost per call (h = {h0:g}, {n0} steps): simulate() {t_fmt(triv['simulate()'])}, "
               f"compiled loop {t_fmt(triv['compiled loop'])}, yardstick {t_fmt(triv['yardstick'])}.")
    m = res["malloc"]
    h = min(next(iter(m.values())))
    out.append(f"Long runs: at h = {h:g} the compiled loop takes {t_fmt(m['glibc default'][h])} with "
               f"glibc's defaults and {t_fmt(m['buffers kept'][h])} when freed buffers are kept (the "
               f"record is written straight into NumPy arrays sized in advance, the last run's again "
               f"when they take at most 256 KiB; fresh pages cost what the difference shows).")
    tight = res["matched"][TARGETS[-1]]
    keys = ("camdyn-rk4", "camdyn-dp54", "camdyn-dop853", "camdyn-rkn12", "ivp-DOP853")
    counts = {k: tight[k].n_rhs for k in keys if k in tight}
    if len(counts) == len(keys):
        out.append(f"Method order: at U0 error {TARGETS[-1]:.0e} camdyn's RK4 needs "
                   f"{counts['camdyn-rk4']}, DP54 {counts['camdyn-dp54']}, DOP853 "
                   f"{counts['camdyn-dop853']} and RKN12 {counts['camdyn-rkn12']} rhs calls (RK4, "
                   f"DOP853 and RKN12 with the dwell exact), SciPy's DOP853 {counts['ivp-DOP853']}.")
    return out


def sections(res) -> list[Section]:
    return [sec_reference(res), sec_rhs(res), sec_rk4(res), sec_dp54(res), sec_matched(res),
            sec_goals(res), sec_overheads(res), sec_malloc(res)]


# -- output -------------------------------------------------------------------------

def text(res, chart_path) -> str:
    lines = [f"camdyn benchmark: CAMSHAFT-1 (4.15), tau = {TAU:g}, Fa = {FA:g}, T in [0, {T_END:g}], "
             f"cycloidal rise; medians of {res['repeat']} repeats; {res['elapsed']:.0f} s", ""]
    for s in sections(res):
        lines += [s.title, ""] + _text_table(s.headers, s.rows) + [""] + s.notes + [""]
    lines += ["In short:"] + [f"- {v}" for v in findings(res)] + ["", f"chart: {chart_path}"]
    return "\n".join(lines)


MD_INTRO = """\
Problem: CAMSHAFT-1, thesis (4.15), X'' = (2 pi/tau)^2 (H - X)/(1 + Fa H'^2), tau = {tau:g}, Fa = {fa:g},
cycloidal rise H = T - sin(2 pi T)/(2 pi) on [0, 1), dwell H = 1 after it, X(0) = X'(0) = 0,
T in [0, {t_end:g}].  Every method integrates [0, 1] and [1, {t_end:g}] separately (breakpoint at T = 1).

Error measure: U0, the residual amplitude after the rise, from the state at T = 1,
U0 = sqrt((X(1) - 1)^2 + (X'(1)/omega)^2), omega = 2 pi/tau = {omega:.6g} (exact: the dwell is an
undamped harmonic oscillation), for every method alike; error = |U0 - U0_ref|, absolute.

Contestants: camdyn RK4, DP54 and DOP853 through the public `simulate(...)` call (what a user
pays) and through the bare compiled loop `Integrator.run(...)` with prebuilt arrays; the yardstick
`bench/yardstick.pyx`, a hand-written Cython RK4 loop with (4.15) inlined, the same steps as
camdyn's RK4 and the trajectory recorded per step; `scipy.integrate.solve_ivp` (DOP853, RK45) and
`scipy.integrate.odeint` (LSODA) on a NumPy right-hand side (`bench/problem.py`).  Adaptive methods:
atol = 1e-3 rtol.  Times: median of {repeat} repeats (timeit, GC off), wall clock, one thread, all in
the same run; the ratios at matched error come from side-by-side timing (interleaved repeats), which
keeps them steadier than the absolute times when the machine's speed drifts (virtual machines).

Chart: `bench/out/error_vs_time.png` (written by `make bench`; not committed).  The other
benchmarks: [BENCHMARKS.md](BENCHMARKS.md).
"""


def markdown(res) -> str:
    lines = ["# Benchmark: CAMSHAFT-1, speed and accuracy", "",
             "Written by `make bench` (`bench/run.py`); rerun it to refresh every figure below.", "",
             MD_INTRO.format(tau=TAU, fa=FA, t_end=T_END, omega=OMEGA, repeat=res["repeat"]),
             "## Machine", ""]
    lines += [f"- {k}: {v}" for k, v in res["machine"].items()]
    lines += [f"- benchmark wall time: {res['elapsed']:.0f} s", "", "## Verdict", ""]
    lines += [f"- {v}" for v in verdict_lines(res)] + ["", "## Where camdyn's time goes, in short", ""]
    lines += [f"- {v}" for v in findings(res)] + [""]
    for s in sections(res):
        lines += [f"## {s.title}", ""] + _md_table(s.headers, s.rows) + [""]
        lines += [n + "  " for n in s.notes] + [""]
    return "\n".join(lines).rstrip() + "\n"


STYLE = {"camdyn-rk4": ("C0", "o", "-"), "camdyn-rk4-bare": ("C0", "o", ":"),
         "camdyn-rk4-steps": ("C0", "o", "--"),
         "yardstick": ("k", "x", "-"), "camdyn-dp54": ("C1", "s", "-"), "camdyn-dp54-bare": ("C1", "s", ":"),
         "camdyn-dop853": ("C5", "P", "-"), "camdyn-dop853-bare": ("C5", "P", ":"),
         "camdyn-rkn12": ("C6", "*", "-"), "camdyn-rkn12-bare": ("C6", "*", ":"),
         "ivp-DOP853": ("C2", "^", "-"), "ivp-RK45": ("C3", "v", "-"), "odeint": ("C4", "D", "-")}


def chart(res, path: Path) -> Path:
    """Log-log U0 error against time per simulation, every sweep point."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(9, 6))
    for key, pts in res["sweeps"].items():
        color, marker, ls = STYLE.get(key, ("gray", ".", "-"))
        ax.loglog([p.seconds * 1e3 for p in pts], [p.error for p in pts], color=color, marker=marker,
                  ls=ls, ms=4, lw=1.2, label=_label(res, key))
    for t in TARGETS:
        ax.axhline(t, color="gray", lw=0.6, ls="--")
    ax.set_xlabel("time per simulation [ms] (median, wall clock, one thread)")
    ax.set_ylabel("|U0 - U0_ref| (absolute)")
    ax.set_title(f"CAMSHAFT-1 (4.15), tau = {TAU:g}, Fa = {FA:g}, T in [0, {T_END:g}]: error vs time")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
