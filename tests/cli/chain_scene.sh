#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A chain's single bodies and interfaces (docs/chains.md section 7): a
# preset's [body.I], [interface.K] and [initial] body.I.* sections and the
# same keys in --set and sweep --vary; the elastic chain with a heavier
# ball and another striker keeps its kinetic energy 2 m (striker at 2 m/s)
# and momentum; the scene written beside --collisions reads back to the
# same run; sweep --vary and fit --free reach a body's key; keys outside
# the chain, unknown or derived are refused, exit 2.
. "$(dirname "$0")/common.inc"
. "$(dirname "$0")/../chain.inc"

steel_chain 'cradle of five with a heavy ball' 5 '1 mm' '50 ms' '[body.3]
R = 12 mm
[initial]
body.5.v = -2 m/s' >"$T/c.preset"

mkdir "$T/exp"
# 2 m with m = 4/3 pi (10 mm)^3 7800 kg/m^3 = 32.6725636 g
if "$BIN" --batch "$T/c.preset" --quiet --collisions "$T/exp/c.csv" >"$T/out1" 2>&1 &&
    grep -q '^  chain       kinetic energy 65.3451 mJ, stored 0 J, dissipated [^,]*, momentum -0.0653451272 kg m/s$' "$T/out1" &&
    grep -q '^  body 1      u = -1.85757 m/s' "$T/out1"; then
	ok "[body.3] R = 12 mm, [initial] body.5.v: energy 2 m and momentum -2 m kept, body 1 leaves"
else
	notok "[body.3] R = 12 mm, [initial] body.5.v: energy 2 m and momentum -2 m kept, body 1 leaves" "$T/out1"
fi

if grep -q '^\[body.3\]$' "$T/exp/c.preset" && grep -q '^R = 0.012 m$' "$T/exp/c.preset" &&
    grep -q '^body.5.v = -2 m/s$' "$T/exp/c.preset" &&
    "$BIN" --batch "$T/exp/c.preset" --quiet >"$T/out2" 2>&1 &&
    grep -v -e 'run time' -e '^wrote ' "$T/out1" >"$T/a" && grep -v 'run time' "$T/out2" >"$T/b" &&
    cmp -s "$T/a" "$T/b"; then
	ok "the scene written beside --collisions has [body.3] and body.5.v and gives the same run"
else
	notok "the scene written beside --collisions has [body.3] and body.5.v and gives the same run" "$T/exp/c.preset"
fi

if "$BIN" --batch "$T/c.preset" >"$T/out" 2>&1 &&
    grep -q '^system      chain of 5 bodies (each body 1, the law between neighbours, but for the overrides), 1 mm apart' "$T/out" &&
    grep -q '^overrides   body.3.R = 12 mm, initial.body.5.v = -2 m/s$' "$T/out"; then
	ok "the report's header names the overrides"
else
	notok "the report's header names the overrides" "$T/out"
fi

# the same through --set: body 3 back to the others' radius, the striker at 1 m/s
if "$BIN" --batch "$T/c.preset" --set body.3.R=10mm --set initial.body.5.v=-1 --quiet >"$T/out" 2>&1 &&
    grep -q '^  body 1      u = -1 m/s' "$T/out" &&
    grep -q '^  chain       kinetic energy 16.3363 mJ, stored 0 J, dissipated [^,]*, momentum -0.0326725636 kg m/s$' "$T/out"; then
	ok "--set body.3.R=10mm --set initial.body.5.v=-1: the uniform cradle, body 1 leaves at -1 m/s"
else
	notok "--set body.3.R=10mm --set initial.body.5.v=-1: the uniform cradle, body 1 leaves at -1 m/s" "$T/out"
fi

if "$BIN" sweep "$T/c.preset" --vary body.3.R=10mm:12mm:2 --out "$T/sw" >"$T/out" 2>&1 &&
    head -1 "$T/sw/runs.csv" | grep -q '^id,body.3.R,status,' &&
    [ "$(grep -c ',ok,' "$T/sw/runs.csv")" -eq 2 ]; then
	ok "sweep --vary body.3.R: two runs, the key a column"
else
	notok "sweep --vary body.3.R: two runs, the key a column" "$T/out"
fi

# fit: body 3's radius from the first four impact times of the run above (t_e is
# column 3 of a chain's CSV, after i and k)
{ echo t_e; cut -d, -f3 "$T/exp/c.csv" | sed -n 2,5p; } >"$T/te.csv"
if "$BIN" fit "$T/c.preset" --data "$T/te.csv" --free body.3.R --set body.3.R=11.5mm --quiet \
    --set run.rtol=1e-13 --out "$T/fit.preset" >"$T/out" 2>&1 &&
    grep -Eq '^  body.3.R +0.0115 +0.012 ' "$T/out" && grep -q '^R = 0.0120000000000' "$T/fit.preset"; then
	ok "fit --free body.3.R from 11.5 mm finds the 12 mm of the impact times"
else
	notok "fit --free body.3.R from 11.5 mm finds the 12 mm of the impact times" "$T/out"
fi

refused() { # NAME PATTERN ARGS...
	name=$1 pat=$2
	shift 2
	"$BIN" --batch "$@" >"$T/out" 2>&1
	rc=$?
	if [ $rc -eq 2 ] && grep -q -- "$pat" "$T/out"; then ok "$name refused, exit 2"
	else notok "$name refused, exit 2 (got $rc)" "$T/out"; fi
}
refused "a body beyond the chain" 'body.6.R: the chain has 5 bodies; accepted: body.1 .. body.5' \
    "$T/c.preset" --set body.6.R=1mm
refused "an interface beyond the chain" 'interface.0.law: the chain of 5 bodies has no interface 0; accepted: interface.1 .. interface.4' \
    "$T/c.preset" --set interface.0.law=shccl
refused "an unknown body key" 'body.2.colour: unknown key; accepted: body.I.E, body.I.nu, body.I.rho, body.I.R, body.I.mass, body.I.F' \
    "$T/c.preset" --set body.2.colour=1
refused "a parameter the interface's law lacks" "interface.2.c: unknown key for interface 2 (law hertz); accepted: law, extension, k, p" \
    "$T/c.preset" --set interface.2.c=1
refused "a derived interface stiffness" 'interface.2.k: derived from the materials of bodies 2 and 3 by Hertz contact theory' \
    "$T/c.preset" --set interface.2.k=1e9
refused "a numbered body in a two-body scene" 'body.1.R: only a chain has numbered bodies and interfaces' \
    hertz-elastic --set body.1.R=1mm
printf '[body.9]\nR = 1 mm\n' >>"$T/c.preset"
refused "a preset's [body.9] in a chain of 5" 'c.preset:[0-9]*: \[body.9\] R: the chain has 5 bodies' "$T/c.preset"

[ "$fails" -eq 0 ]
