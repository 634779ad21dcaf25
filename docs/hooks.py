"""Makes the site's pages before MkDocs reads them: the README cut at its "## " headings, one
page each (links to files of the repository become their paths in code, as the site holds no
source tree), the tutorial notebook, and one API page per public module, rendered by
mkdocstrings from the docstrings."""
from __future__ import annotations

import re
import shutil
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent

API = {
    "Running models": ["camdyn.runtime.core.simulator", "camdyn.runtime.core.result"],
    "Figures and their errors": ["camdyn.runtime.measure.contract", "camdyn.runtime.measure.residual"],
    "Targets and scenes": ["camdyn.runtime.targets.resolve", "camdyn.runtime.targets.scene_files"],
    "Sweeps": ["camdyn.runtime.studies.sweep"],
    "The cam": ["camdyn.runtime.cam.profile", "camdyn.runtime.cam.follower", "camdyn.runtime.cam.stress"],
    "Declaring a model": ["camdyn.derive.model"],
    "Design by the thesis's rules": ["camdyn.thesis.design.method"],
}
"""The reference's pages and the modules on each."""

OPTIONS = {"camdyn.derive.model": "\n    options:\n      filters: [\"!^_\", \"!^ConstraintSolver$\"]"}
"""mkdocstrings options of a module: the constraint solver's docstring writes its matrices
in brackets that Markdown takes for links (README "Constrained models" has them in code)."""


def _slug(title: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", title.lower()).strip("-")


def _links(text: str) -> str:
    def repl(m):
        label, target = m.group(1), m.group(2)
        if target.startswith(("http://", "https://")):
            return m.group(0)
        if target == "docs/serve.png":
            return f"[{label}](serve.png)"
        return f"{label} (`{target}`)"
    return re.sub(r"(?<!!)\[([^\]]+)\]\(([^)]+)\)", repl, text).replace("](docs/serve.png)", "](serve.png)")


def _pages(readme: str) -> list[tuple[str, str]]:
    head, *parts = re.split(r"^## ", readme, flags=re.M)
    pages = [("index.md", _links(head))]
    for part in parts:
        title = part.splitlines()[0].strip()
        pages.append((f"{_slug(title)}.md", _links("# " + part)))
    return pages


def _sources() -> None:
    """docs/src/camdyn: the import namespace over the rooms (derive/, runtime/, ...), as
    pyproject.toml's package-dir maps it, for mkdocstrings to read the modules' source."""
    import tomllib

    src = HERE / "src" / "camdyn"
    if src.exists():
        shutil.rmtree(src.parent)
    src.mkdir(parents=True)
    (src / "__init__.py").write_text('"""camdyn: cam-mechanism dynamics."""\n')
    dirs = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-dir"]
    for package, folder in dirs.items():
        if package.count(".") == 1:
            (src / package.split(".")[1]).symlink_to(ROOT / folder, target_is_directory=True)


# at import, when MkDocs loads this file with the configuration: mkdocstrings takes its
# search paths in its own on_config, which runs before this file's
_sources()


def on_config(config, **kwargs):
    pages = Path(config["docs_dir"])
    for old in pages.iterdir():            # the folder itself stays, held by its .gitignore
        if old.name != ".gitignore":
            shutil.rmtree(old) if old.is_dir() else old.unlink()
    nav = []
    for name, text in _pages((ROOT / "README.md").read_text()):
        (pages / name).write_text(text)
        title = "Overview" if name == "index.md" else text.splitlines()[0][2:].strip()
        nav.append({title: name})
    shutil.copy(HERE / "serve.png", pages / "serve.png")
    shutil.copy(HERE / "tutorial.ipynb", pages / "tutorial.ipynb")
    nav.insert(1, {"Tutorial: from a model file to a design": "tutorial.ipynb"})
    api = []
    for title, modules in API.items():
        name = f"api-{_slug(title)}.md"
        (pages / name).write_text(f"# {title}\n\n" + "\n\n".join(
            f"::: {m}" + OPTIONS.get(m, "") for m in modules) + "\n")
        api.append({title: name})
    nav.append({"API reference": api})
    config["nav"] = nav
    return config
