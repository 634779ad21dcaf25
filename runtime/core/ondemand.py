"""Models on demand: a model that is not pre-generated is derived, generated and compiled on
first use into a per-user cache, and loaded from there at once on every later use.

What asks for one: a DYNACAM scene whose options select a variant outside ``generated/``,
and a user's own model file (`camdyn integrate MODEL.py`).  The build runs
:mod:`camdyn.derive.build` as a program of its own, so this process never loads SymPy; its
progress lines (each stage with its time) are passed on.

The cache lives in platformdirs' user cache folder (``CAMDYN_CACHE_DIR`` overrides it); an
entry is keyed by a hash of what decides the compiled code: the model's source (the file's
bytes, or the option set), the derivation code (every file of ``camdyn.derive``), the
runtime's Cython headers (the ABI, runtime/engine/abi.pxd) and the camdyn, SymPy and Cython
versions.  A build is written into a temporary folder and renamed into place when
complete, so a second process building the same model at the same time cannot corrupt the
entry (the later rename loses and its folder is removed), and a failed build leaves nothing
behind.
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

from .errors import CamdynInputError
from .compiled import CompiledModel

ENV_CACHE = "CAMDYN_CACHE_DIR"


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
    """Hash of the runtime's Cython headers (abi.pxd with CAMDYN_ABI, linalg.pxd, loops.pxi),
    compiled into every model: a cached build from another ABI is never loaded."""
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


def _build(args: list, label: str, entry: Path, progress) -> None:
    """Run the builder into a temporary folder beside ``entry`` and rename it into place."""
    entry.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{entry.name}.", dir=entry.parent))
    # a build takes seconds: without a progress callback the user still hears why on stderr
    say = progress or (lambda msg: print(msg, file=sys.stderr, flush=True))
    say(f"{label}: not in the cache; deriving, generating and compiling it once "
        f"(into {entry})")
    t0 = time.perf_counter()
    try:
        proc = subprocess.Popen([sys.executable, "-m", "camdyn.derive.build", *args, "--out",
                                 str(tmp)], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                text=True)
        errors = []
        for line in proc.stderr:
            line = line.rstrip()
            if line.startswith("error: "):
                errors.append(line[len("error: "):])
            elif line:
                say(line)
        if proc.wait() != 0:
            raise CamdynInputError(errors[-1] if errors else f"{label}: the build failed "
                                                             f"(exit status {proc.returncode})")
        try:
            os.rename(tmp, entry)
        except OSError:
            if not (entry / "build.json").is_file():    # not another process's finished build
                raise
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)
    say(f"{label}: built in {time.perf_counter() - t0:.1f} s; later runs load it from the cache")


def _load(entry: Path) -> CompiledModel:
    info = json.loads((entry / "build.json").read_text())
    name, path = info["name"], entry / info["extension"]
    loader = importlib.machinery.ExtensionFileLoader(name, str(path))
    spec = importlib.util.spec_from_file_location(name, path, loader=loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return CompiledModel(name, module)


_LOADED: dict = {}   # cache entry -> its CompiledModel, loaded once per process


def _cached(kind: str, payload: bytes, stem: str, args: tuple, label: str, progress) -> CompiledModel:
    entry = cache_root() / f"{stem}-{key(kind, payload)}"
    if entry not in _LOADED:
        if not (entry / "build.json").is_file():
            _build(list(args), label, entry, progress)
        _LOADED[entry] = _load(entry)
    return _LOADED[entry]


def model_file(path, progress=None) -> CompiledModel:
    """The compiled model of a user's model file (built on first use)."""
    path = Path(path).resolve()
    if not path.is_file():
        raise CamdynInputError(f"{path}: no such model file")
    return _cached("file", path.read_bytes(), path.stem, ("--file", str(path)),
                   f"model file {path.name}", progress)


def dynacam_variant(options: dict, name: str, progress=None) -> CompiledModel:
    """The compiled DYNACAM variant of an option set outside generated/ (built on first use)."""
    text = json.dumps(options, sort_keys=True)
    return _cached("dynacam", text.encode(), name, ("--dynacam", text), f"DYNACAM variant {name}",
                   progress)
