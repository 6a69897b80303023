#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs every test: the Criterion unit tests, then each script under
# tests/cli/ and tests/tui/ (TAP-style: one "ok - NAME" or "not ok - NAME"
# line per test).  Ends with "N passed, N failed" alone on a line.
#
#   sh tests/run.sh BIN UNIT
#
# BIN is the hybounce binary, UNIT the Criterion test binary.  With
# HYBOUNCE_FUZZ_SMOKE="RUNS HARNESS..." (make check) the fuzz smoke runs last.
set -u
BIN=${1:-build/hybounce}
UNIT=${2:-build/unit-tests}
export HYBOUNCE_BIN="$(cd "$(dirname "$BIN")" && pwd)/$(basename "$BIN")"
export HYBOUNCE_PRESETS="$(pwd)/presets"
passed=0
failed=0

# Criterion: its own summary line is "Synthesis: Tested: N | Passing: N | Failing: N | Crashing: N".
out=$(mktemp)
"$UNIT" --jobs 2 >"$out" 2>&1
status=$?
cat "$out"
syn=$(grep 'Synthesis:' "$out" | tail -n 1)
if [ -n "$syn" ]; then
	p=$(echo "$syn" | sed 's/.*Passing: *\([0-9]*\).*/\1/')
	f=$(echo "$syn" | sed 's/.*Failing: *\([0-9]*\).*/\1/')
	c=$(echo "$syn" | sed 's/.*Crashing: *\([0-9]*\).*/\1/')
	passed=$((passed + p))
	failed=$((failed + f + c))
else
	echo "not ok - unit tests produced no synthesis (exit $status)"
	failed=$((failed + 1))
fi
[ "$status" -ne 0 ] && [ -n "$syn" ] && [ "$f" = 0 ] && [ "$c" = 0 ] && {
	echo "not ok - unit tests exited $status"
	failed=$((failed + 1))
}
rm -f "$out"

# count NAME COMMAND...: runs a TAP-style test command and counts its lines.
count() {
	name=$1
	shift
	out=$(mktemp)
	"$@" >"$out" 2>&1
	status=$?
	cat "$out"
	p=$(grep -c '^ok ' "$out")
	f=$(grep -c '^not ok ' "$out")
	passed=$((passed + p))
	failed=$((failed + f))
	if [ "$status" -ne 0 ] && [ "$f" = 0 ]; then
		echo "not ok - $name exited $status"
		failed=$((failed + 1))
	fi
	if [ "$p" = 0 ] && [ "$f" = 0 ] && [ "$status" = 0 ]; then
		echo "not ok - $name ran no test"
		failed=$((failed + 1))
	fi
	rm -f "$out"
}

for t in tests/cli/*.sh tests/tui/*.sh; do
	[ -f "$t" ] || continue
	count "$t" sh "$t"
done

# The fuzz smoke (make check sets HYBOUNCE_FUZZ_SMOKE="RUNS HARNESS..."):
# each libFuzzer harness for RUNS executions, counted like the scripts.
if [ -n "${HYBOUNCE_FUZZ_SMOKE:-}" ]; then
	# shellcheck disable=SC2086 # RUNS and the harnesses are words
	count "fuzz smoke" sh tests/fuzz/run.sh smoke $HYBOUNCE_FUZZ_SMOKE
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
