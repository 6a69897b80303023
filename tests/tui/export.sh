#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer's export in tmux: the prompt names the folder the files go
# to; a second export to the same name does not replace the first: it goes
# to NAME-2 and says so; an export refused (a missing folder) writes
# nothing and says why.
. "$(dirname "$0")/common.inc"
# logtext SESSION: the screen as one line, box borders and runs of blanks removed
logtext() { screen "$1" | sed 's/│//g' | tr '\n' ' ' | tr -s ' '; }

start a 80 24
wait_for a ' finished$' 150
mkdir -p "$TMP/out"
keys a e
if wait_for a "^BASE: steel-on-bitumen-[0-9]{8}-[0-9]{6}_\$" 30 \
   && wait_for a "^export to $TMP/BASE-trace\\.csv, -collisions\\.csv, \\.preset; BASE\$" 30 && keys a C-u \
   && wait_for a "^export to $TMP/BASE-trace\\.csv, -collisions\\.csv, \\.preset; BASE: _" 30; then
	ok "the export prompt names the folder ($TMP) and proposes a name from the preset"
else
	notok "the export prompt names the folder" a
fi
keys a C-u
keys a -l "out/x"
keys a Enter
if wait_for a '^wrote out/x-trace\.csv' 50 && keys a m && wait_for a 'messages, oldest first' 30 \
   && logtext a | grep -q 'wrote out/x-trace\.csv, out/x-collisions\.csv and out/x\.preset ([0-9][0-9]* samples, 12 collisions)' \
   && [ -s "$TMP/out/x-trace.csv" ] && [ -s "$TMP/out/x-collisions.csv" ] && [ -s "$TMP/out/x.preset" ]; then
	ok "export: the message names the three files written"
else
	notok "export: the message names the three files written" a
fi
keys a Escape
wait_gone a 'messages, oldest first' 30
keys a e
wait_for a 'BASE: ' 30
keys a C-u
keys a -l "out/x"
cksum "$TMP/out/x-trace.csv" "$TMP/out/x-collisions.csv" "$TMP/out/x.preset" >"$TMP/first.sum"
keys a Enter
wait_for a '^wrote out/x-2-trace' 50
keys a m
if wait_for a 'messages, oldest first' 30 \
   && logtext a | grep -q 'wrote out/x-2-trace\.csv, out/x-2-collisions\.csv and out/x-2\.preset (.*); out/x-\* is an earlier export, kept' \
   && cksum "$TMP/out/x-trace.csv" "$TMP/out/x-collisions.csv" "$TMP/out/x.preset" | cmp -s - "$TMP/first.sum" \
   && [ -s "$TMP/out/x-2-trace.csv" ] && [ -s "$TMP/out/x-2.preset" ]; then
	ok "a second export to the same name keeps the first and writes out/x-2-*, saying so"
else
	notok "a second export to the same name keeps the first and writes out/x-2-*, saying so" a
fi
if grep -q '^; hybounce .* (commit [^)]*): ' "$TMP/out/x-2.preset"; then
	ok "the exported scene records the version, the commit and the command line"
else
	notok "the exported scene records the version, the commit and the command line"
	show "$TMP/out/x-2.preset"
fi
keys a q
wait_exit a 50
exit $((failed > 0))
