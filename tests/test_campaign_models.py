"""The campaign (tests/test_campaign.py) over models of the user's own and the on-demand cache
(README "Any model on demand").

Two small model files, each built once into the session's private cache (5-15 s each): the
README's oscillator (m x'' = c (H - x) - d x', its parameters without ranges) and the same with
declared ranges whose spring rate comes from a helper module beside it.  Drawn through
`camdyn integrate`, `sweep`, `stability` and `precision`: parameter values (--set, a name
twice), initial values, grids over them, methods and tolerances; an answer of the oscillator
is held to SciPy's solution of its equation where its inputs are ordinary.

Then the cache's faults, drawn with where in the file they strike: the compiled module
truncated or a byte flipped, replaced by the other model's (the checksums left, or made to
match), the build record truncated, garbled or of the wrong shape, SHA256SUMS with a wrong
digest, garbled, without the record's line or missing, and the helper module changed,
deleted or broken.  Each is found by ``ondemand.check`` on an entry sealed as a build leaves
it (quick: nothing is compiled, nothing loaded), and a few strike the built models' entries
and run in a process of their own (a truncated module loaded would kill it): built again
after one note, giving the sound entry's numbers exactly, or refused in one line.
tests/test_ondemand.py holds the kinds one by one; this draws them.
"""
from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
from pathlib import Path

import pytest
from hypothesis import example, given, strategies as st

from .test_campaign import (FINDINGS, LONG, Opt, _spread, campaign_session, choice, few,  # noqa: F401
                            command, judge, many, num, pairs, run, run_apart, tally, with_out)
from .test_ondemand import readme_model, reference_state

HELPER = "campaign_springs"
RANGED = readme_model().replace(
    "from camdyn.derive.model import Coordinate, Model, Output, Parameter, cam_input, time\n",
    "from camdyn.derive.model import Coordinate, Model, Output, Parameter, cam_input, time\n"
    f"from {HELPER} import C0\n").replace(
    'Parameter("m", 1.0, "kg", "mass")', 'Parameter("m", 1.0, "kg", "mass", low=0.0, '
    'high=10.0, open_low=True)').replace(
    'Parameter("c", 400.0, "N/m", "spring between cam and follower")',
    'Parameter("c", C0, "N/m", "spring between cam and follower", low=0.0, high=1e6)').replace(
    'Parameter("d", 2.0, "N s/m", "damper to the frame")',
    'Parameter("d", 2.0, "N s/m", "damper to the frame", low=0.0, high=100.0)').replace(
    'name="oscillator"', 'name="ranged"')
"""The README's oscillator with declared ranges (m in (0, 10] kg, c in [0, 1e6] N/m, d in
[0, 100] N s/m) and its spring rate from a helper module."""


@pytest.fixture(scope="module")
def models(campaign_session, tmp_path_factory):
    """Both files, built into the session's cache; each one's sound state at t = 2 s."""
    folder = tmp_path_factory.mktemp("models")
    (folder / "oscillator.py").write_text(readme_model())
    (folder / "ranged.py").write_text(RANGED)
    assert "C0" in RANGED and 'name="ranged"' in RANGED and "high=1e6" in RANGED
    (folder / f"{HELPER}.py").write_text("C0 = 400.0\n")
    states = {}
    for name in ("oscillator", "ranged"):
        code, out, err = run(["integrate", str(folder / f"{name}.py"), "--t-end", "2", "--json"])
        assert code == 0, err
        states[name] = json.loads(out)["state"]
    return folder, campaign_session, states


# -- the commands over the model files --------------------------------------------------------

NAMES = ["m", "c", "d"]
SETS = Opt(st.sampled_from(["0.5", "1", "2", "400", "900", "0"]),
           st.sampled_from(["-1", "0", "nan", "inf", "1e300", "1e-300", "1e6", "1e7", "abc", ""]))


