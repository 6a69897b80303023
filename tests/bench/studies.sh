#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# studies.sh [--smoke] BIN OUT.md: per paper study, at the presets' setting
# (rk8pd, rtol 1e-12, atol 1e-14), in one run (a benchmark, not a test):
#  - instructions per right-hand-side evaluation: valgrind callgrind,
#    instructions inside hb_sim_advance (--toggle-collect) / rhs;
#  - rhs evaluations and rejected steps (the batch summary);
#  - engine CPU time (the batch summary's in-process time, median of
#    RUNS) beside SciPy DOP853's (tests/bench/scipy_ref.py, the paper's
#    setting rtol 1e-11, atol 1e-14, CPU time of the simulation alone,
#    median of SCIPY_RUNS), study after study, and their ratio;
#  - the true error against the binary128 reference (tests/reference/,
#    agree.py --max) and the largest error bar that
#    --error gives, both relative (t_e, t_s to t_d; x_c^r to x_c^max; W to
#    |J_Fc v_i| where larger), and e of the first collision with its bar.
# Times are CPU times on a machine that may be loaded: compare them only
# within a row.  Without python3-scipy the SciPy columns are "-".
set -u
smoke=0
[ "${1:-}" = --smoke ] && { smoke=1; shift; }
BIN=${1:-build/hybounce}
OUT=${2:-build/bench/studies.md}
PY=${PYTHON:-python3}
SPY=${SCIPY_PYTHON:-/usr/bin/python3}   # Debian's, with python3-scipy
HERE=$(dirname "$0")
STUDIES="steel-on-bitumen ptfe-pom permanent-contact-shccl permanent-contact-bwshccl permanent-contact-bwmcl"
RUNS=11 SCIPY_RUNS=${SCIPY_RUNS:-5}
[ $smoke = 1 ] && { STUDIES="permanent-contact-bwmcl"; RUNS=3; SCIPY_RUNS=1; }
: "${HYBOUNCE_PRESETS:=$(pwd)/presets}"
export HYBOUNCE_PRESETS
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
scipy=1
"$SPY" -c 'import scipy.integrate, numpy' >/dev/null 2>&1 || scipy=0
cg=1
command -v valgrind >/dev/null || cg=0

median() { sort -g | awk '{ v[NR] = $1 } END { if (NR) print v[int((NR + 1) / 2)]; else print "-" }'; }

{
echo "| study | instructions / rhs | rhs | rejected | engine CPU ms | SciPy DOP853 CPU ms | SciPy / engine | true error | largest error bar | e_0 +- bar |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for s in $STUDIES; do
	P=$HYBOUNCE_PRESETS/$s.preset
	echo "studies.sh: $s" >&2
	"$BIN" --batch "$s" -q >"$T/q" 2>&1 || { echo "studies.sh: $s failed" >&2; exit 1; }
	rhs=$(awk '$1 == "evaluations" { print $2 }' "$T/q")
	rej=$(awk '$1 == "steps" && $2 != "=" { print $4 }' "$T/q")
	ipr=-
	if [ $cg = 1 ]; then
		rm -f "$T/cg.out"
		valgrind --tool=callgrind --toggle-collect=hb_sim_advance \
		    --callgrind-out-file="$T/cg.out" "$BIN" --batch "$s" -q >/dev/null 2>&1
		ir=$(awk '$1 == "summary:" || $1 == "totals:" { print $2; exit }' "$T/cg.out" 2>/dev/null)
		# (a sanitizer build does not run under valgrind: "-")
		[ -n "$ir" ] && ipr=$(awk -v i="$ir" -v r="$rhs" 'BEGIN { printf "%.0f", i / r }')
	fi
	i=0
	while [ $i -lt $RUNS ]; do
		"$BIN" --batch "$s" -q 2>/dev/null | awk '$1 == "run" && $2 == "time" {
		    v = $3; u = $4; if (u == "us") v /= 1000; else if (u == "s") v *= 1000; print v }'
		i=$((i + 1))
	done | median >"$T/cpu"
	cpu=$(awk '{ printf "%.3g", $1 }' "$T/cpu")
	sp=- ratio=-
	if [ $scipy = 1 ]; then
		"$SPY" "$HERE/scipy_ref.py" --max-step 1e-3 --runs $SCIPY_RUNS --json "$T/sc.json" "$P" \
		    >/dev/null 2>&1 &&
		    sp=$("$SPY" -c 'import json, sys; print("%.1f" % (1e3 * json.load(open(sys.argv[1]))["cpu_s"]))' "$T/sc.json") &&
		    ratio=$(awk -v a="$sp" -v b="$cpu" 'BEGIN { printf "%.0fx", a / b }')
	fi
	true_err=-
	if [ -r "tests/reference/$s.csv" ]; then
		"$BIN" --batch "$s" --collisions - 2>/dev/null >"$T/c.csv"
		true_err=$($PY tests/reference/agree.py --max "tests/reference/$s.csv" "$T/c.csv")
	fi
	"$BIN" --batch "$s" --error --check -q >"$T/e" 2>&1
	bar=$(sed -n 's/.*error bars: ok (the largest is \([^ ]*\) x rtol.*/\1/p' "$T/e")
	rtol=$(awk -F' *= *' '$1 == "rtol" { print $2 }' "$P")
	bar=$(awk -v b="$bar" -v r="$rtol" 'BEGIN { if (b == "") print "-"; else printf "%.2g", b * r }')
	e0=$(sed -n 's/.*e_first = \([^,]*\),*$/\1/p; s/.*e_first = \([^,]*\), .*/\1/p' "$T/e" | head -1)
	echo "| $s | $ipr | $rhs | $rej | $cpu | $sp | $ratio | $true_err | $bar | $e0 |"
done
} >"$OUT"
cat "$OUT"
