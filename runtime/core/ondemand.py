"""Models on demand: a model that is not pre-generated is derived, generated and compiled on
first use into a per-user cache, and loaded from there at once on every later use.

What asks for one: a DYNACAM scene whose options select a variant outside ``generated/``,
and a user's own model file (`camdyn integrate MODEL.py`).  The build runs
:mod:`camdyn.derive.build` as a program of its own, so this process never loads SymPy; its
progress lines (each stage with its time) are passed on.

The cache lives in platformdirs' user cache folder (``CAMDYN_CACHE_DIR`` overrides it); an
entry is keyed by a hash of what decides the compiled code: the model's source (the model
file's path and bytes, or the option set), the derivation code (every file of
``camdyn.derive``), the runtime's Cython headers (the ABI, runtime/engine/abi.pxd) and the
camdyn, SymPy and Cython versions.  The modules of the user's that a model file imports are
known only once it has run, so the build records them with their sha256 (derive/build.py
``user_sources``) and an entry whose modules have changed since is built again.

An entry holds the compiled module, its Cython source, the compiler's output, the build
record ``build.json`` and ``SHA256SUMS`` (the format of ``sha256sum -c``) over the record and
the compiled module, checked on every load: a damaged entry (truncated, garbled, a file
missing) is never loaded, as a garbled compiled module could crash the process, but built
again after a one-line note.  One process builds an entry while the others wait for it (a
file lock beside it, ``<entry>.lock``); the build goes into a temporary folder beside the
entry renamed into place when complete, so a failed build leaves nothing behind, and a
killed build's temporary folder is removed by a later build.
"""
from __future__ import annotations

import hashlib
import importlib.machinery
import importlib.util
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from functools import lru_cache
from importlib import metadata
from pathlib import Path

from .errors import CamdynInputError, SimulationError, on_disk, writable_folder
from .compiled import CompiledModel

ENV_CACHE = "CAMDYN_CACHE_DIR"
RECORD = "build.json"
SUMS = "SHA256SUMS"
STALE_SECONDS = 600
"""A temporary build folder this old whose entry nobody is building is a killed build's."""


def cache_root() -> Path:
    """Where compiled models on demand are kept: $CAMDYN_CACHE_DIR, else the user cache."""
    if os.environ.get(ENV_CACHE):
        return Path(os.environ[ENV_CACHE])
    import platformdirs

    return Path(platformdirs.user_cache_dir("camdyn"))


@lru_cache(maxsize=1)
def _derive_digest() -> str:
    """Hash of every file of camdyn.derive (declarations, derivation, templates), read as bytes
    without importing it."""
    spec = importlib.util.find_spec("camdyn.derive")
    h = hashlib.sha256()
    for root in spec.submodule_search_locations:
        for path in sorted(Path(root).rglob("*")):
            if path.is_file() and path.suffix in (".py", ".j2"):
                h.update(str(path.relative_to(root)).encode() + b"\0" + path.read_bytes())
    return h.hexdigest()


@lru_cache(maxsize=1)
def _headers_digest() -> str:
    """Hash of the runtime's Cython headers (every .pxd and .pxi of runtime/engine: the ABI,
    the loops, the dense output, the tableaus), compiled into every model: a cached build
    from other headers is never loaded."""
    spec = importlib.util.find_spec("camdyn.runtime.engine")
    h = hashlib.sha256()
    for root in spec.submodule_search_locations:
        for path in sorted(Path(root).glob("*.px[di]")):
            h.update(path.name.encode() + b"\0" + path.read_bytes())
    return h.hexdigest()


def _version(dist: str) -> str:
    try:
        return metadata.version(dist)
    except metadata.PackageNotFoundError:
        return "none"


def key(kind: str, payload: bytes) -> str:
    h = hashlib.sha256()
    for part in (kind.encode(), payload, _derive_digest().encode(), _headers_digest().encode(),
                 *(f"{d}={_version(d)}".encode() for d in ("camdyn", "sympy", "Cython")),
                 sys.implementation.cache_tag.encode()):
        h.update(part + b"\0")
    return h.hexdigest()[:20]


