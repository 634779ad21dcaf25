"""Stability maps and measured boundaries.

The boundaries are measured by running the compiled methods with the stability check off and
bisecting the largest bounded step (runtime/studies/stability_boundary.py), and set against the
theory of the applicable axis (Hairer & Wanner, Solving ODEs II, sec. IV.2, fig. 2.1):

* the undamped one-DOF model (3.1), lambda = +-i omega: RK4's imaginary-axis limit
  2 sqrt(2) = 2.828;
* the first-order motor model (thesis sec. A.5.4.2), lambda = -G_a/J_ma real: the
  negative-real-axis limit 2.785; so is the one-DOF model with q = 0.9999, whose eigenvalues
  lie 0.8 deg off that axis (boundary 2.7855 in their direction);
* the thesis scheme (4.23)-(4.31) with its mid-step equation eliminated (4.25): 2 sqrt(2).
  The compiled scheme iterates that equation (factor (h omega)^2/8, 100 iterations) and stops
  converging first, at h omega = 2.397 here: measured and asserted as what it is.
"""
import json
import os
import math
import subprocess
import sys

import numpy as np
import pytest

from camdyn.runtime.core import stability
from camdyn.runtime.studies import stability_boundary as sb, stability_map as smap
from camdyn.runtime.core.errors import SimulationError, UnstableStep
from camdyn.runtime.core.simulator import Simulator

TAU = 0.05
OMEGA = 2 * math.pi / TAU
DWELL = (1.0, [1.0, 0.0])     # one-DOF dwell: t0 = 1, at rest at X = H = 1


def camdyn(*args):
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args],
                          capture_output=True, text=True)


# -- measured boundaries ----------------------------------------------------------------

def test_rk4_boundary_on_the_undamped_one_dof_is_the_imaginary_axis_limit():
    b = sb.measure_boundary("one_dof", "rk4", {"tau": TAU}, *DWELL)
    assert b.omega == pytest.approx(OMEGA, rel=1e-6)
    assert b.x == pytest.approx(stability.RK4_IMAG, rel=5e-3)      # measured 2.8286
    assert b.x > stability.RK4_REAL * 1.005                          # not the real-axis one


def test_rk4_boundary_on_the_negative_real_axis():
    """motor1: dw' = -(G_a/J_ma) dw - M_load/J_ma, lambda = -100/s; one_dof with q = 0.9999."""
    b = sb.measure_boundary("motor1", "rk4", {}, 0.2, [0.0])
    assert b.omega == pytest.approx(100.0, rel=1e-6)
    assert b.x == pytest.approx(stability.RK4_REAL, rel=5e-3)      # measured 2.7855
    d = sb.measure_boundary("one_dof", "rk4", {"tau": TAU, "q": 0.9999}, *DWELL)
    assert d.x == pytest.approx(2.785, rel=5e-3)                    # measured 2.7857
    assert d.x < stability.RK4_IMAG / 1.005


def test_koster_scheme_boundary_is_two_sqrt_two():
    """The thesis scheme with the mid-step elimination (4.25), run: 2 sqrt(2) (measured
    2.82841); its step matrix in runtime/core/stability.py says the same."""
    assert sb.koster_scheme_boundary() == pytest.approx(stability.KOSTER_BOUNDARY, rel=5e-3)
    x = 0.9 * stability.KOSTER_BOUNDARY
    X, V = sb.koster_scheme_step(0.3, -0.2, x, 1.0)
    assert [X, V] == pytest.approx(stability.koster_amplification(x) @ [0.3, -0.2], abs=1e-14)


def test_compiled_koster_reaches_the_scheme_boundary():
    """The compiled scheme solves its mid-step equation by Newton's method once the fixed-point
    iteration contracts slowly (factor x^2/8 on this model), so it is bounded up to the
    scheme's own boundary 2 sqrt(2) (measured 2.82841 in the dwell at 1 % amplitude, 2.8290
    over a full stroke); the fixed-point iteration alone gave up at 2.397 ("did not converge":
    (x^2/8)^100 ~ 1e-13 at x ~ 2.4), 15 % inside."""
    b = sb.measure_boundary("one_dof", "koster", {"tau": TAU}, 1.0, [1.01, 0.0])
    assert b.x == pytest.approx(stability.KOSTER_BOUNDARY, rel=5e-3)
    full = sb.measure_boundary("one_dof", "koster", {"tau": TAU}, 0.0, [0.0, 0.0])
    assert full.x == pytest.approx(stability.KOSTER_BOUNDARY, rel=5e-3)
    # where the fixed-point iteration failed, the run now completes, with the check on
    res = Simulator("one_dof", 3.0, "koster", step=2.6 / OMEGA).run({"tau": TAU})
    assert res.t[-1] == pytest.approx(3.0) and np.all(np.isfinite(res.y))


