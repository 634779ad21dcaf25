"""The answer over the band: every candidate law through the residual vibration, the peaks, the
spring, the cam's contact and the drive, its checks, a ranking and the recommended law.

For each law (:func:`design_band`):

1. the worst residual vibration over the whole band, U0 (3.5) times the stroke, with the
   ladder's model (ch. 8: the one-DOF model (3.1), or CAMSHAFT-1/-2 with Fa (4.14), Fv (5.52))
   (:mod:`.residual`);
2. the peak acceleration and jerk at the top speed (:mod:`.kinematics`);
3. the spring that holds over the whole turn at the top speed (secs 4.5.5, 7.5) and the speed
   at which the spring as used lets the follower leave the cam (:mod:`.spring`);
4. the cam under the spring's dynamic contact force: pressure angle, least radius of
   curvature, Hertz's contact pressure (:mod:`.contact`);
5. the drive torque and the flywheel (:mod:`.drive`).

A law passes when its pressure angle stays within the limit, its profile has no undercut or
cusp, its Hertz pressure stays within the allowable and its follower stays on the cam over the
band with the spring used.  The ranking puts the laws that pass first, ordered by the worst
residual; residuals equal within their estimates are ordered by the least spring preload,
then by the peak acceleration.  The laws that fail follow, each with its reasons, a law whose
velocity jumps (its acceleration is infinite there) last.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np

from camdyn.runtime.core.errors import CamdynInputError, SimulationError
from camdyn.runtime.measure.contract import plus_minus

from . import units
from .spec import Machine

ALL = "all"
"""The candidate list that means every law of the library and the polydyne (band_api.md)."""

POLYDYNE = "polydyne"


@dataclass
class LawAnswer:
    """One candidate law over the band: the figures of each step (None where its run failed,
    said in ``reasons``), whether it passes every check, why not, and its warnings."""

    law: str
    theta: float | None
    residual: object = None
    peaks: object = None
    spring: object = None
    contact: object = None
    drive: object = None
    passed: bool = False
    reasons: list = field(default_factory=list)
    warnings: list = field(default_factory=list)
    velocity_jumps: bool = False


@dataclass
class BandAnswer:
    """The machine's answer: the ladder's model, every law, the ranking (law, reason) best
    first, the recommended law (None when no law passes every check) and the run's warnings."""

    machine: Machine
    ladder: object
    laws: list
    ranking: list
    recommended: str | None
    warnings: list = field(default_factory=list)

    @property
    def chosen(self) -> LawAnswer:
        """The law the pictures and exports show: the recommended one, or the nearest when
        none passes."""
        return self.law(self.ranking[0][0])

    def law(self, name: str) -> LawAnswer:
        return next(a for a in self.laws if a.law == name)


# -- the candidates ---------------------------------------------------------------------------

def candidates(m: Machine) -> tuple[list, list]:
    """([(law, theta)], warnings): "all" is every law of the library, the polydyne designed at
    the band's centre tau (runtime/studies/polydyne.py; its tau_d must lie in (0, 1))."""
    from camdyn.runtime.core import laws

    names: list = []
    for item in m.laws:
        for name in (laws.NAMES if item == ALL else [item]):
            if name not in names:
                names.append(name)
    out, warnings = [], []
    centre = 0.5 * (m.taus[0] + m.taus[1])
    for name in names:
        if name != POLYDYNE:
            out.append((name, None))
        elif 0.0 < centre < 1.0:
            out.append((name, centre))
        else:
            warnings.append(f"the polydyne is left out: it is designed at the band's centre, "
                            f"tau = {centre:.4g}, and its design tau lies in (0, 1)")
    if not out:
        raise CamdynInputError("no candidate law to answer (the polydyne alone, and the band "
                               "beyond its design range)")
    return out, warnings


def velocity_jumps(law: str, theta) -> bool:
    """Whether the rise's velocity H' jumps at its ends (the uniform law): the acceleration
    there is infinite and no spring holds the follower on the cam (sec. 7.5)."""
    from camdyn.runtime.core import laws

    H = laws.choose(law, theta).evaluate(np.array([0.0, 1e-12, 1.0 - 1e-12]))
    return bool(np.max(np.abs(H[:, 1])) > 1e-6)


# -- one law ------------------------------------------------------------------------------------

