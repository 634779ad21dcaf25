"""The follower's spring and the camshaft's flywheel, over the rise alone or the whole turn.

Spring (secs 4.5.5 and 7.5).  The follower stays on the cam while the contact force, the
output's inertia force m x'' plus the spring's force F0 + k x, stays positive; where the output
decelerates faster than the spring can pull it back, the follower jumps (sec. 7.5, fig. 7.22).
Sec. 4.5.5 sizes the spring by the largest deceleration.  With a margin mu the spring must meet

    F0 + k x(T) >= (1 + mu) (-m x''(T))   at every T,        x = X h_m', x'' = X'' h_m'/t_m^2

so that for a rate k the least preload is F0_min(k) = max_T [(1 + mu)(-m x'') - k x]: a
piecewise-linear, falling curve whose ends are the least preload at k = 0 (a constant force)
and the least rate without preload.  Any spring on or above the curve holds the follower.
(The contact force is `camdyn profile`'s kinetostatic Q = M omega^2 m'' + k m + Q_0,
runtime/cam/load.py, with m'' the motion's acceleration in the cam angle.)

The motion is taken twice, and the spring must hold both:

* kinetostatic: the rigid follower x = h_m' H of the designed motion (:mod:`.turn`), H'' in
  closed form, as `camdyn profile` checks the cam (the force falling to zero where the follower
  leaves it);
* dynamic: the check run's model (the one-DOF model (3.1) or CAMSHAFT-1 (4.15)) driven by the
  same motion, the rise from rest and the residual vibration it leaves riding into the dwell
  (and with the whole turn into the return and the inner dwell).  One turn from rest is what
  it covers: the vibration left at the turn's end rides into the next rise, and in the
  undamped models each later turn may add up to that vibration's force again (``carried``).

The spring's surge.  A helical spring between its seats has its first surge frequency at
f_s = (1/2) (k/m_s)^(1/2) (m_s the active coils' mass).  That mode is a follower of its own,
driven at one end by the lift: the thesis's one-DOF model (3.1) at tau_s = 1/(f_s t_m) gives
the residual vibration U0(tau_s) it is left with after the rise (ch. 3), beside the harmonic
of the camshaft's speed it sits at.

Flywheel (ch. 5).  The energy the cam gives and takes back over the dynamic run, the output's
kinetic energy, the follower's elastic energy and the spring's,

    E = m x'^2/2 + c_c (h_m' H - x)^2/2 + F0 x + k x^2/2,

swings by dE = max E - min E; a camshaft of polar inertia J at w_s then varies its speed by
the coefficient C_s = (w_max - w_min)/w_s = dE/(J w_s^2).  The J that keeps it within C_s gives
the flywheel factor Fv = m h_m'^2/(J beta_m^2) (5.14b).  The check run leaves the flywheel
effect out (Fv -> oo); its residual vibration bounds the one with the flywheel from above
(sec. 5.7, CAMSHAFT-2), which is not the way to quieten a follower: "cams are no substitutes
for flywheels".

Every extreme is found on a grid of the motion (SAMPLES per unit of T, the run's own points
and the law's segment ends added) and refined by zooming in to XATOL in T, on the
run's dense output or the law's closed form.  Its estimate: for the dynamic figures the run
one notch tighter's difference times check_run.TWIN_FACTOR, plus what the refinement leaves;
for the kinetostatic ones what the refinement leaves.  A figure computed from another carries
that one's error too: the preload's into the contact force, the peak spring force and the
energy swing (|d dE/dF0| <= max x - min x), and the energy swing's into J and Fv.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camdyn.runtime.core.errors import CamdynInputError, SimulationError
from camdyn.runtime.measure.contract import answer
from camdyn.runtime.targets.model_target import ModelTarget

from .check_run import TWIN_FACTOR, stated_errors
from .extremes import XATOL, largest

SAMPLES = 3000
"""Grid points per unit of T on which the extremes are found before they are refined."""


# -- the motion: the run's dense output, or the law's closed form --------------------------------
class RunMotion:
    """x, x', x'' (SI) and H of a run of the check run's model, from its dense output."""

    kind = "dynamic"

    def __init__(self, result, *, stroke, t_m):
        self.result, self.h, self.t_m = result, stroke, t_m
        span = result.t[-1] - result.t[0]
        grid = np.union1d(np.linspace(result.t[0], result.t[-1], int(SAMPLES * span) + 1),
                          result.t)
        self.grids = [grid]
        self._grid = result.sample(grid)

    def at(self, T) -> dict:
        # the grid is read by every figure: sampled once
        s = self._grid if T is self.grids[0] else self.result.sample(T)
        h, t_m = self.h, self.t_m
        return {"x": s["X"] * h, "v": s["Xd"] * h / t_m, "a": s["Xdd"] * h / t_m**2, "H": s["H"]}


class LawMotion:
    """x, x', x'' (SI) and H of the rigid follower through the designed motion (kinetostatic),
    from the law's closed form; one grid per piece between the law's segment ends."""

    kind = "kinetostatic"

    def __init__(self, turn, *, stroke, t_m):
        self.turn, self.h, self.t_m = turn, stroke, t_m
        self.grids = []
        for lo, hi in turn.pieces():
            a, b = lo + XATOL / 10, hi - XATOL / 10
            self.grids.append(np.linspace(a, b, max(3, int(SAMPLES * (b - a)) + 1)))

    def at(self, T) -> dict:
        H = self.turn.motion(T)
        h, t_m = self.h, self.t_m
        return {"x": H[0] * h, "v": H[1] * h / t_m, "a": H[2] * h / t_m**2, "H": H[0]}


# -- the spring's figures of one motion ----------------------------------------------------------
SPRING_KEYS = ("preload", "inertia", "hold", "stroke", "rate")
"""The spring's extremes over one motion, :func:`_spring_extremes`'s keys."""


def _spring_extremes(motion, *, mass, margin, rate, keys=SPRING_KEYS) -> dict:
    """The spring's extremes over one motion (all independent of the preload), those of
    ``keys``:

    preload   max (1 + mu)(-m x'') - k x      (F0_min = max(0, it))
    inertia   max -m x''                       (the largest inertia force off the cam)
    hold      max -(m x'' + k x)               (the least contact force is F0 - it)
    stroke    max x                            (the peak spring force is F0 + k it)
    rate      max (1 + mu)(-m x'')/x where x > 0 and the follower is pulled off
    """
    k = 0.0 if rate is None else rate

    def f(key):
        def g(T):
            s = motion.at(T)
            need = (1.0 + margin) * (-mass * s["a"])
            if key == "preload":
                return need - k * s["x"]
            if key == "inertia":
                return -mass * s["a"]
            if key == "hold":
                return -(mass * s["a"] + k * s["x"])
            if key == "stroke":
                return s["x"]
            with np.errstate(divide="ignore", invalid="ignore"):
                return np.where((need > 0) & (s["x"] > 0), need / np.where(s["x"] > 0, s["x"], 1.0),
                                np.where(need > 0, np.inf, -np.inf))
        return g

    out = {key: largest(f(key), motion.grids) for key in keys}
    return out


def _with_twin(fig_of, base, tight) -> tuple:
    """(figures of the base motion, their errors): for a run, TWIN_FACTOR times the difference
    from the run one notch tighter plus the refinement's; for the law, the refinement's.
    ``fig_of(motion)`` -> {name: Extreme}; errors None where the tighter run is missing."""
    figs = fig_of(base)
    twin = fig_of(tight) if tight is not None else None
    errors = {}
    for key, e in figs.items():
        if base.kind == "kinetostatic":
            ev, eT = e.error, e.T_error
        elif twin is None:
            errors[key] = (None, None)
            continue
        else:
            t = twin[key]
            finite = math.isfinite(e.value) and math.isfinite(t.value)
            ev = ((TWIN_FACTOR * abs(e.value - t.value) + e.error + t.error)
                  if finite else (0.0 if e.value == t.value else math.inf))
            eT = TWIN_FACTOR * abs(e.T - t.T) + e.T_error + t.T_error
        # peaks within the value's error of the largest tie with it: the place is any of them
        errors[key] = (ev, max(eT, e.farthest_tie(2 * ev) if math.isfinite(ev) else eT))
    return figs, errors


def check_margin(margin) -> float:
    """The spring's margin mu as a float in [0, 10], else one line naming the option."""
    try:
        mu = float(margin)
    except (TypeError, ValueError):
        raise CamdynInputError(f"argument --spring-margin: must be a number, got {margin!r}") from None
    if not (math.isfinite(mu) and 0.0 <= mu <= 10.0):
        raise CamdynInputError(f"argument --spring-margin: {mu:g} is out of range: 0 <= margin <= 10 "
                               "(the spring's force over the inertia force, less 1)")
    return mu


