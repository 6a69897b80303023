# SPDX-License-Identifier: GPL-3.0-or-later
"""Sweeps: the library's hb_sweep_* over a Run's scene, results as arrays.

    s = hybounce.sweep("steel-on-bitumen", {"initial.v0": "-0.1:-1:1000"})
    s.runs["e_first"], s.runs["initial.v0"], s.collisions

The sweep is the command line's (`hybounce sweep`): the same points, the
same scenes, run by the library on `jobs` threads into a folder (dir, or
a temporary one removed afterwards), whose runs.csv and collisions.csv
are then read into structured arrays.  So the values are those of
`hybounce sweep ... --out DIR` (numbers in %.17g read back exactly), a
folder left half done (Ctrl-C) resumes as the command line's does, and a
point that fails numerically is a row with status "failed" and its
message, not an exception.
"""
import csv
import os
import tempfile
import threading

import numpy as np

from ._lib import MSG, ffi, lib, msgbuf, text
from .errors import HybounceError, check
from .run import Run, _b

# runs.csv columns that are not numbers
_TEXT = ("status", "message")

# The C types a sweep allocates, taken from hb_sweep_run's own signature:
# a type named by its text ("struct hb_sweep_options *") is parsed by cffi
# with pycparser the first time, 250M instructions (about 0.1 s) that the
# first sweep of a process paid inside the call; these cost nothing.
_OPTIONS_T = ffi.typeof(lib.hb_sweep_run).args[1]
_CANCEL_T = dict(_OPTIONS_T.item.fields)["cancel"].type


def _table(path, ints):
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(row for row in f if not row.startswith("#")))
    header, rows = rows[0], rows[1:]
    cols = list(zip(*rows)) if rows else [()] * len(header)
    fields, data = [], []
    for name, col in zip(header, cols):
        if name in _TEXT:
            width = max([len(v) for v in col] + [1])
            fields.append((name, "U%d" % width))
            data.append(col)
        elif name in ints:
            fields.append((name, "i8"))
            data.append([int(v) for v in col])
        else:
            fields.append((name, "f8"))
            data.append([float(v) if v != "" else np.nan for v in col])
    out = np.zeros(len(rows), dtype=fields)
    for (name, _), col in zip(fields, data):
        out[name] = col
    return out


def _numbers(path, ints):
    """A CSV of numbers only (collisions.csv: an empty cell is NAN), parsed
    by NumPy in one pass (np.fromstring with a separator: %.17g reads back
    exactly): the csv module and a float() per cell took 90 ms of the 1.5 s
    of a 1,000-point sweep with 2,600 collisions, this takes 20 ms."""
    with open(path, encoding="utf-8") as f:
        header = f.readline().rstrip("\n").split(",")
        body = f.read()
    body = body.replace(",\n", ",nan\n")
    while ",," in body:
        body = body.replace(",,", ",nan,")
    data = np.fromstring(body.replace("\n", ","), dtype=np.float64, sep=",")
    rows = body.count("\n")
    if data.size != rows * len(header):
        raise HybounceError("%s: expected %d rows of %d numbers" % (path, rows, len(header)))
    data = data.reshape(rows, len(header))
    out = np.zeros(rows, dtype=[(n, "i8" if n in ints else "f8") for n in header])
    for k, name in enumerate(header):
        out[name] = data[:, k]
    return out


class SweepResult:
    """runs: one row per point (id, the varied keys, status, message, the run
    observables, cpu_s); collisions: id, then the --collisions columns.
    Both structured arrays; frame() and collisions_frame() as DataFrames."""

    def __init__(self, runs, collisions, keys, dir):
        self.runs, self.collisions, self.keys, self.dir = runs, collisions, keys, dir

    def frame(self):
        import pandas
        return pandas.DataFrame(self.runs)

    def collisions_frame(self):
        import pandas
        return pandas.DataFrame(self.collisions)

    def __len__(self):
        return len(self.runs)

    def __repr__(self):
        failed = int(np.sum(self.runs["status"] != "ok")) if len(self.runs) else 0
        return "<hybounce.SweepResult: %d points over %s, %d failed, %d collisions>" % (
            len(self.runs), ", ".join(self.keys), failed, len(self.collisions))


def _axes(vary):
    if isinstance(vary, dict):
        return ["%s=%s" % (k, v) for k, v in vary.items()]
    if isinstance(vary, str):
        return [vary]
    return list(vary)


def sweep(base, vary=None, jobs=None, dir=None, max_points=None, error=False):  # noqa: A002
    """Runs a sweep of base (a Run, or a preset's name or path) over the axes
    vary ({"KEY": "SPEC"} or ["KEY=SPEC", ...]; SPEC as --vary takes it:
    FROM:TO:N, FROM:TO:N:log, V1,V2,...), after the preset's own
    "; sweep: --vary" lines, on jobs threads (default: os.cpu_count()).
    error=True: every point's error bars too, as hybounce sweep --error
    (runs["OBS_err"], collisions["NAME_err"]; about 2.5 times the work).
    Returns a SweepResult; bad input raises InputError with the library's
    message."""
    run = base if isinstance(base, Run) else Run(base)
    msg = msgbuf()
    sw = lib.hb_sweep_new(run._scene, msg, MSG)
    if sw == ffi.NULL:
        check(lib.HB_ENOMEM, msg)
    sw = ffi.gc(sw, lib.hb_sweep_free)
    if max_points is not None:
        lib.hb_sweep_set_max_points(sw, int(max_points), b"max_points= allows more")
    if run.preset_text:
        check(lib.hb_sweep_vary_from_preset(sw, _b(run.preset_text), _b(run.path or "preset"),
                                            msg, MSG), msg)
    for a in _axes(vary or []):
        check(lib.hb_sweep_vary(sw, _b(a), msg, MSG), msg)
    if run.preset_text:
        lib.hb_sweep_error_from_preset(sw, _b(run.preset_text))
    if error:
        lib.hb_sweep_set_error(sw, 1)
    n = lib.hb_sweep_runs_header(sw, ffi.NULL, 0)
    hdr = ffi.new("char[]", n + 1)
    lib.hb_sweep_runs_header(sw, hdr, n + 1)
    header = text(hdr).split(",")
    keys = header[1:1 + lib.hb_sweep_naxes(sw)]

    tmp = None
    if dir is None:
        tmp = tempfile.TemporaryDirectory(prefix="hybounce-sweep-")
        out = os.path.join(tmp.name, "sweep")
    else:
        out = os.fspath(dir)
    try:
        o = ffi.new(_OPTIONS_T)
        cdir = ffi.new("char[]", _b(out))
        cancel = ffi.new(_CANCEL_T)
        o.dir = cdir
        o.jobs = int(jobs) if jobs else (os.cpu_count() or 1)
        o.shard_k, o.shard_n = 0, 1
        o.cancel = cancel
        status = []

        def work():
            status.append(lib.hb_sweep_run(sw, o, msg, MSG))

        # on a thread of its own, so that Ctrl-C reaches Python: the points
        # done are journaled, the library stops, KeyboardInterrupt follows
        t = threading.Thread(target=work, name="hybounce-sweep")
        t.start()
        try:
            t.join()
        except KeyboardInterrupt:
            cancel[0] = 1
            t.join()
            raise
        check(status[0], msg)
        runs = _table(os.path.join(out, "runs.csv"), ("id",))
        colls = _numbers(os.path.join(out, "collisions.csv"), ("id", "i"))
        return SweepResult(runs, colls, keys, None if tmp else out)
    finally:
        if tmp is not None:
            tmp.cleanup()
