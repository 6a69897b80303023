#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer's measured-against-simulated box (M) takes the data's points
# as the fit does, in tmux at 120x40: a file of two bouncing sequences (a
# trial column) with missed impacts (NA), one of them the first, lists each
# given impact under its trial and index, measured since its trial's first
# given impact, and at the fitted values the run meets every one of them
# within the data's noise, tens of microseconds (a row paired with another
# row's simulation would be milliseconds off); the collisions table aligns the first trial at its
# first given impact; a file of drop heights (h_0, h_1 ... with NA) lists
# every given apex as h_i of its drop.  send-keys, then poll capture-pane.
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS (tests/run.sh).
. "$(dirname "$0")/common.inc"
ROOT=$(pwd)
FIT="--set law.c=5002 --set law.alpha=0.29988"

# two trials of the first 8 impacts of bounces.csv: trial a misses impact 2,
# trial b its first impact (so its clock starts at impact 1)
awk -F, '/^#/ || NF == 0 { next } !h { print "trial,t_e"; h = 1; next }
	{ t[n++] = $1 } END {
		for (i = 0; i < 8; i++) print "a," (i == 2 ? "NA" : t[i])
		for (i = 0; i < 8; i++) print "b," (i == 0 ? "" : t[i]) }' \
	"$ROOT/examples/fit/bounces.csv" >"$TMP/trials.csv"
t3=$(awk -F, '/^#/ || NF == 0 { next } !h { h = 1; next } { t[n++] = $1 }
	END { printf "%.4g", (t[3] - t[1]) * 1000 }' "$ROOT/examples/fit/bounces.csv")

start a 120 40 --ascii --data "'$TMP/trials.csv'" $FIT steel-on-bitumen
if wait_for a ' finished$' 150 && wait_for a 'trial 1 t_e \(sim - data\)' 30; then
	ok "--data with trials: the table names the trial it shows"
else
	notok "--data with trials: the table names the trial it shows" a
fi
keys a M
if wait_for a '2 bouncing sequences \(trials\), 12 points' 30 \
   && wait_for a ' +1 +1 +t_e 1 +[0-9.]+ ms ' 10 \
   && ! screen a | grep -Eq ' +1 +t_e 2 ' \
   && ! screen a | grep -Eq ' +2 +t_e 1 ' \
   && wait_for a " +11 +2 +t_e 3 +$t3 ms " 10; then
	ok "M: the given impacts of each trial with their indices, a trial's clock from its first given impact"
else
	notok "M: the given impacts of each trial with their indices, a trial's clock from its first given impact" a
fi
n=$(screen a | grep -Ec ' t_e [0-9]+ +[0-9.]+ ms +[0-9.]+ ms +-?[0-9.]+ (us|ns) ')
if [ "$n" -eq 12 ]; then
	ok "M: at the fitted values every point meets its simulation within the noise, microseconds ($n of 12)"
else
	notok "M: at the fitted values every point meets its simulation within the noise, microseconds ($n of 12)" a
fi
keys a Escape
wait_gone a 'measured against simulated' 30
if wait_for a '^ +3 .* [0-9.]+ ms \([-+][0-9.]+ (us|ns|ps|s)\)' 30 \
   && ! screen a | grep -Eq '^ +2 .* [0-9.]+ ms \([-+]'; then
	ok "the collisions table: the first trial beside the run, nothing beside its missed impact"
else
	notok "the collisions table: the first trial beside the run, nothing beside its missed impact" a
fi
keys a q
wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ] || notok "q quits with status 0" a

# drop heights: a trial per row, h_4 of the second drop missed
start b 120 40 --ascii --data "'$ROOT/examples/fit/heights.csv'" \
	--set law.c=4956.93 --set law.alpha=0.30348 steel-on-bitumen
keys b M
if wait_for b '3 drops with their rebound heights, 14 points' 150 \
   && wait_for b ' +0 +1 +h_1 +6\.973 mm ' 30 \
   && wait_for b ' +1 +2 +h_5 +395\.8 um ' 10 \
   && ! screen b | grep -Eq ' +2 +h_4 ' \
   && [ "$(screen b | grep -Ec ' h_[1-5] +[0-9.]+ (mm|um) +[0-9.]+ (mm|um) +-?[0-9.]+ um ')" -eq 14 ]; then
	ok "M with heights: every given apex as h_i of its drop, the missed one left out"
else
	notok "M with heights: every given apex as h_i of its drop, the missed one left out" b
fi
keys b Escape
keys b q
wait_exit b 50 && [ "$(cat "$TMP/b.rc")" = 0 ] || notok "q quits with status 0" b
exit $((failed > 0))
