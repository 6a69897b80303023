#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The engine side by side with the paper's own method (make bench-scipy; a
# benchmark, not a test): on each of the five paper studies,
#  (a) SciPy's simulation time: tests/bench/scipy_ref.py, the paper's method
#      (solve_ivp, DOP853, rtol 1e-11, atol 1e-14), timed around the
#      simulation only (no import, no preset parsing), median of
#      SCIPY_BENCH_RUNS (7) runs, wall clock (perf_counter);
#  (b) hybounce's engine time: the median wall time of `hybounce --batch
#      PRESET` less that of the same run with run.T = 1 ns, both by
#      hyperfine (HYPERFINE_RUNS = 30 runs after 5 warm-up runs), and the
#      batch summary's own in-process CPU time (median of 11 runs);
#  (c) the ratio (a) / (b);
# and that the two compute the same thing: every collision of the SciPy run
# against hybounce's (t_e, t_s, e, x_c^max, F_c^max), at the paper's setting
# and at rtol 1e-13, atol 1e-16, where the two must agree to 1e-6 on every
# observable of every collision (else the script fails: not the same model).
#
#   sh tests/bench/scipy.sh [--smoke] [BIN] [OUTDIR]
#
# --smoke: one study (permanent-contact-bwmcl), 1 SciPy run, 3 hyperfine
# runs: checks that the bench runs (tests/cli/bench_scipy.sh).
# Writes OUTDIR/scipy.md (the table) and prints it.  The Python is
# $SCIPY_PYTHON, by default /usr/bin/python3: Debian's, with python3-scipy.
# SCIPY_MAX_STEP (s, default 1e-3) is SciPy's step bound (see scipy_ref.py).
set -u
smoke=0
[ "${1:-}" = --smoke ] && { smoke=1; shift; }
BIN=${1:-build/hybounce}
OUT=${2:-build/bench}
PY=${SCIPY_PYTHON:-/usr/bin/python3}
HMAX=${SCIPY_MAX_STEP:-1e-3}
HERE=$(dirname "$0")

if ! "$PY" -c 'import scipy.integrate, numpy' >/dev/null 2>&1; then
	echo "make bench-scipy needs Debian's python3-scipy: apt-get install python3-scipy" \
	    "(or make deps-scipy; $PY has no scipy)" >&2
	exit 1
fi
command -v hyperfine >/dev/null || { echo "bench-scipy: hyperfine is missing (make deps)" >&2; exit 1; }
[ -x "$BIN" ] || { echo "bench-scipy: no $BIN (make)" >&2; exit 1; }

if [ $smoke = 1 ]; then
	STUDIES="permanent-contact-bwmcl"
	RUNS=1 HFRUNS=3 HFWARM=1 CPURUNS=3
else
	STUDIES="steel-on-bitumen ptfe-pom permanent-contact-shccl permanent-contact-bwshccl permanent-contact-bwmcl"
	RUNS=${SCIPY_BENCH_RUNS:-7} HFRUNS=${HYPERFINE_RUNS:-30} HFWARM=5 CPURUNS=11
fi
: "${HYBOUNCE_PRESETS:=$(pwd)/presets}"
export HYBOUNCE_PRESETS
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
mkdir -p "$OUT"
load0=$(cut -d' ' -f1-3 /proc/loadavg)

for s in $STUDIES; do
	P=$HYBOUNCE_PRESETS/$s.preset
	echo "bench-scipy: $s" >&2
	# hybounce: the collisions and the end state, for the comparison
	"$BIN" --batch "$P" --collisions "$T/$s.csv" --trace "$T/$s.trace" --quiet >/dev/null 2>&1 ||
	    { echo "bench-scipy: hybounce --batch $s failed" >&2; exit 1; }
	# (b) hybounce: whole run and negligible horizon, side by side
	hyperfine -N --style none --warmup $HFWARM --runs $HFRUNS --export-json "$T/$s.hf.json" \
	    "$BIN --batch $P" "$BIN --batch $P --set run.T=1ns" >/dev/null 2>&1 ||
	    { echo "bench-scipy: hyperfine on $s failed" >&2; exit 1; }
	# the batch summary's in-process CPU time ("run time  X ms CPU, ...")
	i=0
	while [ $i -lt $CPURUNS ]; do
		"$BIN" --batch "$P" --quiet 2>/dev/null | awk '$1 == "run" && $2 == "time" {
		    v = $3; u = $4; if (u == "us") v /= 1000; else if (u == "s") v *= 1000; print v }'
		i=$((i + 1))
	done >"$T/$s.cpu"
	# (a) SciPy, the paper's setting: timing and comparison
	"$PY" "$HERE/scipy_ref.py" --max-step "$HMAX" --runs $RUNS --against "$T/$s.csv" --trace "$T/$s.trace" \
	    --json "$T/$s.scipy.json" "$P" >"$T/$s.scipy.out" 2>&1 ||
	    { echo "bench-scipy: scipy_ref.py $s failed:" >&2; cat "$T/$s.scipy.out" >&2; exit 1; }
	# the same model: at rtol 1e-13, atol 1e-16 the two agree to 1e-6
	"$PY" "$HERE/scipy_ref.py" --max-step "$HMAX" --rtol 1e-13 --atol 1e-16 --against "$T/$s.csv" \
	    --trace "$T/$s.trace" --json "$T/$s.tight.json" "$P" >"$T/$s.tight.out" 2>&1 ||
	    { echo "bench-scipy: scipy_ref.py --rtol 1e-13 $s failed:" >&2; cat "$T/$s.tight.out" >&2; exit 1; }
