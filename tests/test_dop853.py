"""Dormand-Prince 8(5,3), the method of Hairer, Norsett & Wanner's DOP853 (Solving ODEs I,
sec. II.10), compiled in runtime/engine/loops.pxi with its tableau in dop853.pxd.

The tableau is checked by order conditions and by the order it shows on a nonlinear problem
(NumPy steps against SciPy's independent DOP853 at rtol 1e-13); the compiled loop against the
closed-form free vibration of the one-DOF model, against DP54 at rtol 1e-13, for its dense
output, its events, its stiffness test and its economy at tight tolerances.
"""
import json
import math
import subprocess
import sys

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.core.simulator import Simulator, simulate
from camdyn.runtime.engine import driver

from .test_exact_segments import _free_vibration

TAB = driver.dop853_tableau()
B = TAB["A"][12, :12]


def test_rows_sum_to_the_nodes():
    """sum_j a_ij = c_i for every stage, the dense-output stages included (1e-14)."""
    A, c = TAB["A"], TAB["c"]
    assert np.allclose(A.sum(axis=1), c, rtol=0, atol=1e-14)


@pytest.mark.parametrize("k", range(1, 9))
def test_weights_integrate_polynomials_to_degree_7(k):
    """The quadrature conditions of order 8: sum_i b_i c_i^(k-1) = 1/k, k = 1..8 (1e-14)."""
    assert abs(B @ TAB["c"][:12] ** (k - 1) - 1.0 / k) < 1e-14


def test_error_estimators_vanish_on_low_degrees():
    """e5 = b - b^(5) and e3 = b - b^(3) compare solutions of orders 8, 5 and 3: their
    quadrature sums vanish up to degree 4 and 2 (1e-14), and not beyond, or they would
    estimate nothing."""
    c = TAB["c"][:13]
    for e, order in ((TAB["e5"], 5), (TAB["e3"], 3)):
        sums = [abs(e @ c ** k) for k in range(order + 1)]
        assert max(sums[:order]) < 1e-14
        assert sums[order] > 1e-6


def _pendulum(t, y):
    """A nonlinear, non-autonomous test problem (a driven pendulum)."""
    return np.array([y[1], -np.sin(y[0]) + 0.3 * np.cos(1.3 * t)])


def _step(t, y, h):
    """One step of the tableau in NumPy: the new point and the dense-output function."""
    A, c, d = TAB["A"], TAB["c"], TAB["d"]
    K = np.zeros((16, 2))
    K[0] = _pendulum(t, y)
    for i in range(1, 12):
        K[i] = _pendulum(t + c[i] * h, y + h * A[i, :i] @ K[:i])
    y1 = y + h * B @ K[:12]
    K[12] = _pendulum(t + h, y1)
    for i in range(13, 16):
        K[i] = _pendulum(t + c[i] * h, y + h * A[i, :i] @ K[:i])
    v = [y1 - y, h * K[0] - (y1 - y)]
    v.append((y1 - y) - h * K[12] - v[1])
    v.extend(h * d @ K)

    def dense(s):
        acc = np.zeros(2)
        for j in range(len(v) - 1, 0, -1):
            acc = v[j] + (s if j % 2 == 0 else 1 - s) * acc
        return y + s * (v[0] + (1 - s) * acc)
    return y1, dense


def _reference(t0, t1, y0):
    return solve_ivp(_pendulum, (t0, t1), y0, method="DOP853", rtol=1e-13, atol=1e-15,
                     dense_output=True).sol


def test_order_eight_and_dense_output_of_order_seven():
    """Halving the step divides the error of a step by about 2^9 (local error of an order-8
    method) and of the dense output at mid-step by about 2^8 (order 7); accepted: more than
    2^8.3 and 2^7.3."""
    y0 = np.array([1.0, 0.2])
    ref = _reference(0.0, 1.0, y0)
    errs, dense_errs = [], []
    for h in (0.4, 0.2):
        y1, dense = _step(0.0, y0, h)
        errs.append(np.abs(y1 - ref(h)).max())
        dense_errs.append(np.abs(dense(0.5) - ref(0.5 * h)).max())
    assert errs[0] / errs[1] > 2 ** 8.3
    assert dense_errs[0] / dense_errs[1] > 2 ** 7.3


