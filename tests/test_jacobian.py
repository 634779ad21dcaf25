"""The generated Jacobians d(dy/dt)/dy, and df/dt with them, against central differences of
the right-hand side.

Every registered model, loaded compiled, at random admissible points: states near the default
initial state, perturbed by a few per cent of each state's manifest "scale", parameters at
their defaults and at a random point inside their ranges; in every cam segment (the cam
argument put in each dwell and at the middle of each piece of the rise, for the cycloid, one
rise piece, and the modified trapezoid, five), and for models with modes in every combination
of the force elements' modes.

df/dt (the Rosenbrock method's f_t) is checked as one more column, time weighed by the model
time in which a time-driven cam argument moves by one (differences of step 4e-4 of that).

Tolerance: 1e-6, relative to the row.  Each entry is weighed by its state's manifest scale s
(states of micrometres and of radians in one matrix): |J_ij - D_ij| s_j <= 1e-6 sum_k |D_ik| s_k
(or 1e-6 of 1e-3 |f_i| where that is larger: see _relative_error), D the central differences of eval_rhs with the steps h_j = 4e-4 s_j and h_j/2, extrapolated
(Richardson).  The check is independent of the code under test: the differences use only
eval_rhs, the compiled right-hand side, whose own correctness the other tests establish; their
error, O(h^4) truncation and O(eps |f|/h) rounding, is about 1e-9 relative or less, while a
wrong term of the symbolic Jacobian (a missing chain-rule factor through the cam input, a wrong
sign) is of relative size 1.  (Plain central differences of step 1e-6 s were tried first: on
the stiff DYNACAM variants (c = 1e6 N/m, shaft states of 1e-5 m) their rounding alone reached
1e-4 in the velocity columns.)  Constrained models are checked in each of their three
formulations (augmented with Baumgarte's terms, partitioned, projection): their Jacobian is
A^-1 d(b - A x)/dy of the augmented system, through the partitioned recovery's chain rule
in formulation 1 (camdyn.derive.dae).  Their right-hand side rounds at up to 2e-7 of its
large terms (the augmented solve of beam5, beam6), which the differences divide by their step:
so the reference there is the best of the differences of steps h_j, 10 h_j and 50 h_j (O(h^4)
truncation at the largest, rounding at the smallest), and the tolerance TOL_CONSTRAINED.

A point where a Piecewise of the right-hand side switches within the difference step (a
contact opening, a stick-slip boundary) is no point of the current mode's Jacobian: a point
whose differences of steps h and h/2 disagree with each other is skipped (and replaced), and the
rejected points are counted so that the check cannot go empty.
"""
import itertools

import numpy as np
import pytest
import sympy as sp

from camdyn.derive.models import REGISTRY
from camdyn.runtime.engine import driver
from camdyn.runtime.core import laws
from camdyn.runtime.core.compiled import load

TOL = 1e-6
LAWS = ("cycloidal", "modified-trapezoid")
POINTS = 2          # random points per segment, mode combination and parameter set
FORMULATIONS = (0.0, 1.0, 2.0)
"""A constrained model's formulations: augmented (Baumgarte), partitioned, projection."""
TOL_CONSTRAINED = 1e-5
"""Measured (best of the three steps, every formulation): 2e-9 or less on pendulum_xy, 7e-9
on beam1-4, 4e-7 on beam5, 2e-6 on beam6, where the differences' rounding still shows (their
error grows like 1/h below the steps used); a wrong term is of relative size 1."""
STEP = 4e-4         # difference step per unit of each state's scale


def _law_arrays(model, key):
    choice = laws.choose(key)
    nf = max(len(model.manifest["cam_families"]), 1)
    return (np.full(nf, choice.code, dtype=np.intc), np.full(nf, choice.par)), choice


