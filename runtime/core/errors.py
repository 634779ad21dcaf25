"""Errors users see: bad input is named, failed runs say where they failed; and the checks of
the paths users give (folders to write in, files to read) that name them."""


class CamdynInputError(ValueError):
    """A parameter, option or argument is missing, of the wrong type or out of range.

    The message names the offending item and its admissible range; the CLI
    prints it on one line and exits with status 2.
    """


class SimulationError(RuntimeError):
    """An integration stopped early (step budget, non-finite state, ...)."""


class UnstableStep(SimulationError):
    """A fixed step refused because it lies beyond the method's stability boundary.

    ``estimate`` is the check's :class:`camdyn.runtime.core.stability.Estimate` (h rho, the
    boundary, the largest stable step).  A SimulationError, so every caller that catches
    failed runs catches it too; the stability map tells it apart from a run that blew up.
    """

    def __init__(self, message: str, estimate=None):
        super().__init__(message)
        self.estimate = estimate


class OutFolderError(CamdynInputError):
    """The --out folder cannot take a command's files: it cannot be made or written, or a
    file there is not camdyn's to replace (runtime/core/outdir.py).  Whatever else a command
    tolerates from a part of its work, this ends it."""


def writable_folder(path, what: str = "folder", hint: str = "", argument: str = ""):
    """The folder ``path``, made where missing, that this process may write in; else a
    CamdynInputError naming the ``argument`` it came from and ``what`` it is, followed by
    ``hint`` (what to do)."""
    import os
    from pathlib import Path

    path = Path(path)
    lead = f"{argument}: " if argument else ""
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        why = "a file is in its place" if isinstance(exc, FileExistsError) else \
            exc.strerror or str(exc)
        raise CamdynInputError(f"{lead}cannot create the {what} {path}: {why}{hint}") from None
    if not os.access(path, os.W_OK | os.X_OK):
        raise CamdynInputError(f"{lead}cannot write in the {what} {path}: not writable{hint}")
    return path


def on_disk(path) -> str | None:
    """What ``path`` is on disk, from os.stat alone: "file" (a regular one), "folder", "named
    pipe", "device" or "socket"; None where nothing is (or a file lies on the way).  Nothing
    is opened: a reader of a named pipe blocks until a writer comes, one of /dev/zero never
    reaches the end."""
    import os
    import stat

    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):      # missing, below a file, a NUL in the name
        return None
    if stat.S_ISREG(mode):
        return "file"
    if stat.S_ISDIR(mode):
        return "folder"
    if stat.S_ISFIFO(mode):
        return "named pipe"
    if stat.S_ISSOCK(mode):
        return "socket"
    return "device"
