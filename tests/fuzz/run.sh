#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the libFuzzer harnesses (see fuzz.h and the Makefile's fuzz targets).
#
#   sh tests/fuzz/run.sh smoke RUNS BIN...      each harness RUNS executions (make check);
#                                               fuzz_run, whose every input runs a simulation
#                                               (about 40 times dearer an execution), RUNS/5
#   sh tests/fuzz/run.sh campaign SECONDS BIN... each harness SECONDS (make fuzz)
#
# Seeds are tests/fuzz/corpus/units or, for the preset harnesses,
# tests/fuzz/corpus/preset and presets/ (never written); new inputs go to a
# temporary folder (smoke) or build/fuzz/corpus/NAME (campaign, kept between
# campaigns); a finding is left in build/fuzz/findings/ and reported.
# Prints one TAP line per harness ("ok - fuzz NAME: N executions, 0
# findings") and the total.
set -u
mode=$1
amount=$2
shift 2
FIND=build/fuzz/findings
mkdir -p "$FIND"
total=0
fails=0
for bin in "$@"; do
	name=$(basename "$bin")
	# the preset harnesses share their seeds (the shipped presets and
	# tests/fuzz/corpus/preset) and dictionary
	case $name in
	fuzz_units) seeds=tests/fuzz/corpus/units dict=-dict=tests/fuzz/units.dict ;;
	fuzz_fitdata) seeds="tests/fuzz/corpus/fitdata examples/fit" dict= ;;
	*) seeds="tests/fuzz/corpus/preset presets" dict=-dict=tests/fuzz/preset.dict ;;
	esac
	if [ "$mode" = smoke ]; then
		work=$(mktemp -d)
		runs=$amount
		[ "$name" = fuzz_run ] && runs=$((amount / 5))
		limit="-runs=$runs -seed=1"
	else
		work=build/fuzz/corpus/$name
		mkdir -p "$work"
		limit="-max_total_time=$amount"
	fi
	log=$(mktemp)
	before=$(ls "$FIND" | wc -l)
	# shellcheck disable=SC2086
	ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	    "$bin" $limit $dict -max_len=8192 -timeout=20 -rss_limit_mb=1024 \
	    -print_final_stats=1 -artifact_prefix="$FIND/$name-" "$work" $seeds >"$log" 2>&1
	rc=$?
	after=$(ls "$FIND" | wc -l)
	runs=$(sed -n 's/^stat::number_of_executed_units: *\([0-9]*\).*/\1/p' "$log" | tail -n 1)
	runs=${runs:-0}
	total=$((total + runs))
	known=$(sed -n "s/^$name //p" tests/fuzz/known-failing 2>/dev/null)
	if [ "$rc" -eq 0 ] && [ "$after" -eq "$before" ] && [ "$runs" -gt 0 ]; then
		echo "ok - fuzz $name: $runs executions, 0 findings"
		[ -n "$known" ] && echo "# $name is listed in tests/fuzz/known-failing but found nothing: remove its line"
	elif [ -n "$known" ] && [ "$runs" -gt 0 ]; then
		echo "ok - fuzz $name: $runs executions, a known finding # TODO $known"
		grep -E 'saved, |does not load back|runtime error|SUMMARY' "$log" | head -n 3 | sed 's/^/# /'
	else
		echo "not ok - fuzz $name: $runs executions, exit $rc, findings in $FIND:"
		grep -E 'ERROR|runtime error|SUMMARY|Test unit written|^[a-z].*: .*(saved|back|refus)' "$log" |
		    head -n 20 | sed 's/^/# /'
		fails=$((fails + 1))
	fi
	rm -f "$log"
	[ "$mode" = smoke ] && rm -rf "$work"
done
echo "# fuzz: $total executions over $# harnesses, $fails with findings"
[ "$fails" -eq 0 ]
