#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A recording in the explorer, in tmux at 110x34: --data with a FLAC file
# (and D with the same take as WAV) reads it by content through the one
# loader; a strip under the plots shows its envelope on the plots' t axis
# with the impacts kept (o), the clicks dropped (x) and the run's own
# impacts (+); M lists the dropped clicks with their reason; F fits the
# impacts of the recording and the run's impacts move onto them.  The take
# is made here as tests/cli/onsets.sh makes its takes (onsets_rec.py: damped
# modes, loudness from the speed, pink noise 30 dB down, a handling knock),
# from a run whose law.c and law.alpha are known.  send-keys, then poll
# capture-pane.  Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS (tests/run.sh).
. "$(dirname "$0")/common.inc"
ROOT=$(pwd)
PY=/usr/bin/python3

if ! command -v sox >/dev/null 2>&1 || ! $PY -c 'import numpy' 2>/dev/null; then
	notok "sox and python3-numpy are installed (make deps installs them)"
	exit 1
fi
"$BIN" --batch steel-on-bitumen --set law.c=4400 --set law.alpha=0.35 --collisions - \
	2>/dev/null >"$TMP/col.csv"
$PY "$ROOT/tests/cli/onsets_rec.py" "$TMP/take.f32" "$TMP/take.truth" snr=30 knock=0.1 seed=2 \
	<"$TMP/col.csv"
sox -R -t f32 -r 44100 -c 1 "$TMP/take.f32" -b 16 "$TMP/take.flac" 2>/dev/null
sox -R -t f32 -r 44100 -c 1 "$TMP/take.f32" -b 16 "$TMP/take.wav" 2>/dev/null
# the impacts fit finds in the take: the reference for what the strip shows
(cd "$TMP" && "$BIN" fit steel-on-bitumen --data take.flac --free law.c --onsets-out on.csv \
	>/dev/null 2>&1)
nimp=$(($(grep -cv '^[#t]' "$TMP/on.csv") + 0))
if [ -s "$TMP/take.flac" ] && [ -s "$TMP/take.wav" ] && [ "$nimp" -ge 5 ]; then
	ok "a take made with $nimp impacts the onset detector keeps (FLAC and WAV)"
else
	notok "a take made with its impacts ($nimp)"
fi

# strip SESSION: the rows of the recording's strip (the rec row, two above it, down to the
# contact row): the row with the most o (its top row), the one with the most + and its base
strip() {
	screen "$1" | awk '/^rec/ { r = NR } /^contact/ { c = NR } { l[NR] = substr($0, 10) }
		function n(s, ch) { return gsub(ch, "", s) }
		END { for (i = r - 2; i < c; i++) {
		          if (n(l[i], "o") > bo) { bo = n(l[i], "o"); top = i }
		          if (n(l[i], "[+]") > bp) { bp = n(l[i], "[+]"); mid = i } }
		      print l[top]; print l[mid]; print l[c - 1] }'
}
# count CHAR TEXT: how many CHAR in TEXT (a strip row, past the margin)
count() { printf '%s\n' "$2" | tr -cd "$1" | wc -c; }

start a 110 34 --ascii --data "'$TMP/take.flac'" --set law.c=2000 steel-on-bitumen
if wait_for a ' finished$' 150 && wait_for a '^rec' 30; then
	ok "--data take.flac: a strip named rec under the plots"
else
	notok "--data take.flac: a strip named rec under the plots" a
fi
s=$(strip a)
top=$(printf '%s\n' "$s" | sed -n 1p)
mid=$(printf '%s\n' "$s" | sed -n 2p)
bot=$(printf '%s\n' "$s" | sed -n 3p)
if [ "$(count o "$top")" -eq "$nimp" ] && [ "$(count x "$top")" -ge 1 ]; then
	ok "the strip marks the $nimp impacts kept (o) and the clicks dropped (x) on its top row"
else
	notok "the strip marks the $nimp impacts kept (o, $(count o "$top") shown) and the dropped clicks (x)" a
fi
ncoll=$(screen a | head -n 1 | sed -n 's/.* coll \([0-9]*\) .*/\1/p')
if [ "$(count + "$mid")" -ge "${ncoll:-99}" ] && [ "$(count '*' "$bot")" -ge 20 ]; then
	ok "the strip shows the run's impacts (+) and the envelope ($(count '*' "$bot") columns inked on its base)"
else
	notok "the strip shows the run's impacts (+) and the envelope" a
fi
keys a m
if wait_for a 'messages, oldest first' 30 \
   && screen a | sed 's/│//g' | tr -d '\n' | tr -s ' ' | grep -q "take\.flac: a recording (44100 Hz, [0-9.]* ms), $nimp impacts (o) of [0-9]* clicks"; then
	ok "the message says a recording was read: its rate, length and impacts"
else
	notok "the message says a recording was read" a
fi
keys a Escape
wait_gone a 'messages, oldest first' 30
keys a M
if wait_for a 'measured against simulated \(M\)' 30 && wait_for a 'dropped \(x\) at .* of the recording: ' 30; then
	ok "M: the dropped clicks are listed with their reason"
else
	notok "M: the dropped clicks are listed with their reason" a
fi
keys a Escape
wait_gone a 'measured against simulated \(M\)' 30
# the run's impacts against the recording's before the fit: the table's sim - data of row 1
keys a F
wait_for a 'free keys .*: law\.c,law\.alpha' 30
keys a Enter
if wait_for a '^fit converged' 300; then
	ok "F fits law.c and law.alpha to the recording's impacts"
else
	notok "F fits law.c and law.alpha to the recording's impacts" a
fi
wait_for a ' finished$' 100
# after the fit every + of the first impacts stands in the column of its o (within one)
s=$(strip a)
top=$(printf '%s\n' "$s" | sed -n 1p)
mid=$(printf '%s\n' "$s" | sed -n 2p)
if printf '%s\n%s\n' "$top" "$mid" | awk -v n="$nimp" '
	NR == 1 { for (i = 1; i <= length($0); i++) if (substr($0, i, 1) == "o") o[++no] = i }
	NR == 2 { for (i = 1; i <= length($0); i++) if (substr($0, i, 1) == "+") p[++np] = i }
	END { if (no != n) exit 1
	      for (k = 1; k <= no; k++) { hit = 0
	          for (m = 1; m <= np; m++) if (p[m] - o[k] <= 1 && o[k] - p[m] <= 1) hit = 1
	          if (!hit) exit 1 }
	      exit 0 }'; then
	ok "after the fit each impact of the recording (o) has the run's impact (+) in its column"
else
	notok "after the fit the run's impacts (+) stand under the recording's (o)" a
fi
# D opens the WAV of the same take through the prompt
keys a D
wait_for a '^data file' 30
keys a C-u
keys a -l "$TMP/take.wav"
keys a Enter
if wait_for a "take\\.wav: a recording \\(44100 Hz" 50 && wait_for a '^rec' 30; then
	ok "D opens a WAV recording and shows its strip"
else
	notok "D opens a WAV recording and shows its strip" a
fi
keys a q
wait_exit a 50 || notok "q quits" a
exit $((failed > 0))
