#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The bad-input matrix (issue 10): every row of tests/cli/badinput.tab is one
# class of bad (or borderline) input, run in a fresh folder:
#
#   ID ;; EXIT ;; FRAGMENT ;; SETUP ;; COMMAND [;; XFAIL REASON]
#
# SETUP ("-" for none) prepares the folder, COMMAND is the invocation (both
# through eval; see the helpers below).  A row passes when COMMAND exits
# with EXIT, FRAGMENT (fixed string) is in its standard error or output,
# nothing crashed (no signal, no sanitizer report), a refusal (EXIT 2) says
# what is accepted or expected (or is the system's own reason, such as
# "Permission denied", or lists where a preset was looked for), and, for a
# non-zero EXIT, no file in the
# folder was created or changed ("no file written").
# A row with an XFAIL column states the behaviour issue 10 requires but
# another branch delivers (named in the reason): while it does not hold the
# row prints "ok - ... # TODO xfail: REASON"; once it holds, it says that
# the mark can go.  Runs under the sanitizer build too (make check-asan).
set -u
BIN=${HYBOUNCE_BIN:-build/hybounce}
case $BIN in /*) ;; *) BIN=$(pwd)/$BIN ;; esac
: "${HYBOUNCE_PRESETS:=$(pwd)/presets}"
export HYBOUNCE_PRESETS
TAB=${BADINPUT_TABLE:-tests/cli/badinput.tab}
REPO=$(pwd)
ROOT=$(mktemp -d)
chmod 755 "$ROOT"
trap 'chmod -R u+rwx "$ROOT" 2>/dev/null; rm -rf "$ROOT"' EXIT

# --- helpers for SETUP and COMMAND ---
# $B: the binary, under a time limit (a hang is a failure, exit 124)
# As root, the unprivileged rows' user may not reach the binary and the
# presets where they are (CI clones into a private temporary folder): every
# row runs copies in $ROOT, which that user can reach.
if [ "$(id -u)" = 0 ]; then
	if cp "$BIN" "$ROOT/hybounce" && chmod 755 "$ROOT/hybounce"; then
		BIN=$ROOT/hybounce
	fi
	if [ -d "$HYBOUNCE_PRESETS" ] && cp -R "$HYBOUNCE_PRESETS" "$ROOT/presets" &&
	    chmod -R a+rX "$ROOT/presets"; then
		HYBOUNCE_PRESETS=$ROOT/presets
	fi
fi
B="timeout ${BADINPUT_TIMEOUT:-60} $BIN"
P=$HYBOUNCE_PRESETS
# pre TEXT: in.preset from TEXT (printf %b: \n, \t, \000 ...)
pre() { printf '%b' "$1" >in.preset; }
# sedp EXPR: in.preset from the steel-on-bitumen preset through sed
sedp() { sed "$1" s.preset >in.preset; }
# asuser CMD...: CMD as an unprivileged user (permissions mean nothing to
# root).
asuser() {
	if [ "$(id -u)" = 0 ]; then
		setpriv --reuid=65534 --regid=65534 --clear-groups -- "$@"
	else
		"$@"
	fi
}
# short: the options of a quick run
short="--set run.T=0.05 -q"

snapshot() { find . -mindepth 1 -print0 2>/dev/null |
	xargs -0 stat -c '%n %s %Y.%y %a %F' 2>/dev/null | LC_ALL=C sort; }

n=0 fails=0 crashes=0 refusals=0 xfails=0
while IFS= read -r line; do
	case $line in '#'* | '') continue ;; esac
	id=${line%% ;; *}; rest=${line#* ;; }
	want=${rest%% ;; *}; rest=${rest#* ;; }
	frag=${rest%% ;; *}; rest=${rest#* ;; }
	setup=${rest%% ;; *}; rest=${rest#* ;; }
	case $rest in
	*' ;; '*) cmd=${rest%% ;; *}; xfail=${rest#* ;; } ;;
	*) cmd=$rest; xfail= ;;
	esac
	n=$((n + 1))
	W="$ROOT/$n"
	mkdir "$W" && chmod 777 "$W"
	cd "$W" || exit 1
	cp "$REPO/presets/steel-on-bitumen.preset" s.preset
	chmod 644 s.preset
	[ "$setup" = - ] || eval "$setup" >/dev/null 2>&1
	before=$(snapshot)
	O="$ROOT/$n.out" E="$ROOT/$n.err"
	( eval "$cmd" ) >"$O" 2>"$E" </dev/null
	rc=$?
	after=$(snapshot)
	why= crashed=0
	if [ "$rc" -gt 124 ] || grep -a -q -e 'runtime error' -e 'Sanitizer' -e 'Segmentation' "$E"; then
		why="crashed (exit $rc)"
		crashed=1
		crashes=$((crashes + 1))
	elif [ "$rc" = 124 ]; then
		why="hung (killed after the time limit)"
	elif [ "$rc" != "$want" ]; then
		why="exit $rc, expected $want"
	elif ! grep -a -q -F -e "$frag" "$E" "$O"; then
		why="the message lacks '$frag'"
	elif [ "$want" = 2 ] && ! grep -a -q -i -e accepted -e expected -e known -e "Try 'hybounce --help'" \
	    -e 'No such file' -e 'Permission denied' -e 'Not a directory' -e 'File name too long' \
	    -e 'No space left on device' -e 'e\.g\.' \
	    -e "nor .* is in " "$E"; then
		why="the refusal does not say what is accepted: $(head -c 200 "$E")"
	elif [ "$want" != 0 ] && [ "$before" != "$after" ]; then
		why="a file was written or changed: $(printf '%s\n' "$after" | grep -v -x -F -e "$before" | head -n 3 | tr '\n' ' ')"
	fi
	[ "$want" = 2 ] && refusals=$((refusals + 1))
	if [ -z "$why" ]; then
		extra=
		[ -n "$xfail" ] && extra=" (the xfail mark can go: $xfail)"
		echo "ok - badinput $id: exit $rc, '$frag'$( [ "$want" != 0 ] && echo ', no file written')$extra"
	elif [ -n "$xfail" ] && [ "$crashed" = 0 ]; then
		xfails=$((xfails + 1))
		echo "ok - badinput $id: $why # TODO xfail: $xfail"
	else
		echo "not ok - badinput $id: $why"
		echo "#   command: $cmd"
		sed 's/^/#   stderr: /' "$E" | head -n 4 | cut -c 1-300
		fails=$((fails + 1))
	fi
	cd "$REPO" || exit 1
	chmod -R u+rwx "$W" 2>/dev/null
	rm -rf "$W" "$O" "$E"
done <"$TAB"
echo "# badinput: $n classes tried, $crashes crashes, $refusals expected refusals (exit 2), $xfails expected failures (xfail), $fails failed"
if [ "$n" -ge 190 ]; then echo "ok - badinput: at least 190 classes ($n)"
else echo "not ok - badinput: at least 190 classes (only $n)"; fails=$((fails + 1)); fi
if [ "$crashes" = 0 ]; then echo "ok - badinput: no crash"
else echo "not ok - badinput: $crashes crashes"; fi
[ "$fails" -eq 0 ] && [ "$crashes" -eq 0 ]
