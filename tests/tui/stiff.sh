#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer passes on the engine's word on stiffness: on the stiff
# Maxwell preset (stepper = auto) it says auto went over to bsimp; with
# rk8pd it suggests auto or bsimp.  tmux at 100x30, polled capture-pane.
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
. "$(dirname "$0")/common.inc"

start a 100 30 hard-stiff-maxwell
if wait_for a 'stiff contact at t = [0-9.]+ ms: auto went over to bsimp' 150; then
	ok "a stiff contact under run.stepper = auto: the explorer says auto went over to bsimp"
else
	notok "a stiff contact under run.stepper = auto: the explorer says auto went over to bsimp" a
fi
keys a q
wait_exit a 50 || notok "q quits" a

sed 's/^stepper = auto$/stepper = rk8pd/' "$HYBOUNCE_PRESETS/hard-stiff-maxwell.preset" > "$TMP/stiff-rk8pd.preset"
start b 100 30 "$TMP/stiff-rk8pd.preset"
if wait_for b 'stiff contact at t = [0-9.]+ ms: run.stepper = auto \(or bsimp\) is faster' 150; then
	ok "a stiff contact under rk8pd: the explorer suggests auto or bsimp"
else
	notok "a stiff contact under rk8pd: the explorer suggests auto or bsimp" b
fi
keys b q
wait_exit b 50 || notok "q quits" b
exit $((failed > 0))
