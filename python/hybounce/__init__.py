# SPDX-License-Identifier: GPL-3.0-or-later
"""hybounce: the hybounce engine (libhybounce) from Python.

    >>> import hybounce
    >>> run = hybounce.Run("steel-on-bitumen")
    >>> run.set("law.c", "44 kN s/m").run()
    >>> run.arc.t, run.arc.x_c, run.arc.F_c      # NumPy views, no copy
    >>> run.collisions["e"]                      # structured array
    >>> hybounce.sweep(run, {"initial.v0": "-0.1:-1:100"}).runs["e_first"]
    >>> hybounce.fit(run, "bounces.csv", ["law.c"]).value

The package's version is the library's (hb_version()); a library of
another version is refused at import.  Importing it turns GSL's error
handler off for the process (see _lib.py): a GSL error then comes back as
an error with its message instead of aborting Python.
"""
from ._lib import LIBRARY, LIBRARY_COMMIT, LIBRARY_VERSION, ffi, lib
from ._cdef import HEADER_VERSION as __version__
from .errors import (ChatterError, DoneError, FileError, HybounceError, InputError,
                     NoMemoryError, NumericError)
from .run import Arc, ErrorBars, Run, collision_columns, collision_dtype, open, sample_dtype
from .sweep import SweepResult, sweep
from .fit import FitResult, fit

__all__ = ["Run", "Arc", "ErrorBars", "open", "sweep", "SweepResult", "fit", "FitResult",
           "HybounceError", "InputError", "NoMemoryError", "FileError", "NumericError",
           "ChatterError", "DoneError", "collision_columns", "collision_dtype",
           "sample_dtype", "presets", "__version__"]


def presets():
    """The presets found ({name: title}), as hybounce --list-presets lists them."""
    out = ffi.new("struct hb_preset_info **")
    n = lib.hb_preset_list(out)
    if n < 0:
        raise NoMemoryError("no memory to list the presets")
    try:
        return {ffi.string(out[0][k].name).decode(): ffi.string(out[0][k].title).decode()
                for k in range(n)}
    finally:
        from ._lib import libc
        libc.free(out[0])
