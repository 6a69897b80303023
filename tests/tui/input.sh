#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Typed input in tmux: + then - returns a typed value exactly (the nudge
# works on the value, not on its display), --set takes blanks around the
# key as batch mode does, and non-ASCII typed into a prompt is kept.
# send-keys, then poll capture-pane.  Needs HYBOUNCE_BIN, HYBOUNCE_PRESETS.
. "$(dirname "$0")/common.inc"

find_key() {
	keys "$1" /
	wait_for "$1" '^search parameters' 30 || return 1
	keys "$1" -l "$2"
	keys "$1" Enter
	wait_for "$1" "nudge\) $2:" 30
}

start a 80 24
wait_for a ' finished$' 150
if find_key a initial.x0; then
	keys a Enter
	wait_for a '^initial\.x0 .*: ' 30
	keys a C-u
	keys a -l '12.3456 mm'
	keys a Enter
	wait_for a 'initial\.x0 = 12\.3456 mm: the run restarted' 30
	keys a +
	wait_for a 'initial\.x0 = 13\.58' 30
	keys a -
	wait_for a 'initial\.x0 = 12\.3456 mm: the run restarted' 30
	keys a Enter
	if wait_for a '^initial\.x0 .*: 12\.3456 mm_' 30; then
		ok "+ then - gives back the typed 12.3456 mm exactly (the prompt reads it back)"
	else
		notok "+ then - gives back the typed 12.3456 mm" a
	fi
	keys a Escape
else
	notok "/ finds initial.x0" a
fi

# non-ASCII typed into the export prompt: the file gets the name as typed
mkdir -p "$TMP/out"
keys a e
wait_for a 'BASE: ' 30
keys a C-u
keys a -l "$TMP/out/Ñandú"
keys a Enter
if wait_for a 'wrote .*Ñandú-trace\.csv' 50 && [ -s "$TMP/out/Ñandú-trace.csv" ]; then
	ok "non-ASCII typed into a prompt is kept (Ñandú-trace.csv written)"
else
	notok "non-ASCII typed into a prompt is kept" a
	ls "$TMP/out" | sed 's/^/#   /'
fi
# Backspace removes a whole character, not a byte
keys a e
wait_for a 'BASE: ' 30
keys a C-u
keys a -l "ñú"
keys a BSpace
if wait_for a 'BASE: ñ_$' 30; then
	ok "Backspace removes a whole UTF-8 character"
else
	notok "Backspace removes a whole UTF-8 character" a
fi
keys a Escape
keys a q
wait_exit a 50

# --set with blanks around the key, as in batch mode
start b 80 24 --set "' run.T = 100 ms'"
if wait_for b ' finished$' 150 && wait_for b 't -> .*100 ms$' 30; then
	ok "--set ' run.T = 100 ms' is accepted as in batch mode"
else
	notok "--set ' run.T = 100 ms' is accepted" b
	cat "$TMP/b.rc" 2>/dev/null
fi
keys b q
wait_exit b 50
exit $((failed > 0))