def _targets(choice):
    """Dimensionless cam arguments in every segment: both dwells, the middle of each piece."""
    bp = choice.breakpoints()
    return [bp[0] - 0.3] + [(a + b) / 2 for a, b in zip(bp, bp[1:])] + [bp[-1] + 0.4]


def _parameter_sets(model, rng):
    """Defaults, and each parameter scaled by a random factor in [0.8, 1.25] where the range
    allows (the solver switch of constrained models kept)."""
    p0 = model.parameter_vector()
    out = [p0]
    p = p0.copy()
    for k, spec in enumerate(model.manifest["parameters"]):
        if spec["name"] == "formulation" or p0[k] == 0.0:
            continue
        value = p0[k] * rng.uniform(0.8, 1.25)
        lo = -np.inf if spec["low"] is None else spec["low"]
        hi = np.inf if spec["high"] is None else spec["high"]
        if lo < value < hi:
            p[k] = value
    out.append(p)
    return out


def _place_cam(model, p, y, T, choice):
    """(t, y) with the cam argument at T: by time for a time-affine argument, else by the
    state the argument follows (solved from the manifest's argument text); the constrained
    models' periodic profile by its angle."""
    m = model.manifest
    names = model.state_names
    values = {s["name"]: v for s, v in zip(m["parameters"], p)}
    profile = m.get("cam_profile")
    if profile is not None:          # RDFD: rise [0, beta_r), dwell, fall [pi, pi + beta_r), dwell
        beta = values["beta_r"]
        if 0.0 <= T < 1.0:
            angle = beta * T
        elif T < 0.0:
            angle = np.pi + beta * 0.5          # the fall, as the mirror of the rise
        else:
            angle = (beta + np.pi) / 2          # the outer dwell
        # The profile's argument (the beam's theta) is the contact's cam parameter, which the
        # constraints tie to the time: theta = Omega t for a rigid rod, off it by the rod's
        # deflection over r.  Both go to the angle: the state (the augmented formulation
        # evaluates the profile there) and the time.  In the partitioned formulation theta is
        # a dependent coordinate, recovered by Newton's method with the state's value only as
        # its start: at t = 0 it came back near 0 whatever the angle (or, from far starts,
        # on the other branch x_E = d + r, theta near pi), i.e. within ~1e-5 rad of a segment
        # end, where differences of different steps see the profile's switch (and the branch
        # flipped with the start: ~180 relative).
        y[names.index(profile["argument"])] = angle
        return angle / values["Omega"], y
    t = 0.0
    affine = model.cam_time_affine(p)
    for inst, ab in zip(m["cam_instances"], affine):
        if ab is not None:
            a, b = ab
            t = (T - b) / a
            continue
        arg = sp.sympify(inst["argument"], locals={n: sp.Symbol(n) for n in names + list(values)})
        arg = arg.subs({sp.Symbol(k): v for k, v in values.items()})
        state = sorted(arg.free_symbols, key=str)[0]
        y[names.index(state.name)] = float(sp.solve(sp.Eq(arg, T), state)[0])
    return t, y


def _differences(model, p, law, law_par, t, y, modes, h):
    """(f, central, d1, d2): f = eval_rhs at y, the central differences of eval_rhs
    extrapolated from the steps h and h/2 (Richardson), and the plain central differences
    of step h and h/2, column by column."""
    ns = len(y)
    Y = np.repeat(y[None, :], 4 * ns + 1, axis=0)
    for j in range(ns):
        for k, c in enumerate((1.0, -1.0, 0.5, -0.5)):
            Y[1 + k * ns + j, j] += c * h[j]
    F = driver.eval_rhs(model.capsule, p, law, law_par, np.full(4 * ns + 1, t), Y,
                            element_modes=modes)
    f0 = F[0]
    fp, fm, fp2, fm2 = (F[1 + k * ns:1 + (k + 1) * ns] for k in range(4))
    Yp, Ym, Yp2, Ym2 = (Y[1 + k * ns:1 + (k + 1) * ns].diagonal()[:, None] for k in range(4))
    # row j of fp, ...: the state moved in its j-th component; the steps as represented
    d1, d2 = (fp - fm) / (Yp - Ym), (fp2 - fm2) / (Yp2 - Ym2)
    return f0, ((4.0 * d2 - d1) / 3.0).T, d1.T, d2.T


