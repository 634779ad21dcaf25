"""`make bench` (sweep part): the fig. 4.11 grid through camdyn sweep (README "Sweeps").

Grid: CAMSHAFT-1 (4.15), cycloidal rise and dwell, T in [0, 3], DP54 at rtol 1e-9 (atol 1e-12),
Fa = 0, 0.1, 0.3, 1, 3, 10 and 400 values of tau from 0.06 to 0.7 uniform in 1/tau
(runtime/measure/envelope.py's tau_grid): 2400 runs, each giving U0, U0'', X''min in the rise and its T.

Timed (wall clock, median of repeats taken in turn, so that a drift of the machine's speed
touches all alike; CPU time of the process beside the one-core figures), every sweep without
its error estimate (estimate=False): the estimate runs the grid again one notch tighter, so a
sweep with it takes the time of this one at rtol 1e-9 plus this one at 1e-10:
  bare integrations   Integrator.run of every grid point with its parameter vector and stop
                      times made beforehand: the compiled loops and their record, nothing else
  sweep, one core     sweep(jobs=1): the compiled chunks, integration and figures
  sweep, all cores    sweep(jobs=<cores>): threads around the nogil chunks
  sweep, processes    the same chunks on a process pool of <cores> workers (started inside the
                      timing: what a user would pay), for the choice of threads
  sweep, Dask         sweep(dask=client) on a LocalCluster of 2 worker processes, 1 thread
                      each (cluster start outside the timing, given separately)
  Python path         Simulator.run + residual() per point (compiled figures, a Result each),
                      and Simulator.run + residual_reference() (the SciPy figures, the old path)
Accuracy: the sweep's figures against the old path's, the largest difference per figure over
the grid relative to the figure's largest value.

Other targets, compiled chunks against runs one at a time (one core each, the same points,
taken in turn in every repeat; the tables must be equal to the last bit):
  DYNACAM scene       spring_loaded (fig. 7.2) over its follower stiffness c_x: each point's
                      consistent initial state in Python, the runs and figures of a chunk in
                      one nogil call, against DynacamTarget.run per point
  model file          bench/models/oscillator.py, README's model file (built on first use
                      into camdyn's cache), its states at t = 3 s over its spring c, against
                      Simulator.run per point (one Simulator for all)

    python bench/sweep.py            writes bench/results/BENCHMARKS-sweep.md
    python bench/sweep.py --quick    the same in miniature (2 Fa x 20 tau, one repeat, Dask
                                     included), into a temporary folder
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np

HERE = Path(__file__).parent.resolve()
sys.path.insert(0, str(HERE))

from report import machine_info  # noqa: E402

OTHERS = {"dynacam": 64, "model file": 400}
QUICK_OTHERS = {"dynacam": 4, "model file": 40}
"""Grid points of the other targets' sweeps."""
FA = (0.0, 0.1, 0.3, 1.0, 3.0, 10.0)
N_TAU = 400
QUICK_FA, QUICK_N_TAU = (0.0, 1.0), 20
GOAL = 1.0      # s, one core, the full grid
GOAL_BEST = 0.2  # s, one core, the full grid with the fastest method
REPORT = "BENCHMARKS-sweep.md"


