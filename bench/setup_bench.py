"""Build the benchmark's own Cython modules in place (bench/*.so, never installed).

Run by bench/build.py (from bench/run.py) when a module is missing or stale:

    python setup_bench.py -q build_ext --inplace --build-temp out/build/temp --build-lib out/build/lib

yardstick.pyx   hand-written RK4 loop for (4.15), the yardstick
probe.pyx       the same loop on camdyn's generated right-hand side

Compiled with the flags of camdyn's extensions (setup.py: -O3 -fno-math-errno).  probe.pyx cimports
camdyn's ABI header from the tree camdyn's setup.py stages in
build/cython_include.
"""
from pathlib import Path

from Cython.Build import cythonize
from setuptools import Extension, setup

HERE = Path(__file__).parent.resolve()
INCLUDE = HERE.parent / "build" / "cython_include"
MODULES = ["yardstick", "probe"]

setup(
    name="camdyn-bench",
    ext_modules=cythonize(
        [Extension(name, [str(HERE / f"{name}.pyx")], extra_compile_args=["-O3", "-fno-math-errno"]) for name in MODULES],
        include_path=[str(INCLUDE)],
        compiler_directives={"language_level": 3},
        quiet=True,
    ),
)
