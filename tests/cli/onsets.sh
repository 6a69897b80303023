#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce fit on recordings made here, where the truth is known
# (tests/cli/onsets_rec.py: each impact a few damped modes, its loudness from
# its speed; pink noise, reverberation, handling knocks, a noise blip,
# 48 kHz stereo, a long ring, silence before and after; clicks 3 ms or more
# apart; WAV of several sample formats, FLAC, Ogg Vorbis, MP3, and a FLAC
# named without extension): the onset times of every click at
# 20 dB SNR or better (its peak over the rms of the noise and of the ring
# of the clicks before) lie within 0.1 ms of the truth and no impact is
# invented (each within 2 ms of a true one); each recording is either
# fitted within 3 standard errors of the truth with a relative standard
# error under 10%, or refused with exit 2,
# never answered wrong with exit 0; what is dropped is listed with its
# reason; --onsets-out writes the t_e CSV that --data reads and fits; a
# recording is known by its content (a .wav holding text is refused, a WAV
# through a pipe is named); FFmpeg's log stays off stderr; an estimate
# above --max-relative-se exits 1.  The table of verdicts and the two
# examples after it are README's (between ONSETS-TABLE markers);
#
#     sh tests/cli/onsets.sh --update-readme   rewrites it
. "$(dirname "$0")/common.inc"
ROOT=$(pwd)
PY=/usr/bin/python3
C_TRUE=4400 A_TRUE=0.35

if ! command -v sox >/dev/null 2>&1 || ! $PY -c 'import numpy' 2>/dev/null; then
	notok "sox and python3-numpy are installed (make deps installs them)"
	exit 1
fi
"$BIN" --batch steel-on-bitumen --set law.c=$C_TRUE --set law.alpha=$A_TRUE \
	--collisions - 2>/dev/null >"$T/col.csv"

# estimates FILE: "KEY VALUE" for each estimate of a fit's report
estimates() {
	awk '/^estimates/ { on = 1 } /^correlation/ { on = 0 }
		on && $1 ~ /^law\./ { print $1, $3 }' "$1"
}

# rec NAME DESCRIPTION SOX-OUTPUT-OPTIONS -- GENERATOR-KEYS...: makes $T/NAME.*
rec() {
	name=$1 desc=$2 sr=44100 ch=1
	shift 2
	fmt=
	while [ "$1" != -- ]; do fmt="$fmt $1"; shift; done
	shift
	for kv in "$@"; do
		case $kv in sr=*) sr=${kv#sr=} ;; ch=*) ch=${kv#ch=} ;; esac
	done
	$PY "$ROOT/tests/cli/onsets_rec.py" "$T/$name.f32" "$T/$name.truth" "$@" <"$T/col.csv"
	# shellcheck disable=SC2086
	sox -R -t f32 -r "$sr" -c "$ch" "$T/$name.f32" $fmt "$T/$name.wav" 2>/dev/null
	echo "$name|$desc|$name.wav|$name|0" >>"$T/list"
}

# enc NAME DESCRIPTION FROM FILE [ALIGN]: FROM's recording encoded by sox as
# FILE (its format from its extension, then renamed to FILE without one
# where FILE has none); ALIGN 1: the codec delays the sound (MP3's encoder
# delay), so the onsets are compared after aligning the first
enc() {
	out=$2
	case $4 in *.*) sox -R "$T/$3.wav" "$T/$4" 2>/dev/null ;;
	*) sox -R "$T/$3.wav" "$T/$4.flac" 2>/dev/null && mv "$T/$4.flac" "$T/$4" ;; esac
	echo "$1|$out|$4|$3|${5:-0}" >>"$T/list"
}

rec clean  "clean, 16-bit WAV"                     -b 16 -- seed=1
rec pink30 "pink noise 30 dB below the first impact, 8-bit WAV" -b 8 -- snr=30 seed=2
rec room   "reverberation (RT60 0.4 s), 48 kHz stereo float WAV" -e floating-point -b 32 -- \
	sr=48000 ch=2 reverb=0.4 seed=3
rec knocks "two handling knocks and a noise blip, 24-bit WAV" -b 24 -- knock=0.1 knock2=0.5 \
	blip=0.003 seed=4
rec ring   "a 0.3 s ring, 1 s of silence before, 2 s after, 32-bit WAV" -b 32 -- ring=0.3 pre=1 \
	post=2 seed=5
rec quiet  "a quiet take: pink noise 20 dB below the first impact" -b 16 -- snr=20 seed=6
rec drown  "pink noise as loud as the first impact" -b 16 -- snr=0 seed=7
rec even   "8 clicks at even intervals, as loud: no bouncing" -b 16 -- even=8 seed=8
rec close  "impacts from 50 ms down to 3.4 ms apart, short rings, pink noise 60 dB down (times only: not this preset's)" \
	-b 16 -- geom=0.05,0.8 damp=0.25 snr=60 seed=9
