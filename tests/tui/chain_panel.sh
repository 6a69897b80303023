#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A chain's overrides in the explorer's panel: the chain section lists
# body.3.R and initial.body.5.v with their values; editing body.3.R there
# (Enter, a new value) changes that body alone and restarts the run, and
# the status line says so.
. tests/tui/common.inc
. tests/chain.inc

steel_chain 'cradle of five with a heavy ball' 5 '1 mm' '50 ms' '[body.3]
R = 12 mm
[initial]
body.5.v = -2 m/s' '' >"$TMP/c.preset"

start a 120 50 c.preset
wait_for a 'collisions' 100
keys a Tab
wait_for a 'parameters \(Enter edits' 30
if select_param a body.3.R && screen a | grep -Eq '^  R \(body 3\) +12 mm ' &&
    select_param a initial.body.5.v && screen a | grep -Eq '^  v \(body 5\) +-2 m/s '; then
	ok "the panel's chain section lists body.3.R = 12 mm and initial.body.5.v = -2 m/s"
else
	notok "the panel's chain section lists body.3.R = 12 mm and initial.body.5.v = -2 m/s" a
fi
if edit a body.3.R '11 mm' && wait_for a 'body.3.R = 11 mm: the run restarted from t = 0' 50 &&
    screen a | grep -Eq '^  R \(body 3\) +11 mm '; then
	ok "Enter on body.3.R: 11 mm, the run restarted"
else
	notok "Enter on body.3.R: 11 mm, the run restarted" a
fi
keys a q
wait_exit a 50 || notok "the explorer quits" a

[ "$failed" -eq 0 ]