def model_argv():
    grid = choice(["c=100:900:3", "c=400,900", "m=0.5,1", "d=0:4:2"],
                  ["c=0:1e7:2", "m=-1,1", "m=0,1", "nope=1,2", "c=400,,900", "c=400,400",
                   "d=nan,1", "c=1e300:1e301:2"])
    integrate = command(["integrate", "MODEL", "--json"], {"--t-end": num(2, 0.5, 3)}, {
        "--set": pairs(NAMES, ["nope", ""], SETS), "--initial": pairs(["x", "xd"]),
        "--method": choice(["dp54", "dop853", "rodas4", "radau5", "rk4"], ["koster", "nope"]),
        "--rtol": num(1e-8, 1e-6), "--step": num(1e-3), "--atol": num(1e-9),
        "--state-atol": pairs(["x", "xd"]), "--law": choice(["cycloidal", "3-4-5"], ["nope"]),
        "--no-error-estimate": Opt(st.just(True), st.just(True))})
    sweep = command(["sweep", "MODEL", "--quiet", "--jobs", "1", "--no-error-estimate"],
                    {"--grid": grid}, {"--t-end": num(2, 3), "--method": choice(["dp54"], ["rk4"])})
    stability = command(["stability", "MODEL", "--quiet", "--json", "--methods", "rk4"],
                        {"--param": grid, "--steps": choice(["0.01", "0.001,0.01"], ["0", "nan"])},
                        {"--set": pairs(["m", "d"], ["nope", "c"], SETS), "--t-end": num(2)})
    precision = command(["precision", "MODEL", "--quick", "--no-peers", "--json", "--methods",
                         "dp54"], {}, {"--set": pairs(NAMES, ["nope"], SETS), "--t-end": num(2)})
    return st.tuples(st.sampled_from(["oscillator", "ranged"]),
                     st.one_of(integrate, integrate, sweep, stability, precision))


def _reference_holds(name: str, argv: list, record: dict) -> None:
    """An answer of integrate with ordinary inputs against SciPy's solution of
    m x'' = c (H - x) - d x' (tests/test_ondemand.py reference_state): within ten times its
    estimate plus 1e-9 of the stroke (1 m)."""
    if argv[0] != "integrate" or any(a in argv for a in ("--law", "--initial", "--method",
                                                          "--step")):
        return
    if "--no-error-estimate" in argv:
        return
    given = dict(a.split("=", 1) for a in argv[argv.index("--json"):] if "=" in a)
    try:
        m, c, d = (float(given.get(k, default)) for k, default in
                   (("m", 1.0), ("c", 400.0), ("d", 2.0)))
        t_end = float(argv[argv.index("--t-end") + 1])
    except ValueError:
        return
    if not (0.1 <= m <= 10 and 0 <= c <= 1000 and 0 <= d <= 10 and 0 < t_end <= 3):
        return
    y, _ = reference_state(t_end, m=m, c=c, d=d)
    x, err = record["state"]["x"], record["state_error"]["x"]
    assert abs(x - y[0]) <= 10 * err + 1e-9, (name, argv, x, y[0], err)


@pytest.mark.slow
@many(40)
@given(case=model_argv())
def test_campaign_over_model_files(case, models, tmp_path_factory):
    folder, _, _ = models
    name, argv = case
    argv = [str(folder / f"{name}.py") if a == "MODEL" else a for a in argv]
    if argv[0] != "integrate":
        argv = _spread(with_out(argv, tmp_path_factory.mktemp("m")))
    code, out, err = run(argv)
    verdict = judge(argv, code, out, err, feature="model files")
    if verdict == "answered" and argv[0] == "integrate":
        _reference_holds(name, argv, json.loads(out))


# -- the cache's faults -----------------------------------------------------------------------

def _entry(cache: Path, name: str) -> Path:
    (entry,) = [p for p in cache.iterdir() if p.is_dir() and p.name.startswith(f"{name}-")]
    return entry


def _module(entry: Path) -> Path:
    return entry / json.loads((entry / "build.json").read_text())["extension"]


def _reseal(entry: Path, names) -> None:
    """SHA256SUMS made to match ``names`` as they are now (the fault passes the checksums)."""
    lines = []
    for line in (entry / "SHA256SUMS").read_text().splitlines():
        digest, _, file = line.partition("  ")
        if file in names:
            digest = hashlib.sha256((entry / file).read_bytes()).hexdigest()
        lines.append(f"{digest}  {file}")
    (entry / "SHA256SUMS").write_text("\n".join(lines) + "\n")


def _at(data: bytes, where: float) -> int:
    return min(int(len(data) * where), max(len(data) - 1, 0))


def _flip(path: Path, where: float) -> None:
    data = bytearray(path.read_bytes())
    data[_at(data, where)] ^= 0x40
    path.write_bytes(bytes(data))


def _truncate(path: Path, where: float) -> None:
    os.truncate(path, _at(path.read_bytes(), where))


def _foreign(entry: Path, other: Path, seal: bool) -> None:
    shutil.copyfile(_module(other), _module(entry))
    if seal:
        _reseal(entry, [_module(entry).name])


