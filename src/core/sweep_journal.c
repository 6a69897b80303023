/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_journal.c - a sweep's folder and its journals, below the run, the
 * refinement, the shards and the merge that all use them: reading a file
 * whole, writing a buffer whole, preparing the folder (its identity,
 * sweep.preset, and what a refused point's run undoes), reading a journal
 * block by block (the format: sweep_run.c), a shard's journal's name and
 * its lock.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "hybounce/atomic.h"
#include "hybounce/csv.h"
#include "hybounce/input.h"
#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "clock.h"
#include "sweep_impl.h"

/* See sweep_impl.h. */
char *
sweep_slurp(const char *path, size_t *len, char *msg, size_t n)
{
	char *buf = NULL;

	errno = 0;
	if (access(path, F_OK) != 0 && errno == ENOENT)
		return NULL;
	if (hb_input_read(path, HB_INPUT_PRESET_MAX, &buf, len, msg, n) != HB_OK) {
		errno = EIO;
		return NULL;
	}
	return buf;
}

/*
 * 1 for a provenance comment (outputs.h: "; hybounce V (commit C): ..."):
 * it says which command wrote the file, not what the sweep is, and is left
 * out when a folder's sweep.preset is compared with a command's sweep.
 */
static int
provenance_line(const char *p, const char *end)
{
	const char *colon;

	if ((size_t)(end - p) < 12 || strncmp(p, "; hybounce ", 11) != 0)
		return 0;
	colon = memchr(p, ':', (size_t)(end - p));
	if (colon == NULL)
		return 0;
	for (const char *q = p; q + 8 <= colon; q++)
		if (memcmp(q, "(commit ", 8) == 0)
			return 1;
	return 0;
}

/* Removes the provenance lines of text (len bytes) in place; the new length. */
static size_t
strip_provenance(char *text, size_t len)
{
	size_t w = 0;

	for (size_t r = 0; r < len; ) {
		const char *nl = memchr(text + r, '\n', len - r);
		size_t l = nl != NULL ? (size_t)(nl - (text + r)) + 1 : len - r;

		if (!provenance_line(text + r, text + r + l)) {
			memmove(text + w, text + r, l);
			w += l;
		}
		r += l;
	}
	text[w] = '\0';
	return w;
}

/* See sweep_impl.h. */
int
sweep_write_all(int fd, const char *p, size_t len)
{
	while (len > 0) {
		ssize_t w = write(fd, p, len);

		if (w < 0) {
			if (errno == EINTR)
				continue;
			return -1;
		}
		p += w;
		len -= (size_t)w;
	}
	return 0;
}

static char *
spec_text(const struct hb_sweep *sw, size_t *len)
{
	size_t l = hb_sweep_spec_format(sw, NULL, 0);
	char *t = malloc(l + 1);

	if (t != NULL)
		hb_sweep_spec_format(sw, t, l + 1);
	*len = l;
	return t;
}

/*
 * 1 for the files a sweep folder may hold before its sweep.preset exists:
 * journals, and the atomic writer's temporary files of sweep.preset (those
 * of a process that is gone are removed when sweep.preset is written).
 */
static int
ours(const char *name)
{
	size_t l = strlen(name);

	return strcmp(name, ".") == 0 || strcmp(name, "..") == 0 ||
	       hb_atomic_is_temp(name, SWEEP_SPEC_NAME, NULL) ||
	       (l > 8 && strcmp(name + l - 8, ".journal") == 0);
}

int
hb_sweep_prepare_dir(const struct hb_sweep *sw, const char *dir, char *msg, size_t n)
{
	return hb_sweep_prepare_dir_with(sw, dir, NULL, msg, n);
}

int
hb_sweep_prepare_dir_with(const struct hb_sweep *sw, const char *dir, const char *provenance,
                          char *msg, size_t n)
{
	int made;

	return sweep_prepare_dir(sw, dir, provenance, &made, msg, n);
}

/* See sweep_impl.h. */
int
sweep_prepare_dir(const struct hb_sweep *sw, const char *dir, const char *provenance, int *made,
                  char *msg, size_t n)
{
	char path[4096];
	struct stat st;
	size_t len, have_len;
	char *want, *have;
	int rc;

	*made = 0;
	if (dir == NULL || dir[0] == '\0')
		return hb_status_set(msg, n, HB_EINVAL, "--out: empty folder name; expected a "
		                  "folder for runs.csv and collisions.csv");
	if (mkdir(dir, 0777) == 0)
		*made |= SWEEP_MADE_DIR;
	else if (errno != EEXIST)
		return hb_status_set(msg, n, HB_EINVAL, "--out %s: cannot create the folder: %s",
		                  dir, strerror(errno));
	if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
		return hb_status_set(msg, n, HB_EINVAL, "--out %s: not a folder; expected a folder "
		                  "(created if missing)", dir);
	if (access(dir, W_OK) != 0)
		return hb_status_set(msg, n, HB_EINVAL, "--out %s: cannot write there: %s", dir,
		                  strerror(errno));
	want = spec_text(sw, &len);
	if (want == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	snprintf(path, sizeof path, "%s/" SWEEP_SPEC_NAME, dir);
	have = sweep_slurp(path, &have_len, msg, n);
	if (have != NULL) {
		have_len = strip_provenance(have, have_len);
		rc = have_len == len && memcmp(have, want, len) == 0 ? HB_OK
		   : hb_status_set(msg, n, HB_EINVAL, "--out %s: the folder holds a different "
		                "sweep (%s differs from this one's); expected a new folder, "
		                "or this sweep's own folder to resume it", dir, path);
		free(have);
		free(want);
		return rc;
	}
	if (errno != ENOENT) {
		free(want);
		return HB_EIO;   /* sweep_slurp said why */
	}
	{
		DIR *d = opendir(dir);
		struct dirent *e;

		if (d == NULL) {
			free(want);
			return hb_status_set(msg, n, HB_EIO, "%s: %s", dir, strerror(errno));
		}
		while ((e = readdir(d)) != NULL)
			if (!ours(e->d_name)) {
				hb_status_set(msg, n, HB_EINVAL, "--out %s: the folder is not empty "
				    "and holds no sweep (found %s); expected a new or empty folder",
				    dir, e->d_name);
				closedir(d);
				free(want);
				return HB_EINVAL;
			}
		closedir(d);
	}
	if (provenance != NULL && provenance[0] != '\0') {
		/* The spec, then the line saying which command wrote it. */
		size_t pl = strlen(provenance);
		char *nb = realloc(want, len + pl + 2);

		if (nb == NULL) {
			free(want);
			return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		}
		want = nb;
		memcpy(want + len, provenance, pl);
		want[len + pl] = '\n';
		len += pl + 1;
	}
	rc = hb_atomic_write_file(path, want, len, msg, n);
	free(want);
	if (rc == HB_OK)
		*made |= SWEEP_MADE_SPEC;
	return rc;
}

/* See sweep_impl.h. */
void
sweep_refused_undo(const char *dir, int made, const char *jpath)
{
	char path[4096];

	if (made & SWEEP_MADE_JOURNAL)
		(void)unlink(jpath);
	if (made & SWEEP_MADE_SPEC) {
		snprintf(path, sizeof path, "%s/" SWEEP_SPEC_NAME, dir);
		(void)unlink(path);
	}
	if (made & SWEEP_MADE_DIR)
		(void)rmdir(dir);   /* only when empty: nothing of anyone else's goes */
}

/* ------------------------------------------------------------------ */
/* Journal                                                             */

/* "c,ID," or "r,ID,": kind and id; -1 if the line is not a journal line. */
static int
journal_line(const char *line, size_t len, long *id)
{
	char *end;

	if (len < 4 || (line[0] != 'c' && line[0] != 'r') || line[1] != ',')
		return -1;
	errno = 0;
	*id = strtol(line + 2, &end, 10);
	if (end == line + 2 || *end != ',' || errno != 0 || *id < 0)
		return -1;
	return line[0];
}

/* See sweep_impl.h. */
int
sweep_journal_scan(const char *path, long npoints, int trunc,
             int (*seen)(void *, long, off_t, size_t), void *ctx, char *msg, size_t n)
{
	FILE *f = fopen(path, "r");
	char *line = NULL;
	size_t cap = 0;
	ssize_t got;
	off_t pos = 0, block = 0;
	long id, block_id = -1, lineno = 0;
	int kind, rc = HB_OK;

	if (f == NULL)
		return errno == ENOENT ? HB_OK : hb_status_set(msg, n, HB_EIO, "%s: %s", path,
		                                             strerror(errno));
	while ((got = getline(&line, &cap, f)) > 0) {
		lineno++;
		if (line[got - 1] != '\n')
			break;  /* a torn last line */
		kind = journal_line(line, (size_t)got, &id);
		if (kind < 0 || id >= npoints || (block_id >= 0 && id != block_id)) {
			rc = hb_status_set(msg, n, HB_EINVAL, "%s:%ld: not a line of this sweep's "
			                "journal; remove the file to compute its points again",
			                path, lineno);
			break;
		}
		pos += got;
		if (kind == 'r') {
			if ((rc = seen(ctx, id, block, (size_t)(pos - block))) != HB_OK)
				break;
			block = pos;
			block_id = -1;
		} else {
			block_id = id;
		}
	}
	free(line);
	if (ferror(f) && rc == HB_OK)
		rc = hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	fclose(f);
	if (rc == HB_OK && trunc && truncate(path, block) != 0)
		rc = hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	return rc;
}

/* See sweep_impl.h. */
void
sweep_journal_name(char *buf, size_t n, const char *dir, long k, long nshards)
{
	if (nshards <= 1)
		snprintf(buf, n, "%s/points.journal", dir);
	else
		snprintf(buf, n, "%s/shard-%ld-of-%ld.journal", dir, k, nshards);
}

/*
 * An exclusive lock on the journal open as fd (flock: a second process on
 * the same shard, here or on another node of a shared file system, is
 * refused instead of appending beside it).  A file system without locks is
 * taken as it is.  fd < 0: the open's errno.
 */
int
sweep_journal_lock(int fd, const char *path, char *msg, size_t n)
{
	if (fd < 0)
		return hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	if (flock(fd, LOCK_EX | LOCK_NB) == 0 || errno != EWOULDBLOCK)
		return HB_OK;
	return hb_status_set(msg, n, HB_EIO, "%s: another process is computing these points "
	                     "(the journal is locked); expected one run of a shard at a time",
	                     path);
}

