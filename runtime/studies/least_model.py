"""The least model for a DYNACAM scene (thesis sec. 8.2).

Sec. 8.2 compares the 4-DOF DYNACAM model with its reductions on the two mechanisms of
fig. 8.1 (responses in fig. 8.3): the 2-DOF CAMSHAFT-2 model 'is not permissible if
c_z' << c_x' (its residual acceleration is 2.45 times the 4-DOF one in fig. 8.3a) but
'resembles' the 4-DOF model when c_z' >> c_x (a factor 1.08, fig. 8.3b) (sec. 8.2.4);
CAMSHAFT-1 hardly differs from CAMSHAFT-2 'due to the high Fv-numbers' (sec. 8.2.5);
dropping the follower spring changes the residual amplitude by 1.1 to 1.36 (sec. 8.2.3),
dropping damping by 1.5 to 1.6 (sec. 8.2.2); the design graphs hold only 'if no backlash is
traversed' (sec. 8.2.8).  Those statements are criteria, not numbers for another
mechanism, so here they are reported as the reasons and the error of each reduction is
measured by probes:

1. the chain of candidates, each dropping more than the one before: the scene as given;
   ideal drive (motor -> constant speed); no backlash (rigid gear, bilateral roller); no
   follower spring (roller held on the cam, 'mathematical forcing', sec. 8.2.3); no friction;
   no external force; no tangential shaft deflection y'; no shaft deflections (the 2-DOF
   DYNACAM model); CAMSHAFT-2 (tau, Fa, Fv) (5.15), (5.16); CAMSHAFT-1 (tau, Fa) (4.15);
   one DOF (tau, with the follower's damping q_x; CAMSHAFT-1, -2 are undamped) (3.1).  A shaft direction is dropped with the equivalent magnitudes of
   sec. 5.6, so tau, Fa and Fv stay as they are: c_x -> c_c (4.3), m_x -> m (4.39),
   k -> c_tan R_1/2^2 (4.4), J -> m_tan R_1/2^2 (5.51).  Only elements the scene has give a
   candidate; a DYNACAM variant that is not compiled yet is skipped unless ``build``;
2. a probe of every candidate: the scene's method at rtol 1e-5 and 1e-6 (the second is the
   probe's figure, their difference its error estimate, as runtime/core/methods.py argues);
3. predicted error of a candidate on a figure f: |f_c - f_full| + e_c + e_full from the
   probes, relative to |f_full|; accepted when below the tolerance on every figure;
4. the least (last in the chain) accepted candidate runs at the scene's tolerance; its
   error bound against the full model's exact figure is |f - f_full| + e_full + e, with f
   this run's figure and e its own error, twice |f(rtol) - f(rtol/10)| (one more run);
5. time: the chosen run's CPU time against the full model's at the scene's tolerance,
   measured if ``measure_full`` else estimated from the full probes (step count
   n ~ rtol^-a with a fitted to the two probes, CPU per step of the tighter probe).

The probes cost time too; that is reported, not hidden: for one run of a millisecond
scene they cost more than they save, the choice pays in sweeps over the scene.
"""
from __future__ import annotations

import math
import time
from dataclasses import asdict, dataclass, field

import numpy as np

from ..targets import dynacam, scene_files as scenes
from ..core.errors import CamdynInputError, SimulationError
from ..core.methods import METHODS
from ..measure.extremes import extreme

TOLERANCE = 0.05
"""Default relative tolerance on every requested figure."""

FIGURES = ("U0", "U0dd", "Xdd_min_rise", "T_at_Xdd_min", "Xdd_max_rise", "speed_variation_max")
"""Figures a least model can be asked for: each model of the chain gives them (CAMSHAFT-1
has no cam speed, so it cannot give speed_variation_max)."""

DEFAULT_FIGURES = ("U0", "U0dd", "Xdd_min_rise")
"""What the design graphs of fig. 4.11 and sec. 8.2 are about: positional error, residual
acceleration, largest deceleration in the rise."""

PROBE_RTOL = (1e-5, 1e-6)

OWN_MARGIN = 2.0
"""The chosen run's own error is taken as twice |f(rtol) - f(rtol/10)|: that difference
estimates the error to within about 10 % (runtime/core/methods.py), and on fig8_1a it falls short
of the true error (against rtol 1e-11) by 10 %."""

