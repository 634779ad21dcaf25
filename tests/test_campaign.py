"""A campaign of inputs against the command line: whatever a user types, camdyn answers with
exit 0 and finite figures that carry their estimates, or with one line and exit 1 (a run
that failed) or 2 (bad input); never a traceback, a crash, a hang, never a number from a
failed run.  `camdyn profile`, `figures` and `check` also end with 1 after their report when
a check of theirs fails (`profile`: its JSON's "ok" false, its stderr the checks' warnings).

Hypothesis draws the inputs: option values from a mix of ordinary, boundary and absurd
numbers (0, negative, 1e-300, 1e300, nan, inf) and words, names given twice; built-in scene
files mutated (a number changed to one of those, a key dropped, a key added, a value of the
wrong type).  The quick part runs in `make test`; the long one (more examples, every
command) is marked slow.  This module holds the judge, the runner and the counts, and the
campaign over the models' commands (residual, integrate, sweep, stability, precision), the
small commands (laws, polydyne, figures, scenes, check) and --out; test_campaign_cam.py
holds profile and design, test_campaign_scenes.py the scenes and the beam follower,
test_campaign_page.py the design page, test_campaign_models.py model files and the cache.

Counts: with CAMDYN_CAMPAIGN_TALLY=DIR every process of the run writes, per feature, how
many inputs were tried, answered, refused, and the findings; `python -m tests.test_campaign
DIR` prints them as a table.
"""
from __future__ import annotations

import contextlib
import io
import json
import math
import os
import re
import signal
import subprocess
import sys
import time
import tomllib
from collections import defaultdict
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from camdyn.runtime.cli import main
from camdyn.runtime.targets import scene_files

NUMBERS = st.one_of(
    st.sampled_from([0.0, -1.0, 1e-300, 1e300, float("nan"), float("inf"), -0.0, 1.0, 0.5,
                     2.0, 1e-3, 1e6, -1e300, float("-inf")]),
    st.floats(min_value=-1e3, max_value=1e3, allow_nan=False),
)
WORDS = st.sampled_from(["abc", "", "1e", "--", "0x10", "1,2", "nan", "-inf", "1e400", " ",
                         "1 2", "0.1.2"])
VALUE = st.one_of(NUMBERS.map(repr), WORDS)


@dataclass(frozen=True)
class Opt:
    """An option's values: ``good`` ones a user means, ``bad`` ones (boundary, absurd, words)."""

    good: st.SearchStrategy
    bad: st.SearchStrategy = VALUE


def num(*ordinary) -> Opt:
    """A number option: its ``ordinary`` values, or anything of VALUE."""
    return Opt(st.sampled_from([str(x) for x in ordinary]))


def choice(good, bad=()) -> Opt:
    """A word option: ``good`` words, or ``bad`` ones (default: good ones too)."""
    return Opt(st.sampled_from(list(good)), st.sampled_from(list(bad or good)))


def flag() -> Opt:
    return Opt(st.just(True), st.just(True))


def pairs(good_names, bad_names=("nope", ""), values: Opt | None = None) -> Opt:
    """A repeatable NAME=VALUE option: one good name at a good value, or a list of one or two
    items of any name and value (a name may come twice)."""
    values = values or num(0.1, 0.2)

    def item(names, v):
        return st.tuples(st.sampled_from(list(names)), v).map(lambda kv: f"{kv[0]}={kv[1]}")
    anything = st.one_of(values.good, values.bad)
    return Opt(st.lists(item(good_names, values.good), min_size=1, max_size=1),
               st.lists(item([*good_names, *bad_names], anything), min_size=1, max_size=2))


def argv_of(command: list, options: dict) -> list:
    """``command`` then every option: True a bare flag, a list a repeated option."""
    argv = list(command)
    for k, v in options.items():
        if v is True:
            argv.append(k)
        elif isinstance(v, list):
            for item in v:
                argv += [k, item]
        elif v is not None and v is not False:
            argv += [k, v]
    return argv


SPOILED = st.sampled_from([0, 0, 1, 1, 1, 2, 3])
"""How many of an input's options take a bad value: none (the input a user means), one (the
bad value alone to blame), or several."""


@st.composite
def _options(draw, required: dict, optional: dict, most: int) -> dict:
    chosen = {k: o for k, o in required.items()}
    if optional:
        for k in draw(st.lists(st.sampled_from(sorted(optional)), max_size=most, unique=True)):
            chosen[k] = optional[k]
    spoiled = set(draw(st.lists(st.sampled_from(sorted(chosen)), max_size=draw(SPOILED),
                                unique=True))) if chosen else set()
    return {k: draw(o.bad if k in spoiled else o.good) for k, o in chosen.items()}


def command(head, required=None, optional=None, most=3) -> st.SearchStrategy:
    """argv: ``head`` (a list, or a strategy of one), every ``required`` option and up to
    ``most`` of the ``optional`` ones (each a name -> Opt), none, one or more of them bad."""
    head = head if isinstance(head, st.SearchStrategy) else st.just(list(head))
    return st.tuples(head, _options(required or {}, optional or {}, most)).map(
        lambda a: argv_of(a[0], a[1]))


METHODS = choice(["dp54", "dop853", "rkn12", "radau5", "rodas4", "rk4", "koster"],
                 ["euler", "DP54", "", "rk4 "])
ADAPTIVE = choice(["dp54", "dop853", "rkn12", "radau5", "rodas4"], ["rk4", "koster", "nope", ""])
LAWS = ["cycloidal", "modified-sine", "3-4-5", "simple-harmonic", "parabolic", "uniform",
        "4-5-6-7", "5-6-7-8-9", "modified-trapezoid", "sine-constant-cosine", "polydyne"]
