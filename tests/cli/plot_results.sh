#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The figures of what batch, sweep and fit computed (--plot FILE, the same
# option and rules in each, and hybounce plot DIR), read back as a reader
# would (tests/cli/plot_png.py): batch --plot draws what hybounce plot
# draws; a sweep over one key is one curve per collision index, with its
# legend, the same figure from sweep --plot and from hybounce plot DIR;
# over two keys a heat map whose colour legend darkens steadily from top
# to bottom (greyscale-readable) and whose ends both occur in the map;
# fit --plot: measured and fitted, the residuals in a panel below; every
# --plot refused, before anything runs, when its name is no figure or is
# another file of the command; pgfplots source for all of them.
. "$(dirname "$0")/common.inc"
PY="python3 $(dirname "$0")/plot_png.py"
DPI=100
val() { awk -v k="$1" '$1 == k { print $2; exit }' "$2"; }
legend_has() { grep -q "^legend_style $1 " "$2"; }
SB="--set run.T=0.1"

# --- batch --plot ----------------------------------------------------------------
"$BIN" --batch hertz-elastic -q --collisions "$T/h.csv" --plot "$T/b.png" >/dev/null 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "^wrote $T/b.png\$" "$T/err" && grep -q "^wrote $T/h.csv\$" "$T/err"; then
	ok "batch --plot: exit 0, wrote the CSV and the figure"
else
	notok "batch --plot: exit $rc" "$T/err"
fi
"$BIN" plot hertz-elastic --out "$T/p.png" 2>/dev/null
if cmp -s "$T/b.png" "$T/p.png"; then
	ok "batch --plot: the figure of hybounce plot PRESET, byte for byte"
else
	notok "batch --plot: differs from hybounce plot"
fi
$PY info "$T/b.png" >"$T/b.info"
if [ "$(val panels "$T/b.info")" = 4 ] && [ "$(val legend_shade "$T/b.info")" -gt 50 ]; then
	ok "batch --plot: the state's 4 panels, the contact shade in the legend"
else
	notok "batch --plot: panels" "$T/b.info"
fi
"$BIN" --batch hertz-elastic -q --plot "$T/b.tex" >/dev/null 2>"$T/err"
if grep -q "^wrote $T/b.tex\$" "$T/err" && grep -q "^wrote $T/b.dat\$" "$T/err"; then
	ok "batch --plot FILE.tex: the source and its data"
else
	notok "batch --plot FILE.tex" "$T/err"
fi

# --- a sweep over one key: a curve per collision index -------------------------
"$BIN" sweep steel-on-bitumen --vary law.c=1e3:1e5:9:log $SB --out "$T/s1" -q --jobs 2 \
	--plot "$T/s1.png" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "^wrote $T/s1.png\$" "$T/err"; then
	ok "sweep --plot: exit 0, says wrote"
else
	notok "sweep --plot: exit $rc" "$T/err"
fi
$PY info "$T/s1.png" >"$T/s1.info"
# (at T = 0.1 s the runs have one or two collisions: curves for i = 0 and 1
# only, no legend entry for an index that no run reached)
if [ "$(val panels "$T/s1.info")" = 1 ] && legend_has 0 "$T/s1.info" && legend_has 1 "$T/s1.info" &&
   ! legend_has 2 "$T/s1.info" && ! legend_has 4 "$T/s1.info"; then
	ok "sweep --plot, one key: one panel, a legend entry for i = 0 and 1, the indices the runs reached"
else
	notok "sweep --plot, one key: panels or legend" "$T/s1.info"
fi
"$BIN" plot "$T/s1" --out "$T/s1p.png" 2>"$T/err"
"$BIN" plot "$T/s1/runs.csv" --out "$T/s1r.png" 2>>"$T/err"
if cmp -s "$T/s1.png" "$T/s1p.png" && cmp -s "$T/s1.png" "$T/s1r.png"; then
	ok "hybounce plot DIR and DIR/runs.csv: the figure of sweep --plot"
else
	notok "hybounce plot DIR: differs from sweep --plot" "$T/err"
fi
"$BIN" plot "$T/s1" --observable t_pc --out "$T/tpc.png" 2>"$T/err" && $PY info "$T/tpc.png" >"$T/tpc.info"
if [ "$(val panels "$T/tpc.info")" = 1 ] && [ "$(val legend "$T/tpc.info")" = 0 ]; then
	ok "hybounce plot DIR --observable t_pc: a run's observable, one curve, no legend"
