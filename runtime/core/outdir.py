"""The --out folder of a command: made, or refused in one line; and what camdyn may write in it.

Every command that writes files goes through here (README "Where commands write"): the folder
by :func:`out_folder`, each file by :func:`writing` (or :func:`write_text`, or
:class:`Growing` for a file written piece by piece, a sweep's table).  A file that cannot be
written (a read-only folder, a full disk) ends the command in one line naming it and --out.
While a file is written, Ctrl-C and SIGTERM wait for its last byte and its record
(runtime/core/signals.py); the files written so far are what :class:`Session` says was kept.
"""
from __future__ import annotations

import hashlib
import json
import os
from contextlib import contextmanager
from pathlib import Path

from .errors import OutFolderError
from .signals import held

RECORD = ".camdyn-written"
"""The record camdyn keeps in every folder it writes into (see :func:`out_folder`)."""

_ABOUT = ("The files camdyn wrote in this folder, each with the SHA-256 of what it wrote. "
          "camdyn replaces a file only while it is listed here and unchanged; "
          "--overwrite replaces any.")


def out_folder(out, create: bool = True, files=()):
    """The folder an --out names, made (``create``) or only checked: one that cannot be made
    (below a file, not writable) is an OutFolderError naming --out.  Commands check before
    their runs, so that a bad --out is refused first and a refused input leaves no folder,
    and make it when they write.  ``files``: names the command will write there, each
    claimed now (:func:`claim`), so that a file it may not replace is refused before the
    runs.  None stays None.

    A command never replaces a file in the folder that camdyn did not write.  Each folder
    camdyn writes into keeps a record, ``.camdyn-written`` (JSON: every file camdyn wrote
    there, by name, with the SHA-256 of what it wrote), and a file of the same name is
    replaced only while the record lists it *and* it still holds what camdyn wrote: a
    user's own file (a ``notes.md``, their own ``sweep.csv``), and one of camdyn's edited
    since (a report annotated, a table cleaned up by hand), are the user's work, and the
    command is refused in one line naming the first such file unless --overwrite
    (:func:`claim`).  Re-running a command into the same folder replaces its own files
    without a word.  A file found where the record is missing or unreadable (a folder
    written before camdyn kept one, the record deleted) counts as the user's: a refusal
    costs one --overwrite, a lost file costs the work in it.  From Python, ``with
    session(overwrite=True):`` is --overwrite."""
    if out is None:
        return None
    path = Path(out)
    if not create:
        probe = path
        while not probe.exists() and probe != probe.parent:
            probe = probe.parent
        if probe == path and path.is_dir() and not os.access(path, os.W_OK | os.X_OK):
            raise OutFolderError(f"argument --out: the folder {path} is not writable; give "
                                 "--out a folder camdyn can write")
        if not probe.is_dir() or not os.access(probe, os.W_OK | os.X_OK):
            why = "not a folder" if not probe.is_dir() else "not writable"
            raise OutFolderError(f"argument --out: cannot create the folder {path}: "
                                 f"{probe} is {why}")
    else:
        try:
            path.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise OutFolderError(f"argument --out: cannot create the folder {path}: "
                                 f"{exc.strerror or exc}") from None
        # a folder that exists read-only is made without a word by mkdir(exist_ok=True):
        # refused here, before the runs a command makes this call ahead of, not at its
        # first write after them
        if not os.access(path, os.W_OK | os.X_OK):
            raise OutFolderError(f"argument --out: the folder {path} is not writable; give "
                                 "--out a folder camdyn can write")
    for name in files:
        claim(path / name)
    return path


# -- one command's writing -----------------------------------------------------------------------

class Session:
    """One command's writing: whether it may replace any file (--overwrite), the files it
    wrote so far and, where a command says it better, what it has kept (a sweep's rows)."""

    def __init__(self, overwrite: bool = False):
        self.overwrite = bool(overwrite)
        self.written: list[Path] = []
        self.note: str | None = None

    def kept(self) -> str:
        """What an interrupted command leaves, in words."""
        if self.note:
            return self.note
        if not self.written:
            return "no files written"
        folders = sorted({str(p.parent) for p in self.written})
        names = [p.name if len(folders) == 1 else str(p) for p in self.written]
        shown = ", ".join(names[:4]) + (", ..." if len(names) > 4 else "")
        where = f" in {folders[0]}" if len(folders) == 1 else ""
        return f"{len(names)} file{'s' if len(names) > 1 else ''} kept{where}: {shown}"


class _Now:
    session: Session | None = None


@contextmanager
def session(overwrite: bool = False):
    """The writing of one command (the command line opens one per command)."""
    before, _Now.session = _Now.session, Session(overwrite)
    try:
        yield _Now.session
    finally:
        _Now.session = before


