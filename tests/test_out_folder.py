"""What commands write into --out (runtime/core/outdir.py): a file camdyn did not write, or
changed since, is never replaced without --overwrite; a command's own files are; a folder or
file that cannot be written ends any command in one line naming it and --out."""
import builtins
import io
import json
import os
import re

import pytest

from camdyn.runtime.cli import main
from camdyn.runtime.core import outdir
from camdyn.runtime.core.errors import OutFolderError

STEADY = ["--stroke", "0.015", "--base-radius", "0.026", "--roller-radius", "0.005"]

# every command that writes files, with quick arguments and one file it writes into --out
COMMANDS = {
    "run": (["run", "--quiet"], "report.md"),
    "simulate": (["simulate", "spring_loaded", "--no-error-estimate"], "spring_loaded_Xdd.png"),
    "sweep": (["sweep", "one_dof", "--grid", "tau=0.2,0.3", "--quiet"], "sweep.csv"),
    "stability": (["stability", "one_dof", "--param", "tau=0.2,0.3", "--methods", "rk4",
                   "--steps", "0.01,0.02", "--quiet"], "stability_one_dof_tau.csv"),
    "precision": (["precision", "one_dof", "--set", "tau=0.3", "--no-peers", "--quick",
                   "--methods", "dp54"], "one_dof_precision.json"),
    "profile": (["profile", *STEADY], "cam.dxf"),
    "laws --tau": (["laws", "--tau", "0.15", "--no-error-estimate"], "laws_selection.csv"),
    "laws --sweep": (["laws", "--sweep", "spring_loaded", "--n", "2", "--no-error-estimate"],
                     "laws_sweep.png"),
    "design": (["design", "--stroke", "0.03", "--tau", "0.1", "--fa", "0.5", "--accuracy",
                "1e-4", "--no-check", "--quiet"], "design.json"),
    "figures": (["figures", "--only", "3.4", "--quiet"], "index.html"),
    "integrate": (["integrate", "one_dof", "--t-end", "2", "--set", "tau=0.3"], "one_dof.csv"),
    "beam-follower": (["beam-follower"], "fig4_speed.png"),
}


def _line(capsys) -> str:
    err = capsys.readouterr().err.strip().splitlines()
    return err[-1] if err else ""


def _beam_file():
    from camdyn.runtime.targets.beam_scene import BeamTarget

    return BeamTarget.figure_files()[0]


def _args(name):
    argv, file = COMMANDS[name]
    return argv, (_beam_file() if name == "beam-follower" else file)


@pytest.mark.parametrize("name", list(COMMANDS))
def test_a_file_camdyn_did_not_write_is_refused_and_kept(tmp_path, capsys, name):
    """The user's own file of a name the command writes: exit 2, one line naming it, the file
    as it was; --overwrite is what replaces it."""
    argv, file = _args(name)
    out = tmp_path / "out"
    out.mkdir()
    (out / file).write_text("my own work\n")
    (out / "notes.md").write_text("mine too\n")
    assert main([*argv, "--out", str(out)]) == 2
    assert _line(capsys) == (f"camdyn {argv[0]}: error: argument --out: {out / file} exists "
                             "and camdyn did not write it; --overwrite replaces it (or give "
                             "another --out)")
    assert (out / file).read_text() == "my own work\n"
    assert (out / "notes.md").read_text() == "mine too\n"


@pytest.mark.parametrize("name", ["sweep", "profile", "integrate", "figures"])
def test_a_rerun_replaces_its_own_files_and_leaves_the_users(tmp_path, capsys, name):
    """The same command into the same folder again needs no --overwrite: every file it wrote
    is in the folder's record with the SHA-256 of its content; a file of the user's beside
    them is not touched (nor recorded)."""
    argv, _ = _args(name)
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.md").write_text("mine\n")
    for _ in range(2):
        assert main([*argv, "--out", str(out)]) == 0
    capsys.readouterr()
    record = json.loads((out / outdir.RECORD).read_text())["files"]
    assert "notes.md" not in record and (out / "notes.md").read_text() == "mine\n"
    written = sorted(p.name for p in out.iterdir() if p.is_file() and p.name[0] != ".")
    assert sorted(record) == [n for n in written if n != "notes.md"]
    for n, e in record.items():
        assert e["sha256"] == outdir.digest(out / n), n


