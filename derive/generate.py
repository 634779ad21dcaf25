"""Write and check ``generated/``: the `camdyn derive [--check] [--full]` command.

Every generated file carries two lines under its "GENERATED FILE" notice:

    # Derivation key: sha256:...   hash of everything the file is derived from
    # Text hash: sha256:...        hash of the file itself, without this line

The derivation key hashes the inputs of the file: the model's declaration as built (every
field of the :class:`~camdyn.derive.model.Model`, expressions as ``srepr``; for the cam-law
library the source of ``camlaws.py``), the source of the derive code that turns it into text
(``render.py``, ``emit.py``, ``lagrange.py``, ``printer.py``, ``optimize.py``, ``model.py``, and
``codegen.py`` or, for constrained models, ``dae.py``; ``camlaws_code.py`` for the library) and
the templates, the pinned SymPy version and the camdyn version.  A file whose recorded key equals the key of the current inputs and
whose text still hashes to its recorded text hash was written by ``camdyn derive`` from these
very inputs, so it is not derived again; every other file is (a model edit re-derives that
model only).  The files derived are compared byte for byte with the files on disk
(SymForce's regenerate-and-diff), so a model edit without regeneration, a hand edit of a
generated file, a file from an older camdyn without the two lines, a missing or a stray
file all fail the check.  ``full=True`` (``--full``) ignores the recorded keys and derives
everything: what the check was before the keys, for when an input the key does not see is
suspected.

Derivation runs in parallel processes, longest first (estimated by the size of the file on
disk), since one file depends on one model only.
"""
from __future__ import annotations

import dataclasses
import difflib
import hashlib
import json
import os
import re
from functools import cache
from pathlib import Path

KEEP = {"__init__.py"}
CAMLAWS = "camlaws"
"""The unit name of the cam-law library (its files: camlaws.pxd, camlaws.pyx)."""
CATALOG = "catalog"
"""The unit name of catalog.json, the declarations the runtime reads as data: JSON carries no
stamp, and rendering it derives nothing, so it is rendered and compared every time."""

STAMP_FORMAT = 1
"""Version of the two stamp lines; part of every key, so changing their meaning re-derives."""

DERIVE = Path(__file__).parent
# the derive code each kind of file is printed by; generate.py itself only stamps and compares
_CODE = {
    "model": ("codegen.py", "emit.py", "lagrange.py", "model.py", "optimize.py", "printer.py",
              "render.py"),
    "constrained": ("dae.py", "emit.py", "lagrange.py", "model.py", "optimize.py", "printer.py",
                    "render.py"),
    CAMLAWS: ("camlaws.py", "camlaws_code.py", "emit.py", "printer.py"),
}
_KEY_LINE = re.compile(r"^# Derivation key: (sha256:[0-9a-f]{64})\n", re.M)
_HASH_LINE = re.compile(r"^# Text hash: (sha256:[0-9a-f]{64})\n", re.M)
_NOTICE = "# GENERATED FILE - DO NOT EDIT."


def project_root(start: Path | None = None) -> Path:
    """The camdyn checkout containing ``start`` (default: the working directory)."""
    here = (start or Path.cwd()).resolve()
    for d in (here, *here.parents):
        toml = d / "pyproject.toml"
        if toml.is_file() and 'name = "camdyn"' in toml.read_text() and (d / "generated").is_dir():
            return d
    raise FileNotFoundError(
        "not inside a camdyn checkout (no pyproject.toml of camdyn with a generated/ folder "
        "here or above); give --out DIR")


# -- derivation keys ----------------------------------------------------------------


def _canonical(obj):
    """A JSON-able image of a declaration: dataclasses field by field, SymPy objects as srepr.

    srepr prints arguments in SymPy's canonical order, which does not depend on the hash
    seed (the generated files' source hashes rely on the same)."""
    import sympy as sp

    if isinstance(obj, sp.Basic):
        return ["sympy", sp.srepr(obj)]
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return [type(obj).__qualname__,
                [[f.name, _canonical(getattr(obj, f.name))] for f in dataclasses.fields(obj)]]
    if isinstance(obj, (list, tuple)):
        return [_canonical(x) for x in obj]
    if isinstance(obj, dict):
        return ["dict", sorted([_canonical(k), _canonical(v)] for k, v in obj.items())]
    if isinstance(obj, float):
        return ["float", repr(obj)]
    if obj is None or isinstance(obj, (bool, int, str)):
        return obj
    # a new kind of declaration field must be added here, not silently left out of the key
    raise TypeError(f"cannot key a declaration field of type {type(obj).__name__}")


def declaration_digest(model) -> str:
    """SHA-256 of everything a :class:`~camdyn.derive.model.Model` declares."""
    return hashlib.sha256(json.dumps(_canonical(model)).encode()).hexdigest()