def _time_scale(model, p, y, f) -> float:
    """The "scale" of t in the time column: the shortest model time in which a time-driven cam
    argument a t + b moves by one (1/|a|) or a coordinate moves by its scale at its present
    rate (s_j/|q_j'|: a camshaft turning at omega_s through the explicit time of an ideal
    drive), at most one unit of model time."""
    tc = 1.0
    for ab in model.cam_time_affine(p):
        if ab is not None and ab[0] != 0:
            tc = min(tc, 1.0 / abs(ab[0]))
    s, nq = model.state_scales(), model.manifest["n_q"]
    for j in range(nq):
        if f[j] != 0:
            tc = min(tc, s[j] / abs(f[j]))
    return tc


def _time_differences(model, p, law, law_par, t, y, modes, h):
    """(extrapolated, d1, d2): df/dt by central differences of eval_rhs in t, steps h, h/2."""
    ts = t + np.array([h, -h, h / 2, -h / 2])
    F = driver.eval_rhs(model.capsule, p, law, law_par, ts, np.repeat(y[None, :], 4, axis=0),
                            element_modes=modes)
    d1 = (F[0] - F[1]) / (ts[0] - ts[1])
    d2 = (F[2] - F[3]) / (ts[2] - ts[3])
    return (4.0 * d2 - d1) / 3.0, d1, d2


def _relative_error(J, D, s, f):
    """Largest error of J against D, each entry's as |J_ij - D_ij| s_j relative to its row's
    sum_k |D_ik| s_k (the change of dy_i/dt over a scale step of every state), or where that
    is larger to 1e-3 of the rate |f_i|, or to 1e-8 of the largest row in units of the
    scales: a row that changes by less is below what differences can resolve (their rounding
    is eps |f_i| / h, or that of the terms that cancel in a rate held at zero, as in a
    stuck friction mode)."""
    E = np.abs(J - D) * s[None, :]
    rows = (np.abs(D) * s[None, :]).sum(axis=1)
    sr = s[:len(f)]      # the rows' own scales (a time column adds one to the columns')
    rows = np.maximum(np.maximum(rows, 1e-3 * np.abs(f)), 1e-8 * sr * (rows / sr).max())
    return float((E.max(axis=1) / np.maximum(rows, 1e-300)).max())


def _element_modes(model):
    modes = model.manifest["modes"]
    if not modes:
        return [None]
    return [list(c) for c in itertools.product(*[range(len(md["values"])) for md in modes])]


def _kink(d1, d2, s, f):
    """True when the central differences of steps h and h/2 disagree by more than their
    O(h^2) truncation allows: a switch (a kink of the right-hand side) within the step."""
    return _relative_error(d1, d2, s, f) > 1e-3


def _reference(model, p, law, law_par, t, y, modes, step, timed):
    """(D, scales, f): the central differences at (t, y) with the steps ``step`` times each
    state's scale (and df/dt as one more column where ``timed``), or None where they are not
    finite or see a kink."""
    s = model.state_scales()
    f0, D, D1, D2 = _differences(model, p, law, law_par, t, y, modes, step * s)
    if not (np.all(np.isfinite(f0)) and np.all(np.isfinite(D))) or _kink(D1, D2, s, f0):
        return None
    if not timed:
        return D, s, f0
    # df/dt as one more column, t weighed by its scale
    tc = _time_scale(model, p, y, f0)
    Dt, Dt1, Dt2 = _time_differences(model, p, law, law_par, t, y, modes, step * tc)
    D, D1, D2 = (np.column_stack([a, b]) for a, b in ((D, Dt), (D1, Dt1), (D2, Dt2)))
    se = np.append(s, tc)
    if not np.all(np.isfinite(D)) or _kink(D1, D2, se, f0):
        return None
    return D, se, f0


