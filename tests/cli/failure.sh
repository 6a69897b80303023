#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A run that fails numerically exits 1, says why on stderr (after the
# report), still prints the table and the summary, and still writes what it
# computed.  The failure is provoked with a step bound far below what the
# integrator can take (run.h_max = 1e-300 s).
. "$(dirname "$0")/common.inc"

"$BIN" -b steel-on-bitumen --set run.h_max=1e-300 -t "$T/arc.csv" -c "$T/coll.csv" \
    >"$T/out" 2>"$T/err"
rc=$?
if [ "$rc" -eq 1 ]; then ok "a numerical failure exits 1"
else notok "a numerical failure exits 1 (got $rc)"; sed 's/^/# /' "$T/err" | head -n 5; fi
if grep -q '^hybounce: the run failed: .*(t = .*j = ' "$T/err"; then
	ok "the failure is explained on stderr with its (t, j)"
else
	notok "the failure is explained on stderr with its (t, j)"
	sed 's/^/# /' "$T/err" | head -n 5
fi
if grep -q '^  ended       failed' "$T/out" && grep -q '^collisions (' "$T/out"; then
	ok "the table and the summary are still printed"
else
	notok "the table and the summary are still printed"
fi
if [ "$(wc -l <"$T/arc.csv" 2>/dev/null || echo 0)" -ge 2 ] && [ -s "$T/coll.csv" ] &&
    [ -s "$T/arc.preset" ]; then
	ok "what was computed is still written (arc, collisions, preset)"
else
	notok "what was computed is still written (arc, collisions, preset)"
fi

[ "$fails" -eq 0 ]