def test_compiled_koster_at_2_6_keeps_the_dwell_amplitude():
    """Newton's effect at h omega = 2.6, where the fixed-point iteration (factor 2.6^2/8 = 0.85)
    did not converge: the free vibration in the one-DOF model's dwell, X'' = w^2 (H - X) with
    H = 1, is carried by the scheme's step matrix (runtime/core/stability.py's docstring,
    ``koster_amplification``): [[a, b], [c, a]] on (u, u'/w), u = X - 1, determinant
    a^2 - bc = 1, so the quadratic form -c u^2 + b (u'/w)^2 is invariant (M^T diag(-c, b) M =
    diag(-c, b)): the amplitude is preserved, neither damped nor grown, over 2000 steps."""
    x = 2.6
    M = stability.koster_amplification(x)
    assert np.linalg.det(M) == pytest.approx(1.0, abs=1e-14)
    h = x / OMEGA
    res = Simulator("one_dof", 1.0 + 2000 * h, "koster", step=h, t0=1.0, y0=[1.01, 0.0],
                    check_stability=False).run({"tau": TAU})
    assert len(res.t) == 2001
    u, v = res.y[:, 0] - 1.0, res.y[:, 1] / OMEGA
    # the compiled steps are the step matrix, to rounding
    assert np.column_stack([u[1:], v[1:]]) == pytest.approx((M @ np.vstack([u[:-1], v[:-1]])).T,
                                                           abs=1e-13)
    Q = -M[1, 0] * u ** 2 + M[0, 1] * v ** 2
    assert Q == pytest.approx(Q[0], rel=1e-10)
    # the displacement's envelope: sqrt(Q/(-c)) bounds |u|, reached within a few steps
    assert np.abs(u).max() <= np.sqrt(Q[0] / -M[1, 0]) * (1 + 1e-10)
    assert np.abs(u[-200:]).max() == pytest.approx(np.abs(u[:200]).max(), rel=1e-2)


# -- the check on and off ---------------------------------------------------------------

def test_check_off_runs_what_the_check_refuses_and_reports_a_blow_up():
    h = 1.01 * stability.RK4_IMAG / OMEGA
    with pytest.raises(UnstableStep) as exc:
        Simulator("one_dof", 3.0, "rk4", step=h).run({"tau": TAU})
    assert exc.value.estimate.h_rho == pytest.approx(1.01 * stability.RK4_IMAG, rel=1e-6)
    with pytest.raises(SimulationError, match="non-finite"):   # |R(3.39 i)| = 3.2 a step
        Simulator("one_dof", 30.0, "rk4", step=1.2 * h, check_stability=False).run({"tau": TAU})
    # bounded but beyond the check's line: kept, with the estimate and a warning
    res = Simulator("one_dof", 1.2, "rk4", step=h, check_stability=False).run({"tau": TAU})
    assert not res.stability.stable and "stability check off" in res.warnings[0]


def test_cells_fine_inaccurate_refused_blew_up():
    """tau = 2/19 (a maximum of U0): RK4 at h omega = 0.1 fine at 1e-3; at 1.5 inaccurate
    (RK4 damps the residual vibration by |R(1.5 i)|^N); 1.01 x 2 sqrt(2) refused with the
    check on, blew up with it off (the residual vibration grows over the dwell: |R| = 1.07
    a step, 42 steps; too few to overflow or pass BLOWUP, caught by dwell_growth)."""
    tau = 2 / 19
    w = 2 * math.pi / tau
    p = {"tau": tau}
    target = smap.target_of("one_dof", 3.0)
    ref = smap.reference(target.with_parameters(p))

    def cell(x, check=True):
        return smap.classify_cell(target, "rk4", x / w, p, ref, threshold=1e-3, t_end=3.0,
                                  check_stability=check)

    assert cell(0.1).status == "fine"
    c = cell(1.5)
    assert c.status == "inaccurate" and c.error > 1e-3 and not c.refused
    c = cell(1.01 * stability.RK4_IMAG)
    assert c.status == "refused" and c.refused and c.outcome == "blew up"
    c = cell(1.01 * stability.RK4_IMAG, check=False)
    assert c.status == "blew up" and c.refused and c.figure is None
    assert "grew" in c.reason and c.h_rho == pytest.approx(1.01 * stability.RK4_IMAG, rel=1e-6)
    assert c.cpu_seconds >= 0 and c.n_steps > 0


