"""Errors users see: bad input is named, failed runs say where they failed."""


class CamdynInputError(ValueError):
    """A parameter, option or argument is missing, of the wrong type or out of range.

    The message names the offending item and its admissible range; the CLI
    prints it on one line and exits with status 2.
    """


class SimulationError(RuntimeError):
    """An integration stopped early (step budget, non-finite state, ...)."""
