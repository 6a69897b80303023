#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
#
# oracle.sh - what a change of the engine's shape must not change.
#
#   sh tests/bench/oracle.sh record DIR [HYBOUNCE]   run every shipped preset (and a few
#                                                   variants of the numerics) into DIR
#   sh tests/bench/oracle.sh compare REF NEW         byte-compare two recordings
#
# For every run it keeps the collision table (CSV), the hybrid arc (CSV), and
# the summary's counts: steps, right-hand-side and Jacobian evaluations,
# events, samples (the run time, which varies, is left out).  Provenance lines
# are dropped.  compare exits 1 and names the runs that differ; identical
# tables and counts are what a refactoring of the engine must give.
set -u

usage() {
	echo "usage: $0 record DIR [HYBOUNCE] | compare REF NEW" >&2
	exit 2
}

[ $# -ge 2 ] || usage
here=$(cd "$(dirname "$0")/../.." && pwd)

# name and --set arguments of each variant, run on every preset
variants() {
	echo "base"
	echo "bsimp --set run.stepper=bsimp --set run.limits=no"
	echo "dop853 --set run.stepper=dop853"
	echo "auto --set run.stepper=auto"
	echo "none --set run.reductions=none"
	echo "nokinks --set run.kinks=no"
}

noprov() {
	grep -v '^#' "$1"
}

record() {
	dir=$1
	bin=${2:-$here/build/hybounce}
	mkdir -p "$dir"
	tmp=$(mktemp -d)
	trap 'rm -rf "$tmp"' EXIT
	for p in "$here"/presets/*.preset; do
		name=$(basename "$p" .preset)
		variants | while read -r v args; do
			out=$dir/$name.$v
			# shellcheck disable=SC2086
			"$bin" --batch "$p" $args --quiet --collisions "$tmp/c.csv" --trace "$tmp/t.csv" \
				>"$tmp/sum" 2>&1
			echo "exit $?" >"$out.counts"
			grep -E '^  (ended|end state|collisions|steps|evaluations|events|arc) ' "$tmp/sum" \
				>>"$out.counts"
			if [ -f "$tmp/c.csv" ]; then noprov "$tmp/c.csv" >"$out.collisions.csv"; fi
			if [ -f "$tmp/t.csv" ]; then noprov "$tmp/t.csv" | cksum >"$out.trace.cksum"; fi
			rm -f "$tmp/c.csv" "$tmp/t.csv" "$tmp"/*.preset
		done
	done
	echo "recorded $(ls "$dir"/*.counts | wc -l) runs into $dir"
}

compare() {
	ref=$1 new=$2 bad=0 n=0
	for f in "$ref"/*.counts; do
		r=$(basename "$f" .counts)
		n=$((n + 1))
		for ext in counts collisions.csv trace.cksum; do
			if [ -f "$ref/$r.$ext" ] || [ -f "$new/$r.$ext" ]; then
				if ! cmp -s "$ref/$r.$ext" "$new/$r.$ext"; then
					echo "differs: $r.$ext"
					bad=1
				fi
			fi
		done
	done
	if [ $bad -eq 0 ]; then
		echo "identical: $n runs (tables, arcs, counts)"
	fi
	return $bad
}

case $1 in
record) shift; record "$@" ;;
compare) [ $# -eq 3 ] || usage; compare "$2" "$3" ;;
*) usage ;;
esac