def _say(msg: str) -> None:
    print(f"  [{time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


def _timed(fn):
    w, c = time.perf_counter(), time.process_time()
    out = fn()
    return time.perf_counter() - w, time.process_time() - c, out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--quick", action="store_true",
                    help="a miniature run in seconds, written to a temporary folder")
    args = ap.parse_args(argv)
    repeat = 1 if args.quick else args.repeat
    fa, n_tau = (QUICK_FA, QUICK_N_TAU) if args.quick else (FA, N_TAU)

    from camdyn.runtime.studies import sweep as sw
    from camdyn.runtime.measure.envelope import tau_grid
    from camdyn.runtime.measure.residual import FIGURES, residual, residual_reference
    from camdyn.runtime.targets.grid import default_jobs, run_chunk
    from camdyn.runtime.targets.model_target import ModelTarget

    t_bench = time.perf_counter()
    taus = tau_grid(0.06, 0.7, n_tau)
    grid = {"Fa": list(fa), "tau": taus}
    target = ModelTarget.of("camshaft1", t_end=3.0, method="dp54", rtol=1e-9, law="cycloidal")
    model, sim = target.model, target.simulator
    pts = np.array([[a, b] for a in fa for b in taus])
    ps = [model.parameter_vector({"Fa": float(a), "tau": float(b)}) for a, b in pts]
    stops = [sim.stops(p) for p in ps]
    cores = default_jobs()
    chunks = [pts[i:i + 200] for i in range(0, len(pts), 200)]

    def bare():
        loops = 0.0
        for p, s in zip(ps, stops):
            loops += sim.integrator.run(p, s, 8192).seconds
        return loops

    def processes():
        with ProcessPoolExecutor(max_workers=cores) as pool:
            return list(pool.map(run_chunk, [target] * len(chunks), [("Fa", "tau")] * len(chunks),
                                 chunks))

    from cluster import start_local_cluster

    client, cluster, dask_start = start_local_cluster(_say)
    if client is not None:
        sw.sweep(target, grid, dask=client, progress=False, estimate=False)  # warm the workers (imports)

    times = {k: [] for k in ("bare", "bare_cpu", "bare_loops", "driver_cpu", "one", "one_cpu",
                             "all", "proc", "dask", "one_dop853")}
    # the same grid with camdyn's fastest method here, DOP853 (its dwell exact), at the same rtol
    dop853 = ModelTarget.of("camshaft1", t_end=3.0, method="dop853", rtol=1e-9, law="cycloidal")
    from functools import partial

    from camdyn.runtime.engine import finder
    with_figures = finder.sweep_residual

    def driver_only():
        # the sweep's own compiled driver with the figures left out: the integration's share
        finder.sweep_residual = partial(with_figures, figures_too=False)
        try:
            sw.sweep(target, grid, jobs=1, progress=False, estimate=False)
        finally:
            finder.sweep_residual = with_figures
    result_one = None
    for r in range(repeat):
        _say(f"repeat {r + 1}/{repeat}")
        w, c, loops = _timed(bare)
        times["bare"].append(w)
        times["bare_cpu"].append(c)
        times["bare_loops"].append(loops)
        w, c, _ = _timed(driver_only)
        times["driver_cpu"].append(c)
        w, c, res = _timed(lambda: sw.sweep(target, grid, jobs=1, progress=False,
                                            estimate=False))
        times["one"].append(w)
        times["one_cpu"].append(c)
        result_one = res
        w, c, res_dop853 = _timed(lambda: sw.sweep(dop853, grid, jobs=1, progress=False,
                                                   estimate=False))
        times["one_dop853"].append(w)
        w, c, res_all = _timed(lambda: sw.sweep(target, grid, jobs=cores, progress=False,
                                                estimate=False))
        times["all"].append(w)
        w, c, _ = _timed(processes)
        times["proc"].append(w)
        if client is not None:
            w, c, res_dask = _timed(lambda: sw.sweep(target, grid, dask=client, progress=False,
                                                     estimate=False))
            times["dask"].append(w)
        else:
            res_dask = result_one
            times["dask"].append(float("nan"))
    if client is not None:
        client.close()
        cluster.close()
    same = {name: bool(np.array_equal(res_all[name], result_one[name])
                       and np.array_equal(res_dask[name], result_one[name]))
            for name in FIGURES}

    _say("other targets: compiled chunks against runs one at a time")
    others = other_targets(QUICK_OTHERS if args.quick else OTHERS, repeat)
    med = {k: statistics.median(v) for k, v in times.items()}
    old = {}
    _say("the Python paths, once each (about 20 s on the full grid)")
    runs = []
    w, c, _ = _timed(lambda: runs.extend(sim.run({"Fa": float(a), "tau": float(b)})
                                         for a, b in pts))
    old["runs"] = w
    w, c, figs = _timed(lambda: [residual(r) for r in runs])
    old["residual"] = w
    w, c, ref = _timed(lambda: [residual_reference(r) for r in runs])
    old["reference"] = w
    dev = {}
    for name in FIGURES:
        b = np.array([getattr(x, name) for x in ref])
        for key, res_k in (("dp54", result_one), ("dop853", res_dop853)):
            dev[key, name] = float(np.abs(res_k[name] - b).max() / np.abs(b).max())
    old["deviation"] = dev

    wall = time.perf_counter() - t_bench
    text = markdown(med, times, old, dask_start, cores, same, repeat, wall, fa, n_tau) + \
        others_markdown(others, repeat)
    if args.quick:
        print(text)
    from where import report_folder, write_report

    with report_folder(args.quick) as folder:
        write_report(folder / REPORT, text)
        print(f"wrote {folder / REPORT}")
    print(f"sweep of the {'miniature' if args.quick else 'fig. 4.11'} grid: one core {med['one']:.3f} s "
          f"({med['one'] / med['bare']:.2f} x the bare integrations, {med['bare']:.3f} s); "
          f"{cores} cores {med['all']:.3f} s; Dask (2 workers) {med['dask']:.3f} s")
    return 0


