#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Calls among the files of each part (the engine src/core, the explorer
# src/tui, the command line src/cli) point one way, measured on their
# object files: nm gives each object's defined and undefined global
# symbols; file A calls file B of the same part when A uses a symbol that
# B defines; a file is in a cycle when it reaches itself through another
# file (the transitive closure).  `make lint-cycles` runs this check alone.
# Cycles are being untied: tests/cli/calls.allow lists, one a line as
# PART/FILE.c, the files still allowed in one.  The check fails when a file
# not listed is in a cycle (a new cycle: the calls among the files in
# cycles are shown) and when a listed file is no longer in one (take it off
# the list: the list only shrinks).  It prints each part's files in cycles
# and the counts.  Needs the objects of the build that HYBOUNCE_BIN is in
# (those of a source that is gone are left out); run from the repository root.
. "$(dirname "$0")/common.inc"
BUILD_DIR=$(dirname "$BIN")
ALLOW="$(dirname "$0")/calls.allow"
command -v nm >/dev/null || { echo "not ok - nm is not installed"; exit 1; }

# syms PART: "D PART/FILE SYMBOL" for each definition, "U PART/FILE SYMBOL"
# for each use, of the objects of src/PART
syms() {
	part=$1
	set --
	for o in "$BUILD_DIR"/src/"$part"/*.o; do   # not an object left from a removed source
		[ -f "src/$part/$(basename "$o" .o).c" ] && set -- "$@" "$o"
	done
	[ $# -gt 0 ] || return 0
	{ nm -A --defined-only -g "$@"; nm -A -u "$@"; } | awk -v part="$part" '{
		f = $1; sub(/:.*/, "", f); sub(/.*\//, "", f); sub(/\.o$/, ".c", f)
		if ($(NF - 1) == "U") print "U", part "/" f, $NF
		else if (NF == 3) print "D", part "/" f, $NF
	}'
}

# cycles SYMS: the files in a cycle on stdout; "A B SYMBOL" for each call
# between two of them into $T/edges (appended); the number of files on stderr
cycles() {
	awk -v edges="$T/edges" '
	$1 == "D" { def[$3] = $2; file[$2] = 1; next }
	$1 == "U" { use[++nu] = $2 SUBSEP $3; file[$2] = 1 }
	END {
		n = 0
		for (f in file) { id[f] = ++n; name[n] = f }
		for (k = 1; k <= nu; k++) {
			split(use[k], p, SUBSEP)
			if ((p[2] in def) && def[p[2]] != p[1]) {
				r[id[p[1]], id[def[p[2]]]] = 1
				call[++nc] = p[1] " " def[p[2]] " " p[2]
			}
		}
		for (k = 1; k <= n; k++)
			for (i = 1; i <= n; i++)
				if (r[i, k])
					for (j = 1; j <= n; j++)
						if (r[k, j])
							r[i, j] = 1
		for (i = 1; i <= n; i++)
			for (j = 1; j <= n; j++)
				if (j != i && r[i, j] && r[j, i])
					cyc[name[i]] = 1
		for (f in cyc)
			print f
		for (k = 1; k <= nc; k++) {
			split(call[k], p, " ")
			if ((p[1] in cyc) && (p[2] in cyc) && r[id[p[2]], id[p[1]]])
				print call[k] >>edges
		}
		print n >"/dev/stderr"
	}' "$1"
}

: >"$T/edges"
: >"$T/incycle"
for part in core tui cli; do
	syms "$part" >"$T/syms.$part"
	cycles "$T/syms.$part" 2>"$T/nfiles" | sort >"$T/incycle.$part"
	nfiles=$(cat "$T/nfiles")
	ncyc=$(grep -c . "$T/incycle.$part")
	echo "# $part: $ncyc of $nfiles files are in call cycles:" $(cat "$T/incycle.$part")
	case $part in core) least=60 ;; tui) least=20 ;; *) least=10 ;; esac
	if [ "$nfiles" -ge "$least" ]; then
		ok "measured the calls among the $nfiles files of src/$part"
	else
		notok "measured the calls among the files of src/$part (only $nfiles objects)"
	fi
	cat "$T/incycle.$part" >>"$T/incycle"
done
sort -o "$T/incycle" "$T/incycle"

grep -v '^#' "$ALLOW" | grep . | sort >"$T/allow"
new=$(comm -23 "$T/incycle" "$T/allow")
if [ -z "$new" ]; then
	ok "no file in a call cycle but those of calls.allow"
else
	notok "no file in a call cycle but those of calls.allow (new: $(echo $new))"
	echo "$new" >"$T/new"
	# the calls that close the cycles the new files are in
	awk 'NR == FNR { n[$1] = 1; next } ($1 in n) || ($2 in n) { print $1 " -> " $2 ": " $3 }' \
	    "$T/new" "$T/edges" | sort >"$T/calls"
	show "$T/calls" 40
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
	awk '$1 == "U" { print $3, $2 }' "$T/syms.tui" | LC_ALL=C sort -u >"$T/uses"
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
