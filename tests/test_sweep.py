"""camdyn sweep (runtime/studies/sweep.py): grids, the table, jobs and Dask, the refusals.

The figures themselves are tested against the reference and the closed form in
test_figures_compiled.py; here each grid point's figures are checked against a run of its
own through ``residual()`` (tolerances as there), and the ways of running a sweep (threads,
a Dask cluster, a scene instead of a model) against each other: equal to the last bit, since
each grid point runs the same compiled code on the same numbers.
"""
import csv
import math
import warnings

import numpy as np
import pytest

from camdyn.runtime.studies import sweep
from camdyn.runtime.measure.residual import FIGURES as RESIDUAL_FIGURES
from camdyn.runtime.cli import main
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.measure.residual import residual
from camdyn.runtime.core.simulator import simulate

GRID = {"Fa": [0.0, 2.0], "tau": [0.12, 0.17, 0.3]}   # away from the dips of (3.5) at 1/n


@pytest.fixture(scope="module")
def local():
    return sweep.sweep("camshaft1", GRID, jobs=1, progress=False)


def test_table_holds_every_combination_first_axis_slowest(local):
    """6 rows, Fa slowest; each row's figures equal those of its own run through residual()
    (rtol 1e-9): U0, U0'' to 2e-7 relative, X''min 1e-11, its T 2e-7 (test_figures_compiled.py
    says why)."""
    assert list(local["Fa"]) == [0.0, 0.0, 0.0, 2.0, 2.0, 2.0]
    assert list(local["tau"]) == [0.12, 0.17, 0.3] * 2
    for row in local.rows():
        r = residual(simulate("camshaft1", {"tau": row["tau"], "Fa": row["Fa"]}, 3.0, "dp54",
                              rtol=1e-9))
        assert row["U0"] == pytest.approx(r.U0, rel=2e-7)
        assert row["U0dd"] == pytest.approx(r.U0dd, rel=2e-7)
        assert row["Xdd_min_rise"] == pytest.approx(r.Xdd_min_rise, rel=1e-11)
        assert row["T_at_Xdd_min"] == pytest.approx(r.T_at_Xdd_min, abs=2e-7)


def test_threads_give_the_same_table(local):
    """jobs = 2 with chunks of 1 point (every point on either thread) equals jobs = 1 bit for
    bit."""
    two = sweep.sweep("camshaft1", GRID, jobs=2, progress=False, chunk=1)
    for name in local.names:
        assert np.array_equal(two[name], local[name]), name


def test_study_scene_is_camshaft1_with_its_settings(local):
    """The default scene (camshaft1-study: cycloid, dp54, rtol 1e-9, T in [0, 3]) sweeps
    CAMSHAFT-1 as the model target does: the same table."""
    scene = sweep.sweep("default", GRID, jobs=1, progress=False)
    for name in local.names:
        assert np.array_equal(scene[name], local[name]), name


