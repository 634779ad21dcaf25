"""Build the Cython extensions (the integration driver and every generated model) and list the
packages.

The packages are discovered, not listed by hand: every folder under a room (derive/, generated/,
runtime/, thesis/) is a package camdyn.<room>.<sub>..., so a new subpackage cannot be left out of the
wheel (one was: camdyn.thesis.checks, while only the editable install was tested).

Cython finds cimported .pxd and included .pxi files by package path
(camdyn/runtime/abi.pxd, camdyn/runtime/loops.pxi),
but the design card keeps the sources in top-level folders (runtime/,
generated/).  So the headers are copied into build/cython_include/camdyn/
first and that tree is put on Cython's include path.
"""
import os
import shutil
from pathlib import Path

from Cython.Build import cythonize
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).parent.resolve()
INCLUDE = ROOT / "build" / "cython_include"
FOLDERS = {"runtime": "runtime", "generated": "generated"}
ROOMS = ("derive", "generated", "runtime", "thesis")   # camdyn.<room>: the top-level folder <room>/
# -fno-math-errno: sqrt becomes an instruction; nothing here reads errno
COMPILE_ARGS = ["-O3", "-fno-math-errno"]


def _stage_headers():
    pkg = INCLUDE / "camdyn"
    pkg.mkdir(parents=True, exist_ok=True)
    (pkg / "__init__.pxd").write_text("")
    for sub, folder in FOLDERS.items():
        dst = pkg / sub
        dst.mkdir(exist_ok=True)
        (dst / "__init__.pxd").write_text("")
        for header in sorted([*(ROOT / folder).glob("*.pxd"), *(ROOT / folder).glob("*.pxi")]):
            shutil.copyfile(header, dst / header.name)


def _extensions():
    exts = []
    for sub, folder in FOLDERS.items():
        for pyx in sorted((ROOT / folder).glob("*.pyx")):
            exts.append(Extension(f"camdyn.{sub}.{pyx.stem}", [f"{folder}/{pyx.name}"],
                                  extra_compile_args=COMPILE_ARGS))
    return exts


def _packages():
    packages = []
    for room in ROOMS:
        for folder in sorted(p for p in [ROOT / room, *(ROOT / room).rglob("*")]
                             if p.is_dir() and p.name != "__pycache__"):
            packages.append(".".join(("camdyn", room, *folder.relative_to(ROOT / room).parts)))
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
    package_dir={f"camdyn.{room}": room for room in ROOMS},
    cmdclass={"build_ext": ParallelBuildExt},
    ext_modules=cythonize(
        _extensions(),
        include_path=[str(INCLUDE)],
        compiler_directives={"language_level": 3},
        quiet=True,
    )
)
