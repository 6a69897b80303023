#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce sweep on one machine: the files, bit-identity with --batch runs
# point by point, independence of --jobs, resuming after SIGKILL, a folder
# of another sweep refused, bad input (exit 2, nothing written), failed
# points as rows, progress lines, shards and --merge.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"

P=permanent-contact-shccl
V1="initial.x0=10um:40um:3"
V2="law.c=1e9,4.3e9"

# 1. The files.
"$BIN" sweep $P --vary "$V1" --vary "$V2" --jobs 2 --out "$T/one" >"$T/out" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && [ -f "$T/one/runs.csv" ] && [ -f "$T/one/collisions.csv" ] &&
    [ -f "$T/one/sweep.preset" ] && [ ! -s "$T/out" ]; then
	ok "sweep writes runs.csv, collisions.csv and sweep.preset (exit 0, stdout empty)"
else notok "sweep writes runs.csv, collisions.csv and sweep.preset (exit $rc)" "$T/err"; fi
if [ "$(wc -l <"$T/one/runs.csv")" -eq 7 ] &&
    head -n 1 "$T/one/runs.csv" | grep -q '^id,initial.x0,law.c,status,message,collisions,t_pc,e_first,v_i_first,e_last,v_i_last,x_c_r_total,t_end,j_end,q_c_end,x_end,v_end,x_c_end,leaving,steps,rejected,rhs,jac,cpu_s$' &&
    [ "$(cut -d, -f1 "$T/one/runs.csv" | tail -n +2 | tr '\n' ' ')" = "0 1 2 3 4 5 " ] &&
    head -n 1 "$T/one/collisions.csv" | grep -q '^id,i,t_e,t_s,'; then
	ok "runs.csv: one row per point sorted by id; collisions.csv: id, then the --collisions columns"
else notok "runs.csv: one row per point sorted by id" "$T/one/runs.csv"; fi
if grep -q '^; sweep: --vary initial.x0=10um:40um:3$' "$T/one/sweep.preset" &&
    grep -q '^; sweep: --vary law.c=1e9,4.3e9$' "$T/one/sweep.preset"; then
	ok "sweep.preset holds the scene and the axes"
else notok "sweep.preset holds the scene and the axes" "$T/one/sweep.preset"; fi
if [ "$(ls -A "$T/one" | tr '\n' ' ')" = "collisions.csv runs.csv sweep.preset " ]; then
	ok "a finished sweep leaves exactly runs.csv, collisions.csv and sweep.preset (no journal, no temporary file)"
else notok "a finished sweep leaves exactly its three files ($(ls -A "$T/one" | tr '\n' ' '))"; fi

# 2. Bit-identical to --batch, point by point (collisions to the byte, work counts).
bad=0
tail -n +2 "$T/one/runs.csv" | while IFS=, read -r id x0 c rest; do
	"$BIN" --batch $P --set initial.x0="$x0" --set law.c="$c" --collisions "$T/b.csv" \
	    --quiet >"$T/b.out" 2>/dev/null || { echo "batch $id failed"; continue; }
	tail -n +2 "$T/b.csv" >"$T/b.rows"
	grep "^$id," "$T/one/collisions.csv" | cut -d, -f2- >"$T/s.rows"
	cmp -s "$T/b.rows" "$T/s.rows" || echo "point $id: collisions differ"
	steps=$(sed -n 's/^  steps  *\([0-9]*\) accepted, \([0-9]*\) rejected$/\1,\2/p' "$T/b.out")
	rhs=$(sed -n 's/^  evaluations \([0-9]*\) right-hand side, \([0-9]*\) Jacobian$/\1,\2/p' "$T/b.out")
	row=$(grep "^$id," "$T/one/runs.csv" | cut -d, -f20-23)
	[ "$row" = "$steps,$rhs" ] || echo "point $id: work $row vs batch $steps,$rhs"
	[ -s "$T/b.rows" ] || echo "point $id: no collision"
