"""Models on demand (README "Any model on demand"): a user's model file and a DYNACAM option set outside
generated/ are derived, generated and compiled on first use into the cache, loaded from it
afterwards, and bad files are refused in one line.

The reference for the README's model is written here from its physics, not from camdyn: the
mass m on a spring c whose other end the cam moves by H(t) (cycloidal rise (A.2.8) over
0 <= t <= 1 s, then H = 1), with a damper d to the frame:

    m x'' = c (H - x) - d x',    x(0) = x'(0) = 0,

solved by SciPy's DOP853 at rtol 1e-12, restarted at t = 1 where H'' jumps.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

README = Path(__file__).resolve().parent.parent / "README.md"


def readme_model() -> str:
    """The code block that follows the <!-- user-model: oscillator.py --> marker."""
    text = README.read_text()
    m = re.search(r"<!-- user-model: oscillator\.py -->\s*```python\n(.*?)```", text, re.S)
    assert m, "README.md has no user-model example"
    return m.group(1)


def reference_state(t_end, m=1.0, c=400.0, d=2.0):
    def H(t):
        if t >= 1.0:
            return 1.0
        return t - math.sin(2 * math.pi * t) / (2 * math.pi)

    def rhs(t, y):
        return [y[1], (c * (H(t) - y[0]) - d * y[1]) / m]

    y = [0.0, 0.0]
    out = []
    for a, b in ((0.0, 1.0), (1.0, t_end)):
        s = solve_ivp(rhs, (a, b), y, method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)
        y = s.y[:, -1]
        out.append(s.sol)
    return y, out


def camdyn(*args, cache, cwd=None, **kw):
    env = {**os.environ, "CAMDYN_CACHE_DIR": str(cache)}
    return subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *args], capture_output=True,
                          text=True, timeout=600, env=env, cwd=cwd, **kw)


@pytest.fixture(scope="module")
def user_model(tmp_path_factory):
    folder = tmp_path_factory.mktemp("user")
    path = folder / "oscillator.py"
    path.write_text(readme_model())
    return path, folder / "cache"


@pytest.fixture(scope="module")
def first_run(user_model):
    path, cache = user_model
    out = path.parent / "out"
    p = camdyn("integrate", str(path), "--t-end", "3", "--set", "c=900", "--rtol", "1e-11",
               "--json", "--out", str(out), cache=cache)
    return p, out


def test_readme_model_against_an_independent_solution(first_run):
    """The README's oscillator at c = 900 N/m, built on first use, integrated by DP54 at rtol
    1e-11 to t = 3 s: the final state against the DOP853 reference of the module docstring
    to 1e-8 relative (measured 4e-11), and the CSV written by --out at 200 of its rows to
    1e-7 of the stroke (measured 3e-10)."""
    p, out = first_run
    assert p.returncode == 0, p.stderr
    summary = json.loads(p.stdout)
    assert summary["model"] == "oscillator" and summary["status"] == "ok"
    assert {"method", "t_end", "n_steps", "n_rhs", "cpu_seconds"} <= set(summary)
    y, sols = reference_state(3.0, c=900.0)
    assert summary["state"]["x"] == pytest.approx(y[0], rel=1e-8)
    assert summary["state"]["xd"] == pytest.approx(y[1], rel=1e-8, abs=1e-9)
    data = np.genfromtxt(out / "oscillator.csv", delimiter=",", names=True)
    assert data.dtype.names == ("t", "x", "x_error", "xd", "xd_error", "a", "a_error")
    rows = data[:: max(1, len(data) // 200)]
    want = np.array([sols[0](t)[0] if t <= 1.0 else sols[1](t)[0] for t in rows["t"]])
    assert np.abs(rows["x"] - want).max() < 1e-7
    # each value with its estimate (the run at rtol 1e-12 beside it): the true error of the
    # series lies within ten times its largest estimate
    assert np.abs(rows["x"] - want).max() <= 10 * rows["x_error"].max()
    assert (out / "oscillator.png").stat().st_size > 10_000


def test_first_use_reports_each_stage_with_its_time(first_run):
    p, _ = first_run
    assert "not in the cache; deriving, generating and compiling it once" in p.stderr
    for stage in ("declaration", "derivation and code generation", "compilation"):
        assert re.search(rf"  {stage}: \d+\.\d s", p.stderr), stage
    assert re.search(r"built in \d+\.\d s; later runs load it from the cache", p.stderr)


def test_later_runs_load_from_the_cache_without_sympy(first_run, user_model):
    """The second run finds the entry, builds nothing, and its process never imports SymPy or
    camdyn.derive; it gives the first run's numbers exactly."""
    path, cache = user_model
    code = ("import json, sys\nfrom camdyn.runtime import cli\n"
            f"rc = cli.main(['integrate', {str(path)!r}, '--t-end', '3', '--set', 'c=900', "
            "'--rtol', '1e-11', '--json'])\n"
            "loaded = sorted(m for m in sys.modules if m == 'sympy' or m.startswith('camdyn.derive'))\n"
            "print(json.dumps({'rc': rc, 'loaded': loaded}), file=sys.stderr)\n")
    env = {**os.environ, "CAMDYN_CACHE_DIR": str(cache)}
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                       timeout=300)
    tail = json.loads(p.stderr.strip().splitlines()[-1])
    assert tail == {"rc": 0, "loaded": []}
    assert "not in the cache" not in p.stderr
    assert json.loads(p.stdout)["state"] == json.loads(first_run[0].stdout)["state"]


