#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# --help mentions every option; --version prints the version; --list-laws
# lists the five laws; --list-presets lists every file in presets/.
. "$(dirname "$0")/common.inc"

"$BIN" --help >"$T/help" 2>"$T/err"
rc=$?
missing=
for o in -b --batch -s --set -t --trace -c --collisions --jumps --check -q --quiet \
    --ascii --script --list-presets --list-laws -h --help -V --version; do
	grep -q -- "$o\\b" "$T/help" || missing="$missing $o"
done
if [ "$rc" -eq 0 ] && [ -z "$missing" ]; then ok "--help mentions every option"
else notok "--help mentions every option (exit $rc, missing:$missing)"; fi
"$BIN" -h >"$T/h" 2>&1
if cmp -s "$T/h" "$T/help"; then ok "-h is --help"; else notok "-h is --help"; fi

# "hybounce 0.2.0 (commit HASH)": the VERSION file's number, then the
# commit (abbreviated, -dirty for a modified tree; unknown outside git)
want=$(cat VERSION)
got=$("$BIN" --version 2>&1)
rc=$?
if [ "$rc" -eq 0 ] && printf '%s\n' "$got" |
    grep -Eqx "hybounce $want \(commit ([0-9a-f]{7,}(-dirty)?|unknown)\)"; then
	ok "--version prints hybounce $want (commit ...)"
else
	notok "--version prints hybounce $want (commit ...) (got '$got', exit $rc)"
fi
v=$("$BIN" -V 2>&1)
if [ "$v" = "$got" ]; then ok "-V prints the version"; else notok "-V prints the version"; fi

"$BIN" --list-laws >"$T/laws" 2>"$T/err"
rc=$?
missing=
for l in shccl bwshccl bwmcl hertz linear; do
	grep -q "^$l  " "$T/laws" || missing="$missing $l"
done
if [ "$rc" -eq 0 ] && [ -z "$missing" ]; then ok "--list-laws lists the five laws"
else notok "--list-laws lists the five laws (exit $rc, missing:$missing)"; fi
if grep -q '^      alpha  *(1)  *range (0, 1)  *default 0.35' "$T/laws" &&
    grep -q '^      c  *.*range (0, inf)' "$T/laws"; then
	ok "--list-laws shows each parameter with unit, range and default"
else
	notok "--list-laws shows each parameter with unit, range and default"
	sed 's/^/# /' "$T/laws" | head -n 30
fi

"$BIN" --list-presets >"$T/presets" 2>"$T/err"
rc=$?
missing=
n=0
for f in presets/*.preset; do
	[ -f "$f" ] || continue
	n=$((n + 1))
	grep -q "^$(basename "$f" .preset) " "$T/presets" || missing="$missing $f"
done
if [ "$rc" -eq 0 ] && [ "$n" -gt 0 ] && [ -z "$missing" ]; then
	ok "--list-presets lists every file in presets/ ($n)"
else
	notok "--list-presets lists every file in presets/ (exit $rc, $n files, missing:$missing)"
fi

# The explorer's options are refused in batch mode and vice versa.
"$BIN" -b steel-on-bitumen --ascii >/dev/null 2>&1
rc1=$?
"$BIN" --trace "$T/x.csv" >/dev/null 2>&1 </dev/null
rc2=$?
if [ "$rc1" -eq 2 ] && [ "$rc2" -eq 2 ] && [ ! -e "$T/x.csv" ]; then
	ok "options of the other mode are refused with exit 2"
else
	notok "options of the other mode are refused with exit 2 (got $rc1, $rc2)"
fi

[ "$fails" -eq 0 ]
