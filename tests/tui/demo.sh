#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Teaching with --script: the whole script is checked before anything
# runs (every error with its line, exit 2, no output written); wait-key
# waits for the viewer; captions wrap to the screen or show large; the end
# of the demo waits, the explorer then the viewer's until q.  tmux at
# 80x23: send-keys, then poll capture-pane.
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
# the box borders matched below are UTF-8's; set before the tmux server starts
if locale -a 2>/dev/null | grep -qi '^c\.utf-\?8$'; then
	export LC_ALL=C.UTF-8
fi
. "$(dirname "$0")/common.inc"

# ---- checked before playback ------------------------------------------------------
cat >"$TMP/bad" <<EOS
dump $TMP/early
wait 10
wiat 20
caption fine
size 80by24
wait -3
wait-key
Enter
EOS
"$BIN" --script "$TMP/bad" </dev/null >"$TMP/out" 2>&1
rc=$?
if [ "$rc" = 2 ] && grep -q "bad: 3 errors, nothing played" "$TMP/out" \
   && grep -q "bad:3: unknown script line 'wiat 20'" "$TMP/out" \
   && grep -q "bad:5: size: expected COLSxLINES" "$TMP/out" \
   && grep -q "bad:6: wait: expected a number of milliseconds, got '-3'" "$TMP/out" \
   && [ ! -e "$TMP/early" ]; then
	ok "a script is checked whole before it runs: 3 errors with their lines, exit 2, its dump never written"
else
	notok "a script is checked whole before it runs (rc $rc)"
	sed 's/^/#   /' "$TMP/out"
fi

# ---- README's lesson runs as written (without a terminal) -------------------------
awk '/^### Teaching$/ { on = 1 } on && /^### / && !/Teaching/ { exit } on && /^    / { sub(/^    /, ""); print }' \
    README.md >"$TMP/readme-lesson"
# the run computes while the lesson plays: dump its screen once it has ended
printf 'wait-finished\ndump %s\n' "$TMP/readme-dump" >>"$TMP/readme-lesson"
"$BIN" --script "$TMP/readme-lesson" </dev/null >"$TMP/out" 2>&1
rc=$?
if [ "$rc" = 0 ] && grep -q 'wait-key' "$TMP/readme-lesson" && grep -q ' coll 9 ' "$TMP/readme-dump" \
   && grep -q '^The pinned run (dots) against the new one: each contact in slow motion' "$TMP/readme-dump"; then
	ok "README's lesson runs as written: c ten times larger, pinned, captioned"
else
	notok "README's lesson runs as written (rc $rc)"
	sed 's/^/#   /' "$TMP/out" "$TMP/readme-dump" 2>/dev/null | head -30
fi

# ---- wait-key, captions, the end ----------------------------------------------
cat >"$TMP/lesson" <<EOS
caption-large The first study: a steel ball dropped on bitumen, twelve collisions and then permanent contact
wait-key
caption A caption too long for one line of eighty columns wraps onto the rows above the message line, whole
wait-key
caption the last caption
EOS
start a 80 23 --script "$TMP/lesson"
if wait_for a '│ +The first study: a steel ball dropped on bitumen, twelve +│' 50 \
   && wait_for a '│ +collisions and then permanent contact +│' 10 \
   && wait_for a '^demo: any key goes on, q quits' 10; then
	ok "caption-large: a box over the plots, the text wrapped; wait-key waits"
else
	notok "caption-large: a box over the plots, the text wrapped; wait-key waits" a
fi
keys a x
if wait_for a '^A caption too long for one line of eighty columns wraps onto the rows above the$' 50 \
   && wait_for a '^message line, whole$' 10 && ! screen a | grep -q 'The first study'; then
	ok "a key goes on: the next caption wraps to the screen, whole"
else
	notok "a key goes on: the next caption wraps to the screen, whole" a
fi
keys a x
if wait_for a '^the last caption' 50 && wait_for a '^end of the demo: the explorer is yours \(q quits\)' 50 \
   && [ ! -s "$TMP/a.rc" ]; then
	ok "the end of the script waits (the program goes on)"
else
	notok "the end of the script waits (the program goes on)" a
fi
keys a '?'
if wait_for a 'hybounce keys' 30; then
	ok "after the demo the explorer takes keys (? opens the help)"
else
	notok "after the demo the explorer takes keys (? opens the help)" a
fi
keys a Escape
if wait_for a '^\?:help q:quit' 30; then
	ok "after the viewer's first key the footer lists the explorer's keys again"
else
	notok "after the viewer's first key the footer lists the explorer's keys again" a
fi
keys a q
if wait_exit a 50 && [ "$(cat "$TMP/a.rc")" = 0 ]; then
	ok "q quits after the demo (status 0)"
else
	notok "q quits after the demo (rc $(cat "$TMP/a.rc" 2>/dev/null))" a
fi

# ---- q during a wait-key quits ----------------------------------------------------
printf 'caption waiting\nwait-key\ncaption never shown\n' >"$TMP/w"
start b 80 23 --script "$TMP/w"
wait_for b '^demo: any key goes on, q quits' 50 || notok "wait-key shows its hint" b
keys b q
if wait_exit b 50 && [ "$(cat "$TMP/b.rc")" = 0 ]; then
	ok "q during wait-key quits (status 0)"
else
	notok "q during wait-key quits (rc $(cat "$TMP/b.rc" 2>/dev/null))" b
fi

# ---- a key pauses, another resumes; the footer says so, from the demo's key table ----
printf 'caption playing\nwait 60000\ncaption never shown\n' >"$TMP/p"
start c 80 23 --script "$TMP/p"
if wait_for c '^demo: any key pauses, q quits' 50; then
	keys c x
	if wait_for c '^demo paused: any key resumes, q quits' 30; then
		keys c x
		if wait_for c '^demo: any key pauses, q quits' 30; then
			ok "a key pauses the demo and another resumes it (the footer: any key pauses/resumes, q quits)"
		else
			notok "another key resumes the demo" c
		fi
	else
		notok "a key pauses the demo (demo paused: any key resumes, q quits)" c
	fi
else
	notok "a playing demo's footer: any key pauses, q quits" c
fi
keys c q
if wait_exit c 50 && [ "$(cat "$TMP/c.rc")" = 0 ]; then
	ok "q during playback quits (status 0)"
else
	notok "q during playback quits (rc $(cat "$TMP/c.rc" 2>/dev/null))" c
fi
exit $failed
