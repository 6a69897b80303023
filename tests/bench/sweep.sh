#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The sweep's speed targets (make bench-sweep; a benchmark, not a test):
#  1. rate: the third study's SHCCL preset (permanent-contact-shccl) over
#     N points (initial.x0 from 5 um to 60 um) with --jobs 1 and --jobs 2;
#     target on 2 cores: jobs 2 >= 1.8 x the rate of jobs 1 (wall clock, so
#     a loaded machine shows less: the load average is reported beside it);
#  2. overhead: the CPU time of the whole command (user + sys: start-up,
#     validation of every point, threads, journal, merge) beyond the sum of
#     the points' own CPU time (cpu_s of runs.csv); target < 10 %;
#  3. memory: the peak resident set of sweeps of M/10 and M points of the
#     one-collision restitution example; flat: the same to within a few MB.
#
#   sh tests/bench/sweep.sh [--smoke] [BIN] [OUTDIR]
#
# --smoke: 40 and 200 points, to check that the bench runs (make check).
# Prints the report and writes it to OUTDIR/sweep.txt.
set -u
smoke=0
[ "${1:-}" = --smoke ] && { smoke=1; shift; }
BIN=${1:-build/hybounce}
OUT=${2:-build/bench}
: "${HYBOUNCE_PRESETS:=$(pwd)/presets}"
export HYBOUNCE_PRESETS
if [ $smoke = 1 ]; then N=40; M=200; else N=${SWEEP_BENCH_POINTS:-2000}; M=${SWEEP_BENCH_MEMORY_POINTS:-100000}; fi
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
mkdir -p "$OUT"
REPORT="$OUT/sweep.txt"

# run NAME ARGS...: wall, user+sys CPU, peak RSS of hybounce sweep ARGS --out $T/NAME
run() {
	name=$1
	shift
	/usr/bin/time -f '%e %U %S %M' -o "$T/$name.time" "$BIN" sweep "$@" --quiet --out "$T/$name" ||
	    { echo "bench: sweep $name failed" >&2; exit 1; }
	read -r wall user sys rss <"$T/$name.time"
	points=$(awk -F, 'NR > 1 { s += $NF; n++ } END { printf "%.6f %d", s, n }' "$T/$name/runs.csv")
	set -- $points
	echo "$wall $user $sys $rss $1 $2"
}

{
echo "hybounce sweep benchmark ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) online processors, load average $(cut -d' ' -f1-3 /proc/loadavg))"
echo
r1=$(run j1 permanent-contact-shccl --vary "initial.x0=5um:60um:$N" --jobs 1)
r2=$(run j2 permanent-contact-shccl --vary "initial.x0=5um:60um:$N" --jobs 2)
echo "$r1 $r2" | awk -v n="$N" '{
	rate1 = n / $1; rate2 = n / $7
	printf "1. rate, permanent-contact-shccl, %d points\n", n
	printf "   --jobs 1: %.2f s wall, %.1f points/s\n", $1, rate1
	printf "   --jobs 2: %.2f s wall, %.1f points/s\n", $7, rate2
	printf "   speed-up %.2f x (target >= 1.8 x on 2 free cores)\n\n", rate2 / rate1
	cpu = $2 + $3; own = $5
	printf "2. overhead per point (--jobs 1): command CPU %.3f s, points own CPU %.3f s\n", cpu, own
	printf "   overhead %.1f %% of the points own time, %.1f us per point (target < 10 %%)\n", \
	    100 * (cpu - own) / own, 1e6 * (cpu - own) / n
	cpu = $8 + $9; own = $11
	printf "   --jobs 2: command CPU %.3f s, points own CPU %.3f s, overhead %.1f %%\n\n", \
	    cpu, own, 100 * (cpu - own) / own
}'
m1=$((M / 10))
a=$(run m1 examples/sweeps/restitution-shccl.preset --vary "initial.v0=-1mm/s:-1m/s:$m1:log" --jobs 2)
b=$(run m2 examples/sweeps/restitution-shccl.preset --vary "initial.v0=-1mm/s:-1m/s:$M:log" --jobs 2)
echo "$a $b" | awk '{
	printf "3. memory, examples/sweeps/restitution-shccl, --jobs 2\n"
	printf "   %7d points: peak RSS %6.1f MB (%.1f s wall)\n", $6, $4 / 1024, $1
	printf "   %7d points: peak RSS %6.1f MB (%.1f s wall)\n", $12, $10 / 1024, $7
	printf "   growth %.1f MB for %.0f x the points\n", ($10 - $4) / 1024, $12 / $6
}'
} | tee "$REPORT"