done >"$T/diff"
if [ ! -s "$T/diff" ]; then
	ok "every point equals its --batch run with --set of the row's values (collisions byte for byte, steps and rhs)"
else notok "every point equals its --batch run" "$T/diff"; fi

# 3. Independent of --jobs (and so of the order of completion).
"$BIN" sweep $P --vary "$V1" --vary "$V2" --jobs 1 --quiet --out "$T/j1" 2>"$T/err" &&
"$BIN" sweep $P --vary "$V1" --vary "$V2" --jobs 5 --quiet --out "$T/j5" 2>>"$T/err"
if same_sweep "$T/one" "$T/j1" && same_sweep "$T/one" "$T/j5"; then
	ok "--jobs 1, 2 and 5 give the same files (but for cpu_s)"
else notok "--jobs 1, 2 and 5 give the same files" "$T/err"; fi

# 4. sweep.preset reproduces the sweep.
"$BIN" sweep "$T/one/sweep.preset" --quiet --out "$T/again" 2>"$T/err"
if same_sweep "$T/one" "$T/again"; then ok "sweep DIR/sweep.preset reproduces the sweep"
else notok "sweep DIR/sweep.preset reproduces the sweep" "$T/err"; fi

# 5. Resume after SIGKILL: only the missing points, the same files.
VK="initial.x0=5um:60um:40"
"$BIN" sweep $P --vary "$VK" --jobs 1 --quiet --out "$T/full" 2>"$T/err"
"$BIN" sweep $P --vary "$VK" --jobs 1 --quiet --out "$T/killed" 2>/dev/null &
pid=$!
i=0
while [ $i -lt 400 ]; do
	n=$(grep -c '^r,' "$T/killed/points.journal" 2>/dev/null || true)
	[ "${n:-0}" -ge 5 ] && break
	i=$((i + 1))
	sleep 0.01
done
kill -9 $pid 2>/dev/null
wait $pid 2>/dev/null
done_before=$(grep -c '^r,' "$T/killed/points.journal" 2>/dev/null || echo 0)
if [ ! -f "$T/killed/runs.csv" ] && [ "$done_before" -ge 1 ] && [ "$done_before" -lt 40 ]; then
	ok "SIGKILL mid-sweep leaves a journal of $done_before points and no runs.csv"
else notok "SIGKILL mid-sweep leaves a journal (got $done_before points; runs.csv $(ls "$T/killed"))"; fi
# A torn last block, as a kill in the middle of a write would leave.
printf 'c,39,0,0.1,0.2' >>"$T/killed/points.journal"
"$BIN" sweep $P --vary "$VK" --jobs 2 --out "$T/killed" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "^sweep: resuming: $done_before of 40 points already done$" "$T/err" &&
    [ ! -f "$T/killed/points.journal" ] && same_sweep "$T/full" "$T/killed"; then
	ok "the same command resumes: computes only the missing $((40 - done_before)) points; files equal an uninterrupted run"
else notok "the same command resumes (exit $rc)" "$T/err"; fi
"$BIN" sweep $P --vary "$VK" --out "$T/killed" 2>"$T/err"
if [ $? -eq 0 ] && grep -q 'resuming: 40 of 40' "$T/err" && same_sweep "$T/full" "$T/killed"; then
	ok "a finished sweep run again computes nothing"
else notok "a finished sweep run again computes nothing" "$T/err"; fi

# 6. A folder holding another sweep, or other files, is refused; nothing changes.
cp "$T/one/runs.csv" "$T/runs.before"
"$BIN" sweep $P --vary "initial.x0=10um:40um:4" --vary "$V2" --out "$T/one" 2>"$T/err"
rc=$?
if [ $rc -eq 2 ] && grep -q 'holds a different sweep' "$T/err" && cmp -s "$T/runs.before" "$T/one/runs.csv"; then
	ok "a folder holding a different sweep is refused (exit 2, files untouched)"
