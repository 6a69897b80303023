#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The physics checks in batch mode (issue 10): a run that creates energy
# (hard-bouc-wen-beta with bsimp at rtol 1e-3: W < 0, e up to 1.317) is
# warned about, exit 0; with --check it is a failure, exit 1; a good run
# says "physics: ok" under --check; a contact from rest is explained.
. "$(dirname "$0")/common.inc"
notok() { echo "not ok - $1"; fails=$((fails + 1)); sed 's/^/# /' "$T/err" "$T/out" | tail -n 8; }
LOOSE="--set run.stepper=bsimp --set run.rtol=1e-3 --set run.atol=1e-3"

# shellcheck disable=SC2086
"$BIN" -b hard-bouc-wen-beta $LOOSE -q >"$T/out" 2>"$T/err"
rc=$?
if [ "$rc" -eq 0 ] && grep -q '^  warning     physics: .*passivity: collision [0-9]* returns energy, W = -' "$T/out" &&
    grep -q 'restitution: collision [0-9]* has e = 1\.' "$T/out" &&
    grep -q '^hybounce: warning: the computed run fails 3 physics checks' "$T/err"; then
	ok "a run that creates energy is warned about (report and stderr), exit 0"
else
	notok "a run that creates energy is warned about (report and stderr), exit 0 (got $rc)"
fi
# shellcheck disable=SC2086
"$BIN" -b hard-bouc-wen-beta $LOOSE -q --check >"$T/out" 2>"$T/err"
rc=$?
if [ "$rc" -eq 1 ] && grep -q '^  check       physics: FAILED: ' "$T/out" &&
    grep -q '^hybounce: check failed: the computed run fails' "$T/err"; then
	ok "--check makes it a failure, exit 1"
else
	notok "--check makes it a failure, exit 1 (got $rc)"
fi
"$BIN" -b hard-slow-impact-hertz --set run.stepper=bsimp --set run.rtol=1e-8 --set run.atol=1e-8 --set run.limits=no \
    -q >"$T/out" 2>"$T/err"
if grep -q 'elastic law\|restitution: collision 0 has e = .* where the elastic hertz gives exactly' "$T/out"; then
	ok "an elastic contact's error beyond the tolerance is said"
else
	notok "an elastic contact's error beyond the tolerance is said"
fi
"$BIN" -b steel-on-bitumen -q --check >"$T/out" 2>"$T/err"
rc=$?
if [ "$rc" -eq 0 ] && grep -q '^  check       physics: ok (work-energy residual' "$T/out" &&
    ! grep -q 'warning' "$T/out" "$T/err"; then
	ok "a good run passes the physics checks"
else
	notok "a good run passes the physics checks (got $rc)"
fi
"$BIN" -b steel-on-bitumen -q >"$T/out" 2>"$T/err"
if ! grep -q 'physics' "$T/out" "$T/err"; then
	ok "a good run without --check says nothing more"
else
	notok "a good run without --check says nothing more"
fi
"$BIN" -b nonunique-separation --set initial.x0=0 --set initial.v0=-1e-300 --set loads.F1=1 \
    >"$T/out" 2>"$T/err"
if grep -q '^  note        collision 0 began at zero approach velocity (v_i = -1e-300 m/s' "$T/out"; then
	ok "a contact from rest: its meaningless e is explained"
else
	notok "a contact from rest: its meaningless e is explained"
fi

[ "$fails" -eq 0 ]