def _sha256(path: Path) -> str:
    with open(path, "rb") as f:
        return hashlib.file_digest(f, "sha256").hexdigest()


def _entry(kind: str, payload: bytes, stem: str) -> Path:
    return cache_root() / f"{stem}-{key(kind, payload)}"


def check(entry: Path) -> tuple[str, object]:
    """The state of a cache entry: ("ok", its build record), ("missing", None), ("damaged",
    what is wrong) or ("changed", the user's module that has changed since the build)."""
    try:
        sums_text = (entry / SUMS).read_text()
    except (FileNotFoundError, NotADirectoryError):
        if not entry.is_dir():
            return "missing", None
        return "damaged", f"{SUMS} is missing"
    except OSError as exc:
        return "damaged", f"{SUMS} does not read: {exc.strerror}"
    except UnicodeDecodeError:
        return "damaged", f"{SUMS} is garbled"
    sums = {}
    for line in sums_text.splitlines():
        digest, sep, name = line.partition("  ")
        if not sep or len(digest) != 64:
            return "damaged", f"{SUMS} is garbled"
        sums[name] = digest
    if RECORD not in sums:
        return "damaged", f"{SUMS} has no line for {RECORD}"
    try:
        raw = (entry / RECORD).read_bytes()
    except FileNotFoundError:
        return "damaged", f"{RECORD} is missing"
    except OSError as exc:
        return "damaged", f"{RECORD} does not read: {exc.strerror}"
    if hashlib.sha256(raw).hexdigest() != sums[RECORD]:
        return "damaged", f"{RECORD} does not match its checksum"
    try:
        info = json.loads(raw)
        extension, sources = info["extension"], info["sources"]
        sound = isinstance(info["name"], str) and isinstance(sources, dict) and \
            isinstance(extension, str) and extension == Path(extension).name and extension in sums
    except (ValueError, KeyError, TypeError):
        sound = False
    if not sound:
        return "damaged", f"{RECORD} is not a build record of this camdyn"
    try:
        if _sha256(entry / extension) != sums[extension]:
            return "damaged", f"{extension} does not match its checksum"
    except OSError as exc:
        return "damaged", f"{extension} does not read: {exc.strerror}"
    for path, digest in sources.items():
        try:
            if _sha256(Path(path)) == digest:
                continue
        except OSError:
            pass
        return "changed", path
    return "ok", info


def _seal(folder: Path) -> dict:
    """Write SHA256SUMS over a finished build's record and compiled module; the record."""
    info = json.loads((folder / RECORD).read_text())
    (folder / SUMS).write_text("".join(f"{_sha256(folder / name)}  {name}\n"
                                       for name in (RECORD, info["extension"])))
    return info


def _replace(tmp: Path, entry: Path) -> None:
    """Put the finished build ``tmp`` in place of ``entry`` (a damaged or outdated one is moved
    aside first: a folder can replace an empty folder only)."""
    if entry.is_dir() and not entry.is_symlink():
        aside = Path(tempfile.mkdtemp(prefix=f".{entry.name}.", dir=entry.parent))
        os.replace(entry, aside)
        shutil.rmtree(aside, ignore_errors=True)
    elif entry.exists() or entry.is_symlink():
        entry.unlink()
    os.rename(tmp, entry)


def _lock(root: Path, entry_name: str):
    # imported here: it takes longer to import than a cached load takes (tens of ms)
    from filelock import FileLock

    return FileLock(root / f"{entry_name}.lock")


