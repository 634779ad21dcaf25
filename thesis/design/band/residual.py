"""The worst residual vibration over the speed band, and the least model that gives it.

The follower train is the thesis's one-DOF model (3.1) with tau = T_e/t_m (4.12); tau grows
with the camshaft's speed, so the band [w_lo, w_hi] is a band [tau_lo, tau_hi].  The residual
vibration after the rise, U0 (3.5) in units of the stroke, is u0 = U0 h_m' in metres (about
the static equilibrium).  It oscillates with the speed: for the cycloid on the undamped model

    U0 = tau^3 |sin(pi/tau)| / (pi |1 - tau^2|)                                   (3.5)

whose zeros lie at 1/tau = 2, 3, 4, ...: a period of 1 in x = 1/tau (about tau^2 in tau).
Every law does the same, the residual being the rise's acceleration weighed by a vibration of
the natural period over one unit of T (its spectrum at 2 pi/tau).  So the band is sampled
uniformly in x, PER_PERIOD samples a unit of x, in ONE compiled sweep with its twin one notch
tighter for the error estimates; every local maximum of the samples (the band's ends among
them) is refined by Brent on x with single runs, and so is every gap between samples whose
bound could still exceed the worst found (below); the worst is answered by the answer
contract (runtime/measure/contract.py), and its error covers

* the run: its estimate (the run one notch tighter, and the scan's sampling error);
* Brent: a maximum is flat, so the tolerance XATOL in x costs at most M XATOL^2/2 in the value
  (M bounds |U0''| in x, below); and the runs' own errors may steer the comparisons, which
  costs at most twice their estimate;
* what the samples may have missed: between samples dx apart the curve exceeds the larger
  sample by at most M dx^2/8 (the interpolation bound).  The residual is a spectrum of a rise
  that lasts one unit of T, of bandwidth pi in x, so by Bernstein's inequality |U0''| <= pi^2
  max U0; M takes SAFETY times that (and no less than the samples' own second differences show).
  Every gap whose bound reaches the worst is refined, so nothing left unrefined can beat it
  (unless more than MAX_REFINED gaps qualify: then the excess is added to the error).

The least model (ch. 8).  Without camshaft data the one-DOF model (3.1) with the train's
damping ratio (q, (6.47)).  With camshaft data the shaft's numbers follow (4.1)-(4.14) and
(5.51)-(5.52) (:func:`shaft`); then CAMSHAFT-1 (4.15) against Fa = 0 decides as the check run
does (thesis/design/check_run.py least_model: the one-DOF model where Fa changes the worst U0
over the band by less than its tolerance), and CAMSHAFT-2 comes in only where the cam's inertia
gives a finite Fv that changes it by more than that (sec. 8.2.5: 'due to the high Fv-numbers'
CAMSHAFT-1 hardly differs from CAMSHAFT-2).  The comparisons use the cycloid, the law of the
design graphs (fig. 4.11).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from camdyn.runtime.cam import reduction as red
from camdyn.runtime.core.errors import CamdynInputError, SimulationError
from camdyn.runtime.measure.contract import answer, unavailable
from camdyn.runtime.targets.model_target import ModelTarget

from ..check_run import ONE_DOF_TOLERANCE, least_model
from .spec import Machine

METHOD, RTOL, ATOL = "dop853", 1e-10, 1e-11
"""The runs' method and tolerances (ATOL in strokes): U0 at a maximum to about 5e-7 of itself
(against (3.5)), its estimate from the run at rtol/100 and atol/100; a sweep of 70 points of
the one-DOF model in about 10 ms.  The absolute tolerance keeps the laws that leave the dwell
as T^5 (5-6-7-8-9, the polydyne) from taking 20 000 steps at the tighter run's rtol 1e-12
with the default atol (1e-3 rtol), where the step control meets the rounding."""

PER_PERIOD = 8
"""Samples a unit of x = 1/tau, U0's period near its zeros ((3.5): |sin(pi x)|), that is a
spacing of tau^2/8 in tau: every hump of the curve has about eight samples, and the gap bound
M dx^2/8 is then about 2 % of the curve's largest value."""

