"""What regeneration costs a user: `camdyn derive --check` with nothing changed, and `camdyn
derive` after one model's declaration was edited (the derivation keys of README "What is in
it" let both skip every file whose inputs did not change).  Goal: both under 30 s.

Each figure is the median of ``--repeat`` runs, each in a fresh process (imports included):
  check        `camdyn derive --check` on this checkout (every file's recorded key compared
               with the key of the current inputs; nothing derived);
  check-full   `camdyn derive --check --full` (everything derived again; the old check), once;
  edit MODEL   a copy of generated/, MODEL's declaration edited (its title), `derive` over the
               whole registry into the copy: that model alone is derived.  Done for the
               two costliest models (the DYNACAM variant with both squeeze films, the beam
               follower with six modes) and a small one.
Written to bench/results/BENCHMARKS-derive.md.

    python bench/derive_time.py [--repeat 3] [--no-full]
    python bench/derive_time.py --quick     the check and a small model's edit, once each,
                                            into a temporary folder
"""
from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).parent.resolve()
ROOT = HERE.parent
GOAL = 30.0
REPORT = "BENCHMARKS-derive.md"

_EDIT = r"""
import dataclasses, sys, time
from pathlib import Path
from camdyn.derive import generate
from camdyn.derive.models import REGISTRY
name, out = sys.argv[1], Path(sys.argv[2])
build = REGISTRY[name]
REGISTRY[name] = lambda: dataclasses.replace(build(), title=build().title + " (edited)")
changed = generate.write(out)
assert changed == [name + ".pyx"], changed
"""


def _timed(cmd, env=None) -> float:
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, env=env)
    if proc.returncode:
        raise SystemExit(f"derive_time: {' '.join(map(str, cmd))} failed:\n{proc.stderr}")
    return time.perf_counter() - t0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--no-full", action="store_true", help="skip the full check (about a minute)")
    ap.add_argument("--models", nargs="+", default=["dynacam_axial_ideal_gearsqueeze_groovesqueeze_shafty_shaftz", "beam6", "camshaft1"])
    ap.add_argument("--quick", action="store_true",
                    help="--repeat 1 --no-full --models camshaft1, into a temporary folder")
    ap.add_argument("--out", type=Path, help=f"the report (default: bench/results/{REPORT})")
    args = ap.parse_args(argv)
    if args.quick:
        args.repeat, args.no_full, args.models = 1, True, ["camshaft1"]
    sys.path.insert(0, str(HERE))
    from where import report_folder

    with report_folder(args.quick) as folder:
        return measure(args, args.out or folder / REPORT)


def measure(args, report: Path) -> int:
    from where import write_report

    py = sys.executable
    rows = []

    def row(what, runs):
        med = statistics.median(runs)
        rows.append((what, med, min(runs), max(runs), len(runs)))
        print(f"  {what:32s} median {med:6.1f} s  ({min(runs):.1f}-{max(runs):.1f}, "
              f"{len(runs)} runs)", file=sys.stderr)

    row("derive --check (nothing changed)",
        [_timed([py, "-m", "camdyn.runtime.cli", "derive", "--check"]) for _ in range(args.repeat)])
    if not args.no_full:
        row("derive --check --full", [_timed([py, "-m", "camdyn.runtime.cli", "derive", "--check",
                                              "--full"])])
    for model in args.models:
        runs = []
        for _ in range(args.repeat):
            with tempfile.TemporaryDirectory() as tmp:
                out = Path(tmp) / "generated"
                shutil.copytree(ROOT / "generated", out,
                                ignore=shutil.ignore_patterns("*.so", "*.c", "__pycache__"))
                runs.append(_timed([py, "-c", _EDIT, model, str(out)]))
        row(f"derive after editing {model}", runs)

    cpus = os.cpu_count()
    lines = ["# Regeneration time (`python bench/derive_time.py`)", "",
             f"Wall seconds on this machine ({cpus} CPUs), each run a fresh process; goal: "
             f"under {GOAL:g} s for the check and for a one-model edit.", "",
             "| run | median s | min | max | runs | goal met |", "|---|---:|---:|---:|---:|---|"]
    for what, med, lo, hi, n in rows:
        goal = "" if "full" in what else ("yes" if med < GOAL else "**no**")
        lines.append(f"| {what} | {med:.1f} | {lo:.1f} | {hi:.1f} | {n} | {goal} |")
    lines += ["", "Without the derivation keys every check derived every model (83 s on two cores); "
              "the spread of derivation times over hash seeds is in "
              "[BENCHMARKS-derive-seeds.md](BENCHMARKS-derive-seeds.md) (`bench/derive_seeds.py`)."]
    write_report(report, "\n".join(lines) + "\n")
    print(f"wrote {report}", file=sys.stderr)
    missed = [what for what, med, *_ in rows if "full" not in what and med >= GOAL]
    if missed:   # reported, not fatal: the benches after this one should still run
        print(f"GOAL NOT MET (over {GOAL:g} s): {', '.join(missed)}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
