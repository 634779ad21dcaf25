"""Every kind of target sweeps in compiled chunks (runtime/measure/batch.py,
runtime/engine/finder.pyx sweep_extremes): a DYNACAM scene, the beam follower, a model that
declares no rise (its states at t_end), CAMSHAFT-2's extremes over the whole run and camdyn
design's graphs.  A chunk runs the same
compiled loops on the same numbers as single runs and finds each figure with the same scan,
so its table must equal the one of single runs (base.Target.run_points: one run() per point)
to the last bit: figures, sampling errors, steps and warnings."""
import numpy as np
import pytest

from camdyn.runtime.cli import main
from camdyn.runtime.targets.base import Target
from camdyn.runtime.targets.resolve import resolve


def points_of(grid: dict) -> tuple[tuple, np.ndarray]:
    mesh = np.meshgrid(*grid.values(), indexing="ij")
    return tuple(grid), np.stack([m.ravel() for m in mesh], axis=1)


def assert_same_batches(a, b):
    assert np.array_equal(a.figures, b.figures, equal_nan=True)
    assert np.array_equal(a.sampling, b.sampling, equal_nan=True)
    assert np.array_equal(a.steps, b.steps)
    assert a.warnings == b.warnings


def test_dynacam_chunk_equals_single_runs_with_a_jump():
    """fig. 7.2's spring-loaded follower at its own follower stiffness and at a tenth of its
    spring preload's worth of speed more (the follower leaves the cam there): the chunk's
    figures, where and whether it jumps included, are the single runs', bit for bit."""
    target = resolve("spring_loaded")
    omega = target.scene.parameters["omega_s"]
    names, pts = points_of({"omega_s": [omega, 1.6 * omega]})
    target = target.fit_points(names, pts)
    chunk = target.run_points(names, pts)
    assert_same_batches(chunk, Target.run_points(target, names, pts))
    jumps = chunk.figures[:, target.figure_names().index("jump_occurs")]
    assert jumps.tolist() == [0.0, 1.0]


def test_beam_chunk_equals_single_runs():
    """The beam follower (paper, sec. 4) over a quarter and a third of a revolution at two
    cam speeds: tip deflection, constraint residual, dwell frequency and their sampling
    errors equal the single runs', bit for bit."""
    names, pts = points_of({"omega": [200.0, 260.0], "revolutions": [0.25, 0.3]})
    target = resolve("beam_paper").fit_points(names, pts)
    assert_same_batches(target.run_points(names, pts), Target.run_points(target, names, pts))


def test_beam_chunk_runs_each_model_of_the_grid():
    """A grid over the assumed modes N runs one compiled call per beam<N> model."""
    names, pts = points_of({"modes": [1, 2], "revolutions": [0.2]})
    target = resolve("beam_paper").fit_points(names, pts)
    assert_same_batches(target.run_points(names, pts), Target.run_points(target, names, pts))


@pytest.mark.parametrize("name, grid", [
    ("motor1", {"Mc": [0.5, 1.0, 2.0]}),
    # constrained: every run starts projected onto its constraints, with the note
    ("pendulum_xy", {"L": [0.8, 1.0]}),
])
def test_states_at_t_end_chunk_equals_single_runs(name, grid):
    """A model that declares no rise gives its states at t_end; the chunk's are the single
    runs' (Simulator.run, then the dense output at t_end), bit for bit, warnings included."""
    from camdyn.runtime.targets.model_target import StateTarget

    names, pts = points_of(grid)
    target = resolve(name, model_class=StateTarget, t_end=1.0).fit_points(names, pts)
    assert_same_batches(target.run_points(names, pts), target._points_one_by_one(names, pts))


