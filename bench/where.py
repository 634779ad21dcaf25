"""Where a benchmark writes its report: bench/results/ (the committed figures, with
BENCHMARKS.md as their index) after a full run, a temporary folder after a --quick one.

A quick run is the benchmark in miniature (`make bench-quick`, run by CI so that no benchmark
rots unnoticed): it goes through the same code, report and charts included, and leaves the
committed figures alone.
"""
from __future__ import annotations

import tempfile
from contextlib import contextmanager
from pathlib import Path

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
