/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * names.c - the names the explorer's exports take: an export never
 * replaces an earlier one unasked, it takes the first free STEM-2.EXT,
 * STEM-3.EXT ...  Used by the exports of runs.c, figure.c and the sweep
 * view; calls no other file of the explorer (tests/cli/calls.sh).
 */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "tui.h"

/* 1 if a file (or a link, even dangling) is at path: an export must not replace it unasked. */
int
tui_path_taken(const char *path)
{
	struct stat st;

	return lstat(path, &st) == 0 && !S_ISCHR(st.st_mode) && !S_ISFIFO(st.st_mode);
}

int
tui_unused_name(const char *path, char *out, size_t n)
{
	const char *slash = strrchr(path, '/');
	const char *dot = strrchr(slash != NULL ? slash + 1 : path, '.');
	int stem = dot != NULL && dot != (slash != NULL ? slash + 1 : path)
	           ? (int)(dot - path) : (int)strlen(path);

	if (!tui_path_taken(path)) {
		snprintf(out, n, "%s", path);
		return 0;
	}
	for (int k = 2; k < 1000; k++) {
		if ((size_t)snprintf(out, n, "%.*s-%d%s", stem, path, k, path + stem) >= n)
			return -1;
		if (!tui_path_taken(out))
			return 1;
	}
	return -1;
}
