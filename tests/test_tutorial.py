"""The tutorial notebook (docs/tutorial.ipynb), executed as a reader would run it: from a
model file to a design.  Every cell must run without an error, each view must show what the
answer contract asks for, and the design's tau must be the one (4.39), (4.12) give for the
notebook's follower, computed here independently: tau = 2 pi (m/c)^(1/2)/t_m."""
import math
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

NOTEBOOK = Path(__file__).resolve().parents[1] / "docs" / "tutorial.ipynb"


def test_the_tutorial_runs_from_a_model_file_to_a_design(tmp_path, monkeypatch):
    monkeypatch.setenv("CAMDYN_CACHE_DIR", str(tmp_path / "cache"))
    nb = nbformat.read(NOTEBOOK, as_version=4)
    nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}}).execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    html = [o["data"]["text/html"] for o in outputs if "text/html" in o.get("data", {})]
    # the Result, the Answer and the sweep: each a table with estimates or the run's statistics,
    # its warnings (or "no warnings") and a chart
    assert len(html) >= 3 and all("data:image/png;base64," in h for h in html[:3])
    assert all(("warnings" in h) for h in html[:3])
    assert "\u00b1" in html[1] and "\u00b1" in html[2]
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    tau = 2 * math.pi * math.sqrt(1.0 / 900.0) / 0.3
    stiffer = 2 * math.pi * math.sqrt(1.0 / 4000.0) / 0.3
    assert f"tau                 {tau:.4g}" in text and f"{stiffer:.4g}" in text
    assert (tmp_path / "follower.py").is_file()