def test_three_processes_building_at_once_compile_it_once(tmp_path):
    """Three processes start the same first build at the same moment on a fresh cache: one
    builds while the others wait for it (a lock beside the entry), all three succeed with
    the same numbers, and the cache holds one entry and no temporary folder."""
    model = tmp_path / "oscillator.py"
    model.write_text(readme_model())
    cache = tmp_path / "cache"
    env = {**os.environ, "CAMDYN_CACHE_DIR": str(cache)}
    cmd = [sys.executable, "-m", "camdyn.runtime.cli", "integrate", str(model), "--t-end", "2",
           "--json"]
    procs = [subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                              env=env) for _ in range(3)]
    outs = [p.communicate(timeout=600) for p in procs]
    assert [p.returncode for p in procs] == [0, 0, 0], outs
    states = [json.loads(o[0])["state"] for o in outs]
    assert states[0] == states[1] == states[2]
    assert sum("deriving, generating and compiling" in o[1] for o in outs) == 1, outs
    assert sum(bool(re.search(r"built in \d+\.\d s", o[1])) for o in outs) == 1, outs
    folders = sorted(p.name for p in cache.iterdir() if p.is_dir())
    assert len(folders) == 1 and folders[0].startswith("oscillator-"), folders
    assert (cache / folders[0] / "build.json").is_file()


HELPER_MODEL = ("from camdyn.derive.model import Coordinate, Model, Output, Parameter, "
                "cam_input, time\nfrom springs import C0\n")


def test_a_changed_helper_module_is_built_again(tmp_path):
    """A model file that imports a module of its own from its folder (springs.py, the spring
    rate), run from another working folder: built with c = 400 N/m, then after springs.py
    says 900 N/m built again, each run against the independent solution of the module
    docstring to 1e-6 relative (DP54 at its default rtol 1e-8); a third run loads the
    second build from the cache."""
    folder = tmp_path / "model"
    folder.mkdir()
    text = readme_model().replace(
        "from camdyn.derive.model import Coordinate, Model, Output, Parameter, cam_input, time\n",
        HELPER_MODEL).replace('Parameter("c", 400.0,', 'Parameter("c", C0,')
    assert "C0," in text
    (folder / "oscillator.py").write_text(text)
    cache = tmp_path / "cache"
    for c, says in ((400.0, "not in the cache"), (900.0, "springs.py has changed since it was "
                                                         "built"), (900.0, None)):
        (folder / "springs.py").write_text(f"C0 = {c}\n")
        p = camdyn("integrate", str(folder / "oscillator.py"), "--t-end", "3", "--json",
                   cache=cache, cwd=tmp_path)
        assert p.returncode == 0, p.stderr
        if says:
            assert says in p.stderr, p.stderr
        else:
            assert "deriving" not in p.stderr, p.stderr
        y, _ = reference_state(3.0, c=c)
        assert json.loads(p.stdout)["state"]["x"] == pytest.approx(y[0], rel=1e-6)