else notok "a folder holding a different sweep is refused (exit $rc)" "$T/err"; fi
mkdir "$T/other" && echo hello >"$T/other/notes.txt"
"$BIN" sweep $P --vary "$V2" --out "$T/other" 2>"$T/err"
rc=$?
if [ $rc -eq 2 ] && grep -q 'not empty and holds no sweep' "$T/err" && [ ! -f "$T/other/sweep.preset" ]; then
	ok "a non-empty folder without a sweep is refused (exit 2)"
else notok "a non-empty folder without a sweep is refused (exit $rc)" "$T/err"; fi

# 7. Bad input: exit 2 before anything runs, nothing written.
n=0
for args in "--vary law.nope=1,2" "--vary law.c=1:2" "--vary law.c=1:2:x" "--vary law.c=0:1e9:3:log" \
    "--vary law.c=-1,2" "--vary initial.x0=1m,,2m" "--vary initial.x0=1kg,2kg" \
    "--vary scene.law=shccl:bwmcl:2" "--set law.c=abc --vary initial.x0=1um,2um" \
    "--vary initial.x0=1um,2um --jobs 0" "--vary initial.x0=1um,2um --shard 2/2" \
    "--vary initial.x0=1um,2um --emit pbs" ""; do
	n=$((n + 1))
	# shellcheck disable=SC2086
	"$BIN" sweep $P $args --out "$T/bad$n" >/dev/null 2>"$T/err"
	rc=$?
	if [ $rc -eq 2 ] && [ ! -e "$T/bad$n" ] && [ -s "$T/err" ] && [ "$(wc -l <"$T/err")" -le 3 ]; then :
	else echo "args '$args': exit $rc, $(ls "$T/bad$n" 2>/dev/null | tr '\n' ' ') $(head -c 200 "$T/err")"; fi
done >"$T/diff"
if [ ! -s "$T/diff" ]; then ok "bad --vary, --set, --jobs, --shard, --emit: exit 2 with a message, no folder ($n cases)"
else notok "bad input is exit 2 before anything runs" "$T/diff"; fi
"$BIN" sweep $P --vary "law.c=1e9,4.3e9" 2>"$T/err"
[ $? -eq 2 ] && grep -q 'expected --out DIR' "$T/err" && ok "no --out: exit 2" || notok "no --out: exit 2" "$T/err"
# A combination out of range (gamma in [-beta, beta]) names the point.
"$BIN" sweep permanent-contact-bwshccl --vary "law.beta=1e9,5e9" --vary "law.gamma=2e9,5e9" \
    --out "$T/combo" 2>"$T/err"
rc=$?
if [ $rc -eq 2 ] && grep -q 'point 0 (law.beta=1000000000 law.gamma=2000000000)' "$T/err" && [ ! -e "$T/combo" ]; then
	ok "an invalid combination of values is exit 2 and names the point"
else notok "an invalid combination of values is exit 2 (exit $rc)" "$T/err"; fi
# Each point is checked once, in its run: a bad point after good ones is
# refused with the same message, and what the sweep had begun goes (an
# empty folder given stays, empty).
mkdir "$T/combo2"
"$BIN" sweep permanent-contact-bwshccl --vary "law.beta=5e9,1e9" --vary "law.gamma=2e9" \
    --jobs 1 --out "$T/combo1" 2>"$T/err1"
rc1=$?
"$BIN" sweep permanent-contact-bwshccl --vary "law.beta=5e9,1e9" --vary "law.gamma=2e9" \
    --jobs 2 --out "$T/combo2" 2>"$T/err2"
rc2=$?
if [ $rc1 -eq 2 ] && [ $rc2 -eq 2 ] &&
   grep -q 'point 1 (law.beta=1000000000 law.gamma=2000000000): law.gamma: ' "$T/err1" &&
   [ "$(grep '^hybounce sweep: ' "$T/err1")" = "$(grep '^hybounce sweep: ' "$T/err2")" ] &&
   [ ! -e "$T/combo1" ] && [ -d "$T/combo2" ] &&
   [ -z "$(ls -A "$T/combo2")" ]; then
	ok "a bad point after good ones: exit 2, the same message, nothing left behind"
