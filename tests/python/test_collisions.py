# SPDX-License-Identifier: GPL-3.0-or-later
# The module's collision table of each paper study equals the CLI's
# `hybounce --batch PRESET --collisions -` CSV, bit for bit (as float64
# bits; the CSV's %.17g reads back exactly), and the arc's columns are
# views of the library's samples.
import csv
import io

import numpy as np
import pytest

import hybounce
from conftest import STUDIES, cli


def csv_table(text):
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], rows[1:]


@pytest.mark.parametrize("preset", STUDIES)
def test_collision_table_equals_cli_csv_bit_for_bit(preset):
    header, rows = csv_table(cli("--batch", preset, "--collisions", "-").stdout)
    run = hybounce.Run(preset).run()
    table = run.collisions
    assert header == hybounce.collision_columns()
    assert len(rows) > 0
    assert len(table) == len(rows)
    for k, name in enumerate(header):
        want = np.array([float(r[k]) if r[k] != "" else np.nan for r in rows])
        got = np.asarray(table[name], dtype=np.float64)
        # NaN (an unknown t_f) is an empty cell: both NaN; else equal bits
        both_nan = np.isnan(want) & np.isnan(got)
        same = want.view(np.uint64) == got.view(np.uint64)
        assert np.all(both_nan | same), "%s: column %s differs" % (preset, name)


def test_collisions_frame_has_the_csv_columns():
    run = hybounce.Run("steel-on-bitumen").run()
    df = run.collisions_frame()
    assert list(df.columns) == hybounce.collision_columns()
    assert np.array_equal(df["e"].to_numpy(), run.collisions["e"])


def test_arc_columns_are_views_with_the_sample_stride():
    run = hybounce.Run("steel-on-bitumen").run()
    arc = run.arc
    size = hybounce.ffi.sizeof("struct hb_arc_sample")
    for name in ("t", "x", "v", "x_c", "F_c"):
        col = getattr(arc, name)
        assert col.strides == (size,), name
        assert not col.flags.owndata and not col.flags.writeable, name
    assert arc.j.dtype == np.int64 and arc.z_c.shape == (len(arc), run._scene.law.n_z)
    # the same memory as the library's first and last samples
    a = hybounce.lib.hb_sim_arc(run._sim.ptr)
    first, last = hybounce.lib.hb_arc_at(a, 0), hybounce.lib.hb_arc_at(a, len(arc) - 1)
    assert arc.t.__array_interface__["data"][0] == int(hybounce.ffi.cast("uintptr_t", first))
    assert arc.t[-1] == last.t and arc.F_c[-1] == last.Fc and arc.j[-1] == last.j
    # time is ordered, and the run reached its horizon
    assert np.all(np.diff(arc.t) >= 0) and arc.t[-1] == run.get("run.T")


def test_views_outlive_the_run_object_and_a_new_run():
    run = hybounce.Run("steel-on-bitumen").run()
    t, e = run.arc.t, run.collisions["e"]
    t0, e0 = t.copy(), e.copy()
    run.set("law.c", "44 kN s/m").run()     # a new sim; the old one stays with its views
    del run
    import gc
    gc.collect()
    assert np.array_equal(t, t0) and np.array_equal(e, e0)


def test_set_with_units_equals_cli_set():
    header, rows = csv_table(cli("--batch", "steel-on-bitumen", "--set", "law.c=44 kN s/m",
                                 "--collisions", "-").stdout)
    run = hybounce.Run("steel-on-bitumen")
    run.set("law.c", "44 kN s/m")
    assert run.get("law.c") == 44000.0
    got = run.run().collisions
    assert len(got) == len(rows)
    k = header.index("t_e")
    assert [float(r[k]) for r in rows] == list(got["t_e"])
