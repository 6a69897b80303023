#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Editing as a person expects, at 80x23: the README's what-if walkthrough
# runs as written (Tab, /c, Enter, Enter, 44000, Enter gives law.c =
# 44000); / puts parameters before derived values and n/N step through the
# matches; the first key typed into a pre-filled field replaces the value
# while Home or arrows keep it to edit; u undoes an edit, U resets a value
# to the preset's.  send-keys, then poll capture-pane.
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
. "$(dirname "$0")/common.inc"

start a 80 23
wait_for a ' finished$' 150 || notok "the run finishes" a

# ---- the README's walkthrough, key for key ----------------------------------------
keys a Tab
keys a / c Enter
if wait_for a "^law\\.c: match 1 of [0-9]+ for 'c' \\(n/N: next/previous\\)" 30; then
	ok "/c selects law.c first, not the derived x_c^s"
else
	notok "/c selects law.c first, not the derived x_c^s" a
fi
keys a Enter
if wait_for a '^law\.c \(0, inf\): 4400 N s/m_$' 30; then
	ok "Enter opens the field with the value as it is"
else
	notok "Enter opens the field with the value as it is" a
fi
keys a 4 4 0 0 0
if wait_for a '^law\.c \(0, inf\): 44000_$' 30; then
	ok "typing 44000 replaces the pre-filled value"
else
	notok "typing 44000 replaces the pre-filled value" a
fi
keys a Enter
if wait_for a '^law\.c = 44000: the run restarted from t = 0' 50; then
	ok "the README's walkthrough (Tab /c Enter Enter 44000 Enter) edits law.c"
else
	notok "the README's walkthrough (Tab /c Enter Enter 44000 Enter) edits law.c" a
fi

# ---- u: back to the scene before the edit ------------------------------------------
keys a u
if wait_for a '^undid law\.c = 44000: the run restarted from t = 0' 50 &&
   wait_for a ' c +4400 N s/m ' 30; then
	ok "u undoes the edit: c is 4400 N s/m again"
else
	notok "u undoes the edit: c is 4400 N s/m again" a
fi
keys a u
if wait_for a '^nothing to undo' 30; then
	ok "u with nothing left to undo says so"
else
	notok "u with nothing left to undo says so" a
fi

# ---- Home keeps the value to edit it --------------------------------------------
keys a Enter
wait_for a '^law\.c \(0, inf\): 4400 N s/m_$' 30
keys a Home 1 Enter
if wait_for a '^law\.c = 14400 N s/m: the run restarted' 50; then
	ok "Home then 1 edits the value (14400 N s/m) instead of replacing it"
else
	notok "Home then 1 edits the value (14400 N s/m) instead of replacing it" a
fi
keys a Enter
wait_for a '^law\.c \(0, inf\): 14400 N s/m_$' 30
keys a Left BSpace 5 Enter
if wait_for a "^refused \\(old value kept\\): law\\.c: unknown unit 's5m'" 50; then
	ok "Left and BSpace edit inside the value (N s5m, refused)"
else
	notok "Left and BSpace edit inside the value" a
fi

# ---- U: the value as the preset has it -------------------------------------------
keys a U
if wait_for a '^law\.c reset to 4400 N s/m \(as opened\): the run restarted' 50 &&
   wait_for a ' c +4400 N s/m ' 30; then
	ok "U resets law.c to the preset's 4400 N s/m"
else
	notok "U resets law.c to the preset's 4400 N s/m" a
fi
keys a U
if wait_for a '^law\.c is already as opened: 4400 N s/m' 30; then
	ok "U on an unchanged value says so"
else
	notok "U on an unchanged value says so" a
fi

# ---- n/N: the other matches, derived values last ----------------------------------
keys a / c Enter
wait_for a "^law\\.c: match 1 of" 30
keys a n
if wait_for a "^[a-z_.]+: match 2 of [0-9]+ for 'c'" 30 && ! screen a | grep -q '^law\.c: match'; then
	ok "n selects the next match"
else
	notok "n selects the next match" a
fi
keys a N N
if wait_for a "^derived\\.[a-z_]+: match ([0-9]+) of \\1 for 'c'" 30; then
	ok "N goes back past the first match to the last: a derived value"
else
	notok "N goes back past the first match to the last: a derived value" a
fi
keys a q
wait_exit a 50 || notok "q quits" a
exit $((failed > 0))
