#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# steppers.sh BIN OUT.md: every offered stepper's true error against the
# binary128 reference (tests/reference/STUDY.csv) on the five paper
# studies, at rtol 1e-6 ... 1e-12 (atol = rtol / 100): the largest error
# over every collision observable (tests/reference/agree.py --max: t_e and
# t_s relative to t_d, x_c^r to x_c^max, W to |J_Fc v_i| where larger,
# the rest relative; 1 when the collision count differs), and its ratio to
# rk8pd's at the same tolerance.  A run that the scene refuses is shown as
# "refused" (run.limits = no: every stepper is measured, also where the
# scene refuses it, src/core/scene_limits.c).  Run from the top of the tree
# (make bench-steppers).
BIN=${1:-build/hybounce}
OUT=${2:-build/bench/steppers.md}
PY=${PYTHON:-python3}
STUDIES="steel-on-bitumen ptfe-pom permanent-contact-shccl permanent-contact-bwshccl permanent-contact-bwmcl"
STEPPERS="rk8pd dop853 vern98 auto rkf45 rkck msbdf rk4imp bsimp"
TOLS="1e-6 1e-7 1e-8 1e-9 1e-10 1e-11 1e-12"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
: >"$T/all"
for s in $STUDIES; do
	for st in $STEPPERS; do
		for r in $TOLS; do
			a=$(awk "BEGIN { print $r / 100 }")
			if "$BIN" --batch "$s" --set run.stepper=$st --set run.rtol=$r --set run.atol=$a \
			    --set run.limits=no \
			    --collisions - >"$T/c.csv" 2>"$T/err"; then
				e=$($PY tests/reference/agree.py --max "tests/reference/$s.csv" "$T/c.csv")
			elif grep -q 'refused\|accepted' "$T/err"; then
				e=refused
			else
				e=failed
			fi
			echo "$s $st $r $e" >>"$T/all"
		done
	done
done
awk -v studies="$STUDIES" -v steppers="$STEPPERS" -v tols="$TOLS" '
{ err[$1, $2, $3] = $4 }
END {
	ns = split(studies, S, " "); nt = split(steppers, P, " "); nr = split(tols, R, " ")
	printf "| stepper | rtol |"
	for (i = 1; i <= ns; i++) printf " %s |", S[i]
	printf " worst ratio to rk8pd |\n|---|---|"
	for (i = 1; i <= ns; i++) printf "---|"
	printf "---|\n"
	for (p = 1; p <= nt; p++) for (r = 1; r <= nr; r++) {
		printf "| %s | %s |", P[p], R[r]
		worst = 0; any = 0
		for (i = 1; i <= ns; i++) {
			e = err[S[i], P[p], R[r]]; ref = err[S[i], "rk8pd", R[r]]
			if (e == "refused" || e == "failed") { printf " %s |", e; continue }
			q = (ref + 0 > 0) ? e / ref : 0
			printf " %.2g", e
			if (P[p] != "rk8pd") printf " (%.2gx)", q
			printf " |"
			if (q > worst) worst = q
			any = 1
		}
		if (P[p] == "rk8pd") printf " - |\n"
		else if (!any) printf " refused |\n"
		else printf " %.3g%s |\n", worst, (worst > 10 ? " **over 10x**" : "")
	}
}' "$T/all" >"$OUT"
cp "$T/all" "${OUT%.md}.txt"
echo "steppers.sh: $OUT"
