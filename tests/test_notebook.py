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
    assert np.array_equal(frame.index.to_numpy(), res.t) and frame.index.name == "T"
    ds = res.to_xarray()
    for name in res.names:
        assert np.array_equal(frame[name].to_numpy(), res[name])
        assert np.array_equal(ds[name].values, res[name])
    for spec in [*man["states"], *man["outputs"]]:
        assert frame.attrs["units"][spec["name"]] == spec["unit"] == ds[spec["name"]].attrs["units"]
        assert ds[spec["name"]].attrs["description"] == spec["doc"]
    assert ds["T"].attrs["units"] == "t_m" and ds.attrs["parameter_tau"] == 0.15
    page = res._repr_html_()
    assert "no warnings" in page and str(res.stats["n_steps"]) in page
    assert len(_pictures(page)) == 1


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