else notok "a bad point after good ones (exit $rc1, $rc2; $(ls -A "$T/combo2" 2>&1 | tr '\n' ' '))" "$T/err1"; fi

# 8. A point that fails numerically is a row with its message, not a failed sweep.
"$BIN" sweep steel-on-bitumen --vary "run.h_max=0,1e-300" --set run.T=0.1 --quiet \
    --out "$T/fail" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q '^0,0,ok,' "$T/fail/runs.csv" && grep -q '^1,1e-300,failed,' "$T/fail/runs.csv"; then
	ok "a numerically failed point is a row with status failed and its message (exit 0)"
else notok "a numerically failed point is a row (exit $rc)" "$T/err"; cat "$T/fail/runs.csv" 2>/dev/null | sed 's/^/# /'; fi

# 9. Progress: a line per 10% without a terminal, a bar with rate and ETA on one.
"$BIN" sweep $P --vary "$VK" --out "$T/prog" 2>"$T/err"
if [ "$(grep -c '^sweep: [0-9]*/40 points ([0-9]*%), [0-9.]* points/s, ETA [0-9:]*, 0 failed$' "$T/err")" -eq 10 ]; then
	ok "without a terminal: one progress line per 10% (done/total, rate, ETA, failures)"
else notok "without a terminal: one progress line per 10%" "$T/err"; fi
if command -v script >/dev/null 2>&1; then
	script -qec "$BIN sweep $P --vary $VK --out $T/tty" /dev/null >"$T/tty.out" 2>&1
	if grep -q '40/40 100%' "$T/tty.out" && grep -q 'points/s  ETA' "$T/tty.out" && grep -q '\[##' "$T/tty.out"; then
		ok "on a terminal: a progress bar with done/total, rate, ETA and failures"
	else notok "on a terminal: a progress bar" "$T/tty.out"; fi
else
	echo "ok # SKIP on a terminal: a progress bar (script(1) from util-linux is missing)"
fi

# 10. Shards and --merge: identical to the one-machine run.
for k in 0 1 2; do
	"$BIN" sweep $P --vary "$V1" --vary "$V2" --shard $k/3 --jobs 1 --quiet --out "$T/sh" 2>>"$T/err.sh"
	if [ $k -eq 1 ]; then
		"$BIN" sweep --merge "$T/sh" 2>"$T/err"
		rc=$?
		if [ $rc -eq 1 ] && grep -q '1 of 3 shards incomplete: shard 2 (not started); 2 of 6 points missing' "$T/err" &&
		    [ ! -f "$T/sh/runs.csv" ]; then
			ok "--merge before every shard has finished: exit 1, names the missing shard, writes nothing"
		else notok "--merge of incomplete shards (exit $rc)" "$T/err"; fi
	fi
done
"$BIN" sweep --merge "$T/sh" 2>"$T/err"
if [ $? -eq 0 ] && same_sweep "$T/one" "$T/sh"; then
	ok "--shard 0/3, 1/3, 2/3 then --merge: the files of the one-machine run"
else notok "--shard then --merge equals the one-machine run" "$T/err"; fi
# The journals in id order are merged side by side; journals out of order
# or holding a point twice (blocks reversed, a copy of a block appended: the
# first copy wins) through the merge's index: the same files either way.
rm -f "$T/sh/runs.csv" "$T/sh/collisions.csv"
for j in "$T"/sh/shard-*.journal; do
	awk '{ b = b $0 "\n" } /^r,/ { blk[n++] = b; b = "" } END { for (i = n - 1; i >= 0; i--) printf "%s", blk[i]; printf "%s", blk[0] }' \
	    "$j" >"$j.rev" && mv "$j.rev" "$j"
