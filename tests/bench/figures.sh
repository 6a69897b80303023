#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# make bench-figures: the figure targets, measured side by side.
#
#   - a figure of each paper study (hybounce plot PRESET --out F.png: the
#     run, a 3.5 in figure at 300 dpi, the PNG), whole process, against
#     the same study's batch run (hybounce --batch PRESET -q), timed by
#     hyperfine in one sitting, alternated; the target is under 200 ms;
#   - a 1600x1200 PNG (--size 1600x1200) of each: its bytes, target under
#     300 kB.
#
#     sh tests/bench/figures.sh BIN [RUNS]      (HYBOUNCE_PRESETS as for tests/cli)
#
# Prints a Markdown table: wall time (mean), CPU time (user + system, which
# a loaded machine disturbs less than the wall time) of plot and batch, and
# the PNG's size; then the load average.  On a loaded machine read the CPU
# times and the ratios, not the wall times.
set -u
BIN=${1:-build/hybounce}
RUNS=${2:-10}
case $BIN in /*) ;; *) BIN=$(pwd)/$BIN ;; esac
: "${HYBOUNCE_PRESETS:=$(pwd)/presets}"
export HYBOUNCE_PRESETS
command -v hyperfine >/dev/null 2>&1 || { echo "figures.sh: needs hyperfine (make deps-scipy installs it)" >&2; exit 2; }
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
echo "| study | plot wall | plot CPU | batch wall | batch CPU | 1600x1200 PNG |"
echo "|---|---|---|---|---|---|"
for p in steel-on-bitumen ptfe-pom permanent-contact-bwmcl; do
	hyperfine -N -w 2 -r "$RUNS" --export-json "$T/$p.json" \
		"$BIN plot $p --out $T/$p.png" "$BIN --batch $p -q" >/dev/null 2>&1 || {
		echo "figures.sh: hyperfine failed on $p" >&2; exit 1; }
	"$BIN" plot "$p" --size 1600x1200 --out "$T/$p-big.png" 2>/dev/null
	size=$(wc -c <"$T/$p-big.png")
	python3 - "$T/$p.json" "$p" "$size" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
ms = lambda v: "%.0f ms" % (v * 1000)
cpu = lambda x: x["user"] + x["system"]
print("| %s | %s | %s | %s | %s | %.0f kB |" % (sys.argv[2], ms(r[0]["mean"]), ms(cpu(r[0])),
      ms(r[1]["mean"]), ms(cpu(r[1])), int(sys.argv[3]) / 1000))
EOF
done
echo
echo "load average $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores; $RUNS runs each"
