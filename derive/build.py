"""Build one model on demand: declaration -> Lagrange's equations -> Cython -> compiled module.

The runtime starts this as a program of its own when a scene or `camdyn integrate` asks for a
model that is not among the pre-generated ones (:mod:`camdyn.runtime.core.ondemand`), so the
process that simulates never loads SymPy, and a failed build cannot leave a half-imported
model behind:

    python -m camdyn.derive.build --out DIR (--file MODEL.py | --dynacam OPTIONS_JSON
                                             | --registered NAME)

``MODEL.py`` defines ``build()`` returning a :class:`~camdyn.derive.model.Model`, exactly as
the built-in declarations in ``derive/models/`` do.  DIR receives ``<name>.pyx``, the
compiled ``<name>`` extension and ``build.json`` (name, source, the time of each stage, the
user's modules the build imported with their sha256: :func:`user_sources`).
Progress goes to stderr, one line per stage with its time.  A declaration that does not
import, has no ``build()`` or is refused by the derivation ends with one line naming the file
and the problem, exit status 2.
"""
from __future__ import annotations

import argparse
import importlib.util
import json
import os
import shutil
import sys
import sysconfig
import tempfile
import time
from pathlib import Path

from .flags import COMPILE_ARGS


class BuildError(Exception):
    """A declaration that cannot be built; the message names the source and the problem."""


def _package_dir(name: str) -> Path:
    """Folder of an installed camdyn package, found without importing it (the headers of the
    runtime are build inputs here, not code this module runs)."""
    spec = importlib.util.find_spec(name)
    return Path(next(iter(spec.submodule_search_locations)))


