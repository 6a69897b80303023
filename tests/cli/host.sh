#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# libhybounce as a citizen of its host program (tests/host/):
#  - it exports nothing without the prefix: the shared library's dynamic
#    symbols and the static library's global ones are all hb_;
#  - a host that defines 30 of the library's internal names (names.c, with
#    bodies that abort) links the installed library statically and
#    dynamically (its symbols exported, so that they could interpose) and
#    runs a preset, exports CSV and saves the preset, getting the files of
#    hybounce --batch; a host that defines public names the library calls
#    itself (public.c: hb_atomic_add, hb_status_set, ...) does not redirect
#    the library's own calls to them (dynamic: -Bsymbolic-functions);
#  - the library leaves the process as the host set it: GSL's error
#    handler, locale, signal dispositions and mask, stdout's buffering,
#    environment, umask, working directory and inih's options, through a
#    run, an export, a sweep and a fit (citizen.c);
#  - hb_version() is the version of the header, and --version's commit.
# Prints the figures: prefix-less exported symbols (0), internal names
# the host defines (30).
. "$(dirname "$0")/common.inc"

install_dest
if [ "$rc" -eq 0 ] && [ -f "$LIB/libhybounce.a" ] && [ -e "$LIB/libhybounce.so" ]; then
	ok "make install into a DESTDIR"
else
	notok "make install into a DESTDIR (exit $rc)" "$T/install.log"
fi
export PKG_CONFIG_PATH="$LIB/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$DEST"
CFLAGS_HB=$(pkg-config --cflags hybounce)
LIBS_HB=$(pkg-config --libs hybounce)
# the static library's dependencies, without itself (linked by path)
LIBS_ST=$(pkg-config --static --libs hybounce | sed 's/-lhybounce//')
SAN=
readelf -d "$LIB/libhybounce.so" | grep -q 'libasan' && SAN=-fsanitize=address,undefined

# The figures: exported symbols without the prefix (the compiler's own,
# __*, aside: the sanitizers add __odr_asan.* and the like).
nm -D --defined-only "$LIB/libhybounce.so" | awk 'NF == 3 && $3 !~ /^__/ { print $3 }' >"$T/dyn"
nm -g --defined-only "$LIB/libhybounce.a" | awk 'NF == 3 && $3 !~ /^__/ { print $3 }' >"$T/st"
nodyn=$(grep -cv '^hb_' "$T/dyn")
nost=$(grep -cv '^hb_' "$T/st")
echo "# exported symbols without the hb_ prefix: $nodyn of $(wc -l <"$T/dyn") (nm -D libhybounce.so)," \
    "$nost of $(wc -l <"$T/st") (global in libhybounce.a)"
if [ -s "$T/dyn" ] && [ -s "$T/st" ] && [ "$nodyn" -eq 0 ] && [ "$nost" -eq 0 ]; then
	ok "every exported symbol has the hb_ prefix (shared and static library)"
else
	notok "every exported symbol has the hb_ prefix (not: $(grep -v '^hb_' "$T/dyn" "$T/st" | head -n 5 | tr '\n' ' '))"
fi

# The internal names the host defines: its global symbols that are hidden
# definitions of the engine's objects.
cc -std=c17 -Wall -Wextra -Werror $SAN -c tests/host/names.c -o "$T/names.o" 2>"$T/cc.log" ||
    notok "names.c compiles" "$T/cc.log"
