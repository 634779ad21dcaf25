"""The rooms and their one-way doors, read from the source (README "The house").

derive/ (SymPy, Jinja2) -> generated/ -> runtime/ (NumPy, SciPy, the compiled modules); the
thesis room may import both sides and nothing in the pipeline imports it.  Inside runtime/ the
floors open downwards only: engine < core < measure < cam < targets < studies < cli, and nothing
imports the command line.  No import circle anywhere, counting imports inside functions; no
module reads another module's private (underscore) names.  Checked on every
import statement (module level and inside functions) of every module, with relative imports
resolved, and on the cimports of the generated Cython.  The one sanctioned crossing is the
command line's dispatch: camdyn.runtime.cli hands `camdyn derive` to camdyn.derive and
`camdyn check`, `camdyn laws`, `camdyn design`, `camdyn figures` and `camdyn scenes --template`
to camdyn.thesis, inside those commands' run() only.
"""
import ast
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
ROOMS = ("derive", "generated", "runtime", "thesis")
DISPATCH = {("runtime/cli/derive.py", "run"): "camdyn.derive",
            ("runtime/cli/check.py", "run"): "camdyn.thesis",
            ("runtime/cli/laws.py", "run"): "camdyn.thesis",
            ("runtime/cli/figures.py", "run"): "camdyn.thesis",
            ("runtime/cli/design.py", "run"): "camdyn.thesis",
            # the machine file's template (camdyn scenes --template machine)
            ("runtime/cli/scenes.py", "run"): "camdyn.thesis",
            # the design page's verdict is camdyn design's, made for the page
            ("runtime/cli/page.py", "verdict"): "camdyn.thesis"}


def _module_name(path: Path) -> str:
    rel = path.relative_to(ROOT).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(["camdyn", *parts])


def imports():
    """(file, enclosing function or None, imported module) of every import in the rooms."""
    out = []
    for room in ROOMS:
        for path in sorted((ROOT / room).rglob("*.py")):
            tree = ast.parse(path.read_text(), str(path))
            me = _module_name(path)
            package = me if path.name == "__init__.py" else me.rsplit(".", 1)[0]

            def visit(node, func):
                for child in ast.iter_child_nodes(node):
                    f = func
                    if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                        f = child.name if func is None else func
                    if isinstance(child, ast.Import):
                        for a in child.names:
                            out.append((path, f, a.name))
                    elif isinstance(child, ast.ImportFrom):
                        base = child.module or ""
                        if child.level:
                            up = package.split(".")
                            up = up[:len(up) - child.level + 1]
                            base = ".".join(up + ([base] if base else []))
                        out.append((path, f, base))
                        for a in child.names:    # "from camdyn.thesis import checks"
                            out.append((path, f, f"{base}.{a.name}"))
                    visit(child, f)
            visit(tree, None)
    return out


IMPORTS = imports()


def _crossings(room, targets):
    bad = []
    for path, func, mod in IMPORTS:
        rel = str(path.relative_to(ROOT))
        if not rel.startswith(room + "/"):
            continue
        for t in targets:
            if mod == t or mod.startswith(t + "."):
                if DISPATCH.get((rel, func)) == t:
                    continue
                bad.append(f"{rel}:{func or '<module>'} imports {mod}")
    return bad


def test_the_import_census_sees_the_known_crossing():
    """The census must find the command line's sanctioned dispatch (else it finds nothing)."""
    seen = {(str(p.relative_to(ROOT)), f, m) for p, f, m in IMPORTS}
    assert ("runtime/cli/check.py", "run", "camdyn.thesis.checks.suite") in seen
    assert ("runtime/cli/derive.py", "run", "camdyn.derive.generate") in seen
    assert len(IMPORTS) > 300


def test_derive_never_imports_the_runtime_or_the_thesis():
    assert _crossings("derive", ("camdyn.runtime", "camdyn.thesis")) == []