def declaration_from_file(path: Path):
    """The Model that ``build()`` of a user's model file returns."""
    from .model import Model

    where = str(path)
    if not path.is_file():
        raise BuildError(f"{where}: no such model file")
    # the model's folder first, as `python MODEL.py` has it: a helper module beside the model
    # imports from any working folder
    sys.path.insert(0, str(path.resolve().parent))
    spec = importlib.util.spec_from_file_location(f"camdyn_user_model_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except Exception as exc:      # the user's file: any error is reported, in one line
        raise BuildError(f"{where}: cannot import it: {type(exc).__name__}: {exc}") from None
    build = getattr(module, "build", None)
    if not callable(build):
        raise BuildError(f"{where}: defines no build() returning a camdyn.derive.model.Model")
    try:
        model = build()
    except Exception as exc:
        raise BuildError(f"{where}: build() failed: {type(exc).__name__}: {exc}") from None
    if not isinstance(model, Model):
        raise BuildError(f"{where}: build() returned {type(model).__name__}, not a "
                         "camdyn.derive.model.Model")
    return model


def user_sources() -> dict:
    """{path: sha256} of every module this process imported from outside the Python
    installation and camdyn: the user's own modules that a model file imports, however it
    imports them (beside it, below it, on PYTHONPATH, conditionally or by importlib).

    Executing the file is the only sure way to know what it imports, and the build does that
    anyway, in a process of its own; so the build records exactly the modules it used, and the
    runtime rebuilds the entry when one of them has changed (runtime/core/ondemand.py).  A
    hash of every .py file in the model's folder would instead miss modules found on
    PYTHONPATH, rebuild on edits to files the model never imports, and read a whole tree on
    every load of a model kept in a large folder (a home folder, a project with a virtual
    environment).  Installed packages are left out: their versions are not the user's
    code, and SymPy's and Cython's are in the cache key already."""
    import hashlib
    import site

    installed = {Path(p).resolve() for p in (
        sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix,
        *site.getsitepackages(), site.getusersitepackages(),
        *(sysconfig.get_paths()[k] for k in ("stdlib", "platstdlib", "purelib", "platlib")))}
    # the program itself, under __main__ and multiprocessing's __mp_main__
    main = getattr(sys.modules.get("__main__"), "__file__", None)
    if main:
        installed.add(Path(main).resolve())
    out = {}
    for name, module in list(sys.modules.items()):
        file = getattr(module, "__file__", None)
        if name == "camdyn" or name.startswith("camdyn.") or not file:
            continue
        path = Path(file).resolve()
        if not path.is_file() or any(path.is_relative_to(root) for root in installed):
            continue
        out[str(path)] = hashlib.sha256(path.read_bytes()).hexdigest()
    return dict(sorted(out.items()))


def declaration(args):
    if args.file:
        return declaration_from_file(Path(args.file)), args.file
    if args.dynacam:
        from .models.dynacam import Options, build

        try:
            options = Options(**json.loads(args.dynacam))
        except (TypeError, ValueError) as exc:
            raise BuildError(f"DYNACAM options {args.dynacam}: {exc}") from None
        return build(options), f"DYNACAM {options.name}"
    from .models import REGISTRY

    if args.registered not in REGISTRY:
        raise BuildError(f"no registered model {args.registered!r}")
    return REGISTRY[args.registered](), f"registered model {args.registered}"


def _provenance(args) -> str:
    """The file the declaration comes from, for the generated file's provenance line."""
    if args.file:
        return str(args.file)
    if args.dynacam:
        return "camdyn/derive/models/dynacam.py"
    from .models import REGISTRY
    from .render import source_of

    return source_of(REGISTRY[args.registered])


def _stage_headers(include: Path) -> None:
    """camdyn/runtime/engine/*.pxd, *.pxi and camdyn/generated/camlaws.pxd under ``include``,
    the paths the generated code cimports and includes."""
    for pkg, patterns in (("runtime.engine", ("*.pxd", "*.pxi")), ("generated", ("camlaws.pxd",))):
        src, dst = _package_dir(f"camdyn.{pkg}"), include / "camdyn" / pkg.replace(".", "/")
        dst.mkdir(parents=True, exist_ok=True)
        for level in (dst, *dst.parents):
            if level == include / "camdyn":
                break
            (level / "__init__.pxd").write_text("")
        for pattern in patterns:
            for header in src.glob(pattern):
                shutil.copyfile(header, dst / header.name)
    (include / "camdyn" / "__init__.pxd").write_text("")


def compile_module(name: str, pyx: str, out: Path) -> Path:
    """Compile the Cython source of module ``name`` into ``out``; the extension's path."""
    from Cython.Build import cythonize
    from setuptools import Distribution, Extension

    # the work folder inside ``out``: a killed build leaves it where the next one removes it
    with tempfile.TemporaryDirectory(prefix=".work-", dir=out) as tmp:
        work = Path(tmp)
        _stage_headers(work / "include")
        src = work / f"{name}.pyx"
        src.write_text(pyx)
        ext = Extension(name, [str(src)], extra_compile_args=COMPILE_ARGS)
        dist = Distribution({"ext_modules": cythonize(
            [ext], include_path=[str(work / "include")], quiet=True,
            compiler_directives={"language_level": 3}, build_dir=str(work / "c"))})
        cmd = dist.get_command_obj("build_ext")
        cmd.build_lib, cmd.build_temp = str(work / "lib"), str(work / "tmp")
        cmd.ensure_finalized()
        cmd.run()
        built = work / "lib" / f"{name}{sysconfig.get_config_var('EXT_SUFFIX')}"
        target = out / built.name
        shutil.copyfile(built, target)
    return target


class _output_to:
    """Send this process's stdout and stderr (the C compiler's too) to a file for a while:
    the compiler's warnings are not progress, but they are kept for a failed build."""

    def __init__(self, path: Path):
        self.path = path

    def __enter__(self):
        sys.stdout.flush(), sys.stderr.flush()
        self.file = open(self.path, "w")
        self.saved = [os.dup(1), os.dup(2)]
        os.dup2(self.file.fileno(), 1), os.dup2(self.file.fileno(), 2)

    def __exit__(self, *exc):
        sys.stdout.flush(), sys.stderr.flush()
        for fd, saved in zip((1, 2), self.saved):
            os.dup2(saved, fd)
            os.close(saved)
        self.file.close()
        return False


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m camdyn.derive.build",
                                 description=__doc__.splitlines()[0])
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--file", help="a model file defining build()")
    src.add_argument("--dynacam", metavar="OPTIONS_JSON", help="a DYNACAM option set")
    src.add_argument("--registered", metavar="NAME", help="a model of the registry")
    ap.add_argument("--out", required=True, help="folder to write into (created)")
    args = ap.parse_args(argv)
    out = Path(args.out)
    times = {}

    def stage(label, t0):
        times[label] = time.perf_counter() - t0
        print(f"  {label}: {times[label]:.1f} s", file=sys.stderr, flush=True)

    try:
        t0 = time.perf_counter()
        model, source = declaration(args)
        stage("declaration", t0)
        t0 = time.perf_counter()
        from .render import render_model

        try:
            pyx = render_model(model, _provenance(args))
        except Exception as exc:    # the derivation's refusal, in one line
            raise BuildError(f"{source}: the derivation refused the model: "
                             f"{type(exc).__name__}: {exc}") from None
        stage("derivation and code generation", t0)
        out.mkdir(parents=True, exist_ok=True)
        (out / f"{model.name}.pyx").write_text(pyx)
        t0 = time.perf_counter()
        log = out / "compile.log"
        try:
            with _output_to(log):
                ext = compile_module(model.name, pyx, out)
        except Exception as exc:
            raise BuildError(f"{source}: compiling the generated code failed: "
                             f"{type(exc).__name__}: {exc} (compiler output: {log})") from None
        stage("compilation", t0)
    except BuildError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    (out / "build.json").write_text(json.dumps(
        {"name": model.name, "source": source, "extension": ext.name, "seconds": times,
         "pid": os.getpid(), "sources": user_sources()}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