def _check(model, rng, formulations=(None,), tol=TOL):
    s = model.state_scales()
    # a constrained model's rhs rounds at up to 2e-7 of its large terms (beam5, beam6: the
    # augmented solve), which the differences divide by their step: the better of two steps
    steps = (STEP, 10 * STEP, 50 * STEP) if model.manifest.get("n_constraints") else (STEP,)
    timed = model.manifest.get("time_derivative") == "symbolic"
    worst, checked, skipped = 0.0, 0, 0
    for key in LAWS:
        (law, law_par), choice = _law_arrays(model, key)
        for p_base in _parameter_sets(model, rng):
            for form in formulations:
                p = p_base.copy()
                if form is not None:
                    p[model.parameter_names.index("formulation")] = form
                y0 = model.initial_state(p)
                for T in _targets(choice):
                    for modes in _element_modes(model):
                        got = 0
                        for attempt in range(20 * POINTS):
                            if got == POINTS:
                                break
                            y = y0 + s * rng.normal(0.0, 0.03, size=len(s))
                            t, y = _place_cam(model, p, y, T, choice)
                            found = [_reference(model, p, law, law_par, t, y, modes, step,
                                                timed) for step in steps]
                            found = [r for r in found if r is not None]
                            if not found:
                                skipped += 1
                                continue
                            if timed:
                                J, ft = driver.eval_jacobian(model.capsule, p, law, law_par,
                                                             t, y, element_modes=modes,
                                                             with_time=True)
                                J = np.column_stack([J, ft])
                            else:
                                J = driver.eval_jacobian(model.capsule, p, law, law_par, t,
                                                         y, element_modes=modes)
                            err = min(_relative_error(J, D, se, f0) for D, se, f0 in found)
                            assert err <= tol, (model.name, key, T, modes, form, err)
                            worst = max(worst, err)
                            got += 1
                            checked += 1
                        assert got == POINTS, (f"{model.name}: only {got} smooth points in "
                                               f"segment T={T} modes {modes}")
    return worst, checked, skipped


@pytest.mark.parametrize("name", sorted(REGISTRY))
def test_jacobian_matches_central_differences(name, rng, record_property):
    model = load(name)
    kind = model.manifest["jacobian"]
    constrained = bool(model.manifest.get("n_constraints"))
    assert kind == "symbolic"
    # df/dt (RODAS4's f_t) is derived with J wherever J is
    assert model.manifest["time_derivative"] == kind
    worst, checked, skipped = _check(model, rng, FORMULATIONS if constrained else (None,),
                                     TOL_CONSTRAINED if constrained else TOL)
    record_property("largest_relative_difference", worst)
    print(f"{name}: {checked} points, {skipped} skipped, largest relative difference {worst:.2e}")
    assert checked > 0


def test_partitioned_beam_jacobian_columns():
    """Partitioned, the dependent coordinates (x_E, theta) and their rates are recomputed from
    the independent ones by rhs() (their state values only start Newton's method): their
    columns of the exact Jacobian are zero, so the iteration matrix I - h gamma J is the
    identity there, as it should be for states that f does not read."""
    model = load("beam2")
    p = model.parameter_vector({"formulation": 1.0})
    (law, law_par), _ = _law_arrays(model, "cycloidal")
    y = model.initial_state(p)
    y[model.state_names.index("theta")] = 0.3
    J = driver.eval_jacobian(model.capsule, p, law, law_par, 0.3 / 240.0, y)
    dep = [model.state_names.index(n) for n in ("xE", "theta", "xEd", "thetad")]
    assert np.all(J[:, dep] == 0.0)
    assert np.all(np.isfinite(J)) and np.abs(J).max() > 0
