#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer driven as a person uses it: tmux at fixed sizes, send-keys,
# then poll capture-pane until the expected text appears (never a bare
# sleep).  Needs HYBOUNCE_BIN (absolute path) and HYBOUNCE_PRESETS, as set
# by tests/run.sh.  One "ok - NAME" / "not ok - NAME" line per test.
. "$(dirname "$0")/common.inc"

# ---- 1. start: plots and the collisions table ----------------------------
start a 80 24
if wait_for a 't_e\[ms\]' && wait_for a '^x\[mm\]' && wait_for a '^t -> ' \
   && wait_for a '^ +0 +[0-9.]+ +[0-9.]+ +-' && wait_for a 'coll [1-9]'; then
	ok "starts on steel-on-bitumen with the plots and the collisions table"
else
	notok "starts on steel-on-bitumen with the plots and the collisions table" a
fi

# the table follows the run as it computes; at its end the status line
# counts the first study's 12 collisions and the table ends with the
# permanent contact in progress
if wait_for a 'finished' 150 && wait_for a ' coll 12 ' 10; then
	keys a End
	if wait_for a '^ *>?12 +[0-9.]+ +[0-9.]+ +[-0-9.e]+ +live ' 30; then
		ok "run finished: 12 collisions, the permanent contact shown live"
	else
		notok "run finished: 12 collisions, the permanent contact shown live" a
	fi
else
	notok "run finished: 12 collisions" a
fi

# ---- 2. pause, earlier collision: t, j and the table's cursor row change --
keys a space
wait_for a ' paused ' 30
keys a End
wait_for a ' paused ' 30
j1=$(status_field a j)
t1=$(status_field a t)
keys a '{'
wait_gone a " t=$t1 " 30
j2=$(status_field a j)
t2=$(status_field a t)
keys a '{'
wait_gone a " j=$j2 " 30
j3=$(status_field a j)
t3=$(status_field a t)
i3=$(( (j3 - 1) / 2 ))
if [ -n "$j2" ] && [ -n "$j3" ] && [ "$j3" -lt "$j2" ] && [ "$j2" -le "$j1" ] \
   && [ $((j3 % 2)) = 1 ] && [ "$t3" != "$t2" ] && screen a | grep -Eq "^ *>$i3 "; then
	ok "pause and go to an earlier collision: j $j1 -> $j2 -> $j3, table row $i3 marked"
else
	notok "pause and go to an earlier collision (j $j1 -> $j2 -> $j3)" a
fi

# ---- 3. edit c at the cursor ---------------------------------------------
keys a Tab
if wait_for a 'parameters \(Enter edits' 30 && select_param a law.c; then
	keys a Enter
	wait_for a '^law\.c .*: ' 30
	keys a C-u
	keys a -l '6000 N s/m'
	keys a Enter
	if wait_for a 'law\.c = 6000 N s/m: the run restarted from t = 0 \(b: branch here\)' 50 \
	   && wait_for a ' c +6000 N s/m' 30 && wait_for a 'finished' 100; then
		ok "edit c: the run restarts from t = 0 with the new value, the cursor keeps its t"
	else
		notok "edit c: the run restarts from t = 0 with the new value" a
	fi
else
	notok "edit c: parameter row law.c not found" a
fi

# ---- 4. refuse alpha = 1.5 -------------------------------------------------
if select_param a law.alpha || { keys a Home; select_param a law.alpha; }; then
	:
fi
# the selection may lie below law.alpha: walk up
n=0
while ! screen a | grep -q "nudge) law.alpha:" && [ $n -lt 40 ]; do
	keys a Up
	sleep 0.05
	n=$((n + 1))
done
old=$(screen a | grep -E '^ +alpha ' | awk '{print $2}')
keys a Enter
wait_for a '^law\.alpha .*: ' 30
keys a C-u
keys a -l '1.5'
keys a Enter
# the message is longer than the line: m shows it whole
if wait_for a 'refused.*m: whole' 30 && screen a | grep -Eq "^ +alpha +$old" \
   && keys a m && wait_for a 'refused \(old value kept\): law\.alpha: .*' 30 \
   && screen a | tr -d '\n' | grep -q '(0, 1)' && keys a Escape && wait_gone a 'messages, oldest' 30; then
	ok "alpha = 1.5 refused with the accepted range (0, 1); old value $old kept"
