# SPDX-License-Identifier: GPL-3.0-or-later
"""The library's errors as Python exceptions.

Every function of libhybounce returns 0 or an enum hb_status and leaves a
message in a buffer (or, for a run, in hb_sim_errmsg); the module raises
the exception of that status with that message, unchanged:

    HybounceError          any of them; .status (the code), .message
      InputError           HB_EINVAL: bad input (also a ValueError)
      NoMemoryError        HB_ENOMEM (also a MemoryError)
      FileError            HB_EIO: a file could not be read or written (also an OSError)
      NumericError         HB_ENUMERIC: the integration failed
      ChatterError         HB_ECHATTER: a run would jump without end at one instant
      DoneError            HB_EDONE: the run had already ended, or a sweep was stopped
"""


class HybounceError(Exception):
    """An error of libhybounce: .status is its code, .message its message."""

    status = None

    def __init__(self, message, status=None):
        super().__init__(message)
        self.message = message
        if status is not None:
            self.status = status

    def __str__(self):
        return self.message


class InputError(HybounceError, ValueError):
    status = 1


class NoMemoryError(HybounceError, MemoryError):
    status = 2


class FileError(HybounceError, OSError):
    status = 3

    def __str__(self):
        return self.message


class NumericError(HybounceError):
    status = 4


class ChatterError(HybounceError):
    status = 5


class DoneError(HybounceError):
    status = 6


_BY_STATUS = {c.status: c for c in (InputError, NoMemoryError, FileError, NumericError,
                                     ChatterError, DoneError)}


def error(status, message):
    """The exception for a status and its message (not raised)."""
    cls = _BY_STATUS.get(status, HybounceError)
    if not message:
        message = "status %d" % status
    e = cls(message, status)
    return e


def check(status, msg):
    """Raises the error of a nonzero status with the message in the char[] msg."""
    if status != 0:
        from ._lib import text
        raise error(status, text(msg))
