#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The what-if loop in tmux at 80x23 (an 80x24 terminal under tmux or
# screen): an edit restarts the run from t = 0 and keeps the cursor's t;
# an export after an edit reproduces the run; "branch here" continues from
# the cursor, its export records the branch and --batch reproduces it;
# / finds a parameter by name.  send-keys, then poll capture-pane.
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
. "$(dirname "$0")/common.inc"

# ncoll SESSION: the number of completed collisions on the status line
ncoll() { screen "$1" | head -n 1 | sed -n 's/.* coll \([0-9]*\) .*/\1/p'; }
# rows FILE: data rows of a CSV file
rows() { echo $(($(wc -l <"$1") - 1)); }

mkdir -p "$TMP/out"

# ---- the issue's case: } five times, law.c = 44000, export, re-run in batch ----------
start a 80 23
if wait_for a ' finished$' 150 && wait_for a 't_e\[ms\]' 10 && wait_for a '^\?:help' 10; then
	ok "80x23: the full layout (plots, table, readout, message, footer)"
else
	notok "80x23: the full layout" a
fi
keys a Home
wait_for a '^#0 t=0 s ' 30
keys a '}' '}' '}' '}' '}'
if wait_for a ' j=9 q_c=1 ' 30; then
	t5=$(screen a | sed -n 's/^#[0-9]* t=\([^ ]*\) ms .*/\1/p')
	before=$(ncoll a)
	if edit a law.c 44000 && wait_for a 'law\.c = 44000: the run restarted from t = 0' 50 \
	   && wait_for a ' finished$' 100 && wait_for a "^#[0-9]+ t=" 30 \
	   && t6=$(screen a | sed -n 's/^#[0-9]* t=\([^ ]*\) ms .*/\1/p') \
	   && awk -v a="$t5" -v b="$t6" 'BEGIN { d = a - b; exit !(d < 1 && d > -1) }'; then
		after=$(ncoll a)
		ok "edit at collision 5: the run restarted from t = 0, the cursor stayed at t = $t5 ms (sample at $t6 ms; $before -> $after collisions)"
	else
		notok "edit at collision 5 restarts the run and keeps the cursor's t ($t5)" a
	fi
else
	notok "} five times reaches collision 5 (j = 9)" a
fi
keys a e
wait_for a 'BASE: ' 30
keys a C-u
keys a -l "$TMP/out/c44"
keys a Enter
if wait_for a "wrote $TMP/out/c44-trace\.csv" 50 && [ -s "$TMP/out/c44-collisions.csv" ]; then
	pre=$(ls "$TMP/out/"c44*.preset | head -n 1)
	"$BIN" --batch "$pre" --collisions "$TMP/out/rerun.csv" >/dev/null 2>&1
	if [ -s "$TMP/out/rerun.csv" ] && cmp -s "$TMP/out/rerun.csv" "$TMP/out/c44-collisions.csv"; then
		ok "export after an edit: hybounce -b on the saved scene gives the same $(rows "$TMP/out/rerun.csv") collisions, byte for byte"
	else
		notok "export after an edit reproduces the run ($(rows "$TMP/out/c44-collisions.csv") exported, $(rows "$TMP/out/rerun.csv" 2>/dev/null) re-run)" a
	fi
else
	notok "export after an edit" a
fi

# ---- what if c were ten times larger, asked at the end of the run -----------------
keys a End
wait_for a ' paused finished$' 30
tab1=$(screen a | grep -E '^ +>?[0-9]+ ' | head -n 3)
if edit a law.c 4400 && wait_for a 'law\.c = 4400: the run restarted' 50 && wait_for a ' finished$' 100; then
	tab2=$(screen a | grep -E '^ +>?[0-9]+ ' | head -n 3)
	if [ "$tab1" != "$tab2" ] && [ -n "$tab2" ]; then
		ok "an edit with the cursor in the final permanent contact changes the whole table"
	else
		notok "an edit at the end changes the table" a
	fi
else
	notok "an edit at the end of the run" a
fi

# ---- branch here -------------------------------------------------------------------
keys a Home
wait_for a '^#0 t=0 s ' 30
keys a '}' '}' '}'
wait_for a ' j=5 q_c=1 ' 30
keys a b
if wait_for a 'branch here: the next edit' 30 && edit a law.c 44000 \
   && wait_for a 'law\.c = 44000 from t = .* \(branch here\)' 50 && wait_for a ' finished$' 100; then
	ok "b then an edit: the run continues from the cursor (branch here)"
else
	notok "b then an edit continues from the cursor" a
fi
keys a e
wait_for a 'BASE: ' 30
keys a C-u
keys a -l "$TMP/out/br"
keys a Enter
if wait_for a "wrote $TMP/out/br-trace\.csv" 50 && keys a m \
   && wait_for a 'messages, oldest first' 30 \
   && screen a | tr -d '\n' | sed 's/│//g' | tr -s ' ' | grep -q 'records the 1 branch (the first at t = .*) and --batch replays it'; then
	ok "the export of a branched run says the scene file records the branch"
else
	notok "the export of a branched run says the scene file records the branch" a
fi
if head -n 1 "$TMP/out/br.preset" | grep -q 'a run with 1 branch: the scene below from t = 0' \
   && grep -q '^\[branch 1\]$' "$TMP/out/br.preset" && grep -q '^law\.c = 44000 N s/m$' "$TMP/out/br.preset"; then
	ok "the exported preset records the branch: [branch 1] with t, j, the state and law.c"
else
	notok "the exported preset records the branch"
	sed 's/^/#   /' "$TMP/out/br.preset" | head -n 5
fi
"$BIN" --batch "$TMP/out/br.preset" --collisions "$TMP/out/br-rerun.csv" >"$TMP/out/br-rerun.txt" 2>&1
if [ -s "$TMP/out/br-rerun.csv" ] && cmp -s "$TMP/out/br-rerun.csv" "$TMP/out/br-collisions.csv" \
   && grep -q '^branch 1    from t = ' "$TMP/out/br-rerun.txt"; then
	ok "export after a branch: --batch on it gives the same $(rows "$TMP/out/br-rerun.csv") collisions, byte for byte, and names the branch"
else
	notok "export after a branch reproduces the run ($(rows "$TMP/out/br-collisions.csv") exported, $(rows "$TMP/out/br-rerun.csv" 2>/dev/null) re-run)"
	sed 's/^/#   /' "$TMP/out/br-rerun.txt" | head -n 5
fi
keys a Escape
wait_gone a 'messages, oldest first' 30

# ---- search ---------------------------------------------------------------------------
keys a /
wait_for a '^search parameters' 30
keys a -l x0
if wait_for a 'nudge\) initial\.x0:' 30; then
	keys a Escape
	ok "/ x0 selects initial.x0 as it is typed"
else
	notok "/ x0 selects initial.x0" a
fi
keys a /
wait_for a '^search parameters' 30
keys a -l nosuchkey
keys a Enter
if wait_for a "no parameter matches 'nosuchkey'" 30; then
	ok "/ with no match says so"
else
	notok "/ with no match says so" a
fi
keys a q
wait_exit a 50 || notok "q quits" a
exit $((failed > 0))