@dataclass
class Motions:
    """The motions the spring and the flywheel are read off: the kinetostatic one over the span
    (:class:`LawMotion`), the check run's model over it (:class:`RunMotion`) and its run one
    notch tighter (None: no estimate), what the dynamic run covers, and its warnings."""

    turn: object
    kinetostatic: LawMotion
    dynamic: RunMotion
    tight: RunMotion | None
    covers: str
    warnings: list


def _add(a, b):
    return None if a is None or b is None else a + b


def _place(figure, errors, which, turn, t_m) -> dict:
    """Where an extreme lies, with the errors of T, the cam angle and the time."""
    e, eT = errors
    where = turn.where(figure.T, t_m)
    where["by"] = which
    where["T_error"] = eT
    where["cam_angle_error"] = None if eT is None or turn.beta_m is None else eT * turn.beta_m
    where["time_error"] = None if eT is None or t_m is None else eT * t_m
    return where


def spring(motions: Motions, *, mass, stroke, t_m, margin, rate=None, spring_mass=None,
           speed_rpm=None, law="cycloidal", theta=None, U0_design=None, tau=None,
           arm_length=None) -> dict:
    """The least spring that holds the follower on the cam over the ``motions`` (kinetostatic
    and dynamic) with the margin; with ``spring_mass`` also its surge; with ``arm_length`` (a
    rocker) its preload and rate as a torque and a torsional rate at the pivot too."""
    mu = check_margin(margin)
    turn = motions.turn
    fig = {}
    for which, base, tight in (("kinetostatic", motions.kinetostatic, None),
                               ("dynamic", motions.dynamic, motions.tight)):
        fig[which] = _with_twin(lambda m: _spring_extremes(m, mass=mass, margin=mu, rate=rate),
                                base, tight)
    # the binding motion: the larger least preload (max(a, b) errs by at most the larger error)
    kin, dyn = fig["kinetostatic"][0]["preload"], fig["dynamic"][0]["preload"]
    which = "dynamic" if dyn.value >= kin.value else "kinetostatic"
    figs, errs = fig[which]

    def both(key, pick=max):
        vals = [fig[w][0][key].value for w in fig]
        es = [fig[w][1][key][0] for w in fig]
        return pick(vals), (None if None in es else max(es))

    pre, pre_e = both("preload")
    preload = max(0.0, pre)
    if pre_e is not None and preload <= pre_e:
        # not told from zero: none is needed (at rest, T = 0, the need is exactly 0)
        preload, pre_e = 0.0, pre_e + preload
    inertia, inertia_e = both("inertia")
    hold, hold_e = both("hold")
    x_max, x_max_e = both("stroke")
    k = 0.0 if rate is None else rate
    rate_min, rate_e = both("rate")
    at = _binding_place(fig, which, pre_e)
    out = {"margin": mu, "rate": rate, "covers": motions.covers, **turn.describe(),
           "preload_min": preload, "preload_min_error": pre_e,
           "T_binding": figs["preload"].T, "T_binding_error": at[1],
           "binding": _place(figs["preload"], at, which, turn, t_m),
           "inertia_force_max": inertia, "inertia_force_max_error": inertia_e,
           "peak_spring_force": preload + k * x_max,
           "peak_spring_force_error": _add(pre_e, None if x_max_e is None else k * x_max_e),
           "contact_force_min": preload - hold, "contact_force_min_error": _add(pre_e, hold_e)}
    out.update(_rate_end(fig, rate_min, rate_e, turn, t_m))
    for w in fig:
        f, e = fig[w]
        out[w] = {"preload_min": max(0.0, f["preload"].value),
                  "preload_min_error": e["preload"][0],
                  "binding": _place(f["preload"], e["preload"], w, turn, t_m),
                  "inertia_force_max": f["inertia"].value,
                  "inertia_force_max_error": e["inertia"][0]}
    warnings = list(motions.warnings)
    if turn.whole:
        out["carried"] = _carried(motions, mass=mass, stroke=stroke, t_m=t_m, margin=mu,
                                  rate=k, tau=tau)
        warnings += _carried_warning(out["carried"], mu, inertia)
    if arm_length is not None:
        out["rocker"] = _at_pivot(out, arm_length, mass)
    if spring_mass is not None:
        surge, w = _surge(spring_mass, rate=rate, t_m=t_m, speed_rpm=speed_rpm, law=law,
                          theta=theta, U0_design=U0_design)
        out["surge"] = surge
        warnings += w
    out["warnings"] = warnings
    return out


