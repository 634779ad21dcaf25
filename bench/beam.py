"""`make bench` (second part): the Rayleigh-beam follower's two formulations, speed against
accuracy (the paper's cam and rod, README "Rayleigh-beam follower").

Problem: the paper's case (N assumed modes, Omega = 240 rad/s, one cam revolution from the
rigid state at theta = 0).  Error measure: max |v_E| over the revolution against a reference
run at rtol = 1e-12 of the same formulation and N (the two formulations' references agree to
the digits printed).  Times: median of repeated runs, CPU of the compiled integration only,
both formulations timed alternately in the same process; the ratio partitioned/augmented is
the figure to read, absolute times drift with the machine.

Second part: N = 6 as `camdyn beam-follower --modes 6` runs it (augmented, the mode amplitudes
to MODE_ATOL of the rod's deflection scale, their rates to that times the highest frozen
frequency), one revolution, DOP853 and DP54; error against DOP853 at rtol 1e-11 with a thousandth
of that mode tolerance; the goal: one revolution at rtol 1e-6 in under 0.3 s of CPU.

    python bench/beam.py            writes bench/results/BENCHMARKS-beam.md and
                                    bench/out/beam_error_vs_time.png
    python bench/beam.py --quick    the same in miniature (N = 2, two tolerances, one repeat,
                                    a looser reference), into a temporary folder
"""
from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time
from dataclasses import replace
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

HERE = Path(__file__).parent.resolve()
ROOT = HERE.parent
RTOLS = (1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10)
REF_RTOL = 1e-12
FORMS = ("augmented", "partitioned")
REPORT = "BENCHMARKS-beam.md"


