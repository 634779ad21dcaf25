"""Stability of the fixed-step methods: a step beyond the boundary is refused, one near it warned.

A fixed-step run (RK4, the thesis scheme "koster") is stable when h lambda lies inside the
method's region of absolute stability for every eigenvalue lambda of the Jacobian df/dy of the
first-order right-hand side, frozen along the run.  The compiled loop checks it as it goes
(runtime/engine/loops.pxi, ``_stab_check``): at the start of a step, from the model's generated
Jacobian, the limiting eigenvalue (closed form for two states, else the dominant pair of a
power iteration on the Krylov plane {q, J q}, kept warm from check to check) against the
boundary in its direction (``loop_boundary``, this module's table); at every interval's start,
after every event, and in between every 16 steps at most (64 while h |lambda| is under a
quarter of the boundary), sooner as h |lambda| nears it.  A step beyond it stops the run there (driver status UNSTABLE): the refusal names
that time, h |lambda|, |lambda| and the largest stable step.  A run to the end records the
largest h |lambda|/boundary it saw and where, from which the warning near the boundary is
worded (``from_loop``); nothing is evaluated in Python before or after the run.

Why the Jacobian and not the stages.  Hairer's stiffness test reads |k_s - k_(s-1)| /
|y_s - y_(s-1)| off two stages at the same time (DP54 does, for its note): free, but a Rayleigh
quotient along whatever direction the stages differ in.  Along DP54 runs at the RK4 stages
(k3 - k2 against h/2 (k2 - k1)) it measured 0.008 to 60 times the spectral radius in the
Euclidean norm, and 0.008 to 5.2 times with DP54's frequency weighting (exact only for one
undamped degree of freedom; 0.30 of it, median, on the chain of sec. 3.7), and it cannot tell
the imaginary axis (2.828) from the real one (2.785): it could neither refuse the steps this
check refuses nor name where.  The generated Jacobian costs one evaluation a check: on
CAMSHAFT-1 (bench/run.py's problem, h = 1/150 to 1/356) about 230 instructions a check, half
of them the Jacobian's cam-law evaluation, 5 % of the compiled loop's instructions at a check
every 16 steps (valgrind).  It is called through a pointer, with copies of the state and the
context: inlined, its code cost the stepping loop about 15 % even with the check off (the
state spilled out of registers around it); now the loop with the check is within the timing
noise of the loop without it (bench/run.py, BENCHMARKS-camshaft1.md).  The check it replaces, central-difference Jacobians and NumPy's eigenvalues at 48 or more
recorded points after the run, cost about 1 ms a call, 25 to 110 times the loop.

Boundaries, |h lambda| along the direction of lambda (the eigenvalue reflected into the left
half-plane: a mode that grows physically is judged by its magnitude, not refused for growing):

* RK4, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24.  On the imaginary axis |R(ix)|^2 =
  1 - x^6/72 + x^8/576 <= 1 for x <= 2 sqrt(2) = 2.828 (exact); on the negative real axis
  2.785.  An undamped or lightly damped oscillation (the cam followers of the thesis) has
  lambda = +-i omega: its boundary is h omega <= 2 sqrt(2).  Other directions are found
  numerically (first exit of |R| > 1 along the ray, ``ray_boundary``).
* koster, the thesis scheme (4.23)-(4.31) on y'' = -w^2 y, x = h w, c = 1/(1 + x^2/8): the
  step maps (X, X') by [[1 - c x^2/2, x - c x^3/4], [-c x, 1 - c x^2/2]], determinant 1 and
  trace 2 - c x^2: stable (|trace| <= 2, no amplitude error at all) exactly for
  x <= 2 sqrt(2) = 2.828, which is also where the mid-step fixed-point iteration stops
  contracting (factor x^2/8).  Measured from that matrix in tests/test_stability.py.  The
  scheme is analysed on the undamped test equation only: its boundary is applied to |h lambda|
  in every direction.  The compiled scheme solves the mid-step equation by fixed-point
  iteration only while that contracts fast (factor <= 0.1 a sweep) and by Newton's method with
  the model's Jacobian beyond (runtime/engine/loops.pxi), which converges in one step on this linear
  equation at any x: the compiled boundary is 2 sqrt(2) too (measured 2.8284,
  runtime/studies/stability_boundary.py; with the plain iteration it gave up at h w ~ 2.35-2.40).

"Near the boundary": the step still gives a bounded solution, but the fastest mode is damped or
shifted in phase heavily.  Criterion: over one period of the fastest mode (2 pi/rho) the error
of the discrete amplification against the exact one, |R^N e^(-2 pi i) - 1| with
N = 2 pi/(h rho) steps, exceeds 1 %.  That is at h rho = 0.662 for RK4 (0.23 of its boundary)
and 0.278 for koster (second order: phase error only).  The thesis's fine step 0.01 tau gives
h rho = 0.063 for the one-DOF model; its "stable for dT <= 0.1 tau" (sec. 4.4.2) is
h rho = 0.63, a 4.9 % phase error per period with koster.

Largest stable step reported: SAFETY (0.9) times boundary/|lambda| of the limiting eigenvalue.

``spectra`` and ``assess`` estimate the same from recorded points in Python, for the studies
that draw the theory line of a stability map (runtime/studies/stability_map.py,
stability_boundary.py).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from functools import lru_cache

import numpy as np

from ..engine import driver

SQRT8 = 2.0 * math.sqrt(2.0)
RK4_IMAG = SQRT8            # RK4 on the imaginary axis (exact)
RK4_REAL = 2.785293563405   # RK4 on the negative real axis: R(-x) = 1, x > 0
KOSTER_BOUNDARY = SQRT8     # thesis scheme on y'' = -w^2 y (exact, see the module docstring)
WARN_PER_PERIOD = 0.01      # per-period error of the fastest mode that earns a warning
WARN_RK4 = 0.6622           # h rho where RK4's per-period error reaches 1 %
WARN_KOSTER = 0.2778        # same for the thesis scheme
SAFETY = 0.9                # largest stable step = SAFETY * boundary / |lambda|
SAMPLES = 48                # recorded points a study's step limit reads (stability_map.step_limit)
BOUNDARY_POINTS = 1025      # RK4's boundary tabulated over the direction of lambda


def rk4_R(z):
    return 1 + z + z ** 2 / 2 + z ** 3 / 6 + z ** 4 / 24


def koster_amplification(x: float) -> np.ndarray:
    """The thesis scheme's step matrix on y'' = -w^2 y, x = h w, acting on (X, X'/w)."""
    c = 1.0 / (1.0 + x * x / 8.0)
    return np.array([[1 - c * x * x / 2, x - c * x ** 3 / 4], [-c * x, 1 - c * x * x / 2]])


def per_period_error(method: str, x: float) -> float:
    """|R^N exp(-2 pi i) - 1|, N = 2 pi/x: amplitude and phase error over one period of an
    undamped mode with h omega = x (the warning criterion)."""
    if method == "rk4":
        r = complex(rk4_R(1j * x))
    else:
        # koster_amplification(x) = [[a, b], [c, a]]: eigenvalues a +- sqrt(b c)
        (a, b), (c, _) = koster_amplification(x)
        r = complex(a, math.sqrt(max(-b * c, 0.0)))
    n = 2 * math.pi / x
    amp = abs(r) ** n
    phase = (math.atan2(r.imag, r.real) - x) * n
    return abs(amp * complex(math.cos(phase), math.sin(phase)) - 1.0)


def ray_boundaries(R, phis, r_max: float = 6.0, n: int = 6000) -> np.ndarray:
    """First r > 0 where |R(r e^(i phi))| exceeds 1, for each phi (bisection after a scan)."""
    d = np.exp(1j * np.atleast_1d(np.asarray(phis, dtype=float)))[:, None]
    r = np.linspace(r_max / n, r_max, n)
    out = np.abs(R(r[None, :] * d)) > 1.0 + 1e-12
    k = np.argmax(out, axis=1)
    lo = np.where(k > 0, r[np.maximum(k - 1, 0)], 0.0)
    hi = r[k]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        bad = np.abs(R(mid * d[:, 0])) > 1.0 + 1e-12
        hi = np.where(bad, mid, hi)
        lo = np.where(bad, lo, mid)
    return np.where(out.any(axis=1), lo, r_max)


def ray_boundary(R, phi: float, r_max: float = 6.0, n: int = 6000) -> float:
    """First r > 0 where |R(r e^(i phi))| exceeds 1 (bisection after a scan)."""
    return float(ray_boundaries(R, [phi], r_max, n)[0])


@lru_cache(maxsize=None)
def _rk4_table() -> np.ndarray:
    """RK4's boundary at u = |Re lambda|/|lambda| = k/(N - 1): the table the compiled check
    interpolates linearly (within 4e-6 of ray_boundary in every direction)."""
    u = np.linspace(0.0, 1.0, BOUNDARY_POINTS)
    b = ray_boundaries(rk4_R, math.pi / 2 + np.arcsin(u))
    b[0], b[-1] = RK4_IMAG, RK4_REAL
    return b


def loop_boundary(method: str) -> np.ndarray:
    """The boundary the compiled check takes (run.stab_bound): RK4's table over the direction,
    or the thesis scheme's one value."""
    if method == "koster":
        return np.array([KOSTER_BOUNDARY])
    return _rk4_table()


