#!/bin/sh
# The explorer opens a preset with --set as batch mode does (one function,
# preset_open): blanks around the key and the value are ignored, so
# --set ' run.T = 1 ms' gives a 1 ms run: the panel shows T = 1 ms and the
# time axis ends at 1.0 ms.
. tests/tui/common.inc

start a 140 60 hertz-elastic --set "' run.T = 1 ms'"
if wait_for a ' T +1 ms' 50; then
	ok "explorer: --set ' run.T = 1 ms' sets run.T to 1 ms"
else
	notok "explorer: --set ' run.T = 1 ms' sets run.T to 1 ms" a
fi
if wait_for a 't -> .* 1\.0 ms' 50; then
	ok "explorer: the time axis ends at T = 1 ms"
else
	notok "explorer: the time axis ends at T = 1 ms" a
fi
$TM send-keys -t a q
exit $((failed > 0))
