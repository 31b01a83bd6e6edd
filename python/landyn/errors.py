"""The exceptions of the landyn package: one class per failure status of the C API.

    LandynError                 base class of everything this package raises
     +-- LandynLibraryError     liblandyn.so not found, not loadable, or lacking a function
     +-- LandynInputError       invalid deck, override or argument (LANDYN_ERR_INPUT); the message
     |    |                     names group, variable and value, every problem of a deck
     |    +-- LandynOutputNameError   unknown output name (also a KeyError; suggests the closest)
     +-- LandynOrderError       call out of order: time going backwards, past t_end, set_input
     |                          after the run ended, advancing after a failure (LANDYN_ERR_ORDER)
     +-- LandynFailedError      the simulation failed (diverged); write_result still works
     |                          (LANDYN_ERR_FAILED)
     +-- LandynFileError        the result file could not be written (LANDYN_ERR_FILE)
     +-- LandynClosedError      the Simulation was closed (or its handle is not live: LANDYN_ERR_HANDLE)
"""
from __future__ import annotations


class LandynError(Exception):
    """Base class of every exception of the landyn package. ``status``: the C API's status code (0 if none)."""

    status = 0

    def __init__(self, message: str, status: int = 0) -> None:
        super().__init__(message)
        self.message = message
        if status:
            self.status = status

    def __str__(self) -> str:
        return self.message


class LandynLibraryError(LandynError):
    """liblandyn.so was not found, could not be loaded, or lacks a function of include/landyn.h."""


class LandynInputError(LandynError):
    """Invalid deck text, override or argument (LANDYN_ERR_INPUT); the message lists every problem."""

    status = 1


class LandynOutputNameError(LandynInputError, KeyError):
    """An output name the simulation does not have (the message suggests the closest one)."""

    def __str__(self) -> str:  # KeyError would quote the message
        return self.message


class LandynOrderError(LandynError):
    """A call out of order: time going backwards, past t_end, after the run ended or failed (LANDYN_ERR_ORDER)."""

    status = 3


class LandynFailedError(LandynError):
    """The simulation failed (diverged) (LANDYN_ERR_FAILED); write_result still writes what was run."""

    status = 4


class LandynFileError(LandynError):
    """The result file could not be written (LANDYN_ERR_FILE); the message says why."""

    status = 5


class LandynClosedError(LandynError):
    """The Simulation was closed, or its handle is not a live one (LANDYN_ERR_HANDLE)."""

    status = 2


_BY_STATUS = {1: LandynInputError, 2: LandynClosedError, 3: LandynOrderError, 4: LandynFailedError,
              5: LandynFileError}


def error_for(status: int, message: str) -> LandynError:
    """The exception for a failure status of the C API, with the library's message."""
    cls = _BY_STATUS.get(status, LandynError)
    return cls(message or f"LANDYN status {status}", status)