sed -i '$s/$/|times/' "$T/list"
enc flac   "the pink-noise take as FLAC" pink30 pink30.flac
enc ogg    "the stereo room take as Ogg Vorbis" room room.ogg
enc mp3    "the knocks take as MP3 (128 kb/s)" knocks knocks.mp3 1
enc noext  "the ring take as FLAC named without extension" ring ring-take

: >"$T/table"
nfit=0 nrec=0
while IFS='|' read -r name desc file truth align only; do
	"$BIN" fit steel-on-bitumen --data "$T/$file" --free law.c,law.alpha -q \
		--out "$T/$name.preset" --onsets-out "$T/$name.csv" >"$T/$name.out" 2>"$T/$name.err"
	rc=$?
	# onset times: every click at 20 dB SNR or better within 0.1 ms; none invented
	if [ -f "$T/$name.csv" ]; then
		grep -v '^#' "$T/$name.csv" | sed 1d >"$T/$name.det"
	else
		sed -n '/^   i      t \[s\]/,/^            (e of/p' "$T/$name.out" | sed '1d;$d' |
			awk '{print $2}' >"$T/$name.det"
	fi
	if awk -v align="$align" 'NR == FNR { t[NR] = $1; s[NR] = $2; n = NR; next }
		{ d[FNR] = $1; m = FNR }
		END {
			if (align) for (k = m; k >= 1; k--) d[k] += t[1] - d[1]
			for (i = 1; i <= n; i++) {
				if (s[i] != "inf" && s[i] + 0 < 20) continue
				hit = 0
				for (k = 1; k <= m; k++) { e = d[k] - t[i]; if (e < 0) e = -e; if (e <= 1e-4) hit = 1 }
				if (!hit) { printf "# missed %s (snr %s)\n", t[i], s[i]; bad = 1 }
			}
			for (k = 1; k <= m; k++) {
				hit = 0
				for (i = 1; i <= n; i++) { e = d[k] - t[i]; if (e < 0) e = -e; if (e <= 2e-3) hit = 1 }
				if (!hit) { printf "# invented %s\n", d[k]; bad = 1 }
			}
			exit bad
		}' "$T/$truth.truth" "$T/$name.det" >"$T/$name.cmp"; then
		ok "$name: onsets within 0.1 ms of the truth (clicks at 20 dB SNR or better), none invented"
	else
		notok "$name: onsets within 0.1 ms of the truth, none invented" "$T/$name.cmp"
	fi
	if [ "$only" = times ]; then
		printf '| %s | %s | %s of %s clicks within 0.1 ms | (onset times only) |\n' "$name" \
			"$desc" "$(awk 'NR == FNR { t[NR] = $1; n = NR; next }
				{ for (i = 1; i <= n; i++) { e = $1 - t[i]; if (e < 0) e = -e
					if (e <= 1e-4) { k++; break } } } END { print k + 0 }' \
				"$T/$truth.truth" "$T/$name.det")" "$(wc -l <"$T/$truth.truth")" >>"$T/table"
		continue
	fi
	nrec=$((nrec + 1))
	# the verdict
	est=$(awk '/^estimates/ { on = 1 } /^correlation/ { on = 0 }
		on && $1 == "law.c" { c = $3; sc = $4 } on && $1 == "law.alpha" { a = $3; sa = $4 }
		END { if (c != "") printf "%s %s %s %s", c, sc, a, sa }' "$T/$name.out")
	if [ "$rc" -eq 2 ] && [ -z "$est" ]; then
		verdict=refused
		why=$(sed -n 's/^hybounce fit: --data [^:]*: //p' "$T/$name.err" | head -1 | cut -d';' -f1)
		printf '| %s | %s | - | refused (exit 2): %s |\n' "$name" "$desc" "$why" >>"$T/table"
	else
		verdict=$(echo "$rc $est" | awk -v c0=$C_TRUE -v a0=$A_TRUE '{
			ok = $1 == 0 && $3 > 0 && $5 > 0 && $2 / $3 > 10 && $4 / $5 > 10 &&
			     ($2 - c0) ^ 2 <= 9 * $3 ^ 2 && ($4 - a0) ^ 2 <= 9 * $5 ^ 2
			print ok ? "fitted" : "WRONG" }')
		# shellcheck disable=SC2086
		printf '| %s | %s | c = %.0f ± %.2g, alpha = %.4f ± %.2g | %s (exit %s) |\n' "$name" \
			"$desc" ${est:-0 0 0 0} "$verdict" "$rc" >>"$T/table"
	fi
	case $verdict in
	fitted) nfit=$((nfit + 1)); ok "$name: fitted within 3 standard errors of the truth, each under 10%" ;;
	refused) ok "$name: refused with exit 2 and the reason" ;;
	*) notok "$name: a wrong answer (exit $rc: $est)" "$T/$name.out" ;;
	esac
