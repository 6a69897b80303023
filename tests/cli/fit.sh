#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce fit from the command line: the README's worked example runs as
# written and prints what the README shows; the fitted preset reproduces
# the fit; a recording made with sox from the program's own impact times
# gives them back within 0.5 ms and the restitution within 1%, and fits;
# bad input exits 2 and writes nothing; keys the data cannot tell apart
# exit 1 and are named; the man page documents every option of fit --help.
#
#     sh tests/cli/fit.sh --update-readme   rewrites the README example's output
. "$(dirname "$0")/common.inc"

# --- the README's worked example, run as written in a folder of its own -----
readme_example FIT-EXAMPLE 'fit example' tests/cli/fit.sh "${1:-}"
if [ -f "$T/readme/fitted.preset" ] &&
	grep -q '^c = 5002.15' "$T/readme/fitted.preset" &&
	grep -q '^alpha = 0.29988' "$T/readme/fitted.preset"; then
	ok "the example writes fitted.preset with the estimates"
else
	notok "the example writes fitted.preset with the estimates"
fi

# --- the fitted preset reproduces the fit; --residuals -------------------------
"$BIN" fit steel-on-bitumen --data examples/fit/bounces.csv --free law.c,law.alpha \
	--out "$T/f.preset" --residuals "$T/res.csv" --quiet >"$T/out" 2>"$T/err"
rc=$?
"$BIN" --batch "$T/f.preset" --collisions - 2>/dev/null | cut -d, -f2 | sed -n '2,11p' >"$T/te"
# simulated t_e - t_e^0 of the fit against the fitted preset's own run
if [ "$rc" -eq 0 ] && [ "$(head -1 "$T/res.csv")" = "point,row,observable,measured,simulated,sd,resid,start,trial,index" ] &&
	awk -F, 'NR == FNR { t[FNR] = $1; next } FNR > 1 {
		d = t[FNR] - t[1] - $5; if (d < 0) d = -d; if (d > 1e-9) bad = 1; n++ }
		END { exit !(n == 9 && !bad) }' "$T/te" "$T/res.csv"; then
	ok "the fitted preset's run gives the fit's simulated impact times (to 1 ns)"
else
	notok "the fitted preset's run gives the fit's simulated impact times (exit $rc)"
	sed 's/^/# /' "$T/err" | head -5
fi
if grep -q 'iteration 1: cost' "$T/err"; then
	notok "--quiet prints no progress lines"
else
	ok "--quiet prints no progress lines"
fi

# --- a recording made with sox from the program's impact times -----------------
if command -v sox >/dev/null 2>&1; then
	"$BIN" --batch steel-on-bitumen --set law.c='5 kN s/m' --set law.alpha=0.3 \
		--collisions - 2>/dev/null | cut -d, -f2 | sed -n '2,9p' >"$T/true"
	sox -n -r 44100 -b 16 "$T/click.wav" synth 0.006 sine 2500 fade q 0 0.006 0.006 2>/dev/null
	set --
	i=0
	while read -r t; do
		sox "$T/click.wav" "$T/c$i.wav" pad "$t" 2>/dev/null
		set -- "$@" -v 1 "$T/c$i.wav"
		i=$((i + 1))
	done <"$T/true"
	sox -n -r 44100 -b 16 "$T/noise.wav" synth 0.5 whitenoise vol 0.01 2>/dev/null
	sox -m "$@" -v 1 "$T/noise.wav" "$T/rec.wav" 2>/dev/null
	"$BIN" fit steel-on-bitumen --data "$T/rec.wav" --free law.c,law.alpha \
		--out "$T/rec.preset" >"$T/rec.out" 2>"$T/rec.err"
	rc=$?
	sed -n '/^   i      t \[s\]/,/^            (e of/p' "$T/rec.out" | sed '1d;$d' >"$T/onsets"
	if [ "$(wc -l <"$T/onsets")" -eq 8 ] &&
		awk 'NR == FNR { t[FNR - 1] = $1; next }
			{ d = $2 - t[$1]; if (d < 0) d = -d; if (d > 0.5e-3) bad = 1 }
			END { exit bad }' "$T/true" "$T/onsets"; then
		ok "a sox recording gives the 8 impact times within 0.5 ms"
	else
		notok "a sox recording gives the 8 impact times within 0.5 ms"
		sed 's/^/# /' "$T/onsets" "$T/rec.err" | head -12
	fi
	if awk 'NR == FNR { t[FNR - 1] = $1; next }
		$1 >= 2 { e = (t[$1] - t[$1 - 1]) / (t[$1 - 1] - t[$1 - 2]);
			r = ($4 - e) / e; if (r < 0) r = -r; if (r > 0.01) bad = 1; n++ }
		END { exit !(n == 6 && !bad) }' "$T/true" "$T/onsets"; then
		ok "the recording's restitution sequence is within 1% of the true one"
	else
		notok "the recording's restitution sequence is within 1% of the true one"
	fi
	if [ "$rc" -eq 0 ] && grep -q '^  law.c  *4400  *5[0-9][0-9][0-9]\.' "$T/rec.out" &&
		[ -f "$T/rec.preset" ]; then
		ok "the recording fits (exit 0, c back near 5 kN s/m, preset written)"
	else
		notok "the recording fits (exit $rc)"
		grep -E 'stopped|law\.' "$T/rec.out" | sed 's/^/# /'
	fi
	# the explorer's --data reads the same recording through the same loader
	printf 'M\ndump %s\nq\n' "$T/rec.screen" >"$T/rec.keys"
	"$BIN" steel-on-bitumen --data "$T/rec.wav" --script "$T/rec.keys" >/dev/null 2>"$T/rec.xerr"
	rc=$?
	if [ "$rc" -eq 0 ] && grep -q 'rec.wav: a recording ([0-9]* Hz, [0-9]* ms), 8 impact' "$T/rec.screen"; then
		ok "the explorer's --data takes the recording as fit does (8 impacts)"
	else
		notok "the explorer's --data takes the recording as fit does (exit $rc)" "$T/rec.xerr"
		sed 's/^/# /' "$T/rec.screen" 2>/dev/null | head -12
	fi
