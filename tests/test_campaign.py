"""A campaign of inputs against the command line: whatever a user types, camdyn answers with
exit 0 and finite figures that carry their estimates, or with one line and exit 1 (a run
that failed) or 2 (bad input); never a traceback, never a number from a failed run.

Hypothesis draws the inputs: option values from a mix of ordinary, boundary and absurd
numbers (0, negative, 1e-300, 1e300, nan, inf) and words; built-in scene files mutated (a
number changed to one of those, a key dropped, a key added, a value of the wrong type).  The
quick part runs in `make test`; the long one (more examples, every command) is marked slow.
"""
from __future__ import annotations

import contextlib
import io
import json
import math
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings, strategies as st

from camdyn.runtime.cli import main
from camdyn.runtime.targets import scene_files

NUMBERS = st.one_of(
    st.sampled_from([0.0, -1.0, 1e-300, 1e300, float("nan"), float("inf"), -0.0, 1.0, 0.5,
                     2.0, 1e-3, 1e6]),
    st.floats(min_value=-1e3, max_value=1e3, allow_nan=False),
)
WORDS = st.sampled_from(["abc", "", "1e", "--", "0x10", "1,2", "nan", "-inf", "1e400"])
VALUE = st.one_of(NUMBERS.map(repr), WORDS)


