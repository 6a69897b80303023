#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# What an export may write over: never the preset being run nor a shipped
# preset (exit 2 before the run, nothing written); a device or FIFO in
# place, with no .preset beside it; through a symbolic link, which stays;
# any other overwrite said in the "wrote" line.
. "$(dirname "$0")/common.inc"
RUN="--set run.T=100ms -q"
W=$T/w
mkdir "$W"

# 1. The preset being run, beside the CSV: refused, untouched.
{ echo '; my comments'; cat "$HYBOUNCE_PRESETS/hertz-elastic.preset"; } >"$W/my.preset"
cp "$W/my.preset" "$T/my.copy"
(cd "$W" && "$BIN" -b ./my.preset $RUN -c my.csv >"$T/out" 2>"$T/err")
rc=$?
if [ "$rc" -eq 2 ] && cmp -s "$W/my.preset" "$T/my.copy" && [ ! -e "$W/my.csv" ] &&
    grep -q 'is the preset being run' "$T/err" && [ ! -s "$T/out" ]; then
	ok "-b ./my.preset -c my.csv: refused before the run, my.preset untouched"
else
	notok "-b ./my.preset -c my.csv: refused before the run, my.preset untouched (exit $rc)"
	show "$T/err"
fi

# 2. A shipped preset beside the CSV: refused.
sum=$(cat "$HYBOUNCE_PRESETS"/*.preset | cksum)
"$BIN" -b hertz-elastic $RUN -t "$HYBOUNCE_PRESETS/steel-on-bitumen.csv" >/dev/null 2>"$T/err"
rc=$?
if [ "$rc" -eq 2 ] && [ "$(cat "$HYBOUNCE_PRESETS"/*.preset | cksum)" = "$sum" ] &&
    [ ! -e "$HYBOUNCE_PRESETS/steel-on-bitumen.csv" ] && grep -q 'shipped preset' "$T/err"; then
	ok "-t presets/steel-on-bitumen.csv: refused, the shipped presets untouched"
else
	notok "-t presets/steel-on-bitumen.csv: refused, the shipped presets untouched (exit $rc)"
	show "$T/err"
	rm -f "$HYBOUNCE_PRESETS/steel-on-bitumen.csv"
fi

# 3. /dev/null: written in place, no /dev/null.preset; the scene beside the file.
(cd "$W" && "$BIN" -b hertz-elastic $RUN -t /dev/null -c coll.csv >/dev/null 2>"$T/err")
rc=$?
if [ "$rc" -eq 0 ] && [ -c /dev/null ] && [ ! -e /dev/null.preset ] &&
    grep -q '^wrote /dev/null (written in place)$' "$T/err" &&
    grep -q '^wrote coll.preset$' "$T/err" && [ -s "$W/coll.preset" ]; then
	ok "-t /dev/null: written in place, no .preset beside it, the scene beside coll.csv"
else
	notok "-t /dev/null: written in place, no .preset beside it (exit $rc)"
	show "$T/err"
fi
rm -f "$W"/*

# 4. A FIFO: written in place, its reader gets the CSV.
mkfifo "$W/fifo.csv"
cat "$W/fifo.csv" >"$T/fromfifo" &
reader=$!
(cd "$W" && timeout 20 "$BIN" -b hertz-elastic $RUN -c fifo.csv >/dev/null 2>"$T/err")
rc=$?
wait "$reader"
if [ "$rc" -eq 0 ] && [ -p "$W/fifo.csv" ] && [ ! -e "$W/fifo.preset" ] &&
    [ "$(head -n 1 "$T/fromfifo" | cut -d, -f1-3)" = "i,t_e,t_s" ]; then
	ok "a FIFO is written in place and stays a FIFO; no .preset beside it"
else
	notok "a FIFO is written in place and stays a FIFO (exit $rc)"
	show "$T/err"
fi
rm -f "$W"/*

# 5. A symbolic link: kept; the file it leads to is written; said so.
mkdir "$W/data"
echo old >"$W/data/real.csv"
ln -s data/real.csv "$W/link.csv"
(cd "$W" && "$BIN" -b hertz-elastic $RUN -c link.csv >/dev/null 2>"$T/err")
rc=$?
if [ "$rc" -eq 0 ] && [ -L "$W/link.csv" ] &&
    [ "$(head -n 1 "$W/data/real.csv" | cut -d, -f1)" = "i" ] &&
    grep -q "^wrote link.csv (through the link, to .*data/real.csv, replacing it)$" "$T/err"; then
	ok "a symbolic link is kept and written through, and the wrote line says so"
else
	notok "a symbolic link is kept and written through (exit $rc)"
	show "$T/err"
fi

# 6. An overwrite is named; a new file is not.
(cd "$W" && "$BIN" -b hertz-elastic $RUN -c c.csv >/dev/null 2>"$T/err1" &&
    "$BIN" -b hertz-elastic $RUN -c c.csv >/dev/null 2>"$T/err2")
if grep -q '^wrote c.csv$' "$T/err1" && grep -q '^wrote c.preset$' "$T/err1" &&
    grep -q '^wrote c.csv (replaced the existing file)$' "$T/err2" &&
    grep -q '^wrote c.preset (replaced the existing file)$' "$T/err2"; then
	ok "the wrote line names an overwrite, and only an overwrite"
else
	notok "the wrote line names an overwrite, and only an overwrite"
	show "$T/err1"; show "$T/err2"
fi

# 7. A folder is refused before the run.
mkdir "$W/dir.csv"
"$BIN" -b hertz-elastic $RUN -c "$W/dir.csv" >/dev/null 2>"$T/err"
rc=$?
if [ "$rc" -eq 2 ] && grep -q 'is a folder' "$T/err"; then
	ok "a folder as the export is refused (exit 2)"
else
	notok "a folder as the export is refused (exit $rc)"
	show "$T/err"
fi
[ "$fails" -eq 0 ]