def test_a_file_changed_since_camdyn_wrote_it_is_refused_overwrite_replaces_it(tmp_path, capsys):
    """A table camdyn wrote and the user edited is the user's work now: refused, naming it;
    --overwrite writes it afresh and records it again."""
    out = tmp_path / "cam"
    assert main(["profile", *STEADY, "--out", str(out)]) == 0
    original = (out / "cam.csv").read_text()
    (out / "cam.csv").write_text(original + "my note\n")
    assert main(["profile", *STEADY, "--out", str(out)]) == 2
    assert _line(capsys) == (f"camdyn profile: error: argument --out: {out / 'cam.csv'} was "
                             "changed since camdyn wrote it; --overwrite replaces it (or give "
                             "another --out)")
    assert (out / "cam.csv").read_text() == original + "my note\n"
    assert main(["profile", *STEADY, "--out", str(out), "--overwrite"]) == 0
    assert (out / "cam.csv").read_text() == original
    assert outdir.entry(out / "cam.csv")["sha256"] == outdir.digest(out / "cam.csv")


def test_the_record_decides_what_camdyn_may_replace(tmp_path):
    """claim/writing/entry from Python: a new name may be written; a file without a record,
    with a record it no longer matches, or behind an unreadable record is refused; a
    session with overwrite (--overwrite) may replace any; a folder where a file goes never."""
    new = tmp_path / "a.txt"
    assert outdir.claim(new) == new
    with outdir.writing(new) as p:
        p.write_text("one")
    assert outdir.entry(new)["sha256"] == outdir.digest(new)
    assert outdir.write_text(new, "two") == new           # camdyn's and unchanged
    new.write_text("edited")
    with pytest.raises(OutFolderError, match="was changed since camdyn wrote it"):
        outdir.claim(new)
    theirs = tmp_path / "b.txt"
    theirs.write_text("theirs")
    with pytest.raises(OutFolderError, match="exists and camdyn did not write it"):
        outdir.write_text(theirs, "x")
    assert theirs.read_text() == "theirs"
    with outdir.session(overwrite=True) as s:
        outdir.write_text(theirs, "x")
    assert theirs.read_text() == "x" and s.written == [theirs]
    (tmp_path / outdir.RECORD).write_text("{not json")
    with pytest.raises(OutFolderError, match="exists and camdyn did not write it"):
        outdir.claim(theirs)
    (tmp_path / "c.txt").mkdir()
    with outdir.session(overwrite=True), pytest.raises(OutFolderError, match="is a folder"):
        outdir.claim(tmp_path / "c.txt")


def _unwritable(monkeypatch, folder):
    """open() refuses to write anything below ``folder``, as a read-only folder would (the
    tests run as root, for whom permissions do not)."""
    real = builtins.open

    def guarded(file, mode="r", *args, **kwargs):
        if any(c in mode for c in "wax+") and str(os.fspath(file)).startswith(str(folder)):
            raise PermissionError(13, "Permission denied", os.fspath(file))
        return real(file, mode, *args, **kwargs)

    monkeypatch.setattr(builtins, "open", guarded)
    monkeypatch.setattr(io, "open", guarded)


LONG = ("beam-follower", "laws --tau", "design")
"""Commands whose files come after runs of more than a few seconds."""


@pytest.mark.parametrize("name", [n for n in COMMANDS if n not in LONG]
                         + [pytest.param(n, marks=pytest.mark.slow) for n in LONG])
def test_a_folder_that_cannot_be_written_is_one_line(tmp_path, capsys, monkeypatch, name):
    """Writing any file fails (permission denied): one line naming the file and --out, exit
    2, no traceback; the folder had to exist (a missing one would be made)."""
    argv, _ = _args(name)
    out = tmp_path / "out"
    out.mkdir()
    _unwritable(monkeypatch, out)
    assert main([*argv, "--out", str(out)]) == 2
    line = _line(capsys)
    assert re.fullmatch(rf"camdyn {argv[0]}: error: argument --out: cannot write "
                        rf"{re.escape(str(out))}/\S+: Permission denied; give --out a folder "
                        "camdyn can write", line), line


def test_an_unwritable_folder_is_refused_before_the_runs(tmp_path, capsys, monkeypatch):
    """os.access says the folder is not writable: the sweep is refused before it runs."""
    monkeypatch.setattr(os, "access", lambda path, mode: False)
    assert main(["sweep", "one_dof", "--grid", "tau=0.2", "--out", str(tmp_path)]) == 2
    assert _line(capsys) == (f"camdyn sweep: error: argument --out: the folder {tmp_path} is "
                             "not writable; give --out a folder camdyn can write")
