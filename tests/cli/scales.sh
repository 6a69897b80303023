#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The batch header's "absolute tolerance = atol x scale" lists one scale per
# component of the contact ODE that was integrated, however many: with
# run.reductions=none the components that the reductions leave out (x, and
# the obstacle's x_m and v_m) come on top of the reduced ODE's, for every
# shipped preset with a contact (up to 11 components; the list stopped at 8).
. "$(dirname "$0")/common.inc"

# scales: the "name value" pairs of the header, one a line.
scales() {
	awk '/absolute tolerance = atol x scale/ { f = 1; next }
	     f && /^ *$/ { exit }
	     f { sub(/^ +/, ""); s = s (s == "" ? "" : " ") $0 }
	     END { n = split(s, p, ", "); for (i = 1; i <= n; i++) print p[i] }'
}

"$BIN" --batch ptfe-pom --set run.reductions=none >"$T/out" 2>&1
scales <"$T/out" | cut -d' ' -f1 | tr '\n' ' ' >"$T/names"
if [ "$(cat "$T/names")" = "x x_c v z_c W J_Fc J_Fe E_e x_m v_m " ]; then
	ok "ptfe-pom, run.reductions=none: the 10 components' scales ($(cat "$T/names"))"
else
	notok "ptfe-pom, run.reductions=none: the 10 components' scales, got '$(cat "$T/names")'" "$T/out"
fi

checked=0 most=0
for p in "$HYBOUNCE_PRESETS"/*.preset; do
	b=$(basename "$p" .preset)
	"$BIN" --batch "$b" >"$T/d" 2>&1
	"$BIN" --batch "$b" --set run.reductions=none >"$T/n" 2>&1
	scales <"$T/d" | cut -d' ' -f1 | sort >"$T/dn"
	[ -s "$T/dn" ] || continue # no contact: no scales
	scales <"$T/n" >"$T/np"
	cut -d' ' -f1 "$T/np" | sort >"$T/nn"
	{ cat "$T/dn"; printf 'v_m\nx\nx_m\n'; } | sort >"$T/want"
	nv=$(awk 'NF == 2 && $2 + 0 > 0' "$T/np" | wc -l)
	n=$(wc -l <"$T/np")
	if cmp -s "$T/nn" "$T/want" && [ "$nv" -eq "$n" ]; then
		checked=$((checked + 1))
		[ "$n" -gt "$most" ] && most=$n
	else
		notok "$b, run.reductions=none: one positive scale per component (got $(tr '\n' ' ' <"$T/nn"), want $(tr '\n' ' ' <"$T/want"))"
	fi
done
if [ "$checked" -ge 10 ] && [ "$most" -ge 11 ]; then
	ok "run.reductions=none: every component's scale printed for $checked presets (up to $most components)"
else
	notok "run.reductions=none: $checked presets checked, up to $most components"
fi
[ "$fails" -eq 0 ]