def _carried_warning(c: dict, mu: float, inertia: float) -> list:
    """The warning where the vibration one turn leaves may add more to the least preload, a
    turn, than the margin leaves over the largest inertia force."""
    if c["force"] is None or c["force"] <= mu * inertia:
        return []
    return [f"follower spring: the vibration one turn leaves (x'' amplitude {c['xdd']:.3g} "
            f"m/s^2 at the turn's end) rides into the next rise and may add up to "
            f"{c['force']:.3g} N a turn to the least preload, more than the margin leaves "
            f"({mu * inertia:.3g} N): a larger margin or a stiffer follower"]


def least_preload(motions: Motions, *, mass, stroke, t_m, margin, rate=None, tau=None) -> dict:
    """The least preload of :func:`spring` alone, for a caller that sizes many springs (every
    law over a speed band): each motion's least preload with its error and binding place, as
    spring() gives them under "kinetostatic" and "dynamic", and over the whole turn the
    vibration one turn leaves ("carried") with its warning ("warnings").  The least rate, the
    peak spring force and the least contact force of spring() are left out: a fifth of its
    extremes, each found and refined as there."""
    mu = check_margin(margin)
    turn = motions.turn
    out, inertia = {}, 0.0
    for which, base, tight in (("kinetostatic", motions.kinetostatic, None),
                               ("dynamic", motions.dynamic, motions.tight)):
        f, e = _with_twin(lambda m: _spring_extremes(m, mass=mass, margin=mu, rate=rate,
                                                     keys=("preload",)), base, tight)
        out[which] = {"preload_min": max(0.0, f["preload"].value),
                      "preload_min_error": e["preload"][0],
                      "binding": _place(f["preload"], e["preload"], which, turn, t_m)}
        if turn.whole:
            inertia = max(inertia, _spring_extremes(base, mass=mass, margin=mu, rate=rate,
                                                    keys=("inertia",))["inertia"].value)
    warnings = list(motions.warnings)
    if turn.whole:
        c = out["carried"] = _carried(motions, mass=mass, stroke=stroke, t_m=t_m, margin=mu,
                                      rate=0.0 if rate is None else rate, tau=tau)
        warnings += _carried_warning(c, mu, inertia)
    out["warnings"] = warnings
    return out