@pytest.mark.parametrize("q", [0.0, 0.1])
def test_the_compiled_loop_follows_the_closed_form(q):
    """The one-DOF dwell integrated step by step (exact steps off): every recorded point and
    3001 dense-output samples within 1e-9 of the closed-form free vibration at rtol 1e-10."""
    tau, y0 = 0.15, [1.02, -0.3]
    res = Simulator("one_dof", 3.0, "dop853", rtol=1e-10, t0=1.0, y0=y0,
                    exact_segments=False).run({"tau": tau, "q": q})
    x, v = _free_vibration(tau, q, *y0, res.t - 1.0)
    w = 2 * math.pi / tau
    assert np.abs(res["X"] - x).max() < 1e-9 and np.abs(res["Xd"] - v).max() < 1e-9 * w
    T = np.linspace(1.0, 3.0, 3001)
    s = res.sample(T)
    x, v = _free_vibration(tau, q, *y0, T - 1.0)
    assert np.abs(s["X"] - x).max() < 1e-9 and np.abs(s["Xd"] - v).max() < 1e-9 * w
    assert res.stats["n_rhs"] > 100


def test_camshaft1_agrees_with_dp54_and_needs_fewer_calls():
    """CAMSHAFT-1 (4.15), tau 0.15, Fa 2 over [0, 3]: at rtol 1e-12 DOP853's dense output is
    within 1e-10 of DP54 at rtol 1e-13 everywhere; at rtol 1e-10 it needs less than half the
    right-hand-side calls DP54 needs at rtol 1e-10 for no larger an error."""
    p = {"tau": 0.15, "Fa": 2.0}
    ref = simulate("camshaft1", p, 3.0, "dp54", rtol=1e-13, exact_segments=False)
    T = np.linspace(0.0, 3.0, 3001)
    r = ref.sample(T)
    a = simulate("camshaft1", p, 3.0, "dop853", rtol=1e-12, exact_segments=False).sample(T)
    assert max(np.abs(a[k] - r[k]).max() for k in ("X", "Xd")) < 1e-10
    runs = {m: simulate("camshaft1", p, 3.0, m, rtol=1e-10, exact_segments=False)
            for m in ("dp54", "dop853")}
    err = {m: max(np.abs(run.sample(T)[k] - r[k]).max() for k in ("X", "Xd"))
           for m, run in runs.items()}
    assert runs["dop853"].stats["n_rhs"] * 2 < runs["dp54"].stats["n_rhs"]
    assert err["dop853"] <= err["dp54"]


def test_events_land_where_dp54_puts_them():
    """CAMSHAFT-2's events (its cam segments follow the shaft angle, a state): DOP853 at
    rtol 1e-11 finds the same events as DP54 at rtol 1e-12, at the same times to 1e-8, and
    ends in the same state to 1e-8."""
    p = {}
    a = simulate("camshaft2", p, 3.0, "dop853", rtol=1e-11)
    b = simulate("camshaft2", p, 3.0, "dp54", rtol=1e-12)
    assert a.stats["n_events"] == b.stats["n_events"] > 0
    ta = a.t[:-1][np.diff(a.t) == 0]      # an event is recorded twice (left and right limit)
    tb = b.t[:-1][np.diff(b.t) == 0]
    assert len(ta) == len(tb) and np.abs(ta - tb).max() < 1e-8
    assert np.abs(a.y[-1] - b.y[-1]).max() < 1e-8


def test_stiffness_test_fires_on_a_stiff_dwell_only():
    """One-DOF nearly critically damped (q = 0.99): once the vibration has died out in the
    dwell, rtol 1e-6 lets the step grow until h |lambda| reaches DOP853's boundary (about 6):
    stiff by Hairer's definition, noted at a time in the dwell.  Undamped, never."""
    res = simulate("one_dof", {"tau": 0.05, "q": 0.99}, 3.0, "dop853", rtol=1e-6,
                   exact_segments=False)
    assert res.stiff_from_T is not None and 1.0 < res.stiff_from_T < 3.0
    assert simulate("one_dof", {"tau": 0.05}, 3.0, "dop853", rtol=1e-6,
                    exact_segments=False).stiff_from_T is None


