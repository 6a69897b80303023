#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The README's examples are real: the explorer's screens at 80x24 (the
# plots, the space-time view of a cradle) and the
# batch example are what the program prints now (make readme-examples
# regenerates them; the batch run's CPU time is the one line allowed to
# differ).  Needs HYBOUNCE_BIN; run from the top folder.
set -u
BIN=${HYBOUNCE_BIN:?HYBOUNCE_BIN is not set}
. "$(dirname "$0")/readme.inc"
failed=0
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT INT TERM HUP

if ! locale -a 2>/dev/null | grep -qi '^c\.utf-\?8$'; then
	echo "ok - # SKIP no C.UTF-8 locale for the Braille screen"
else
	readme_block README.md SCREEN >"$T/have"
	readme_screen "$BIN" >"$T/want"
	if [ -s "$T/want" ] && cmp -s "$T/have" "$T/want"; then
		echo "ok - README: the explorer's screen at 80x24 is a real capture ($(grep -c '' "$T/want") lines)"
	else
		echo "not ok - README: the explorer's screen is stale (make readme-examples)"
		diff "$T/have" "$T/want" | head -20 | sed 's/^/# /'
		failed=1
	fi
fi
if ! locale -a 2>/dev/null | grep -qi '^c\.utf-\?8$'; then
	echo "ok - # SKIP no C.UTF-8 locale for the Braille space-time screen"
else
	readme_block README.md SPACETIME >"$T/have"
	readme_spacetime "$BIN" >"$T/want"
	if grep -q 'space-time: 5 bodies, # contact; t = ' "$T/want" && cmp -s "$T/have" "$T/want"; then
		echo "ok - README: the space-time view at 80x24 is a real capture"
	else
		echo "not ok - README: the space-time view's screen is stale (make readme-examples)"
		diff "$T/have" "$T/want" | head -20 | sed 's/^/# /'
		failed=1
	fi
fi
readme_block README.md BATCH | grep -v '  run time  ' >"$T/have"
readme_batch "$BIN" | grep -v '  run time  ' >"$T/want"
if grep -q 'collisions (12 completed)' "$T/want" && cmp -s "$T/have" "$T/want"; then
	echo "ok - README: the batch example is the output of a real run"
else
	echo "not ok - README: the batch example is stale (make readme-examples)"
	diff "$T/have" "$T/want" | head -20 | sed 's/^/# /'
	failed=1
fi
exit $failed
