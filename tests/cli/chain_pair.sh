#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The reduced system is the chain of one ball on the floor (docs/chains.md,
# "One driver of a flow interval, two systems"): each shipped preset of
# the reduced system that a chain can express (constant loads; the
# chain's indentation limit not passed) run as such a chain, --set
# chain.n=1 --set chain.floor=yes with its x0 and v0 as the gap and the
# striker's velocity, ends as the preset does and prints the same
# collision table to the last digit, but for the two columns that print
# round-off (x_c^r in fm, W in fJ for an elastic law), which any change
# in the order of operations moves: the one driver on the clusters'
# system gives the pair's numbers.  The counts of rhs are in each line
# (within 2% of the preset's on 7 of the 13 that evaluate; see
# docs/chains.md).  The presets whose obstacle is a mass of inf (the
# paper's linear-law examples) are the same reduced system.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"

# table FILE SKIPK: the batch table's rows, one value a line as "row column value",
# the k column dropped (SKIPK 1), x_c^r and W dropped (round-off)
table() {
	awk -v skipk="$2" '
		/^ *i  / && !h { n = split($0, hd, "  +"); m = 0
			for (j = 1; j <= n; j++) { if (hd[j] == "") continue; name[++m] = hd[j] } h = 1; next }
		h && /^ *[0-9]/ { r++; c = 0
			for (j = 1; j <= NF; j++) { c++; col = name[c]
				if (skipk && col == "k") continue
				if (col ~ /^x_c\^r/ || col ~ /^W /) continue
				print r, col, $j } next }
		h && !/^ *[0-9]/ { exit }' "$1"
}
for p in hard-bounce-end hard-drop-1um hard-n1 hard-slow-impact-hertz hard-slow-impact-shccl \
    hertz-elastic permanent-contact-bwmcl permanent-contact-bwshccl permanent-contact-shccl \
    steel-on-bitumen table-tennis-ittf nonunique-separation hard-linear-maxwell nonunique-rest; do
	x0=$(sed -n 's/^x0 *= *//p' "$HYBOUNCE_PRESETS/$p.preset")
	v0=$(sed -n 's/^v0 *= *//p' "$HYBOUNCE_PRESETS/$p.preset")
	"$BIN" --batch "$p" >"$T/pair" 2>&1
	"$BIN" --batch "$p" --set chain.n=1 --set chain.floor=yes --set "initial.body.1.gap=$x0" \
	    --set "striker.v=${v0:-0}" >"$T/chain" 2>&1
	table "$T/pair" 0 >"$T/tp"
	table "$T/chain" 1 >"$T/tc"
	rp=$(awk '$1 == "evaluations" { print $2 }' "$T/pair")
	rc=$(awk '$1 == "evaluations" { print $2 }' "$T/chain")
	if [ -s "$T/tp" ] || grep -q '^  collisions  0$' "$T/pair"; then :; else
		notok "$p: no table read from the pair's report" "$T/pair"
		continue
	fi
	if cmp -s "$T/tp" "$T/tc" &&
	    [ "$(grep '^  ended ' "$T/pair")" = "$(grep '^  ended ' "$T/chain")" ]; then
		ok "$p as a chain of one ball on the floor: the same end and table ($(wc -l <"$T/tp") values; rhs $rp as two bodies, $rc as a chain)"
	else
		notok "$p as a chain of one ball on the floor: the same end and table" "$T/chain"
		diff "$T/tp" "$T/tc" | head -n 10 | sed 's/^/# /'
	fi
done
[ "$fails" -eq 0 ]