def test_runtime_never_imports_derive_sympy_or_the_thesis():
    assert _crossings("runtime", ("camdyn.derive", "camdyn.thesis", "sympy", "jinja2")) == []


def test_generated_code_uses_only_the_runtime_abi():
    """Every generated module cimports from camdyn.runtime and the cam-law library only, and
    imports no camdyn Python module at all."""
    bad = []
    for path in sorted((ROOT / "generated").glob("*.pyx")):
        for line in path.read_text().splitlines():
            m = re.match(r"\s*(?:from\s+(\S+)\s+)?c?import\s+(\S+)", line)
            if not m or line.lstrip().startswith("#"):
                continue
            mod = m.group(1) or m.group(2)
            if mod.startswith("camdyn") and not (mod.startswith("camdyn.runtime.")
                                                 or mod == "camdyn.generated.camlaws"):
                bad.append(f"{path.name}: {line.strip()}")
            if "cimport" not in line and mod.startswith("camdyn"):
                bad.append(f"{path.name}: {line.strip()}")
    assert bad == []


def test_no_import_cycles_between_modules():
    """The module-level import graph of the rooms has no cycle (a function-level import is a
    door opened on use; module-level cycles are the ones that break imports)."""
    graph = {}
    names = {_module_name(p) for room in ROOMS for p in (ROOT / room).rglob("*.py")}
    for path, func, mod in IMPORTS:
        if func is None and mod in names:
            graph.setdefault(_module_name(path), set()).add(mod)
    for start in graph:
        graph[start].discard(start)
    state = {}

    def dfs(node, stack):
        state[node] = 1
        for nxt in graph.get(node, ()):
            # a package importing its own submodules is how __init__ files re-export
            if nxt.startswith(node + "."):
                continue
            if state.get(nxt) == 1:
                raise AssertionError(" -> ".join(stack + [node, nxt]))
            if state.get(nxt) is None:
                dfs(nxt, stack + [node])
        state[node] = 2

    for node in sorted(graph):
        if node not in state:
            dfs(node, [])


def test_the_theory_never_imports_the_runtime():
    """thesis/theory/ is typed in from the thesis and compared with the runs: it imports nothing
    of camdyn.runtime, not even inside a function."""
    assert _crossings("thesis/theory", ("camdyn.runtime",)) == []


def test_the_thesis_never_imports_the_command_line():
    """The command line hands commands to the thesis room, never the other way round."""
    assert _crossings("thesis", ("camdyn.runtime.cli",)) == []


RUNTIME_COMMANDS = {
    "residual": ["residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2", "--json"],
    "beam-follower": ["beam-follower", "--revolutions", "0.1", "--json"],
    "integrate": ["integrate", "one_dof", "--t-end", "2", "--json"],
    "run-beam": ["run", "beam_paper", "--quiet", "--out", "{tmp}/beam"],
    "simulate": ["simulate", "spring_loaded", "--json"],
    "run-dynacam": ["run", "indexing", "--quiet", "--out", "{tmp}/indexing"],
    "scenes": ["scenes"],
}


@pytest.mark.parametrize("name", sorted(RUNTIME_COMMANDS))
def test_a_simulating_command_never_loads_sympy(name, tmp_path):
    """The command runs in a process of its own; afterwards neither sympy nor camdyn.derive
    nor camdyn.thesis is among the loaded modules."""
    args = [a.replace("{tmp}", str(tmp_path)) for a in RUNTIME_COMMANDS[name]]
    code = ("import json, sys\nfrom camdyn.runtime import cli\n"
            f"rc = cli.main({args!r})\n"
            "bad = sorted(m for m in sys.modules if m.split('.')[0] == 'sympy' "
            "or m.startswith(('camdyn.derive', 'camdyn.thesis')))\n"
            "print(json.dumps({'rc': rc, 'loaded': bad[:5]}), file=sys.stderr)\n")
    env = {**os.environ, "MPLBACKEND": "Agg"}
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                       timeout=300, cwd=tmp_path)
    assert json.loads(p.stderr.strip().splitlines()[-1]) == {"rc": 0, "loaded": []}, p.stderr


