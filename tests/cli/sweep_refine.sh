#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce sweep --refine: a boundary of a shipped example located to 1e-3
# of its axis with at most 10 % of the runs of the uniform grid of that
# resolution, and where the dense uniform grid puts it (the same points,
# bit for bit); a threshold of e; two axes against their dense grid; the
# refined column; resuming from a journal (and a torn one); bad input.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"

EX=examples/sweeps/restitution-shccl.preset
V="initial.v0=-1mm/s:-1m/s:21:log"

# The class changes (pairs of neighbouring rows) of a uniform sweep's
# runs.csv: column $2 (1-based), by existence (empty or not), or by the
# threshold $3 ("<0.5"): "ID_A,ID_B" per line.
changes() {
	awk -F, -v col="$2" -v thr="${3:-}" 'NR > 1 {
		v = $col
		if (thr == "") c = (v == "") ? 0 : 1
		else if (v == "") c = 2
		else c = (v + 0 < substr(thr, 2) + 0) ? 1 : 0
		if (NR > 2 && c != pc) print pid "," $1
		pc = c; pid = $1
	}' "$1"
}

# 1. One boundary: permanent contact or a collision that ends (e_first exists).
"$BIN" sweep $EX --vary "$V" --refine e_first --jobs 2 --out "$T/r" >"$T/out" 2>"$T/err"
rc=$?
runs=$(($(wc -l <"$T/r/runs.csv") - 1))
if [ $rc -eq 0 ] && [ ! -s "$T/out" ] && [ -f "$T/r/boundaries.csv" ] &&
    [ "$(ls -A "$T/r" | tr '\n' ' ')" = "boundaries.csv collisions.csv runs.csv sweep.preset " ] &&
    grep -q '^; sweep: --refine e_first$' "$T/r/sweep.preset"; then
	ok "--refine writes runs.csv, collisions.csv, boundaries.csv and a '; sweep: --refine' line"
else notok "--refine writes its files (exit $rc)" "$T/err"; fi
if [ "$(wc -l <"$T/r/boundaries.csv")" -eq 2 ] &&
    head -n 1 "$T/r/boundaries.csv" | grep -qx 'id_a,id_b,axis,from,to,initial.v0,e_first_a,e_first_b' &&
    grep -q "^sweep: refined: 1 boundary located to 0.00078 of the axis (6 bisections) in $runs runs, 21 of the grid and $((runs - 21)) added; the uniform grid of that resolution is 1281 runs" "$T/err"; then
	ok "one boundary, located to 1/1280 of the axis in $runs runs; the summary says so"
else notok "one boundary and its summary" "$T/err"; show "$T/r/boundaries.csv"; fi
if [ "$runs" -le 128 ]; then
	ok "the boundary costs $runs runs, at most 10 % of the 1281 of the uniform grid of that resolution"
else notok "the boundary costs $runs runs, more than 10 % of 1281"; fi

# The dense uniform grid of that resolution: the same boundary, the same points.
"$BIN" sweep $EX --vary "initial.v0=-1mm/s:-1m/s:1281:log" --jobs 2 --quiet --out "$T/u" 2>"$T/err"
changes "$T/u/runs.csv" 7 >"$T/want"
cut -d, -f1,2 "$T/r/boundaries.csv" | tail -n +2 >"$T/got"
if [ -s "$T/want" ] && cmp -s "$T/want" "$T/got"; then
	ok "the refined boundary is the dense uniform grid's: points $(tr '\n' ' ' <"$T/got")"
else notok "the refined boundary is the dense uniform grid's (want $(tr '\n' ' ' <"$T/want"))" "$T/got"; fi
# Every refined point is the uniform grid's point of the same id, to the bit.
sed 's/,[^,]*,[^,]*$//' "$T/r/runs.csv" >"$T/rr"
nocpu "$T/u/runs.csv" >"$T/uu"
awk -F, 'NR == FNR { want[$1] = $0; next } FNR > 1 && want[$1] != $0 { print "point " $1 " differs" }' \
    "$T/uu" "$T/rr" >"$T/diff"
awk -F, 'NR == FNR { if (FNR > 1) keep[$1] = 1; next } FNR == 1 || ($1 in keep)' \
    "$T/r/runs.csv" "$T/u/collisions.csv" >"$T/ucoll"
if [ ! -s "$T/diff" ] && cmp -s "$T/ucoll" "$T/r/collisions.csv"; then
	ok "each refined point's row and collisions equal the uniform sweep's point of that id"
else notok "refined points equal the uniform sweep's" "$T/diff"; fi
# The refined column: 0 on the grid (every 64th lattice point), the round otherwise.
head -n 1 "$T/r/runs.csv" | grep -q ',jac,refined,cpu_s$' &&
awk -F, 'NR > 1 { lv = $(NF - 1); if (($1 % 64 == 0) != (lv == 0) || lv < 0 || lv > 6) bad++ }
    END { exit bad > 0 }' "$T/r/runs.csv"
if [ $? -eq 0 ] && [ "$(awk -F, 'NR > 1 && $(NF - 1) == 0' "$T/r/runs.csv" | wc -l)" -eq 21 ]; then
	ok "runs.csv's refined column: 0 for the 21 grid points, the round (1-6) for the added ones"
else notok "runs.csv's refined column" "$T/r/runs.csv"; fi

# 2. Resuming: a journal of some of the points (and a torn block at its end).
mkdir "$T/res"
cp "$T/r/sweep.preset" "$T/res/"
for id in 0 64 128 640 1280 256; do
	grep "^$id," "$T/r/collisions.csv" | sed 's/^/c,/'
	grep "^$id," "$T/r/runs.csv" | sed 's/,[^,]*,\([^,]*\)$/,\1/; s/^/r,/'