def test_map_counts_and_theory_line():
    m = smap.run_map("one_dof", "tau", [2 / 19, 2 / 9], ["rk4", "dp54"],
                     steps=[0.002, 0.01, 0.06], rtols=[1e-3, 1e-9], threshold=1e-3)
    assert len(m.cells) == 2 * 3 + 2 * 2
    assert m.step_limit["rk4"] == pytest.approx([stability.RK4_IMAG * t / (2 * math.pi)
                                                 for t in (2 / 19, 2 / 9)], rel=1e-6)
    status = {(c.method, round(c.param, 4), c.setting): c.status for c in m.cells}
    assert status[("rk4", round(2 / 19, 4), 0.06)] == "refused"     # h omega = 3.6
    assert status[("rk4", round(2 / 9, 4), 0.002)] == "fine"
    assert status[("dp54", round(2 / 9, 4), 1e-9)] == "fine"
    assert all(c.n_steps > 0 for c in m.cells if c.method == "dp54")
    fine = smap.largest_fine(m, "rk4")
    assert fine[1] is not None and fine[1] < m.step_limit["rk4"][1]


# -- the thesis, sec. 4.4.2 ---------------------------------------------------------------

CASES = [(tau, Fa) for Fa in (0.5, 0.8, 1.5, 2.0) for tau in (0.07, 0.1, 0.125, 0.15, 0.175,
                                                              0.2, 0.25)]


def test_thesis_step_criterion_and_the_one_and_a_half_percent():
    """"Stable if Delta T <= 0.1 tau" is h omega = 0.628, 4.5 times inside the measured
    boundary 2.828 (Delta T = 0.45 tau): the thesis's criterion is an accuracy criterion, not
    the stability limit.  "From 0.1 tau to 0.01 tau the residual amplitude changes by 1.5 %":
    measured with koster on CAMSHAFT-1 over the practical range of fig. 4.11 (tau 0.07-0.25,
    Fa 0.5-2; the thesis does not say where), the median change is 1.28 %, which agrees; but
    it is no bound: near a minimum of U0 (tau = 0.1, Fa = 0.5: U0 = 4.3e-5) it is 93 %, and
    10 of the 28 cases exceed 1.5 %.  Asserted: the median within a factor 1.5 of 1.5 % (the
    thesis gives one figure from an unknown set of cases), and the spread."""
    r = sb.thesis_step_comparison(CASES, sb.koster_scheme_boundary())
    assert r["thesis_h_omega"] == pytest.approx(0.6283, abs=1e-4)
    assert r["measured_step_over_tau"] == pytest.approx(0.450, abs=1e-3)
    assert r["margin"] == pytest.approx(4.50, abs=0.01)
    assert 0.015 / 1.5 <= r["change_median"] <= 0.015 * 1.5          # measured 0.0128
    over = sum(c["change"] > 0.015 for c in r["cases"])
    assert 5 <= over <= 15 and r["change_max"] > 0.5                  # measured 10, 0.93


def test_the_reference_carries_its_estimate_and_its_window():
    """The map's reference is the answer contract's: its figure U0 at DP54 rtol 1e-11 with its
    estimate, checked against (3.5) (the undamped one-DOF model is its closed form: the true
    error lies within ten times the estimate); its run must hold the window U0 needs (one
    period tau past the rise): at tau = 0.9 an end T = 1.5 given by the user is refused
    naming the end it needs, 1.9."""
    from camdyn.runtime.core.errors import CamdynInputError
    from camdyn.runtime.measure import references

    m = smap.run_map("one_dof", "tau", [2 / 9, 0.9], ["dp54"], rtols=[1e-6], threshold=1e-3)
    for tau, u0, rel in zip(m.values, m.reference, m.reference_error):
        exact = references.U0(tau)
        assert 0 < rel < 1e-8
        assert abs(u0 - exact) <= 10 * rel * u0 + 1e-15
    assert m.t_end == [3.0, 3.0] and m.warnings == []
    with pytest.raises(CamdynInputError, match="give t_end >= 1.9"):
        smap.run_map("one_dof", "tau", [0.9], ["dp54"], rtols=[1e-6], t_end=1.5)
    # a threshold the reference cannot resolve is said
    m = smap.run_map("one_dof", "tau", [2 / 9], ["dp54"], rtols=[1e-6], threshold=1e-11)
    assert len(m.warnings) == 1 and "cannot tell fine from inaccurate" in m.warnings[0]


# -- the command ------------------------------------------------------------------------

