"""Errors users see: bad input is named, failed runs say where they failed."""


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
