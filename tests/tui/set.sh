#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer opens a preset with --set as batch mode does (one function,
# hb_preset_open): blanks around the key and the value are ignored, so
# --set ' run.T = 1 ms' gives a 1 ms run: the panel shows T = 1 ms and the
# time axis ends at 1.0 ms.
. tests/tui/common.inc

start a 140 60 hertz-elastic --set "' run.T = 1 ms'"
if wait_for a ' T +1 ms' 50; then
	ok "explorer: --set ' run.T = 1 ms' sets run.T to 1 ms"
else
	notok "explorer: --set ' run.T = 1 ms' sets run.T to 1 ms" a
fi
if wait_for a 't -> .* 1\.0 ms' 50; then
	ok "explorer: the time axis ends at T = 1 ms"
else
	notok "explorer: the time axis ends at T = 1 ms" a
fi

# Typed values in the panel: + on a whole number steps it as a whole number
# (run.J 100000 -> 110000), and Enter starts the prompt from text that reads
# back to the same value (law.alpha = 0.123456789, which the panel shows as
# 0.1235).
start b 140 60 steel-on-bitumen --set law.alpha=0.123456789
keys b Tab
wait_for b 'parameters \(Enter edits' 30
if select_param b law.alpha; then
	keys b Enter
	if screen b | grep -Eq ' alpha +0\.1235 *$' &&
	    wait_for b '^law\.alpha \(0, 1\): 0\.123456789_' 30; then
		ok "Enter on law.alpha (shown 0.1235) opens the prompt on 0.123456789, the exact value"
	else
		notok "Enter on law.alpha (shown 0.1235) opens the prompt on 0.123456789, the exact value" b
	fi
	keys b Escape
	wait_for b 'cancelled' 30
else
	notok "parameter row law.alpha found" b
fi
if select_param b run.J; then
	keys b +
	if wait_for b 'run\.J = 110000[:;]' 30; then ok "+ on run.J steps the whole number 100000 to 110000"
	else notok "+ on run.J steps the whole number 100000 to 110000" b; fi
	keys b -
	if wait_for b 'run\.J = 100000[:;]' 30; then ok "- on run.J steps it back to 100000"
	else notok "- on run.J steps it back to 100000" b; fi
else
	notok "parameter row run.J found" b
fi
$TM send-keys -t b q
$TM send-keys -t a q
exit $((failed > 0))
