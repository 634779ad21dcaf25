"""Where camdyn's time goes: right-hand-side cost and per-call overheads.

rhs_costs()        one evaluation of (4.15): camdyn's generated rhs (measured in C
                   by driver.rhs_cost_ns), the yardstick's inlined one, NumPy's
overheads(h)       one RK4 run at step h five ways, from the public call down to
                   the yardstick without a trajectory record
malloc_effect(hs)  the compiled loop with and without glibc returning the
                   trajectory buffers to the kernel after every call (subprocesses)

Run as a script (`python bench/diagnostics.py --bare-times H...`) it prints the
median time of the bare compiled loop, for malloc_effect.
"""
from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).parent.resolve()
RHS_CALLS = 2_000_000
T_RISE, T_DWELL = 0.3, 2.0


def rhs_costs(repeat: int) -> dict:
    """ns per right-hand-side evaluation of (4.15), medians of `repeat` loops."""
    from camdyn.runtime.engine import driver

    import yardstick
    from competitors import model_arguments
    from problem import FA, TAU, rhs_rise
    from timing import median_seconds

    cap, p, codes, pars = model_arguments()
    y = np.array([0.1, 0.2])

    def c_cost(t):
        return statistics.median(driver.rhs_cost_ns(cap, p, codes, pars, t, y, RHS_CALLS)
                                 for _ in range(repeat))

    return {
        "camdyn generated rhs, rise": c_cost(T_RISE),
        "camdyn generated rhs, dwell": c_cost(T_DWELL),
        "yardstick inlined rhs, rise": statistics.median(
            yardstick.rhs_cost_ns(TAU, FA, T_RISE, 0.1, RHS_CALLS) for _ in range(repeat)),
        "NumPy rhs (SciPy runs), rise": 1e9 * median_seconds(lambda: rhs_rise(T_RISE, y), repeat),
    }


def overheads(h: float, repeat: int) -> dict:
    """Seconds per RK4 run at step h: public call, bare loop, probe, yardstick (+/- record)."""
    import probe
    import yardstick
    from competitors import camdyn_bare, camdyn_simulate, model_arguments
    from problem import FA, T_END, TAU
    from timing import median_seconds_side_by_side

    cap, p, codes, pars = model_arguments()
    runs = {
        "simulate()": camdyn_simulate("rk4", exact=False).runner(h),
        "compiled loop": camdyn_bare("rk4", exact=False).runner(h),
        "probe: yardstick loop + camdyn rhs": lambda: probe.rk4_model(cap, p, codes, pars, h, T_END),
        "yardstick": lambda: yardstick.rk4(TAU, FA, h, T_END),
        "yardstick, no record": lambda: yardstick.rk4(TAU, FA, h, T_END, False),
    }
    return median_seconds_side_by_side(runs, repeat)


def _bare_times(hs: list[float], repeat: int) -> dict:
    from competitors import camdyn_bare
    from timing import median_seconds

    comp = camdyn_bare("rk4", exact=False)
    return {repr(h): median_seconds(comp.runner(h), repeat) for h in hs}


def malloc_effect(hs: list[float], repeat: int) -> dict:
    """Bare loop times in fresh processes: glibc defaults vs buffers kept (no mmap/trim)."""
    keep = {"MALLOC_MMAP_THRESHOLD_": "1000000000", "MALLOC_TRIM_THRESHOLD_": "1000000000"}
    out = {}
    for name, extra in (("glibc default", {}), ("buffers kept", keep)):
        env = dict(os.environ, **extra)
        cmd = [sys.executable, str(HERE / "diagnostics.py"), "--bare-times", str(repeat),
               *map(repr, hs)]
        done = subprocess.run(cmd, env=env, capture_output=True, text=True, check=True)
        out[name] = {float(k): v for k, v in json.loads(done.stdout).items()}
    return out


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "--bare-times":
        print(json.dumps(_bare_times([float(a) for a in sys.argv[3:]], int(sys.argv[2]))))
    else:
        sys.exit(__doc__)
