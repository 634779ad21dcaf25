"""Speed against accuracy: a work-precision study of one problem.

Every method runs over a ladder of settings, each run is scored against a tight reference, and
the chart shows the error against CPU time, log-log, one line per method, SciPy's integrators
(:mod:`camdyn.runtime.studies.peers`) on the same generated right-hand side and Jacobian beside camdyn's.

* the ladder: rtol = 1e-3 ... 1e-10 (one per decade) for the adaptive methods (dp54, dop853, rodas4 and
  the peers, atol = 1e-3 rtol times the states' tolerance scales, camdyn's default); for the fixed-step ones
  (rk4, koster) N, 2N, 4N, ... 128N steps over the run, N the steps DP54 takes at rtol 1e-3.
  ``quick`` takes every other rung.
* the reference: DP54 at rtol 1e-13.  Its own error is estimated by scoring DP54 at rtol 1e-12
  against it: with the error roughly proportional to rtol that is the 1e-12 run's error, ten
  times the reference's, so the estimate is a safe bound; errors near it are not resolved.
* the score of a run: the relative error |v - v_ref|/|v_ref| of every headline figure and
  max_i |y_i - y_ref,i|/max(|y_ref,i|, scale_i) of the final state (scale_i the manifest's state
  scale), and the largest of them.  Headline figures: the target's own (runtime/targets/), read
  from a run of any integrator as every other command reads them: the residual-vibration
  figures of a model that declares a rise (one_dof, CAMSHAFT-1, -2), a DYNACAM scene's summary
  figures (those `camdyn simulate` reports, a full turn's return included), the beam
  follower's largest tip deflection; the final state alone otherwise.
* timing: CPU time (time.process_time) of the integration alone, figures excluded; a run under
  0.05 s is repeated, three times in all, and the median taken.
* failures: a fixed step beyond the stability boundary is "refused", a run that stops early or a
  peer whose solver fails "failed", a peer or a method that cannot run the model "skipped" (with
  the reason: rkn12 on a model with events or damping);
  none of them is a point of a line, all are rows of the CSV and JSON.
"""
from __future__ import annotations

import csv
import json
import math
import statistics
import time
from dataclasses import asdict, dataclass, field

import numpy as np

from . import peers as _peers
from ..core.errors import CamdynInputError, SimulationError
from ..core.methods import METHODS
from ..core.outdir import write_text, writing
from ..targets.problem import Problem

RTOL_LADDER = tuple(10.0 ** -k for k in range(3, 11))
"""The adaptive methods' tolerances, loosest first."""

DOUBLINGS = 8
"""Rungs of the fixed-step ladder: N 2^k steps, k = 0 .. DOUBLINGS - 1."""

REFERENCE_RTOL, CHECK_RTOL = 1e-13, 1e-12
"""DP54's tolerance for the reference and for the run that estimates the reference's error."""

REPEAT_BELOW = 0.05
"""Runs of less CPU time (s) than this are timed three times, the median kept."""


def final_state(run) -> np.ndarray:
    return np.array(run.y_end if isinstance(run, _peers.PeerRun) else run.y[-1], dtype=float)


def score(problem: Problem, figures: dict, y_end, ref: dict) -> dict:
    """Relative error of every figure and of the final state against the reference, and
    their maximum ("error")."""
    out = {}
    for key, r in ref["figures"].items():
        v = figures.get(key)
        out[key] = abs(v - r) / (abs(r) if r != 0 else 1.0) if v is not None else math.inf
    r = np.asarray(ref["final_state"])
    scale = np.maximum(np.abs(r), problem.model.state_scales())
    out["final_state"] = float(np.max(np.abs(np.asarray(y_end) - r) / scale))
    out["error"] = max(out.values())
    return out