BAD_LAWS = ["nope", "", "Cycloidal", "cycloidal ", "3-4-5.csv"]


# -- the runner -------------------------------------------------------------------------------

LIMIT = 300.0
"""Seconds after which a command is taken for hung: far above any run the campaign draws
(each is under a few seconds), so a busy machine does not make a finding of a slow run."""


_LAST = {"seconds": 0.0}
"""How long the latest run took (for the log)."""


class Hang(BaseException):
    """The command did not end within LIMIT (a BaseException: no ``except Exception`` of the
    command's swallows it)."""


@contextlib.contextmanager
def _alarm(seconds: float):
    """Hang raised in this (the main) thread after ``seconds``; a compiled loop that holds
    the interpreter is stopped when it returns, and the run is then a finding all the same."""
    if seconds is None or not hasattr(signal, "setitimer") or \
            signal.getsignal(signal.SIGALRM) not in (signal.SIG_DFL, signal.SIG_IGN, None):
        yield
        return

    def ring(signum, frame):
        raise Hang(f"no answer within {seconds:g} s")

    signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, signal.SIG_DFL)


def run(argv: list[str], limit: float = LIMIT) -> tuple[object, str, str]:
    """camdyn ``argv`` in this process: (status, stdout, stderr); SystemExit (argparse) is a
    status too.  An exception that escapes ``main`` is returned as the status "exception:
    ..." (with its traceback on stderr), a hang as "hang: ...", for :func:`judge`."""
    import traceback

    out, err = io.StringIO(), io.StringIO()
    t0 = time.monotonic()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            with _alarm(limit):
                code = main(argv)
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else 2
        except Hang as exc:
            code = f"hang: {exc}"
        except Exception as exc:         # noqa: BLE001 - what escapes main is the finding
            traceback.print_exc()
            code = f"exception: {type(exc).__name__}: {exc}"
    took = time.monotonic() - t0
    if isinstance(code, int) and took > limit:
        code = f"hang: took {took:.0f} s (the loop held the interpreter)"
    _LAST["seconds"] = took
    return code, out.getvalue(), err.getvalue()


def run_apart(argv: list[str], limit: float = LIMIT, env: dict | None = None,
              cwd=None) -> tuple[object, str, str]:
    """camdyn ``argv`` in a process of its own (where a crash or a hang in a compiled loop
    must not take the test session with it): a signal's death is the status "crash: ...", a
    timeout "hang: ..."."""
    t0 = time.monotonic()
    try:
        p = subprocess.run([sys.executable, "-m", "camdyn.runtime.cli", *argv],
                           capture_output=True, text=True, timeout=limit,
                           env={**os.environ, **(env or {})}, cwd=cwd)
    except subprocess.TimeoutExpired as exc:
        return (f"hang: no answer within {limit:g} s", exc.stdout or "", exc.stderr or "")
    finally:
        _LAST["seconds"] = time.monotonic() - t0
    code = p.returncode
    if code < 0:
        code = f"crash: killed by {signal.Signals(-code).name}"
    return code, p.stdout, p.stderr


# -- the counts -------------------------------------------------------------------------------

TALLY: dict = defaultdict(lambda: {"tried": 0, "answered": 0, "checks failed": 0,
                                   "refused": 0, "run failed": 0, "findings": {}})
"""Per feature: the inputs tried, answered (0), answered with a failed check of the command's
(profile, figures, check: 1 with the report), refused as bad input (2), failed runs (1), and
the findings by kind, each kind with the distinct inputs that made it."""

FINDINGS = ("traceback", "crash", "hang", "wrong answer")


_TMP = re.compile(r"/\S*/pytest-of-[^/]+/pytest-\d+/")


def tally(feature: str, verdict: str, argv) -> None:
    row = TALLY[feature]
    row["tried"] += 1
    if verdict in FINDINGS:          # the same input in another tmp folder is the same input
        said = _TMP.sub("<tmp>/", " ".join(map(str, argv)))
        row["findings"].setdefault(verdict, set()).add(re.sub(r"<tmp>/[^/\s]+", "<tmp>", said))
    else:
        row[verdict] += 1


def write_tally() -> None:
    """This process's counts into $CAMDYN_CAMPAIGN_TALLY/tally-<pid>.json (none without it)."""
    folder = os.environ.get("CAMDYN_CAMPAIGN_TALLY")
    if not folder:
        return
    Path(folder).mkdir(parents=True, exist_ok=True)
    data = {f: {**row, "findings": {k: sorted(v) for k, v in row["findings"].items()}}
            for f, row in TALLY.items()}
    (Path(folder) / f"tally-{os.getpid()}.json").write_text(json.dumps(data, indent=1))


def tally_table(folder) -> str:
    """The counts of every process in ``folder``, summed, as a Markdown table."""
    total: dict = defaultdict(lambda: defaultdict(int))
    found: dict = defaultdict(lambda: defaultdict(set))
    for path in sorted(Path(folder).glob("tally-*.json")):
        for feature, row in json.loads(path.read_text()).items():
            for k, v in row.items():
                if k == "findings":
                    for kind, argvs in v.items():
                        found[feature][kind].update(argvs)
                else:
                    total[feature][k] += v
    head = ["feature", "tried", "answered (0)", "check failed (1, report)", "refused (2)",
            "run failed (1)", *FINDINGS]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for feature in sorted(total):
        t = total[feature]
        lines.append("| " + " | ".join([feature, *(str(t[k]) for k in (
            "tried", "answered", "checks failed", "refused", "run failed")),
            *(str(len(found[feature][k])) for k in FINDINGS)]) + " |")
    for feature in sorted(found):
        for kind, argvs in sorted(found[feature].items()):
            for a in sorted(argvs):
                lines.append(f"\n{feature}, {kind}: {a}")
    return "\n".join(lines)


