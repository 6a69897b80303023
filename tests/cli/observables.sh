#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The run observables are one table (observables.h): the batch summary's
# "observables" line and a sweep's runs.csv give the same value of each,
# for every shipped preset, and on a long run whose kept collisions are
# thinned (hertz-elastic, run.T = 30 s, run.max_samples = 1024: 469
# collisions, 85 kept) both count all 469.  The sweep varies run.rtol over
# the one value that the batch run gets with --set, so the scenes are the
# same; runs.csv's %.17g values are compared at the summary's 6 digits.
. "$(dirname "$0")/common.inc"

# batch_obs FILE: the summary's "name = value" pairs, one a line, unit dropped.
batch_obs() {
	awk '/^  observables / { f = 1; sub(/^  observables /, "") }
	     f && !/^  observables/ && /^  [a-z]/ && !/^              / && s != "" { f = 0 }
	     f { sub(/^ +/, ""); s = s " " $0 }
	     END { n = split(s, p, ","); for (i = 1; i <= n; i++) {
	             sub(/^ +/, "", p[i]); split(p[i], w, " "); print w[1] " " w[3] } }' "$1"
}
# csv_obs FILE: runs.csv's observables of row 1 as "name value" at %.6g
# ("-" for an empty field), the columns from collisions to jac.
csv_obs() {
	awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "collisions") a = i;
	                   for (i = 1; i <= NF; i++) if ($i == "jac") b = i;
	                   for (i = a; i <= b; i++) name[i] = $i; next }
	         NR == 2 { for (i = a; i <= b; i++)
	                     if ($i == "") print name[i], "-";
	                     else if ($i ~ /^-?[0-9]+$/ && length($i) < 16) print name[i], $i;
	                     else printf "%s %.6g\n", name[i], $i }' "$1"
}

# compare NAME [SET...]: batch and a one-point sweep of preset NAME.
compare() {
	name=$1
	shift
	rtol=$("$BIN" --batch "$name" "$@" 2>/dev/null | sed -n 's/^run .* rtol = \([^,]*\),.*/\1/p')
	"$BIN" --batch "$name" "$@" --set "run.rtol=$rtol" >"$T/batch" 2>"$T/err"
	rm -rf "$T/sw"
	"$BIN" sweep "$name" "$@" --vary "run.rtol=$rtol" --jobs 1 --quiet --out "$T/sw" 2>>"$T/err"
	batch_obs "$T/batch" >"$T/b"
	csv_obs "$T/sw/runs.csv" >"$T/c"
	n=$(wc -l <"$T/b")
	if [ -n "$rtol" ] && [ "$n" -eq 18 ] && cmp -s "$T/b" "$T/c"; then
		agreed=$((agreed + 1))
		return 0
	fi
	notok "$name $*: batch and runs.csv agree on the 18 observables"
	diff "$T/b" "$T/c" | sed 's/^/# /' | head -n 10
	show "$T/err" 5
	return 1
}

agreed=0 presets=0
for p in "$HYBOUNCE_PRESETS"/*.preset; do
	presets=$((presets + 1))
	compare "$(basename "$p" .preset)"
done
if [ "$agreed" -eq "$presets" ] && [ "$presets" -ge 10 ]; then
	ok "batch summary and runs.csv agree on every observable for all $presets shipped presets"
else
	notok "batch summary and runs.csv agree for $agreed of $presets presets"
fi

if compare hertz-elastic --set run.T=30 --set run.max_samples=1024 &&
    grep -qx 'collisions 469' "$T/b" && grep -qx 'collisions 469' "$T/c" &&
    grep -q 'collisions  469 (85 kept' "$T/batch"; then
	ok "hertz-elastic, 30 s, max_samples 1024: batch and runs.csv both count 469 collisions (85 kept), and agree on every observable"
else
	notok "hertz-elastic, 30 s, max_samples 1024: 469 collisions in batch and runs.csv" "$T/c"
fi
# the sum of x_c^r covers the thinned collisions too: the kept ones sum to less
kept=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "x_c_r") k = i; next }
                { s += $k } END { printf "%.17g", s }' "$T/sw/collisions.csv")
total=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "x_c_r_total") k = i; next }
                 { print $k }' "$T/sw/runs.csv")
if awk -v k="$kept" -v t="$total" 'BEGIN { exit !(t > k && k > 0) }'; then
	ok "x_c_r_total ($total m) sums every collision, more than the 85 kept ones ($kept m)"
else
	notok "x_c_r_total sums every collision (total $total, kept $kept)"
fi
[ "$fails" -eq 0 ]
