# SPDX-License-Identifier: GPL-3.0-or-later
"""Fits: the library's hb_fit_* over a Run's scene, results as arrays.

    f = hybounce.fit("steel-on-bitumen", "bounces.csv", ["law.c", "law.alpha"])
    f.value, f.se, f.corr, f.points["resid"], f.fitted.run()

data is a data file as `hybounce fit` reads it (a path), or a sequence
of impact times t_e (s, ascending: a bouncing sequence).  The points are
copied from the library's result, which it frees.
"""
import os

import numpy as np

from ._lib import MSG, ffi, lib, msgbuf, text
from ._arrays import struct_dtype
from .errors import check
from .run import Run, _b


class FitResult:
    """keys, start, value, se (NumPy arrays, SI), corr (P x P), points (a
    structured array: row, obs, measured, simulated, sd, resid, start),
    cost0, cost, iter, runs, reason (words), why, unident, sd_scaled, cond,
    and fitted: a Run of the scene at the estimates.  With numerical=True:
    numerical (each estimate's numerical error, SI; NAN with numerical_why
    saying why when it could not be had) and numerical_rtol, as hybounce
    fit reports them; else numerical is None."""

    def __repr__(self):
        vals = ", ".join("%s = %.6g +- %.2g" % (k, v, s)
                         for k, v, s in zip(self.keys, self.value, self.se))
        return "<hybounce.FitResult: %s; %s after %d iterations, %d runs, cost %.6g -> %.6g>" % (
            vals, self.reason, self.iter, self.runs, self.cost0, self.cost)


def _data(data, d, msg):
    if isinstance(data, (str, bytes, os.PathLike)):
        check(lib.hb_fit_data_load(_b(data), d, msg, MSG), msg)
        return
    t = np.ascontiguousarray(data, dtype=np.float64)
    if t.ndim != 1:
        raise ValueError("hybounce.fit: data is a path or a 1-D sequence of impact times")
    check(lib.hb_fit_data_from_times(ffi.cast("double *", ffi.from_buffer(t)), ffi.NULL,
                                     len(t), b"times", d, msg, MSG), msg)


def fit(base, data, keys, jobs=0, max_iter=0, xtol=0.0, gtol=0.0, ftol=0.0, numerical=False):
    """Fits the keys (e.g. ["law.c", "law.alpha"]) of base (a Run, or a
    preset's name or path) to data.  numerical=True: each estimate's
    numerical error too (one more evaluation of the data, with rk8pd at a
    hundredth of run.rtol).  InputError with the library's message for bad
    input; otherwise a FitResult, whatever the reason it stopped."""
    run = base if isinstance(base, Run) else Run(base)
    if isinstance(keys, str):
        keys = [keys]
    msg = msgbuf()
    d = ffi.new("struct hb_fit_data *")
    r = ffi.new("struct hb_fit_result *")
    ckeys = [ffi.new("char[]", _b(k)) for k in keys]
    karr = ffi.new("char *[]", ckeys)
    o = ffi.new("struct hb_fit_options *")
    o.keys, o.nkeys = karr, len(keys)
    o.max_iter, o.jobs = int(max_iter), int(jobs)
    o.xtol, o.gtol, o.ftol = xtol, gtol, ftol
    o.numerical = 1 if numerical else 0
    _data(data, d, msg)
    try:
        check(lib.hb_fit_run(run._scene, d, o, r, msg, MSG), msg)
        res = FitResult()
        p = r.np
        res.keys = [text(r.key[k]) for k in range(p)]
        res.start = np.array([r.start[k] for k in range(p)])
        res.value = np.array([r.value[k] for k in range(p)])
        res.se = np.array([r.se[k] for k in range(p)])
        m = lib.HB_FIT_MAX_FREE
        res.corr = np.array([[r.corr[i * m + j] for j in range(p)] for i in range(p)])
        dt = struct_dtype("struct hb_fit_point")
        res.points = np.frombuffer(ffi.buffer(r.point, r.npoints * dt.itemsize), dt).copy() \
            if r.npoints else np.zeros(0, dt)
        res.obs_names = [text(lib.hb_fit_obs_name(k)) for k in range(lib.HB_FIT_OBS_COUNT)]
        res.cost0, res.cost = r.cost0, r.cost
        res.iter, res.runs, res.cond = r.iter, r.runs, r.cond
        res.reason = text(lib.hb_fit_reason_str(r.reason))
        res.why, res.unident = text(r.why), text(r.unident)
        res.sd_scaled = bool(r.sd_scaled)
        res.numerical = np.array([r.num_err[k] for k in range(p)]) if r.num_on else None
        res.numerical_rtol = r.num_rtol if r.num_on else None
        res.numerical_why = text(r.num_why) if r.num_on else None
        res.fitted = Run._of_scene(ffi.addressof(r.fitted))
        return res
    finally:
        lib.hb_fit_result_free(r)
        lib.hb_fit_data_free(d)
