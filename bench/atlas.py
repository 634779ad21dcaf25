"""`make bench` (atlas part): a design atlas of CAMSHAFT-1 through camdyn sweep.

The atlas: CAMSHAFT-1 (4.15), rise and dwell, T in [0, 3], for 8 cam laws (every law of
runtime/core/laws.py but the uniform one, whose acceleration is infinite at its ends) x 20
Fa (0, then 0.01 to 10 geometrically) x 1000 tau from 0.06 to 0.7 (uniform in 1/tau, as
fig. 4.11) = 160,000 runs, DOP853 at rtol 1e-9 with its exact dwell, the residual figures U0,
U0'', X''min in the rise and its T, error estimates off (one sweep per law).

Timed (wall clock, whole atlas, median of repeats): sweep(jobs=<cores>), the compiled chunks
on threads; and sweep(dask=client) on a LocalCluster of 2 worker processes, 1 thread each
(cluster start outside the timing, given separately).  The two tables must be equal bit for
bit.  Goal: the atlas in under 15 s on this 2-core machine.

    python bench/atlas.py            writes bench/results/BENCHMARKS-atlas.md
    python bench/atlas.py --quick    2 laws x 2 Fa x 20 tau, one repeat, into a temporary folder
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np

HERE = Path(__file__).parent.resolve()
sys.path.insert(0, str(HERE))

from report import machine_info  # noqa: E402

LAWS = ("cycloidal", "modified-sine", "3-4-5", "simple-harmonic", "parabolic", "4-5-6-7",
        "modified-trapezoid", "sine-constant-cosine")
FA = (0.0, *np.geomspace(0.01, 10.0, 19))
N_TAU = 1000
QUICK = (LAWS[:2], (0.0, 1.0), 20)
METHOD, RTOL = "dop853", 1e-9
GOAL = 15.0     # s, the whole atlas on this machine's cores
REPORT = "BENCHMARKS-atlas.md"
FIGURES = ("U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min")


def _say(msg: str) -> None:
    print(f"  [{time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


def atlas(laws, grid, **how) -> dict:
    """law -> the sweep's figure columns."""
    from camdyn.runtime.studies import sweep as sw
    from camdyn.runtime.targets.model_target import ModelTarget

    out = {}
    for law in laws:
        target = ModelTarget.of("camshaft1", t_end=3.0, method=METHOD, rtol=RTOL, law=law)
        res = sw.sweep(target, grid, progress=False, estimate=False, **how)
        out[law] = {k: np.asarray(res.columns[k]) for k in FIGURES}
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true",
                    help="a miniature run in seconds, written to a temporary folder")
    args = ap.parse_args(argv)
    laws, fa, n_tau = QUICK if args.quick else (LAWS, FA, N_TAU)
    repeat = 1 if args.quick else args.repeat

    from camdyn.runtime.measure.envelope import tau_grid
    from camdyn.runtime.targets.grid import default_jobs

    t_bench = time.perf_counter()
    grid = {"Fa": [float(f) for f in fa], "tau": tau_grid(0.06, 0.7, n_tau)}
    n = len(laws) * len(fa) * n_tau
    cores = default_jobs()
    _say(f"{n} runs: {len(laws)} laws x {len(fa)} Fa x {n_tau} tau, {cores} cores")
    atlas(laws[:1], {"Fa": grid["Fa"][:1], "tau": grid["tau"][:8]}, jobs=cores)  # imports, builds
    times = {"threads": [], "dask": []}
    table = None
    for r in range(repeat):
        t0 = time.perf_counter()
        table = atlas(laws, grid, jobs=cores)
        times["threads"].append(time.perf_counter() - t0)
        _say(f"repeat {r + 1}/{repeat}: {times['threads'][-1]:.2f} s on {cores} threads")
    from cluster import start_local_cluster

    client, cluster, dask_start = start_local_cluster(_say)
    same = None
    if client is not None:
        atlas(laws[:1], {"Fa": grid["Fa"][:1], "tau": grid["tau"][:8]}, dask=client)
        for r in range(repeat):
            t0 = time.perf_counter()
            on_dask = atlas(laws, grid, dask=client)
            times["dask"].append(time.perf_counter() - t0)
            _say(f"repeat {r + 1}/{repeat}: {times['dask'][-1]:.2f} s on Dask")
        client.close()
        cluster.close()
        same = all(np.array_equal(on_dask[law][k], table[law][k]) for law in laws
                   for k in FIGURES)
    med = {k: statistics.median(v) if v else float("nan") for k, v in times.items()}
    text = markdown(med, times, n, laws, fa, n_tau, cores, dask_start, same, table, repeat,
                    time.perf_counter() - t_bench)
    if args.quick:
        print(text)
    from where import report_folder, write_report

    with report_folder(args.quick) as folder:
        write_report(folder / REPORT, text)
        print(f"wrote {folder / REPORT}")
    print(f"atlas of {n} runs: {med['threads']:.2f} s on {cores} threads, "
          f"{med['dask']:.2f} s on Dask (2 workers)")
    return 0


def markdown(med, times, n, laws, fa, n_tau, cores, dask_start, same, table, repeat,
             wall) -> str:
    per_run = 1e6 * med["threads"] * cores / n
    verdict = "MET" if med["threads"] < GOAL else "NOT MET"
    lines = ["# Atlas benchmark: 8 cam laws x 20 Fa x 1000 tau of CAMSHAFT-1", "",
             "Written by `make bench` (`bench/atlas.py`; its docstring says what is timed).", "",
             f"CAMSHAFT-1 (4.15), rise and dwell, T in [0, 3], {METHOD.upper()} rtol {RTOL:g} "
             f"(its dwell exact), residual figures, error estimates off: {len(laws)} laws x "
             f"{len(fa)} Fa x {n_tau} tau = {n} runs.", "",
             "## Machine", ""]
    lines += [f"- {k}: {v}" for k, v in machine_info().items()]
    lines += [f"- benchmark wall time: {wall:.0f} s", "",
              "## Verdict", "",
              f"- Goal 'the atlas in under {GOAL:g} s on this machine ({cores} cores)': "
              f"**{verdict}** ({med['threads']:.2f} s, median of {repeat}; "
              f"{per_run:.0f} us of one core a run).",
              f"- On Dask (LocalCluster, 2 worker processes): {med['dask']:.2f} s "
              f"(cluster start {dask_start:.1f} s, not included); the same table bit for bit: "
              f"{'yes' if same else 'n/a' if same is None else 'NO'}.", "",
              "## Times", "",
              "| run | median | all repeats |", "|:---|---:|:---|",
              f"| camdyn sweep, {cores} threads | {med['threads']:.2f} s | "
              f"{', '.join(f'{t:.2f}' for t in times['threads'])} |",
              f"| camdyn sweep on Dask, 2 workers | {med['dask']:.2f} s | "
              f"{', '.join(f'{t:.2f}' for t in times['dask'])} |", "",
              "## The atlas in short", "",
              "Per law: the smallest U0 over the grid at Fa = 0 and at the largest Fa, and the "
              "deepest X''min in the rise (the table itself is not kept).", "",
              "| law | min U0, Fa = 0 | min U0, largest Fa | min X''min in the rise |",
              "|:---|---:|---:|---:|"]
    k0, k1 = slice(0, n_tau), slice((len(fa) - 1) * n_tau, len(fa) * n_tau)
    for law in laws:
        t = table[law]
        lines.append(f"| {law} | {t['U0'][k0].min():.3g} | {t['U0'][k1].min():.3g} | "
                     f"{t['Xdd_min_rise'].min():.4g} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
