#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The presets calibrated on published ball standards: each is dropped from
# the standard's height and its first rebound (the apex, (e v_i)^2 / (2 g)
# from the collisions CSV) must lie inside the standard's band:
#   table-tennis-ittf  ITTF: from 305 mm onto a steel block, 240-260 mm
#   tennis-itf         ITF: from 100 in onto concrete, 53-58 in
# Two controls show the check can fail: the same balls with their damping
# doubled rebound below the band, without damping (c = 0) above it.
. "$(dirname "$0")/common.inc"

# band PRESET DROP_M LO_M HI_M WANT [SET...]: WANT "in", "below" or "above"
band() {
	p=$1 drop=$2 lo=$3 hi=$4 want=$5
	shift 5
	if ! "$BIN" --batch "$p" "$@" -q --collisions "$T/$p.csv" >"$T/$p.out" 2>&1; then
		notok "$p${*:+ $*}: the batch run" "$T/$p.out"
		return
	fi
	got=$(awk -F, -v drop="$drop" -v lo="$lo" -v hi="$hi" '
		NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
		NR == 2 { h = ($(col["e"]) * $(col["v_i"])) ^ 2 / (2 * 9.81)
		          printf "%s %.6g", (h < lo ? "below" : h > hi ? "above" : "in"), h }' \
		"$T/$p.csv")
	x0=$(sed -n 's/^x0 = //p' "presets/$p.preset")
	case $got in
	"$want "*) ok "$p${*:+ $*}: dropped from $x0, first rebound ${got#* } m: $want the band [$lo, $hi] m" ;;
	*) notok "$p${*:+ $*}: first rebound '$got', wanted $want [$lo, $hi] m" "$T/$p.csv" ;;
	esac
}

for p in table-tennis-ittf tennis-itf; do
	[ -f "presets/$p.preset" ] && ok "$p is shipped" || notok "$p is shipped"
done
grep -q '^x0 = 305 mm' presets/table-tennis-ittf.preset && ok "table-tennis-ittf: dropped from 305 mm" ||
	notok "table-tennis-ittf: dropped from 305 mm"
grep -q '^x0 = 2540 mm' presets/tennis-itf.preset && ok "tennis-itf: dropped from 100 in (2540 mm)" ||
	notok "tennis-itf: dropped from 100 in (2540 mm)"

band table-tennis-ittf 0.305 0.240 0.260 in
band table-tennis-ittf 0.305 0.240 0.260 below --set 'law.c=5494 N s m^-2'
band table-tennis-ittf 0.305 0.240 0.260 above --set law.c=0
band tennis-itf 2.54 1.3462 1.4732 in
band tennis-itf 2.54 1.3462 1.4732 below --set 'law.c=1759 N s m^-2'
band tennis-itf 2.54 1.3462 1.4732 above --set law.c=0

[ "$fails" -eq 0 ]