def test_cli_writes_png_csv_json(tmp_path):
    p = camdyn("stability", "one_dof", "--param", "tau=0.105263,0.222222", "--steps",
               "0.002,0.02,0.06", "--rtols", "1e-4,1e-8", "--methods", "rk4", "koster", "dp54",
               "--out", str(tmp_path), "--json")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert {f.rsplit(".", 1)[1] for f in out["files"]} == {"png", "csv", "json"}
    assert (tmp_path / "stability_one_dof_tau.png").stat().st_size > 1000
    csv_lines = (tmp_path / "stability_one_dof_tau.csv").read_text().splitlines()
    assert csv_lines[0].startswith("method,param,setting,status,outcome")
    assert len(csv_lines) == 1 + 2 * 3 * 2 + 2 * 2
    full = json.loads((tmp_path / "stability_one_dof_tau.json").read_text())
    assert full["counts"]["rk4"]["refused"] == out["counts"]["rk4"]["refused"] >= 1
    assert "stability_one_dof" in p.stderr or p.stderr.count("camdyn stability:") == 6


@pytest.mark.parametrize("args, part", [
    (["--param", "tau=0:1:3"], "tau=0 is out of range"),
    (["--param", "tau=a:b"], "argument --param"),
    (["--param", "nope=0.1:0.2:2"], "has no parameter nope"),
    (["--threshold", "2"], "argument --threshold"),
    (["--steps", "-1,2"], "argument --steps"),
    (["--methods", "euler"], "unknown method"),
])
def test_cli_refuses_bad_input_with_one_line(args, part, tmp_path):
    p = camdyn("stability", "one_dof", "--out", str(tmp_path), "--quiet", *args)
    assert p.returncode == 2
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and part in lines[0], p.stderr
    assert lines[0].startswith("camdyn stability: error:")


# -- the beam follower (E or N) -------------------------------------------------------------

def test_beam_map_cells_against_their_own_runs():
    """The beam follower's map over N (dp54, rodas4 over rtol): each cell's error is
    |max |v_E| - reference| / reference, recomputed here from an independent run of the same
    case through runtime/targets/beam.py (same figure to 1e-12), the reference DP54 at rtol 1e-9; at a
    threshold of 1e-5 the loose rtol 1e-3 is inaccurate and rtol 1e-8 fine (measured errors on
    N = 1: dp54 ~1e-4 / ~1e-9)."""
    from dataclasses import replace

    from camdyn.runtime.targets import beam
    from camdyn.runtime.studies import stability_beam
    from camdyn.runtime.targets.beam_case import Case

    m = stability_beam.run_map("N", [1], ["dp54", "rodas4"], [1e-3, 1e-8], threshold=1e-5)
    ref = beam.run(Case(modes=1, rtol=1e-9))[0]["max_abs_tip_deflection"]
    assert m.reference[0] == pytest.approx(ref, rel=1e-12)
    # its estimate: the change from rtol 1e-8, a bound well inside the threshold
    loose = beam.run(Case(modes=1, rtol=1e-8))[0]["max_abs_tip_deflection"]
    assert m.reference_error[0] == pytest.approx(abs(ref - loose) / ref, rel=1e-9)
    assert m.reference_error[0] < 1e-6 and m.warnings == []
    for c in m.cells:
        v = beam.run(Case(modes=1, rtol=c.setting, method=c.method))[0]["max_abs_tip_deflection"]
        assert c.figure == pytest.approx(v, rel=1e-12)
        assert c.error == pytest.approx(abs(v - ref) / ref, rel=1e-9)
        assert c.status == ("fine" if c.error <= 1e-5 else "inaccurate")
    by = {(c.method, c.setting): c.status for c in m.cells}
    assert by["dp54", 1e-3] == "inaccurate" and by["dp54", 1e-8] == "fine"


def test_beam_map_cli_and_bad_input(tmp_path):
    """`camdyn stability beam-follower --param N=1` writes PNG, CSV, JSON; an N outside 1..6,
    a non-positive E, --steps (the beam map takes rtols) and an unknown --param are refused
    in one line with status 2."""
    p = camdyn("stability", "beam-follower", "--param", "N=1", "--rtols", "1e-4,1e-6",
               "--out", str(tmp_path), "--json", "--quiet")
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["counts"]["dp54"]["fine"] + out["counts"]["dp54"]["inaccurate"] == 2
    for f in out["files"]:
        assert os.path.getsize(f) > 0
    for bad in (["--param", "N=7"], ["--param", "E=-1,2e11"], ["--param", "N=1", "--steps", "1e-3"],
                ["--param", "tau=0.1"]):
        p = camdyn("stability", "beam-follower", *bad, "--out", str(tmp_path), "--quiet")
        assert p.returncode == 2 and len(p.stderr.strip().splitlines()) == 1, (bad, p.stderr)
