#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Calls among the explorer's files point one way, measured on its object
# files: nm gives each object's defined and undefined global symbols; file
# A calls file B when A uses a symbol that B defines; a file is in a cycle
# when it reaches itself through another file (the transitive closure).
# Cycles are being untied: tests/cli/calls.allow lists, one a line, the
# files still allowed in one.  The check fails when a file not listed is in
# a cycle (a new cycle) and when a listed file is no longer in one (take it
# off the list: the list only shrinks).  It prints the cycles' files and
# the count.  Needs the objects of the build that HYBOUNCE_BIN is in.
. "$(dirname "$0")/common.inc"
BUILD_DIR=$(dirname "$BIN")
ALLOW="$(dirname "$0")/calls.allow"
command -v nm >/dev/null || { echo "not ok - nm is not installed"; exit 1; }

objs=$(ls "$BUILD_DIR"/src/tui/*.o 2>/dev/null)
if [ -z "$objs" ]; then
	notok "the explorer's objects are in $BUILD_DIR/src/tui"
	exit 1
fi
# "D FILE SYMBOL" for each definition, "U FILE SYMBOL" for each use
for o in $objs; do
	f=$(basename "$o" .o).c
	nm --defined-only -g "$o" | awk -v f="$f" 'NF == 3 { print "D", f, $3 }'
	nm -u "$o" | awk -v f="$f" '{ print "U", f, $NF }'
done >"$T/syms"

# the files in a cycle, and how many files there are
awk '
$1 == "D" { def[$3] = $2; file[$2] = 1; next }
$1 == "U" { use[++nu] = $2 SUBSEP $3; file[$2] = 1 }
END {
	n = 0
	for (f in file) { id[f] = ++n; name[n] = f }
	for (k = 1; k <= nu; k++) {
		split(use[k], p, SUBSEP)
		if ((p[2] in def) && def[p[2]] != p[1])
			r[id[p[1]], id[def[p[2]]]] = 1
	}
	for (k = 1; k <= n; k++)
		for (i = 1; i <= n; i++)
			if (r[i, k])
				for (j = 1; j <= n; j++)
					if (r[k, j])
						r[i, j] = 1
	for (i = 1; i <= n; i++) {
		cyc = 0
		for (j = 1; j <= n; j++)
			if (j != i && r[i, j] && r[j, i])
				cyc = 1
		if (cyc)
			print name[i]
	}
	print n >"/dev/stderr"
}' "$T/syms" 2>"$T/nfiles" | sort >"$T/incycle"
nfiles=$(cat "$T/nfiles")
ncyc=$(grep -c . "$T/incycle")
echo "# $ncyc of $nfiles explorer files are in call cycles:" $(cat "$T/incycle")

if [ "$nfiles" -ge 20 ]; then
	ok "measured the calls among $nfiles explorer files"
else
	notok "measured the calls among the explorer files (only $nfiles objects)"
fi
grep -v '^#' "$ALLOW" | grep . | sort >"$T/allow"
new=$(comm -23 "$T/incycle" "$T/allow")
if [ -z "$new" ]; then
	ok "no file in a call cycle but those of calls.allow"
else
	notok "no file in a call cycle but those of calls.allow (new: $(echo $new))"
fi
gone=$(comm -13 "$T/incycle" "$T/allow")
if [ -z "$gone" ]; then
	ok "every file of calls.allow is still in a cycle (the list is no longer than it must be)"
else
	notok "every file of calls.allow is still in a cycle (take off: $(echo $gone))"
fi

# The explorer reaches the engine through the public API (include/hybounce,
# hb_ names) and the engine's text and number helpers only: no other
# symbol of src/core (an internal function such as scene_chain_body).
core_objs=$(ls "$BUILD_DIR"/src/core/*.o 2>/dev/null)
if [ -n "$core_objs" ]; then
	nm --defined-only -g $core_objs | awk 'NF == 3 { print $3 }' | LC_ALL=C sort -u >"$T/core"
	awk '$1 == "U" { print $3, $2 }' "$T/syms" | LC_ALL=C sort -u >"$T/uses"
	internal=$(LC_ALL=C join "$T/uses" "$T/core" | awk '
		$1 ~ /^(hb_|HB_)/ { next }
		$1 ~ /^(cnum_|textbuf_)/ || $1 == "csv_put_num" { next }
		{ printf "%s%s (%s)", sep, $1, $2; sep = ", " }')
	if [ -z "$internal" ]; then
		ok "the explorer uses the engine's public API only (and its text/number helpers)"
	else
		notok "the explorer uses the engine's public API only (internal: $internal)"
	fi
else
	notok "the engine's objects are in $BUILD_DIR/src/core"
fi
exit $((fails > 0))
