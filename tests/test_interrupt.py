"""Ctrl-C and SIGTERM (runtime/core/signals.py, the command line's main): one line saying what
was kept, status 130 or 143, no traceback, no file half written; a sweep keeps its finished
rows and --resume ends with the table an uninterrupted sweep writes, to the last bit; an
interrupted `camdyn figures` leaves an index of what it drew."""
import os
import signal
import subprocess
import sys
import time

import pytest

from camdyn.runtime.cli import main
from camdyn.runtime.core import outdir, signals

GRID = ["--grid", "Fa=0,2", "--grid", "tau=0.06:0.7:300:inv"]
"""600 points of CAMSHAFT-1 (fig. 4.11's tau grid), 19 chunks of 32: long enough to stop."""


def _sweep(out, *extra):
    return ["sweep", "camshaft1", *GRID, "--quiet", "--out", str(out), *extra]


@pytest.fixture(scope="module")
def clean(tmp_path_factory):
    """The table of an uninterrupted sweep (with the error estimate: both passes)."""
    out = tmp_path_factory.mktemp("clean")
    assert main(_sweep(out)) == 0
    return out


def _last_line(text: str) -> str:
    lines = text.strip().splitlines()
    return lines[-1] if lines else ""


def _rows(path) -> int:
    with open(path) as fh:
        return sum(1 for _ in fh) - 1


def _same_tables(a, b) -> None:
    assert (a / "sweep.csv").read_bytes() == (b / "sweep.csv").read_bytes()
    pq = pytest.importorskip("pyarrow.parquet")
    assert pq.read_table(a / "sweep.parquet").equals(pq.read_table(b / "sweep.parquet"))


def test_a_signal_waits_for_the_file_being_written(tmp_path):
    """SIGTERM inside outdir.writing (under the command line's handlers): the file is written
    whole and recorded, then Interrupted (a KeyboardInterrupt) with status 143; the handlers
    before come back."""
    before = signal.getsignal(signal.SIGTERM)
    path = tmp_path / "table.csv"
    with pytest.raises(signals.Interrupted) as info, signals.handled():
        with outdir.writing(path) as p, open(p, "w") as fh:
            fh.write("a,b\n")
            os.kill(os.getpid(), signal.SIGTERM)
            fh.write("1,2\n")
    assert info.value.status == 143 and isinstance(info.value, KeyboardInterrupt)
    assert path.read_text() == "a,b\n1,2\n"
    assert outdir.entry(path)["sha256"] == outdir.digest(path)
    assert signal.getsignal(signal.SIGTERM) is before


def test_an_interrupted_command_names_the_files_it_kept(tmp_path, capsys, monkeypatch):
    """Ctrl-C while `camdyn profile` draws its picture, after the CSV and DXF: exit 130 and
    one line naming the two files kept, both whole and recorded."""
    from camdyn.runtime.cam.profile import CamProfile

    monkeypatch.setattr(CamProfile, "write_png",
                        lambda self, path: os.kill(os.getpid(), signal.SIGINT))
    out = tmp_path / "cam"
    argv = ["profile", "--stroke", "0.015", "--base-radius", "0.026", "--roller-radius",
            "0.005", "--out", str(out)]
    assert main(argv) == 130
    assert capsys.readouterr().err.strip() == (f"camdyn profile: interrupted; 2 files kept in "
                                               f"{out}: cam.csv, cam.dxf")
    for name in ("cam.csv", "cam.dxf"):
        assert outdir.entry(out / name) is not None


def test_a_sweep_stopped_midway_resumes_to_the_uninterrupted_table(tmp_path, capsys,
                                                                   monkeypatch, clean):
    """SIGTERM after the second chunk's rows (in this process, through the real handler):
    exit 143, one line with the rows kept; the table holds two chunks' whole rows (75 points
    each: 600 points on one thread, default_chunk) with their estimates and warnings;
    --resume runs the other 450 points and ends with the clean sweep's sweep.csv byte for
    byte (and its Parquet table)."""
    from camdyn.runtime.studies import sweep as sw

    add = sw._Table.add

    def add_then_stop(self, columns):
        add(self, columns)
        if self.kept >= 150:
            os.kill(os.getpid(), signal.SIGTERM)

    monkeypatch.setattr(sw._Table, "add", add_then_stop)
    out = tmp_path / "sweep"
    assert main(_sweep(out, "--jobs", "1")) == 143
    assert _last_line(capsys.readouterr().err) == (
        f"camdyn sweep: interrupted; 150 of 600 points kept in {out / 'sweep.csv'} "
        "(--resume continues)")
    clean_lines = (clean / "sweep.csv").read_text().splitlines(keepends=True)
    assert (out / "sweep.csv").read_text() == "".join(clean_lines[:151])
    monkeypatch.setattr(sw._Table, "add", add)
    assert main(_sweep(out, "--resume")) == 0
    assert "600 points (150 kept from the table, 450 run now)" in capsys.readouterr().out
    _same_tables(out, clean)


