#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# chains.sh BIN OUT.md: the work of a chain's run (a benchmark, not a test),
# in counts: instructions inside hb_sim_advance (valgrind callgrind,
# --toggle-collect), right-hand-side evaluations, accepted steps, and the
# run's CPU time from the batch summary (a loaded machine: compare times
# only within a row).  Steel balls of R 10 mm, the Hertz law, rtol 1e-12,
# atol 1e-14, no gravity:
#  1. a touching Newton's cradle of 5 struck at 1 m/s, over 10 ms, and
#     the stacked-drop preset as it ships (its own laws and tolerances);
#  2. a touching chain of 100 beads struck at 1 m/s over the time its
#     solitary wave takes to cross it (100 diameters at the speed measured
#     in tests/test_chain.c, 670 m/s: 3 ms), per bead;
#  3. the cost of a step against N: touching chains of 10, 100 and 1,000
#     beads struck at 1 m/s over 0.2 ms (the wave crosses about 7 beads:
#     the same events at every N), instructions per step and per rhs;
#     and chains 1 mm apart over 5 ms (one contact at a time, the rest in
#     flight);
#  4. the explorer on the 100-bead chain of 2: instructions a frame drawn
#     in its plots and in the space-time view (--script, callgrind).
#  --smoke (first): rows 1 and the N = 10 rows of 3 only (make check's
#  bounded run of this benchmark).
set -u
smoke=0
if [ "${1:-}" = --smoke ]; then
	smoke=1
	shift
fi
BIN=${1:-build/hybounce}
OUT=${2:-build/bench/chains.md}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
cg=1
command -v valgrind >/dev/null || cg=0
# a sanitizer's build does not run under valgrind: no instructions counted
grep -a -q -e __asan_init -e __tsan_init "$BIN" && cg=0

. "$(dirname "$0")/../chain.inc"
steel_chain 'bench chain' 5 '0 m' '10 ms' >"$T/chain.preset"

# run NAME ARG...: one row's counts into $T/NAME.{q,ir}, the batch run with ARG...
run() {
	name=$1
	shift
	"$BIN" --batch "$@" -q >"$T/$name.q" 2>&1 || { echo "chains.sh: $name failed" >&2; cat "$T/$name.q" >&2; exit 1; }
	ir=-
	if [ $cg = 1 ]; then
		rm -f "$T/cg.out"
		valgrind --tool=callgrind --toggle-collect=hb_sim_advance --callgrind-out-file="$T/cg.out" \
		    "$BIN" --batch "$@" -q >/dev/null 2>&1
		ir=$(awk '$1 == "summary:" || $1 == "totals:" { print $2; exit }' "$T/cg.out" 2>/dev/null)
		[ -n "$ir" ] || ir=-
	fi
	echo "$ir" >"$T/$name.ir"
}
# chain NAME N SPACING T: run NAME on the bench chain of N beads SPACING apart over T
chain() {
	run "$1" "$T/chain.preset" --set chain.n="$2" --set chain.spacing="$3" --set run.T="$4"
}
# frame VIEW NDUMP: instructions in app_draw for NDUMP frames of the explorer on the
# 100-bead chain over 3 ms, finished, in VIEW (plots, or V: the space-time view)
frame() {
	[ $cg = 1 ] || { echo -; return; }
	{ echo "size 100x30"; echo "wait-finished"; echo "Home"; [ "$1" = V ] && { echo V; echo "wait 60000"; }
	  k=0; while [ $k -lt "$2" ]; do echo "dump $T/d$k.txt"; k=$((k + 1)); done; } >"$T/s.txt"
	rm -f "$T/cgf"
	valgrind --tool=callgrind --toggle-collect=app_draw --collect-atstart=no \
	    --callgrind-out-file="$T/cgf" "$BIN" --script "$T/s.txt" --set chain.n=100 \
	    --set chain.spacing=0 --set run.T=3ms "$T/chain.preset" >/dev/null 2>&1
	v=$(sed -n 's/^totals: *\([0-9]*\).*/\1/p; s/^summary: *\([0-9]*\).*/\1/p' "$T/cgf" 2>/dev/null | head -n 1)
	echo "${v:--}"
}
# field NAME: rhs steps collisions cpu_ms instructions
field() {
	rhs=$(awk '$1 == "evaluations" { print $2 }' "$T/$1.q")
	steps=$(awk '$1 == "steps" && $3 == "accepted," { print $2 }' "$T/$1.q")
	coll=$(awk '$1 == "collisions" && NF == 2 { print $2 }' "$T/$1.q")
	cpu=$(awk '$1 == "run" && $2 == "time" { v = $3; u = $4; if (u == "us") v /= 1000; else if (u == "s") v *= 1000; printf "%.3g", v }' "$T/$1.q")
	echo "$rhs $steps $coll $cpu $(cat "$T/$1.ir")"
}

