#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The space-time view (V) in tmux at 80x24, in ASCII: on a Newton's cradle
# of five balls 10 mm apart it draws one line per body and marks each of
# the four contacts with # at its interface, from the top down, and shows
# the cursor's time (the status line's); f saves that view as a PNG
# figure (one panel: the bodies and the contacts); on a chain of 100 it thins the
# lines and says so, and still marks the contacts; V again gives the
# plots back; K shows x, x_c and F_c of one interface at a time (k= on
# the status line), then the run's own; B the position and velocity of one
# body at a time (b=); the key is in the help; quitting
# exits 0.
. "$(dirname "$0")/common.inc"
. "$(dirname "$0")/../chain.inc"
PY="$(pwd)/tests/cli/plot_png.py"

steel_chain cradle 5 '10 mm' '60 ms' >"$TMP/cradle.preset"

# rows of the view's canvas (below its title, above the t axis)
canvas() { screen "$1" | sed -n '/space-time: /,/^t ->/p' | sed '1d;$d' | cut -c10-; }

start a 80 24 --ascii cradle.preset
wait_for a ' finished$' 150
keys a space         # pause: the cursor stays where it is
# the collision table of a chain: the interface k after i, 4 down to 1
if wait_for a '^ +i +k +t_e\[ms\]' 30 && wait_for a '^ +0 +4 ' 10 && wait_for a '^ +3 +1 ' 10; then
	ok "the collision table gives each contact's interface k after i"
else
	notok "the collision table gives each contact's interface k after i" a
fi
keys a V
if wait_for a '^ +space-time: 5 bodies, # contact; t = [0-9.]+ [mu]?s$' 100 &&
   [ "$(canvas a | grep -c '\*')" -ge 5 ]; then
	ok "V: the space-time view of 5 bodies, one line each"
else
	notok "V: the space-time view of 5 bodies, one line each" a
fi
# the four contacts, each a # on its own row, lower as t goes on (the wave goes down)
rows=$(canvas a | awk '{ c = index($0, "#"); if (c) print NR, c }')
if [ "$(echo "$rows" | wc -l)" -eq 4 ] &&
   echo "$rows" | awk 'NR > 1 && ($1 <= r || $2 <= c) { bad = 1 } { r = $1; c = $2 } END { exit bad }'; then
	ok "four contacts marked #, each lower and later than the one before"
else
	notok "four contacts marked #, each lower and later than the one before ($rows)" a
fi
# the cursor's time: the status line's t
keys a End
if wait_for a '^ cradle hertz t=60 ms ' 30 && wait_for a '^ +space-time: .*; t = 60 ms$' 30; then
	ok "the title shows the cursor's time (End: 60 ms, as on the status line)"
else
	notok "the title shows the cursor's time (End: 60 ms, as on the status line)" a
fi
# f saves the space-time view shown: one panel, the bodies, the contacts, the cursor
keys a f
png=$TMP/cradle-view.png
if wait_for a '^wrote cradle-view\.png: the space-time view \(5 bodies, 4 contacts, the cursor\)' 100 \
   && [ -s "$png" ]; then
	python3 "$PY" info "$png" >"$TMP/st-info.txt"
	if grep -q '^panels 1$' "$TMP/st-info.txt" && [ "$(awk '$1 == "ink" { print $2 }' "$TMP/st-info.txt")" -gt 5000 ] \
	   && grep -q '^legend_style 0 ' "$TMP/st-info.txt" && grep -q '^legend_style 1 ' "$TMP/st-info.txt"; then
		ok "f saves the space-time view: one panel, the bodies' and the contacts' styles in the legend"
	else
		notok "f saves the space-time view: one panel, both styles in the legend"
		grep -v frame "$TMP/st-info.txt" | sed 's/^/#   /'
	fi
else
	notok "f saves the space-time view (the message, the file)" a
fi
keys a V
if wait_for a '^ +(whole run|follow the cursor)' 30 && wait_for a '^space-time view off' 30; then
	ok "V again: the plots"
else
	notok "V again: the plots" a
fi
# K: the plots of one interface, k= on the status line; after the last, the run's own again
keys a K
if wait_for a '^ cradle hertz k=1 t=' 30 && wait_for a '^ +interface 1 \(bodies 1 and 2\)$' 30 &&
   screen a | grep -q '^x\[mm\]' && screen a | grep -q '^F_c\[kN\]'; then
	ok "K: x, x_c and F_c of interface 1, k=1 on the status line"
else
	notok "K: x, x_c and F_c of interface 1, k=1 on the status line" a