done <"$T/list"
# --- what was dropped, and why ------------------------------------------------
if grep -q 'dropped .* clicks found' "$T/knocks.out" &&
	grep -q 'before the first impact and far quieter than it' "$T/knocks.out" &&
	grep -q 'louder than it (a knock?)' "$T/knocks.out" &&
	grep -q 'between two impacts: it would split the interval' "$T/knocks.out"; then
	ok "the blip and the knocks are listed as dropped, each with its reason"
else
	notok "the blip and the knocks are listed as dropped, each with its reason" "$T/knocks.out"
fi
if grep -q 'nearly even intervals' "$T/even.err" && [ ! -e "$T/even.preset" ]; then
	ok "clicks at even intervals are refused as no bouncing sequence, nothing fitted"
else
	notok "clicks at even intervals are refused as no bouncing sequence" "$T/even.err"
fi
if grep -q 'too noisy to time impacts' "$T/drown.err" &&
	! grep -q 'lower --onset-threshold (' "$T/drown.err"; then
	ok "a take drowned in noise says so, not to lower --onset-threshold"
else
	notok "a take drowned in noise says so" "$T/drown.err"
fi
sox -R -n -r 44100 -b 16 "$T/silent.wav" trim 0 0.5 2>/dev/null
"$BIN" fit steel-on-bitumen --data "$T/silent.wav" --free law.c -q --out "$T/s.preset" \
	>/dev/null 2>"$T/silent.err"
rc=$?
if [ "$rc" -eq 2 ] && grep -q 'nothing in its 0.5 s rises above 5 x the noise' "$T/silent.err" &&
	grep -q 'accepted: a recording of a bouncing sequence' "$T/silent.err"; then
	ok "a silent take says that nothing rises above the noise, and what is accepted"
else
	notok "a silent take says that nothing rises above the noise (exit $rc)" "$T/silent.err"
fi

# --- --onsets-out: the t_e CSV that --data reads ---------------------------------
if [ "onsets      $(grep -c '^[0-9]' "$T/knocks.csv") in" = \
	"$(grep -o '^onsets  *[0-9]* in' "$T/knocks.out")" ] &&
	grep -q '^#[0-9.]*  (dropped: ' "$T/knocks.csv" &&
	"$BIN" fit steel-on-bitumen --data "$T/knocks.csv" --free law.c,law.alpha -q \
		--out "$T/csv.preset" >"$T/csv.out" 2>&1 &&
	estimates "$T/knocks.out" >"$T/e1" && estimates "$T/csv.out" >"$T/e2" &&
	[ "$(wc -l <"$T/e1")" -eq 2 ] && paste "$T/e1" "$T/e2" | awk '{ d = ($4 - $2) / $2 }
		$1 != $3 || d > 1e-6 || d < -1e-6 { bad = 1 } END { exit bad }'; then
	ok "--onsets-out writes the impacts (and the dropped clicks as comments); fitting it gives the same estimates"
else
	notok "--onsets-out's CSV fits to the recording's estimates" "$T/csv.out"
fi
if [ -s "$T/even.csv" ] && grep -q '^t_e$' "$T/even.csv"; then
	ok "--onsets-out is written for a refused recording too, to correct by hand"
else
	notok "--onsets-out is written for a refused recording too" "$T/even.err"
fi
"$BIN" fit steel-on-bitumen --data "$T/clean.wav" --free law.c -q --out "$T/same" \
	--onsets-out "$T/same" >/dev/null 2>"$T/same.err"
rc=$?
if [ "$rc" -eq 2 ] && grep -q -- '--onsets-out' "$T/same.err" && [ ! -e "$T/same" ]; then
	ok "--onsets-out naming the same file as --out is refused before anything is written"
else
	notok "--onsets-out naming the same file as --out is refused (exit $rc)" "$T/same.err"
fi
"$BIN" fit steel-on-bitumen --data "$T/knocks.csv" --free law.c -q --out "$T/x.preset" \
	--onsets-out "$T/x.csv" >/dev/null 2>"$T/x.err"
rc=$?
if [ "$rc" -eq 2 ] && grep -q 'is no recording' "$T/x.err" && [ ! -e "$T/x.csv" ]; then
	ok "--onsets-out with CSV data is refused"
else
	notok "--onsets-out with CSV data is refused (exit $rc)" "$T/x.err"
fi

