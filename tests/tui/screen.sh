#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer's screen in tmux: small terminals (down to 60x16), the help
# (F1) inside a bordered box at 80 columns with the legend of the contact
# strip and status fields, F10, unknown keys, the panel's paging, sections
# and ends, the preset picker's ends, the mouse and the presentation mode.
# send-keys, then poll capture-pane.  Needs HYBOUNCE_BIN, HYBOUNCE_PRESETS.
. "$(dirname "$0")/common.inc"

# click SESSION X Y: a left click at 0-based column X, row Y (X10 mouse
# encoding, what ncurses asks of tmux's "screen" terminal), press then release
click() {
	p=$(printf "\\$(printf %o $((33 + $2)))")$(printf "\\$(printf %o $((33 + $3)))")
	keys "$1" -l "$(printf '\033[M ')$p"
	keys "$1" -l "$(printf '\033[M#')$p"
}
# wheel SESSION X Y DIR: a wheel turn (DIR up or down) at X, Y
wheel() {
	p=$(printf "\\$(printf %o $((33 + $2)))")$(printf "\\$(printf %o $((33 + $3)))")
	if [ "$4" = up ]; then b='`'; else b='a'; fi
	keys "$1" -l "$(printf '\033[M')$b$p"
}

# ---- sizes ---------------------------------------------------------------------
start s 60 16
if wait_for s ' coll 12 .* finished$' 150 && wait_for s '^x\[mm\]' 10 && wait_for s 't_e\[ms\]' 10 \
   && wait_for s '^#[0-9]+ t=' 10 && wait_for s '^\?:help' 10 \
   && [ "$(screen s | grep -Ec '^ +>?[0-9]+ +[0-9.]+ ')" -ge 3 ]; then
	ok "60x16 (the documented minimum): plots, 3 table rows, readout, message and footer"
else
	notok "60x16: every pane" s
fi
$TM resize-window -t s -x 59 -y 16
if wait_for s 'terminal too small: need at least 60x16' 30; then
	ok "59x16: the too-small message names the minimum 60x16"
else
	notok "59x16: the too-small message" s
fi
$TM resize-window -t s -x 70 -y 20
if wait_for s '^x\[mm\]' 30 && wait_gone s 'too small' 30; then
	ok "70x20: back to the plots"
else
	notok "70x20 redraws" s
fi
keys s F10
if wait_exit s 50 && [ "$(cat "$TMP/s.rc")" = 0 ]; then
	ok "F10 quits with status 0"
else
	notok "F10 quits with status 0"
fi

# ---- an extreme horizon: the time axis stays readable --------------------------------
start h 80 24 --set run.T=1e308
if wait_for h '^t -> .*[0-9]e\+[0-9]+' 100 && ! screen h | grep -q '[0-9]\{12\}'; then
	ok "run.T = 1e308: the time axis reads 2e+295-style labels, never 30 digits"
else
	notok "run.T = 1e308: the time axis stays readable" h
fi
keys h q
wait_exit h 50

# ---- help, unknown keys --------------------------------------------------------------
start a 80 24
wait_for a ' finished$' 150
keys a 1
if wait_for a 'unknown key 1: \? \(or F1\) for help' 30; then
	ok "an unknown key gets a hint (? or F1 for help)"
else
	notok "an unknown key gets a hint" a
fi
keys a F1
if wait_for a 'hybounce keys' 30 && wait_for a 'play / pause' 10 \
   && [ "$(screen a | sed -n '3,20p' | grep -c '│$')" -ge 15 ] \
   && screen a | sed -n 2p | grep -q '^┌─ hybounce keys .*─┐$' && screen a | sed -n 21p | grep -Eq '^└─*( more [a-zA-Z (),]*\) )?─*┘$'; then
	ok "F1: the help in a box with a right border, within 80 columns"
else
	notok "F1: the help in a bordered box" a
fi
# page down to the end, collecting every page (what is explained does not depend on the page size)
: >"$TMP/help"
n=0
while [ $n -lt 12 ] && ! screen a | grep -q 'more above (Up) ─┘$'; do
	screen a >"$TMP/page"
	cat "$TMP/page" >>"$TMP/help"
	keys a PgDn
	n=$((n + 1))
	i=0   # until the page has moved (the box's rows: the status line moves while playing)
	while [ $i -lt 30 ] && [ "$(screen a | sed -n '3,20p')" = "$(sed -n '3,20p' "$TMP/page")" ]; do
		sleep 0.1
		i=$((i + 1))
	done
