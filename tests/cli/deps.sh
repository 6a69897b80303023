#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Dependencies point one way: no cycle among the #include "..." of src/ and
# include/ (tsort finds loops); units.h includes no other header of ours;
# law_common.h declares no function that law.c defines; the engine
# (src/core) includes no header of the front ends and no curses.
. "$(dirname "$0")/common.inc"

edges=$(for f in src/*/*.c src/*/*.h include/hybounce/*.h tools/*.c; do
	[ -f "$f" ] || continue
	sed -n 's/^#include "\(.*\)".*/\1/p' "$f" | while read -r inc; do
		printf '%s %s\n' "$(basename "$f")" "$(basename "$inc")"
	done
done)
n=$(printf '%s\n' "$edges" | grep -c .)
if out=$(printf '%s\n' "$edges" | tsort 2>&1 >/dev/null) && [ -z "$out" ] && [ "$n" -gt 50 ]; then
	ok "no include cycle ($n includes)"
else
	notok "no include cycle ($n includes)"
	echo "$out" | sed 's/^/# /'
fi

# export.h (the visibility and extern "C" macros) is the one header every
# public header includes.
if grep '^#include "' include/hybounce/units.h | grep -qv '"export.h"'; then
	notok "units.h includes no header of ours but export.h"
else
	ok "units.h includes no header of ours but export.h"
fi

# functions declared in law_common.h (a line "name(" after a type line) vs defined in law.c
decl=$(awk '/^[a-z_]+\(/ { sub(/\(.*/, ""); print }' src/core/law_common.h)
bad=
for d in $decl; do
	grep -q "^$d(" src/core/law.c && bad="$bad $d"
done
if [ -z "$bad" ]; then ok "law_common.h declares no function of law.c"
else notok "law_common.h declares no function of law.c (found:$bad)"; fi

bad=$(grep -l '#include <curses.h>\|#include "tui.h"\|#include "batch.h"\|#include "term.h"' \
    src/core/*.c src/core/*.h include/hybounce/*.h 2>/dev/null)
if [ -z "$bad" ]; then ok "the engine includes no front-end header"
else notok "the engine includes no front-end header ($bad)"; fi
exit $((fails > 0))
