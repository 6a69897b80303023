#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Measured data in the explorer (issue 13, part 4), in tmux at 120x40:
# --data shows the impacts of a bouncing sequence as o on the x plot and
# beside the simulated t_e in the table; M lists every point, measured
# against simulated; F fits the free keys from a distant start with a
# progress line, pins the start and takes the fitted values; D opens
# another file (separate drops) and refuses a bad one keeping the old data;
# a bad --data exits 2 before taking the terminal.  send-keys, then poll
# capture-pane.  Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS (tests/run.sh).
. "$(dirname "$0")/common.inc"
ROOT=$(pwd)
DATA=$ROOT/examples/fit/bounces.csv

# the measured time since the first impact of row 1, as the box shows it (ms)
t1=$(awk -F, '/^#/ || NF == 0 { next } !h { for (i = 1; i <= NF; i++) if ($i == "t_e") c = i; h = 1; next }
	{ t[n++] = $c } END { printf "%.4g", (t[1] - t[0]) * 1000 }' "$DATA")
rows=$(awk -F, '/^#/ || NF == 0 { next } { n++ } END { print n - 2 }' "$DATA")

start a 120 40 --ascii --data "'$DATA'" --set law.c=2000 --set law.alpha=0.6 steel-on-bitumen
if wait_for a ' finished$' 150 && wait_for a 'data t_e \(sim - data\)' 30 \
   && wait_for a '^ +1 .* [0-9.]+ ms \(-[0-9.]+ ms\)' 30; then
	ok "--data: the table shows the measured t_e of each collision and sim - data (ms off at the start)"
else
	notok "--data: the table shows the measured t_e of each collision and sim - data" a
fi
if screen a | grep -Eq '^ +0 [^a-zA-Z]*(o[^a-zA-Z]*){8,}$'; then
	ok "--data: the measured impacts are marked o on the x plot at x = 0"
else
	notok "--data: the measured impacts are marked o on the x plot at x = 0" a
fi

keys a M
if wait_for a 'measured against simulated \(M\)' 30 \
   && wait_for a "one bouncing sequence, $((rows + 1)) impacts" 10 \
   && wait_for a " +1 +1 t_e 1 +$t1 ms +[0-9.]+ ms +-[0-9.]+ ms" 10 \
   && [ "$(screen a | grep -Ec ' +[0-9]+ t_e [0-9]+ +[0-9.]+ ms')" -eq "$rows" ]; then
	ok "M: every point of the sequence, measured ($t1 ms for row 1) against simulated"
else
	notok "M: every point of the sequence, measured against simulated" a
fi
keys a Escape
wait_gone a 'measured against simulated' 30

keys a F
if wait_for a '^fit to .*: free keys .*law\.c,law\.alpha' 30; then
	ok "F: asks for the free keys, law.c,law.alpha by default"
else
	notok "F: asks for the free keys, law.c,law.alpha by default" a
fi
keys a Enter
if wait_for a '^fit law\.c,law\.alpha: iteration [0-9]+, cost [0-9.e+-]+ \(start [0-9.e+-]+\), [0-9]+ runs +F stops' 100; then
	ok "F: a progress line while it fits"
else
	notok "F: a progress line while it fits" a
fi
# the README's fit of the same data gives c = 5002 N s/m and alpha = 0.29988
if wait_for a '^fit converged \(.*\) after [0-9]+ iterations, [0-9]+ runs, cost' 300 && keys a m \
   && wait_for a ' law\.c = 500[0-9.]* N s/m \+- [0-9.]+ N s/m, law\.alpha = 0\.299[0-9]* \+- 0\.000[0-9]*' 30; then
	ok "F: the fit converges to the README's estimates, with standard errors"
else
	notok "F: the fit converges to the README's estimates, with standard errors" a
fi
if wait_for a ' fit law\.c,law\.alpha to .* started' 30 \
   && ! screen a | grep -q 'iteration [0-9]*, cost'; then
	ok "F: the start and the outcome are logged, the progress lines are not"
else
	notok "F: the start and the outcome are logged, the progress lines are not" a
fi
keys a Escape
if wait_for a '\.1 alpha = 0\.6 \+1 +\* now alpha = 0\.299[0-9]* \+1' 50 && wait_for a ' finished$' 100 \
   && wait_for a '^ +1 .* [0-9.]+ ms \([-+][0-9.]+ (us|ns|µs)\)' 30; then
	ok "F: the start is pinned; the fitted run meets the data within microseconds"
else
	notok "F: the start is pinned; the fitted run meets the data within microseconds" a
fi

# D: a file that does not load keeps the old data; then separate drops
keys a D
wait_for a '^data file .*: ' 30
keys a C-u
keys a -l "$TMP/none.csv"
keys a Enter
if wait_for a 'data not loaded: .*none\.csv' 30; then
	keys a M
	if wait_for a 'bounces\.csv: one bouncing sequence' 30; then
		ok "D: a file that does not load is named, and the old data stay"
	else
		notok "D: a file that does not load is named, and the old data stay" a
	fi
	keys a Escape
else
	notok "D: a file that does not load is named" a
fi
printf 'v_i,e\n-0.6,0.52\n-0.3,0.6\n' >"$TMP/drops.csv"
keys a D
wait_for a '^data file .*: ' 30
keys a C-u
keys a -l "$TMP/drops.csv"
keys a Enter
keys a M
if wait_for a 'drops\.csv: 2 separate drops, 2 points' 50 \
   && wait_for a ' +0 +- +e +0\.5200 +0\.[0-9]+ +-?0\.[0-9]+' 50 \
   && wait_for a ' +1 +- +e +0\.6000 +0\.[0-9]+ +-?0\.[0-9]+' 10; then
	ok "D: separate drops, each e measured against simulated"
else
	notok "D: separate drops, each e measured against simulated" a
fi
keys a Escape
keys a q
wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ] || notok "q quits with status 0" a

# a bad --data is bad input: exit 2, named, before the terminal is taken
start b 80 24 --data "'$TMP/none.csv'" steel-on-bitumen "2>'$TMP/b.err'"
if wait_exit b 50 && [ "$(cat "$TMP/b.rc")" = 2 ] && grep -q 'none\.csv' "$TMP/b.err"; then
	ok "--data FILE that does not load: exit 2, the file named"
else
	notok "--data FILE that does not load: exit 2, the file named"
	sed 's/^/# /' "$TMP/b.err" 2>/dev/null
fi
exit $((failed > 0))
