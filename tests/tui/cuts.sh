#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# At 80x23 nothing is cut without a mark and a way to read it whole: a cut
# text ends in an ellipsis (> without UTF-8), and each cut has its place
# where it is whole: the status line's preset name in the log, the help's
# further rows behind "more below", a picker's entry under its list, a
# parameter's description above the field Enter opens, an export prompt's
# folder on the rows above it, the table's data column in M, a message in
# the log.  send-keys, then poll capture-pane.
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
# the box borders matched below are UTF-8's; set before the tmux server starts
if locale -a 2>/dev/null | grep -qi '^c\.utf-\?8$'; then
	export LC_ALL=C.UTF-8
fi
. "$(dirname "$0")/common.inc"
CUT='(…|>)'

# the screen's rows joined, box borders and blanks removed, to find a text
# wrapped over rows (compared without its blanks)
joined() { screen "$1" | sed 's/^[^│]*│\(.*\)│.*$/\1/' | tr -d ' \n'; }
wait_joined() {
	want=$(printf '%s' "$2" | tr -d ' ')
	i=0
	while [ "$i" -lt "${3:-50}" ]; do
		joined "$1" | grep -Fq -- "$want" && return 0
		i=$((i + 1))
		sleep 0.1
	done
	return 1
}

# ---- the status line: a long preset name, marked; whole in the log ---------------
long=a-scene-whose-name-is-far-too-long-for-the-status-line
cp "$HYBOUNCE_PRESETS/steel-on-bitumen.preset" "$TMP/$long.preset"
start a 80 23 "$long.preset"
wait_for a ' finished$' 150 || notok "the run finishes" a
if wait_for a "^ a-scene-whose-n[a-z-]*$CUT bwmcl t=" 30; then
	ok "status line: a preset name too long is cut with a mark"
else
	notok "status line: a preset name too long is cut with a mark" a
fi
keys a m
if wait_for a "messages, oldest first" 30 && wait_joined a "$long"; then
	ok "the log (m) shows the preset's name whole"
else
	notok "the log (m) shows the preset's name whole" a
fi
keys a Escape

# ---- the help: what is below is said, and reachable ------------------------------
keys a '?'
if wait_for a 'more below \(Down\)' 30; then
	ok "help: the bottom border says more rows follow"
else
	notok "help: the bottom border says more rows follow" a
fi
# the explorer's keys, then the legend, which explains the cut mark
n=0
while [ "$n" -lt 12 ] && ! wait_joined a "every column is in the exported CSV." 10; do
	keys a PgDn
	n=$((n + 1))
done
if wait_joined a "every column is in the exported CSV."; then
	ok "help: the cut mark is explained after the explorer's keys"
else
	notok "help: the cut mark is explained after the explorer's keys" a
fi
# then every other mode's keys, to the last row: the sweep view's
keys a PgDn PgDn PgDn PgDn PgDn PgDn PgDn PgDn PgDn PgDn PgDn PgDn PgDn PgDn PgDn PgDn
if wait_gone a 'more below' 50 && wait_for a 'more above \(Up\)' 30 &&
   wait_joined a "F10 quit the explorer"; then
	ok "help: its last row is reached, the keys of every mode before it"
else
	notok "help: its last row is reached, the keys of every mode before it" a
fi
keys a Escape

# ---- pickers: a cut entry, marked in the list, whole under it -------------------
keys a o
wait_for a 'open a preset' 30 || notok "o opens the preset picker" a
n=0
while [ "$n" -lt 40 ] && ! screen a | grep -q '│ permanent-contact-bwmcl: '; do
	keys a Down
	n=$((n + 1))
	sleep 0.05
done
if wait_for a "permanent-contact-bwmcl +Permanent contact, BWMCL on bitumen \\(thi[a-z]*$CUT│" 30; then
	ok "preset picker: a title too long for the list is cut with a mark"
else
	notok "preset picker: a title too long for the list is cut with a mark" a
fi
if wait_joined a "permanent-contact-bwmcl: Permanent contact, BWMCL on bitumen (third study)."; then
	ok "preset picker: the selected entry's title and description are whole under the list"
else
	notok "preset picker: the selected entry's title and description are whole under the list" a
fi
keys a Escape L
if wait_for a 'contact law \(Enter' 30 &&
   wait_joined a "x_c > 0 needs no continuation and ext has no effect (rule R1)"; then
	ok "law picker: the law's whole description under the list"
else
	notok "law picker: the law's whole description under the list" a
fi
keys a Escape

# ---- the parameter panel: a description cut in its header, whole on Enter -------
keys a /
wait_for a '^search parameters' 30
keys a -l run.kinks
keys a Enter
if wait_for a "nudge\\) run\\.kinks: end steps on the kinks of the [a-z ]*$CUT\$" 30; then
	ok "panel header: a description too long is cut with a mark"
else
	notok "panel header: a description too long is cut with a mark" a
fi
keys a Enter
if wait_for a '^run\.kinks yes, no: yes_' 30 &&
   wait_joined a "run.kinks: end steps on the kinks of the law and the loads (no: only to measure their effect)"; then
	ok "Enter: the parameter's description whole above the field"
else
	notok "Enter: the parameter's description whole above the field" a
fi
keys a Escape
keys a q
wait_exit a 50

# ---- the export prompt: a long folder whole, on the rows above the field --------
deep="$TMP/a-folder-with-a-long-name-for-the-export-prompt/and-one-more-level-below-it"
mkdir -p "$deep"
$TM new-session -d -s b -x 80 -y 23 "cd '$deep' && '$BIN'; echo \$? > '$TMP/b.rc'"
wait_for b ' finished$' 150 || notok "the run finishes" b
keys b e
if wait_for b '^BASE: steel-on-bitumen-[0-9-]+_$' 30 &&
   wait_joined b "export to $deep/BASE-trace.csv, -collisions.csv, .preset; BASE"; then
	ok "export prompt: the folder whole on the rows above the field"
else
	notok "export prompt: the folder whole on the rows above the field" b
fi
keys b Escape
keys b q
wait_exit b 50

# ---- the table: the data column past the edge, marked; whole in M -------------
start c 80 23 --data "$(pwd)/examples/fit/bounces.csv" steel-on-bitumen
wait_for c ' finished$' 150 || notok "the run finishes" c
if wait_for c "^ +i t_e\\[ms\\] .* Lambda$CUT\$" 30 && wait_for c '^ +0 +63\.86 .* -0\.01122$' 30; then
	ok "table: the data column past the edge is marked in the header, no digit cut"
else
	notok "table: the data column past the edge is marked in the header, no digit cut" c
fi
keys c Escape Tab Home S
if wait_for c "^sweep: body1\\.name is .*\\.\\.\\. m: whole\$" 30; then
	ok "message line: a long message ends in '... m: whole'"
else
	notok "message line: a long message ends in '... m: whole'" c
fi
keys c m
if wait_for c 'messages, oldest first' 30 &&
   wait_joined c "a sweep varies a number that is typed (law, bodies,"; then
	ok "the log (m) shows the long message whole"
else
	notok "the log (m) shows the long message whole" c
fi
keys c Escape q
wait_exit c 50
exit $failed
