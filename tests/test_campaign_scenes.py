"""The campaign (tests/test_campaign.py) over scenes: every built-in scene mutated (a number
changed to an absurd one, a key dropped or added, a value of the wrong type, a table dropped,
a [turn] added, the law changed), DYNACAM option tables (a rocker, a flat face, on a radial or
an axial cam, held by a spring, on both sides or in a groove), the study scenes' [follower]
table, through `camdyn simulate`, `run` and `precision` with every adaptive method and the
absolute tolerances; and `camdyn beam-follower` with absurd rods, speeds and runs.

An option set that no pre-generated variant has is derived on demand (a minute or two the
first time): the quick campaign draws only the pre-generated ones and those the options'
rules refuse at once; the slow one adds one variant built on demand into the session's
private cache (test_campaign.py's campaign_session) and mutates scenes on it.
"""
from __future__ import annotations

import copy
import itertools
import tomllib

import pytest
from hypothesis import given, strategies as st

from camdyn.runtime.targets import scene_files

from .test_campaign import (ADAPTIVE, LONG, NUMBERS, QUICK, VALUE, Opt, _dump, _numbers,  # noqa: F401
                            _spread, campaign_session, choice, command, few, flag, judge,
                            law_folder, many, mutate_table, num, pairs, run, run_apart,
                            with_out)

BUILTINS = ["spring_loaded", "indexing", "indexing_squeeze", "fig8_1a", "fig8_1b", "rocker",
            "rocker_study", "beam_paper", "default"]
DYNACAM = ["spring_loaded", "indexing", "indexing_squeeze", "fig8_1a", "fig8_1b", "rocker"]


def test_the_campaign_draws_every_built_in_scene():
    """The list above is `camdyn scenes`: a scene added later is drawn too, or this fails."""
    assert sorted(BUILTINS) == sorted(name for name, _, _ in scene_files.builtins())


def _table(name: str) -> dict:
    return tomllib.loads(scene_files.builtin(name).read_text())


# -- the mutations ----------------------------------------------------------------------------

HOW = ["none", "scale", "scale", "number", "number", "drop", "add", "type", "table", "turn",
       "law", "kind"]


def mutations(scenes=BUILTINS):
    """(scene, how, which, a number): how the built-in scene is changed (see :func:`mutant`)."""
    return st.tuples(st.sampled_from(scenes), st.sampled_from(HOW), st.integers(0, 10_000),
                     NUMBERS)


LAW_WORDS = ["cycloidal", "uniform", "parabolic", "modified-sine", "nope", "", "../nope.csv",
             "blend.toml", "/dev/zero", "."]
KINDS = ["dynacam", "beam-follower", "camshaft1-study", "nope", ""]