def test_dask_local_cluster_gives_the_same_table(local):
    """A LocalCluster of two workers (threads, so that it starts in a second) runs the chunks:
    the same table, bit for bit."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster:
        on_dask = sweep.sweep("camshaft1", GRID, dask=cluster, progress=False, chunk=2)
        # and in the larger tasks a cluster gets by default (sweep.DASK_CHUNK)
        default = sweep.sweep("camshaft1", GRID, dask=cluster, progress=False)
    assert on_dask.where.startswith("dask")
    for name in local.names:
        assert np.array_equal(on_dask[name], local[name]), name
        assert np.array_equal(default[name], local[name]), name


def test_csv_parquet_and_charts(local, tmp_path):
    """sweep.csv has a column per axis, figure, its error estimate, the warnings and the steps,
    and reads back to the last bit; sweep.parquet (with pyarrow) too; one chart per figure."""
    files = local.write(tmp_path)
    with open(tmp_path / "sweep.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert list(rows[0]) == ["Fa", "tau", "U0", "U0_error", "U0dd", "U0dd_error", "Xdd_min_rise",
                             "Xdd_min_rise_error", "T_at_Xdd_min", "T_at_Xdd_min_error",
                             "warnings", "n_steps"]
    assert len(rows) == 6
    for k, row in enumerate(rows):
        for name, text in row.items():
            if name == "warnings":
                assert text == local[name][k] == ""
            else:
                assert float(text) == local[name][k]
    for fig in RESIDUAL_FIGURES:
        assert (tmp_path / f"{fig}.png").stat().st_size > 1000
    pq = pytest.importorskip("pyarrow.parquet")
    table = pq.read_table(tmp_path / "sweep.parquet").to_pydict()
    assert np.array_equal(table["U0"], local["U0"])
    assert tmp_path / "sweep.parquet" in files


@pytest.mark.parametrize("text,name,values", [
    ("tau=0.1:0.3:3", "tau", [0.1, 0.2, 0.3]),
    ("Fa=0,0.5,2", "Fa", [0.0, 0.5, 2.0]),
    ("tau=0.1:1:3:log", "tau", [0.1, math.sqrt(0.1), 1.0]),
    ("tau=0.1:0.5:3:inv", "tau", [0.1, 1 / 6, 0.5]),   # uniform in 1/tau: 10, 6, 2
])
def test_axis_syntax(text, name, values):
    got_name, got = sweep.parse_axis(text)
    assert got_name == name
    assert got == pytest.approx(values, rel=1e-14)


@pytest.mark.parametrize("text", ["tau=inf:0.5:3", "tau=0.1:nan:3:log", "tau=-inf:1:2:inv"])
def test_infinite_ends_are_refused_before_spacing(text):
    """inf and nan ends are refused by name before numpy spaces them (which printed
    RuntimeWarnings on stderr beside the one-line error)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(CamdynInputError, match="tau.*finite"):
            sweep.parse_axis(text)


@pytest.mark.parametrize("grid,words", [
    ({"stiffness": [1.0]}, ["stiffness", "tau", "Fa"]),          # unknown: lists the names
    ({"Fa": [-1.0]}, ["Fa", "range"]),                            # out of its declared range
    ({"tau": [0.0, 0.1]}, ["tau", "range"]),
    ({"tau": [float("nan")]}, ["tau", "finite"]),
])
def test_bad_grids_are_refused_naming_the_parameter(grid, words):
    with pytest.raises(CamdynInputError) as exc:
        sweep.sweep("camshaft1", grid, jobs=1, progress=False)
    for w in words:
        assert w in str(exc.value)


def test_cli_writes_the_table(tmp_path, capsys):
    rc = main(["sweep", "camshaft1", "--grid", "Fa=0,2", "--grid", "tau=0.1:0.3:3",
               "--jobs", "2", "--out", str(tmp_path), "--quiet"])
    assert rc == 0
    out = capsys.readouterr().out
    assert out.startswith("6 runs of camshaft1")
    with open(tmp_path / "sweep.csv") as fh:
        assert fh.readline().strip() == ("Fa,tau,U0,U0_error,U0dd,U0dd_error,Xdd_min_rise,"
                                         "Xdd_min_rise_error,T_at_Xdd_min,T_at_Xdd_min_error,"
                                         "warnings,n_steps")