def test_resume_refuses_a_table_of_another_sweep_or_one_edited(tmp_path, capsys, clean):
    """--resume continues only a table camdyn wrote for the same sweep: another grid, or a
    table changed by hand, is refused in one line (the table as it was); without a table
    --resume simply runs the sweep."""
    out = tmp_path / "s"
    assert main(["sweep", "one_dof", "--grid", "tau=0.2,0.3", "--quiet", "--out", str(out),
                 "--resume"]) == 0
    table = (out / "sweep.csv").read_text()
    assert main(["sweep", "one_dof", "--grid", "tau=0.2,0.4", "--quiet", "--out", str(out),
                 "--resume"]) == 2
    assert _last_line(capsys.readouterr().err) == (
        f"camdyn sweep: error: argument --resume: {out / 'sweep.csv'} is the table of another "
        "sweep (target, grid, method, tolerance, t_end or error estimate); give the command "
        "that wrote it, or drop --resume to start afresh")
    (out / "sweep.csv").write_text(table + "0.5,1,2\n")
    assert main(["sweep", "one_dof", "--grid", "tau=0.2,0.3", "--quiet", "--out", str(out),
                 "--resume"]) == 2
    assert _last_line(capsys.readouterr().err) == (
        f"camdyn sweep: error: argument --resume: {out / 'sweep.csv'} was not written by "
        "camdyn, or was changed since; drop --resume to start afresh (--overwrite replaces it)")
    assert (out / "sweep.csv").read_text() == table + "0.5,1,2\n"


def test_an_interrupted_figure_build_leaves_an_index_of_what_it_drew(tmp_path, capsys,
                                                                     monkeypatch):
    """Ctrl-C while the second of two figures is drawn: exit 130, one line, and index.html
    lists the first figure with its picture and says it holds 1 of the 2 chosen."""
    from camdyn.thesis.figures import build

    one = build.build_one
    calls = []

    def second_interrupted(fig, *args):
        calls.append(fig.id)
        if len(calls) == 2:
            os.kill(os.getpid(), signal.SIGINT)
        return one(fig, *args)

    monkeypatch.setattr(build, "build_one", second_interrupted)
    out = tmp_path / "figures"
    assert main(["figures", "--only", "3.4,8.6", "--quiet", "--out", str(out)]) == 130
    assert calls == ["3.4", "8.6"]
    assert capsys.readouterr().err.strip() == (f"camdyn figures: interrupted; 1 of 2 figures "
                                               f"drawn, listed in {out / 'index.html'}")
    page = (out / "index.html").read_text()
    assert 'id="fig3_4"' in page and "fig8_6" not in page, page[:2000]
    assert "This page lists 1 of the 2 figures chosen" in " ".join(page.split())
    assert page.rstrip().endswith("</html>")
    pics = [p for p in os.listdir(out) if p.endswith(".png")]
    assert pics and all(f'src="{p}"' in page for p in pics)


# -- from outside: real signals to a running command ----------------------------------------------

def _start(argv):
    return subprocess.Popen([sys.executable, "-m", "camdyn.runtime.cli", *argv],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def _wait_for(proc, ready, timeout=120.0):
    """Poll until ``ready()`` (the command still running), or fail the test."""
    end = time.monotonic() + timeout
    while not ready():
        if proc.poll() is not None:
            pytest.fail(f"the command ended before it could be stopped: {proc.stderr.read()}")
        if time.monotonic() > end:
            proc.kill()
            pytest.fail("the command never got there")
        time.sleep(0.005)


@pytest.mark.parametrize("sig, status", [(signal.SIGINT, 130),
                                         pytest.param(signal.SIGTERM, 143, marks=pytest.mark.slow)])
def test_a_sweep_killed_from_outside_resumes_to_the_same_table(tmp_path, capsys, clean, sig,
                                                               status):
    """`camdyn sweep` as a process, stopped by SIGINT (Ctrl-C) or SIGTERM once it has written
    rows: its status, one line on stderr naming the rows kept (as many as the table holds),
    no traceback; `--resume` then writes the uninterrupted sweep's table byte for byte."""
    out = tmp_path / "sweep"
    table = out / "sweep.csv"
    proc = _start(_sweep(out, "--jobs", "1"))
    _wait_for(proc, lambda: table.exists() and _rows(table) >= 32)
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == status, err
    assert "Traceback" not in err
    kept = _rows(table)
    assert 32 <= kept < 600
    assert err.strip() == (f"camdyn sweep: interrupted; {kept} of 600 points kept in {table} "
                           "(--resume continues)")
    assert outdir.entry(table) is not None           # whole rows, recorded as camdyn's
    assert main(_sweep(out, "--resume")) == 0
    assert f"({kept} kept from the table, {600 - kept} run now)" in capsys.readouterr().out
    _same_tables(out, clean)


@pytest.mark.slow
def test_a_figure_build_killed_from_outside_leaves_its_index(tmp_path):
    """`camdyn figures` as a process, SIGTERM while the second figure (the paper's fig. 5,
    several seconds of runs) is drawn: status 143, one line, index.html listing fig. 3.4."""
    out = tmp_path / "figures"
    proc = _start(["figures", "--only", "3.4,paper 5", "--quiet", "--out", str(out)])
    index = out / "index.html"
    _wait_for(proc, lambda: index.exists() and 'id="fig3_4"' in index.read_text())
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 143, err
    assert err.strip() == f"camdyn figures: interrupted; 1 of 2 figures drawn, listed in {index}"
    page = index.read_text()
    assert "This page lists 1 of the 2 figures chosen" in " ".join(page.split())
    assert page.rstrip().endswith("</html>")
