# SPDX-License-Identifier: GPL-3.0-or-later
"""A run of a scene: open a preset, set values with units, run, read the
arc and the collisions as NumPy arrays.

    run = hybounce.Run("steel-on-bitumen")     # a name or a path
    run.set("law.c", "44 kN s/m")              # as --set takes it
    run.run()
    run.arc.t, run.arc.x_c, run.arc.F_c        # views of the library's arc
    run.collisions["e"]                        # a structured array
    run.error()["e"]                           # its error bars (a second run)

Copies.  The arc's columns and the collision table are views of the
library's memory (struct hb_arc_sample and struct hb_collision arrays,
strided: no copy), read-only, and keep the run's sim alive.  A Run never
advances a sim it has handed out: run() again makes a new sim, so views
of an earlier run stay valid and unchanged.  Copies happen where the
memory is the library's to free or another library wants its own:
collisions_frame() and Arc.frame() copy into pandas (a DataFrame holds
its own columns), a sweep's tables are read from its CSV files, and a
fit's points are copied before the library frees its result.  (Arc.z_c,
the law's internal states, is a view of the first n_z of the struct's
HB_LAW_MAX_Z columns: still no copy.)

Threads.  A Run is one scene and one sim: like the library's, it must not
be used by two threads at once, and any number of Runs may run at once,
each in its own thread: cffi releases the GIL during every call into the
library, so they run in parallel.  Nothing global is touched (but at the
import, which turns GSL's error handler off: _lib.py).
"""
import math
import os

import numpy as np

from ._lib import MSG, ffi, lib, libc, msgbuf, text
from ._arrays import struct_dtype, view
from .errors import HybounceError, InputError, check, error

_KIND_NUMBER, _KIND_WHOLE, _KIND_TEXT, _KIND_CHOICE = range(4)


def _b(s):
    if isinstance(s, os.PathLike):
        s = os.fspath(s)
    if isinstance(s, bytes):
        return s
    return str(s).encode("utf-8")


def _sets(sets):
    """dict {KEY: VALUE} or ["KEY=VALUE", ...] -> list of b"KEY=VALUE"."""
    if sets is None:
        return []
    if isinstance(sets, dict):
        return [_b("%s=%s" % (k, _value_text(v))) for k, v in sets.items()]
    if isinstance(sets, (str, bytes)):
        sets = [sets]
    return [_b(s) for s in sets]


def _value_text(v):
    if isinstance(v, float):
        return repr(v)  # the shortest text that reads back to the same double
    return str(v)


def _cstrings(items):
    keep = [ffi.new("char[]", s) for s in items]
    arr = ffi.new("char *[]", keep) if keep else ffi.NULL
    return arr, keep


class _Sim:
    """Owns one struct hb_sim (freed with the last reference)."""

    def __init__(self, scene):
        msg = msgbuf()
        s = lib.hb_sim_new(scene, msg, MSG)
        if s == ffi.NULL:
            raise InputError(text(msg))
        self.ptr = ffi.gc(s, lib.hb_sim_free)


_SAMPLE = None
_COLLISION = None


def sample_dtype():
    """The dtype of struct hb_arc_sample (C member names: t, j, q, kind, x, ..., z, Fc, ...)."""
    global _SAMPLE
    if _SAMPLE is None:
        _SAMPLE = struct_dtype("struct hb_arc_sample")
    return _SAMPLE


def collision_dtype():
    """The dtype of struct hb_collision, its members named as the CSV's columns
    (i, t_e, t_s, t_d, t_f, v_i, e, x_c_max, F_c_max, x_c_r, W, J_Fc, J_Fe,
    Lambda) from the library's column table; j, xcr_sum and complete as in C."""
    global _COLLISION
    if _COLLISION is None:
        rename = {}
        for k in range(lib.hb_collision_ncolumns):
            col = lib.hb_collision_columns[k]
            rename[col.off] = text(col.name)
        _COLLISION = struct_dtype("struct hb_collision", rename)
    return _COLLISION


def collision_columns():
    """The CSV columns of --collisions, in order."""
    return [text(lib.hb_collision_columns[k].name) for k in range(lib.hb_collision_ncolumns)]


