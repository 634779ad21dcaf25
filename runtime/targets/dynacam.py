"""Running a DYNACAM scene: consistent initial state, one compiled run, the thesis's figures.

The run starts at rest relative to the nominal motion, in the dwell before the rise
(T = run.T_start < 0): the cam turns at w_s, every other velocity is zero and the
positions are the static equilibrium under the spring preload, the external force and
friction, with every element in its initial mode.  This is what the consistent initial
conditions (6.49)-(6.68) of the thesis give; here they are found numerically from the
generated right-hand side (all accelerations and first-order rates zero), so they hold
for any option set.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from ..engine import driver
from ..core.errors import CamdynInputError, SimulationError
from ..measure.extremes import extreme, place_error
from .scene_files import DynacamScene
from ..core.methods import METHODS
from ..core.simulator import Simulator

# summary keys, in the order printed
KEYS = ("variant", "tau", "Fa", "Fv", "Xdd_min_rise", "T_at_Xdd_min", "Xdd_max_rise", "U0dd", "U0",
        "U_static",
        "jump", "speed_variation_max", "motor_speed_variation_max", "n_events", "cpu_seconds")


def characteristics(opts, p: dict) -> dict:
    """tau, Fa, Fv of the scene's parameters, as App. 7 forms them.

    c_c = 1/(1/c_x + 1/c_z) (4.3); m = m_x + m_z (c_c/c_z)^2 (4.39), (5.50);
    tan alpha_me = h_m/(R_1/2 beta_m) (4.13) with R_1/2 = R_b + h_m/2 for radial cams (4.1),
    R_b for axial ones; the shaft's tangential stiffness at R_1/2, 1/c_tan = R_1/2^2/k + 1/c_y
    (4.4); Fa = (c_c/c_tan) tan^2 alpha_me (4.14); m_tan = (J/R_1/2^2)(c_tan/c_beta)^2 +
    m_y (c_tan/c_y)^2 (5.51); Fv = (m/m_tan) tan^2 alpha_me (5.52); tau = T_e/t_m with
    T_e = 2 pi (m/c_c)^(1/2) and t_m = beta_m/w_s.

    A flat face or a rocker takes the same to the contact (:func:`contact_form`).  ``k_tan``
    and ``J_tan`` are the torsion and inertia that alone give the shaft's compliance and mass
    seen by the follower (a shaft rigid sideways, sec. 5.6).
    """
    try:
        out = _characteristics(opts, p)
    except (OverflowError, ZeroDivisionError):
        out = {}
    if not out or not (all(math.isfinite(v) for v in out.values())
                       and all(out[k] > 0 for k in ("tau", "Fa", "Fv", "c_c", "m", "t_m"))):
        used = ["c_x", "m_x", "h_m", "R_b", "beta_m", "omega_s", "k", "J"]
        used += ["c_z", "m_z"] if opts.shaft_z else []
        used += ["c_y", "m_y"] if opts.shaft_y else []
        raise CamdynInputError(
            "the scene's parameters give no finite, positive tau, Fa and Fv ((4.3)-(5.52)): "
            + ", ".join(f"{k} = {p[k]:g}" for k in used)
            + "; check their magnitudes (SI units: m, kg, N/m, rad)")
    return out


def rocker_check(p: dict, flat_face: bool = False) -> None:
    """A rocker's arm must reach the base pitch circle: |d_p - l_a| < R_b < d_p + l_a (the
    triangle cam centre, pivot, roller centre at the rise start; derive/models/dynacam.py);
    a flat face's line, f_f from the pivot, touches the base circle R_b only with the pivot
    off the circle's tangent there: |R_b - f_f| < d_p (_rocker_flat)."""
    from ..cam.follower import arm_reaches

    d, l, r = p["d_p"], p["l_a"], p["R_b"]
    if flat_face:
        f = p.get("f_f", 0.0)
        if not abs(r - f) < d:
            raise CamdynInputError(
                f"rocker: a flat face f_f = {f:g} m from a pivot at d_p = {d:g} m cannot touch "
                f"the base circle R_b = {r:g} m at the rise start; it needs "
                "|R_b - f_f| < d_p")
        return
    if not arm_reaches(d, l, r):
        raise CamdynInputError(
            f"rocker: the arm l_a = {l:g} m pivoted at d_p = {d:g} m cannot reach the base pitch "
            f"circle R_b = {r:g} m; it needs |d_p - l_a| < R_b < d_p + l_a")


