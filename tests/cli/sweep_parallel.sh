#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce sweep --emit parallel, run for real with GNU parallel on the local
# cores (and through --sshlogin ':', parallel's name for this machine): the
# merged files equal the one-machine sweep's.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"
if ! command -v parallel >/dev/null 2>&1; then
	notok "GNU parallel is installed (make deps installs it)"
	exit 0
fi
# parallel's one-time citation notice stays out of the test's way.
export HOME="$T/home"
mkdir -p "$HOME/.parallel" && touch "$HOME/.parallel/will-cite"

P=permanent-contact-shccl
set -- --vary "initial.x0=5um:60um:12" --vary "law.c=1e9,4.3e9"
"$BIN" sweep $P "$@" --quiet --out "$T/one" 2>"$T/err" || notok "one-machine sweep" "$T/err"

"$BIN" sweep $P "$@" --out "$T/par" --emit parallel --shards 5 >"$T/cmd" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && [ "$(wc -l <"$T/cmd")" -eq 1 ] && grep -q '^parallel .* --shard {}/5 ::: 0 1 2 3 4 && .* sweep --quiet --merge ' "$T/cmd" &&
    [ -f "$T/par/sweep.preset" ] && [ ! -f "$T/par/runs.csv" ]; then
	ok "--emit parallel prints one command line (5 shards, then --merge) and writes sweep.preset"
else notok "--emit parallel prints one command line (exit $rc)" "$T/cmd"; fi
timeout 120 sh -c "$(cat "$T/cmd")" >"$T/out" 2>&1
rc=$?
if [ $rc -eq 0 ] && same_sweep "$T/one" "$T/par" && [ -f "$T/par/shard-4-of-5.journal" ]; then
	ok "GNU parallel runs the 5 shards and the merge: files equal the one-machine sweep"
else notok "GNU parallel runs the shards and the merge (exit $rc)" "$T/out"; fi

"$BIN" sweep $P "$@" --out "$T/ssh" --emit parallel --shards 3 --sshlogin ':' >"$T/cmd" 2>"$T/err"
if grep -q "^parallel --halt now,fail=1 --sshlogin ':' " "$T/cmd" &&
    timeout 120 sh -c "$(cat "$T/cmd")" >"$T/out" 2>&1 && same_sweep "$T/one" "$T/ssh"; then
	ok "--emit parallel --sshlogin ':' (this machine as an ssh login) gives the same files"
else notok "--emit parallel --sshlogin ':' gives the same files" "$T/out"; cat "$T/cmd" | sed 's/^/# /'; fi
exit 0