@pytest.fixture(scope="module", autouse=True)
def campaign_session(tmp_path_factory):
    """Every campaign module: a private on-demand cache for the session (a DYNACAM variant
    or a model file drawn is built there, never in the user's), a scratch working folder
    (a default --out is written there, not into the checkout), and the counts written when
    the module ends."""
    base = tmp_path_factory.getbasetemp()
    cache = base / "campaign-cache"
    cache.mkdir(exist_ok=True)
    scratch = base / "campaign-cwd"
    scratch.mkdir(exist_ok=True)
    before = os.environ.get("CAMDYN_CACHE_DIR"), os.getcwd()
    os.environ["CAMDYN_CACHE_DIR"] = str(cache)
    os.chdir(scratch)
    try:
        yield cache
    finally:
        os.chdir(before[1])
        if before[0] is None:
            os.environ.pop("CAMDYN_CACHE_DIR", None)
        else:
            os.environ["CAMDYN_CACHE_DIR"] = before[0]
        write_tally()


# -- the judge --------------------------------------------------------------------------------

ESTIMATED = {
    "residual": ("U0", "U0dd", "Xdd_min_rise"),
    "simulate": ("Xdd_min_rise", "U0dd", "U0"),
    "integrate": ("state",),
    "beam-follower": ("max_abs_tip_deflection", "dwell_frequency_hz"),
    "profile": ("max_abs_pressure_angle_deg", "min_rho_profile"),
}
"""The headline figures of each command's JSON, each of which must carry ``<figure>_error``
(a number, or null where no estimate was asked for)."""

REPORTS_FAILED_CHECKS = ("profile", "figures", "check")
"""Commands that end with 1 after their report when a check of theirs fails."""

_NON_FINITE = re.compile(r"(?:^|[\s=(:,\[])[-+]?(?:nan|inf)(?=$|[\s,)\]])", re.I | re.M)


def finite_figures(record, where="answer") -> None:
    """Every number of a JSON answer finite (JSON has no NaN: a NaN or inf would have been
    printed as NaN/Infinity, which json.loads accepts, so check), every error estimate a
    number >= 0 or null."""
    if isinstance(record, float):
        assert math.isfinite(record), f"{where} = {record}"
    elif isinstance(record, dict):
        for k, x in record.items():
            finite_figures(x, f"{where}.{k}")
            if k.endswith("_error") and isinstance(x, (int, float)) and not isinstance(x, bool):
                assert x >= 0, f"{where}.{k} = {x} < 0"
    elif isinstance(record, list):
        for i, x in enumerate(record):
            finite_figures(x, f"{where}[{i}]")


def carries_estimates(name: str, record) -> None:
    for key in ESTIMATED.get(name, ()):
        if isinstance(record, dict) and record.get(key) is not None:
            assert f"{key}_error" in record, f"{key} has no {key}_error"


def _error_lines(err: str) -> list:
    return [l for l in err.splitlines() if "error:" in l or "run failed:" in l]


def _verdict(argv, code, out, err) -> tuple[str, str | None]:
    """(verdict, what is wrong): a finding's kind and its reason, or how the command ended."""
    name = argv[0]
    if isinstance(code, str):
        kind = code.split(":")[0]
        return {"exception": "traceback", "hang": "hang", "crash": "crash"}[kind], code
    if "Traceback" in err:
        return "traceback", err[-2000:]
    if code not in (0, 1, 2):
        return "crash", f"status {code}"
    if code and name in REPORTS_FAILED_CHECKS and out.strip():
        return _failed_check(argv, out, err)
    if code:
        lines = _error_lines(err)
        if len(lines) != 1:
            return "wrong answer", f"{len(lines)} error lines: {err[-2000:]}"
        if not lines[0].startswith(f"camdyn {name}"):
            return "wrong answer", f"the error line names no command: {lines[0]}"
        if out.strip():
            return "wrong answer", f"a failed run printed {out[:500]}"
        return ("refused" if code == 2 else "run failed"), None
    if _error_lines(err):
        return "wrong answer", f"status 0 with an error line: {err[-1000:]}"
    return _answer(argv, out)


def _answer(argv, out, verdict="answered"):
    try:
        if "--json" in argv:
            record = json.loads(out)
            finite_figures(record)
            carries_estimates(argv[0], record)
        else:
            if argv[0] == "laws":   # inf is a value there, as the tables say: the impact
                # sensitivity where H'' jumps (3.15)-(3.16), the uniform law's H''max (App. 2)
                out = re.sub(r"(?<=\s)[-+]?inf(?=\s|$)", "", out, flags=re.M)
            bad = _NON_FINITE.search(out)
            assert not bad, f"a non-finite number in the text: {out[max(0, bad.start() - 200):bad.end() + 50]}"
    except (AssertionError, ValueError) as exc:
        return "wrong answer", str(exc)
    return verdict, None


def _failed_check(argv, out, err):
    """Status 1 after the report: its stderr only the command's warnings and notes (and at
    most one error line, a file that could not be written); profile's JSON says "ok": false,
    its text FAIL."""
    lines = _error_lines(err)
    others = [l for l in err.splitlines() if l.strip() and l not in lines and
              not l.startswith(f"camdyn {argv[0]}: warning: ")]
    if argv[0] == "profile" and (len(lines) > 1 or others):
        return "wrong answer", f"stderr beside the warnings: {err[-1500:]}"
    if argv[0] == "profile":
        if "--json" in argv:
            try:
                if json.loads(out).get("ok") is not False:
                    return "wrong answer", "status 1 with \"ok\" not false"
            except ValueError as exc:
                return "wrong answer", f"status 1 with no JSON: {exc}"
        elif "FAIL" not in out:
            return "wrong answer", "status 1 and no FAIL in the report"
    return _answer(argv, out, "checks failed")


