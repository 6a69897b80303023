# SPDX-License-Identifier: GPL-3.0-or-later
# The rest of the API: values, repr, fits, threads, and the README's session.
import os
import re
import threading
import doctest

import numpy as np

import hybounce
from conftest import ROOT


def test_get_set_and_the_preset_text():
    run = hybounce.open("steel-on-bitumen", ["run.T=0.1 s"])
    assert run.get("run.T") == 0.1 and run.text("run.T") in ("100 ms", "0.1 s")
    assert run.get("run.stepper") in ("rk8pd", "dop853", "auto")
    run.set("initial.v0", -0.5)
    assert run.get("initial.v0") == -0.5
    assert "law.c" in run.keys()
    copy = hybounce.Run(None)
    assert copy.law is not None
    assert "[law]" in run.preset()


def test_a_preset_opens_by_path_as_by_name():
    path = os.path.join(ROOT, "presets", "ptfe-pom.preset")
    by_path, by_name = hybounce.Run(path), hybounce.open("ptfe-pom")
    assert by_path.path == path and by_path.preset() == by_name.preset()
    assert by_path.run().collisions.tobytes() == by_name.run().collisions.tobytes()


def test_repr_says_what_and_how_it_ended():
    run = hybounce.Run("steel-on-bitumen")
    assert repr(run).endswith("law bwmcl, not run>")
    run.run()
    assert re.search(r"\d+ samples, 12 collisions, horizon T = 0.5 s reached", repr(run))
    assert repr(run.arc).startswith("<hybounce.Arc: ")


def test_runs_on_threads_equal_runs_one_after_another():
    want = [hybounce.Run(p).run().collisions["t_e"].copy()
            for p in ("steel-on-bitumen", "ptfe-pom")] * 2
    got = [None] * 4

    def work(k, p):
        got[k] = hybounce.Run(p).run().collisions["t_e"]

    ts = [threading.Thread(target=work, args=(k, p))
          for k, p in enumerate(("steel-on-bitumen", "ptfe-pom") * 2)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    for w, g in zip(want, got):
        assert np.array_equal(w, g)


def test_a_fit_returns_arrays():
    # impact times of the preset itself with c changed: the fit finds c back
    truth = hybounce.Run("steel-on-bitumen", {"run.T": "0.3 s", "law.c": "30 kN s/m"}).run()
    times = truth.collisions["t_e"]
    f = hybounce.fit(hybounce.Run("steel-on-bitumen", {"run.T": "0.3 s"}), times, ["law.c"],
                     jobs=2)
    assert f.keys == ["law.c"] and f.value.shape == (1,) and f.corr.shape == (1, 1)
    assert abs(f.value[0] - 30e3) < 30.0, f
    assert len(f.points) == len(times) - 1 and f.points.dtype.names[:2] == ("row", "obs")
    assert f.fitted.get("law.c") == f.value[0]
    assert "law.c = " in repr(f)


def test_the_readme_session():
    # the README's Python session, verbatim, as a doctest
    with open(os.path.join(ROOT, "README.md")) as f:
        readme = f.read()
    m = re.search(r"<!-- PYTHON-SESSION-BEGIN -->\n```python\n(.*?)```\n<!-- PYTHON-SESSION-END -->",
                  readme, re.S)
    assert m, "README.md has no Python session between the PYTHON-SESSION markers"
    session = m.group(1)
    assert session.count(">>> ") >= 5
    test = doctest.DocTestParser().get_doctest(session, {}, "README", "README.md", 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    out = []
    runner.run(test, out=out.append)
    assert runner.failures == 0, "".join(out)
