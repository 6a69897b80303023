#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# hybounce fit --jobs N gives the result of --jobs 1 to the bit: the same
# report on stdout, the same fitted preset (but for its provenance line,
# which holds the command), residuals and JSON report, for 1, 2 and 3
# threads, with P = 2 and P = 1 free keys (with P = 1 the Jacobian's
# column runs beside each trial point: fit.c f_cb) and for several trials.
# The stderr line "runs: ... s of CPU; ... s on N threads" is a
# measurement and is not compared; its form is checked.
. "$(dirname "$0")/common.inc"

printf 'trial,t_e\nA,0.063843\nA,0.140077\nA,0.189077\nA,0.223\nB,1.063855\nB,1.140034\nB,1.1891\nB,1.2233\n' \
	>"$T/trials.csv"

# same NAME ARGS...: the outputs of ARGS with --jobs 1, 2 and 3 are the same
same() {
	n=$1
	shift
	for j in 1 2 3; do
		"$BIN" fit "$@" --jobs "$j" --out "$T/$n$j.preset" --residuals "$T/$n$j.res.csv" \
			--report "$T/$n$j.json" >"$T/$n$j.out" 2>"$T/$n$j.err"
		echo $? >"$T/$n$j.rc"
		sed "s|$T/$n$j|OUT|g" "$T/$n$j.out" >"$T/$n$j.cmp"
		noprov "$T/$n$j.preset" >"$T/$n$j.preset.cmp"
	done
	for j in 2 3; do
		bad=""
		cmp -s "$T/${n}1.rc" "$T/$n$j.rc" || bad="$bad exit"
		cmp -s "$T/${n}1.cmp" "$T/$n$j.cmp" || bad="$bad stdout"
		cmp -s "$T/${n}1.preset.cmp" "$T/$n$j.preset.cmp" || bad="$bad preset"
		cmp -s "$T/${n}1.res.csv" "$T/$n$j.res.csv" || bad="$bad residuals"
		cmp -s "$T/${n}1.json" "$T/$n$j.json" || bad="$bad report"
		if [ -z "$bad" ] && [ -s "$T/$n$j.res.csv" ]; then
			ok "$n: --jobs $j gives what --jobs 1 gives, to the bit (exit $(cat "$T/$n$j.rc"))"
		else
			notok "$n: --jobs $j differs from --jobs 1 in:$bad" "$T/$n$j.err"
		fi
	done
	if grep -q "^hybounce fit: runs: .* s of CPU; .* s on 3 threads with a core each (.*x)$" \
		"$T/${n}3.err"; then
		ok "$n: the runs' CPU time and their span on 3 threads are reported"
	else
		notok "$n: the runs' CPU time and their span on 3 threads are reported" "$T/${n}3.err"
	fi
}

same p2 steel-on-bitumen --data examples/fit/bounces.csv --free law.c,law.alpha \
	--set law.c=2000 --set law.alpha=0.6
same p1 steel-on-bitumen --data examples/fit/bounces.csv --free law.c --set law.c=2000 \
	--set law.alpha=0.3
same trials steel-on-bitumen --data "$T/trials.csv" --free law.c,law.alpha --set law.c=3000 \
	--set law.alpha=0.5 --max-relative-se 1

[ "$fails" -eq 0 ]