def judge(argv, code, out, err, feature: str | None = None) -> str:
    """The contract of every command (module doc), counted under ``feature`` (the command by
    default); a finding fails the test, naming its kind.  Returns the verdict."""
    verdict, why = _verdict(argv, code, out, err)
    tally(feature or argv[0], verdict, argv)
    if os.environ.get("CAMDYN_CAMPAIGN_LOG"):       # every input and how it ended, to read
        with open(os.environ["CAMDYN_CAMPAIGN_LOG"], "a") as log:
            said = (_error_lines(err) or [""])[0][:300]
            log.write(f"{feature or argv[0]}\t{verdict}\t{code}\t{json.dumps(argv)}\t{said}"
                      f"\t{_LAST['seconds']:.2f}\n")
    assert verdict not in FINDINGS, (verdict, argv, why)
    return verdict


QUICK = settings(max_examples=40, deadline=None, derandomize=True, database=None,
                 suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture,
                                        HealthCheck.filter_too_much, HealthCheck.data_too_large])
LONG = settings(max_examples=400, deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture,
                                       HealthCheck.filter_too_much, HealthCheck.data_too_large])


def few(n: int) -> settings:
    """QUICK with ``n`` examples."""
    return settings(QUICK, max_examples=n)


def many(n: int) -> settings:
    """LONG with ``n`` examples."""
    return settings(LONG, max_examples=n)


# -- law files --------------------------------------------------------------------------------

BLEND = '[[point]]\nT = 0\nH = 0\n"H\'" = 0\n"H\'\'" = 0\n[[point]]\nT = 0.5\nH = 0.5\n' \
        '"H\'" = 2.0\n"H\'\'" = "match"\n[[point]]\nT = 1\nH = 1\n"H\'" = 0\n"H\'\'" = 0\n'


def _cycloid_table(n: int, sep=",", header="angle,lift\n") -> str:
    rows = [f"{120 * i / (n - 1)!r}{sep}{20 * (i / (n - 1) - math.sin(2 * math.pi * i / (n - 1)) / (2 * math.pi))!r}"
            for i in range(n)]
    return header + "\n".join(rows) + "\n"


LAW_FILES = {
    "blend.toml": BLEND,
    "bspline.toml": "[bspline]\ncontrol = [0, 0, 0, 0.5, 1, 1, 1]\ndegree = 5\n",
    "bspline_deg9.toml": "[bspline]\ncontrol = [0, 0, 0, 0, 1, 1, 1, 1]\ndegree = 9\n",
    "table.csv": _cycloid_table(121),
    "table.txt": _cycloid_table(61, sep=" ", header=""),
    "table.dat": _cycloid_table(31, sep="\t", header="# angle lift\n"),
    "coarse.csv": _cycloid_table(5),
    "rounded.csv": "\n".join(f"{i},{round(20 * (i / 120 - math.sin(2 * math.pi * i / 120) / (2 * math.pi)), 2)}"
                             for i in range(121)) + "\n",
    "falling.csv": "0,1\n1,0.5\n2,0\n",
    "one_row.csv": "0,0\n",
    "nan.csv": "0,0\n1,nan\n2,1\n",
    "binary.csv": bytes(range(256)) * 4,
    "latin1.txt": "0,0\n1,0.5\n2,1\n# \xe9\n".encode("latin-1"),
    "nul.dat": b"0,0\n1\x00,1\n",
    "empty.csv": b"",
    "empty.toml": b"",
    "broken.toml": b"[[point]\nT = 0\n",
    "scalar.toml": b"point = 3\n",
    "control.toml": b"[bspline]\ncontrol = 5\n",
    "point_strings.toml": b'[[point]]\nT = "a"\nH = 0\n',
    "bspline_nan.toml": b"[bspline]\ncontrol = [0, nan, 1]\n",
    "huge_degree.toml": b"[bspline]\ncontrol = [0, 1]\ndegree = 1000\n",
}
"""Law files of every kind: good ones (tables, blends, B-splines) and ones that cannot be
read or shaped."""


@pytest.fixture(scope="session")
def law_folder(tmp_path_factory) -> Path:
    """LAW_FILES written, a folder named like a law file, a named pipe, and a missing path."""
    folder = tmp_path_factory.mktemp("laws")
    for name, text in LAW_FILES.items():
        (folder / name).write_bytes(text if isinstance(text, bytes) else text.encode())
    (folder / "folder.csv").mkdir()
    os.mkfifo(folder / "pipe.csv")
    return folder


GOOD_LAW_FILES = ["blend.toml", "bspline.toml", "bspline_deg9.toml", "table.csv", "table.txt",
                  "table.dat"]
BAD_LAW_FILES = [*(n for n in LAW_FILES if n not in GOOD_LAW_FILES), "folder.csv", "pipe.csv",
                 "missing.csv", "/dev/zero.csv", "/dev/zero"]


def law_choice(good=LAWS, bad=BAD_LAWS) -> Opt:
    """A law: a name of the library or a good law file (``@name``, resolved by
    :func:`laws_in`); bad: a word, or a law file that cannot be read or shaped."""
    def files(names):
        return st.sampled_from(names).map(lambda n: "@" + n)
    good_ = files(GOOD_LAW_FILES)
    return Opt(st.one_of(st.sampled_from(list(good)), good_) if good else good_,
               st.one_of(st.sampled_from(list(bad)), files(BAD_LAW_FILES)))


