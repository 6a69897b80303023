# SPDX-License-Identifier: GPL-3.0-or-later
# The package's version is the library's; a library of another version is
# refused at import with a clear message; the import turns GSL's error
# handler off.
import os
import shutil
import subprocess
import sys

import pytest

import hybounce


def test_the_version_is_the_librarys():
    assert hybounce.__version__ == hybounce.LIBRARY_VERSION
    assert hybounce.__version__ == hybounce.ffi.string(hybounce.lib.hb_version()).decode()


def test_a_mismatch_is_refused_by_the_check():
    from hybounce._lib import check_version
    with pytest.raises(ImportError, match=r"package is version 9\.9\.9.*libhybounce.* is version 0"):
        check_version("9.9.9", "0.2.0", "/lib/libhybounce.so.1")
    check_version("0.2.0", "0.2.0", "/lib/libhybounce.so.1")


def test_a_package_generated_for_another_version_is_refused_at_import(tmp_path):
    # a copy of the package whose headers "were" of another version
    pkg = os.path.dirname(hybounce.__file__)
    shutil.copytree(pkg, tmp_path / "hybounce", ignore=shutil.ignore_patterns("__pycache__"))
    cdef = tmp_path / "hybounce" / "_cdef.py"
    text = cdef.read_text().replace("HEADER_VERSION = %r" % hybounce.__version__,
                                    "HEADER_VERSION = '0.0.1'")
    assert "HEADER_VERSION = '0.0.1'" in text
    cdef.write_text(text)
    p = subprocess.run([sys.executable, "-c", "import hybounce"], capture_output=True, text=True,
                       env=dict(os.environ, PYTHONPATH=str(tmp_path)))
    assert p.returncode != 0
    assert "ImportError: hybounce: the Python package is version 0.0.1" in p.stderr
    assert "is version %s" % hybounce.__version__ in p.stderr and "refused" in p.stderr


def test_a_missing_library_is_named(tmp_path):
    p = subprocess.run([sys.executable, "-c", "import hybounce"], capture_output=True, text=True,
                       env=dict(os.environ, HYBOUNCE_LIB=str(tmp_path / "libnone.so")))
    assert p.returncode != 0 and "cannot load libhybounce from $HYBOUNCE_LIB" in p.stderr
    assert str(tmp_path / "libnone.so") in p.stderr


def test_the_import_turns_gsl_error_handler_off():
    # gsl_set_error_handler_off returns the handler it replaces: GSL's
    # default is NULL (abort); after the import it is GSL's "off" handler
    code = ("import hybounce._lib as L; h = L._gsl.gsl_set_error_handler_off(); "
            "print(h != L.ffi.NULL)")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert p.returncode == 0 and p.stdout.strip() == "True", p.stderr
