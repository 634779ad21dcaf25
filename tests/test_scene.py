"""DYNACAM scene files: strict checking before anything runs (issue 4, item 4)."""
import copy
import json
import subprocess
import sys
import tomllib

import pytest

from camdyn.runtime import dynacam, scene as scenes
from camdyn.runtime.errors import CamdynInputError


def _data(name):
    return tomllib.loads(scenes.builtin(name).read_text())


@pytest.mark.parametrize("name", ["indexing", "spring_loaded"])
def test_builtin_scenes_load(name):
    sc = scenes.load(name)
    assert sc.variant.startswith("dynacam_")
    assert set(sc.parameters) == {p for p in scenes._declared_parameters(sc.options)} - {"beta_0"}


@pytest.mark.parametrize("edit,message", [
    (lambda d: d["parameters"].pop("c_x"), "parameters.c_x is missing"),
    (lambda d: d["parameters"].__setitem__("m_x", -1.0), "parameters.m_x=-1 is out of range"),
    (lambda d: d["parameters"].__setitem__("J", "heavy"), "parameters.J must be a number"),
    (lambda d: d["parameters"].__setitem__("J", True), "parameters.J must be a number"),
    (lambda d: d["parameters"].__setitem__("q_x", 1.5), "parameters.q_x=1.5 is out of range"),
    (lambda d: d["parameters"].__setitem__("V_R", 1.0), "parameters.V_R is not a parameter"),
    (lambda d: d["parameters"].__setitem__("beta_0", 0.1), "parameters.beta_0 is set by the run"),
    (lambda d: d["options"].__setitem__("gear", "chain"), "options.gear='chain': choose one of"),
    (lambda d: d["options"].__setitem__("spring", 1), "options.spring must be true or false"),
    (lambda d: d["options"].__setitem__("flywheel", True), "options.flywheel is not an option"),
    (lambda d: d["run"].__setitem__("T_end", -1.0), "run.T_end=-1 is out of range"),
    # a run that stops inside the rise has no largest rise deceleration to report
    (lambda d: d["run"].__setitem__("T_end", 0.9), r"run.T_end=0.9 is out of range [1, 50]"),
    (lambda d: d.__setitem__("colour", "red"), "colour is not a scene key"),
    (lambda d: d.__setitem__("law", "spline"), "unknown cam law 'spline'"),
])
def test_bad_scenes_are_refused_by_name(edit, message):
    d = copy.deepcopy(_data("indexing"))
    edit(d)
    with pytest.raises(CamdynInputError, match=message.replace("(", r"\(").replace("[", r"\[")):
        scenes.from_dict(d)


def test_options_without_a_generated_variant_are_refused_before_running():
    d = copy.deepcopy(_data("indexing"))
    d["options"]["external"] = True
    d["parameters"]["F_ex"] = 10.0
    sc = scenes.from_dict(d)
    with pytest.raises(CamdynInputError, match="dynacam_acbg_yze, which is not generated"):
        dynacam.run(sc)


def test_cli_names_the_bad_parameter(tmp_path):
    text = scenes.builtin("spring_loaded").read_text().replace("c_s = 1000.0", "c_s = -5.0")
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    proc = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", "simulate", str(bad), "--json",
                           "--out", str(tmp_path / "out")], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2
    assert "parameters.c_s=-5 is out of range" in proc.stderr
    assert proc.stdout == "" and not (tmp_path / "out").exists()


def test_characteristics_of_the_scenes_are_the_printed_ones():
    """tau, Fa, Fv formed from the scene parameters as App. 7 forms them: indexing tau = 0.08,
    Fa = 3.34, Fv = 7.5 (A.7.2, fig. A.7.3); spring-loaded tau = 0.141 (0.142 with the table's
    c_c), Fa = 2.04, Fv = 2.68 (A.7.3, fig. A.7.6).  Tolerance: the printed digits."""
    ix = scenes.load("indexing")
    ch = dynacam.characteristics(ix.options, ix.parameters)
    assert ch["tau"] == pytest.approx(0.08, abs=0.005)
    assert ch["Fa"] == pytest.approx(3.34, abs=0.01)
    assert ch["Fv"] == pytest.approx(7.5, abs=0.05)
    sl = scenes.load("spring_loaded")
    ch = dynacam.characteristics(sl.options, sl.parameters)
    assert ch["tau"] == pytest.approx(0.141, abs=0.0015)
    assert ch["Fa"] == pytest.approx(2.04, abs=0.005)
    assert ch["Fv"] == pytest.approx(2.68, abs=0.05)
