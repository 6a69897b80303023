#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# --set is read by one function (hb_preset_open_named) for every front end:
# --batch, sweep, fit and the explorer's command line accept the same
# overrides (blanks around the key and the value are ignored, units
# allowed) and give the same scene, and refuse the same ones with exit
# status 2 and the same message (after the program's own "hybounce sweep: "
# or "hybounce fit: ").  A table: one row per --set form, a column per front
# end.  --vary KEY=SPEC and --free KEY,... take blanks the same way.
. "$(dirname "$0")/common.inc"
export TERM="${TERM:-xterm}"
P=steel-on-bitumen
DATA=$(pwd)/examples/fit/bounces.csv
printf 'e\nEnter\nq\n' >"$T/export.keys"

# scene FILE: a preset without comments, blank lines, names, descriptions and
# the body1.E that fit fits (body2 is a fixed obstacle without E of its own
# in this preset, so only body1's line goes).
scene() { grep -v -e '^;' -e '^$' -e '^name =' -e '^description =' -e '^E = ' "$1"; }

# run FRONTEND SET: $rc, $T/msg (the message without the program's prefix),
# $T/scene.FRONTEND (the scene it opened, when it went on).
run() {
	fe=$1
	rm -rf "$T/w" && mkdir "$T/w"
	case $fe in
	batch) (cd "$T/w" && "$BIN" --batch $P --set "$2" --trace t.csv --quiet) >/dev/null 2>"$T/err" ;;
	sweep) (cd "$T/w" && "$BIN" sweep $P --set "$2" --vary 'run.rtol=1e-7' --out o --emit parallel \
	           --shards 1) >/dev/null 2>"$T/err" ;;
	fit) (cd "$T/w" && "$BIN" fit $P --data "$DATA" --free body1.E --max-iter 1 --set "$2" \
	         --out f.preset --quiet) >/dev/null 2>"$T/err" ;;
	explorer) (cd "$T/w" && "$BIN" $P --set "$2" --ascii --script "$T/export.keys") \
	              </dev/null >/dev/null 2>"$T/err" ;;
	esac
	rc=$?
	sed -e 's/^hybounce sweep: //' -e 's/^hybounce fit: //' -e 's/^hybounce: //' "$T/err" >"$T/msg"
	rm -f "$T/scene.$fe"
	for f in "$T/w/t.preset" "$T/w/o/sweep.preset" "$T/w/f.preset" "$T/w"/$P-*.preset; do
		[ -f "$f" ] && scene "$f" >"$T/scene.$fe"
	done
}
fes="batch sweep fit explorer"

# Accepted forms: each gives the scene of its plain form, in every front end.
n_good=0
while IFS='|' read -r form plain; do
	[ -n "$form" ] || continue
	n_good=$((n_good + 1))
	row="" bad=0
	for fe in $fes; do
		run $fe "$plain"
		mv "$T/scene.$fe" "$T/plain.$fe" 2>/dev/null
		run $fe "$form"
		row="$row $fe $rc"
		# fit stopped at --max-iter 1 exits 1, with the preset written
		if [ "$rc" -gt $([ $fe = fit ] && echo 1 || echo 0) ] || [ ! -s "$T/scene.$fe" ] || ! cmp -s "$T/scene.$fe" "$T/plain.$fe" ||
		    ! cmp -s "$T/scene.$fe" "$T/scene.batch"; then
			bad=1
			show "$T/msg"
		fi
	done
	if [ $bad -eq 0 ]; then
		ok "--set '$form' is --set '$plain' in every front end:$row, one scene"
	else
		notok "--set '$form' is --set '$plain' in every front end:$row"
	fi
done <<'EOF_GOOD'
 run.T = 400 ms|run.T=0.4
run.T=400ms |run.T=0.4
	initial.x0	=	20 mm	|initial.x0=0.02
 body1.R = 2 cm|body1.R=0.02
 law.alpha = 0.25 |law.alpha=0.25
 run.stepper = auto |run.stepper=auto
scene.law = bwmcl|scene.law=bwmcl
EOF_GOOD

# Refused forms: exit 2 and one message everywhere.
n_bad=0
while IFS= read -r form; do
	[ -n "$form" ] || continue
	n_bad=$((n_bad + 1))
	row="" bad=0 first=""
	for fe in $fes; do
		run $fe "$form"
		row="$row $fe $rc"
		if [ -z "$first" ]; then
			first=$(cat "$T/msg")
		fi
		if [ "$rc" -ne 2 ] || [ ! -s "$T/msg" ] || [ "$(cat "$T/msg")" != "$first" ]; then
			bad=1
			show "$T/msg"
		fi
	done
	if [ $bad -eq 0 ]; then
		ok "--set '$form' refused alike:$row ($first)"
	else
		notok "--set '$form' refused alike:$row"
	fi
done <<'EOF_BAD'
run.T=-1 s
 run.T = -1 s
run.T
=1
 = 1
law.nosuch=1
nosuch.key=1
run.stepper=euler
initial.x0=1 kg
law.alpha=2
 law.c = abc
scene.name=a ; b
run.J=2.5
run.T=
body1.R = -2 cm
EOF_BAD
ok "--set forms tried: $n_good accepted and $n_bad refused, each in 4 front ends"

# A preset that is not there: one message too.
row="" first="" bad=0
for fe in $fes; do
	P=no-such-preset run $fe 'run.T=1'
	row="$row $fe $rc"
	[ -z "$first" ] && first=$(cat "$T/msg")
	{ [ "$rc" -eq 2 ] && [ "$(cat "$T/msg")" = "$first" ]; } || bad=1
done
if [ $bad -eq 0 ] && echo "$first" | grep -q "^preset 'no-such-preset': "; then
	ok "a missing preset is refused alike:$row"
else notok "a missing preset is refused alike:$row ($first)" "$T/msg"; fi

# --vary and --free: blanks around keys and values as with --set.
"$BIN" sweep $P --vary ' initial.x0 = 5 mm : 20 mm : 3 ' --vary '	law.c =  0.3,0.4 ' \
    --set run.T=50ms --out "$T/v1" --quiet 2>"$T/err" &&
"$BIN" sweep $P --vary 'initial.x0=5 mm : 20 mm : 3' --vary 'law.c=0.3,0.4' \
    --set run.T=50ms --out "$T/v2" --quiet 2>>"$T/err"
if [ $? -eq 0 ] && same_sweep "$T/v1" "$T/v2"; then
	ok "--vary ' KEY = SPEC ' is --vary KEY=SPEC (same sweep.preset and runs)"
else notok "--vary ' KEY = SPEC ' is --vary KEY=SPEC" "$T/err"; fi
# (one iteration: exit 1, stopped at the cap, the preset written)
"$BIN" fit $P --data "$DATA" --free ' body1.E ,	initial.x0 ' --max-iter 1 --out "$T/f1.preset" \
    --quiet >/dev/null 2>"$T/err"
"$BIN" fit $P --data "$DATA" --free body1.E,initial.x0 --max-iter 1 --out "$T/f2.preset" \
    --quiet >/dev/null 2>>"$T/err"
if [ -s "$T/f1.preset" ] && [ "$(noprov "$T/f1.preset")" = "$(noprov "$T/f2.preset")" ]; then
	ok "--free ' KEY , KEY ' is --free KEY,KEY"
else notok "--free ' KEY , KEY ' is --free KEY,KEY" "$T/err"; fi
[ "$fails" -eq 0 ]
