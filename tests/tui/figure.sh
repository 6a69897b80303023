#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# f saves the explorer's view as a figure, in tmux at 100x30: the message
# says where (PRESET-view.png in the working folder); the PNG, read back as
# a reader would (tests/cli/plot_png.py), is not blank, has the three
# panels of the view (x, x_c, F_c), the legend with a style per run (a pin
# and the current run) and the contact shade; a second f writes
# PRESET-view-2.png and keeps the first; the loop view (y) gives one panel.
# send-keys, then poll capture-pane.  Needs HYBOUNCE_BIN and
# HYBOUNCE_PRESETS (tests/run.sh).
. "$(dirname "$0")/common.inc"
PY="python3 $(pwd)/tests/cli/plot_png.py"
# val KEY FILE: the value after KEY in plot_png.py's output
val() { $PY info "$2" | awk -v k="$1" '$1 == k { print $2; exit }'; }

start a 100 30 steel-on-bitumen
wait_for a ' finished$' 150
keys a p
wait_for a 'pinned run 1' 30
if edit a law.c 44000 && wait_for a 'law\.c = 44000: the run restarted' 50 && wait_for a ' finished$' 100; then
	ok "a pinned run and an edited one to draw"
else
	notok "a pinned run and an edited one to draw" a
fi
keys a f
if wait_for a '^wrote steel-on-bitumen-view\.png: the view as a figure \(3 panels, 2 runs, the cursor\)' 100 \
   && [ -s "$TMP/steel-on-bitumen-view.png" ]; then
	ok "f: the message says where the figure went (steel-on-bitumen-view.png)"
else
	notok "f: the message says where the figure went" a
fi
png=$TMP/steel-on-bitumen-view.png
if [ -s "$png" ] && [ "$(val ink "$png")" -gt 20000 ] && [ "$(val panels "$png")" -eq 3 ]; then
	ok "the PNG is not blank ($(val ink "$png") pixels inked) and has the view's 3 panels"
else
	notok "the PNG is not blank and has the view's 3 panels ($(val ink "$png" 2>/dev/null) inked, $(val panels "$png" 2>/dev/null) panels)"
fi
$PY info "$png" >"$TMP/info.txt"
if grep -q '^legend_style 0 ' "$TMP/info.txt" && grep -q '^legend_style 1 ' "$TMP/info.txt" \
   && [ "$(val legend_shade "$png")" -gt 50 ]; then
	ok "its legend has the current run's style, the pin's style and the contact shade"
else
	notok "its legend has both runs' styles and the contact shade"
	grep -v frame "$TMP/info.txt" | sed 's/^/#   /'
fi
cksum "$png" >"$TMP/first.sum"
keys a f
if wait_for a '^wrote steel-on-bitumen-view-2\.png: the view as a figure' 100 \
   && [ -s "$TMP/steel-on-bitumen-view-2.png" ] && cksum "$png" | cmp -s - "$TMP/first.sum"; then
	ok "a second f writes steel-on-bitumen-view-2.png and keeps the first"
else
	notok "a second f writes steel-on-bitumen-view-2.png and keeps the first" a
fi
keys a y
wait_for a 'hysteresis loop' 30
keys a f
if wait_for a '^wrote steel-on-bitumen-view-3\.png: the view as a figure \(1 panel, 2 runs' 100 \
   && [ "$(val panels "$TMP/steel-on-bitumen-view-3.png")" -eq 1 ] \
   && [ "$(val ink "$TMP/steel-on-bitumen-view-3.png")" -gt 5000 ]; then
	ok "the loop view saves as one panel (F_c against x_c)"
else
	notok "the loop view saves as one panel" a
fi
keys a q
wait_exit a 50 || notok "q quits" a
exit $((failed > 0))
