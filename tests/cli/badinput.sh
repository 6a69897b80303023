#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The bad-input matrix: every row of tests/cli/badinput.tab is one class of
# bad (or borderline) input, run for every front end that takes it:
#
#   ID ;; BATCH SWEEP FIT EXPLORER PLOT ;; FRAGMENT ;; SETUP ;; COMMAND [;; XFAIL REASON]
#
# The second field holds, per front end, the exit status expected from it,
# or "-" where the row does not apply (an explorer row whose input is good
# would start the terminal UI: not applicable).  An exit with a trailing x
# ("0x") marks that front end alone as an expected failure; without any x
# the row's XFAIL REASON covers every front end of the row.
#
# Each (row, front end) pair is a class, run in a fresh folder holding
# s.preset (a copy of steel-on-bitumen) and d.csv (three impact times).
# SETUP ("-" for none) prepares it; COMMAND runs (both through eval, with
# standard input /dev/null and output to a file) with $B bound to the
# front end, which takes the front-end-neutral part: the preset first, then
# --set, --data, output paths ... :
#
#   batch      hybounce --batch ARGS
#   sweep      hybounce sweep ARGS, plus --vary run.rtol=1e-9,1e-10,
#              --out sw and --jobs 1 where ARGS give none of these
#   fit        hybounce fit ARGS --quiet, plus --data d.csv, --free law.c and
#              --out fit.preset where ARGS give none of these
#   explorer   hybounce ARGS, standard input and output not a terminal:
#              bad input must be refused (exit 2) before the UI would start
#   plot       hybounce plot ARGS, plus --out o-fig.png where ARGS give none
#
# each under a time limit (a hang is exit 124; MATRIX_TIMEOUT=S before $B
# shortens it for a row that may hang).  $H is the bare binary under the
# same limit, for a row written for one front end.  FRAGMENT "=ran" stands
# for the front end's own line of a completed run ("ended" of the batch
# summary, "wrote sw/runs.csv", "wrote fit.preset", "wrote o-fig.png").
#
# A class passes when the command exits as expected, FRAGMENT (fixed
# string) is in its standard error or output, nothing crashed (no signal,
# no sanitizer report), a refusal (exit 2) says what is accepted or
# expected (or is the system's own reason, such as "Permission denied"),
# for a non-zero exit no file in the folder was created or changed (names,
# sizes, times, modes and MD5 sums), for any exit every file that was there
# before has the same bytes (but files named o-* that a successful run may
# write), the presets folder ($P, a copy of the shipped one) is unchanged,
# and no file named PWNED appeared (a canary: values hold $(touch PWNED),
# `touch PWNED` ...).  An XFAIL row states the behaviour required while
# another branch delivers it (or a bug to fix, "bug: ..."): while it does
# not hold the class prints "ok - ... # TODO xfail: REASON"; once it holds,
# it says that the mark can go.  A crash is never an expected failure.
#
# The five front ends run side by side, each over the whole table in
# folders of its own; their lines follow one another.  The totals: rows
# (distinct classes of input), classes run, crashes, refusals, expected
# failures, files damaged or lost, commands injected.  Runs under the
# sanitizer build too (make check-asan).
set -u
BIN=${HYBOUNCE_BIN:-build/hybounce}
case $BIN in /*) ;; *) BIN=$(pwd)/$BIN ;; esac
: "${HYBOUNCE_PRESETS:=$(pwd)/presets}"
export HYBOUNCE_PRESETS
TAB=${BADINPUT_TABLE:-tests/cli/badinput.tab}
REPO=$(pwd)
ROOT=$(mktemp -d)
chmod 755 "$ROOT"
trap 'chmod -R u+rwx "$ROOT" 2>/dev/null; rm -rf "$ROOT"' EXIT

# Every class runs copies in $ROOT: the presets (each front end its own
# copy, $P; a row that damages it damages the copy, restored for the next
# class), and as root the binary too, which the unprivileged rows' user
# may not reach where it is (CI clones into a private temporary folder).
if [ "$(id -u)" = 0 ] && cp "$BIN" "$ROOT/hybounce" && chmod 755 "$ROOT/hybounce"; then
	BIN=$ROOT/hybounce
fi
SHIPPED=$HYBOUNCE_PRESETS
presets_sum() { (cd "${1:-$P}" 2>/dev/null && find . -type f -exec md5sum {} + | LC_ALL=C sort); }
SSUM=$(presets_sum "$SHIPPED")
PSUM=$SSUM
# A sanitizer build (make check-asan): memcap uses the allocator's limit.
SAN=0
grep -a -q -e __asan_init -e __ubsan_handle "$BIN" 2>/dev/null && SAN=1
# GNU parallel's one-time citation notice stays out of the way.
export HOME="$ROOT/home"
mkdir -p "$HOME/.parallel" && touch "$HOME/.parallel/will-cite"

# --- the front ends ($B) and the bare binary ($H) ---
# sq WORD: WORD single-quoted for sh
sq() { printf "'%s'" "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")"; }
TL=${BADINPUT_TIMEOUT:-60}
mkdir "$ROOT/fe"
# wrapper NAME DEFAULTS-SCRIPT EXEC-LINE
wrapper() {
	{
		echo '#!/bin/sh'
		echo "# the bad-input matrix's front end: $1"
		printf '%s\n' "$2"
		printf 'exec timeout "${MATRIX_TIMEOUT:-%s}" %s %s\n' "$TL" "$(sq "$BIN")" "$3"
	} >"$ROOT/fe/$1"
	chmod 755 "$ROOT/fe/$1"
}
wrapper batch '' '--batch "$@"'
wrapper hybounce '' '"$@"'
wrapper explorer '' '"$@"'
wrapper sweep 'v=1 o=1 j=1
for a in "$@"; do
	case $a in
	--vary | --vary=* | -v | -v?*) v=0 ;;
	--out | --out=* | -o | -o?* | --merge | --merge=*) o=0 ;;
	--jobs | --jobs=* | -j | -j?*) j=0 ;;
	esac
done
[ $v = 1 ] && set -- "$@" --vary run.rtol=1e-9,1e-10
[ $o = 1 ] && set -- "$@" --out sw
[ $j = 1 ] && set -- "$@" --jobs 1' 'sweep "$@"'
wrapper fit 'd=1 f=1 o=1
for a in "$@"; do
	case $a in
	--data | --data=* | -d | -d?*) d=0 ;;
	--free | --free=* | -f | -f?*) f=0 ;;
	--out | --out=* | -o | -o?*) o=0 ;;
	esac
done
[ $d = 1 ] && set -- "$@" --data d.csv
[ $f = 1 ] && set -- "$@" --free law.c
[ $o = 1 ] && set -- "$@" --out fit.preset' 'fit "$@" --quiet'
wrapper plot 'o=1
for a in "$@"; do
	case $a in
	--out | --out=* | -o | -o?*) o=0 ;;
	esac
done
[ $o = 1 ] && set -- "$@" --out o-fig.png' 'plot "$@"'
H=$ROOT/fe/hybounce
# A stand-in for Slurm's sbatch (rows that run what --emit slurm printed):
# takes the options the emitted script uses (--wrap, --chdir, --output,
# --array with N, N-M and lists of them, --dependency=afterok:... or
# afterany:..., --parsable, --job-name, --ntasks, --cpus-per-task, --time,
# --mem, --partition, --account, --qos) and refuses any other, runs the job
# at once (each task of --array, in the --chdir folder, with Slurm's
# variables set, its output to --output with %j %A %a replaced), skips a
# job whose afterok dependency failed, and prints the job's id.
mkdir "$ROOT/slurm"
cat >"$ROOT/slurm/sbatch" <<'EOF'
#!/bin/sh
state=${0%/*}/state
mkdir -p "$state" || exit 1
arr=0 array=0 chdir=. output=slurm-%j.out wrap= haswrap=0 dep= cpus= parsable=0 script=
for a in "$@"; do
	case $a in
	--array=*) arr=${a#--array=}; array=1 ;;
	--chdir=*) chdir=${a#--chdir=} ;;
	--output=*) output=${a#--output=} ;;
	--wrap=*) wrap=${a#--wrap=}; haswrap=1 ;;
	--dependency=*) dep=${a#--dependency=} ;;
	--cpus-per-task=*) cpus=${a#--cpus-per-task=} ;;
	--parsable) parsable=1 ;;
	--job-name=* | --ntasks=* | --time=* | --mem=* | --partition=* | --account=* | --qos=*) ;;
	-*) echo "sbatch (stand-in): option not supported: $a" >&2; exit 1 ;;
	*) [ -z "$script" ] || { echo "sbatch (stand-in): two scripts" >&2; exit 1; }; script=$a ;;
	esac
done
if [ "$haswrap" = 0 ]; then
	if [ -n "$script" ]; then wrap=$(cat "$script") || exit 1; else wrap=$(cat); fi
fi
id=$(($(cat "$state/last" 2>/dev/null || echo 4241) + 1))
echo "$id" >"$state/last"
run=1
case $dep in
'') ;;
afterok:*)
	for d in $(echo "${dep#afterok:}" | tr ':' ' '); do
		[ -e "$state/ok-$d" ] || run=0
	done ;;
afterany:*) ;;   # the jobs before ran already, whatever their fate
*) echo "sbatch (stand-in): dependency not supported: $dep" >&2; exit 1 ;;
esac
if [ "$run" = 1 ]; then
	fail=0
	for r in $(echo "$arr" | tr ',' ' '); do
		i=${r%-*}
		while [ "$i" -le "${r#*-}" ]; do
			o=$output
			case $o in *%*) o=$(printf '%s' "$o" | sed "s/%j/$id/g; s/%A/$id/g; s/%a/$i/g") ;; esac
			if [ "$array" = 1 ]; then
				(cd "$chdir" && SLURM_JOB_ID=$id SLURM_ARRAY_JOB_ID=$id SLURM_ARRAY_TASK_ID=$i \
					SLURM_CPUS_PER_TASK=$cpus sh -c "$wrap" >"$o" 2>&1) || fail=1
			else
				(cd "$chdir" && SLURM_JOB_ID=$id SLURM_CPUS_PER_TASK=$cpus \
					sh -c "$wrap" >"$o" 2>&1) || fail=1
			fi
			i=$((i + 1))
		done
	done
	[ "$fail" = 1 ] || : >"$state/ok-$id"
fi
if [ "$parsable" = 1 ]; then echo "$id"; else echo "Submitted batch job $id"; fi
EOF
chmod 755 "$ROOT/slurm/sbatch"
SLURM=$ROOT/slurm

# --- helpers for SETUP and COMMAND ---
# pre TEXT: in.preset from TEXT (printf %b: \n, \t, \000 ...)
pre() { printf '%b' "$1" >in.preset; }
# sedp EXPR: in.preset from the steel-on-bitumen preset through sed
sedp() { sed "$1" s.preset >in.preset; }
# dat TEXT: in.csv from TEXT (printf %b)
dat() { printf '%b' "$1" >in.csv; }
# asuser CMD...: CMD as an unprivileged user (permissions mean nothing to
# root).
asuser() {
	if [ "$(id -u)" = 0 ]; then
		setpriv --reuid=65534 --regid=65534 --clear-groups -- "$@"
	else
		"$@"
	fi
}
# memcap CMD...: CMD with its memory bounded (1 GiB of address space, or
# in a sanitizer build 256 MiB per allocation, the allocator's warning of
# a refused allocation left out), for rows whose input is endless.
memcap() {
	if [ "$SAN" = 1 ]; then
		ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}allocator_may_return_null=1:max_allocation_size_mb=256 \
			"$@" 2>"$S.memcap"
		s=$?
		grep -v -e 'WARNING: AddressSanitizer failed to allocate' "$S.memcap" >&2
		return $s
	fi
	(ulimit -v 1048576 && "$@")
}
# without TEXT CMD...: CMD, whose standard error must not hold TEXT (else
# exit 9)
without() {
	w=$1
	shift
	"$@" 2>"$S.without"
	s=$?
	cat "$S.without" >&2
	! grep -q -F -e "$w" "$S.without" || s=9
	return $s
}
# feed FILE FIFO: writes FILE into FIFO in the background (gives up after 20 s)
feed() { (timeout 20 sh -c 'cat "$1" >"$2"' sh "$1" "$2" &); }
# $quick: a short horizon for rows that run; $short: the same, quiet, for batch
quick="--set run.T=0.05"
short="--set run.T=0.05 -q"

# snapshot: every name in the folder with its size, time, mode and type,
# then the regular files' MD5 sums
snapshot() {
	find . -mindepth 1 -printf '%p %s %T@ %m %y\n' -type f -exec md5sum {} + 2>/dev/null |
		LC_ALL=C sort
}
# the folder every class starts from
mkdir "$ROOT/start"
cp "$REPO/presets/steel-on-bitumen.preset" "$ROOT/start/s.preset"
printf 't_e\n0.063843\n0.140077\n0.189077\n' >"$ROOT/start/d.csv"
chmod 777 "$ROOT/start"
chmod 644 "$ROOT/start/s.preset" "$ROOT/start/d.csv"

# run_class FE WANT XFAIL: one (row, front end) pair; the row is in
# id, frag, setup, cmd; the front end's folders in W, P, S.
run_class() {
	fe=$1 want=$2 xf=$3
	n=$((n + 1))
	cp -p -R "$ROOT/start" "$W"
	cd "$W" || exit 1
	[ "$setup" = - ] || (eval "$setup") >/dev/null 2>&1
	snapshot >"$S.0"
	(eval "$cmd") >"$S.out" 2>"$S.err" </dev/null
	rc=$?
	snapshot >"$S.1"
	E=$S.err
	# the files that were there keep their bytes (o-* may be written by a run)
	lost= changed=
	if ! cmp -s "$S.0" "$S.1"; then
		changed=$(grep -v -x -F -f "$S.0" "$S.1" | head -n 3 | tr '\n' ' ')
		lost=$(grep '^[0-9a-f]\{32\}  ' "$S.0" | grep -v -x -F -f "$S.1" | sed 's/^[0-9a-f]*  //' |
			{ if [ "$want" = 0 ]; then grep -v '^\./o-'; else cat; fi; } | head -n 3 | tr '\n' ' ')
	fi
	canary=
	[ -e PWNED ] && canary=PWNED
	case "$setup $cmd" in
	*PWNED*) canary=$(find "$W" -name PWNED 2>/dev/null | head -n 1) ;;
	esac
	shipped=
	case "$setup $cmd" in
	*'$P'* | *presets*)
		if [ "$(presets_sum)" != "$PSUM" ]; then
			shipped="a shipped preset was changed"
			rm -rf "$P" && cp -R "$SHIPPED" "$P" && chmod -R a+rX "$P"
		fi ;;
	esac
	frag1=$frag
	if [ "$frag" = =ran ]; then
		case $fe in
		batch) frag1=ended ;;
		sweep) frag1="wrote sw/runs.csv" ;;
		fit) frag1="wrote fit.preset" ;;
		plot) frag1="wrote o-fig.png" ;;
		*) frag1="(=ran does not apply to $fe)" ;;
		esac
	fi
	why= crashed=0 hurt=0 inj=0
	if [ "$rc" -gt 128 ] || grep -a -q -e 'runtime error' -e 'Sanitizer' -e 'Segmentation' "$E"; then
		why="crashed (exit $rc)"
		crashed=1
		crashes=$((crashes + 1))
	elif [ -n "$canary" ]; then
		why="a command was injected: ${canary#"$ROOT"/} exists"
		inj=1
	elif [ -n "$lost" ] || [ -n "$shipped" ]; then
		why="a file was damaged or lost: $lost$shipped"
		hurt=1
	elif [ "$rc" = 124 ]; then
		why="hung (killed after the time limit)"
	elif [ "$rc" != "$want" ]; then
		why="exit $rc, expected $want"
	elif ! grep -a -q -F -e "$frag1" "$E" "$S.out"; then
		why="the message lacks '$frag1'"
	elif [ "$want" = 2 ] && ! grep -a -q -i -e accepted -e expected -e known -e "Try 'hybounce" \
	    -e 'No such file' -e 'Permission denied' -e 'Not a directory' -e 'File name too long' \
	    -e 'No space left on device' -e 'e\.g\.' \
	    -e "nor .* is in " "$E"; then
		why="the refusal does not say what is accepted: $(head -c 200 "$E" | tr '\n' ' ')"
	elif [ "$want" != 0 ] && [ -n "$changed" ]; then
		why="a file was written or changed: $changed"
	fi
	[ "$want" = 2 ] && refusals=$((refusals + 1))
	if [ -z "$why" ]; then
		extra=
		[ -n "$xf" ] && extra=" (the xfail mark can go: $xf)"
		echo "ok - badinput $id [$fe]: exit $rc, '$frag1'$( [ "$want" != 0 ] && echo ', no file written')$extra"
	elif [ -n "$xf" ] && [ "$crashed" = 0 ]; then
		xfails=$((xfails + 1))
		xdamaged=$((xdamaged + hurt))
		xinjected=$((xinjected + inj))
		echo "ok - badinput $id [$fe]: $why # TODO xfail: $xf"
	else
		damaged=$((damaged + hurt))
		injected=$((injected + inj))
		echo "not ok - badinput $id [$fe]: $why"
		echo "#   command: $cmd"
		sed 's/^/#   stderr: /' "$E" | head -n 4 | cut -c 1-300
		fails=$((fails + 1))
	fi
	cd "$REPO" || exit 1
	rm -rf "$W" 2>/dev/null || { chmod -R u+rwx "$W"; rm -rf "$W"; }
	[ -z "$canary" ] || rm -f "$canary"
}

# run_fe INDEX FE: every row's class for the front end FE (the INDEXth exit
# field), in folders of its own; TAP lines on stdout, the counts in
# $ROOT/FE.counts.  The front ends run side by side.
run_fe() {
	k=$1 fe=$2
	rows=0 n=0 fails=0 crashes=0 refusals=0 xfails=0 damaged=0 injected=0 xdamaged=0 xinjected=0
	W=$ROOT/w-$fe S=$ROOT/s-$fe P=$ROOT/presets-$fe B=$ROOT/fe/$fe
	cp -R "$SHIPPED" "$P" && chmod -R a+rX "$P"
	HYBOUNCE_PRESETS=$P
	while IFS= read -r line; do
		case $line in '#'* | '') continue ;; esac
		id=${line%% ;; *}; rest=${line#* ;; }
		exits=${rest%% ;; *}; rest=${rest#* ;; }
		frag=${rest%% ;; *}; rest=${rest#* ;; }
		setup=${rest%% ;; *}; rest=${rest#* ;; }
		case $rest in
		*' ;; '*) cmd=${rest%% ;; *}; xfail=${rest#* ;; } ;;
		*) cmd=$rest; xfail= ;;
		esac
		# shellcheck disable=SC2086 # five words
		set -- $exits
		bad=
		[ $# = 5 ] || bad="$# exit fields, expected 5 (BATCH SWEEP FIT EXPLORER PLOT)"
		for e in "$@"; do
			case $e in - | [0-9] | [0-9][0-9] | [0-9]x | [0-9][0-9]x) ;; *) bad="exit field '$e'" ;; esac
		done
		case $exits in *x*) [ -n "$xfail" ] || bad="an x mark without an XFAIL reason" ;; esac
		if [ -n "$bad" ]; then
			if [ "$k" = 1 ]; then
				echo "not ok - badinput $id: the table's row is malformed: $bad"
				fails=$((fails + 1))
			fi
			continue
		fi
		rows=$((rows + 1))
		shift $((k - 1))
		e=$1
		[ "$e" = - ] && continue
		xf=
		case $exits in
		*x*) case $e in *x) xf=$xfail ;; esac ;;
		*) xf=$xfail ;;
		esac
		run_class "$fe" "${e%x}" "$xf"
	done <"$TAB"
	if [ "$(presets_sum)" != "$PSUM" ]; then
		echo "not ok - badinput [$fe]: the presets are as shipped at the end"
		damaged=$((damaged + 1))
		fails=$((fails + 1))
	fi
	echo "rows=$rows n=$n fails=$fails crashes=$crashes refusals=$refusals xfails=$xfails" \
		"damaged=$damaged injected=$injected xdamaged=$xdamaged xinjected=$xinjected" >"$ROOT/$fe.counts"
}

FES="batch sweep fit explorer plot"
# BADINPUT_FES: some of them only (a table's column being written)
k=0
for fe in $FES; do
	k=$((k + 1))
	case " ${BADINPUT_FES:-$FES} " in *" $fe "*) ;; *) continue ;; esac
	run_fe $k "$fe" >"$ROOT/$fe.tap" 2>&1 &
done
wait
n=0 fails=0 crashes=0 refusals=0 xfails=0 damaged=0 injected=0 xdamaged=0 xinjected=0
per=
FES=${BADINPUT_FES:-$FES}
for fe in $FES; do
	cat "$ROOT/$fe.tap"
	t_n=$n t_fails=$fails t_crashes=$crashes t_refusals=$refusals t_xfails=$xfails
	t_damaged=$damaged t_injected=$injected t_xdamaged=$xdamaged t_xinjected=$xinjected
	n=0
	if [ -f "$ROOT/$fe.counts" ]; then
		. "$ROOT/$fe.counts"
	else
		echo "not ok - badinput [$fe]: the front end's run ended early"
		fails=$((fails + 1))
	fi
	eval "n_$fe=$n"
	per="$per${per:+, }$fe $n"
	n=$((t_n + n)) fails=$((t_fails + fails)) crashes=$((t_crashes + crashes))
	refusals=$((t_refusals + refusals)) xfails=$((t_xfails + xfails))
	damaged=$((t_damaged + damaged)) injected=$((t_injected + injected))
	xdamaged=$((t_xdamaged + xdamaged)) xinjected=$((t_xinjected + xinjected))
done
if [ "$(presets_sum "$SHIPPED")" != "$SSUM" ]; then
	echo "not ok - badinput: the shipped presets are unchanged"
	damaged=$((damaged + 1))
	fails=$((fails + 1))
fi
echo "# badinput: ${rows:-0} rows (distinct classes of input), $n (row, front end) classes run: $per"
echo "# badinput: $crashes crashes, $refusals expected refusals (exit 2), $xfails expected" \
	"failures (xfail), $damaged files damaged or lost, $injected commands injected, $fails failed"
echo "# badinput: among the expected failures, $xdamaged damage or lose a file and" \
	"$xinjected have a command injected (each names the branch or the bug that fixes it)"
if [ "${rows:-0}" -ge 276 ]; then echo "ok - matrix: at least 276 distinct rows (${rows:-0})"
else echo "not ok - matrix: at least 276 distinct rows (only ${rows:-0})"; fails=$((fails + 1)); fi
if [ "$n" -ge 500 ]; then echo "ok - matrix: at least 500 classes ($n over ${rows:-0} rows)"
else echo "not ok - matrix: at least 500 classes (only $n)"; fails=$((fails + 1)); fi
for fe in $FES; do
	if eval "[ \${n_$fe:-0} -ge 50 ]"; then echo "ok - matrix: at least 50 classes run by $fe"
	else echo "not ok - matrix: at least 50 classes run by $fe"; fails=$((fails + 1)); fi
done
if [ "$crashes" = 0 ]; then echo "ok - matrix: no crash"
else echo "not ok - matrix: $crashes crashes"; fi
if [ "$damaged" = 0 ]; then echo "ok - matrix: no file damaged or lost"
else echo "not ok - matrix: $damaged classes damaged or lost a file"; fi
if [ "$injected" = 0 ]; then echo "ok - matrix: no command injected"
else echo "not ok - matrix: $injected classes had a command injected"; fi
[ "$fails" -eq 0 ] && [ "$crashes" -eq 0 ]
