"""Ctrl-C and SIGTERM: a command stops by an exception the command line turns into one line
saying what was kept (README "Stopping a command"), and never between a file's last byte and
its record in the --out folder (runtime/core/outdir.py), so nothing is left half written.

Inside :func:`handled` (the command line's ``main``) SIGINT and SIGTERM raise
:class:`Interrupted`, whose ``status`` is the shell's 128 + the signal's number (130, 143);
inside :func:`held` a signal waits until the block ends.  Both act in the main thread only,
where Python runs signal handlers; elsewhere they change nothing.
"""
from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

SIGNALS = (signal.SIGINT, signal.SIGTERM)
"""The signals that stop a command: Ctrl-C and a polite kill."""


class Interrupted(KeyboardInterrupt):
    """SIGINT or SIGTERM arrived.  A KeyboardInterrupt, so that whatever cleans up after
    Ctrl-C (``finally`` blocks, a progress bar, a thread pool) cleans up after SIGTERM too."""

    def __init__(self, signum: int):
        super().__init__(signal.Signals(signum).name)
        self.signum = int(signum)

    @property
    def status(self) -> int:
        """The exit status a shell gives a command the signal ended: 128 + its number."""
        return 128 + self.signum


class _State:
    depth = 0              # how many held() blocks are open in the main thread
    pending = None         # the signal that arrived inside them


def _main_thread() -> bool:
    return threading.current_thread() is threading.main_thread()


def _raise(signum, frame):
    if _State.depth:
        if _State.pending is None:
            _State.pending = signum
        return
    raise Interrupted(signum)


@contextmanager
def handled():
    """SIGINT and SIGTERM raise :class:`Interrupted` inside the block; the handlers before
    it come back after it."""
    if not _main_thread():
        yield
        return
    before = {s: signal.getsignal(s) for s in SIGNALS}
    for s in SIGNALS:
        signal.signal(s, _raise)
    try:
        yield
    finally:
        for s, h in before.items():
            signal.signal(s, h)
        _State.pending = None


@contextmanager
def held():
    """A signal arriving inside the block is raised when it ends (the outermost block), so
    that what the block writes is written whole."""
    if not _main_thread():
        yield
        return
    _State.depth += 1
    try:
        yield
    finally:
        _State.depth -= 1
        if not _State.depth and _State.pending is not None:
            signum, _State.pending = _State.pending, None
            raise Interrupted(signum)