def _binding_place(fig, which, error) -> tuple:
    """(error, T_error) of where the least preload binds: the binding motion's, or where the
    two motions' least preloads lie within the error of each other, either's place."""
    e, eT = fig[which][1]["preload"]
    other = fig["kinetostatic" if which == "dynamic" else "dynamic"]
    a, b = fig[which][0]["preload"], other[0]["preload"]
    if eT is not None and error is not None and abs(a.value - b.value) <= 2 * error:
        eT = max(eT, abs(a.T - b.T) + (other[1]["preload"][1] or 0.0))
    return e, eT


def _rate_end(fig, rate_min, rate_e, turn, t_m) -> dict:
    """The least rate without preload, the family's other end; None where no rate alone holds
    the follower (it is pulled off where x <= 0: on the base circle, vibrating)."""
    if rate_min < math.inf:
        which = max(fig, key=lambda w: fig[w][0]["rate"].value)
        f, e = fig[which]
        if not math.isfinite(rate_e or 0.0):
            rate_e = 0.0 if rate_min == -math.inf else None
        return {"rate_min_without_preload": max(0.0, rate_min),
                "rate_min_without_preload_error": rate_e,
                "T_binding_rate": f["rate"].T, "T_binding_rate_error": e["rate"][1],
                "rate_binding": _place(f["rate"], e["rate"], which, turn, t_m),
                "rate_min_without_preload_reason": None}
    which = "dynamic" if not math.isfinite(fig["dynamic"][0]["rate"].value) else "kinetostatic"
    f, e = fig[which]
    where = turn.where(f["rate"].T, t_m)
    return {"rate_min_without_preload": None, "rate_min_without_preload_error": None,
            "T_binding_rate": f["rate"].T, "T_binding_rate_error": e["rate"][1],
            "rate_binding": _place(f["rate"], e["rate"], which, turn, t_m),
            "rate_min_without_preload_reason": (
                f"no rate alone holds the follower: the {which} motion pulls it off at T = "
                f"{f['rate'].T:.4g} ({where['part']}) where x <= 0, on the base circle, where a "
                "spring without preload pushes with no force; give it a preload")}


