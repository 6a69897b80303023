#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Bad input exits 2 with a message on stderr that names the file or key and
# what is accepted, and leaves no CSV behind: unknown option, missing
# preset, out-of-range and wrongly-united --set, a malformed preset file,
# an unwritable --trace path.
. "$(dirname "$0")/common.inc"
mkdir "$T/out"

# bad NAME PATTERN ARGS...: runs hybounce ARGS with both exports into
# $T/out; expects exit 2, PATTERN (grep -F, may be "") on stderr, nothing
# on stdout's table, and $T/out still empty.
bad() {
	name=$1 pat=$2
	shift 2
	"$BIN" "$@" -t "$T/out/arc.csv" -c "$T/out/coll.csv" >"$T/stdout" 2>"$T/stderr" </dev/null
	rc=$?
	left=$(ls -A "$T/out")
	if [ "$rc" -ne 2 ]; then
		notok "$name: exit 2 (got $rc)"
		sed 's/^/# /' "$T/stderr" | head -n 5
	elif [ -n "$pat" ] && ! grep -qF -- "$pat" "$T/stderr"; then
		notok "$name: message mentions '$pat'"
		sed 's/^/# /' "$T/stderr" | head -n 5
	elif [ -n "$left" ]; then
		notok "$name: no file left behind (found: $left)"
		rm -f "$T/out/"* "$T/out/".??* 2>/dev/null
	elif [ ! -s "$T/stderr" ]; then
		notok "$name: a message on stderr"
	else
		ok "$name: exit 2, message, no CSV left ($(head -n 1 "$T/stderr"))"
	fi
}

bad "unknown option" "--bogus" -b steel-on-bitumen --bogus
bad "missing preset" "no-such-preset-x" -b no-such-preset-x
bad "missing preset path" "$T/nowhere.preset" -b "$T/nowhere.preset"
bad "--set law.alpha=1.5" "(0, 1)" -b steel-on-bitumen --set law.alpha=1.5
bad "--set law.alpha=1.5 names the key" "alpha" -b steel-on-bitumen --set law.alpha=1.5
bad "--set initial.x0='-1 mm'" "x0" -b steel-on-bitumen --set "initial.x0=-1 mm"
bad "--set body1.R='20 GPa'" "body1.R" -b steel-on-bitumen --set "body1.R=20 GPa"
bad "--set without =" "KEY=VALUE" -b steel-on-bitumen --set law.alpha
bad "--set of an unknown key" "law.nosuchkey" -b steel-on-bitumen --set law.nosuchkey=1
bad "--set of a bad number" "abc" -b steel-on-bitumen --set initial.x0=abc

# The expected unit of body1.R (a length) is named.
"$BIN" -b steel-on-bitumen --set "body1.R=20 GPa" >/dev/null 2>"$T/stderr"
if grep -Eq 'length|expected.*[( ]m[) ,;]|[( ]m[) ,;].*expected|\(e\.g\. [a-z]*m\)' "$T/stderr"; then
	ok "--set body1.R='20 GPa' names the expected unit ($(head -n 1 "$T/stderr"))"
else
	notok "--set body1.R='20 GPa' names the expected unit"
	sed 's/^/# /' "$T/stderr"
fi

# A malformed preset: line 4 is not "key = value".
cat >"$T/broken.preset" <<'INI'
[scene]
name = broken
law = hertz
this line is not a key and a value
INI
bad "malformed preset" "$T/broken.preset:4" -b "$T/broken.preset"
# A value with the wrong unit on line 3.
cat >"$T/unit.preset" <<'INI'
[body1]
E = 200 GPa
R = 20 GPa
INI
bad "preset value with a wrong unit" "$T/unit.preset:3" -b "$T/unit.preset"

# An unwritable --trace path: exit 2, nothing created anywhere.
"$BIN" -b steel-on-bitumen -t /nonexistent/x.csv -c "$T/out/coll.csv" >"$T/stdout" 2>"$T/stderr"
rc=$?
if [ "$rc" -eq 2 ] && [ ! -e /nonexistent/x.csv ] && [ -z "$(ls -A "$T/out")" ] &&
    grep -qF /nonexistent/x.csv "$T/stderr"; then
	ok "unwritable --trace /nonexistent/x.csv: exit 2, named, no file created ($(head -n 1 "$T/stderr"))"
else
	notok "unwritable --trace /nonexistent/x.csv: exit 2, named, no file created (exit $rc)"
	sed 's/^/# /' "$T/stderr" | head -n 5
fi
# ... and a --collisions path that is a folder.
mkdir "$T/dir.csv"
"$BIN" -b steel-on-bitumen -t "$T/out/arc.csv" -c "$T/dir.csv" >"$T/stdout" 2>"$T/stderr"
rc=$?
if [ "$rc" -eq 2 ] && [ -z "$(ls -A "$T/out")" ] && [ -z "$(ls -A "$T/dir.csv")" ] &&
    grep -qF "$T/dir.csv" "$T/stderr"; then
	ok "--collisions naming a folder: exit 2, named, no file created"
else
	notok "--collisions naming a folder: exit 2, named, no file created (exit $rc)"
	sed 's/^/# /' "$T/stderr" | head -n 5
fi
rmdir "$T/dir.csv"

[ "$fails" -eq 0 ]
