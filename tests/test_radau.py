"""Radau IIA of order 5, the method of Hairer & Wanner's RADAU5 (Solving ODEs II, sec. IV.8),
compiled in runtime/engine/loops.pxi with its constants in radau.pxd.

The constants are checked against the Butcher tableau; the compiled loop against the closed-form
free vibration of the one-DOF model (order 5 on fixed steps, adaptive accuracy), against SciPy's
Radau at tight tolerances on two classic stiff problems (Van der Pol at mu = 1000, Robertson's
reaction) built as model files, against DP54 on stiff camdyn models and on a model with events;
--method radau5 on the commands.  Each tolerance is stated with the value measured when it was
set.  Step counts are compared, never wall time.
"""
import json
import math
import textwrap

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from camdyn.runtime import cli
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.core.methods import ADAPTIVE, METHODS, RADAU5, make
from camdyn.runtime.core.simulator import Simulator, simulate
from camdyn.runtime.engine import driver

from .test_exact_segments import _free_vibration
from .test_rodas import _main, _rel_err, _simulate_json

K = driver.radau_constants()
S6 = math.sqrt(6.0)
# the Butcher tableau of Radau IIA of order 5 (Hairer & Wanner II, Table IV.5.6)
A = np.array([[(88 - 7 * S6) / 360, (296 - 169 * S6) / 1800, (-2 + 3 * S6) / 225],
              [(296 + 169 * S6) / 1800, (88 + 7 * S6) / 360, (-2 - 3 * S6) / 225],
              [(16 - S6) / 36, (16 + S6) / 36, 1 / 9]])


def test_nodes_and_error_weights_in_closed_form():
    """c = ((4 - sqrt 6)/10, (4 + sqrt 6)/10, 1) and the error estimator's weights
    (-(13 + 7 sqrt 6)/3, (-13 + 7 sqrt 6)/3, -1/3) (RADAU5's DD1-DD3), to 1e-15; the rows of
    A sum to c."""
    assert np.allclose(K["c"], [(4 - S6) / 10, (4 + S6) / 10, 1.0], rtol=0, atol=1e-15)
    assert np.allclose(K["dd"], [-(13 + 7 * S6) / 3, (-13 + 7 * S6) / 3, -1 / 3], rtol=0,
                       atol=1e-14)
    assert np.allclose(A.sum(axis=1), K["c"], rtol=0, atol=1e-15)


def test_transformation_diagonalizes_the_inverse_tableau():
    """TI = T^-1 and TI A^-1 T = [[gamma, 0, 0], [0, alpha, -beta], [0, beta, alpha]] with the
    loop's gamma, alpha, beta, to 1e-13 (the transformed Newton systems are exactly those)."""
    T, TI = K["T"], K["TI"]
    assert np.abs(TI @ T - np.eye(3)).max() < 1e-14
    g, a, b = K["gamma"], K["alpha"], K["beta"]
    block = np.array([[g, 0, 0], [0, a, -b], [0, b, a]])
    assert np.abs(TI @ np.linalg.inv(A) @ T - block).max() < 1e-13
    ev = np.sort_complex(np.linalg.eigvals(np.linalg.inv(A)))
    assert np.allclose(ev, np.sort_complex([g, a + 1j * b, a - 1j * b]), rtol=1e-15, atol=1e-14)


def test_error_weights_annihilate_low_degrees():
    """The estimate (gamma/h - J)^-1 (f(y0) + sum dd_i z_i/h) compares the step with one of
    order 3: for y' = p(t), p of degree <= 2 (z_i the exact integrals of p over [0, c_i h]),
    the bracket vanishes (1e-13); for degree 3 it does not, or it would estimate nothing."""
    c, dd = K["c"], K["dd"]
    for deg in range(4):
        # y' = t^deg, y(0) = 0, h = 1: z_i = c_i^(deg + 1)/(deg + 1), f(y0) = 0^deg
        z = c ** (deg + 1) / (deg + 1)
        r = (1.0 if deg == 0 else 0.0) + dd @ z
        if deg < 3:
            assert abs(r) < 1e-13, (deg, r)
        else:
            assert abs(r) > 1e-3, (deg, r)