def boundary(method: str, eigs: np.ndarray) -> np.ndarray:
    """The method's boundary |h lambda| along the direction of each eigenvalue (reflected into
    the left half-plane), as the compiled check reads it."""
    eigs = np.asarray(eigs, dtype=complex)
    if method == "koster":
        return np.full(eigs.shape, KOSTER_BOUNDARY)
    mag = np.abs(eigs)
    u = np.divide(np.abs(eigs.real), mag, out=np.zeros(mag.shape), where=mag > 0)
    return np.interp(u, np.linspace(0.0, 1.0, BOUNDARY_POINTS), _rk4_table())


def warn_level(method: str) -> float:
    return WARN_RK4 if method == "rk4" else WARN_KOSTER


@dataclass(frozen=True)
class Estimate:
    """The stability check of one fixed-step run.

    h                    the step asked for (intervals are cut into equal steps no longer)
    rho, T               |lambda| of the limiting eigenvalue (the one that allows the smallest
                         stable step; for the oscillators here the spectral radius) and where
    h_rho                h * rho
    boundary             the method's boundary in the direction of that eigenvalue
    largest_stable_step  SAFETY * boundary / |lambda| of the limiting eigenvalue
    accurate_step        the step below which the per-period error stays under 1 %
    per_period_error     that error at this step (undamped mode with h omega = h rho)
    stable               every sampled h lambda inside the region
    """

    method: str
    h: float
    rho: float
    T: float
    h_rho: float
    boundary: float
    largest_stable_step: float
    accurate_step: float
    per_period_error: float
    stable: bool

    @property
    def near(self) -> bool:
        return self.stable and self.h_rho > warn_level(self.method)

    def as_dict(self) -> dict:
        return asdict(self)


