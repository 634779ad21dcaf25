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
