#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The hints the modes show in their titles are printed from their key
# tables (keys_hint): the help's and the log's "Up/Down/PgUp/PgDn scroll,
# any other key closes", the pickers' "Enter opens, Esc closes"; and the
# help's key labels line up however long the longest ("PgDn space").
# send-keys, then poll capture-pane.
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
. "$(dirname "$0")/common.inc"

start a 120 40 steel-on-bitumen
wait_for a ' finished$' 150 || notok "the run finishes" a

keys a '?'
if wait_for a 'hybounce keys \(Up/Down/PgUp/PgDn scroll, any other key closes\)' 30; then
	ok "the help's title: its keys, from its table"
else
	notok "the help's title: its keys, from its table" a
fi
# the help's own list (PgDn: the lists follow the explorer's) has a 10-column label
n=0
while [ "$n" -lt 20 ] && ! screen a | grep -q 'In the help (?, F1):'; do
	keys a PgDn
	wait_for a 'hybounce keys' 10
	n=$((n + 1))
done
# ... and a line at a time until its last row, PgDn space, is on the screen too
# (where the pages fall depends on the length of the lists before it)
n=0
while [ "$n" -lt 40 ] && ! screen a | grep -q 'PgDn space scroll down a page'; do
	keys a Down
	wait_for a 'hybounce keys' 10
	n=$((n + 1))
done
# "Up k" and "PgDn space" start their text in the same column
col_up=$(screen a | awk '/Up k  *scroll up a line/ { print index($0, "scroll up a line"); exit }')
col_dn=$(screen a | awk '/PgDn space scroll down a page/ { print index($0, "scroll down a page"); exit }')
# the help's and the log's list show these two rows; the help's come first
if [ -n "$col_up" ] && [ "$col_up" = "$col_dn" ]; then
	ok "the help's labels line up past 9 columns (text at column $col_up)"
else
	notok "the help's labels line up past 9 columns (Up k: '$col_up', PgDn space: '$col_dn')" a
fi
keys a x
wait_gone a 'hybounce keys' 30 || notok "any other key closes the help" a

keys a m
if wait_for a 'messages, oldest first \(Up/Down/PgUp/PgDn scroll, any other key closes\)' 30; then
	ok "the log's title: its keys, from its table"
else
	notok "the log's title: its keys, from its table" a
fi
keys a x
wait_gone a 'messages, oldest first' 30 || notok "any other key closes the log" a

keys a o
if wait_for a 'open a preset \(Enter opens, Esc closes\)' 30; then
	ok "the preset picker's title: Enter opens, Esc closes, from its table"
else
	notok "the preset picker's title: Enter opens, Esc closes, from its table" a
fi
keys a Escape
wait_gone a 'open a preset' 30 || notok "Esc closes the preset picker" a

keys a L
if wait_for a 'contact law \(Enter chooses, Esc closes\)' 30; then
	ok "the law picker's title: Enter chooses, Esc closes, from its table"
else
	notok "the law picker's title: Enter chooses, Esc closes, from its table" a
fi
keys a Escape
wait_gone a 'contact law \(' 30 || notok "Esc closes the law picker" a

keys a q
wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ] || notok "q quits with status 0" a
exit $((failed > 0))
