# SPDX-License-Identifier: GPL-3.0-or-later
# A sweep from Python gives the values of the CLI's runs.csv and
# collisions.csv for the same sweep.
import csv

import numpy as np

import hybounce
from conftest import cli

AXES = {"initial.v0": "-0.1:-1:4", "law.c": "30 kN s/m,60 kN s/m"}


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def test_sweep_gives_the_cli_runs_csv(tmp_path):
    out = tmp_path / "cli"
    args = ["sweep", "steel-on-bitumen", "--quiet", "--jobs", "2", "--out", str(out)]
    for k, v in AXES.items():
        args += ["--vary", "%s=%s" % (k, v)]
    cli(*args)
    header, rows = read(out / "runs.csv")
    s = hybounce.sweep("steel-on-bitumen", AXES, jobs=2)
    assert s.keys == ["initial.v0", "law.c"]
    assert list(s.runs.dtype.names) == header
    assert len(s.runs) == len(rows) == 8
    for k, name in enumerate(header):
        if name == "cpu_s":     # a measurement
            continue
        col = s.runs[name]
        for row, v in zip(rows, col):
            if name in ("status", "message"):
                assert row[k] == v, name
            elif row[k] == "":
                assert np.isnan(v), name
            else:
                assert float(row[k]) == v, name
    ch, crows = read(out / "collisions.csv")
    assert list(s.collisions.dtype.names) == ch and len(s.collisions) == len(crows)
    for k, name in enumerate(ch):
        want = np.array([float(r[k]) if r[k] != "" else np.nan for r in crows])
        got = s.collisions[name].astype(np.float64)
        assert np.all((want == got) | (np.isnan(want) & np.isnan(got))), name


def test_sweep_into_a_folder_leaves_the_cli_files(tmp_path):
    s = hybounce.sweep(hybounce.Run("steel-on-bitumen"), ["initial.v0=-0.1,-0.2"], jobs=1,
                       dir=tmp_path / "sw")
    assert s.dir == str(tmp_path / "sw")
    assert (tmp_path / "sw" / "runs.csv").exists() and (tmp_path / "sw" / "sweep.preset").exists()
    assert list(s.runs["id"]) == [0, 1]
    assert list(s.runs["initial.v0"]) == [-0.1, -0.2]
    assert set(s.runs["status"]) == {"ok"}
    assert "2 points over initial.v0" in repr(s)
    assert list(s.frame()["id"]) == [0, 1]
