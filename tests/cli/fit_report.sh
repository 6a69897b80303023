#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce fit's report and verdict: --report FILE.json parses (python3
# json) and its numbers agree with what they are derived from (dof = N - P,
# reduced chi-square = cost / dof, AIC and BIC in the form stated, the 95%
# interval value +- t(0.975, dof) se, the chi-square tails), read back to
# the same doubles as --residuals; exit 0 only when credible: residuals
# inconsistent with the stated sd (too large or too small), a fit that did
# not converge, exit 1 with the reason, the estimates still printed and the
# report written; --report goes through the output policy.
. "$(dirname "$0")/common.inc"

FIT="$BIN fit steel-on-bitumen --free law.c,law.alpha --set law.c=2000 --set law.alpha=0.6 -q"
grep -v '^#' examples/fit/bounces.csv >"$T/stated.csv"
awk -F, 'NR == 1 { print; next } { print $1 ",3e-6" }' "$T/stated.csv" >"$T/tight.csv"
awk -F, 'NR == 1 { print; next } { print $1 ",300e-6" }' "$T/stated.csv" >"$T/loose.csv"
awk -F, '{ print $1 }' "$T/stated.csv" >"$T/nosd.csv"

# check.py REPORT [RESIDUALS]: the report's numbers against their definitions
cat >"$T/check.py" <<'PY'
import csv, json, math, sys
r = json.load(open(sys.argv[1]))
def close(a, b, tol=1e-12):
    assert abs(a - b) <= tol * max(1.0, abs(a), abs(b)), (a, b)
def chi2_below(x, k):
    # the regularized lower incomplete gamma P(k/2, x/2), by its series
    a, z = k / 2.0, x / 2.0
    term = s = 1.0 / a
    n = 0
    while term > 1e-17 * s:
        n += 1
        term *= z / (a + n)
        s += term
    return s * math.exp(-z + a * math.log(z) - math.lgamma(a))
N, P, dof, cost = r["points"], r["free_parameters"], r["dof"], r["cost"]
assert (N, P, dof) == (9, 2, 7), (N, P, dof)
close(r["chi2_reduced"], cost / dof)
close(r["t95"], 2.3646242515927844, 1e-9)     # Student's t, 0.975, 7 dof
for p in r["parameters"]:
    close(p["ci95"][0], p["value"] - r["t95"] * p["se"])
    close(p["ci95"][1], p["value"] + r["t95"] * p["se"])
    close(p["relative_se"], p["se"] / abs(p["value"]))
    assert p["at_bound"] is None
assert len(r["correlation"]) == 2
close(r["correlation"][0][0], 1.0, 1e-12)
close(r["correlation"][0][1], r["correlation"][1][0])
if r["noise"]["stated"]:
    assert r["information_criteria"].startswith("least squares with known variance")
    close(r["aic"], cost + 2 * P)
    close(r["bic"], cost + P * math.log(N))
    close(r["noise"]["p_below"], chi2_below(cost, dof), 1e-9)
    close(r["noise"]["p_above"], 1 - chi2_below(cost, dof), 1e-9)
    assert r["noise"]["test_level"] == 0.05
else:
    assert r["information_criteria"].startswith("least squares with unknown variance")
    close(r["aic"], N * math.log(cost / N) + 2 * P)
    close(r["bic"], N * math.log(cost / N) + P * math.log(N))
    assert r["noise"]["p_above"] is None and r["noise"]["verdict"] == "no noise stated"
assert r["credible"] == (r["exit_status"] == 0) == (r["reasons"] == [])
if len(sys.argv) > 2:
    rows = list(csv.DictReader(open(sys.argv[2])))
    assert len(rows) == len(r["residuals"]) == N
    for a, b in zip(rows, r["residuals"]):
        for k in ("measured", "simulated", "sd", "resid"):
            assert float(a[k]) == b[k], (k, a[k], b[k])   # the same doubles
print(r["exit_status"], r["noise"]["verdict"], r["credible"])
PY

# --- stated noise, consistent: exit 0, the report checks out ----------------------
$FIT --data "$T/stated.csv" --out "$T/a.preset" --report "$T/a.json" --residuals "$T/a.res" \
	>"$T/a.out" 2>"$T/a.err"
rc=$?
if [ "$rc" -eq 0 ] && python3 "$T/check.py" "$T/a.json" "$T/a.res" >"$T/a.py" 2>&1 &&
	grep -qx '0 consistent True' "$T/a.py"; then
	ok "--report: the JSON parses and its numbers agree with their definitions; exit 0"
