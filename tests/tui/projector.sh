#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The presentation mode (T) holds up on a projector, at 80x23: each axis
# keeps its scale over the run (no jump at a bounce), lines are thick
# (two Braille dot rows), slow motion shows a contact forming (the view
# zooms on it, the curve drawn only up to the cursor), and T again gives
# the light theme (black on white).  tmux: send-keys, poll capture-pane.
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
command -v perl >/dev/null || { echo "ok - # SKIP perl is not installed"; exit 0; }
if ! locale -a 2>/dev/null | grep -qi '^c\.utf-\?8$'; then
	echo "ok - # SKIP no C.UTF-8 locale for the Braille screen"
	exit 0
fi
# before the tmux server starts (common.inc): the explorer draws Braille
export LC_ALL=C.UTF-8
. "$(dirname "$0")/common.inc"

# margins SCREEN: the plots' tick labels and names (rows 3-17, columns 1-8)
margins() { sed -n '3,17p' "$1" | perl -CS -ne 'print substr($_, 0, 8), "\n"'; }

start a 80 23
wait_for a ' finished$' 150 || notok "the run finishes" a
# the follow view without presentation: its x_c scale is the window's own
keys a v
wait_for a 'follow the cursor' 30
keys a T
wait_for a 'presentation: contacts in slow motion' 30 || notok "T starts the presentation" a

# ---- held scales, a contact forming, thick lines ------------------------------
seen_flight=0 seen_contact=0 formed=0 zoomed=0 i=0
: >"$TMP/margins"
while [ "$i" -lt 400 ]; do
	screen a >"$TMP/s"
	st=$(head -n 1 "$TMP/s")
	j=$(echo "$st" | sed -n 's/.* j=\([0-9]*\) .*/\1/p')
	case $st in
	*" q_c=0 "*) seen_flight=1 ;;
	*" q_c=1 "*" slow "*)
		seen_contact=1
		# the t axis spans a few milliseconds: the view is on the contact
		span=$(sed -n 's/^t -> *//p' "$TMP/s" | tr -s ' ' '\n' | grep -E '^[0-9.]+$' | head -n 2 | tr '\n' ' ')
		set -- $span
		if [ $# = 2 ] && perl -e "exit !($2 - $1 <= 5)"; then zoomed=1; fi
		# nothing of the current run drawn right of the cursor on the F_c rows
		if perl -CS -ne '
			BEGIN { $cur = -1 }
			if ($. == 3) { $cur = index($_, ":") }
			if ($. >= 12 && $. <= 16 && $cur > 9) { $r = substr($_, $cur + 1); $bad = 1 if $r =~ /[\x{2801}-\x{28FF}]/ }
			END { exit($cur > 9 && !$bad ? 0 : 1) }' "$TMP/s"; then
			formed=1
		fi ;;
	esac
	margins "$TMP/s" | cksum >>"$TMP/margins"
	[ -n "$j" ] && [ "$j" -ge 2 ] && [ "$seen_contact" = 1 ] && break
	i=$((i + 1))
	sleep 0.05
done
# every frame's margins are the same
nframes=$(grep -c '' "$TMP/margins")
kinds=$(sort -u "$TMP/margins" | grep -c '')
if [ "$seen_flight" = 1 ] && [ "$seen_contact" = 1 ] && [ "$nframes" -ge 5 ] && [ "$kinds" = 1 ]; then
	ok "T: the axes hold their scales through flight and a contact ($nframes frames)"
else
	notok "T: the axes hold their scales through flight and a contact (flight $seen_flight, contact $seen_contact, $nframes frames, $kinds different margins)" a
fi
if [ "$zoomed" = 1 ] && [ "$formed" = 1 ]; then
	ok "T, slow motion: the view zooms on the contact and F_c is drawn only up to the cursor"
else
	notok "T, slow motion: the view zooms on the contact (zoomed $zoomed) and F_c forms at the cursor ($formed)" a
fi
if screen a | perl -CS -ne '$ok = 1 if /[\x{281B}\x{2836}\x{28E4}]{20}/; END { exit !$ok }'; then
	ok "T: lines are thick (rows of two-dot-high Braille)"
else
	notok "T: lines are thick (rows of two-dot-high Braille)" a
fi

# ---- the light theme ----------------------------------------------------------------
keys a T
if wait_for a 'presentation on the light theme' 30 \
   && $TM capture-pane -p -e -t a | grep -q "$(printf '\033')\\[30m$(printf '\033')\\[47m"; then
	ok "T again: the light theme, black on white"
else
	notok "T again: the light theme, black on white" a
fi
keys a T
if wait_for a 'presentation off' 30 && wait_for a 't_e\[ms\]' 30 \
   && ! $TM capture-pane -p -e -t a | grep -q "$(printf '\033')\\[47m"; then
	ok "T a third time: back to the explorer as it was, on the terminal's colours"
else
	notok "T a third time: back to the explorer as it was" a
fi
keys a q
wait_exit a 50
exit $failed
