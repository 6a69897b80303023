#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Branch here (b) on a chain, in tmux at 80x24 on newtons-cradle-5: the
# cursor on the second collision (} twice: interface 3's contact begins,
# j = 2), b, then body.1.mass = 10 g (a, KEY = VALUE): the run continues
# from there; the rows of the contacts begun before it keep their t_e,
# v_i, e and x_c^max, the far ball's contact (interface 1, after the
# branch) changes.  The export records [branch 1] and --batch on it gives
# the same collisions, byte for byte.  Then b with a change of the initial
# state (striker v): it cannot continue, the run restarts from t = 0.
. "$(dirname "$0")/common.inc"

rows() { screen "$1" | grep -E '^ +>?[0-9]+ +[0-9]+ +[0-9.e+-]+ ' ; }
# row SESSION I: columns i k t_e t_d v_i e x_c^max of row I
row() { rows "$1" | sed 's/>/ /' | awk -v i="$2" '$1 == i { print $1, $2, $3, $5, $6, $7 }'; }
rowfull() { rows "$1" | sed 's/>/ /' | awk -v i="$2" '$1 == i { print $0 }'; }

start a 80 24 newtons-cradle-5
wait_for a 'finished' 100 && wait_for a '^ +i +k +t_e' 30 && [ "$(rows a | wc -l)" -eq 4 ] \
	|| notok "newtons-cradle-5: four collisions" a
r0=$(row a 0) r1=$(row a 1) r3=$(rowfull a 3)
keys a Home
wait_for a '^#0 t=0 s ' 30
keys a '}' '}'
if wait_for a '^#[0-9]+ t=1 ms j=2 q_c=1 ' 30; then
	ok "} twice: the cursor on the second collision's commencement (j = 2)"
else
	notok "} twice: the cursor on the second collision's commencement (j = 2)" a
fi
keys a b
if wait_for a 'branch here: the next edit' 30; then
	ok "b on a chain: armed"
else
	notok "b on a chain: armed" a
fi
keys a a
wait_for a '^add a key of one body or interface' 30 || notok "a: the prompt" a
keys a -l 'body.1.mass = 10 g'
keys a Enter
if wait_for a 'body\.1\.mass = 10 g from t = 1 ms, j = 2 \(branch here\)' 50 && wait_for a 'finished' 100; then
	ok "body.1.mass = 10 g: the run continues from the cursor (branch here)"
else
	notok "body.1.mass = 10 g: the run continues from the cursor (branch here)" a
fi
keys a Tab
wait_for a '^ +i +k +t_e' 30 || notok "Tab: the table" a
if [ "$(rows a | wc -l)" -eq 4 ] && [ "$(row a 0)" = "$r0" ] && [ "$(row a 1)" = "$r1" ] \
   && [ -n "$(rowfull a 3)" ] && [ "$(rowfull a 3)" != "$r3" ]; then
	ok "the table: the contacts begun before the branch keep t_e, v_i, e, x_c^max; interface 1's changed"
else
	notok "the table: the contacts begun before the branch kept, interface 1's changed ($r3)" a
fi

keys a e
wait_for a '^export to .*; BASE' 30 || notok "e: the export prompt" a
keys a C-u
keys a -l br
keys a Enter
if wait_for a 'wrote br-trace\.csv, br-collisions\.csv and br\.preset' 50 \
   && grep -q '^\[branch 1\]$' "$TMP/br.preset" && grep -q '^body\.1\.mass = 0\.01 kg$' "$TMP/br.preset"; then
	ok "the export records [branch 1] with body.1.mass"
else
	notok "the export records [branch 1] with body.1.mass" a
	sed 's/^/#   /' "$TMP/br.preset" 2>/dev/null | tail -n 12
fi
"$BIN" --batch "$TMP/br.preset" --collisions "$TMP/rerun.csv" >"$TMP/rerun.txt" 2>&1
if [ -s "$TMP/rerun.csv" ] && cmp -s "$TMP/rerun.csv" "$TMP/br-collisions.csv" \
   && grep -q '^branch 1    from t = 1 ms (j = 2)' "$TMP/rerun.txt"; then
	ok "--batch on the export: the same collisions, byte for byte, from the branch"
else
	notok "--batch on the export: the same collisions, byte for byte, from the branch"
	sed 's/^/#   /' "$TMP/rerun.txt" | head -n 8
fi

keys a b
wait_for a 'branch here: the next edit' 30 || notok "b again: armed" a
keys a /
wait_for a '^search parameters' 30
keys a -l striker.v
keys a Enter
wait_for a 'nudge\) striker\.v:' 30 || notok "/striker.v: selected" a
keys a Enter
wait_for a '^striker\.v .*: ' 30 || notok "striker v: its prompt" a
keys a C-u
keys a -l -- '-2 m/s'
keys a Enter
if wait_for a 'striker\.v = -2 m/s: cannot branch here' 50 && wait_for a '^#0 t=0 s j=0 ' 30; then
	ok "b, then the striker's velocity: cannot continue, the run restarted from t = 0"
else
	notok "b, then the striker's velocity: cannot continue, the run restarted from t = 0" a
fi
keys a q
wait_exit a 50 || notok "the explorer quits" a

[ "$failed" -eq 0 ]