else
	notok "plot --observable t_pc" "$T/tpc.info"
fi
"$BIN" plot "$T/s1" --collisions 2 --out "$T/c2.png" 2>"$T/err" && $PY info "$T/c2.png" >"$T/c2.info"
if legend_has 0 "$T/c2.info" && ! legend_has 1 "$T/c2.info"; then
	ok "hybounce plot DIR --collisions 2: one curve"
else
	notok "plot DIR --collisions 2" "$T/c2.info"
fi

# a sweep in shards: --merge DIR --plot FILE draws the merged sweep
for k in 0 1; do
	"$BIN" sweep steel-on-bitumen --vary law.c=1e3:1e5:9:log $SB --out "$T/sh" -q --jobs 1 \
		--shard $k/2 2>/dev/null
done
"$BIN" sweep --merge "$T/sh" --plot "$T/sh.png" 2>"$T/err"
if grep -q "^wrote $T/sh.png\$" "$T/err" && cmp -s "$T/sh.png" "$T/s1.png"; then
	ok "sweep --merge DIR --plot: the figure of the same sweep run whole"
else
	notok "sweep --merge --plot" "$T/err"
fi

# --- over two keys: a heat map and its colour legend ---------------------------
"$BIN" sweep steel-on-bitumen --vary law.c=1e3:1e5:5:log --vary initial.x0='10 um,20 um,40 um' \
	$SB --out "$T/s2" -q --jobs 2 --plot "$T/s2.png" 2>"$T/err"
$PY bar "$T/s2.png" >"$T/s2.bar" 2>&1
if [ "$(val bar_rising "$T/s2.bar")" = 1 ] && [ "$(val bar_grey_span "$T/s2.bar")" -gt 150 ]; then
	ok "sweep --plot, two keys: the colour legend's grey level rises steadily bottom to top"
else
	notok "heat map: colour legend" "$T/s2.bar"
fi
if [ "$(awk '$1 == "bar_bottom" { print ($2 < 100 && $4 > $3) }' "$T/s2.bar")" = 1 ] &&
   [ "$(awk '$1 == "bar_top" { print ($2 > 200 && $3 > 200 && $4 < 100) }' "$T/s2.bar")" = 1 ]; then
	ok "heat map: viridis, dark violet at the bottom, yellow at the top"
else
	notok "heat map: the legend's colours" "$T/s2.bar"
fi
if [ "$(val map_top "$T/s2.bar")" -gt 100 ] && [ "$(val map_bottom "$T/s2.bar")" -gt 100 ]; then
	ok "heat map: the legend's two ends both occur in the map"
else
	notok "heat map: the map's colours" "$T/s2.bar"
fi
"$BIN" plot "$T/s2" --out "$T/s2.tex" 2>"$T/err"
if [ "$(grep -c '^\\begin{axis}' "$T/s2.tex")" = 2 ] && grep -q 'xmode=log' "$T/s2.tex" &&
   [ "$(grep -c '^\\fill\[fill={rgb' "$T/s2.tex")" -ge 15 ]; then
	ok "heat map FILE.tex: the map (a log x axis, its cells) and the legend as two axes"
else
	notok "heat map FILE.tex" "$T/s2.tex"
fi

# --- fit --plot -------------------------------------------------------------------
"$BIN" fit steel-on-bitumen --data examples/fit/bounces.csv --free law.c,law.alpha -q \
	--out "$T/f.preset" --plot "$T/f.png" >/dev/null 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "^wrote $T/f.png\$" "$T/err" && grep -q "^wrote $T/f.preset\$" "$T/err"; then
	ok "fit --plot: exit 0, wrote the preset and the figure"
else
	notok "fit --plot: exit $rc" "$T/err"
fi
$PY info "$T/f.png" >"$T/f.info"
if [ "$(val panels "$T/f.info")" = 2 ] && legend_has 0 "$T/f.info" && legend_has 1 "$T/f.info"; then
	ok "fit --plot, a sequence: intervals and residuals (2 panels), measured and fitted in the legend"
else
	notok "fit --plot: panels or legend" "$T/f.info"
