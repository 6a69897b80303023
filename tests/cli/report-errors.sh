#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Output that cannot be written is an error: the report, --help, --version,
# --list-laws and --list-presets to a full device (/dev/full) or a closed
# standard output exit 2 with "write error on standard output: REASON";
# the export is still written; a reader that goes away (| head, SIGPIPE
# ignored) is no error.
. "$(dirname "$0")/common.inc"

check() { # NAME EXPECTED-REASON ARGS... (stdout already redirected by the caller)
	name=$1 reason=$2 rc=$3
	if [ "$rc" -eq 2 ] && [ "$(grep -c "^hybounce: write error on standard output: $reason\$" "$T/err")" -eq 1 ]; then
		ok "$name: exit 2, says why"
	else
		notok "$name: exit 2, says why (exit $rc)"
		show "$T/err"
	fi
}

if [ -w /dev/full ]; then
	for args in "-b steel-on-bitumen" "-b steel-on-bitumen -q" "-b steel-on-bitumen --jumps" \
	    "--help" "--version" "--list-laws" "--list-presets"; do
		"$BIN" $args >/dev/full 2>"$T/err"
		check "$args >/dev/full" "No space left on device" $?
	done
	# A failed run (exit 1) whose report cannot be written: exit 2.
	"$BIN" -b steel-on-bitumen -q --set run.J=3 >/dev/full 2>"$T/err"
	check "a run that stops at run.J, report to /dev/full" "No space left on device" $?
	# The export is written all the same.
	(cd "$T" && "$BIN" -b steel-on-bitumen -c coll.csv >/dev/full 2>"$T/err")
	rc=$?
	if [ "$rc" -eq 2 ] && [ -s "$T/coll.csv" ] && [ -s "$T/coll.preset" ] &&
	    grep -q '^wrote coll.csv$' "$T/err"; then
		ok "report to /dev/full: the export is still written"
	else
		notok "report to /dev/full: the export is still written (exit $rc)"
		show "$T/err"
	fi
else
	ok "write errors on /dev/full # SKIP /dev/full is not writable here"
fi

for args in "-b steel-on-bitumen" "--help" "--list-laws"; do
	"$BIN" $args >&- 2>"$T/err"
	check "$args with standard output closed" "Bad file descriptor" $?
done
# Closed stdout and an export: the export's file does not take fd 1.
(cd "$T" && rm -f c2.csv && "$BIN" -b steel-on-bitumen -c c2.csv >&- 2>"$T/err")
rc=$?
if [ "$rc" -eq 2 ] && [ "$(head -n 1 "$T/c2.csv" | cut -d, -f1)" = "i" ]; then
	ok "closed standard output and an export: the CSV is intact, exit 2"
else
	notok "closed standard output and an export: the CSV is intact, exit 2 (exit $rc)"
	show "$T/err"
fi

# A reader that stops early, SIGPIPE ignored: no message, the run's status.
(trap '' PIPE; "$BIN" -b steel-on-bitumen 2>"$T/err"; echo $? >"$T/rc") | head -n 1 >/dev/null
if [ "$(cat "$T/rc")" -eq 0 ] && [ ! -s "$T/err" ]; then
	ok "report | head with SIGPIPE ignored: quiet, exit 0"
else
	notok "report | head with SIGPIPE ignored: quiet, exit 0 (exit $(cat "$T/rc"))"
	show "$T/err"
fi
[ "$fails" -eq 0 ]