def laws_in(argv: list, folder: Path) -> list:
    """``@name`` items of ``argv`` as paths in ``folder``."""
    return [str(folder / a[1:]) if a.startswith("@") and not a.startswith("@/") else
            a[1:] if a.startswith("@/") else a for a in argv]


# -- the models' commands ---------------------------------------------------------------------

def residual_argv(quick=False):
    def one(model):
        fv = {"--fv": num(2.5, 10)} if model == "camshaft2" else {}
        return command(["residual", "--model", model, "--json"], {"--tau": num(0.15, 0.3), **fv}, {
            "--fa": num(0.5, 2), "--fv": num(2.5), "--q": num(0.05), "--rtol": num(1e-8),
            "--t-end": num(3, 5), "--theta": num(0.1, 0.3), "--design-tau": num(0.15),
            "--method": METHODS, "--step": num(0.001, 0.01), "--atol": num(1e-9),
            "--state-atol": pairs(["X", "Xd"]), "--law": law_choice(),
            "--no-error-estimate": flag()})
    return st.sampled_from(["one-dof", "camshaft1", "camshaft2", "one-dof", "camshaft1",
                            "one_dof", "nope", ""]).flatmap(one)


INTEGRATED = {"one_dof": ["X", "Xd"], "camshaft1": ["X", "Xd"], "pendulum_xy": ["x", "y"],
              "camshaft2": ["X", "Xd"], "roller": ["x", "xd"], "motor1": ["X", "Xd"]}


def integrate_argv(quick=False):
    def one(model):
        states = INTEGRATED.get(model, ["X"])
        return command(["integrate", model, "--json"], {"--t-end": num(2, 0.5)}, {
            "--rtol": num(1e-8), "--step": num(0.001), "--method": METHODS,
            "--set": pairs(["tau", "Fa"], ["nope", "TAU", "", "q"]),
            "--initial": pairs(states, ["nope", ""], Opt(st.sampled_from(["0.1", "-0.2"]),
                                                         st.sampled_from(["1e300", "-1e101", "nan",
                                                                          "inf", "1e100"]))),
            "--atol": num(1e-9), "--state-atol": pairs(states),
            "--max-steps": choice(["1000", "5000000"], ["0", "1.5", "x", "-1", "1e9"]),
            "--exact-segments": choice(["on", "off"], ["yes", ""]),
            "--law": law_choice(), "--theta": num(0.1),
            "--turn": choice(["90,90,90,90", "120,60,100,80"],
                             ["a", "0,0,0,360", "90,90,90", "nan,90,90,90", "180,0,180,0"]),
            "--return-law": choice(["cycloidal", "uniform"], ["nope"]),
            "--dependent": choice(["x", "y"], ["x,y", "", "nope"]),
            "--no-error-estimate": flag()})
    return st.sampled_from([*INTEGRATED, "nope"]).flatmap(one)


GRIDS = choice(["tau=0.1:0.2:2", "tau=0.1,0.2", "Fa=0,1", "tau=0.1:0.3:3:log",
                "tau=0.1:0.3:3:inv"],
               ["tau=0.1,,0.2", "tau=0.1,0.2,", "tau=0.1,0.2,0.1", "tau=0.2:0.2:3",
                "tau=0.1:0.3:3:sq", "tau=", "=0.1", "tau", "tau=nan:1:2", "tau=0.1:inf:2",
                "Fa=-1,1", "nope=1,2", "tau=0.1:0.2:1e9", "tau=0.1:0.2:-2", "tau=0.1,0.2 ",
                "tau=1e-300:0.2:2"])


def sweep_argv(quick=False):
    any_grid = st.tuples(st.sampled_from(["tau", "Fa", "nope"]), VALUE, VALUE,
                         st.sampled_from(["1", "3", "0", "x", "2:log", "2:inv"])).map(
        lambda g: f"{g[0]}={g[1]}:{g[2]}:{g[3]}")
    grid = Opt(st.lists(GRIDS.good, min_size=1, max_size=1),
               st.lists(st.one_of(GRIDS.bad, any_grid, GRIDS.good), min_size=1, max_size=2))
    targets = ["one_dof", "camshaft1"] + ([] if quick else ["camshaft2", "nope"])
    return command(st.sampled_from(targets).map(lambda t: ["sweep", t, "--quiet"]),
                   {"--grid": grid, "--jobs": choice(["1"], ["0", "-1", "x"])}, {
        "--rtol": num(1e-8), "--t-end": num(3), "--step": num(0.001),
        "--method": METHODS, "--atol": num(1e-9), "--state-atol": pairs(["X", "Xd"]),
        "--law": law_choice(["cycloidal", "3-4-5"]), "--no-error-estimate": flag()})


def stability_argv(quick=False):
    params = choice(["tau=0.2,0.3", "tau=0.3", "tau=0.2:0.3:2", "tau=0.2:0.3:2:log"],
                    ["tau=0.1,,0.2", "tau=0.2,0.2", "tau=", "kappa=100:1000:2", "nope=1,2",
                     "tau=nan", "tau=0,0.1", "tau=0.2:0.3:0"])
    steps = choice(["0.01", "0.01,0.02", "0.01:0.02:2"],
                   ["0.01,,0.02", "0.01,0.01", "0", "-0.01", "nan", "1e300", "a", ""])
    rtols = choice(["1e-6", "1e-6,1e-8"], ["1e-6,,1e-8", "0", "2", "nan", "1e-3:1e-6:2:log"])
    methods = choice([["rk4"], ["koster"], ["rk4", "koster"]], [["nope"], ["dp54", "dp54"]])
    return command(st.sampled_from(["one_dof", "camshaft1"]).map(
        lambda m: ["stability", m, "--quiet", "--json"]),
        {"--methods": methods, "--param": params, "--steps": steps}, {
        "--rtols": rtols, "--set": pairs(["q"], ["tau", "nope", ""]),
        "--threshold": num(1e-3), "--t-end": num(2), "--law": law_choice(["cycloidal"])})


