#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A bounded smoke of make bench-chains: the chains benchmark runs (the
# cradle of 5, the stacked drop, the chains of 10) and reports counts,
# instructions (callgrind; "-" in a sanitizer build) and times (reported,
# not asserted: the target of 5 ms is the benchmark's to show).
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"
num='[0-9][0-9]*'
ir="$num"
grep -a -q -e __asan_init -e __tsan_init "$BIN" && ir='-'
if sh tests/bench/chains.sh --smoke "$BIN" "$T/chains.md" >"$T/out" 2>&1 &&
    grep -q "^| touching cradle, struck at 1 m/s | 5 | 10 ms | 4 | $num | $num | $ir | - | [0-9.]* |$" "$T/chains.md" &&
    grep -q "^| stacked-drop (the preset: a tennis ball on a basketball, dropped) | 2 | 3 s | 6 | $num | $num | $ir | - | [0-9.]* |$" "$T/chains.md" &&
    grep -q "^| touching, struck at 1 m/s | 10 | 0.2 ms | $num | $num | $ir | " "$T/chains.md" &&
    grep -q "^| 1 mm apart, struck at 1 m/s | 10 | 5 ms | $num | $num | $ir | " "$T/chains.md" &&
    ! grep -q '| 100 |\|| 1000 |' "$T/chains.md"; then
	echo "ok - the chains benchmark (make bench-chains) runs: the cradle of 5, the stacked drop, the cost of a step at N = 10"
else
	echo "not ok - the chains benchmark (make bench-chains) runs"
	sed 's/^/# /' "$T/out"
fi
