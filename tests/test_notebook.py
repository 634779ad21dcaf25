"""Results in a notebook: rich HTML views, pandas and xarray tables (runtime/core/display.py).

References: the objects' own columns and arrays, read by index independently of the
conversions; the model's manifest for the units; the answer contract for what a view must
carry (every figure beside its error estimate, the warnings or the words that there are
none, a chart).
"""
import base64
import re

import numpy as np
import pytest

from camdyn.runtime.core.errors import CamdynInputError
from camdyn.runtime.core.simulator import simulate
from camdyn.runtime.measure.contract import answer
from camdyn.runtime.studies.sweep import sweep
from camdyn.runtime.targets.resolve import resolve

AXES = {"Fa": [0.0, 0.5], "tau": [0.1, 0.15, 0.2]}


@pytest.fixture(scope="module")
def swept():
    return sweep("default", AXES, progress=False)


def _pictures(page: str) -> list[bytes]:
    return [base64.b64decode(m) for m in re.findall(r'src="data:image/png;base64,([^"]+)"', page)]


def test_a_sweep_as_an_xarray_dataset_on_its_grid(swept):
    """to_xarray(): the axes are the coordinates in the grid's order, each figure and its
    error a variable over them; every value is the table's row for those axis values (found
    by matching the row's axis columns, not by the reshape under test), exactly; the units
    are the manifest's."""
    ds = swept.to_xarray()
    assert list(ds.sizes) == ["Fa", "tau"] and dict(ds.sizes) == {"Fa": 2, "tau": 3}
    rows = swept.rows()
    for Fa in AXES["Fa"]:
        for tau in AXES["tau"]:
            row = next(r for r in rows if r["Fa"] == Fa and r["tau"] == tau)
            for name in ("U0", "U0_error", "U0dd", "Xdd_min_rise_error", "n_steps"):
                assert float(ds[name].sel(Fa=Fa, tau=tau)) == row[name], (name, Fa, tau)
            assert str(ds["warnings"].sel(Fa=Fa, tau=tau).item()) == row["warnings"]
    assert ds["tau"].attrs["units"] == "1" and ds["U0_error"].attrs["description"] == \
        "error estimate of U0"


def test_a_sweep_as_a_pandas_frame_and_as_html(swept):
    """to_pandas(): every column of the table, row by row; the HTML view: a row per point with
    each figure as 'value ± error' (6 digits), the warnings of the points that warned, and a
    PNG chart."""
    frame = swept.to_pandas()
    assert list(frame.columns) == swept.names and len(frame) == len(swept)
    for name in ("U0", "U0_error", "tau"):
        assert np.array_equal(frame[name].to_numpy(), np.asarray(swept[name], dtype=float))
    page = swept._repr_html_()
    for i in range(len(swept)):
        assert f"{swept['U0'][i]:.6g} \u00b1 {swept['U0_error'][i]:.6g}" in page
    for w in swept["warnings"]:
        if w:
            assert w.split(":")[0] in page
    pictures = _pictures(page)
    assert len(pictures) == 1 and pictures[0][:8] == b"\x89PNG\r\n\x1a\n"


def test_a_run_as_pandas_and_xarray_with_the_manifest_s_units():
    """Result.to_pandas() and to_xarray(): every state and output at the recorded points,
    equal to result[name]; the time the index (coordinate); the units and descriptions those
    of the model's manifest; the HTML view with the run's statistics, the parameters, its
    warnings (none here) and a chart."""
    res = simulate("camshaft1", {"tau": 0.15, "Fa": 2.0}, t_end=3.0, method="dp54", rtol=1e-8)
    man = res.model.manifest
    frame = res.to_pandas()
    assert np.array_equal(frame.index.to_numpy(), np.unique(res.t)) and frame.index.name == "T"
    ds = res.to_xarray()
    for name in res.names:
        assert np.array_equal(ds[name].values, res[name])
    for spec in [*man["states"], *man["outputs"]]:
        assert frame.attrs["units"][spec["name"]] == spec["unit"] == ds[spec["name"]].attrs["units"]
        assert ds[spec["name"]].attrs["description"] == spec["doc"]
    assert ds["T"].attrs["units"] == "t_m" and ds.attrs["parameter_tau"] == 0.15
    page = res._repr_html_()
    assert "no warnings" in page and str(res.stats["n_steps"]) in page
    assert len(_pictures(page)) == 1


def test_a_run_s_frame_has_one_row_per_time_the_right_limit_at_a_breakpoint():
    """The end of the rise (T = 1) is recorded twice, as left and right limit: the frame's
    index had it twice.  Now every time once, the row at a breakpoint the last point recorded
    there (the right limit), every other row the recorded point itself; the Dataset keeps
    both limits, told apart by ``segment`` (0 before the breakpoint, 1 from it)."""
    res = simulate("camshaft1", {"tau": 0.15, "Fa": 2.0}, t_end=3.0, method="dp54", rtol=1e-8)
    twice = res.t[1:][res.t[1:] == res.t[:-1]]
    assert list(twice) == [1.0]                   # the case the test is about
    frame = res.to_pandas()
    assert frame.index.is_unique and len(frame) == len(res.t) - 1
    last = {}
    for k, t in enumerate(res.t):         # the last point recorded at each time
        last[t] = k
    rows = np.array([last[t] for t in frame.index])
    assert list(frame.index) == sorted(last)
    for name in res.names:
        assert np.array_equal(frame[name].to_numpy(), res[name][rows]), name
    ds = res.to_xarray()
    seg = ds["segment"].values
    k = int(np.flatnonzero(res.t == 1.0)[0])
    assert seg[k] == 0 and seg[k + 1] == 1 and set(seg[:k + 1]) == {0} and set(seg[k + 1:]) == {1}


