#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# report.sh [DIR]: after `make bench` (DIR, default build/bench), splices the
# per-study table (DIR/study-table.md) into README.md between the
# STUDY-TABLE markers, and writes tests/bench/REPORT.md: a header, the
# README's engine summary (between the ENGINE-V2 markers) and the bench's
# own report (DIR/report.md), then, unchanged, the sections between the
# REFERENCE-SECTIONS markers (make bench-steppers writes into them), and
# DIR/studies.md, when there, into README.md (STUDIES-SUMMARY) and the
# report (STUDIES).  Run from the top of the tree (make bench-docs).
dir=${1:-build/bench}
here=$(dirname "$0")
for f in "$dir/study-table.md" "$dir/report.md"; do
	[ -r "$f" ] || { echo "report.sh: cannot read $f (run make bench first)" >&2; exit 2; }
done
. tests/tui/readme.inc
{ echo; cat "$dir/study-table.md"; echo; } | readme_splice README.md STUDY-TABLE || exit 1
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
the README carries, then the bench's report. Steps, rejected steps, rhs
counts and errors do not depend on the machine's load; times do (the
summary's side-by-side times were measured with hyperfine, the bench's
in-process).

## Engine v2 (as in the README)

HEAD
	readme_block README.md ENGINE-V2 | grep -v -e '^<!-- STUDY-TABLE-BEGIN -->$' -e '^<!-- STUDY-TABLE-END -->$'
	echo
	echo 'The report below is the new run (`make bench`), with the dop853 rows among the extra settings of each study.'
	echo
	cat "$dir/report.md"
	echo
	echo '<!-- REFERENCE-SECTIONS-BEGIN -->'
	cat "$kept"
	echo '<!-- REFERENCE-SECTIONS-END -->'
} >"$out.new" && mv "$out.new" "$out"
rm -f "$kept"
# make bench's per-study summary against the reference and SciPy
if [ -r "$dir/studies.md" ]; then
	{ echo; cat "$dir/studies.md"; echo; } | readme_splice README.md STUDIES-SUMMARY || exit 1
	{ echo; cat "$dir/studies.md"; echo; } | readme_splice "$out" STUDIES || exit 1
fi
echo "README.md (STUDY-TABLE) and $out written"
