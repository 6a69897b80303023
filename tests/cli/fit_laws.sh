#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce fit --laws: every law fitted to the same data and ranked by AIC.
# On synthetic data from one law (the README's sequence, made by BWMCL; a
# sequence made here by SHCCL) the generating law ranks first, exits 0 and
# is the law of the fitted preset; the JSON report (parsed by python3 json)
# lists the laws in the order of their AIC; the exit status is the best
# law's verdict; LAW:KEY prefixes of --free and --set, and what is refused.
. "$(dirname "$0")/common.inc"

FIT="$BIN fit steel-on-bitumen"

# check.py REPORT LAW...: the laws ranked as given, AIC as stated, the best first
cat >"$T/check.py" <<'PY'
import json, math, sys
r = json.load(open(sys.argv[1]))
laws = [l["law"] for l in r["laws"]]
assert laws == sys.argv[2:], laws
assert r["best"] == laws[0]
aic = [l["aic"] for l in r["laws"]]
assert aic == sorted(aic), aic
for l in r["laws"]:
    assert abs(l["aic"] - (l["cost"] + 2 * l["free_parameters"])) <= 1e-9 * abs(l["aic"])
assert r["exit_status"] == r["laws"][0]["exit_status"]
print(r["exit_status"], r["laws"][0]["credible"])
PY

# --- the README's sequence, made by BWMCL ------------------------------------------
$FIT --data examples/fit/bounces.csv --laws shccl,bwshccl,bwmcl --set bwmcl:law.c=2000 \
	--set bwmcl:law.alpha=0.6 --out "$T/b.preset" --report "$T/b.json" -q >"$T/b.out" 2>"$T/b.err"
rc=$?
if [ "$rc" -eq 0 ] && python3 "$T/check.py" "$T/b.json" bwmcl bwshccl shccl >"$T/b.py" 2>&1 &&
	grep -qx '0 True' "$T/b.py" && grep -q '^  1    bwmcl     2      3.268' "$T/b.out" &&
	grep -q '^best        bwmcl$' "$T/b.out" && grep -q '^law = bwmcl$' "$T/b.preset" &&
	grep -q '^c = 5002.15' "$T/b.preset"; then
	ok "--laws on data made by BWMCL: BWMCL ranks first by AIC, exit 0, its fitted preset written"
else
	notok "--laws on data made by BWMCL: BWMCL ranks first by AIC, exit 0 (exit $rc)" "$T/b.py"
	show "$T/b.out" 40
fi

# --- a sequence made by SHCCL (c = 5e8), 30 us of noise -----------------------------
"$BIN" --batch steel-on-bitumen --set scene.law=shccl --set law.c=5e8 -q -c "$T/c.csv" >/dev/null 2>&1
python3 -c '
import csv, random, sys
random.seed(21)
rows = list(csv.DictReader(open(sys.argv[1])))[:12]
print("t_e,sd_t_e")
for r in rows:
    print("%.7f,30e-6" % (float(r["t_e"]) + random.gauss(0, 30e-6)))' "$T/c.csv" >"$T/shccl.csv"
$FIT --data "$T/shccl.csv" --laws shccl,bwshccl,bwmcl --set shccl:law.c=2e8 \
	--out "$T/s.preset" --report "$T/s.json" -q >"$T/s.out" 2>"$T/s.err"
rc=$?
if [ "$rc" -eq 0 ] && python3 "$T/check.py" "$T/s.json" shccl bwshccl bwmcl >"$T/s.py" 2>&1 &&
	grep -qx '0 True' "$T/s.py" && grep -q '^law = shccl$' "$T/s.preset" &&
	python3 -c 'import json, sys
l = json.load(open(sys.argv[1]))["laws"][0]["parameters"][0]
assert l["key"] == "law.c" and l["ci95"][0] <= 5e8 <= l["ci95"][1], l' "$T/s.json"; then
	ok "--laws on data made by SHCCL: SHCCL ranks first, its 95% interval holds the truth, exit 0"
