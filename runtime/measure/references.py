"""The one-DOF residual-vibration amplitudes in closed form, in NumPy (no SymPy at run time).

U0   = tau^3 |sin(pi/tau)| / (pi (1 - tau^2))          positional error after the rise (3.5)
U0'' = 4 pi tau |sin(pi/tau)| / (1 - tau^2)            residual acceleration (3.6)

for the cycloidal rise (3.2) on the one-DOF model (3.1).  The symbolic forms are
:mod:`camdyn.thesis.theory`; tests/test_one_dof.py holds the two equal.
"""
import numpy as np


def U0(tau):
    """(3.5); a float for a float, an array for an array."""
    t = np.asarray(tau, dtype=float)
    out = t**3 * np.abs(np.sin(np.pi / t)) / (np.pi * (1 - t**2))
    return float(out) if out.ndim == 0 else out


def U0dd(tau):
    """(3.6); a float for a float, an array for an array."""
    t = np.asarray(tau, dtype=float)
    out = 4 * np.pi * t * np.abs(np.sin(np.pi / t)) / (1 - t**2)
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