def _carried(motions: Motions, *, mass, stroke, t_m, margin, rate, tau) -> dict:
    """The vibration one turn from rest leaves at its end, T = P (the cam at rest in the inner
    dwell): its amplitude U = |(X - H, X'/w)| (w = 2 pi/tau, the follower's own frequency
    with the cam at rest), x'' = h_m' w^2 U/t_m^2, and the force it may add a turn to the
    least preload, (1 + mu) m x'' + k h_m' U; with the run one notch tighter's difference
    (times TWIN_FACTOR) as its error."""
    if tau is None:
        return {"U": None, "U_error": None, "x": None, "x_error": None, "xdd": None,
                "xdd_error": None, "force": None, "force_error": None}
    w = 2 * math.pi / tau

    def amplitude(run):
        if run is None:
            return None
        res = run.result
        s = res.sample(np.array([res.t[-1]]))
        return float(math.hypot(s["X"][0] - s["H"][0], s["Xd"][0] / w))

    U, Ut = amplitude(motions.dynamic), amplitude(motions.tight)
    eU = None if Ut is None else TWIN_FACTOR * abs(U - Ut)
    per_U = (1.0 + margin) * mass * stroke * w**2 / t_m**2 + rate * stroke
    return {"U": U, "U_error": eU, "x": stroke * U, "x_error": None if eU is None else stroke * eU,
            "xdd": stroke * w**2 * U / t_m**2,
            "xdd_error": None if eU is None else stroke * w**2 * eU / t_m**2,
            "force": per_U * U, "force_error": None if eU is None else per_U * eU}


def _at_pivot(sp: dict, l: float, mass: float) -> dict:
    """A rocker's spring at its pivot, as `camdyn profile` takes it: the preload F0 l (N m),
    the rate k l^2 (N m/rad) and the arm's inertia m l^2 (kg m^2) (sec. 2.4, (2.55)-(2.57))."""
    def torque(key, power=1):
        v, e = sp.get(key), sp.get(f"{key}_error")
        return (None if v is None else v * l**power), (None if e is None else e * l**power)
    F, eF = torque("preload_min")
    out = {"arm_length": l, "preload_torque": F, "preload_torque_error": eF,
           "inertia_about_pivot": mass * l**2,
           "contact_torque_min": torque("contact_force_min")[0],
           "contact_torque_min_error": torque("contact_force_min")[1]}
    if sp["rate"] is not None:
        out["rate_torsional"] = sp["rate"] * l**2
    else:
        out["rate_torsional_min_without_preload"], out["rate_torsional_min_without_preload_error"] = \
            torque("rate_min_without_preload", 2)
    return out


