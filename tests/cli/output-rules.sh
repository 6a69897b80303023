#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The output policy (outputs.h) and the input rules (input.h) hold for fit
# and sweep as for batch: an output pointed at the command's own data, its
# preset or a shipped preset, or two outputs at one file, are refused with
# exit 2 before anything runs and every input is left byte for byte; a
# device is written in place, never replaced; a replaced file is named in
# the "wrote" line.  Inputs are read once (a pipe or a FIFO works), bounded
# (/dev/zero refused with the limit named); a NUL byte in a data row is an
# error naming the row and the column.  A sweep larger than the limit is
# refused unless --max-points allows it.  Outputs carry the provenance line.
. "$(dirname "$0")/common.inc"
ROOT=$(pwd)
W=$T/w
mkdir "$W"
cp "$ROOT/examples/fit/bounces.csv" "$W/"
cp "$HYBOUNCE_PRESETS/steel-on-bitumen.preset" "$W/mine.preset"
cksum "$W/bounces.csv" "$W/mine.preset" "$HYBOUNCE_PRESETS/steel-on-bitumen.preset" >"$T/inputs.sum"
inputs_same() { (cd "$W" && cksum bounces.csv mine.preset) >/dev/null && \
	cksum "$W/bounces.csv" "$W/mine.preset" "$HYBOUNCE_PRESETS/steel-on-bitumen.preset" | cmp -s - "$T/inputs.sum"; }

# refused NAME PATTERN CMD...: exit 2, the message matches, the inputs unchanged, no new file.
refused() {
	name=$1 pat=$2
	shift 2
	ls -A "$W" >"$T/before"
	(cd "$W" && "$@" >"$T/out" 2>"$T/err")
	rc=$?
	ls -A "$W" >"$T/after"
	if [ "$rc" -eq 2 ] && grep -q -- "$pat" "$T/err" && inputs_same && cmp -s "$T/before" "$T/after" &&
	    ! grep -q iteration "$T/err"; then
		ok "$name: refused (exit 2), inputs unchanged, nothing written"
	else
		notok "$name: refused (exit 2), inputs unchanged, nothing written (exit $rc)"
		show "$T/err"
	fi
}
# both law parameters: with law.c alone the residuals are far above the
# stated noise (alpha is not the truth), and the fit is not credible (exit 1)
FIT="$BIN fit steel-on-bitumen --data bounces.csv --free law.c,law.alpha -q"
refused "fit --out the data file" "--out bounces.csv is the data file" $FIT --out bounces.csv
refused "fit --residuals the data file" "--residuals ./bounces.csv is the data file" \
	$FIT --residuals ./bounces.csv
refused "fit --out the preset being fitted" "is the preset being fitted" \
	"$BIN" fit mine.preset --data bounces.csv --free law.c -q --out mine.preset
refused "fit --out a link to the preset being fitted" "is the preset being fitted" \
	sh -c "ln -sf mine.preset link.preset && $BIN fit mine.preset --data bounces.csv --free law.c -q --out link.preset; rc=\$?; rm -f link.preset; exit \$rc"
refused "fit --out a shipped preset" "is a shipped preset" \
	"$BIN" fit mine.preset --data bounces.csv --free law.c -q \
	--out "$HYBOUNCE_PRESETS/hertz-elastic.preset"
refused "fit --out X --residuals X" "are the same file" $FIT --out x.preset --residuals ./x.preset
refused "fit --out into a missing folder" "--out nodir/x.preset" $FIT --out nodir/x.preset

# A device is written in place, never replaced; a replaced file is named.
(cd "$W" && $FIT --out /dev/null --residuals r.csv >/dev/null 2>"$T/err")
rc=$?
if [ "$rc" -eq 0 ] && [ -c /dev/null ] && grep -q '^wrote /dev/null (written in place)$' "$T/err" &&
    grep -q '^wrote r.csv$' "$T/err"; then
	ok "fit --out /dev/null: written in place, the device stays a device"
else
	notok "fit --out /dev/null: written in place (exit $rc)"; show "$T/err"
