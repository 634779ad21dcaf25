"""Stability maps of the beam follower: each method over rtol (or step) against Young's modulus E
or the number of assumed modes N (the paper's Rayleigh-beam follower).

The stiffness parameter of the beam follower is its rod: a stiffer rod (E up) or more modes
(N up) raise the highest natural frequency of the frozen rod, which holds an explicit method
to ever smaller steps whatever the tolerance, while the tip deflection (the headline figure,
max |v_E| over the revolution) hardly changes.  One cell is one case of
:class:`camdyn.runtime.targets.beam_case.Case` run for its revolutions, classified as in
:mod:`camdyn.runtime.studies.stability_map` (fine, inaccurate, refused, blew up) against a reference
run of the same case: DP54 at rtol ``REF_RTOL`` (a rod stiff enough to make that too costly,
more than ``REF_MAX_STEPS`` steps, takes RODAS4 at the same rtol).  A run past
``MAX_STEPS`` steps counts as "blew up" (the step budget), with that reason: a map must not
spend an hour in one cell.
"""
from __future__ import annotations

import math
import time
from dataclasses import replace

import numpy as np

from ..targets import beam
from ..targets.beam_case import Case
from ..core.errors import CamdynInputError, SimulationError, UnstableStep
from ..core.methods import METHODS
from .stability_map import Cell, StabilityMap

REF_RTOL = 1e-9          # the reference (DP54; beam6 at rtol 1e-10 collapses its step)
REF_MAX_STEPS = 5_000_000
MAX_STEPS = 2_000_000    # a cell's step budget
PARAMS = {"E": "Young's modulus of the rod, Pa", "N": "assumed modes, 1 to 6"}
FIGURE = "max |v_E|"


def _case(base: Case, param: str, value: float) -> Case:
    if param == "N":
        n = int(round(value))
        if n != value or not 1 <= n <= 6:
            raise CamdynInputError(f"N={value:g} is out of range: an integer 1 <= N <= 6")
        return replace(base, modes=n)
    if not (math.isfinite(value) and value > 0):
        raise CamdynInputError(f"E={value:g} is out of range: 0 < E")
    return replace(base, E=float(value))


def run_case(case: Case, max_steps: int):
    """(max |v_E|, result, CPU seconds) of one case, with a step budget."""
    sim, _ = beam.simulator(case, max_steps=max_steps)
    c0 = time.process_time()
    res = sim.run(beam.parameters(case))
    cpu = time.process_time() - c0        # the integration's, before the figure is read off
    return beam.tip_max(res), res, cpu


def reference(case: Case) -> tuple[float, float]:
    """(max |v_E|, its relative error) of ``case`` at REF_RTOL: DP54, or RODAS4 where DP54
    would need more than REF_MAX_STEPS steps.  The error: the change from the same method at
    10 REF_RTOL, which estimates that looser run's error and so bounds this one's (a run one
    notch tighter would collapse the step of the stiffest rods, beam6 at rtol 1e-10)."""
    for method in ("dp54", "rodas4"):
        try:
            v = run_case(replace(case, method=method, rtol=REF_RTOL), REF_MAX_STEPS)[0]
            loose = run_case(replace(case, method=method, rtol=10 * REF_RTOL), REF_MAX_STEPS)[0]
            return v, abs(v - loose) / abs(v)
        except SimulationError:
            if method == "rodas4":
                raise


def classify(case: Case, ref: float, threshold: float, param: float) -> Cell:
    """One cell: ``case`` (its method and rtol) against the reference figure."""
    try:
        v, res, cpu = run_case(case, MAX_STEPS)
    except UnstableStep as exc:        # not reached with the adaptive methods; kept for clarity
        return Cell(case.method, param, case.rtol, "refused", "refused", True, str(exc), None,
                    None, math.nan, None, None, None, None)
    except SimulationError as exc:
        return Cell(case.method, param, case.rtol, "blew up", "blew up", False, str(exc), None,
                    None, math.nan, None, None, None, None)
    err = abs(v - ref) / abs(ref)
    status = "fine" if err <= threshold else "inaccurate"
    st = res.stats
    return Cell(case.method, param, case.rtol, status, status, False, "", float(v), float(err),
                cpu, float(st["seconds"]), int(st["n_steps"]), int(st["n_rhs"]), None)