{
echo "hybounce chains benchmark ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) online processors, load average $(cut -d' ' -f1-3 /proc/loadavg))"
echo
echo "| run | N | T | collisions | steps | rhs | instructions (hb_sim_advance) | per bead: rhs, instructions | CPU ms (loaded) |"
echo "|---|---|---|---|---|---|---|---|---|"
chain cradle5 5 0 10ms
set -- $(field cradle5)
echo "| touching cradle, struck at 1 m/s | 5 | 10 ms | $3 | $2 | $1 | $5 | - | $4 |"
run stacked stacked-drop
set -- $(field stacked)
echo "| stacked-drop (the preset: a tennis ball on a basketball, dropped) | 2 | 3 s | $3 | $2 | $1 | $5 | - | $4 |"
if [ $smoke = 0 ]; then
	chain wave100 100 0 3ms
	set -- $(field wave100)
	echo "| touching chain, the wave across it | 100 | 3 ms | $3 | $2 | $1 | $5 | $(awk -v r="$1" -v i="$5" 'BEGIN { printf "%.0f, %s", r / 100, (i == "-") ? "-" : sprintf("%.0f", i / 100) }') | $4 |"
fi
Ns="10 100 1000"
[ $smoke = 1 ] && Ns=10
echo
echo "Cost of a step against N (the same physical events at every N):"
echo
echo "| chain | N | T | steps | rhs | instructions | per step | per rhs |"
echo "|---|---|---|---|---|---|---|---|"
for n in $Ns; do
	chain "t$n" "$n" 0 0.2ms
	set -- $(field "t$n")
	echo "| touching, struck at 1 m/s | $n | 0.2 ms | $2 | $1 | $5 | $(awk -v s="$2" -v i="$5" 'BEGIN { if (i == "-") print "-"; else printf "%.0f", i / s }') | $(awk -v r="$1" -v i="$5" 'BEGIN { if (i == "-") print "-"; else printf "%.0f", i / r }') |"
done
for n in $Ns; do
	chain "a$n" "$n" 1mm 5ms
	set -- $(field "a$n")
	echo "| 1 mm apart, struck at 1 m/s | $n | 5 ms | $2 | $1 | $5 | $(awk -v s="$2" -v i="$5" 'BEGIN { if (i == "-" || s == 0) print "-"; else printf "%.0f", i / s }') | $(awk -v r="$1" -v i="$5" 'BEGIN { if (i == "-" || r == 0) print "-"; else printf "%.0f", i / r }') |"
done
if [ $smoke = 0 ]; then
	echo
	echo "The explorer on the 100-bead chain (the wave across it, 3 ms; --script at 100x30, the run"
	echo "finished, the space-time view's bodies computed, in slices between frames, until idle):"
	echo "instructions a frame drawn (app_draw, inclusive; 11 frames less 1, over 10):"
	echo
	echo "| view | samples | instructions a frame | a frame at 1e9 instructions a second |"
	echo "|---|---|---|---|"
	samples=$(awk '$1 == "arc" { print $2 }' "$T/wave100.q")
	for view in plots V; do
		label="the plots (x, x_c, F_c of the body and interface chosen) and the table"
		[ "$view" = V ] && label="the space-time view (V): every body's line, the contacts"
		f=$(frame "$view" 11)
		g=$(frame "$view" 1)
		echo "| $label | $samples | $(awk -v a="$f" -v b="$g" 'BEGIN { if (a == "-" || b == "-") print "-"; else printf "%.0f", (a - b) / 10 }') | $(awk -v a="$f" -v b="$g" 'BEGIN { if (a == "-" || b == "-") print "-"; else printf "%.2g ms", (a - b) / 10 / 1e6 }') |"
	done
fi
} >"$OUT"
cat "$OUT"
