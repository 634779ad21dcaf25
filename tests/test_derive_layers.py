"""The floors inside derive/, read from the source (every import, at module level and inside
functions, relative imports resolved).

The two printers of model modules, codegen.py (M q'' = f) and dae.py (the multiplier form),
stand side by side on emit.py (the template environment, the plain symbols, the manifest's
common entries) and do not import each other; render.py, above both, chooses between them.
No module of derive/ reads a private (underscore) name of another.
"""
import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DERIVE = ROOT / "derive"


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(["camdyn", *parts])


def _census():
    """Per module of derive/: the camdyn.derive modules it imports, and the private names it
    takes from them (``from .x import _y``, or ``x._y`` on an imported module ``x``)."""
    out = {}
    for path in sorted(DERIVE.rglob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        me = _module_name(path)
        package = me if path.name == "__init__.py" else me.rsplit(".", 1)[0]
        imported, private, aliases = set(), [], {}
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for a in node.names:
                    imported.add(a.name)
                    if a.asname:
                        aliases[a.asname] = a.name
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    up = package.split(".")
                    base = ".".join(up[:len(up) - node.level + 1] + ([base] if base else []))
                imported.add(base)
                for a in node.names:
                    imported.add(f"{base}.{a.name}")    # "from . import codegen"
                    aliases[a.asname or a.name] = f"{base}.{a.name}"
                    if base.startswith("camdyn.derive") and a.name.startswith("_") \
                            and not a.name.startswith("__"):
                        private.append(f"{base}.{a.name}")
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) \
                    and node.attr.startswith("_") and not node.attr.startswith("__"):
                target = aliases.get(node.value.id, "")
                if target.startswith("camdyn.derive"):
                    private.append(f"{target}.{node.attr}")
        out[me] = (imported, private)
    return out


CENSUS = _census()


def _imports(module: str, target: str) -> bool:
    return any(m == target or m.startswith(target + ".") for m in CENSUS[module][0])


def test_the_census_sees_the_printers_and_their_floor():
    assert _imports("camdyn.derive.codegen", "camdyn.derive.emit")
    assert _imports("camdyn.derive.dae", "camdyn.derive.emit")
    assert _imports("camdyn.derive.render", "camdyn.derive.codegen")
    assert _imports("camdyn.derive.render", "camdyn.derive.dae")


def test_codegen_and_dae_do_not_import_each_other():
    assert not _imports("camdyn.derive.codegen", "camdyn.derive.dae")
    assert not _imports("camdyn.derive.dae", "camdyn.derive.codegen")


def test_the_shared_floor_imports_no_printer():
    for printer in ("codegen", "dae", "render", "generate", "build"):
        assert not _imports("camdyn.derive.emit", f"camdyn.derive.{printer}"), printer


def test_no_module_reads_another_modules_private_names():
    found = {m: private for m, (_, private) in CENSUS.items() if private}
    assert found == {}
