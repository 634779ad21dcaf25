"""A constrained model's dependent coordinates chosen per run (Simulator(dependent=...),
simulate(dependent=...), --dependent), instead of the ones its ConstraintSolver declares.

The pendulum in Cartesian coordinates (derive/models/pendulum.py) declares y dependent; with
x dependent coordinate partitioning solves x = +-sqrt(L^2 - y^2) instead, singular where
Phi_x = 2 x = 0 (the rod hanging straight down), as the declared choice is where Phi_y = 2 y
= 0 (the horizontal rod).  Released at theta0 = 1.2 rad and run for 0.3 s the bob stays
between theta = 0.6 and 1.2 rad, away from both.  References, independent of the generated
code: the pendulum's own ODE theta'' = -(g/L) sin theta by SciPy's solve_ivp (DOP853,
rtol 1e-12), its energy integral, and the consistent start solved by hand.  The beam
follower (derive/models/beam.py) takes the cam angle theta as independent with b1 and x_E
dependent, against its augmented formulation (multipliers: no partition at all).
"""
import json
import math
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from camdyn.runtime.cli import main
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.core.simulator import Simulator, simulate
from camdyn.runtime.engine import driver

P = {"m": 2.0, "L": 0.8, "g": 9.81, "theta0": 1.2, "formulation": 1.0}
T_END = 0.3


def _pendulum(dependent, t_end=T_END, **params):
    sim = Simulator("pendulum_xy", t_end, "dp54", rtol=1e-11, dependent=dependent)
    return sim.run({**P, **params})


def _angle(t):
    """theta(t) of the pendulum ODE released at rest from theta0."""
    L, g = P["L"], P["g"]
    sol = solve_ivp(lambda _, s: [s[1], -g / L * math.sin(s[0])], (0.0, float(t[-1])),
                    [P["theta0"], 0.0], method="DOP853", rtol=1e-12, atol=1e-14, t_eval=t)
    assert sol.success
    return sol.y[0]


def test_both_choices_follow_the_pendulum_ode_and_each_other():
    """y dependent (declared) and x dependent, partitioned: the angle within 1e-9 rad of the
    ODE's (measured: 4e-12 and 2e-12), each other within 1e-10 (measured 4e-12), the energy
    within 1e-10 of its start (measured 1e-11); the run away from both singular
    configurations."""
    t = np.linspace(0.0, T_END, 301)
    ref = _angle(t)
    runs = {dep: _pendulum(dep).sample(t) for dep in (("y",), ("x",))}
    for s in runs.values():
        assert np.abs(s["theta"] - ref).max() < 1e-9
        assert np.abs(s["E"] - s["E"][0]).max() < 1e-10 * abs(s["E"][0])
        assert np.abs(s["Phi"]).max() < 1e-12
    assert ref.min() > 0.5          # x stays away from 0, y from 0 (theta < pi/2)
    for name in ("x", "y", "theta"):
        assert np.abs(runs[("x",)][name] - runs[("y",)][name]).max() < 1e-10


def test_the_choice_is_the_run_s_own_and_reaches_the_compiled_code():
    """The dependent set in force, and the partition the compiled code takes: None for the
    declared one, [x, y] (dependent first) for x."""
    declared = Simulator("pendulum_xy", T_END, "dp54", rtol=1e-8)
    chosen = Simulator("pendulum_xy", T_END, "dp54", rtol=1e-8, dependent="x")
    same = Simulator("pendulum_xy", T_END, "dp54", rtol=1e-8, dependent=["y"])
    assert declared.dependent == ("y",) and declared.part is None
    assert same.dependent == ("y",) and same.part is None
    assert chosen.dependent == ("x",) and chosen.part.tolist() == [0, 1]
    assert chosen.run(P).dependent == ("x",)


def test_the_right_hand_side_recovers_the_chosen_coordinate():
    """Off the constraint, the partitioned right-hand side keeps the independent coordinate
    and recovers the dependent one: with x dependent and the state (x, y) = (0.5, -0.7),
    y' = 0.3, x = sqrt(L^2 - y^2) and x' = -y y'/x (by hand); dx/dt is that x'."""
    sim = Simulator("pendulum_xy", T_END, "dp54", rtol=1e-8, dependent="x")
    m = sim.model
    p = m.parameter_vector(P)
    y = np.array([[0.5, -0.7, 0.0, 0.3]])
    x = math.sqrt(P["L"] ** 2 - 0.49)
    f_x = driver.eval_rhs(m.capsule, p, sim.law_codes, sim.law_pars, np.zeros(1), y,
                          part=sim.part)[0]
    f_y = driver.eval_rhs(m.capsule, p, sim.law_codes, sim.law_pars, np.zeros(1), y)[0]
    assert f_x[0] == pytest.approx(0.7 * 0.3 / x, rel=1e-12)
    assert f_x[1] == pytest.approx(0.3, rel=1e-14)
    assert f_y[0] == pytest.approx(0.0, abs=1e-15)       # y dependent: x' = 0 kept


