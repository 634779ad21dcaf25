"""The least model of a DYNACAM scene (runtime/studies/least_model.py; thesis sec. 8.2) on the two
mechanisms of thesis fig. 8.1, whose model comparison is sec. 8.2.4-8.2.5 (fig. 8.3).

Every error bound is checked against independent full runs: the scene's own 4-DOF model at
tight tolerance, and CAMSHAFT-2 through dynacam.reduced_models (another figure extraction,
over the dwell after the cam's rise).  The scenes run in milliseconds, so the whole file
takes a few seconds.
"""
import json
import math
import subprocess
import sys

import pytest

from camdyn.runtime.targets import dynacam, scene_files as scenes
from camdyn.runtime.studies import least_model
from camdyn.runtime.core.methods import DP54

FIGS = least_model.DEFAULT_FIGURES
TOL = least_model.TOLERANCE


@pytest.fixture(scope="module")
def decided(tmp_path_factory):
    """choose() on fig8_1a, fig8_1b and spring_loaded with an empty on-demand cache (so the
    chain holds the pre-generated variants only, whatever the user's cache holds), with the
    full model's run at the scene's rtol and at 1e-11 for each."""
    mp = pytest.MonkeyPatch()
    mp.setenv("CAMDYN_CACHE_DIR", str(tmp_path_factory.mktemp("cache")))
    out = {}
    try:
        for name in ("fig8_1a", "fig8_1b", "spring_loaded"):
            sc = scenes.load(name)
            r = least_model.choose(sc)
            full = dynacam.run(sc)[0]
            ref = dynacam.run(sc, method=DP54(rtol=1e-11))[0]
            out[name] = (sc, r, full, ref)
    finally:
        mp.undo()
    return out


def _cand(r, key):
    return next(c for c in r["candidates"] if c["key"] == key)


def test_fig8_1a_two_dof_reduction_rejected_sec_8_2_4(decided):
    """Sec. 8.2.4: 'replacement of the four-degrees-of-freedom model by a two-degrees-of-
    freedom model is not permissible if c_z' << c_x' (fig. 8.1a: c_z'/c_x = 0.1 in the scene
    file; fig. 8.3a: U0'' of curve (5) is 2.45 times that of curve (4)).  Both the 2-DOF
    DYNACAM model and CAMSHAFT-2 must be rejected, the criterion must say 'against', and the
    model that runs must keep the shaft's z direction.  The predicted U0'' error of CAMSHAFT-2
    must be the one of the full-tolerance comparison of dynacam.reduced_models to 1e-3, and
    1 + that error the thesis's 2.45 to 10 % (as tests/test_dynacam.py takes it)."""
    sc, r, full, _ = decided["fig8_1a"]
    assert r["chosen"] in ("full", "no_shaft_y")
    for key in ("no_shafts", "camshaft2", "camshaft1", "one_dof"):
        assert not _cand(r, key)["accepted"], key
    cz = next(c for c in _cand(r, "camshaft2")["criteria"] if c["name"] == "c_z'/c_x")
    assert cz["value"] == pytest.approx(sc.parameters["c_z"] / sc.parameters["c_x"], rel=1e-12)
    assert cz["value"] == pytest.approx(0.1, rel=1e-9) and cz["verdict"] == "against"
    u = dynacam.reduced_models(sc, full)
    true = abs(u["2dof"] - u["4dof"]) / u["4dof"]
    pred = _cand(r, "camshaft2")["predicted"]["U0dd"]
    assert pred == pytest.approx(true, abs=1e-3)
    assert 1 + pred == pytest.approx(2.45, rel=0.10)


