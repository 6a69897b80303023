#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The sweep view's 2-D map in tmux at 80x24, in ASCII: S sweeps the damping
# c, then S on v0 sweeps v0; m maps e over v0 (across) and c (up), row by
# row in the background; the legend gives each shade's range; e exports
# the grid (i1,i2,KEY1,KEY2,OBS, one row per point) and a second export
# keeps the first; the shades' range is the first row's and stays (the
# legend counts later values outside it; r takes all values); X marks the
# current scene and 1 a pinned run's; m goes back to the curve; with b on,
# the map marks its rows' boundaries |; quitting exits 0.
. "$(dirname "$0")/common.inc"

start a 80 24 --ascii
wait_for a ' finished$' 150
# the first key: c, over 3 values
keys a / ; keys a -l law.c ; keys a Enter
wait_for a 'nudge\) law\.c:' 30
keys a S
wait_for a '^sweep law\.c over FROM:TO:N' 30
keys a C-u ; keys a -l "2000:8000:3" ; keys a Enter
wait_for a '^sweep: e of collision 0 against law\.c = 2000:8000:3 +3/3 done$' 300
keys a m
if wait_for a '^map not started: a map needs a second key' 30; then
	ok "m with one key swept says how to choose the second"
else
	notok "m with one key swept says how to choose the second" a
fi
# the second key: v0, chosen as the first was
keys a q
wait_gone a '^sweep: e of' 30
keys a / ; keys a -l v0 ; keys a Enter
wait_for a 'nudge\) initial\.v0:' 30
keys a S
wait_for a '^sweep initial\.v0 over FROM:TO:N' 30
keys a C-u ; keys a -l -- "-0.2 m/s:-1 m/s:4" ; keys a Enter
wait_for a '^sweep: e of collision 0 against initial\.v0 = .* 4/4 done$' 300
keys a m
if wait_for a '^map: e of collision 0 over initial\.v0 \(across\) and law\.c \(up\) +12/12 done$' 300 \
   && screen a | grep -q ' legend: e *$' \
   && [ "$(screen a | grep -Ec ' [.:=+*#@-] [-0-9.e+]+\.\.[-0-9.e+]+ *$')" -eq 8 ] \
   && screen a | grep -q '? no such value'; then
	ok "m maps e over v0 and c; the legend gives each shade's range"
else
	notok "m maps e over v0 and c with its legend" a
fi
# the map's cells: shades of the ASCII ramp, nothing left blank once done
if [ "$(screen a | sed -n '3,20p' | cut -c11-50 | grep -c '[.:=+*#@-]\{30\}')" -ge 10 ]; then
	ok "the map's cells are drawn in ASCII shades"
else
	notok "the map's cells are drawn in ASCII shades" a
fi
keys a e
wait_for a '^export the map as CSV to: steel-on-bitumen-initial\.v0-law\.c-e\.csv_$' 30
keys a Enter
f="$TMP/steel-on-bitumen-initial.v0-law.c-e.csv"
if wait_for a '^wrote steel-on-bitumen-initial\.v0-law\.c-e\.csv \(12 of 4 x 3 points\)' 30 \
   && [ "$(head -1 "$f")" = "i1,i2,initial.v0,law.c,e" ] \
   && [ "$(wc -l < "$f")" -eq 13 ] \
   && sed -n 2p "$f" | grep -q '^0,0,-0\.2[0-9]*,2000,' \
   && sed -n 13p "$f" | grep -q '^3,2,-1,8000,'; then
	ok "e exports the map as CSV: i1,i2,KEY1,KEY2,OBS, one row per grid point"
else
	notok "e exports the map as CSV" a
	sed 's/^/# /' "$f"
fi
cp "$f" "$TMP/first.csv"
keys a e
wait_for a '^export the map as CSV to: ' 30
keys a Enter
if wait_for a '^wrote steel-on-bitumen-initial\.v0-law\.c-e-2\.csv \(12 of 4 x 3 points' 30 \
   && cmp -s "$f" "$TMP/first.csv"; then
	ok "a second export keeps the first (NAME-2.csv)"
else
	notok "a second export keeps the first" a
fi
# the current scene on the map: v0 = 0 is off it; after v0 = -0.5 m/s it is
# the X on the cell of v0 = -0.467 m/s (across) and c = 5000 (up)
if screen a | grep -q 'X scene: off the map' && [ "$(screen a | sed -n '3,22p' | cut -c11-55 | grep -c X)" -eq 0 ]; then
	ok "the map says when the current scene is off it"
else
	notok "the map says when the current scene is off it" a
