"""The second constrained model: a pendulum in Cartesian coordinates (derive/models/pendulum.py),
generated through the same constraint layer as the beam follower (derive/dae.py,
templates/constrained.pyx.j2).

References, all independent of the generated code: the pendulum's own ODE theta'' =
-(g/L) sin theta integrated by SciPy's solve_ivp (DOP853, rtol 1e-12); the closed-form
period 4 sqrt(L/g) K(sin^2(theta0/2)) of the nonlinear pendulum (scipy.special.ellipk takes
the parameter m = k^2); the rod's tension m L theta'^2 + m g cos theta = m g (3 cos theta -
2 cos theta0) from the energy integral; the critically damped decay Phi (1 + w t) e^(-w t)
that Baumgarte's terms impose on a perturbed constraint; the small-angle solution
theta0 cos(sqrt(g/L) t); the multiplier form solved by hand for M = m I.  Every tolerance
is stated with the figure measured when it was set.
"""
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.special import ellipk

from camdyn.runtime.engine import driver
from camdyn.runtime.core.compiled import load
from camdyn.runtime.core.simulator import simulate

ROOT = Path(__file__).resolve().parents[1]
FORMULATIONS = {"augmented": 0.0, "partitioned": 1.0, "projection": 2.0}
# a heavier bob on a shorter rod than the defaults, so that m, L and g all show in the checks
P = {"m": 2.0, "L": 0.8, "g": 9.81, "theta0": 1.2}
T_END = 8.0


def _run(formulation, rtol=1e-12, t_end=T_END, y0=None, **params):
    return simulate("pendulum_xy", {**P, "formulation": FORMULATIONS[formulation], **params},
                    t_end=t_end, method="dp54", rtol=rtol, y0=y0)


def _run_off_constraint(formulation, y0, t_end, **params):
    """A run that starts where y0 puts it, off the constraint (Simulator(consistent=False)):
    what the formulation itself does with a state off the constraint."""
    from camdyn.runtime.core.simulator import Simulator

    sim = Simulator("pendulum_xy", t_end, "dp54", rtol=1e-12, y0=y0, consistent=False)
    return sim.run({**P, "formulation": FORMULATIONS[formulation], **params})


def _grid(res, n=4001):
    return res.sample(np.linspace(res.t[0], res.t[-1], n))


