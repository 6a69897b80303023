#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# tui_frame.sh - what the explorer's frame costs against the arc's length,
# on study 1 (steel-on-bitumen) with run.T = 66 s (about 25k samples) and
# 730 s (about 250k), at 100x30:
#   1. instructions per frame drawn (app_draw, inclusive), counted with
#      callgrind in scripted mode (--script: the same drawing code on a
#      screen whose output is /dev/null) on the finished run, the whole run
#      in view as playback shows it: 11 frames less 1 frame, over 10, so
#      that the first frame's one pass over the arc is left out;
#   2. playback's share of a core: the explorer in tmux, playing the
#      finished run for 10 s, its CPU time (utime + stime) over that time;
#   3. computing while drawing against batch: the wall time from start to
#      "finished" in the explorer (in tmux) and of --batch, side by side,
#      three times each: batch / explorer (1: the batch rate).
# 2 and 3 are timings: on a loaded machine they move; 1 is a count.
#
#     sh tests/bench/tui_frame.sh BIN [T ...]        (make bench-tui)
set -u
BIN=${1:?usage: tui_frame.sh BIN [T ...]}
shift
[ $# -gt 0 ] || set -- 66 730
export HYBOUNCE_PRESETS="${HYBOUNCE_PRESETS:-$(pwd)/presets}"
T=$(mktemp -d)
SOCK=hbbench$$
TM="tmux -L $SOCK -f /dev/null"
trap '$TM kill-server 2>/dev/null; rm -rf "$T"' EXIT INT TERM
$TM new-session -d -s keep -x 20 -y 5 "sleep 86400"
HZ=$(getconf CLK_TCK)

now() { date +%s.%N; }
# frame_ir T NDUMP: instructions in app_draw for NDUMP frames after computing the run
frame_ir() {
	{ echo "size 100x30"; echo "wait-finished"; echo "Home"
	  k=0; while [ $k -lt "$2" ]; do echo "dump $T/d$k.txt"; k=$((k + 1)); done; } >"$T/s.txt"
	valgrind --tool=callgrind --toggle-collect=app_draw --collect-atstart=no \
		--callgrind-out-file="$T/cg" "$BIN" --script "$T/s.txt" --set run.T="$1" \
		steel-on-bitumen >/dev/null 2>&1
	sed -n 's/^totals: *\([0-9]*\).*/\1/p; s/^summary: *\([0-9]*\).*/\1/p' "$T/cg" | head -n 1
}
# cpu PID: utime + stime of PID, in clock ticks
cpu() { awk '{ print $14 + $15 }' "/proc/$1/stat"; }
# explorer T: starts it in session e; its pid in $pid once it has finished computing
explorer() {
	$TM new-session -d -s e -x 100 -y 30 "exec '$BIN' --set run.T=$1 steel-on-bitumen"
	while ! $TM capture-pane -p -t e 2>/dev/null | head -n 1 | grep -q ' finished$'; do
		sleep 0.05
	done
	pid=$($TM list-panes -t e -F '#{pane_pid}')
}
quit() {
	$TM send-keys -t e q
	while $TM has-session -t e 2>/dev/null; do sleep 0.05; done
}

for t in "$@"; do
	samples=$("$BIN" --batch steel-on-bitumen --set run.T="$t" 2>/dev/null |
		sed -n 's/^ *arc *\([0-9]*\) samples.*/\1/p')
	ir1=$(frame_ir "$t" 1)
	ir11=$(frame_ir "$t" 11)
	# 2. playback
	explorer "$t"
	$TM send-keys -t e Home ' '
	sleep 1
	c0=$(cpu "$pid")
	sleep 10
	c1=$(cpu "$pid")
	quit
	# 3. computing while drawing
	ratio=
	for rep in 1 2 3; do
		b0=$(now)
		"$BIN" --batch steel-on-bitumen --set run.T="$t" >/dev/null 2>&1
		b1=$(now)
		e0=$(now)
		explorer "$t"
		e1=$(now)
		quit
		ratio="$ratio $(echo "$b0 $b1 $e0 $e1" | awk '{ printf "%.2f", ($2 - $1) / ($4 - $3) }')"
	done
	echo "T = $t s, $samples samples: $(((ir11 - ir1) / 10)) instructions a frame drawn;" \
	     "playback $(echo "$c0 $c1 $HZ" | awk '{ printf "%.1f", 100 * ($2 - $1) / $3 / 10 }')% of a core;" \
	     "computing at batch x$ratio"
done