else
	notok "alpha = 1.5 refused with the accepted range (0, 1)" a
fi

# ---- 5. switch the law -----------------------------------------------------
keys a Tab
keys a L
if wait_for a 'contact law \(Enter chooses' 30; then
	for k in 1 2 3 4 5 6; do keys a Up; done
	keys a Enter
	if wait_for a '^ steel-on-bitumen shccl ' 50 && wait_for a 'law shccl' 30; then
		ok "law picker: switched to shccl"
	else
		notok "law picker: switched to shccl" a
	fi
else
	notok "law picker opens" a
fi

# ---- 6. pin a run and see the legend -------------------------------------
keys a p
if wait_for a 'pinned run 1' 30 && wait_for a '\.1 same scene +\* now same scene' 30; then
	keys a L
	wait_for a 'contact law' 30
	keys a Down
	keys a Enter
	if wait_for a '\.1 law = shccl.* +\* now law = bwshccl' 50; then
		ok "pin: legend shows the ghost and the new run (bwshccl)"
	else
		notok "pin: legend shows the ghost and the new run" a
	fi
else
	notok "pin: legend" a
fi
keys a P
wait_for a 'pinned runs cleared' 30 || notok "P clears pins" a

# ---- 7. export -------------------------------------------------------------
keys a e
if wait_for a 'BASE: ' 30 && keys a C-u \
   && wait_for a '^export to /.*/BASE-trace\.csv, -collisions\.csv, \.preset; BASE: _' 30; then
	keys a -l "$TMP/out/run1"
	mkdir -p "$TMP/out"
	keys a Enter
	if wait_for a "wrote $TMP/out/run1-trace.csv" 50 \
	   && [ -s "$TMP/out/run1-trace.csv" ] && [ -s "$TMP/out/run1-collisions.csv" ] \
	   && [ -s "$TMP/out/run1.preset" ] && [ ! -e "$TMP/out/run1-trace.preset" ] \
	   && head -n 1 "$TMP/out/run1-trace.csv" | grep -q '^t,j,q_c,x,v,x_c' \
	   && awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad || NR < 3 }' "$TMP/out/run1-trace.csv" \
	   && awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad || NR < 2 }' "$TMP/out/run1-collisions.csv" \
	   && "$BIN" --batch "$TMP/out/run1.preset" -q >/dev/null 2>&1; then
		ok "export: trace and collisions CSV and the scene run1.preset written and parse"
	else
		notok "export: trace and collisions CSV and the scene run1.preset written and parse" a
		ls -l "$TMP/out" | sed 's/^/#   /'
	fi
else
	notok "export prompt" a
fi
# a failed export says why and loses nothing
keys a e
wait_for a 'BASE: ' 30
keys a C-u
keys a -l "$TMP/no/such/dir/run2"
keys a Enter
if wait_for a 'export failed' 30 && wait_for a '^t -> ' 10; then
	ok "export into a missing folder fails with a message"
else
	notok "export into a missing folder fails with a message" a
fi

# ---- 8. resize --------------------------------------------------------------
$TM resize-window -t a -x 120 -y 40
if wait_for a '^t -> .* ms$' 30 && wait_for a '^x\[mm\]' 30 \
   && [ "$(screen a | wc -l)" -ge 39 ] && screen a | tail -n 1 | grep -q '?:help'; then
	ok "resize to 120x40 redraws"
else
	notok "resize to 120x40 redraws" a
fi
$TM resize-window -t a -x 60 -y 15
if wait_for a 'terminal too small: need at least 60x16' 30; then
	ok "60x15 shows the too-small message"
else
	notok "60x15 shows the too-small message" a
fi
$TM resize-window -t a -x 80 -y 24
if wait_for a '^t -> ' 30 && wait_gone a 'too small' 30; then
	ok "back to 80x24 redraws"
else
	notok "back to 80x24 redraws" a
fi

# ---- 9. help and quit --------------------------------------------------------
keys a '?'
if wait_for a 'hybounce keys' 30 && wait_for a 'play / pause' 10; then
	ok "help overlay lists the keys"
else
	notok "help overlay lists the keys" a
fi
keys a Escape
wait_gone a 'hybounce keys' 30
keys a q
if wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ]; then
	ok "q quits with status 0"
else
	notok "q quits with status 0 (rc: $(cat "$TMP/a.rc" 2>/dev/null))"
