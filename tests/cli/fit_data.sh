#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Data as instruments and spreadsheets write them (hybounce fit --data):
# units in the header, NA or an empty cell for a missed impact, several
# trials in one file, drop and rebound heights.  The truth is known: the
# data are made from runs of steel-on-bitumen at law.c = 5000 N s/m,
# law.alpha = 0.3 (hybounce --batch --collisions), with Gaussian noise of a
# stated sd (python3, fixed seeds), written the way an instrument would;
# each file is fitted from c = 3000, alpha = 0.5 and must give back the
# truth within 3 standard errors, each under 10% of its estimate, exit 0,
# with the report (--report JSON) counting the points, trials and missed
# values as written.  A file with the same times in ms and in s gives the
# same estimates.  The README's example of a file of heights
# (examples/fit/heights.csv) runs as written and prints what the README
# shows:
#     sh tests/cli/fit_data.sh --update-readme   rewrites that output
. "$(dirname "$0")/common.inc"

command -v python3 >/dev/null 2>&1 || { echo "1..0 # SKIP python3 is not installed"; exit 0; }

TRUTH="--set law.c=5000 --set law.alpha=0.3"
for h in 20 15 10; do
	# shellcheck disable=SC2086
	"$BIN" --batch steel-on-bitumen $TRUTH --set "initial.x0=$h mm" --collisions "$T/c$h.csv" \
		-q >"$T/batch$h.out" 2>&1 || notok "batch run from $h mm" "$T/batch$h.out"
done

# make.py: the data files, from the collisions of the three runs
cat >"$T/make.py" <<'PY'
import csv, random, sys
T = sys.argv[1]
def coll(h):
    return list(csv.DictReader(open("%s/c%d.csv" % (T, h))))
g = 9.81
c20 = coll(20)
te = [float(r["t_e"]) for r in c20][:10]
rnd = random.Random(21)
sd = 30e-6
# units: t_e in ms, sd in us, a byte-order mark
with open(T + "/units.csv", "w", encoding="utf-8-sig") as f:
    f.write("t_e [ms],sd_t_e (us)\n")
    noisy = [t + rnd.gauss(0, sd) for t in te]
    for t in noisy:
        f.write("%.6f,%g\n" % (t * 1e3, sd * 1e6))
with open(T + "/seconds.csv", "w") as f:
    f.write("t_e,sd_t_e\n")
    for t in noisy:
        f.write("%.9f,%.9g\n" % (t, sd))
# NA: impacts 3 and 6 of the same take missed ("NA" and an empty cell), the
# sequence keeps its indices
with open(T + "/na.csv", "w") as f:
    f.write("t_e,sd_t_e\n")
    for i, t in enumerate(noisy):
        v = "NA" if i == 3 else "" if i == 6 else "%.9f" % t
        f.write("%s,%g\n" % (v, sd))
# three trials of the same drop, each its own noise, the first impact of trial 2 missed
with open(T + "/trials.csv", "w") as f:
    f.write("trial,t_e [s],sd_t_e [s]\n")
    for k, name in enumerate(("A", "B", "C")):
        for i, t in enumerate(te[:8]):
            v = "N/A" if (k == 1 and i == 0) else "%.7f" % (t + 0.5 * k + rnd.gauss(0, sd))
            f.write("%s,%s,%g\n" % (name, v, sd))
# heights: drops from 20, 15, 10 mm, the apex after each of 5 impacts, in mm, sd 20 um;
# one apex missed
sdh = 20e-6
with open(T + "/heights.csv", "w") as f:
    f.write("h_0 [mm],h_1 [mm],h_2 [mm],h_3 [mm],h_4 [mm],h_5 [mm],sd_h [mm]\n")
    for h in (20, 15, 10):
        rows = coll(h)
        ap = [(float(r["e"]) * float(r["v_i"])) ** 2 / (2 * g) for r in rows[:5]]
        cells = ["%g" % h] + ["%.5f" % ((a + rnd.gauss(0, sdh)) * 1e3) for a in ap]
        if h == 15:
            cells[4] = "NA" # h_4 of the drop from 15 mm
        f.write(",".join(cells) + ",%g\n" % (sdh * 1e3))
PY
python3 "$T/make.py" "$T" || notok "python3 makes the data files"

# check.py REPORT POINTS TRIALS KIND: the truth within 3 se, each se under 10%
cat >"$T/check.py" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
truth = {"law.c": 5000.0, "law.alpha": 0.3}
assert r["points"] == int(sys.argv[2]), ("points", r["points"])
assert r["trials"] == int(sys.argv[3]), ("trials", r["trials"])
assert r["kind"] == sys.argv[4], r["kind"]
assert r["credible"] and r["exit_status"] == 0, r["reasons"]
for p in r["parameters"]:
    d = abs(p["value"] - truth[p["key"]])
    assert d <= 3 * p["se"], (p["key"], p["value"], p["se"], d / p["se"])
    assert p["relative_se"] < 0.1, (p["key"], p["relative_se"])