@pytest.mark.parametrize("n", [1, 4, 6, 9])
@pytest.mark.parametrize("kind", ["real", "complex"])
def test_small_lu_against_numpy(n, kind):
    """The LU routines of linalg.pxd the implicit loops factor with (the real one for RODAS4 and
    RADAU5's gamma/h - J, the complex one for RADAU5's (alpha + i beta)/h - J), on both sides of
    LA_SMALL = 6 (loops over the whole square, unrolled, up to it; over the triangle above it):
    the solution of numpy.linalg.solve to 1e-12 relative (measured 4e-16), on matrices whose
    leading entries vanish so that every row must be pivoted; a singular one (a zero column) is
    refused."""
    rng = np.random.default_rng(n)
    A = rng.standard_normal((n, n)) + (1j * rng.standard_normal((n, n)) if kind == "complex" else 0)
    A[:, 0] *= 1e-3
    A[0, 0] = 0.0
    A += 3.0 * np.eye(n)[::-1]          # well conditioned, the large entries off the diagonal
    b = rng.standard_normal(n) + (1j * rng.standard_normal(n) if kind == "complex" else 0)
    x = driver.solve_lu(A, b)
    assert np.iscomplexobj(x) == (kind == "complex")
    ref = np.linalg.solve(A, b)
    assert np.max(np.abs(x - ref)) <= 1e-12 * np.max(np.abs(ref))
    A[:, -1] = 0.0
    assert driver.solve_lu(A, b) is None


def test_fixed_step_ladder_shows_order_five():
    """The one-DOF dwell (linear: the simplified Newton iteration is exact there) from T = 1
    with steps held at h (first step = max step = h, a tolerance that accepts every step):
    halving h divides the error at T = 3 against the closed form by 2^p.  Measured p = 4.99,
    5.02, 5.01 for 80 -> 160 -> 320 -> 640 steps (h omega = 1.05 ... 0.13; errors 5.8e-8 ...
    1.8e-12); asserted 4.7 < p < 5.3."""
    tau, q, y0 = 0.15, 0.1, [1.02, -0.3]
    x_end, _ = _free_vibration(tau, q, *y0, 2.0)
    errs = []
    for n in (80, 160, 320, 640):
        h = 2.0 / n
        r = Simulator("one_dof", 3.0, RADAU5(rtol=0.5, atol=1.0, first_step=h, max_step=h),
                      t0=1.0, y0=y0, exact_segments=False).run({"tau": tau, "q": q})
        assert r.stats["n_rejected"] == 0 and r.stats["n_steps"] == n
        errs.append(abs(r.y[-1, 0] - x_end))
    p = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert np.all((p > 4.7) & (p < 5.3)), p


@pytest.mark.parametrize("q", [0.0, 0.1])
def test_the_adaptive_loop_follows_the_closed_form(q):
    """The one-DOF dwell at rtol 1e-9 (exact steps off): every recorded point within 1e-11
    and 3001 samples of the dense output within 1e-10 of the closed form (measured 7e-13 and
    6e-14 at the points, the samples of the quintic over three points the same; the cubic
    Hermite interpolant's were 2.2e-11 and 1.6e-10)."""
    tau, y0 = 0.15, [1.02, -0.3]
    res = Simulator("one_dof", 3.0, "radau5", rtol=1e-9, t0=1.0, y0=y0,
                    exact_segments=False).run({"tau": tau, "q": q})
    w = 2 * math.pi / tau
    x, v = _free_vibration(tau, q, *y0, res.t - 1.0)
    assert np.abs(res["X"] - x).max() < 1e-11 and np.abs(res["Xd"] - v).max() < 1e-11 * w
    T = np.linspace(1.0, 3.0, 3001)
    s = res.sample(T)
    x, v = _free_vibration(tau, q, *y0, T - 1.0)
    assert np.abs(s["X"] - x).max() < 1e-10 and np.abs(s["Xd"] - v).max() < 1e-10 * w