done
load1=$(cut -d' ' -f1-3 /proc/loadavg)

"$PY" - "$T" "$OUT/scipy.md" "$load0" "$load1" "$RUNS" "$HFRUNS" "$CPURUNS" $STUDIES <<'EOF'
import json, statistics, sys, datetime, os, platform
T, out, load0, load1, runs, hfruns, cpuruns = sys.argv[1:8]
studies = sys.argv[8:]
names = {"steel-on-bitumen": "1, steel on bitumen (BWMCL)",
         "ptfe-pom": "2, PTFE on POM (BWSHCCL, full)",
         "permanent-contact-shccl": "3, SHCCL",
         "permanent-contact-bwshccl": "3, BWSHCCL",
         "permanent-contact-bwmcl": "3, BWMCL"}
cpu = "?"
try:
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
except OSError:
    pass
rows, bad = [], []
for s in studies:
    sc = json.load(open(os.path.join(T, s + ".scipy.json")))
    ti = json.load(open(os.path.join(T, s + ".tight.json")))
    hf = json.load(open(os.path.join(T, s + ".hf.json")))["results"]
    full, neg = hf[0]["median"], hf[1]["median"]
    eng = full - neg
    cpus = [float(x) for x in open(os.path.join(T, s + ".cpu")) if x.strip()]
    a, b = sc["against"], ti["against"]
    worst = max(b[k] for k in ("t_e", "t_s", "e", "x_c_max", "F_c_max"))
    if a["n_scipy"] != a["n_hybounce"] or b["n_scipy"] != b["n_hybounce"] or not worst <= 1e-6:
        bad.append(s)
    rows.append((names.get(s, s), sc, full, neg, eng, statistics.median(cpus), a, b, worst))

L = []
L.append("# hybounce against the paper's own method (make bench-scipy)")
L.append("")
L.append("%s UTC; %s, %d online processors; load average %s before, %s after; "
         "Python %s, SciPy %s, NumPy %s." % (
             datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M"), cpu, os.cpu_count(),
             load0, load1, platform.python_version(),
             __import__("scipy").__version__, __import__("numpy").__version__))
L.append("")
L.append("SciPy: tests/bench/scipy_ref.py, solve_ivp DOP853 rtol 1e-11 atol 1e-14 "
         "max_step %g s, wall time of the simulation alone, median of %s runs. "
         "hybounce: the presets (rk8pd rtol 1e-12 atol 1e-14); engine = median wall "
         "time of `hybounce --batch PRESET` less that of the same run with "
         "`--set run.T=1ns` (hyperfine -N, %s runs each); CPU = the batch summary's "
         "in-process CPU time (median of %s). Differences: the largest relative "
         "difference over the collisions between the two programs, at the paper's "
         "setting and (in brackets) with SciPy at rtol 1e-13 atol 1e-16."
         % (rows[0][1]["h_max"], runs, hfruns, cpuruns))
L.append("")
L.append("| study | SciPy ms | hybounce engine ms | ratio | hybounce CPU ms | "
         "batch / T = 1 ns ms | collisions SciPy / hybounce | e | t_e | "
         "t_s, x_c^max, F_c^max | SciPy steps / rhs |")
L.append("|---|---|---|---|---|---|---|---|---|---|---|")
for name, sc, full, neg, eng, cpum, a, b, worst in rows:
    L.append("| %s | %.1f | %.3f | %.0fx | %.3f | %.2f / %.2f | %d / %d | %.1e (%.1e) | "
             "%.1e (%.1e) | %.1e (%.1e) | %d / %d |" % (
                 name, 1e3 * sc["wall_s"], 1e3 * eng, sc["wall_s"] / eng, cpum,
                 1e3 * full, 1e3 * neg, a["n_scipy"], a["n_hybounce"], a["e"], b["e"],
                 a["t_e"], b["t_e"], max(a["t_s"], a["x_c_max"], a["F_c_max"]),
                 max(b["t_s"], b["x_c_max"], b["F_c_max"]),
                 sc["stats"]["steps"], sc["stats"]["nfev"]))
L.append("")
if bad:
    L.append("NOT THE SAME MODEL: at rtol 1e-13 the collisions of %s differ from "
             "hybounce's by more than 1e-6 (or in number)." % ", ".join(bad))
else:
    L.append("Same model: at rtol 1e-13 every collision of every study agrees with "
             "hybounce's to 1e-6 or better on t_e, t_s, e, x_c^max and F_c^max.")
text = "\n".join(L) + "\n"
open(out, "w").write(text)
sys.stdout.write(text)
sys.exit(1 if bad else 0)
EOF