def run_map(param: str, values, methods, rtols, *, threshold: float = 1e-3,
            base: Case | None = None, progress=None) -> StabilityMap:
    """The beam follower's map over ``values`` of ``param`` ("E" or "N") for the adaptive
    ``methods`` over ``rtols``; the other data from ``base`` (the paper's case by default)."""
    if param not in PARAMS:
        raise CamdynInputError(f"the beam follower's map parameter is E or N, not {param!r}")
    for k in methods:
        if k not in METHODS or not METHODS[k].adaptive:
            raise CamdynInputError(f"method {k!r}: the beam follower's map takes dp54 and rodas4")
    if not (isinstance(threshold, (int, float)) and 0 < threshold < 1):
        raise CamdynInputError(f"threshold={threshold!r} is out of range: 0 < threshold < 1")
    rtols = sorted(float(r) for r in rtols)
    if not rtols or any(not 1e-14 <= r < 1 for r in rtols):
        raise CamdynInputError("rtols must lie in 1e-14 <= rtol < 1")
    base = base or Case()
    values = sorted(float(v) for v in values)
    cases = [_case(base, param, v) for v in values]       # every value checked before a run
    say = progress or (lambda msg: None)
    refs, ref_errors = [], []
    for v, c in zip(values, cases):
        ref, err = reference(c)
        refs.append(ref)
        ref_errors.append(err)
        say(f"beam follower {param}={v:g}: reference {FIGURE} = {ref:.9e} ± {err * ref:.2g}")
    smap = StabilityMap(f"beam follower ({base.formulation})", param, values,
                        {"modes": base.modes} if param == "E" else {"E": base.E},
                        {k: rtols for k in methods}, threshold, FIGURE, True, refs, {},
                        reference_run=f"DP54 (or RODAS4 for a stiff rod) rtol {REF_RTOL:g}",
                        reference_error=ref_errors)
    smap.warnings += [
        f"the reference at {param} = {v:g} is only good to {e:.2g} (relative), not well inside "
        f"the threshold {threshold:g}: it cannot tell fine from inaccurate there; raise "
        "--threshold" for v, e in zip(values, ref_errors) if e > 0.1 * threshold]
    for meth in methods:
        for v, c, ref in zip(values, cases, refs):
            row = [classify(replace(c, method=meth, rtol=r), ref, threshold, v) for r in rtols]
            smap.cells += row
            say(f"beam follower {meth} {param}={v:g}: "
                + " ".join(x.status.replace(" ", "_") for x in row))
    return smap


def default_values(param: str) -> list:
    """E: the paper's steel and 10 and 100 times stiffer; N: 1, 2, 3."""
    if param == "E":
        return list(Case().E * np.array([1.0, 10.0, 100.0]))
    return [1.0, 2.0, 3.0]


NAMES = ("beam-follower", "beam")
"""What `camdyn stability` calls the beam follower."""


def study(param, methods, fixed: dict, rtols, steps, *, threshold: float,
          progress=None) -> StabilityMap:
    """The beam follower's map over E or N (``param`` = (name, values), default N): dp54 and
    rodas4 over rtol (default 1e-4 .. 1e-8), the paper's case otherwise (``fixed``: modes=N
    with E, E=... with N)."""
    name, values = param if param is not None else ("N", None)
    if name not in PARAMS:
        raise CamdynInputError(f"argument --param: {name}: the beam follower's map takes "
                               "E=START:STOP:N[:log] or N=a,b,c")
    if steps:
        raise CamdynInputError("argument --steps: the beam follower's map takes --rtols "
                               "(dp54, rodas4)")
    base = Case()
    for k, v in fixed.items():
        if k == "modes":
            base = replace(base, modes=int(v))
        elif k == "E":
            base = replace(base, E=float(v))
        else:
            raise CamdynInputError(f"argument --set: the beam follower's map takes modes=N or "
                                   f"E=PA besides its --param, not {k}")
    return run_map(name, values or default_values(name), methods or ["dp54", "rodas4"],
                   rtols or [1e-4, 1e-5, 1e-6, 1e-7, 1e-8], threshold=threshold, base=base,
                   progress=progress)