# sec. 8.2.4, fig. 8.3a/b: the 2-DOF model's residual acceleration against the 4-DOF one's
THESIS_2DOF_FACTOR = {"c_z'/c_x << 1 (fig. 8.3a)": 2.45, "c_z'/c_x >> 1 (fig. 8.3b)": 1.08}


@dataclass
class Criterion:
    """A sec. 8.2 statement applied to the scene: value, what the thesis says, and whether it
    speaks for the reduction ("for"), against it ("against"), or leaves it open ("open")."""

    name: str
    value: float | None
    verdict: str
    text: str


@dataclass
class Candidate:
    key: str
    label: str
    scene: object = None            # a DYNACAM scene, or None for the CAMSHAFT models
    model: str | None = None        # camshaft2, camshaft1, one_dof
    params: dict = field(default_factory=dict)
    states: int = 0
    criteria: list = field(default_factory=list)
    note: str = ""                  # why it was not probed
    probe: dict | None = None       # figure -> value at the tighter probe rtol
    probe_error: dict | None = None  # figure -> |loose - tight|
    probe_cpu: float = 0.0
    probe_steps: tuple = ()
    probe_cpus: tuple = ()
    probe_extra: dict = field(default_factory=dict)   # the full probe's motor speed, backlash
    predicted: dict = field(default_factory=dict)   # figure -> relative predicted error
    accepted: bool = False
    jump: bool | None = None

    def as_dict(self) -> dict:
        out = {k: v for k, v in asdict(self).items() if k not in ("scene",)}
        out["variant"] = self.scene.variant if self.scene is not None else self.model
        return out


# -- the chain ------------------------------------------------------------------------------------

def _compiled(options) -> bool:
    from ..core.variants import is_compiled

    return is_compiled(options)


def _with_options(sc, changes: dict, build: bool):
    """The scene with ``changes`` to its options and the parameters the new variant does not
    declare dropped; None when that variant is not compiled and ``build`` is off."""
    from ..core.variants import Options

    opts = Options(**{**asdict(sc.options), **changes})
    if not build and not _compiled(opts):
        return None
    declared = scenes.declared_parameters(opts)
    drop = tuple(k for k in sc.parameters if k not in declared)
    return scenes.replace(sc, changes, drop=drop)


def _shaft_free(sc, drop_y: bool, drop_z: bool, build: bool):
    """The scene without shaft direction y' and/or z', with the equivalent magnitudes of
    sec. 5.6 so that tau, Fa, Fv do not change (see the module docstring)."""
    ch = dynacam.characteristics(sc.options, sc.parameters)
    changes, new = {}, {}
    if drop_z and sc.options.shaft_z:
        changes["shaft_z"] = False
        new.update(c_x=ch["c_c"], m_x=ch["m"])
    if drop_y and sc.options.shaft_y:
        changes["shaft_y"] = False
        new.update(k=ch["k_tan"], J=ch["J_tan"])
    reduced = _with_options(sc, changes, build)
    return None if reduced is None else scenes.replace(reduced, parameters=new)


def _max_slope_sq(sc) -> float:
    """max H'^2 of the scene's law over the rise: CAMSHAFT-1's stiffness dip is
    1 + Fa H'^2 (4.15), 1 + 4 Fa for the cycloid (4.19)."""
    from ..core.laws import choose

    H = choose(sc.law, sc.theta).evaluate(np.linspace(0.0, 1.0, 2001))
    return float(np.max(H[:, 1] ** 2))