def markdown(med, times, old, dask_start, cores, same, repeat, wall, fa=FA, n_tau=N_TAU) -> str:
    n = len(fa) * n_tau
    ms = lambda s: f"{1e3 * s:.0f} ms"   # noqa: E731
    rows = [
        ("bare integrations (Integrator.run, prebuilt inputs)", med["bare"],
         f"CPU {ms(med['bare_cpu'])}; compiled loops alone {ms(med['bare_loops'])}"),
        ("camdyn sweep, one core (jobs=1)", med["one"],
         f"CPU {ms(med['one_cpu'])}; without the figures CPU {ms(med['driver_cpu'])}"),
        ("camdyn sweep, one core, DOP853 rtol 1e-9 (its dwell exact)", med["one_dop853"], ""),
        (f"camdyn sweep, all cores (jobs={cores}, threads)", med["all"], ""),
        (f"the same chunks on {cores} processes (pool start included)", med["proc"], ""),
        ("camdyn sweep on Dask (LocalCluster, 2 worker processes)", med["dask"],
         f"cluster start {dask_start:.1f} s, not included"),
    ]
    if old:
        rows += [("Python path: Simulator.run per point", old["runs"], ""),
                 ("  + residual() per run (compiled figures)", old["runs"] + old["residual"],
                  f"figures {ms(old['residual'])}"),
                 ("  + residual_reference() per run (the old path, SciPy)",
                  old["runs"] + old["reference"], f"figures {ms(old['reference'])}")]
    lines = ["# Sweep benchmark: the fig. 4.11 grid", "",
             "Written by `make bench` (`bench/sweep.py`; its docstring says what is timed).", "",
             f"CAMSHAFT-1 (4.15), cycloidal rise and dwell, T in [0, 3], DP54 rtol 1e-9; Fa = "
             f"{', '.join(f'{f:g}' for f in fa)} x {n_tau} tau from 0.06 to 0.7 (uniform in "
             f"1/tau) = {n} runs, U0, U0'', X''min in the rise and its T each.", "",
             "## Machine", ""]
    lines += [f"- {k}: {v}" for k, v in machine_info().items()]
    lines += [f"- benchmark wall time: {wall:.0f} s", ""]
    one = med["one"]
    verdict = "MET" if one < GOAL else "NOT MET"
    lines += ["## Verdict", "",
              f"- Goal 'the fig. 4.11 grid in under {GOAL:g} s on one core': **{verdict}** "
              f"({one:.3f} s, median of {repeat}).",
              f"- Ratio to the bare integrations: **{one / med['bare']:.2f}** "
              f"({one:.3f} s against {med['bare']:.3f} s; in CPU time "
              f"{med['one_cpu'] / med['bare_cpu']:.2f}, {med['one_cpu']:.3f} s against "
              f"{med['bare_cpu']:.3f} s): what the figures, the chunking and the Python around a "
              "sweep add to integrating the grid.",
              f"- Goal 'the fig. 4.11 grid in under {GOAL_BEST:g} s on one core with camdyn's "
              f"fastest method' (DOP853, its dwell exact): "
              f"**{'MET' if med['one_dop853'] < GOAL_BEST else 'NOT MET'}** "
              f"({med['one_dop853']:.3f} s, median of {repeat}).",
              ]
    if old:
        lines.append(f"- Against the old path (a Result and SciPy's figures per run): "
                     f"{(old['runs'] + old['reference']) / one:.0f}x faster.")
    lines += [f"- All cores ({cores}): {med['all']:.3f} s, {one / med['all']:.2f}x one core; "
              f"Dask with 2 local workers: {med['dask']:.3f} s.",
              "- Tables of threads, Dask and one core equal to the last bit: "
              + ("yes" if all(same.values()) else f"NO ({same})"), ""]
    lines += ["## Times (median of repeats, wall clock)", "",
              "| what | time | per run | note |", "|:---|---:|---:|:---|"]
    for label, t, note in rows:
        lines.append(f"| {label} | {t:.3f} s | {1e6 * t / n:.0f} us | {note} |")
    lines += ["", "CPU times are the process's, every thread counted: the Dask scheduler of the "
              "LocalCluster runs in this process and adds a little while it idles.", ""]
    lines += ["Every repeat (s): " + "; ".join(
        f"{k} " + ", ".join(f"{x:.3f}" for x in v) for k, v in times.items()), ""]
    if old:
        lines += ["## Accuracy against the old path", "",
                  "Largest difference over the grid, relative to the figure's largest value "
                  "(the sweep refines the 4 best peaks of a scan of every 3rd recorded point; the "
                  "old path the best of 12 samples a step: where peaks are equal to within the "
                  "integration error, as in the undamped dwell, either may be taken).", "",
                  "| figure | DP54: max difference / max value | DOP853 |", "|:---|---:|---:|"]
        names = dict.fromkeys(name for _, name in old["deviation"])
        lines += [f"| {k} | {old['deviation']['dp54', k]:.1e} | "
                  f"{old['deviation']['dop853', k]:.1e} |" for k in names]
        lines.append("")
    lines += ["## Threads or processes", "",
              "A chunk of grid points runs in compiled code holding no GIL (runtime/engine/finder.pyx),",
              "so threads share the cores without copying anything; processes must start, import",
              "camdyn and pickle their chunks back. camdyn sweep uses threads; the process row",
              "above is the measured alternative.  On a machine whose cores are busy with other",
              "work the all-cores figure gains less than the core count.", ""]
    return "\n".join(lines)


