#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# libhybounce as an outside program sees it: `make install` into a DESTDIR
# puts the shared library (with its soname), the static library, the public
# headers under include/hybounce/ and hybounce.pc in place; the shared
# library exports only what the public headers declare; the examples (C and
# C++) build with `pkg-config --cflags --libs hybounce` alone and print the
# collisions the batch mode prints, to the bit; `make uninstall` removes it
# all.  Also: the core keeps no mutable static state (re-entrancy).
. "$(dirname "$0")/common.inc"

install_dest
PREFIX=$(sed -n 's/^prefix=//p' "$pc" 2>/dev/null)
if [ "$rc" -eq 0 ] && [ -n "$pc" ] && [ -n "$PREFIX" ]; then ok "make install into a DESTDIR (prefix $PREFIX)"
else notok "make install into a DESTDIR (exit $rc)" "$T/install.log"; fi

# the soname's number, from the Makefile (raised when the ABI changes)
SOV=$(sed -n 's/^SOVERSION := //p' Makefile)
SONAME=libhybounce.so.$SOV
missing=
for f in lib/libhybounce.a lib/libhybounce.so lib/$SONAME lib/pkgconfig/hybounce.pc \
    bin/hybounce share/man/man1/hybounce.1; do
	[ -e "$DEST$PREFIX/$f" ] || missing="$missing $f"
done
for h in include/hybounce/*.h include/hybounce/version.h; do
	[ -f "$DEST$PREFIX/$h" ] || missing="$missing $h"
done
if [ -z "$missing" ]; then ok "libraries, headers, hybounce.pc, binary and man page installed"
else notok "libraries, headers, hybounce.pc, binary and man page installed (missing:$missing)"; fi

so=$(readelf -d "$LIB/libhybounce.so" 2>/dev/null | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
if [ -n "$SOV" ] && [ "$so" = "$SONAME" ] && [ "$(readlink "$LIB/libhybounce.so")" = "$SONAME" ] &&
    [ -f "$LIB/$(readlink "$LIB/$SONAME")" ]; then
	ok "the shared library has the soname $SONAME and its links"
else
	notok "the shared library has the soname $SONAME and its links (soname '$so')"
fi

# Exported: every defined dynamic symbol must be declared in a public header
# (but for the compiler's own, __*: the sanitizers add __odr_asan.*).
nm -D --defined-only "$LIB/libhybounce.so" | awk 'NF == 3 && $3 !~ /^__/ { print $3 }' >"$T/exported"
n=0 extra=
while read -r sym; do
	n=$((n + 1))
	grep -qw -- "$sym" include/hybounce/*.h "$BUILD/include/hybounce/version.h" || extra="$extra $sym"
done <"$T/exported"
if [ "$n" -ge 50 ] && [ -z "$extra" ]; then
	ok "libhybounce.so exports only what the public headers declare ($n symbols)"
else
	notok "libhybounce.so exports only what the public headers declare ($n symbols; internal:$extra)"
fi

# C++: every public header opens and closes with the extern "C" guards.
unguarded=
for h in include/hybounce/*.h; do
	[ "$h" = include/hybounce/export.h ] && continue
	grep -q '^HB_BEGIN_DECLS$' "$h" && grep -q '^HB_END_DECLS$' "$h" || unguarded="$unguarded $h"
done
if [ -z "$unguarded" ]; then ok "every public header has HB_BEGIN_DECLS / HB_END_DECLS"
else notok "every public header has HB_BEGIN_DECLS / HB_END_DECLS (not:$unguarded)"; fi

export PKG_CONFIG_PATH="$LIB/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$DEST"
PC=$(pkg-config --cflags --libs hybounce 2>"$T/pc.err")
if [ -n "$PC" ]; then ok "pkg-config --cflags --libs hybounce finds the installed library"; echo "# $PC"
else notok "pkg-config --cflags --libs hybounce finds the installed library" "$T/pc.err"; fi
PCS=$(pkg-config --static --cflags --libs hybounce 2>/dev/null)
# A sanitized library (make check-asan) needs the sanitizer runtime first.
SAN=
readelf -d "$LIB/libhybounce.so" | grep -q 'libasan' && SAN=-fsanitize=address,undefined

# Each public header compiles on its own, as C17 and as C++17 (version.h,
# generated, too).
bad=
for h in include/hybounce/*.h include/hybounce/version.h; do
	printf '#include <hybounce/%s>\ntypedef int hb_not_empty;\n' "${h##*/}" >"$T/h.c"
	cp "$T/h.c" "$T/h.cpp"
	cc -std=c17 -Wall -Wextra -pedantic -Werror $(pkg-config --cflags hybounce) \
	    -fsyntax-only "$T/h.c" >>"$T/h.log" 2>&1 || bad="$bad C:${h##*/}"
	c++ -std=c++17 -Wall -Wextra -pedantic -Werror $(pkg-config --cflags hybounce) \
	    -fsyntax-only "$T/h.cpp" >>"$T/h.log" 2>&1 || bad="$bad C++:${h##*/}"
done
if [ -z "$bad" ]; then ok "each installed header compiles alone as C17 and as C++17"
else notok "each installed header compiles alone as C17 and as C++17 (fails:$bad)" "$T/h.log"; fi

"$BIN" --batch steel-on-bitumen --collisions - 2>/dev/null |
    awk -F, 'NR > 1 { print $1, $2, $3, $6, $7 }' >"$T/want"
[ -s "$T/want" ] || notok "batch --collisions - gives the reference collisions"

