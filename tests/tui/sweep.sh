#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer's sweep view in tmux at 80x24: S on the selected parameter
# proposes a range, the curve fills in from background threads with the
# current scene marked on it, the observable and the law change, a curve
# is pinned, the curve is exported as CSV, a bad range is refused keeping
# the curve, b locates a boundary of the curve, a parameter that is not a number is refused, and quitting
# during a long sweep cancels it at once.
. "$(dirname "$0")/common.inc"

start a 80 24 --ascii
wait_for a ' finished$' 150
keys a / ; keys a -l v0 ; keys a Enter
if wait_for a 'nudge\) initial\.v0:' 30 && keys a S \
   && wait_for a '^sweep initial\.v0 over FROM:TO:N\[:log\] or V1,V2,\.\.\.: .*m/s:.*:41_$' 30; then
	ok "S proposes a range for the selected parameter"
else
	notok "S proposes a range for the selected parameter" a
fi
keys a C-u ; keys a -l -- "-0.2 m/s:-1 m/s:9" ; keys a Enter
if wait_for a '^sweep: e of collision 0 against initial\.v0 = -0\.2 m/s:-1 m/s:9 +9/9 done$' 300 \
   && screen a | grep -q '^\* now bwmcl  @ scene: v0 = 0 m/s, e = 0\.59' \
   && screen a | grep -q '^v0 -> ' && [ "$(screen a | grep -c '\*')" -ge 5 ]; then
	ok "the curve of e against v0 fills in, the legend gives the current scene's value"
else
	notok "the curve of e against v0 fills in" a
fi
# the current scene on the curve: v0 = -0.5 m/s lies inside the range
keys a q
wait_gone a '^sweep: e of' 30
keys a Enter ; keys a C-u ; keys a -l -- "-0.5 m/s" ; keys a Enter
wait_for a ' finished$' 150
keys a S
if wait_for a '@ scene: v0 = -500 mm/s, e = 0\.5' 50 && screen a | grep -q '^ .*@' \
   && screen a | grep -q '9/9 done'; then
	ok "S reopens the curve; the current scene is marked @ on it"
else
	notok "the current scene is marked @ on the curve" a
fi
keys a o
if wait_for a '^sweep: v_i of collision 0 against initial\.v0 .* 9/9 done$' 300 \
   && screen a | grep -q '^v_i\[m*m/s\]'; then
	ok "o: the next observable (v_i of collision 0)"
else
	notok "o: the next observable" a
fi
keys a O
wait_for a '^sweep: e of collision 0 .* 9/9 done$' 300
keys a p
if wait_for a '^pinned bwmcl as 1' 30 && keys a L \
   && wait_for a '^sweep: e of collision 0 .* 9/9 done$' 300 \
   && screen a | grep -q '^\.1 bwmcl (9/9)  \* now hertz'; then
	ok "p pins the curve, L computes another law next to it"
else
	notok "p pins the curve, L computes another law next to it" a
fi
keys a r ; keys a C-u ; keys a -l "fast" ; keys a Enter
if wait_for a '^sweep not started: .*initial\.v0' 30 && screen a | grep -q '9/9 done'; then
	ok "a bad range is refused with a message; the curve is kept"
else
	notok "a bad range is refused; the curve is kept" a
fi
keys a e
wait_for a '^export the curve as CSV to: steel-on-bitumen-initial\.v0-e\.csv_$' 30
keys a Enter
if wait_for a '^wrote steel-on-bitumen-initial\.v0-e\.csv \(9 of 9 points\)' 30 \
   && [ "$(head -1 "$TMP/steel-on-bitumen-initial.v0-e.csv")" = "initial.v0,i,e" ] \
   && [ "$(wc -l < "$TMP/steel-on-bitumen-initial.v0-e.csv")" -eq 10 ] \
   && sed -n 2p "$TMP/steel-on-bitumen-initial.v0-e.csv" | grep -q '^-0\.2,0,1$\|^-0\.20*[0-9]*,0,0\.99'; then
	ok "e exports the curve as CSV (header, one row per point)"
else
	notok "e exports the curve as CSV" a
	head -3 "$TMP/steel-on-bitumen-initial.v0-e.csv" | sed 's/^/# /'