@dataclass
class Row:
    """One run of the ladder."""

    method: str
    family: str                   # "camdyn" or "scipy"
    setting_name: str             # "rtol" or "step"
    setting: float | None
    status: str                   # "ok", "refused", "failed", "skipped"
    error: float | None = None
    cpu_seconds: float | None = None
    n_steps: int | None = None
    n_rhs: int | None = None
    n_jac: int | None = None
    repeats: int = 0
    errors: dict = field(default_factory=dict)
    message: str = ""


@dataclass
class Study:
    """A work-precision study: the reference and every row."""

    label: str
    model: str
    kind: str
    t_end: float
    reference: dict
    rows: list

    def as_dict(self) -> dict:
        return {"label": self.label, "model": self.model, "kind": self.kind, "t_end": self.t_end,
                "reference": self.reference, "rows": [asdict(r) for r in self.rows]}

    def methods(self) -> list:
        seen = []
        for r in self.rows:
            if r.method not in seen:
                seen.append(r.method)
        return seen

    def write_json(self, path) -> str:
        write_text(path, json.dumps(finite(self.as_dict()), indent=1))
        return str(path)

    def write_csv(self, path) -> str:
        figs = list(self.reference["figures"]) + ["final_state"]
        cols = ["method", "family", "setting_name", "setting", "status", "error", "cpu_seconds",
                "n_steps", "n_rhs", "n_jac", "repeats"] + [f"error_{k}" for k in figs] + ["message"]
        with writing(path), open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(cols)
            for r in self.rows:
                d = asdict(r)
                w.writerow([d[c] if c in d else "" for c in cols[:11]]
                           + [r.errors.get(k, "") for k in figs] + [r.message])
        return str(path)

    def chart(self, path) -> str:
        """Error against CPU time, log-log, one line per method; the reference's error
        estimate as a dotted line; refused, failed and skipped runs listed below the axes."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(10, 6))
        notes = []
        for k, name in enumerate(self.methods()):
            rows = [r for r in self.rows if r.method == name]
            ok = [r for r in rows if r.status == "ok" and r.error and r.cpu_seconds]
            camdyn = rows[0].family == "camdyn"
            if ok:
                ax.loglog([r.cpu_seconds for r in ok], [max(r.error, 1e-17) for r in ok],
                          "o-" if camdyn else "s--", lw=2.0 if camdyn else 1.2, ms=4,
                          color=f"C{k % 10}", label=name if camdyn else f"{name} (SciPy)")
            for status in ("refused", "failed", "skipped"):
                bad = [r for r in rows if r.status == status]
                if bad:
                    settings = ", ".join(f"{r.setting:.3g}" for r in bad if r.setting is not None)
                    why = bad[0].message.split(";")[0][:110]
                    notes.append(f"{name}: {status}" + (f" at {bad[0].setting_name} {settings}"
                                                        if status != "skipped" else "")
                                 + f" ({why})")
        est = self.reference.get("error_estimate")
        if est:
            ax.axhline(est, color="0.4", ls=":", lw=1,
                       label=f"reference error bound {est:.1g}")
        ax.set_xlabel("CPU time of the integration [s]")
        ax.set_ylabel("relative error, largest over the headline figures and the final state")
        ax.set_title(f"Work-precision: {self.label}", fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
        fig.subplots_adjust(left=0.09, right=0.78, bottom=0.1 + 0.022 * len(notes))
        if notes:
            fig.text(0.01, 0.01, "\n".join(notes), fontsize=6.5, va="bottom", family="monospace")
        with writing(path):
            fig.savefig(path, dpi=110)
        plt.close(fig)
        return str(path)


def finite(obj):
    """JSON-safe copy: non-finite floats become None."""
    if isinstance(obj, dict):
        return {k: finite(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [finite(v) for v in obj]
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def _timed(call, seconds_of=None, warm: bool = False):
    """(last value, median CPU seconds, repeats): a run under REPEAT_BELOW is repeated.
    ``warm``: one untimed call first (a method's first rung: imports, first-use caches)."""
    times, value = [], None
    if warm:
        call()
    for _ in range(3):
        c0 = time.process_time()
        value = call()
        cpu = time.process_time() - c0 if seconds_of is None else seconds_of(value)
        times.append(cpu)
        if cpu >= REPEAT_BELOW:
            break
    return value, statistics.median(times), len(times)


def fixed_steps(n_base: int, quick: bool) -> list:
    """Step counts of the fixed-step ladder."""
    ks = range(0, DOUBLINGS, 2 if quick else 1)
    return [n_base * 2**k for k in ks]


def rtol_ladder(quick: bool) -> tuple:
    return RTOL_LADDER[::2] if quick else RTOL_LADDER


def reference(problem: Problem, progress=None) -> dict:
    """The reference figures and final state (DP54 at REFERENCE_RTOL) and the estimate of
    their error (DP54 at CHECK_RTOL scored against them)."""
    say = progress or (lambda msg: None)
    out = {}
    for rtol in (REFERENCE_RTOL, CHECK_RTOL):
        c0 = time.process_time()
        res = problem.simulator(METHODS["dp54"](rtol=rtol)).run(problem.params)
        figs = problem.figures(res)
        say(f"reference dp54 rtol={rtol:g}: {res.stats['n_steps']} steps, "
            f"{time.process_time() - c0:.3g} s")
        if rtol == REFERENCE_RTOL:
            out = {"method": "dp54", "rtol": rtol, "figures": figs,
                   "final_state": final_state(res).tolist(), "n_steps": int(res.stats["n_steps"]),
                   "state_names": problem.model.state_names}
        else:
            check = score(problem, figs, final_state(res), out)
            out.update(check_rtol=rtol, error_estimate=check["error"],
                       error_estimate_by_figure={k: v for k, v in check.items() if k != "error"})
    return out


def camdyn_row(problem: Problem, ref: dict, name: str, setting: float, warm: bool = False) -> Row:
    """One camdyn run of the ladder, timed and scored."""
    cls = METHODS[name]
    kind = "rtol" if cls.adaptive else "step"
    row = Row(name, "camdyn", kind, setting, "ok")
    try:
        sim = problem.simulator(cls(rtol=setting) if cls.adaptive else cls(step=setting))
    except CamdynInputError as exc:      # a method this model is not for (rkn12 on a contact)
        row.status, row.message = "skipped", str(exc)
        return row
    try:
        res, cpu, reps = _timed(lambda: sim.run(problem.params), warm=warm)
        figs = problem.figures(res)
    except SimulationError as exc:
        row.status = "refused" if "beyond the stability limit" in str(exc) else "failed"
        row.message = str(exc)
        return row
    row.errors = score(problem, figs, final_state(res), ref)
    row.error = row.errors.pop("error")
    row.cpu_seconds, row.repeats = cpu, reps
    row.n_steps, row.n_rhs = int(res.stats["n_steps"]), int(res.stats["n_rhs"])
    return row


def peer_row(problem: Problem, ref: dict, name: str, rtol: float, sample_times=None,
             warm: bool = False) -> Row:
    """One run of a SciPy peer, timed (its integration alone) and scored."""
    row = Row(name, "scipy", "rtol", rtol, "ok")

    def call():
        return _peers.run_peer(name, problem.model, problem.params, problem.t_end, rtol,
                               law=problem.law, theta=problem.theta, y0=problem.y0,
                               sample_times=sample_times)

    run, cpu, reps = _timed(call, lambda r: r.cpu_seconds, warm=warm)
    if not run.ok:
        row.status, row.message = run.status, run.message
        row.setting = None if run.status == "skipped" else rtol
        return row
    row.errors = score(problem, problem.figures(run), final_state(run), ref)
    row.error = row.errors.pop("error")
    row.cpu_seconds, row.repeats = cpu, reps
    row.n_steps, row.n_rhs, row.n_jac = run.n_steps, run.n_rhs, run.n_jac
    return row


def study(problem: Problem, methods=None, peers=None, quick: bool = False,
          progress=None) -> Study:
    """Run the whole study: the reference, then every method over its ladder, then the peers.

    methods  camdyn's methods (default: all of METHODS)
    peers    SciPy peers (default: all of peers.PEERS; () for none)
    """
    say = progress or (lambda msg: None)
    methods = list(METHODS) if methods is None else list(methods)
    peer_names = list(_peers.PEERS) if peers is None else list(peers)
    for m in methods:
        if m not in METHODS:
            raise CamdynInputError(f"argument --methods: unknown method {m!r}; choose from "
                                   f"{', '.join(METHODS)}")
    for m in peer_names:
        if m not in _peers.PEERS:
            raise CamdynInputError(f"argument --peers: unknown peer {m!r}; choose from "
                                   f"{', '.join(_peers.PEERS)}")
    ref = reference(problem, say)
    rows = []
    n_base = None

    def log(row):
        rows.append(row)
        setting = "" if row.setting is None else f" {row.setting_name}={row.setting:.3g}"
        if row.status == "ok":
            say(f"{row.method}{setting}: error {row.error:.3g}, {row.cpu_seconds:.3g} s CPU")
        else:
            say(f"{row.method}{setting}: {row.status}: {row.message.split(';')[0][:160]}")

    for name in methods:
        if METHODS[name].adaptive:
            for k, rtol in enumerate(rtol_ladder(quick)):
                log(camdyn_row(problem, ref, name, rtol, warm=k == 0))
                if rows[-1].status == "skipped":
                    rows[-1].setting = None
                    break
            continue
        if n_base is None:
            loose = problem.simulator(METHODS["dp54"](rtol=RTOL_LADDER[0])).run(problem.params)
            n_base = max(16, int(loose.stats["n_steps"]))
        span = problem.t_end
        for k, n in enumerate(fixed_steps(n_base, quick)):
            log(camdyn_row(problem, ref, name, span / n, warm=k == 0))
    sample_times = None
    if "odeint" in peer_names:
        # odeint reports at the reference's steps, four points each (its dense output)
        res = problem.simulator(METHODS["dp54"](rtol=RTOL_LADDER[-1])).run(problem.params)
        t = res.t
        sample_times = np.unique((t[:-1, None] + np.diff(t)[:, None]
                                  * np.linspace(0, 1, 4, endpoint=False)).ravel())
    for name in peer_names:
        reason = _peers.skip_reason(name, problem.model)
        if reason:
            log(Row(name, "scipy", "rtol", None, "skipped", message=reason))
            continue
        for k, rtol in enumerate(rtol_ladder(quick)):
            log(peer_row(problem, ref, name, rtol, sample_times, warm=k == 0))
    return Study(problem.label, problem.model.name, problem.kind, problem.t_end, ref, rows)


# -- the problem of a target ----------------------------------------------------------------

def problem(arg: str, params: dict, t_end: float | None, progress=None):
    """The problem named on the command line: a scene (file or built-in; its span is its own)
    or a model (a model file, built on demand, or a built-in model), as its target runs it
    (runtime/targets/problem.py): the residual-vibration figures of a model that declares a
    rise (to t_end, default 3), else the final state (t_end required)."""
    from ..targets.resolve import resolve

    try:
        target = resolve(arg, model_class=None, progress=progress)
    except CamdynInputError as exc:
        raise CamdynInputError(f"SCENE_OR_MODEL {exc}") from None
    if t_end is not None:
        try:
            target = target.with_settings(t_end=t_end)
        except CamdynInputError as exc:
            raise CamdynInputError(f"argument --t-end: {exc}") from None
    target = target.with_parameters(params)
    try:
        pr = target.problem()
    except CamdynInputError as exc:
        raise CamdynInputError(str(exc) if str(exc).startswith("argument") else
                               f"argument --t-end: {exc}") from None
    shown = ", ".join(f"{k}={v:g}" for k, v in params.items())
    pr.label = f"{target.title}" + (f" ({shown})" if shown else "") + f", to {pr.t_end:g}"
    return pr
