#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The generated parts of the man page (PRESETS keys, --collisions columns)
# and of the README (collisions table) agree with the engine's tables:
# hybounce-gendoc --check fails when one is stale (fix: make docs).  And
# every key of the table is in the man page, every column in the README.
. "$(dirname "$0")/common.inc"
GENDOC=$(dirname "$BIN")/hybounce-gendoc

if [ ! -x "$GENDOC" ]; then
	notok "$GENDOC is built (make all builds it)"
	exit 1
fi
for f in man/hybounce.1 README.md; do
	if out=$("$GENDOC" --check "$f" 2>&1); then
		ok "$f: the generated blocks agree with the tables"
	else
		notok "$f: the generated blocks agree with the tables"
		echo "$out" | sed 's/^/# /'
	fi
done

# --check must fail on a stale block (the test can fail).
sed 's/^Default: 9.81 m\/s^2\.$/Default: 9.80 m\/s^2./' man/hybounce.1 > "$T/stale.1"
if ! cmp -s man/hybounce.1 "$T/stale.1" && ! "$GENDOC" --check "$T/stale.1" 2>/dev/null; then
	ok "a stale man page is detected"
else
	notok "a stale man page is detected"
fi
cp "$T/stale.1" "$T/fixed.1"
"$GENDOC" "$T/fixed.1" 2>/dev/null
if cmp -s man/hybounce.1 "$T/fixed.1"; then ok "make docs restores it"
else notok "make docs restores it"; fi

# every key --set accepts is documented (the panel keys of the default scene)
missing=
for k in name description law extension E nu rho R mass g F1 F2 ramp F_e0 T_e T_s x0 v0 \
    x_m0 v_m0 T J stepper rtol atol h_max max_samples chatter reductions kinks limits; do
	grep -q "^\.It Cm $k\$" man/hybounce.1 || missing="$missing $k"
done
if [ -z "$missing" ]; then ok "the man page lists every preset key"
else notok "the man page lists every preset key (missing:$missing)"; fi

# the README table and the CSV header list the same columns
hdr=$("$BIN" --batch hertz-elastic --collisions - 2>/dev/null | head -1 | tr ',' ' ')
missing=
for c in $hdr; do
	grep -q "^| \`$c\` |" README.md || missing="$missing $c"
done
if [ -n "$hdr" ] && [ -z "$missing" ]; then ok "the README documents every CSV column ($hdr)"
else notok "the README documents every CSV column (missing:$missing)"; fi
exit $((fails > 0))
