#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""make bench-python: a 1,000-point sweep from Python (hybounce.sweep)
against the same sweep from the command line (hybounce sweep), alternated
in one run, so that both see the same load.

    PYTHONPATH=build/python python3 tests/bench/python_sweep.py build/hybounce [ROUNDS]

The CLI's time is its whole process (exec, preset, sweep, CSV files); the
Python's is the call to hybounce.sweep (the sweep, its CSV files, reading
them back into arrays) in a process that has already imported the
module.  Both use the same number of threads.  Beside the wall time, the
CPU time (user + system, getrusage: the child's for the CLI, this
process's for Python), which a loaded machine disturbs less.  Prints each
round, then the medians and their ratios; the target is a wall-time ratio
within 10%.  The machine may be loaded: read the ratios, not the seconds.
"""
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import hybounce

PRESET = "steel-on-bitumen"
SETS = ["run.T=0.2 s"]
AXIS = ("initial.v0", "-0.1:-1:1000")


def main():
    binary = sys.argv[1]
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    jobs = os.cpu_count() or 1
    base = hybounce.Run(PRESET, SETS)
    tmp = tempfile.mkdtemp(prefix="hybounce-bench-python-")
    cli_t, py_t, cli_c, py_c = [], [], [], []

    def cpu(who):
        r = resource.getrusage(who)
        return r.ru_utime + r.ru_stime
    try:
        cmd = [binary, "sweep", PRESET, "--quiet", "--jobs", str(jobs),
               "--vary", "%s=%s" % AXIS]
        for s in SETS:
            cmd += ["--set", s]
        for k in range(rounds):
            out = os.path.join(tmp, "cli%d" % k)
            c0, t0 = cpu(resource.RUSAGE_CHILDREN), time.perf_counter()
            subprocess.run(cmd + ["--out", out], check=True, stdout=subprocess.DEVNULL)
            cli_t.append(time.perf_counter() - t0)
            cli_c.append(cpu(resource.RUSAGE_CHILDREN) - c0)
            c0, t0 = cpu(resource.RUSAGE_SELF), time.perf_counter()
            res = hybounce.sweep(base, {AXIS[0]: AXIS[1]}, jobs=jobs)
            py_t.append(time.perf_counter() - t0)
            py_c.append(cpu(resource.RUSAGE_SELF) - c0)
            assert len(res.runs) == 1000 and set(res.runs["status"]) == {"ok"}
            print("round %d: hybounce sweep %.3f s (CPU %.3f s), hybounce.sweep %.3f s (CPU %.3f s)"
                  % (k + 1, cli_t[-1], cli_c[-1], py_t[-1], py_c[-1]))
    finally:
        shutil.rmtree(tmp)
    c, p = statistics.median(cli_t), statistics.median(py_t)
    load = os.getloadavg()
    print("1,000-point sweep of %s (%s, %s=%s), %d threads, %d rounds alternated"
          % (PRESET, ", ".join(SETS), AXIS[0], AXIS[1], jobs, rounds))
    print("median: hybounce sweep %.3f s, hybounce.sweep from Python %.3f s: ratio %.3f "
          "(target <= 1.10)" % (c, p, p / c))
    c, p = statistics.median(cli_c), statistics.median(py_c)
    print("median CPU: hybounce sweep %.3f s, hybounce.sweep %.3f s: ratio %.3f" % (c, p, p / c))
    print("load average %.2f %.2f %.2f on %d cores: timings are noisy; compare the ratio"
          % (load[0], load[1], load[2], jobs))


if __name__ == "__main__":
    main()
