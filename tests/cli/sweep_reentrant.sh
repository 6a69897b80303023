#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The engine is re-entrant: no hidden mutable static state, and the same
# point run in many threads at once gives the same bytes.
#  1. The writable static objects of the engine's objects (.data and .bss,
#     in libhybounce-internal.a, which keeps them apart; read-only
#     tables live in .rodata / .data.rel.ro, per-thread buffers in .tbss)
#     are only hb_step_bsimp_shifted, a pointer to a const step type set at
#     load time and never written (declared like GSL's own
#     gsl_odeiv2_step_*), and hb_preset_dirs()'s thread key, created once
#     under pthread_once (dirs_tls, dirs_once in preset_find.c), and the
#     table of libaubio's functions, loaded once under pthread_once and only
#     read after (aubio_once, aubio_tab, aubio_loaded, aubio_why in
#     onset_aubio.c), the lock around inih's process-wide options
#     (ini_lock in preset.c, preset_ini.h), and the C locale numbers are
#     read and written in, made once under pthread_once (cnum_locale,
#     cnum_once in cnum.c).
#  2. One point, 12 times, on 4 threads: every row and collision equal.
# make check-tsan runs this script with a ThreadSanitizer build
# (build-tsan/hybounce, TSAN_OPTIONS=halt_on_error=1): any data race fails it.
# Run from the repository root with $HYBOUNCE_BIN (see tests/run.sh).
. "$(dirname "$0")/common.inc"

LIB=$(dirname "$BIN")/libhybounce-internal.a
if [ -f "$LIB" ] && command -v objdump >/dev/null 2>&1; then
	# "SYMBOL (object)" for each object symbol in a writable data section.
	objdump -t "$LIB" | awk '
	    /^[^ ]*\.o:/ { obj = $1; sub(/:$/, "", obj) }
	    $3 == "O" && ($4 == ".data" || $4 == ".bss" || $4 ~ /^\.(data|bss)\./) && $4 !~ /^\.data\.rel\.ro/ {
	        name = $NF; sub(/\.[0-9]+$/, "", name)
	        if (name !~ /^(__asan|__odr_asan|__ubsan|\.L|___asan)/) print name " (" obj ")" }' |
	    sort -u >"$T/statics"
	grep -v -x -e 'hb_step_bsimp_shifted (step_bsimp.o)' -e 'dirs_tls (preset_find.o)' \
	    -e 'dirs_once (preset_find.o)' -e 'aubio_once (onset_aubio.o)' \
	    -e 'aubio_tab (onset_aubio.o)' -e 'aubio_loaded (onset_aubio.o)' \
	    -e 'aubio_why (onset_aubio.o)' -e 'ini_lock (preset.o)' \
	    -e 'cnum_locale (cnum.o)' -e 'cnum_once (cnum.o)' "$T/statics" >"$T/unknown"
	if grep -q -x 'hb_step_bsimp_shifted (step_bsimp.o)' "$T/statics" && [ ! -s "$T/unknown" ]; then
		ok "the engine has no mutable static state but a const step pointer, a pthread_once thread key, the once-loaded aubio table, inih's lock and the once-made C locale (objdump of .data and .bss)"
	else notok "libhybounce.a: unexpected mutable statics" "$T/unknown"; fi
else
	notok "objdump and $LIB are there to list the engine's writable statics"
fi

"$BIN" sweep steel-on-bitumen --vary "law.c=4400,4400,4400,4400,4400,4400,4400,4400,4400,4400,4400,4400" \
    --set run.T=0.2 --jobs 4 --quiet --out "$T/same" 2>"$T/err"
rc=$?
rows=$(tail -n +2 "$T/same/runs.csv" 2>/dev/null | cut -d, -f2- | sed 's/,[^,]*$//' | sort -u | wc -l)
colls=$(tail -n +2 "$T/same/collisions.csv" 2>/dev/null | cut -d, -f2- | sort | uniq -c | awk '{ print $1 }' | sort -u)
if [ $rc -eq 0 ] && [ "$rows" -eq 1 ] && [ "$colls" = 12 ] && [ ! -s "$T/err" ]; then
	ok "the same point 12 times on 4 threads: identical rows and collisions, no sanitizer report"
else notok "the same point 12 times on 4 threads (exit $rc, $rows distinct rows, counts $colls)" "$T/err"; fi
exit 0