def test_camshaft2_chunk_finds_the_run_extremes_of_single_runs():
    """CAMSHAFT-2's figures over the whole run (the cam's largest speed deviation and the
    shaft's largest wind-up, sec. 5.5.5, fig. 5.6) come from the compiled chunk too: with the
    scan of a single run every figure, sampling error and step count equals single runs', bit
    for bit; with the sweep's scan (a grid's) the run extremes still do, and the residual
    figures lie within 1e-9 of their largest value."""
    from camdyn.runtime.targets.model_target import ModelTarget

    names, pts = ("tau", "Fa"), np.array([[0.1, 0.5], [0.15, 1.0], [0.2, 2.0]])
    target = ModelTarget.of("camshaft2", rtol=1e-8).fit_points(names, pts)
    one = target._points_one_by_one(names, pts)
    assert_same_batches(target.residual_points(names, pts, reference=True), one)
    chunk = target.run_points(names, pts)
    assert target.figure_names()[4:] == ("Bdot_dev_max", "windup_max")
    assert np.array_equal(chunk.figures[:, 4:], one.figures[:, 4:])
    assert np.array_equal(chunk.sampling[:, 4:], one.sampling[:, 4:])
    for k in (0, 1, 2):
        assert np.abs(chunk.figures[:, k] - one.figures[:, k]).max() \
            <= 1e-9 * np.abs(one.figures[:, k]).max()


