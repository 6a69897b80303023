#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer under a decimal-comma locale (German, French) and the
# Turkish one: it takes the character set from the locale (Braille plots
# in UTF-8) and nothing else, so numbers stay C numbers.  A shipped preset
# opens with o, measured data with D, 0.31 typed in a field is taken, the
# screen and the sweep view (S, a range with decimals) show dots, and the
# export (e) writes files that
# `hybounce --batch` on the exported preset reproduces byte for byte and
# that pandas reads to the same floats, with the header's column count, as
# the batch run's under LANG=C.  The locales come from `make deps`, pandas
# (python3-pandas) too: a missing one fails, never skips.
. "$(dirname "$0")/common.inc"

REPO=$(pwd)
PY=
for p in /usr/bin/python3 python3; do
	if "$p" -c 'import pandas' 2>/dev/null; then PY=$p; break; fi
done
[ -n "$PY" ] || notok "pandas is not installed (make deps installs python3-pandas)"

# pandas_same A B: both CSVs read by pandas (round-trip float parsing) give
# the same frame, with as many columns as the header names and a plain
# row index (a row with more fields than the header would shift the
# columns into the index).
pandas_same() {
	"$PY" - "$1" "$2" <<'EOF'
import sys
import pandas as pd
a, b = sys.argv[1], sys.argv[2]
fa = pd.read_csv(a, float_precision="round_trip")
fb = pd.read_csv(b, float_precision="round_trip")
ncol = len(open(a).readline().rstrip("\n").split(","))
ok = (fa.shape[1] == ncol and isinstance(fa.index, pd.RangeIndex)
      and list(fa.columns) == list(fb.columns) and fa.shape == fb.shape
      and all(fa.dtypes[c].kind in "fi" for c in fa.columns)
      and fa.equals(fb))
print("# pandas: %s %dx%d, %s %dx%d, %d header fields" % (a.rsplit("/", 1)[-1], fa.shape[0],
      fa.shape[1], b.rsplit("/", 1)[-1], fb.shape[0], fb.shape[1], ncol))
sys.exit(0 if ok else 1)
EOF
}

# table_dots SESSION FILE: polls until the collisions table (from its header
# to the readout line below it, saved in FILE) has rows, the first with a
# decimal dot, and no decimal comma anywhere.
table_dots() {
	i=0
	while [ "$i" -lt 30 ]; do
		screen "$1" | sed -n '/ t_e\[ms\] /,/^#[0-9]* t=/p' >"$2"
		if [ "$(wc -l <"$2")" -gt 3 ] && grep -q '^ *>\{0,1\}0  *[0-9]*\.[0-9]' "$2" &&
		    grep -q '^#[0-9]* t=[0-9]*\.[0-9]' "$2" && ! grep -q '[0-9],[0-9]' "$2"; then
			return 0
		fi
		i=$((i + 1))
		sleep 0.1
	done
	return 1
}

# start_in NAME ENV: the explorer in an 100x30 session with only ENV for the locale.
start_in() {
	rm -f "$TMP/$1.rc"
	$TM new-session -d -s "$1" -x 100 -y 30 \
	    "cd '$TMP' && env -u LC_ALL -u LC_NUMERIC -u LC_CTYPE -u LANG -u LANGUAGE $2 '$BIN'; echo \$? > '$TMP/$1.rc'"
}

