# SPDX-License-Identifier: GPL-3.0-or-later
# Error bars from Python: Run.error() gives the NAME_err columns of
# hybounce --batch --error --collisions to the bit, and the observables'
# bars; sweep(error=True) gives those of hybounce sweep --error.
import csv

import numpy as np
import pytest

import hybounce
from conftest import cli


def read(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    return rows[0], rows[1:]


def test_run_error_is_batch_error(tmp_path):
    out = tmp_path / "c.csv"
    cli("--batch", "permanent-contact-shccl", "--error", "--quiet", "--collisions", str(out))
    header, rows = read(out)
    run = hybounce.Run("permanent-contact-shccl").run()
    bars = run.error()
    assert isinstance(bars, hybounce.ErrorBars)
    assert len(bars.collisions) == len(run.collisions) == len(rows) > 0
    assert list(bars.collisions["i"]) == list(run.collisions["i"])
    errs = [n for n in header if n.endswith("_err")]
    assert len(errs) == len(hybounce.collision_columns()) - 1
    for name in errs:
        col = header.index(name)
        want = np.array([float(r[col]) if r[col] != "" else np.nan for r in rows])
        got = bars[name[:-4]]
        assert np.array_equal(got, want, equal_nan=True), name
    # a copy: the arrays outlive the estimate, and are the caller's
    bars.collisions["e"][0] = 1.0
    assert bars.rtol == pytest.approx(run.get("run.rtol") / 100)
    assert not bars.at_floor and bars.other_total == run.observables()["collisions"]


def test_run_error_observables():
    run = hybounce.Run("steel-on-bitumen").run()
    obs = run.error().observables
    assert set(obs) == set(run.observables())
    for k in ("steps", "rejected", "rhs", "jac"):
        assert np.isnan(obs[k]), k
    assert 0 < obs["e_first"] < 1e-8
    assert obs["e_first"] == run.error()["e"][0]   # the first collision's, as batch prints it


def test_run_error_needs_a_run():
    with pytest.raises(hybounce.HybounceError, match="run"):
        hybounce.Run("steel-on-bitumen").error()


def test_sweep_error_is_the_cli(tmp_path):
    out = tmp_path / "cli"
    cli("sweep", "permanent-contact-shccl", "--vary", "law.c=1e9,4.3e9", "--error", "--quiet",
        "--jobs", "2", "--out", str(out))
    header, rows = read(out / "runs.csv")
    s = hybounce.sweep("permanent-contact-shccl", {"law.c": "1e9,4.3e9"}, jobs=2, error=True)
    assert list(s.runs.dtype.names) == header and "e_first_err" in header
    col = header.index("e_first_err")
    assert [float(r[col]) for r in rows] == list(s.runs["e_first_err"])
    cheader, crows = read(out / "collisions.csv")
    assert list(s.collisions.dtype.names) == cheader and "e_err" in cheader
    col = cheader.index("e_err")
    assert [float(r[col]) for r in crows] == list(s.collisions["e_err"])
    plain = hybounce.sweep("permanent-contact-shccl", {"law.c": "1e9,4.3e9"}, jobs=2)
    assert "e_first_err" not in plain.runs.dtype.names


def test_fit_numerical_is_the_cli(tmp_path):
    import json
    import os
    from conftest import ROOT
    data = os.path.join(ROOT, "examples", "fit", "bounces.csv")
    keys = ["law.c", "law.alpha"]
    cli("fit", "steel-on-bitumen", "--data", data, "--free", ",".join(keys), "--quiet",
        "--out", str(tmp_path / "f.preset"), "--report", str(tmp_path / "r.json"))
    rep = json.load(open(tmp_path / "r.json"))
    f = hybounce.fit("steel-on-bitumen", data, keys, numerical=True)
    assert list(f.numerical) == [p["numerical_error"] for p in rep["parameters"]]
    assert f.numerical_rtol == rep["numerical_rtol"] and f.numerical_why == ""
    assert np.all((f.numerical > 0) & (f.numerical < 0.1 * f.se))
    assert hybounce.fit("steel-on-bitumen", data, keys).numerical is None
