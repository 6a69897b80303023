#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The explorer's modes (src/tui/mode.h): adding a mode is its own file and
# its line in the registry.  Every "const struct mode mode_NAME" defined in
# src/tui is listed in tui_modes (src/tui/modes.c) and declared in mode.h,
# and nothing else is; a file defines at most one mode, with its own key
# table; no key table is defined outside a mode's file; the key lists of
# the help, the man page and the README come from the registry (keys.c and
# mode_help.c name no mode).  Reads the sources only.
. "$(dirname "$0")/common.inc"
cd "$(dirname "$0")/../.." || exit 1

# mode_NAME FILE, for each mode defined
grep -H '^const struct mode mode_[a-z_0-9]* = {' src/tui/*.c |
	sed 's/^\([^:]*\):const struct mode \(mode_[a-z_0-9]*\) .*/\2 \1/' | sort >"$T/defined"
n=$(grep -c . "$T/defined")
sed -n 's/^	&\(mode_[a-z_0-9]*\),$/\1/p' src/tui/modes.c | sort >"$T/registered"
sed -n '/^extern const struct mode mode_/,/;/p' src/tui/mode.h | tr ',;' '\n\n' |
	sed -n 's/.*\(mode_[a-z_0-9]*\).*/\1/p' | sort >"$T/declared"
cut -d' ' -f1 "$T/defined" >"$T/names"

if [ "$n" -ge 9 ] && cmp -s "$T/names" "$T/registered"; then
	ok "the registry (modes.c) lists every mode defined in src/tui, and no other ($n modes)"
else
	notok "the registry (modes.c) lists every mode defined in src/tui, and no other"
	diff "$T/names" "$T/registered" | sed 's/^/# /'
fi
if cmp -s "$T/names" "$T/declared"; then
	ok "mode.h declares every mode defined, and no other"
else
	notok "mode.h declares every mode defined, and no other"
	diff "$T/names" "$T/declared" | sed 's/^/# /'
fi
# the explorer first: the help and the documents list it first
if [ "$(sed -n 's/^	&\(mode_[a-z_0-9]*\),$/\1/p' src/tui/modes.c | head -n 1)" = mode_main ]; then
	ok "the explorer (mode_main) is the registry's first mode"
else
	notok "the explorer (mode_main) is the registry's first mode"
fi

bad=
for f in $(cut -d' ' -f2 "$T/defined" | sort -u); do
	if [ "$(grep -c '^const struct mode mode_' "$f")" -ne 1 ]; then
		bad="$bad $f(several modes)"
	elif ! grep -q '^static const struct mode_key [a-z_]*\[\] = {' "$f" ||
	     ! grep -q '\.keys = MODE_KEYS(' "$f"; then
		bad="$bad $f(no key table of its own)"
	fi
done
# a key table only where a mode is
for f in $(grep -l 'struct mode_key [a-z_]*\[\] = {' src/tui/*.c); do
	grep -q '^const struct mode mode_' "$f" || bad="$bad $f(a key table without a mode)"
done
if [ -z "$bad" ]; then
	ok "each mode is in a file of its own, with its own key table"
else
	notok "each mode is in a file of its own, with its own key table:$bad"
fi

# the lists are printed from the registry: keys.c and the help name no mode
if grep -n '&mode_[a-z]\|mode_main\|mode_sweep' src/tui/keys.c src/tui/mode_help.c |
	grep -v 'mode_help\b' >"$T/named"; then
	notok "keys.c and mode_help.c list the modes of the registry, naming none" "$T/named"
else
	ok "keys.c and mode_help.c list the modes of the registry, naming none"
fi
# the generator of the man page and README lists takes the registry
if grep -q 'keys_man(tui_modes' tests/gen_keys.c && grep -q 'keys_markdown(tui_modes' tests/gen_keys.c; then
	ok "make keys-doc prints the lists of every mode of the registry"
else
	notok "make keys-doc prints the lists of every mode of the registry"
fi
[ "$fails" -eq 0 ]
