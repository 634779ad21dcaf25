"""Re-run the mutants that showed the test suite's gaps in a review, and the tests that kill them.

`make mutation-findings`.

Each finding in ``findings.toml`` is one hand-made mutant: a line of a module replaced by a
wrong one.  In a scratch copy of the tree (``build/mutation/finding-<n>``, the layout of
run.py's trees) the line is replaced, the models named in ``regenerate`` are re-derived and
the extensions named in ``rebuild`` recompiled there, and then

* the ``before`` tests (those that existed when the finding was made) run for the record,
* the ``tests`` run and must fail: the finding is caught.

The first failing test of each run is printed; the exit status is 1 when a mutant is not
caught.  Needs Cython for the findings that recompile (the ``mutation`` extra installs it).

    python tests/mutation/findings.py [--only N] [--out out/mutation/findings.md]
"""
from __future__ import annotations

import argparse
import re
import shlex
import subprocess
import sys
import time
import tomllib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from run import HERE, ROOT, log, make_tree, pytest_command, tree_env  # noqa: E402

from camdyn.derive.flags import COMPILE_ARGS  # noqa: E402

# the package's compile flags (derive/flags.py); the scratch tree is a plain package, so its
# extensions are built from their package paths with the tree itself on Cython's include path
BUILD = """
import sys
from Cython.Build import cythonize
from setuptools import Extension, setup
names = sys.argv[1:]
sys.argv[1:] = ["build_ext", "--inplace", "-q"]
setup(script_args=sys.argv[1:], ext_modules=cythonize(
    [Extension("camdyn." + n.replace("/", "."), ["camdyn/" + n + ".pyx"],
               extra_compile_args=%r) for n in names],
    include_path=["."], compiler_directives={"language_level": 3}, quiet=True))
""" % (COMPILE_ARGS,)


def apply(tree: Path, finding: dict) -> None:
    path = tree / "camdyn" / finding["file"]
    text = path.read_text()
    n = text.count(finding["original"])
    if n != 1:
        raise SystemExit(f"finding {finding['name']!r}: the original line occurs {n} times "
                         f"in {finding['file']} (must be once); update findings.toml")
    path.write_text(text.replace(finding["original"], finding["mutant"]))


def regenerate(tree: Path, models: list) -> None:
    out = tree / "camdyn" / "generated"
    p = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "derive", "--out", str(out),
                        "--only", *models], cwd=tree, env=tree_env(tree), capture_output=True,
                       text=True)
    if p.returncode != 0:
        raise SystemExit(f"camdyn derive --only {' '.join(models)} failed:\n{p.stderr[-2000:]}")
    if "wrote" not in p.stdout:
        raise SystemExit(f"the mutant left generated/{'/'.join(models)} unchanged: the model "
                         "line is not used by the derivation")


def rebuild(tree: Path, names: list) -> None:
    for sub in ("", "runtime", "runtime/engine", "generated"):   # package markers for Cython's cimport
        (tree / "camdyn" / sub / "__init__.pxd").touch()
    # setup() would read the tree's pyproject.toml (the project's own build); keep it out
    pyproject = tree / "pyproject.toml"
    pyproject.rename(tree / "pyproject.toml.off")
    try:
        p = subprocess.run([sys.executable, "-c", BUILD, *names], cwd=tree, env=tree_env(tree),
                           capture_output=True, text=True)
    finally:
        (tree / "pyproject.toml.off").rename(pyproject)
    if p.returncode != 0:
        raise SystemExit(f"recompiling {names} failed (is Cython installed? pip install "
                         f"'.[mutation]'):\n{p.stderr[-3000:]}")


def first_failure(output: str) -> str:
    for line in output.splitlines():
        m = re.match(r"(FAILED|ERROR) (\S+)", line)
        if m:
            return m.group(2)
    return "(no test named; see the output)"


def run_tests(tree: Path, tests: list) -> tuple[bool, str, float]:
    """(failed, first failing test, seconds)."""
    start = time.perf_counter()
    cmd = shlex.split(pytest_command(["-rfE", *tests]))
    p = subprocess.run(cmd, cwd=tree, env=tree_env(tree), capture_output=True, text=True)
    return p.returncode != 0, first_failure(p.stdout), time.perf_counter() - start


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", type=int, action="append", help="finding number (1-based)")
    ap.add_argument("--out", type=Path, default=ROOT / "out" / "mutation" / "findings.md")
    args = ap.parse_args(argv)
    findings = tomllib.loads((HERE / "findings.toml").read_text())["finding"]
    lines = ["# The review's findings, re-run as mutants (make mutation-findings)", "",
             "| # | mutant | the older tests | now caught by |", "|---|---|---|---|"]
    missed = 0
    for k, f in enumerate(findings, start=1):
        if args.only and k not in args.only:
            continue
        log(f"finding {k}: {f['name']}")
        tree = make_tree(f"finding-{k}", ROOT)
        apply(tree, f)
        if f.get("regenerate"):
            regenerate(tree, f["regenerate"])
        if f.get("rebuild"):
            rebuild(tree, f["rebuild"])
        if f.get("before"):
            failed, which, sec = run_tests(tree, f["before"])
            before = f"fail ({which})" if failed else f"all pass ({sec:.0f} s)"
        else:
            before = "-"
        failed, which, sec = run_tests(tree, f["tests"])
        missed += not failed
        now = f"**{which}**" if failed else f"NOT CAUGHT by {' '.join(f['tests'])}"
        log(f"finding {k}: before: {before}; now: {now}")
        lines.append(f"| {k} | {f['name']}: `{f['file']}` `{f['original'].strip()}` -> "
                     f"`{f['mutant'].strip()}` | {before} | {now} |")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main())