def test_a_bare_run_says_it_has_no_figures_and_how_to_get_them():
    """A Result's view showed a run without a figure or an estimate, silently: it now says it
    has none and gives the call that does; that call, run as printed, answers every figure
    with its estimate."""
    import html

    from camdyn.runtime.measure.contract import answer
    from camdyn.runtime.targets.resolve import resolve

    res = simulate("camshaft1", {"tau": 0.15, "Fa": 2.0}, t_end=3.0, method="dp54", rtol=1e-8)
    page = res._repr_html_()
    assert "figures: none here" in page and "no warnings" in page
    call = html.unescape(re.search(r"(answer\(resolve\(.*?\)\))</code>", page).group(1))
    a = eval(call, {"answer": answer, "resolve": resolve})
    assert set(a.figures) >= {"U0", "U0dd"} and all(a.errors[f] is not None for f in a.figures)


def test_a_grid_with_a_repeated_value_is_refused():
    """A repeated grid value gave a Dataset whose coordinate has a value twice (sel() cannot
    pick one): refused in one line naming the axis and the value."""
    with pytest.raises(CamdynInputError) as exc:
        sweep("one_dof", {"tau": [0.1, 0.2, 0.1]}, progress=False)
    assert str(exc.value) == "grid tau: 0.1 is given more than once; give each value once"


def test_step_counts_are_whole_numbers_everywhere(swept):
    """n_steps came out as float64 in the table, the DataFrame and the Dataset: whole numbers
    now, each the count of its point's run (the study's own, one run per point)."""
    assert swept["n_steps"].dtype.kind == "i"
    assert swept.to_pandas()["n_steps"].dtype.kind == "i"
    assert swept.to_xarray()["n_steps"].dtype.kind == "i"
    study = resolve("default")
    for row in swept.rows()[:2]:
        one = study.with_parameters({"Fa": row["Fa"], "tau": row["tau"]}).run()
        assert row["n_steps"] == one.stats["n_steps"]


def test_an_answer_as_an_xarray_dataset():
    """Answer.to_xarray(), as Result's and SweepResult's: every figure a variable with its
    estimate ``<figure>_error`` beside it (the estimate's parts its attributes), the target's
    units and descriptions as attributes, the warnings as the Dataset's."""
    target = resolve("camshaft1")
    a = answer(target)
    ds = a.to_xarray()
    specs = {f.name: f for f in target.figures()}
    for name, value in a.figures.items():
        assert float(ds[name]) == value and float(ds[f"{name}_error"]) == a.errors[name]
        assert ds[name].attrs == {"units": specs[name].unit, "description": specs[name].doc}
        assert ds[f"{name}_error"].attrs["description"] == f"error estimate of {name}"
        for part, e in a.sources[name].items():
            assert ds[f"{name}_error"].attrs[f"error_{part}"] == e
    assert ds.attrs["warnings"] == ("; ".join(a.warnings) or "none")
    bare = answer(target, estimate=False).to_xarray()
    assert all(np.isnan(float(bare[f"{n}_error"])) for n in a.figures)


def test_an_answer_shows_each_figure_with_its_estimate_and_its_parts():
    """Answer (one run of a target with the contract's estimates): the HTML view and the
    DataFrame hold every figure with its estimate and the estimate's parts, as as_dict()."""
    a = answer(resolve("camshaft1"))
    record = a.as_dict()
    frame = a.to_pandas()
    page = a._repr_html_()
    for name, value in a.figures.items():
        assert frame.loc[name, "value"] == value and frame.loc[name, "error"] == record[f"{name}_error"]
        assert f"{value:.6g} \u00b1 {record[name + '_error']:.6g}" in page
        for part, e in record["error_sources"][name].items():
            assert frame.loc[name, f"error_{part}"] == e
    assert "no warnings" in page and len(_pictures(page)) == 1


def test_a_notebook_s_plotting_backend_is_left_as_it_was(swept):
    """The views draw without pyplot, so they do not switch a notebook's backend."""
    import matplotlib

    before = matplotlib.get_backend()
    matplotlib.use("svg")
    try:
        swept._repr_html_()
        assert matplotlib.get_backend() == "svg"
    finally:
        matplotlib.use(before)


def test_without_pandas_the_conversion_is_refused_in_one_line(swept, monkeypatch):
    """A conversion whose library is missing says what to install, in one line."""
    import builtins

    real = builtins.__import__

    def no_pandas(name, *args, **kw):
        if name == "pandas" or name.startswith("pandas."):
            raise ImportError(name)
        return real(name, *args, **kw)

    monkeypatch.delitem(__import__("sys").modules, "pandas", raising=False)
    monkeypatch.setattr(builtins, "__import__", no_pandas)
    with pytest.raises(CamdynInputError) as exc:
        swept.to_pandas()
    assert str(exc.value) == ("SweepResult.to_pandas() needs pandas: pip install "
                              "'camdyn[notebook]' (or pip install pandas)")