else
	notok "sox is installed (make deps installs it)"
fi

# --- exit statuses -------------------------------------------------------------
# bad NAME PATTERN ARGS...: exit 2, PATTERN on stderr, no preset written
bad() {
	name=$1 pat=$2
	shift 2
	rm -f "$T/bad.preset"
	"$BIN" fit "$@" --out "$T/bad.preset" >/dev/null 2>"$T/bad.err"
	rc=$?
	if [ "$rc" -eq 2 ] && grep -qF -- "$pat" "$T/bad.err" && [ ! -e "$T/bad.preset" ]; then
		ok "$name: exit 2, says so, writes nothing"
	else
		notok "$name: exit 2, says so, writes nothing (exit $rc)"
		sed 's/^/# /' "$T/bad.err" | head -3
	fi
}
printf 'a,b\n1,2\n' >"$T/nocols.csv"
printf 't_e\n0.1\n0.3\n0.2\n' >"$T/order.csv"
bad "no --data" "--data FILE is required" steel-on-bitumen --free law.c
bad "no --free" "--free KEY" steel-on-bitumen --data examples/fit/bounces.csv
bad "unknown key" "law.zz: not a numeric key" steel-on-bitumen --data examples/fit/bounces.csv --free law.zz
bad "derived key" "law.k is derived" steel-on-bitumen --data examples/fit/bounces.csv --free law.k
bad "unrecognised columns" "nocols.csv:1: no data columns" steel-on-bitumen --data "$T/nocols.csv" --free law.c
bad "times out of order" "increasing order" steel-on-bitumen --data "$T/order.csv" --free law.c
bad "missing data file" "nope.csv" steel-on-bitumen --data "$T/nope.csv" --free law.c
bad "a start with no collision" "at the start" steel-on-bitumen --data examples/fit/bounces.csv \
	--free law.c --set loads.g=0
bad "--residuals in a missing folder" "--residuals $T/nodir/r.csv" steel-on-bitumen \
	--data examples/fit/bounces.csv --free law.c --residuals "$T/nodir/r.csv"
"$BIN" fit steel-on-bitumen --data examples/fit/bounces.csv --free law.c \
	--out "$T/nodir/x.preset" >/dev/null 2>"$T/nodir.err"
rc=$?
if [ "$rc" -eq 2 ] && grep -qF -- "--out $T/nodir/x.preset" "$T/nodir.err" &&
	! grep -q iteration "$T/nodir.err"; then
	ok "--out in a missing folder: exit 2 before fitting"
else
	notok "--out in a missing folder: exit 2 before fitting (exit $rc)"
fi
printf 'not sound\n' >"$T/fake.wav"
bad "a .wav that is no recording" "cannot be read as a recording" steel-on-bitumen \
	--data "$T/fake.wav" --free law.c
bad "unknown onset method" "onset method 'nonsense'" steel-on-bitumen --data "$T/rec.wav" \
	--free law.c --onset-method nonsense
bad "unknown option" "unrecognized option" steel-on-bitumen --data examples/fit/bounces.csv --free law.c --frob

"$BIN" fit steel-on-bitumen --data examples/fit/bounces.csv --free body1.E,body2.E \
	--out "$T/unid.preset" >"$T/unid.out" 2>/dev/null
rc=$?
if [ "$rc" -eq 1 ] && grep -q 'not identifiable from these data: body1.E, body2.E' "$T/unid.out" &&
	[ -f "$T/unid.preset" ]; then
	ok "body1.E and body2.E together: exit 1, named as not identifiable, best point written"
else
	notok "body1.E and body2.E together: exit 1, named as not identifiable (exit $rc)"
	grep stopped "$T/unid.out" | sed 's/^/# /'
fi

# --- fit --help and the man page -------------------------------------------------
missing=
n=0
for o in $("$BIN" fit --help | grep -o -- '--[a-z][a-z-]*' | sort -u); do
	n=$((n + 1))
	grep -q "^\.It .*Fl -${o#--}\\b" man/hybounce.1 || missing="$missing $o"
done
if [ "$n" -ge 12 ] && [ -z "$missing" ]; then ok "the man page documents every option of fit --help ($n)"
else notok "the man page documents every option of fit --help ($n found, missing:$missing)"; fi
if "$BIN" --help | grep -q 'hybounce fit PRESET'; then ok "hybounce --help mentions fit"
else notok "hybounce --help mentions fit"; fi

[ "$fails" -eq 0 ]
