#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# report.sh [DIR]: after `make bench` (DIR, default build/bench), splices the
# per-study table (DIR/study-table.md) into docs/speed-and-accuracy.md between the
# STUDY-TABLE markers, and writes tests/bench/REPORT.md: a header, the
# engine summary of docs/speed-and-accuracy.md (between the ENGINE-V2 markers), the bench's
# own report (DIR/report.md), then, unchanged, the sections between the
# REFERENCE-SECTIONS markers (make bench-steppers writes into them),
# tests/bench/REPORT-figures.md (the figure and Python targets), the
# chains' section (make bench-chains) and the sweep's (DIR/sweep.txt, from make bench-sweep; kept from the old report
# when there is none); and DIR/studies.md, when there, into README.md
# (STUDIES-SUMMARY) and the report (STUDIES).  Run from the top of the tree
# (make bench-docs).
dir=${1:-build/bench}
here=$(dirname "$0")
for f in "$dir/study-table.md" "$dir/report.md"; do
	[ -r "$f" ] || { echo "report.sh: cannot read $f (run make bench first)" >&2; exit 2; }
done
. tests/tui/readme.inc
doc=docs/speed-and-accuracy.md
{ echo; cat "$dir/study-table.md"; echo; } | readme_splice "$doc" STUDY-TABLE || exit 1
out="$here/REPORT.md"
# The sections measured against the binary128 reference (make
# bench-steppers) are kept as they are: they come from their own targets.
kept=$(mktemp)
readme_block "$out" REFERENCE-SECTIONS >"$kept"
{
	cat <<'HEAD'
# Speed against error: benchmark report (issue 8)

This file is written by `make bench-docs` from the latest `make bench`
(tests/bench/bench.c, which writes build/bench/report.md and
build/bench/work-precision.csv, the full run): first the engine-v2 summary
docs/speed-and-accuracy.md carries, then the bench's report. Steps, rejected steps, rhs
counts and errors do not depend on the machine's load; times do (the
summary's side-by-side times were measured with hyperfine, the bench's
in-process).

## Engine v2 (as in docs/speed-and-accuracy.md)

HEAD
	readme_block "$doc" ENGINE-V2 | grep -v -e '^<!-- STUDY-TABLE-BEGIN -->$' -e '^<!-- STUDY-TABLE-END -->$'
	echo
	echo 'The report below is the new run (`make bench`), with the dop853 rows among the extra settings of each study.'
	echo
	cat "$dir/report.md"
	echo
	echo '<!-- REFERENCE-SECTIONS-BEGIN -->'
	cat "$kept"
	echo '<!-- REFERENCE-SECTIONS-END -->'
	# the figure and Python targets (make bench-figures, make bench-python),
	# measured by hand: kept as written
	echo
	cat "$here/REPORT-figures.md"
	# the chains' figures (make bench-chains writes between its CHAINS
	# markers): kept as the report has them
	if [ -r "$out" ] && grep -q '^## Chains (make bench-chains)$' "$out"; then
		echo
		sed -n '/^## Chains (make bench-chains)$/,/^## Sweeps (make bench-sweep)$/p' "$out" |
			sed '$!b; /^## Sweeps/d' | sed -e :a -e '/^\n*$/{$d;N;ba' -e '}'
	fi
	# the sweep's figures (make bench-sweep), last: the latest run's and
	# the subsections written by hand after it, else the section as the
	# report had it
	if [ -r "$dir/sweep.txt" ]; then
		echo
		echo '## Sweeps (make bench-sweep)'
		echo
		echo 'The latest `make bench-sweep` (tests/bench/sweep.sh), as it printed it. The'
		echo 'times of section 1 depend on the load of the machine (its first line gives'
		echo 'the load average: above the processors, other programs share them); the'
		echo 'instructions, bytes and runs of sections 2 to 4 do not.'
		echo
		echo '```'
		cat "$dir/sweep.txt"
		echo '```'
		# the subsections written by hand below it (what each change did): kept
		if [ -r "$out" ]; then
			sed -n '/^## Sweeps (make bench-sweep)$/,$p' "$out" | sed -n '/^### /,$p' >"$kept.sweep"
			if [ -s "$kept.sweep" ]; then
				echo
				cat "$kept.sweep"
			fi
			rm -f "$kept.sweep"
		fi
	elif [ -r "$out" ]; then
		echo
		sed -n '/^## Sweeps (make bench-sweep)$/,$p' "$out"
	fi
} >"$out.new" && mv "$out.new" "$out"
rm -f "$kept"
# make bench's per-study summary against the reference and SciPy
if [ -r "$dir/studies.md" ]; then
	{ echo; cat "$dir/studies.md"; echo; } | readme_splice README.md STUDIES-SUMMARY || exit 1
	{ echo; cat "$dir/studies.md"; echo; } | readme_splice "$out" STUDIES || exit 1
fi
echo "$doc (STUDY-TABLE), README.md (STUDIES-SUMMARY) and $out written"