MIN_SAMPLES = 17
"""The fewest samples of a band (a band short in x still shows its shape)."""

XATOL = 2e-5
"""Brent's tolerance in x = 1/tau: at a maximum it costs at most M XATOL^2/2, some 4e-9 of the
value."""

SAFETY = 2.0
"""The margin of M over Bernstein's pi^2 max U0 (the slow growth of the envelope, (3.5)'s
tau^3, and the models whose natural frequency varies over the rise)."""

MAX_REFINED = 24
"""The most brackets refined by Brent in one band; a gap beyond them that could still hold the
worst adds its bound's excess to the error."""

LADDER_LAW = "cycloidal"
"""The law the ladder compares the models with: the design graphs' (fig. 4.11)."""

ONE_DOF_TAU = 1.0
"""The one-DOF model's tau is below this (its manifest); CAMSHAFT-1 at Fa = 0 is the same
model (sec. 4.2) and takes tau to 10."""

FV_INFINITE = 1e6
"""CAMSHAFT-2's largest Fv: beyond it the cam's inertia is negligible against the follower's
(Fv -> oo, where CAMSHAFT-2 is CAMSHAFT-1, sec. 8.2.5)."""


# -- the shaft's numbers (4.1)-(4.14), (5.51)-(5.52) ------------------------------------------

def pitch_radius(m: Machine) -> float:
    """R_1/2 (4.1): the roller centre's distance from the cam centre in mid-rise.

    A translating roller's r_b + r_r + h/2 (with an offset e, its distance from the centre,
    (e^2 + ((r_b + r_r)^2 - e^2)^(1/2) + h/2)^2)^(1/2)); a rocker's from the triangle cam
    centre, pivot, roller centre (pivot distance a, arm l) at half its swing Phi/2 past the
    angle psi_0 where the roller sits on the base pitch circle; a flat face's r_b + h/2 (its
    contact force has no tangential part, so R_1/2 drops out of Fa)."""
    r0 = m.base_radius + (m.roller_radius or 0.0)
    h = m.output_stroke
    if m.follower == "translating-roller":
        e = m.offset
        return math.hypot(e, math.sqrt(r0**2 - e**2) + h / 2)
    if m.follower == "oscillating-roller":
        a, arm = m.pivot_distance, m.arm_length
        psi0 = math.acos((a**2 + arm**2 - r0**2) / (2 * a * arm))
        psi = psi0 + math.radians(m.swing) / 2
        return math.sqrt(a**2 + arm**2 - 2 * a * arm * math.cos(psi))
    return m.base_radius + h / 2