else
	notok "--report: the JSON parses and its numbers agree with their definitions; exit 0 (exit $rc)" "$T/a.py"
fi
if grep -q '^dof         9 points - 2 free parameters = 7 degrees of freedom$' "$T/a.out" &&
	grep -q '^chi-square  reduced 0.46.* stated noise: consistent .*two-sided test at 0.05' "$T/a.out" &&
	grep -q '^AIC, BIC    7.26.* known variance' "$T/a.out" &&
	grep -q '95% interval: t with 7 dof, 2.365 se' "$T/a.out" &&
	grep -q '^wrote .*a.json' "$T/a.err"; then
	ok "the text report shows dof, reduced chi-square and the noise test, AIC/BIC, t intervals"
else
	notok "the text report shows dof, reduced chi-square and the noise test, AIC/BIC, t intervals" "$T/a.out"
fi

# --- residuals 10 times the stated sd; a tenth of it: exit 1, the reason --------
for case in tight:larger:1 loose:smaller:1; do
	name=${case%%:*}; rest=${case#*:}; word=${rest%%:*}
	$FIT --data "$T/$name.csv" --out "$T/$name.preset" --report "$T/$name.json" \
		>"$T/$name.out" 2>"$T/$name.err"
	rc=$?
	if [ "$rc" -eq 1 ] && grep -q "not credible: residuals $word than the stated noise" "$T/$name.err" &&
		grep -q '^  law.c ' "$T/$name.out" && [ -f "$T/$name.preset" ] &&
		python3 "$T/check.py" "$T/$name.json" >"$T/$name.py" 2>&1 &&
		grep -qx "1 residuals $word than the stated noise False" "$T/$name.py"; then
		ok "sd_t_e ${name}: residuals $word than the stated noise: exit 1, the reason, the estimates still printed and written"
	else
		notok "sd_t_e ${name}: residuals $word than the stated noise: exit 1, the reason, the estimates still printed and written (exit $rc)" "$T/$name.err"
	fi
done

# --- no sd: unknown variance, no test; exit 0 -------------------------------------
$FIT --data "$T/nosd.csv" --out "$T/n.preset" --report "$T/n.json" >"$T/n.out" 2>"$T/n.err"
rc=$?
if [ "$rc" -eq 0 ] && python3 "$T/check.py" "$T/n.json" >"$T/n.py" 2>&1 &&
	grep -qx '0 no noise stated True' "$T/n.py" &&
	grep -q 'no test: the data carry no sd' "$T/n.out"; then
	ok "without sd: AIC and BIC of unknown variance, no noise test, exit 0"
else
	notok "without sd: AIC and BIC of unknown variance, no noise test, exit 0 (exit $rc)" "$T/n.py"
fi

# --- not converged: exit 1, the reason in the report ------------------------------
$FIT --data "$T/stated.csv" --max-iter 2 --out "$T/m.preset" --report "$T/m.json" \
	>"$T/m.out" 2>"$T/m.err"
rc=$?
if [ "$rc" -eq 1 ] && grep -q 'not credible: not converged' "$T/m.err" &&
	python3 -c 'import json,sys; r = json.load(open(sys.argv[1]))
assert not r["converged"] and not r["credible"] and r["exit_status"] == 1
assert r["reasons"][0].startswith("not converged")' "$T/m.json" 2>"$T/m.py"; then
	ok "a fit stopped by --max-iter: exit 1, 'not converged' in stderr and the report"
else
	notok "a fit stopped by --max-iter: exit 1, 'not converged' in stderr and the report (exit $rc)" "$T/m.py"
fi

# --- the output policy: --report never the data, never another output ------------
$FIT --data "$T/stated.csv" --out "$T/p.preset" --report "$T/p.preset" >/dev/null 2>"$T/p.err"
rc=$?
$FIT --data "$T/stated.csv" --out "$T/q.preset" --report "$T/stated.csv" >/dev/null 2>"$T/q.err"
rc2=$?
if [ "$rc" -eq 2 ] && [ "$rc2" -eq 2 ] && [ ! -e "$T/p.preset" ] && [ ! -e "$T/q.preset" ] &&
	grep -q '^hybounce fit: --report' "$T/p.err" && grep -q '^hybounce fit: --report' "$T/q.err" &&
	[ "$(grep -c . "$T/stated.csv")" -eq 11 ]; then
	ok "--report the same as --out, or the data: exit 2, nothing written"
else
	notok "--report the same as --out, or the data: exit 2, nothing written (exit $rc, $rc2)" "$T/p.err"
fi

[ "$fails" -eq 0 ]
