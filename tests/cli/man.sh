#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The man page lints clean with mandoc and documents every long option
# that --help lists.
. "$(dirname "$0")/common.inc"

if ! command -v mandoc >/dev/null 2>&1; then
	notok "mandoc is installed (make deps installs it)"
else
	out=$(mandoc -Tlint -W warning man/hybounce.1 2>&1)
	rc=$?
	if [ "$rc" -eq 0 ] && [ -z "$out" ]; then ok "mandoc -Tlint -W warning man/hybounce.1 is clean"
	else notok "mandoc -Tlint -W warning man/hybounce.1 is clean (exit $rc)"; echo "$out" | sed 's/^/# /'; fi
fi

opts=$("$BIN" --help 2>/dev/null | grep -o -- '--[a-z][a-z-]*' | sort -u)
missing=
n=0
for o in $opts; do
	n=$((n + 1))
	name=${o#--}
	grep -q "^\.It Fl -$name\\b\|^\.It .* Fl -$name\\b" man/hybounce.1 || missing="$missing $o"
done
if [ "$n" -ge 13 ] && [ -z "$missing" ]; then ok "the man page documents every long option of --help ($n)"
else notok "the man page documents every long option of --help ($n found, missing:$missing)"; fi

for s in NAME SYNOPSIS DESCRIPTION OPTIONS "BATCH OUTPUT" PRESETS "CSV FILES" \
    "EXPLORER KEYS" ENVIRONMENT FILES "EXIT STATUS" EXAMPLES "SEE ALSO"; do
	grep -q "^\.Sh $s\$" man/hybounce.1 || missing="$missing [$s]"
done
if [ -z "$missing" ]; then ok "the man page has every section"
else notok "the man page has every section (missing:$missing)"; fi
if grep -q '^\.\\" KEYS-BEGIN' man/hybounce.1 && grep -q '^\.\\" KEYS-END' man/hybounce.1; then
	ok "the man page marks the explorer keys (KEYS-BEGIN/KEYS-END)"
else
	notok "the man page marks the explorer keys (KEYS-BEGIN/KEYS-END)"
fi

# Every CSV column of include/hybounce/csv.h has an entry in CSV FILES.
missing=
for c in t j q_c x v x_c z_c1 F_c F_er x_m v_m v_m1 i t_e t_s t_d t_f v_i e x_c_max \
    F_c_max x_c_r W J_Fc J_Fe Lambda; do
	grep -q "^\.It Li $c\( ,\|\$\)" man/hybounce.1 || missing="$missing $c"
done
if [ -z "$missing" ]; then ok "the man page documents every CSV column"
else notok "the man page documents every CSV column (missing:$missing)"; fi

[ "$fails" -eq 0 ]
