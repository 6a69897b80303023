#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# make check-tex: the pgfplots source of hybounce plot compiles with
# pdflatex (each kind, from a paper study; a sweep's curves and heat map;
# a fit's figure; runs compared) into a one-page PDF of the figure's size.  Not part of make check: it needs TeX Live's pgfplots
# (texlive-pictures, texlive-latex-base: about 220 MB; make deps-tex
# installs them).
#
#     sh tests/tex/check.sh        (HYBOUNCE_BIN, HYBOUNCE_PRESETS as for tests/cli)
. "$(dirname "$0")/../cli/common.inc"

if ! command -v pdflatex >/dev/null 2>&1; then
	notok "pdflatex is installed (make deps-tex installs it)"
	exit 1
fi
"$BIN" sweep steel-on-bitumen --vary law.c=1e3:1e5:5:log --set run.T=0.1 --out "$T/s1" -q 2>/dev/null
"$BIN" sweep steel-on-bitumen --vary law.c=1e3:1e5:5:log --vary initial.x0='10 um,40 um' \
	--set run.T=0.1 --out "$T/s2" -q 2>/dev/null
for k in state:steel-on-bitumen observables:ptfe-pom loop:permanent-contact-bwmcl \
    sweep:"$T/s1" heatmap:"$T/s2" fit: compare:steel-on-bitumen; do
	kind=${k%%:*} p=${k#*:}
	case $kind in
	heatmap) "$BIN" plot "$p" --out "$T/$kind.tex" 2>"$T/err" ;;
	compare) "$BIN" plot "$p" --laws shccl,bwmcl --variant law.c=2000 --variant law.c=20000 \
	             --out "$T/$kind.tex" 2>"$T/err" ;;
	fit) p=examples/fit/bounces.csv
	     "$BIN" fit steel-on-bitumen --data "$p" --free law.c,law.alpha -q --out "$T/f.preset" \
	         --plot "$T/$kind.tex" >/dev/null 2>"$T/err" ;;
	*) "$BIN" plot "$p" --kind "$kind" --out "$T/$kind.tex" 2>"$T/err" ;;
	esac
	if [ ! -s "$T/$kind.tex" ]; then
		notok "the $kind figure of $p as pgfplots source" "$T/err"
		continue
	fi
	if (cd "$T" && pdflatex -interaction=nonstopmode -halt-on-error "$kind.tex" >"$kind.out" 2>&1) &&
	   [ -s "$T/$kind.pdf" ]; then
		ok "pdflatex compiles the $kind figure of $p"
	else
		notok "pdflatex $kind.tex ($p)" "$T/$kind.log"
		grep -A3 '^!' "$T/$kind.log" | sed 's/^/# /' | head -n 12
		continue
	fi
	if command -v pdfinfo >/dev/null 2>&1; then
		if pdfinfo "$T/$kind.pdf" >"$T/info" 2>&1 && grep -q '^Pages: *1$' "$T/info"; then
			ok "$kind.pdf: one page ($(sed -n 's/^Page size: *//p' "$T/info"))"
		else
			notok "$kind.pdf: pdfinfo" "$T/info"
		fi
	fi
done
[ "$fails" -eq 0 ]