def _camdyn_version() -> str:
    from importlib import metadata

    try:
        return metadata.version("camdyn")
    except metadata.PackageNotFoundError:
        # a checkout used without installing it: the version it declares
        toml = DERIVE.parent / "pyproject.toml"
        found = re.search(r'^version = "([^"]+)"', toml.read_text(), re.M) if toml.is_file() else None
        if not found:
            raise RuntimeError("camdyn is not installed and its pyproject.toml gives no version; "
                               "install it (pip install -e .)") from None
        return found.group(1)


@cache
def _code_digest(kind: str) -> dict:
    """Hashes of the derive code and the templates that print a file of ``kind``, and the
    versions the text depends on."""
    import sympy as sp

    # the cam-law library's own templates print no model (a model only cimports the
    # library), so a new law or a change of the library re-derives the library alone
    own = (lambda p: p.name.startswith("camlaws.")) if kind == CAMLAWS else \
        (lambda p: not p.name.startswith("camlaws."))
    files = [DERIVE / name for name in _CODE[kind]] + sorted(
        p for p in (DERIVE / "templates").glob("*.j2") if own(p) or p.name == "preamble.j2")
    return {"format": STAMP_FORMAT, "kind": kind, "sympy": sp.__version__,
            "camdyn": _camdyn_version(),
            "code": {str(p.relative_to(DERIVE)): hashlib.sha256(p.read_bytes()).hexdigest()
                     for p in files}}


def model_key(model, source: str) -> str:
    """Derivation key of the generated module of ``model`` declared in ``source``."""
    kind = "constrained" if model.constraints else "model"
    inputs = {**_code_digest(kind), "declaration": declaration_digest(model), "source": source}
    return "sha256:" + hashlib.sha256(json.dumps(inputs, sort_keys=True).encode()).hexdigest()


def camlaws_key() -> str:
    """Derivation key of the cam-law library (camlaws.py is among its code)."""
    return "sha256:" + hashlib.sha256(json.dumps(_code_digest(CAMLAWS), sort_keys=True)
                                      .encode()).hexdigest()


# -- stamps ---------------------------------------------------------------------------


def _text_hash(text_without_hash_line: str) -> str:
    return "sha256:" + hashlib.sha256(text_without_hash_line.encode()).hexdigest()


def stamp(text: str, key: str) -> str:
    """``text`` with the derivation key and the text hash under its "GENERATED FILE" notice."""
    lines = text.splitlines(keepends=True)
    at = next((i for i, line in enumerate(lines[:10]) if line.startswith(_NOTICE)), None)
    if at is None:
        raise ValueError("generated text without the GENERATED FILE notice in its first lines")
    # after the notice and its continuation line
    keyed = "".join(lines[:at + 2] + [f"# Derivation key: {key}\n"] + lines[at + 2:])
    pos = keyed.index("# Derivation key: ")
    end = keyed.index("\n", pos) + 1
    return keyed[:end] + f"# Text hash: {_text_hash(keyed)}\n" + keyed[end:]


def read_stamp(text: str) -> tuple[str | None, bool]:
    """(recorded derivation key, whether the text still hashes to its recorded text hash).

    (None, False) for a text without the two lines (hand-written, or from an older camdyn)."""
    head = text[:4000]
    key, recorded = _KEY_LINE.search(head), _HASH_LINE.search(head)
    if not key or not recorded:
        return None, False
    rest = text[:recorded.start()] + text[recorded.end():]
    return key.group(1), _text_hash(rest) == recorded.group(1)


# -- rendering, in worker processes ---------------------------------------------------


def files_of(unit: str) -> list[str]:
    """File names a unit (a registered model, the cam-law library, the catalog) generates."""
    return {CAMLAWS: ["camlaws.pxd", "camlaws.pyx"], CATALOG: ["catalog.json"]}.get(
        unit, [f"{unit}.pyx"])


def _unit_job(unit: str, recorded: dict, full: bool):
    """(key, {file: stamped text} or None): derive the unit unless every file of it records
    the current key and is intact (``recorded``: file -> (key, intact))."""
    from .render import render_camlaws, render_catalog, render_model, source_of

    if unit == CATALOG:
        return None, render_catalog()
    if unit == CAMLAWS:
        key = camlaws_key()
    else:
        from .models import REGISTRY

        model = REGISTRY[unit]()
        if model.name != unit:
            raise ValueError(f"registry key {unit!r} differs from model name {model.name!r}")
        source = source_of(REGISTRY[unit])
        key = model_key(model, source)
    if not full and all(recorded.get(f) == (key, True) for f in files_of(unit)):
        return key, None
    texts = render_camlaws() if unit == CAMLAWS else {f"{unit}.pyx": render_model(model, source)}
    return key, {name: stamp(text, key) for name, text in texts.items()}