fi
# a second export to the same name keeps the first: NAME-2.csv, said so
cp "$TMP/steel-on-bitumen-initial.v0-e.csv" "$TMP/first.csv"
keys a e
wait_for a '^export the curve as CSV to: steel-on-bitumen-initial\.v0-e\.csv_$' 30
keys a Enter
if wait_for a '^wrote steel-on-bitumen-initial\.v0-e-2\.csv \(9 of 9 points\); steel-on' 30 \
   && cmp -s "$TMP/first.csv" "$TMP/steel-on-bitumen-initial.v0-e.csv" \
   && [ -s "$TMP/steel-on-bitumen-initial.v0-e-2.csv" ]; then
	ok "a second curve export keeps the first and writes NAME-2.csv, saying so"
else
	notok "a second curve export keeps the first and writes NAME-2.csv, saying so" a
fi
# a range of 10^9 points is refused at once, the explorer stays responsive
keys a r ; keys a C-u ; keys a -l -- "-1 mm/s:-10 m/s:1000000000:log" ; keys a Enter
if wait_for a '^sweep not started: --vary initial\.v0=-1 mm/s:-10 m/s:1000000000:log' 30 \
   && wait_for a '^sweep: e of collision 0 against initial\.v0 = -0\.2 m/s:-1 m/s:9 +9/9 done$' 30; then
	ok "a range of 10^9 points is refused at once, the curve kept"
else
	notok "a range of 10^9 points is refused at once, the curve kept" a
fi
# the view's own keys: its footer and ? (the help, at its list) from its key table
if screen a | tail -n 1 | grep -q '^o:obs <>:collision r:range L:law b:bounds p:pin m:map e:export q:close ?:keys'; then
	ok "the sweep view's footer lists its keys"
else
	notok "the sweep view's footer lists its keys" a
fi
keys a '?'
if wait_for a 'hybounce keys' 30 && wait_for a 'In the sweep view \(S\):' 10 \
   && wait_for a ' o {5,}the next observable' 10 && wait_for a ' > \. {5,}the next collision i' 10; then
	ok "? in the sweep view: the help, at the view's keys"
else
	notok "? in the sweep view: the help, at the view's keys" a
fi
keys a x
if wait_gone a 'hybounce keys' 30 && wait_for a '^sweep: e of collision 0 ' 10; then
	ok "any other key closes the help, back in the sweep view"
else
	notok "any other key closes the help, back in the sweep view" a
fi
keys a q
wait_gone a '^sweep: e of' 30
keys a / ; keys a -l scene.law ; keys a Enter
wait_for a 'nudge\) scene\.law:' 30
keys a S
if wait_for a '^sweep: scene\.law is not a number' 30; then
	ok "a parameter that is not a number is refused"
else
	notok "a parameter that is not a number is refused" a
fi
# b: the boundaries of the curve, bisected to 1e-3 of the range: the
# restitution example's e of collision 0 exists from -3.72 mm/s on (hybounce
# sweep --refine e_first puts it between -3.7113 and -3.7314 mm/s)
cp examples/sweeps/restitution-shccl.preset "$TMP/"
start b 80 24 --ascii restitution-shccl.preset
wait_for b ' finished$' 150
keys b / ; keys b -l v0 ; keys b Enter
wait_for b 'nudge\) initial\.v0:' 30
keys b S
wait_for b '^sweep initial\.v0 over' 30
keys b C-u ; keys b -l -- "-1mm/s:-1m/s:21:log" ; keys b Enter
wait_for b '^sweep: e of collision 0 .* 21/21 done' 300
keys b b
if wait_for b '@ scene: .*  \| -3\.721 mm/s$' 300 \
   && [ "$(screen b | grep -c '^ .*|')" -ge 15 ]; then
	ok "b locates the curve's boundary (| at -3.721 mm/s, where --refine puts it)"
else
	notok "b locates the curve's boundary" b
fi
keys b b
if wait_for b '^boundaries off' 30 && ! screen b | grep -q 'boundary'; then
	ok "b again: boundaries off"
else
	notok "b again: boundaries off" b
fi
keys b F10
wait_exit b 50
# a long sweep: quitting cancels the workers at once
keys a / ; keys a -l v0 ; keys a Enter
wait_for a 'nudge\) initial\.v0:' 30
keys a S
wait_for a '^sweep: e of' 30
keys a r ; keys a C-u ; keys a -l -- "-1 mm/s:-10 m/s:400:log" ; keys a Enter
wait_for a '^sweep: e of collision 0 .*/400 done, computing$' 100
keys a F10
if wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ]; then
	ok "quitting during a long sweep cancels it and exits 0"
else
	notok "quitting during a long sweep cancels it" a
fi
exit $((failed > 0))