def _record(entry: Path, how: str, where: float) -> None:
    rec = entry / "build.json"
    if how == "truncate":
        _truncate(rec, where)
    elif how == "garble":
        _flip(rec, where)
    else:                       # valid JSON of the wrong shape, its checksum made to match
        rec.write_text(json.dumps([1, 2, 3]) if where < 0.5 else json.dumps({"name": 3}))
        _reseal(entry, ["build.json"])


def _sums(entry: Path, how: str, where: float) -> None:
    sums = entry / "SHA256SUMS"
    text = sums.read_text()
    if how == "digest":
        i = _at(text.encode(), where * 0.4)       # within the first line's digest
        text = text[:i] + ("0" if text[i] != "0" else "1") + text[i + 1:]
        sums.write_text(text)
    elif how == "garble":
        _flip(sums, where)
    elif how == "no record line":
        sums.write_text("".join(l + "\n" for l in text.splitlines() if "build.json" not in l))
    else:
        sums.unlink()


FAULTS = {
    "module truncated": lambda e, o, h, w: _truncate(_module(e), w),
    "module byte flipped": lambda e, o, h, w: _flip(_module(e), w),
    "module foreign, sums kept": lambda e, o, h, w: _foreign(e, o, False),
    "module foreign, sums matched": lambda e, o, h, w: _foreign(e, o, True),
    "record truncated": lambda e, o, h, w: _record(e, "truncate", w),
    "record garbled": lambda e, o, h, w: _record(e, "garble", w),
    "record of the wrong shape": lambda e, o, h, w: _record(e, "shape", w),
    "sums with a wrong digest": lambda e, o, h, w: _sums(e, "digest", w),
    "sums garbled": lambda e, o, h, w: _sums(e, "garble", w),
    "sums without the record's line": lambda e, o, h, w: _sums(e, "no record line", w),
    "sums missing": lambda e, o, h, w: _sums(e, "missing", w),
    "helper changed": lambda e, o, h, w: h.write_text(f"C0 = {100.0 + 800.0 * w!r}\n"),
    "helper deleted": lambda e, o, h, w: h.unlink(),
    "helper broken": lambda e, o, h, w: h.write_text("C0 = (\n"),
}
HELPER_FAULTS = ("helper changed", "helper deleted", "helper broken")
"""The faults of the ranged model's helper module (the oscillator has none)."""


def faults():
    return st.tuples(st.sampled_from(sorted(FAULTS)), st.floats(0.0, 0.999),
                     st.sampled_from(["oscillator", "ranged"])).map(
        lambda f: (f[0], f[1], "ranged" if f[0] in HELPER_FAULTS else f[2]))


def _sealed_entry(cache: Path, name: str, sources: dict) -> Path:
    """An entry as a build leaves it (runtime/core/ondemand.py _seal): a module's bytes (not
    loaded here: ondemand.check reads, never loads), its build record and SHA256SUMS."""
    from camdyn.runtime.core import ondemand

    entry = cache / f"{name}-{hashlib.sha256(name.encode()).hexdigest()[:20]}"
    entry.mkdir(parents=True)
    extension = f"{name}.cpython-311-x86_64-linux-gnu.so"
    (entry / extension).write_bytes(name.encode() * 4096)
    (entry / "build.json").write_text(json.dumps({"name": name, "extension": extension,
                                                  "sources": sources}))
    ondemand._seal(entry)
    return entry


def check_fault(fault, folder: Path) -> None:
    """ondemand.check on an entry with ``fault``: "damaged" with one line saying what is
    wrong, or "changed" naming the helper module, for every fault but a foreign module whose
    checksums were made to match (only its load finds that: the process test below)."""
    from camdyn.runtime.core import ondemand

    kind, where, name = fault
    helper = folder / f"{HELPER}.py"
    helper.write_text("C0 = 400.0\n")
    digest = hashlib.sha256(helper.read_bytes()).hexdigest()
    entries = {n: _sealed_entry(folder / "cache", n, {str(helper): digest} if n == "ranged"
                                else {}) for n in ("oscillator", "ranged")}
    assert ondemand.check(entries[name])[0] == "ok"
    FAULTS[kind](entries[name], entries["ranged" if name == "oscillator" else "oscillator"],
                 helper, where)
    state, detail = ondemand.check(entries[name])
    said = [kind, f"at {where:.3f}", name]
    want = ("changed" if kind in HELPER_FAULTS else
            "ok" if kind == "module foreign, sums matched" else "damaged")
    tally("cache faults (check)", "refused" if state == want else "wrong answer", said)
    assert state == want, (said, state, detail)
    if want == "changed":
        assert detail == str(helper)
    elif want == "damaged":
        assert isinstance(detail, str) and detail and "\n" not in detail


