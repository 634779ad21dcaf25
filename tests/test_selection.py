"""Cam-law selection criteria of thesis sec. 9.2.2: `camdyn laws --tau T --fa F`,
thesis/design/selection.py."""
import json
import math
import subprocess
import sys

import numpy as np
import pytest

from camdyn.runtime.core.errors import CamdynInputError

from camdyn.runtime.measure import references as closed_forms
from camdyn.runtime.measure.envelope import envelope, tau_grid
from camdyn.thesis.design import selection
from camdyn.thesis.theory import impact


def test_impact_sensitivity_of_the_cycloid():
    """r_e/S^(2/3) at the cycloid's reversal points, |H'''| = 4 pi^2 (A.2.16): (18 pi^2)^(1/3) =
    5.62, the reading of (3.16) that gives sec. 7.4.4's printed r_e = 0.31 at S = 1.27e-2."""
    row = selection.criteria("cycloidal", 0.15, 0.0)
    want = (18 * math.pi ** 2) ** (1 / 3)
    for k in ("impact_T0", "impact_T05", "impact_T1"):
        assert row[k] == pytest.approx(want, rel=1e-12)
    S = 1.27e-2
    assert row["impact_T0"] * S ** (2 / 3) == pytest.approx(impact.r_e_from_backlash(S), rel=1e-12)
    assert round(row["impact_T0"] * S ** (2 / 3), 2) == 0.31


def test_impulsive_jerk_is_infinite_sensitivity():
    """Where H'' jumps (simple harmonic at T = 0 and 1, parabolic everywhere) the follower meets
    an impact without backlash: the sensitivity is infinite, not a number."""
    sh = selection.criteria("simple-harmonic", 0.15, 0.0)
    assert math.isinf(sh["impact_T0"]) and math.isinf(sh["impact_T1"])
    assert math.isfinite(sh["impact_T05"])


def test_envelope_at_fa0_is_the_closed_forms():
    """At Fa = 0 CAMSHAFT-1 is the one-DOF model: the envelope of the simulated U0 around tau
    equals the envelope of (3.5) on the same grid (runs at rtol 1e-9; asserted 1e-6).  Its
    estimate covers the envelope of (3.5) on a grid a hundred times finer (what the
    sampling leaves) and stays below 1e-3 of it; the window brackets tau with maxima on
    both sides (1.5 dip spacings each way)."""
    from camdyn.runtime.measure.envelope import maxima

    for tau in (0.15, 0.3):
        row = selection.criteria("cycloidal", tau, 0.0)
        taus = selection.window("cycloidal", tau, 0.0)
        mt, _ = maxima(taus, closed_forms.U0(taus))
        assert mt.min() < tau < mt.max()
        assert row["U0_envelope"] == pytest.approx(
            float(envelope(taus, closed_forms.U0(taus))(tau)), rel=1e-6)
        assert row["U0dd_envelope"] == pytest.approx(
            float(envelope(taus, closed_forms.U0dd(taus))(tau)), rel=1e-6)
        fine = tau_grid(taus[0], taus[-1], 100 * len(taus))
        for k, form in (("U0", closed_forms.U0), ("U0dd", closed_forms.U0dd)):
            true = float(envelope(fine, form(fine))(tau))
            assert abs(row[f"{k}_envelope"] - true) <= row[f"{k}_envelope_error"], (tau, k)
            assert row[f"{k}_envelope_error"] < 1e-3 * true, (tau, k)


def test_pressure_angle_of_the_cycloid_cam():
    """alpha_max of a 90/90/90/90 deg cycloidal cam (h 15 mm, r_b 26 mm, r_r 5 mm, no offset)
    against the closed form tan alpha = s'(phi)/(r_b + r_r + s(phi)), s = h (x - sin(2 pi x)/
    (2 pi)), x = phi/beta, over 1e5 angles of the rise: within 0.01 deg (the cam is sampled at
    10 points a degree)."""
    geo = {"stroke": 0.015, "base_radius": 0.026, "roller_radius": 0.005}
    row = selection.criteria("cycloidal", 0.15, 0.0, geometry=geo)
    beta = math.pi / 2
    x = np.linspace(0, 1, 100001)
    s = 0.015 * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    ds = 0.015 / beta * (1 - np.cos(2 * np.pi * x))
    want = np.degrees(np.arctan(ds / (0.031 + s))).max()
    assert row["alpha_max_deg"] == pytest.approx(want, abs=0.01)
    assert 0 < row["rho_min"] < 0.031