def _surge(spring_mass, *, rate, t_m, speed_rpm, law, theta, U0_design) -> tuple[dict, list]:
    """The spring's surge (module doc) and its warnings."""
    if rate is None:
        raise CamdynInputError("argument --spring-mass: the surge frequency needs the spring's "
                               "rate, --spring-rate N/M")
    warnings = []
    f_s = 0.5 * math.sqrt(rate / spring_mass)
    tau_s = 1.0 / (f_s * t_m)
    surge = {"spring_mass": spring_mass, "f_surge": f_s, "tau_surge": tau_s,
             "harmonic": None if speed_rpm is None else f_s / (speed_rpm / 60.0)}
    if tau_s >= 1.0:
        warnings.append(f"spring surge: its period 1/f_s = {1 / f_s:.4g} s is not shorter than "
                        f"the rise t_m = {t_m:.4g} s (tau_s = {tau_s:.3g}): the coils cannot "
                        "follow the lift. Use a stiffer or lighter spring.")
        surge.update(U0=None, U0_error=None)
        return surge, warnings
    try:
        s = answer(ModelTarget.of("one_dof", {"tau": tau_s}, method="dp54", rtol=1e-10,
                                  law=law, theta=theta))
        surge.update(U0=s.figures["U0"], U0_error=stated_errors(s)["U0"])
        warnings += [f"spring surge run: {w}" for w in s.warnings]
    except SimulationError as exc:
        surge.update(U0=None, U0_error=None)
        warnings.append(f"spring surge run failed: {exc}")
    if surge["U0"] is not None and U0_design is not None and surge["U0"] > U0_design:
        warnings.append(f"spring surge: the coils ring after the rise with U0(tau_s = "
                        f"{tau_s:.3g}) = {surge['U0']:.3g}, more than the follower itself "
                        f"({U0_design:.3g}). Use a stiffer or lighter spring.")
    return surge, warnings


# -- the flywheel --------------------------------------------------------------------------------
def check_fluctuation(fluctuation) -> float:
    """The coefficient of speed fluctuation C_s as a float in (0, 1), else one line."""
    try:
        cs = float(fluctuation)
    except (TypeError, ValueError):
        raise CamdynInputError(f"argument --speed-fluctuation: must be a number, got "
                               f"{fluctuation!r}") from None
    if not (math.isfinite(cs) and 0.0 < cs < 1.0):
        raise CamdynInputError(f"argument --speed-fluctuation: {cs:g} is out of range: 0 < C_s < 1 "
                               "((w_max - w_min)/w_s)")
    return cs


def _energy_extremes(motion, *, mass, stroke, stiffness, preload, rate) -> dict:
    """max E and max -E over the motion (module doc's E), and max x, max -x."""
    def E(T):
        s = motion.at(T)
        x = s["x"]
        return (0.5 * mass * s["v"]**2 + 0.5 * stiffness * (s["H"] * stroke - x)**2
                + preload * x + 0.5 * rate * x**2)
    return {"E_max": largest(E, motion.grids), "E_min": largest(lambda T: -E(T), motion.grids),
            "x_max": largest(lambda T: motion.at(T)["x"], motion.grids),
            "x_min": largest(lambda T: -motion.at(T)["x"], motion.grids)}


def flywheel(motions: Motions, *, mass, stroke, t_m, w_s, beta_m, stiffness, fluctuation,
             preload=0.0, preload_error=0.0, rate=0.0) -> dict:
    """The camshaft inertia that keeps its speed within the coefficient ``fluctuation`` over
    the dynamic run of ``motions``, and the flywheel factor Fv (5.14b) it gives; the energy
    swing's error adds what the preload's error moves it by (at most (max x - min x) times)."""
    cs = check_fluctuation(fluctuation)
    figs, errs = _with_twin(lambda m: _energy_extremes(m, mass=mass, stroke=stroke,
                                                       stiffness=stiffness, preload=preload,
                                                       rate=rate),
                            motions.dynamic, motions.tight)
    dE = figs["E_max"].value + figs["E_min"].value
    x_span = figs["x_max"].value + figs["x_min"].value
    e_run = _add(errs["E_max"][0], errs["E_min"][0])
    e_dE = None if e_run is None or preload_error is None else e_run + x_span * preload_error
    J = dE / (cs * w_s**2)
    Fv = mass * stroke**2 / (J * beta_m**2) if J > 0 else math.inf
    rel = None if e_dE is None or dE <= 0 else e_dE / dE
    return {"speed_fluctuation": cs, "energy_swing": dE, "energy_swing_error": e_dE,
            "J": J, "J_error": None if e_dE is None else e_dE / (cs * w_s**2),
            "Fv": Fv, "Fv_error": None if rel is None else (Fv * rel / (1 - rel) if rel < 1
                                                            else math.inf),
            "with_spring": bool(preload or rate), "covers": motions.covers,
            "whole_turn": motions.turn.whole}
