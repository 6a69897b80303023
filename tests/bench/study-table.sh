#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# study-table.sh [CSV]: the per-study table of docs/speed-and-accuracy.md
# and tests/bench/REPORT.md, from a `make bench` run (default
# build/bench/work-precision.csv) and the run before issue 8
# (tests/bench/before-issue-8.csv: rk8pd at rtol 1e-12, atol 1e-14, the
# presets' setting then and now; its numbers come from the bench of that
# engine and cannot be produced again).
csv=${1:-build/bench/work-precision.csv}
before=$(dirname "$0")/before-issue-8.csv
[ -r "$csv" ] || { echo "study-table.sh: cannot read $csv (run make bench)" >&2; exit 2; }
printf '| study | setting | rhs | of before | rejected | ms | t (/t_d) | e | x_c^max | F_c^max | state at T |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|\n'
awk -F, -v before="$before" '
function comma(n,   s) { s = sprintf("%d", n); while (s ~ /[0-9][0-9][0-9][0-9]/) sub(/[0-9][0-9][0-9]($|,)/, ",&", s); return s }
function e2(x) { return sprintf("%.1e", x) }
BEGIN {
	while ((getline line < before) > 0) {
		if (line ~ /^preset,/) continue
		# preset,"study",rhs,rejected,ms,t,e,xc,F,T
		match(line, /"[^"]*"/); study = substr(line, RSTART + 1, RLENGTH - 2)
		split(line, a, ","); p = a[1]
		rest = substr(line, RSTART + RLENGTH + 1); split(rest, b, ",")
		order[++n] = p; name[p] = study
		brhs[p] = b[1]; brej[p] = b[2]; bms[p] = b[3]
		bt[p] = b[4]; be[p] = b[5]; bx[p] = b[6]; bF[p] = b[7]; bT[p] = b[8]
	}
}
NR > 1 && $5 == "ok" {
	key = $1 SUBSEP $2 SUBSEP $3 SUBSEP $4
	rhs[key] = $11
	row[key] = sprintf("%s | %%.2f | %d | %.2f | %s | %s | %s | %s | %s", comma($11), $10, $6, e2($15), e2($17), e2($18), e2($19), e2($21))
}
END {
	for (i = 1; i <= n; i++) {
		p = order[i]
		printf "| %s | rk8pd 1e-12, before issue 8 | %s | 1 | %d | %s | %s | %s | %s | %s | %s |\n", name[p], comma(brhs[p]), brej[p], bms[p], bt[p], be[p], bx[p], bF[p], bT[p]
		split("rk8pd 1e-12 1e-14;dop853 3e-14 1e-14", set, ";")
		for (j = 1; j <= 2; j++) {
			split(set[j], w, " ")
			key = p SUBSEP w[1] SUBSEP w[2] SUBSEP w[3]
			if (!(key in row))
				continue
			printf "| | %s %s%s | " row[key] " |\n", w[1], w[2], j == 1 ? " (the presets)" : "", rhs[key] / brhs[p]
		}
	}
}' "$csv"