def test_error_follows_rtol_on_a_smooth_model():
    """CAMSHAFT-1 (tau 0.3, Fa 0.5), one rise and dwell to T = 3: the error of X against DP54
    at rtol 1e-12 stays below rtol and falls at least 20-fold a step of 100 in rtol (measured
    1.2e-5, 2.8e-7, 2.3e-9 at rtol 1e-4, 1e-6, 1e-8)."""
    T = np.linspace(0.0, 3.0, 301)
    ref = simulate("camshaft1", {"tau": 0.3, "Fa": 0.5}, 3.0, "dp54", rtol=1e-12).sample(T)["X"]
    errs = []
    for rtol in (1e-4, 1e-6, 1e-8):
        r = simulate("camshaft1", {"tau": 0.3, "Fa": 0.5}, 3.0, "radau5", rtol=rtol)
        errs.append(np.abs(r.sample(T)["X"] - ref).max())
        assert errs[-1] < rtol
    assert errs[1] < errs[0] / 20 and errs[2] < errs[1] / 20


VDP = '''
"""Van der Pol's oscillator, y1' = y2, y2' = mu (1 - y1^2) y2 - y1."""
from camdyn.derive.model import FirstOrder, Model, Parameter, time
import sympy as sp

t = time("t")
mu = Parameter("mu", 1000.0, "1", "stiffness parameter")


def build():
    y1, y2 = sp.Function("y1", real=True)(t), sp.Function("y2", real=True)(t)
    return Model(name="vdp", title="Van der Pol", reference="Hairer & Wanner II, sec. IV.1",
                 doc=__doc__, time=t, time_unit="s", coordinates=(), kinetic=sp.Integer(0),
                 potential=sp.Integer(0), parameters=(mu,), outputs=(),
                 first_order=(FirstOrder("y1", "1", "position", y2, initial=2.0),
                              FirstOrder("y2", "1", "velocity",
                                         mu.symbol * (1 - y1 ** 2) * y2 - y1, scale=1000.0)))
'''

ROBER = '''
"""Robertson's chemical reaction (Hairer & Wanner II, sec. IV.1, (1.4))."""
from camdyn.derive.model import FirstOrder, Model, Parameter, time
import sympy as sp

t = time("t")
k1 = Parameter("k1", 0.04, "1/s", "slow reaction")
k2 = Parameter("k2", 3e7, "1/s", "fast reaction")
k3 = Parameter("k3", 1e4, "1/s", "moderate reaction")


def build():
    a, b, c = (sp.Function(n, real=True)(t) for n in ("a", "b", "c"))
    r1, r2, r3 = k1.symbol * a, k2.symbol * b ** 2, k3.symbol * b * c
    return Model(name="rober", title="Robertson", reference="Hairer & Wanner II, sec. IV.1",
                 doc=__doc__, time=t, time_unit="s", coordinates=(), kinetic=sp.Integer(0),
                 potential=sp.Integer(0), parameters=(k1, k2, k3), outputs=(),
                 first_order=(FirstOrder("a", "1", "species A", -r1 + r3, initial=1.0),
                              FirstOrder("b", "1", "species B", r1 - r2 - r3, scale=1e-4),
                              FirstOrder("c", "1", "species C", r2)))
'''


@pytest.fixture(scope="module")
def model_files(tmp_path_factory):
    """The two stiff classics as model files, built into an empty cache of their own."""
    from camdyn.runtime.core import ondemand

    folder = tmp_path_factory.mktemp("stiff")
    mp = pytest.MonkeyPatch()
    mp.setenv("CAMDYN_CACHE_DIR", str(folder / "cache"))
    try:
        out = {}
        for name, text in (("vdp", VDP), ("rober", ROBER)):
            path = folder / f"{name}.py"
            path.write_text(textwrap.dedent(text))
            out[name] = ondemand.model_file(str(path))
        yield out
    finally:
        mp.undo()