def _entry(cache: Path) -> Path:
    (entry,) = [p for p in cache.iterdir() if p.is_dir() and not p.name.startswith(".")]
    return entry


def _flip(path: Path, at: float = 0.5) -> None:
    data = bytearray(path.read_bytes())
    data[int(len(data) * at)] ^= 0x40
    path.write_bytes(bytes(data))


DAMAGES = {
    "truncated module": (lambda e: os.truncate(next(e.glob("*.so")), 1000),
                         "oscillator.cpython-.* does not match its checksum"),
    "garbled module": (lambda e: _flip(next(e.glob("*.so"))),
                       "oscillator.cpython-.* does not match its checksum"),
    "empty record": (lambda e: (e / "build.json").write_text(""),
                     "build.json does not match its checksum"),
    "truncated record": (lambda e: os.truncate(e / "build.json", 40),
                         "build.json does not match its checksum"),
    "deleted record": (lambda e: (e / "build.json").unlink(), "build.json is missing"),
    "deleted checksums": (lambda e: (e / "SHA256SUMS").unlink(), "SHA256SUMS is missing"),
}


@pytest.fixture(scope="module")
def sound_entry(tmp_path_factory):
    """A cache with the README's model built in it, to copy and damage."""
    folder = tmp_path_factory.mktemp("sound")
    (folder / "oscillator.py").write_text(readme_model())
    p = camdyn("integrate", str(folder / "oscillator.py"), "--t-end", "2", "--json",
               cache=folder / "cache")
    assert p.returncode == 0, p.stderr
    return folder, json.loads(p.stdout)["state"]


# each a build of its own; the others' checks are test_checks_of_an_entry_name_what_is_wrong's
REBUILT = ("truncated module", "empty record", "deleted record")


@pytest.mark.parametrize("damage", [d if d in REBUILT else pytest.param(d, marks=pytest.mark.slow)
                                    for d in sorted(DAMAGES)])
def test_a_damaged_entry_is_rebuilt_with_a_note(sound_entry, tmp_path, damage):
    """A damaged cache entry (the compiled module truncated -- loading it killed the process
    with SIGBUS -- or garbled, the build record empty, truncated or deleted, the checksums
    deleted) is never loaded: one note on stderr names it, it is built again and the run
    gives the sound entry's numbers exactly; the next run loads the new entry."""
    folder, state = sound_entry
    cache = tmp_path / "cache"
    shutil.copytree(folder / "cache", cache)
    harm, why = DAMAGES[damage]
    harm(_entry(cache))
    for run in range(2):
        p = camdyn("integrate", str(folder / "oscillator.py"), "--t-end", "2", "--json",
                   cache=cache)
        assert p.returncode == 0 and json.loads(p.stdout)["state"] == state, p.stderr
        assert "Traceback" not in p.stderr
        notes = [ln for ln in p.stderr.splitlines() if ln.startswith("camdyn: ")]
        if run == 0:
            assert len(notes) == 1 and re.fullmatch(
                rf"camdyn: cache entry for model file oscillator\.py was damaged \({why}\); "
                "rebuilding", notes[0]), p.stderr
        else:
            assert notes == [] and "deriving" not in p.stderr, p.stderr
    assert [p.name for p in cache.iterdir() if p.name.startswith(".")] == []