fi
(cd "$W" && $FIT --out f.preset --residuals r.csv >/dev/null 2>"$T/err")
if grep -q '^wrote f.preset$' "$T/err" && grep -q '^wrote r.csv (replaced the existing file)$' "$T/err" &&
    grep -q "^; hybounce [^ ]* (commit [^)]*): .*fit steel-on-bitumen --data bounces.csv --free law.c,law.alpha -q --out f.preset --residuals r.csv\$" "$W/f.preset"; then
	ok "fit: the wrote lines name the replaced file; the fitted preset records version, commit and command"
else
	notok "fit: the wrote lines name the replaced file; the fitted preset records the command"
	show "$T/err"; tail -n 2 "$W/f.preset" | sed 's/^/# /'
fi
if "$BIN" -b "$W/f.preset" -q >/dev/null 2>"$T/err"; then
	ok "the fitted preset with its provenance line runs with --batch"
else
	notok "the fitted preset with its provenance line runs with --batch"; show "$T/err"
fi
# The provenance line quotes what a shell would split.
(cd "$W" && "$BIN" -b steel-on-bitumen -q --set 'run.T = 5 ms' -c "a b'c.csv" >/dev/null 2>&1)
line=$(grep '^; hybounce .*(commit ' "$W/a b'c.preset" | sed 's/^; [^:]*: //')
if [ -n "$line" ] && eval "set -- $line" && [ "$6" = 'run.T = 5 ms' ] && [ "$8" = "a b'c.csv" ] && [ $# -eq 8 ]; then
	ok "the provenance line pastes into a shell as the same arguments"
else
	notok "the provenance line pastes into a shell as the same arguments ($line)"
fi

# Inputs read once: a pipe, a FIFO; bounded; NUL bytes.
(cd "$W" && cat bounces.csv | $FIT --data /dev/stdin --out p.preset >/dev/null 2>"$T/err")
rc=$?
(cd "$W" && $FIT --out q.preset >/dev/null 2>&1)
if [ "$rc" -eq 0 ] && [ "$(grep -c '^law\|^c = ' "$W/p.preset")" -ge 1 ] &&
    [ "$(sed -n '/^\[law\]/,/^\[/p' "$W/p.preset")" = "$(sed -n '/^\[law\]/,/^\[/p' "$W/q.preset")" ]; then
	ok "fit --data from a pipe fits as the file does"
else
	notok "fit --data from a pipe fits as the file does (exit $rc)"; show "$T/err"
fi
mkfifo "$T/fifo"
cat "$W/bounces.csv" >"$T/fifo" &
(cd "$W" && timeout 60 $FIT --data "$T/fifo" --out fifo.preset >/dev/null 2>"$T/err")
rc=$?
if [ "$rc" -eq 0 ] && [ -s "$W/fifo.preset" ]; then
	ok "fit --data from a FIFO: read once, no hang"
else
	notok "fit --data from a FIFO: read once, no hang (exit $rc)"; show "$T/err"
fi
(cd "$W" && timeout 60 $FIT --data /dev/zero --out z.preset >/dev/null 2>"$T/err")
rc=$?
if [ "$rc" -eq 2 ] && grep -q 'larger than 64 MiB' "$T/err" && [ ! -e "$W/z.preset" ]; then
	ok "fit --data /dev/zero: refused at the 64 MiB limit, named"
else
	notok "fit --data /dev/zero: refused at the limit (exit $rc)"; show "$T/err"
fi
printf 't_e\n0\n0.1\n0.2\0junk\n0.3\n' >"$W/nul.csv"
(cd "$W" && $FIT --data nul.csv --out n.preset >/dev/null 2>"$T/err")
rc=$?
if [ "$rc" -eq 2 ] && grep -q 'nul.csv:4: data row 3, column 1 (t_e): a NUL byte' "$T/err" &&
    [ ! -e "$W/n.preset" ]; then
	ok "a NUL byte in a data row: an error naming the row and the column"
else
	notok "a NUL byte in a data row: an error naming the row and the column (exit $rc)"; show "$T/err"
fi
cat "$HYBOUNCE_PRESETS/hertz-elastic.preset" >"$T/fifo" &
(cd "$W" && timeout 60 "$BIN" sweep "$T/fifo" --set run.T=0.2 --vary initial.x0=10mm:20mm:2 -q \
    --out fs >/dev/null 2>"$T/err")
rc=$?
if [ "$rc" -eq 0 ] && [ "$(wc -l <"$W/fs/runs.csv")" -eq 3 ]; then
	ok "sweep on a preset from a FIFO: read once"
else
	notok "sweep on a preset from a FIFO: read once (exit $rc)"; show "$T/err"
fi

# Sweep: the folder of a shipped preset is never written into.
ls -A "$HYBOUNCE_PRESETS" >"$T/p.before"
"$BIN" sweep steel-on-bitumen --vary law.c=1000:2000:2 -q --out "$HYBOUNCE_PRESETS" 2>"$T/err"
rc=$?
if [ "$rc" -eq 2 ] && ls -A "$HYBOUNCE_PRESETS" | cmp -s - "$T/p.before" && inputs_same; then
	ok "sweep --out the preset folder: refused, nothing written"
else
	notok "sweep --out the preset folder: refused (exit $rc)"; show "$T/err"
fi

# Work bounded: 10^9 points refused at once, naming the count, the limit and --max-points.
(cd "$W" && timeout 20 "$BIN" sweep steel-on-bitumen --vary law.c=1:2:1000000000 --out big 2>"$T/err")
rc=$?
if [ "$rc" -eq 2 ] && grep -q '1000000000 points, more than the limit of 1000000 points; accepted: at most 1000000 points; --max-points N' "$T/err" &&
    [ ! -e "$W/big" ]; then
	ok "a sweep of 10^9 points is refused at once, naming the limit and --max-points"
else
	notok "a sweep of 10^9 points is refused at once (exit $rc)"; show "$T/err"
fi
(cd "$W" && "$BIN" sweep steel-on-bitumen --vary law.c=1000:2000:3 --vary law.alpha=0.3,0.4 \
    --max-points 5 --out five 2>"$T/err")
rc=$?
(cd "$W" && "$BIN" sweep steel-on-bitumen --set run.T=0.05 --vary law.c=1000:2000:3 \
    --vary law.alpha=0.3,0.4 --max-points 6 -q --out six 2>"$T/err2")
rc2=$?
if [ "$rc" -eq 2 ] && grep -q 'the sweep would have 6 points, more than the limit of 5' "$T/err" &&
    [ "$rc2" -eq 0 ] && [ "$(wc -l <"$W/six/runs.csv")" -eq 7 ]; then
	ok "--max-points N: N points run, N+1 refused"
else
	notok "--max-points N: N points run, N+1 refused (exit $rc, $rc2)"; show "$T/err"; show "$T/err2"
fi
if grep -q "^; hybounce [^ ]* (commit [^)]*): .* sweep steel-on-bitumen --set run.T=0.05 .*--out six\$" "$W/six/sweep.preset" &&
    (cd "$W" && "$BIN" sweep six/sweep.preset --jobs 1 -q --out six 2>"$T/err"); then
	ok "sweep.preset records version, commit and command; another command line resumes the folder"
else
	notok "sweep.preset records version, commit and command; another command line resumes the folder"
	show "$T/err"
fi
# Sweep: a complete folder run again is kept and said so; a merge that
# replaces the files names that.
(cd "$W" && "$BIN" sweep six/sweep.preset --jobs 1 --out six 2>"$T/err")
(cd "$W" && for k in 0 1; do "$BIN" sweep six/sweep.preset -q --shard $k/2 --out sh; done &&
    "$BIN" sweep --merge sh 2>/dev/null && "$BIN" sweep --merge sh 2>"$T/err2")
if grep -q '^kept six/runs.csv (the sweep was complete)$' "$T/err" &&
    grep -q '^wrote sh/runs.csv (replaced the existing file)$' "$T/err2" &&
    grep -q '^wrote sh/collisions.csv (replaced the existing file)$' "$T/err2"; then
	ok "sweep: a complete folder is kept and said so; --merge names the files it replaces"
else
	notok "sweep: a complete folder is kept; --merge names the files it replaces"
	show "$T/err"; show "$T/err2"
fi
exit $((fails > 0))