def chain(sc, tolerance: float = TOLERANCE, build: bool = False) -> list[Candidate]:
    """The candidates for scene ``sc``, from the scene itself to the one-DOF model."""
    o, p = sc.options, sc.parameters
    ch = dynacam.characteristics(o, p)
    out = [Candidate("full", f"as given ({sc.variant})", scene=sc)]
    cur = sc

    def step(key, label, changes, criteria):
        nonlocal cur
        nxt = _with_options(cur, changes, build)
        from ..core.variants import Options

        name = Options(**{**asdict(cur.options), **changes}).name
        if nxt is None:
            out.append(Candidate(key, label, criteria=criteria,
                                 note=f"variant {name} is not compiled (--build-variants builds it)"))
            return
        cur = nxt
        out.append(Candidate(key, label, scene=nxt, criteria=criteria))

    if o.motor != "constant":
        step("ideal_drive", "ideal drive: constant speed at the gear", {"motor": "constant"},
             [Criterion("motor speed variation", None, "open",
                        "App. 5, sec. A.5.4.3: the motor's speed varies by under 2 % (measured by "
                        "the full probe)")])
    if o.gear != "rigid" or o.roller in ("groove", "groove-squeeze"):
        step("no_backlash", "no backlash: rigid gear, bilateral roller",
             {"gear": "rigid", "roller": "bilateral"},
             [Criterion("backlash traversed", None, "open",
                        "sec. 8.2.8: the design graphs hold 'if no backlash is traversed'; "
                        "sec. 7.4.4: traversal doubles X'' (fig. 7.15 against 7.16)")])
    if o.roller == "contact" or o.spring:
        step("no_spring", "no follower spring: roller held on the cam (sec. 8.2.3)",
             {"roller": "bilateral", "spring": False},
             [Criterion("follower jump", None, "open",
                        "sec. 8.2.3: without the spring the residual amplitude is lower by "
                        "1.36 (fig. 8.3a) and 1.1 (fig. 8.3b); a model without it cannot jump")])
    if o.cam_friction or o.linkage_friction:
        step("no_friction", "no Coulomb friction", {"cam_friction": False,
                                                    "linkage_friction": False}, [])
    if o.external:
        step("no_force", "no external force", {"external": False}, [])
    # the shaft's stiffnesses as the contact feels them: z through i_z, y through i_y against
    # the torsion through the mean slope h_1 (k/R_1/2^2 for the translating roller, whose
    # i_y is h_1/R_1/2; a flat face square to its motion feels no y)
    i_y, i_z = ch["tan_alpha_me"], ch["i_z_me"]
    cz = p.get("c_z") / i_z**2 if o.shaft_z else None
    cy = p.get("c_y") if o.shaft_y else None
    c_beta = p["k"] * i_y**2 / (p["h_m"] / p["beta_m"]) ** 2
    crit_z = ([Criterion("c_z'/c_x", cz / p["c_x"], "against" if cz < p["c_x"] else "for",
                         "sec. 8.2.4: replacing the 4-DOF model by the 2-DOF one 'is not "
                         "permissible if c_z' << c_x' (U0'' off by a factor 2.45, fig. 8.3a, "
                         "c_z'/c_x = 0.1); with c_z' >> c_x it 'resembles' it (1.08, fig. 8.3b)")]
              if cz is not None else [])
    crit_y = ([Criterion("c_y'/c_beta'", cy / c_beta if c_beta > 0 else math.inf,
                         "for" if cy > c_beta else "against",
                         "sec. 8.2.7: with c_y' >> c_beta' the tangential compliance is that of "
                         "the shaft's torsion, so folding y' into c_tan (4.4) changes little")]
              if cy is not None else [])
    def shaft(key, label, drop_y, drop_z, criteria):
        from ..core.variants import Options

        red = _shaft_free(cur, drop_y, drop_z, build)
        changes = {k: False for k, d in (("shaft_y", drop_y), ("shaft_z", drop_z)) if d}
        name = Options(**{**asdict(cur.options), **changes}).name
        note = "" if red is not None else f"variant {name} is not compiled (--build-variants builds it)"
        out.append(Candidate(key, label, scene=red, criteria=criteria, note=note))

    if o.shaft_y and o.shaft_z:
        # the two 3-DOF alternatives, side by side: dropping either keeps the other
        shaft("no_shaft_y", "no tangential shaft deflection y' (c_tan, m_tan kept)", True, False,
              crit_y)
        shaft("no_shaft_z", "no shaft deflection z' along the follower (c_c, m kept)", False, True,
              crit_z)
    if o.shaft_y or o.shaft_z:
        shaft("no_shafts", "2-DOF DYNACAM: no shaft deflections (c_c, m, c_tan, m_tan kept)",
              True, True, crit_z + crit_y)
    q = {k: p.get(k, 0.0) for k in ("q_x", "q_b", "q_y", "q_z")}
    damped = any(v > 0 for v in q.values())
    crit_damp = ([Criterion("damping q", max(q.values()), "against",
                            "sec. 8.2.2: zero damping raises the residual amplitude by 1.5 "
                            "(fig. 8.3a) and 1.6 (fig. 8.3b); CAMSHAFT-1, -2 are undamped")]
                 if damped else [])
    co = cur.options
    plain = (co.motor == "constant" and co.gear == "rigid" and co.roller == "bilateral"
             and not (co.spring or co.cam_friction or co.linkage_friction or co.external))
    crit_elem = ([] if plain else
                 [Criterion("elements", None, "against",
                            "the CAMSHAFT models have no motor, backlash, spring, friction or force")])
    out.append(Candidate("camshaft2", "CAMSHAFT-2 (tau, Fa, Fv) (5.15), (5.16)", model="camshaft2",
                         params={"tau": ch["tau"], "Fa": ch["Fa"], "Fv": ch["Fv"]},
                         criteria=crit_z + crit_y + crit_damp + crit_elem))
    fv = ch["Fv"]
    out.append(Candidate("camshaft1", "CAMSHAFT-1 (tau, Fa) (4.15)", model="camshaft1",
                         params={"tau": ch["tau"], "Fa": ch["Fa"]},
                         criteria=[Criterion("Fv", fv, "for" if fv >= 2.42 else "open",
                                             "sec. 8.2.5: CAMSHAFT-1 and -2 'show hardly any "
                                             "differences, due to the high Fv-numbers' (2.42, "
                                             "2.68): the cam's flywheel effect is negligible")]))
    dip = ch["Fa"] * _max_slope_sq(sc)
    out.append(Candidate("one_dof", "one DOF, constant fictitious speed (tau) (3.1)", model="one_dof",
                         params={"tau": ch["tau"], "q": q["q_x"]},
                         criteria=[Criterion("Fa max H'^2", dip,
                                             "for" if dip < tolerance else "against",
                                             "(4.15), (4.19): CAMSHAFT-1's stiffness dips by "
                                             "1 + Fa H'^2 in the rise; the one-DOF model is "
                                             "Fa = 0 (fig. 4.11: at tau = 0.15, Fa = 2 gives "
                                             "17.5 times the U0 of Fa = 0)")]))
    from ..core.compiled import load

    for c in out:
        if c.scene is not None:
            c.states = len(dynacam.variant_model(c.scene).state_names)
        elif c.model is not None:
            c.states = len(load(c.model).state_names)
    return out