fi
printf 'v_i,e,t_d\n-0.1,0.62,0.0021\n-0.2,0.58,0.0019\n-0.4,0.55,0.0017\n-0.8,0.5,0.0015\n-1.2,0.47,0.0014\n' >"$T/drops.csv"
"$BIN" fit steel-on-bitumen --data "$T/drops.csv" --free law.c -q --out "$T/d.preset" \
	--plot "$T/d.png" >/dev/null 2>"$T/err"
$PY info "$T/d.png" >"$T/d.info"
if [ "$(val panels "$T/d.info")" = 4 ]; then
	ok "fit --plot, drops of e and t_d: two panels over their residuals"
else
	notok "fit --plot, drops: panels" "$T/d.info"
fi
"$BIN" fit steel-on-bitumen --data examples/fit/bounces.csv --laws shccl,bwmcl -q \
	--out "$T/l.preset" --plot "$T/l.svg" >/dev/null 2>"$T/err"
if grep -q "^wrote $T/l.svg\$" "$T/err" && grep -q '<svg' "$T/l.svg"; then
	ok "fit --laws --plot: the best law's figure"
else
	notok "fit --laws --plot" "$T/err"
fi

# --- several runs in one figure: the legend says what differs ------------------
"$BIN" plot steel-on-bitumen --variant law.c=2000 --variant law.c=20000 $SB --dpi $DPI \
	--out "$T/v.png" 2>"$T/err" && $PY info "$T/v.png" >"$T/v.info"
if [ "$(val panels "$T/v.info")" = 6 ] && legend_has 0 "$T/v.info" && legend_has 1 "$T/v.info" &&
   ! legend_has 2 "$T/v.info" && [ "$(val legend_shade "$T/v.info")" -lt 10 ]; then
	ok "plot --variant x2: the state's 6 panels, two runs in the legend, no contact shade"
else
	notok "plot --variant: panels or legend" "$T/v.info"
fi
"$BIN" plot steel-on-bitumen --variant law.c=2000 --variant law.c=20000 $SB --out "$T/v.tex" 2>"$T/err"
if [ "$(grep -c '^\\addlegendentry{law\.c = ' "$T/v.tex")" = 2 ] && ! grep -q 'addlegendentry{.*alpha' "$T/v.tex"; then
	ok "plot --variant: the legend names law.c, the one key that differs"
else
	notok "plot --variant: legend entries" "$T/v.tex"
fi
"$BIN" plot steel-on-bitumen --laws shccl,bwshccl,bwmcl --kind loop $SB --dpi $DPI \
	--out "$T/laws.png" 2>"$T/err" && $PY info "$T/laws.png" >"$T/laws.info"
"$BIN" plot steel-on-bitumen --laws shccl,bwshccl,bwmcl --kind loop $SB --out "$T/laws.tex" 2>>"$T/err"
if [ "$(val panels "$T/laws.info")" = 1 ] && legend_has 2 "$T/laws.info" &&
   grep -q 'addlegendentry{scene\.law = shccl' "$T/laws.tex" && grep -q 'addlegendentry{scene\.law = bwmcl' "$T/laws.tex"; then
	ok "plot --laws --kind loop: one panel, a loop and a legend entry per law, named by its law"
else
	notok "plot --laws: panels or legend" "$T/err"
fi
"$BIN" plot hertz-elastic ptfe-pom --kind observables --out "$T/two.tex" 2>"$T/err"
if grep -q 'addlegendentry{hertz-elastic}' "$T/two.tex" && grep -q 'addlegendentry{ptfe-pom}' "$T/two.tex" &&
   [ "$(grep -c '^\\begin{axis}' "$T/two.tex")" = 9 ]; then
	ok "plot PRESET PRESET: presets that differ in many keys are named by their names"
else
	notok "plot two presets: legend" "$T/two.tex"
fi

# --- refused before anything runs: exit 2, nothing written ---------------------
refused() {
	name=$1 pattern=$2
	shift 2
	rm -rf "$T/r"
	mkdir "$T/r"
	"$@" >"$T/out" 2>"$T/err"
	rc=$?
	if [ $rc -eq 2 ] && grep -q -- "$pattern" "$T/err" && [ -z "$(ls -A "$T/r")" ]; then
		ok "$name: exit 2, says '$pattern', nothing written"
	else
		notok "$name: exit $rc" "$T/err"
	fi
}
refused "batch --plot FILE.gif" 'expected a file ending in .png, .pdf, .svg or .tex' \
	"$BIN" --batch hertz-elastic -q --collisions "$T/r/c.csv" --plot "$T/r/f.gif"