def answer_law(m: Machine, law: str, theta, ladder) -> LawAnswer:
    """The five steps of the module doc for one law; a run that fails ends the law's answer
    there, its reason said."""
    from . import contact, drive, kinematics, residual, spring

    a = LawAnswer(law, theta, velocity_jumps=velocity_jumps(law, theta))
    try:
        a.residual = residual.worst_residual(m, law, ladder, theta=theta)
        a.peaks = kinematics.peaks(m, law, m.speeds[1], theta=theta)
        a.spring = spring.spring(m, law, ladder, theta=theta)
        theta_deg, force = contact_load(a.spring)
        a.contact = contact.contact(m, law, theta_deg, force, theta=theta)
        a.drive = drive.drive(m, law, ladder, a.spring.preload_used, theta=theta)
    except SimulationError as exc:
        a.reasons.append(f"its run failed: {exc}")
    for part in (a.residual, a.peaks, a.spring, a.contact, a.drive):
        a.warnings += [w for w in getattr(part, "warnings", ()) or () if w not in a.warnings]
    a.reasons += checks(m, a)
    a.passed = not a.reasons
    return a


def contact_load(sp) -> tuple[np.ndarray, np.ndarray]:
    """The contact force the cam carries: at each cam angle the larger of the lowest and the
    top speed's.  The force is the spring's plus m x'', and x'' grows as w^2 at each angle
    (x'' = h H''/t_m^2, t_m = beta_m/w), so its largest over the band is at one of the ends;
    Hertz's pressure grows with the force, so its largest is under this envelope."""
    lo = np.asarray(sp.contact_force_lo, dtype=float)
    hi = np.asarray(sp.contact_force_hi, dtype=float)
    return np.asarray(sp.theta_deg, dtype=float), np.maximum(lo, hi)


def checks(m: Machine, a: LawAnswer) -> list:
    """The reasons ``a`` fails, [] when it passes every check; each names the figure, its
    estimate and the limit."""
    why = []
    if a.velocity_jumps:
        why.append("its velocity jumps at the ends of the rise and the return: the "
                   "acceleration is infinite there and no spring holds the follower")
    c = a.contact
    if c is not None:
        pa, pa_e = c.pressure_angle_max_deg, _err(c, "pressure_angle_max_deg")
        if pa > m.max_pressure_angle:
            why.append(f"pressure angle {pa:.4g}{plus_minus(pa_e)} deg beyond the limit "
                       f"{m.max_pressure_angle:g} deg")
        if c.undercut:
            why.append(f"the profile is undercut or has a cusp (least radius of curvature "
                       f"{c.rho_min * 1e3:.4g}{plus_minus(_err(c, 'rho_min') * 1e3)} mm)")
        if c.hertz_allowed is not None and c.hertz_stress_max is not None \
                and c.hertz_stress_max > c.hertz_allowed:
            why.append(f"Hertz contact pressure {c.hertz_stress_max / 1e6:.4g}"
                       f"{plus_minus(_err(c, 'hertz_stress_max') / 1e6)} MPa beyond the "
                       f"allowable {c.hertz_allowed / 1e6:.4g} MPa")
    sp = a.spring
    if sp is not None:
        top = m.speeds[1]
        if sp.jump_speed is not None and sp.jump_speed <= top:
            rpm = units.speed_in(sp.jump_speed, m.speed_unit)
            why.append(f"the follower leaves the cam from {rpm:.4g}"
                       f"{plus_minus(units.speed_in(_err(sp, 'jump_speed'), m.speed_unit))} "
                       f"{m.speed_unit} with the spring used (top speed "
                       f"{units.speed_in(top, m.speed_unit):.4g} {m.speed_unit})")
        need = sp.preload_min
        if need is not None and sp.preload_used < need - _err(sp, "preload_min"):
            f, unit = (m.lever, "N m") if m.rocker else (1.0, "N")
            why.append(f"the spring's preload {sp.preload_used * f:.4g} {unit} is below the "
                       f"least that holds with the margin {m.spring_margin:g} at the top speed, "
                       f"{need * f:.4g}{plus_minus(_err(sp, 'preload_min') * f)} {unit}")
    return why


def _err(obj, key: str) -> float:
    """A figure's estimate for a comparison (0 where there is none)."""
    e = _est(obj, key)
    return 0.0 if e is None else e


def _times(e, f):
    """An estimate scaled into other units (None stays None)."""
    return None if e is None else e * f


def _est(obj, key: str) -> float | None:
    """A figure's estimate, None where the figure has none."""
    e = getattr(obj, f"{key}_error", None)
    return float(e) if e is not None and math.isfinite(e) else None


# -- the ranking --------------------------------------------------------------------------------

