# SPDX-License-Identifier: GPL-3.0-or-later
"""The library, loaded once: cffi's ABI mode over libhybounce.so with the
declarations of its public headers (_cdef.py, generated from them at build
time by python/gen_cdef.py).

Where the library is looked for, in order: $HYBOUNCE_LIB (a path), then
the places _cdef.LIBRARIES names (the build tree's libhybounce.so for a
package built by `make python`; the installed soname, then the same file
under the install's LIBDIR, for a package installed by `make install`).

Two things happen here once, at import:
  - the version check: the library's hb_version() must be the version of
    the headers the package was generated from (_cdef.HEADER_VERSION):
    another library may have other struct layouts, and is refused with an
    ImportError that names both versions and where each came from;
  - GSL's error handler is turned off (gsl_set_error_handler_off, from the
    libgsl the library itself links): GSL's default handler aborts the
    process, which would take the Python interpreter with it; turned off,
    a GSL error comes back as a status, which the library turns into an
    error with its message.  libhybounce leaves that choice to its host (it
    changes nothing that belongs to the process); this module, as a host,
    makes it, as the hybounce program does.  It is process-wide: a program
    that imports hybounce and wants GSL's handler back calls
    gsl_set_error_handler itself after the import.
"""
import os

import cffi

from . import _cdef

ffi = cffi.FFI()
ffi.cdef(_cdef.CDEF)
# from libgsl, which libhybounce links: turning its handler off (above)
ffi.cdef("void *gsl_set_error_handler_off(void);")
# from the C library: the preset text hb_preset_open_text hands over
ffi.cdef("void free(void *);")
libc = ffi.dlopen(None)

MSG = 4096  # the size of the message buffers handed to the library


def _open():
    env = os.environ.get("HYBOUNCE_LIB")
    tried = []
    names = [env] if env else list(_cdef.LIBRARIES)
    for name in names:
        try:
            return ffi.dlopen(name), name
        except OSError as e:
            tried.append("%s (%s)" % (name, e))
    where = "$HYBOUNCE_LIB" if env else "the places this package was built for"
    raise ImportError("hybounce: cannot load libhybounce from %s: %s; set HYBOUNCE_LIB to the "
                      "path of libhybounce.so.%s" % (where, "; ".join(tried), _cdef.SOVERSION))


lib, LIBRARY = _open()
LIBRARY_VERSION = ffi.string(lib.hb_version()).decode()
LIBRARY_COMMIT = ffi.string(lib.hb_version_commit()).decode()


def check_version(package_version, library_version, library_path):
    """Refuses a library whose version is not the package's (ImportError)."""
    if package_version != library_version:
        raise ImportError(
            "hybounce: the Python package is version %s (generated from the headers of "
            "libhybounce %s) but the library it loaded, %s, is version %s: their structures "
            "may differ, so it is refused; rebuild the package with `make python` (or install "
            "both with `make install`), or point HYBOUNCE_LIB at libhybounce %s"
            % (package_version, package_version, library_path, library_version, package_version))


check_version(_cdef.HEADER_VERSION, LIBRARY_VERSION, LIBRARY)


def _gsl_off():
    # the libgsl of libhybounce's own link (its soname, found at build
    # time): already loaded with it, so dlopen finds that same copy
    for name in _cdef.GSL_LIBRARIES:
        try:
            gsl = ffi.dlopen(name)
        except OSError:
            continue
        gsl.gsl_set_error_handler_off()
        return gsl
    raise ImportError("hybounce: cannot open libgsl (%s) to turn its error handler off"
                      % ", ".join(_cdef.GSL_LIBRARIES))


_gsl = _gsl_off()


def msgbuf():
    return ffi.new("char[]", MSG)


def text(p):
    """A C string (char * or char[]) as str; None for NULL."""
    if p == ffi.NULL:
        return None
    return ffi.string(p).decode("utf-8", "replace")