def shaft(m: Machine) -> dict | None:
    """The camshaft's numbers at the output, None without camshaft data.

    h_1 = h_m'/beta_m is the output's mean slope (m/rad).  A roller's contact force has a
    tangential part: tan alpha_me = h_1/R_1/2 (4.13) of it bends the shaft sideways, and
    1/c_tan = R_1/2^2/k + 1/c_y (4.4) (k the shaft's torsional stiffness, c_y its bending
    stiffness at the cam) gives Fa = (c_c/c_tan) tan^2 alpha_me (4.14).  A flat face pushes
    along its normal only, which bends the shaft along the follower's own line (a part of c_c,
    (4.3)); it winds the shaft alone, Fa = c_c h_1^2/k.  (Both are the compliance the
    follower sees, C = h_1^2/k + i_y^2/c_y with i_y = tan alpha_me or 0, times c_c.)  The
    cam's inertia J: m_tan = (J/R_1/2^2)(c_tan/c_beta)^2, c_beta = k/R_1/2^2 (5.51), and
    Fv = (m/m_tan) tan^2 alpha_me (5.52), = m/M with M = J h_1^2/(k^2 C^2).  Without J (or
    with a rigid torsion, which J cannot wind) the cam's inertia is left out: Fv -> oo, the
    limit in which CAMSHAFT-2 is CAMSHAFT-1 (sec. 8.2.5).  A term whose stiffness is not given
    is rigid."""
    if not m.has_camshaft:
        return None
    k, c_y, J = (m.camshaft_torsional_stiffness, m.camshaft_bending_stiffness,
                 m.camshaft_inertia)
    h_1 = m.output_stroke / m.rise_angle
    R = pitch_radius(m)
    tan_me = red.mean_slope(m.output_stroke, R, m.rise_angle) if m.roller else 0.0
    torsion = 0.0 if k is None else h_1**2 / k
    bending = 0.0 if c_y is None else tan_me**2 / c_y
    C = torsion + bending
    c_c, mass = m.output_stiffness, m.output_mass
    Fa = c_c * C
    if J is None or k is None or C == 0.0:
        Fv, M = math.inf, 0.0
    else:
        M = J * h_1**2 / (k**2 * C**2)
        Fv = mass / M
    c_tan = (tan_me**2 / C if C > 0 else math.inf) if m.roller else None
    return {"h_1": h_1, "pitch_radius": R, "tan_alpha_me": tan_me if m.roller else None,
            "c_tan": c_tan, "compliance": C, "Fa": Fa, "m_tan": M * tan_me**2 if m.roller
            else None, "Fv": Fv,
            "formulas": {"pitch_radius": "R_1/2 (4.1)",
                         "tan_alpha_me": "h_m'/(R_1/2 beta_m) (4.13)",
                         "c_tan": "1/(R_1/2^2/k + 1/c_y) (4.4)",
                         "Fa": ("(c_c/c_tan) tan^2 alpha_me (4.14)" if m.roller
                                else "c_c h_m'^2/(k beta_m^2) (4.14), (5.12b)"),
                         "Fv": "(m/m_tan) tan^2 alpha_me (5.51), (5.52)"}}


# -- the ladder of models (ch. 8) -------------------------------------------------------------

@dataclass(frozen=True)
class Ladder:
    """The least model that gives the machine's residual vibration (ch. 8).

    model      "one_dof" | "camshaft1" | "camshaft2"
    params     what the model takes besides tau: q for one_dof, Fa for camshaft1, Fa and Fv
               for camshaft2
    why        the rule of ch. 8 that chose it, citing the section
    warnings   what the choice leaves out (the damping, in the undamped CAMSHAFT models)
    shaft      the camshaft's numbers (:func:`shaft`), empty without camshaft data
    """

    model: str
    params: dict
    why: str
    warnings: tuple = ()
    shaft: dict = field(default_factory=dict)