def _half_radius(opts, p: dict) -> float:
    """R_1/2 (4.1): R_b + h_m/2 for a radial cam, R_b for an axial one."""
    return p["R_b"] + p["h_m"] / 2 if opts.cam == "radial" else p["R_b"]


def mean_ratios(opts, p: dict) -> tuple[float, float]:
    """(i_y, i_z): how far the contact moves per unit of the shaft's deflections y and z
    (6.22) in mid-rise at the mean slope h_m/beta_m.  For the translating roller (4.13)'s
    tan alpha_me and 1, for the translating flat face 0 and 1; for a rocker its generated
    outputs tan_alpha and i_z (derive/models/dynacam.py, _rocker and _rocker_flat) at B = 1/2
    under the uniform law, whose h and h' there are h_m/2 and h_m/beta_m."""
    if not getattr(opts, "rocker", False):
        if getattr(opts, "flat_face", False):
            return 0.0, 1.0
        return p["h_m"] / (_half_radius(opts, p) * p["beta_m"]), 1.0
    from ..core.laws import choose
    from ..core.variants import options_model

    model = options_model(opts)         # pre-generated, or built on demand (a rocker in a groove)
    pv = model.parameter_vector({k: v for k, v in p.items() if k in model.parameter_names})
    pv[model.parameter_names.index("beta_0")] = 0.0
    law = choose("uniform")
    Y = np.zeros((1, len(model.state_names)))
    Y[0, model.state_names.index("beta")] = p["beta_m"] / 2
    out = driver.eval_outputs(model.capsule, pv, np.array([law.code], dtype=np.intc),
                              np.array([law.par]), np.zeros(1), Y)[0]
    names = model.output_names
    return float(out[names.index("tan_alpha")]), float(out[names.index("i_z")])


def _characteristics(opts, p: dict) -> dict:
    if getattr(opts, "rocker", False) or getattr(opts, "flat_face", False):
        return contact_form(opts, p, *mean_ratios(opts, p))
    c_x, m_x = p["c_x"], p["m_x"]
    if opts.shaft_z:
        c_c = 1.0 / (1.0 / c_x + 1.0 / p["c_z"])
        m = m_x + p["m_z"] * (c_c / p["c_z"]) ** 2
    else:
        c_c, m = c_x, m_x
    R_half = _half_radius(opts, p)
    tan_me = p["h_m"] / (R_half * p["beta_m"])
    c_beta = p["k"] / R_half**2
    flex = 1.0 / c_beta + (1.0 / p["c_y"] if opts.shaft_y else 0.0)
    c_tan = 1.0 / flex
    m_tan = p["J"] / R_half**2 * (c_tan / c_beta) ** 2
    if opts.shaft_y:
        m_tan += p["m_y"] * (c_tan / p["c_y"]) ** 2
    t_m = p["beta_m"] / p["omega_s"]
    return {"tau": 2 * math.pi * math.sqrt(m / c_c) / t_m, "Fa": c_c / c_tan * tan_me**2,
            "Fv": m / m_tan * tan_me**2, "t_m": t_m, "c_c": c_c, "m": m, "tan_alpha_me": tan_me,
            "c_tan": c_tan, "m_tan": m_tan, "i_z_me": 1.0, "k_tan": c_tan * R_half**2,
            "J_tan": m_tan * R_half**2}