if len(sys.argv) > 5:
    idx = sorted(set((q["trial"], q["index"]) for q in r["residuals"]))
    assert idx == eval(sys.argv[5]), idx
PY

FIT="fit steel-on-bitumen --free law.c,law.alpha --set law.c=3000 --set law.alpha=0.5 -q"
# fitone NAME POINTS TRIALS KIND [INDICES]: fits T/NAME.csv and checks its report
fitone() {
	n=$1
	shift
	# shellcheck disable=SC2086
	"$BIN" $FIT --data "$T/$n.csv" --out "$T/$n.preset" --report "$T/$n.json" \
		>"$T/$n.out" 2>"$T/$n.err"
	rc=$?
	if [ "$rc" -eq 0 ] && python3 "$T/check.py" "$T/$n.json" "$@" >"$T/$n.py" 2>&1; then
		ok "$n: fitted back within 3 se of the truth, as $2 $3 of $1 points"
	else
		notok "$n: exit $rc, fitted back within 3 se of the truth" "$T/$n.py"
		show "$T/$n.out" 30
		show "$T/$n.err"
	fi
}

fitone units 9 1 sequence
fitone seconds 9 1 sequence
# the same times in ms (and a BOM) as in s: the same estimates, to 1e-3 se
# (the values differ in their last bits: a millisecond is no power of 2)
if [ -f "$T/units.json" ] && [ -f "$T/seconds.json" ] && python3 - "$T/units.json" "$T/seconds.json" <<'PY'
import json, sys
a, b = (json.load(open(x)) for x in sys.argv[1:3])
for p, q in zip(a["parameters"], b["parameters"]):
    assert abs(p["value"] - q["value"]) <= 1e-3 * q["se"], (p, q)
PY
then ok "t_e [ms] and sd_t_e (us) give what the same times in s give"
else notok "t_e [ms] and sd_t_e (us) give what the same times in s give"
fi
grep -q "10 rows, 9 points, weighted by sd" "$T/units.out" && ok "units: the data line" ||
	notok "units: the data line" "$T/units.out"

fitone na 7 1 sequence "[(1, 1), (1, 2), (1, 4), (1, 5), (1, 7), (1, 8), (1, 9)]"
grep -q "10 rows, 7 points, 2 missed (NA)" "$T/na.out" && ok "na: 2 missed, said so" ||
	notok "na: 2 missed, said so" "$T/na.out"

fitone trials 20 3 sequence
grep -q "3 bouncing sequences (trials, fitted jointly" "$T/trials.out" &&
	ok "trials: the report says how many trials" || notok "trials: the report says how many trials" "$T/trials.out"
# trial B lost its first impact: its clocks align on impact 1, its points are impacts 2..7
if python3 - "$T/trials.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
b = [q["index"] for q in r["residuals"] if q["trial"] == 2]
assert b == [2, 3, 4, 5, 6, 7], b
PY
then ok "trials: a trial whose first impact is missed aligns on its next"
else notok "trials: a trial whose first impact is missed aligns on its next"
fi

fitone heights 14 3 heights "[(1, 1), (1, 2), (1, 3), (1, 4), (1, 5), (2, 1), (2, 2), (2, 3), (2, 5), (3, 1), (3, 2), (3, 3), (3, 4), (3, 5)]"
grep -q "rebound heights of 3 drops" "$T/heights.out" && ok "heights: the data line" ||
	notok "heights: the data line" "$T/heights.out"

# heights need a flight under gravity alone
"$BIN" $FIT --data "$T/heights.csv" --set loads.g=0 --out "$T/g0.preset" >"$T/g0.out" 2>&1
rc=$?
if [ "$rc" -eq 2 ] && grep -q "rebound heights need a flight under gravity alone" "$T/g0.out" &&
	[ ! -e "$T/g0.preset" ]; then
	ok "heights without gravity: refused (exit 2), nothing written"
else
	notok "heights without gravity: exit $rc" "$T/g0.out"
fi

# --- the README's example of heights, run as written in a folder of its own --
readme_example FIT-DATA-EXAMPLE 'example of heights' tests/cli/fit_data.sh "${1:-}"
# and its estimates are those of the truth, within a standard error
if [ -f "$T/readme/heights-fit.preset" ] && awk '
	/^  law.c / && !hc { c = ($3 - 5000) / $4; hc = 1 }
	/^  law.alpha / && !ha { a = ($3 - 0.3) / $4; ha = 1 }
	END { exit !(hc && ha && c * c <= 1 && a * a <= 1) }' "$T/got"; then
	ok "the example of heights: c and alpha within one standard error of the truth"
else
	notok "the example of heights: c and alpha within one standard error of the truth" "$T/got"
fi

[ "$fails" -eq 0 ]
