#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# --script on a real terminal plays on the real screen, for teaching: the
# captions appear on the message line while the run plays, waits take real
# time, a key pressed by the viewer pauses and resumes it, q quits.  A folder given as the
# script is refused.  tmux: send-keys, then poll capture-pane.
. "$(dirname "$0")/common.inc"

cat >"$TMP/lesson" <<EOS
# a lesson: the first study, then what c changes
caption First study: a steel ball dropped on bitumen
wait 1500
/
text:law.c
Enter
caption Now ten times the damping c
Enter
C-u
text:44000
Enter
wait-finished
T
caption Each contact in slow motion
wait 60000
EOS
start a 80 24 --script "$TMP/lesson"
if wait_for a 'First study: a steel ball dropped on bitumen' 50 && wait_for a '^x\[mm\]' 10 \
   && wait_for a 't_e\[ms\]' 10; then
	ok "--script on a terminal plays on the real screen with its caption"
else
	notok "--script on a terminal plays on the real screen with its caption" a
fi
if wait_for a 'Each contact in slow motion' 100 && wait_gone a 't_e\[ms\]' 10 \
   && wait_for a 'c +4\.4e\+04|coll 9 ' 10 && wait_for a ' slow playing' 100; then
	ok "the script edits c, switches to the presentation mode and captions it"
else
	notok "the script edits c and switches to the presentation mode" a
fi
keys a x
if wait_for a '^demo paused: any key resumes, q quits' 50 && wait_for a ' paused ' 10; then
	ok "a key pressed by the viewer pauses the demo (the cursor stops)"
else
	notok "a key pressed by the viewer pauses the demo" a
fi
keys a x
if wait_for a '^demo: any key pauses, q quits' 50 && wait_for a ' playing ' 30; then
	ok "another key resumes it"
else
	notok "another key resumes it" a
fi
keys a q
if wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ]; then
	ok "q quits the demo (status 0)"
else
	notok "q quits the demo (rc $(cat "$TMP/a.rc" 2>/dev/null))" a
fi

mkdir -p "$TMP/adir"
"$BIN" --script "$TMP/adir" </dev/null >"$TMP/out" 2>&1
rc=$?
if [ "$rc" = 2 ] && grep -q "adir: is a directory" "$TMP/out"; then
	ok "--script given a folder: exit 2 with a message"
else
	notok "--script given a folder: exit 2 (rc $rc: $(cat "$TMP/out"))"
fi
exit $((failed > 0))
