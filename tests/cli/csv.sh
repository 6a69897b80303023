#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# --trace and --collisions write parseable CSV with the documented header,
# the same number of fields on every row and numbers that parse, plus the
# scene as a .preset beside them; batch on that saved preset reproduces the
# collisions CSV byte for byte.  Done for every preset in presets/.
. "$(dirname "$0")/common.inc"

COLL_HEADER='i,t_e,t_s,t_d,t_f,v_i,e,x_c_max,F_c_max,x_c_r,W,J_Fc,J_Fe,Lambda'
ARC_HEADER_RE='^t,j,q_c,x,v,x_c(,z_c1(,z_c2)?)?,F_c,F_er(,x_m,v_m,v_m1,v_m2)?$'

# csv_ok FILE [COLUMN [ANYWHERE]]: prints nothing if every row has as many
# fields as the header (a header alone is fine) and every field is a finite
# number (COLUMN may be empty in the last row only), else the first problem.
# ANYWHERE: columns ("6,8") that may be empty in any row (a chain: t_f after
# each interface's last contact, e of a touching pair pushed together).
csv_ok() {
	awk -F, -v ec="${2:-0}" -v any=",${3:-}," '
	{ sub(/\r$/, "") }
	NR == 1 { nf = NF; next }
	NF != nf { printf "line %d: %d fields, header has %d\n", NR, NF, nf; bad = 1; exit }
	{
		for (k = 1; k <= NF; k++) {
			if ($k == "" && index(any, "," k ",")) continue
			if ($k == "" && k == ec) { empty = NR; continue }
			if ($k !~ /^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$/) {
				printf "line %d field %d: \"%s\" is not a number\n", NR, k, $k
				bad = 1; exit
			}
		}
	}
	END {
		if (bad) exit
		if (empty && empty != NR) printf "line %d: field %d empty before the last row\n", empty, ec
	}' "$1" 2>&1
}

for f in presets/*.preset; do
	[ -f "$f" ] || continue
	name=$(basename "$f" .preset)
	d=$T/$name
	mkdir -p "$d"
	"$BIN" -b "$name" -q -t "$d/arc.csv" -c "$d/coll.csv" >"$d/out" 2>"$d/err"
	rc=$?
	if [ "$rc" -eq 0 ] && [ -s "$d/arc.csv" ] && [ -s "$d/coll.csv" ] &&
	    grep -q "^wrote $d/arc.csv\$" "$d/err" && grep -q "^wrote $d/coll.csv\$" "$d/err"; then
		ok "$name: --trace and --collisions write both files and say so"
	else
		notok "$name: --trace and --collisions write both files and say so (exit $rc)"
		sed 's/^/# /' "$d/err" | head -n 5
		continue
	fi

	h=$(head -n 1 "$d/coll.csv" | tr -d '\r')
	want=$COLL_HEADER any=
	if grep -q '^\[chain\]' "$f"; then # a chain: the interface k after i
		want=$(echo "$COLL_HEADER" | sed 's/^i,/i,k,/') any=6,8
	fi
	if [ "$h" = "$want" ]; then ok "$name: collisions CSV header as documented"
	else notok "$name: collisions CSV header as documented (got '$h')"; fi
	h=$(head -n 1 "$d/arc.csv" | tr -d '\r')
	if echo "$h" | grep -Eq "$ARC_HEADER_RE"; then ok "$name: arc CSV header as documented ($h)"
	else notok "$name: arc CSV header as documented (got '$h')"; fi

	p=$(csv_ok "$d/arc.csv" "")
	[ "$(wc -l <"$d/arc.csv")" -ge 3 ] || p="fewer than two samples"
	if [ -z "$p" ]; then ok "$name: arc CSV rows have equal fields and numbers parse"
	else notok "$name: arc CSV rows have equal fields and numbers parse: $p"; fi
	# t_f (column 5) of the last collision is unknown when no flight follows it.
	p=$(csv_ok "$d/coll.csv" 5 $any)
	if [ -z "$p" ]; then ok "$name: collisions CSV rows have equal fields and numbers parse"
	else notok "$name: collisions CSV rows have equal fields and numbers parse: $p"; fi

	n=$(sed -n 's/^  collisions  \([0-9]*\)$/\1/p' "$d/out")
	rows=$(($(wc -l <"$d/coll.csv") - 1))
	if [ "$rows" = "$n" ]; then ok "$name: one collisions CSV row per collision ($n)"
	else notok "$name: one collisions CSV row per collision ($rows rows, summary '$n')"; fi

	if [ -s "$d/arc.preset" ] && grep -q "^wrote $d/arc.preset\$" "$d/err"; then
		ok "$name: the scene is saved beside the CSV as arc.preset"
	else
		notok "$name: the scene is saved beside the CSV as arc.preset"
		continue
	fi
	"$BIN" -b "$d/arc.preset" -q -c "$d/again.csv" >/dev/null 2>"$d/err2"
	rc=$?
	if [ "$rc" -eq 0 ] && cmp -s "$d/coll.csv" "$d/again.csv"; then
		ok "$name: batch on the saved preset reproduces the collisions CSV byte for byte"
	else
		notok "$name: batch on the saved preset reproduces the collisions CSV byte for byte (exit $rc)"
		diff "$d/coll.csv" "$d/again.csv" | head -n 6 | sed 's/^/# /'
		sed 's/^/# /' "$d/err2" | head -n 5
	fi
	# The line "; export ID: ..." names each export (csv.h), the line
	# "; hybounce V (commit C): COMMAND" its command (outputs.h): left out here.
	grep -v -e '^; export ' -e '^; hybounce .*(commit .*): ' "$d/arc.preset" >"$d/a.scene"
	grep -v -e '^; export ' -e '^; hybounce .*(commit .*): ' "$d/again.preset" >"$d/b.scene"
	if [ -s "$d/again.preset" ] && [ "$(wc -l <"$d/a.scene")" -gt 10 ] &&
	    cmp -s "$d/a.scene" "$d/b.scene"; then
		ok "$name: the saved preset saves itself identically"
	else
		notok "$name: the saved preset saves itself identically"
		diff "$d/a.scene" "$d/b.scene" | head -n 6 | sed 's/^/# /'
	fi
done

[ "$fails" -eq 0 ]