# --- recognised by content -----------------------------------------------------
printf 't_e\n0.1\n' >"$T/text.wav"
"$BIN" fit steel-on-bitumen --data "$T/text.wav" --free law.c -q --out "$T/t.preset" \
	>/dev/null 2>"$T/t.err"
rc=$?
if [ "$rc" -eq 2 ] && grep -q 'no sound header; accepted: WAV, FLAC, Ogg' "$T/t.err"; then
	ok "a .wav holding text is refused: its first bytes are no sound header"
else
	notok "a .wav holding text is refused (exit $rc)" "$T/t.err"
fi
mkfifo "$T/fifo"
cat "$T/clean.wav" >"$T/fifo" &
"$BIN" fit steel-on-bitumen --data "$T/fifo" --free law.c -q --out "$T/p.preset" \
	>/dev/null 2>"$T/p.err"
rc=$?
wait
if [ "$rc" -eq 2 ] && grep -q 'a recording (WAV) is read by name' "$T/p.err"; then
	ok "a recording through a pipe is recognised and refused, naming its format"
else
	notok "a recording through a pipe is refused (exit $rc)" "$T/p.err"
fi
if grep -q 'vorbis\|@ 0x' "$T/ogg.err"; then
	notok "FFmpeg's log stays off stderr" "$T/ogg.err"
else
	ok "FFmpeg's log stays off stderr"
fi

if [ "$nfit" -ge $((nrec - 2)) ]; then
	ok "$nfit of $nrec recordings fitted right, none wrong"
else
	notok "$nfit of $nrec recordings fitted right (at least $((nrec - 2)) expected)" "$T/table"
fi

# --- the gate: converged is not credible --------------------------------------
"$BIN" fit steel-on-bitumen --data "$T/knocks.csv" --free law.c,law.alpha -q \
	--max-relative-se 1e-6 --out "$T/g.preset" >/dev/null 2>"$T/g.err"
rc=$?
if [ "$rc" -eq 1 ] && grep -q 'not credible: the standard error of law.c is .* above 1e-06 (--max-relative-se)' "$T/g.err" &&
	[ -s "$T/g.preset" ]; then
	ok "an estimate whose relative standard error exceeds --max-relative-se exits 1, named, still written"
else
	notok "an estimate above --max-relative-se exits 1 (exit $rc)" "$T/g.err"
fi

# --- README: the table, one recording fitted end to end, one refused ------------
{
	echo "| recording | what it is | estimate ± standard error | verdict |"
	echo "|---|---|---|---|"
	cat "$T/table"
	echo
	echo "A take with knocks and a blip, fitted end to end (the dropped clicks are"
	echo "listed with their reason):"
	echo
	(cd "$T" && echo '$ hybounce fit steel-on-bitumen --data knocks.wav --free law.c,law.alpha \' &&
		echo '      --onsets-out knocks-onsets.csv --quiet' &&
		"$BIN" fit steel-on-bitumen --data knocks.wav --free law.c,law.alpha \
			--onsets-out knocks-onsets.csv --quiet --out knocks-fit.preset 2>&1 | sed '1,2d') |
		sed 's/^/    /'
	echo
	echo "A take that is no bouncing sequence, refused:"
	echo
	(cd "$T" && echo '$ hybounce fit steel-on-bitumen --data even.wav --free law.c,law.alpha' &&
		"$BIN" fit steel-on-bitumen --data even.wav --free law.c,law.alpha 2>&1 | sed '1,2d';
		echo "\$ echo \$?" && echo 2) | sed 's/^/    /'
} | sed 's/ *$//' >"$T/readme"
sed -n '/^<!-- ONSETS-TABLE-BEGIN -->$/,/^<!-- ONSETS-TABLE-END -->$/p' README.md |
	sed '1,2d;$d' | sed '$d' >"$T/readme.old"
if [ "${1:-}" = --update-readme ]; then
	awk -v got="$T/readme" '
		/^<!-- ONSETS-TABLE-BEGIN -->$/ { print; print ""; while ((getline l < got) > 0) print l
			print ""; skip = 1; next }
		/^<!-- ONSETS-TABLE-END -->$/ { skip = 0 }
		!skip { print }' README.md >"$T/README.new" && cp "$T/README.new" README.md
	echo "# README.md: the recordings' table and examples rewritten"
	cp "$T/readme" "$T/readme.old"
fi
if cmp -s "$T/readme" "$T/readme.old"; then
	ok "README's table of recordings and its two examples are what this run gives"
else
	notok "README's table of recordings is what this run gives (sh tests/cli/onsets.sh --update-readme rewrites it)"
	diff "$T/readme.old" "$T/readme" | head -20 | sed 's/^/# /'
fi
[ "$fails" -eq 0 ]