@pytest.mark.parametrize("argv,words", [
    (["sweep", "camshaft1", "--grid", "tau=0.1:0.3"], ["--grid", "START:STOP:N"]),
    (["sweep", "camshaft1", "--grid", "Q=0.1:0.3:3"], ["grid Q", "parameters are"]),
    (["sweep", "camshaft1", "--grid", "tau=0:0.3:3:log"], ["tau", "START, STOP > 0"]),
    (["sweep", "camshaft1", "--grid", "tau=0.1:0.3:0"], ["tau", "N=0"]),
    (["sweep", "nowhere", "--grid", "tau=0.1:0.3:3"], ["nowhere", "neither a model"]),
    (["sweep", "camshaft1", "--grid", "tau=0.2", "--jobs", "0"], ["jobs"]),
    (["sweep", "one_dof", "--grid", "tau=0.2", "--t-end", "0.5"], ["rise"]),
    # an rtol beside a fixed step was ignored without a word
    (["sweep", "camshaft1", "--grid", "tau=0.2", "--method", "rk4", "--step", "1e-3",
      "--rtol", "1e-6"], ["rtol", "rk4", "step"]),
    (["sweep", "default", "--grid", "tau=0.2", "--method", "koster", "--step", "1e-3",
      "--rtol", "1e-6"], ["rtol", "koster", "step"]),
    # --jobs was ignored beside --dask; an address without a port raised ValueError
    (["sweep", "camshaft1", "--grid", "tau=0.2", "--jobs", "2", "--dask", "tcp://127.0.0.1:1"],
     ["--jobs", "--dask"]),
    (["sweep", "camshaft1", "--grid", "tau=0.2", "--dask", "foo"], ["--dask", "foo"]),
    # a fixed-step method on a scene was blamed on the grid ('grid c_x: run.method=...')
    (["sweep", "spring_loaded", "--grid", "c_x=3e5", "--method", "rk4"], ["method rk4", "scene takes"]),
    # two axes of one name: refused naming it (the CLI said 'a parameter')
    (["sweep", "camshaft1", "--grid", "tau=0.2", "--grid", "tau=0.3"], ["--grid", "tau", "twice"]),
    # the table of 1e10 points raised MemoryError (75 GiB) with a traceback
    (["sweep", "camshaft1", "--grid", "tau=0.1:0.5:100000", "--grid", "Fa=0:1:100000"],
     ["tau (100000) x Fa (100000)", "1e+10", "1,000,000"]),
])
def test_cli_refusals_are_one_line(argv, words, capsys):
    rc = main(argv + ["--quiet"])
    err = capsys.readouterr().err
    assert rc == 2
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    for w in words:
        assert w in err


def test_dynacam_scene_sweep_is_its_summary():
    """A DYNACAM scene (fig. 7.2's spring-loaded follower) swept over its follower stiffness
    c_x: each row's figures are those of runtime/targets/dynacam.py's summary of the scene with that
    value, bit for bit (the same run; about 1 s)."""
    from camdyn.runtime.targets import dynacam, scene_files as scenes

    sc = scenes.load("spring_loaded")
    name = "c_x"
    values = [sc.parameters[name], 1.1 * sc.parameters[name]]
    res = sweep.sweep("spring_loaded", {name: values}, jobs=1, progress=False)
    for k, v in enumerate(values):
        summary, _ = dynacam.run(scenes.replace(sc, parameters={name: v}))
        assert res["U0"][k] == summary["U0"]
        assert res["speed_variation_max"][k] == summary["speed_variation_max"]
        assert bool(res["jump_occurs"][k]) == summary["jump"]["occurs"]


def test_error_estimate_is_the_change_at_a_hundredth_of_rtol():
    """<figure>_error = 1.5 |v(rtol) - v(rtol/100)| plus the scan's sampling error (none here
    but the place of X''min's; runtime/measure/contract.py), the second sweep's own figures;
    at tau = 0.15, Fa = 2 (thesis sec. 4.7's case) it bounds the true
    error of U0, U0'' against rtol 1e-12 within a factor 10 (as tests/test_accuracy.py
    asks of camdyn residual)."""
    grid = {"Fa": [2.0], "tau": [0.15]}
    est = sweep.sweep("camshaft1", grid, rtol=1e-8, jobs=1, progress=False)
    tight = sweep.sweep("camshaft1", grid, rtol=1e-10, jobs=1, progress=False)
    ref = sweep.sweep("camshaft1", grid, rtol=1e-13, jobs=1, progress=False)
    from camdyn.runtime.measure.extremes import place_error

    for name in RESIDUAL_FIGURES:
        # the place of X''min carries how well the refinement places it besides
        placed = place_error(est[name][0]) if name == "T_at_Xdd_min" else 0.0
        assert est[f"{name}_error"][0] == pytest.approx(
            1.5 * abs(est[name][0] - tight[name][0]) + placed, rel=1e-12)
    for name in ("U0", "U0dd"):
        true = abs(est[name][0] - ref[name][0])
        assert true / 10 <= est[f"{name}_error"][0] <= 10 * true, name


