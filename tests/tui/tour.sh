#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The README's five-minute tour runs as written: its keys and its screens
# are read from README.md itself (between the TOUR markers: a "**Run:**"
# line, then "**Keys:**" lines of `key` tokens, each followed by the
# indented screen lines it leads to), then replayed in tmux at 80x23 as a
# new user would, from the top folder with no HYBOUNCE_PRESETS.  A step
# passes when every screen line it shows is on the screen (`...` in a
# line stands for anything).  Changing the README's tour changes this test.
# Needs HYBOUNCE_BIN; run from the top folder.
# a new user's terminal speaks UTF-8 (the screens below show its ellipsis);
# set before the tmux server starts (common.inc)
if locale -a 2>/dev/null | grep -qi '^c\.utf-\?8$'; then
	export LC_ALL=C.UTF-8
fi
. "$(dirname "$0")/common.inc"
TOP=$(pwd)

# The tour as a plan: R CMD, then per step K TOKEN... and E LINE...
awk '
	/^<!-- TOUR-END -->$/ { on = 0 }
	on && /^\*\*Run:\*\* / {
		if (match($0, /`[^`]*`/)) print "R " substr($0, RSTART + 1, RLENGTH - 2)
		next
	}
	on && /^\*\*Keys:\*\* / {
		print "S"
		s = substr($0, 11)
		while (match(s, /`[^`]*`/)) { print "K " substr(s, RSTART + 1, RLENGTH - 2); s = substr(s, RSTART + RLENGTH) }
		next
	}
	on && /^    / { l = substr($0, 5); sub(/ +$/, "", l); print "E " l; next }
	/^<!-- TOUR-BEGIN -->$/ { on = 1 }
' README.md >"$TMP/plan"

cmd=$(sed -n 's/^R //p' "$TMP/plan")
steps=$(grep -c '^S$' "$TMP/plan")
if [ "$cmd" = "make run" ] && [ "$steps" -ge 5 ]; then
	ok "README's tour starts with make run and has $steps steps"
else
	notok "README's tour (TOUR markers) starts with make run and has steps (run: '$cmd', $steps steps)"
	exit 1
fi
# make run builds, then runs the program from the top folder with no argument
if awk '/^run:/ { on = 1; next } on && /^[^\t]/ { on = 0 } on' Makefile | grep -q '^	\./\$(BIN)$'; then
	ok "make run opens \$(BIN) from the top folder with no argument, as the tour replays it"
else
	notok "make run opens \$(BIN) from the top folder with no argument, as the tour replays it"
fi

# key TOKEN: a tmux key name is one key, anything else is typed letter by letter
named() { echo "$1" | grep -Eq '^(Enter|Tab|BTab|Escape|Esc|Space|BSpace|Up|Down|Left|Right|Home|End|PgUp|PgDn|C-.|F[0-9]+)$'; }

# expect FILE: polls until every line of FILE (one ERE per line) is on the screen
expect() {
	i=0
	while [ "$i" -lt 150 ]; do
		$TM capture-pane -p -t tour >"$TMP/screen" 2>/dev/null
		all=1
		while IFS= read -r re; do
			grep -Eq -- "$re" "$TMP/screen" || { all=0; break; }
		done <"$1"
		[ "$all" = 1 ] && return 0
		i=$((i + 1))
		sleep 0.1
	done
	return 1
}

$TM new-session -d -s tour -x 80 -y 23 \
    "cd '$TOP' && env -u HYBOUNCE_PRESETS '$BIN'; echo \$? > '$TMP/tour.rc'"

# step N KEYS: sends the step's keys, then checks its screen lines
nkeys=0 n=0 quit=0
flush() {
	[ -z "$desc" ] && return 0
	if [ -s "$TMP/want" ]; then
		if expect "$TMP/want"; then
			ok "tour step $n ($desc): the screen shows what README shows"
		else
			notok "tour step $n ($desc): the screen shows what README shows" tour
			echo "# missing:"
			while IFS= read -r re; do
				grep -Eq -- "$re" "$TMP/screen" || echo "#   $re"
			done <"$TMP/want"
		fi
	fi
	: >"$TMP/want"
}
: >"$TMP/want"
desc="make run"
while IFS= read -r line; do
	case $line in
	"R "*) ;;
	S)
		flush
		n=$((n + 1)) desc="" ;;
	"K "*)
		tok=${line#K }
		desc="${desc:+$desc }$tok"
		if named "$tok"; then
			keys tour "$tok"
			nkeys=$((nkeys + 1))
		else
			keys tour -l "$tok"
			nkeys=$((nkeys + ${#tok}))
		fi
		[ "$tok" = q ] && quit=1 ;;
	"E "*)
		# the README's line as an ERE: metacharacters literal, `...` anything
		printf '%s\n' "${line#E }" | sed -e 's/[][\\.*^$+?(){}|]/\\&/g' -e 's/\\\.\\\.\\\./.*/g' >>"$TMP/want" ;;
	esac
done <"$TMP/plan"
flush

if [ "$quit" = 1 ]; then
	if wait_exit tour 50 && [ "$(cat "$TMP/tour.rc")" = 0 ]; then
		ok "the tour's last key quits the explorer (exit 0)"
	else
		notok "the tour's last key quits the explorer (exit 0)" tour
	fi
fi
# "what if c were ten times larger?", both runs compared, in under 15 keys
if [ "$nkeys" -lt 15 ]; then
	ok "the tour takes $nkeys keys (fewer than 15)"
else
	notok "the tour takes $nkeys keys (fewer than 15)"
fi
# a manual, not a history: no issue numbers or "before issue N" in README
hist=$(grep -n -i -E 'issue [0-9#]|issues? [0-9]+|previous stop|before issue|closing commit' README.md | head -5)
if [ -z "$hist" ]; then
	ok "README names no issue and tells no development history"
else
	notok "README names no issue and tells no development history (docs/ or tests/bench/REPORT.md hold it)"
	echo "$hist" | sed 's/^/# /'
fi
exit $failed
