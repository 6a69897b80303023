#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# An ASCII scatter plot of two columns of sweeps' runs.csv, one symbol per
# sweep folder (o, +, x, *, #):
#
#   sh examples/sweeps/plot.sh [-logx] [-absx] XCOL YCOL DIR...
#
# XCOL and YCOL are column names of runs.csv (v_i_first, e_first, law.c,
# collisions, t_pc ...).  Rows with an empty value are left out.
set -u
logx=0
absx=0
while [ $# -gt 0 ]; do
	case $1 in
	-logx) logx=1; shift ;;
	-absx) absx=1; shift ;;
	*) break ;;
	esac
done
if [ $# -lt 3 ]; then
	echo "usage: sh examples/sweeps/plot.sh [-logx] [-absx] XCOL YCOL DIR..." >&2
	exit 2
fi
xc=$1 yc=$2
shift 2
n=0
for d in "$@"; do
	n=$((n + 1))
	awk -F, -v xc="$xc" -v yc="$yc" -v k="$n" -v name="$d" '
	    NR == 1 { for (i = 1; i <= NF; i++) { if ($i == xc) x = i; if ($i == yc) y = i }
	              if (!x || !y) { print "plot.sh: " name "/runs.csv has no column " (x ? yc : xc) > "/dev/stderr"; exit 2 }
	              next }
	    $x != "" && $y != "" { print k, $x, $y }' "$d/runs.csv" || exit 2
done | awk -v logx="$logx" -v absx="$absx" -v xc="$xc" -v yc="$yc" -v names="$*" '
	BEGIN { W = 64; H = 20; split("o + x * #", sym, " "); split(names, nm, " ") }
	{
		x = $2 + 0; if (absx) x = x < 0 ? -x : x
		if (logx) { if (x <= 0) next; x = log(x) / log(10) }
		k[NR] = $1; X[NR] = x; Y[NR] = $3 + 0; m = NR
		if (m == 1 || x < x0) x0 = x; if (m == 1 || x > x1) x1 = x
		if (m == 1 || Y[NR] < y0) y0 = Y[NR]; if (m == 1 || Y[NR] > y1) y1 = Y[NR]
	}
	END {
		if (m == 0) { print "plot.sh: no rows with both values" > "/dev/stderr"; exit 1 }
		if (x1 == x0) x1 = x0 + 1; if (y1 == y0) y1 = y0 + 1
		for (r = 0; r < H; r++) for (c = 0; c < W; c++) g[r, c] = " "
		for (i = 1; i <= m; i++) {
			c = int((X[i] - x0) / (x1 - x0) * (W - 1) + 0.5)
			r = int((y1 - Y[i]) / (y1 - y0) * (H - 1) + 0.5)
			g[r, c] = sym[k[i]]
		}
		for (r = 0; r < H; r++) {
			lab = r == 0 ? sprintf("%9.3g", y1) : r == H - 1 ? sprintf("%9.3g", y0) : ""
			line = sprintf("%9s |", lab)
			for (c = 0; c < W; c++) line = line g[r, c]
			print line
		}
		line = "          +"; for (c = 0; c < W; c++) line = line "-"; print line
		l = logx ? sprintf("%.3g", 10 ^ x0) : sprintf("%.3g", x0)
		h = logx ? sprintf("%.3g", 10 ^ x1) : sprintf("%.3g", x1)
		printf "          %-*s%*s\n", W / 2, l, W / 2 + 1, h
		printf "          %s%s%s against %s;", yc, "", "", (absx ? "|" xc "|" : xc) (logx ? " (log scale)" : "")
		for (i = 1; i in nm; i++) printf " %s %s", sym[i], nm[i]
		printf "\n"
	}'