def spectra(model, p, law_codes, law_pars, t, y, mode=None, element_modes=None):
    """Eigenvalues of the finite-difference Jacobian at each point: a list of arrays."""
    t = np.ascontiguousarray(np.atleast_1d(np.asarray(t, dtype=float)))
    y = np.ascontiguousarray(np.atleast_2d(np.asarray(y, dtype=float)))
    scale = np.ascontiguousarray(model.state_scales(), dtype=float)
    J = driver.eval_jacobian_fd(model.capsule, p, law_codes, law_pars, t, y, scale,
                                 None if mode is None else np.ascontiguousarray(mode, dtype=np.intc),
                                 element_modes)
    return [np.linalg.eigvals(j) if np.all(np.isfinite(j)) else np.array([np.nan]) for j in J]


def assess(method: str, h: float, times, spectra_list) -> Estimate | None:
    """The estimate from eigenvalues at the given times; None without a usable point."""
    best = None    # (stable step of the limiting eigenvalue, time, |lambda|, boundary)
    t_any = None
    for T, ev in zip(times, spectra_list):
        ev = np.asarray(ev, dtype=complex)
        if not np.all(np.isfinite(ev)):
            continue
        if t_any is None:
            t_any = float(T)
        mag = np.abs(ev)
        keep = mag > 0
        if not keep.any():
            continue
        ev, mag = ev[keep], mag[keep]
        b = boundary(method, ev)
        hs = b / mag
        k = int(np.argmin(hs))
        if best is None or hs[k] < best[0]:
            best = (float(hs[k]), float(T), float(mag[k]), float(b[k]))
    if t_any is None:
        return None
    if best is None:
        return estimate(method, h, 0.0, t_any, math.inf)
    _, T, lam, b = best
    return estimate(method, h, lam, T, b)