done >"$T/res/points.journal"
printf 'c,1,0,0.1' >>"$T/res/points.journal"
"$BIN" sweep "$T/res/sweep.preset" --out "$T/res" --jobs 2 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q 'resuming: 6 of 6 points already done' "$T/err" &&
    [ ! -f "$T/res/points.journal" ] && same_sweep "$T/r" "$T/res" &&
    cmp -s "$T/r/boundaries.csv" "$T/res/boundaries.csv"; then
	ok "a journal of 6 points (and a torn block) resumes to the same files"
else notok "resuming a refined sweep (exit $rc)" "$T/err"; fi
"$BIN" sweep "$T/res/sweep.preset" --out "$T/res" 2>"$T/err"
if [ $? -eq 0 ] && grep -q 'kept .*boundaries.csv' "$T/err" && same_sweep "$T/r" "$T/res"; then
	ok "a complete refined sweep run again is kept"
else notok "a complete refined sweep run again is kept" "$T/err"; fi

# 3. A threshold of e: e_first < 0.5 (three boundaries: the collision begins, e rises through 0.5, falls through it).
"$BIN" sweep $EX --vary "$V" --refine 'e_first<0.5' --jobs 2 --quiet --out "$T/t" 2>"$T/err"
changes "$T/u/runs.csv" 7 '<0.5' >"$T/want"
cut -d, -f1,2 "$T/t/boundaries.csv" | tail -n +2 >"$T/got"
if [ "$(wc -l <"$T/got")" -eq 3 ] && cmp -s "$T/want" "$T/got" &&
    awk -F, 'function cls(v) { return v == "" ? 2 : v + 0 < 0.5 }
        NR > 1 && cls($7) == cls($8) { bad++ } END { exit bad > 0 }' "$T/t/boundaries.csv"; then
	ok "e_first<0.5: three boundaries, where the dense uniform grid has them"
else notok "e_first<0.5: three boundaries (want $(tr '\n' ' ' <"$T/want"))" "$T/got"; fi

# 4. Two axes: the impact velocity and c; the boundary cells' edges are the dense grid's.
V2="law.c=1e9:1e10:5:log"
"$BIN" sweep $EX --vary "initial.v0=-1mm/s:-10mm/s:5:log" --vary "$V2" --refine e_first:0.02 \
    --jobs 2 --quiet --out "$T/two" 2>"$T/err"
rc=$?
"$BIN" sweep $EX --vary "initial.v0=-1mm/s:-10mm/s:65:log" --vary "law.c=1e9:1e10:65:log" \
    --jobs 2 --quiet --out "$T/two-u" 2>>"$T/err"
# the dense grid's class changes along each axis: "ID_A,ID_B"
awk -F, 'NR > 1 { c[$1] = ($8 == "") ? 0 : 1 }
    END { for (id = 0; id < 65 * 65; id++) {
        if (id % 65 < 64 && c[id] != c[id + 1]) print id "," id + 1
        if (id + 65 < 65 * 65 && c[id] != c[id + 65]) print id "," id + 65 } }' \
    "$T/two-u/runs.csv" | sort >"$T/want"
cut -d, -f1,2 "$T/two/boundaries.csv" | tail -n +2 | sort >"$T/got"
truns=$(($(wc -l <"$T/two/runs.csv") - 1))
if [ $rc -eq 0 ] && [ -s "$T/want" ] && cmp -s "$T/want" "$T/got" && [ "$truns" -lt 4225 ]; then
	ok "two axes: the $(wc -l <"$T/got") boundary edges of the dense 65 x 65 grid, in $truns of its 4225 runs"
else notok "two axes: the dense grid's boundary edges ($truns runs)" "$T/err"; fi

# 5. Bad input: exit 2, nothing written.
for args in "--refine nosuch" "--refine e_first:0" "--refine e_first:2" "--refine e_first<x" \
    "--vary law.c=1e9,2e9 --refine e_first" "--refine e_first --shard 0/2" \
    "--refine e_first --emit slurm" "--vary run.T=0.1:0.2:2 --vary law.c=1e9:1e10:2 --refine e_first"; do
	# shellcheck disable=SC2086
	"$BIN" sweep $EX --vary "$V" $args --out "$T/bad" >/dev/null 2>"$T/err"
	rc=$?
	if [ $rc -eq 2 ] && [ ! -e "$T/bad/runs.csv" ] && grep -q 'accepted' "$T/err"; then
		ok "$args: exit 2 saying what is accepted"
	else notok "$args: exit 2 (got $rc)" "$T/err"; fi
	rm -rf "$T/bad"
done
# A refused point of the grid (each is validated in its run): exit 2, named, nothing left.
"$BIN" sweep permanent-contact-bwshccl --vary "law.beta=5e9:1e9:3" --set law.gamma=2e9 \
    --refine e_first:0.1 --jobs 2 --quiet --out "$T/rbad" 2>"$T/err"
rc=$?
if [ $rc -eq 2 ] && [ ! -e "$T/rbad" ] &&
   grep -q 'point 16 (law.beta=1000000000): law.gamma: ' "$T/err"; then
	ok "a refined sweep with a bad point: exit 2 naming it, no folder left"
else notok "a refined sweep with a bad point (exit $rc)" "$T/err"; fi
"$BIN" sweep --merge "$T/r" >/dev/null 2>"$T/err"
if [ $? -ne 0 ] && grep -q 'refined sweep' "$T/err"; then
	ok "--merge of a refined folder says the folder's own command resumes it"
else notok "--merge of a refined folder" "$T/err"; fi

[ "$fails" -eq 0 ]