def test_an_event_cut_keeps_the_step_extension():
    """A step cut at an event keeps the whole step's degree-7 extension on its shortened part
    (its extras refitted, dense.pxd): DOP853's dense output of CAMSHAFT-2 at rtol 1e-11 within
    1e-8 of DP54's at rtol 1e-12 at 2001 times, the steps cut at events included."""
    a = simulate("camshaft2", {}, 3.0, "dop853", rtol=1e-11)
    b = simulate("camshaft2", {}, 3.0, "dp54", rtol=1e-12)
    T = np.linspace(0.0, 3.0, 2001)
    sa, sb = a.sample(T), b.sample(T)
    for name in a.state_names:
        assert np.abs(sa[name] - sb[name]).max() < 1e-8 * max(1.0, np.abs(sb[name]).max()), name


@pytest.mark.parametrize("exact", [False, True])
def test_dense_output_on_first_use_takes_the_same_steps(exact):
    """CAMSHAFT-1 (4.15), tau 0.15, Fa 2, rtol 1e-9, with the dense output left to its first
    use (the default) and computed as the run goes: the same recorded points bit for bit;
    three right-hand-side calls fewer for every integrated step; then the record, the
    dense output at 601 times and U0 read off it the same to rounding (1e-15)."""
    p, T = {"tau": 0.15, "Fa": 2.0}, np.linspace(0.0, 3.0, 601)
    runs = {d: Simulator("camshaft1", 3.0, "dop853", rtol=1e-9, exact_segments=exact,
                         dense_output=d).run(p) for d in (False, True)}
    lean, full = runs[False], runs[True]
    assert np.array_equal(lean.t, full.t) and np.array_equal(lean.y, full.y)
    assert np.array_equal(lean.f, full.f)
    # exact: the rise's steps alone are integrated, one a recorded point before T = 1
    steps = full.stats["n_steps"] if not exact else int(np.count_nonzero(full.t < 1.0))
    assert full.stats["n_rhs"] - lean.stats["n_rhs"] == 3 * steps > 0
    assert np.isnan(lean._rows[:-1, 5:]).any() and not np.isnan(full.record).any()
    assert np.abs(lean.record - full.record).max() < 1e-15
    sl, sf = lean.sample(T), full.sample(T)
    assert max(np.abs(sl[k] - sf[k]).max() for k in ("X", "Xd")) < 1e-15


def test_a_model_with_events_makes_its_dense_output_where_an_event_crossed():
    """CAMSHAFT-2 locates its events on the dense output: with it left out, a run still makes
    it on the steps where an event crossed, and on no other; the same steps bit for bit, three
    calls fewer on each other step.  The rest is made on first use, step by step from the
    recorded starts (16 calls a step): bit for bit the record of the run that made it all."""
    lean, full = (Simulator("camshaft2", 3.0, "dop853", rtol=1e-8, dense_output=d).run({})
                  for d in (False, True))
    ns = len(full.state_names)
    assert np.array_equal(lean._rows[:, :1 + 2 * ns], full._rows[:, :1 + 2 * ns])
    left_out = np.isnan(lean._rows[:, 1 + 2 * ns])
    steps = np.flatnonzero(np.diff(full.t) > 0)
    assert 0 < np.count_nonzero(~left_out[steps]) < 0.2 * steps.size   # the events' steps
    # the left-out rows carry their step's length, from which they are made again
    h = lean._rows[left_out, 2 + 2 * ns]
    assert np.abs(h - np.diff(full.t)[left_out[:-1]]).max() <= 1e-15 * full.t[-1]
    assert full.stats["n_rhs"] - lean.stats["n_rhs"] == 3 * np.count_nonzero(left_out)
    assert lean.stats["n_events"] == full.stats["n_events"] > 0
    assert np.array_equal(lean.record, full.record)
    assert lean.stats["n_rhs_dense_output"] == 16 * np.count_nonzero(left_out)


def test_sampling_makes_the_dense_output_of_the_sampled_steps_only():
    """A DOP853 run of CAMSHAFT-1 (tau 0.15, Fa 2; the dwell integrated, not stepped over)
    with its dense output left out, sampled at five times: five steps made again (80 calls),
    the values bit for bit those of the run that made it all, the other steps still left
    out."""
    p = {"tau": 0.15, "Fa": 2.0}
    lean, full = (Simulator("camshaft1", 3.0, "dop853", rtol=1e-9, exact_segments=False,
                            dense_output=d).run(p) for d in (False, True))
    T = np.array([0.1234, 0.5, 0.98765, 1.7, 2.9])
    a, b = lean.sample(T), full.sample(T)
    assert all(np.array_equal(a[k], b[k]) for k in b)
    assert lean.stats["n_rhs_dense_output"] == 16 * 5
    ns = len(lean.state_names)
    steps = np.diff(lean.t) > 0            # a stop's two rows make no step
    assert np.count_nonzero(~np.isnan(lean._rows[:-1, 1 + 2 * ns][steps])) == 5