def other_targets(sizes: dict, repeat: int) -> dict:
    """{kind: (points, per-point times, compiled times, tables equal)} (module doc)."""
    from camdyn.runtime.targets.base import Target
    from camdyn.runtime.targets.model_target import StateTarget
    from camdyn.runtime.targets.resolve import resolve

    dyn = resolve("spring_loaded")
    c_x = dyn.scene.parameters["c_x"]
    model_file = str(HERE / "models" / "oscillator.py")      # built on demand, then cached
    cases = {"dynacam": (dyn, "c_x", np.linspace(0.8 * c_x, 1.2 * c_x, sizes["dynacam"])),
             "model file": (resolve(model_file, model_class=StateTarget, t_end=3.0, rtol=1e-9,
                                    progress=_say),
                            "c", np.linspace(300.0, 900.0, sizes["model file"]))}
    out = {}
    for kind, (target, name, values) in cases.items():
        pts = values[:, None]
        target = target.fit_points((name,), pts)
        slow, fast, same = [], [], True
        figs = target.figure_names()

        def one_at_a_time():
            if kind == "dynacam":        # a scene's run per point: its own Simulator
                return Target.run_points(target, (name,), pts).figures
            # a model's runs share one Simulator, as `camdyn sweep` ran them point by point
            return np.array([[target.read(target.simulator.run({name: float(v)})).figures[f]
                              for f in figs] for v in values])
        for _ in range(repeat):
            w, _, a = _timed(one_at_a_time)
            slow.append(w)
            w, _, b = _timed(lambda: target.run_points((name,), pts))
            fast.append(w)
            same &= bool(np.array_equal(a, b.figures, equal_nan=True))
        out[kind] = (len(pts), slow, fast, same)
    return out


def others_markdown(others: dict, repeat: int) -> str:
    lines = ["", "## Other targets: compiled chunks against runs one at a time", "",
             "One core each, the same points (bench/sweep.py's docstring says what is run); "
             f"median of {repeat}.", "",
             "| target | points | one at a time | compiled chunk | ratio | tables equal to the "
             "last bit |", "|:---|---:|---:|---:|---:|:---|"]
    for kind, (n, slow, fast, same) in others.items():
        a, b = statistics.median(slow), statistics.median(fast)
        lines.append(f"| {kind} | {n} | {a:.3f} s | {b:.3f} s | **{a / b:.2f}** | "
                     f"{'yes' if same else 'NO'} |")
    return "\n".join(lines + [""])


if __name__ == "__main__":
    sys.exit(main())
