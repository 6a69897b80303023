#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Comparing runs in tmux at 80x23: a pinned run is labelled by what differs
# from the current one, told apart by colour and by marker (in Braille too),
# and c puts the differences of each collision in the table.  The readout
# line shows the sample at the cursor whole.  send-keys, then poll
# capture-pane.  Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS (tests/run.sh).
. "$(dirname "$0")/common.inc"

# ---- pin, edit, legend -----------------------------------------------------------
start a 80 23
wait_for a ' finished$' 150
keys a p
if wait_for a 'pinned run 1' 30 && edit a law.c 44000 && wait_for a ' finished$' 100 \
   && wait_for a '\.1 c = 4400 N s/m +\* now c = 4\.4e\+04 N s/m' 30; then
	ok "pin then edit: the legend labels each run by what differs (c = 4400 against c = 4.4e+04)"
else
	notok "pin then edit: the legend labels each run by what differs" a
fi
# Braille plots: the pinned run's marker '.' sits on its curve among the dots
if screen a | sed -n '3,14p' | grep -q '⣀' && screen a | sed -n '3,14p' | cut -c12- | grep -q '\.'; then
	ok "Braille plots carry the pinned run's marker"
else
	notok "Braille plots carry the pinned run's marker" a
fi
keys a p
wait_for a 'pinned run 2' 30
keys a p
wait_for a 'pinned run 3' 30
keys a p
if wait_for a 'at most 3 pinned runs; P clears them' 30; then
	ok "up to three pinned runs"
else
	notok "up to three pinned runs" a
fi

# ---- the table's differences -------------------------------------------------------
keys a c
if wait_for a 'differences of each collision against pinned run 1' 30 \
   && wait_for a 'dt_e\[[a-z]*s\] .* de .*dx_c\^max\[[a-z]*m\]' 30 && wait_for a 'F_c\^max\[[a-zA-Z]*N\]  vs 1$' 10 \
   && screen a | grep -Eq '^ +>?1 +[0-9.]+ +-?[0-9.e+-]+ +[0-9.]+ +-?[0-9.e+-]+ '; then
	ok "c: the table shows dt_e, de and dx_c^max against pinned run 1"
else
	notok "c: the table shows the differences against pinned run 1" a
fi
# alpha moves e by a few per cent: de fills its column, and must not run into e
keys a P
wait_for a 'pinned runs cleared' 30
keys a p
wait_for a 'pinned run 1' 30
edit a law.alpha 0.5
wait_for a ' finished$' 100
for i in 1 2 3 4; do
	screen a | grep -q ' dt_e\[.*vs 1$' && break
	keys a c
	wait_for a 'table: ' 30
done
hdr=$(screen a | grep ' dt_e\[.*vs 1$' | awk '{print NF}')
bad=$(screen a | grep -E '^ +>?[0-9]+ +[0-9]' | awk -v h="$hdr" 'NF != h - 2 {print}')
if [ -n "$hdr" ] && [ -z "$bad" ]; then
	ok "c: every row of the differences has its $((hdr - 2)) cells apart (de filling its column)"
else
	notok "c: a row's cells run together ($bad)" a
fi
keys a c c c
if wait_for a 'table: the current run only' 30 && wait_for a 'Lambda' 10; then
	ok "c cycles through the pinned runs and back to the plain table"
else
	notok "c cycles back to the plain table" a
fi
keys a P
wait_for a 'pinned runs cleared' 30

# ---- the readout: step sample by sample --------------------------------------------
keys a Home
wait_for a '^#0 t=0 s j=0 q_c=0 x=20 mm v=0 m/s' 30
keys a '}'
wait_for a ' j=1 q_c=1 ' 30
r1=$(screen a | grep -A1 '^#[0-9]' | tr '\n' ' ')
keys a .
wait_gone a "^$(echo "$r1" | cut -d' ' -f1-3) " 30
r2=$(screen a | grep -A1 '^#[0-9]' | tr '\n' ' ')
n1=$(echo "$r1" | sed 's/^#\([0-9]*\) .*/\1/'); n2=$(echo "$r2" | sed 's/^#\([0-9]*\) .*/\1/')
t1=$(echo "$r1" | sed 's/.* t=\([^ ]*\) .*/\1/'); t2=$(echo "$r2" | sed 's/.* t=\([^ ]*\) .*/\1/')
if [ "$n2" = $((n1 + 1)) ] && [ "$t1" != "$t2" ] \
   && echo "$r2" | grep -Eq '^#[0-9]+ t=[0-9.]+ ms j=1 q_c=1 x=-?[0-9.]+ [a-z]*m v=-?[0-9.]+ [a-z]*m/s +x_c=-?[0-9.]+ [a-z]*m F_c=-?[0-9.]+ [a-zA-Z]*N z_c1=[-0-9.e]+ z_c2=[-0-9.e]+' ; then
	ok "readout: sample $n1 -> $n2, t $t1 -> $t2 ms told apart, with x, v, x_c, F_c, z_c and units"
else
	notok "readout while stepping ($r1 / $r2)" a
fi
keys a q
wait_exit a 50

# ---- ASCII plots: each run its glyph ---------------------------------------------------
start b 80 24 --ascii
wait_for b ' finished$' 150
keys b p
wait_for b 'pinned run 1' 30
edit b law.c 44000
if wait_for b '\.1 c = 4400 N s/m +\* now' 50 && wait_for b ' finished$' 100 \
   && screen b | sed -n '3,14p' | cut -c12- | grep -q '\.' && screen b | sed -n '3,14p' | cut -c12- | grep -q '\*'; then
	ok "--ascii: the pinned run drawn with '.', the current one with '*', as the legend says"
else
	notok "--ascii: pinned and current runs told apart by glyph" b
fi
keys b q
wait_exit b 50
exit $((failed > 0))