def _residual_key(a: LawAnswer):
    r = a.residual
    return (math.inf, 0.0) if r is None else (r.value, r.error or 0.0)


def _preload_key(a: LawAnswer):
    sp = a.spring
    if sp is None or sp.preload_min is None:
        return (math.inf, 0.0)
    return (sp.preload_min, _err(sp, "preload_min"))


def _acceleration_key(a: LawAnswer):
    p = a.peaks
    return (math.inf, 0.0) if p is None else (p.acceleration_max, _err(p, "acceleration_max"))


KEYS = (_residual_key, _preload_key, _acceleration_key)
"""The ranking's order: the worst residual, then the least preload, then the peak
acceleration."""


def ordered(items: list, keys=KEYS) -> list:
    """``items`` by the first key's value; those whose values agree within their estimates
    with the first of a run of them (|v - v0| <= e + e0) are a tie, ordered by the next key."""
    if not keys or len(items) < 2:
        return list(items)
    key, rest = keys[0], keys[1:]
    items = sorted(items, key=lambda x: key(x)[0])
    out, group = [], []
    for item in items:
        if group and not _tied(key(group[0]), key(item)):
            out += ordered(group, rest)
            group = []
        group.append(item)
    return out + ordered(group, rest)


def _tied(a, b) -> bool:
    (va, ea), (vb, eb) = a, b
    if math.isinf(va) or math.isinf(vb):
        return va == vb
    return abs(va - vb) <= ea + eb


def rank(answers: list) -> list:
    """[(law, reason)], best first: the laws that pass by :data:`KEYS`, then those that fail,
    a law whose velocity jumps last, then by how many checks fail, each run by the same keys."""
    passing = ordered([a for a in answers if a.passed])
    failing = sorted([a for a in answers if not a.passed],
                     key=lambda a: (a.velocity_jumps, len(a.reasons)))
    grouped = []
    for k in sorted({(a.velocity_jumps, len(a.reasons)) for a in failing}):
        grouped += ordered([a for a in failing if (a.velocity_jumps, len(a.reasons)) == k])
    out = []
    for i, a in enumerate(passing):
        out.append((a.law, "passes every check; " + _why_here(a, passing[i - 1] if i else None)))
    for a in grouped:
        out.append((a.law, "fails: " + "; ".join(a.reasons)))
    return out


def _why_here(a: LawAnswer, before: LawAnswer | None) -> str:
    """The figure that places ``a`` after ``before``."""
    r = a.residual
    text = f"worst residual {r.value * 1e6:.4g}{plus_minus(_times(r.error, 1e6))} um"
    if before is not None and _tied(_residual_key(before), _residual_key(a)):
        if _tied(_preload_key(before), _preload_key(a)):
            p = a.peaks
            text += (f", as {before.law}'s within the estimates, and so are the preloads; "
                     f"peak acceleration {p.acceleration_max:.4g} m/s^2")
        else:
            text += (f", as {before.law}'s within the estimates; spring preload "
                     f"{a.spring.preload_min:.4g} N")
    return text


# -- the machine ----------------------------------------------------------------------------------

def design_band(m: Machine, progress=None) -> BandAnswer:
    """Every candidate law of ``m`` over its band (module doc); ``progress`` gets one line per
    law."""
    from . import residual

    say = progress or (lambda msg: None)
    ladder = residual.ladder(m)
    todo, warnings = candidates(m)
    answers = []
    for i, (law, theta) in enumerate(todo, 1):
        a = answer_law(m, law, theta, ladder)
        answers.append(a)
        say(f"{law} ({i}/{len(todo)}): " + progress_line(m, a))
    if all(a.residual is None for a in answers):
        raise SimulationError("no candidate law could be answered: "
                              + "; ".join(f"{a.law}: {a.reasons[0]}" for a in answers))
    ranking = rank(answers)
    best = answers[[a.law for a in answers].index(ranking[0][0])]
    return BandAnswer(m, ladder, answers, ranking, best.law if best.passed else None,
                      warnings + list(getattr(ladder, "warnings", ()) or ()))


def progress_line(m: Machine, a: LawAnswer) -> str:
    if a.residual is None:
        return a.reasons[0]
    r = a.residual
    return (f"worst residual {r.value * 1e6:.4g} um at "
            f"{units.speed_in(r.speed, m.speed_unit):.4g} {m.speed_unit}, "
            + ("passes every check" if a.passed else f"fails {len(a.reasons)} check"
               + ("s" if len(a.reasons) > 1 else "")))


# -- JSON (SI) ----------------------------------------------------------------------------------

