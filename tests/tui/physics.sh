#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer runs the physics checks that --batch runs: on
# hard-bouc-wen-beta with bsimp at rtol = atol = 1e-3 (batch: "fails 3
# physics checks") the status line says so, the log names each check and
# its collision, and the table marks the impossible e with "!".  A run that
# passes shows none of it.  tmux at 80x23, polled capture-pane.
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
. "$(dirname "$0")/common.inc"

start a 80 23 hard-bouc-wen-beta --set run.stepper=bsimp --set run.rtol=1e-3 --set run.atol=1e-3
if wait_for a 'fails 3 checks$' 300; then
	ok "a run that creates energy: the status line says it fails 3 checks"
else
	notok "a run that creates energy: the status line says it fails 3 checks" a
fi
if screen a | grep -Eq '^physics: the computed run fails 3 physics checks'; then
	ok "the message line says what batch warns"
else
	notok "the message line says what batch warns" a
fi
# the first collision: e = 1.179, above what bwshccl allows
if screen a | grep -Eq '^ +>?0 .* 1\.179! '; then
	ok "the table marks collision 0's impossible e with !"
else
	notok "the table marks collision 0's impossible e with !" a
fi
keys a m
if wait_for a 'physics check failed: work-energy identity' 50 &&
   screen a | grep -q 'physics check failed: passivity: collision 14 returns' &&
   screen a | grep -q 'physics check failed: restitution: collision 41 has e'; then
	ok "the log names each failed check and its collision"
else
	notok "the log names each failed check and its collision" a
fi
keys a Escape
wait_gone a 'messages, oldest first' 50 || notok "the log closes" a
# collision 41 (e = 1.994) is marked in its row too
keys a G
n=0
while [ "$n" -lt 60 ] && ! screen a | grep -Eq '^ +>?41 .* 1\.994! '; do
	keys a k
	n=$((n + 1))
	sleep 0.05
done
if screen a | grep -Eq '^ +>?41 .* 1\.994! '; then
	ok "collision 41's e = 1.994 is marked with !"
else
	notok "collision 41's e = 1.994 is marked with !" a
fi
keys a q
wait_exit a 50 || notok "q quits" a

# the same preset as shipped passes: no mark, no failure
start b 80 23 hard-bouc-wen-beta
if wait_for b 'finished$' 300 && ! screen b | grep -Eq 'fails [0-9] check|[0-9]! |^physics'; then
	ok "a run that passes: finished, no mark"
else
	notok "a run that passes: finished, no mark" b
fi
keys b q
wait_exit b 50 || notok "q quits" b
exit $((failed > 0))
