"""Scene files: one format with a kind, strict checking before anything runs (README
"Scenes")."""
import copy
import json
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from camdyn.runtime.targets import dynacam, scene_files as scenes
from camdyn.runtime.targets.resolve import KINDS, load_scene
from camdyn.runtime.core.errors import CamdynInputError

ROOT = Path(__file__).resolve().parents[1]


def _data(name):
    return tomllib.loads(scenes.builtin(name).read_text())


@pytest.mark.parametrize("name", ["indexing", "spring_loaded"])
def test_builtin_scenes_load(name):
    sc = scenes.load(name)
    assert sc.variant.startswith("dynacam_")
    assert set(sc.parameters) == {p for p in scenes.declared_parameters(sc.options)} - {"beta_0"}


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


# -- one format for every kind -------------------------------------------------------------------

def _cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args], capture_output=True,
                          text=True, timeout=300, cwd=cwd)


def test_every_builtin_scene_loads_as_its_kind():
    """Every file of runtime/scenes/ says its kind and loads through the one loader as that
    kind; `camdyn scenes --json` lists exactly these files with their kinds and titles."""
    files = sorted(p.stem for p in scenes.builtin("indexing").parent.glob("*.toml"))
    listed = json.loads(_cli("scenes", "--json").stdout)
    assert [r["name"] for r in listed] == files
    types = {"dynacam": scenes.DynacamScene, "camshaft1-study": dict, "beam-follower": scenes.BeamScene}
    for row in listed:
        data = _data(row["name"])
        assert row["kind"] == data["kind"] and row["title"] == data["title"]
        kind, sc = load_scene(row["name"])
        assert kind == data["kind"] and isinstance(sc, types[kind])
    assert {r["kind"] for r in listed} == set(KINDS)


@pytest.mark.parametrize("name, drop, says", [
    ("spring_loaded", (), 'add the line kind = "dynacam"'),
    ("default", (), 'move [response] and [graphs] under [study]'),
])
def test_a_scene_of_the_old_format_is_told_what_changed(tmp_path, name, drop, says):
    """A file without kind, as every scene was before kinds, is refused by `camdyn run` and
    `camdyn simulate` with one line that says what to change (status 2, nothing run)."""
    data = _data(name)
    text = scenes.builtin(name).read_text().replace(f'kind = "{data["kind"]}"\n', "")
    if name == "default":   # the study's old layout: [response], [graphs], [integration]
        text = (text.replace("[study.response]", "[response]").replace("[study.graphs]", "[graphs]")
                .replace("[run]", "[integration]"))
    old = tmp_path / "old.toml"
    old.write_text(text)
    for cmd in ("run", "simulate"):
        p = _cli(cmd, str(old), "--out", str(tmp_path / "out"))
        assert p.returncode == 2 and "the scene has no kind" in p.stderr and says in p.stderr
        assert len(p.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "out").exists()


def test_simulate_refuses_another_kind_and_points_to_run():
    p = _cli("simulate", "beam_paper")
    assert p.returncode == 2
    assert "is a beam-follower scene, not a dynacam one; `camdyn run` runs any kind" in p.stderr


@pytest.mark.parametrize("edit, message", [
    (lambda d: d["parameters"].__setitem__("modes", 9), "modes=9: choose an integer from 1 to"),
    (lambda d: d["parameters"].__setitem__("modes", 2.5), "parameters.modes must be an integer"),
    (lambda d: d["parameters"].__setitem__("rise", -0.01), "rise=-0.01: must be a positive number"),
    (lambda d: d["parameters"].__setitem__("rayleigh", 1), "rayleigh must be true or false"),
    (lambda d: d["parameters"].__setitem__("colour", 1), "parameters.colour is not a beam-follower"),
    (lambda d: d["run"].__setitem__("formulation", "lagrange"), "formulation='lagrange': choose one of"),
    (lambda d: d.__setitem__("options", {}), "options is not a key of a beam-follower scene"),
    (lambda d: d.__setitem__("kind", "camshaft2"), "kind='camshaft2': choose one of"),
])
def test_bad_beam_scenes_are_refused_by_name(edit, message):
    d = copy.deepcopy(_data("beam_paper"))
    edit(d)
    with pytest.raises(CamdynInputError, match=message.replace("(", r"\(").replace("[", r"\[")):
        scenes.kind_of(d, "x", KINDS) and scenes.beam_from_dict(d)


