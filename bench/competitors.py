"""The contestants: each integrates (4.15) over [0, 1] and [1, 3] for one setting.

A Competitor knows, for a setting x (the step h of RK4, or rtol of an adaptive
method):

    runner(x)  a zero-argument callable doing one whole simulation, the thing timed
    info(x)    one untimed run: (X(1), X'(1), right-hand-side evaluations)

Adaptive methods all use atol = ATOL_FACTOR * rtol on both states (camdyn's
default for CAMSHAFT-1, whose state scales are 1).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Callable

import numpy as np
from scipy.integrate import odeint, solve_ivp

from camdyn.runtime.engine import driver
from camdyn.runtime.core import laws as camlaws
from camdyn.runtime.core.compiled import load
from camdyn.runtime.core.simulator import Simulator, simulate

import yardstick
from problem import FA, MODEL, PARAMS, T_BREAK, T_END, TAU, rhs_dwell, rhs_rise, state_at_break

ATOL_FACTOR = 1e-3
MAX_STEPS = 5_000_000
ODEINT_MXSTEP = 1_000_000
Y0 = np.zeros(2)


@dataclass(frozen=True)
class Competitor:
    key: str
    label: str
    setting: str                     # "h" or "rtol"
    grid: tuple                      # settings swept for the error-vs-time curve
    runner: Callable[[float], Callable[[], object]]
    info: Callable[[float], tuple[float, float, int]]
    family: str                      # "camdyn", "yardstick" or "scipy"


# -- grids ---------------------------------------------------------------------------

def rk4_grid(n_min: int = 20, n_max: int = 10000, per_decade: int = 16) -> tuple:
    """Steps h = 1/n (n equal steps in the rise), n geometric at 16 per decade.

    RK4's error goes as h^4, so 16 steps per decade of n are 4 per decade of error.
    """
    lo, hi = math.log10(n_min), math.log10(n_max)
    ns = sorted({int(round(10 ** (lo + k / per_decade)))
                 for k in range(int((hi - lo) * per_decade) + 1)})
    return tuple(1.0 / n for n in ns)


def rtol_grid(first: int = 3, last: int = 13, per_decade: int = 4) -> tuple:
    """rtol = 10^-3 ... 10^-13 at 4 per decade."""
    return tuple(10.0 ** (-k / per_decade) for k in range(first * per_decade, last * per_decade + 1))


# -- camdyn --------------------------------------------------------------------------

def _camdyn_kwargs(method: str, x: float) -> dict:
    return {"step": x} if method == "rk4" else {"rtol": x}


def camdyn_simulate(method: str, exact: bool = True) -> Competitor:
    """The public call, simulate(...), as a user makes it (Python overhead included); with
    ``exact`` False every step integrated, the dwell too (the like-for-like comparison with
    the yardstick, which integrates it)."""

    def runner(x):
        kw = _camdyn_kwargs(method, x)
        # exact: simulate()'s default (RK4, DOP853 and RKN12 step over the dwell exactly,
        # DP54 integrates it)
        return lambda: simulate(MODEL, PARAMS, T_END, method,
                                exact_segments=None if exact else False, **kw)

    def info(x):
        r = runner(x)()
        return (*state_at_break(r.t, r.y), int(r.stats["n_rhs"]))

    grid = rk4_grid() if method == "rk4" else rtol_grid()
    key, label = f"camdyn-{method}", f"camdyn {method.upper()} simulate()"
    if not exact:
        key, label = key + "-steps", label + ", dwell integrated"
    return Competitor(key, label, "h" if method == "rk4" else "rtol", grid, runner, info, "camdyn")


def model_arguments() -> tuple:
    """(capsule, p, law codes, law parameters) of the benchmark problem, for C-level probes."""
    m = load(MODEL)
    law = camlaws.choose("cycloidal")
    return (m.capsule, m.parameter_vector(PARAMS), np.array([law.code], dtype=np.intc),
            np.array([law.par], dtype=float))


def bare_arguments(method: str, x: float, exact: bool = True) -> tuple:
    """What simulate() hands the compiled loops, prepared once beforehand:
    (the prepared Integrator, p, stops, cap)."""
    kw = _camdyn_kwargs(method, x)
    sim = Simulator(MODEL, T_END, method, exact_segments=None if exact else False, **kw)
    p = sim.model.parameter_vector(PARAMS)
    stops = sim.stops(p)
    if method == "rk4":
        cap = driver.fixed_step_points(0.0, stops, x)
    else:
        n_points = sim.run(PARAMS).t.shape[0]  # the record size simulate() would reserve
        cap = n_points + n_points // 4
    return sim.integrator, p, stops, cap


def camdyn_bare(method: str, exact: bool = True) -> Competitor:
    """The compiled loops alone (Integrator.run), everything prepared; ``exact`` as in
    camdyn_simulate."""

    def runner(x):
        integ, p, stops, cap = bare_arguments(method, x, exact)
        return lambda: integ.run(p, stops, cap)

    def info(x):
        out = runner(x)()
        if out.status != 0:
            raise RuntimeError(driver.STATUS_TEXT[out.status])
        rows = out.rows[:out.n]
        return (*state_at_break(rows[:, 0], rows[:, 1:3]), int(out.n_rhs))

    grid = rk4_grid() if method == "rk4" else rtol_grid()
    return Competitor(f"camdyn-{method}-bare", f"camdyn {method.upper()} compiled loop",
                      "h" if method == "rk4" else "rtol", grid, runner, info, "camdyn")


# -- the yardstick -------------------------------------------------------------------

def yardstick_rk4() -> Competitor:
    """Hand-written compiled RK4 (bench/yardstick.pyx), same steps as camdyn's RK4."""

    def runner(x):
        return lambda: yardstick.rk4(TAU, FA, x, T_END)

    def info(x):
        t, _, x1, v1 = yardstick.rk4(TAU, FA, x, T_END)
        return x1, v1, 4 * (len(t) - 2)

    return Competitor("yardstick", "hand-written RK4 (yardstick)", "h", rk4_grid(), runner, info,
                      "yardstick")