refused "batch --plot the same file as --trace" 'same file' \
	"$BIN" --batch hertz-elastic -q --trace "$T/r/x.png" --plot "$T/r/x.png"
refused "batch --plot in a missing folder" 'accepted' \
	"$BIN" --batch hertz-elastic -q --collisions "$T/r/c.csv" --plot "$T/r/no/f.png"
refused "sweep --plot FILE.csv" 'expected a file ending in .png' \
	"$BIN" sweep hertz-elastic --vary initial.v0=-1:-2:2 --out "$T/r/s" --plot "$T/r/s.csv"
refused "sweep --plot with --emit" 'draw it when it is merged' \
	"$BIN" sweep hertz-elastic --vary initial.v0=-1:-2:2 --out "$T/r/s" --emit parallel --plot "$T/r/s.png"
refused "sweep --plot with --shard" 'draw it when it is merged' \
	"$BIN" sweep hertz-elastic --vary initial.v0=-1:-2:2 --out "$T/r/s" --shard 0/2 --plot "$T/r/s.png"
refused "fit --plot FILE.jpg" 'expected a file ending in .png' \
	"$BIN" fit steel-on-bitumen --data examples/fit/bounces.csv --free law.c --out "$T/r/f.preset" --plot "$T/r/f.jpg"
refused "fit --plot the same file as --report" 'same file' \
	"$BIN" fit steel-on-bitumen --data examples/fit/bounces.csv --free law.c --out "$T/r/f.preset" --report "$T/r/x.svg" --plot "$T/r/x.svg"
refused "plot DIR --observable nonsense" 'expected a collision' \
	"$BIN" plot "$T/s1" --observable nonsense --out "$T/r/x.png"
refused "plot DIR over two keys --collisions 0,1" 'draws one collision' \
	"$BIN" plot "$T/s2" --collisions 0,1 --out "$T/r/x.png"
refused "plot nine runs" 'at most 8' \
	"$BIN" plot steel-on-bitumen --variant law.c=1 --variant law.c=2 --variant law.c=3 \
	--laws shccl,bwmcl,bwshccl --out "$T/r/x.png"
refused "plot two runs --kind loop --collisions 0,1" 'one collision' \
	"$BIN" plot steel-on-bitumen --laws shccl,bwmcl --kind loop --collisions 0,1 --out "$T/r/x.png"
refused "plot --laws with an unknown law" 'law' \
	"$BIN" plot steel-on-bitumen --laws shccl,nolaw --out "$T/r/x.png"
refused "plot DIR --variant" 'compare runs of presets' \
	"$BIN" plot "$T/s1" --variant law.c=1 --out "$T/r/x.png"
refused "plot DIR DIR" 'one sweep' \
	"$BIN" plot "$T/s1" "$T/s2" --out "$T/r/x.png"
refused "plot DIR --set" 'expected no --set' \
	"$BIN" plot "$T/s1" --set law.c=1 --out "$T/r/x.png"
refused "plot DIR --out DIR/runs.csv" 'expected a file ending in .png' \
	"$BIN" plot "$T/s1" --out "$T/s1/runs.csv"
refused "plot a folder without a sweep" 'runs.csv' \
	"$BIN" plot "$T/r" --out "$T/r/x.png"
"$BIN" sweep steel-on-bitumen --vary law.c=1e3:1e5:2:log --vary initial.x0='10 um,20 um' \
	--vary law.alpha=0.2,0.3 $SB --out "$T/s3" -q --jobs 2 2>/dev/null
refused "plot DIR over three keys" 'a figure draws one' \
	"$BIN" plot "$T/s3" --out "$T/r/x.png"
nocpu "$T/s1/runs.csv" >"$T/runs.before"
"$BIN" plot "$T/s1" --out "$T/s1/sweep.preset.png" >/dev/null 2>&1
nocpu "$T/s1/runs.csv" >"$T/runs.after"
if cmp -s "$T/runs.before" "$T/runs.after"; then
	ok "plot DIR: the sweep's files unchanged"
else
	notok "plot DIR changed runs.csv"
fi

[ "$fails" -eq 0 ]