def test_cli_sweeps_the_states_of_a_model_without_a_rise(tmp_path, capsys):
    """`camdyn sweep` of a model that declares no rise writes every state at t_end with its
    estimate, one row a point; without --t-end it is refused in one line (exit 2)."""
    rc = main(["sweep", "motor1", "--grid", "Mc=0.5,1", "--t-end", "1", "--out",
               str(tmp_path), "--quiet"])
    assert rc == 0
    head, *rows = (tmp_path / "sweep.csv").read_text().splitlines()
    from camdyn.runtime.core.compiled import load

    states = load("motor1").state_names
    assert head.split(",")[:1 + 2 * len(states)] == ["Mc"] + [
        c for s in states for c in (s, f"{s}_error")]
    assert len(rows) == 2
    capsys.readouterr()
    rc = main(["sweep", "motor1", "--grid", "Mc=0.5,1", "--out", str(tmp_path / "b"),
               "--quiet"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and "--t-end" in err[0]


def test_design_graphs_are_single_runs_figures():
    """camdyn design's graphs (thesis/design/graphs.py) through compiled chunks: with the
    scan of a single run they are residual() of each run alone, bit for bit; with the
    sweep's scan (the default) within 1e-9 of the largest value of the window."""
    from camdyn.runtime.core.simulator import Simulator
    from camdyn.runtime.measure.residual import residual
    from camdyn.thesis.design.graphs import METHOD, RTOL, Graphs

    for Fa in (0.0, 0.8):
        ref = Graphs("cycloidal", reference=True).samples(4.0, 6.0, Fa)
        fast = Graphs("cycloidal").samples(4.0, 6.0, Fa)
        for tau, U0, U2 in zip(*ref):
            sim = Simulator("camshaft1", Graphs.t_end(tau), METHOD, rtol=RTOL, law="cycloidal")
            r = residual(sim.run({"tau": float(tau), "Fa": Fa}))
            assert (U0, U2) == (r.U0, r.U0dd)
        assert np.array_equal(ref[0], fast[0])
        for k in (1, 2):
            assert np.abs(fast[k] - ref[k]).max() <= 1e-9 * ref[k].max()


LINKED = '''"""A follower of two masses joined by a rigid link, pulled through a spring towards
s(t) = 1 - exp(-4 t) (a rise that ends at t = 1 for its residual figures)."""
import sympy as sp

from camdyn.derive.model import (Constraint, ConstraintSolver, Coordinate, Model, Output,
                                 Parameter, Residual, time)

t = time("t")
x = Coordinate("x", "m", "first mass", initial=0.0)
y = Coordinate("y", "m", "second mass, on the link", initial=0.02)
m = Parameter("m", 0.5, "kg", "each mass", low=0.0, open_low=True)
c = Parameter("c", 400.0, "N/m", "spring", low=0.0, open_low=True)
d = Parameter("d", 0.5, "N s/m", "damper to the frame", low=0.0)
w = Parameter("w_B", 10.0, "1/s", "Baumgarte rate", low=0.0)
form = Parameter("formulation", 0.0, "1", "formulation", low=0.0, high=2.0)


def build() -> Model:
    X, Y = x(t), y(t)
    s = 1 - sp.exp(-4 * t)
    return Model(name="linked", title="Linked follower", reference="test", doc=__doc__, time=t,
                 time_unit="s", coordinates=(x, y),
                 kinetic=m.symbol * (X.diff(t) ** 2 + Y.diff(t) ** 2) / 2,
                 potential=c.symbol * (s - X) ** 2 / 2, dissipation=d.symbol * X.diff(t) ** 2 / 2,
                 parameters=(m, c, d, w, form),
                 outputs=(Output("U", X - s, "m", "positional error"),
                          Output("Xdd", X.diff(t, 2), "m/s^2", "acceleration")),
                 constraints=(Constraint("link", Y - X, "lam", "N", "link force"),),
                 solver=ConstraintSolver(baumgarte_rate=w.symbol, formulation=form.symbol,
                                         dependent=("y",)),
                 residual=Residual("U", "Xdd", rise_end=1.0))
'''
"""A constrained model with a rise: its declared start (y = 0.02 off the link) is projected
onto the constraint before every run, with a note."""


@pytest.fixture(scope="module")
def linked(tmp_path_factory):
    """The model file above, built on demand into a cache of the test's own; its rise, which
    ends at t = 1, declared as an unconstrained model declares it."""
    import os

    from camdyn.runtime.core import ondemand

    folder = tmp_path_factory.mktemp("linked")
    path = folder / "linked.py"
    path.write_text(LINKED)
    old = os.environ.get(ondemand.ENV_CACHE)
    os.environ[ondemand.ENV_CACHE] = str(folder / "cache")
    try:
        model = ondemand.model_file(str(path))      # loaded once per process
        assert model.manifest.get("residual") == {"error": "U", "acceleration": "Xdd",
                                                  "rise_end": 1.0, "rise_state": ""}
        yield str(path)
    finally:
        if old is None:
            del os.environ[ondemand.ENV_CACHE]
        else:
            os.environ[ondemand.ENV_CACHE] = old


def _no_single_runs(monkeypatch, *classes):
    """Every single-run road of these targets made to fail: a chunk that took one fails."""
    def refuse(*args, **kwargs):
        raise AssertionError("a single run inside a compiled chunk")
    from camdyn.runtime.core.simulator import Simulator

    monkeypatch.setattr(Simulator, "run", refuse)
    for cls in classes:
        monkeypatch.setattr(cls, "run", refuse)
        if hasattr(cls, "_points_one_by_one"):
            monkeypatch.setattr(cls, "_points_one_by_one", refuse)


def _count_calls(monkeypatch, module, name):
    calls = []
    real = getattr(module, name)

    def counted(*args, **kwargs):
        calls.append(1)
        return real(*args, **kwargs)
    monkeypatch.setattr(module, name, counted)
    return calls


def _residual_chunks_against_single_runs(monkeypatch, target, names, pts):
    """(single runs, chunk) of a model target's residual figures at ``pts``: both compiled
    calls go to finder.sweep_residual with no single run; with the scan of a single run the
    chunk equals the single runs bit for bit, with the sweep's own scan its figures lie within
    1e-9 of their largest value."""
    from camdyn.runtime.engine import finder
    from camdyn.runtime.targets.model_target import ModelTarget

    one = target._points_one_by_one(names, pts)
    calls = _count_calls(monkeypatch, finder, "sweep_residual")
    with monkeypatch.context() as m:
        _no_single_runs(m, ModelTarget)
        ref = target.residual_points(names, pts, reference=True)
        chunk = target.run_points(names, pts)
    assert len(calls) == 2
    assert_same_batches(ref, one)
    for k in range(3):
        assert np.abs(chunk.figures[:, k] - one.figures[:, k]).max() \
            <= 1e-9 * np.abs(one.figures[:, k]).max()
    return one, chunk


def test_constrained_model_chunk_equals_single_runs(linked, monkeypatch):
    """A constrained model with a rise (the model file above) sweeps in one compiled call
    (finder.sweep_residual), each point from its consistent state solved beforehand: with the
    scan of a single run its figures, sampling errors, steps and notes (the start projected
    onto the link) equal single runs' (Simulator.run, then residual()), bit for bit; with the
    sweep's scan the run's notes and steps still do, and the figures lie within 1e-9 of their
    largest value (the scan's sampling density, as for CAMSHAFT-1 and -2)."""
    from camdyn.runtime.targets.model_target import ModelTarget

    names, pts = ("c", "d"), np.array([[300.0, 0.5], [500.0, 0.0], [800.0, 1.0]])
    target = ModelTarget.of(linked, rtol=1e-8).fit_points(names, pts)
    one, chunk = _residual_chunks_against_single_runs(monkeypatch, target, names, pts)
    assert all(len(w) == 1 and "violated the constraints" in w[0] for w in one.warnings)
    assert chunk.warnings == one.warnings
    assert np.array_equal(chunk.steps, one.steps)


def test_rise_ending_at_an_output_chunk_equals_single_runs(monkeypatch):
    """A DYNACAM variant run as a model: its rise ends where the output B (the cam angle over
    the rise angle, (6.17)) reaches 1, found on the record in compiled code for a single run
    and a chunk alike; with the scan of a single run the chunk's figures are the single runs',
    bit for bit, and with the sweep's scan within 1e-9 of their largest value."""
    from camdyn.runtime.targets.model_target import ModelTarget

    target = ModelTarget.of("dynacam_radial_ideal_rigidgear_bilateral", rtol=1e-8)
    assert target.spec["rise_state"] not in target.model.state_names
    c_x = target.model.parameter_vector()[target.model.parameter_names.index("c_x")]
    names, pts = ("c_x",), np.array([[c_x], [1.3 * c_x]])
    _residual_chunks_against_single_runs(monkeypatch, target.fit_points(names, pts), names, pts)


def test_output_crossing_is_brents_to_its_tolerance():
    """The compiled crossing of an output (bisection on the dense output) lands where SciPy's
    brentq on the same dense output does (runtime/measure/extremes.py crossing_time), to
    their tolerances of 1e-14."""
    from camdyn.runtime.core.simulator import simulate
    from camdyn.runtime.measure.extremes import crossing_time, first_crossing

    res = simulate("dynacam_radial_ideal_rigidgear_bilateral", t_end=0.2, rtol=1e-8)
    assert "B" in res.output_names
    level = 0.5 * (res["B"][0] + res["B"][-1])
    assert abs(first_crossing(res, "B", level) - crossing_time(res, "B", level)) <= 4e-14


def _turn_scene(tmp_path, upper_dwell: float, ret: float):
    from camdyn.runtime.targets import scene_files as scenes

    text = (scenes.builtin("spring_loaded").read_text().replace("T_end = 1.5", "T_end = 5.0")
            + f"\n[turn]\nupper_dwell = {upper_dwell:g}\nreturn = {ret:g}\n")
    path = tmp_path / "turn.toml"
    path.write_text(text)
    return str(path)


def test_turn_chunk_equals_single_runs_with_window_estimates(tmp_path, monkeypatch):
    """A DYNACAM scene with a full turn whose upper dwell (2 deg, 0.08 of the rise) is shorter
    than one period of the follower's mode (0.14): U0 and U0'' are read from it, each with a
    warning and an estimate of the part of the oscillation the dwell does not show
    (runtime/measure/modes.py amplitude_bound; 0.034 of 13.4 for U0'' at the scene's own
    values).
    The chunk samples each record where a single run's estimate does, in one compiled call
    per cam law (two rise angles beta_m: two calls), and its table equals single runs'
    (DynacamTarget.run per point), estimates and warnings included, bit for bit."""
    from camdyn.runtime.measure import batch
    from camdyn.runtime.targets.dynacam_scene import DynacamTarget

    target = resolve(_turn_scene(tmp_path, 2.0, 40.0))
    p = target.scene.parameters
    names, pts = points_of({"c_x": [p["c_x"], 1.2 * p["c_x"]],
                            "beta_m": [p["beta_m"], 0.9 * p["beta_m"]]})
    target = target.fit_points(names, pts)
    single = Target.run_points(target, names, pts)
    calls = _count_calls(monkeypatch, batch, "run_batch")
    with monkeypatch.context() as m:
        _no_single_runs(m, DynacamTarget)
        chunk = target.run_points(names, pts)
    assert len(calls) == 2
    assert_same_batches(chunk, single)
    # the window's estimate is there: every point warns of U0 and U0'' and U0'' carries it
    assert all(sorted(w.split()[0] for w in ws if " is read from a dwell of " in w)
               == ["U0", "U0dd"] for ws in chunk.warnings)
    k = target.figure_names().index("U0dd")
    assert np.all(chunk.sampling[:, k] > 0.0)
