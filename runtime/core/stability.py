"""Stability of the fixed-step methods: a step beyond the boundary is refused, one near it warned.

A fixed-step run (RK4, the thesis scheme "koster") is stable when h lambda lies inside the
method's region of absolute stability for every eigenvalue lambda of the Jacobian df/dy of the
first-order right-hand side, frozen along the run.  The Jacobian is estimated by central
differences of the compiled rhs (``driver.eval_jacobian_fd``; no generated Jacobian is used),
its eigenvalues by the small dense eigenproblem (n_states <= ~40), at the start of the run
(before it: a step beyond the boundary there is refused at once) and at a sample of recorded
points after it (every breakpoint interval's start and ``SAMPLES`` points spread over the
record); the most restrictive one counts.

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
SAMPLES = 48                # recorded points checked after a run, besides the interval starts


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
        ev = np.linalg.eigvals(koster_amplification(x))
        r = complex(ev[np.argmax(ev.imag)])
    n = 2 * math.pi / x
    amp = abs(r) ** n
    phase = (math.atan2(r.imag, r.real) - x) * n
    return abs(amp * complex(math.cos(phase), math.sin(phase)) - 1.0)


def ray_boundary(R, phi: float, r_max: float = 6.0, n: int = 6000) -> float:
    """First r > 0 where |R(r e^(i phi))| exceeds 1 (bisection after a scan)."""
    d = complex(math.cos(phi), math.sin(phi))
    r = np.linspace(r_max / n, r_max, n)
    out = np.abs(R(r * d)) > 1.0 + 1e-12
    if not out.any():
        return r_max
    k = int(np.argmax(out))
    lo, hi = (r[k - 1] if k else 0.0), r[k]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if abs(R(mid * d)) > 1.0 + 1e-12:
            hi = mid
        else:
            lo = mid
    return lo


@lru_cache(maxsize=None)
def _rk4_table() -> tuple[np.ndarray, np.ndarray]:
    phi = np.linspace(math.pi / 2, math.pi, 361)
    b = np.array([ray_boundary(rk4_R, p) for p in phi])
    b[0], b[-1] = RK4_IMAG, RK4_REAL
    return phi, b


def boundary(method: str, eigs: np.ndarray) -> np.ndarray:
    """The method's boundary |h lambda| along the direction of each eigenvalue."""
    eigs = np.asarray(eigs, dtype=complex)
    if method == "koster":
        return np.full(eigs.shape, KOSTER_BOUNDARY)
    phi = np.arctan2(np.abs(eigs.imag), -np.abs(eigs.real))   # reflected into the left half-plane
    tab_phi, tab_b = _rk4_table()
    return np.interp(phi, tab_phi, tab_b)


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
    if best is None:   # a Jacobian without dynamics: no limit
        return Estimate(method, h, 0.0, t_any, 0.0, math.inf, math.inf, math.inf, 0.0, True)
    h_stable, T, lam, b = best
    x = h * lam
    err = per_period_error(method, x) if x < SQRT8 else math.inf
    return Estimate(method=method, h=h, rho=lam, T=T, h_rho=x, boundary=b,
                    largest_stable_step=SAFETY * h_stable, accurate_step=warn_level(method) / lam,
                    per_period_error=err, stable=h <= h_stable)


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
