#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Error bars in the explorer (E), in tmux at 120x40: once the run has
# ended a second run at rtol / 100 is computed between frames; the
# selected collision then has a row of error bars under it in the table and
# its e to the digit of its error in the readout, the same bar as batch
# --error writes in the collisions CSV; an edit computes them again for the
# new run; E again hides them.  send-keys, then poll capture-pane.  Needs
# HYBOUNCE_BIN and HYBOUNCE_PRESETS (tests/run.sh).
. "$(dirname "$0")/common.inc"

# batch --error: e and its error bar of collision 0, as the readout prints them
(cd "$TMP" && "$BIN" --batch steel-on-bitumen --error -q --collisions b.csv >/dev/null 2>&1)
want=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
	$1 == 0 { printf "%.0e", $(c["e_err"]) }' "$TMP/b.csv")
[ -n "$want" ] || notok "batch --error wrote collision 0's e_err"

start a 120 40 --ascii steel-on-bitumen
wait_for a ' finished$' 150 || notok "the run ends" a
keys a E
if wait_for a '^error bars on: a second run' 30 || wait_for a '^error bars: rk8pd' 30; then
	ok "E: error bars on, the second run computed between frames"
else
	notok "E: error bars on, the second run computed between frames" a
fi
if wait_for a ' \+-: rtol 1e-14$' 300 && wait_for a '^error bars: rk8pd at rtol 1e-14; the largest' 30; then
	ok "E: the status line and the message say when the bars are there, and how large"
else
	notok "E: the status line and the message say when the bars are there, and how large" a
fi
if wait_for a "coll 0: e=0\.5899554[0-9]*\+-$want( |$)" 30; then
	ok "E: the readout gives the selected collision's e +- $want, batch --error's bar"
else
	notok "E: the readout gives the selected collision's e +- $want, batch --error's bar" a
fi
if wait_for a '^ +\+- +[0-9]e[-+][0-9]+ .*error bars \(E\)' 30 \
   && [ "$(screen a | grep -A1 -E '^ *>?0 ' | grep -Ec '^ +\+- ')" -eq 1 ]; then
	ok "E: a row of error bars under the selected collision in the table"
else
	notok "E: a row of error bars under the selected collision in the table" a
fi
e0=$(screen a | sed -n 's/.*coll 0: e=\([0-9.]*\)+-.*/\1/p' | head -n 1)

edit a law.alpha 0.4
if wait_for a ' \+-: (computing|rtol 1e-14)$' 100 && wait_for a ' \+-: rtol 1e-14$' 300 \
   && wait_for a 'coll 0: e=0\.[0-9]+\+-[0-9]e-[0-9]+' 30 \
   && ! screen a | grep -q "coll 0: e=$e0+-"; then
	ok "an edit: the bars are computed again for the new run"
else
	notok "an edit: the bars are computed again for the new run (e was $e0)" a
fi
keys a Escape
keys a E
if wait_for a '^error bars off' 30 && wait_gone a 'error bars \(E\)' 30 \
   && ! screen a | grep -Eq 'coll 0: e=|\+-: '; then
	ok "E again: the bars are gone from the table, the readout and the status line"
else
	notok "E again: the bars are gone from the table, the readout and the status line" a
fi
keys a q
wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ] || notok "q quits with status 0" a
exit $((failed > 0))