def render_unit(unit: str) -> dict[str, str]:
    """File name -> stamped text of one unit (a registered model, the cam-law library, the
    catalog), derived now."""
    return _unit_job(unit, {}, True)[1]


def _run_jobs(units: list[str], recorded: dict, full: bool, cost: dict, workers: int | None):
    """{unit: (key, texts or None)}, derived in parallel, the costliest first."""
    from concurrent.futures import ProcessPoolExecutor

    order = sorted(units, key=lambda u: (-cost.get(u, float("inf")), u))
    workers = workers or min(len(order), os.cpu_count() or 1)
    if workers <= 1:
        return {u: _unit_job(u, recorded, full) for u in order}
    with ProcessPoolExecutor(max_workers=workers) as pool:
        futures = {u: pool.submit(_unit_job, u, recorded, full) for u in order}
        return {u: f.result() for u, f in futures.items()}


def _units(only) -> list[str]:
    """The cam-law library and the models ``only`` (all registered models when None)."""
    from .models import REGISTRY

    names = sorted(REGISTRY) if only is None else sorted(set(only))
    unknown = sorted(set(names) - set(REGISTRY))
    if unknown:
        raise KeyError(f"no model {unknown[0]!r} in the registry; known: {', '.join(sorted(REGISTRY))}")
    return [CAMLAWS, CATALOG] + names


def _generated_files(out: Path) -> set[str]:
    return {p.name for p in out.iterdir() if p.is_file() and p.suffix in (".pyx", ".pxd", ".json")}


def _on_disk(out: Path, units: list[str]) -> tuple[dict, dict, dict]:
    """(file -> text, file -> (recorded key, intact), unit -> cost estimate) of what exists."""
    texts, recorded, cost = {}, {}, {}
    for unit in units:
        for name in files_of(unit):
            path = out / name
            if path.is_file():
                texts[name] = path.read_text()
                recorded[name] = read_stamp(texts[name])
                # the larger the file, the longer its derivation took: start those first
                cost[unit] = cost.get(unit, 0) + len(texts[name])
    return texts, recorded, cost


# -- the command ----------------------------------------------------------------------


def write(out: Path, only=None, full: bool = False, workers: int | None = None) -> list[str]:
    """Regenerate into ``out`` (all models, or those named in ``only``): every file that is
    missing, edited, or derived from other inputs than the current ones (every file with
    ``full``).  Returns the names of files that changed.  Stray files are removed only on a
    run over the whole registry."""
    units = _units(only)
    out.mkdir(parents=True, exist_ok=True)
    old, recorded, cost = _on_disk(out, units)
    results = _run_jobs(units, recorded, full, cost, workers)
    changed = []
    for _, texts in results.values():
        for name, text in sorted((texts or {}).items()):
            if old.get(name) != text:
                (out / name).write_text(text)
                changed.append(name)
    if only is None:
        expected = {name for unit in units for name in files_of(unit)}
        for stale in sorted(_generated_files(out) - expected - KEEP):
            (out / stale).unlink()
            changed.append(stale + " (removed)")
    return sorted(changed)


def _why(name: str, recorded: dict, key: str | None) -> str:
    if key is None:
        return "differs from what the declarations give now"
    rec_key, intact = recorded[name]
    if rec_key is None:
        return "no derivation key (written by hand or by an older camdyn)"
    if not intact:
        return "edited after generation (its text hash differs)"
    if rec_key != key:
        return "derived from other inputs than the current ones (derivation key differs)"
    return "differs from a fresh derivation of the same inputs"


def check(out: Path, only=None, full: bool = False, workers: int | None = None) -> list[str]:
    """Problems of ``out`` as lines: missing, stale (with a unified diff) and stray files.

    Missing files are reported without deriving anything.  Files that record the current
    derivation key and are intact are trusted; the others (all with ``full``) are derived
    and compared byte for byte."""
    units = _units(only)
    expected = {name for unit in units for name in files_of(unit)}
    present = _generated_files(out) if out.is_dir() else set()
    problems = [f"missing: {name}" for name in sorted(expected - present)]
    if problems:
        return problems
    old, recorded, cost = _on_disk(out, units)
    results = _run_jobs(units, recorded, full, cost, workers)
    for unit in units:
        key, texts = results[unit]
        for name, text in sorted((texts or {}).items()):
            if old[name] != text:
                diff = difflib.unified_diff(old[name].splitlines(), text.splitlines(),
                                            f"generated/{name}", f"fresh/{name}", lineterm="", n=1)
                problems.append(f"stale: {name}: {_why(name, recorded, key)}")
                problems.extend("    " + line for line in list(diff)[:40])
    if only is None:
        for extra in sorted(present - expected - KEEP):
            problems.append(f"not generated by any model: {extra}")
    return problems
