#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A chain scene in batch: the header names the chain, the summary gives each
# body's velocity and kinetic energy and the chain's totals (Newton's cradle
# of three: the bottom ball leaves with the striker's velocity), --set
# reaches the chain keys, --check passes, and what a chain cannot run yet is
# refused with the key named, or stops the run saying why.
. "$(dirname "$0")/common.inc"

cat >"$T/cradle.preset" <<'P'
[scene]
name = cradle of three
law = hertz
[body1]
E = 200 GPa
nu = 0.3
rho = 7800 kg/m^3
R = 10 mm
[chain]
n = 3
spacing = 1 mm
[striker]
v = -1 m/s
[loads]
g = 0
[run]
T = 10 ms
rtol = 1e-12
atol = 1e-14
P

if "$BIN" --batch "$T/cradle.preset" --check >"$T/out" 2>&1 &&
    grep -q '^system      chain of 3 bodies (each body 1, the law between neighbours), 1 mm apart, striker (body 3) at -1 m/s$' "$T/out" &&
    grep -q '^collisions (2 completed)$' "$T/out" &&
    grep -q '^  body 1      u = -1 m/s, kinetic energy 16.3363 mJ$' "$T/out" &&
    grep -q '^  chain       kinetic energy 16.3363 mJ, momentum -0.0326725636 kg m/s$' "$T/out" &&
    grep -q '^  check       solution pair: ok' "$T/out" &&
    grep -q '^  check       physics: ok' "$T/out"; then
	ok "cradle of three: chain header, two collisions, bodies and totals, --check"
else
	notok "cradle of three: chain header, two collisions, bodies and totals, --check" "$T/out"
fi

if "$BIN" --batch "$T/cradle.preset" --set chain.n=5 --set striker.v=-3 --quiet >"$T/out" 2>&1 &&
    grep -q '^  collisions  4$' "$T/out" &&
    grep -q '^  body 1      u = -3 m/s' "$T/out" && grep -q '^  body 5 ' "$T/out"; then
	ok "--set chain.n=5 --set striker.v=-3: four collisions, body 1 leaves at -3 m/s"
else
	notok "--set chain.n=5 --set striker.v=-3: four collisions, body 1 leaves at -3 m/s" "$T/out"
fi

"$BIN" --batch "$T/cradle.preset" --set chain.spacing=0 >"$T/out" 2>&1
rc=$?
if [ $rc -eq 2 ] && grep -q 'chain.spacing: value 0 is out of range; accepted: (0, inf) m' "$T/out"; then
	ok "touching bodies (chain.spacing = 0) refused, exit 2"
else
	notok "touching bodies (chain.spacing = 0) refused, exit 2 (got $rc)" "$T/out"
fi

"$BIN" --batch "$T/cradle.preset" --set loads.F1=1 >"$T/out" 2>&1
rc=$?
if [ $rc -eq 2 ] && grep -q "loads.F1: a chain's load is gravity alone; accepted: 0 N" "$T/out"; then
	ok "a chain with loads.F1 refused, exit 2"
else
	notok "a chain with loads.F1 refused, exit 2 (got $rc)" "$T/out"
fi

# 1 nm apart the struck ball reaches the next one while the first contact lasts
"$BIN" --batch "$T/cradle.preset" --set chain.spacing=1nm --quiet >"$T/out" 2>&1
rc=$?
if [ $rc -eq 1 ] && grep -q 'interface 1 (bodies 1 and 2) closed while interface 2 was in contact: a chain carries one contact at a time' "$T/out"; then
	ok "two contacts at once stop the run naming both, exit 1"
else
	notok "two contacts at once stop the run naming both, exit 1 (got $rc)" "$T/out"
fi

[ "$fails" -eq 0 ]
