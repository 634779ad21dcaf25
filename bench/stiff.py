"""`make bench` (stiff part): camdyn's implicit method against its explicit one and SciPy's
implicit peers on the stiff cases (README "Failures and stiffness").

Cases
    roller_bilateral   the roller on its contact spring in series with the follower linkage
                       (thesis sec. 9.2.1), held without backlash: contact stiffness ratio
                       kappa = 100 and 1000, contact damping ratio zeta = 0 and 0.1, mass ratio
                       mu = 0.05, tau = 0.15, cycloidal rise and dwell, T in [0, 3]
    roller             the same in a groove with backlash S = 0.001 (contact opens and closes,
                       events): kappa = 1000, zeta = 0.1; camdyn only (the peers do not apply
                       the model's event actions)
    beam6              the Rayleigh-beam follower with N = 6 modes, one revolution (paper's
                       case), and with E x 1e6 (the rigid limit), with and without the roller's
                       inertia

Error measure (the follower's): max |X(T) - X_ref(T)| over 3001 points of [0, 3], X in strokes,
against DP54 at rtol 1e-12; the beam: |max |v_E| - reference| / reference, the reference
DOP853 at rtol 1e-11 (RADAU5 at 1e-10 where DOP853 exceeds the step budget) with the mode
amplitudes to MODE_ATOL/1000 of the rod's deflection scale.

Contestants, on the same generated right-hand side and Jacobian: camdyn dp54 (and dop853 on the
beam follower at N = 6), camdyn's implicit methods rodas4 and radau5, each also with per-state
tolerances (+atol: the roller's states R, R' left to the follower's error control: state_atol
R = 1, R' = 1e3, so that the L-stable method steps over the ringing contact mode; +mode-atol:
the beam's mode amplitudes to `camdyn beam-follower`'s MODE_ATOL of the rod's deflection scale,
their rates to that times the highest frozen frequency w_N; +exact: the dwell, where the roller's
model is linear and time invariant, stepped over with its propagator, Simulator's
exact_segments, for dp54 too; the goals take each side's cheaper run at each target), and SciPy's
Radau, BDF, LSODA (runtime/studies/peers.py: the compiled rhs one point
per call, the generated Jacobian).  Times: CPU time of the integration, median of repeats
(camdyn 5, each of enough runs to last 5 ms; a peer 3 when a run is under 0.5 s, else 1;
the beam: 5 when a run is under 1 s, else 1).  Matched error: the cost of a method
at a target error is read off its work-precision curve (log-log interpolation between the two
rungs around the target; the cheapest run if that is already below it).  A goal's ratio is
paired: the runs on both sides timed in interleaved rounds, the median of the rounds' ratios
(PAIRED_ROUNDS), so that the machine's drift between two ladders does not enter it; the tables'
ratios are the quotients of the ladders' own times.

    python bench/stiff.py            writes bench/results/BENCHMARKS-stiff.md and its charts,
                                     bench/results/charts/stiff_*.png
    python bench/stiff.py --quick    the same in miniature (one roller on its spring, the roller
                                     in its groove, the beam follower with two modes; two
                                     tolerances, one repeat), into a temporary folder
"""
from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np

HERE = Path(__file__).parent.resolve()
sys.path.insert(0, str(HERE))

from report import machine_info  # noqa: E402

T_GRID = np.linspace(0.0, 3.0, 3001)
TARGETS = (1e-4, 1e-5, 1e-6)
ROLLER_ATOL = (("R", 1.0), ("Rd", 1e3))
IMPLICIT = ("rodas4+atol", "radau5+atol")   # the contestants of the roller's goals, each
EXACT = "+exact"                              # with its run over the exact dwell beside it
REPORT = "BENCHMARKS-stiff.md"
CHARTS = "charts"           # beside the report


