#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# "--trace -" and "--collisions -" write that CSV to stdout: byte for byte
# the file the same run writes, with the report on stderr so that stdout
# holds the CSV alone; no file named "-" and no .preset beside stdout (the
# scene goes beside the other CSV when that one is a file); both "-" at
# once is refused (exit 2); a failed run (exit 1) still writes its CSV; a
# reader that stops early (| head) gets no error storm, with SIGPIPE left
# alone or ignored; any other write error on stdout exits 2 and says so.
. "$(dirname "$0")/common.inc"
case $BIN in /*) ;; *) BIN=$(pwd)/$BIN ;; esac
show() { sed 's/^/# /' "$1" | head -n 5; }

COLL_HEADER='i,t_e,t_s,t_d,t_f,v_i,e,x_c_max,F_c_max,x_c_r,W,J_Fc,J_Fe,Lambda'
# Every run below happens in an empty folder, so that a stray "-" shows.
W=$T/cwd
mkdir "$W"
# entries: the names in the work folder, one a line, sorted.
entries() { (cd "$W" && ls -A | sort); }

# The reference: the same runs written to files.
"$BIN" -b steel-on-bitumen -q -t "$T/arc.csv" -c "$T/coll.csv" >/dev/null 2>&1 ||
    notok "reference run of steel-on-bitumen (exit $?)"

# 1. --collisions -
(cd "$W" && "$BIN" -b steel-on-bitumen -c - >"$T/out" 2>"$T/err")
rc=$?
if [ "$rc" -eq 0 ] && [ "$(head -n 1 "$T/out")" = "$COLL_HEADER" ] &&
    cmp -s "$T/out" "$T/coll.csv"; then
	ok "--collisions - writes the collisions CSV to stdout, byte for byte the file"
else
	notok "--collisions - writes the collisions CSV to stdout, byte for byte the file (exit $rc)"
	show "$T/err"
fi
if grep -q '^hybounce .* batch run$' "$T/err" && grep -q '^collisions (' "$T/err" &&
    grep -q '^summary$' "$T/err" && ! grep -q 'batch run\|^summary' "$T/out"; then
	ok "with a CSV on stdout the report (header, table, summary) goes to stderr"
else
	notok "with a CSV on stdout the report (header, table, summary) goes to stderr"
fi
if [ -z "$(entries)" ] && ! grep -q '^wrote' "$T/err"; then
	ok "--collisions - leaves no file (no '-', no '-.preset') and no 'wrote' line"
else
	notok "--collisions - leaves no file (no '-', no '-.preset') and no 'wrote' line: $(entries | tr '\n' ' ')"
fi

# 2. --trace=- (the long form with =), quiet
(cd "$W" && "$BIN" -b steel-on-bitumen -q --trace=- >"$T/out" 2>"$T/err")
rc=$?
if [ "$rc" -eq 0 ] && cmp -s "$T/out" "$T/arc.csv" && [ -z "$(entries)" ]; then
	ok "--trace=- writes the arc CSV to stdout, byte for byte the file, and no file"
else
	notok "--trace=- writes the arc CSV to stdout, byte for byte the file, and no file (exit $rc)"
	show "$T/err"
fi
if grep -q '^summary$' "$T/err" && ! grep -q '^collisions (\|batch run$' "$T/err"; then
	ok "--quiet with a CSV on stdout: only the summary, on stderr"
else
	notok "--quiet with a CSV on stdout: only the summary, on stderr"
fi

# 3. one to stdout, the other to a file: the scene goes beside the file.
(cd "$W" && "$BIN" -b steel-on-bitumen -q -t - -c "$T/c2.csv" >"$T/out" 2>"$T/err")
rc=$?
if [ "$rc" -eq 0 ] && cmp -s "$T/out" "$T/arc.csv" && cmp -s "$T/c2.csv" "$T/coll.csv" &&
    [ -s "$T/c2.preset" ] && grep -q "^wrote $T/c2.csv\$" "$T/err" &&
    grep -q "^wrote $T/c2.preset\$" "$T/err" && [ "$(grep -c '^wrote' "$T/err")" -eq 2 ] &&
    [ -z "$(entries)" ]; then
	ok "-t - -c FILE: arc on stdout, FILE and FILE's .preset written and announced"
else
	notok "-t - -c FILE: arc on stdout, FILE and FILE's .preset written and announced (exit $rc)"
	show "$T/err"
fi

# 4. both "-": refused before the run.
(cd "$W" && "$BIN" -b steel-on-bitumen -t - --collisions - >"$T/out" 2>"$T/err")
rc=$?
if [ "$rc" -eq 2 ] && [ ! -s "$T/out" ] && [ -z "$(entries)" ] &&
    grep -q -- '--trace.*--collisions.*standard output' "$T/err" &&
    grep -q 'expected a file path' "$T/err" && [ "$(wc -l <"$T/err")" -eq 1 ]; then
	ok "--trace - --collisions - is refused (exit 2) with one message naming both"
else
	notok "--trace - --collisions - is refused (exit 2) with one message naming both (exit $rc)"
	show "$T/err"
fi

# 5. ./- is a file named "-".
(cd "$W" && "$BIN" -b steel-on-bitumen -q -c ./- >"$T/out" 2>"$T/err")
rc=$?
if [ "$rc" -eq 0 ] && cmp -s "$W/-" "$T/coll.csv" && [ -s "$W/-.preset" ] &&
    grep -q '^  ended' "$T/out"; then
	ok "-c ./- writes a file named '-' (and the report stays on stdout)"
else
	notok "-c ./- writes a file named '-' (and the report stays on stdout) (exit $rc)"
fi
rm -f "$W/-" "$W/-.preset"

# 6. a failed run (exit 1) still writes what it computed to stdout.
"$BIN" -b steel-on-bitumen --set run.h_max=1e-300 -q -t "$T/fa.csv" >/dev/null 2>&1
(cd "$W" && "$BIN" -b steel-on-bitumen --set run.h_max=1e-300 -q -t - \
    >"$T/out" 2>"$T/err")
rc=$?
if [ "$rc" -eq 1 ] && [ "$(wc -l <"$T/out")" -ge 2 ] && cmp -s "$T/out" "$T/fa.csv" &&
    grep -q '^hybounce: the run failed: ' "$T/err" && [ -z "$(entries)" ]; then
	ok "a failed run (exit 1) still writes its arc to stdout, as to a file"
else
	notok "a failed run (exit 1) still writes its arc to stdout, as to a file (exit $rc)"
	show "$T/err"
fi

# 7. | head: the reader leaves early.  SIGPIPE as inherited (normally the
# default: killed quietly, 141), then ignored (EPIPE: stop quietly, exit 0).
( cd "$W" && "$BIN" -b ptfe-pom -q -t - 2>"$T/err"; echo $? >"$T/rc" ) | head -n 1 >"$T/h"
rc=$(cat "$T/rc")
if [ "$(cat "$T/h")" = "t,j,q_c,x,v,x_c,z_c1,F_c,F_er,x_m,v_m,v_m1,v_m2" ] &&
    { [ "$rc" -eq 141 ] || [ "$rc" -eq 0 ]; } && ! grep -qi 'hybounce:\|pipe' "$T/err"; then
	ok "--trace - | head -n 1: the header, then a quiet end (exit $rc)"
else
	notok "--trace - | head -n 1: the header, then a quiet end (exit $rc)"
	show "$T/err"
fi
( trap '' PIPE; cd "$W" && "$BIN" -b ptfe-pom -q -t - 2>"$T/err"; echo $? >"$T/rc" ) |
    head -n 1 >"$T/h"
rc=$(cat "$T/rc")
if [ "$(cat "$T/h")" = "t,j,q_c,x,v,x_c,z_c1,F_c,F_er,x_m,v_m,v_m1,v_m2" ] &&
    [ "$rc" -eq 0 ] && ! grep -qi 'hybounce:\|pipe' "$T/err" &&
    [ "$(wc -l <"$T/err")" -lt 20 ] && [ -z "$(entries)" ]; then
	ok "with SIGPIPE ignored, --trace - | head -n 1 stops quietly with exit 0"
else
	notok "with SIGPIPE ignored, --trace - | head -n 1 stops quietly with exit 0 (exit $rc)"
	show "$T/err"
fi

# 8. any other write error on stdout is an export failure (exit 2).
if [ -w /dev/full ]; then
	(cd "$W" && "$BIN" -b steel-on-bitumen -q -c - >/dev/full 2>"$T/err")
	rc=$?
	if [ "$rc" -eq 2 ] &&
	    grep -q '^hybounce: export failed: standard output: write error: ' "$T/err"; then
		ok "a full stdout (/dev/full) exits 2 and says so"
	else
		notok "a full stdout (/dev/full) exits 2 and says so (exit $rc)"
		show "$T/err"
	fi
else
	ok "a full stdout (/dev/full) exits 2 and says so # SKIP no /dev/full"
fi

[ "$fails" -eq 0 ]
