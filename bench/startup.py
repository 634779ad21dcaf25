"""`make bench` (start-up part): how long the common commands take as a user runs them, each a
fresh process, against starting Python with camdyn imported (the least any command costs).

Timed, in turn in every repeat (so that a drift of the machine's speed touches all alike), the
wall time and the CPU time of the process (user + system, every thread counted):
  baseline            python -c "import camdyn"
  camdyn --help       the commands and their lines of help
  camdyn residual     one rise of CAMSHAFT-1 at tau 0.15, Fa 2, with its error estimate
  camdyn simulate     the spring-loaded scene of fig. 7.2 (its summary)
  camdyn design       the README's examples: the short one (tau 0.2, Fa 0.1, u0 <= 0.1 mm),
                      App. 7's indexing mechanism and its follower with the App. 5 motor, each
                      with its check run
and, in this process after one warm-up call, design() of the three examples without the check
run (the graphs and the limits: their runs on every core), median of the repeats.  The
machine's load average is noted before and after: the goal (every design under 1 s of wall
time) is for a machine not busy with other work.

    python bench/startup.py            writes bench/results/BENCHMARKS-startup.md
    python bench/startup.py --quick    one repeat, into a temporary folder
"""
from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).parent.resolve()
REPORT = "BENCHMARKS-startup.md"
GOAL = 1.0
"""s of wall time, every design example, on a quiet machine."""

SHORT = ["--stroke", "0.02", "--tau", "0.2", "--fa", "0.1", "--accuracy", "1e-4"]
INDEXING = ["--stroke", "0.0981", "--cam-angle", "1.745", "--speed", "60", "--mass", "45",
            "--stiffness", "3.65e6", "--c-tan", "157109", "--pitch-radius", "0.085",
            "--ratio", "1.745", "--accuracy", "0.5e-3"]
FOLLOWER = ["--stroke", "0.0309", "--cam-angle", "0.436", "--speed", "47.5", "--mass", "1.46",
            "--stiffness", "0.376e6", "--c-tan", "38256", "--pitch-radius", "0.075", "--ratio",
            "2.06", "--accuracy", "1e-4", "--motor-rpm", "3000", "--spring", "--worm", "0.36",
            "0.05", "--slip-limit", "0.016"]
DESIGNS = {"design (short)": SHORT, "design (App. 7 indexing)": INDEXING,
           "design (App. 7 follower, motor)": FOLLOWER}


def commands() -> dict:
    """What is run, by label: the baseline first."""
    cli = [str(Path(sys.executable).with_name("camdyn"))]
    if not Path(cli[0]).exists():
        cli = [sys.executable, "-m", "camdyn.runtime.cli"]
    out = {"baseline: python -c \"import camdyn\"": [sys.executable, "-c", "import camdyn"],
           "camdyn --help": cli + ["--help"],
           "camdyn residual": cli + ["residual", "--model", "camshaft1", "--tau", "0.15",
                                     "--fa", "2"],
           "camdyn simulate": cli + ["simulate", "spring_loaded"]}
    out.update({f"camdyn {k}": cli + ["design", *v] for k, v in DESIGNS.items()})
    return out


def run_once(argv) -> tuple[float, float]:
    """(wall, CPU) of one fresh process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def in_process(repeat: int) -> dict:
    """design() of each example without its check run, median wall time after a warm-up."""
    from camdyn.thesis.design import machine
    from camdyn.thesis.design.method import design

    def kwargs(argv):
        pairs = dict(zip(argv[::2], argv[1::2]))
        num = {k.lstrip("-").replace("-", "_"): float(v) for k, v in pairs.items()
               if k not in ("--cam-angle", "--motor-rpm", "--spring", "--worm", "--slip-limit")}
        if "--cam-angle" in pairs:
            num["cam_angle_rad"] = machine.cam_angle(pairs["--cam-angle"])
        return {("Fa" if k == "fa" else k): v for k, v in num.items()}

    out = {}
    for label, argv in DESIGNS.items():
        kw = kwargs(argv[:argv.index("--motor-rpm")] if "--motor-rpm" in argv else argv)
        d = design(**kw, check=False)
        times = []
        for _ in range(repeat):
            t0 = time.perf_counter()
            design(**kw, check=False)
            times.append(time.perf_counter() - t0)
        out[label] = (statistics.median(times), d["graph_runs"])
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--quick", action="store_true", help="one repeat, into a temporary folder")
    ap.add_argument("--out", type=Path, help=f"the report (default: bench/results/{REPORT})")
    args = ap.parse_args(argv)
    if args.quick:
        args.repeat = 1
    sys.path.insert(0, str(HERE))
    from where import report_folder

    with report_folder(args.quick) as folder:
        return measure(args, args.out or folder / REPORT)


def measure(args, report: Path) -> int:
    from report import machine_info
    from where import write_report

    cmds = commands()
    load_before = os.getloadavg()
    times = {k: [] for k in cmds}
    for _ in range(args.repeat):
        for label, argv in cmds.items():
            times[label].append(run_once(argv))
    graphs = in_process(args.repeat)
    load_after = os.getloadavg()
    base = statistics.median(w for w, _ in times[next(iter(cmds))])
    rows = []
    for label, ts in times.items():
        wall, cpu = statistics.median(w for w, _ in ts), statistics.median(c for _, c in ts)
        rows.append((label, wall, cpu, wall - base))
        print(f"  {label:42s} wall {wall:6.3f} s  CPU {cpu:6.3f} s", file=sys.stderr)
    designs = [r for r in rows if r[0].startswith("camdyn design")]
    slowest = max(designs, key=lambda r: r[1])
    lines = ["# Start-up: the common commands as a user runs them (make bench: bench/startup.py)",
             "", "Each command a fresh process, wall and CPU time (user + system), median of "
             f"{args.repeat}, the commands taken in turn in every repeat; `bench/startup.py`'s "
             "docstring says what is run.", "", "## Machine", ""]
    lines += [f"- {k}: {v}" for k, v in machine_info().items()]
    lines += [f"- load average (1, 5, 15 min) before: {', '.join(f'{x:.2f}' for x in load_before)}"
              f"; after: {', '.join(f'{x:.2f}' for x in load_after)}", "", "## Verdict", "",
              f"- Goal 'every design example under {GOAL:g} s of wall time': "
              f"**{'MET' if slowest[1] < GOAL else 'NOT MET'}** (slowest {slowest[0]}: "
              f"{slowest[1]:.3f} s; the goal is for a machine not busy with other work, see the "
              "load average above).", "", "## Times", "",
              "| command | wall [s] | CPU [s] | wall over the baseline [s] |",
              "|:---|---:|---:|---:|"]
    lines += [f"| {label} | {wall:.3f} | {cpu:.3f} | {extra:+.3f} |" for label, wall, cpu, extra in rows]
    lines += ["", "## design() in this process (no check run)", "",
              "| example | time [s] | graph runs |", "|:---|---:|---:|"]
    lines += [f"| {label} | {t:.3f} | {n} |" for label, (t, n) in graphs.items()]
    write_report(report, "\n".join(lines) + "\n")
    print(f"wrote {report}", file=sys.stderr)
    if slowest[1] >= GOAL:
        # reported, not fatal: a busy machine slows every process alike (the baseline shows it)
        print(f"GOAL NOT MET: {slowest[0]} took {slowest[1]:.3f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