def test_the_jacobian_follows_the_chosen_partition():
    """The exact Jacobian with x dependent against central differences of the right-hand
    side with the same choice (measured agreement 4e-11 relative)."""
    sim = Simulator("pendulum_xy", T_END, "dp54", rtol=1e-8, dependent="x")
    m = sim.model
    p = m.parameter_vector(P)
    y = np.array([0.55, -0.58, 0.9, 0.85])
    J = driver.eval_jacobian(m.capsule, p, sim.law_codes, sim.law_pars, 0.0, y, part=sim.part)
    fd = driver.eval_jacobian_fd(m.capsule, p, sim.law_codes, sim.law_pars, np.zeros(1),
                                 y[None, :], np.ones(4), part=sim.part)[0]
    assert np.abs(J - fd).max() < 1e-6 * np.abs(fd).max()
    declared = driver.eval_jacobian(m.capsule, p, sim.law_codes, sim.law_pars, 0.0, y)
    assert np.abs(J - declared).max() > 0.1          # the choice changes it


@pytest.mark.parametrize("dependent, expected", [
    (("y",), [0.5, -math.sqrt(0.64 - 0.25), 0.0, 0.0]),
    (("x",), [math.sqrt(0.64 - 0.49), -0.7, 0.7 * 0.3 / math.sqrt(0.64 - 0.49), 0.3]),
])
def test_the_consistent_start_keeps_the_chosen_independent_values(dependent, expected):
    """A start off the constraint, (x, y, x', y') = (0.5, -0.7, 0, 0.3), L = 0.8: the
    independent coordinate and its rate are kept, the dependent ones solved by hand (x^2 +
    y^2 = L^2 on the branch of the sign carried, x x' + y y' = 0), with a note naming them."""
    sim = Simulator("pendulum_xy", 0.05, "dp54", rtol=1e-10, y0=[0.5, -0.7, 0.0, 0.3],
                    dependent=dependent)
    res = sim.run(P)
    assert np.abs(res.y[0] - expected).max() < 1e-13
    assert len(res.warnings) == 1 and f"{dependent[0]}, {dependent[0]}d recovered" in \
        res.warnings[0]


def test_a_singular_choice_at_the_start_is_refused_in_one_line():
    """x dependent with the rod hanging straight down: Phi_x = 2 x = 0 there; y dependent
    starts there without complaint."""
    with pytest.raises(CamdynInputError) as exc:
        _pendulum("x", theta0=0.0)
    assert str(exc.value) == (
        "pendulum_xy: the constraints cannot be solved for the dependent coordinates x at the "
        "initial state (Phi_Q restricted to them is singular there); give other initial "
        "values or choose other dependent coordinates (dependent=..., --dependent NAMES)")
    assert _pendulum("y", t_end=0.05, theta0=0.0)["y"][-1] == pytest.approx(-0.8, abs=1e-14)


@pytest.mark.parametrize("dependent, shown", [
    ("z", "'z'"), (("x", "y"), "'x,y'"), ((), "''"), ((1,), "'1'"), ("x,x", "'x,x'"),
])
def test_bad_names_are_refused_in_one_line(dependent, shown):
    with pytest.raises(CamdynInputError) as exc:
        Simulator("pendulum_xy", 1.0, "dp54", dependent=dependent)
    assert str(exc.value) == (f"dependent={shown}: pendulum_xy takes 1 distinct name of its "
                              "coordinates x, y (declared: y)")


def test_a_model_without_constraints_takes_no_dependent_coordinates():
    with pytest.raises(CamdynInputError) as exc:
        Simulator("one_dof", 3.0, "dp54", dependent="x")
    assert str(exc.value) == ("dependent: model one_dof has no constraints; dependent "
                              "coordinates are chosen for constrained models only")


def test_simulate_keys_its_cache_by_the_choice():
    """simulate() keeps prepared simulators; a run with x dependent is not served by the one
    with y dependent (nor the reverse)."""
    a = simulate("pendulum_xy", P, t_end=0.05, rtol=1e-9)
    b = simulate("pendulum_xy", P, t_end=0.05, rtol=1e-9, dependent=["x"])
    c = simulate("pendulum_xy", P, t_end=0.05, rtol=1e-9)
    assert (a.dependent, b.dependent, c.dependent) == (("y",), ("x",), ("y",))


