#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The binary128 reference (tests/reference/ref.c, built as hybounce-ref
# beside hybounce): a short run of it still agrees with the cached tables
# (tests/reference/STUDY.csv, `make reference`) to 1e-20, and the engine's
# default run of each study is within 1e-9 of it (the two model the same
# scene).
. "$(dirname "$0")/common.inc"
REF=$(dirname "$BIN")/hybounce-ref
PY=${PYTHON:-python3}
AGREE=tests/reference/agree.py

if [ ! -x "$REF" ]; then
	notok "reference: $REF is built (make all)"
	exit 1
fi
ok "reference: hybounce-ref is built"

for s in steel-on-bitumen permanent-contact-shccl; do
	"$REF" "$s" --tol 1e-22 --collisions 2 >"$T/short.csv" 2>"$T/err" &&
	    $PY $AGREE --limit 1e-20 --rows 2 "tests/reference/$s.csv" "$T/short.csv" >"$T/out" 2>&1 &&
	    ok "reference: $s, 2 collisions at tolerance 1e-22 agree with the cached table to 1e-20" ||
	    notok "reference: $s, a short run agrees with the cached table" "$T/out"
done

for s in steel-on-bitumen ptfe-pom permanent-contact-shccl permanent-contact-bwshccl \
    permanent-contact-bwmcl; do
	"$BIN" --batch "$s" --collisions - >"$T/eng.csv" 2>/dev/null &&
	    $PY $AGREE --limit 1e-9 "tests/reference/$s.csv" "$T/eng.csv" >"$T/out" 2>&1 &&
	    ok "reference: $s, the engine's default run is within 1e-9 of the reference" ||
	    notok "reference: $s, the engine agrees with the reference" "$T/out"
	n_ref=$(grep -c '^[0-9]' "tests/reference/$s.csv")
	n_eng=$(grep -c '^[0-9]' "$T/eng.csv")
	[ "$n_ref" = "$n_eng" ] && ok "reference: $s, $n_ref collisions in both" ||
	    notok "reference: $s, $n_ref collisions in the reference, $n_eng in the engine"
done

# the reference refuses what it does not know, naming what it accepts
if "$REF" no-such-study >"$T/o" 2>"$T/e"; then
	notok "reference: an unknown study is refused"
elif grep -q "accepted: steel-on-bitumen" "$T/e"; then
	ok "reference: an unknown study is refused, naming the studies"
else
	notok "reference: an unknown study's message names the studies" "$T/e"
fi
[ "$fails" -eq 0 ]
