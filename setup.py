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
import os
import runpy
import shutil
import tomllib
from pathlib import Path

from Cython.Build import cythonize
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).parent.resolve()
INCLUDE = ROOT / "build" / "cython_include"
PACKAGE_DIR = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-dir"]
COMPILED = ("camdyn.runtime.engine", "camdyn.generated")   # the packages with .pyx modules
# the flags say why in derive/flags.py, which the model files' builds read too
COMPILE_ARGS = runpy.run_path(str(ROOT / "derive" / "flags.py"))["COMPILE_ARGS"]


def _folder(package: str) -> Path:
    """The source folder of ``package``, through the package folder it lies in."""
    top = next(p for p in PACKAGE_DIR if package == p or package.startswith(p + "."))
    return ROOT / PACKAGE_DIR[top] / Path(*package[len(top):].split(".")[1:])


def _stage_headers():
    pkg = INCLUDE / "camdyn"
    pkg.mkdir(parents=True, exist_ok=True)
    (pkg / "__init__.pxd").write_text("")
    for package in COMPILED:
        dst = INCLUDE.joinpath(*package.split("."))
        dst.mkdir(parents=True, exist_ok=True)
        for level in (dst, *dst.parents):
            if level == pkg:
                break
            (level / "__init__.pxd").write_text("")
        folder = _folder(package)
        for header in sorted([*folder.glob("*.pxd"), *folder.glob("*.pxi")]):
            shutil.copyfile(header, dst / header.name)


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
    """Compile the extensions on every core: the DYNACAM variants are large."""

    def finalize_options(self):
        super().finalize_options()
        if not self.parallel:
            self.parallel = os.cpu_count() or 1


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