# example NAME COMPILER FLAGS... SOURCE: builds, runs on steel-on-bitumen,
# compares with the batch mode's collisions.
example() {
	name=$1 cc=$2
	shift 2
	if ! $cc "$@" -o "$T/$name" >"$T/$name.log" 2>&1; then
		notok "$name builds with pkg-config alone" "$T/$name.log"
		return
	fi
	ok "$name builds with pkg-config alone"
	LD_LIBRARY_PATH=$LIB "$T/$name" steel-on-bitumen >"$T/$name.out" 2>"$T/$name.err"
	rc=$?
	grep -v '^#' "$T/$name.out" >"$T/$name.rows"
	if [ "$rc" -eq 0 ] && [ -s "$T/$name.rows" ] && cmp -s "$T/$name.rows" "$T/want"; then
		ok "$name prints the collisions of hybounce --batch, to the bit ($(wc -l <"$T/want") rows)"
	else
		notok "$name prints the collisions of hybounce --batch, to the bit (exit $rc)" "$T/$name.err"
		diff "$T/$name.rows" "$T/want" | head -n 5 | sed 's/^/# /'
	fi
}
example run_preset cc -std=c17 -Wall -Wextra -Werror $SAN examples/run_preset.c $PC
example run_preset_cpp c++ -std=c++17 -Wall -Wextra -Werror $SAN examples/run_preset.cpp $PC
if [ -z "$SAN" ]; then
	example run_preset_static cc -std=c17 -Wall -Wextra -Werror -static examples/run_preset.c $PCS
else
	ok "run_preset_static # SKIP a sanitized build cannot link -static"
fi
if LD_LIBRARY_PATH=$LIB "$T/run_preset" no-such-preset >/dev/null 2>"$T/err"; [ $? -eq 2 ] &&
    grep -q 'no-such-preset' "$T/err"; then
	ok "run_preset reports a bad preset with the library's message and exits 2"
else
	notok "run_preset reports a bad preset with the library's message and exits 2" "$T/err"
fi

v=$("$DEST$PREFIX/bin/hybounce" --version 2>&1)
case $v in
hybounce*) ok "the installed binary runs ($v)" ;;
*) notok "the installed binary runs ($v)" ;;
esac

# Re-entrancy: no object of the core in writable static storage, except
# hb_preset_dirs()'s per-thread buffer (.tbss) with the pthread key that frees
# it when its thread ends (dirs_tls, dirs_once: set once by pthread_once),
# the step type pointer hb_step_bsimp_shifted, which is set once at
# compile time, like GSL's own, and the table of libaubio's functions,
# loaded once under pthread_once (aubio_once, aubio_tab, aubio_loaded,
# aubio_why in onset_aubio.c), the lock around inih's process-wide
# options (ini_lock in preset.c, preset_ini.h), and the C locale that numbers
# are read and written in, made once under pthread_once (cnum_locale,
# cnum_once in cnum.c).
objdump -t "$BUILD"/src/core/*.o |
    awk '$2 ~ /^[lg]$/ && $0 ~ / O / && $0 ~ /[ \t]\.(data|bss)/ && $0 !~ /\.data\.rel\.ro/ {
	    print $NF }' | grep -v '^hb_step_bsimp_shifted$\|^dirs_tls$\|^dirs_once$\|^ini_lock$\|^aubio_\(once\|tab\|loaded\|why\)$\|^cnum_\(locale\|once\)$' | grep -v '^__\|^\.' >"$T/statics"
if [ ! -s "$T/statics" ]; then ok "the core keeps no mutable static state"
else notok "the core keeps no mutable static state (found: $(tr '\n' ' ' <"$T/statics"))"; fi

# The Python package: installed where Debian's python3 looks (PYTHONDIR,
# under the DESTDIR here), its declarations naming the installed soname;
# it imports over the installed library (HYBOUNCE_LIB: the DESTDIR is not
# on the loader's path) and runs a preset.  Under a sanitizer build the
# library's runtime is preloaded, as tests/cli/python.sh does.
cdef=$(find "$DEST" -path '*/dist-packages/hybounce/_cdef.py' | head -n 1)
pre=
for rt in libasan libubsan; do
	pre="$pre $(ldd "$LIB/$SONAME" 2>/dev/null | sed -n "s/.*$rt\.so[^ ]* => \([^ ]*\).*/\1/p" | head -n 1)"
done
pre=$(echo $pre)
if [ -n "$cdef" ] && grep -q "^LIBRARIES = \['$SONAME', '$PREFIX/lib/$SONAME'\]" "$cdef" &&
    env ${pre:+LD_PRELOAD="$pre"} ASAN_OPTIONS=detect_leaks=0 PYTHONPATH="$(dirname "$(dirname "$cdef")")" \
    HYBOUNCE_LIB="$LIB/$SONAME" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -c '
import hybounce
r = hybounce.Run("steel-on-bitumen").run()
assert hybounce.__version__ == hybounce.LIBRARY_VERSION and len(r.collisions) > 0
print(hybounce.__version__, len(r.collisions))' >"$T/py.out" 2>&1; then
	ok "the installed Python package runs over the installed library ($(cat "$T/py.out"), ${cdef#"$DEST"})"
else
	notok "the installed Python package runs over the installed library (${cdef:-no _cdef.py})" "$T/py.out"
fi

MAKEFLAGS= MAKELEVEL= make -s BUILD="$BUILD" DESTDIR="$DEST" uninstall >"$T/uninstall.log" 2>&1
left=$(find "$DEST" ! -type d | sed "s|^$DEST||")
if [ -z "$left" ]; then ok "make uninstall removes every installed file"
else notok "make uninstall removes every installed file (left:$(echo $left))"; fi

[ "$fails" -eq 0 ]
