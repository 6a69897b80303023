#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A bounded smoke of make bench-sweep: the sweep benchmark runs (40 and 200
# points) and reports the scaling beside independent processes, the overhead
# in instructions and the memory per point.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"
# The overhead in instructions: callgrind's count (not in a sanitizer build).
instr='^   overhead -*[0-9.]* % of the points own'
perpoint='^   per point beyond start-up: -*[0-9]* instructions, overhead -*[0-9.]* %'
# the cheapest preset: the sweep's own work, and the point's run inside the sweep
cheap='^   nonunique-rest  *a point owns  *[0-9]* instructions; the sweep adds  *-*[0-9]* a point: *-*[0-9.]* %'
inside='^  *inside the sweep the point costs  *[0-9]* ([-+][0-9.]* %); in all [-+][0-9.]* % of a batch run$'
if grep -a -q -e __asan_init -e __tsan_init "$BIN"; then
	instr='^2. overhead in instructions: not measured'
	perpoint=$instr
	cheap=$instr
	inside=$instr
fi
# The scaling table: a row per J up to the online processors (1, 2, ...).
two='^   speed-up [0-9.]* x at --jobs 2'
[ "$(nproc)" -lt 2 ] && two='^ *1 .*%$'
if sh tests/bench/sweep.sh --smoke "$BIN" "$T" >"$T/out" 2>&1 &&
    grep -q '^ *1  *[0-9.]*  *[0-9.]*  *100%  *[0-9.]*  *[0-9.]*  *100%$' "$T/sweep.txt" &&
    grep -q "$two" "$T/sweep.txt" && grep -q "$instr" "$T/sweep.txt" && grep -q "$perpoint" "$T/sweep.txt" &&
    grep -q "$cheap" "$T/sweep.txt" && grep -q "$inside" "$T/sweep.txt" &&
    grep -q '^       200 points: peak RSS  *[0-9.]* MB' "$T/sweep.txt" &&
    grep -q '^   1 boundary located to 0.00078 of the axis (6 bisections) in [0-9]* runs' "$T/sweep.txt"; then
	echo "ok - the sweep benchmark (make bench-sweep) runs: scaling, overhead, memory, refinement"
else
	echo "not ok - the sweep benchmark (make bench-sweep) runs"
	sed 's/^/# /' "$T/out"
fi