def _number(v):
    """A float for JSON, None for no number (JSON has no NaN or infinity)."""
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


def _figure(d: dict, key: str, value, error) -> None:
    d[key] = _number(value)
    d[f"{key}_error"] = None if d[key] is None else _number(error)


def law_json(m: Machine, a: LawAnswer) -> dict:
    """One law's figures in SI, each number with its ``_error`` beside it."""
    d = {"law": a.law, "passed": a.passed, "reasons": list(a.reasons)}
    if a.theta is not None:
        _figure(d, "law_parameter", a.theta, 0.0)
    r, p, sp, c, dr = a.residual, a.peaks, a.spring, a.contact, a.drive
    if r is not None:
        _figure(d, "residual_max", r.value, r.error)
        if getattr(r, "model", ""):      # the ladder's model, or one above it past tau = 1
            d["residual_model"] = r.model
        _figure(d, "residual_max_speed", r.speed, r.speed_error)
        _figure(d, "residual_max_speed_rpm", units.speed_in(r.speed, "rpm"),
                units.speed_in(r.speed_error, "rpm"))
        _figure(d, "residual_max_tau", r.tau, r.tau * r.speed_error / r.speed)
    if p is not None:
        _figure(d, "acceleration_max", p.acceleration_max, _est(p, "acceleration_max"))
        _figure(d, "jerk_max", p.jerk_max, _est(p, "jerk_max"))
        if not math.isfinite(p.jerk_max):
            d["jerk_max_note"] = "infinite: the law's acceleration jumps"
    if sp is not None:
        _spring_json(m, d, sp)
    if c is not None:
        _figure(d, "pressure_angle_max_deg", c.pressure_angle_max_deg,
                _est(c, "pressure_angle_max_deg"))
        _figure(d, "rho_min", c.rho_min, _est(c, "rho_min"))
        d["undercut"] = bool(c.undercut)
        _figure(d, "hertz_stress_max", c.hertz_stress_max, _est(c, "hertz_stress_max"))
    if dr is not None:
        _figure(d, "torque_max", dr.torque_max, _est(dr, "torque_max"))
        if dr.flywheel_inertia is not None:
            _figure(d, "flywheel_inertia", dr.flywheel_inertia, _est(dr, "flywheel_inertia"))
    d["warnings"] = list(a.warnings)
    return d


def _spring_json(m: Machine, d: dict, sp) -> None:
    _figure(d, "spring_preload_min_kinetostatic", sp.preload_min_kinetostatic,
            _est(sp, "preload_min_kinetostatic"))
    _figure(d, "spring_preload_min", sp.preload_min, _est(sp, "preload_min"))
    _figure(d, "spring_preload_used", sp.preload_used, used_error(m, sp))
    for key in ("binding_part", "binding_angle_deg", "binding_part_kinetostatic",
                "binding_angle_deg_kinetostatic"):
        v = getattr(sp, key, None)
        if isinstance(v, str):
            d[f"spring_{key}"] = v
        elif v is not None:
            _figure(d, f"spring_{key}", v, _est(sp, key))
    if m.rocker:       # a rocker's spring at its pivot: F_0 l, as the designer gives it
        _figure(d, "spring_preload_used_at_pivot", sp.preload_used * m.lever,
                _times(used_error(m, sp), m.lever))
        _figure(d, "spring_preload_min_at_pivot", sp.preload_min * m.lever,
                _times(_est(sp, "preload_min"), m.lever))
    if sp.jump_speed is None:
        d["jump_speed"] = None
        d["jump_speed_note"] = "the follower stays on the cam up to twice the top speed"
    else:
        _figure(d, "jump_speed", sp.jump_speed, _est(sp, "jump_speed"))
        _figure(d, "jump_speed_rpm", units.speed_in(sp.jump_speed, "rpm"),
                _times(_est(sp, "jump_speed"), units.speed_in(1.0, "rpm")))


def used_error(m: Machine, sp) -> float | None:
    """The preload used is the designer's (exact) or the least sized (its estimate)."""
    if m.output_spring_preload is not None:
        return 0.0
    e = _est(sp, "preload_used")
    return e if e is not None else _est(sp, "preload_min")


def machine_json(m: Machine) -> dict:
    d = {k: (list(v) if isinstance(v, tuple) else v) for k, v in dataclasses.asdict(m).items()}
    d.update(output_stroke=m.output_stroke, output_mass=m.output_mass,
             output_stiffness=m.output_stiffness, output_spring_rate=m.output_spring_rate,
             period=m.period, tau_band=list(m.taus),
             speed_band_rpm=[units.speed_in(w, "rpm") for w in m.speeds])
    return d