def estimate(method: str, h: float, lam: float, T: float, b: float) -> Estimate:
    """The estimate of a step h whose limiting eigenvalue has |lambda| = lam at T, boundary b
    in its direction (lam = 0: a Jacobian without dynamics, no limit)."""
    if lam <= 0:
        return Estimate(method, h, 0.0, T, 0.0, math.inf, math.inf, math.inf, 0.0, True)
    x = h * lam
    err = per_period_error(method, x) if x < SQRT8 else math.inf
    return Estimate(method=method, h=h, rho=lam, T=T, h_rho=x, boundary=b,
                    largest_stable_step=SAFETY * b / lam, accurate_step=warn_level(method) / lam,
                    per_period_error=err, stable=x <= b)


def from_loop(method: str, h: float, out) -> Estimate | None:
    """The estimate the compiled check recorded (driver.RunRecord: where h |lambda|/b was
    largest, that |lambda| and b); None when it checked no step."""
    if not out.n_checks or not out.stab_ratio >= 0:
        return None
    return estimate(method, h, float(out.stab_rho), float(out.stab_t), float(out.stab_b))


def sample_indices(t: np.ndarray, n: int, samples: int = SAMPLES) -> np.ndarray:
    """Recorded points to check: the first, each interval's start (right limit at a stop
    recorded twice) and ``samples`` spread evenly over the first n points."""
    if n <= 0:
        return np.zeros(0, dtype=int)
    t = t[:n]
    starts = np.flatnonzero(np.diff(t) == 0) + 1
    even = np.linspace(0, n - 1, min(samples, n)).round().astype(int)
    return np.unique(np.concatenate([[0], starts, even]))


def refusal(model_name: str, tname: str, e: Estimate) -> str:
    """The one-line message of a step beyond the boundary."""
    name = {"rk4": "RK4", "koster": "the thesis scheme (koster)"}[e.method]
    return (f"{model_name} with {e.method}: step h = {e.h:g} is beyond the stability limit of "
            f"{name}: h*rho = {e.h_rho:.4g} > {e.boundary:.4g} (spectral radius of the Jacobian "
            f"rho = {e.rho:.6g} at {tname} = {e.T:.6g}, boundary |h lambda| in that eigenvalue's "
            f"direction; 2 sqrt(2) = 2.828 for an undamped oscillation); largest stable step "
            f"{e.largest_stable_step:.4g} ({SAFETY:g} x boundary/rho); use a smaller step")


def warning(tname: str, e: Estimate) -> str:
    """The one-line warning of a step near the boundary."""
    return (f"{e.method} step h = {e.h:g} is near its stability limit: h*rho = {e.h_rho:.3g} "
            f"of {e.boundary:.3g} (rho = {e.rho:.6g} at {tname} = {e.T:.6g}); the fastest mode "
            f"is damped or distorted by {100 * e.per_period_error:.3g} % per period; for under "
            f"{100 * WARN_PER_PERIOD:g} % use step <= {e.accurate_step:.3g}")