def contact_form(opts, p: dict, i_y: float, i_z: float) -> dict:
    """:func:`characteristics` for any follower, the shaft taken to the contact: with the mean
    slope h_1 = h_m/beta_m and the ratios i_y, i_z by which the shaft's deflections reach the
    contact in mid-rise (:func:`mean_ratios`), the compliance seen there is
    C = h_1^2/k + i_y^2/c_y and the shaft's mass M = (J h_1^2/k^2 + m_y i_y^2/c_y^2)/C^2
    (the torque F h_1 winds the shaft, the force F i_y bends it); then Fa = c_c C,
    Fv = m/M, c_c = 1/(1/c_x + i_z^2/c_z), m = m_x + m_z (c_c i_z/c_z)^2.  At the translating
    roller's ratios (tan alpha_me, 1) these are (4.3)-(5.52) term by term (R_1/2 = h_1/i_y)."""
    c_x, m_x = p["c_x"], p["m_x"]
    if opts.shaft_z:
        c_c = 1.0 / (1.0 / c_x + i_z**2 / p["c_z"])
        m = m_x + p["m_z"] * (c_c * i_z / p["c_z"]) ** 2
    else:
        c_c, m = c_x, m_x
    h_1 = p["h_m"] / p["beta_m"]
    C = h_1**2 / p["k"] + (i_y**2 / p["c_y"] if opts.shaft_y else 0.0)
    M = (p["J"] * h_1**2 / p["k"] ** 2 + (p["m_y"] * i_y**2 / p["c_y"] ** 2 if opts.shaft_y
                                          else 0.0)) / C**2
    t_m = p["beta_m"] / p["omega_s"]
    return {"tau": 2 * math.pi * math.sqrt(m / c_c) / t_m, "Fa": c_c * C, "Fv": m / M,
            "t_m": t_m, "c_c": c_c, "m": m, "tan_alpha_me": i_y, "i_z_me": i_z,
            "c_tan": i_y**2 / C, "m_tan": M * i_y**2, "k_tan": h_1**2 / C, "J_tan": M * h_1**2}


def equilibrium(model, p: np.ndarray, sim: Simulator, t: float = 0.0,
                guess: np.ndarray | None = None) -> np.ndarray:
    """State at time ``t`` in steady dwell: accelerations and first-order rates zero (at
    t = 0 the run's start, before the rise; at a time in a later dwell the state the run
    would settle to there, :func:`dwell_static`).

    Unknowns: every position but the input angle phi (it is the time reference, taken from
    ``guess``, else the declared start), the first-order states; velocities are the nominal
    ones (cam at the input speed).
    """
    return _equilibrium(model, p, sim.law_codes, sim.law_pars, np.array(sim.modes0, dtype=np.intc),
                        t, guess)


def _equilibrium(model, p: np.ndarray, law_codes, law_pars, modes: np.ndarray, t: float,
                 guess: np.ndarray | None) -> np.ndarray:
    names = model.state_names
    n_q = model.manifest["n_q"]
    y = model.initial_state(p) if guess is None else np.array(guess, dtype=float)
    w_s = p[model.parameter_names.index("omega_s")]
    # phi turns with the input; so does the squeeze-film gear wheel phir, which in steady dwell
    # sits on its flank (a film carries load only while it closes): phir = phi, as declared
    free = [k for k, s in enumerate(names) if k < n_q or (k >= 2 * n_q and s not in ("phi", "phir"))]
    scale = model.state_scales()[free]
    modes = modes.copy()
    # sticking linkage friction leaves x undetermined: solve without it (the frictionless
    # equilibrium has zero force to hold, so sticking is consistent there)
    specs = model.manifest.get("modes", [])
    for j, spec in enumerate(specs):
        if spec["name"] == "linkfric":
            p = p.copy()
            p[model.parameter_names.index("nu_x")] = 0.0
            modes[j] = spec["values"].index("forward")
        elif spec["name"] == "roller":
            modes[j] = spec["values"].index(spec["initial"])     # on the cam
    t0 = np.array([float(t)])
    i_dw = names.index("dw") if "dw" in names else None
    i_beta = names.index("beta")
    if guess is not None:
        # the velocities of the steady dwell are the declared start's: the cam at the input
        # speed, every other at rest
        y[n_q:2 * n_q] = model.initial_state(p)[n_q:2 * n_q]

    def state(u):
        yy = y.copy()
        yy[free] = u * scale
        yy[n_q + i_beta] = w_s + (yy[i_dw] if i_dw is not None else 0.0)
        return yy

    def resid(u):
        f = driver.eval_rhs(model.capsule, p, law_codes, law_pars, t0, state(u)[None, :],
                                element_modes=modes)[0]
        r = np.concatenate([f[n_q:2 * n_q], [f[k] for k in free if k >= 2 * n_q]])
        return r

    from scipy.optimize import least_squares

    r0 = np.abs(resid(y[free] / scale)) + 1.0
    sol = least_squares(lambda u: resid(u) / r0, y[free] / scale, xtol=1e-15, ftol=1e-15,
                        gtol=1e-15, max_nfev=2000)
    out = state(sol.x)
    if not np.all(np.isfinite(out)):
        raise SimulationError("no consistent initial state found (non-finite equilibrium)")
    return out