fi
keys a K K K
if wait_for a '^ cradle hertz k=4 t=' 30 && wait_for a '^ +interface 4 \(bodies 4 and 5\)$' 30; then
	ok "K three times more: interface 4"
else
	notok "K three times more: interface 4" a
fi
keys a K
if wait_for a '^ cradle hertz t=' 30 && wait_for a '^ +(whole run|follow the cursor)' 30; then
	ok "K after the last interface: the run's own plots, no k="
else
	notok "K after the last interface: the run's own plots, no k=" a
fi
# B: the position y and velocity u of one body, b= on the status line; body 1
# (the lowest) rests until the wave reaches it and leaves at -1 m/s, the
# striker (body 5) falls at -1 m/s and stops; after the last, the run's own
keys a B
if wait_for a '^ cradle hertz b=1 t=' 30 && wait_for a '^ +body 1 of 5 \(the lowest\): position y and velocity u$' 30 \
   && screen a | grep -q '^y\[mm\]' && screen a | grep -q '^u\[m/s\]' && screen a | grep -q '^ *-1\.0 '; then
	ok "B: y and u of body 1, b=1 on the status line"
else
	notok "B: y and u of body 1, b=1 on the status line" a
fi
# body 1's u: 0 on the left of the u panel, -1 m/s on its right (it leaves last)
u_rows() { screen a | sed -n '/^ *0\.0 /,/^ *-1\.0 /p'; }
if [ "$(u_rows | head -n 1 | cut -c10-20 | tr -cd '*' | wc -c)" -ge 5 ] \
   && [ "$(u_rows | tail -n 1 | rev | cut -c1-10 | tr -cd '*' | wc -c)" -ge 5 ]; then
	ok "body 1 rests, then leaves at -1 m/s"
else
	notok "body 1 rests, then leaves at -1 m/s" a
fi
keys a B ; keys a B ; keys a B ; keys a B
if wait_for a '^ cradle hertz b=5 t=' 30 && wait_for a '^ +body 5 of 5 \(the top one\)' 30 \
   && [ "$(u_rows | tail -n 1 | cut -c10-20 | tr -cd '*' | wc -c)" -ge 5 ]; then
	ok "B four times more: body 5, the striker, at -1 m/s first"
else
	notok "B four times more: body 5, the striker, at -1 m/s first" a
fi
keys a K
if wait_for a '^ cradle hertz k=1 t=' 30 && wait_for a '^ +interface 1 \(bodies 1 and 2\)$' 30; then
	ok "K after B: an interface instead of the body"
else
	notok "K after B: an interface instead of the body" a
fi
keys a B ; keys a B ; keys a B ; keys a B ; keys a B ; keys a B
if wait_for a '^ cradle hertz t=' 30 && wait_for a '^ +(whole run|follow the cursor)' 30; then
	ok "B after the last body: the run's own plots, no b="
else
	notok "B after the last body: the run's own plots, no b=" a
fi
keys a '?'
wait_for a 'hybounce keys' 30
n=0
while [ $n -lt 10 ] && ! screen a | grep -q 'V  *space-time view on / off'; do
	keys a PgDn
	n=$((n + 1))
	wait_for a 'hybounce keys' 30
done
if screen a | grep -q 'V  *space-time view on / off' && screen a | grep -q "K  *a chain's next interface" \
   && screen a | grep -q "B  *the next body for the plots"; then
	ok "the help lists V, K and B"
else
	notok "the help lists V, K and B" a
fi
keys a q
keys a q
if wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ]; then
	ok "quit exits 0"
else
	notok "quit exits 0" a
fi

# a chain of 100: thinned lines, said in the title, and the 99 contacts marked
start b 80 24 --ascii cradle.preset --set chain.n=100 --set chain.spacing=1mm --set run.T=120ms
wait_for b ' finished$' 150
keys b V
if wait_for b '^ +space-time: 100 bodies \(every [0-9]+(st|nd|rd|th) drawn\), # contact; t = ' 150 &&
   [ "$(canvas b | grep -c '#')" -ge 5 ]; then
	ok "100 bodies: every m-th drawn, said in the title; the contacts marked"
else
	notok "100 bodies: every m-th drawn, said in the title; the contacts marked" b
fi
keys b q
if wait_exit b 50 && [ "$(cat "$TMP/b.rc")" = 0 ]; then
	ok "quit exits 0 (100 bodies)"
else
	notok "quit exits 0 (100 bodies)" b
fi
exit $((failed > 0))