def _progress(msg: str) -> None:
    print(f"  [{time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


@dataclass
class Point:
    method: str
    rtol: float
    error: float | None
    cpu: float | None
    steps: int | None
    rhs: int | None
    status: str = "ok"
    note: str = ""
    rungs: tuple = ()       # the runs (method, rtol) an interpolated cost is read between
    frac: float = 0.0       # ... and where between them, in logarithms of the error

    @property
    def runs(self) -> tuple:
        """The runs (method, rtol) its cost is read from: its own, or the two around it."""
        return self.rungs or ((self.method, self.rtol),)


def _between(c0: float, c1: float, frac: float) -> float:
    """The cost a fraction ``frac`` of the way from c0 to c1, log-log."""
    return math.exp(math.log(c0) + frac * math.log(c1 / c0))


@dataclass
class CaseResult:
    key: str
    title: str
    points: list = field(default_factory=list)
    timers: dict = field(default_factory=dict)   # (method, rtol) -> a batch of its runs

    def best_at(self, methods, target: float) -> Point | None:
        """The cheapest of ``methods`` at ``target`` (cost_at), None where none reaches it."""
        pts = [p for p in (self.cost_at(m, target) for m in methods) if p is not None]
        return min(pts, key=lambda p: p.cpu) if pts else None

    def cost_at(self, method: str, target: float) -> Point | None:
        """The CPU time at which ``method`` reaches the error ``target``: along its runs in
        order of cost, the first at or below the target, interpolated log-log with the run
        before it (the work-precision curve between two rungs); a run no dearer than it that
        is accurate enough has the cost of its own (no extrapolation below the cheapest)."""
        pts = sorted((p for p in self.points if p.method == method and p.status == "ok"
                      and p.error is not None and p.cpu), key=lambda p: p.cpu)
        prev = None
        for p in pts:
            if p.error <= target:
                if prev is None or prev.error <= p.error:
                    return p
                f = math.log(prev.error / target) / math.log(prev.error / p.error)
                return Point(method, p.rtol, target, _between(prev.cpu, p.cpu, f), None, None, "interpolated",
                             f"between rtol {prev.rtol:.0e} and {p.rtol:.0e}",
                             ((method, prev.rtol), (method, p.rtol)), f)
            if prev is None or p.error < prev.error:
                prev = p
        return None


# -- the roller cases ---------------------------------------------------------------------

BATCH_CPU = 0.005
"""Seconds of CPU a timed batch lasts at least: a run of tens of microseconds, timed alone,
is at the mercy of the machine's scheduler (the ratios of two such runs moved by half
between repeats), so short runs are timed in batches, as timeit does."""


class Batch:
    """Calls of ``fn`` timed together, as many as last BATCH_CPU."""

    def __init__(self, fn):
        self.fn = fn
        c0 = time.process_time()
        self.out = fn()
        self.inner = max(1, math.ceil(BATCH_CPU / max(time.process_time() - c0, 1e-7)))

    def __call__(self) -> float:
        """CPU seconds of one call, from a batch."""
        c0 = time.process_time()
        for _ in range(self.inner):
            self.out = self.fn()
        return (time.process_time() - c0) / self.inner


def _median_cpu(fn, repeat: int):
    """(median CPU seconds of one call over ``repeat`` batches, the last result, the batch)."""
    batch = Batch(fn)
    return statistics.median(batch() for _ in range(repeat)), batch.out, batch


PAIRED_ROUNDS = 9
"""Rounds of a paired ratio.  The machine's speed drifts over seconds (one method's ladder
ran 1.7x slower than minutes before), so a goal's ratio is not the quotient of two costs timed
apart: each round times both sides' batches back to back, in alternating order, and the ratio
is the median of the rounds' ratios."""


def paired_ratio(res: CaseResult, fast: Point, slow: Point, rounds: int = PAIRED_ROUNDS) -> float:
    """slow's cost over fast's, both as cost_at read them, timed in interleaved rounds."""
    def cost(p: Point, times: dict) -> float:
        if not p.rungs:
            return times[p.runs[0]]
        return _between(*(times[k] for k in p.rungs), p.frac)

    keys = list(dict.fromkeys(fast.runs + slow.runs))
    ratios = []
    for k in range(rounds):
        times = {key: res.timers[key]() for key in (keys if k % 2 == 0 else keys[::-1])}
        ratios.append(cost(slow, times) / cost(fast, times))
    return statistics.median(ratios)


def roller_case(model: str, params: dict, rtols, peer_rtols, repeat: int) -> CaseResult:
    from camdyn.runtime.core import methods as M
    from camdyn.runtime.studies import peers
    from camdyn.runtime.core.errors import SimulationError
    from camdyn.runtime.core.compiled import load
    from camdyn.runtime.core.simulator import Simulator

    title = f"{model} " + ", ".join(f"{k} = {v:g}" for k, v in params.items())
    res = CaseResult(f"{model}_" + "_".join(f"{k}{v:g}" for k, v in params.items()), title)
    ref = Simulator(model, 3.0, M.DP54(rtol=1e-12)).run(params)
    x_ref = ref.sample(T_GRID)["X"]
    _progress(f"{title}: reference {ref.stats['n_steps']} steps")
    makers = {"dp54": lambda r: M.DP54(rtol=r), "rodas4": lambda r: M.RODAS4(rtol=r),
              "rodas4+atol": lambda r: M.RODAS4(rtol=r, state_atol=ROLLER_ATOL),
              "radau5": lambda r: M.RADAU5(rtol=r),
              "radau5+atol": lambda r: M.RADAU5(rtol=r, state_atol=ROLLER_ATOL)}
    # +exact: the same method with the dwell, where the model is linear and time invariant,
    # stepped over with its propagator (Simulator's exact_segments; the others at their default)
    names = ["dp54", "dp54" + EXACT, "rodas4", "rodas4+atol", "rodas4+atol" + EXACT, "radau5",
             "radau5+atol", "radau5+atol" + EXACT]
    for name in names:
        make = makers[name.removesuffix(EXACT)]
        exact = True if name.endswith(EXACT) else None         # None: the method's default
        for rtol in rtols:
            sim = Simulator(model, 3.0, make(rtol), exact_segments=exact)
            try:
                sim.run(params)                                    # warm the caches
                cpu, r, batch = _median_cpu(lambda sim=sim: sim.run(params), repeat)
            except SimulationError as exc:
                res.points.append(Point(name, rtol, None, None, None, None, "failed", str(exc)))
                continue
            err = float(np.max(np.abs(r.sample(T_GRID)["X"] - x_ref)))
            res.points.append(Point(name, rtol, err, cpu, r.stats["n_steps"], r.stats["n_rhs"]))
            res.timers[(name, rtol)] = batch
        _progress(f"  {name}: done")
    m = load(model)
    for name in ("Radau", "BDF", "LSODA"):
        for rtol in peer_rtols:
            runs = []
            for k in range(3):
                pr = peers.run_peer(name, m, params, 3.0, rtol, max_rhs=400_000)
                runs.append(pr)
                if not pr.ok or pr.cpu_seconds > 0.5:
                    break
            pr = runs[-1]
            if pr.status != "ok":
                res.points.append(Point(name, rtol, None, None, None, pr.n_rhs or None, pr.status,
                                        pr.message[:80]))
                continue
            err = float(np.max(np.abs(pr.sample(T_GRID)["X"] - x_ref)))
            cpu = statistics.median(p.cpu_seconds for p in runs)
            res.points.append(Point(name, rtol, err, cpu, pr.n_steps, pr.n_rhs))
        _progress(f"  {name}: done")
    return res


# -- the beam follower -------------------------------------------------------------------

def _beam_kw(label: str) -> dict:
    """The case's fields a contestant's label asks for: "dop853", or "dop853+mode-atol" for
    the mode tolerance `camdyn beam-follower` runs with (beam_case.MODE_ATOL)."""
    from camdyn.runtime.targets.beam_case import MODE_ATOL

    method, _, extra = label.partition("+")
    return {"method": method, **({"mode_atol": MODE_ATOL} if extra == "mode-atol" else {})}


def beam_reference(case_kw: dict, budget: int):
    """(max |v_E|, which run) of the tightest affordable run: DOP853 at rtol 1e-11 with the
    mode amplitudes to MODE_ATOL/1000 of the rod's deflection scale (within 4e-10 of DOP853
    at rtol 1e-10 with the rates held to Omega times that, at N = 6), else RADAU5 at rtol
    1e-10 with the same; None where both exceed the step budget."""
    from camdyn.runtime.studies import stability_beam
    from camdyn.runtime.targets.beam_case import MODE_ATOL, Case
    from camdyn.runtime.core.errors import SimulationError

    for method, rtol in (("dop853", 1e-11), ("radau5", 1e-10)):
        try:
            case = Case(**case_kw, method=method, rtol=rtol, mode_atol=MODE_ATOL / 1000)
            return stability_beam.run_case(case, budget)[0], f"{method}, rtol {rtol:g}"
        except SimulationError:
            continue
    return None, None


def beam_case(key: str, title: str, case_kw: dict, settings, repeat: int,
              budget: int = 2_000_000) -> CaseResult:
    """The beam follower: each (contestant, rtol, step budget) against beam_reference (none
    where that exceeds its budget too: then steps and times only)."""
    from camdyn.runtime.studies import stability_beam
    from camdyn.runtime.targets.beam_case import Case
    from camdyn.runtime.core.errors import SimulationError

    res = CaseResult(key, title)
    ref, how = beam_reference(case_kw, budget)
    _progress(f"{title}: " + (f"reference ({how}) max |v_E| = {ref:.9e}" if how
                              else "no reference within the step budget"))
    for method, rtol, limit in settings:
        case = Case(**case_kw, **_beam_kw(method), rtol=rtol)
        try:
            runs = [stability_beam.run_case(case, limit)]
            # a single run of a fraction of a second is at the mercy of the machine's noise:
            # the short ones are repeated, as the goal's own measurement (bench/beam.py) is
            if runs[0][2] < 1.0:
                runs += [stability_beam.run_case(case, limit) for _ in range(repeat - 1)]
        except SimulationError as exc:
            res.points.append(Point(method, rtol, None, None, None, None, "failed",
                                    f"{str(exc)[:90]} (step budget {limit:,})"))
            _progress(f"  {method} {rtol:g}: failed")
            continue
        v, r, _ = runs[-1]
        cpu = statistics.median(x[2] for x in runs)
        err = None if ref is None else abs(v - ref) / ref
        res.points.append(Point(method, rtol, err, cpu, int(r.stats["n_steps"]),
                                int(r.stats["n_rhs"])))
        _progress(f"  {method} {rtol:g}: {r.stats['n_steps']} steps, {cpu:.3f} s")
    return res


# -- report -------------------------------------------------------------------------------

def _fmt(x, spec):
    return "-" if x is None or (isinstance(x, float) and not math.isfinite(x)) else format(x, spec)


def chart(res: CaseResult, path: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for method in dict.fromkeys(p.method for p in res.points):
        pts = sorted((p for p in res.points if p.method == method and p.status == "ok"
                      and p.error and p.cpu), key=lambda p: p.rtol, reverse=True)
        if not pts:
            continue
        style = "--" if method in ("Radau", "BDF", "LSODA") else "-"
        ax.loglog([p.cpu for p in pts], [p.error for p in pts], style, marker="o", ms=3,
                  label=method)
    if not ax.lines:
        ax.text(0.5, 0.5, "no run finished within its step budget\n(see the table)",
                ha="center", va="center", transform=ax.transAxes)
        ax.set_xscale("log")
        ax.set_yscale("log")
    ax.set_xlabel("CPU time of the integration, s")
    ax.set_ylabel("follower error" if res.key.startswith("roller") else "relative error of max |v_E|")
    ax.set_title(res.title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if ax.lines:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _where(p: Point) -> str:
    return p.note if p.status == "interpolated" else f"rtol {p.rtol:.0e}"


def ratio_rows(res: CaseResult, fast: str, slow: str) -> list[str]:
    out = []
    for target in TARGETS:
        a, b = res.cost_at(fast, target), res.cost_at(slow, target)
        if a is None or b is None:
            out.append(f"| {target:.0e} | {fast} {_fmt(a and a.cpu * 1e3, '.3g')} ms | "
                       f"{slow} {_fmt(b and b.cpu * 1e3, '.3g')} ms | - |")
            continue
        out.append(f"| {target:.0e} | {fast} {a.cpu * 1e3:.3g} ms ({_where(a)}) | "
                   f"{slow} {b.cpu * 1e3:.3g} ms ({_where(b)}) | {b.cpu / a.cpu:.1f} |")
    return out


def markdown(results: list, info: dict, wall: float) -> str:
    lines = ["# Stiff benchmarks", "",
             "Written by `make bench` (`bench/stiff.py`); rerun it to refresh every figure below.",
             "", (__doc__ or "").split("\n\n", 1)[1].split("    python")[0].strip(),
             "", "## Machine", ""]
    lines += [f"- {k}: {v}" for k, v in info.items()] + [f"- benchmark wall time: {wall:.0f} s", ""]
    lines += ["## Verdict", ""] + verdict(results) + [""]
    for res in results:
        lines += [f"## {res.title}", "", f"![{res.key}]({CHARTS}/stiff_{res.key}.png)", ""]
        lines += ["| method | rtol | error | CPU ms | steps | rhs calls | status |",
                  "|---|---|---|---|---|---|---|"]
        for p in res.points:
            lines.append(f"| {p.method} | {p.rtol:.0e} | {_fmt(p.error, '.2e')} | "
                         f"{_fmt(p.cpu and p.cpu * 1e3, '.3g')} | {_fmt(p.steps, 'd')} | "
                         f"{_fmt(p.rhs, 'd')} | {p.status}{(': ' + p.note) if p.note else ''} |")
        if any(p.method in IMPLICIT for p in res.points):
            lines += ["", "Cost at matched follower error (read off each method's work-precision curve):", "",
                      "| target | implicit | other | ratio |", "|---|---|---|---|"]
            for fast in IMPLICIT + tuple(m + EXACT for m in IMPLICIT):
                for other in ("dp54", "dp54" + EXACT, "Radau", "BDF", "LSODA"):
                    if any(p.method == other for p in res.points):
                        lines += ratio_rows(res, fast, other)
        lines.append("")
    lines += ["## When to pick which", "",
              "- A fast mode that only rings and that the answer does not need (the roller on its "
              "contact spring, seen from the follower): rodas4 or radau5 with that mode's states "
              "given large `state_atol`; they step over the mode (L-stable) at about the same cost "
              "and the follower's error stays controlled. Its own history (contact force) is then "
              "not resolved.",
              "- A fast mode whose motion is part of the answer (the beam's higher modes in the tip "
              "deflection, the contact force history): it must be resolved, and dp54 resolves it "
              "more cheaply than an implicit method (order 5, no linear algebra); the charts show "
              "dp54 ahead there.",
              "- A fast mode that is heavily damped (a stiff shaft, a motor's electrical time "
              "constant: chain3 with c3 = 1e6, motor2 with T_el = 1e-6 in the README): rodas4 or "
              "radau5; dp54 is held to its stability limit whatever the tolerance.",
              "- The beam follower: dop853 with the mode tolerance (+mode-atol, the command's "
              "default), which lets it step at its stability limit for the fastest frozen mode; "
              "at the library's default tolerances every method resolves the fastest mode's "
              "ringing to 1e-17 m, the implicit ones at several times the explicit ones' price. "
              "Its rigid limit (E x 1e6) with the mode tolerance: rodas4 or radau5, which step "
              "over the modes without the roller's inertia; with it, see the table.", ""]
    return "\n".join(lines)


def verdict(results: list) -> list[str]:
    out = []
    by = {r.key: r for r in results}
    r = by.get("roller_bilateral_kappa1000_zeta0.1")
    if r is not None:
        for fast in IMPLICIT:
            # against dp54 each side at its best: the cheaper of its run integrating the dwell
            # and its run stepping over it; SciPy's Radau integrates it, and so does camdyn's
            for other, goal, mine in ((("dp54", "dp54" + EXACT), 10.0, (fast, fast + EXACT)),
                                      (("Radau",), 20.0, (fast,))):
                parts, ok = [], []
                for target in TARGETS:
                    a, b = r.best_at(mine, target), r.best_at(other, target)
                    if a is None or b is None:
                        parts.append(f"{target:.0e}: -")
                        continue
                    # the peers' runs are not batched: their costs are compared as timed
                    q = (paired_ratio(r, a, b) if all(k in r.timers for k in a.runs + b.runs)
                         else b.cpu / a.cpu)
                    parts.append(f"{target:.0e}: {q:.1f} ({a.method} against {b.method})")
                    ok.append(q >= goal)
                other = " or ".join(other)
                state = "MET at every target" if len(ok) == len(TARGETS) and all(ok) else (
                    "MET at some targets" if any(ok) else "NOT MET")
                out.append(f"- Goal '{' or '.join(mine)} >= {goal:g}x faster than {other} at equal follower "
                           f"error (roller, ratio 1000, zeta 0.1)': {state} ({'; '.join(parts)}).")
    b = by.get("beam6")
    if b is not None:
        for method in dict.fromkeys(p.method for p in b.points):
            pts = [p for p in b.points if p.method == method and p.rtol == 1e-6]
            if pts and pts[0].status == "ok":
                out.append(f"- Goal 'beam N = 6, rtol 1e-6, one revolution under 0.3 s' with "
                           f"{method}: {pts[0].cpu:.2f} s, "
                           f"{'MET' if pts[0].cpu < 0.3 else 'NOT MET'}.")
            elif pts:
                out.append(f"- beam N = 6, rtol 1e-6 with {method}: {pts[0].status}.")
    return out


def full_run(with_beam: bool) -> list:
    """The cases of the module docstring, every method over its tolerance ladder."""
    rtols = tuple(10.0 ** (-k / 2) for k in range(6, 17))          # 1e-3 ... 1e-8, two per decade
    peer_rtols = (1e-3, 1e-4, 1e-5, 1e-6)
    repeat = 5
    results = []
    for kappa in (100.0, 1000.0):
        for zeta in (0.0, 0.1):
            results.append(roller_case("roller_bilateral", {"kappa": kappa, "zeta": zeta}, rtols,
                                       peer_rtols, repeat))
    results.append(roller_case("roller", {"kappa": 1000.0, "zeta": 0.1}, rtols, (), repeat))
    if with_beam:
        from camdyn.runtime.targets.beam_case import Case
        E = Case().E
        methods = ("dp54", "dop853", "rodas4", "radau5")
        results.append(beam_case("beam6", "beam follower, N = 6, one revolution", {"modes": 6},
                                 [(m + extra, rtol, 2_000_000) for extra in ("", "+mode-atol")
                                  for m in methods for rtol in (1e-4, 1e-6)], 5))
        rigid = [("dp54", 1e-4, 1_000_000)] + [(m + extra, 1e-4, 200_000)
                                               for extra in ("", "+mode-atol")
                                               for m in ("rodas4", "radau5")]
        results.append(beam_case("beam6_E1e6", "beam follower, N = 6, E x 1e6 (rigid limit)",
                                 {"modes": 6, "E": E * 1e6}, rigid, 1, budget=1_000_000))
        results.append(beam_case("beam6_E1e6_Jr0", "beam follower, N = 6, E x 1e6 (rigid "
                                 "limit), no roller inertia", {"modes": 6, "E": E * 1e6,
                                                               "roller_inertia": 0.0},
                                 [(m + "+mode-atol", rtol, 200_000) for m in ("rodas4", "radau5")
                                  for rtol in (1e-4, 1e-6)], 1, budget=1_000_000))
    return results


def quick_run(with_beam: bool) -> list:
    """Every kind of case once, cheaply: what a full run does, in seconds."""
    results = [roller_case("roller_bilateral", {"kappa": 100.0, "zeta": 0.1}, (1e-3, 1e-5),
                           (1e-4,), 1),
               roller_case("roller", {"kappa": 1000.0, "zeta": 0.1}, (1e-3,), (), 1)]
    if with_beam:
        results.append(beam_case("beam2", "beam follower, N = 2, one revolution", {"modes": 2},
                                 [("dp54", 1e-4, 200_000), ("rodas4", 1e-4, 200_000),
                                  ("radau5", 1e-4, 200_000), ("dop853+mode-atol", 1e-4, 200_000)],
                                 1, budget=200_000))
    return results


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true",
                    help="a miniature run in seconds, written to a temporary folder")
    ap.add_argument("--no-beam", action="store_true", help="leave the beam follower out")
    args = ap.parse_args(argv)
    from where import report_folder, write_report

    start = time.time()
    results = (quick_run if args.quick else full_run)(not args.no_beam)
    wall = time.time() - start
    for line in verdict(results):
        print(line)
    with report_folder(args.quick) as folder:
        charts = folder / CHARTS
        charts.mkdir(parents=True, exist_ok=True)
        for res in results:
            chart(res, charts / f"stiff_{res.key}.png")
        write_report(folder / REPORT, markdown(results, machine_info(), wall) + "\n")
        print(f"wrote {folder / REPORT} and {len(results)} charts in {charts}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