def precision_argv(quick=False):
    targets = ["one_dof", "camshaft1"] + ([] if quick else ["spring_loaded", "nope"])
    return command(st.sampled_from(targets).map(
        lambda t: ["precision", t, "--no-peers", "--quick", "--json"]),
        {"--methods": choice([["dp54"], ["rk4"], ["dop853", "rodas4"]], [["nope"]])}, {
        "--set": pairs(["tau"], ["nope", "", "Fa"]), "--t-end": num(2, 3)})


def _spread(argv: list) -> list:
    """--methods A B: argv_of wrote ["--methods", "A", "--methods", "B"] for a list; the
    command takes one --methods with several words."""
    out, methods = [], []
    i = 0
    while i < len(argv):
        if argv[i] == "--methods" and i + 1 < len(argv):
            methods.append(argv[i + 1])
            i += 2
            continue
        out.append(argv[i])
        i += 1
    return out + (["--methods", *methods] if methods else [])


def with_out(argv: list, folder: Path) -> list:
    return [*argv, "--out", str(folder)]


@QUICK
@given(argv=st.one_of(residual_argv(True), integrate_argv(True)))
def test_quick_campaign_over_the_models_commands(argv, law_folder):
    argv = laws_in(argv, law_folder)
    judge(argv, *run(argv))


@few(10)
@given(argv=st.one_of(sweep_argv(True), stability_argv(True), precision_argv(True)))
def test_quick_campaign_over_grids_maps_and_ladders(argv, law_folder, tmp_path_factory):
    argv = _spread(with_out(laws_in(argv, law_folder), tmp_path_factory.mktemp("o")))
    judge(argv, *run(argv))


@pytest.mark.slow
@many(150)
@given(argv=st.one_of(residual_argv(), integrate_argv(), sweep_argv(), stability_argv(),
                      precision_argv()))
def test_campaign_over_the_models_commands(argv, law_folder, tmp_path_factory):
    argv = laws_in(argv, law_folder)
    if argv[0] in ("sweep", "stability", "precision"):
        argv = _spread(with_out(argv, tmp_path_factory.mktemp("o")))
    judge(argv, *run(argv))


LAW_FILE_TAKERS = {
    "residual": ["residual", "--model", "one-dof", "--tau", "0.15", "--law"],
    "integrate": ["integrate", "one_dof", "--t-end", "1", "--law"],
    "sweep": ["sweep", "one_dof", "--grid", "tau=0.1,0.2", "--quiet", "--out", "OUT", "--law"],
    "stability": ["stability", "one_dof", "--methods", "rk4", "--steps", "0.01", "--param",
                  "tau=0.2,0.3", "--quiet", "--out", "OUT", "--law"],
    "design": ["design", "--stroke", "0.02", "--tau", "0.15", "--fa", "0", "--quiet", "--law"],
    "profile": ["profile", "--stroke", "0.02", "--base-radius", "0.04", "--roller-radius",
                "0.01", "--out", "OUT", "--law"],
    "profile --return-law": ["profile", "--stroke", "0.02", "--base-radius", "0.04",
                             "--roller-radius", "0.01", "--out", "OUT", "--return-law"],
    "laws --rise": ["laws", "--rise"],
}
"""Every command that takes a law file, with quick arguments, the file last."""


@pytest.mark.parametrize("taker, file", [
    *((t, "binary.csv") for t in sorted(LAW_FILE_TAKERS)),
    *(("residual", f) for f in ("latin1.txt", "nul.dat", "empty.toml", "broken.toml",
                                "scalar.toml", "folder.csv", "pipe.csv")),
    ("profile", "pipe.csv"), ("design", "scalar.toml")])
def test_a_law_file_that_cannot_be_read_is_one_line_everywhere(taker, file, law_folder,
                                                                tmp_path):
    """`residual --law BINARYFILE` ended in a UnicodeDecodeError traceback: every command
    that takes a law file refuses one that cannot be read in one line naming it (status 2,
    nothing written), whatever is wrong with it (not UTF-8, a NUL byte, empty, not TOML, a
    TOML of the wrong shape, a folder, a pipe: never opened)."""
    argv = [str(tmp_path / "out") if a == "OUT" else a for a in LAW_FILE_TAKERS[taker]]
    argv.append(str(law_folder / file))
    code, out, err = run(argv)
    assert judge(argv, code, out, err, feature="findings") == "refused"
    assert file in err
    assert not (tmp_path / "out").exists() or os.listdir(tmp_path / "out") == []


# -- the small commands: laws, polydyne, figures, scenes, check -------------------------------

def laws_argv(quick=False):
    plain = command(["laws"], {}, {"--theta": num(0.1, 0.3), "--json": flag()})
    rise = command(["laws"], {"--rise": law_choice([], ["cycloidal", "nope", ""])},
                   {"--json": flag()})
    shaped = command(["laws", "--no-error-estimate"], {
        "--tau": num(0.15), "--stroke": num(0.02), "--base-radius": num(0.04),
        "--roller-radius": num(0.01)}, {"--fa": num(0, 2), "--json": flag()})
    out_of_range = st.one_of(VALUE, st.sampled_from(["0.99", "1"]))
    tau = command(["laws", "--no-error-estimate"], {"--tau": Opt(out_of_range, out_of_range)},
                  {"--fa": num(0, 100.5)})
    sweep = command(["laws", "--no-error-estimate"], {
        "--sweep": choice(["spring_loaded", "fig8_1a"], ["indexing", "default", "nope", ""]),
        "--n": choice(["2"], ["1", "201", "x", "0"])}, {
        "--law": choice(["modified-sine", "sine-constant-cosine"], ["cycloidal", "nope"]),
        "--values": choice(["0.1,0.2"], ["0.1,,0.2", "0.1,0.1", "nan", "", "0.6"])})
    if quick:      # App. 2's table is derived in SymPy (20 s, once a process), laws --tau
        # runs every law's envelope (a minute): the rises and the refusals of --tau only
        return st.one_of(rise, tau.filter(lambda a: not _in_range(a, "--tau", 0, 0.99)))
    return st.one_of(plain, rise, shaped, tau, sweep)


