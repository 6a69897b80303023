#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer's time controls, views, pickers and parameter nudges, in
# tmux at 80x24 (send-keys, then poll capture-pane; never a bare sleep).
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
# One "ok - NAME" / "not ok - NAME" line per test.
. "$(dirname "$0")/common.inc"

# ---- slow motion through contacts ------------------------------------------
start a 80 24
if wait_for a 't_e\[ms\]' && wait_for a ' x0\.02 slow playing' 100; then
	ok "playback slows down inside a contact (slow motion)"
else
	notok "playback slows down inside a contact (slow motion)" a
fi
keys a s
if wait_for a 'slow motion through contacts off' 30 && wait_gone a ' slow playing' 30; then
	ok "s turns slow motion off"
else
	notok "s turns slow motion off" a
fi

# ---- speed -------------------------------------------------------------------
keys a +
if wait_for a ' x0\.05 ' 30; then
	keys a - -
	if wait_for a ' x0\.01 ' 30; then
		ok "+ and - change the playback speed in 1-2-5 steps"
	else
		notok "- slows playback" a
	fi
else
	notok "+ speeds playback" a
fi

# ---- stepping and jumps --------------------------------------------------------
keys a Home
if wait_for a ' t=0 s j=0 q_c=0 .* paused ' 30; then
	keys a .
	if wait_gone a ' t=0 s ' 30 && wait_for a ' j=0 ' 10; then
		keys a ,
		if wait_for a ' t=0 s j=0 ' 30; then
			ok ". and , step one sample forward and back"
		else
			notok ", steps back" a
		fi
	else
		notok ". steps forward" a
	fi
else
	notok "Home pauses at t = 0" a
fi
keys a ]
if wait_for a ' t=63\.8[0-9]* ms j=1 q_c=1 ' 30; then
	keys a ]
	if wait_for a ' j=2 q_c=0 ' 30; then
		keys a [
		if wait_for a ' j=1 q_c=1 ' 30; then
			ok "] and [ move to the next and previous jump"
		else
			notok "[ previous jump" a
		fi
	else
		notok "] twice" a
	fi
else
	notok "] next jump" a
fi
keys a Right
if wait_for a ' j=[0-9]+ ' 10 && ! screen a | head -n 1 | grep -q ' t=63\.8'; then
	ok "Right scrubs the cursor in time"
else
	notok "Right scrubs the cursor in time" a
fi

# ---- Enter on a table row: zoom and cursor ---------------------------------------
keys a Home
keys a Down Down Enter
if wait_for a 'zoom: collision 2' 30 && wait_for a ' t=188\.[0-9]* ms j=5 q_c=1 ' 30 \
   && wait_for a '^ *>2 ' 10; then
	ok "Enter on row 2 zooms on collision 2 and moves the cursor to its t_e"
else
	notok "Enter on row 2 zooms on collision 2 and moves the cursor to its t_e" a
fi
keys a v
if wait_for a 'hysteresis loop: F_c against x_c, collision 2' 30; then
	keys a v
	if wait_for a 'against j' 30; then
		keys a v
		if wait_for a 'whole run' 30; then
			keys a v
			if wait_for a 'follow the cursor' 30; then
				ok "v cycles the views: zoom, loop, against j, whole run, follow"
			else
				notok "v: follow view" a
			fi
		else
			notok "v: whole run" a
		fi
	else
		notok "v: against j" a
	fi
else
	notok "v: loop view after zoom" a
fi
keys a C-l
if wait_for a '^t -> ' 30 && wait_for a 'follow the cursor' 10; then
	ok "C-l redraws"
else
	notok "C-l redraws" a
fi

# ---- preset picker, restart ---------------------------------------------------------
keys a o
if wait_for a 'open a preset' 30 && wait_for a 'ptfe-pom' 10; then
	picker_up a ptfe-pom && keys a Enter
	if wait_for a '^ ptfe-pom ' 50 && wait_for a 'opened .*ptfe-pom\.preset' 10; then
		ok "o opens the preset picker; Enter loads ptfe-pom"
	else
		notok "preset picker loads ptfe-pom" a
	fi
else
	notok "o opens the preset picker" a
fi
keys a r
if wait_for a 'restarted from t = 0' 30; then
	ok "r restarts the run"
else
	notok "r restarts the run" a
fi

# ---- nudge a value: an initial condition restarts the run and says so ----------------
keys a Tab
if wait_for a 'parameters \(Enter edits' 30 && select_param a initial.x0; then
	before=$(screen a | grep -E '^ +x0 ' | awk '{print $2, $3}')
	keys a +
	if wait_for a 'initial\.x0 = [0-9.e+-]+ [a-z]*m: the run restarted from t = 0' 30; then
		after=$(screen a | grep -E '^ +x0 ' | awk '{print $2, $3}')
		if [ "$before" != "$after" ]; then
			ok "+ in the panel nudges x0 ($before -> $after) and says the run restarted"
		else
			notok "+ nudge changed nothing ($before)" a
		fi
	else
		notok "+ in the panel nudges x0" a
	fi
	keys a q
else
	notok "parameter row initial.x0 not found" a
	keys a q
fi
if wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ]; then
	ok "q quits with status 0"
else
	notok "q quits with status 0"
fi

# ---- + and - step through a list of choices (the stepper) ---------------------
# (run.limits = no: at the preset's rtol 1e-12 rkf45 is refused)
start b 120 40 steel-on-bitumen --set run.limits=no
keys b Tab
if wait_for b 'parameters \(Enter edits' 30 && select_param b run.stepper; then
	keys b +
	if wait_for b 'run\.stepper = rkf45' 30 && screen b | grep -Eq '^ +stepper +rkf45'; then
		keys b - -
		if wait_for b 'run\.stepper = vern98' 30 && screen b | grep -Eq '^ +stepper +vern98'; then
			ok "+ and - step run.stepper through its choices (rk8pd -> rkf45 -> rk8pd -> vern98)"
		else
			notok "- steps run.stepper back, cycling to vern98 (the last)" b
		fi
	else
		notok "+ steps run.stepper to the next choice" b
	fi
else
	notok "parameter row run.stepper not found" b
fi
keys b q
wait_exit b 50 || notok "q quits" b

[ "$failed" -eq 0 ]