def test_checks_of_an_entry_name_what_is_wrong(sound_entry, tmp_path):
    """ondemand.check on a sound entry and on each kind of damage, in this process: the
    sound one is "ok" with its record, each damaged one "damaged" with what is wrong, a
    record that is valid JSON but not a build record (its checksum updated too) as well."""
    import hashlib

    from camdyn.runtime.core import ondemand

    folder, _ = sound_entry
    state, info = ondemand.check(_entry(folder / "cache"))
    assert state == "ok" and info["name"] == "oscillator" and info["sources"] == {}
    for damage, (harm, why) in sorted(DAMAGES.items()):
        cache = tmp_path / damage.replace(" ", "-")
        shutil.copytree(folder / "cache", cache)
        harm(_entry(cache))
        state, detail = ondemand.check(_entry(cache))
        assert state == "damaged" and re.fullmatch(why, detail), (damage, detail)
    entry = _entry(cache)
    record = b'{"name": "oscillator"}'
    (entry / "build.json").write_bytes(record)
    sums = (entry / "SHA256SUMS").read_text().splitlines()
    sums = [ln if not ln.endswith("build.json") else
            f"{hashlib.sha256(record).hexdigest()}  build.json" for ln in sums]
    (entry / "SHA256SUMS").write_text("\n".join(sums) + "\n")
    assert ondemand.check(entry) == ("damaged", "build.json is not a build record of this "
                                                "camdyn")
    assert ondemand.check(tmp_path / "nothing") == ("missing", None)


