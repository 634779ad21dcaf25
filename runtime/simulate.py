"""``simulate(model, params, t_end, method=...)``: one run of a generated model."""
from __future__ import annotations

import math
import time as _time

import numpy as np

from . import _integrate, laws as _laws, methods as _methods
from .errors import CamdynInputError, SimulationError
from .models import CompiledModel, load
from .result import Result


def _law_choices(model: CompiledModel, law, theta):
    fams = model.families
    if isinstance(law, dict):
        missing = set(fams) - set(law)
        if missing:
            raise CamdynInputError(f"no cam law given for input {', '.join(sorted(missing))}")
        chosen = {f: law[f] if isinstance(law[f], _laws.LawChoice) else _laws.choose(law[f], theta)
                  for f in fams}
    else:
        choice = law if isinstance(law, _laws.LawChoice) else _laws.choose(law, theta)
        chosen = {f: choice for f in fams}
    codes = np.array([chosen[f].code for f in fams] or [0], dtype=np.intc)[: max(len(fams), 1)]
    pars = np.array([chosen[f].par for f in fams] or [0.0], dtype=float)[: max(len(fams), 1)]
    return chosen, codes, pars


def stop_times(model: CompiledModel, p, chosen: dict, t0: float, t_end: float) -> np.ndarray:
    """Cam-law breakpoints in time inside (t0, t_end), then t_end.

    A cam input whose argument is a t + b has its law breakpoints at
    (bp - b)/a; inputs driven by a state (H(B)) need events instead.
    """
    stops = {float(t_end)}
    affine = model.cam_time_affine(p)
    for inst, ab in zip(model.manifest["cam_instances"], affine):
        if ab is None:
            continue
        a, b = ab
        if a == 0:
            continue
        for bp in chosen[inst["family"]].breakpoints():
            tb = (bp - b) / a
            if t0 < tb < t_end:
                stops.add(float(tb))
    return np.array(sorted(stops))


def simulate(model, params: dict | None = None, t_end: float = 3.0, method="dp54", *,
             rtol: float | None = None, atol: float | None = None, step: float | None = None,
             law="cycloidal", theta: float | None = None, y0=None, t0: float = 0.0,
             max_steps: int = 5_000_000) -> Result:
    """Integrate ``model`` from t0 to t_end.

    model   name of a generated model ("camshaft1") or a CompiledModel
    params  parameter values by name; the others take their defaults
    method  "dp54" (rtol, atol), "rk4" or "koster" (step), or a method object
    law     cam-law name, or {family: name} for models with several inputs;
            theta is the law's shape parameter (modified sine)
    """
    m = model if isinstance(model, CompiledModel) else load(model)
    p = m.parameter_vector(params)
    if isinstance(method, str):
        method = _methods.make(method, rtol=rtol, atol=atol, step=step)
    elif rtol is not None or atol is not None or step is not None:
        raise CamdynInputError("give rtol/atol/step inside the method object, not beside it")
    try:
        t0, t_end = float(t0), float(t_end)
    except (TypeError, ValueError):
        raise CamdynInputError("t0 and t_end must be numbers") from None
    if not (math.isfinite(t0) and math.isfinite(t_end) and t_end > t0):
        raise CamdynInputError(f"t_end={t_end:g} must be finite and greater than t0={t0:g}")
    chosen, codes, pars = _law_choices(m, law, theta)
    n = len(m.state_names)
    y_init = m.initial_state() if y0 is None else np.array(y0, dtype=float).ravel()
    if y_init.shape != (n,) or not np.all(np.isfinite(y_init)):
        raise CamdynInputError(f"y0 must be {n} finite numbers ({', '.join(m.state_names)})")
    stops = stop_times(m, p, chosen, t0, t_end)
    if method.adaptive:
        atol_vec = (method.atol if method.atol is not None else 1e-3 * method.rtol) * m.state_scales()
        h, h_max, rtol_v = method.first_step or 0.0, min(method.max_step, t_end - t0), method.rtol
    else:
        atol_vec, h, h_max, rtol_v = np.ones(n), method.step, method.step, 0.0
        if (t_end - t0) / method.step > max_steps:
            raise CamdynInputError(
                f"step={method.step:g} needs more than max_steps={max_steps} steps over "
                f"[{t0:g}, {t_end:g}]")
    c0 = _time.process_time()
    raw = _integrate.integrate(m.capsule, method.code, p, codes, pars, y_init, t0, stops, h, h_max,
                               rtol_v, np.ascontiguousarray(atol_vec, dtype=float), int(max_steps))
    cpu = _time.process_time() - c0
    if raw["status"] != 0:
        raise SimulationError(f"{m.name} with {method.name}: {raw['message']} at "
                              f"{m.manifest['time']['name']} = {raw['t_fail']:.6g}")
    values = dict(zip(m.parameter_names, p.tolist()))
    return Result(m, values, p, (codes, pars), chosen, method, raw, cpu)
