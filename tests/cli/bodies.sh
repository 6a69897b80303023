#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# --bodies FILE: each body's final mass, position, velocity and kinetic
# energy as CSV, after the provenance line; the same numbers as the
# summary's body lines and chain totals; one body for a drop on the floor;
# refused (exit 2, nothing written) as the same file as the scene saved
# beside --collisions, the preset being run, or standard output.
. "$(dirname "$0")/common.inc"
. "$(dirname "$0")/../chain.inc"

steel_chain 'cradle of three' 3 '1 mm' '10 ms' >"$T/c.preset"

cd "$T" || exit 1
if "$BIN" --batch c.preset --quiet --bodies b.csv >out 2>err &&
    grep -qx 'wrote b.csv' err &&
    head -1 b.csv | grep -q '^# hybounce .*(commit .*): .*--bodies b.csv$' &&
    sed -n 2p b.csv | grep -qx 'body,m,y,u,K' && [ "$(wc -l <b.csv)" -eq 5 ] &&
    awk -F, 'NR > 2 { K += $5; P += $2 * $4 }
             END { if (sprintf("%.6g", K) != "0.0163363" || sprintf("%.9g", P) != "-0.0326725636") exit 1 }' b.csv &&
    awk -F, '$1 == 1 { if (sprintf("%.6g", $4) != "-1") exit 1 }' b.csv &&
    grep -q '^  chain       kinetic energy 16.3363 mJ, stored 0 J, dissipated [^,]*, momentum -0.0326725636 kg m/s$' out; then
	ok "--bodies: provenance, header, three bodies whose K and m u sum to the summary's totals"
else
	notok "--bodies: provenance, header, three bodies whose K and m u sum to the summary's totals" b.csv
fi

if "$BIN" --batch hertz-elastic --set run.T=0.05 --quiet --bodies h.csv >out 2>&1 &&
    [ "$(grep -c '^[0-9]' h.csv)" -eq 1 ]; then
	ok "--bodies on a drop on the floor: one body"
else
	notok "--bodies on a drop on the floor: one body" h.csv
fi

refused() { # NAME PATTERN ARGS...
	name=$1 pat=$2
	shift 2
	rm -f x.csv x.preset
	"$BIN" --batch "$@" >out 2>&1
	rc=$?
	if [ $rc -eq 2 ] && grep -q -- "$pat" out && [ ! -e x.csv ] && [ ! -e x.preset ]; then
		ok "--bodies $name refused, exit 2, nothing written"
	else
		notok "--bodies $name refused, exit 2, nothing written (got $rc)" out
	fi
}
refused "as the scene saved beside --collisions" 'the scene saved beside the CSV x.preset and --bodies x.preset are the same file' \
    c.preset -c x.csv --bodies x.preset
refused "as the preset being run" '--bodies c.preset is the preset being run' c.preset --bodies c.preset
refused "to standard output" '--bodies -: ' c.preset --bodies -

[ "$fails" -eq 0 ]
