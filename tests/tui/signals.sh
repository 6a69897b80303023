#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# How the explorer ends: Ctrl-C, SIGTERM, Ctrl-\ (SIGQUIT) and SIGHUP
# restore the terminal (cursor shown, alternate screen left) and exit with
# 128 + the signal; without a terminal on standard input or output it
# refuses at once with status 2, pointing at --batch and --script.
# tmux keeps each pane open after the program so that its terminal state
# can be read (#{alternate_on}, #{cursor_flag}).  Needs HYBOUNCE_BIN.
. "$(dirname "$0")/common.inc"

# run NAME: the explorer in a pane that stays open; its pid in NAME.pid
run() {
	printf 'echo $$ > "%s/%s.pid"\nexec "%s" "$@"\n' "$TMP" "$1" "$BIN" >"$TMP/run-$1.sh"
	rm -f "$TMP/$1.rc"
	$TM new-session -d -s "$1" -x 80 -y 24 \
	    "cd '$TMP' && sh '$TMP/run-$1.sh'; echo \$? > '$TMP/$1.rc'; printf 'after-exit\\n'; sleep 60"
}
# restored NAME: the pane is back on the normal screen with the cursor shown
restored() {
	wait_for "$1" '^after-exit' 30 \
	&& [ "$($TM display -p -t "$1" '#{alternate_on}#{cursor_flag}')" = 01 ]
}

for case in "C-c INT 130" "TERM TERM 143" 'C-\ QUIT 131' "HUP HUP 129"; do
	set -- $case
	how=$1 sig=$2 want=$3
	s=$(echo "$sig" | tr 'A-Z' 'a-z')
	run "$s"
	if wait_for "$s" '^x\[mm\]' 100 \
	   && [ "$($TM display -p -t "$s" '#{alternate_on}#{cursor_flag}')" = 10 ]; then
		case $how in
		C-*) keys "$s" "$how" ;;
		*) kill -"$sig" "$(cat "$TMP/$s.pid")" ;;
		esac
		if wait_exit "$s" 50 && [ "$(cat "$TMP/$s.rc")" = "$want" ] && restored "$s"; then
			ok "SIG$sig ($how): terminal restored (cursor shown, normal screen), exit status $want"
		else
			notok "SIG$sig ($how): terminal restored and exit $want (rc $(cat "$TMP/$s.rc" 2>/dev/null), state $($TM display -p -t "$s" '#{alternate_on}#{cursor_flag}'))" "$s"
		fi
	else
		notok "SIG$sig: the explorer starts on the alternate screen with the cursor hidden" "$s"
	fi
	$TM kill-session -t "$s" 2>/dev/null
done

# q: status 0 and the terminal restored too
run q
wait_for q '^x\[mm\]' 100
keys q q
if wait_exit q 50 && [ "$(cat "$TMP/q.rc")" = 0 ] && restored q; then
	ok "q: terminal restored, exit status 0"
else
	notok "q: terminal restored, exit status 0" q
fi

# no terminal: refused at once, status 2
timeout 10 "$BIN" </dev/null >"$TMP/out" 2>"$TMP/err"
rc=$?
if [ "$rc" = 2 ] && grep -q 'standard input is not one' "$TMP/err" && grep -q -- '--batch' "$TMP/err" \
   && grep -q -- '--script' "$TMP/err" && [ ! -s "$TMP/out" ]; then
	ok "standard input not a terminal: exit 2 at once, pointing at --batch and --script"
else
	notok "standard input not a terminal: exit 2 (rc $rc: $(cat "$TMP/err"))"
fi
rm -f "$TMP/o.rc"
$TM new-session -d -s o -x 80 -y 24 "cd '$TMP' && '$BIN' >'$TMP/o.out'; echo \$? > '$TMP/o.rc'; sleep 60"
if wait_exit o 100 && [ "$(cat "$TMP/o.rc")" = 2 ] && wait_for o 'standard output is not one' 30 \
   && [ ! -s "$TMP/o.out" ]; then
	ok "standard output not a terminal: exit 2 with the message on the terminal"
else
	notok "standard output not a terminal: exit 2 (rc $(cat "$TMP/o.rc" 2>/dev/null))" o
fi
exit $((failed > 0))
