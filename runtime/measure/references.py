"""The one-DOF residual-vibration amplitudes in closed form, in NumPy (no SymPy at run time).

U0   = tau^3 |sin(pi/tau)| / (pi |1 - tau^2|)          positional error after the rise (3.5)
U0'' = 4 pi tau |sin(pi/tau)| / |1 - tau^2|            residual acceleration (3.6)

for the cycloidal rise (3.2) on the one-DOF model (3.1).  Both are amplitudes, >= 0: the
dwell's error (3.4b) is tau^3 sin(pi/tau)/(pi (1 - tau^2)) cos(pi/tau (2T - 1)), and its
amplitude the absolute value of the factor before the cosine.  The thesis prints them for the
one-DOF model's tau < 1, where 1 - tau^2 > 0; CAMSHAFT-1 at Fa = 0 is the same model and
takes tau up to 10, where 1 - tau^2 < 0 and the printed form would be negative.  At tau = 1
(resonance with the rise) both have a finite limit, 1/2 and 2 pi^2: near it they are written
with sinc (x = 1 - 1/tau, sin(pi/tau) = sin(pi x), so |sin(pi/tau)|/|1 - tau^2| =
pi |sinc x|/(tau (1 + tau))), which keeps them exact there instead of 0/0.  The symbolic forms
are :mod:`camdyn.thesis.theory`; tests/test_one_dof.py holds the two equal.
"""
import numpy as np

NEAR_RESONANCE = 0.5
"""|1 - 1/tau| below which the sinc form is used (2/3 < tau < 2): there it is exact to
rounding, and the quotient form loses digits to the cancellation in 1 - tau^2."""


def _ratio(t: np.ndarray) -> np.ndarray:
    """|sin(pi/tau)| / |1 - tau^2|, finite through tau = 1."""
    x = 1.0 - 1.0 / t
    near = np.abs(x) < NEAR_RESONANCE
    with np.errstate(divide="ignore", invalid="ignore"):
        far = np.abs(np.sin(np.pi / t)) / np.abs(1.0 - t**2)
    return np.where(near, np.pi * np.abs(np.sinc(x)) / (t * (1.0 + t)), far)


def U0(tau):
    """(3.5), the amplitude for every tau > 0; a float for a float, an array for an array."""
    t = np.asarray(tau, dtype=float)
    out = t**3 * _ratio(t) / np.pi
    return float(out) if out.ndim == 0 else out


def U0dd(tau):
    """(3.6), the amplitude for every tau > 0; a float for a float, an array for an array."""
    t = np.asarray(tau, dtype=float)
    out = 4 * np.pi * t * _ratio(t)
    return float(out) if out.ndim == 0 else out


ONE_DOF_AT = {"one_dof": {"q": 0.0}, "camshaft1": {"Fa": 0.0}}
"""The models that are the undamped one-DOF model (3.1) at these parameter values: CAMSHAFT-1
with a rigid shaft (Fa = 0, sec. 4.2), the one-DOF model without damping (q = 0)."""


def beside(model: str, law, params: dict) -> dict:
    """U0 (3.5) and U0'' (3.6) in closed form, to print beside a run of ``model`` with these
    parameter values, where the run is the cycloidal rise on the undamped one-DOF model;
    else nothing."""
    at = ONE_DOF_AT.get(model)
    if law != "cycloidal" or at is None or any(params.get(k, 0.0) != v for k, v in at.items()):
        return {}
    return {"U0_closed_form": U0(params["tau"]), "U0dd_closed_form": U0dd(params["tau"])}
