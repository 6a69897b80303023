#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# version.sh TEMPLATE VERSIONFILE: prints include/hybounce/version.h (the
# Makefile writes it where it differs).  The release number is the
# VERSION file's; in a git checkout of this tree, `git describe --tags
# --always --dirty` refines it with the commit (see version.h.in).
set -eu
tmpl=$1 vfile=$2
num=$(tr -d ' \t\r\n' <"$vfile")
case $num in
[0-9]*.[0-9]*.[0-9]*) ;;
*) echo "$vfile: '$num' is not MAJOR.MINOR.PATCH" >&2; exit 1 ;;
esac
major=${num%%.*} rest=${num#*.}
minor=${rest%%.*} patch=${rest#*.}
string=$num commit=unknown
src=$(cd "$(dirname "$vfile")" && pwd -P)
# only this tree's own repository (not a tarball unpacked inside another one)
top=$(git -C "$src" rev-parse --show-toplevel 2>/dev/null || true)
if [ -n "$top" ] && [ "$(cd "$top" && pwd -P)" = "$src" ] &&
    desc=$(git -C "$src" describe --tags --always --dirty 2>/dev/null); then
	hash=$(git -C "$src" rev-parse --short=7 HEAD)
	dirty=
	case $desc in *-dirty) dirty=1 desc=${desc%-dirty} ;; esac
	commit=$hash${dirty:+-dirty}
	case $desc in
	"$num" | "v$num") string=$num${dirty:++g$hash.dirty} ;;
	*) string=$num+g$hash${dirty:+.dirty} ;;
	esac
fi
sed -e "s|@MAJOR@|$major|" -e "s|@MINOR@|$minor|" -e "s|@PATCH@|$patch|" \
    -e "s|@STRING@|$string|" -e "s|@COMMIT@|$commit|" "$tmpl"
