#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The collisions table of one interface of a chain (i), in tmux at 80x24
# on newtons-cradle-5 (four contacts, one at each interface, from the
# striker's k = 4 down): i shows interface 1's alone (its column headed
# k=1, one row, the message says 1 of 4), each i the next, after k = 4
# every interface's again; } from t = 0 with interface 2 shown puts the
# cursor at that interface's collision, and then } and { find no later
# nor earlier one (its own only: the others are not rows), its row marked >
# though other interfaces are in contact at that time too; cut at 1.002 ms,
# the three contacts in progress are three live rows, and with interface 1
# (no collision yet) shown, Enter says so instead of
# zooming on a row not shown; on a two-body scene i says there is one
# interface and leaves the table whole.
. "$(dirname "$0")/common.inc"

# rows of the table: "  I  K ..." (the cursor's row ">I")
rows() { screen "$1" | grep -E '^ +>?[0-9]+ +[0-9]+ +[0-9.e+-]+ ' ; }
nrows() { rows "$1" | wc -l; }
# rows of a two-body table: "  I T_E ..."
rows2() { screen "$1" | grep -E '^ +>?[0-9]+ +[0-9.e+-]+ +[0-9.e+-]+ ' | wc -l; }

start a 80 24 newtons-cradle-5
if wait_for a 'finished' 100 && [ "$(nrows a)" -eq 4 ] &&
    [ "$(rows a | awk '{ print $2 }' | tr '\n' ' ')" = "4 3 2 1 " ] &&
    screen a | grep -Eq '^ +i +k +t_e'; then
	ok "the whole table: four rows, k 4 3 2 1, the column headed k"
else
	notok "the whole table: four rows, k 4 3 2 1, the column headed k" a
fi

keys a i
if wait_for a 'table: interface 1 alone \(bodies 1 and 2\), 1 of 4 collisions' 30 &&
    screen a | grep -Eq '^ +i +k=1 +t_e' && [ "$(nrows a)" -eq 1 ] &&
    rows a | grep -Eq '^ +>?3 +1 '; then
	ok "i: interface 1 alone, headed k=1, its one row (collision 3)"
else
	notok "i: interface 1 alone, headed k=1, its one row (collision 3)" a
fi

keys a i
if wait_for a 'table: interface 2 alone \(bodies 2 and 3\)' 30 &&
    screen a | grep -Eq '^ +i +k=2 +t_e' && [ "$(nrows a)" -eq 1 ] &&
    rows a | grep -Eq '^ +>?2 +2 '; then
	ok "i again: interface 2 alone (collision 2)"
else
	notok "i again: interface 2 alone (collision 2)" a
fi

# } from t = 0 goes to interface 2's collision, at its t_e (about 1 ms: a pushed contact,
# whose commencement a rounding-level approach decides)
keys a g
wait_for a '^#0 t=0 ' 30 || notok "g: the cursor to t = 0" a
keys a '}'
if wait_for a '^#[0-9]+ t=1(\.0[0-9]*)? ms j=[0-9]+ q_c=1 ' 30; then
	# the cursor's row is marked: collision 2 is in progress there (so are 0 and 1, not rows)
	if rows a | grep -Eq '^ +>2 +2 '; then
		ok "} with interface 2 shown: its row marked > at the cursor, beside other interfaces' contacts"
	else
		notok "} with interface 2 shown: its row marked > at the cursor, beside other interfaces' contacts" a
	fi
	keys a '}'
	if wait_for a 'no later collision of interface 2' 30; then
		keys a '{'
		if wait_for a 'no earlier collision of interface 2' 30; then
			ok "} with interface 2 shown: the cursor to its collision (t = 1 ms, in contact), then none later nor earlier"
		else
			notok "} with interface 2 shown: the cursor to its collision (t = 1 ms, in contact), then none later nor earlier" a
		fi
	else
		notok "} with interface 2 shown: the cursor to its collision (t = 1 ms, in contact), then none later nor earlier" a
	fi
else
	notok "} with interface 2 shown: the cursor to its collision (t = 1 ms, in contact), then none later nor earlier" a
fi

keys a i i
if wait_for a 'table: interface 4 alone \(bodies 4 and 5\)' 30 && rows a | grep -Eq '^ +>?0 +4 ' &&
    [ "$(nrows a)" -eq 1 ]; then
	ok "i twice more: interface 4 alone (collision 0)"
else
	notok "i twice more: interface 4 alone (collision 0)" a
fi
keys a i
if wait_for a "table: every interface's collisions, 4" 30 && [ "$(nrows a)" -eq 4 ] &&
    screen a | grep -Eq '^ +i +k +t_e'; then
	ok "after the last interface: every interface's again"
else
	notok "after the last interface: every interface's again" a
fi
keys a q
wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ] || notok "the explorer quits with 0" a

# cut at 1.002 ms, the cursor at the end (G): interfaces 4, 3 and 2 in contact side by side,
# interface 1 not yet: three live rows (k 2, 3, 4), each marked in progress; with interface 1
# shown there is no row, and Enter says so instead of zooming on a row not shown
start c 80 24 newtons-cradle-5 --set run.T=1.002ms
wait_for c 'finished' 100 || notok "newtons-cradle-5 runs to 1.002 ms" c
keys c G
if wait_for c '^#[0-9]+ t=1\.002 ms ' 30 && [ "$(nrows c)" -eq 3 ] && [ "$(rows c | grep -c '^ *>.* live ')" -eq 3 ] &&
    [ "$(rows c | awk '{ print $2 }' | tr '\n' ' ')" = "2 3 4 " ]; then
	ok "at 1.002 ms, the cursor at the end: three contacts in progress, k 2 3 4, each live and marked >"
else
	notok "at 1.002 ms, the cursor at the end: three contacts in progress, k 2 3 4, each live and marked >" c
fi
keys c i
wait_for c 'table: interface 1 alone \(bodies 1 and 2\), 0 of 3 collisions' 30 || notok "i: interface 1 alone, no row" c
keys c Enter
if wait_for c 'interface 1 has no collision \(yet; i: every interface' 30 && ! screen c | grep -q 'zoom'; then
	ok "Enter with interface 1 shown and no row: the message, no zoom"
else
	notok "Enter with interface 1 shown and no row: the message, no zoom" c
fi
keys c q
wait_exit c 50 || notok "the explorer quits" c

start b 80 24 hertz-elastic
wait_for b 'finished' 100 || notok "hertz-elastic runs" b
n0=$(rows2 b)
keys b i
if wait_for b 'one interface only: the table lists every collision' 30 && [ "$n0" -gt 0 ] && [ "$(rows2 b)" -eq "$n0" ] &&
    ! screen b | grep -Eq 'k=|^ +i +k '; then
	ok "a two-body scene: i says there is one interface, the table unchanged ($n0 rows)"
else
	notok "a two-body scene: i says there is one interface, the table unchanged ($n0 rows)" b
fi
keys b q
wait_exit b 50 || notok "the explorer quits" b

[ "$failed" -eq 0 ]