def test_van_der_pol_mu_1000_against_scipy_radau(model_files):
    """Van der Pol at mu = 1000 over [0, 3000] (nearly two relaxation periods, each with two
    jumps of y2 ~ 1e3 over dt ~ 1e-3): from radau5 at rtol 1e-9 (atol 1e-12), y1 at t = 3000
    within 1e-8 and at 301 samples within 1e-7 of SciPy's Radau at rtol 1e-12 (measured 2.4e-10
    and 2.4e-9), in 100 times fewer steps than DP54 at rtol 1e-6 (which takes 234,941 over the
    first tenth of the run; radau5 5,078 over all of it)."""
    m = model_files["vdp"]
    mu = 1000.0

    def f(t, y):
        return [y[1], mu * (1 - y[0] ** 2) * y[1] - y[0]]

    def jac(t, y):
        return [[0.0, 1.0], [-2 * mu * y[0] * y[1] - 1.0, mu * (1 - y[0] ** 2)]]

    T = np.linspace(0.0, 3000.0, 301)
    ref = solve_ivp(f, (0.0, 3000.0), [2.0, 0.0], method="Radau", rtol=1e-12, atol=1e-12,
                    jac=jac, dense_output=True)
    assert ref.success
    r = Simulator(m, 3000.0, RADAU5(rtol=1e-9, atol=1e-12)).run({})
    assert abs(r.y[-1, 0] - ref.y[0, -1]) < 1e-8
    assert np.abs(r.sample(T)["y1"] - ref.sol(T)[0]).max() < 1e-7
    d = Simulator(m, 300.0, "dp54", rtol=1e-6, max_steps=10_000_000).run({})
    assert r.stats["n_steps"] * 100 < d.stats["n_steps"] * 10      # dp54 over a tenth


def test_robertson_against_scipy_radau(model_files):
    """Robertson's reaction over [0, 1e5] (rates 0.04, 3e7, 1e4: eigenvalues down to -1e4 while
    the solution changes over decades of t), radau5 at rtol 1e-6 (the state scales give b the
    absolute tolerance 1e-13): the three concentrations at t = 1e5 within 1e-9 of SciPy's
    Radau at rtol 1e-12, b (~ 1e-7 there) within 1e-6 relative (measured 1.9e-11 and 1.1e-9,
    in 200 steps), and a + b + c = 1 to 1e-13 (measured 9e-16: the simplified Newton
    iteration keeps linear invariants, e^T J = 0)."""
    m = model_files["rober"]

    def f(t, y):
        a, b, c = y
        return [-0.04 * a + 1e4 * b * c, 0.04 * a - 3e7 * b * b - 1e4 * b * c, 3e7 * b * b]

    ref = solve_ivp(f, (0.0, 1e5), [1.0, 0.0, 0.0], method="Radau", rtol=1e-12,
                    atol=[1e-14, 1e-18, 1e-14])
    assert ref.success
    r = Simulator(m, 1e5, RADAU5(rtol=1e-6)).run({})
    assert np.abs(r.y[-1] - ref.y[:, -1]).max() < 1e-9
    assert r.y[-1, 1] == pytest.approx(ref.y[1, -1], rel=1e-6)
    assert abs(r.y[:, :3].sum(axis=1) - 1.0).max() < 1e-13


@pytest.mark.parametrize("params", [{"c3": 1e6}, {"c2": 1e4, "c3": 1e6}])
def test_stiff_chain_far_fewer_steps(params):
    """chain3 with a spring 1e6 (1e4) times the others at rtol 1e-6: radau5 (L-stable) in 100
    times fewer steps than DP54, its states within 1e-4 (relative to each state's range) of
    DP54 at rtol 1e-12 (measured 638 and 589 steps against 267,661 and 286,133, errors
    1.2e-6, 5.2e-7)."""
    T = np.linspace(0.0, 3.0, 601)
    ref = simulate("chain3", params, 3.0, "dp54", rtol=1e-12)
    d = simulate("chain3", params, 3.0, "dp54", rtol=1e-6)
    r = simulate("chain3", params, 3.0, "radau5", rtol=1e-6)
    assert r.stats["n_steps"] * 100 < d.stats["n_steps"]
    assert _rel_err("chain3", r, ref, T) < 1e-4