class Arc:
    """The hybrid arc of a finished run: one entry per sample, in hybrid-time
    order (a jump is two samples with the same t and consecutive j).

    Columns, views of the library's samples (no copy, read-only): t, j, q_c,
    x, v, x_c, z_c (n x n_z: the law's internal states), F_c, F_er, x_m,
    v_m, and the running W, J_Fc, J_Fe, x_c_max, F_c_max, E_e, W_c, kind.
    .samples is the whole structured array (C member names).
    """

    _COLUMNS = {"t": "t", "j": "j", "q_c": "q", "kind": "kind", "x": "x", "v": "v",
                "x_c": "xc", "F_c": "Fc", "F_er": "Fer", "x_m": "xm", "v_m": "vm",
                "W": "W", "J_Fc": "JFc", "J_Fe": "JFe", "x_c_max": "xcmax",
                "F_c_max": "Fcmax", "E_e": "Ee", "W_c": "Wc"}

    def __init__(self, sim, n_z):
        a = lib.hb_sim_arc(sim.ptr)
        n = lib.hb_arc_len(a)
        # hb_arc_at(a, 0) is the first of n contiguous samples (arc.h: the
        # arc's samples are one array); the view checks the last one too
        first = lib.hb_arc_at(a, 0) if n else ffi.NULL
        if n and lib.hb_arc_at(a, n - 1) != first + (n - 1):
            raise HybounceError("the arc's samples are not contiguous: cannot view them")
        self.samples = view(first, n, sample_dtype(), sim)
        self.n_z = n_z
        self.thinned = lib.hb_arc_thinned(a)
        self.skipped = lib.hb_arc_skipped(a)

    def __len__(self):
        return len(self.samples)

    def __getattr__(self, name):
        c = Arc._COLUMNS.get(name)
        if c is None:
            raise AttributeError(name)
        return self.samples[c]

    @property
    def z_c(self):
        return self.samples["z"][:, :self.n_z]

    def columns(self):
        """The columns of the CSV's --trace, in its order: {name: array}."""
        out = {k: getattr(self, k) for k in ("t", "j", "q_c", "x", "v", "x_c")}
        for k in range(self.n_z):
            out["z_c%d" % (k + 1)] = self.z_c[:, k]
        out["F_c"] = self.F_c
        out["F_er"] = self.F_er
        return out

    def frame(self):
        """A pandas DataFrame of columns() (a copy)."""
        import pandas
        return pandas.DataFrame(self.columns())

    def __repr__(self):
        if not len(self):
            return "<hybounce.Arc: no samples>"
        return "<hybounce.Arc: %d samples, t 0 .. %.6g s, j 0 .. %d%s>" % (
            len(self), self.t[-1], self.j[-1],
            ", thinned %d times" % self.thinned if self.thinned else "")


class ErrorBars:
    """The error bars of a run (Run.error()), NumPy arrays the caller owns
    (copies: the library frees its estimate).

    collisions: a structured array of collision_dtype(), one row per
        completed collision of the run (Run.collisions' rows, in order),
        i and j as there, every other field the absolute error of that
        value (the --collisions CSV's NAME_err columns); NAN where the
        tighter run has no such collision.
    observables: {name: error} for every run observable (as
        Run.observables()), NAN for the counts of work (steps, rejected,
        rhs, jac).
    rtol, atol: the second run's tolerances; at_floor: True when rtol / 100
        was below 1e-15 (the estimate is less sure); other_total,
        other_rhs: that run's completed collisions and rhs evaluations.
    """

    def __init__(self, e):
        n = e.ncoll
        self.collisions = np.array(view(e.coll, n, collision_dtype(), None)) if n else \
            np.zeros(0, collision_dtype())
        self.observables = {text(lib.hb_observables[k].name): e.obs[k]
                            for k in range(lib.HB_OBS_COUNT)}
        self.rtol, self.atol, self.at_floor = e.rtol, e.atol, bool(e.at_floor)
        self.other_total, self.other_rhs = e.other_total, e.other_rhs

    def __getitem__(self, name):
        """bars["e"]: the error of field e of every collision (an array)."""
        return self.collisions[name]

    def __repr__(self):
        return "<hybounce.ErrorBars: %d collisions, rtol %.3g%s>" % (
            len(self.collisions), self.rtol, " (at the floor)" if self.at_floor else "")