def ladder(m: Machine) -> Ladder:
    """The least model of ``m`` over its band (module doc)."""
    tau_hi = m.taus[1]
    if tau_hi > 10.0:
        raise CamdynInputError(
            f"the band's top speed gives tau = T_e/t_m = {tau_hi:.3g} (4.12), beyond the "
            "models' 10: the follower's natural period outlasts ten rise times; stiffen the "
            "train, lighten it, or lower the top speed")
    numbers = shaft(m)
    if numbers is None:
        return _one_dof(m, "no camshaft data: a rigid shaft, constant angular velocity, the "
                           "one-DOF model (3.1) (ch. 3)", {})
    if numbers["Fa"] > 100.0:
        raise CamdynInputError(
            f"the camshaft gives Fa = {numbers['Fa']:.3g} (4.14), beyond the models' 100: the "
            "shaft is far too soft for the follower (camshaft.torsional_stiffness, "
            "camshaft.bending_stiffness); stiffen it or enlarge the base circle")
    Fa, Fv = numbers["Fa"], numbers["Fv"]
    if Fa == 0.0:
        return _one_dof(m, "the camshaft data give Fa = 0 (a flat face on a shaft rigid in "
                           "torsion): a rigid shaft for the follower, the one-DOF model (3.1) "
                           "(ch. 3)", numbers)
    taus = m.taus
    w_Fa = _ladder_worst("camshaft1", {"Fa": Fa}, taus)
    w_0 = _ladder_worst("camshaft1", {"Fa": 0.0}, taus)
    model, why = least_model(w_Fa, w_0, Fa)
    why = why.replace("U0 envelope", "worst U0 over the band")
    if math.isfinite(Fv) and Fv <= FV_INFINITE:
        w_Fv = _ladder_worst("camshaft2", {"Fa": Fa, "Fv": Fv}, taus)
        change = abs(w_Fv / w_Fa - 1.0)
        if change >= ONE_DOF_TOLERANCE:
            return _undamped(m, "camshaft2", {"Fa": Fa, "Fv": Fv},
                             f"Fv = {Fv:.3g} (5.52) changes the worst U0 over the band by "
                             f"{100 * change:.3g} % against CAMSHAFT-1 (Fv -> oo): the cam's "
                             "speed varies, CAMSHAFT-2 (5.15), (5.16) is needed (sec. 8.2.5)",
                             numbers)
        why += (f"; Fv = {Fv:.3g} (5.52) changes it by {100 * change:.2g} % (< "
                f"{100 * ONE_DOF_TOLERANCE:g} %): the flywheel effect is left out (sec. 8.2.5)")
    elif math.isfinite(Fv):
        why += (f"; Fv = {Fv:.3g} (5.52): the cam's inertia is negligible (Fv -> oo, "
                "sec. 8.2.5)")
    else:
        why += ("; no cam inertia (or a rigid torsion) given: it is left out, Fv -> oo "
                "(sec. 8.2.5)")
    if model == "one-dof":
        return _one_dof(m, why, numbers)
    return _undamped(m, "camshaft1", {"Fa": Fa}, why, numbers)


def _one_dof(m: Machine, why: str, numbers) -> Ladder:
    """The one-DOF model with the train's damping, or CAMSHAFT-1 at Fa = 0 (the same model,
    sec. 4.2) where the band reaches tau >= 1, which the one-DOF model does not take."""
    numbers = numbers or {}
    if m.taus[1] < ONE_DOF_TAU:
        return Ladder("one_dof", {"q": float(m.damping_ratio)}, why, (), numbers)
    why += (f"; the band reaches tau = {m.taus[1]:.3g} >= 1, which the one-DOF model does not "
            "take: CAMSHAFT-1 at Fa = 0, the same model (sec. 4.2), up to tau = 10")
    return _undamped(m, "camshaft1", {"Fa": 0.0}, why, numbers)


def _undamped(m: Machine, model: str, params: dict, why: str, numbers) -> Ladder:
    warnings = ()
    if m.damping_ratio > 0:
        warnings = (f"the train's damping ratio {m.damping_ratio:g} is left out: {model} is "
                    "undamped, and leaving damping out raised the residual by a factor 1.5 "
                    "to 1.6 in sec. 8.2.2: on the safe side",)
    return Ladder(model, dict(params), why, warnings, dict(numbers or {}))


def _ladder_worst(model: str, params: dict, taus) -> float:
    """The worst U0 of the ladder's law over ``taus`` (refined, without error estimates)."""
    target = ModelTarget.of(model, params, method=METHOD, rtol=RTOL, atol=ATOL, law=LADDER_LAW)
    band = _Band(target, taus, sigma=math.pi)
    band.scan(estimate=False)
    return band.search().value


# -- the law's shape parameter ----------------------------------------------------------------