fi

# ---- 10. a larger terminal: table and parameters side by side ---------------
start b 160 48
if wait_for b 't_e\[ms\]' && wait_for b '-- bodies --' && wait_for b '-- run --' \
   && wait_for b '^x\[mm\]'; then
	ok "160x48: plots, table and parameter panel together"
else
	notok "160x48: plots, table and parameter panel together" b
fi
keys b 3
if wait_for b 'third study' 50 && wait_for b '\.1 law = shccl \+[0-9]+  o2 law = bwshccl \+[0-9]+  \* now law = bwmcl' 30; then
	ok "key 3: the paper's third study, three runs pinned with a legend"
else
	notok "key 3: the paper's third study, three runs pinned with a legend" b
fi
keys b y
if wait_for b 'hysteresis loop: F_c against x_c' 30 && wait_for b '^x_c -> ' 10; then
	ok "hysteresis loop view"
else
	notok "hysteresis loop view" b
fi
keys b J
if wait_for b 'against j' 30 && wait_for b '^j -> ' 10; then
	ok "view of the arc against j"
else
	notok "view of the arc against j" b
fi
keys b C-c
if wait_exit b 50; then
	ok "Ctrl-C leaves the explorer (status $(cat "$TMP/b.rc"))"
else
	notok "Ctrl-C leaves the explorer" b
fi

# ---- 11. SIGHUP, NO_COLOR, ASCII ------------------------------------------
# (the program's pid comes from a wrapper that execs it: no pgrep needed)
printf 'echo $$ > "%s/c.pid"\nexec "%s" --ascii\n' "$TMP" "$BIN" >"$TMP/run-c.sh"
rm -f "$TMP/c.rc"
$TM new-session -d -s c -x 80 -y 24 "cd '$TMP' && sh '$TMP/run-c.sh'; echo \$? > '$TMP/c.rc'"
if wait_for c '^x\[mm\]' && screen c | grep -q '\*'; then
	ok "--ascii plots with '*'"
else
	notok "--ascii plots with '*'" c
fi
kid=$(cat "$TMP/c.pid" 2>/dev/null)
if [ -n "$kid" ] && kill -HUP "$kid" && wait_exit c 50; then
	ok "SIGHUP leaves the explorer through term_end (status $(cat "$TMP/c.rc"))"
else
	notok "SIGHUP leaves the explorer" c
fi
$TM kill-session -t c 2>/dev/null

rm -f "$TMP/d.rc"
$TM new-session -d -s d -x 80 -y 24 \
    "cd '$TMP' && NO_COLOR=1 '$BIN' ; echo \$? > '$TMP/d.rc'"
if wait_for d 't_e\[ms\]' && wait_for d 'finished' 100; then
	keys d q
	if wait_exit d 50 && [ "$(cat "$TMP/d.rc")" = 0 ]; then
		ok "NO_COLOR: runs and quits"
	else
		notok "NO_COLOR: quits" d
	fi
else
	notok "NO_COLOR: runs" d
fi

# ---- 12. a preset that does not load: status 2, message after the terminal is restored
start e 80 24 no-such-preset
if wait_exit e 50 && [ "$(cat "$TMP/e.rc")" = 2 ]; then
	ok "an unknown preset exits with status 2"
else
	notok "an unknown preset exits with status 2 (rc $(cat "$TMP/e.rc" 2>/dev/null))"
fi

# ---- 13. responsive while a long run computes ---------------------------------
# a step bound of 1 ns inside contacts makes the run take minutes
start f 80 24 --set "'run.h_max=1e-9 s'"
if wait_for f ' computing$' 100; then
	keys f '?'
	if wait_for f 'hybounce keys' 20; then
		keys f Escape
		wait_gone f 'hybounce keys' 20
		keys f Tab
		if wait_for f 'parameters \(Enter edits' 20 && screen f | head -n 1 | grep -q ' computing$'; then
			keys f q
			if wait_exit f 30 && [ "$(cat "$TMP/f.rc")" = 0 ]; then
				ok "responsive while a long run computes (help, focus, quit within 2-3 s)"
			else
				notok "quit while computing" f
			fi
		else
			notok "Tab while computing" f
		fi
	else
		notok "help while computing" f
	fi
else
	notok "a long run shows computing" f
fi

[ "$failed" -eq 0 ]
