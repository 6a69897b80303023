#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# tests/bench/studies.sh --smoke (make bench's per-study summary) runs: one
# study, and its row carries the work (rhs, rejected steps), the engine's
# time, the true error against tests/reference (below 1e-9) and the
# largest --error bar; the callgrind and SciPy columns are numbers where
# valgrind and python3-scipy are there (a sanitizer build is "-").
. "$(dirname "$0")/common.inc"
sh tests/bench/studies.sh --smoke "$BIN" "$T/s.md" >"$T/out" 2>&1
st=$?
row=$(grep '^| permanent-contact-bwmcl |' "$T/s.md" 2>/dev/null)
if [ $st -eq 0 ] && echo "$row" | awk -F' *\\| *' '
    $3 !~ /^([0-9]+|-)$/ { exit 1 }            # instructions / rhs
    $4 !~ /^[0-9]+$/ || $5 !~ /^[0-9]+$/ { exit 1 }
    !($6 > 0) { exit 1 }                       # engine ms
    $7 != "-" && !($7 > 0) { exit 1 }          # SciPy ms
    !($9 + 0 > 0 && $9 + 0 < 1e-9) { exit 1 }  # true error
    !($10 + 0 > 0) { exit 1 }                  # error bar
    $11 !~ /\+-/ { exit 1 }'; then
	ok "bench_studies: the summary row of a study is whole ($row)"
else
	notok "bench_studies: studies.sh --smoke (exit $st)" "$T/out"
fi
[ "$fails" -eq 0 ]