else
	notok "--laws on data made by SHCCL: SHCCL ranks first (exit $rc)" "$T/s.py"; show "$T/s.out" 40
fi

# --- the exit status is the best law's verdict --------------------------------------
$FIT --data examples/fit/bounces.csv --laws bwmcl,shccl --set bwmcl:law.c=2000 \
	--set bwmcl:law.alpha=0.6 --max-relative-se 0.0005 --out "$T/v.preset" -q >"$T/v.out" 2>"$T/v.err"
rc=$?
if [ "$rc" -eq 1 ] && grep -q '^hybounce fit: not credible (the best law, bwmcl): the standard error of law.c' "$T/v.err" &&
	[ -f "$T/v.preset" ]; then
	ok "--laws: the best law not credible: exit 1, the reason, its preset still written"
else
	notok "--laws: the best law not credible: exit 1, the reason (exit $rc)" "$T/v.err"
fi

# --- --free LAW:KEY: that law's keys; a plain key for the others --------------------
$FIT --data examples/fit/bounces.csv --laws bwmcl,shccl --free bwmcl:law.c --free law.c \
	--out "$T/f.preset" -q >"$T/f.out" 2>"$T/f.err"
if grep -q '^law         bwmcl: free law.c$' "$T/f.out" && grep -q '^law         shccl: free law.c$' "$T/f.out"; then
	ok "--free LAW:KEY for one law, a plain key for the others"
else
	notok "--free LAW:KEY for one law, a plain key for the others" "$T/f.out"
fi

# --- refused: exit 2, nothing written -------------------------------------------------
refused() { # NAME EXPECTED-MESSAGE ARGS...
	name=$1; want=$2; shift 2
	$FIT --data examples/fit/bounces.csv --out "$T/r.preset" -q "$@" >/dev/null 2>"$T/r.err"
	rc=$?
	if [ "$rc" -eq 2 ] && grep -q -- "$want" "$T/r.err" && [ ! -e "$T/r.preset" ]; then
		ok "refused: $name"
	else
		notok "refused: $name (exit $rc)" "$T/r.err"
	fi
}
refused "a law given twice" "--laws shccl,shccl: shccl given twice; accepted: each law once" --laws shccl,shccl
refused "a law without default keys and no --free" "--laws hertz: no free keys; accepted: --free hertz:KEY" --laws shccl,hertz
refused "an unknown law" "--laws nosuch: " --laws shccl,nosuch
refused "--set for a law not in --laws" "--set bwmcl:law.c=1: the law before ':' is not one of --laws" --laws shccl --set bwmcl:law.c=1
refused "--free for a law not in --laws" "--free bwmcl:law.c: the law before ':' is not one of --laws" --laws shccl --free bwmcl:law.c

# --- the README's example, as printed ------------------------------------------------
sed -n '/^<!-- FIT-LAWS-BEGIN -->$/,/^<!-- FIT-LAWS-END -->$/p' README.md | sed '1,2d;$d' |
	sed '/^    \$ /,/2>\/dev\/null/d' | sed 's/^    //' | sed '$d' >"$T/readme.expected"
$FIT --data examples/fit/bounces.csv --laws shccl,bwshccl,bwmcl --set bwmcl:law.c=2000 \
	--set bwmcl:law.alpha=0.6 --out "$T/fitted.preset" -q 2>/dev/null | sed -n '/^ranked/,$p' |
	sed 's/ *$//' >"$T/readme.got"
if [ -s "$T/readme.expected" ] && cmp -s "$T/readme.expected" "$T/readme.got"; then
	ok "the README's --laws example prints what the README shows"
else
	notok "the README's --laws example prints what the README shows"
	diff "$T/readme.expected" "$T/readme.got" | head -20 | sed 's/^/# /'
fi

[ "$fails" -eq 0 ]