# -- runs and their figures -----------------------------------------------------------------------

def _method(sc, rtol):
    return METHODS[sc.method](rtol=rtol)


def _camshaft_figures(sc, model: str, params: dict, rtol: float) -> tuple[dict, int]:
    """Figures of a CAMSHAFT / one-DOF run over the scene's windows (nominal 0 < T < 1 for the
    rise, 1 < T < T_end for the dwell, as dynacam.summarize takes them)."""
    from ..core.simulator import simulate

    res = simulate(model, params, sc.T_end, sc.method, rtol=rtol, law=sc.law, theta=sc.theta,
                   dense_output=True)
    xmin, tmin = extreme(res, "Xdd", 0.0, 1.0, absolute=False, minimum=True)
    xmax, _ = extreme(res, "Xdd", 0.0, 1.0, absolute=False, minimum=False)
    out = {"U0": extreme(res, "U", 1.0, sc.T_end, absolute=True, minimum=False)[0],
           "U0dd": extreme(res, "Xdd", 1.0, sc.T_end, absolute=True, minimum=False)[0],
           "Xdd_min_rise": xmin, "T_at_Xdd_min": tmin, "Xdd_max_rise": xmax}
    if "Bdot_dev" in res.output_names:
        # refined on the dense output, as the DYNACAM summary it is compared with takes it
        out["speed_variation_max"] = extreme(res, "Bdot_dev", float(res.t[0]), float(res.t[-1]),
                                             absolute=True, minimum=False)[0]
    elif model == "one_dof":
        out["speed_variation_max"] = 0.0      # constant fictitious angular velocity, by definition
    return out, int(res.stats["n_steps"])


def run_candidate(sc, cand: Candidate, rtol: float) -> tuple[dict, int, float, dict | None]:
    """(figures, steps, CPU seconds, DYNACAM summary or None) of one run of a candidate."""
    start = time.process_time()
    if cand.scene is not None:
        summary, res = dynacam.run(cand.scene, method=_method(cand.scene, rtol))
        figs = {k: summary.get(k) for k in FIGURES}
        figs["jump"] = summary["jump"]["occurs"]
        figs["motor_speed_variation_max"] = summary["motor_speed_variation_max"]
        figs["backlash_traversed"] = _traversed(cand.scene, res)
        steps = summary["n_steps"]
    else:
        summary = None
        figs, steps = _camshaft_figures(sc, cand.model, cand.params, rtol)
        figs["jump"] = False
    return figs, steps, time.process_time() - start, summary