@pytest.mark.parametrize("angles", [(120.0, 60.0, 120.0, 60.0), pytest.param(
    (60.0, 120.0, 100.0, 80.0), marks=pytest.mark.slow)])
def test_laws_take_the_real_angles(angles):
    """camdyn laws --angles: alpha_max of the cycloidal cam at the cam's own rise angle (25 mm
    in 120 deg: 21.2 deg, not the 27-32 deg of a 90 deg rise), against the closed form
    tan alpha = s'/(r_b + r_r + s), s' = h/beta (1 - cos 2 pi x), over 1e5 angles of the rise
    (the return mirrors it): within its estimate and 0.01 deg; the uniform law's corners give
    a least radius of 0 with the check's warning."""
    rows = {r["law"]: r for r in selection.select(
        0.1, None, None, 0.025, 0.04, 0.01, estimate=False,
        angles=",".join(f"{a:g}" for a in angles)).rows}
    beta = math.radians(min(angles[0], angles[2]))        # the steeper of rise and return
    x = np.linspace(0, 1, 100001)
    s = 0.025 * (x - np.sin(2 * np.pi * x) / (2 * np.pi))
    ds = 0.025 / beta * (1 - np.cos(2 * np.pi * x))
    want = np.degrees(np.arctan(ds / (0.05 + s))).max()
    row = rows["cycloidal"]
    assert abs(row["alpha_max_deg"] - want) <= max(row["alpha_max_deg_error"], 0.01)
    assert rows["uniform"]["rho_min"] == 0.0
    assert any("jumps" in w for w in rows["uniform"]["warnings"])


def test_laws_angles_are_refused_alone_or_bad():
    for kw, words in (({"angles": "120,60,120,60"}, "goes with --stroke"),
                      ({"angles": "120,60,100,60", "stroke": 0.025, "base_radius": 0.04,
                        "roller_radius": 0.01}, "argument --angles")):
        with pytest.raises(CamdynInputError, match=words):
            selection.select(0.1, estimate=False, **kw)


def camdyn(*args):
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args],
                          capture_output=True, text=True)


def test_cli_table_json_and_bad_input(tmp_path):
    p = camdyn("laws", "--tau", "0.2", "--fa", "0.3", "--json", "--out", str(tmp_path))
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert [r["law"] for r in out["rows"]][0] == "cycloidal" and len(out["files"]) == 2
    for bad in (["--tau", "1.5"], ["--tau", "0.2", "--stroke", "0.01"], ["--fa", "0.3"]):
        p = camdyn("laws", *bad)
        assert p.returncode == 2 and len(p.stderr.strip().splitlines()) == 1, (bad, p.stderr)


@pytest.mark.parametrize("argv, words", [
    (["--tau", "0.1", "--fa", "inf"], ["--fa", "0 <= Fa <= 100"]),      # failed after a run
    (["--tau", "0.1", "--theta", "0.7"], ["--theta", "0.5"]),           # after two laws ran
    (["--tau", "0.1", "--law", "cycloidal"], ["--law", "--sweep"]),     # dropped unread
    (["--stroke", "0.01", "--base-radius", "0.05", "--roller-radius", "0.01"],
     ["--stroke", "--tau"]),                                            # table without them
    (["--out", "x"], ["--out", "--tau"]),
    (["--n", "3"], ["--n", "--sweep"]),
])
def test_bad_or_stray_options_are_one_line_before_any_run(capsys, argv, words):
    """Refused before the first law runs: one line on stderr (no progress line), exit 2."""
    from camdyn.runtime.cli import main

    rc = main(["laws", *argv])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and len(err.splitlines()) == 1, err
    assert all(w in err for w in words), err


@pytest.mark.parametrize("argv", [["laws", "--tau", "0.1"],
                                  ["laws", "--sweep", "spring_loaded", "--n", "2"],
                                  ["design", "--stroke", "0.1", "--tau", "0.1", "--fa", "0"]])
def test_out_that_cannot_be_made_is_one_line_before_any_run(tmp_path, capsys, argv):
    """--out below a file: an OSError traceback after the runs (laws --tau, laws --sweep,
    design); now one line naming --out, exit 2, before any run (no progress line)."""
    from camdyn.runtime.cli import main

    (tmp_path / "f").write_text("")
    assert main([*argv, "--out", str(tmp_path / "f" / "sub")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "argument --out" in err, err