def sweep_temporaries(root: Path, entry: Path) -> None:
    """Remove the temporary folders killed builds left in the cache: ``entry``'s own (its lock
    is held, so nobody is writing them), and any other older than STALE_SECONDS whose entry
    nobody is building."""
    from filelock import Timeout

    now = time.time()
    for tmp in root.glob(".*.*"):
        owner = tmp.name[1:].rpartition(".")[0]
        if not tmp.is_dir() or not owner:
            continue
        if owner == entry.name:
            shutil.rmtree(tmp, ignore_errors=True)
            continue
        try:
            if now - tmp.stat().st_mtime < STALE_SECONDS:
                continue
        except OSError:
            continue
        lock = _lock(root, owner)
        try:
            lock.acquire(timeout=0)
        except Timeout:    # being built: its temporary folder is in use
            continue
        try:
            shutil.rmtree(tmp, ignore_errors=True)
        finally:
            lock.release()


BUILD_LIMIT = 1200.0
"""Seconds a build may take before it is stopped (a run failure, saying so): every DYNACAM
variant and every model file of the tests builds in well under it (the slowest, a rocker
held on both sides, in about a minute); a derivation that would run for hours (SymPy's
simplify on a long expression, which a rocker's took once) ends in bounded time."""

HEARTBEAT = 15.0
"""Seconds of silence from the builder after which the user hears how long it has run."""

EXPECTED = {"--dynacam": "a DYNACAM variant takes 20 s to 2 minutes on one core"}
"""What a build takes, said when it starts, by the builder's first argument."""


def _build(args: list, label: str, entry: Path, say, why: str) -> dict:
    """Run the builder into a temporary folder beside ``entry``, seal it and rename it into
    place; the build record.  Its stages are passed on as they end, and a line every
    HEARTBEAT seconds of silence says it is still at work; beyond BUILD_LIMIT it is stopped."""
    import threading

    tmp = Path(tempfile.mkdtemp(prefix=f".{entry.name}.", dir=entry.parent))
    expected = EXPECTED.get(args[0], "a model file takes seconds to a minute")
    say(f"{label}: {why} (into {entry}; {expected}, once)")
    t0 = time.perf_counter()
    quiet = threading.Event()
    last = [t0]

    def heartbeat(proc):
        while not quiet.wait(HEARTBEAT / 3):
            now = time.perf_counter()
            if now - t0 > BUILD_LIMIT:
                proc.kill()
                return
            if now - last[0] >= HEARTBEAT:
                last[0] = now
                say(f"{label}: still building, {now - t0:.0f} s so far")

    try:
        proc = subprocess.Popen([sys.executable, "-m", "camdyn.derive.build", *args, "--out",
                                 str(tmp)], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                text=True)
        watcher = threading.Thread(target=heartbeat, args=(proc,), daemon=True)
        watcher.start()
        errors = []
        try:
            for line in proc.stderr:
                line = line.rstrip()
                last[0] = time.perf_counter()
                if line.startswith("error: "):
                    errors.append(line[len("error: "):])
                elif line:
                    say(line)
            status = proc.wait()
        finally:
            quiet.set()
            watcher.join()
        if time.perf_counter() - t0 > BUILD_LIMIT and status != 0:
            raise SimulationError(f"{label}: the build ran for more than {BUILD_LIMIT:.0f} s "
                                  "and was stopped; nothing was cached")
        if status != 0:
            raise CamdynInputError(errors[-1] if errors else f"{label}: the build failed "
                                                             f"(exit status {proc.returncode})")
        info = _seal(tmp)
        _replace(tmp, entry)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)
    say(f"{label}: built in {time.perf_counter() - t0:.1f} s; later runs load it from the cache")
    return info


_OPENED: set = set()
"""Compiled modules this process has asked the dynamic loader for, by path.  The loader keeps
the first library it opened at a path for the process's life: one that opened but did not
load (a foreign module put in an entry's place) would come back in place of its rebuilt
successor, so a path asked for again is loaded from a fresh copy of its file."""


