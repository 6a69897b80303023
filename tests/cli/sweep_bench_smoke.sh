#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A bounded smoke of make bench-sweep: the sweep benchmark runs (40 and 200
# points) and reports the rate, the overhead and the memory.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"
if sh tests/bench/sweep.sh --smoke "$BIN" "$T" >"$T/out" 2>&1 &&
    grep -q '^   speed-up [0-9.]* x' "$T/sweep.txt" && grep -q '^   overhead -*[0-9.]* %' "$T/sweep.txt" &&
    grep -q '^       200 points: peak RSS  *[0-9.]* MB' "$T/sweep.txt"; then
	echo "ok - the sweep benchmark (make bench-sweep) runs: rate, overhead, memory"
else
	echo "not ok - the sweep benchmark (make bench-sweep) runs"
	sed 's/^/# /' "$T/out"
fi