def _reference(theta0, L, g, t):
    """theta(t), theta'(t) of the pendulum ODE, released at rest from theta0."""
    sol = solve_ivp(lambda _, s: [s[1], -g / L * math.sin(s[0])], (0.0, float(t[-1])),
                    [theta0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14, t_eval=t)
    assert sol.success
    return sol.y


@pytest.mark.parametrize("formulation", sorted(FORMULATIONS))
def test_constraint_residual_stays_small(formulation):
    """|Phi|/L^2 over 8 s (about 4 periods), 4001 points, dp54 at rtol 1e-12: measured
    4.7e-13 augmented (w_B = 10 rad/s), 3.5e-16 partitioned (y recovered by Newton's method
    at every evaluation); asserted 1e-11.  The rate residual of the augmented state,
    Phi'/(L sqrt(g L)) with Phi' = 2 (x x' + y y'): measured 1.5e-12, asserted 1e-11."""
    res = _run(formulation)
    s = _grid(res)
    L = P["L"]
    phi = np.abs(s["Phi"]).max() / L**2
    assert phi < 1e-11
    if formulation != "partitioned":
        rate = 2 * np.abs(s["x"] * s["xd"] + s["y"] * s["yd"]).max() / (L * math.sqrt(P["g"] * L))
        assert rate < 1e-11


def test_baumgarte_drives_a_perturbed_constraint_back():
    """Augmented form from a start off the constraint (y 1e-3 L too low, at rest): Baumgarte's
    terms make Phi'' + 2 w Phi' + w^2 Phi = 0 hold exactly, so with Phi'(0) = 0 the residual is
    Phi(0) (1 + w t) e^(-w t).  At w_B = 10 rad/s over 3 s, 601 points, dp54 at rtol 1e-12:
    measured deviation from that curve 6.7e-10 of |Phi(0)| (3e-13 m^2, the integration
    error), asserted 1e-8; |Phi| after 3 s: 4.1e-11 of |Phi(0)| (the curve gives 2.9e-12),
    asserted 1e-9."""
    L, th0, w = P["L"], P["theta0"], 10.0
    y0 = [L * math.sin(th0), -L * math.cos(th0) - 1e-3 * L, 0.0, 0.0]
    res = _run_off_constraint("augmented", y0, 3.0, w_B=w)
    s = res.sample(np.linspace(0.0, 3.0, 601))
    phi0 = y0[0] ** 2 + y0[1] ** 2 - L**2
    expected = phi0 * (1 + w * s["t"]) * np.exp(-w * s["t"])
    assert np.abs(s["Phi"] - expected).max() < 1e-8 * abs(phi0)
    assert abs(s["Phi"][-1]) < 1e-9 * abs(phi0)


def test_partitioning_recovers_a_perturbed_constraint_at_once():
    """Partitioned form from the same start off the constraint: y is recovered from x by
    Newton's method at every evaluation, so the outputs see Phi = 0 from t = 0 on (measured
    |Phi|/L^2 1.7e-16 over 1 s), asserted 1e-13."""
    L, th0 = P["L"], P["theta0"]
    y0 = [L * math.sin(th0), -L * math.cos(th0) - 1e-3 * L, 0.0, 0.0]
    res = _run_off_constraint("partitioned", y0, 1.0)
    s = res.sample(np.linspace(0.0, 1.0, 201))
    assert np.abs(s["Phi"]).max() / L**2 < 1e-13


@pytest.mark.parametrize("formulation", sorted(FORMULATIONS))
def test_energy_is_conserved_without_damping(formulation):
    """c = 0: E(t) - E(0) over 8 s relative to m g L, dp54 at rtol 1e-12, 4001 points:
    measured 4.6e-13 augmented, 4.7e-12 partitioned; asserted 1e-10.  E(0) is the closed
    form -m g L cos theta0: measured 8.9e-16 relative, asserted 1e-14."""
    res = _run(formulation)
    s = _grid(res)
    m, g, L = P["m"], P["g"], P["L"]
    assert s["E"][0] == pytest.approx(-m * g * L * math.cos(P["theta0"]), rel=1e-14)
    assert np.abs(s["E"] - s["E"][0]).max() / (m * g * L) < 1e-10


def test_energy_balance_with_damping():
    """c = 0.5 N s/m: E(t) + int_0^t c |v|^2 dt = E(0), the dissipated work integrated by
    Simpson's rule on 8001 points of the dense output over 8 s.  Measured imbalance 1.6e-12
    of m g L; asserted 1e-8.  The bob loses 86 % of its energy above the lowest point; asserted
    more than a tenth, else the check would not see the damping."""
    from scipy.integrate import cumulative_simpson

    c = 0.5
    res = _run("augmented", c=c)
    s = _grid(res, 8001)
    m, g, L = P["m"], P["g"], P["L"]
    work = cumulative_simpson(c * (s["xd"] ** 2 + s["yd"] ** 2), x=s["t"], initial=0.0)
    assert np.abs(s["E"] + work - s["E"][0]).max() / (m * g * L) < 1e-8
    assert work[-1] > 0.1 * (s["E"][0] + m * g * L)


@pytest.mark.parametrize("formulation", sorted(FORMULATIONS))
def test_angle_and_rod_force_against_the_pendulum_ode(formulation):
    """theta = atan2(x, -y) against theta'' = -(g/L) sin theta (solve_ivp DOP853, rtol 1e-12)
    at 801 points over 8 s: measured max error 1.9e-12 rad augmented, 2.7e-12 partitioned;
    asserted 1e-9 rad.  The multiplier against the tension of the reference,
    lambda = m g (3 cos theta - 2 cos theta0)/(2 L) (sign: M Q'' + Phi_Q^T lambda = f with
    Phi_Q = [2x, 2y], the rod pulling the bob towards the hinge): measured 3.4e-12 and
    1.0e-11 of m g/(2 L), asserted 1e-8; the output tension equals 2 L lambda: measured
    7.2e-16 of m g, asserted 1e-12."""
    res = _run(formulation)
    t = np.linspace(0.0, T_END, 801)
    s = res.sample(t)
    m, g, L, th0 = P["m"], P["g"], P["L"], P["theta0"]
    theta, _ = _reference(th0, L, g, t)
    assert np.abs(s["theta"] - theta).max() < 1e-9
    lam_ref = m * g * (3 * np.cos(theta) - 2 * math.cos(th0)) / (2 * L)
    assert np.abs(s["lambda_rod"] - lam_ref).max() / (m * g / (2 * L)) < 1e-8
    assert np.abs(s["tension"] - 2 * L * s["lambda_rod"]).max() / (m * g) < 1e-12


@pytest.mark.parametrize("formulation", sorted(FORMULATIONS))
def test_period_is_the_elliptic_closed_form(formulation):
    """The zero crossings of theta (released at rest: at T/4, 3T/4, ...), located by brentq on
    the dense output, against T = 4 sqrt(L/g) K(k^2), k = sin(theta0/2), theta0 = 1.2 rad
    (T = 1.9705 s, 9.8 % above the small-angle 2 pi sqrt(L/g)), 7 crossings in 8 s: measured
    relative error of the first 4e-14 and of the mean half-period 3e-15 (augmented), asserted
    1e-9 in every formulation."""
    res = _run(formulation)
    L, g, th0 = P["L"], P["g"], P["theta0"]
    period = 4 * math.sqrt(L / g) * ellipk(math.sin(th0 / 2) ** 2)
    assert period > 1.09 * 2 * math.pi * math.sqrt(L / g)

    def theta(tt):
        return float(res.sample([tt])["theta"][0])

    crossings = [brentq(theta, (k + 0.5) * period / 2 - 0.2, (k + 0.5) * period / 2 + 0.2,
                        xtol=1e-14) for k in range(int(T_END / period * 2) - 1)]
    assert len(crossings) >= 6
    assert crossings[0] == pytest.approx(period / 4, rel=1e-9)
    half = np.diff(crossings).mean()
    assert half == pytest.approx(period / 2, rel=1e-9)


def test_small_angles_follow_the_linear_pendulum():
    """theta0 = 0.01 rad: theta(t) against theta0 cos(sqrt(g/L) t) over 5 s.  The nonlinear
    frequency is lower by theta0^2/16 (phase lag 1e-4 rad after 5 s), so the difference is
    about 1e-6 rad: measured 1.08e-6 rad, asserted 2e-6 (2e-4 of theta0)."""
    th0 = 0.01
    res = _run("augmented", t_end=5.0, theta0=th0)
    t = np.linspace(0.0, 5.0, 501)
    s = res.sample(t)
    lin = th0 * np.cos(math.sqrt(P["g"] / P["L"]) * t)
    assert np.abs(s["theta"] - lin).max() < 2e-6


def test_right_hand_side_is_the_multiplier_form_solved_by_hand(rng):
    """dy/dt and lambda of the generated module at 50 random states off the constraint
    (c, w_B random) against M = m I solved by hand: 2 (x x'' + y y'') = gamma_B with
    gamma_B = -2 |v|^2 - 2 w Phi' - w^2 Phi gives
    lambda = -(m gamma_B + 2 c (x x' + y y') + 2 m g y)/(4 (x^2 + y^2)),
    x'' = (-c x' - 2 x lambda)/m, y'' = (-m g - c y' - 2 y lambda)/m.  Relative 1e-12."""
    model = load("pendulum_xy")
    law, par = np.zeros(1, dtype=np.intc), np.zeros(1)
    for _ in range(50):
        m, L, g, c, w = rng.uniform(0.5, 3.0), rng.uniform(0.2, 2.0), rng.uniform(1, 20), \
            rng.uniform(0, 2), rng.uniform(0, 50)
        p = model.parameter_vector({"m": m, "L": L, "g": g, "c": c, "w_B": w})
        x, y, xd, yd = rng.uniform(-1.5, 1.5, 4) * L
        Y = np.array([[x, y, xd, yd]])
        t0 = np.zeros(1)
        dy = driver.eval_rhs(model.capsule, p, law, par, t0, Y)[0]
        out = dict(zip(model.output_names, driver.eval_outputs(model.capsule, p, law, par, t0, Y)[0]))
        phi, phid = x * x + y * y - L * L, 2 * (x * xd + y * yd)
        gam = -2 * (xd * xd + yd * yd) - 2 * w * phid - w * w * phi
        lam = -(m * gam + 2 * c * (x * xd + y * yd) + 2 * m * g * y) / (4 * (x * x + y * y))
        xdd, ydd = (-c * xd - 2 * x * lam) / m, (-m * g - c * yd - 2 * y * lam) / m
        scale = abs(g) + abs(lam) * L / m + (xd * xd + yd * yd) / L + w * w * L
        np.testing.assert_allclose(dy, [xd, yd, xdd, ydd], rtol=0, atol=1e-12 * scale)
        assert out["lambda_rod"] == pytest.approx(lam, rel=1e-11, abs=1e-12 * m * scale / L)


def test_manifest_declares_the_constraint_and_no_cam():
    """The manifest comes from the declaration: one constraint with its multiplier, the
    solver's parameters, y dependent, no cam profile and no cam family."""
    man = load("pendulum_xy").manifest
    assert man["constraints"] == [{"name": "rod", "multiplier": "lambda_rod"}]
    assert man["solver"] == {"baumgarte_rate": "w_B", "formulation": "formulation"}
    assert man["dependent"] == ["y"]
    assert man["cam_profile"] is None and man["cam_families"] == []
    out = {o["name"]: o for o in man["outputs"]}
    assert out["lambda_rod"]["unit"] == "N/m"
    beam = load("beam1").manifest
    assert beam["cam_profile"]["family"] == "R" and beam["solver"]["baumgarte_rate"] == "w_B"


BEAM_NAMES = ("lambda1", "lambda2", "beta_r", "w_B", "RDFD", "rdfd", "paper", "beam", "Beam",
              "(1)", "(6)", "(7)", "(20)", "(21)", "(25)", "Phi1", "Phi2", "xE", "Omega",
              "theta")


def test_constraint_layer_carries_no_beam_names():
    """derive/dae.py and templates/constrained.pyx.j2 name nothing of the beam follower: its
    multipliers, rise angle, Baumgarte rate, profile, coordinates, equation numbers."""
    for rel in ("derive/dae.py", "derive/templates/constrained.pyx.j2"):
        text = (ROOT / rel).read_text()
        found = [name for name in BEAM_NAMES if name in text]
        assert not found, f"{rel} names {found}"


def test_generated_pendulum_has_no_cam_code():
    """Without a profile the generated module neither defines nor calls _profile, nor cimports
    the cam-law library; the names it has are its own."""
    text = (ROOT / "generated" / "pendulum_xy.pyx").read_text()
    for name in ("_profile(", "camlaw", "_cam0", "beta", "lambda1", "Phi1", "RDFD"):
        assert name not in text, name


def test_integrate_command_runs_the_pendulum():
    """camdyn integrate pendulum_xy --t-end 2 --json: runs, and the final state is on the
    constraint (|x^2 + y^2 - L^2| < 1e-8 at the default rtol) with the default L = 1 m."""
    p = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "integrate", "pendulum_xy",
                        "--t-end", "2", "--json"], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    st = out["state"]
    assert out["model"] == "pendulum_xy" and out["status"] == "ok"
    assert abs(st["x"] ** 2 + st["y"] ** 2 - 1.0) < 1e-8