def _load(entry: Path, info: dict) -> CompiledModel:
    name, path = info["name"], entry / info["extension"]
    fresh = None
    if path in _OPENED:
        fresh = Path(tempfile.mkdtemp(prefix=f"camdyn-{name}-"))
        shutil.copy2(path, fresh / path.name)
    _OPENED.add(path)
    where = path if fresh is None else fresh / path.name
    try:
        loader = importlib.machinery.ExtensionFileLoader(name, str(where))
        spec = importlib.util.spec_from_file_location(name, where, loader=loader)
        module = importlib.util.module_from_spec(spec)
        loader.exec_module(module)
    finally:
        if fresh is not None:       # the loaded library stays mapped without its file
            shutil.rmtree(fresh, ignore_errors=True)
    return CompiledModel(name, module)


def _locked(lock, label: str, say):
    """``lock`` acquired, waiting for another process's build with a word to the user."""
    from filelock import Timeout

    try:
        lock.acquire(timeout=0)
    except Timeout:
        say(f"{label}: another camdyn process is building it; waiting for it")
        lock.acquire()
    return lock


_LOADED: dict = {}   # cache entry -> its CompiledModel, loaded once per process


def _cached(entry: Path, args: tuple, label: str, progress) -> CompiledModel:
    if entry not in _LOADED:
        _LOADED[entry] = _get(entry, list(args), label, progress)
    return _LOADED[entry]


def _get(entry: Path, args: list, label: str, progress) -> CompiledModel:
    state, detail = check(entry)
    if state == "ok":     # the common case: no lock, nothing written
        try:
            return _load(entry, detail)
        except (ImportError, OSError):      # replaced since the check: see below
            pass
    # a build takes seconds: without a progress callback the user still hears why on stderr
    say = progress or (lambda msg: print(msg, file=sys.stderr, flush=True))
    root = writable_folder(entry.parent, "cache folder",
                           f"; set {ENV_CACHE} to a folder camdyn may write in")
    lock = _locked(_lock(root, entry.name), label, say)
    try:
        state, detail = check(entry)     # another process may have built it meanwhile
        if state == "ok":
            try:
                return _load(entry, detail)
            except (ImportError, OSError) as exc:
                state, detail = "damaged", f"the compiled module does not load: {exc}"
        if state == "damaged":
            print(f"camdyn: cache entry for {label} was damaged ({detail}); rebuilding",
                  file=sys.stderr, flush=True)
        why = {"missing": "not in the cache; deriving, generating and compiling it once",
               "damaged": "deriving, generating and compiling it again",
               "changed": f"{detail} has changed since it was built; deriving, generating "
                          "and compiling it again"}[state]
        sweep_temporaries(root, entry)
        info = _build(args, label, entry, say, why)
    finally:
        lock.release()
    try:
        return _load(entry, info)
    except (ImportError, OSError) as exc:
        raise SimulationError(f"{label}: the compiled module just built in {entry} does not "
                              f"load: {exc}") from None


def model_file(path, progress=None) -> CompiledModel:
    """The compiled model of a user's model file (built on first use).  Its path is part of
    the key, not its bytes alone: the same file in two folders may import two different
    helper modules."""
    path = Path(path).resolve()
    if on_disk(path) != "file":
        raise CamdynInputError(f"{path}: no such model file")
    try:
        text = path.read_bytes()
    except OSError as exc:
        raise CamdynInputError(f"{path}: cannot read the model file: {exc.strerror}") from None
    return _cached(_entry("file", str(path).encode() + b"\0" + text, path.stem),
                   ("--file", str(path)), f"model file {path.name}", progress)


def _variant_entry(options: dict, name: str) -> tuple[str, Path]:
    text = json.dumps(options, sort_keys=True)
    return text, _entry("dynacam", text.encode(), name)


def dynacam_variant(options: dict, name: str, progress=None) -> CompiledModel:
    """The compiled DYNACAM variant of an option set outside generated/ (built on first use)."""
    text, entry = _variant_entry(options, name)
    return _cached(entry, ("--dynacam", text), f"DYNACAM variant {name}", progress)


def has_variant(options: dict, name: str) -> bool:
    """Whether the cache holds a sound entry for the DYNACAM variant of an option set."""
    return check(_variant_entry(options, name)[1])[0] == "ok"