def test_run_any_kind_writes_the_summary_of_its_own_command(tmp_path):
    """`camdyn run` on a DYNACAM scene and on the beam follower writes report.json with the same
    figures as `camdyn simulate --json` and `camdyn beam-follower --json` give for them."""
    p = _cli("run", "spring_loaded", "--out", str(tmp_path / "a"), "--quiet")
    assert p.returncode == 0, p.stderr
    got = json.loads((tmp_path / "a" / "report.json").read_text())
    want = json.loads(_cli("simulate", "spring_loaded", "--json").stdout)
    assert got["kind"] == "dynacam"
    for key in ("tau", "Fa", "Fv", "Xdd_min_rise", "T_at_Xdd_min", "U0dd", "U0"):
        assert got[key] == pytest.approx(want[key], rel=1e-12), key
    assert any(f.endswith("spring_loaded_Xdd.png") for f in got["figures"])
    p = _cli("run", "beam_paper", "--out", str(tmp_path / "b"), "--quiet")
    assert p.returncode == 0, p.stderr
    got = json.loads((tmp_path / "b" / "report.json").read_text())
    want = json.loads(_cli("beam-follower", "--json").stdout)
    assert got["kind"] == "beam-follower"
    for key in ("max_abs_tip_deflection", "max_constraint_residual", "dwell_frequency_hz"):
        assert got[key] == pytest.approx(want[key], rel=1e-12), key


def test_runtime_options_are_the_declaration_s():
    """The runtime's Options (built from generated/catalog.json, no SymPy) against the
    declaration's (camdyn.derive.models.dynacam.Options): the same fields, defaults, choices and
    docs, and the same variant name for all 6912 option sets; the 11520 with a pair no variant
    has (dynacam.EXCLUDES: a rocker or a flat face on an axial cam, ...) and an invalid choice
    are refused by both in the same words."""
    import itertools
    from dataclasses import fields

    from camdyn.derive.models import dynacam as declared
    from camdyn.runtime.core import variants

    mine, theirs = fields(variants.Options), fields(declared.Options)
    assert [(f.name, f.default, f.metadata["doc"]) for f in mine] == \
           [(f.name, f.default, f.metadata["doc"]) for f in theirs]
    assert variants.CHOICES == declared.Options.CHOICES
    keys = [f.name for f in theirs]
    values = [declared.Options.CHOICES.get(k, (False, True)) for k in keys]
    n = refused = 0
    for combo in itertools.product(*values):
        kw = dict(zip(keys, combo))
        try:
            name = declared.Options(**kw).name
        except ValueError as exc:
            with pytest.raises(ValueError, match=re.escape(str(exc))):
                variants.Options(**kw)
            refused += 1
            continue
        assert variants.Options(**kw).name == name, kw
        n += 1
    assert (n, refused) == (6912, 11520)
    for cls in (variants.Options, declared.Options):
        with pytest.raises(ValueError, match="option gear='chain': choose one of"):
            cls(gear="chain")