def note(text: str) -> None:
    """What the running command has kept so far, in its own words (for the line an
    interruption ends it with)."""
    if _Now.session is not None:
        _Now.session.note = text


# -- the record -----------------------------------------------------------------------------------

def digest(path) -> str:
    """SHA-256 of a file's content."""
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _entries(folder: Path) -> dict:
    try:
        data = json.loads((folder / RECORD).read_text())
    except (OSError, ValueError):
        return {}
    files = data.get("files") if isinstance(data, dict) else None
    return files if isinstance(files, dict) else {}


@contextmanager
def _locked(folder: Path):
    """The folder's record to oneself (two commands writing into one folder at once)."""
    try:
        import fcntl
    except ImportError:             # no flock: commands rarely share a folder at once
        yield
        return
    fd = os.open(folder, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)


def _record(path: Path, sha256: str, about=None) -> None:
    folder = path.parent
    with _locked(folder):
        files = _entries(folder)
        files[path.name] = {"sha256": sha256, **({"about": about} if about is not None else {})}
        tmp = folder / f"{RECORD}.{os.getpid()}"
        tmp.write_text(json.dumps({"about": _ABOUT, "files": files}, indent=1, sort_keys=True))
        os.replace(tmp, folder / RECORD)
    if _Now.session is not None and path not in _Now.session.written:
        _Now.session.written.append(path)


def entry(path) -> dict | None:
    """The record of a file camdyn wrote and nobody changed since (its "sha256" and the
    "about" it was written with), or None."""
    path = Path(path)
    if path.is_symlink() or not path.is_file():
        return None
    e = _entries(path.parent).get(path.name)
    if not isinstance(e, dict):
        return None
    try:
        same = digest(path) == e.get("sha256")
    except OSError:
        return None
    return e if same else None


def claim(path) -> Path:
    """``path``, if camdyn may write it (:func:`out_folder`): it does not exist, or camdyn
    wrote it and it is unchanged, or --overwrite; else a refusal naming it."""
    path = Path(path)
    if not os.path.lexists(path):
        return path
    if path.is_dir() and not path.is_symlink():
        raise OutFolderError(f"argument --out: {path} is a folder where camdyn writes a "
                             "file; give another --out")
    if (_Now.session is not None and _Now.session.overwrite) or entry(path) is not None:
        return path
    why = ("was changed since camdyn wrote it" if path.name in _entries(path.parent)
           else "exists and camdyn did not write it")
    raise OutFolderError(f"argument --out: {path} {why}; --overwrite replaces it (or give "
                         "another --out)")


@contextmanager
def _reported(path: Path):
    try:
        yield
    except OSError as exc:
        raise OutFolderError(f"argument --out: cannot write {path}: {exc.strerror or exc}; "
                             "give --out a folder camdyn can write") from None


@contextmanager
def writing(path, about=None):
    """Write the file ``path`` inside the block (the block gets the path): claimed first
    (:func:`claim`), its folder made, and recorded as camdyn's when the block ends; a
    signal arriving meanwhile waits for that.  ``about`` goes into its record."""
    path = claim(path)
    with held(), _reported(path):
        path.parent.mkdir(parents=True, exist_ok=True)
        yield path
        _record(path, digest(path), about)


def write_text(path, text: str) -> Path:
    """Write ``text`` to ``path`` through :func:`writing`; returns the path."""
    with writing(path) as p:
        p.write_text(text)
    return p


class Growing:
    """A file written piece by piece (a sweep's table, row by row): every piece written
    whole, flushed and recorded, so that an interrupted command leaves each piece it
    finished, recorded as camdyn's.  ``append``: continue the file (its record must be
    camdyn's, :func:`entry`); else it starts afresh with ``first``."""

    def __init__(self, path, first: str = "", *, append: bool = False, about=None):
        self.path, self.about = Path(path), about
        if append and entry(self.path) is None:
            raise OutFolderError(f"{self.path} was not written by camdyn or was changed "
                                 "since; it cannot be continued")
        if not append:
            claim(self.path)
        with held(), _reported(self.path):
            self.path.parent.mkdir(parents=True, exist_ok=True)
            self._hash = hashlib.sha256(self.path.read_bytes() if append else b"")
            self._fh = open(self.path, "ab" if append else "wb")
            self._put(first)

    def add(self, text: str) -> None:
        with held(), _reported(self.path):
            self._put(text)

    def _put(self, text: str) -> None:
        data = text.encode()
        self._fh.write(data)
        self._fh.flush()
        self._hash.update(data)
        _record(self.path, self._hash.hexdigest(), self.about)

    def close(self) -> None:
        self._fh.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