def test_a_killed_build_leaves_no_temporary_folder_behind(tmp_path):
    """A build killed halfway leaves its temporary folder (hidden, beside the entry); the next
    build of the same model removes it (nobody else can be writing it: the entry's lock is
    free) and puts its own in place, leaving the cache with one entry and nothing hidden."""
    import signal
    import time

    model = tmp_path / "oscillator.py"
    model.write_text(readme_model())
    cache = tmp_path / "cache"
    env = {**os.environ, "CAMDYN_CACHE_DIR": str(cache)}
    proc = subprocess.Popen([sys.executable, "-m", "camdyn.runtime.cli", "integrate", str(model),
                             "--t-end", "1"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True, env=env, start_new_session=True)
    for line in proc.stderr:    # the build has begun: its temporary folder exists
        if "declaration:" in line:
            break
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait(timeout=60)
    time.sleep(0.5)
    hidden = [p.name for p in cache.iterdir() if p.name.startswith(".")]
    assert len(hidden) == 1 and hidden[0].startswith(".oscillator-"), hidden
    p = camdyn("integrate", str(model), "--t-end", "1", "--json", cache=cache)
    assert p.returncode == 0, p.stderr
    assert [p.name for p in cache.iterdir() if p.name.startswith(".")] == []
    assert len([p for p in cache.iterdir() if p.is_dir()]) == 1


def test_old_temporary_folders_of_other_entries_go_unless_being_built(tmp_path):
    """sweep_temporaries beside a build of entry A: A's own temporary folder goes at any age;
    another entry's goes when older than STALE_SECONDS and nobody holds its lock; one being
    built (its lock held by another process) or a recent one stays."""
    import time

    from camdyn.runtime.core import ondemand

    old = time.time() - ondemand.STALE_SECONDS - 60
    names = {".a-1.x": old, ".a-1.y": time.time(), ".b-2.x": old, ".c-3.x": old,
             ".d-4.x": time.time()}
    for name, mtime in names.items():
        (tmp_path / name).mkdir()
        (tmp_path / name / "part.pyx").write_text("")
        os.utime(tmp_path / name, (mtime, mtime))
    holder = subprocess.Popen(
        [sys.executable, "-c", "import sys, time\nfrom filelock import FileLock\n"
         f"lock = FileLock({str(tmp_path / 'c-3.lock')!r})\nlock.acquire()\n"
         "print('held', flush=True)\n"
         "time.sleep(60)\n"], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        ondemand.sweep_temporaries(tmp_path, tmp_path / "a-1")
    finally:
        holder.kill()
        holder.wait()
    assert sorted(p.name for p in tmp_path.iterdir() if p.is_dir()) == [".c-3.x", ".d-4.x"]


def test_an_unusable_cache_folder_is_refused_in_one_line(tmp_path):
    """A file in the cache folder's place, or a cache folder below a file: exit status 2 and
    one line naming the folder and CAMDYN_CACHE_DIR, before any build."""
    model = tmp_path / "oscillator.py"
    model.write_text(readme_model())
    (tmp_path / "afile").write_text("")
    for cache, why in ((tmp_path / "afile", "a file is in its place"),
                       (tmp_path / "afile" / "cache", "Not a directory")):
        p = camdyn("integrate", str(model), "--t-end", "1", cache=cache)
        assert p.returncode == 2 and p.stdout == "", p.stderr
        assert p.stderr.splitlines() == [
            f"camdyn integrate: error: cannot create the cache folder {cache}: {why}; set "
            "CAMDYN_CACHE_DIR to a folder camdyn may write in"]


def _no_writing(monkeypatch):
    """Folders read-only to this process (the tests run as root, whom chmod does not stop)."""
    access = os.access
    monkeypatch.setattr(os, "access", lambda path, mode, **kw:
                        not mode & os.W_OK and access(path, mode, **kw))


def test_a_read_only_cache_folder_is_refused_but_a_sound_entry_in_it_loads(
        tmp_path, sound_entry, monkeypatch, capsys):
    """A cache folder this process may not write in: a model that would need building is
    refused in one line (exit status 2); a sound entry in it loads all the same (a load
    writes nothing)."""
    from camdyn.runtime import cli
    from camdyn.runtime.core import ondemand

    folder, state = sound_entry
    other = tmp_path / "other.py"
    other.write_text(readme_model().replace('name="oscillator"', 'name="other"'))
    monkeypatch.setenv("CAMDYN_CACHE_DIR", str(folder / "cache"))
    _no_writing(monkeypatch)
    capsys.readouterr()
    assert cli.main(["integrate", str(other), "--t-end", "1"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.splitlines() == [
        f"camdyn integrate: error: cannot write in the cache folder {folder / 'cache'}: not "
        "writable; set CAMDYN_CACHE_DIR to a folder camdyn may write in"]
    ondemand._LOADED.clear()
    assert cli.main(["integrate", str(folder / "oscillator.py"), "--t-end", "2", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["state"] == state


CHILD = """
import contextlib, io, json, os, sys
from camdyn.runtime import cli
access = os.access
os.access = lambda p, mode, **kw: not (str(p).endswith("secret.py") and mode & os.R_OK) \
    and access(p, mode, **kw)
out = []
for path in sys.argv[2:]:
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        rc = cli.main([*json.loads(sys.argv[1]).replace("MODEL", path).split("|")])
    out.append([path, rc, err.getvalue().splitlines()])
print(json.dumps(out))
"""

COMMANDS = {"integrate": "integrate|MODEL|--t-end|1", "sweep": "sweep|MODEL|--grid|c=1:2:2",
            "precision": "precision|MODEL|--quick", "stability": "stability|MODEL|--param|c=1:2:2"}


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_a_model_argument_that_is_no_model_file_is_refused_without_blocking(tmp_path, command):
    """MODEL of integrate, sweep, precision and stability (one resolver,
    runtime/targets/model_target.py model_file): a folder (named .py or not), a file not
    ending in .py, /dev/zero, a named pipe (named .py or not) or a file this process may not
    read is refused in one line naming it, exit status 2, and nothing is opened: a named
    pipe would block its reader, /dev/zero never ends."""
    scenes = command in ("sweep", "precision")
    (tmp_path / "adir").mkdir()
    (tmp_path / "folder.py").mkdir()
    (tmp_path / "notes.txt").write_text("x = 1\n")
    (tmp_path / "secret.py").write_text(readme_model())
    os.mkfifo(tmp_path / "pipe")
    os.mkfifo(tmp_path / "pipe.py")
    allowed = "a model file (.py) or a scene file (.toml)" if scenes else "a model file (.py)"
    want = {"adir": f"adir is a folder, not {allowed}",
            "folder.py": f"folder.py is a folder, not {allowed}",
            "notes.txt": "notes.txt: neither a model file (.py) nor a scene file (.toml)"
            if scenes else "notes.txt: not a model file (a .py file defining build())",
            "/dev/zero": f"/dev/zero is a device, not {allowed}",
            "pipe": f"pipe is a named pipe, not {allowed}",
            "pipe.py": f"pipe.py is a named pipe, not {allowed}",
            "secret.py": "secret.py: cannot read the model file (permission denied)"}
    p = subprocess.run([sys.executable, "-c", CHILD, json.dumps(COMMANDS[command]), *want],
                       capture_output=True, text=True, timeout=120, cwd=tmp_path,
                       env={**os.environ, "CAMDYN_CACHE_DIR": str(tmp_path / "cache")})
    assert p.returncode == 0, p.stderr
    lead = f"camdyn {command}: error: " + ("SCENE_OR_MODEL " if command == "precision" else "")
    for path, rc, lines in json.loads(p.stdout):
        assert rc == 2 and lines == [lead + want[path]], (path, rc, lines)
    assert not (tmp_path / "cache").exists()


BAD_FILES = {
    "syntax": ("def build(:\n", "cannot import it: SyntaxError"),
    "no-build": ("x = 1\n", "defines no build()"),
    "build-raises": ("def build():\n    raise RuntimeError('no model today')\n",
                     "build() failed: RuntimeError: no model today"),
    "not-a-model": ("def build():\n    return 42\n", "build() returned int, not a"),
    "refused": ("from camdyn.derive.model import Coordinate, Model, Parameter, time\n"
                "t = time('t')\nx = Coordinate('x', 'm', 'position')\n"
                "k = Parameter('k', 1.0, 'N/m', 'spring')\n"
                "def build():\n    X = x(t)\n"
                "    return Model(name='massless', title='', reference='', doc='', time=t,\n"
                "                 time_unit='s', coordinates=(x,), kinetic=0 * X.diff(t),\n"
                "                 potential=k.symbol * X**2 / 2, parameters=(k,), outputs=())\n",
                "the derivation refused the model: ValueError: massless: coordinate x has no "
                "inertia"),
}


@pytest.mark.parametrize("case", sorted(BAD_FILES))
def test_a_bad_model_file_is_refused_in_one_line_and_leaves_no_entry(tmp_path, case):
    text, says = BAD_FILES[case]
    model = tmp_path / f"{case.replace('-', '_')}.py"
    model.write_text(text)
    cache = tmp_path / "cache"
    p = camdyn("integrate", str(model), "--t-end", "1", "--json", cache=cache)
    assert p.returncode == 2 and p.stdout == ""
    errors = [ln for ln in p.stderr.splitlines() if "error" in ln]
    assert len(errors) == 1 and str(model) in errors[0] and says in errors[0], p.stderr
    # the entry's lock file may stay, empty: no entry, no temporary folder
    assert not cache.exists() or [p for p in cache.iterdir() if p.is_dir()] == []


def test_integrate_refuses_bad_arguments_by_name(tmp_path):
    cases = [(["nosuchmodel", "--t-end", "1"], "is neither a model file (.py) nor a built-in"),
             (["one_dof", "--t-end", "1", "--set", "tau"], "argument --set: 'tau' is not NAME=VALUE"),
             (["one_dof", "--t-end", "1", "--set", "tau=2"], "tau=2 is out of range"),
             (["one_dof", "--t-end", "1", "--initial", "Y=1"], "argument --initial: one_dof has no state Y"),
             (["one_dof", "--t-end", "1", "--rtol", "1e-8", "--step", "0.01"], "give one")]
    for args, says in cases:
        p = camdyn("integrate", *args, cache=tmp_path / "cache")
        assert p.returncode == 2 and says in p.stderr, (args, p.stderr)


@pytest.mark.slow
def test_dynacam_variant_outside_generated_is_built_on_first_use(tmp_path, monkeypatch, capfd):
    """The indexing scene with an external force on the output selects
    dynacam_axial_ideal_backlash_groove_shafty_shaftz_force, which is not pre-generated: loading
    the scene builds it (its parameters are checked against its compiled manifest; measured
    ~11 s), and at F_ex = 0 its run is that of the pre-generated variant without the force
    to 1e-9 of the peak X'' (the same declaration without the force; measured 0).  A second
    use loads it from the cache."""
    import copy
    import tomllib

    from camdyn.runtime.targets import dynacam, scene_files as scenes
    from camdyn.runtime.core import ondemand

    monkeypatch.setenv("CAMDYN_CACHE_DIR", str(tmp_path))
    d = tomllib.loads(scenes.builtin("indexing").read_text())
    base = scenes.from_dict(copy.deepcopy(d))
    d["options"]["external"] = True
    d["parameters"]["F_ex"] = 0.0
    capfd.readouterr()
    sc = scenes.from_dict(copy.deepcopy(d))
    assert "not in the cache" in capfd.readouterr().err
    assert sc.variant == "dynacam_axial_ideal_backlash_groove_shafty_shaftz_force"
    assert sc.variant not in ondemand_available()
    s_new, r_new = dynacam.run(sc)
    s_old, r_old = dynacam.run(base)
    T = np.linspace(-0.05, 1.45, 301)
    a = np.array([dynacam.sample_at(sc, r_new, x) for x in T])
    b = np.array([dynacam.sample_at(base, r_old, x) for x in T])
    assert np.abs(a - b).max() <= 1e-9 * np.abs(b).max()
    ondemand._LOADED.clear()
    sc = scenes.from_dict(copy.deepcopy(d))
    said = []
    dynacam.run(sc, progress=said.append)
    assert "not in the cache" not in capfd.readouterr().err + "".join(said)


def ondemand_available():
    from camdyn.runtime.core.compiled import available

    return available()


def test_a_long_build_says_it_is_at_work_and_is_stopped_at_its_limit(tmp_path, monkeypatch):
    """A build heard from every HEARTBEAT seconds of silence ("still building, N s so far"),
    and stopped at BUILD_LIMIT with a run failure that caches nothing (here 1 s and 3 s,
    against the README model's build of several seconds)."""
    from camdyn.runtime.core import ondemand
    from camdyn.runtime.core.errors import SimulationError

    monkeypatch.setattr(ondemand, "HEARTBEAT", 1.0)
    monkeypatch.setattr(ondemand, "BUILD_LIMIT", 3.0)
    monkeypatch.setenv("CAMDYN_CACHE_DIR", str(tmp_path / "cache"))
    model = tmp_path / "oscillator.py"
    model.write_text(readme_model())
    said = []
    with pytest.raises(SimulationError, match="more than 3 s and was stopped"):
        ondemand.model_file(model, progress=said.append)
    assert "model file takes seconds to a minute, once" in said[0]
    assert any(re.fullmatch(r".*: still building, \d+ s so far", s) for s in said), said
    assert [p for p in (tmp_path / "cache").iterdir() if not p.name.endswith(".lock")] == []


@pytest.mark.slow
def test_a_rocker_held_on_both_sides_builds_in_bounded_time(tmp_path, monkeypatch):
    """The rocker scene with roller = "bilateral" selects a variant that is not pre-generated;
    its derivation ran in SymPy's simplify for more than 25 minutes, now about a minute
    (derive/codegen.py: a model that keeps its forces unexpanded is not simplified).  Where
    the spring-held rocker never leaves the cam (its run's least roller gap stays negative),
    the two give the same motion: X'' within 1e-6 of its peak over the run."""
    import copy
    import tomllib

    from camdyn.runtime.targets import dynacam, scene_files as scenes

    monkeypatch.setenv("CAMDYN_CACHE_DIR", str(tmp_path))
    d = tomllib.loads(scenes.builtin("rocker").read_text())
    held = scenes.from_dict(copy.deepcopy(d))
    d["options"]["roller"] = "bilateral"
    both = scenes.from_dict(copy.deepcopy(d))
    assert both.variant not in ondemand_available()
    s_held, r_held = dynacam.run(held)
    s_both, r_both = dynacam.run(both)
    assert not s_held["jump"]["occurs"] and r_held["roller_gap"].max() < 0
    T = np.linspace(-0.05, 1.95, 401)
    a = np.array([dynacam.sample_at(both, r_both, x) for x in T])
    b = np.array([dynacam.sample_at(held, r_held, x) for x in T])
    assert np.abs(a - b).max() <= 1e-6 * np.abs(b).max()