n=0
for a in LANG=de_DE.UTF-8 LC_ALL=fr_FR.UTF-8 LANG=tr_TR.UTF-8; do
	n=$((n + 1))
	s=s$n
	loc=${a#*=}
	if [ "$(env -u LC_ALL -u LC_NUMERIC -u LANG "$a" locale decimal_point 2>/dev/null)" != , ]; then
		notok "$a: the locale $loc is missing or has no decimal comma (make deps installs it)"
		continue
	fi
	mkdir -p "$TMP/out$n"
	start_in $s "$a"
	# t on the status line moves with playback (t=0 s at first, a whole
	# 500 ms at the end): wait for a value with decimals
	if wait_for $s ' finished$' 150 && wait_for $s '⣀' 10 &&
	    wait_for $s '^ *steel-on-bitumen .* t=[0-9]+\.[0-9]+ (ms|s) ' 300; then
		ok "$a: the default preset runs, plots in Braille (UTF-8 from the locale), t with a dot on the status line"
	else notok "$a: the default preset runs with Braille plots and a dot in t" $s; fi

	# o: a shipped preset (ptfe-pom is above the current steel-on-bitumen)
	keys $s o
	if wait_for $s 'open a preset' 30 && picker_up $s ptfe-pom && keys $s Enter &&
	    wait_for $s '^ ptfe-pom bwshccl ' 50 && wait_for $s ' finished$' 150; then
		ok "$a: o opens the shipped preset ptfe-pom"
	else notok "$a: o opens the shipped preset ptfe-pom" $s; fi

	# 0.31 typed in a field
	if edit $s body1.nu 0.31 && wait_for $s 'body1\.nu = 0\.31' 50 &&
	    wait_for $s ' finished$' 150; then
		ok "$a: 0.31 typed in body1.nu is taken (and shown as 0.31)"
	else notok "$a: 0.31 typed in body1.nu is taken" $s; fi
	keys $s Tab
	if wait_for $s ' t_e\[ms\] ' 30 && table_dots $s "$TMP/table$n"; then
		ok "$a: the table and the readout show decimal dots, no decimal comma"
	else notok "$a: the table and the readout show decimal dots" $s; fi

	# e: the export
	keys $s e
	wait_for $s 'BASE: ' 30
	keys $s C-u
	keys $s -l "out$n/x"
	keys $s Enter
	if wait_for $s "wrote out$n/x-trace\\.csv" 80 && [ -s "$TMP/out$n/x-collisions.csv" ] &&
	    [ -s "$TMP/out$n/x.preset" ]; then
		ok "$a: e exports the trace, the collisions and the preset"
	else notok "$a: e exports the trace, the collisions and the preset" $s; fi
	if grep -q '^nu = 0\.31' "$TMP/out$n/x.preset" &&
	    ! grep -Eq '^[^;].*[0-9],[0-9]' "$TMP/out$n/x.preset"; then
		ok "$a: the exported preset holds nu = 0.31 and no decimal comma"
	else notok "$a: the exported preset holds nu = 0.31 and no decimal comma"; fi
	(cd "$TMP/out$n" && env -u LC_ALL -u LC_NUMERIC LANG=C "$BIN" --batch x.preset \
	    --trace b-trace.csv --collisions b-collisions.csv --quiet >/dev/null 2>b.err)
	if cmp -s "$TMP/out$n/x-collisions.csv" "$TMP/out$n/b-collisions.csv" &&
	    cmp -s "$TMP/out$n/x-trace.csv" "$TMP/out$n/b-trace.csv"; then
		ok "$a: --batch on the exported preset (LANG=C) gives the exported trace and collisions byte for byte"
	else
		notok "$a: --batch on the exported preset reproduces the export"
		sed 's/^/# /' "$TMP/out$n/b.err" | head -n 5
	fi
	for f in trace collisions; do
		if [ -n "$PY" ] && pandas_same "$TMP/out$n/x-$f.csv" "$TMP/out$n/b-$f.csv"; then
			ok "$a: pandas reads the exported $f as the batch run's under LANG=C (same floats, same columns)"
		else notok "$a: pandas reads the exported $f as the batch run's"; fi
	done

	# D: measured data
	keys $s D
	wait_for $s '^data file' 30
	keys $s -l "$REPO/examples/fit/bounces.csv"
	keys $s Enter
	if wait_for $s '^data .*bounces\.csv: one bouncing sequence, 10 impacts' 50 &&
	    wait_for $s ' data t_e ' 30 && wait_for $s ' 88\.472 ms \(' 30; then
		ok "$a: D opens measured data (10 impacts; its t_e in the table, with a dot)"
	else notok "$a: D opens measured data" $s; fi

	# S: the sweep view reads a range with decimals and shows dots
	keys $s / ; keys $s -l v0 ; keys $s Enter
	wait_for $s 'nudge\) initial\.v0:' 30 && keys $s S
	wait_for $s '^sweep initial\.v0 over ' 30
	keys $s C-u ; keys $s -l -- "-0.25 m/s:-1.25 m/s:5" ; keys $s Enter
	if wait_for $s '^sweep: e of collision 0 against initial\.v0 = -0\.25 m/s:-1\.25 m/s:5 +5/5 done$' 300 &&
	    wait_for $s '^\* now .*, e = [0-9]\.[0-9]' 30 &&
	    ! screen $s | grep -v '^sweep' | grep -q '[0-9],[0-9]'; then
		ok "$a: the sweep view takes -0.25 m/s:-1.25 m/s:5 and shows decimal dots"
	else notok "$a: the sweep view takes a range with decimals" $s; fi
	keys $s q
	wait_gone $s '^sweep: e of' 30
	keys $s q
	wait_exit $s 50 || notok "$a: q ends the explorer" $s
done
exit $((failed > 0))