@few(25)
@given(fault=faults())
def test_quick_campaign_the_cache_finds_every_fault(fault, tmp_path_factory):
    check_fault(fault, tmp_path_factory.mktemp("fault"))


@pytest.mark.slow
@many(150)
@given(fault=faults())
def test_campaign_the_cache_finds_every_fault(fault, tmp_path_factory):
    check_fault(fault, tmp_path_factory.mktemp("fault"))


NOTE = re.compile(r"camdyn: cache entry for model file (\w+)\.py was damaged \((.+)\); rebuilding")


LOADED_FOREIGN = "module foreign, sums matched"
"""The one fault only a load finds: that process has the foreign module's file open under
the entry's name, and dlopen keeps the first file it opened at a path, so the rebuilt module
is loaded from a fresh copy of its file (runtime/core/ondemand.py _load): held by the test
below."""


@pytest.mark.slow
@many(3)
@example(fault=("helper deleted", 0.0, "ranged"))                   # the build's import fails
@given(fault=faults().filter(lambda f: f[0] != LOADED_FOREIGN))
def test_campaign_a_damaged_entry_is_rebuilt_or_refused(fault, models, tmp_path_factory):
    """The fault in a copy of the session's cache, then `camdyn integrate MODEL --t-end 2
    --json` in a process of its own on it: the sound entry's state exactly after one note
    (damaged), or after the build's "has changed" line SciPy's solution at the helper's new
    spring rate, or one line refusing the model (the helper deleted or broken); the next run
    loads without a note."""
    folder, cache, states = models
    kind, where, name = fault
    copy = tmp_path_factory.mktemp("rebuild") / "cache"
    shutil.copytree(cache, copy, ignore=shutil.ignore_patterns("*.lock", ".*"))
    env = {"CAMDYN_CACHE_DIR": str(copy)}
    helper = folder / f"{HELPER}.py"
    kept = helper.read_text()
    argv = ["integrate", str(folder / f"{name}.py"), "--t-end", "2", "--json"]
    try:
        FAULTS[kind](_entry(copy, name), _entry(copy, "ranged" if name == "oscillator" else
                                                "oscillator"), helper, where)
        code, out, err = run_apart(argv, env=env)
        verdict = judge(argv, code, out, err, feature="cache faults (rebuild)")
        again = run_apart(argv, env=env) if verdict == "answered" else None
    finally:                # the session's model as it was (its own entry never changed)
        helper.write_text(kept)
    if kind in ("helper deleted", "helper broken"):
        assert verdict == "refused" and f"{name}.py" in err, err
        return
    assert verdict == "answered", err
    notes = [l for l in err.splitlines() if l.startswith("camdyn: ")]
    if kind == "helper changed":
        assert notes == [] and f"{HELPER}.py has changed since it was built" in err, err
        y, _ = reference_state(2.0, c=100.0 + 800.0 * where)
        record = json.loads(out)
        assert abs(record["state"]["x"] - y[0]) <= 10 * record["state_error"]["x"] + 1e-9
    else:
        assert len(notes) == 1 and NOTE.fullmatch(notes[0]), err
        assert NOTE.fullmatch(notes[0]).group(1) == name
        assert json.loads(out)["state"] == states[name]
    code, out, err = again
    assert code == 0 and "camdyn: " not in err and "deriving" not in err, err


@pytest.mark.slow
def test_a_foreign_module_under_matching_checksums_is_rebuilt_and_loaded(models,
                                                                         tmp_path_factory):
    """Another model's compiled module in the entry, its checksum made to match: found when
    loaded (its init function is another model's), one note, built again, and the run gives
    the sound entry's state in the same process."""
    folder, cache, states = models
    copy = tmp_path_factory.mktemp("foreign") / "cache"
    shutil.copytree(cache, copy, ignore=shutil.ignore_patterns("*.lock", ".*"))
    FAULTS[LOADED_FOREIGN](_entry(copy, "oscillator"), _entry(copy, "ranged"), None, 0.0)
    argv = ["integrate", str(folder / "oscillator.py"), "--t-end", "2", "--json"]
    code, out, err = run_apart(argv, env={"CAMDYN_CACHE_DIR": str(copy)})
    verdict = judge(argv, code, out, err, feature="cache faults (rebuild)")
    notes = [l for l in err.splitlines() if l.startswith("camdyn: ")]
    assert len(notes) == 1 and "does not load" in notes[0], err
    assert verdict == "answered", err
    assert json.loads(out)["state"] == states["oscillator"]