@pytest.mark.parametrize("y0, words", [
    ([1.5, -0.5, 0.0, 0.0], "pendulum_xy: Newton's method found no y on the constraints from "
                            "the independent coordinates (x = 1.5, xd = 0); give initial "
                            "values closer to them"),
    ([1.0, 0.0, 0.0, 0.0], "pendulum_xy: the constraints cannot be solved for the dependent "
                           "coordinates y at the initial state (Phi_Q restricted to them is "
                           "singular there); give other initial values or choose other "
                           "dependent coordinates (dependent=..., --dependent NAMES)"),
])
def test_an_impossible_start_is_refused_naming_the_dependent_coordinate(y0, words):
    """L = 1: x = 1.5 leaves no y with x^2 + y^2 = 1 (Newton's method cannot converge);
    x = 1, y = 0 is on the constraint but Phi_y = 2 y = 0 there.  One line each, naming y."""
    from camdyn.runtime.core.errors import CamdynInputError
    from camdyn.runtime.core.simulator import Simulator

    with pytest.raises(CamdynInputError) as exc:
        Simulator("pendulum_xy", 1.0, "dp54", rtol=1e-8, y0=y0).run(
            {"L": 1.0, "theta0": 1.0, "formulation": 2.0})
    assert str(exc.value) == words
