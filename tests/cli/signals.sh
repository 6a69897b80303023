#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# SIGTERM and SIGINT in batch mode end the run, and what was computed is
# reported and written, as after a numerical failure; the exit status is
# 128 + the signal.  A run that lasts more than a second shows its progress
# on standard error when that is a terminal (a pty, from script(1)), and
# not otherwise.
. "$(dirname "$0")/common.inc"
# A run of hours: the elastic ball bouncing for 10^5 s.
LONG="-b hertz-elastic --set run.T=1e5 --set run.J=1e12"

# cpu_ticks PID: user + system CPU time of PID, in clock ticks.
cpu_ticks() { awk '{ print $14 + $15 }' "/proc/$1/stat" 2>/dev/null || echo 0; }
# wait_busy PID: until PID has run for 0.3 s of CPU (its handlers are set
# long before), at most 20 s.
wait_busy() {
	i=0
	while [ "$(cpu_ticks "$1")" -lt 30 ] && [ "$i" -lt 400 ]; do
		kill -0 "$1" 2>/dev/null || return
		sleep 0.05
		i=$((i + 1))
	done
}

for sig in TERM INT; do
	case $sig in TERM) want=143 ;; INT) want=130 ;; esac
	rm -f "$T"/c.*
	# env --default-signal: a background job of a script ignores SIGINT.
	(cd "$T" && exec env --default-signal=INT "$BIN" $LONG -c c.csv >"$T/out" 2>"$T/err") &
	pid=$!
	wait_busy "$pid"
	kill "-$sig" "$pid"
	wait "$pid"
	rc=$?
	rows=$(($(wc -l <"$T/c.csv" 2>/dev/null || echo 1) - 1))
	n=$(sed -n 's/^  collisions  \([0-9]*\)$/\1/p' "$T/out")
	if [ "$rc" -eq "$want" ] && [ "$rows" -gt 0 ] && [ "$rows" = "$n" ] &&
	    [ -s "$T/c.preset" ] && grep -q "^  ended       interrupted by SIG$sig at t = " "$T/out" &&
	    grep -q "^hybounce: interrupted by SIG$sig: what was computed is reported and written\$" "$T/err" &&
	    grep -q '^wrote c.csv$' "$T/err" && ! grep -q "$(printf '\r')" "$T/err"; then
		ok "SIG$sig: the report and the CSV of what was computed ($rows collisions), exit $want"
	else
		notok "SIG$sig: the report and the CSV of what was computed, exit $want (exit $rc, $rows rows, summary '$n')"
		show "$T/out"; show "$T/err"
	fi
done

# A signal ignored on entry stays ignored (nohup): the run goes on.
(cd "$T" && exec "$BIN" -b hertz-elastic --set run.T=500 -q >"$T/out" 2>"$T/err") &
pid=$!
wait_busy "$pid"
kill -INT "$pid" 2>/dev/null
sent=$?
wait "$pid"
rc=$?
if [ "$sent" -eq 0 ] && [ "$rc" -eq 0 ] && grep -q 'ended       horizon' "$T/out"; then
	ok "SIGINT ignored on entry (a background job) stays ignored"
else
	notok "SIGINT ignored on entry stays ignored (exit $rc, kill $sent)"
	show "$T/out"
fi

# Progress on a terminal: script(1) gives the run a pty.
if command -v script >/dev/null 2>&1; then
	script -qfec "sh -c 'echo \$\$ >\"$T/pid\"; exec \"$BIN\" $LONG -q'" "$T/ts" >/dev/null 2>&1 &
	spid=$!
	i=0
	while ! grep -q 'Ctrl-C stops and writes' "$T/ts" 2>/dev/null && [ "$i" -lt 400 ]; do
		sleep 0.05
		i=$((i + 1))
	done
	kill -TERM "$(cat "$T/pid")"
	wait "$spid"
	if grep -q "hybounce: t = .* of 100000 s (.*%), j = [0-9]*, [0-9]* collisions, [0-9]* s; Ctrl-C stops and writes" "$T/ts" &&
	    grep -q "$(printf '\r\033\\[K')" "$T/ts" && grep -q 'interrupted by SIGTERM' "$T/ts"; then
		ok "a run past one second shows its progress on a terminal, then erases it"
	else
		notok "a run past one second shows its progress on a terminal, then erases it"
		tr '\r' '\n' <"$T/ts" | show /dev/stdin
	fi
else
	ok "progress on a terminal # SKIP script(1) missing"
fi
[ "$fails" -eq 0 ]