def turned(model, p: np.ndarray, y0: np.ndarray, dt: float, lifted: bool) -> np.ndarray:
    """A first guess of the state ``dt`` after the start ``y0`` for :func:`dwell_static`: the
    cam, the motor and the gear wheel turned on at the input speed, the follower lifted by
    the stroke in the dwell after the rise (``lifted``)."""
    y = np.array(y0, dtype=float)
    names = model.state_names
    for angle in ("beta", "phi", "phir"):
        if angle in names:
            y[names.index(angle)] += p[model.parameter_names.index("omega_s")] * dt
    if lifted and "x" in names:
        y[names.index("x")] += p[model.parameter_names.index("h_m")]
    return y


def initial_modes(model) -> np.ndarray:
    """Every force element in its declared initial mode (the roller on the cam)."""
    return np.array([s["values"].index(s["initial"]) for s in model.manifest.get("modes", [])],
                    dtype=np.intc)


def dwell_static(model, p: np.ndarray, law_codes, law_pars, t: float, guess: np.ndarray,
                 name: str = "U") -> float:
    """Output ``name`` at the static equilibrium of the dwell that holds time ``t``: where
    the follower would settle there, pressed by its spring's preload and rate, the contact
    force deflecting the follower train and the shaft.  U there is -(F_0 + c_s h)/(c_x h_m)
    for a spring-held follower on a rigid shaft: the residual vibration U0 is measured about
    it, or more preload would read as more vibration.  ``guess``: a state near the dwell's
    (the run's own there, or the start's with the cam turned on)."""
    y = _equilibrium(model, p, law_codes, law_pars, initial_modes(model), t, guess)
    out = driver.eval_outputs(model.capsule, p, law_codes, law_pars, np.array([float(t)]),
                              y[None, :])[0]
    return float(out[model.output_names.index(name)])


def variant_model(scene: DynacamScene, progress=None):
    """The compiled variant the scene's options select (:func:`variants.options_model`)."""
    from ..core.variants import options_model

    return options_model(scene.options, progress)


@dataclass
class Prepared:
    """A scene ready to run: its compiled variant, parameter values (beta_0 placed from
    run.T_start), characteristic numbers (4.3)-(5.52), the Simulator from the consistent
    initial state, and the time of the rise t_m."""

    model: object
    params: dict
    characteristics: dict
    simulator: Simulator
    y0: np.ndarray
    t_m: float
    t_end: float


def scene_method(scene: DynacamScene):
    """The method of the scene's [run]: method, rtol and absolute tolerances."""
    return METHODS[scene.method](rtol=scene.rtol, atol=scene.atol, state_atol=scene.state_atol)


def prepare(scene: DynacamScene, method=None, progress=None) -> Prepared:
    """The scene's run made ready: ``method`` by default the scene's (DP54 unless it says
    rodas4) at its rtol with no step limit (a step-limited one serves as a reference)."""
    model = variant_model(scene, progress)
    params, ch, t_end = placed(scene)
    if method is None:
        method = scene_method(scene)
    law = scene.cam_law()
    sim = Simulator(model, t_end, method, law=law, modes=scene.modes, max_steps=MAX_STEPS)
    p = model.parameter_vector(params)
    y0 = equilibrium(model, p, sim)
    sim = simulator_from(scene, model, y0, t_end, method)
    return Prepared(model, params, ch, sim, y0, ch["t_m"], t_end)


def simulator_from(scene: DynacamScene, model, y0, t_end: float, method=None) -> Simulator:
    """The Simulator of the scene's run from y0 (its equilibrium, :func:`equilibrium`) to t_end
    (:func:`placed`)."""
    return Simulator(model, t_end, scene_method(scene) if method is None else method,
                     law=scene.cam_law(), modes=scene.modes, max_steps=MAX_STEPS, y0=y0,
                     dense_output=True)


MAX_STEPS = 2_000_000
"""The most steps of a scene's run."""