for o in "$BUILD"/src/core/*.o; do
	readelf -sW "$o" | awk '$5 == "GLOBAL" && $6 == "HIDDEN" && $7 != "UND" && $8 !~ /^__/ { print $8 }'
done | sort -u >"$T/internal"
# (the compiler's own, __*, aside: ASan adds __odr_asan_gen_NAME to both)
nm -g --defined-only "$T/names.o" | awk 'NF == 3 && $3 !~ /^__/ { print $3 }' | sort -u >"$T/hostnames"
nnames=$(comm -12 "$T/internal" "$T/hostnames" | wc -l)
echo "# internal names of the library the host defines: $nnames"
if [ "$nnames" -eq 30 ]; then ok "the host defines 30 of the library's internal names"
else notok "the host defines 30 of the library's internal names ($nnames)"; fi

# The reference: hybounce --batch's files.
PRESET=steel-on-bitumen
mkdir -p "$T/ref"
"$BIN" --batch "$PRESET" --trace "$T/ref/trace.csv" --collisions "$T/ref/collisions.csv" \
    >/dev/null 2>"$T/ref.err" || notok "hybounce --batch writes the reference" "$T/ref.err"
# a preset's scene: its lines but comments and blank ones
scene() { grep -v '^;' "$1" 2>/dev/null | grep -v '^$'; }
scene "$T/ref/trace.preset" >"$T/ref/scene"
[ -s "$T/ref/scene" ] || notok "hybounce --batch writes the reference's preset"

# host NAME LINK...: builds tests/host/host_run.c with NAME's link line, runs
# it, compares its files with the reference.
host() {
	name=$1
	shift
	if ! cc -std=c17 -Wall -Wextra -Werror $SAN $CFLAGS_HB tests/host/host_run.c "$@" \
	    -o "$T/$name" >"$T/$name.log" 2>&1; then
		notok "$name: links" "$T/$name.log"
		return
	fi
	mkdir -p "$T/$name.out"
	LD_LIBRARY_PATH=$LIB "$T/$name" "$PRESET" "$T/$name.out" >"$T/$name.stdout" 2>"$T/$name.err"
	rc=$?
	bad=
	for f in trace.csv collisions.csv; do
		cmp -s "$T/ref/$f" "$T/$name.out/$f" || bad="$bad $f"
	done
	scene "$T/$name.out/trace.preset" | cmp -s - "$T/ref/scene" || bad="$bad trace.preset"
	scene "$T/$name.out/saved.preset" | cmp -s - "$T/ref/scene" || bad="$bad saved.preset"
	if [ "$rc" -eq 0 ] && [ -z "$bad" ]; then
		ok "$name: runs $PRESET, exports CSV and saves the preset: the files of hybounce --batch"
	else
		notok "$name: runs $PRESET, exports CSV and saves the preset: the files of hybounce --batch (exit $rc, differ:$bad)" "$T/$name.err"
	fi
}
host host-static "$T/names.o" "$LIB/libhybounce.a" $LIBS_ST
host host-dynamic -rdynamic "$T/names.o" $LIBS_HB
cc -std=c17 -Wall -Wextra -Werror $SAN -c tests/host/public.c -o "$T/public.o" 2>"$T/cc.log" ||
    notok "public.c compiles" "$T/cc.log"
host host-public -rdynamic "$T/public.o" $LIBS_HB
if LD_LIBRARY_PATH=$LIB ldd "$T/host-dynamic" 2>/dev/null | grep -q "$LIB/libhybounce.so" &&
    ! LD_LIBRARY_PATH=$LIB ldd "$T/host-static" 2>/dev/null | grep -q libhybounce; then
	ok "host-dynamic runs the installed libhybounce.so, host-static none"
else
	notok "host-dynamic runs the installed libhybounce.so, host-static none"
fi

# The version: the header's is the library's, and its commit is --version's.
set -- $(sed -n 's/^version //p' "$T/host-dynamic.stdout")
commit=$("$BIN" --version | sed -n '1s/^hybounce [0-9]*\.[0-9]*\.[0-9]* (commit \(.*\))$/\1/p')
if [ $# -eq 3 ] && [ "$1" = "$2" ] && [ -n "$commit" ] && [ "$3" = "$commit" ] &&
    [ "${1%%+*}" = "$(cat VERSION)" ]; then
	ok "hb_version() is HB_VERSION_STRING ($1), hb_version_commit() is --version's ($3)"
else
	notok "hb_version() is HB_VERSION_STRING, hb_version_commit() is --version's (got '$*', --version '$commit')"
fi

# No process-wide side effects.
if cc -std=c17 -Wall -Wextra -Werror $SAN $CFLAGS_HB $(pkg-config --cflags gsl inih) \
    tests/host/citizen.c -o "$T/citizen" $LIBS_HB $(pkg-config --libs gsl inih) -ldl \
    >"$T/citizen.log" 2>&1; then
	mkdir -p "$T/citizen.out"
	LD_LIBRARY_PATH=$LIB "$T/citizen" "$HYBOUNCE_PRESETS/$PRESET.preset" \
	    "$(pwd)/examples/fit/bounces.csv" "$T/citizen.out" >"$T/citizen.stdout" 2>"$T/citizen.err"
	rc=$?
	cat "$T/citizen.stdout"
	fails=$((fails + $(grep -c '^not ok' "$T/citizen.stdout")))
	if [ "$rc" -ne 0 ] || [ "$(grep -c '^ok' "$T/citizen.stdout")" -ne 13 ]; then
		notok "citizen runs to its end, 13 checks (exit $rc)" "$T/citizen.err"
	fi
else
	notok "citizen.c builds" "$T/citizen.log"
fi

MAKEFLAGS= MAKELEVEL= make -s BUILD="$BUILD" DESTDIR="$DEST" uninstall >/dev/null 2>&1
[ "$fails" -eq 0 ]
