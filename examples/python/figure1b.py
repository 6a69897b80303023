#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The paper's figure 1(b): the observables per collision of the first
study (steel ball on bitumen) against the collision index.

    PYTHONPATH=build/python python3 examples/python/figure1b.py [PREFIX]

Writes PREFIX.csv (default figure1b.csv: i and the observables, %.17g) and,
when matplotlib is installed (Debian's python3-matplotlib), PREFIX.png:
one panel per observable, t_d, t_f, v_i, e, x_c^max, x_c^r, F_c^max, W and
Lambda, in SI units.  Without matplotlib it says the plot was skipped.
"""
import sys

import hybounce

# (CSV column, label in matplotlib's mathtext, unit) as the paper's panels
PANELS = [("t_d", "t_d", "s"), ("t_f", "t_f", "s"), ("v_i", "v_i", "m/s"), ("e", "e", ""),
          ("x_c_max", "x_c^{max}", "m"), ("x_c_r", "x_c^r", "m"), ("F_c_max", "F_c^{max}", "N"),
          ("W", "W", "J"), ("Lambda", "\\Lambda", "")]


def main(prefix="figure1b"):
    run = hybounce.Run("steel-on-bitumen").run()
    c = run.collisions
    with open(prefix + ".csv", "w", encoding="utf-8") as f:
        f.write(",".join(["i"] + [p[0] for p in PANELS]) + "\n")
        for row in c:
            cells = ["%d" % row["i"]] + ["" if row[p[0]] != row[p[0]] else "%.17g" % row[p[0]]
                                         for p in PANELS]
            f.write(",".join(cells) + "\n")
    print("wrote %s.csv (%d collisions of %s)" % (prefix, len(c), run.name))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed (Debian: python3-matplotlib): the plot is skipped")
        return 0
    fig, axes = plt.subplots(3, 3, figsize=(7.0, 5.5), sharex=True, constrained_layout=True)
    for ax, (col, label, unit) in zip(axes.flat, PANELS):
        ax.plot(c["i"], c[col], "o-", ms=3, lw=1, color="black")
        ax.set_ylabel("$%s$%s" % (label, " [%s]" % unit if unit else ""))
        ax.grid(True, lw=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("collision i")
    fig.suptitle(run.name)
    fig.savefig(prefix + ".png", dpi=150)
    print("wrote %s.png" % prefix)
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