def placed(scene: DynacamScene) -> tuple[dict, dict, float]:
    """(the parameter values with beta_0 placed from run.T_start, the characteristic numbers
    (4.3)-(5.52), the run's end in time) of a scene."""
    params = dict(scene.parameters)
    params["beta_0"] = -scene.T_start * params["beta_m"]
    if getattr(scene.options, "rocker", False):
        rocker_check(params, getattr(scene.options, "flat_face", False))
    ch = characteristics(scene.options, params)
    return params, ch, (scene.T_end - scene.T_start) * ch["t_m"]


@dataclass
class SceneRun:
    """One run of a scene: the summary (what `camdyn simulate` shows), the sampling error of
    each figure found by a scan, and the run itself."""

    summary: dict
    sampling: dict
    result: object


def run_scene(scene: DynacamScene, progress=None, method=None, prepared: Prepared | None = None) -> SceneRun:
    """Run a scene (see :func:`prepare`)."""
    pr = prepare(scene, method, progress) if prepared is None else prepared
    if progress:
        progress(f"{scene.title}: {scene.variant}, T from {scene.T_start:g} to {scene.T_end:g}")
    start = time.process_time()
    res = pr.simulator.run(pr.params)
    cpu = time.process_time() - start
    summary, sampling = summarize(scene, pr.model, res, pr.characteristics, cpu)
    summary["method"] = pr.simulator.method.name
    return SceneRun(summary, sampling, res)


def run(scene: DynacamScene, progress=None, method=None) -> tuple[dict, object]:
    """Run a scene; returns (summary, result) (see :func:`run_scene`)."""
    r = run_scene(scene, progress, method)
    return r.summary, r.result


FIGURES = ("Xdd_min_rise", "T_at_Xdd_min", "Xdd_max_rise", "U0dd", "U0", "speed_variation_max",
           "motor_speed_variation_max", "Xdd_absmax_return", "U0dd_return", "U0_return")
"""The headline figures of a scene's summary that get an error estimate (the last three only
with a full turn)."""


def nominal_T(scene: DynacamScene, res) -> np.ndarray:
    """Dimensionless time of the nominal motion, T = w_s t/beta_m + T_start."""
    t_m = res.params["beta_m"] / res.params["omega_s"]
    return res.t / t_m + scene.T_start


def sample_at(scene: DynacamScene, res, T: float, name: str = "Xdd") -> float:
    """Output ``name`` at the nominal time T, through the dense output."""
    t_m = res.params["beta_m"] / res.params["omega_s"]
    return float(res.sample(np.array([(T - scene.T_start) * t_m]))[name][0])


def mode_changes(scene: DynacamScene, res, mode: str) -> list:
    """(T, new value) at every switch of a force element's mode, in order."""
    T = nominal_T(scene, res)
    values = res.element_mode(mode)
    return [(float(T[i + 1]), values[i + 1]) for i in np.flatnonzero(values[1:] != values[:-1])]


@dataclass(frozen=True)
class Span:
    """A headline figure read as an extreme: of output ``name`` on [a, b] of the run's time,
    of |v| (``absolute``), least (``minimum``) or largest; ``time_key``: the figure that holds
    where it lies, as the nominal T."""

    key: str
    name: str
    a: float
    b: float
    absolute: bool
    minimum: bool
    time_key: str | None = None


def headline_spans(scene: DynacamScene, t_m: float, t0: float, t_end: float,
                   outputs) -> tuple[tuple, tuple]:
    """(every headline figure's key in order, the Spans of those a run of [t0, t_end] reaches)
    (:func:`headline`); ``outputs``: the variant's output names."""
    keys = ["Xdd_min_rise", "T_at_Xdd_min", "Xdd_max_rise", "U0dd", "U0"]
    spans = []
    rise0, rise1 = -scene.T_start * t_m, (1 - scene.T_start) * t_m
    spans.append(Span("Xdd_min_rise", "Xdd", rise0, rise1, False, True, "T_at_Xdd_min"))
    spans.append(Span("Xdd_max_rise", "Xdd", rise0, rise1, False, False))
    turn = scene.cam_law() if scene.turn is not None else None
    # with a full turn the dwell after the rise ends where the return starts
    dwell_end = t_end if turn is None else min(t_end, (1 + turn.up - scene.T_start) * t_m)
    if dwell_end > rise1:
        spans.append(Span("U0dd", "Xdd", rise1, dwell_end, True, False))
        spans += about_static("U0", rise1, dwell_end)
    if turn is not None:
        keys += ["Xdd_absmax_return", "U0_return", "U0dd_return"]
        ret0 = (1 + turn.up - scene.T_start) * t_m
        ret1 = (1 + turn.up + turn.r - scene.T_start) * t_m
        low1 = min(t_end, (turn.period - scene.T_start) * t_m)
        if t_end > ret0:
            spans.append(Span("Xdd_absmax_return", "Xdd", ret0, min(ret1, t_end), True, False))
        if low1 > ret1:
            spans += about_static("U0_return", ret1, low1)
            spans.append(Span("U0dd_return", "Xdd", ret1, low1, True, False))
    keys += ["speed_variation_max", "motor_speed_variation_max"]
    spans.append(Span("speed_variation_max", "speed_var", t0, t_end, True, False))
    if "motor_speed_var" in outputs:
        spans.append(Span("motor_speed_variation_max", "motor_speed_var", t0, t_end, True, False))
    return tuple(keys), tuple(spans)