def test_variant_names_are_words_that_each_mean_one_thing():
    """A variant's name spells its options with one word per choice and per
    element switched on; no word stands for two things, so the name can be read back into the
    option set (all 6912 names distinct and parsed back to their options), and the generated
    file of every pre-generated variant states each option in words in its header."""
    import itertools
    from dataclasses import fields

    from camdyn.derive.models import DYNACAM_VARIANTS
    from camdyn.derive.models import dynacam as declared

    meaning = {}
    for key, words in declared.NAME_WORDS.items():
        for value, word in words.items():
            meaning.setdefault(word, []).append((key, value))
    for word, key in declared.NAME_FLAGS:
        meaning.setdefault(word, []).append((key, True))
    assert {w: m for w, m in meaning.items() if len(m) > 1} == {}
    assert all(w.isalnum() and w.islower() for w in meaning)
    keys = [f.name for f in fields(declared.Options)]
    values = [declared.Options.CHOICES.get(k, (False, True)) for k in keys]
    names = set()
    for combo in itertools.product(*values):
        try:
            opts = declared.Options(**dict(zip(keys, combo)))
        except ValueError:            # a pair no variant has (dynacam.EXCLUDES)
            continue
        words = opts.name.split("_")
        assert words[0] == "dynacam"
        back = {k: False for k in keys if k not in declared.Options.CHOICES}
        back.update(dict(meaning[w][0] for w in words[1:]))
        assert declared.Options(**back) == opts
        names.add(opts.name)
    assert len(names) == 6912
    for opts in DYNACAM_VARIANTS:
        head = (ROOT / "generated" / f"{opts.name}.pyx").read_text()[:6000]
        assert "from camdyn/derive/models/dynacam.py;" in head
        for key in keys:
            value = getattr(opts, key)
            shown = value if isinstance(value, str) else ("yes" if value else "no")
            assert f"#   {key} = {shown}: " in head, (opts.name, key)


@pytest.mark.parametrize("what", ["device", "fifo", "folder", "huge"])
def test_only_a_regular_scene_file_is_read(what, tmp_path):
    """A named pipe would block the reader for ever and /dev/zero never end: only a regular
    file of at most 1 MiB is opened; anything else is one line naming the path, exit 2, at
    once (the subprocess has 60 s; it answers in well under one)."""
    import os

    path = {"device": "/dev/zero", "folder": str(tmp_path)}.get(what)
    if what == "fifo":
        path = str(tmp_path / "scene.toml")
        os.mkfifo(path)
    elif what == "huge":
        path = str(tmp_path / "huge.toml")
        with open(path, "w") as fh:
            fh.write('kind = "dynacam"\n' + "# padding\n" * 200_000)
    for cmd in (["simulate", path], ["run", path, "--out", str(tmp_path / "o")]):
        p = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *cmd],
                           capture_output=True, text=True, timeout=60)
        assert p.returncode == 2 and p.stdout == "", (cmd, p.stderr)
        lines = p.stderr.strip().splitlines()
        assert len(lines) == 1 and f"scene file {path}" in lines[0], lines
        assert {"device": "is a device", "fifo": "is a named pipe",
                "folder": "is a folder", "huge": "too large"}[what] in lines[0]


@pytest.mark.parametrize("name", ["h_m", "R_b"])
def test_parameters_beyond_any_mechanism_are_refused_by_name(name, tmp_path):
    """1e300 m of stroke or base radius overflowed tau, Fa, Fv (4.3)-(5.52) with a traceback;
    now one line listing the parameters they are formed from, exit 2.  beta_m, an angle, has
    a range of its own: 0 < beta_m <= 2 pi."""
    base = (scenes.builtin("spring_loaded")).read_text()
    text = "\n".join(f"{name} = 1e300" if line.startswith(f"{name} = ") else line
                     for line in base.splitlines())
    path = tmp_path / "big.toml"
    path.write_text(text)
    p = _cli("simulate", str(path))
    assert p.returncode == 2, p.stderr
    assert p.stderr.count("\n") == 1 and f"{name} = 1e+300" in p.stderr
    assert "no finite, positive tau, Fa and Fv" in p.stderr
    text = "\n".join("beta_m = 7.0" if line.startswith("beta_m = ") else line
                     for line in base.splitlines())
    path.write_text(text)
    p = _cli("simulate", str(path))
    assert p.returncode == 2 and p.stderr.count("\n") == 1 and "beta_m=7" in p.stderr