done
"$BIN" sweep --merge "$T/sh" 2>"$T/err"
if [ $? -eq 0 ] && same_sweep "$T/one" "$T/sh" && [ "$(grep -c '^r,0,' "$T/sh/shard-0-of-3.journal")" -eq 2 ]; then
	ok "--merge of journals out of order, a point twice: the files of the one-machine run"
else notok "--merge of journals out of order equals the one-machine run" "$T/err"; fi
"$BIN" sweep --merge "$T/nothing" 2>"$T/err"
[ $? -eq 2 ] && grep -q 'expected a sweep folder' "$T/err" && ok "--merge of a folder without a sweep: exit 2 (bad input)" ||
	notok "--merge of a folder without a sweep: exit 2 (bad input)" "$T/err"

# 11. The classic maps of examples/sweeps: each is a valid preset (batch
# --check) and its sweep runs: every point ok, e in (0, 1] where a
# collision separated.
for f in examples/sweeps/*.preset; do
	name=$(basename "$f" .preset)
	if "$BIN" --batch "$f" --check --quiet >"$T/out" 2>&1 && grep -q 'check       solution pair: ok' "$T/out"; then
		ok "examples/sweeps/$name: batch --check passes"
	else notok "examples/sweeps/$name: batch --check passes" "$T/out"; fi
	"$BIN" sweep "$f" --quiet --out "$T/ex-$name" 2>"$T/err"
	rc=$?
	rows=$(tail -n +2 "$T/ex-$name/runs.csv" 2>/dev/null | wc -l)
	bad=$(tail -n +2 "$T/ex-$name/runs.csv" 2>/dev/null |
	    awk -F, '$(NF-20) != "ok" || ($(NF-16) != "" && ($(NF-16) <= 0 || $(NF-16) > 1)) { n++ } END { print n + 0 }')
	if [ $rc -eq 0 ] && [ "$rows" -ge 20 ] && [ "$bad" -eq 0 ]; then
		ok "examples/sweeps/$name: the sweep runs ($rows points, all ok, e in (0, 1])"
	else notok "examples/sweeps/$name: the sweep runs (exit $rc, $rows rows, $bad bad)" "$T/err"; fi
done

# 12. The man page documents every long option of hybounce sweep --help.
missing=
for o in $("$BIN" sweep --help | grep -o -- '--[a-z][a-z-]*' | sort -u); do
	grep -q "^\.It Fl -${o#--}\\b\|^\.It .* Fl -${o#--}\\b" man/hybounce.1 || missing="$missing $o"
done
if [ -z "$missing" ] && grep -q '^\.Sh SWEEPS$' man/hybounce.1; then
	ok "the man page (SWEEPS) documents every option of hybounce sweep --help"
else notok "the man page documents every option of hybounce sweep --help (missing:$missing)"; fi

# 13. The README's example plot is what plot.sh draws from those sweeps.
for l in shccl bwshccl bwmcl; do cp -r "$T/ex-restitution-$l" "$T/e-$l"; done
R=$(pwd)
(cd "$T" && sh "$R/examples/sweeps/plot.sh" -logx -absx v_i_first e_first e-shccl e-bwshccl e-bwmcl) >"$T/plot" 2>&1
awk '/^    \$ sh examples\/sweeps\/plot.sh -logx -absx v_i_first e_first e-shccl e-bwshccl e-bwmcl$/ { on = 1; next }
     on && /^$/ { exit } on { sub(/^    /, ""); print }' README.md >"$T/readme.plot"
if [ -s "$T/plot" ] && cmp -s "$T/plot" "$T/readme.plot"; then
	ok "README's restitution plot is plot.sh's output for the example sweeps"
else notok "README's restitution plot is plot.sh's output for the example sweeps" "$T/plot"; diff "$T/plot" "$T/readme.plot" | head -5 | sed 's/^/# /'; fi

# 14. SIGINT (and SIGTERM): the points in hand are finished and kept, exit
# 128+N, and the same command resumes, with threads (--jobs 2) and without
# (--jobs 1: the calling thread computes the points).  400 points: the
# workers wake the writer for a batch of blocks (or after 0.1 s), so the
# journal grows in steps.  (env --default-signal: a background job of a
# script inherits SIGINT ignored, and an ignored signal stays so.)
VI="initial.x0=5um:60um:400"
"$BIN" sweep $P --vary "$VI" --jobs 2 --quiet --out "$T/fullint" 2>"$T/err" || notok "the 400-point sweep runs" "$T/err"
for j in 2 1; do
	env --default-signal=INT "$BIN" sweep $P --vary "$VI" --jobs $j --out "$T/int$j" 2>"$T/int.err" &
	pid=$!
	i=0
	while [ $i -lt 400 ]; do
		n=$(grep -c '^r,' "$T/int$j/points.journal" 2>/dev/null || true)
		[ "${n:-0}" -ge 3 ] && break
		i=$((i + 1))
		sleep 0.01
	done
	kill -INT $pid
	wait $pid
	rc=$?
	n=$(grep -c '^r,' "$T/int$j/points.journal" 2>/dev/null || echo 0)
	if [ $rc -eq 130 ] && grep -q "^hybounce sweep: stopped with $n of 400 points done; the same command resumes$" "$T/int.err" &&
	    [ ! -f "$T/int$j/runs.csv" ] && [ "$(tail -c 1 "$T/int$j/points.journal" | od -An -c | tr -d ' ')" = '\n' ]; then
		ok "SIGINT, --jobs $j: exit 130, the $n points done are journaled whole, no runs.csv"
	else notok "SIGINT, --jobs $j: exit 130 and the points done journaled (exit $rc, $n points)" "$T/int.err"; fi
	"$BIN" sweep $P --vary "$VI" --jobs $j --quiet --out "$T/int$j" 2>"$T/err"
	if [ $? -eq 0 ] && same_sweep "$T/fullint" "$T/int$j"; then ok "after SIGINT, --jobs $j, the same command completes the sweep"
	else notok "after SIGINT, --jobs $j, the same command completes the sweep" "$T/err"; fi
done

# One process a shard: while another holds its journal (flock, as a second
# run of the shard would), a run of the same shard is refused and leaves the
# journal as it was; once it is free, the run completes.
"$BIN" sweep $P --vary "initial.x0=5um:60um:6" --out "$T/lock" --shard 1/2 --quiet 2>"$T/err" ||
    notok "shard 1/2 runs" "$T/err"
: >"$T/lock/shard-0-of-2.journal"
flock "$T/lock/shard-0-of-2.journal" "$BIN" sweep "$T/lock/sweep.preset" --out "$T/lock" \
    --shard 0/2 --quiet 2>"$T/err"
rc=$?
if [ $rc -eq 1 ] && [ ! -s "$T/lock/shard-0-of-2.journal" ] &&
    grep -q 'shard-0-of-2.journal: another process is computing these points (the journal is locked)' "$T/err"; then
	ok "a second run of a shard whose journal is locked is refused (exit 1), the journal untouched"
else notok "a run of a locked shard is refused (exit $rc)" "$T/err"; fi
"$BIN" sweep "$T/lock/sweep.preset" --out "$T/lock" --shard 0/2 --quiet 2>"$T/err" &&
    "$BIN" sweep --merge "$T/lock" --quiet 2>>"$T/err"
rc=$?
if [ $rc -eq 0 ] && [ "$(grep -c '^r,' "$T/lock/shard-0-of-2.journal")" -eq 3 ] && [ -f "$T/lock/runs.csv" ]; then
	ok "the lock released, the shard runs and merges"
else notok "the lock released, the shard runs and merges (exit $rc)" "$T/err"; fi

exit 0
