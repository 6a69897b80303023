# SPDX-License-Identifier: GPL-3.0-or-later
"""NumPy views of the library's arrays of structs, without a copy.

A struct's dtype is made from cffi's own view of the struct (the offsets
and the size the generated declarations give, padding included), so a
column of a view is a strided array over the library's memory: for
struct hb_arc_sample, t is a float64 array with a stride of
sizeof(struct hb_arc_sample) bytes (152 on x86-64), not a copy.

The memory stays the library's; a view keeps the object that owns it
(the run's sim) alive for as long as the view lives, and is read-only
(the library owns it; np.array(view) makes a writable copy).
"""
import numpy as np

from ._lib import ffi


def _scalar(t):
    if t.kind != "primitive":
        return None
    if t.cname in ("double", "float"):
        return np.dtype("f%d" % ffi.sizeof(t))
    if t.cname == "char":
        return np.dtype("S1")
    unsigned = t.cname.startswith("unsigned") or t.cname in ("size_t", "uintptr_t")
    return np.dtype(("u%d" if unsigned else "i%d") % ffi.sizeof(t))


def struct_dtype(ctype, rename=None):
    """The NumPy dtype of a C struct: its numeric members at their offsets,
    named as in C (or as rename maps an offset), pointers left out."""
    t = ffi.typeof(ctype)
    rename = rename or {}
    names, formats, offsets = [], [], []
    for name, f in t.fields:
        ft = f.type
        if ft.kind == "array":
            item = _scalar(ft.item)
            if item is None:
                continue
            fmt = np.dtype("S%d" % ft.length) if item == np.dtype("S1") else np.dtype((item, (ft.length,)))
        else:
            fmt = _scalar(ft)
            if fmt is None:
                continue
        names.append(rename.get(f.offset, name))
        formats.append(fmt)
        offsets.append(f.offset)
    return np.dtype({"names": names, "formats": formats, "offsets": offsets,
                     "itemsize": ffi.sizeof(t)})


def view(ptr, n, dtype, owner):
    """A read-only structured array over n structs at ptr, keeping owner alive."""
    if n == 0 or ptr == ffi.NULL:
        return np.zeros(0, dtype)
    # a pointer that holds owner: its "destructor" is a closure over owner,
    # and ffi.buffer, then the array, hold the pointer
    kept = ffi.gc(ffi.cast(ffi.typeof(ptr), ptr), lambda _p, _o=owner: None)
    arr = np.frombuffer(ffi.buffer(kept, n * dtype.itemsize), dtype=dtype)
    arr.flags.writeable = False
    return arr
