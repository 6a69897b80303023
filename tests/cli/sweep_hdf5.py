# SPDX-License-Identifier: GPL-3.0-or-later
"""sweep_hdf5.py H5 CSVDIR [refined]: DIR/sweep.h5 as h5py and pandas read it
holds what runs.csv and collisions.csv of the same sweep hold (numbers to
the bit, texts, empty fields as NaN), chunked and compressed, with units,
columns and the spec as attributes.  Exits 0, or 1 naming what differs
(used by tests/cli/sweep_hdf5.sh)."""
import sys

import h5py
import numpy as np
import pandas as pd


def fail(what):
    print(what)
    sys.exit(1)


h5, csvdir = sys.argv[1], sys.argv[2]
f = h5py.File(h5, "r")
for key in ("spec", "hybounce", "provenance"):
    if key not in f.attrs:
        fail("no root attribute " + key)
spec = f.attrs["spec"]
spec = spec.decode() if isinstance(spec, bytes) else spec
if "; sweep: --vary " not in spec:
    fail("the spec attribute lacks the axes")
for name in ("runs", "collisions"):
    d = f[name]
    if d.chunks is None or d.compression != "gzip" or not d.shuffle:
        fail(name + ": not chunked, shuffled and compressed")
    cols = [c.decode() if isinstance(c, bytes) else c for c in d.attrs["columns"]]
    units = [u.decode() if isinstance(u, bytes) else u for u in d.attrs["units"]]
    if cols != list(d.dtype.names) or len(units) != len(cols):
        fail(name + ": attributes columns/units do not match the fields")
    want = pd.read_csv(f"{csvdir}/{name}.csv", float_precision="round_trip",
                       keep_default_na=False, na_values=[""])
    got = pd.DataFrame(d[()])
    if list(got.columns) != list(want.columns) or len(got) != len(want):
        fail(f"{name}: columns or rows differ: {list(got.columns)} {len(got)} vs "
             f"{list(want.columns)} {len(want)}")
    for c in want.columns:
        if c == "cpu_s":
            continue
        a, b = got[c], want[c]
        if a.dtype == object:
            same = (a.str.decode("utf-8") == b.fillna("").astype(str)).all()
        else:
            same = np.array_equal(a.to_numpy(dtype=float), b.to_numpy(dtype=float),
                                  equal_nan=True)
        if not same:
            fail(f"{name}.{c} differs")
    u = dict(zip(cols, units))
    if name == "runs" and (u.get("t_pc") != "s" or u.get("initial.v0") != "m/s"
                           or u.get("cpu_s") != "s"):
        fail("runs: units " + repr(u))
    if name == "collisions" and (u.get("t_e") != "s" or u.get("F_c_max") != "N"):
        fail("collisions: units " + repr(u))
if len(sys.argv) > 3 and "refined" not in f["runs"].dtype.names:
    fail("runs: no refined column")
sys.exit(0)
