#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce plot: figures read back as a reader would (tests/cli/plot_png.py
# decodes the PNG with zlib alone): not blank; one frame per panel (the
# state's panels: x, v, x_c, F_c, one per z_c, F_e where it varies; nine
# observables; one loop); the contact shading over the columns of the
# collisions of the same run's CSV (batch --collisions) and clear over
# the flights; the legend above the frames, in the palette's colours;
# SIGTERM writes the figure of what was computed and exits 143;
# PDF and SVG well formed; FILE.tex with FILE.dat (one axis per panel,
# the shading, the columns it reads; tests/tex/check.sh compiles it); --size in pixels gives that PNG, under 300 kB;
# bad input exits 2 and writes nothing; --help names every option the man
# page documents.
. "$(dirname "$0")/common.inc"
PY="python3 $(dirname "$0")/plot_png.py"
DPI=120

# png NAME FILE: the file is a PNG
png() {
	if [ "$(head -c 8 "$2" | od -An -c | tr -d ' ')" = '211PNG\r\n032\n' ]; then ok "$1"; else notok "$1"; fi
}
# val KEY FILE: the value after KEY in plot_png.py's output
val() { awk -v k="$1" '$1 == k { print $2; exit }' "$2"; }

# --- the state against t ------------------------------------------------------
for p in hertz-elastic:4 ptfe-pom:6 permanent-contact-bwmcl:6; do
	name=${p%%:*} want=${p#*:}
	"$BIN" plot "$name" --dpi $DPI --out "$T/$name.png" 2>"$T/err"
	rc=$?
	if [ $rc -eq 0 ] && grep -q "^wrote $T/$name.png\$" "$T/err"; then
		ok "plot $name: exit 0, says wrote"
	else
		notok "plot $name: exit $rc" "$T/err"
	fi
	png "plot $name: a PNG" "$T/$name.png"
	$PY info "$T/$name.png" >"$T/$name.info"
	ink=$(val ink "$T/$name.info")
	if [ "${ink:-0}" -gt 10000 ]; then ok "plot $name: not blank ($ink pixels)"; else notok "plot $name: ink ${ink:-none}" "$T/$name.info"; fi
	n=$(val panels "$T/$name.info")
	if [ "$n" = "$want" ]; then ok "plot $name: $want panels"; else notok "plot $name: $n panels, expected $want" "$T/$name.info"; fi
	# one t axis: every frame spans the same columns
	if [ "$(awk '$1 == "frame" { print $2 - $2 % 2, $3 - $3 % 2 }' "$T/$name.info" | sort -u | wc -l)" -le 2 ]; then
		ok "plot $name: the panels share one t axis"
	else
		notok "plot $name: frames at different columns" "$T/$name.info"
	fi
	# the legend: the shade's swatch and its label above the first frame
	if [ "$(val legend_shade "$T/$name.info")" -gt 50 ] && [ "$(val legend "$T/$name.info")" -gt 200 ]; then
		ok "plot $name: the legend shows the contact shade"
	else
		notok "plot $name: no legend" "$T/$name.info"
	fi
	# the same run's collisions and end time, from the batch CSVs
	"$BIN" --batch "$name" -q --collisions "$T/$name.csv" --trace "$T/$name.trace.csv" >/dev/null 2>&1
	tend=$(tail -n 1 "$T/$name.trace.csv" | cut -d, -f1)
	ncoll=$(grep -c '^[0-9]' "$T/$name.csv")
	$PY shade "$T/$name.png" "$T/$name.csv" "$tend" >"$T/$name.shade"
	if [ "$(val hit "$T/$name.shade")" = "$ncoll" ] && [ "$(val miss "$T/$name.shade")" = 0 ]; then
		ok "plot $name: the $ncoll collisions lie on shaded columns"
	else
		notok "plot $name: shading off the collisions ($ncoll collisions)" "$T/$name.shade"
	fi
	if [ "$(val flight_clear "$T/$name.shade")" -ge 1 ] && [ "$(val flight_shaded "$T/$name.shade")" = 0 ]; then
		ok "plot $name: the flights are not shaded"
	else
		notok "plot $name: shading over flights" "$T/$name.shade"
	fi
done

# --- observables per collision, and the loop -------------------------------
"$BIN" plot ptfe-pom --kind observables --dpi $DPI --out "$T/obs.png" 2>"$T/err" &&
	$PY info "$T/obs.png" >"$T/obs.info"
if [ "$(val panels "$T/obs.info")" = 9 ]; then ok "plot --kind observables: 9 panels"; else notok "plot --kind observables: panels" "$T/obs.info"; fi

"$BIN" plot steel-on-bitumen --kind loop --dpi $DPI --out "$T/loop.png" 2>"$T/err" &&
	$PY info "$T/loop.png" >"$T/loop.info"
if [ "$(val panels "$T/loop.info")" = 1 ]; then ok "plot --kind loop: 1 panel"; else notok "plot --kind loop: panels" "$T/loop.info"; fi
# the legend's colours: the first three of the palette (blue, vermillion,
# bluish green), one per collision
legend_has() { grep -q "^legend_style $1 " "$2"; }
if legend_has 0 "$T/loop.info" && legend_has 1 "$T/loop.info" &&
   legend_has 2 "$T/loop.info"; then
	ok "plot --kind loop: a legend entry per collision, in the palette"
else
	notok "plot --kind loop: legend colours" "$T/loop.info"
fi
"$BIN" plot steel-on-bitumen --kind loop --collisions 0,4 --dpi $DPI --out "$T/loop2.png" 2>"$T/err" &&
	$PY info "$T/loop2.png" >"$T/loop2.info"
if legend_has 0 "$T/loop2.info" && legend_has 1 "$T/loop2.info" &&
   ! legend_has 2 "$T/loop2.info"; then
	ok "plot --collisions 0,4: two legend entries"
else
	notok "plot --collisions 0,4: legend colours" "$T/loop2.info"
fi

# --- formats and sizes ---------------------------------------------------------
"$BIN" plot hertz-elastic --out "$T/f.pdf" 2>"$T/err"
if [ "$(head -c 5 "$T/f.pdf")" = "%PDF-" ] && tail -c 8 "$T/f.pdf" | grep -q '%%EOF'; then
	ok "plot FILE.pdf: a PDF"
else
	notok "plot FILE.pdf" "$T/err"
fi
if command -v pdfinfo >/dev/null 2>&1; then
	if pdfinfo "$T/f.pdf" >"$T/pdfinfo" 2>&1 && grep -q '^Pages: *1$' "$T/pdfinfo" &&
	   grep -q '^Page size: *252 x ' "$T/pdfinfo"; then
		ok "plot FILE.pdf: pdfinfo reads one page 252 pt (3.5 in) wide"
	else
		notok "plot FILE.pdf: pdfinfo" "$T/pdfinfo"
	fi
fi
"$BIN" plot hertz-elastic --kind loop --width 8.9cm --out "$T/f.svg" 2>"$T/err"
if python3 -c 'import sys, xml.etree.ElementTree as E
r = E.parse(sys.argv[1]).getroot()
sys.exit(0 if r.tag.endswith("}svg") and r.get("width", "").startswith("252") else 1)' "$T/f.svg" 2>"$T/err"; then
	ok "plot FILE.svg: parses as SVG, 8.9 cm = 252 pt wide"
else
	notok "plot FILE.svg" "$T/err"
fi
"$BIN" plot ptfe-pom --size 1600x1200 --out "$T/big.png" 2>"$T/err"
# IHDR: width and height, big-endian, at bytes 16..23
wh=$(od -An -tu1 -j16 -N8 "$T/big.png" | awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }')
size=$(wc -c <"$T/big.png")
if [ "$wh" = "1600 1200" ] && [ "$size" -lt 300000 ]; then
	ok "plot --size 1600x1200: 1600 x 1200 pixels, $size bytes"
else
	notok "plot --size 1600x1200: $wh, $size bytes" "$T/err"
fi

# --- pgfplots source: FILE.tex and FILE.dat (make check-tex compiles them) --
"$BIN" plot hertz-elastic --out "$T/fig.tex" 2>"$T/err"
rc=$?
if [ $rc -eq 0 ] && grep -q "^wrote $T/fig.tex\$" "$T/err" && grep -q "^wrote $T/fig.dat\$" "$T/err"; then
	ok "plot FILE.tex: writes FILE.tex and FILE.dat"
else
	notok "plot FILE.tex: exit $rc" "$T/err"
fi
# one axis per panel, one shaded rectangle per collision, every curve a
# pair of columns of the data file, every environment closed
"$BIN" --batch hertz-elastic -q --collisions "$T/h.csv" >/dev/null 2>&1
if [ "$(grep -c '^\\begin{axis}' "$T/fig.tex")" = 4 ] && [ "$(grep -c '^\\end{axis}' "$T/fig.tex")" = 4 ] &&
   [ "$(grep -c '^\\fill\[hbshade\]' "$T/fig.tex")" = "$((4 * $(grep -c '^[0-9]' "$T/h.csv")))" ] &&
   grep -q '^\\end{document}$' "$T/fig.tex"; then
	ok "plot FILE.tex: 4 axes, each collision shaded in each"
else
	notok "plot FILE.tex: axes or shading" "$T/fig.tex"
fi
missing=
for c in $(grep -o 'table\[x=x[0-9]*, y=y[0-9]*\] {fig.dat}' "$T/fig.tex" | sed 's/.*x=\(x[0-9]*\), y=\(y[0-9]*\).*/\1 \2/'); do
	grep -v '^#' "$T/fig.dat" | head -n 1 | tr ' ' '\n' | grep -qx "$c" || missing="$missing $c"
done
cols=$(grep -v '^#' "$T/fig.dat" | head -n 1 | wc -w)
if [ -z "$missing" ] && [ "$cols" = 8 ] &&
   [ "$(grep -v '^#' "$T/fig.dat" | awk '{ print NF }' | sort -u)" = 8 ]; then
	ok "plot FILE.tex: the data file has the 8 columns the .tex reads, on every row"
else
	notok "plot FILE.tex: data columns ($cols; missing:$missing)" "$T/fig.dat"
fi
if LC_ALL=de_DE.UTF-8 "$BIN" plot hertz-elastic --out "$T/de.tex" 2>/dev/null &&
   ! grep -v '^#' "$T/de.dat" | grep -q '[0-9],[0-9]'; then
	ok "plot FILE.tex: numbers with a decimal point under de_DE"
else
	notok "plot FILE.tex: de_DE numbers" "$T/de.dat"
fi

# --- a signal: the figure of what was computed, then 128 + N (signals.c) ----
"$BIN" plot hertz-elastic --set run.T=1e5 --set run.J=1e12 --dpi 72 --out "$T/sig.png" 2>"$T/err" &
pid=$!
i=0
# until the run has had 0.3 s of CPU (utime + stime, in ticks)
while [ "$(awk '{ print $14 + $15 }' "/proc/$pid/stat" 2>/dev/null || echo 0)" -lt 30 ] && [ "$i" -lt 400 ]; do
	sleep 0.05; i=$((i + 1))
done
kill -TERM "$pid"
wait "$pid"
rc=$?
if [ "$rc" -eq 143 ] && grep -q '^hybounce plot: SIGTERM: the run stopped; the figure shows what was computed$' "$T/err" &&
   grep -q "^wrote $T/sig.png\$" "$T/err"; then
	png "plot, SIGTERM: the figure of what was computed, exit 143" "$T/sig.png"
else
	notok "plot, SIGTERM: exit $rc" "$T/err"
fi

# --- bad input: exit 2, a message naming what is accepted, nothing written --
bad() {
	name=$1 pattern=$2
	shift 2
	"$BIN" plot "$@" >"$T/out" 2>"$T/err"
	rc=$?
	if [ $rc -eq 2 ] && grep -q -- "$pattern" "$T/err" && [ ! -e "$T/bad.png" ]; then
		ok "plot $name: exit 2, says '$pattern'"
	else
		notok "plot $name: exit $rc" "$T/err"
	fi
}
bad 'unknown format' 'expected a file ending in .png, .pdf, .svg or .tex' hertz-elastic --out "$T/bad.gif"
bad 'no --out' 'no --out FILE' hertz-elastic
bad 'unknown kind' 'expected state, observables, loop or sweep' hertz-elastic --kind heat --out "$T/bad.png"
bad 'bad --width' 'expected a length such as 3.5in' hertz-elastic --width 3.5 --out "$T/bad.png"
bad 'bad --size' 'expected WIDTHxHEIGHT' hertz-elastic --size 1600 --out "$T/bad.png"
bad 'bad --dpi' 'pixels per inch from 36 to 2400' hertz-elastic --dpi 0 --out "$T/bad.png"
bad '--collisions without loop' 'only --kind loop' hertz-elastic --collisions 1 --out "$T/bad.png"
bad 'bad --collisions' 'expected collision indices' hertz-elastic --kind loop --collisions 1,x --out "$T/bad.png"
bad 'no such collision' 'no collision i = 99' hertz-elastic --kind loop --collisions 99 --out "$T/bad.png"
bad 'unknown preset' 'no-such-preset' no-such-preset --out "$T/bad.png"
bad 'bad --set' 'law.c' hertz-elastic --set law.c=oops --out "$T/bad.png"
bad 'missing folder' "$T/none" hertz-elastic --out "$T/none/bad.png"
cp "$HYBOUNCE_PRESETS/hertz-elastic.preset" "$T/self.png"
"$BIN" plot "$T/self.png" --out "$T/self.png" >"$T/out" 2>"$T/err"
rc=$?
if [ $rc -eq 2 ] && grep -q 'is the preset being run' "$T/err" && cmp -s "$T/self.png" "$HYBOUNCE_PRESETS/hertz-elastic.preset"; then
	ok "plot: --out the preset being run is refused, the preset intact"
else
	notok "plot: --out the preset being run: exit $rc" "$T/err"
fi

# --- the man page documents every option of plot --help ----------------------
missing= n=0
for o in $("$BIN" plot --help | grep -o -- '--[a-z][a-z-]*' | sort -u); do
	n=$((n + 1))
	grep -q "^\.It .*Fl -${o#--}\\b" man/hybounce.1 || missing="$missing $o"
done
if [ "$n" -ge 9 ] && [ -z "$missing" ]; then ok "the man page documents every option of plot --help ($n)"
else notok "the man page documents every option of plot --help ($n found, missing:$missing)"; fi

[ "$fails" -eq 0 ]