fi
keys a q
wait_gone a '^map: ' 30
keys a Enter ; keys a C-u ; keys a -l -- "-0.5 m/s" ; keys a Enter
wait_for a ' finished$' 150
keys a S
if wait_for a 'X the current scene' 30 \
   && [ "$(screen a | sed -n '3,22p' | cut -c11-55 | grep -c X)" -eq 1 ] \
   && screen a | sed -n '3,22p' | cut -c11-55 | grep -q '^[^X]\{11,22\}X'; then
	ok "the current scene is marked X on the map"
else
	notok "the current scene is marked X on the map" a
fi
# the shades' range is the first row's (c = 2000), fixed: the legend's ends
# are row 0's least and greatest e, and it counts the later values outside
lo=$(awk -F, '$2 == 0 && $5 != "" && $5 == $5 + 0 { print $5 }' "$TMP/first.csv" | sort -g | head -n 1)
hi=$(awk -F, '$2 == 0 && $5 != "" && $5 == $5 + 0 { print $5 }' "$TMP/first.csv" | sort -g | tail -n 1)
out=$(awk -F, -v lo="$lo" -v hi="$hi" 'NR > 1 && $2 > 0 && $5 != "" && $5 == $5 + 0 && ($5 < lo + 0 || $5 > hi + 0) { n++ } END { print n + 0 }' "$TMP/first.csv")
glo=$(awk -v x="$lo" 'BEGIN { printf "%.3g", x }')
ghi=$(awk -v x="$hi" 'BEGIN { printf "%.3g", x }')
if [ -n "$lo" ] && screen a | grep -q '(range of the first row)' \
   && screen a | grep -Fq "@ " && screen a | grep -F "@ " | grep -Fq "..$ghi" \
   && screen a | grep -F ". $glo.." >/dev/null \
   && if [ "$out" -eq 0 ]; then ! screen a | grep -q 'the range: r\|above: r'; \
      else screen a | grep -q "$out \(above\|below\) the range: r"; fi; then
	ok "the shades' range is the first row's ($glo..$ghi), $out later values outside it counted"
else
	notok "the shades' range is the first row's ($glo..$ghi; $out outside)" a
fi
keys a r
if wait_for a '^map: the shades. range is now ' 30 && wait_for a '\(range: r\)' 10; then
	ok "r fixes the shades' range anew, to the values computed"
else
	notok "r fixes the shades' range anew" a
fi
# a pinned run's scene is marked with its number, as X the current one:
# pin v0 = -0.5 m/s, then v0 = -0.9 m/s
mapcells() { sed -n '3,22p' | grep -v -- '->' | cut -c11-55; }
keys a q
wait_gone a '^map: ' 30
keys a p
wait_for a '^pinned' 30
keys a Enter ; keys a C-u ; keys a -l -- "-0.9 m/s" ; keys a Enter
wait_for a ' finished$' 150
keys a S
if wait_for a '1 the pinned run' 30 && wait_for a 'X the current scene' 10 \
   && [ "$(screen a | mapcells | grep -c 1)" -eq 1 ] \
   && [ "$(screen a | mapcells | grep -c X)" -eq 1 ] \
   && [ "$(screen a | mapcells | grep -n 1 | cut -d: -f1)" = \
        "$(screen a | mapcells | grep -n X | cut -d: -f1)" ] \
   && screen a | mapcells | grep -q '1.*X'; then
	ok "the pinned run's scene is marked 1 on the map, left of the current X on the same c"
else
	notok "the pinned run's scene is marked 1 on the map" a
fi
keys a m
if wait_for a '^sweep: e of collision 0 against initial\.v0' 30; then
	ok "m goes back to the curve"
else
	notok "m goes back to the curve" a
fi
# boundaries (b on the curve): the map's rows locate theirs and mark them |,
# as the curve view does; on the collision count they lie between v0's points
keys a o ; keys a o ; keys a o
wait_for a '^sweep: collisions against initial\.v0' 30 || notok "o to the collisions" a
keys a b
wait_for a '^sweep: collisions against initial\.v0 .* 4/4 done, [0-9]+ boundar' 300 || notok "b locates the curve's boundaries" a
keys a m
if wait_for a '^map: collisions over initial\.v0 \(across\) and law\.c \(up\) +12/12 done$' 300 \
   && wait_for a '\| boundary, : bisecting$' 10 \
   && [ "$(screen a | mapcells | grep -c '|')" -ge 1 ]; then
	ok "with b on, the map marks each row's boundaries |"
else
	notok "with b on, the map marks each row's boundaries |" a
fi
keys a F10
if wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ]; then
	ok "F10 leaves the explorer with the map, exit 0"
else
	notok "F10 leaves the explorer with the map, exit 0" a
fi
exit $((failed > 0))
