#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# python.sh - the Python package's tests (tests/python/test_*.py, pytest),
# one TAP line per test from pytest's JUnit report, so that tests/run.sh
# counts them.  The package is the one `make python` placed beside the
# binary ($(dirname BIN)/python: build/python, build-asan/python), over the
# library of that build.  pytest's exit 5 (no test collected) and any exit
# without a report are failures.  Under a sanitizer build the library needs
# its runtime loaded first: LD_PRELOAD (leak detection off: the interpreter
# is not the code under test).
. "$(dirname "$0")/common.inc"

PY=${PYTHON:-/usr/bin/python3}
PKG=$(dirname "$BIN")/python
if [ ! -f "$PKG/hybounce/_cdef.py" ]; then
	notok "python: no package in $PKG (make python)"
	exit 1
fi
LIB=$(sed -n "s/^LIBRARIES = \['\([^']*\)'.*/\1/p" "$PKG/hybounce/_cdef.py")
pre=""
for rt in libasan libubsan libtsan; do
	if ldd "$LIB" 2>/dev/null | grep -q "$rt\.so"; then
		pre="$pre $(ldd "$LIB" | sed -n "s/.*\($rt\.so[^ ]*\) => \([^ ]*\).*/\2/p" | head -n 1)"
	fi
done
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
env ${pre:+LD_PRELOAD="${pre# }"} PYTHONPATH="$PKG" PYTHONDONTWRITEBYTECODE=1 HYBOUNCE_BIN="$BIN" \
    "$PY" -m pytest -q -p no:cacheprovider --junitxml="$T/report.xml" tests/python >"$T/out" 2>&1
rc=$?
if [ "$rc" -eq 5 ]; then
	notok "python: pytest collected no tests (exit 5)" "$T/out"
	exit 1
fi
if [ ! -s "$T/report.xml" ]; then
	notok "python: pytest exited $rc without a report" "$T/out"
	exit 1
fi
"$PY" - "$T/report.xml" <<'PYEOF' >"$T/tap"
import sys
import xml.etree.ElementTree as ET
n = 0
for case in ET.parse(sys.argv[1]).iter("testcase"):
    n += 1
    name = "python: %s::%s" % (case.get("classname"), case.get("name"))
    bad = case.find("failure") if case.find("failure") is not None else case.find("error")
    if case.find("skipped") is not None:
        print("ok - %s # SKIP %s" % (name, case.find("skipped").get("message", "")))
    elif bad is not None:
        print("not ok - %s" % name)
        for line in (bad.get("message") or "").splitlines()[:10]:
            print("# " + line)
    else:
        print("ok - %s" % name)
if n == 0:
    print("not ok - python: the report lists no test")
PYEOF
cat "$T/tap"
fails=$(grep -c '^not ok' "$T/tap")
if [ "$rc" -ne 0 ] && [ "$fails" -eq 0 ]; then
	notok "python: pytest exited $rc" "$T/out"
fi
[ "$fails" -eq 0 ]
