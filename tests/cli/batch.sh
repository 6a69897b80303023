#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Batch mode on every preset in presets/: exit 0, a collision table header,
# the summary; the paper's first study (steel-on-bitumen) has at least ten
# collisions; --check --jumps passes on every preset.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"

npresets=0
for f in presets/*.preset; do
	[ -f "$f" ] || continue
	npresets=$((npresets + 1))
	name=$(basename "$f" .preset)
	"$BIN" --batch "$name" >"$T/out" 2>"$T/err"
	rc=$?
	if [ "$rc" -eq 0 ]; then ok "batch $name exits 0"
	else notok "batch $name exits 0 (got $rc)" "$T/err"; fi
	if grep -Eq '^ *i +(k +)?t_e \[[a-z]*s\] .* e .*x_c\^max \[[a-zA-Z]*m\].*Lambda$' "$T/out"; then
		ok "batch $name prints the collision table header"
	else
		notok "batch $name prints the collision table header" "$T/out"
	fi
	if grep -q '^summary$' "$T/out" && grep -q '^  ended ' "$T/out" &&
	    grep -q '^  end state   t = ' "$T/out" && grep -q '^  collisions  [0-9]' "$T/out" &&
	    grep -q '^  steps       [0-9]' "$T/out"; then
		ok "batch $name prints the summary"
	else
		notok "batch $name prints the summary" "$T/out"
	fi
	if grep -q '^preset  *'"$name"' ' "$T/out" && grep -q '^law  *[a-z]*: ' "$T/out" &&
	    grep -Eq '^system  *(reduced H_r|full H_f|chain of [0-9]+ bodies)' "$T/out" &&
	    grep -q '^derived     E\* = ' "$T/out" && grep -q '^run  *T = .*rtol = ' "$T/out"; then
		ok "batch $name prints the header block"
	else
		notok "batch $name prints the header block" "$T/out"
	fi
	# Rows of the table: as many as the summary's count.
	n=$(sed -n 's/^  collisions  \([0-9]*\)$/\1/p' "$T/out")
	rows=$(awk '/^collisions \(/ { on = 1; getline; next } on && (/^$/ || /^contact in progress/) { on = 0 }
	            on && /^ *[0-9]+  / { n++ } END { print n + 0 }' "$T/out")
	if [ -n "$n" ] && [ "$rows" = "$n" ]; then
		ok "batch $name: one table row per collision ($n)"
	else
		notok "batch $name: one table row per collision (rows $rows, summary '$n')" "$T/out"
	fi
	if [ "$name" = steel-on-bitumen ]; then
		if [ -n "$n" ] && [ "$n" -ge 10 ]; then
			ok "batch steel-on-bitumen has >= 10 collisions ($n)"
		else
			notok "batch steel-on-bitumen has >= 10 collisions (got '$n')" "$T/out"
		fi
	fi

	"$BIN" -b "$name" --check --jumps --quiet >"$T/out" 2>"$T/err"
	rc=$?
	if [ "$rc" -eq 0 ] && grep -q 'solution pair: ok' "$T/out" &&
	    grep -q '^jumps ([0-9]*)' "$T/out" && ! grep -q 'collisions (' "$T/out"; then
		ok "batch $name --check --jumps --quiet: solution pair ok"
	else
		notok "batch $name --check --jumps --quiet: solution pair ok (exit $rc)" "$T/out"
		sed 's/^/# /' "$T/err" | head -n 5
	fi
done
if [ "$npresets" -gt 0 ]; then ok "presets/ holds $npresets presets"
else notok "presets/ holds presets"; fi
if [ -f presets/steel-on-bitumen.preset ]; then ok "the default preset steel-on-bitumen exists"
else notok "the default preset steel-on-bitumen exists"; fi

# The engine's word on stiffness: a suggestion under rk8pd, the switch under auto, silence elsewhere.
"$BIN" --batch hard-stiff-maxwell --set run.stepper=rk8pd --quiet >"$T/out" 2>&1
if grep -q '^  stiffness   the contact flow is stiff from t = .*: rk8pd is held back by stability' "$T/out" &&
    grep -q -- '--set run.stepper=auto (or bsimp) takes far fewer steps' "$T/out"; then
	ok "batch on a stiff contact under rk8pd suggests auto or bsimp"
else
	notok "batch on a stiff contact under rk8pd suggests auto or bsimp" "$T/out"
fi
"$BIN" --batch hard-stiff-maxwell --quiet >"$T/out" 2>&1
if grep -q '^  stiffness   .*run.stepper = auto went over to bsimp' "$T/out"; then
	ok "batch on a stiff contact under auto says it went over to bsimp"
else
	notok "batch on a stiff contact under auto says it went over to bsimp" "$T/out"
fi
"$BIN" --batch steel-on-bitumen --quiet >"$T/out" 2>&1
if ! grep -q 'stiff' "$T/out"; then ok "batch on the first study says nothing of stiffness"
else notok "batch on the first study says nothing of stiffness" "$T/out"; fi

# a run cut in a contact: its row has its own magnitudes (x_c^r is the indentation
# now, millions of the completed rows' fm): in the column's unit, as 7.9112e+09,
# not as a run of ten digits and more; a value that would read 0 likewise
"$BIN" --batch hertz-elastic --set run.T=0.0959s >"$T/out" 2>&1
live=$(sed -n '/^contact in progress/{n;p;}' "$T/out")
if [ -n "$live" ] && echo "$live" | awk '{ for (i = 1; i <= NF; i++) if (length($i) > 11) bad = 1 } END { exit bad }' &&
    echo "$live" | grep -Eq ' 7\.9112e\+09 '; then
	ok "a contact in progress: its values in the column's unit, in scientific notation where fixed would not read"
else
	notok "a contact in progress: its values in the column's unit, in scientific notation where fixed would not read" "$T/out"
fi
"$BIN" --batch steel-on-bitumen >"$T/out" 2>&1
if sed -n '/^contact in progress/{n;p;}' "$T/out" | grep -Eq '^12 .* -8\.97[0-9]+e-14 '; then
	ok "the first study's permanent contact: v_i in mm/s as -8.97e-14, not -0.00"
else
	notok "the first study's permanent contact: v_i in mm/s as -8.97e-14, not -0.00" "$T/out"
fi

[ "$fails" -eq 0 ]
