# SPDX-License-Identifier: GPL-3.0-or-later
# A chain from Python: run.bodies equals `hybounce --batch PRESET --bodies
# FILE` bit for bit (the CSV's %.17g reads back exactly), for chains and for
# the two-body scenes; run.chain_balance() is the batch summary's chain line
# and --check's identities: an elastic cradle keeps its energy and momentum,
# a dissipative one dissipates, and a two-body scene is not a chain.
import csv
import math

import numpy as np
import pytest

import hybounce
from conftest import cli


def bodies_csv(tmp_path, preset):
    path = tmp_path / "bodies.csv"
    cli("--batch", preset, "--quiet", "--bodies", str(path))
    rows = [r for r in csv.reader(open(path)) if r and not r[0].startswith("#")]
    return rows[0], rows[1:]


@pytest.mark.parametrize("preset", ["newtons-cradle-3", "newtons-cradle-5-bwmcl", "stacked-drop",
                                    "steel-on-bitumen", "hertz-elastic"])
def test_bodies_equal_the_cli_csv_bit_for_bit(tmp_path, preset):
    header, rows = bodies_csv(tmp_path, preset)
    got = hybounce.Run(preset).run().bodies
    assert header == list(got.dtype.names)
    assert len(rows) == len(got) > 0
    assert list(got["body"]) == [int(r[0]) for r in rows]
    for k, name in enumerate(header[1:], start=1):
        want = np.array([float(r[k]) for r in rows])
        assert np.all(want.view(np.uint64) == np.asarray(got[name]).view(np.uint64)), \
            "%s: column %s differs" % (preset, name)


def test_elastic_cradle_keeps_energy_and_momentum():
    run = hybounce.Run("newtons-cradle-5").run()
    b = run.chain_balance()
    assert b["ok"] and b["message"] == ""
    total = b["kinetic"] + b["stored"] + b["dissipated"]
    assert math.isclose(total, b["kinetic0"], rel_tol=1e-10)
    assert abs(b["dissipated"]) < 1e-10 * b["kinetic0"]
    assert math.isclose(b["momentum"], b["momentum0"], rel_tol=1e-10)
    assert b["kinetic"] == pytest.approx(run.bodies["K"].sum(), rel=1e-15)
    assert b["energy_resid"] < 1e-10 and b["momentum_resid"] < 1e-10


def test_dissipative_cradle_dissipates():
    b = hybounce.Run("newtons-cradle-5-bwmcl").run().chain_balance()
    assert b["ok"]
    assert 0 < b["dissipated"] < b["kinetic0"]
    assert b["kinetic"] < b["kinetic0"]


def test_two_body_scene_is_not_a_chain():
    run = hybounce.Run("hertz-elastic").run()
    with pytest.raises(hybounce.InputError):
        run.chain_balance()
