"""The command line's smaller holes: --out checked before any run, NAME=VALUE options and grids
given twice or with empty items, a selection of checks that selects nothing, the inputs a
sweep holds off its grid, the closed form beside a residual run, and initial values beyond
what the integrator's arithmetic holds.

References: the user's own file byte for byte and the folder's listing (nothing written); the
run entry points replaced by one that fails the test if called (refused *before* any run);
the model's manifest for the defaults; SciPy's solve_ivp on the one-DOF model (3.1) for the
residual amplitudes (3.5), (3.6).
"""
import contextlib
import io
import json
import math
import os

import numpy as np
import pytest

from camdyn.runtime.cli import main


def run(argv):
    """camdyn ``argv`` in this process: (status, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else 2
    return code, out.getvalue(), err.getvalue()


def refused(argv, *words):
    """``argv`` is refused as bad input: exit 2, one line on stderr (no traceback) naming the
    command and holding every one of ``words``; nothing on stdout.  Returns the line."""
    code, out, err = run(argv)
    assert "Traceback" not in err, err
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and not out.strip(), (argv, code, out, err)
    assert lines[0].startswith(f"camdyn {argv[0]}: error: "), lines
    for w in words:
        assert w in lines[0], (w, lines[0])
    return lines[0]


# -- --out: every name and the folder checked before any run ------------------------------

class Ran(AssertionError):
    """A run started where the command should have refused first."""


RUNS = {"stability": "camdyn.runtime.studies.stability_map.study",
        "simulate": "camdyn.runtime.measure.contract.answer",
        "precision": "camdyn.runtime.studies.precision.study",
        "laws --tau": "camdyn.thesis.design.selection.table",
        "laws --sweep": "camdyn.thesis.design.shape_sweep.sweep",
        "integrate": "camdyn.runtime.measure.contract.answer",
        "sweep": "camdyn.runtime.targets.grid.GridPlan.run",
        "run": "camdyn.runtime.measure.contract.answer",
        "beam-follower": "camdyn.runtime.measure.contract.answer"}
"""Where each command's runs start (the laws' modules load SymPy: patched only for them)."""


def _no_runs(monkeypatch, name):
    """The road command ``name`` takes to its runs fails the test if taken.  The modules that
    bind ``answer`` when first imported are imported before the patch, so that none of them
    keeps the patched one for the rest of the session."""
    import camdyn.runtime.studies.stability_map  # noqa: F401
    import camdyn.runtime.targets.camshaft1_study  # noqa: F401
    if name.startswith("laws"):
        import camdyn.thesis.design.shape_sweep  # noqa: F401

    def ran(*args, **kwargs):
        raise Ran("a run started before --out was refused")

    monkeypatch.setattr(RUNS[name.split(" default")[0]], ran)


# every command whose --out this covers, quick arguments, and one file it writes there (the
# one written last, or after others: refusing it after writing those was the hole)
WRITERS = {
    "stability": (["stability", "one_dof", "--param", "tau=0.2,0.3", "--methods", "rk4",
                   "--steps", "0.01,0.02", "--quiet"], "stability_one_dof_tau.csv"),
    "stability default param": (["stability", "one_dof", "--methods", "rk4", "--steps",
                                 "0.01", "--quiet"], "stability_one_dof_tau.json"),
    "simulate": (["simulate", "spring_loaded", "--no-error-estimate"], "spring_loaded_torque.png"),
    "precision": (["precision", "one_dof", "--set", "tau=0.3", "--no-peers", "--quick",
                   "--methods", "dp54"], "one_dof_precision.png"),
    "laws --tau": (["laws", "--tau", "0.15", "--no-error-estimate"], "laws_selection.png"),
    "laws --sweep": (["laws", "--sweep", "spring_loaded", "--n", "2", "--no-error-estimate"],
                     "laws_sweep.csv"),
    "integrate": (["integrate", "one_dof", "--t-end", "2", "--set", "tau=0.3"], "one_dof.png"),
    "sweep": (["sweep", "one_dof", "--grid", "tau=0.2,0.3", "--quiet"], "U0dd.png"),
    # a DYNACAM scene's diagrams, written after report.json's answer
    "run": (["run", "spring_loaded", "--no-error-estimate", "--quiet"],
            "spring_loaded_torque.png"),
    "beam-follower": (["beam-follower", "--no-error-estimate"], "fig9_rise.png"),
}


@pytest.mark.parametrize("name", list(WRITERS))
def test_a_users_file_in_out_is_refused_before_any_run(tmp_path, monkeypatch, name):
    """A file of the user's with the name of one of the command's outputs: refused in one
    line naming it, no run started (the runs' entry points fail the test), no file written,
    the user's file byte for byte as it was."""
    argv, file = WRITERS[name]
    out = tmp_path / "out"
    out.mkdir()
    mine = b"my own,work\n1,2\n"
    (out / file).write_bytes(mine)
    _no_runs(monkeypatch, name)
    refused([*argv, "--out", str(out)], f"{out / file} exists and camdyn did not write it")
    assert sorted(os.listdir(out)) == [file]
    assert (out / file).read_bytes() == mine


def _read_only(monkeypatch, folder):
    """``folder`` read-only: chmod 0o500, and where that does not stop this process (root),
    os.access says so as it would."""
    folder.chmod(0o500)
    if not os.access(folder, os.W_OK):
        return
    real = os.access

    def access(path, mode, *args, **kwargs):
        if os.path.abspath(os.fspath(path)) == str(folder) and mode & os.W_OK:
            return False
        return real(path, mode, *args, **kwargs)

    monkeypatch.setattr(os, "access", access)


@pytest.mark.parametrize("name", list(WRITERS))
def test_a_read_only_out_is_refused_before_any_run(tmp_path, monkeypatch, name):
    """A read-only --out: one line saying it is not writable, before any run, nothing in it."""
    argv, _ = WRITERS[name]
    out = tmp_path / "out"
    out.mkdir()
    _read_only(monkeypatch, out)
    _no_runs(monkeypatch, name)
    try:
        refused([*argv, "--out", str(out)], f"the folder {out} is not writable")
        assert os.listdir(out) == []
    finally:
        out.chmod(0o700)


# -- NAME=VALUE options and grids -----------------------------------------------------------

@pytest.mark.parametrize("argv, flag, name", [
    (["integrate", "one_dof", "--t-end", "2", "--set", "tau=0.1", "--set", "tau=0.2"],
     "--set", "tau"),
    (["integrate", "one_dof", "--t-end", "2", "--initial", "X=0.1", "--initial", "X=0.2"],
     "--initial", "X"),
    (["integrate", "one_dof", "--t-end", "2", "--state-atol", "X=1e-9", "--state-atol",
      "X=1e-8"], "--state-atol", "X"),
    (["residual", "--model", "one-dof", "--tau", "0.2", "--state-atol", "Xd=1e-9",
      "--state-atol", "Xd=1e-8"], "--state-atol", "Xd"),
    (["stability", "one_dof", "--set", "q=0.1", "--set", "q=0.2", "--steps", "0.01"],
     "--set", "q"),
    (["precision", "one_dof", "--set", "tau=0.3", "--set", "tau=0.4", "--no-peers"],
     "--set", "tau"),
])
def test_a_name_given_twice_is_refused_naming_it(argv, flag, name, tmp_path):
    """--set tau=0.1 --set tau=0.2 kept the last without a word; now refused, naming the
    option and the name."""
    refused([*argv, *(["--out", str(tmp_path)] if argv[0] in ("stability", "precision")
                      else [])], f"argument {flag}: {name} is given twice")
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("grid, words", [
    ("tau=0.1,,0.2", ("argument --grid: tau:", "empty item")),
    ("tau=0.1,0.2,", ("argument --grid: tau:", "empty item")),
    ("tau=0.1,0.2,0.1", ("argument --grid: tau:", "gives 0.1 more than once")),
    ("tau=0.2:0.2:3", ("argument --grid: tau:", "gives 0.2 more than once")),
])
def test_a_grid_with_an_empty_or_repeated_value_is_refused(grid, words, tmp_path):
    """An empty list item was dropped and a repeated value ran twice (a Dataset with a
    repeated coordinate): both refused in one line."""
    refused(["sweep", "one_dof", "--grid", grid, "--out", str(tmp_path), "--quiet"], *words)
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("flag, text", [("--param", "tau=0.1,,0.2"), ("--steps", "0.01,,0.02"),
                                        ("--param", "tau=0.2,0.2")])
def test_a_stability_grid_with_an_empty_or_repeated_value_is_refused(flag, text, tmp_path):
    argv = ["stability", "one_dof", "--methods", "rk4", "--out", str(tmp_path), flag, text]
    if flag != "--steps":
        argv += ["--steps", "0.01"]
    refused(argv, f"argument {flag}:")


def test_a_check_selection_that_selects_nothing_is_refused(monkeypatch):
    """-k nosuchkey ran no check and passed (exit 0); now refused, naming the pattern and how
    to see the keys; --list shows the selected keys without running any."""
    from camdyn.thesis.checks import suite

    monkeypatch.setattr(suite, "run", lambda *a, **k: (_ for _ in ()).throw(Ran("ran")))
    refused(["check", "-k", "nosuchkey"], "'nosuchkey'", "camdyn check --list")
    refused(["check", "-k", "nosuchkey", "--topic", "spine"], "--topic spine")
    code, out, err = run(["check", "--list", "-k", "U0dd"])
    keys = out.split()
    assert code == 0 and keys and all("U0dd" in k for k in keys)
    assert keys == [c.key for c in suite.select(None, "U0dd")]
    code, out, _ = run(["check", "--list", "-k", "U0dd", "--json"])
    assert code == 0 and json.loads(out) == keys


# -- a sweep's inputs off its grid -------------------------------------------------------------

def test_a_sweep_carries_the_inputs_it_held_at_their_values(tmp_path, monkeypatch):
    """camdyn sweep camshaft2 over tau ran at the model's Fa and Fv and did not say so: the
    table (CSV, Parquet), the DataFrame and the Dataset carry Fa and Fv at the values the
    manifest declares as defaults, the summary says they were the defaults; and they are what
    ran: the same point with Fa and Fv given as one-value axes gives the same figures."""
    from camdyn.runtime.core.compiled import load
    from camdyn.runtime.studies.sweep import sweep

    from camdyn.runtime.studies.sweep import SweepResult

    monkeypatch.setattr(SweepResult, "charts", lambda self, out_dir: [])    # seconds, not tested
    defaults = {p["name"]: p["default"] for p in load("camshaft2").manifest["parameters"]}
    code, out, err = run(["sweep", "camshaft2", "--grid", "tau=0.15", "--out", str(tmp_path),
                          "--quiet", "--no-error-estimate"])
    assert code == 0, err
    assert f"held: Fa = {defaults['Fa']:g}, Fv = {defaults['Fv']:g} at the model's defaults" \
        in out
    head, row = (tmp_path / "sweep.csv").read_text().splitlines()
    cells = dict(zip(head.split(","), row.split(",")))
    assert float(cells["Fa"]) == defaults["Fa"] and float(cells["Fv"]) == defaults["Fv"]
    pq = pytest.importorskip("pyarrow.parquet")
    table = pq.read_table(tmp_path / "sweep.parquet").to_pydict()
    assert table["Fa"] == [defaults["Fa"]] and table["Fv"] == [defaults["Fv"]]

    held = sweep("camshaft2", {"tau": [0.15]}, progress=False, estimate=False)
    given = sweep("camshaft2", {"tau": [0.15], "Fa": [defaults["Fa"]], "Fv": [defaults["Fv"]]},
                  progress=False, estimate=False)
    for f in ("U0", "U0dd", "Xdd_min_rise"):
        assert held[f][0] == given[f][0]
    assert held.to_pandas()["Fv"].tolist() == [defaults["Fv"]]
    ds = held.to_xarray()
    assert float(ds["Fa"]) == defaults["Fa"] and ds["Fa"].dims == ()
    assert ds["Fa"].attrs["description"] == "held at the model's default"
    assert given.held == {}            # every input on the grid: nothing held


# -- the closed form beside a residual run ----------------------------------------------------

def _one_dof_amplitudes(tau: float) -> tuple[float, float]:
    """U0 and U0'' of the cycloidal rise on the undamped one-DOF model (3.1), by SciPy: X'' =
    w^2 (H - X), w = 2 pi/tau, H = T - sin(2 pi T)/(2 pi) up to T = 1; after it the error
    u = X - 1 oscillates freely, amplitude sqrt(u^2 + (u'/w)^2) at T = 1 (H' = 0 there)."""
    from scipy.integrate import solve_ivp

    w = 2 * math.pi / tau

    def rhs(T, y):
        H = T - math.sin(2 * math.pi * T) / (2 * math.pi)
        return [y[1], w * w * (H - y[0])]

    sol = solve_ivp(rhs, (0.0, 1.0), [0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14)
    u, v = sol.y[0, -1] - 1.0, sol.y[1, -1]
    U0 = math.hypot(u, v / w)
    return U0, w * w * U0


@pytest.mark.parametrize("tau", [0.3, 0.75, 0.98, 1.0, 1.02, 1.5, 2.0, 4.0])
def test_the_closed_forms_are_amplitudes_at_every_tau(tau):
    """(3.5), (3.6) as amplitudes: equal to SciPy's free vibration after the rise at tau below,
    at and above 1 (1 - tau^2 < 0 made them negative beyond 1; 0/0 at 1), to 1e-8."""
    from camdyn.runtime.measure import references
    from camdyn.thesis.theory import numeric

    U0, U0dd = _one_dof_amplitudes(tau)
    assert references.U0(tau) == pytest.approx(U0, rel=1e-8)
    assert references.U0dd(tau) == pytest.approx(U0dd, rel=1e-8)
    if tau != 1.0:          # the symbolic form as the thesis prints it, with |1 - tau^2|
        assert numeric.U0(tau) == pytest.approx(U0, rel=1e-8)
        assert numeric.U0dd(tau) == pytest.approx(U0dd, rel=1e-8)


@pytest.mark.parametrize("tau", ["2", "1"])
def test_camdyn_residual_prints_the_closed_form_amplitude_beside_the_run(tau):
    """camdyn residual --model camshaft1 --fa 0 (the one-DOF model) at tau >= 1: the closed
    forms beside U0 and U0'' are positive and agree with them within the run's estimate."""
    code, out, err = run(["residual", "--model", "camshaft1", "--tau", tau, "--fa", "0",
                          "--json"])
    assert code == 0 and "Traceback" not in err and "RuntimeWarning" not in err
    r = json.loads(out)
    for f in ("U0", "U0dd"):
        closed = r[f"{f}_closed_form"]
        assert closed > 0 and abs(r[f] - closed) <= r[f"{f}_error"] + 1e-9 * r[f]


# -- initial values beyond the integrator's arithmetic ----------------------------------------

@pytest.mark.parametrize("value", ["1e300", "1e150", "-1e101", "nan", "inf"])
def test_an_initial_value_out_of_range_is_refused_naming_initial(value):
    """--initial X=1e300 ran and said "step budget used up": the error control's sum of
    squares overflows at the first step.  Refused in one line naming --initial and the
    range (or, for nan and inf, that it is no finite number)."""
    line = refused(["integrate", "one_dof", "--t-end", "2", "--initial", f"X={value}"],
                   "argument --initial: X=")
    assert ("|X| <= 1e+100" in line) == math.isfinite(float(value))


def test_an_initial_value_at_the_limit_runs():
    """X = 1e100 times the scale runs, as the linear one-DOF model does from any state: from
    rest at X0 the dwell's free vibration is X0 cos(w T) plus the response to the rise, so
    X(T)/X0 at T = 2 is cos(2 w) to the rise's part over X0 (1e-100)."""
    code, out, err = run(["integrate", "one_dof", "--t-end", "2", "--set", "tau=0.3",
                          "--initial", "X=1e100", "--json"])
    assert code == 0, err
    X = json.loads(out)["state"]["X"]
    w = 2 * math.pi / 0.3
    # rtol 1e-8 over 6.7 periods: measured 2.3e-8
    assert X / 1e100 == pytest.approx(math.cos(2 * w), abs=1e-6)


def test_a_run_that_fails_from_given_initial_values_names_them():
    """A run that fails from the user's initial values (pendulum_xy from x = 1e100: its
    constraint's square overflows) says it started from --initial, in its one line."""
    code, out, err = run(["integrate", "pendulum_xy", "--t-end", "1", "--initial", "x=1e100"])
    lines = err.strip().splitlines()
    assert code == 1 and len(lines) == 1 and "Traceback" not in err
    assert lines[0].startswith("camdyn integrate: run failed: ")
    assert lines[0].endswith("the run started from --initial x=1e+100")
