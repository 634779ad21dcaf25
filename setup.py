"""Build the Cython extensions: the integrators and every generated model.

Cython finds cimported .pxd files by package path (camdyn/runtime/abi.pxd),
but the design card keeps the sources in top-level folders (runtime/,
generated/).  So the .pxd headers are copied into build/cython_include/camdyn/
first and that tree is put on Cython's include path.
"""
import shutil
from pathlib import Path

from Cython.Build import cythonize
from setuptools import Extension, setup

ROOT = Path(__file__).parent.resolve()
INCLUDE = ROOT / "build" / "cython_include"
FOLDERS = {"runtime": "runtime", "generated": "generated"}


def _stage_headers():
    pkg = INCLUDE / "camdyn"
    pkg.mkdir(parents=True, exist_ok=True)
    (pkg / "__init__.pxd").write_text("")
    for sub, folder in FOLDERS.items():
        dst = pkg / sub
        dst.mkdir(exist_ok=True)
        (dst / "__init__.pxd").write_text("")
        for pxd in sorted((ROOT / folder).glob("*.pxd")):
            shutil.copyfile(pxd, dst / pxd.name)


def _extensions():
    exts = []
    for sub, folder in FOLDERS.items():
        for pyx in sorted((ROOT / folder).glob("*.pyx")):
            exts.append(Extension(f"camdyn.{sub}.{pyx.stem}", [f"{folder}/{pyx.name}"],
                                  extra_compile_args=["-O3"]))
    return exts


_stage_headers()
setup(
    ext_modules=cythonize(
        _extensions(),
        include_path=[str(INCLUDE)],
        compiler_directives={"language_level": 3},
        quiet=True,
    )
)