def test_runs_with_different_choices_on_threads_do_not_share_them():
    """The choice lives in each run's context, not in the module: eight runs alternating x
    and y dependent on four threads give each choice's own sequential result, to the bit."""
    sims = {d: Simulator("pendulum_xy", T_END, "dp54", rtol=1e-10, dependent=d)
            for d in ("x", "y")}
    alone = {d: s.run(P).y[-1] for d, s in sims.items()}
    assert not np.array_equal(alone["x"], alone["y"])    # rounding tells them apart
    order = ["x", "y"] * 4
    with ThreadPoolExecutor(4) as pool:
        ends = list(pool.map(lambda d: sims[d].run(P).y[-1], order))
    for d, y in zip(order, ends):
        assert np.array_equal(y, alone[d])


def test_integrate_command_takes_the_choice(capsys):
    """camdyn integrate --dependent x: the state at t_end against the pendulum ODE (1e-7 m),
    and the choice in the JSON."""
    rc = main(["integrate", "pendulum_xy", "--t-end", str(T_END), "--rtol", "1e-11",
               "--dependent", "x", "--no-error-estimate", "--json",
               *[a for k, v in P.items() for a in ("--set", f"{k}={v}")]])
    captured = capsys.readouterr()
    assert rc == 0, captured.err
    out = json.loads(captured.out)
    theta = _angle(np.array([0.0, T_END]))[-1]
    assert out["dependent"] == ["x"]
    assert out["state"]["x"] == pytest.approx(P["L"] * math.sin(theta), abs=1e-7)
    assert out["state"]["y"] == pytest.approx(-P["L"] * math.cos(theta), abs=1e-7)


@pytest.mark.parametrize("argv, message", [
    (["integrate", "pendulum_xy", "--t-end", "1", "--dependent", "q"],
     "camdyn integrate: error: argument --dependent: dependent='q': pendulum_xy takes 1 "
     "distinct name of its coordinates x, y (declared: y)"),
    (["integrate", "one_dof", "--t-end", "1", "--dependent", "x"],
     "camdyn integrate: error: argument --dependent: dependent: model one_dof has no "
     "constraints; dependent coordinates are chosen for constrained models only"),
    (["integrate", "pendulum_xy", "--t-end", "1", "--set", "theta0=0", "--dependent", "x"],
     "camdyn integrate: error: pendulum_xy: the constraints cannot be solved for the "
     "dependent coordinates x at the initial state (Phi_Q restricted to them is singular "
     "there); give other initial values or choose other dependent coordinates "
     "(dependent=..., --dependent NAMES)"),
])
def test_bad_choices_on_the_command_line_are_one_line_with_status_2(argv, message, capsys):
    rc = main(argv)
    err = capsys.readouterr().err
    assert rc == 2
    assert err == message + "\n"


def test_command_line_end_to_end():
    """The installed command, in a process of its own: --dependent in the help, and a run."""
    cmd = [sys.executable, "-m", "camdyn.runtime.cli", "integrate"]
    h = subprocess.run(cmd + ["--help"], capture_output=True, text=True, timeout=120)
    assert "--dependent NAMES" in h.stdout and "Coordinate partitioning" in h.stdout
    p = subprocess.run(cmd + ["pendulum_xy", "--t-end", "0.1", "--set", "formulation=1",
                              "--dependent", "x", "--json", "--no-error-estimate"],
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    st = json.loads(p.stdout)["state"]
    assert abs(st["x"] ** 2 + st["y"] ** 2 - 1.0) < 1e-10


# -- the beam follower: the cam angle as the independent coordinate ---------------------------

def test_beam_follower_with_the_cam_angle_independent():
    """beam2 (N = 2, the paper's data) over the rise, partitioned with b1 and x_E dependent
    (theta and b2 integrated) against the declared x_E, theta dependent and against the
    augmented formulation, which partitions nothing: the tip deflection v_E (an output, at the
    recovered state) within 1e-6 of its peak (measured 8e-9 and 8e-10), the cam law's
    displacement S(theta) within 1e-12 m (measured 1e-16)."""
    from camdyn.runtime.targets import beam
    from camdyn.runtime.targets.beam_case import Case

    case = Case(modes=2, formulation="partitioned", rtol=1e-9)
    t_end = 0.3 * case.period
    out = {}
    for key, dependent, formulation in (("chosen", ("b1", "xE"), 1.0),
                                        ("declared", None, 1.0), ("augmented", None, 0.0)):
        sim, model = beam.simulator(case, t_end)
        sim = Simulator(model, t_end, beam.integrator(case), law=case.law,
                        y0=beam.initial_state(case, model), dependent=dependent)
        res = sim.run({**beam.parameters(case), "formulation": formulation})
        out[key] = res.sample(np.linspace(0.0, t_end, 400))
    peak = np.abs(out["augmented"]["vE"]).max()
    assert peak > 1e-5
    for key in ("chosen", "declared"):
        assert np.abs(out[key]["vE"] - out["augmented"]["vE"]).max() < 1e-6 * peak
        assert np.abs(out[key]["S"] - out["augmented"]["S"]).max() < 1e-12
