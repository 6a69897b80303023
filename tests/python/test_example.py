# SPDX-License-Identifier: GPL-3.0-or-later
# examples/python/figure1b.py writes the first study's observables per
# collision (the paper's figure 1(b) data), equal to the CLI's collisions,
# and plots them when matplotlib is installed, else says it skipped the plot.
import csv
import os
import subprocess
import sys

import hybounce
from conftest import ROOT, cli


def test_figure1b_writes_the_first_studys_collisions(tmp_path):
    prefix = str(tmp_path / "fig")
    p = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "python", "figure1b.py"),
                        prefix], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    with open(prefix + ".csv") as f:
        got = list(csv.DictReader(f))
    want = list(csv.DictReader(cli("--batch", "steel-on-bitumen", "--collisions", "-")
                               .stdout.splitlines()))
    assert len(got) == len(want) > 0
    for g, w in zip(got, want):
        for k in g:
            assert g[k] == "" and w[k] == "" or float(g[k]) == float(w[k]), k
    try:
        import matplotlib  # noqa: F401
        assert os.path.getsize(prefix + ".png") > 10000 and "wrote %s.png" % prefix in p.stdout
    except ImportError:
        assert "the plot is skipped" in p.stdout and not os.path.exists(prefix + ".png")


def test_figure1b_without_matplotlib_says_the_plot_is_skipped(tmp_path):
    # a matplotlib that cannot be imported, first on the path
    (tmp_path / "block").mkdir()
    (tmp_path / "block" / "matplotlib.py").write_text("raise ImportError('blocked')\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(tmp_path / "block"), os.environ.get("PYTHONPATH", "")]))
    prefix = str(tmp_path / "fig")
    p = subprocess.run([sys.executable, os.path.join(ROOT, "examples", "python", "figure1b.py"),
                        prefix], capture_output=True, text=True, env=env)
    assert p.returncode == 0, p.stderr
    assert "python3-matplotlib" in p.stdout and "the plot is skipped" in p.stdout
    assert os.path.exists(prefix + ".csv") and not os.path.exists(prefix + ".png")