class Run:
    """One scene and its run.

    Run(preset=None, sets=None): preset is a name (found as the command line
    finds it: $HYBOUNCE_PRESETS, ./presets, the installed presets) or a
    path; None is the library's default scene.  sets: {"KEY": VALUE} or
    ["KEY=VALUE", ...], applied as --set applies them.
    """

    def __init__(self, preset=None, sets=None):
        self._scene = ffi.new("struct hb_scene *")
        self._sim = None
        self._arc = None
        self.path = None
        self.preset_text = None
        if preset is None:
            lib.hb_scene_defaults(self._scene)
            for s in _sets(sets):
                k, _, v = s.decode().partition("=")
                self.set(k.strip(), v.strip())
            return
        items = _sets(sets)
        arr, keep = _cstrings(items)
        msg = msgbuf()
        path = ffi.new("char[]", 4096)
        textp = ffi.new("char **")
        check(lib.hb_preset_open_text(_b(preset), arr, len(items), self._scene, path, 4096,
                                      textp, msg, MSG), msg)
        self.path = text(path)
        try:
            self.preset_text = text(textp[0])
        finally:
            libc.free(textp[0])

    @classmethod
    def _of_scene(cls, scene):
        r = cls.__new__(cls)
        r._scene = ffi.new("struct hb_scene *", scene[0])
        r._sim = r._arc = r.path = r.preset_text = None
        return r

    def copy(self):
        """A new Run of the same scene (not run)."""
        r = Run._of_scene(self._scene)
        r.path, r.preset_text = self.path, self.preset_text
        return r

    # -- the scene -------------------------------------------------------
    def set(self, key, value):
        """Sets a value as --set does: a text with units ("44 kN s/m", "20 mm",
        "rk8pd") or a number in SI units.  InputError names the key and
        what is accepted.  Returns the Run (calls chain)."""
        msg = msgbuf()
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            err = ffi.new("struct hb_scene_error *")
            rc = lib.hb_scene_set_number(self._scene, _b(key), float(value), err)
            if rc != 0:
                lib.hb_scene_error_str(err, msg, MSG)
                raise error(rc, text(msg))
        else:
            check(lib.hb_scene_set(self._scene, _b(key), _b(value), msg, MSG), msg)
        return self

    def _info(self, key):
        info = ffi.new("struct hb_scene_keyinfo *")
        err = ffi.new("struct hb_scene_error *")
        rc = lib.hb_scene_get(self._scene, _b(key), info, err)
        if rc != 0:
            msg = msgbuf()
            lib.hb_scene_error_str(err, msg, MSG)
            raise error(rc, text(msg))
        return info

    def get(self, key):
        """The value of a key: a float in SI units (int for whole numbers),
        or the text of a text or choice key."""
        info = self._info(key)
        if info.kind == _KIND_NUMBER:
            return info.number
        if info.kind == _KIND_WHOLE:
            return int(info.number) if math.isfinite(info.number) else info.number
        if info.kind == _KIND_CHOICE and 0 <= info.choice < info.nchoices:
            return text(info.choices[info.choice])
        return text(info.value)

    def text(self, key):
        """The value of a key as a text that reads back exactly ("20 mm")."""
        info = self._info(key)
        return text(info.edit) or text(info.value)

    def unit(self, key):
        """The SI unit of a number key ("N s m^-5/2"; "" for a pure number)."""
        return text(self._info(key).unit)

    def keys(self):
        """The keys of the scene, as the explorer's panel lists them."""
        info = ffi.new("struct hb_scene_keyinfo *")
        out = []
        for i in range(lib.hb_scene_nkeys(self._scene)):
            if lib.hb_scene_key(self._scene, i, info) == 0:
                out.append(text(info.key))
        return out

    def preset(self):
        """The scene as a preset's text (exact: %.17g values)."""
        n = lib.hb_preset_format(self._scene, ffi.NULL, 0)
        buf = ffi.new("char[]", n + 1)
        lib.hb_preset_format(self._scene, buf, n + 1)
        return text(buf)

    def save(self, path):
        """Writes the scene as a preset (atomically)."""
        msg = msgbuf()
        check(lib.hb_preset_save(_b(path), self._scene, msg, MSG), msg)

    @property
    def name(self):
        return text(self._scene.name)

    @property
    def law(self):
        return text(self._scene.law.name) if self._scene.law != ffi.NULL else None

    # -- the run -----------------------------------------------------------
    def run(self):
        """Runs the scene to its end (horizon T, jump cap J or failure) in a new
        sim.  A failure raises NumericError / ChatterError with the
        library's message; what was computed before it stays readable
        (arc, collisions).  Returns the Run."""
        sim = _Sim(self._scene)
        self._sim, self._arc = sim, None
        rc = lib.hb_sim_run(sim.ptr)
        if rc != 0:
            raise error(rc, text(lib.hb_sim_errmsg(sim.ptr)))
        return self

    def _need(self):
        if self._sim is None:
            raise HybounceError("this scene has not been run: call run() first")
        return self._sim

    @property
    def arc(self):
        """The arc (Arc): its columns are NumPy views of the library's samples."""
        if self._arc is None:
            self._arc = Arc(self._need(), self._scene.law.n_z)
        return self._arc

    @property
    def collisions(self):
        """The completed collisions kept (structured array, a view: no copy),
        its fields named as the --collisions CSV's columns."""
        sim = self._need()
        n = lib.hb_sim_ncollisions(sim.ptr)
        first = lib.hb_sim_collision(sim.ptr, 0) if n else ffi.NULL
        if n and lib.hb_sim_collision(sim.ptr, n - 1) != first + (n - 1):
            raise HybounceError("the collisions are not contiguous: cannot view them")
        return view(first, n, collision_dtype(), sim)

    def collisions_frame(self):
        """The collisions as a pandas DataFrame with the CSV's columns (a copy)."""
        import pandas
        c = self.collisions
        return pandas.DataFrame({k: c[k] for k in collision_columns()})

    @property
    def bodies(self):
        """The bodies at the run's last sample, from the bottom up, as
        --bodies writes them: a structured array with fields body (1 ..),
        m (kg), y (m, the centre's position), u (m/s) and K (J, the
        kinetic energy m u^2 / 2): 2 bodies in the full system, 1 in the
        reduced one, chain.n in a chain (a copy: computed)."""
        sim = self._need()
        n = lib.hb_sim_nbodies(sim.ptr)
        out = np.zeros(n, dtype=[("body", "i4"), ("m", "f8"), ("y", "f8"), ("u", "f8"), ("K", "f8")])
        b = ffi.new("struct hb_sim_body *")
        for i in range(n):
            if lib.hb_sim_body(sim.ptr, i, b) != 0:
                raise HybounceError("body %d: not available" % (i + 1))
            out[i] = (i + 1, b.m, b.y, b.u, 0.5 * b.m * b.u * b.u)
        return out

    def chain_balance(self):
        """A chain's balance at the run's last sample, as the batch
        summary's "chain" line and --check compute it (hb_check_chain):
        {"kinetic", "stored", "dissipated", "absorbed", "loads", "kinetic0"}
        in J, {"momentum", "momentum0", "impulse"} in kg m/s (the momentum
        is checked only without a floor), the residuals "energy_resid" and
        "momentum_resid" (relative; nan where not checked) and "ok" (every
        identity of --check holds) with "message" (why not; "" when ok).
        InputError for a scene that is not a chain."""
        sim = self._need()
        r = ffi.new("struct hb_check_chain *")
        msg = msgbuf()
        rc = lib.hb_check_chain(sim.ptr, r, msg, MSG)
        if rc != 0 and lib.hb_sim_scene(sim.ptr).chain.n == 0:
            raise error(rc, text(msg))
        return {"kinetic": r.kinetic, "stored": r.stored, "dissipated": r.dissipated,
                "absorbed": r.absorbed, "loads": r.loads, "kinetic0": r.kinetic0,
                "momentum": r.p, "momentum0": r.p0, "impulse": r.impulse,
                "energy_resid": r.eresid, "momentum_resid": r.presid if r.momentum else math.nan,
                "ok": rc == 0, "message": text(msg) if rc != 0 else ""}

    @property
    def ended(self):
        """Why the run ended, in words ("horizon T = 0.5 s reached at j = 25")."""
        return text(lib.hb_sim_end_str(self._need().ptr))

    @property
    def failed(self):
        return lib.hb_sim_end(self._need().ptr) == lib.HB_SIM_END_FAIL

    def observables(self):
        """The run's observables as runs.csv has them: {name: value}."""
        sim = self._need()
        return {text(lib.hb_observables[k].name): lib.hb_observable_value(sim.ptr, k)
                for k in range(lib.HB_OBS_COUNT)}

    def error(self):
        """Error bars of the finished run (ErrorBars): the estimate of
        hybounce --batch --error (the library's hb_error_estimate: the scene
        run again with rk8pd at a hundredth of the tolerances, about the
        cost of the run again).  A failure of that second run raises
        NumericError with its message."""
        sim = self._need()
        e = ffi.new("struct hb_error_estimate *")
        msg = msgbuf()
        rc = lib.hb_error_estimate(sim.ptr, ffi.NULL, e, msg, MSG)
        if rc != 0:
            raise error(rc, text(msg))
        try:
            return ErrorBars(e)
        finally:
            lib.hb_error_free(e)

    def stats(self):
        """The integrator's counts (steps, rejected, rhs, jac, jumps, ...)."""
        st = lib.hb_sim_stats(self._need().ptr)
        names = ("steps", "rejected", "rhs", "jac", "jumps", "kinks", "located", "dips",
                 "flights_closed", "stiff", "switched", "seconds", "wall")
        return {k: getattr(st, k) for k in names}

    def __repr__(self):
        head = "<hybounce.Run %r" % self.name
        if self.path:
            head += " from %s" % self.path
        head += ", law %s" % self.law
        if self._sim is None:
            return head + ", not run>"
        sim = self._sim.ptr
        return head + ": %d samples, %d collisions, %s>" % (
            lib.hb_arc_len(lib.hb_sim_arc(sim)), lib.hb_sim_collisions_total(sim),
            text(lib.hb_sim_end_str(sim)))


def open(preset=None, sets=None):  # noqa: A001 - hybounce.open, as in the brief's API
    """Run(preset, sets): a scene from a preset's name or path."""
    return Run(preset, sets)