def ladder_json(ladder) -> dict:
    return {"name": ladder.model, "params": {k: _number(v) for k, v in ladder.params.items()},
            "why": ladder.why}


def as_json(a: BandAnswer) -> dict:
    """The answer in SI (m, rad/s, N, Pa, N m, kg m^2; angles in deg), every figure with its
    ``_error``; "recommended" the best law's name (null when none passes every check)."""
    return {"machine": machine_json(a.machine), "model": ladder_json(a.ladder),
            "laws": [law_json(a.machine, x) for x in a.laws],
            "ranking": [{"law": law, "passed": a.law(law).passed, "reason": why}
                        for law, why in a.ranking],
            "recommended": a.recommended, "warnings": all_warnings(a)}


def all_warnings(a: BandAnswer) -> list:
    """The run's warnings: the machine's, then each law's named by it."""
    return list(a.warnings) + [w if w.startswith(f"{x.law}:") else f"{x.law}: {w}"
                               for x in a.laws for w in x.warnings]


# -- text (mm, um, MPa, rpm, N or N m) ----------------------------------------------------------

def _pm(v, e, scale=1.0, fmt=".4g") -> str:
    """A figure and its estimate: "v ± e", "v (no estimate)" where it has none."""
    if v is None or not math.isfinite(v):
        return "inf" if v is not None else "-"
    return f"{v * scale:{fmt}}" + (" (no estimate)" if e is None else
                                   f" ± {abs(e) * scale:.1g}")


def header(m: Machine) -> list:
    u = m.speed_unit
    lo, hi = (units.speed_in(w, u) for w in m.speeds)
    if m.rocker:
        motion = (f"swing {m.swing:g} deg (arc {m.output_stroke * 1e3:.4g} mm at the roller), "
                  f"pivot {m.pivot_distance * 1e3:g} mm")
        train = (f"J = {m.output_mass * m.lever ** 2:.4g} kg m^2, k_t = "
                 f"{m.output_stiffness * m.lever ** 2:.4g} N m/rad (m = {m.output_mass:.4g} kg, "
                 f"c = {m.output_stiffness:.4g} N/m at the roller)")
    else:
        motion = f"stroke {m.stroke * 1e3:.4g} mm"
        train = f"m = {m.output_mass:.4g} kg, c = {m.output_stiffness:.4g} N/m"
    r, d1, f, d2 = m.angles
    return [f"{m.title}: {m.follower} follower, {motion}, base circle {m.base_radius * 1e3:g} mm",
            f"  rise {r:g}, outer dwell {d1:g}, return {f:g}, inner dwell {d2:g} deg; "
            f"{lo:.4g} to {hi:.4g} {u} (tau {m.taus[0]:.4g} to {m.taus[1]:.4g}, T_e = "
            f"{m.period * 1e3:.4g} ms (4.39))",
            f"  {train}; " + spring_given(m)]


def spring_given(m: Machine) -> str:
    """The spring as the designer gave it: a rocker's at its pivot, and at its roller."""
    if m.rocker:
        rate = (f"spring rate {m.output_spring_rate * m.lever ** 2:.4g} N m/rad at the pivot "
                f"({m.output_spring_rate:.4g} N/m at the roller)")
        preload = (f", preload {m.spring_preload:.4g} N m" if m.spring_preload is not None
                   else ", preload sized")
    else:
        rate = f"spring rate {m.output_spring_rate:.4g} N/m"
        preload = (f", preload {m.spring_preload:.4g} N" if m.spring_preload is not None
                   else ", preload sized")
    return rate + preload + f", margin {m.spring_margin:g}"


COLUMNS = (("law", 24), ("", 6), ("worst residual um", 19), ("at", 16), ("a max m/s^2", 18),
           ("preload N", 17), ("alpha max deg", 16), ("rho min mm", 17), ("Hertz MPa", 17),
           ("torque N m", 16))
"""The table's columns and their widths (a cell is "value ± estimate")."""


