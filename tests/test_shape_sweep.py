"""Shape-parameter sweep on a DYNACAM scene (thesis/design/shape_sweep.py, `camdyn laws --sweep`)
against plain scene runs and thesis fig. 8.8."""
import dataclasses

import numpy as np
import pytest

from camdyn.runtime.targets import dynacam, scene_files as scenes
from camdyn.runtime.core.errors import CamdynInputError
from camdyn.thesis.design import shape_sweep


@pytest.fixture(scope="module")
def spring():
    return scenes.load("spring_loaded")


def test_sweep_point_equals_a_plain_run(spring):
    """A grid point is the scene run with that law and parameter, to 1e-12; at theta = 1/4 the
    modified sine is the cycloid (A.2.17), so that point equals the scene's own cycloidal run
    to the runs' error estimates (rtol 1e-8 runs whose segments differ: 1e-6 relative)."""
    rows = shape_sweep.sweep(spring, "modified-sine", [0.1, 0.25], errors=False)
    plain, _ = dynacam.run(dataclasses.replace(spring, law="modified-sine", theta=0.1))
    for k in shape_sweep.FIELDS:
        assert rows[0][k] == pytest.approx(plain[k], rel=1e-12)
    cyc, _ = dynacam.run(spring)
    assert spring.law == "cycloidal"
    for k in shape_sweep.FIELDS:
        assert rows[1][k] == pytest.approx(cyc[k], rel=1e-6)


def test_sweep_refuses_bad_input(spring):
    with pytest.raises(CamdynInputError, match="no shape parameter"):
        shape_sweep.sweep(spring, "cycloidal", errors=False)
    with pytest.raises(CamdynInputError, match="theta=0.6 is out of range"):
        shape_sweep.sweep(spring, "modified-sine", [0.1, 0.6], errors=False)
    with pytest.raises(CamdynInputError, match="--n"):
        shape_sweep.grid("modified-sine", 1)


def test_fig_8_8_optimum_and_improvements(spring):
    """Thesis sec. 8.2 on fig. 8.8 (spring-loaded mechanism, modified sine): the optimum is
    "at about theta = 0.1", the residual amplitude improves "by a factor of 2.9" on the
    cycloid (theta = 0.25) and the variation of the fictitious angular velocity "by a factor of
    2.7, almost coinciding with the positional-error optimum".  The scene takes some values the
    thesis does not print (spring_loaded.toml), so the factors are held to 20 % and the optima
    to theta 0.08 .. 0.14 (0.115 and 0.135 here, factors 3.04 and 3.17 on this grid)."""
    rows = shape_sweep.sweep(spring, "modified-sine", np.linspace(0.05, 0.25, 21), errors=False)
    u = shape_sweep.best(rows, "U0dd")
    w = shape_sweep.best(rows, "speed_variation_max")
    assert 0.08 <= u["theta"] <= 0.14 and 0.08 <= w["theta"] <= 0.14
    assert rows[-1]["U0dd"] / u["U0dd"] == pytest.approx(2.9, rel=0.2)
    assert rows[-1]["speed_variation_max"] / w["speed_variation_max"] == pytest.approx(2.7, rel=0.2)


def _camdyn(*args):
    import subprocess
    import sys

    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args],
                          capture_output=True, text=True)


def test_cli_sweep_json_files_and_bad_input(tmp_path, spring):
    """`camdyn laws --sweep`: rows equal the library's sweep (1e-12), the CSV and chart are
    written; bad input is one line on stderr, status 2."""
    import json

    p = _camdyn("laws", "--sweep", "spring_loaded", "--law", "sine-constant-cosine",
                "--values", "0.2,0.5", "--no-error-estimate", "--json", "--out", str(tmp_path))
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["parameter"] == "c" and len(out["files"]) == 2
    ref = shape_sweep.sweep(spring, "sine-constant-cosine", [0.2, 0.5], errors=False)
    for got, want in zip(out["rows"], ref):
        assert got["U0dd"] == pytest.approx(want["U0dd"], rel=1e-12)
    for bad in (["--law", "cycloidal"], ["--values", "0.1,x"], ["--values", "0.7"],
                ["--n", "1"]):
        p = _camdyn("laws", "--sweep", "spring_loaded", *bad)
        assert p.returncode == 2 and len(p.stderr.strip().splitlines()) == 1, (bad, p.stderr)


def test_scca_sweep_meets_the_modified_sine_at_c_zero(spring):
    """The SCCA law's c -> 0 end is the modified sine with theta = 1/8 (both: sine quarter
    waves over the first and last eighth, a cosine half wave between): the sweep at c = 1e-7
    equals the modified-sine run at 1/8 to 1e-5 (the law moves by O(c))."""
    scca = shape_sweep.sweep(spring, "sine-constant-cosine", [1e-7], errors=False)[0]
    ms = shape_sweep.sweep(spring, "modified-sine", [0.125], errors=False)[0]
    for k in shape_sweep.FIELDS:
        assert scca[k] == pytest.approx(ms[k], rel=1e-5), k


@pytest.mark.parametrize("argv, words", [
    (["--tau", "0.1"], ["--tau", "--sweep"]),
    (["--theta", "0.2"], ["--theta", "--sweep"]),
    (["--n", "3", "--values", "0.1,0.2"], ["--n", "--values"]),
    (["--values", "0.1,nan"], ["argument --values", "theta=nan"]),      # said --theta
])
def test_cli_sweep_refuses_options_it_would_drop(capsys, argv, words):
    """Options of the selection, or --n beside --values, were dropped unread: one line, exit 2."""
    from camdyn.runtime.cli import main

    rc = main(["laws", "--sweep", "spring_loaded", *argv])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and len(err.splitlines()) == 1, err
    assert all(w in err for w in words), err


def test_cli_sweep_failed_run_is_status_1(capsys, monkeypatch):
    """A failed run is not bad input: status 1 with 'run failed', as every command (it was
    status 2, the input errors' status)."""
    from camdyn.runtime.cli import main
    from camdyn.runtime.core.errors import SimulationError

    def fails(*args, **kwargs):
        raise SimulationError("step budget used up")
    monkeypatch.setattr(shape_sweep, "sweep", fails)
    assert main(["laws", "--sweep", "spring_loaded", "--n", "2"]) == 1
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "run failed" in err, err