STATIC = {"U0": "U_static", "U0_return": "U_static_return"}
"""The residual amplitudes of U measured about the dwell's static equilibrium, and the
figure that holds where that lies (:func:`dwell_static`)."""


def about_static(key: str, a: float, b: float) -> list:
    """The Spans of a residual amplitude of U about the static equilibrium of its dwell
    [a, b]: the largest and the least U there (:func:`combine_static`)."""
    return [Span(f"{key}:max", "U", a, b, False, False), Span(f"{key}:min", "U", a, b, False, True)]


def static_times(spans) -> dict:
    """Residual amplitude -> the time (mid-dwell) its static equilibrium is found at."""
    return {sp.key[:-4]: 0.5 * (sp.a + sp.b) for sp in spans if sp.key.endswith(":max")}


def combine_static(figures: dict, sampling: dict, statics: dict) -> None:
    """U0 = max(U_max - U_s, U_s - U_min) over the dwell, U_s its static equilibrium
    (``statics``: amplitude -> U_s); the amplitude's sampling error the larger of the two
    extremes'.  U_s goes into the figures beside it (:data:`STATIC`)."""
    for key, u_s in statics.items():
        hi, lo = figures.pop(f"{key}:max", None), figures.pop(f"{key}:min", None)
        s_hi, s_lo = sampling.pop(f"{key}:max", 0.0), sampling.pop(f"{key}:min", 0.0)
        if hi is None or lo is None:
            continue
        figures[key] = max(hi - u_s, u_s - lo)
        sampling[key] = max(s_hi, s_lo)
        figures[STATIC[key]] = u_s


def headline(scene: DynacamScene, res, t_m: float) -> tuple[dict, dict]:
    """The scene's headline figures of a run (a camdyn Result or another integrator's run that
    offers ``sample``) and the sampling error of each: the extremes of X'' in the rise (nominal
    0 < T < 1), U0'' and U0 in the dwell after it (to the run's end, or to the return of a
    full turn), the largest speed variations over the run, and with a [turn] the return's
    largest |X''| and U0, U0'' in the lower dwell after it.  Every extreme is refined on the
    dense output, not read at the recorded steps."""
    keys, spans = headline_spans(scene, t_m, float(res.t[0]), float(res.t[-1]),
                                 res.model.output_names)
    figures, sampling = dict.fromkeys(keys), {}
    for sp in spans:
        e = extreme(res, sp.name, sp.a, sp.b, absolute=sp.absolute, minimum=sp.minimum)
        read_span(sp, e, t_m, scene.T_start, figures, sampling)
    statics = {}
    for key, t in static_times(spans).items():
        # guessed from the start as a grid's chunk guesses it, so that both find the same
        # level to the last bit
        guess = turned(res.model, res.p, res.y[0], t - float(res.t[0]), lifted=key == "U0")
        statics[key] = dwell_static(res.model, res.p, res.law_codes, res.law_pars, t, guess)
    combine_static(figures, sampling, statics)
    return figures, sampling


def read_span(sp: Span, e, t_m: float, T_start: float, figures: dict, sampling: dict) -> None:
    """The figure (and where it lies) and its sampling error of Span ``sp`` from its extreme."""
    figures[sp.key] = e.value
    sampling[sp.key] = e.sampling_error
    if sp.time_key:
        figures[sp.time_key] = e.at / t_m + T_start
        sampling[sp.time_key] = place_error(e.at) / t_m


