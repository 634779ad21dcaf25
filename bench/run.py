"""`make bench`: speed and accuracy of camdyn on CAMSHAFT-1, thesis (4.15).

tau = 0.15, Fa = 2, cycloidal rise, T in [0, 3], split at the breakpoint T = 1.
Measures in one run: the cost of one right-hand-side call; the median time per
simulation of camdyn's RK4 and DP54 (public simulate() and the bare compiled
loop) with the error of U0; a hand-written compiled RK4 loop (the yardstick,
bench/yardstick.pyx) on the same steps, against camdyn's RK4 integrating them
all (exact_segments=False) and as a user calls it (the dwell, linear and time
invariant, stepped over exactly); solve_ivp (DOP853, RK45) and odeint
on a NumPy right-hand side; the speed ratios at matched error.

Prints the tables, writes bench/results/BENCHMARKS-camshaft1.md and the chart
bench/out/error_vs_time.png.

    python bench/run.py            full run (about a minute here)
    python bench/run.py --quick    the same in miniature (three settings a method, one repeat,
                                   seconds), into a temporary folder: bench/results untouched
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from dataclasses import dataclass
from pathlib import Path

# single-threaded timing: keep OpenBLAS's idle worker threads out of the picture
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

HERE = Path(__file__).parent.resolve()
REPORT = "BENCHMARKS-camshaft1.md"
# 64 + 128 steps: what a call costs besides integrating.  The coarsest round step that is
# neither refused nor warned of (h rho = 0.654 under RK4's warning level 0.662, rho = 2 pi/tau
# = 41.9): near the boundary a run's warning is worded in Python, and that would be counted as
# the cost of a call.  Run with the check on, as a user runs it.  The quick pass times it too.
TRIVIAL_STEP = 1 / 64
REF_RTOL, REF_CHECK_STEP = 1e-13, 1e-4
SAME_STEPS_CHECK = 0.01
FINAL_REPEAT_FACTOR = 2         # matched-error timings: 2 repeat + 1 repeats (15 in a full run)


@dataclass(frozen=True)
class Plan:
    """How much is measured: the tables' settings, the steps of the malloc comparison, the
    repeats, and whether the sweeps are thinned to three settings a method."""

    rk4_table: tuple
    dp54_table: tuple
    malloc_steps: tuple
    repeat: int
    thin: bool


FULL = Plan((2e-2, 1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4),
            (1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10), (1e-3, 1e-4), 7, False)
QUICK = Plan((2e-2, 1e-3), (1e-4, 1e-8), (1e-3,), 1, True)


def _progress(msg: str) -> None:
    print(f"  [{time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


def reference() -> dict:
    """U0 from camdyn DP54 at rtol 1e-13, checked against RK4 at h = 1e-4 (camdyn and yardstick)."""
    from competitors import camdyn_simulate, yardstick_rk4
    from problem import u0

    dp = camdyn_simulate("dp54").info(REF_RTOL)
    u_ref = u0(dp[0], dp[1])
    checks = {f"camdyn RK4, h = {REF_CHECK_STEP:g}": camdyn_simulate("rk4").info(REF_CHECK_STEP),
              f"yardstick RK4, h = {REF_CHECK_STEP:g}": yardstick_rk4().info(REF_CHECK_STEP)}
    return {"u0": u_ref, "rtol": REF_RTOL,
            "checks": {k: u0(v[0], v[1]) - u_ref for k, v in checks.items()},
            "same_steps": same_steps(SAME_STEPS_CHECK)}


def same_steps(h: float) -> dict:
    """Do camdyn's RK4 and the yardstick take the same steps?  Compare their records."""
    import numpy as np

    import yardstick
    from camdyn.runtime.core.simulator import simulate
    from problem import FA, MODEL, PARAMS, T_END, TAU

    r = simulate(MODEL, PARAMS, T_END, "rk4", step=h, exact_segments=False)
    t, y, _, _ = yardstick.rk4(TAU, FA, h, T_END)
    same_t = r.t.shape == t.shape and bool(np.array_equal(r.t, t))
    return {"h": h, "points": len(t), "same_t": same_t,
            "max_dy": float(np.abs(r.y - y).max()) if same_t else float("nan")}