def _row(m: Machine, rank_no, a: LawAnswer) -> str:
    r, p, sp, c, dr = a.residual, a.peaks, a.spring, a.contact, a.drive
    u = m.speed_unit
    f = m.lever if m.rocker else 1.0
    cells = [f"{rank_no:>2} {a.law}", "ok" if a.passed else "FAIL",
             _pm(r.value, r.error, 1e6) if r else "-",
             (_pm(units.speed_in(r.speed, u), units.speed_in(r.speed_error, u)) if r else "-"),
             _pm(p.acceleration_max, _est(p, "acceleration_max")) if p else "-",
             _pm(sp.preload_used * f, _times(used_error(m, sp), f)) if sp else "-",
             _pm(c.pressure_angle_max_deg, _est(c, "pressure_angle_max_deg")) if c else "-",
             _pm(c.rho_min, _est(c, "rho_min"), 1e3) if c else "-",
             (_pm(c.hertz_stress_max, _est(c, "hertz_stress_max"), 1e-6)
              if c and c.hertz_stress_max is not None else "-"),
             _pm(dr.torque_max, _est(dr, "torque_max")) if dr else "-"]
    return _cells(cells)


def _cells(cells) -> str:
    """One line of the table: each cell padded to its column, a space at least between."""
    return "".join(f"{x:<{w - 1}} " for x, (_, w) in zip(cells, COLUMNS)).rstrip()


def text(a: BandAnswer, warnings: bool = True) -> str:
    """The designer's table: one row a law, best first, every figure ± its estimate; the
    reasons a law fails, the recommended design's spring and drive, the model and why, and
    (``warnings``) the warnings, which the command line gives on stderr instead."""
    m = a.machine
    L = header(m)
    lad = a.ladder
    params = ", ".join(f"{k} = {v:.4g}" for k, v in lad.params.items())
    L.append(f"model: {lad.model}" + (f" ({params})" if params else "") + f": {lad.why}")
    L.append("")
    cols = [n for n, _ in COLUMNS]
    cols[3] = f"at {m.speed_unit}"
    if m.rocker:
        cols[5] = "preload N m"
    L.append(_cells(["   " + cols[0], *cols[1:]]))
    for i, (law, _) in enumerate(a.ranking, 1):
        L.append(_row(m, i, a.law(law)))
    L.append("(worst residual over the band and the speed it is at; a max at the top speed; "
             "the preload used" + (" at the pivot" if m.rocker else "") + "; ± each estimate)")
    L.append("")
    for law, why in a.ranking:
        if why.startswith("fails"):
            L.append(f"{law} {why}")
    L += recommendation(a)
    said = all_warnings(a) if warnings else []
    if said:
        L.append("")
        L += [f"warning: {w}" for w in said]
    return "\n".join(L)


def recommendation(a: BandAnswer) -> list:
    m = a.machine
    best = a.chosen
    if a.recommended is None:
        L = [f"no candidate passes every check; the nearest is {best.law}"]
    else:
        L = [f"recommended: {best.law}" + (f" (designed for tau = {best.theta:.4g})"
                                           if best.theta is not None else "")
             + f" ({a.ranking[0][1]})"]
    sp, dr = best.spring, best.drive
    if sp is not None:
        L.append("  spring: " + spring_line(m, sp))
    if dr is not None:
        line = f"  drive: peak torque {_pm(dr.torque_max, _est(dr, 'torque_max'))} N m"
        if dr.flywheel_inertia is not None:
            line += (f"; flywheel {_pm(dr.flywheel_inertia, _est(dr, 'flywheel_inertia'))} "
                     f"kg m^2 for a fluctuation {m.speed_fluctuation:g}")
        L.append(line)
    return L


def spring_line(m: Machine, sp) -> str:
    u = m.speed_unit
    f, unit = (m.lever, "N m at the pivot") if m.rocker else (1.0, "N")

    def force(key, value):
        return _pm(value * f, _times(_est(sp, key), f))
    used = _pm(sp.preload_used * f, _times(used_error(m, sp), f))
    text = (f"preload {used} {unit} "
            + ("(sized: the least that holds, dynamic" if m.output_spring_preload is None
               else "(as given; the least that holds, dynamic")
            + f", {force('preload_min', sp.preload_min)}; kinetostatic "
            f"{force('preload_min_kinetostatic', sp.preload_min_kinetostatic)})")
    part, angle = getattr(sp, "binding_part", None), getattr(sp, "binding_angle_deg", None)
    if part is not None:
        text += f", binding in the {part}" + (f" at {angle:.1f} deg" if angle is not None else "")
    if sp.jump_speed is None:
        text += "; the follower stays on the cam up to twice the top speed"
    else:
        jump = _pm(units.speed_in(sp.jump_speed, u),
                   _times(_est(sp, "jump_speed"), units.speed_in(1.0, u)))
        text += f"; the follower leaves the cam from {jump} {u}"
    return text
