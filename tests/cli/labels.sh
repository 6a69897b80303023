#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# What a user reads never cites the paper's internal LaTeX labels
# ("tab:one", "eq. bwm_psi1", "eqs. u_1") or the project's issue numbers
# ("hard case of issue 4"): --help texts, the preset list and files, the
# law list with each parameter's help, the man page, a batch report.
set -u
BIN=${HYBOUNCE_BIN:-build/hybounce}
PRESETS=${HYBOUNCE_PRESETS:-presets}
fails=0
ok() { echo "ok - $1"; }
notok() { echo "not ok - $1"; fails=$((fails + 1)); }
LABEL='(tab|sec|ex|eq|fig|def|thm|rem):[a-z]|Example [a-z]+_[a-z_]+|eqs?\. [a-z][a-z0-9]*_[a-z0-9_]+|eqs?\. (k_hertz|x_static|ramp|vanishing|law)\b|issue [0-9]'

# the pattern itself finds what it must
if printf '%s\n' 'Table tab:one' 'by eq. k_hertz' '(eq. bwm_psi1)' 'eqs. u_1, u_2' \
    '(hard case of issue 4)' '(Example nonuniq_sep, section' | grep -Ec "$LABEL" | grep -qx 6 \
   && ! printf '%s\n' 'Table 1 of the paper' 'eq. (12)' 'Hertz contact theory' | grep -Eq "$LABEL"; then
	ok "the label pattern finds labels and passes plain words"
else
	notok "the label pattern finds labels and passes plain words"
fi

check() { # NAME: reads the text on stdin
	if found=$(grep -En "$LABEL"); then
		notok "$1 cites no internal label"
		printf '%s\n' "$found" | sed 's/^/#   /'
	else
		ok "$1 cites no internal label"
	fi
}

"$BIN" --help 2>&1 | check "--help"
"$BIN" sweep --help 2>&1 | check "sweep --help"
"$BIN" fit --help 2>&1 | check "fit --help"
"$BIN" --list-presets 2>&1 | check "--list-presets"
"$BIN" --list-laws 2>&1 | check "--list-laws"
cat "$PRESETS"/*.preset | check "the preset files (titles, descriptions, comments)"
check "the man page" < man/hybounce.1
"$BIN" --batch steel-on-bitumen --set run.T='5 ms' 2>&1 | check "a batch report"
"$BIN" --batch ptfe-pom --set run.T='5 ms' 2>&1 | check "a batch report of the full system"
"$BIN" --batch steel-on-bitumen --set law.k=1e8 2>&1 | check "the message of a derived key"
exit $((fails > 0))
