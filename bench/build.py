"""Compile the benchmark's own Cython modules (yardstick, probe) into bench/."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).parent.resolve()
SOURCES = ["yardstick.pyx", "probe.pyx"]
HEADERS = HERE.parent / "build" / "cython_include" / "camdyn" / "runtime" / "engine"  # setup.py stages it


def _stale() -> bool:
    for src in SOURCES:
        stem = src[:-4]
        built = list(HERE.glob(f"{stem}.*.so"))
        deps = [HERE / src, HERE / "setup_bench.py", HEADERS / "abi.pxd"]
        if not built or min(b.stat().st_mtime for b in built) < max(d.stat().st_mtime for d in deps):
            return True
    return False


def build() -> None:
    """Run bench/setup_bench.py build_ext in place when a module is missing or stale."""
    if not _stale():
        return
    if not (HEADERS / "abi.pxd").exists():
        raise SystemExit(f"{HEADERS / 'abi.pxd'} is missing: build camdyn first (make build)")
    print("building bench/yardstick.pyx and bench/probe.pyx ...", flush=True)
    tmp = HERE / "out" / "build"
    cmd = [sys.executable, str(HERE / "setup_bench.py"), "-q", "build_ext", "--inplace",
           "--build-temp", str(tmp / "temp"), "--build-lib", str(tmp / "lib")]
    done = subprocess.run(cmd, cwd=HERE, capture_output=True, text=True)
    if done.returncode != 0:
        sys.stderr.write(done.stdout + done.stderr)
        raise SystemExit("building the benchmark's Cython modules failed")
