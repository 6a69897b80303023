#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce sweep --error: each point's error bars (error.h) as columns,
# OBS_err in runs.csv and NAME_err in collisions.csv; every point's
# collisions byte for byte those of hybounce --batch --error with the
# row's --set; kept through sweep.preset by a shard, --merge, a resume,
# --refine and --format hdf5; refused with --merge.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"

P=permanent-contact-shccl
V1="initial.x0=10um,40um"
V2="law.c=1e9,4.3e9"
OBS="collisions t_pc e_first v_i_first e_last v_i_last x_c_r_total t_end j_end q_c_end x_end v_end x_c_end leaving"

# 1. The files: the error columns, the spec line.
"$BIN" sweep $P --vary "$V1" --vary "$V2" --error --jobs 2 --quiet --out "$T/one" 2>"$T/err"
rc=$?
want="id,initial.x0,law.c,status,message,$(echo $OBS steps rejected rhs jac | tr ' ' ,),$(for o in $OBS; do printf '%s_err,' $o; done)cpu_s"
if [ $rc -eq 0 ] && [ "$(head -n 1 "$T/one/runs.csv")" = "$want" ] &&
    head -n 1 "$T/one/collisions.csv" | grep -q '^id,i,t_e,.*,Lambda,t_e_err,t_s_err,.*,e_err,.*,Lambda_err$' &&
    grep -qx '; sweep: --error' "$T/one/sweep.preset"; then
	ok "sweep --error: runs.csv has OBS_err beside each observable (not the work counts), collisions.csv NAME_err, sweep.preset a '; sweep: --error' line"
else notok "sweep --error: the files (exit $rc)" "$T/err"; show "$T/one/runs.csv" 2; fi
# every error bar of an ok point is filled: a number, >= 0
# (columns 24 to 36; t_pc_err, 25, is empty where there is no permanent contact;
# leaving_err, 37, is empty for two bodies, which have no chain to leave)
bad=$(awk -F, 'NR > 1 { if ($4 != "ok") n++; for (k = 24; k <= 36; k++) if (k != 25 && ($k == "" || $k < 0)) n++ } END { print n + 0 }' "$T/one/runs.csv")
bad2=$(awk -F, 'NR > 1 && $0 !~ /^#/ { for (k = 16; k <= NF; k++) if ($k == "" || $k < 0) n++ } END { print n + 0 }' "$T/one/collisions.csv")
if [ "$bad" -eq 0 ] && [ "$bad2" -eq 0 ]; then
	ok "sweep --error: every error bar of every point and collision is a number >= 0"
else notok "sweep --error: empty or negative error bars ($bad in runs, $bad2 in collisions)" "$T/one/runs.csv"; fi

# 2. Bit-identical to --batch --error, point by point; e_first_err is the
# first collision's e_err.
tail -n +2 "$T/one/runs.csv" | while IFS=, read -r id x0 c rest; do
	"$BIN" --batch $P --set initial.x0="$x0" --set law.c="$c" --error --collisions "$T/b.csv" \
	    --quiet >"$T/b.out" 2>/dev/null || { echo "batch $id failed"; continue; }
	tail -n +2 "$T/b.csv" >"$T/b.rows"
	grep "^$id," "$T/one/collisions.csv" | cut -d, -f2- >"$T/s.rows"
	[ -s "$T/b.rows" ] || echo "point $id: no collision"
	cmp -s "$T/b.rows" "$T/s.rows" || echo "point $id: collisions differ"
	ee=$(head -n 1 "$T/s.rows" | awk -F, '{ print $(7 + 13) }')   # i, 13 values, e_err the 6th error
	ef=$(grep "^$id," "$T/one/runs.csv" | cut -d, -f26)
	[ -n "$ee" ] && [ "$ee" = "$ef" ] || echo "point $id: e_first_err $ef, the first collision's e_err $ee"
done >"$T/diff"
if [ ! -s "$T/diff" ]; then
	ok "sweep --error: every point's collisions and error bars are its --batch --error run's, byte for byte"
else notok "sweep --error against --batch --error" "$T/diff"; fi

# 3. Shards, one of them run from DIR/sweep.preset alone, then --merge.
"$BIN" sweep $P --vary "$V1" --vary "$V2" --error --shard 0/2 --jobs 1 --quiet --out "$T/sh" 2>"$T/err" &&
"$BIN" sweep "$T/sh/sweep.preset" --shard 1/2 --jobs 1 --quiet --out "$T/sh" 2>>"$T/err" &&
"$BIN" sweep --merge "$T/sh" --quiet 2>>"$T/err"
if [ $? -eq 0 ] && same_sweep "$T/one" "$T/sh"; then
	ok "sweep --error in two shards (the second from sweep.preset, without --error) then --merge: the files of the one-machine run"