def theta_of(m: Machine, law: str, theta=None):
    """The shape parameter ``law`` runs with: ``theta`` as given, or for the polydyne its
    design tau at the band's centre speed (runtime/studies/polydyne.py: the one-DOF output
    follows the degree-9 rise exactly there)."""
    if law != "polydyne" or theta is not None:
        return theta
    lo, hi = m.speeds
    tau_c = m.tau(0.5 * (lo + hi))
    if not 0.0 < tau_c < 1.0:
        raise CamdynInputError(
            f"polydyne: the band's centre speed gives tau = {tau_c:.3g}, and a polydyne is "
            "designed for 0 < tau_d < 1 (the rise longer than the natural period); choose "
            "another law, or a stiffer or lighter train")
    return tau_c


# -- the worst residual -----------------------------------------------------------------------

@dataclass(frozen=True)
class WorstResidual:
    """The largest residual amplitude u0 = U0 h_m' over the band (module doc).

    value, error          m; the error covers the run, Brent's tolerance and the samples' gaps
    speed, speed_error    rad/s where it occurs, and how well that is placed
    tau                   there
    curve_*               the curve for the chart, speed ascending: the sweep's samples and the
                          refined maxima, each with its error (m)
    warnings              the runs' and the ladder's
    model                 the model that gave it (the Ladder's)
    error_parts           m: "run", "brent", "gaps"
    samples, refined      the sweep's points and the brackets Brent refined
    """

    law: str
    value: float
    error: float | None
    speed: float
    speed_error: float
    tau: float
    curve_speeds: np.ndarray
    curve_values: np.ndarray
    curve_errors: np.ndarray
    warnings: tuple
    model: str = ""
    error_parts: dict = field(default_factory=dict)
    samples: int = 0
    refined: int = 0


def worst_residual(m: Machine, law: str, ladder: Ladder, theta=None) -> WorstResidual:
    """The worst residual of ``law`` over ``m``'s band on ``ladder``'s model (module doc)."""
    theta = theta_of(m, law, theta)
    target = ModelTarget.of(ladder.model, ladder.params, method=METHOD, rtol=RTOL, atol=ATOL,
                            law=law, theta=theta)
    q = float(ladder.params.get("q", 0.0))
    band = _Band(target, m.taus, sigma=math.pi * (1.0 + 2.0 * q))
    band.scan(estimate=True)
    found = band.search()
    best = band.answer_at(found)
    h = m.output_stroke
    to_speed = m.rise_angle / m.period
    taus, values, errors = band.curve(best)
    error = None if best.error is None else best.error * h
    parts = {k: (None if v is None else v * h) for k, v in best.parts.items()}
    return WorstResidual(
        law=law, value=best.value * h, error=error, speed=to_speed / best.x,
        speed_error=to_speed * best.place_error / best.x**2, tau=1.0 / best.x,
        curve_speeds=taus * to_speed, curve_values=values * h,
        curve_errors=errors * h, warnings=tuple(dict.fromkeys([*ladder.warnings,
                                                               *band.warnings,
                                                               *best.warnings])),
        model=ladder.model, error_parts=parts, samples=len(band.x), refined=band.refined)


@dataclass
class _Peak:
    """A refined maximum: x = 1/tau, U0 there, its bracket's curvature estimate."""

    x: float
    value: float
    lo: float
    hi: float
    curvature: float
    at_end: bool = False
    error: float | None = None
    parts: dict = field(default_factory=dict)
    place_error: float = 0.0
    warnings: tuple = ()


