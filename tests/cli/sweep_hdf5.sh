#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce sweep --format hdf5: DIR/sweep.h5 instead of the CSV files, read
# by h5py and pandas to the same values as the CSV sweep (chunked,
# compressed, units and spec as attributes); a complete folder kept, a
# CSV folder not mixed with HDF5; shards merged into HDF5; a refined sweep;
# --emit passes the format to its merge; memory flat in the points.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"

PY=${PYTHON:-/usr/bin/python3}
if ! "$PY" -c 'import h5py, pandas' 2>/dev/null; then
	echo "ok - # SKIP python3-h5py or python3-pandas missing (make deps installs them)"
	exit 0
fi
CHECK="$(pwd)/tests/cli/sweep_hdf5.py"
EX=examples/sweeps/restitution-shccl.preset
V1="initial.v0=-1mm/s:-1m/s:30:log"
V2="scene.law=shccl,hertz"

# 1. The file, against the CSV sweep of the same command.
"$BIN" sweep $EX --vary "$V1" --vary "$V2" --jobs 2 --format hdf5 --out "$T/h" >"$T/out" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && [ "$(ls -A "$T/h" | tr '\n' ' ')" = "sweep.h5 sweep.preset " ] &&
    grep -q "^wrote $T/h/sweep.h5$" "$T/err" && [ ! -s "$T/out" ]; then
	ok "--format hdf5 writes DIR/sweep.h5 (and sweep.preset), no CSV, no journal"
else notok "--format hdf5 writes DIR/sweep.h5 (exit $rc)" "$T/err"; fi
"$BIN" sweep $EX --vary "$V1" --vary "$V2" --jobs 2 --quiet --out "$T/c" 2>"$T/err"
if "$PY" "$CHECK" "$T/h/sweep.h5" "$T/c" >"$T/py" 2>&1; then
	ok "h5py and pandas read /runs and /collisions as runs.csv and collisions.csv hold them (to the bit), chunked, compressed, with units, columns and spec"
else notok "sweep.h5 holds what the CSV files hold" "$T/py"; fi

# 2. Run again: kept; a folder complete as CSV is not turned into HDF5.
"$BIN" sweep $EX --vary "$V1" --vary "$V2" --format hdf5 --out "$T/h" 2>"$T/err"
if [ $? -eq 0 ] && grep -q "^kept $T/h/sweep.h5 (the sweep was complete)$" "$T/err"; then
	ok "a complete HDF5 sweep run again is kept"
else notok "a complete HDF5 sweep run again is kept" "$T/err"; fi
"$BIN" sweep $EX --vary "$V1" --vary "$V2" --format hdf5 --out "$T/c" 2>"$T/err"
if [ $? -eq 2 ] && grep -q 'holds this sweep complete as runs.csv and collisions.csv' "$T/err" &&
    [ ! -e "$T/c/sweep.h5" ]; then
	ok "--format hdf5 on a folder complete as CSV: exit 2, saying so"
else notok "--format hdf5 on a folder complete as CSV" "$T/err"; fi

# 3. Shards merged into HDF5.
for k in 0 1 2; do
	"$BIN" sweep $EX --vary "$V1" --vary "$V2" --jobs 1 --quiet --shard $k/3 --out "$T/s" 2>>"$T/err"
done
"$BIN" sweep --merge "$T/s" --format hdf5 2>"$T/err"
if [ $? -eq 0 ] && [ -f "$T/s/sweep.h5" ] && [ ! -e "$T/s/runs.csv" ] &&
    "$PY" "$CHECK" "$T/s/sweep.h5" "$T/c" >"$T/py" 2>&1; then
	ok "--merge DIR --format hdf5: three shards into sweep.h5, the same values"
else notok "--merge --format hdf5 of shards" "$T/err"; show "$T/py"; fi
"$BIN" sweep $EX --vary "$V1" --vary "$V2" --out "$T/e" --emit parallel --shards 2 \
    --format hdf5 >"$T/line" 2>"$T/err"
if [ $? -eq 0 ] && grep -q -- "--merge .* --shards 2 --format hdf5$" "$T/line"; then
	ok "--emit parallel --format hdf5: the merge writes sweep.h5"
else notok "--emit parallel --format hdf5" "$T/line"; fi

