"""Where a benchmark writes its report: bench/results/ (the committed figures, with
BENCHMARKS.md as their index) after a full run, a temporary folder after a --quick one.

A quick run is the benchmark in miniature (`make bench-quick`, run by CI so that no benchmark
rots unnoticed): it goes through the same code, report and charts included, and leaves the
committed figures alone.
"""
from __future__ import annotations

import subprocess
import tempfile
import time
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).parent.resolve().parent
RESULTS = Path(__file__).parent.resolve() / "results"
SCRATCH = Path(__file__).parent.resolve() / "out"
"""Charts of a full run that are not committed (bench/out/, ignored by git)."""


@contextmanager
def report_folder(quick: bool):
    """The folder to write a report into: bench/results/, or for a quick run a temporary folder
    removed afterwards."""
    if not quick:
        RESULTS.mkdir(exist_ok=True)
        yield RESULTS
        return
    with tempfile.TemporaryDirectory(prefix="camdyn-bench-quick-") as tmp:
        yield Path(tmp)


def scratch_folder(quick: bool, report: Path) -> Path:
    """Where the uncommitted charts go: bench/out/, or the quick run's temporary folder."""
    folder = report if quick else SCRATCH
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def _git(*args: str) -> str:
    try:
        return subprocess.run(["git", *args], capture_output=True, text=True, cwd=ROOT,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def commit() -> str:
    """The commit measured, short, and whether the tree had changes not yet committed."""
    sha = _git("rev-parse", "--short", "HEAD") or "unknown"
    dirty = _git("status", "--porcelain", "--untracked-files=no")
    return f"{sha} with uncommitted changes" if dirty else sha


def stamp() -> str:
    """The line under a report's title: when, and at which commit, it was measured."""
    return f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} at commit {commit()}."


def write_report(path: Path, text: str) -> None:
    """Write a report, its stamp (date and commit) as the line after its title."""
    title, _, rest = text.partition("\n")
    if not rest.startswith("\n"):
        rest = "\n" + rest
    path.write_text(f"{title}\n\n{stamp()}\n{rest}")
