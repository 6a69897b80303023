#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer's scripted mode (--script FILE): keys from a file, screen
# dumps as text, no terminal needed (stdin and stdout are not a tty here).
# Needs HYBOUNCE_BIN and HYBOUNCE_PRESETS, as set by tests/run.sh.
set -u
BIN=${HYBOUNCE_BIN:?HYBOUNCE_BIN is not set}
export HYBOUNCE_PRESETS="${HYBOUNCE_PRESETS:-$(pwd)/presets}"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT INT TERM HUP
failed=0
ok() { echo "ok - $1"; }
notok() { echo "not ok - $1"; failed=$((failed + 1)); [ -f "${2:-}" ] && sed 's/^/#   /' "$2"; }

cat >"$TMP/s1" <<EOS
# start, run to the end, go back two collisions, dump
wait-finished
End
{
{
dump $TMP/d1
Tab
dump $TMP/d2
size 60x15
dump $TMP/d3
size 160x48
y
dump $TMP/d4
q
EOS
"$BIN" --ascii --script "$TMP/s1" </dev/null >"$TMP/out" 2>&1
rc=$?
if [ "$rc" = 0 ] && [ -s "$TMP/d1" ] && [ "$(wc -l <"$TMP/d1")" = 24 ]; then
	ok "--script runs without a terminal and dumps 24 lines (status $rc)"
else
	notok "--script runs without a terminal and dumps 24 lines (status $rc)" "$TMP/out"
fi
if grep -q '^ steel-on-bitumen bwmcl t=314\.[0-9]* ms j=23 q_c=1 coll 12 .* paused finished' "$TMP/d1" \
   && grep -q 't_e\[ms\]' "$TMP/d1" && grep -Eq '^ *>11 ' "$TMP/d1" \
   && grep -q '^x\[mm\]' "$TMP/d1" && grep -q '\*' "$TMP/d1"; then
	ok "dump: status line at collision 11 (j = 23), table row marked, ASCII plots"
else
	notok "dump: status line at collision 11 (j = 23), table row marked, ASCII plots" "$TMP/d1"
fi
if grep -q '^-- bodies --' "$TMP/d2" && grep -q 'parameters (Enter edits' "$TMP/d2"; then
	ok "dump after Tab: the parameter panel"
else
	notok "dump after Tab: the parameter panel" "$TMP/d2"
fi
if grep -q 'terminal too small: need at least 60x16' "$TMP/d3" && [ "$(wc -l <"$TMP/d3")" = 15 ]; then
	ok "size 60x15: the too-small screen"
else
	notok "size 60x15: the too-small screen" "$TMP/d3"
fi
if grep -q 'hysteresis loop: F_c against x_c, collision 11' "$TMP/d4" && [ "$(wc -l <"$TMP/d4")" = 48 ] \
   && grep -q -- '-- run --' "$TMP/d4"; then
	ok "size 160x48 and the loop view of the collision at the cursor"
else
	notok "size 160x48 and the loop view of the collision at the cursor" "$TMP/d4"
fi

# an edit, a refused edit and an export, typed through text:
# find how many Downs select law.alpha: try until the panel header names it
found=""
i=0
while [ $i -lt 60 ] && [ -z "$found" ]; do
	{ echo Tab; j=0; while [ $j -lt $i ]; do echo Down; j=$((j + 1)); done; echo "dump $TMP/e1"; } >"$TMP/s3"
	"$BIN" --ascii --script "$TMP/s3" </dev/null >/dev/null 2>&1
	grep -q 'nudge) law.alpha:' "$TMP/e1" && found=$i
	i=$((i + 1))
done
if [ -n "$found" ]; then
	{
		echo Tab
		j=0; while [ $j -lt "$found" ]; do echo Down; j=$((j + 1)); done
		echo Enter; echo C-u; echo "text:1.5"; echo Enter
		echo "dump $TMP/e2"
		echo m; echo "dump $TMP/e2m"; echo Esc
		echo Enter; echo C-u; echo "text:0.4"; echo Enter
		echo wait-finished
		echo "dump $TMP/e3"
		echo e; echo C-u; echo "text:$TMP/x"; echo Enter
		echo "dump $TMP/e4"
	} >"$TMP/s4"
	"$BIN" --ascii --script "$TMP/s4" </dev/null >"$TMP/out" 2>&1
	if grep -q 'refused.*m: whole' "$TMP/e2" && grep -Eq '^ +alpha +0\.35' "$TMP/e2" \
	   && grep -q 'messages, oldest first' "$TMP/e2m" && tr -d '\n' <"$TMP/e2m" | grep -q 'refused.*(0, 1)'; then
		ok "script: alpha = 1.5 refused with (0, 1), old value kept"
	else
		notok "script: alpha = 1.5 refused with (0, 1), old value kept" "$TMP/e2"
	fi
	if grep -Eq '^ +alpha +0\.4 ' "$TMP/e3" && grep -q 'finished' "$TMP/e3"; then
		ok "script: alpha = 0.4 accepted and the run finished"
	else
		notok "script: alpha = 0.4 accepted and the run finished" "$TMP/e3"
	fi
	if [ -s "$TMP/x-trace.csv" ] && [ -s "$TMP/x-collisions.csv" ] && grep -q "wrote $TMP/x-trace.csv" "$TMP/e4" \
	   && "$BIN" --batch "$(ls "$TMP"/x*.preset | head -n 1)" -q >/dev/null 2>&1 \
	   && grep -q '0.40000000000000002\|= *0.4$\|alpha *= *0.4' "$(ls "$TMP"/x*.preset | head -n 1)"; then
		ok "script: export writes the CSVs and a scene preset that loads and keeps alpha = 0.4"
	else
		notok "script: export writes the CSVs and a scene preset that loads and keeps alpha = 0.4" "$TMP/e4"
		ls "$TMP" | sed 's/^/#   /'
	fi
else
	notok "script: law.alpha row not found in the panel" "$TMP/e1"
fi

# a bad script line: status 2, message naming the line
printf 'wait 10\nfrobnicate\n' >"$TMP/bad"
"$BIN" --script "$TMP/bad" </dev/null >"$TMP/out" 2>&1
rc=$?
if [ "$rc" = 2 ] && grep -q "bad:2: unknown script line 'frobnicate'" "$TMP/out"; then
	ok "a bad script line exits 2 naming FILE:LINE"
else
	notok "a bad script line exits 2 naming FILE:LINE (status $rc)" "$TMP/out"
fi
"$BIN" --script "$TMP/no-such-script" </dev/null >"$TMP/out" 2>&1
rc=$?
if [ "$rc" = 2 ] && grep -q 'no-such-script' "$TMP/out"; then
	ok "a missing script exits 2"
else
	notok "a missing script exits 2 (status $rc)" "$TMP/out"
fi

[ "$failed" -eq 0 ]