# 4. A refined sweep: sweep.h5 with the refined column, boundaries.csv beside it.
"$BIN" sweep $EX --vary "initial.v0=-1mm/s:-1m/s:21:log" --refine e_first --format hdf5 \
    --quiet --out "$T/r5" 2>"$T/err" &&
"$BIN" sweep $EX --vary "initial.v0=-1mm/s:-1m/s:21:log" --refine e_first --quiet \
    --out "$T/r" 2>>"$T/err"
if [ "$(ls -A "$T/r5" | tr '\n' ' ')" = "boundaries.csv sweep.h5 sweep.preset " ] &&
    cmp -s "$T/r/boundaries.csv" "$T/r5/boundaries.csv" &&
    "$PY" "$CHECK" "$T/r5/sweep.h5" "$T/r" refined >"$T/py" 2>&1; then
	ok "--refine --format hdf5: sweep.h5 (with the refined column) and boundaries.csv"
else notok "--refine --format hdf5" "$T/err"; show "$T/py"; fi

# 5. Bad input.
"$BIN" sweep $EX --vary "$V1" --format xml --out "$T/bad" >/dev/null 2>"$T/err"
if [ $? -eq 2 ] && grep -q "accepted: csv, hdf5" "$T/err" && [ ! -e "$T/bad" ]; then
	ok "--format xml: exit 2, saying what is accepted"
else notok "--format xml: exit 2" "$T/err"; fi

# 6. Memory: the merge into HDF5 streams.  Journals of 100,000 and 300,000
# points (one real point's block, its id changed) merged; the peak resident
# size grows by what the CSV merge keeps (journals in id order are read side
# by side: a bit a point; a range's values are computed, not kept), not by
# the file.  (Below 100,000 points the
# library's caches are still filling: 20,000 points take 7 MB less.)
mkjournal() {
	"$BIN" sweep $EX --vary "initial.v0=-1mm/s:-1m/s:$1:log" --out "$T/m$1" --emit parallel \
	    --shards 1 >/dev/null 2>&1
	awk -v n="$1" -F, '
	    FILENAME ~ /collisions/ && FNR == 2 { sub(/^[^,]*,/, ""); c = $0 }
	    FILENAME ~ /runs/ && FNR == 2 { sub(/^[^,]*,[^,]*,/, ""); r = $0 }
	    END { for (i = 0; i < n; i++) { print "c," i "," c; print "r," i ",-0.5," r } }' \
	    "$T/r/collisions.csv" "$T/r/runs.csv" >"$T/m$1/points.journal"
}
rss() {
	"$PY" -c 'import resource, subprocess, sys
rc = subprocess.run(sys.argv[1:]).returncode
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss if rc == 0 else -1)' "$@"
}
if grep -a -q -e __asan_init -e __tsan_init "$BIN" 2>/dev/null; then
	# the sanitizer's allocator keeps freed blocks (its quarantine): no measure of the merge
	echo "ok - # SKIP the HDF5 merge's memory: a sanitizer build (make check measures it)"
	[ "$fails" -eq 0 ]
	exit
fi
mkjournal 100000
mkjournal 300000
a=$(rss "$BIN" sweep --merge "$T/m100000" --format hdf5 --quiet)
b=$(rss "$BIN" sweep --merge "$T/m300000" --format hdf5 --quiet)
rows=$("$PY" -c 'import h5py, sys; print(len(h5py.File(sys.argv[1])["runs"]))' "$T/m300000/sweep.h5")
per=$(( (b - a) * 1024 / 200000 ))
if [ "$a" -gt 0 ] && [ "$b" -gt 0 ] && [ "$rows" -eq 300000 ] && [ "$per" -le 4 ]; then
	ok "the HDF5 merge streams: 300,000 points take $(( b - a )) kB more than 100,000 ($per bytes a point; the file is $(( $(wc -c <"$T/m300000/sweep.h5") / 1024 )) kB, its journal $(( $(wc -c <"$T/m300000/points.journal") / 1024 )) kB)"
else notok "the HDF5 merge streams (peak $a kB and $b kB, $per bytes a point, $rows rows)"; fi
rm -rf "$T/m100000" "$T/m300000"

[ "$fails" -eq 0 ]