def _traversed(sc, res) -> bool:
    """Whether the run traverses backlash: the gear's mode or a grooved roller's changes."""
    names = [m["name"] for m in res.model.manifest.get("modes", [])]
    keys = [k for k in ("gear",) if k in names and sc.options.gear != "rigid"]
    if sc.options.roller in ("groove", "groove-squeeze") and "roller" in names:
        keys.append("roller")
    for k in keys:
        v = res.element_mode(k)
        if np.any(v[1:] != v[:-1]):
            return True
    return False


def _probe(sc, cand: Candidate, figures) -> None:
    loose, tight = (run_candidate(sc, cand, r) for r in PROBE_RTOL)
    cand.probe = {k: tight[0].get(k) for k in figures}
    cand.jump = bool(tight[0]["jump"])
    cand.probe_error = {k: (None if loose[0].get(k) is None or tight[0].get(k) is None
                            else abs(loose[0][k] - tight[0][k])) for k in figures}
    cand.probe_cpu = loose[2] + tight[2]
    cand.probe_steps = (loose[1], tight[1])
    cand.probe_cpus = (loose[2], tight[2])
    cand.probe_extra = {k: tight[0][k] for k in ("motor_speed_variation_max", "backlash_traversed")
                        if k in tight[0]}


def _estimate_full_cpu(full: Candidate, rtol: float) -> float:
    """CPU time of the full model at ``rtol`` from its two probes: steps n ~ rtol^-a with a
    fitted to the probes (DP54: a close to 1/5), time t = t_0 + b n fitted to them too (the
    consistent initial state and the figures cost a part that hardly grows with n)."""
    (n1, n2), (t1, t2) = full.probe_steps, full.probe_cpus
    a = math.log(max(n2, 1) / max(n1, 1)) / math.log(PROBE_RTOL[0] / PROBE_RTOL[1])
    n = n2 * (PROBE_RTOL[1] / rtol) ** a
    b = (t2 - t1) / (n2 - n1) if n2 > n1 else 0.0
    t0 = t2 - b * n2
    if b <= 0 or t0 < 0:            # timer noise: take the time as proportional to the steps
        return t2 * n / max(n2, 1)
    return t0 + b * n


# -- the decision -------------------------------------------------------------------------------

def choose(sc, figures=DEFAULT_FIGURES, tolerance: float = TOLERANCE, build: bool = False,
           measure_full: bool = False, progress=None) -> dict:
    """Probe the chain, pick the least candidate within ``tolerance`` on every figure, run it at
    the scene's tolerance and state its error bounds and the time saved (module docstring)."""
    if getattr(sc, "turn", None) is not None:
        raise CamdynInputError("--model auto: the scene has a [turn]; the reductions of sec. 8.2 "
                               "are compared over one rise and dwell, so drop [turn] for the choice")
    figures = tuple(figures)
    bad = [f for f in figures if f not in FIGURES]
    if not bad and len(set(figures)) < len(figures):
        twice = next(f for f in figures if figures.count(f) > 1)
        raise CamdynInputError(f"--figures: {twice} is given twice; give each figure once, from "
                               f"{', '.join(FIGURES)}")
    if bad or not figures:
        raise CamdynInputError(f"--figures: {bad[0] if bad else '(none)'} is not a figure of the "
                               f"least-model choice; choose from {', '.join(FIGURES)}")
    if not (isinstance(tolerance, (int, float)) and 0 < tolerance < 1):
        raise CamdynInputError(f"--tolerance={tolerance!r} is out of range: 0 < tolerance < 1 "
                               "(relative error)")
    say = progress or (lambda msg: None)
    cands = chain(sc, tolerance, build)
    full = cands[0]
    for c in cands:
        if c.note:
            say(f"least model: {c.key}: skipped, {c.note}")
            continue
        say(f"least model: probing {c.key}")
        if c is full:
            _probe(sc, c, figures)
            continue
        try:
            _probe(sc, c, figures)
        except (SimulationError, CamdynInputError) as exc:
            # a reduction that cannot be run is not a candidate; the full model's failure is
            # the scene's and stops the command
            c.probe, c.note = None, f"its probe failed: {exc}"
    for c in cands:
        if c.probe is None:
            continue
        missing = [f for f in figures if c.probe.get(f) is None or full.probe.get(f) is None]
        if missing:
            c.note = f"does not give {', '.join(missing)}"
            continue
        for f in figures:
            ref = abs(full.probe[f])
            diff = abs(c.probe[f] - full.probe[f]) + c.probe_error[f] + full.probe_error[f]
            c.predicted[f] = diff / ref if ref > 0 else (0.0 if diff == 0 else math.inf)
        if full.jump and not c.jump:
            c.note = "the full model's follower jumps and this one does not"
            continue
        c.accepted = all(c.predicted[f] < tolerance for f in figures)
        if c is not full:
            _criteria_from_probe(c, full, tolerance)
    chosen = [c for c in cands if c.accepted][-1] if any(c.accepted for c in cands) else full
    say(f"least model: running {chosen.key} at rtol {sc.rtol:g}")
    figs, steps, cpu, summary = run_candidate(sc, chosen, sc.rtol)
    # its own error estimate: one more run at rtol/10 (runtime/core/methods.py)
    tight, _, _, _ = run_candidate(sc, chosen, sc.rtol / 10)
    own = {f: OWN_MARGIN * abs(figs[f] - tight[f]) for f in figures}
    if chosen is full:
        bound = dict(own)
    else:
        bound = {f: abs(figs[f] - full.probe[f]) + full.probe_error[f] + own[f] for f in figures}
    rel = {f: bound[f] / abs(figs[f]) if figs[f] else math.inf for f in figures}
    estimate = _estimate_full_cpu(full, sc.rtol)
    if chosen is full:
        full_cpu, measured = cpu, True
    elif measure_full:
        full_cpu, measured = run_candidate(sc, full, sc.rtol)[2], True
    else:
        full_cpu, measured = estimate, False
    probes_cpu = sum(c.probe_cpu for c in cands)
    return {"scene": sc.title, "variant": sc.variant, "tolerance": tolerance,
            "figures": list(figures), "chosen": chosen.key, "chosen_label": chosen.label,
            "why": why(cands, chosen, figures, tolerance),
            "candidates": [c.as_dict() for c in cands],
            "result": {f: figs[f] for f in figures}, "bound": bound, "bound_relative": rel,
            "summary": summary,
            "time": {"chosen_cpu_seconds": cpu, "chosen_steps": steps,
                     "full_cpu_seconds": full_cpu, "full_measured": measured,
                     "full_cpu_seconds_estimate": estimate,
                     "saved_cpu_seconds": full_cpu - cpu,
                     "speedup": full_cpu / cpu if cpu > 0 else None,
                     "probes_cpu_seconds": probes_cpu}}


