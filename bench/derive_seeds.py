"""How long deriving a model takes under different PYTHONHASHSEED values.

Python randomizes str hashes per process, so the iteration order of sets and the order in
which SymPy meets equal-ranked terms can change from run to run; a derivation whose cost
depends on that order is a regeneration whose cost is a lottery.  This runs every (seed,
model) pair in its own subprocess with a time limit and prints seed, model, seconds and the
first digits of the SHA-256 of the generated text (the same text under every seed is the
byte-identity promise of generated/).

    python bench/derive_seeds.py                                  slow models, 3 fixed + 3 random seeds
    python bench/derive_seeds.py --models camshaft2 beam3 --seeds 0 1 random random
    python bench/derive_seeds.py --all --timeout 300
    python bench/derive_seeds.py --quick      camshaft1 under seeds 0 and 1, into a temporary folder

Written to bench/results/BENCHMARKS-derive-seeds.md.

A run over the time limit is reported as "> LIMIT" (and the bench exits 1), so a
pathological seed shows up as such instead of hanging the bench.
"""
from __future__ import annotations

import argparse
import os
import random
import statistics
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).parent.resolve()
ROOT = HERE.parent
REPORT = "BENCHMARKS-derive-seeds.md"

# the models that took longest to derive (and dynacam_axial_ideal_backlash_groove_shafty_shaftz,
# the variant whose derivation once ran away under some seeds)
SLOW = ("dynacam_axial_ideal_backlash_groove_shafty_shaftz", "dynacam_axial_ideal_gearsqueeze_groovesqueeze_shafty_shaftz", "dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_camfriction_linkfriction_spring", "dynacam_radial_motor2_rigidgear_contact_shafty_shaftz_spring",
        "beam6", "camlaws")

_CHILD = r"""
import hashlib, resource, sys
name = sys.argv[1]
from camdyn.derive.generate import render_unit
texts = render_unit(name)   # stamped: the derivation key must not depend on the seed either
text = "".join(texts[k] for k in sorted(texts))
r = resource.getrusage(resource.RUSAGE_SELF)
print(f"{r.ru_utime + r.ru_stime:.2f} {hashlib.sha256(text.encode()).hexdigest()[:12]}")
"""


def run_one(model: str, seed: int, timeout: float) -> tuple[float | None, float, str]:
    """(wall seconds, CPU seconds, text digest) of deriving ``model`` under ``seed`` in a
    fresh interpreter (imports included); (None, 0, "") past ``timeout``."""
    env = dict(os.environ, PYTHONHASHSEED=str(seed))
    t0 = time.perf_counter()
    try:
        proc = subprocess.run([sys.executable, "-c", _CHILD, model], cwd=ROOT, env=env,
                              capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, 0.0, ""
    if proc.returncode:
        raise SystemExit(f"derive_seeds: {model} under seed {seed} failed: "
                         f"{proc.stderr.strip().splitlines()[-1]}")
    cpu, digest = proc.stdout.split()
    # wall time is what a user waits for; CPU time is what stays comparable on a busy machine
    return time.perf_counter() - t0, float(cpu), digest


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--models", nargs="+", default=list(SLOW), metavar="MODEL",
                    help="registered models (or 'camlaws'); default: " + " ".join(SLOW))
    ap.add_argument("--all", action="store_true", help="every registered model and camlaws")
    ap.add_argument("--seeds", nargs="+", default=["0", "1", "12345", "random", "random", "random"],
                    help="PYTHONHASHSEED values; 'random' draws one (printed in the table)")
    ap.add_argument("--timeout", type=float, default=180.0, help="seconds per run (default 180)")
    ap.add_argument("--quick", action="store_true",
                    help="--models camshaft1 --seeds 0 1, into a temporary folder")
    ap.add_argument("--out", type=Path, help=f"the report (default: bench/results/{REPORT})")
    args = ap.parse_args(argv)
    if args.quick:
        args.models, args.seeds, args.all = ["camshaft1"], ["0", "1"], False
    sys.path.insert(0, str(HERE))
    from where import report_folder

    with report_folder(args.quick) as folder:
        return measure(args, args.out or folder / REPORT)


def measure(args, report: Path) -> int:
    from where import write_report

    models = args.models
    if args.all:
        sys.path.insert(0, str(ROOT.parent))
        from camdyn.derive.models import REGISTRY
        models = sorted(REGISTRY) + ["camlaws"]
    seeds = [random.randrange(2**32) if s == "random" else int(s) for s in args.seeds]

    w = max(len(m) for m in models)
    print(f"{'seed':>10}  {'model':<{w}} {'wall s':>8} {'CPU s':>7}  text sha256")
    times: dict[str, list] = {m: [] for m in models}
    digests: dict[str, set] = {m: set() for m in models}
    over = False
    for seed in seeds:
        for model in models:
            wall, cpu, digest = run_one(model, seed, args.timeout)
            if wall is None:
                over = True
                print(f"{seed:>10}  {model:<{w}} {'> ' + format(args.timeout, 'g'):>8}", flush=True)
                continue
            times[model].append(cpu)
            digests[model].add(digest)
            print(f"{seed:>10}  {model:<{w}} {wall:8.1f} {cpu:7.1f}  {digest}", flush=True)
    print()
    print(f"{'model':<{w}} {'CPU s: min':>10} {'median':>7} {'max':>7}  distinct texts")
    rows = []
    for model in models:
        ts = times[model]
        if ts:
            print(f"{model:<{w}} {min(ts):10.1f} {statistics.median(ts):7.1f} {max(ts):7.1f}  "
                  f"{len(digests[model])}")
            rows.append(f"| {model} | {min(ts):.1f} | {statistics.median(ts):.1f} | {max(ts):.1f} | "
                        f"{len(ts)} | {len(digests[model])} |")
    write_report(report, "\n".join([
        "# Derivation time under different hash seeds (`python bench/derive_seeds.py`)",
        "", f"Seeds: {', '.join(map(str, seeds))}; CPU seconds of one derivation in a fresh process.",
        "", "| model | CPU s min | median | max | runs | distinct texts |",
        "|---|---:|---:|---:|---:|---:|", *rows]) + "\n")
    print(f"wrote {report}")
    differing = [m for m in models if len(digests[m]) > 1]
    if differing:
        print("different text under different seeds: " + ", ".join(differing))
    return 1 if over or differing else 0


if __name__ == "__main__":
    sys.exit(main())
