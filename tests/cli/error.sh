#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# batch --error: an error bar on every observable (error.h), checked
# against the binary128 reference (tests/reference/): on the five paper
# studies at their presets' tolerance (study 1 and the SHCCL study also at
# rtol 1e-10) every estimate of a true error above 1e-13 lies within
# [0.5, 100] x that error (tests/reference/agree.py --errors); the report prints VALUE +- ERROR, the
# collisions CSV has a NAME_err column per value, and --check fails where
# an error bar exceeds 100 x run.rtol.
. "$(dirname "$0")/common.inc"
PY=${PYTHON:-python3}
AGREE=tests/reference/agree.py

for s in steel-on-bitumen permanent-contact-shccl; do
	for r in 1e-12 1e-10; do
		a=$(awk "BEGIN { print $r / 100 }")
		"$BIN" --batch "$s" --set run.rtol=$r --set run.atol=$a --error \
		    --collisions - >"$T/e.csv" 2>"$T/rep" &&
		    $PY $AGREE --errors "tests/reference/$s.csv" "$T/e.csv" >"$T/out" 2>&1 &&
		    grep -q 'estimates of a true error above 1e-13, 0 outside' "$T/out" &&
		    ! grep -q ' 0 estimates of a true error' "$T/out" &&
		    ok "error: $s at rtol $r: every error bar within [0.5, 100] x the true error ($(grep -o '[0-9]* estimates' "$T/out"))" ||
		    notok "error: $s at rtol $r: error bars against the reference" "$T/out"
	done
done
# the other three studies at their presets' tolerance
for s in ptfe-pom permanent-contact-bwshccl permanent-contact-bwmcl; do
	"$BIN" --batch "$s" --error --collisions - >"$T/e.csv" 2>"$T/rep" &&
	    $PY $AGREE --errors "tests/reference/$s.csv" "$T/e.csv" >"$T/out" 2>&1 &&
	    grep -q 'estimates of a true error above 1e-13, 0 outside' "$T/out" &&
	    ok "error: $s at its tolerance: every error bar within [0.5, 100] x the true error ($(grep -o '[0-9]* estimates' "$T/out"))" ||
	    notok "error: $s: error bars against the reference" "$T/out"
done

# the report: VALUE +- ERROR in the summary, a table of error bars
"$BIN" --batch steel-on-bitumen --error >"$T/rep" 2>"$T/err"
st=$?
[ $st -eq 0 ] && grep -q '^error bars (estimated global error' "$T/rep" &&
    grep -Eq 'e_first = 0\.5899554839[0-9]* \+- [0-9]e-1[0-9]' "$T/rep" &&
    ok "error: the report carries the error bars (e_first = VALUE +- ERROR)" ||
    notok "error: the report carries the error bars (exit $st)" "$T/rep"
# without --error, nothing of it
"$BIN" --batch steel-on-bitumen --collisions "$T/plain.csv" >"$T/rep2" 2>&1
if grep -q '+-\|error bars' "$T/rep2" || head -1 "$T/plain.csv" | grep -q _err; then
	notok "error: no error bars without --error" "$T/rep2"
else
	ok "error: no error bars without --error"
fi

# the CSV: one NAME_err column per value column, a number in each
"$BIN" --batch permanent-contact-shccl --error --collisions "$T/c.csv" >/dev/null 2>&1
h=$(grep -v '^#' "$T/c.csv" | head -1)
nv=$(echo "$h" | tr ',' '\n' | grep -vc '_err$')
ne=$(echo "$h" | tr ',' '\n' | grep -c '_err$')
[ "$ne" -eq $((nv - 1)) ] && echo "$h" | grep -q ',e_err,' &&
    awk -F, 'NR > 1 && $0 !~ /^#/ { for (k = 15; k <= NF; k++) if ($k == "" && k != 18) bad = 1 }
        END { exit bad }' "$T/c.csv" &&
    ok "error: the collisions CSV has $ne NAME_err columns, filled" ||
    notok "error: the collisions CSV's error columns ($nv values, $ne errors)" "$T/c.csv"

# --check: the shipped tolerance passes, a stepper that misses it fails
"$BIN" --batch steel-on-bitumen --error --check -q >"$T/rep" 2>&1 &&
    grep -q 'check       error bars: ok (the largest is' "$T/rep" &&
    ok "error: --check --error passes study 1 at the preset's tolerance" ||
    notok "error: --check --error on study 1" "$T/rep"
"$BIN" --batch steel-on-bitumen --set run.stepper=msbdf --set run.limits=no --error --check -q >"$T/rep" 2>"$T/err"
st=$?
[ $st -eq 1 ] && grep -q 'check       error bars: FAILED: collision [0-9]*: .* above 100 x rtol' "$T/rep" &&
    grep -q 'check failed: collision' "$T/err" &&
    ok "error: --check --error fails msbdf on study 1 (exit 1, naming the collision and the limit)" ||
    notok "error: --check --error on msbdf (exit $st)" "$T/rep"

# --error belongs to --batch
"$BIN" --error steel-on-bitumen >"$T/o" 2>"$T/e"
st=$?
[ $st -eq 2 ] && grep -q -- '--error needs --batch' "$T/e" &&
    ok "error: --error without --batch is refused" ||
    notok "error: --error without --batch (exit $st)" "$T/e"
# --error on a preset that records branches (the explorer's b): refused, as
# the second run would start from t = 0 without them
{ cat "$HYBOUNCE_PRESETS/steel-on-bitumen.preset"; printf '\n[branch 1]\nt = 0.05 s\nj = 1\nx = 0 m\nv = 0 m/s\nx_c = 0 m\ncontact = no\nlaw.c = 44000 N s/m\n'; } >"$T/br.preset"
"$BIN" --batch "$T/br.preset" --error -q >"$T/o" 2>"$T/e"
st=$?
[ $st -eq 2 ] && grep -q -- '--error: .*br.preset records 1 branch .*accepted: --error on a preset without \[branch\] sections' "$T/e" &&
    ok "error: --error on a preset with a branch is refused (exit 2, saying why)" ||
    notok "error: --error on a branched preset (exit $st)" "$T/e"
[ "$fails" -eq 0 ]