def dwell_spans(scene: DynacamScene, t_m: float, t_end: float) -> dict:
    """Output -> (start, end) of each dwell a figure is read from, in the run's time: the
    dwell after the rise (to the run's end, or to a full turn's return) and a full turn's
    lower dwell after the return (to the next rise or the run's end)."""
    rise1 = (1 - scene.T_start) * t_m
    if scene.turn is None:
        return {"U0": (rise1, t_end), "U0dd": (rise1, t_end)}
    turn = scene.cam_law()
    up = min(t_end, (1 + turn.up - scene.T_start) * t_m)
    ret1 = (1 + turn.up + turn.r - scene.T_start) * t_m
    low1 = min(t_end, (turn.period - scene.T_start) * t_m)
    return {"U0": (rise1, up), "U0dd": (rise1, up), "U0_return": (ret1, low1),
            "U0dd_return": (ret1, low1)}


def summarize(scene: DynacamScene, model, res, ch: dict, cpu: float) -> tuple[dict, dict]:
    """(summary, sampling errors) of a run: the headline figures in the order `camdyn
    simulate` prints them, the jump of a follower that leaves the cam, and the run's record."""
    T = nominal_T(scene, res)
    t_m = res.params["beta_m"] / res.params["omega_s"]
    figures, sampling = headline(scene, res, t_m)
    out = {"title": scene.title, "variant": scene.variant, "tau": ch["tau"], "Fa": ch["Fa"],
           "Fv": ch["Fv"]}
    for key in FIGURES[:5]:          # the rise's and the dwell's; the speeds follow below
        out[key] = figures[key]
    out["U_static"] = figures.get("U_static")
    if scene.turn is not None:
        turn = scene.cam_law()
        out["turn"] = {"angles_deg": list(turn.angles_deg), "return_law": turn.ret.key,
                       "period_T": turn.period}
        for key in ("Xdd_absmax_return", "U0_return", "U0dd_return"):
            out[key] = figures[key]
        out["U_static_return"] = figures.get("U_static_return")
    jump = {"occurs": False, "T": None}
    if scene.options.roller == "contact":
        free = res.element_mode("roller") == "free"
        if free.any():
            jump = {"occurs": True, "T": float(T[np.flatnonzero(free)[0]])}
    out["jump"] = jump
    out["speed_variation_max"] = figures["speed_variation_max"]
    out["motor_speed_variation_max"] = figures["motor_speed_variation_max"]
    out["n_events"] = int(res.stats["n_events"])
    out["n_steps"] = int(res.stats["n_steps"])
    # DP54's stiffness test (Hairer): where it fired, as the nominal T; fixed-step warnings
    out["stiff_from_T"] = (None if res.stiff_from_T is None
                           else res.stiff_from_T / t_m + scene.T_start)
    out["warnings"] = list(res.warnings)
    out["cpu_seconds"] = cpu
    out["characteristics"] = {k: ch[k] for k in ("t_m", "c_c", "m", "tan_alpha_me", "c_tan", "m_tan")}
    return out, sampling


def reduced_models(scene: DynacamScene, summary: dict) -> dict:
    """Residual acceleration amplitude U0dd of the scene's run beside that of the reduced
    models with the same characteristic numbers (thesis sec. 8.2.4, 8.2.5, fig. 8.3 curves
    (4), (5), (6)): CAMSHAFT-2 at (tau, Fa, Fv) (5.15), (5.16) and CAMSHAFT-1 at (tau, Fa)
    (4.15), each over the same dwell, 1 < T < T_end.

    The comparison is the thesis's only when the scene is undamped, without follower spring
    and with the roller held on the cam, as fig. 8.3's curves (4)-(6) are.
    """
    from ..measure.residual import residual
    from ..core.simulator import simulate

    tau, Fa, Fv = summary["tau"], summary["Fa"], summary["Fv"]
    out = {"4dof": summary["U0dd"]}
    for key, model, params in (("2dof", "camshaft2", {"tau": tau, "Fa": Fa, "Fv": Fv}),
                               ("1dof", "camshaft1", {"tau": tau, "Fa": Fa})):
        res = simulate(model, params, scene.T_end, "dp54", rtol=1e-10)
        out[key] = residual(res).U0dd
    return out


