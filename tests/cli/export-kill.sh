#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A kill at any instant of an export leaves every target either its complete
# old version or its complete new version; a mixed set shows, both as
# different modification times (every file of one export carries the
# export's identifier as its modification time) and as CSV files whose
# cksum(1) differs from what the preset's export line says; what a killed
# export leaves behind is removed by the next export.  strace (Debian's strace package) kills
# the export at its Nth rename, write, link, unlink and fsync, for every N
# until the export runs through; and a failed rename is undone.
. "$(dirname "$0")/common.inc"

# LeakSanitizer cannot run under ptrace (the sanitizer build): no leak check here.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
export ASAN_OPTIONS
if ! command -v strace >/dev/null 2>&1 || ! strace -o /dev/null true 2>/dev/null; then
	ok "kills during an export # SKIP strace missing or ptrace not permitted"
	exit 0
fi

OLD="--set run.T=100ms"
NEW="--set run.T=150ms"
W=$T/w
mkdir "$W" "$T/old" "$T/new"
# The two versions of the set: old (in place before each trial) and new.
(cd "$T/old" && "$BIN" -b steel-on-bitumen -q $OLD -t arc.csv -c coll.csv >/dev/null 2>&1) &&
(cd "$T/new" && "$BIN" -b steel-on-bitumen -q $NEW -t arc.csv -c coll.csv >/dev/null 2>&1) ||
    { notok "reference exports"; exit 1; }
# The scene without its "; export ID" line, which names each export.
scene() { grep -v '^; export ' "$1"; }
scene "$T/new/arc.preset" >"$T/new.scene"

# cksum_says FILE: 0 when the cksum the preset's export line gives for FILE
# is what cksum(1) computes.
cksum_says() {
	want=$(tail -n 1 "$W/arc.preset" | sed -n "s/.* $1 (cksum \([0-9]*\) \([0-9]*\)).*/\1 \2/p")
	[ -n "$want" ] && [ "$want" = "$(cksum <"$W/$1" | sed 's/ *-$//')" ]
}

# version FILE: old, new or damaged.
version() {
	f=$1
	if cmp -s "$W/$f" "$T/old/$f"; then echo old; return; fi
	case $f in
	*.preset)
		# complete: the scene of the new run and a whole export line
		if scene "$W/$f" | cmp -s - "$T/new.scene" &&
		    tail -n 1 "$W/$f" | grep -q '^; export .*modification time$'; then
			echo new; return
		fi ;;
	*) if cmp -s "$W/$f" "$T/new/$f"; then echo new; return; fi ;;
	esac
	echo damaged
}

trials=0 killed=0 damaged=0 hidden=0 unseen=0 mixed=0
for call in rename write link unlink fsync; do
	n=1
	while [ "$n" -lt 400 ]; do
		rm -f "$W"/*
		cp -p "$T/old/arc.csv" "$T/old/coll.csv" "$T/old/arc.preset" "$W/"
		# (sh -c: the shell that says "Killed" writes to /dev/null)
		sh -c 'cd "$1" && shift && "$@" >/dev/null 2>&1' sh "$W" strace -f -o /dev/null \
		    -e "inject=$call:signal=SIGKILL:when=$n" \
		    "$BIN" -b steel-on-bitumen -q $NEW -t arc.csv -c coll.csv 2>/dev/null
		rc=$?
		trials=$((trials + 1))
		[ "$rc" -eq 0 ] && break
		if [ "$rc" -ne 137 ]; then
			notok "$call #$n: the run ended with exit $rc, not by the injected SIGKILL"
			break
		fi
		killed=$((killed + 1))
		set -- $(version arc.csv) $(version coll.csv) $(version arc.preset)
		case "$*" in *damaged*)
			damaged=$((damaged + 1))
			echo "# $call #$n: damaged set: $*" ;;
		esac
		if [ "$*" != "old old old" ] && [ "$*" != "new new new" ]; then
			mixed=$((mixed + 1))
			stamps=$(stat -c %y "$W/arc.csv" "$W/coll.csv" "$W/arc.preset" | sort -u | wc -l)
			if [ "$stamps" -lt 2 ]; then
				hidden=$((hidden + 1))
				echo "# $call #$n: mixed set ($*) with one modification time"
			fi
			if cksum_says arc.csv && cksum_says coll.csv; then
				unseen=$((unseen + 1))
				echo "# $call #$n: mixed set ($*) whose preset's cksums match"
			fi
		fi
		if [ "$*" = "new new new" ] || [ "$*" = "old old old" ]; then
			if ! cksum_says arc.csv || ! cksum_says coll.csv; then
				notok "$call #$n: a whole set ($1) whose preset's cksums do not match"
			fi
		fi
		# The next export removes what the killed one left.
		(cd "$W" && "$BIN" -b steel-on-bitumen -q $NEW -t arc.csv -c coll.csv >/dev/null 2>&1)
		left=$(cd "$W" && ls -A | grep -c 'hbtmp')
		if [ "$left" -ne 0 ]; then
			notok "$call #$n: the next export left $left temporary files"
			ls -A "$W" | sed 's/^/# /'
		fi
		n=$((n + 1))
	done
	[ "$n" -ge 400 ] && notok "$call: the export never ran through under strace"
	echo "# $call: killed at each of $((n - 1)) calls"
done
echo "# $trials runs, $killed killed during the run or the export, $mixed mixed sets"
if [ "$killed" -ge 20 ] && [ "$damaged" -eq 0 ]; then
	ok "every kill left each file complete, old or new ($killed kills, 0 damaged)"
else
	notok "every kill left each file complete, old or new ($killed kills, $damaged damaged)"
fi
if [ "$hidden" -eq 0 ]; then
	ok "every mixed set shows as different modification times ($mixed mixed, 0 undetectable)"
else
	notok "every mixed set shows as different modification times ($hidden of $mixed not)"
fi
if [ "$unseen" -eq 0 ] && [ "$mixed" -gt 0 ]; then
	ok "every mixed set shows in the preset's cksums ($mixed mixed, 0 undetectable)"
else
	notok "every mixed set shows in the preset's cksums ($unseen of $mixed not)"
fi

# A rename that fails: the renames made are undone, the old set stays,
# exit 2, no temporary file left.
for n in 1 2 3; do
	rm -f "$W"/*
	cp -p "$T/old/arc.csv" "$T/old/coll.csv" "$T/old/arc.preset" "$W/"
	(cd "$W" && strace -f -o /dev/null -e "inject=rename:error=EIO:when=$n" \
	    "$BIN" -b steel-on-bitumen -q $NEW -t arc.csv -c coll.csv >/dev/null 2>"$T/err")
	rc=$?
	set -- $(version arc.csv) $(version coll.csv) $(version arc.preset)
	left=$(ls -A "$W" | grep -c 'hbtmp')
	if [ "$rc" -eq 2 ] && [ "$*" = "old old old" ] && [ "$left" -eq 0 ] &&
	    grep -q 'export failed: .*Input/output error' "$T/err"; then
		ok "rename #$n fails: the old set is put back, exit 2, nothing left"
	else
		notok "rename #$n fails: the old set is put back, exit 2, nothing left (exit $rc, $*, $left left)"
		sed 's/^/# /' "$T/err"
	fi
done
[ "$fails" -eq 0 ]
