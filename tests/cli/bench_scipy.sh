#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# make bench-scipy (tests/bench/scipy.sh, tests/bench/scipy_ref.py) without
# depending on SciPy: the script refuses a Python without scipy with the
# install hint, and scipy_ref.py compiles.  Where Debian's python3-scipy is
# installed, a bounded smoke of the bench also runs (one study): its SciPy
# model must agree with hybounce (the script's own check at rtol 1e-13).
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"

if SCIPY_PYTHON=false sh tests/bench/scipy.sh "$BIN" "$T/out" >"$T/noscipy" 2>&1; then
	notok "bench-scipy without scipy fails" "$T/noscipy"
elif grep -q "make bench-scipy needs Debian's python3-scipy: apt-get install python3-scipy" "$T/noscipy" &&
    [ ! -e "$T/out/scipy.md" ]; then
	ok "bench-scipy without scipy fails and says how to install it"
else
	notok "bench-scipy without scipy says how to install it" "$T/noscipy"
fi

PY=
for p in /usr/bin/python3 python3; do
	command -v "$p" >/dev/null 2>&1 && { PY=$p; break; }
done
if [ -z "$PY" ]; then
	ok "scipy_ref.py compiles # SKIP no python3"
elif "$PY" -c 'import py_compile, sys; py_compile.compile(sys.argv[1], cfile=sys.argv[2], doraise=True)' \
    tests/bench/scipy_ref.py "$T/scipy_ref.pyc" >"$T/pyc" 2>&1; then
	ok "scipy_ref.py compiles"
else
	notok "scipy_ref.py compiles" "$T/pyc"
fi

if ! /usr/bin/python3 -c 'import scipy.integrate' >/dev/null 2>&1; then
	ok "bench-scipy smoke # SKIP no python3-scipy"
elif ! command -v hyperfine >/dev/null 2>&1; then
	# make deps-scipy installs both; python3-scipy may come alone (another package's need)
	ok "bench-scipy smoke # SKIP no hyperfine (make deps-scipy)"
elif sh tests/bench/scipy.sh --smoke "$BIN" "$T/out" >"$T/smoke" 2>&1 &&
    grep -q '^| 3, BWMCL | [0-9.]* | [0-9.-]* | [0-9-]*x | ' "$T/out/scipy.md" &&
    grep -q '^Same model: ' "$T/out/scipy.md"; then
	ok "bench-scipy smoke: the SciPy model agrees with hybounce, times reported"
else
	notok "bench-scipy smoke" "$T/smoke"
fi
[ "$fails" -eq 0 ]