def _in_range(argv, flag_, low, high) -> bool:
    try:
        return low < float(argv[argv.index(flag_) + 1]) < high
    except (ValueError, IndexError):
        return False


def polydyne_argv(quick=False):
    return command(["polydyne", "--quiet", "--json", "--no-error-estimate"],
                   {"--design-tau": num(0.15, 0.3)}, {
        "--taus": choice(["0.1:0.2:3", "0.2:0.4:5"],
                         ["0.2:0.1:3", "a", "0.1:0.2:0", "0.1:0.2:1e9", "0.1:0.2", "0:0.2:3",
                          "0.1:1.5:3", "nan:0.2:3", "0.1,0.2", "0.1:0.1:3"]),
        "--q": num(0.05)})


FIGURES = choice(["3.3", "3.4"], ["nope", "", ",", "3.3,3.3", "3.3,nope", " 3.3 ", "paper 99",
                                  "4.99"])


def figures_argv(quick=False):
    return command(["figures", "--quiet", "--quick"], {"--only": FIGURES})


def check_argv(quick=False):
    keys = choice(["table3I.U0dd.0.105"], ["nosuchkey", "", " ", "U0dd"])
    # run: one check, or a selection of none (-k "" selects all of them, -k U0dd nine: listed)
    one = choice(["table3I.U0dd.0.105"], ["nosuchkey", " ", "NOSUCHKEY"])
    return st.one_of(
        command(["check", "--quiet", "--no-error-estimate"], {"-k": one}, {
            "--topic": choice(["spine"], ["nope", ""]), "--json": flag()}),
        command(["check", "--list"], {}, {"-k": keys, "--topic": choice(["spine"], ["nope"]),
                                          "--json": flag()}))


def scenes_argv(quick=False):
    return command(["scenes"], {}, {"--json": flag()})


def small_argv(quick=False):
    return st.one_of(laws_argv(quick), polydyne_argv(quick), figures_argv(quick),
                     check_argv(quick), scenes_argv(quick))


def small_case(argv, tmp_path_factory):
    """laws --tau and --sweep, polydyne and figures write into --out (laws only those two)."""
    if argv[0] in ("polydyne", "figures") or "--tau" in argv or "--sweep" in argv:
        argv = with_out(argv, tmp_path_factory.mktemp("o"))
    judge(argv, *run(argv))


@few(15)
@given(argv=small_argv(True))
def test_quick_campaign_over_the_small_commands(argv, law_folder, tmp_path_factory):
    small_case(laws_in(argv, law_folder), tmp_path_factory)


@pytest.mark.slow
@many(60)
@given(argv=small_argv())
def test_campaign_over_the_small_commands(argv, law_folder, tmp_path_factory):
    small_case(laws_in(argv, law_folder), tmp_path_factory)


# -- --out: a user's file named like an output, or a folder that is read-only -----------------

OUT_WRITERS = {
    "stability": (["stability", "one_dof", "--param", "tau=0.2,0.3", "--methods", "rk4",
                   "--steps", "0.01,0.02", "--quiet"],
                  ["stability_one_dof_tau.csv", "stability_one_dof_tau.png",
                   "stability_one_dof_tau.json"], "camdyn.runtime.studies.stability_map.study"),
    "simulate": (["simulate", "spring_loaded", "--no-error-estimate"],
                 ["spring_loaded_torque.png", "spring_loaded_Xdd.png"],
                 "camdyn.runtime.measure.contract.answer"),
    "precision": (["precision", "one_dof", "--set", "tau=0.3", "--no-peers", "--quick",
                   "--methods", "dp54"], ["one_dof_precision.png", "one_dof_precision.csv",
                                          "one_dof_precision.json"],
                  "camdyn.runtime.studies.precision.study"),
    "laws --tau": (["laws", "--tau", "0.15", "--no-error-estimate"],
                   ["laws_selection.png", "laws_selection.csv"],
                   "camdyn.thesis.design.selection.table"),
    "laws --sweep": (["laws", "--sweep", "spring_loaded", "--n", "2", "--no-error-estimate"],
                     ["laws_sweep.csv", "laws_sweep.png"],
                     "camdyn.thesis.design.shape_sweep.sweep"),
    "integrate": (["integrate", "one_dof", "--t-end", "2", "--set", "tau=0.3"],
                  ["one_dof.png", "one_dof.csv"], "camdyn.runtime.measure.contract.answer"),
    "sweep": (["sweep", "one_dof", "--grid", "tau=0.2,0.3", "--quiet"],
              ["U0dd.png", "sweep.csv"], "camdyn.runtime.targets.grid.GridPlan.run"),
    "run": (["run", "spring_loaded", "--quiet", "--no-error-estimate"],
            ["report.json", "spring_loaded_Xdd.png", "spring_loaded_torque.png"],
            "camdyn.runtime.measure.contract.answer"),
    "design": (["design", "--stroke", "0.02", "--tau", "0.15", "--fa", "0.5", "--quiet"],
               ["design.json", "design.png"], None),
    "beam-follower": (["beam-follower", "--revolutions", "0.25", "--no-error-estimate"],
                      ["fig4_modes.png", "fig9_rise.png"],
                      "camdyn.runtime.measure.contract.answer"),
    "polydyne": (["polydyne", "--design-tau", "0.15", "--quiet", "--no-error-estimate"],
                 ["polydyne.png", "polydyne.json"], "camdyn.runtime.studies.polydyne.compensation"),
    "profile": (["profile", "--stroke", "0.02", "--base-radius", "0.04", "--roller-radius",
                 "0.01", "--points-per-degree", "1"],
                ["cam.csv", "cam.dxf", "cam.png", "cam.json"], None),
}
"""Every command that writes into --out: quick arguments, files it writes there, and where its
runs start (None: the command has no run to speak of before it writes)."""