def test_stiff_first_order_states():
    """motor2 with an electrical time constant of 1e-6 against t_m = 0.1 (first-order states):
    100 times fewer steps than DP54 at rtol 1e-6, error < 1e-5 against DP54 at 1e-12
    (measured 237 steps against 302,394, error 2.8e-7)."""
    T = np.linspace(0.0, 1.0, 601)
    p = {"T_el": 1e-6}
    ref = simulate("motor2", p, 1.0, "dp54", rtol=1e-12)
    d = simulate("motor2", p, 1.0, "dp54", rtol=1e-6)
    r = simulate("motor2", p, 1.0, "radau5", rtol=1e-6)
    assert r.stats["n_steps"] * 100 < d.stats["n_steps"]
    assert _rel_err("motor2", r, ref, T) < 1e-5


def test_jacobian_and_lu_are_kept_across_steps():
    """The roller on its contact spring (kappa 1000, zeta 0.1, the roller's states out of the
    error control) at rtol 1e-6: RADAU5 keeps its Jacobian while the Newton iteration contracts
    fast and its LU factors while the step stays within 1-1.2 times the factored one: fewer
    than 0.1 Jacobians and 0.5 LU factorizations a step (measured 32 and 247 in 850 steps),
    where RODAS4 takes one of each every step (866 Jacobians in 866 steps)."""
    from camdyn.runtime.core.methods import RODAS4

    p, atol = {"kappa": 1000.0, "zeta": 0.1}, (("R", 1.0), ("Rd", 1e3))
    s = Simulator("roller_bilateral", 3.0, RADAU5(rtol=1e-6, state_atol=atol)).run(p).stats
    assert s["n_jac"] < 0.1 * s["n_steps"] and s["n_lu"] < 0.5 * s["n_steps"], s
    s = Simulator("roller_bilateral", 3.0, RODAS4(rtol=1e-6, state_atol=atol)).run(p).stats
    assert s["n_jac"] == s["n_steps"] and s["n_lu"] >= s["n_steps"], s


@pytest.mark.parametrize("scene", ["indexing", "spring_loaded"])
def test_scenes_with_events_and_modes(scene):
    """`camdyn simulate SCENE --method radau5` against the same command with dp54 (both at the
    scene's rtol 1e-8): the rise extremes and the residual amplitude within 1e-5 relative, the
    same jump."""
    a, b = _simulate_json(scene, "dp54"), _simulate_json(scene, "radau5")
    assert b["method"] == "radau5" and a["method"] == "dp54"
    for key in ("Xdd_min_rise", "Xdd_max_rise", "U0dd", "U0"):
        assert b[key] == pytest.approx(a[key], rel=1e-5), key
    assert a["jump"] == b["jump"]


def test_roller_contact_events_coincide_with_dp54():
    """The roller in its groove (backlash S = 0.001, kappa = 1000, zeta = 0.1: the contact opens
    and closes, 91 times over [0, 3], each located as an event): radau5 at rtol 1e-10 against
    DP54 at 1e-11 switches the contact as many times, each at the same T within 2e-5, and the
    follower agrees within 1e-7 (measured 2.3e-6 and 5.5e-9; the switch times drift apart as
    the bounces accumulate: DP54 at rtol 1e-8 is 2.8e-3 off, radau5 at 1e-8 8.4e-5)."""
    p = {"kappa": 1000.0, "zeta": 0.1}
    runs = [simulate("roller", p, 3.0, m, rtol=r) for m, r in (("dp54", 1e-11), ("radau5", 1e-10))]
    switches = []
    for r in runs:
        values = r.element_mode("contact")
        switches.append(r.t[1:][values[1:] != values[:-1]])
    assert len(switches[0]) == len(switches[1]) == 91
    assert np.abs(switches[0] - switches[1]).max() < 2e-5
    T = np.linspace(0.0, 3.0, 3001)
    assert np.abs(runs[0].sample(T)["X"] - runs[1].sample(T)["X"]).max() < 1e-7


