#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Numbers are the same bytes whatever the locale: every front end that reads
# or writes numbers, run under decimal-comma locales (German, French) and a
# Turkish one (where 'I' and 'i' are not one letter under a case fold), set
# through LANG, LC_ALL or LC_NUMERIC alone, gives exactly what it gives
# under LANG=C.  One table: a row per environment, a column per front end
# (y: run it there).  The locales come from `make deps`; a missing one is a
# failure, never a skip.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"

# env                     batch set sweep fit
TABLE='
LANG=de_DE.UTF-8          y     y   y     y
LC_ALL=de_DE.UTF-8        y     y   y     y
LC_NUMERIC=de_DE.UTF-8    y     y   y     y
LANG=fr_FR.UTF-8          y     y   y     y
LC_ALL=fr_FR.UTF-8        y     y   y     y
LC_NUMERIC=fr_FR.UTF-8    y     y   y     y
LANG=tr_TR.UTF-8          y     y   y     y
LC_ALL=tr_TR.UTF-8        y     y   y     y
LC_NUMERIC=tr_TR.UTF-8    y     y   y     y
'

# inenv ASSIGNMENT CMD...: CMD with only ASSIGNMENT for the locale.
inenv() {
	a=$1
	shift
	env -u LC_ALL -u LC_NUMERIC -u LC_CTYPE -u LANG -u LANGUAGE "$a" "$@"
}

# The front ends, each writing into folder $1 (relative to $T) under
# environment $2.  What is measured is cut: the time in the sidecar
# preset's export line, the report's run time line, the sweep's cpu_s and
# progress lines.
run_batch() {
	mkdir -p "$T/$1" && (cd "$T/$1" &&
	    inenv "$2" "$BIN" --batch steel-on-bitumen --trace tr.csv --collisions co.csv \
	        >out 2>err) || return 1
	grep -v '^  run time ' "$T/$1/out" >"$T/$1/report" && rm "$T/$1/out" &&
	sed 's/^; export [0-9T:.-]*Z: /; export ID: /' "$T/$1/tr.preset" >"$T/$1/sidecar" &&
	    rm "$T/$1/tr.preset"
}
run_set() {
	mkdir -p "$T/$1" && (cd "$T/$1" &&
	    inenv "$2" "$BIN" --batch steel-on-bitumen --set 'law.c=4.4 kN s/m' \
	        --set 'body1.nu=0.3' --set 'initial.x0 = 1.5e1 mm' --collisions co.csv \
	        --quiet >out 2>err) || return 1
	grep -v '^  run time ' "$T/$1/out" >"$T/$1/report" && rm "$T/$1/out" &&
	sed 's/^; export [0-9T:.-]*Z: /; export ID: /' "$T/$1/co.preset" >"$T/$1/sidecar" &&
	    rm "$T/$1/co.preset"
}
run_sweep() {
	# --out relative: the provenance line of sweep.preset names the command
	mkdir -p "$T/$1" && (cd "$T/$1" &&
	    inenv "$2" "$BIN" sweep permanent-contact-shccl --vary 'initial.x0=10um:40um:3' \
	        --vary 'law.c=1e9,4.3e9' --set 'body1.nu=0.31' --jobs 2 --out sw \
	        >/dev/null 2>err) || return 1
	nocpu "$T/$1/sw/runs.csv" >"$T/$1/runs" && mv "$T/$1/sw/collisions.csv" "$T/$1/collisions" &&
	    mv "$T/$1/sw/sweep.preset" "$T/$1/sweep.preset" && rm -r "$T/$1/sw"
}
run_fit() {
	mkdir -p "$T/$1" && (cd "$T/$1" &&
	    inenv "$2" "$BIN" fit steel-on-bitumen --data "$OLDPWD/examples/fit/bounces.csv" \
	        --free law.c,law.alpha --out f.preset --residuals res.csv >report 2>err) &&
	# the runs' CPU time is a measurement: its numbers must still be C numbers
	sed -i -E 's/^(hybounce fit: runs: )[0-9.e+-]+ s of CPU; [0-9.e+-]+ s (on [0-9]+ threads? with a core each) \([0-9.]+x\)$/\1X s of CPU; X s \2 (Xx)/' \
	    "$T/$1/err"
}

# The references, under LANG=C.
for fe in batch set sweep fit; do
	if "run_$fe" "C-$fe" LANG=C; then
		ok "$fe under LANG=C (the reference)"
	else notok "$fe under LANG=C (the reference)" "$T/C-$fe/err"; fi
done
grep -q '^c = 4400 N s/m$' "$T/C-set/sidecar" && grep -q '^nu = 0.29999999999999999$' \
    "$T/C-set/sidecar" && grep -q '^x0 = 0.014999999999999999 m$' "$T/C-set/sidecar" &&
	ok "--set 'law.c=4.4 kN s/m', 'body1.nu=0.3' and 'initial.x0 = 1.5e1 mm' read under LANG=C" ||
	notok "--set values with decimals read under LANG=C" "$T/C-set/sidecar"

have_locales=$(locale -a 2>/dev/null | tr 'A-Z' 'a-z')
n=0
echo "$TABLE" | while read -r a batch set sweep fit; do
	[ -n "$a" ] || continue
	n=$((n + 1))
	loc=${a#*=}
	norm=$(echo "$loc" | tr 'A-Z' 'a-z' | sed 's/utf-8$/utf8/')
	if ! echo "$have_locales" | grep -qx "$norm"; then
		notok "$a: the locale $loc is not installed (make deps installs it)"
		continue
	fi
	# The environment really asks for a decimal comma (all three do).
	dp=$(inenv "$a" locale decimal_point 2>/dev/null)
	if [ "$dp" = , ]; then
		ok "$a: the locale's decimal point is a comma"
	else notok "$a: the locale's decimal point is '$dp', not a comma"; fi
	for fe in batch set sweep fit; do
		eval "on=\$$fe"
		[ "$on" = y ] || continue
		d="$n-$fe"
		if ! "run_$fe" "$d" "$a"; then
			notok "$fe under $a fails" "$T/$d/err"
			continue
		fi
		diffs="" same=""
		for f in $(cd "$T/C-$fe" && ls); do
			# stderr: fit's iteration lines hold numbers; the others' none
			[ "$f" = err ] && [ "$fe" != fit ] && continue
			if cmp -s "$T/C-$fe/$f" "$T/$d/$f"; then same="$same $f"; else diffs="$diffs $f"; fi
		done
		[ "$(cd "$T/C-$fe" && ls)" = "$(cd "$T/$d" && ls)" ] || diffs="$diffs (file list)"
		if [ -z "$diffs" ]; then
			ok "$fe under $a:$same identical to LANG=C"
		else
			notok "$fe under $a: differs from LANG=C in$diffs"
			for f in $diffs; do
				[ -f "$T/$d/$f" ] && diff "$T/C-$fe/$f" "$T/$d/$f" | head -n 6 | sed 's/^/# /'
			done
		fi
	done
done >"$T/rows"
cat "$T/rows"
if grep -q '^not ok' "$T/rows"; then
	fails=$((fails + $(grep -c '^not ok' "$T/rows")))
fi
echo "# locale table: $(grep -c '^ok' "$T/rows") ok, $(grep -c '^not ok' "$T/rows") not ok over $(echo "$TABLE" | grep -c =) environments"

[ "$fails" -eq 0 ]