def run(argv: list[str]) -> tuple[int, str, str]:
    """camdyn ``argv`` in this process: (status, stdout, stderr); SystemExit (argparse) is
    a status too."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else 2
    return code, out.getvalue(), err.getvalue()


def finite_figures(record) -> None:
    """Every number of a JSON answer finite (JSON has no NaN: a NaN or inf would have been
    printed as NaN/Infinity, which json.loads accepts, so check), every figure that has an
    estimate key with a number or null there."""
    def walk(v, where):
        if isinstance(v, float):
            assert math.isfinite(v), f"{where} = {v}"
        elif isinstance(v, dict):
            for k, x in v.items():
                walk(x, f"{where}.{k}")
        elif isinstance(v, list):
            for i, x in enumerate(v):
                walk(x, f"{where}[{i}]")
    walk(record, "answer")


def judge(argv, code, out, err) -> None:
    """The contract of every command (module doc)."""
    assert "Traceback" not in err, (argv, err)
    assert code in (0, 1, 2), (argv, code, err)
    if code:
        lines = [l for l in err.splitlines() if "error:" in l or "run failed:" in l]
        assert len(lines) == 1, (argv, err)
        assert lines[0].startswith("camdyn"), (argv, err)
        assert not out.strip(), (argv, "a failed run printed", out)
    elif "--json" in argv:
        finite_figures(json.loads(out))


QUICK = settings(max_examples=40, deadline=None, derandomize=True,
                 suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
LONG = settings(max_examples=400, deadline=None, derandomize=True,
                suppress_health_check=[HealthCheck.too_slow,
                                       HealthCheck.function_scoped_fixture])


def residual_argv():
    opts = st.fixed_dictionaries({}, optional={
        "--tau": VALUE, "--fa": VALUE, "--fv": VALUE, "--q": VALUE, "--rtol": VALUE,
        "--t-end": VALUE, "--theta": VALUE,
        "--method": st.sampled_from(["dp54", "rk4", "koster", "rodas4", "euler"]),
        "--step": VALUE,
        "--law": st.sampled_from(["cycloidal", "modified-sine", "parabolic", "nope"])})
    return st.tuples(st.sampled_from(["one-dof", "camshaft1", "camshaft2"]), opts).map(
        lambda a: ["residual", "--model", a[0], "--json",
                   *[x for k, v in a[1].items() for x in (k, v)]])


def integrate_argv():
    opts = st.fixed_dictionaries({"--t-end": VALUE}, optional={
        "--rtol": VALUE, "--step": VALUE,
        "--method": st.sampled_from(["dp54", "rk4", "koster", "rodas4"]),
        "--set": st.tuples(st.sampled_from(["tau", "Fa", "q", "m", "nope"]), VALUE).map(
            lambda kv: f"{kv[0]}={kv[1]}"),
        "--initial": st.tuples(st.sampled_from(["X", "Xd", "x", "nope"]), VALUE).map(
            lambda kv: f"{kv[0]}={kv[1]}")})
    return st.tuples(st.sampled_from(["one_dof", "camshaft1", "pendulum_xy"]), opts).map(
        lambda a: ["integrate", a[0], "--json",
                   *[x for k, v in a[1].items() for x in (k, v)]])


def profile_argv():
    opts = st.fixed_dictionaries({"--stroke": VALUE, "--base-radius": VALUE,
                                  "--roller-radius": VALUE}, optional={
        "--offset": VALUE, "--max-pressure-angle": VALUE,
        "--points-per-degree": st.sampled_from(["1", "0", "1001", "5", "x"]),
        "--angles": st.sampled_from(["90,90,90,90", "0,180,90,90", "100,100,100,100", "a"]),
        "--law": st.sampled_from(["cycloidal", "3-4-5", "nope"]),
        "--law-parameter": VALUE})
    return opts.map(lambda a: ["profile", "--json",
                               *[x for k, v in a.items() for x in (k, v)]])


def design_argv():
    opts = st.fixed_dictionaries({"--stroke": VALUE}, optional={
        "--rise-time": VALUE, "--speed": VALUE, "--cam-angle": VALUE, "--mass": VALUE,
        "--stiffness": VALUE, "--tau": VALUE, "--fa": VALUE, "--accuracy": VALUE,
        "--residual-acceleration": VALUE})
    return opts.map(lambda a: ["design", "--json", "--no-check", "--quiet",
                               *[x for k, v in a.items() for x in (k, v)]])


def sweep_argv():
    grid = st.tuples(st.sampled_from(["tau", "Fa", "nope"]), VALUE, VALUE,
                     st.sampled_from(["1", "3", "0", "x", "2:log", "2:inv"])).map(
        lambda g: f"{g[0]}={g[1]}:{g[2]}:{g[3]}")
    opts = st.fixed_dictionaries({"--grid": grid}, optional={
        "--rtol": VALUE, "--t-end": VALUE, "--step": VALUE,
        "--method": st.sampled_from(["dp54", "rk4", "rodas4"])})
    return st.tuples(st.sampled_from(["one_dof", "camshaft1"]), opts).map(
        lambda a: ["sweep", a[0], "--quiet", "--jobs", "1",
                   *[x for k, v in a[1].items() for x in (k, v)]])


@QUICK
@given(argv=st.one_of(residual_argv(), integrate_argv(), profile_argv()))
def test_quick_campaign_over_command_options(argv, tmp_path_factory):
    if argv[0] == "profile":
        argv = [*argv, "--out", str(tmp_path_factory.mktemp("p"))]
    judge(argv, *run(argv))


@pytest.mark.slow
@LONG
@given(argv=st.one_of(residual_argv(), integrate_argv(), profile_argv(), design_argv(),
                      sweep_argv()))
def test_campaign_over_command_options(argv, tmp_path_factory):
    if argv[0] in ("profile", "sweep"):
        argv = [*argv, "--out", str(tmp_path_factory.mktemp("p"))]
    judge(argv, *run(argv))


def _numbers(table, where=()):
    """(path, value) of every number in a TOML table."""
    for k, v in table.items():
        if isinstance(v, dict):
            yield from _numbers(v, (*where, k))
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            yield (*where, k), v


def _dump(table) -> str:
    """A TOML text of ``table`` (nested tables, numbers, strings, booleans, lists)."""
    def value(v):
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, float):
            return "nan" if math.isnan(v) else ("inf" if v == math.inf else
                                                "-inf" if v == -math.inf else repr(v))
        if isinstance(v, str):
            return json.dumps(v)
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return repr(v)

    lines, tables = [], []
    for k, v in table.items():
        (tables if isinstance(v, dict) else lines).append((k, v))
    out = [f"{k} = {value(v)}" for k, v in lines]

    def section(prefix, t):
        flat = [(k, v) for k, v in t.items() if not isinstance(v, dict)]
        out.append(f"[{prefix}]")
        out.extend(f"{k} = {value(v)}" for k, v in flat)
        for k, v in t.items():
            if isinstance(v, dict):
                section(f"{prefix}.{k}", v)
    for k, v in tables:
        section(k, v)
    return "\n".join(out) + "\n"


SCENES = ["spring_loaded", "indexing", "fig8_1b"]


def mutations():
    return st.tuples(st.sampled_from(SCENES), st.sampled_from(["number", "drop", "add", "type"]),
                     st.integers(0, 10_000), NUMBERS)


def mutate(name, how, pick, number, folder) -> str:
    table = tomllib.loads(scene_files.builtin(name).read_text())
    nums = list(_numbers(table))
    path, _ = nums[pick % len(nums)]
    node = table
    for k in path[:-1]:
        node = node[k]
    if how == "number":
        node[path[-1]] = number
    elif how == "drop":
        del node[path[-1]]
    elif how == "add":
        node["unheard_of"] = number
    else:
        node[path[-1]] = "text"
    f = folder / f"{name}_{how}_{pick}.toml"
    f.write_text(_dump(table))
    return str(f)


@QUICK
@given(m=mutations())
def test_quick_campaign_over_mutated_scenes(m, tmp_path_factory):
    argv = ["simulate", mutate(*m, tmp_path_factory.mktemp("s")), "--json"]
    judge(argv, *run(argv))


@pytest.mark.slow
@LONG
@given(m=mutations(), command=st.sampled_from(["simulate", "run", "precision"]))
def test_campaign_over_mutated_scenes(m, command, tmp_path_factory):
    folder = tmp_path_factory.mktemp("s")
    argv = [command, mutate(*m, folder)]
    if command == "simulate":
        argv.append("--json")
    elif command == "run":
        argv += ["--out", str(folder / "out"), "--quiet", "--no-error-estimate"]
    else:
        argv += ["--no-peers", "--quick", "--out", str(folder / "out"), "--json"]
    judge(argv, *run(argv))