def _progress(msg: str) -> None:
    print(f"  [{time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


def tip_max(case, calls: bool = False) -> tuple:
    """(max |v_E|, CPU seconds of the integration, steps, max |Phi|) of one run; with
    ``calls``, also (the run's right-hand-side calls, those its figures made after it: the
    DOP853 dense output the run left out, made where the extremes refine a peak)."""
    from camdyn.runtime.targets import beam

    sim, _ = beam.simulator(case)
    c0 = time.process_time()
    res = sim.run(beam.parameters(case))
    cpu = time.process_time() - c0
    s = beam.summarize(case, res, cpu)
    out = (s["max_abs_tip_deflection"], cpu, s["n_steps"], s["max_constraint_residual"])
    if calls:
        out += (res.stats["n_rhs"], res.stats.get("n_rhs_dense_output", 0))
    return out


def measure(modes_list, repeat: int, rtols=RTOLS, ref_rtol=REF_RTOL) -> list:
    from camdyn.runtime.targets import beam

    rows = []
    for n in modes_list:
        base = replace(beam.Case(), modes=n)
        refs = {f: tip_max(replace(base, formulation=f, rtol=ref_rtol))[0] for f in FORMS}
        _progress(f"N = {n}: references {refs['augmented']:.12e} / {refs['partitioned']:.12e}")
        for rtol in rtols:
            times = {f: [] for f in FORMS}
            info = {}
            for _ in range(repeat):
                for f in FORMS:       # alternate, so that a drift of the machine hits both
                    v, cpu, steps, phi = tip_max(replace(base, formulation=f, rtol=rtol))
                    times[f].append(cpu)
                    info[f] = (abs(v - refs[f]) / refs[f], steps, phi)
            row = {"modes": n, "rtol": rtol, "ref_diff": abs(refs["augmented"] - refs["partitioned"]) / refs["augmented"]}
            for f in FORMS:
                row[f] = {"cpu": statistics.median(times[f]), "error": info[f][0], "steps": info[f][1],
                          "phi": info[f][2]}
            row["ratio"] = row["partitioned"]["cpu"] / row["augmented"]["cpu"]
            rows.append(row)
            _progress(f"N = {n}, rtol = {rtol:g}: ratio partitioned/augmented {row['ratio']:.2f}")
    return rows


SIX_SETTINGS = (("dop853", 1e-6), ("dp54", 1e-6), ("dop853", 1e-9))
GOAL_CPU = 0.3
"""Seconds of CPU for one revolution of N = 6 at rtol 1e-6 (the goal of the second part)."""


def six_modes(repeat: int, modes: int = 6, settings=SIX_SETTINGS) -> list:
    """The second part: rows of (method, rtol, CPU median, steps, error) at the command's mode
    tolerance."""
    from camdyn.runtime.targets import beam
    from camdyn.runtime.targets.beam_case import MODE_ATOL

    base = replace(beam.Case(), modes=modes, mode_atol=MODE_ATOL)
    ref = tip_max(replace(base, method="dop853", rtol=1e-11, mode_atol=MODE_ATOL / 1000))[0]
    rows = []
    for method, rtol in settings:
        runs = [tip_max(replace(base, method=method, rtol=rtol), calls=True) for _ in range(repeat)]
        v, _, steps, _, n_rhs, n_after = runs[-1]
        rows.append({"modes": modes, "method": method, "rtol": rtol, "steps": steps,
                     "cpu": statistics.median(r[1] for r in runs), "error": abs(v - ref) / ref,
                     "rhs": n_rhs, "rhs_after": n_after})
        _progress(f"N = {modes}, {method}, rtol = {rtol:g}: {steps} steps, "
                  f"{rows[-1]['cpu']:.3f} s")
    return rows


def six_report(rows, repeat: int) -> list[str]:
    lines = [f"## N = {rows[0]['modes']} with the command's mode tolerance", "",
             f"`camdyn beam-follower --modes 6`'s tolerances (MODE_ATOL), augmented, one revolution; "
             f"CPU: median of {repeat} runs; error: max |v_E| against DOP853 at rtol 1e-11 with "
             "MODE_ATOL/1000, relative.  rhs calls: the run's; after: those the figures made "
             "after it (DOP853's dense output, left out of the run but where a cam segment "
             "ends, made step by step where an extreme refines or verifies a peak).", "",
             "| N | method | rtol | CPU [s] | steps | rhs calls | after | error |",
             "|---|---|---|---|---|---|---|---|"]
    lines += [f"| {r['modes']} | {r['method']} | {r['rtol']:.0e} | {r['cpu']:.3f} | {r['steps']} | "
              f"{r['rhs']} | {r['rhs_after']} | {r['error']:.1e} |" for r in rows]
    lines.append("")
    for r in rows:
        if r["rtol"] == 1e-6:
            met = "MET" if r["cpu"] < GOAL_CPU else "NOT MET"
            lines.append(f"- Goal 'N = {r['modes']}, rtol 1e-6, one revolution under "
                         f"{GOAL_CPU:g} s of CPU' with {r['method']}: {r['cpu']:.3f} s, {met}.")
    return lines + [""]


def chart(rows, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for n in sorted({r["modes"] for r in rows}):
        for f, mark in zip(FORMS, ("o-", "s--")):
            pts = [(r[f]["cpu"], max(r[f]["error"], 1e-16)) for r in rows if r["modes"] == n]
            ax.loglog(*zip(*pts), mark, label=f"N = {n}, {f}")
    ax.set_xlabel("CPU time of one revolution [s] (median)")
    ax.set_ylabel("relative error of max |v_E|")
    ax.set_title("Rayleigh-beam follower: error against CPU time (DP54, rtol 1e-5 .. 1e-10)")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def report(rows, repeat: int, ref_rtol=REF_RTOL, six=()) -> str:
    import numpy as np
    import scipy

    lines = ["# Benchmark: the Rayleigh-beam follower's two formulations", "",
             "Written by `make bench` (`bench/beam.py`); rerun it to refresh every figure below.", "",
             "Problem: the paper's case, Omega = 240 rad/s, one cam revolution, DP54 at the rtol given. "
             f"Error: max |v_E| against a run at rtol = {ref_rtol:g} of the same formulation and N, relative. "
             f"Times: median of {repeat} runs, CPU of the compiled integration, the two formulations "
             "alternated in the same process; ratio = partitioned/augmented.", "",
             f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} logical CPUs, "
             f"Python {platform.python_version()}, NumPy {np.__version__}, SciPy {scipy.__version__}; "
             f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}.", "",
             "| N | rtol | augmented CPU [s] | error | steps | max abs Phi [m] | partitioned CPU [s] | error | steps | max abs Phi [m] | ratio |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        a, p = r["augmented"], r["partitioned"]
        lines.append(f"| {r['modes']} | {r['rtol']:.0e} | {a['cpu']:.3f} | {a['error']:.1e} | {a['steps']} | "
                     f"{a['phi']:.1e} | {p['cpu']:.3f} | {p['error']:.1e} | {p['steps']} | {p['phi']:.1e} | "
                     f"{r['ratio']:.2f} |")
    ratios = [r["ratio"] for r in rows]
    lines += ["", f"Ratio partitioned/augmented over all rows: median {statistics.median(ratios):.2f}, "
              f"range {min(ratios):.2f}-{max(ratios):.2f}.  The references of the two formulations "
              f"differ by at most {max(r['ref_diff'] for r in rows):.1e} (relative).", "",
              "Chart: `bench/out/beam_error_vs_time.png` (not committed).", ""]
    if six:
        lines += six_report(six, repeat)
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true",
                    help="a miniature run in seconds, written to a temporary folder")
    args = ap.parse_args(argv)
    sys.path.insert(0, str(HERE))
    from where import report_folder, scratch_folder, write_report

    if args.quick:
        repeat, modes, rtols, ref_rtol = 1, (2,), (1e-5, 1e-7), 1e-9
        six = six_modes(1, modes=2, settings=(("dop853", 1e-6),))
    else:
        repeat, modes, rtols, ref_rtol = 5, (2, 3, 4), RTOLS, REF_RTOL
        six = six_modes(repeat)
    rows = measure(modes, repeat, rtols, ref_rtol)
    text = report(rows, repeat, ref_rtol, six)
    print(text)
    with report_folder(args.quick) as folder:
        chart(rows, scratch_folder(args.quick, folder) / "beam_error_vs_time.png")
        write_report(folder / REPORT, text)
        print(f"wrote {folder / REPORT}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
