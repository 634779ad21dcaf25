"""Ctrl-C and SIGTERM (runtime/core/signals.py, the command line's main): one line saying what
was kept, status 130 or 143, no traceback, no file half written."""
import os
import signal

import pytest

from camdyn.runtime.cli import main
from camdyn.runtime.core import outdir, signals

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