def test_dense_output_must_be_true_or_false():
    with pytest.raises(CamdynInputError, match="dense_output must be True or False"):
        Simulator("camshaft1", 3.0, "dop853", dense_output="yes")


def _camdyn(*args):
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args],
                          capture_output=True, text=True)


def test_cli_takes_dop853():
    """`camdyn residual --method dop853` answers with its error estimate, like dp54."""
    p = _camdyn("residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2",
                   "--method", "dop853", "--rtol", "1e-9", "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    ref = json.loads(_camdyn("residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2",
                                "--rtol", "1e-12", "--json").stdout)
    assert out["method"] == "dop853" and out["warnings"] == []
    assert 0 < out["U0_error"] < 1e-9
    assert abs(out["U0"] - ref["U0"]) <= 10 * out["U0_error"]


def test_a_compiled_sweep_scans_dop853s_sparse_record_densely_enough():
    """DOP853 records about 8 points a period at rtol 1e-9 (DP54 about 87): the compiled
    sweep's scan samples its steps as densely as DP54's in the dwell and 18 times a period in
    the rise (runtime/targets/model_target.py, scan_density), so that its figures equal those
    read off each run by the Python path (residual(), 12 samples a step) to 1e-7 of their
    scale, times included, on fig. 4.11's fastest taus, where every third point alone once
    missed the deepest trough by 0.1 in T, and at tau = 0.2, whose two deepest troughs differ
    by 6e-8 of their depth (the recorded points alone took the shallower one)."""
    from camdyn.runtime.measure.residual import residual
    from camdyn.runtime.studies import sweep as sw
    from camdyn.runtime.targets.model_target import ModelTarget

    taus = [0.06, 0.0883394834, 0.1146394856, 0.2]
    target = ModelTarget.of("camshaft1", t_end=3.0, method="dop853", rtol=1e-9)
    res = sw.sweep(target, {"Fa": [0.0, 3.0], "tau": taus}, jobs=1, progress=False,
                   estimate=False)
    cols = res.columns
    for j in range(len(cols["tau"])):
        p = {"Fa": float(cols["Fa"][j]), "tau": float(cols["tau"][j])}
        f = residual(simulate("camshaft1", p, 3.0, "dop853", rtol=1e-9))
        for name in ("U0", "U0dd", "Xdd_min_rise"):
            ref = getattr(f, name)
            assert abs(cols[name][j] - ref) <= 1e-7 * max(abs(ref), 1.0), (p, name)
        assert abs(cols["T_at_Xdd_min"][j] - f.T_at_Xdd_min) <= 1e-6, p


def test_a_figure_on_large_left_out_steps_makes_them_and_equals_the_full_run_s():
    """CAMSHAFT-1 (tau 0.15, Fa 2) at rtol 1e-4, the dwell integrated in 71 steps: the cubic
    Hermite interpolant is far off there, so the extreme of |U| over the dwell makes the
    left-out steps and equals, value, instant and sampling error bit for bit, the one found
    on the run that made its dense output.  Allowed to keep the Hermite scan (hermite_tol 1),
    it finds the same peak to within the sampling error it then reports."""
    from camdyn.runtime.measure.extremes import extreme

    p = {"tau": 0.15, "Fa": 2.0}
    lean, full, loose = (Simulator("camshaft1", 3.0, "dop853", rtol=1e-4, exact_segments=False,
                                   dense_output=d).run(p) for d in (False, True, False))
    kw = dict(absolute=True, minimum=False, per_step=4, candidates=4)
    a, b = (extreme(r, "U", 1.0, 3.0, **kw) for r in (lean, full))
    assert (a.value, a.at, a.sampling_error) == (b.value, b.at, b.sampling_error)
    c = extreme(loose, "U", 1.0, 3.0, hermite_tol=1.0, **kw)
    assert loose.stats["n_rhs_dense_output"] < lean.stats["n_rhs_dense_output"]
    assert abs(c.value - b.value) <= c.sampling_error and c.sampling_error > 0