def _criteria_from_probe(c: Candidate, full: Candidate, tolerance: float) -> None:
    """Fill the criteria the full probe measures: the motor's speed variation (App. 5), whether
    backlash is traversed (sec. 8.2.8), whether the follower jumps (sec. 8.2.3)."""
    for cr in c.criteria:
        if cr.name == "follower jump":
            cr.value = float(bool(full.jump))
            cr.verdict = "against" if full.jump else "open"
        elif cr.name == "motor speed variation":
            v = full.probe_extra.get("motor_speed_variation_max")
            if v is not None:
                cr.value, cr.verdict = v, "for" if v < tolerance else "against"
        elif cr.name == "backlash traversed":
            v = full.probe_extra.get("backlash_traversed")
            if v is not None:
                cr.value, cr.verdict = float(v), "against" if v else "for"


def why(cands, chosen, figures, tolerance) -> str:
    """One paragraph: the chosen model, its predicted errors and criteria, and what stopped the
    next smaller one."""
    def errs(c):
        return ", ".join(f"{f} {100 * c.predicted[f]:.2g} %" for f in figures if f in c.predicted)

    def crit(c):
        return "; ".join(f"{cr.name} = {cr.value:.3g} ({cr.verdict})" if cr.value is not None
                         else f"{cr.name} ({cr.verdict})" for cr in c.criteria)

    parts = []
    if chosen.key == "full":
        parts.append("no probed reduction keeps every requested figure within "
                     f"{100 * tolerance:g} %, so the scene's own model runs")
    else:
        parts.append(f"{chosen.key}: predicted error {errs(chosen)} (all below "
                     f"{100 * tolerance:g} %)")
        if crit(chosen):
            parts.append(f"criteria: {crit(chosen)}")
    k = cands.index(chosen)
    for c in cands[k + 1:]:
        if c.note:
            parts.append(f"{c.key} not taken: {c.note}")
        elif not c.accepted:
            worst = max(figures, key=lambda f: c.predicted.get(f, 0.0))
            text = (f"{c.key} rejected: {worst} off by {100 * c.predicted[worst]:.3g} % "
                    f"> {100 * tolerance:g} %")
            if crit(c):
                text += f" ({crit(c)})"
            parts.append(text)
    return "; ".join(parts)