class _Band:
    """The band in x = 1/tau: the sweep, the search for the worst, its answer."""

    def __init__(self, target: ModelTarget, taus, sigma: float):
        tau_lo, tau_hi = taus
        self.sigma = sigma
        x_lo, x_hi = 1.0 / tau_hi, 1.0 / tau_lo
        n = max(MIN_SAMPLES, math.ceil((x_hi - x_lo) * PER_PERIOD) + 1) if x_hi > x_lo else 1
        self.x = np.linspace(x_lo, x_hi, n)
        self.target = target
        self.refined = 0
        self.warnings: list = []
        self.extra: list = []            # (x, U0, error) of refined maxima, for the curve

    # -- the sweep ---------------------------------------------------------------------------
    def scan(self, estimate: bool) -> None:
        """U0 at every sample in one compiled sweep (and its twin one notch tighter)."""
        points = (1.0 / self.x)[:, None]
        self.target = self.target.fit_points(("tau",), points)   # the dwell every point needs
        k = self.target.figure_names().index("U0")
        base = self.target.residual_points(("tau",), points)
        self.f = base.figures[:, k].copy()
        self.e = np.zeros_like(self.f) if not estimate else np.full_like(self.f, np.nan)
        if estimate:
            tight, why = self._tighter_sweep(points)
            if tight is not None:
                factor = self.target.method().estimate_factor
                self.e = np.abs(self.f - tight.figures[:, k]) * factor + base.sampling[:, k]
            else:
                self.warnings.append(unavailable(why))
        self.warnings += [w for ws in base.warnings for w in ws]

    def _tighter_sweep(self, points):
        tighter = self.target.tighter()
        if tighter is None:
            return None, f"rtol={RTOL:g} has no tighter notch"
        try:
            return tighter.residual_points(("tau",), points), None
        except (SimulationError, CamdynInputError) as exc:
            return None, f"the sweep one notch tighter failed ({exc})"

    def single(self, x: float) -> float:
        """U0 of one run at tau = 1/x (the single run's scan, bit for bit)."""
        b = self.target.residual_points(("tau",), np.array([[1.0 / x]]), reference=True)
        return float(b.figures[0, self.target.figure_names().index("U0")])

    # -- the search --------------------------------------------------------------------------
    @property
    def bound_M(self) -> float:
        """M >= |U0''| in x: SAFETY sigma^2 max U0 (Bernstein), no less than the samples'
        own second differences show away from the curve's zeros (where U0 = |g| of a smooth
        g has a corner that bounds nothing: a maximum does not lie there)."""
        M = SAFETY * self.sigma**2 * float(np.max(self.f))
        if len(self.x) >= 3:
            dx = self.x[1] - self.x[0]
            f = self.f
            d2 = np.abs(np.diff(f, 2))                  # centred at samples 1 .. n-2
            low = np.zeros(len(f), dtype=bool)
            low[1:-1] = (f[1:-1] <= f[:-2]) & (f[1:-1] <= f[2:])
            near = low.copy()
            near[1:] |= low[:-1]
            near[:-1] |= low[1:]
            smooth = ~near[1:-1]
            if smooth.any():
                M = max(M, float(np.max(d2[smooth])) / dx**2)
        return M

    def search(self) -> _Peak:
        """The worst U0 over the band: the samples' local maxima (the ends among them) refined
        by Brent, then every gap whose bound could still beat the worst."""
        x, f = self.x, self.f
        e = np.nan_to_num(self.e, nan=0.0)
        if len(x) == 1:
            return _Peak(float(x[0]), float(f[0]), float(x[0]), float(x[0]), 0.0, True)
        dx = x[1] - x[0]
        M = self.bound_M
        gap = M * dx**2 / 8.0
        # a gap's bound: its larger sample, its error, and what the curve may do between
        bounds = np.maximum(f[:-1], f[1:]) + np.maximum(e[:-1], e[1:]) + gap
        k = int(np.argmax(f))
        best = _Peak(float(x[k]), float(f[k]), float(x[k]), float(x[k]), 0.0,
                     at_end=k in (0, len(x) - 1))
        done = np.zeros(len(x) - 1, dtype=bool)
        # the samples' local maxima first (largest first): bracket [x_{i-1}, x_{i+1}]
        interior = np.flatnonzero((f[1:-1] >= f[:-2]) & (f[1:-1] >= f[2:])) + 1
        order = sorted(interior, key=lambda i: -f[i])
        for i in order:
            if max(bounds[i - 1], bounds[i]) < best.value - e[k]:
                continue
            best = self._refine(i - 1, i + 1, best, done, M)
        # then every gap not yet bracketed whose bound reaches the worst
        while True:
            open_ = np.flatnonzero(~done & (bounds >= best.value - e[k]))
            if not open_.size or self.refined >= MAX_REFINED:
                break
            j = int(open_[np.argmax(bounds[open_])])
            best = self._refine(j, j + 1, best, done, M)
        left = np.flatnonzero(~done & (bounds > best.value))
        best.parts = {"gaps": float(max(0.0, bounds[left].max() - best.value)) if left.size
                      else 0.0}
        return best

    def _refine(self, i: int, j: int, best: _Peak, done, M: float) -> _Peak:
        """Brent on [x_i, x_j]; the better of its maximum and the best so far."""
        x, f = self.x, self.f
        done[i:j] = True
        self.refined += 1
        xs, v = maximize(self.single, float(x[i]), float(x[j]), XATOL)
        curvature = self._curvature(i, j)
        self.extra.append((xs, v))
        # a sample that ends the band may beat an inner point Brent never reaches exactly
        for s in (i, j):
            if f[s] > v:
                xs, v = float(x[s]), float(f[s])
        if v > best.value:
            end = xs in (float(x[0]), float(x[-1]))
            return _Peak(xs, v, float(x[i]), float(x[j]), curvature, at_end=end)
        return best

    def _curvature(self, i: int, j: int) -> float:
        """|U0''| near the bracket from its samples' second difference (the place's error)."""
        x, f = self.x, self.f
        c = min(max(i + (j - i) // 2, 1), len(x) - 2)
        dx = x[1] - x[0]
        return abs(f[c - 1] - 2 * f[c] + f[c + 1]) / dx**2

    # -- the answer --------------------------------------------------------------------------
    def answer_at(self, peak: _Peak) -> _Peak:
        """The worst through the answer contract: its value, its error (the run's, Brent's, the
        gaps'), where it is and how well that is placed."""
        a = answer(self.target.with_parameters({"tau": 1.0 / peak.x}))
        peak.value = float(a.figures["U0"])
        e_run = a.errors.get("U0")
        peak.warnings = tuple(w for w in a.warnings if _about_U0(w))
        M = self.bound_M if len(self.x) > 1 else 0.0
        if e_run is None:
            peak.error = None
            peak.parts = {"run": None, "brent": None, "gaps": peak.parts.get("gaps", 0.0)}
        else:
            brent = M * XATOL**2 / 2 + 2 * e_run
            peak.parts = {"run": e_run, "brent": brent, "gaps": peak.parts.get("gaps", 0.0)}
            peak.error = e_run + brent + peak.parts["gaps"]
        peak.place_error = self._place_error(peak)
        self._near_ties(peak)
        return peak

    def _place_error(self, peak: _Peak) -> float:
        """How far in x the worst may lie from where it was found: Brent's tolerance and the
        width over which a maximum of curvature c stays within its error, sqrt(2 e/c); at a
        band's end with a clear slope, nothing."""
        if len(self.x) == 1:
            return 0.0
        dx = self.x[1] - self.x[0]
        e = peak.error or 0.0
        if peak.at_end:
            k = 0 if peak.x == self.x[0] else len(self.x) - 1
            slope = abs(self.f[k] - self.f[1 if k == 0 else k - 1]) / dx
            return 0.0 if slope * dx > 2 * e else dx
        if peak.curvature <= 0:
            return dx
        return min(dx, XATOL + math.sqrt(2 * e / peak.curvature))

    def _near_ties(self, peak: _Peak) -> None:
        """A warning where another maximum, elsewhere in the band, is as large within the
        error: the worst speed is then either."""
        if peak.error is None:
            return
        dx = self.x[1] - self.x[0] if len(self.x) > 1 else 0.0
        for xs, v in self.extra:
            if abs(xs - peak.x) > 2 * dx and v >= peak.value - 2 * peak.error:
                self.warnings.append(
                    f"the residual is as large, within its error, at tau = {1 / xs:.5g} as at "
                    f"tau = {1 / peak.x:.5g}: the worst speed may be either")
                return

    def curve(self, best: _Peak) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(tau ascending, U0, error) of the samples and the refined maxima, for the chart:
        the worst with its answered error, another refined maximum with the largest error of
        the samples beside it (the same method and tolerance)."""
        xs, fs, es = list(self.x), list(self.f), list(self.e)
        dx = self.x[1] - self.x[0] if len(self.x) > 1 else 0.0
        for x, v in self.extra:
            if x == best.x:
                continue
            near = np.abs(self.x - x) <= dx
            xs.append(x)
            fs.append(v)
            es.append(float(np.max(self.e[near])) if near.any() else math.nan)
        e_best = math.nan if best.error is None else best.error
        if best.x in xs:
            k = xs.index(best.x)
            fs[k], es[k] = best.value, e_best
        else:
            xs.append(best.x)
            fs.append(best.value)
            es.append(e_best)
        order = np.argsort(xs)[::-1]              # x descending: tau (speed) ascending
        return (1.0 / np.asarray(xs)[order], np.asarray(fs)[order], np.asarray(es)[order])


OTHER_FIGURES = ("U0dd", "Xdd_min_rise", "T_at_Xdd_min", "Bdot_dev_max", "windup_max")
"""The run's figures other than U0, whose own warnings (an estimate that does not resolve
them) say nothing of U0."""


def _about_U0(warning: str) -> bool:
    """Whether a warning of the answered run concerns U0 (or the run as a whole)."""
    return not any(warning.startswith((f"{f} = ", f"no error estimate for {f}"))
                   for f in OTHER_FIGURES)


# -- Brent's method on a bounded interval -----------------------------------------------------

GOLDEN = 0.5 * (3.0 - math.sqrt(5.0))


def maximize(fn, a: float, b: float, xatol: float) -> tuple[float, float]:
    """(x, fn(x)) at the largest value of ``fn`` on [a, b] by Brent's method (golden section
    and parabolic steps, R. P. Brent, Algorithms for Minimization without Derivatives, 1973,
    ch. 5; SciPy's fminbound): the point lies within ``xatol`` of a local maximum."""
    if not b > a:
        return a, fn(a)
    x = w = v = a + GOLDEN * (b - a)
    fx = fw = fv = -fn(x)
    d = e = 0.0
    while True:
        mid = 0.5 * (a + b)
        tol1 = xatol / 3.0 + 1e-12 * abs(x)
        tol2 = 2.0 * tol1
        if abs(x - mid) <= tol2 - 0.5 * (b - a):
            return x, -fx
        parabolic = False
        if abs(e) > tol1:
            r = (x - w) * (fx - fv)
            q = (x - v) * (fx - fw)
            p = (x - v) * q - (x - w) * r
            q = 2.0 * (q - r)
            if q > 0.0:
                p = -p
            q = abs(q)
            if abs(p) < abs(0.5 * q * e) and q * (a - x) < p < q * (b - x):
                e, d = d, p / q
                u = x + d
                if (u - a) < tol2 or (b - u) < tol2:
                    d = tol1 if mid >= x else -tol1
                parabolic = True
        if not parabolic:
            e = (b - x) if x < mid else (a - x)
            d = GOLDEN * e
        u = x + (d if abs(d) >= tol1 else (tol1 if d > 0 else -tol1))
        fu = -fn(u)
        if fu <= fx:
            if u >= x:
                a = x
            else:
                b = x
            v, fv, w, fw, x, fx = w, fw, x, fx, u, fu
        else:
            if u < x:
                a = u
            else:
                b = u
            if fu <= fw or w == x:
                v, fv, w, fw = w, fw, u, fu
            elif fu <= fv or v == x or v == w:
                v, fv = u, fu
