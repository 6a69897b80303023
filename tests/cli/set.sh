#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# --set is read by one function (hb_preset_open) for both front ends: the batch
# run and the explorer accept the same overrides (blanks around the key and
# the value are ignored) and refuse the same ones with the same message and
# exit status 2.
. "$(dirname "$0")/common.inc"

# blanks: the same run as without them
a=$("$BIN" --batch hertz-elastic --set ' run.T = 1 ms' --quiet 2>&1 | grep 'ended')
b=$("$BIN" --batch hertz-elastic --set 'run.T=1 ms' --quiet 2>&1 | grep 'ended')
if [ -n "$a" ] && [ "$a" = "$b" ] && echo "$a" | grep -q 'T = 0.001 s'; then
	ok "batch: --set ' run.T = 1 ms' is run.T=1 ms ($a)"
else
	notok "batch: --set ' run.T = 1 ms' is run.T=1 ms ('$a' vs '$b')"
fi

for set in 'run.T=-1 s' ' run.T = -1 s' 'run.T' '=1' 'law.nosuch=1' 'run.stepper=euler' \
    'initial.x0=1 kg' 'law.alpha=2' 'scene.name=a ; b' 'run.J=2.5'; do
	mb=$("$BIN" --batch hertz-elastic --set "$set" 2>&1 >/dev/null)
	rb=$?
	me=$("$BIN" hertz-elastic --set "$set" 2>&1 </dev/null >/dev/null)
	re=$?
	if [ "$rb" -eq 2 ] && [ "$re" -eq 2 ] && [ -n "$mb" ] && [ "$mb" = "$me" ]; then
		ok "--set '$set': batch and explorer refuse it alike, exit 2 ($mb)"
	else
		notok "--set '$set': batch and explorer refuse it alike (batch $rb '$mb', explorer $re '$me')"
	fi
done
exit $((fails > 0))