def mutant(table: dict, how: str, pick: int, number: float) -> dict:
    """``table`` changed: not at all, a number scaled by a factor from 1/2 to 2 (a scene a user
    means), a number replaced, a key dropped or added, a value of the wrong type (as
    test_campaign.mutate_table), a whole table dropped, a [turn] of drawn angles added, the
    law or the kind replaced by another."""
    if how == "none":
        return table
    if how == "scale":
        factor = 2.0 ** ((pick % 201) / 100 - 1)
        nums = [p for p, v in _numbers(table) if v]
        path = nums[pick % len(nums)]
        node = table
        for k in path[:-1]:
            node = node[k]
        node[path[-1]] = node[path[-1]] * factor
        return table
    if how in ("number", "drop", "add", "type"):
        return mutate_table(table, how, pick, number)
    if how == "table":
        tables = sorted(k for k, v in table.items() if isinstance(v, dict)) or ["none"]
        table.pop(tables[pick % len(tables)], None)
    elif how == "turn":
        angles = [60.0, 90.0, 0.0, number, 360.0, 120.0]
        table["turn"] = {"upper_dwell": angles[pick % 6], "return": angles[(pick // 6) % 6]}
        if pick % 3 == 0:
            table["turn"]["return_law"] = LAW_WORDS[pick % len(LAW_WORDS)]
    elif how == "law":
        table["law"] = LAW_WORDS[pick % len(LAW_WORDS)]
        if pick % 4 == 0:
            table["theta"] = number
    else:
        table["kind"] = KINDS[pick % len(KINDS)]
    return table


def write_mutant(m, folder) -> str:
    name, how, pick, number = m
    f = folder / f"{name}_{how}_{pick}.toml"
    f.write_text(_dump(mutant(_table(name), how, pick, number)))
    (folder / "blend.toml").write_text("[bspline]\ncontrol = [0, 0, 0, 0.5, 1, 1, 1]\n")
    return str(f)


# -- DYNACAM option tables: rockers and flat faces --------------------------------------------

OPTION_CHOICES = {"rocker": [False, True], "flat_face": [False, True], "cam": ["radial", "axial"],
                  "roller": ["contact", "bilateral", "groove"], "spring": [True, False]}
EXTRA_PARAMETERS = {"d_p": 0.10, "l_a": 0.08, "f_f": 0.0, "F_0": 10.0, "c_s": 1000.0,
                    "s_g": 1.0e-2, "s_r": 1.3e-4}
"""Values for the parameters an option adds (the rocker's arm, the flat face's offset, the
spring, the backlash of gear and groove), as the built-in scenes give them."""


def _status(options: dict) -> str:
    """"refused" (no variant has these options), "compiled" (pre-generated) or "on demand"."""
    from camdyn.runtime.core.compiled import available
    from camdyn.runtime.core.errors import CamdynInputError
    from camdyn.runtime.core.variants import Options

    try:
        name = Options(**options).name
    except CamdynInputError:
        return "refused"
    return "compiled" if name in available() else "on demand"


def option_sets():
    """Every combination of OPTION_CHOICES over the rocker scene's options, by status."""
    base = _table("rocker")["options"]
    out = {"refused": [], "compiled": [], "on demand": []}
    for values in itertools.product(*OPTION_CHOICES.values()):
        opts = {**base, **dict(zip(OPTION_CHOICES, values))}
        out[_status(opts)].append(opts)
    return out


OPTION_SETS = option_sets()
AT_HAND = OPTION_SETS["refused"] + OPTION_SETS["compiled"]
ON_DEMAND = {"roller": "bilateral", "spring": True, "rocker": True, "flat_face": False}
"""The one option set outside generated/ the slow campaign builds (a bilateral rocker, the
derivation tests/test_ondemand.py bounds at about a minute)."""


def fitted(options: dict, base: str, fit: bool, pick: int, number: float) -> dict:
    """A scene of ``base`` with ``options``: with ``fit`` its parameters those the variant
    declares (dropping the others, adding the missing ones from EXTRA_PARAMETERS), one of them
    then set to ``number``; without, the base scene's parameters as they are."""
    table = _table(base)
    table["options"] = dict(options)
    params = table["parameters"]
    if fit:
        names = _declared(options)
        if names is not None:
            pool = {**EXTRA_PARAMETERS, **{k: v for s in DYNACAM for k, v in
                                            _table(s)["parameters"].items()}}
            table["parameters"] = params = {k: params.get(k, pool.get(k)) for k in names
                                            if k in params or k in pool}
        if pick % 3 == 0 and params:
            params[sorted(params)[pick % len(params)]] = number
    return table


def _declared(options: dict):
    """The parameter names of the variant's manifest (pre-generated), or those the options'
    rules add to the base ones (a variant on demand), or None (refused options)."""
    from camdyn.runtime.core.compiled import available, load
    from camdyn.runtime.core.errors import CamdynInputError
    from camdyn.runtime.core.variants import Options

    try:
        name = Options(**options).name
    except CamdynInputError:
        return None
    if name in available():
        return [p["name"] for p in load(name).manifest["parameters"]]
    names = [k for k in _table("rocker")["parameters"] if k not in ("d_p", "l_a", "F_0", "c_s")]
    names += ["d_p", "l_a"] * options.get("rocker", False) + ["F_0", "c_s"] * options["spring"]
    return names + ["f_f"] * (options.get("rocker", False) and options.get("flat_face", False))


def option_tables(sets=None):
    sets = st.sampled_from(sets) if sets else st.one_of(st.sampled_from(OPTION_SETS["compiled"]),
                                                        st.sampled_from(OPTION_SETS["refused"]))
    return st.tuples(sets, st.sampled_from(["rocker", "spring_loaded",
                                                             "fig8_1a", "indexing"]),
                     st.sampled_from([True, True, True, False]), st.integers(0, 10_000),
                     NUMBERS)


def write_options(o, folder) -> str:
    options, base, fit, pick, number = o
    f = folder / f"options_{base}_{pick}.toml"
    f.write_text(_dump(fitted(options, base, fit, pick, number)))
    return str(f)


# -- the commands over scenes -----------------------------------------------------------------

STATES = ["x", "beta", "y", "z", "xd"]


def scene_options(command_: str, quick: bool) -> dict:
    """The options of ``command_`` over a scene (run: written into --out by the caller)."""
    tol = {"--method": ADAPTIVE, "--atol": num(1e-9, 1e-6), "--state-atol": pairs(STATES)}
    if command_ == "simulate":
        auto = {} if quick else {"--model": choice(["auto", "scene"], ["nope"]),
                                 "--tolerance": num(0.05), "--figures": choice(
                                     ["U0,U0dd"], ["nope", "", "U0,U0", "U0,,U0dd"])}
        return {**tol, **auto, "--no-error-estimate": flag()}
    if command_ == "run":
        return tol
    return {}       # precision: its --methods is in HEADS (one method: a ladder is a dozen runs)


HEADS = {"simulate": ["simulate", "SCENE", "--json"],
         "run": ["run", "SCENE", "--quiet", "--no-error-estimate"],
         "precision": ["precision", "SCENE", "--no-peers", "--quick", "--json", "--methods",
                       "dp54"]}


def scene_case(command_: str, scene: str, tail: list, folder):
    """``command_`` over ``scene`` with the options ``tail``, judged under "<command> (scenes)"."""
    argv = [scene if a == "SCENE" else a for a in HEADS[command_]] + list(tail)
    if command_ in ("run", "precision"):
        argv = _spread(with_out(argv, folder / "out"))
    return judge(argv, *run(argv), feature=f"{command_} (scenes)")


def commands_and_options(quick):
    """(command, its options) over a scene."""
    names = ["simulate", "simulate", "run"] + ([] if quick else ["precision"])
    return st.sampled_from(names).flatmap(
        lambda c: st.tuples(st.just(c), command([], {}, scene_options(c, quick), most=2)))


@QUICK
@given(m=mutations(), co=commands_and_options(True))
def test_quick_campaign_over_mutated_built_in_scenes(m, co, tmp_path_factory):
    folder = tmp_path_factory.mktemp("s")
    scene_case(co[0], write_mutant(m, folder), co[1], folder)


@pytest.mark.slow
@many(100)
@given(m=mutations(), co=commands_and_options(False))
def test_campaign_over_mutated_built_in_scenes(m, co, tmp_path_factory):
    folder = tmp_path_factory.mktemp("s")
    scene_case(co[0], write_mutant(m, folder), co[1], folder)


@few(20)
@given(o=option_tables(), co=commands_and_options(True))
def test_quick_campaign_over_rocker_and_flat_face_options(o, co, tmp_path_factory):
    folder = tmp_path_factory.mktemp("o")
    scene_case(co[0], write_options(o, folder), co[1], folder)


@pytest.mark.slow
@many(40)
@given(o=option_tables(), co=commands_and_options(False))
def test_campaign_over_rocker_and_flat_face_options(o, co, tmp_path_factory):
    folder = tmp_path_factory.mktemp("o")
    scene_case(co[0], write_options(o, folder), co[1], folder)


@pytest.mark.slow
def test_a_variant_built_on_demand_answers(tmp_path):
    """The rocker scene held on both sides, its parameters as the variant declares them:
    built into the session's cache, then answered (status 0, every figure finite with its
    estimate key), as the pre-generated spring-held rocker is."""
    options = {**_table("rocker")["options"], **ON_DEMAND}
    assert _status(options) == "on demand"
    verdict = scene_case("simulate", write_options((options, "rocker", True, 1, 0.0), tmp_path),
                         [], tmp_path)
    assert verdict == "answered"


@pytest.mark.slow
@many(12)
@given(o=option_tables([{**_table("rocker")["options"], **ON_DEMAND}]))
def test_campaign_over_a_variant_built_on_demand(o, tmp_path_factory):
    """A bilateral rocker: built once into the session's private cache (a minute or two),
    then its mutated scenes run from there."""
    folder = tmp_path_factory.mktemp("d")
    scene_case("simulate", write_options(o, folder), ["--no-error-estimate"], folder)


# -- the study scenes' [follower] -------------------------------------------------------------

FOLLOWER_KEYS = ["kind", "swing", "arm_length", "arm_inertia", "arm_stiffness", "speed",
                 "cam_angle", "pitch_radius", "c_tan", "stroke", "mass", "stiffness", "nope"]


def followers():
    return st.tuples(st.sampled_from(["set", "set", "drop", "kind"]),
                     st.sampled_from(FOLLOWER_KEYS), st.one_of(NUMBERS, st.sampled_from(
                         ["translating", "oscillating-roller", "rocker", "", "text"])))


def write_follower(f, folder) -> str:
    how, key, value = f
    table = _table("rocker_study")
    fol = table["follower"]
    if how == "set":
        fol[key] = value
    elif how == "drop":
        fol.pop(key, None)
    else:
        fol["kind"] = value if isinstance(value, str) else "translating"
    path = folder / f"study_{how}_{key}.toml"
    path.write_text(_dump(table))
    return str(path)


@few(6)
@given(f=followers())
def test_quick_campaign_over_a_study_scenes_follower(f, tmp_path_factory):
    folder = tmp_path_factory.mktemp("f")
    scene_case("run", write_follower(f, folder), [], folder)


@pytest.mark.slow
@many(20)
@given(f=followers())
def test_campaign_over_a_study_scenes_follower(f, tmp_path_factory):
    folder = tmp_path_factory.mktemp("f")
    scene_case("run", write_follower(f, folder), [], folder)


# -- the findings on scenes -------------------------------------------------------------------

@pytest.mark.parametrize("option", ["rocker", "flat_face"])
def test_a_rocker_or_a_flat_face_on_an_axial_cam_is_one_line(option, tmp_path):
    """`camdyn simulate` of a rocker or a flat face on an axial cam ended in a ValueError
    traceback; it is refused in one line naming both options."""
    table = _table("rocker")
    table["options"].update({"cam": "axial", "rocker": option == "rocker",
                             "flat_face": option == "flat_face"})
    path = tmp_path / "axial.toml"
    path.write_text(_dump(table))
    argv = ["simulate", str(path)]
    code, out, err = run(argv)
    assert judge(argv, code, out, err, feature="findings") == "refused"
    assert f'option {option}=true with cam="axial"' in err


# -- camdyn beam-follower ---------------------------------------------------------------------

BEAM = {
    "--omega": num(240, 120, 360), "--modes": choice(["1", "2", "3"], ["0", "7", "2.5", "x", "-1"]),
    "--rod-radius": num(0.005, 0.007), "--distance": num(0.112, 0.122),
    "--base-radius": num(0.026, 0.03), "--rise": num(0.015, 0.008),
    "--revolutions": choice(["0.25", "0.5"], ["1e9", "0", "-1", "nan", "1e-300", "1e300", "inf",
                                              "1e-9", "x", "1e6"]),
    "--roller-inertia": num(0, 6.25e-7),
    "--formulation": choice(["augmented", "partitioned", "projection"], ["lagrange", ""]),
    "--method": choice(["dop853", "dp54", "rodas4", "radau5", "rkn12"], ["rk4", "nope"]),
    "--rtol": num(1e-6, 1e-9), "--atol": num(1e-6), "--state-atol": pairs(["b1", "b1d"]),
    "--mode-atol": num(3e-5, 1e-3), "--no-rayleigh": flag(), "--rayleigh": flag(),
}


def beam_argv(quick=False):
    head = ["beam-follower", "--json"] + (["--no-error-estimate"] if quick else [])
    return command(head, {"--revolutions": BEAM["--revolutions"]},
                   {k: v for k, v in BEAM.items() if k != "--revolutions"}, most=3)


@few(20)
@given(argv=beam_argv(True))
def test_quick_campaign_over_the_beam_follower(argv):
    judge(argv, *run(argv))


@pytest.mark.slow
@many(60)
@given(argv=beam_argv())
def test_campaign_over_the_beam_follower(argv):
    judge(argv, *run(argv))


BEAM_FINDINGS = {
    "rod 1e-9 (was SIGSEGV)": (["--rod-radius", "1e-9", "--no-error-estimate"], "--rod-radius"),
    "1e9 revolutions (was a hang)": (["--revolutions", "1e9", "--no-error-estimate"],
                                     "--revolutions"),
    "omega 1e9 (was a meaningless answer)": (["--omega", "1e9"], "--omega"),
}


@pytest.mark.parametrize("name", sorted(BEAM_FINDINGS))
def test_the_beam_findings_are_refused_before_any_run(name, monkeypatch):
    """Each is refused in one line naming its flag, and no run starts (the run's entry point
    fails the test if reached)."""
    from .test_campaign import no_runs

    args, flag_ = BEAM_FINDINGS[name]
    no_runs(monkeypatch, "camdyn.runtime.measure.contract.answer", "beam-follower")
    argv = ["beam-follower", *args]
    code, out, err = run(argv)
    assert judge(argv, code, out, err, feature="findings") == "refused"
    assert err.startswith(f"camdyn beam-follower: error: argument {flag_}:")


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(BEAM_FINDINGS))
def test_the_beam_findings_in_a_process_of_their_own(name):
    """The same in a process of its own, where a crash (the 1 nm rod's SIGSEGV) or a hang
    (1e9 revolutions) is seen for what it is rather than taking the session with it."""
    args, flag_ = BEAM_FINDINGS[name]
    argv = ["beam-follower", *args]
    code, out, err = run_apart(argv, limit=120)
    assert judge(argv, code, out, err, feature="findings") == "refused"
    assert f"argument {flag_}:" in err
