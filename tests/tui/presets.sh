#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Presets are found beside the program (BIN/../presets, as build/hybounce in
# the source tree), not only through ./presets: the explorer started in an
# empty folder with HYBOUNCE_PRESETS unset opens the default preset and
# lists the presets in its picker.  send-keys, then poll capture-pane.
. "$(dirname "$0")/common.inc"
case $BIN in /*) ;; *) BIN=$(pwd)/$BIN ;; esac
if [ ! -d "$(dirname "$BIN")/../presets" ]; then
	echo "ok - # SKIP no presets folder beside $BIN"
	exit 0
fi
mkdir -p "$TMP/elsewhere"
rm -f "$TMP/p.rc"
$TM new-session -d -s p -x 80 -y 24 \
    "cd '$TMP/elsewhere' && env -u HYBOUNCE_PRESETS '$BIN'; echo \$? > '$TMP/p.rc'"
if wait_for p 'steel-on-bitumen bwmcl' 100 && wait_for p 't_e\[ms\]' 30; then
	ok "from another folder, without HYBOUNCE_PRESETS: the default preset opens (found beside the program)"
else
	notok "the default preset is found beside the program" p
fi
keys p o
if wait_for p 'open a preset' 30 && wait_for p 'ptfe-pom' 10 \
   && wait_for p "$(cd "$(dirname "$BIN")/../presets" && pwd -P | sed 's/[.[\*^$]/\\&/g')|/\.\./presets/" 10; then
	ok "the preset picker lists the presets beside the program"
else
	notok "the preset picker lists the presets beside the program" p
fi
keys p Escape
keys p q
wait_exit p 50
out=$(cd "$TMP/elsewhere" && env -u HYBOUNCE_PRESETS "$BIN" --batch ptfe-pom -q 2>&1)
if [ $? = 0 ] && echo "$out" | grep -q '^  collisions'; then
	ok "batch mode from another folder finds ptfe-pom beside the program"
else
	notok "batch mode from another folder finds ptfe-pom ($out)"
fi
exit $((failed > 0))
