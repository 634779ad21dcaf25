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