def test_fig8_1b_two_dof_reduction_accepted_sec_8_2_4(decided):
    """Sec. 8.2.4: with c_z' >> c_x (fig. 8.1b, c_z'/c_x = 10) 'the four-degrees-of-freedom
    model resembles that with two degrees of freedom' (fig. 8.3b: a factor 1.08).  CAMSHAFT-2
    must be accepted at 5 % on U0, U0'', X''_min and be the chosen model or be passed by a
    smaller one; the criterion must say 'for'.  The predicted U0'' error must be the
    full-tolerance comparison's to 1e-3 (dynacam.reduced_models)."""
    sc, r, full, _ = decided["fig8_1b"]
    c2 = _cand(r, "camshaft2")
    assert c2["accepted"] and _cand(r, "no_shafts")["accepted"]
    order = [c["key"] for c in r["candidates"]]
    assert order.index(r["chosen"]) >= order.index("camshaft2")
    cz = next(c for c in c2["criteria"] if c["name"] == "c_z'/c_x")
    assert cz["value"] == pytest.approx(10.0, rel=1e-9) and cz["verdict"] == "for"
    u = dynacam.reduced_models(sc, full)
    assert c2["predicted"]["U0dd"] == pytest.approx(abs(u["2dof"] - u["4dof"]) / u["4dof"], abs=1e-3)


@pytest.mark.parametrize("name", ["fig8_1a", "fig8_1b", "spring_loaded"])
def test_error_bound_holds_against_the_full_model(decided, name):
    """The stated bound on every figure against the full model's figure at rtol 1e-11
    (error ~1e-10 relative): |f - f_full| <= bound, and the bound is not loose: below
    10 times the true error plus 1e-9 |f_full|, or below the tolerance."""
    _, r, _, ref = decided[name]
    for f in FIGS:
        true = abs(r["result"][f] - ref[f])
        assert true <= r["bound"][f], (f, true, r["bound"][f])
        assert (r["bound"][f] <= 10 * true + 1e-9 * abs(ref[f])
                or r["bound"][f] <= TOL * abs(ref[f])), (f, true, r["bound"][f])


@pytest.mark.parametrize("name", ["fig8_1a", "fig8_1b"])
def test_probes_predict_the_full_tolerance_differences(decided, name):
    """Every probed candidate's predicted error (probes at rtol 1e-5, 1e-6) against the
    difference of the candidate and the full model both run at the scene's rtol 1e-8: equal to
    2e-3 (relative), and never below it by more than 1e-5: the prediction is the model error,
    not the probes' numerical error."""
    sc, r, full, _ = decided[name]
    chain = {c.key: c for c in least_model.chain(sc)}
    for c in r["candidates"]:
        if not c["predicted"] or c["key"] == "full":
            continue
        figs = least_model.run_candidate(sc, chain[c["key"]], sc.rtol)[0]
        for f in FIGS:
            true = abs(figs[f] - full[f]) / abs(full[f])
            assert c["predicted"][f] == pytest.approx(true, abs=2e-3), (c["key"], f)
            assert c["predicted"][f] >= true - 1e-5, (c["key"], f)


@pytest.mark.parametrize("name", ["fig8_1a", "fig8_1b"])
def test_shaft_free_scene_keeps_tau_Fa_Fv(name):
    """Dropping the shaft directions with the equivalent magnitudes of sec. 5.6 (c_x -> c_c
    (4.3), m_x -> m (4.39), k -> c_tan R_1/2^2 (4.4), J -> m_tan R_1/2^2 (5.51)) keeps the
    printed characteristic numbers of fig. 8.1 (tau, Fa, Fv) to 1e-12."""
    sc = scenes.load(name)
    red = least_model._shaft_free(sc, True, True, build=False)
    assert not (red.options.shaft_y or red.options.shaft_z)
    a = dynacam.characteristics(sc.options, sc.parameters)
    b = dynacam.characteristics(red.options, red.parameters)
    for k in ("tau", "Fa", "Fv"):
        assert b[k] == pytest.approx(a[k], rel=1e-12)


def test_one_dof_criterion_is_the_cycloid_stiffness_dip_4_19(decided):
    """The one-DOF criterion Fa max H'^2 is 4 Fa for the cycloid (H'max = 2, (A.2.9)): the
    stiffness dip 1 + 4 Fa of (4.19); to 1e-6 (the law sampled on 2001 points hits T = 1/2)."""
    sc, r, _, _ = decided["fig8_1b"]
    c = _cand(r, "one_dof")["criteria"][0]
    Fa = dynacam.characteristics(sc.options, sc.parameters)["Fa"]
    assert c["name"] == "Fa max H'^2"
    assert c["value"] == pytest.approx(4 * Fa, rel=1e-6)