def test_a_dwell_shorter_than_a_period_is_refused():
    """U0 is the largest |U| in the dwell: with less than one period tau of the residual
    vibration after T = 1 it came out too small (camshaft1 at tau = 0.1, t_end = 1.0001:
    7.0e-4 against 1.76e-3).  Refused below 1 + tau; from 1 + tau on, the one-DOF model's U0
    is (3.5), tau^3/(1 - tau^2)/pi |sin(pi/tau)|, to 1e-6."""
    from camdyn.runtime.measure import references as cf

    with pytest.raises(CamdynInputError, match=r"t_end >= 1\.3"):
        sweep.sweep("one_dof", {"tau": [0.23, 0.3]}, t_end=1.25, jobs=1, progress=False)
    res = sweep.sweep("one_dof", {"tau": [0.23, 0.3]}, t_end=1.3, jobs=1, progress=False)
    assert res["U0"] == pytest.approx([cf.U0(0.23), cf.U0(0.3)], rel=1e-6)


def test_a_one_point_grid_is_drawn(tmp_path):
    """A grid of one point drew an empty chart (a line through one point has no length); the
    point is drawn as a marker: the chart holds pixels of the line colour (C0, #1f77b4)."""
    import matplotlib.image as mpimg

    res = sweep.sweep("camshaft1", {"tau": [0.3]}, jobs=1, progress=False)
    res.charts(tmp_path)
    img = mpimg.imread(tmp_path / "U0.png")[..., :3]
    c0 = np.array([0x1f, 0x77, 0xb4]) / 255
    assert (np.abs(img - c0).max(axis=-1) < 0.05).sum() >= 20


def test_dynacam_error_estimates_are_for_run_figures_only():
    """A DYNACAM scene's sweep: a column <figure>_error for the run's figures, each 1.5 |v - v'|
    of the run at rtol/100 (runtime/core/methods.py), 0 for tau, Fa, Fv (they follow from the
    parameters, exactly) and none for jump_occurs (a yes or no)."""
    from camdyn.runtime.targets import dynacam, scene_files as scenes

    sc = scenes.load("fig8_1b")
    res = sweep.sweep("fig8_1b", {"c_x": [sc.parameters["c_x"]]}, jobs=1, progress=False)
    names = set(res.names)
    assert "jump_occurs_error" not in names
    assert [res[f"{k}_error"][0] for k in ("tau", "Fa", "Fv")] == [0.0, 0.0, 0.0]
    summary, _ = dynacam.run(sc)
    tight, _ = dynacam.run(sc, method=dynacam.scene_method(sc).tighter())
    for key in ("U0", "U0dd", "Xdd_min_rise"):
        assert res[f"{key}_error"][0] == pytest.approx(1.5 * abs(summary[key] - tight[key]),
                                                       rel=1e-9, abs=1e-15)


def test_turn_scene_sweep_adds_the_return(tmp_path):
    """A DYNACAM scene with a [turn]: the sweep's table has the return's figures too, each
    equal to the summary of a plain `simulate` run of that scene (the same run, bit for bit)."""
    from camdyn.runtime.targets import dynacam, scene_files as scenes

    text = (scenes.builtin("spring_loaded").read_text().replace("T_end = 1.5", "T_end = 5.0")
            + "\n[turn]\nupper_dwell = 50\nreturn = 40\n")
    path = tmp_path / "turn.toml"
    path.write_text(text)
    res = sweep.sweep(str(path), {"c_x": [0.407e6]}, jobs=1, progress=False)
    summary, _ = dynacam.run(scenes.load(str(path)))
    for key in ("U0", "Xdd_absmax_return", "U0dd_return", "U0_return"):
        assert res[key][0] == summary[key], key


def test_default_chunks_grow_with_the_grid():
    """About eight chunks a thread, never fewer points than the target's own chunk and at most
    MAX_CHUNK: a large grid pays for fewer Python round trips, a small one keeps even shares."""
    from types import SimpleNamespace

    from camdyn.runtime.targets.grid import MAX_CHUNK, default_chunk

    model = SimpleNamespace(chunk=32)
    assert default_chunk(model, 2400, 1) == 300
    assert default_chunk(model, 2400, 2) == 150
    assert default_chunk(model, 100, 2) == 32
    assert default_chunk(model, 10**6, 2) == MAX_CHUNK == 512
    assert default_chunk(SimpleNamespace(chunk=1), 7, 1) == 1
