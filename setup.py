"""What of the build must be code: the compiled extensions, the Cython headers they cimport, the
subpackages.  Everything that can be declared (metadata, dependencies, extras, which folder is
which package, package data) is in pyproject.toml.

The subpackages are discovered, not listed by hand: every folder below a package folder of
pyproject.toml's [tool.setuptools.package-dir] (camdyn.derive = derive/, ...) is a package
camdyn.<room>.<sub>..., so a new subpackage cannot be left out of the wheel (one was:
camdyn.thesis.checks, while only the editable install was tested).

Cython finds cimported .pxd and included .pxi files by package path
(camdyn/runtime/engine/abi.pxd, camdyn/runtime/engine/loops.pxi), but the repository keeps the
sources in top-level folders (runtime/, generated/).  So the headers are copied into
build/cython_include/camdyn/ first and that tree is put on Cython's include path.
"""
import functools
import hashlib
import os
import runpy
import shutil
import subprocess
import sys
import sysconfig
import tomllib
from pathlib import Path

from Cython.Build import cythonize
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).parent.resolve()
INCLUDE = ROOT / "build" / "cython_include"
EXT_CACHE = ROOT / "build" / "ext-cache"
PACKAGE_DIR = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-dir"]
COMPILED = ("camdyn.runtime.engine", "camdyn.generated")   # the packages with .pyx modules
# the flags say why in derive/flags.py, which the model files' builds read too
COMPILE_ARGS = runpy.run_path(str(ROOT / "derive" / "flags.py"))["COMPILE_ARGS"]


def _folder(package: str) -> Path:
    """The source folder of ``package``, through the package folder it lies in."""
    top = next(p for p in PACKAGE_DIR if package == p or package.startswith(p + "."))
    return ROOT / PACKAGE_DIR[top] / Path(*package[len(top):].split(".")[1:])


def _write_if_changed(path: Path, data: bytes):
    """Write only what differs: cythonize and build_ext compare times, and a header rewritten
    with the same text would translate and compile every module again (pip runs setup.py three
    times a build, and the wheel check builds after the editable install)."""
    if not path.exists() or path.read_bytes() != data:
        path.write_bytes(data)


def _stage_headers():
    pkg = INCLUDE / "camdyn"
    pkg.mkdir(parents=True, exist_ok=True)
    _write_if_changed(pkg / "__init__.pxd", b"")
    for package in COMPILED:
        dst = INCLUDE.joinpath(*package.split("."))
        dst.mkdir(parents=True, exist_ok=True)
        for level in (dst, *dst.parents):
            if level == pkg:
                break
            _write_if_changed(level / "__init__.pxd", b"")
        folder = _folder(package)
        for header in sorted([*folder.glob("*.pxd"), *folder.glob("*.pxi")]):
            _write_if_changed(dst / header.name, header.read_bytes())


def _extensions():
    exts = []
    for package in COMPILED:
        for pyx in sorted(_folder(package).glob("*.pyx")):
            exts.append(Extension(f"{package}.{pyx.stem}", [str(pyx.relative_to(ROOT))],
                                  extra_compile_args=COMPILE_ARGS))
    return exts


def _packages():
    packages = []
    for top, room in PACKAGE_DIR.items():
        for folder in sorted(p for p in [ROOT / room, *(ROOT / room).rglob("*")]
                             if p.is_dir() and p.name != "__pycache__"):
            packages.append(".".join((top, *folder.relative_to(ROOT / room).parts)))
    return packages


class ParallelBuildExt(build_ext):
    """Compile the extensions on every core (the DYNACAM variants are large), and each one only
    when its C source, flags or compiler changed.

    pip builds an editable install in a fresh temporary folder each time, so setuptools' own
    up-to-date test never holds there: without the cache below, regenerating one model and
    reinstalling compiled all of them again, and `pip install .` after the editable install
    compiled everything a second time.  A compiled module is kept in build/ext-cache/ under a
    hash of everything its bytes depend on (the C file Cython wrote embeds the .pyx, the .pxd
    and .pxi it includes and Cython's version)."""

    def finalize_options(self):
        super().finalize_options()
        if not self.parallel:
            self.parallel = os.cpu_count() or 1

    def _key(self, ext) -> str:
        compiler = getattr(self.compiler, "compiler_so", [])
        h = hashlib.sha256()
        for part in (sys.version, sysconfig.get_config_var("EXT_SUFFIX"),
                     *compiler, *getattr(self.compiler, "linker_so", []), *COMPILE_ARGS,
                     *(ext.extra_compile_args or []), *(ext.extra_link_args or []),
                     _compiler_version(compiler[0] if compiler else "")):
            h.update(str(part).encode() + b"\0")
        for source in ext.sources:
            h.update(Path(source).read_bytes())
        return h.hexdigest()[:32]

    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name))
        cached = EXT_CACHE / f"{ext.name}.{self._key(ext)}{target.suffix}"
        if cached.exists():
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(cached, target)
            return
        super().build_extension(ext)
        EXT_CACHE.mkdir(parents=True, exist_ok=True)
        for old in EXT_CACHE.glob(f"{ext.name}.*"):     # one version of each module is kept
            old.unlink(missing_ok=True)
        partial = cached.with_name(cached.name + f".{os.getpid()}.part")
        shutil.copyfile(target, partial)
        os.replace(partial, cached)      # never a half-written module under its final name


@functools.cache
def _compiler_version(command: str) -> str:
    try:
        return subprocess.run([command, "--version"], capture_output=True, text=True,
                              timeout=30).stdout
    except (OSError, subprocess.SubprocessError):
        return command


_stage_headers()
setup(
    packages=_packages(),
    cmdclass={"build_ext": ParallelBuildExt},
    ext_modules=cythonize(
        _extensions(),
        include_path=[str(INCLUDE)],
        compiler_directives={"language_level": 3},
        quiet=True,
        # Cython translates a module on one core (the largest, beam6, takes 9 s): every core
        nthreads=os.cpu_count() or 1,
    )
)