done
screen a >>"$TMP/help"
if grep -q '\[===\] a longer contact' "$TMP/help" && grep -q 'x0\.02: simulated seconds per second' "$TMP/help" \
   && grep -q 'computing/finished/failed' "$TMP/help"; then
	ok "help explains the contact strip (#, [], [===], ^) and the status fields (x0.02, slow, finished)"
else
	notok "help explains the contact strip and the status fields" a
fi
keys a Escape
wait_gone a 'hybounce keys' 30

# ---- the parameter panel: pages, ends, sections -------------------------------------------
keys a Tab
wait_for a 'parameters \(Enter edits' 30
keys a G
if wait_for a 'nudge\) run\.' 30; then
	keys a g
	if wait_for a 'nudge\) body1\.' 30; then
		ok "G and g (End, Home) go to the panel's last and first rows"
	else
		notok "g goes to the panel's first row" a
	fi
else
	notok "G goes to the panel's last row" a
fi
keys a PgDn
if wait_for a 'nudge\) body1\.mass' 30; then
	ok "PgDn moves the panel a page"
else
	notok "PgDn moves the panel a page" a
fi
keys a '}'
if wait_for a 'nudge\) (scene\.)?.*:' 30 && screen a | grep -q -- '-- derived --'; then
	keys a '}'
	if wait_for a 'nudge\) (law\.|scene\.law)' 30; then
		ok "} jumps to the next section of the panel"
	else
		notok "} jumps to the law section" a
	fi
else
	notok "} jumps to the next section" a
fi
keys a Tab
wait_for a 't_e\[ms\]' 30

# ---- the preset picker's ends -----------------------------------------------------------
# the selected preset's path is shown on the box's last text row
first=$(ls "$HYBOUNCE_PRESETS" | sed -n "1s/\.preset$//p"); last=$(ls "$HYBOUNCE_PRESETS" | sed -n "\$s/\.preset$//p")
keys a o
wait_for a 'open a preset' 30
keys a g
if wait_for a "/$first\.preset\)? +│" 30; then
	keys a G
	if wait_for a "/$last\.preset\)? +│" 30; then
		keys a Home
		wait_for a "/$first\.preset\)? +│" 30
		keys a PgDn
		if wait_gone a "/$first\.preset\)? +│" 30; then
			keys a End
			if wait_for a "/$last\.preset\)? +│" 30; then
				ok "the preset picker takes g, G, Home, End and PgDn ($first ... $last)"
			else
				notok "End in the preset picker" a
			fi
		else
			notok "PgDn in the preset picker" a
		fi
	else
		notok "G in the preset picker" a
	fi
else
	notok "g in the preset picker" a
fi
keys a Escape
wait_gone a 'open a preset' 30

# ---- the mouse ------------------------------------------------------------------------------
# the table's rows start at row 18 (0-based) at 80x24: row 18 is its first visible row
first=$(screen a | sed -n 19p | awk '{ print $1 }' | tr -d '>')
click a 5 19
if wait_for a "^ +>$((first + 1)) " 30 && wait_for a ' paused ' 10; then
	ok "a click on a table row selects that collision and moves the cursor there"
else
	notok "a click on a table row selects it" a
fi
click a 12 5
if wait_for a ' t=[0-9.]+ ms j=[02] q_c=0 ' 30; then
	ok "a click in the plots moves the cursor to that time"
else
	notok "a click in the plots moves the cursor" a
fi
t1=$(screen a | head -n 1)
wheel a 40 5 down
if wait_gone a "^$t1\$" 30; then
	ok "the wheel over the plots scrubs in time"
else
	notok "the wheel over the plots scrubs" a
fi

# ---- presentation mode --------------------------------------------------------------------
h1=$(screen a | grep -c '')
keys a T
if wait_for a 'presentation: contacts in slow motion, looping' 30 && wait_gone a 't_e\[ms\]' 30 \
   && wait_for a 'follow the cursor' 10 && wait_for a ' slow playing' 100; then
	ok "T: presentation mode, no table, the plots follow each contact in slow motion"
else
	notok "T: presentation mode" a
fi
keys a T
# with colours T again is the light theme (tests/tui/projector.sh), a third T ends it
wait_for a 'presentation on the light theme|presentation off' 30
screen a | grep -q 'presentation on the light theme' && keys a T
if wait_for a 'presentation off' 30 && wait_for a 't_e\[ms\]' 30; then
	ok "T again (a third time with colours) restores the table"
else
	notok "T again restores the table" a
fi
keys a q
wait_exit a 50
exit $((failed > 0))