def sweeps(bench, groups) -> dict:
    """Every competitor's error-vs-time sweep; a group is timed side by side."""
    out = {}
    for group in groups:
        t0 = time.perf_counter()
        got = bench.sweep(group)
        out.update(got)
        names = ", ".join(c.label for c in group)
        _progress(f"{names}: {len(got[group[0].key])} settings, {time.perf_counter() - t0:.1f} s")
    return out


def matched_settings(bench, comps, sweeps_, target) -> dict:
    """Each competitor's matched point; bare loop and yardstick on the steps of their simulate() run."""
    from matching import matched

    pts = {k: matched(v, target) for k, v in sweeps_.items()}
    same = {"camdyn-rk4-steps": "camdyn-rk4", "camdyn-rk4-bare": "camdyn-rk4",
            "yardstick": "camdyn-rk4", "camdyn-dp54-bare": "camdyn-dp54",
            "camdyn-dop853-bare": "camdyn-dop853", "camdyn-rkn12-bare": "camdyn-rkn12"}
    for key, lead in same.items():
        if pts[lead] is not None:
            pts[key] = bench.points([comps[key]], pts[lead].setting)[0]
    return {k: p for k, p in pts.items() if p is not None}


def finals(bench, comps, sweeps_, repeat) -> dict:
    """Per target, every competitor at its matched setting, timed side by side."""
    from matching import TARGETS, final_times

    out = {}
    for target in TARGETS:
        t0 = time.perf_counter()
        out[target] = final_times(bench, comps, matched_settings(bench, comps, sweeps_, target), repeat)
        _progress(f"matched error {target:.0e}: side-by-side timing, {time.perf_counter() - t0:.1f} s")
    return out


def collect(plan: Plan) -> dict:
    """Every measurement of the benchmark, in one process and one run."""
    import diagnostics
    from competitors import sweep_groups
    from matching import Bench

    repeat = plan.repeat
    groups = sweep_groups(thin=plan.thin)
    rk4_trio, dp54_pair = groups[0], groups[1]
    ref = reference()
    _progress(f"reference U0 = {ref['u0']:.15g}")
    bench = Bench(ref["u0"], repeat)
    res = {"repeat": repeat, "reference": ref, "comps": {c.key: c for g in groups for c in g}}
    res["rhs"] = diagnostics.rhs_costs(repeat)
    res["sweeps"] = sweeps(bench, groups)
    res["rk4_table"] = [dict(zip((c.key for c in rk4_trio), bench.points(rk4_trio, h)))
                        for h in plan.rk4_table]
    res["dp54_table"] = [dict(zip((c.key for c in dp54_pair), bench.points(dp54_pair, r)))
                         for r in plan.dp54_table]
    res["final_repeat"] = FINAL_REPEAT_FACTOR * repeat + 1
    res["matched"] = finals(bench, res["comps"], res["sweeps"], res["final_repeat"])
    _progress("overhead breakdown")
    steps = sorted({v["camdyn-rk4"].setting for v in res["matched"].values() if "camdyn-rk4" in v},
                   reverse=True)
    # the per-step costs are slopes between the trivial run and a fine one: one is needed even
    # where RK4 reached no target (a thinned sweep)
    steps = steps or [min(plan.rk4_table)]
    res["overheads"] = {h: diagnostics.overheads(h, repeat) for h in (TRIVIAL_STEP, *steps)}
    res["malloc"] = diagnostics.malloc_effect(list(plan.malloc_steps), repeat)
    return res


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true",
                    help="a miniature run in seconds, written to a temporary folder")
    ap.add_argument("--no-write", action="store_true", help=f"print only, do not write {REPORT}")
    args = ap.parse_args(argv)

    sys.path.insert(0, str(HERE))
    import build

    build.build()
    import report
    from where import report_folder, scratch_folder, write_report

    t0 = time.perf_counter()
    res = collect(QUICK if args.quick else FULL)
    res["machine"] = report.machine_info()
    res["elapsed"] = time.perf_counter() - t0
    with report_folder(args.quick) as folder:
        chart = report.chart(res, scratch_folder(args.quick, folder) / "error_vs_time.png")
        print(report.text(res, chart))
        if not args.no_write:
            write_report(folder / REPORT, report.markdown(res))
            print(f"wrote {folder / REPORT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
