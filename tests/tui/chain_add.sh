#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Adding a key of one body of a chain from the explorer (a), in tmux at
# 80x24 on newtons-cradle-5: a asks for the key, initial.body.3.v (which
# the preset does not give: the chain's 0 m/s is proposed), then 0.5; the
# run restarts with it (six collisions instead of four, the first at
# interface 3 at t = 0), the panel lists v (body 3) 500 mm/s; u takes it
# away again; body.3.mass = 100 g typed at once is set; the exported scene holds it, and the explorer opened on
# that file runs it (its row in the panel, the same six collisions).  A
# key outside the chain is refused with the range; on a scene holding 64
# such keys a new one is refused with the limit, nothing changed; on a
# two-body scene a says it is for chains.  (b on a chain: chain_branch.sh.)
. "$(dirname "$0")/common.inc"

rows() { screen "$1" | grep -E '^ +>?[0-9]+ +[0-9]+ +[0-9.e+-]+ ' ; }
nrows() { rows "$1" | wc -l; }

start a 80 24 newtons-cradle-5
wait_for a 'finished' 100 && [ "$(nrows a)" -eq 4 ] || notok "newtons-cradle-5: four collisions" a

keys a a
if wait_for a '^add a key of one body or interface \[= VALUE\] \(1 of 64 held\)' 30; then
	keys a -l interface.5.c
	keys a Enter
	if wait_for a 'add: interface\.5\.c: the chain of 5 bodies has no interface 5' 30; then
		ok "a: interface.5.c is refused with the interfaces there are"
	else
		notok "a: interface.5.c is refused with the interfaces there are" a
	fi
else
	notok "a: the prompt for a key of one body or interface, 1 of 64 held" a
fi

keys a a
wait_for a '^add a key of one body' 30 || notok "a again: the prompt" a
keys a -l initial.body.3.v
keys a Enter
if wait_for a '^initial\.body\.3\.v .*\(new: the chain.s value now\): 0 m/s' 30; then
	ok "initial.body.3.v: its value asked, the chain's 0 m/s proposed"
else
	notok "initial.body.3.v: its value asked, the chain's 0 m/s proposed" a
fi
keys a -l 0.5
keys a Enter
if wait_for a 'initial\.body\.3\.v = 0\.5: the run restarted from t = 0' 50 && wait_for a 'finished' 100 &&
    screen a | grep -Eq 'parameters \(Enter edits, \+/- nudge\) initial\.body\.3\.v:' &&
    screen a | grep -Eq '^  v \(body 3\) +500 mm/s '; then
	ok "0.5: the run restarted, the panel lists v (body 3) 500 mm/s, selected"
else
	notok "0.5: the run restarted, the panel lists v (body 3) 500 mm/s, selected" a
fi
keys a Tab
if wait_for a '^ +i +k +t_e' 30 && [ "$(nrows a)" -eq 6 ] && rows a | head -n 1 | grep -Eq '^ +>?0 +3 +0 '; then
	ok "the table: six collisions, the first at interface 3 at t = 0"
else
	notok "the table: six collisions, the first at interface 3 at t = 0" a
fi

keys a e
wait_for a '^export to .*; BASE' 30 || notok "e: the export prompt" a
keys a C-u
keys a -l added
keys a Enter
if wait_for a 'wrote added-trace\.csv, added-collisions\.csv and added\.preset' 50 &&
    grep -Eq '^body\.3\.v = 0\.5 m/s' "$TMP/added.preset" &&
    [ "$(grep -c '^i,k\|^[0-9]' "$TMP/added-collisions.csv")" -eq 7 ]; then
	ok "the exported scene holds body.3.v = 0.5 m/s in [initial], its table six collisions"
else
	notok "the exported scene holds body.3.v = 0.5 m/s in [initial], its table six collisions" a
	sed 's/^/#   /' "$TMP/added.preset" 2>/dev/null
fi

keys a u
if wait_for a 'undid initial\.body\.3\.v = 0\.5' 30 && wait_for a 'finished' 100 &&
    wait_for a '^ +i +k +t_e' 30 && [ "$(nrows a)" -eq 4 ] && ! screen a | grep -q 'v (body 3)'; then
	ok "u: the key taken away, four collisions again"
else
	notok "u: the key taken away, four collisions again" a
fi
keys a a
wait_for a '^add a key of one body' 30 || notok "a: the prompt" a
keys a -l 'body.3.mass = 100 g'
keys a Enter
if wait_for a 'body\.3\.mass = 100 g: the run restarted from t = 0' 50 &&
    wait_for a '^  mass \(body 3\) +100 g ' 30; then
	ok "a with KEY = VALUE: body.3.mass = 100 g at once, its row in the panel"
else
	notok "a with KEY = VALUE: body.3.mass = 100 g at once, its row in the panel" a
fi
keys a q
wait_exit a 50 || notok "the explorer quits" a

start b 80 24 added.preset
if wait_for b 'finished' 100 && [ "$(nrows b)" -eq 6 ] && keys b / && wait_for b '^search parameters' 30 &&
    keys b -l initial.body.3.v && keys b Enter && wait_for b '^  v \(body 3\) +500 mm/s ' 30; then
	ok "the exported preset reopened: v (body 3) 500 mm/s in the panel, six collisions"
else
	notok "the exported preset reopened: v (body 3) 500 mm/s in the panel, six collisions" b
fi
keys b q
wait_exit b 50 || notok "the explorer quits" b

# a chain of 64 whose every body has its own initial velocity: 64 keys held
{
	printf '[scene]\nname = full\nlaw = hertz\n[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 1 mm\n'
	printf '[chain]\nn = 64\nspacing = 1 mm\n[initial]\n'
	i=1
	while [ "$i" -le 64 ]; do printf 'body.%d.v = 0\n' "$i"; i=$((i + 1)); done
	printf '[loads]\ng = 0\n[run]\nT = 1 ms\n'
} >"$TMP/full.preset"
start c 80 24 full.preset
wait_for c 'full hertz' 100 || notok "the chain of 64 opens" c
keys c a
wait_for c '^add a key of one body or interface \[= VALUE\] \(64 of 64 held\)' 30 || notok "a: 64 of 64 held" c
keys c -l 'body.2.R = 2 mm'
keys c Enter
if wait_for c 'add: refused: 64 of 64 keys of single bodies and interfaces held' 30 &&
    ! screen c | grep -q 'R (body 2)'; then
	ok "64 keys held: a new one is refused with the limit, the panel unchanged"
else
	notok "64 keys held: a new one is refused with the limit, the panel unchanged" c
fi
keys c q
wait_exit c 50 || notok "the explorer quits" c

start d 80 24 hertz-elastic
wait_for d 'hertz-elastic' 100 || notok "hertz-elastic opens" d
keys d a
if wait_for d "add: a chain's keys of one body or interface only" 30 && ! screen d | grep -q '^add a key'; then
	ok "a two-body scene: a says it is for chains, no prompt"
else
	notok "a two-body scene: a says it is for chains, no prompt" d
fi
keys d q
wait_exit d 50 || notok "the explorer quits" d

[ "$failed" -eq 0 ]