def test_method_options_and_cli(capsys):
    """radau5 is an adaptive method everywhere a method is named; --method radau5 on residual
    and integrate; a step is refused in one line."""
    assert "radau5" in ADAPTIVE and METHODS["radau5"] is RADAU5
    assert make("radau5", rtol=1e-5) == RADAU5(rtol=1e-5)
    assert RADAU5(rtol=1e-6).tighter() == RADAU5(rtol=1e-8)
    with pytest.raises(CamdynInputError, match="radau5 takes rtol"):
        make("radau5", step=0.01)
    rc, out, err = _main(capsys, "residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2",
                         "--method", "radau5", "--json")
    assert rc == 0, err
    r = json.loads(out)
    assert r["method"] == "radau5" and r["rtol"] == 1e-10
    rc2, out2, _ = _main(capsys, "residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2",
                         "--json")
    assert r["U0"] == pytest.approx(json.loads(out2)["U0"], rel=1e-6)
    rc, out, err = _main(capsys, "integrate", "chain3", "--set", "c3=1e6", "--t-end", "3",
                         "--method", "radau5", "--rtol", "1e-6", "--json")
    assert rc == 0, err
    assert json.loads(out)["method"] == "radau5" and json.loads(out)["n_steps"] < 2000


@pytest.mark.parametrize("method, rtol, gain", [("radau5", 1e-5, 30.0), ("radau5", 1e-7, 100.0),
                                                ("rodas4", 1e-5, 2.0), ("rodas4", 1e-7, 3.0)])
def test_dense_output_is_the_quintic_over_three_points(method, rtol, gain):
    """RADAU5's and RODAS4's dense output (loops.pxi, _rec_three_point): at the middle of every
    step from the second on, the Hermite quintic through value and slope at the step's ends
    and at the start of the step before, computed independently by SciPy's
    KroghInterpolator from the record, to 1e-13 (measured 4e-16); on the first the cubic
    Hermite one.  On the one-DOF dwell it errs no more than the recorded points themselves
    (x 1.05) and far less than the cubic Hermite interpolant of the same points: measured
    gains 61, 450 (RADAU5 at rtol 1e-5, 1e-7) and 2.7, 5.0 (RODAS4, order 4, whose points
    dominate); asserted 30, 100, 2, 3."""
    from scipy.interpolate import CubicHermiteSpline, KroghInterpolator

    tau, q, y0 = 0.15, 0.1, [1.02, -0.3]
    res = Simulator("one_dof", 3.0, method, rtol=rtol, t0=1.0, y0=y0,
                    exact_segments=False).run({"tau": tau, "q": q})
    t, x, f = res.t, res["X"], res.f[:, 0]
    assert np.all(np.diff(t) > 0)
    mid = 0.5 * (t[1:] + t[:-1])
    dense = res.sample(mid)["X"]
    krogh = [KroghInterpolator(np.repeat(t[k - 1:k + 2], 2),
                               [x[k - 1], f[k - 1], x[k], f[k], x[k + 1], f[k + 1]])(mid[k])
             for k in range(1, len(mid))]
    hermite = CubicHermiteSpline(t, x, f)(mid)
    assert np.abs(dense[1:] - krogh).max() < 1e-13
    assert abs(dense[0] - hermite[0]) < 1e-15
    exact = _free_vibration(tau, q, *y0, mid - 1.0)[0]
    at_points = np.abs(x - _free_vibration(tau, q, *y0, t - 1.0)[0]).max()
    err = np.abs(dense - exact).max()
    assert err < 1.05 * at_points
    assert np.abs(hermite - exact).max() > gain * err
