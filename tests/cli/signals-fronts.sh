#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# One signal policy for batch, sweep and fit (src/cli/signals.c): SIGINT,
# SIGTERM and SIGHUP write what was computed and exit 128 + N; a signal
# ignored on entry (nohup, trap '' HUP) stays ignored.  fit mid-run writes
# its best point so far as the fitted preset and the residuals, marked as
# interrupted; batch writes its CSV on SIGHUP too; a sweep whose SIGHUP is
# ignored runs to its end.
. "$(dirname "$0")/common.inc"

# wait_line FILE PATTERN: until FILE has a line matching PATTERN (at most 60 s).
wait_line() {
	i=0
	while ! grep -q "$2" "$1" 2>/dev/null && [ "$i" -lt 1200 ]; do
		sleep 0.05
		i=$((i + 1))
	done
}
# A fit of many short iterations: 400 separate drops, one thread.
{ echo "v_i,e"; i=1; while [ "$i" -le 400 ]; do echo "0.$((i % 9 + 1)),0.$((i % 5 + 3))"; i=$((i + 1)); done; } >"$T/drops.csv"

for sig in INT TERM HUP; do
	case $sig in INT) want=130 ;; TERM) want=143 ;; HUP) want=129 ;; esac
	rm -f "$T/f.preset" "$T/r.csv" "$T/out" "$T/err"
	# env --default-signal: a background job of a script ignores SIGINT.
	(cd "$T" && exec env --default-signal=INT,HUP "$BIN" fit steel-on-bitumen --data drops.csv \
	    --free law.c,law.alpha --jobs 1 --out f.preset --residuals r.csv >"$T/out" 2>"$T/err") &
	pid=$!
	wait_line "$T/err" '^hybounce fit: iteration 2:'
	kill "-$sig" "$pid"
	wait "$pid"
	rc=$?
	iters=$(sed -n 's/^stopped .* after \([0-9]*\) iterations.*/\1/p' "$T/out")
	if [ "$rc" -eq "$want" ] && [ "${iters:-0}" -ge 2 ] &&
	    grep -q "^stopped     interrupted by SIG$sig (the best point so far) after " "$T/out" &&
	    grep -q "^description = .*(interrupted by SIG$sig after $iters iterations: the best point so far, not converged)\\.\$" "$T/f.preset" &&
	    [ "$(wc -l <"$T/r.csv")" -eq 401 ] &&
	    grep -q "^hybounce fit: interrupted by SIG$sig: the best point so far is reported and written\$" "$T/err" &&
	    "$BIN" -b "$T/f.preset" -q >/dev/null 2>&1; then
		ok "fit, SIG$sig after $iters iterations: the best point written (preset, residuals), exit $want"
	else
		notok "fit, SIG$sig: the best point written, exit $want (exit $rc, ${iters:-no} iterations)"
		show "$T/out" 8; show "$T/err" 8
	fi
done

# fit with SIGHUP ignored on entry runs to its end.
rm -f "$T/out" "$T/err"
(cd "$T" && trap '' HUP && exec "$BIN" fit steel-on-bitumen --data drops.csv --free law.c \
    --jobs 1 --max-iter 4 --out g.preset >"$T/out" 2>"$T/err") &
pid=$!
wait_line "$T/err" '^hybounce fit: iteration 1:'
kill -HUP "$pid"
wait "$pid"
rc=$?
if [ "$rc" -le 1 ] && [ -s "$T/g.preset" ] && ! grep -q interrupted "$T/out"; then
	ok "fit: SIGHUP ignored on entry (nohup) stays ignored, the fit ends (exit $rc)"
else
	notok "fit: SIGHUP ignored on entry stays ignored (exit $rc)"; show "$T/err" 8
fi

# batch: SIGHUP writes what was computed too.
(cd "$T" && exec "$BIN" -b hertz-elastic --set run.T=1e5 --set run.J=1e12 -c c.csv \
    >"$T/out" 2>"$T/err") &
pid=$!
i=0
while [ "$(awk '{ print $14 + $15 }' "/proc/$pid/stat" 2>/dev/null || echo 0)" -lt 30 ] && [ "$i" -lt 400 ]; do
	sleep 0.05; i=$((i + 1))
done
kill -HUP "$pid"
wait "$pid"
rc=$?
rows=$(($(wc -l <"$T/c.csv" 2>/dev/null || echo 1) - 1))
if [ "$rc" -eq 129 ] && [ "$rows" -gt 0 ] && [ -s "$T/c.preset" ] &&
    grep -q '^  ended       interrupted by SIGHUP at t = ' "$T/out" &&
    grep -q '^hybounce: interrupted by SIGHUP: what was computed is reported and written$' "$T/err"; then
	ok "batch, SIGHUP: the report and the CSV of what was computed ($rows collisions), exit 129"
else
	notok "batch, SIGHUP: the report and the CSV of what was computed, exit 129 (exit $rc, $rows rows)"
	show "$T/err" 8
fi

# sweep: nohup-style (SIGHUP ignored on entry) keeps running; SIGHUP otherwise stops it.
for how in ignored caught; do
	rm -rf "$T/sw" "$T/err"
	if [ $how = ignored ]; then
		(trap '' HUP && exec "$BIN" sweep hertz-elastic --vary run.T=1:3:40 -q --jobs 1 \
		    --out "$T/sw" 2>"$T/err") &
	else
		(exec env --default-signal=HUP "$BIN" sweep hertz-elastic --vary run.T=1:3:40 -q \
		    --jobs 1 --out "$T/sw" 2>"$T/err") &
	fi
	pid=$!
	wait_line "$T/sw/points.journal" '^r,1,'
	kill -HUP "$pid"
	wait "$pid"
	rc=$?
	if [ $how = ignored ] && [ "$rc" -eq 0 ] && [ "$(wc -l <"$T/sw/runs.csv")" -eq 41 ]; then
		ok "sweep under nohup (SIGHUP ignored): SIGHUP does not stop it, 40 points, exit 0"
	elif [ $how = caught ] && [ "$rc" -eq 129 ] && [ ! -e "$T/sw/runs.csv" ] &&
	    grep -q 'stopped with [0-9]* of 40 points done; the same command resumes' "$T/err"; then
		ok "sweep: SIGHUP stops it with the points done journaled, exit 129"
	else
		notok "sweep, SIGHUP $how (exit $rc)"; show "$T/err" 8
	fi
done
exit $((fails > 0))
