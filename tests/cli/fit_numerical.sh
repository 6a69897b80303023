#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce fit: each estimate's numerical error (fit.h: the residuals at
# the estimates made again with rk8pd at run.rtol / 100, carried through
# the Jacobian) beside its standard error, in the report and in --report's
# JSON; against the truth (a fit at a loose tolerance lands within 0.1 to
# 10 x the numerical error it states of the fit at the preset's); a fit
# whose numerical error is not well below its standard error is not
# credible (exit 1, named), the estimates still written.
. "$(dirname "$0")/common.inc"

FIT="$BIN fit steel-on-bitumen --free law.c,law.alpha -q"
grep -v '^#' examples/fit/bounces.csv >"$T/stated.csv"
awk -F, 'NR == 1 { print; next } { print $1 ",30e-9" }' "$T/stated.csv" >"$T/tiny.csv"

# 1. At the preset's tolerance: a column, a line saying how, the JSON fields.
$FIT --data "$T/stated.csv" --out "$T/a.preset" --report "$T/a.json" >"$T/a.out" 2>"$T/a.err"
rc=$?
if [ $rc -eq 0 ] && grep -q '^  key .* std error .* numerical  unit$' "$T/a.out" &&
    grep -q '^  numerical: how far each estimate moves when the runs are made at rtol 1e-14 (rk8pd' "$T/a.out" &&
    python3 - "$T/a.json" <<'PY' >"$T/a.py" 2>&1
import json, sys
r = json.load(open(sys.argv[1]))
assert r["numerical_rtol"] == 1e-14, r["numerical_rtol"]
for p in r["parameters"]:
    assert 0 < p["numerical_error"] < 0.1 * p["se"], p
    assert p["numerical_well_below_se"] is True, p
assert r["credible"] and "numerical_failed" not in r
PY
then
	ok "fit: every estimate has a numerical error, well below its standard error, in the report and the JSON (exit 0)"
else notok "fit: the numerical error in the report and the JSON (exit $rc)" "$T/a.py"; cat "$T/a.out" | show /dev/stdin 30; fi

# 2. Against the truth: at run.rtol 1e-4 the estimates lie within 0.1 to
# 10 x their stated numerical error of those at the preset's tolerance.
$FIT --set run.rtol=1e-4 --data "$T/stated.csv" --out "$T/b.preset" --report "$T/b.json" \
    >"$T/b.out" 2>"$T/b.err"
rc=$?
if [ $rc -eq 0 ] && python3 - "$T/a.json" "$T/b.json" <<'PY' >"$T/b.py" 2>&1
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
assert b["numerical_rtol"] == 1e-6, b["numerical_rtol"]
for pa, pb in zip(a["parameters"], b["parameters"]):
    moved, said = abs(pb["value"] - pa["value"]), pb["numerical_error"]
    assert 0.1 * said <= moved <= 10 * said, (pb["key"], moved, said)
    print(pb["key"], moved, said)
PY
then
	ok "fit at run.rtol 1e-4: each estimate lies within 0.1 to 10 x its numerical error of the preset tolerance's ($(tr '\n' ' ' <"$T/b.py"))"
else notok "fit at run.rtol 1e-4 against the preset's tolerance (exit $rc)" "$T/b.py"; fi

# 3. Not well below: sd of 30 ns make the standard errors a thousandth of the
# numerical error at run.rtol 1e-4: not credible, named, still written.
$FIT --set run.rtol=1e-4 --data "$T/tiny.csv" --out "$T/c.preset" --report "$T/c.json" \
    >"$T/c.out" 2>"$T/c.err"
rc=$?
if [ $rc -eq 1 ] && grep -q '^hybounce fit: not credible: the numerical error of law.c is .*, not well below its standard error .* (above 0.1 of it): the tolerance, not the data, limits the estimate; expected a smaller run.rtol$' "$T/c.err" &&
    grep -q '^  law.c .*  NUMERICAL ERROR NOT WELL BELOW SE$' "$T/c.out" && [ -s "$T/c.preset" ] &&
    python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
assert not r["credible"] and r["exit_status"] == 1
assert all(p["numerical_well_below_se"] is False for p in r["parameters"])
assert any("numerical error of law.c" in x for x in r["reasons"])' "$T/c.json" 2>"$T/c.py"; then
	ok "fit: a numerical error not well below the standard error is not credible (exit 1, named, the estimates written)"
else notok "fit: a numerical error not well below the standard error (exit $rc)" "$T/c.err"; show "$T/c.py"; fi
[ "$fails" -eq 0 ]
