"""Mutation testing of camdyn's pure-Python physics (`make mutation`).

cosmic-ray changes one operator or constant at a time (a mutant) and runs the tests that
should notice; a mutant the tests do not notice *survives*.  The targets, their tests and the
operators are in ``targets.toml`` beside this file; survivors that were examined and found
equivalent or harmless are in ``survivors/<target>.toml``, each with its reason.

cosmic-ray mutates the files it tests in place, so the run happens in scratch copies of the
tree (``build/mutation/tree<j>/camdyn/...``, one per parallel job, with the compiled
extensions of the build copied along), never in the checkout.  Each mutant of a target is drawn
from a seeded sample, so reruns compare; ``--sample 0`` runs every mutant.  The report goes to
``out/mutation/report.md`` and ``report.json``: per target the mutants drawn, killed
(a failing test or a timeout), survived, and the survivors with their diffs, explained or not.

    python tests/mutation/run.py [--only NAME] [--sample N] [--budget-minutes M] [--jobs J]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import random
import re
import shlex
import shutil
import sqlite3
import subprocess
import sys
import threading
import time
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
PACKAGES = ("derive", "generated", "runtime", "thesis")   # camdyn.<name>: the top-level <name>/


def log(msg: str) -> None:
    print(f"[mutation {time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


@dataclass
class Target:
    name: str
    modules: list
    tests: list
    checks: list = field(default_factory=list)      # key prefixes of the camdyn check registry
    results: list = field(default_factory=list)    # (module, operator, diff, outcome)
    n_mutants: int = 0
    n_filtered: int = 0
    baseline_seconds: float = math.nan
    status: str = "not run"

    def test_args(self, tree: Path) -> list:
        """The target's test files that exist, and its rows of the check registry as node ids
        (a -k expression would filter the other files' tests too)."""
        args = [t for t in self.tests if (tree / t).exists()]
        if self.checks:
            p = subprocess.run([sys.executable, "-c", "from camdyn.thesis.checks import suite; "
                                "print('\\n'.join(c.key for c in suite.registry()))"],
                               cwd=tree, env=tree_env(tree), capture_output=True, text=True, check=True)
            keys = [k for k in p.stdout.split() if k.startswith(tuple(self.checks))]
            if not keys:
                raise SystemExit(f"target {self.name!r}: no check key starts with {self.checks}")
            args += [f"tests/test_checks.py::test_check[{k}]" for k in keys]
        return args


def load_targets(path: Path) -> tuple[dict, list]:
    conf = tomllib.loads(path.read_text())
    targets = [Target(t["name"], t["modules"], t["tests"], t.get("checks", []))
               for t in conf.pop("target")]
    for t in targets:
        for m in t.modules:
            if not (ROOT / m).is_file():
                raise SystemExit(f"targets.toml: target {t.name!r}: no module {m}")
    return conf, targets


def load_survivors(folder: Path) -> list:
    """The examined survivors, one file per target: [[survivor]] module, operator (a regular
    expression), line (the original source line), mutant (the mutated line), reason."""
    out = []
    for path in sorted(folder.glob("*.toml")):
        for s in tomllib.loads(path.read_text()).get("survivor", []):
            missing = {"module", "line", "reason"} - set(s)
            if missing:
                raise SystemExit(f"{path}: a survivor lacks {', '.join(sorted(missing))}")
            out.append(s)
    return out


def make_tree(name: str, source: Path) -> Path:
    """A scratch copy of the package (with its compiled extensions) and the tests."""
    tree = ROOT / "build" / "mutation" / name
    if tree.exists():
        shutil.rmtree(tree)
    ignore = shutil.ignore_patterns("__pycache__", "*.c", "*.html", ".pytest_cache")
    for pkg in PACKAGES:
        shutil.copytree(source / pkg, tree / "camdyn" / pkg, ignore=ignore)
    (tree / "camdyn" / "__init__.py").write_text("")
    shutil.copytree(source / "tests", tree / "tests", ignore=ignore)
    shutil.copyfile(source / "pyproject.toml", tree / "pyproject.toml")
    if not any((tree / "camdyn" / "runtime" / "engine").glob("driver*.so")):
        raise SystemExit(f"{source}: the extensions are not built; run `make build` first")
    return tree


def tree_env(tree: Path) -> dict:
    env = dict(os.environ)
    # the scratch copy shadows the installed camdyn; no byte code, so a mutant is always recompiled
    env["PYTHONPATH"] = str(tree) + os.pathsep + env.get("PYTHONPATH", "")
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    env["MPLBACKEND"] = "Agg"
    return env


def pytest_command(args: list) -> str:
    return shlex.join([sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider",
                       "-p", "no:xdist", "-p", "no:randomly", "--no-header", *args])


def mutation_key(module: str, operator: str, diff: str) -> tuple:
    """What identifies a mutant across edits elsewhere in the file: the lines it changes."""
    minus = " | ".join(ln[1:].strip() for ln in diff.splitlines()
                       if ln.startswith("-") and not ln.startswith("---"))
    plus = " | ".join(ln[1:].strip() for ln in diff.splitlines()
                      if ln.startswith("+") and not ln.startswith("+++"))
    return module, operator, minus, plus


def explain(survivors: list, module: str, operator: str, diff: str) -> str | None:
    mod, op, minus, plus = mutation_key(module, operator, diff)
    for s in survivors:
        if (s["module"] == mod and re.fullmatch(s.get("operator", ".*"), op)
                and s["line"].strip() == minus and s.get("mutant", plus).strip() == plus):
            return s["reason"]
    return None


class Job:
    """One target in one scratch tree: cosmic-ray init, filter, sample, baseline, exec."""

    def __init__(self, target: Target, tree: Path, conf: dict, deadline: float):
        self.t, self.tree, self.conf, self.deadline = target, tree, conf, deadline
        slug = re.sub(r"\W+", "_", target.name).strip("_")
        self.dir = tree.parent / "sessions" / slug
        self.dir.mkdir(parents=True, exist_ok=True)
        self.db = self.dir / "session.sqlite"
        self.cfg = self.dir / "config.toml"

    def write_config(self, timeout: float) -> None:
        paths = [str(self.tree / "camdyn" / Path(m)) for m in self.t.modules]
        lines = ["[cosmic-ray]",
                 f"module-path = {json.dumps(paths)}",
                 f"timeout = {timeout:.1f}",
                 "excluded-modules = []",
                 f"test-command = {json.dumps(pytest_command(self.t.test_args(self.tree)))}",
                 "[cosmic-ray.distributor]", 'name = "local"',
                 "[cosmic-ray.filters.operators-filter]",
                 f"exclude-operators = {json.dumps(self.conf['exclude_operators'])}"]
        self.cfg.write_text("\n".join(lines) + "\n")

    def cr(self, *args) -> None:
        exe = Path(sys.executable).parent
        subprocess.run([str(exe / args[0]), *args[1:]], cwd=self.tree, env=tree_env(self.tree),
                       check=True, capture_output=True, text=True)

    def baseline(self) -> float:
        cmd = shlex.split(pytest_command(self.t.test_args(self.tree)))
        start = time.perf_counter()
        p = subprocess.run(cmd, cwd=self.tree, env=tree_env(self.tree), capture_output=True,
                           text=True)
        if p.returncode != 0:
            raise RuntimeError(f"{self.t.name}: the tests fail without any mutant:\n"
                               f"{p.stdout[-3000:]}")
        return time.perf_counter() - start

    def sample(self, n: int, seed: int) -> None:
        """Mark everything but a seeded sample of the pending mutants as skipped."""
        from cosmic_ray.work_db import WorkDB, use_db
        from cosmic_ray.work_item import WorkerOutcome, WorkResult

        with use_db(str(self.db), WorkDB.Mode.open) as db:
            pending = list(db.pending_work_items)
            self.t.n_mutants = db.num_work_items
            self.t.n_filtered = self.t.n_mutants - len(pending)

            def order(item):
                m = item.mutations[0]
                return (Path(m.module_path).name, m.operator_name, m.occurrence)

            pending.sort(key=order)
            keep = set(range(len(pending))) if n <= 0 or n >= len(pending) else \
                set(random.Random(seed).sample(range(len(pending)), n))
            skip = [it.job_id for k, it in enumerate(pending) if k not in keep]
            if skip:
                db.set_multiple_results(skip, WorkResult(output="not in the sample",
                                                         worker_outcome=WorkerOutcome.SKIPPED))

    def progress(self) -> tuple[int, int]:
        con = sqlite3.connect(self.db)
        try:
            done = con.execute("select count(*) from work_results where lower(worker_outcome) != 'skipped'").fetchone()[0]
            total = con.execute("select count(*) from work_items").fetchone()[0]
            skipped = con.execute("select count(*) from work_results where lower(worker_outcome) = 'skipped'").fetchone()[0]
        finally:
            con.close()
        return done, total - skipped

    def run(self) -> None:
        t = self.t
        if self.db.exists():
            self.db.unlink()
        t.baseline_seconds = self.baseline()
        # a mutant may slow the tests (an iteration that no longer converges): allow a margin,
        # and count a timeout as killed, as cosmic-ray does
        self.write_config(max(20.0, 5.0 * t.baseline_seconds))
        self.cr("cosmic-ray", "init", str(self.cfg), str(self.db))
        self.cr("cr-filter-operators", str(self.db), str(self.cfg))
        self.sample(self.conf["sample"], self.conf["seed"] + sum(map(ord, t.name)))
        done, total = self.progress()
        log(f"{t.name}: {total} mutants to run (of {t.n_mutants}; {t.n_filtered} filtered "
            f"operators), tests take {t.baseline_seconds:.1f} s")
        proc = subprocess.Popen([str(Path(sys.executable).parent / "cosmic-ray"), "exec",
                                 str(self.cfg), str(self.db)], cwd=self.tree,
                                env=tree_env(self.tree), stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, start_new_session=True)
        last = time.monotonic()
        while proc.poll() is None:
            time.sleep(2.0)
            if time.monotonic() > self.deadline:
                os.killpg(proc.pid, 9)
                proc.wait()
                t.status = "stopped at the time budget"
                break
            if time.monotonic() - last > 30:
                done, total = self.progress()
                log(f"{t.name}: {done}/{total}")
                last = time.monotonic()
        else:
            t.status = "complete" if proc.returncode == 0 else f"cosmic-ray exit {proc.returncode}"
        self.collect()

    def collect(self) -> None:
        from cosmic_ray.work_db import WorkDB, use_db

        prefix = str(self.tree / "camdyn") + os.sep
        with use_db(str(self.db), WorkDB.Mode.open) as db:
            for item, result in db.completed_work_items:
                if result.worker_outcome == "skipped":
                    continue
                m = item.mutations[0]
                module = str(m.module_path).replace(prefix, "")
                diff = (result.diff or "").replace(prefix, "")
                if result.worker_outcome != "normal":
                    outcome = "incompetent"
                else:
                    outcome = str(result.test_outcome.value)
                    if outcome == "killed" and (result.output or "").strip() == "timeout":
                        outcome = "timeout"
                self.t.results.append({"module": module, "operator": m.operator_name,
                                       "line": m.start_pos[0], "diff": diff, "outcome": outcome})


def wilson(k: int, n: int, z: float = 1.96) -> tuple[float, float]:
    if n == 0:
        return math.nan, math.nan
    p = k / n
    d = 1 + z * z / n
    c = (p + z * z / (2 * n)) / d
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
    return c - h, c + h


def report(targets: list, survivors: list, conf: dict, out: Path, seconds: float) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    rows, unexplained, explained = [], [], []
    tot = {"killed": 0, "timeout": 0, "survived": 0, "incompetent": 0}
    for t in targets:
        c = {k: sum(r["outcome"] == k for r in t.results) for k in tot}
        for k in tot:
            tot[k] += c[k]
        n = c["killed"] + c["timeout"] + c["survived"]
        for r in t.results:
            if r["outcome"] == "survived":
                _, _, r["original"], r["mutant"] = mutation_key(r["module"], r["operator"], r["diff"])
                r["reason"] = explain(survivors, r["module"], r["operator"], r["diff"])
                (explained if r["reason"] else unexplained).append((t.name, r))
        rows.append({"target": t.name, "modules": t.modules, "status": t.status,
                     "mutants": t.n_mutants, "filtered": t.n_filtered, "run": n + c["incompetent"],
                     **c, "score": (n - c["survived"]) / n if n else None,
                     "tests_seconds": t.baseline_seconds})
    n = tot["killed"] + tot["timeout"] + tot["survived"]
    killed = n - tot["survived"]
    lo, hi = wilson(killed, n)
    summary = {"score": killed / n if n else None, "score_95": [lo, hi], "mutants_run": n,
               "survived": tot["survived"], "explained": len(explained),
               "unexplained": len(unexplained), "sample_per_target": conf["sample"],
               "seed": conf["seed"], "seconds": seconds, "targets": rows}
    (out / "report.json").write_text(json.dumps(
        {**summary, "survivors": [{"target": name, **r} for name, r in explained + unexplained]},
        indent=1))
    md = ["# Mutation report (make mutation)", "",
          f"Score {100 * summary['score']:.1f} % of {n} mutants killed "
          f"(95 % interval {100 * lo:.1f}-{100 * hi:.1f} %), {tot['survived']} survived: "
          f"{len(explained)} examined and explained (tests/mutation/survivors/), "
          f"{len(unexplained)} not.  Sample of {conf['sample']} mutants per target (seed "
          f"{conf['seed']}), {seconds / 60:.1f} min.", "",
          "| target | mutants | run | killed | timeout | survived | score | tests [s] | status |",
          "|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in rows:
        score = f"{100 * r['score']:.1f} %" if r["score"] is not None else "-"
        md.append(f"| {r['target']} | {r['mutants']} | {r['run']} | {r['killed']} | {r['timeout']} "
                  f"| {r['survived']} | {score} | {r['tests_seconds']:.1f} | {r['status']} |")
    for title, group in (("Survivors not yet explained", unexplained),
                         ("Survivors examined: equivalent or harmless", explained)):
        md += ["", f"## {title}", ""]
        for name, r in group:
            md.append(f"- {r['module']}:{r['line']} `{r['operator']}`"
                      + (f": {r['reason']}" if r.get("reason") else ""))
            md += ["  ```diff"] + ["  " + ln for ln in r["diff"].splitlines()
                                    if ln[:1] in "+-" and ln[:3] not in ("---", "+++")] + ["  ```"]
    (out / "report.md").write_text("\n".join(md) + "\n")
    return summary


def recheck(report_json: Path, targets: list, tests: list | None, source: Path) -> int:
    """Apply each unexplained survivor of an earlier report, one at a time, in a scratch tree of
    its own and run the target's tests (or ``tests``) against it: which survivors the tests
    kill now.  Several rechecks of different targets can run at once."""
    survivors = load_survivors(HERE / "survivors")
    old = json.loads(report_json.read_text())["survivors"]
    alive = 0
    for t in targets:
        mine = [r for r in old if r["target"] == t.name
                and not explain(survivors, r["module"], r["operator"], r["diff"])]
        if not mine:
            continue
        slug = re.sub(r"\W+", "_", t.name).strip("_")
        tree = make_tree(f"recheck-{slug}", source)
        args = tests if tests else t.test_args(tree)
        for r in mine:
            patch = "\n".join(r["diff"].splitlines()[1:]) + "\n"
            pkg = str(tree / "camdyn")
            subprocess.run(["patch", "-s", "-p1", "-d", pkg], input=patch, text=True, check=True)
            try:
                p = subprocess.run(shlex.split(pytest_command(args)), cwd=tree, env=tree_env(tree),
                                   capture_output=True, text=True, timeout=600)
                killed = p.returncode != 0
            except subprocess.TimeoutExpired:
                killed = True
            finally:
                subprocess.run(["patch", "-s", "-R", "-p1", "-d", pkg], input=patch, text=True,
                               check=True)
            alive += not killed
            _, _, was, now = mutation_key(r["module"], r["operator"], r["diff"])
            print(f"{'killed  ' if killed else 'SURVIVES'} {r['module']}:{r['line']} "
                  f"{r['operator'].split('/')[-1]}: {was}  ->  {now}")
    print(f"{alive} survive", file=sys.stderr)
    return 1 if alive else 0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", action="append", help="run only targets whose name contains this")
    ap.add_argument("--sample", type=int, help="mutants per target (0: all)")
    ap.add_argument("--budget-minutes", type=float)
    ap.add_argument("--jobs", type=int)
    ap.add_argument("--source", type=Path, default=ROOT,
                    help="tree to copy (default: this checkout; its extensions must be built)")
    ap.add_argument("--out", type=Path, default=ROOT / "out" / "mutation")
    ap.add_argument("--recheck", type=Path, metavar="REPORT_JSON",
                    help="re-run the unexplained survivors of an earlier report.json against the "
                         "tests as they are now (with --only: of those targets)")
    ap.add_argument("--tests", nargs="+", help="with --recheck: run these pytest arguments "
                                               "instead of the target's tests")
    args = ap.parse_args(argv)
    conf, targets = load_targets(HERE / "targets.toml")
    for key in ("sample", "budget_minutes", "jobs"):
        if getattr(args, key) is not None:
            conf[key] = getattr(args, key)
    if args.only:
        targets = [t for t in targets if any(o in t.name for o in args.only)]
        if not targets:
            raise SystemExit(f"--only {args.only}: no such target")
    if args.recheck:
        return recheck(args.recheck, targets, args.tests, args.source.resolve())
    start = time.monotonic()
    deadline = start + 60 * conf["budget_minutes"]
    jobs = max(1, min(conf["jobs"], len(targets)))
    trees = [make_tree(f"tree{j}", args.source.resolve()) for j in range(jobs)]
    log(f"{len(targets)} targets, {jobs} scratch trees under build/mutation, budget "
        f"{conf['budget_minutes']:g} min")
    queue = list(targets)
    lock = threading.Lock()
    errors = []

    def worker(tree):
        while True:
            with lock:
                if not queue or time.monotonic() > deadline:
                    return
                t = queue.pop(0)
            try:
                Job(t, tree, conf, deadline).run()
                log(f"{t.name}: {t.status}")
            except Exception as exc:    # one broken target must not lose the others' results
                t.status = f"error: {exc}".splitlines()[0]
                errors.append(f"{t.name}: {exc}")
                log(f"{t.name}: {t.status}")

    threads = [threading.Thread(target=worker, args=(tree,)) for tree in trees]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    summary = report(targets, load_survivors(HERE / "survivors"), conf, args.out,
                     time.monotonic() - start)
    log(f"score {100 * summary['score']:.1f} % ({summary['mutants_run']} mutants, "
        f"{summary['survived']} survived, {summary['unexplained']} unexplained); "
        f"report: {args.out / 'report.md'}")
    for e in errors:
        log(e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
