/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_shards.c - the shards of a sweep folder: which journals it holds,
 * which shards are done (hb_sweep_shards_done, for --emit's resubmission)
 * and, for a merge that cannot be made, which are missing or incomplete,
 * by number.  A shard's points are K, K + N, K + 2N, ... (sweep.h).
 */
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "sweep_impl.h"

/* See sweep_impl.h. */
int
sweep_journals_list(const char *dir, char ***names, int *count, char *msg, size_t n)
{
	struct dirent *e;
	int rc = HB_OK;
	DIR *d;

	*names = NULL;
	*count = 0;
	if ((d = opendir(dir)) == NULL)
		return hb_status_set(msg, n, HB_EIO, "%s: %s", dir, strerror(errno));
	while ((e = readdir(d)) != NULL) {
		size_t l = strlen(e->d_name);
		char **nn;

		if (l <= 8 || strcmp(e->d_name + l - 8, ".journal") != 0)
			continue;
		if (*count == 65535 ||
		    (nn = realloc(*names, (size_t)(*count + 1) * sizeof **names)) == NULL) {
			rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			break;
		}
		*names = nn;
		if (((*names)[*count] = strdup(e->d_name)) == NULL) {
			rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			break;
		}
		(*count)++;
	}
	closedir(d);
	return rc;
}

void
sweep_names_free(char **names, int count)
{
	for (int i = 0; i < count; i++)
		free(names[i]);
	free(names);
}

/* N of "shard-K-of-N.journal", 0 for another name. */
static long
shards_of_name(const char *name)
{
	long k, ns;
	int end = 0;

	if (sscanf(name, "shard-%ld-of-%ld.journal%n", &k, &ns, &end) == 2 &&
	    name[end] == '\0' && k >= 0 && ns > k)
		return ns;
	return 0;
}

/* The shard count of the journals when they all name the same one, else 0. */
long
sweep_shards_of_names(char *const *names, int count)
{
	long ns = 0;

	for (int i = 0; i < count; i++) {
		long m = shards_of_name(names[i]);

		if (m == 0 || (ns != 0 && m != ns))
			return 0;
		ns = m;
	}
	return ns;
}

/* Points of shard k of ns in a sweep of np points. */
static long
shard_points(long np, long k, long ns)
{
	return k < np ? (np - k + ns - 1) / ns : 0;
}

/*
 * "2 of 4 shards incomplete: shard 1 (not started), shard 3 (3 of 5
 * points); 8 of 20 points missing" into msg, from have(ctx, id).
 */
int
sweep_shards_missing_msg(const char *dir, long np, long ns, int (*have)(const void *, long),
                         const void *ctx, long missing, char *msg, size_t n)
{
	char list[1400];
	size_t used = 0;
	long bad = 0, shown = 0;

	list[0] = '\0';
	for (long k = 0; k < ns; k++) {
		long pts = shard_points(np, k, ns), got = 0;

		for (long id = k; id < np; id += ns)
			got += have(ctx, id);
		if (got == pts)
			continue;
		bad++;
		if (shown < 12 && used < sizeof list - 64) {
			int w = got == 0
			    ? snprintf(list + used, sizeof list - used, "%sshard %ld (not started)",
			               shown ? ", " : "", k)
			    : snprintf(list + used, sizeof list - used, "%sshard %ld (%ld of %ld "
			               "points)", shown ? ", " : "", k, got, pts);
			used += (size_t)w;
			shown++;
		}
	}
	if (bad > shown)
		snprintf(list + used, sizeof list - used, ", and %ld more", bad - shown);
	return hb_status_set(msg, n, HB_EINVAL, "%s: %ld of %ld shard%s incomplete: %s; %ld of "
	                     "%ld points missing", dir, bad, ns, ns == 1 ? "" : "s", list,
	                     missing, np);
}

/* ------------------------------------------------------------------ */
/* Shards done                                                         */

static int
bit_add(void *ctx, long id, off_t off, size_t len)
{
	unsigned char *bits = ctx;

	(void)off;
	(void)len;
	bits[id / 8] |= (unsigned char)(1u << (id % 8));
	return HB_OK;
}

long
hb_sweep_shards_done(const struct hb_sweep *sw, const char *dir, long nshards,
                     unsigned char *done, char *msg, size_t n)
{
	long np = hb_sweep_npoints(sw), count = 0;
	char path[4200], c[4200], **names = NULL;
	unsigned char *bits;
	int nnames = 0, rc;

	snprintf(path, sizeof path, "%s/runs.csv", dir);
	snprintf(c, sizeof c, "%s/collisions.csv", dir);
	if (access(path, F_OK) == 0 && access(c, F_OK) == 0) {
		/* Merged: runs.csv is only ever written complete. */
		memset(done, 1, (size_t)nshards);
		return nshards;
	}
	if ((bits = calloc((size_t)np / 8 + 1, 1)) == NULL) {
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		return -1;
	}
	rc = sweep_journals_list(dir, &names, &nnames, msg, n);
	for (int i = 0; i < nnames && rc == HB_OK; i++) {
		snprintf(path, sizeof path, "%s/%s", dir, names[i]);
		rc = sweep_journal_scan(path, np, 0, bit_add, bits, msg, n);
	}
	sweep_names_free(names, nnames);
	for (long k = 0; k < nshards && rc == HB_OK; k++) {
		long id = k;

		while (id < np && (bits[id / 8] & (1u << (id % 8))))
			id += nshards;
		done[k] = id >= np;
		count += done[k];
	}
	free(bits);
	return rc == HB_OK ? count : -1;
}