# -- SciPy on a NumPy right-hand side ------------------------------------------------------

def _ivp_pair(method: str, rtol: float):
    atol = ATOL_FACTOR * rtol
    a = solve_ivp(rhs_rise, (0.0, T_BREAK), Y0, method=method, rtol=rtol, atol=atol)
    b = solve_ivp(rhs_dwell, (T_BREAK, T_END), a.y[:, -1], method=method, rtol=rtol, atol=atol)
    return a, b


def scipy_ivp(method: str) -> Competitor:
    """scipy.integrate.solve_ivp, the rise and the dwell as two calls."""

    def runner(x):
        return lambda: _ivp_pair(method, x)

    def info(x):
        a, b = _ivp_pair(method, x)
        if not (a.success and b.success):
            raise RuntimeError(f"solve_ivp {method} failed at rtol={x:g}")
        return float(a.y[0, -1]), float(a.y[1, -1]), int(a.nfev + b.nfev)

    return Competitor(f"ivp-{method}", f"solve_ivp {method}", "rtol", rtol_grid(), runner, info,
                      "scipy")


def _odeint_pair(rtol: float, full_output: bool = False):
    kw = dict(tfirst=True, rtol=rtol, atol=ATOL_FACTOR * rtol, mxstep=ODEINT_MXSTEP,
              full_output=full_output)
    a = odeint(rhs_rise, Y0, [0.0, T_BREAK], **kw)
    ya = a[0] if full_output else a
    b = odeint(rhs_dwell, ya[1], [T_BREAK, T_END], **kw)
    return a, b


def scipy_odeint() -> Competitor:
    """scipy.integrate.odeint (LSODA), the rise and the dwell as two calls."""

    def runner(x):
        return lambda: _odeint_pair(x)

    def info(x):
        (ya, ia), (_, ib) = _odeint_pair(x, full_output=True)
        if ia["message"] != "Integration successful." or ib["message"] != "Integration successful.":
            raise RuntimeError(f"odeint failed at rtol={x:g}: {ia['message']} / {ib['message']}")
        return float(ya[1, 0]), float(ya[1, 1]), int(ia["nfe"][-1] + ib["nfe"][-1])

    return Competitor("odeint", "odeint (LSODA)", "rtol", rtol_grid(), runner, info, "scipy")


# three settings a method, loose, middling and tight, for a quick run (bench/run.py --quick)
THIN_GRIDS = {"h": (1 / 20, 1 / 200, 1 / 2000), "rtol": (1e-4, 1e-7, 1e-10)}


def sweep_groups(thin: bool = False) -> list[list[Competitor]]:
    """The competitors in groups timed side by side; each group shares its grid (with
    ``thin``, three settings of it)."""
    # RK4's bare loop runs the yardstick's steps, the dwell integrated: like for like
    groups = [[camdyn_simulate("rk4"), camdyn_simulate("rk4", exact=False),
               camdyn_bare("rk4", exact=False), yardstick_rk4()],
              [camdyn_simulate("dp54"), camdyn_bare("dp54")],
              [camdyn_simulate("dop853"), camdyn_bare("dop853")],
              [camdyn_simulate("rkn12"), camdyn_bare("rkn12")],
              [scipy_ivp("DOP853")], [scipy_ivp("RK45")], [scipy_odeint()]]
    if thin:
        groups = [[replace(c, grid=THIN_GRIDS[c.setting]) for c in g] for g in groups]
    return groups