# -- the floors of the house, every import counted (module level and inside functions) --------

NAMES = {_module_name(p) for room in ROOMS for p in (ROOT / room).rglob("*.py")}
PACKAGES = {_module_name(p) for room in ROOMS for p in (ROOT / room).rglob("__init__.py")}


def _edges():
    """(importer, imported) of every import between the rooms' modules: ``from pkg import mod``
    is an edge to the module only (the package itself is not what is read)."""
    edges = set()
    for path in sorted(p for room in ROOMS for p in (ROOT / room).rglob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        me = _module_name(path)
        package = me if path.name == "__init__.py" else me.rsplit(".", 1)[0]
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for a in node.names:
                    if a.name in NAMES:
                        edges.add((me, a.name))
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    up = package.split(".")
                    base = ".".join(up[:len(up) - node.level + 1] + ([base] if base else []))
                subs = [f"{base}.{a.name}" for a in node.names if f"{base}.{a.name}" in NAMES]
                for s in subs:
                    edges.add((me, s))
                if len(subs) < len(node.names) and base in NAMES:
                    edges.add((me, base))
    return {(a, b) for a, b in edges if a != b and not b.startswith(a + ".")}


EDGES = _edges()


def test_the_edges_are_seen():
    """The census must see known imports, at module level and inside functions."""
    assert ("camdyn.runtime.targets.model_target", "camdyn.runtime.core.simulator") in EDGES
    assert ("camdyn.runtime.cli.run", "camdyn.runtime.targets.resolve") in EDGES   # in run()
    assert len(EDGES) > 300


def test_no_import_circle_anywhere():
    """The import graph of every module of the rooms, imports inside functions counted, has no
    circle (a function-level import is still a door one way)."""
    graph = {}
    for a, b in EDGES:
        graph.setdefault(a, set()).add(b)
    state = {}

    def dfs(node, stack):
        state[node] = 1
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                raise AssertionError(" -> ".join(stack + [node, nxt]))
            if state.get(nxt) is None:
                dfs(nxt, stack + [node])
        state[node] = 2

    for node in sorted(graph):
        if node not in state:
            dfs(node, [])


FLOORS = {"engine": 0, "core": 1, "measure": 2, "cam": 3, "targets": 4, "studies": 5, "cli": 6}
"""runtime/'s subpackages by floor: an import goes to a lower floor, or stays in its own
subpackage."""


def _floor(module: str):
    parts = module.split(".")
    if parts[:2] != ["camdyn", "runtime"] or len(parts) < 4:
        return None, None
    return parts[2], FLOORS.get(parts[2])


def test_runtime_floors_open_downwards_only():
    bad = []
    for a, b in EDGES:
        sa, fa = _floor(a)
        sb, fb = _floor(b)
        if fa is None or fb is None or sa == sb:
            continue
        if fb >= fa:
            bad.append(f"{a} imports {b}")
    assert bad == []


def test_nothing_imports_the_command_line():
    bad = [f"{a} imports {b}" for a, b in EDGES
           if b.startswith("camdyn.runtime.cli") and not a.startswith("camdyn.runtime.cli")]
    assert bad == []


def test_every_subpackage_of_runtime_has_a_floor():
    subs = {p.name for p in (ROOT / "runtime").iterdir()
            if p.is_dir() and (p / "__init__.py").exists()}
    assert subs == set(FLOORS)


def _private_reads():
    """Every read of another module's private name: ``from x import _y`` and ``x._y`` on an
    imported module ``x`` of the rooms."""
    out = []
    for path in sorted(p for room in ROOMS for p in (ROOT / room).rglob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        me = _module_name(path)
        package = me if path.name == "__init__.py" else me.rsplit(".", 1)[0]
        aliases = {}
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for a in node.names:
                    if a.asname:
                        aliases[a.asname] = a.name
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    up = package.split(".")
                    base = ".".join(up[:len(up) - node.level + 1] + ([base] if base else []))
                for a in node.names:
                    aliases[a.asname or a.name] = f"{base}.{a.name}"
                    if base.startswith("camdyn") and a.name.startswith("_") \
                            and not a.name.startswith("__") and base != me:
                        out.append(f"{me}: from {base} import {a.name}")
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) \
                    and node.attr.startswith("_") and not node.attr.startswith("__"):
                target = aliases.get(node.value.id, "")
                if target in NAMES and target != me:
                    out.append(f"{me}: {node.value.id}.{node.attr}")
    return out


def test_no_module_reads_another_modules_private_names():
    assert _private_reads() == []


HEAVY = ("numpy", "scipy", "matplotlib", "sympy", "dask", "distributed", "tqdm", "pyarrow",
         "ezdxf", "jinja2", "camdyn.generated.")
"""What a command may load only when it uses it: the libraries that take tenths of a second
to import, and the compiled models (each a module of its own)."""

LOADS = {
    "help": (["--help"], []),
    "design": (["design", "--stroke", "0.02", "--tau", "0.2", "--fa", "0.1", "--accuracy",
                "1e-4", "--no-check", "--quiet"],
               ["camdyn.generated.camlaws", "camdyn.generated.camshaft1", "numpy"]),
    "design-chart": (["design", "--stroke", "0.02", "--tau", "0.2", "--fa", "0.1", "--accuracy",
                      "1e-4", "--no-check", "--quiet", "--out", "{tmp}/d"],
                     ["camdyn.generated.camlaws", "camdyn.generated.camshaft1", "matplotlib",
                      "numpy"]),
    "design-motor": (["design", "--stroke", "0.0309", "--tau", "0.1413", "--fa", "2.07",
                      "--rise-time", "0.0877", "--mass", "1.46", "--accuracy", "1e-4",
                      "--motor-rpm", "3000", "--spring", "--worm", "0.36", "0.05",
                      "--slip-limit", "0.016", "--no-check", "--quiet"],
                     ["camdyn.generated.camlaws", "camdyn.generated.camshaft1", "numpy"]),
    "residual": (["residual", "--model", "camshaft1", "--tau", "0.15", "--fa", "2"],
                 ["camdyn.generated.camlaws", "camdyn.generated.camshaft1", "numpy"]),
}


@pytest.mark.parametrize("name", sorted(LOADS))
def test_a_command_loads_only_what_it_uses(name, tmp_path):
    """The command runs in a process of its own; afterwards the heavy libraries and compiled
    models loaded are exactly those it needs: `camdyn --help` none (a command's arguments are
    read only for that command), `camdyn design` no matplotlib without --out, no other model
    than CAMSHAFT-1 and no SymPy for a motor (the first-order motor is NumPy's),
    `camdyn residual` no SciPy (its figures are the compiled finder's)."""
    argv, want = LOADS[name]
    args = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    code = ("import contextlib, io, json, sys\nfrom camdyn.runtime import cli\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            "    try:\n"
            f"        rc = cli.main({args!r})\n"
            "    except SystemExit as exc:\n"
            "        rc = exc.code\n"
            f"heavy = {HEAVY!r}\n"
            "loaded = sorted({m if m.startswith('camdyn.') else m.split('.')[0] for m in sys.modules\n"
            "                 if m.startswith(heavy) or m.split('.')[0] in heavy})\n"
            "print(json.dumps({'rc': rc, 'loaded': loaded}), file=sys.stderr)\n")
    env = {**os.environ, "MPLBACKEND": "Agg"}
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                       timeout=300, cwd=tmp_path)
    assert json.loads(p.stderr.strip().splitlines()[-1]) == {"rc": 0, "loaded": want}, p.stderr
