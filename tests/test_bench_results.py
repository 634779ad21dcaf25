"""The benchmarks' reports and their quick pass, read from the files (nothing is run here).

Every report lives in bench/results/ and is listed in its index, BENCHMARKS.md; every link in
them and in the README resolves; every benchmark script (a script of bench/ with a main())
takes --quick and is run so by `make bench-quick`, which CI runs.
"""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "bench" / "results"
LINK = re.compile(r"\]\(([^)#\s]+)\)")


def _links(path: Path) -> list[str]:
    return [m for m in LINK.findall(path.read_text()) if "://" not in m]


def test_every_report_is_in_bench_results_and_in_the_index():
    assert not list(ROOT.glob("BENCHMARKS*.md")), "reports belong in bench/results/"
    reports = {p.name for p in RESULTS.glob("BENCHMARKS-*.md")}
    assert reports and set(_links(RESULTS / "BENCHMARKS.md")) >= reports


def test_links_of_the_reports_and_the_readme_resolve():
    missing = [f"{page.relative_to(ROOT)}: {link}"
               for page in [ROOT / "README.md", *sorted(RESULTS.glob("*.md"))]
               for link in _links(page) if not (page.parent / link).exists()]
    assert missing == []


def _recipe(target: str) -> str:
    text = (ROOT / "Makefile").read_text()
    found = re.search(rf"^{re.escape(target)}:.*\n((?:\t.*\n)+)", text, re.M)
    assert found, f"no target {target} in the Makefile"
    return found.group(1)


def test_every_benchmark_has_a_quick_pass_that_make_bench_quick_runs():
    scripts = sorted(p for p in (ROOT / "bench").glob("*.py") if "\ndef main(" in p.read_text())
    assert len(scripts) >= 7
    quick = _recipe("bench-quick")
    for script in scripts:
        assert '"--quick"' in script.read_text(), script.name
        assert f"bench/{script.name} --quick" in quick, script.name
    assert "bench-quick" in (ROOT / ".ci" / "run").read_text()


def test_every_benchmark_writes_its_report_through_the_stamp():
    """A report says when and at which commit it was measured: every benchmark script writes
    it with where.write_report, and no script writes a file otherwise."""
    scripts = sorted(p for p in (ROOT / "bench").glob("*.py") if "\ndef main(" in p.read_text())
    for script in scripts:
        text = script.read_text()
        assert "write_report(" in text and ".write_text(" not in text, script.name


def test_the_stamp_is_the_line_under_the_title(tmp_path, monkeypatch):
    """where.write_report: the title, a blank line, 'Measured <YYYY-MM-DD HH:MM> UTC at commit
    <git rev-parse --short HEAD>[ with uncommitted changes].', a blank line, the report."""
    import subprocess
    import sys

    monkeypatch.syspath_prepend(str(ROOT / "bench"))
    import where

    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                          cwd=ROOT, check=True).stdout.strip()
    for body in ("# Title\n\nFirst paragraph.\n", "# Title\nFirst paragraph.\n"):
        where.write_report(tmp_path / "r.md", body)
        lines = (tmp_path / "r.md").read_text().split("\n")
        assert lines[0] == "# Title" and lines[1] == "" and lines[3] == ""
        assert re.fullmatch(rf"Measured \d{{4}}-\d\d-\d\d \d\d:\d\d UTC at commit {head}"
                            r"( with uncommitted changes)?\.", lines[2]), lines[2]
        assert lines[4:] == ["First paragraph.", ""]
    sys.modules.pop("where", None)