else notok "sweep --error in shards then --merge" "$T/err"; fi
# the same folder without --error holds another sweep: refused
"$BIN" sweep $P --vary "$V1" --vary "$V2" --quiet --out "$T/one" 2>"$T/err"
rc=$?
if [ $rc -eq 2 ] && grep -q 'sweep' "$T/err"; then
	ok "sweep without --error on a folder of the sweep with it: refused (exit 2)"
else notok "sweep without --error on an --error folder (exit $rc)" "$T/err"; fi

# 4. Resume: a journal of half the points (shard 0 of 2's, as points.journal),
# completed from sweep.preset alone, without --error; and --jobs 1.
"$BIN" sweep $P --vary "$V1" --vary "$V2" --error --shard 0/2 --jobs 1 --quiet --out "$T/half" 2>"$T/err"
mkdir "$T/res" && cp "$T/half/sweep.preset" "$T/res/" &&
    cp "$T/half/shard-0-of-2.journal" "$T/res/points.journal"
"$BIN" sweep "$T/res/sweep.preset" --jobs 1 --out "$T/res" --progress 100 2>"$T/err"
rc=$?
"$BIN" sweep $P --vary "$V1" --vary "$V2" --error --jobs 1 --quiet --out "$T/r2" 2>>"$T/err"
if [ $rc -eq 0 ] && grep -q '^sweep: resuming: 2 of 4 points already done$' "$T/err" &&
    same_sweep "$T/one" "$T/res" && same_sweep "$T/one" "$T/r2"; then
	ok "sweep --error resumed from its sweep.preset (2 of 4 points journaled), and at --jobs 1: the files of the first run"
else notok "sweep --error resumed (exit $rc)" "$T/err"; fi

# 5. --merge takes no --error (the folder's sweep.preset says).
"$BIN" sweep --merge "$T/sh" --error 2>"$T/err"
rc=$?
if [ $rc -eq 2 ] && grep -q -- '--merge DIR takes no preset and no other option' "$T/err"; then
	ok "sweep --merge --error: refused (exit 2)"
else notok "sweep --merge --error (exit $rc)" "$T/err"; fi

# 6. --refine keeps its boundaries with error bars beside.
EX=examples/sweeps/restitution-shccl.preset
V="initial.v0=-1mm/s:-1m/s:5:log"
"$BIN" sweep $EX --vary "$V" --refine e_first:0.05 --jobs 2 --quiet --out "$T/rf" 2>"$T/err" &&
"$BIN" sweep $EX --vary "$V" --refine e_first:0.05 --error --jobs 2 --quiet --out "$T/rfe" 2>>"$T/err"
if [ $? -eq 0 ] && cmp -s "$T/rf/boundaries.csv" "$T/rfe/boundaries.csv" &&
    head -n 1 "$T/rfe/runs.csv" | grep -q ',leaving_err,refined,cpu_s$' &&
    [ "$(wc -l <"$T/rf/runs.csv")" -eq "$(wc -l <"$T/rfe/runs.csv")" ]; then
	ok "sweep --refine --error: the same points and boundaries, the error columns before 'refined'"
else notok "sweep --refine --error" "$T/err"; fi

# 7. --format hdf5: the same values as the CSV files, units on the error columns.
PY=${PYTHON:-/usr/bin/python3}
if "$PY" -c 'import h5py, pandas' 2>/dev/null; then
	VH="initial.v0=-1mm/s:-1m/s:3:log"
	"$BIN" sweep $EX --vary "$VH" --error --format hdf5 --jobs 2 --quiet --out "$T/h" 2>"$T/err" &&
	"$BIN" sweep $EX --vary "$VH" --error --jobs 2 --quiet --out "$T/hc" 2>>"$T/err"
	if [ $? -eq 0 ] && "$PY" tests/cli/sweep_hdf5.py "$T/h/sweep.h5" "$T/hc" >"$T/py" 2>&1 &&
	    "$PY" -c '
import sys, h5py
f = h5py.File(sys.argv[1], "r")
def units(d):
    return dict(zip([c.decode() if isinstance(c, bytes) else c for c in d.attrs["columns"]],
                    [u.decode() if isinstance(u, bytes) else u for u in d.attrs["units"]]))
r, c = units(f["runs"]), units(f["collisions"])
ok = r["v_i_first_err"] == "m/s" and r["t_pc_err"] == "s" and c["t_e_err"] == "s" and c["F_c_max_err"] == "N"
ok = ok and f["runs"].dtype["e_first_err"].kind == "f" and f["runs"].dtype["t_pc_err"].kind == "f"
sys.exit(0 if ok else 1)' "$T/h/sweep.h5" >>"$T/py" 2>&1; then
		ok "sweep --error --format hdf5: the CSV sweep's values to the bit, the error columns numbers in their observable's unit"
	else notok "sweep --error --format hdf5" "$T/py"; fi
else
	echo "ok - # SKIP python3-h5py or python3-pandas missing (make deps installs them)"
fi
[ "$fails" -eq 0 ]