def test_spring_loaded_motor_dropped_under_2_percent_A_5_4_3(decided):
    """Sec. A.5.4.3: the asynchronous motor's speed varies by under 2 %; the full probe of
    spring_loaded must measure that (criterion 'for') and the ideal drive must be accepted at
    5 %.  The follower spring may not be dropped: sec. 8.2.3 finds the residual amplitude
    1.1 lower without it; ours, with the scene's damping, is off by more than the tolerance."""
    _, r, _, _ = decided["spring_loaded"]
    drive = _cand(r, "ideal_drive")
    crit = drive["criteria"][0]
    assert 0 < crit["value"] < 0.02 and crit["verdict"] == "for"
    assert drive["accepted"]
    assert not _cand(r, "no_spring")["accepted"]
    assert r["chosen"] == "ideal_drive"


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "simulate", *args],
                          capture_output=True, text=True, timeout=300)


def test_cli_model_auto_json_and_bad_input(tmp_path):
    """`camdyn simulate fig8_1b --model auto --json` gives CAMSHAFT-2 with bounds; a figure the
    choice does not know, or a tolerance outside (0, 1), is one line naming the argument and
    its allowed values, exit 2."""
    import os

    env_dir = str(tmp_path)
    p = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "simulate", "fig8_1b",
                        "--model", "auto", "--json"], capture_output=True, text=True, timeout=300,
                       env={**os.environ, "CAMDYN_CACHE_DIR": env_dir})
    assert p.returncode == 0, p.stderr
    out = json.loads(p.stdout)
    assert out["chosen"] == "camshaft2"
    assert all(math.isfinite(out["bound"][f]) for f in FIGS)
    for args, word in ((["--figures", "U0,nope"], "--figures"),
                       (["--tolerance", "1.5"], "--tolerance")):
        p = _cli("fig8_1b", "--model", "auto", *args)
        lines = p.stderr.strip().splitlines()
        assert p.returncode == 2 and len(lines) == 1 and word in lines[0], p.stderr
        assert "Traceback" not in p.stderr


@pytest.mark.parametrize("args, words", [
    (["--figures", "U0,U0"], ["--figures", "U0", "twice"]),     # ran, printing U0 twice
    (["--figures", ","], ["--figures", "choose from"]),
    (["--tolerance", "nan"], ["--tolerance", "0 < tolerance < 1"]),
    (["--tolerance", "inf"], ["--tolerance", "0 < tolerance < 1"]),
    (["--tolerance", "0"], ["--tolerance", "0 < tolerance < 1"]),
    (["--no-error-estimate"], ["--no-error-estimate", "--model auto"]),   # ignored before
])
def test_bad_choice_input_is_one_line(capsys, args, words):
    """Refused before any probe: one line naming the argument and what it allows, exit 2."""
    from camdyn.runtime.cli import main

    rc = main(["simulate", "fig8_1b", "--model", "auto", *args])
    err = capsys.readouterr().err.strip()
    assert rc == 2 and len(err.splitlines()) == 1, err
    assert all(w in err for w in words), err


@pytest.mark.slow
def test_fig8_1a_with_built_variants_drops_y_not_z(tmp_path, monkeypatch):
    """With the 3-DOF variants built on demand (about 7 s each, into an empty cache):
    dropping the shaft's z direction from fig8_1a is rejected (sec. 8.2.4: c_z' << c_x, the
    U0'' error is of the order of the 2-DOF model's factor 2.45 - 1), dropping y (c_y'/c_beta'
    = 7.6) may be accepted; whichever runs, its bounds hold against the full run at rtol
    1e-11 as in test_error_bound_holds_against_the_full_model."""
    monkeypatch.setenv("CAMDYN_CACHE_DIR", str(tmp_path))
    sc = scenes.load("fig8_1a")
    r = least_model.choose(sc, build=True)
    z = _cand(r, "no_shaft_z")
    assert z["predicted"] and not z["accepted"]
    assert z["predicted"]["U0dd"] > 1.0
    assert r["chosen"] in ("full", "no_shaft_y")
    ref = dynacam.run(sc, method=DP54(rtol=1e-11))[0]
    for f in FIGS:
        true = abs(r["result"][f] - ref[f])
        assert true <= r["bound"][f] <= max(10 * true + 1e-9 * abs(ref[f]), TOL * abs(ref[f]))