class Ran(AssertionError):
    """A run started where the command should have refused first."""


BINDERS = ("camdyn.runtime.targets.camshaft1_study", "camdyn.runtime.studies.stability_map",
           "camdyn.thesis.design.shape_sweep")
"""Modules that bind the runs' entry point at their import (from ... import answer): imported
before it is replaced, or one first imported meanwhile would keep the replacement for good."""


def no_runs(monkeypatch, entry: str, what: str) -> None:
    """``entry`` (a dotted path) fails the test if called while ``monkeypatch`` holds."""
    import importlib

    for name in BINDERS:
        importlib.import_module(name)

    def ran(*a, **k):
        raise Ran(f"{what}: a run started before the command refused")
    monkeypatch.setattr(entry, ran)


def _read_only(monkeypatch, folder: Path) -> None:
    """``folder`` read-only: chmod 0o500, and where that does not stop this process (root),
    os.access says so as it would (as tests/test_cli_findings.py does)."""
    folder.chmod(0o500)
    if not os.access(folder, os.W_OK):
        return
    real = os.access

    def access(path, mode, *args, **kwargs):
        if os.path.abspath(os.fspath(path)) == str(folder) and mode & os.W_OK:
            return False
        return real(path, mode, *args, **kwargs)

    monkeypatch.setattr(os, "access", access)


def out_hazards():
    return st.tuples(st.sampled_from(sorted(OUT_WRITERS)), st.sampled_from(["file", "read-only"]),
                     st.integers(0, 10))


def out_hazard(case, tmp_path, monkeypatch):
    """One hazard: the command, a user's file named like one of its outputs (byte for byte
    as it was, and nothing written beside it) or a read-only --out (nothing written); a
    refusal before any run (the run's entry point fails the test if reached)."""
    name, hazard, pick = case
    argv, files, entry = OUT_WRITERS[name]
    out = tmp_path / f"out-{name.replace(' ', '')}-{hazard}-{pick}"
    out.mkdir()
    mine = b"my own,work\n1,2\n"
    if hazard == "file":
        (out / files[pick % len(files)]).write_bytes(mine)
    with monkeypatch.context() as mp:
        if entry:
            no_runs(mp, entry, name)
        if hazard == "read-only":
            _read_only(mp, out)
        try:
            argv = [*argv, "--out", str(out)]
            code, o, e = run(argv)
        finally:
            out.chmod(0o700)
    verdict = judge(argv, code, o, e, feature="--out")
    assert verdict == "refused", (argv, code, e)
    if hazard == "file":
        assert sorted(os.listdir(out)) == [files[pick % len(files)]]
        assert (out / files[pick % len(files)]).read_bytes() == mine
    else:
        assert os.listdir(out) == []


@few(12)
@given(case=out_hazards())
def test_quick_campaign_over_out_folders(case, tmp_path, monkeypatch):
    out_hazard(case, tmp_path, monkeypatch)


@pytest.mark.slow
@many(30)
@given(case=out_hazards())
def test_campaign_over_out_folders(case, tmp_path, monkeypatch):
    out_hazard(case, tmp_path, monkeypatch)


# -- scenes mutated (the three of two months ago; every built-in in test_campaign_scenes.py) --

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


def mutations(scenes=SCENES):
    return st.tuples(st.sampled_from(scenes), st.sampled_from(["number", "drop", "add", "type"]),
                     st.integers(0, 10_000), NUMBERS)


def mutate_table(table: dict, how, pick, number) -> dict:
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
    return table


def mutate(name, how, pick, number, folder) -> str:
    table = mutate_table(tomllib.loads(scene_files.builtin(name).read_text()), how, pick, number)
    f = folder / f"{name}_{how}_{pick}.toml"
    f.write_text(_dump(table))
    return str(f)


@few(20)
@given(m=mutations())
def test_quick_campaign_over_mutated_scenes(m, tmp_path_factory):
    argv = ["simulate", mutate(*m, tmp_path_factory.mktemp("s")), "--json"]
    judge(argv, *run(argv))


@pytest.mark.slow
@many(50)
@given(m=mutations(), command_=st.sampled_from(["simulate", "run", "precision"]))
def test_campaign_over_mutated_scenes(m, command_, tmp_path_factory):
    folder = tmp_path_factory.mktemp("s")
    argv = [command_, mutate(*m, folder)]
    if command_ == "simulate":
        argv.append("--json")
    elif command_ == "run":
        argv += ["--out", str(folder / "out"), "--quiet", "--no-error-estimate"]
    else:
        argv += ["--no-peers", "--quick", "--out", str(folder / "out"), "--json"]
    judge(argv, *run(argv))


if __name__ == "__main__":          # python -m tests.test_campaign DIR: the counts' table
    print(tally_table(sys.argv[1]))
