/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_merge.c - a sweep folder's journals put together: the merge into
 * runs.csv and collisions.csv (see sweep.h); which journals a folder holds
 * and which of its shards are done or missing is sweep_shards.c.
 *
 * Merge.  The union of the journals in the folder (by point id; the first
 * copy wins) is written in id order to runs.csv and collisions.csv as one
 * set of the atomic writer (atomic.h): a reader never sees half a file and
 * a failed merge leaves the old ones.  An incomplete folder is refused with
 * the shards that are missing or incomplete, by number, so that only those
 * are computed again.  When every journal holds its points in increasing
 * id order, each once (a sweep written in one go: the writer orders a
 * grid's blocks), the journals are read side by side, a bit per point
 * kept; otherwise an index of 8 bytes per point (an offset and a journal
 * number).  Never the points' text.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hybounce/atomic.h"
#include "hybounce/csv.h"
#include "hybounce/error.h"
#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "sweep_impl.h"

/*
 * Where each point's block is: its offset in its journal (48 bits, 256 TB)
 * and the journal's number (16 bits) in 8 bytes; its end is found when it
 * is read (the block ends with its "r," line).
 */
#define INDEX_NONE UINT64_MAX
#define INDEX_MAX_OFF ((uint64_t)1 << 48)

struct index {
	uint64_t *at;     /* (offset << 16) | journal, INDEX_NONE: not seen */
	int cur;
	long count;
};

static int
index_add(void *ctx, long id, off_t off, size_t len)
{
	struct index *x = ctx;

	(void)len;
	if (x->at[id] != INDEX_NONE)
		return HB_OK;  /* the first copy wins */
	if ((uint64_t)off >= INDEX_MAX_OFF)
		return HB_ENOMEM;  /* a journal of 256 TB */
	x->at[id] = (uint64_t)off << 16 | (uint64_t)x->cur;
	x->count++;
	return HB_OK;
}

/*
 * The first pass: whether the journals can be merged side by side, every
 * journal sorted by id and no id twice (bits: one per point).
 */
struct order {
	unsigned char *bits;
	long *last, *blocks;   /* each journal's last id and its blocks */
	int cur, sorted;
	long count;
};

static int
order_add(void *ctx, long id, off_t off, size_t len)
{
	struct order *o = ctx;

	(void)off;
	(void)len;
	if (id <= o->last[o->cur] || (o->bits[id / 8] & (1u << (id % 8))))
		o->sorted = 0;
	o->bits[id / 8] |= (unsigned char)(1u << (id % 8));
	o->last[o->cur] = id;
	o->blocks[o->cur]++;
	o->count++;
	return HB_OK;
}

/* Merged side by side up to this many journals (a scan of the cursors a
 * point); more, or journals out of order, take the index. */
enum { MERGE_SIDE_MAX = 16 };

/* A journal read block after block (the side-by-side merge). */
struct cursor {
	char *blk;
	size_t cap, len;
	off_t off;
	long id, done;     /* id: the block's point, LONG_MAX: none left */
};

static int
index_has(const void *ctx, long id)
{
	return ((const struct index *)ctx)->at[id] != INDEX_NONE;
}

/*
 * Reads the block at off of fd into *buf (grown as needed, *cap bytes):
 * from off up to the end of its "r," line.  Returns its length, or 0 for
 * a short read.
 */
static size_t
read_block(int fd, off_t off, char **buf, size_t *cap)
{
	size_t have = 0, scan = 0, want = 2048;

	for (;;) {
		ssize_t got;

		if (have + want + 1 > *cap) {
			char *nb = realloc(*buf, have + want + 1);

			if (nb == NULL)
				return 0;
			*buf = nb;
			*cap = have + want + 1;
		}
		got = pread(fd, *buf + have, want, off + (off_t)have);
		if (got <= 0)
			return 0;
		have += (size_t)got;
		while (scan < have) {
			char *nl = memchr(*buf + scan, '\n', have - scan);

			if (nl == NULL)
				break;
			if ((*buf)[scan] == 'r') {
				size_t end = (size_t)(nl - *buf) + 1;

				(*buf)[end] = '\0';
				return end;
			}
			scan = (size_t)(nl - *buf) + 1;
		}
		want *= 2;
	}
}

/* A block's id: its first line's "c,ID," or "r,ID,". */
static long
block_id(const char *blk)
{
	long id = 0;

	/* "c,ID," or "r,ID,": the digits the writer put there */
	for (const char *p = blk + 2; *p >= '0' && *p <= '9'; p++)
		id = id * 10 + (*p - '0');
	return id;
}

/* The lines of block blk into the sink or the two files. */
static int
emit_block(const char *blk, const struct hb_sweep_sink *sink, void *ctx, FILE *runs, FILE *coll,
           char *msg, size_t n)
{
	int rc = HB_OK;

	for (const char *p = blk; *p; ) {
		const char *end = strchr(p, '\n');
		size_t l = (size_t)(end - p) + 1;

		if (sink != NULL && (rc = sink->row(ctx, p[0] == 'r', p + 2, l - 3, msg, n)) != HB_OK)
			break;
		if (sink == NULL)
			fwrite(p + 2, 1, l - 2, p[0] == 'r' ? runs : coll);
		p += l;
	}
	return rc;
}

/* See sweep_impl.h (from an empty run's CSV). */
int
sweep_collisions_header(const struct hb_scene *sc, int err, char *buf, size_t n, char *msg,
                        size_t mn)
{
	struct hb_sim *s = hb_sim_new(sc, msg, mn);
	struct hb_error_estimate none = { 0 };   /* no rows: the header alone */
	char *t = NULL;
	size_t tl = 0;
	FILE *f;
	int rc;

	if (s == NULL)
		return HB_EINVAL;
	f = open_memstream(&t, &tl);
	if (f == NULL) {
		hb_sim_free(s);
		return hb_status_set(msg, mn, HB_ENOMEM, "out of memory");
	}
	rc = hb_csv_stream_collisions_err(f, s, err ? &none : NULL, msg, mn);
	fclose(f);
	hb_sim_free(s);
	if (rc == HB_OK && t != NULL)
		snprintf(buf, n, "%.*s", (int)strcspn(t, "\n"), t);
	free(t);
	return rc;
}

/* Loads DIR/sweep.preset into a sweep. */
static struct hb_sweep *
load_spec(const char *dir, struct hb_scene *sc, char *msg, size_t n)
{
	char path[4096], m[1024];
	struct hb_sweep *sw;
	char *text;

	snprintf(path, sizeof path, "%s/" SWEEP_SPEC_NAME, dir);
	m[0] = '\0';
	text = sweep_slurp(path, NULL, m, sizeof m);
	if (text == NULL && m[0] == '\0')
		snprintf(m, sizeof m, "%.900s: %s", path, strerror(ENOENT));
	if (text == NULL) {
		hb_status_set(msg, n, HB_EINVAL, "%s; expected a sweep folder (--out DIR of "
		           "hybounce sweep)", m[0] ? m : path);
		return NULL;
	}
	m[0] = '\0';
	if (hb_preset_load_string(text, path, sc, m, sizeof m) != HB_OK) {
		hb_status_set(msg, n, HB_EINVAL, "%s", m);
		free(text);
		return NULL;
	}
	sw = hb_sweep_new(sc, msg, n);
	/* The folder's sweep was accepted (and its size allowed) when it was made. */
	if (sw != NULL)
		hb_sweep_set_max_points(sw, 1000000000L, NULL);
	if (sw != NULL && hb_sweep_vary_from_preset(sw, text, path, msg, n) != HB_OK) {
		hb_sweep_free(sw);
		sw = NULL;
	}
	if (sw != NULL)
		hb_sweep_error_from_preset(sw, text);
	if (sw != NULL && hb_sweep_refine_from_preset(sw, text, path, msg, n) != HB_OK) {
		hb_sweep_free(sw);
		sw = NULL;
	}
	if (sw != NULL && hb_sweep_npoints(sw) == 0) {
		hb_status_set(msg, n, HB_EINVAL, "%s: no '; sweep: --vary' line", path);
		hb_sweep_free(sw);
		sw = NULL;
	}
	free(text);
	return sw;
}

int
hb_sweep_merge(const char *dir, char *msg, size_t n)
{
	return hb_sweep_merge_shards(dir, 0, msg, n);
}

int
hb_sweep_merge_shards(const char *dir, long nshards, char *msg, size_t n)
{
	return hb_sweep_merge_to(dir, nshards, NULL, NULL, msg, n);
}

int
hb_sweep_merge_to(const char *dir, long nshards, const struct hb_sweep_sink *sink, void *ctx,
                  char *msg, size_t n)
{
	struct hb_scene sc;
	struct hb_sweep *sw = load_spec(dir, &sc, msg, n);
	int rc;

	if (sw == NULL)
		return HB_EINVAL;
	if (hb_sweep_refined(sw)) {
		hb_sweep_free(sw);
		return hb_status_set(msg, n, HB_EINVAL, "%s holds a refined sweep (--refine), which "
		                     "runs on one machine and merges itself; expected: hybounce "
		                     "sweep %s/" SWEEP_SPEC_NAME " --out %s, which resumes it", dir,
		                     dir, dir);
	}
	rc = sweep_merge_into(sw, dir, nshards, 0, sink, ctx, msg, n);
	hb_sweep_free(sw);
	return rc;
}

int
sweep_merge_into(const struct hb_sweep *sw, const char *dir, long nshards, int whole,
                 const struct hb_sweep_sink *sink, void *ctx, char *msg, size_t n)
{
	const struct hb_scene *sc = sweep_base(sw);
	struct index x = { 0 };
	struct order od = { 0 };
	int side = 0;      /* the journals merged side by side, no index */
	char **names = NULL, hdr[4096], path[4200];
	int nnames = 0, *fds = NULL, rc = HB_OK;
	struct hb_atomic_set set;
	FILE *runs = NULL, *coll = NULL;
	int set_open = 0, sink_open = 0;
	char *blk = NULL, chdr[4300];
	size_t cap = 0;
	long np = hb_sweep_npoints(sw);

	if ((rc = sweep_journals_list(dir, &names, &nnames, msg, n)) != HB_OK)
		goto out;
	fds = malloc((size_t)(nnames + 1) * sizeof *fds);
	if (fds == NULL) {
		rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		goto out;
	}
	for (int i = 0; i < nnames; i++)
		fds[i] = -1;
	if (whole && nnames == 1 && strcmp(names[0], "points.journal") == 0) {
		/* written whole and in order by the run that merges it */
		od.blocks = calloc(1, sizeof *od.blocks);
		if (od.blocks == NULL) {
			rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			goto out;
		}
		od.blocks[0] = np;
		side = 1;
	} else if (nnames <= MERGE_SIDE_MAX) {
		od.bits = calloc((size_t)np / 8 + 1, 1);
		od.last = malloc((size_t)(nnames + 1) * sizeof *od.last);
		od.blocks = calloc((size_t)nnames + 1, sizeof *od.blocks);
		if (od.bits == NULL || od.last == NULL || od.blocks == NULL) {
			rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			goto out;
		}
		od.sorted = 1;
		for (int i = 0; i < nnames && rc == HB_OK && od.sorted; i++) {
			snprintf(path, sizeof path, "%s/%s", dir, names[i]);
			od.cur = i;
			od.last[i] = -1;
			rc = sweep_journal_scan(path, np, 0, order_add, &od, msg, n);
		}
		if (rc != HB_OK)
			goto out;
		side = od.sorted && od.count == np;
		free(od.bits);
		od.bits = NULL;
	}
	if (side) {
		for (int i = 0; i < nnames && rc == HB_OK; i++) {
			snprintf(path, sizeof path, "%s/%s", dir, names[i]);
			if (od.blocks[i] > 0 && (fds[i] = open(path, O_RDONLY | O_CLOEXEC)) < 0)
				rc = hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
		}
		if (rc != HB_OK)
			goto out;
		goto headers;
	}
	x.at = malloc((size_t)np * sizeof *x.at);
	if (x.at == NULL) {
		rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		goto out;
	}
	for (long i = 0; i < np; i++)
		x.at[i] = INDEX_NONE;
	for (int i = 0; i < nnames && rc == HB_OK; i++) {
		snprintf(path, sizeof path, "%s/%s", dir, names[i]);
		x.cur = i;
		rc = sweep_journal_scan(path, np, 0, index_add, &x, msg, n);
		if (rc == HB_ENOMEM)
			rc = hb_status_set(msg, n, HB_ENOMEM, "%s: a journal of 256 TB or more", path);
		/* A journal that is not there (a dangling link, one removed since) holds nothing. */
		if (rc == HB_OK && (fds[i] = open(path, O_RDONLY | O_CLOEXEC)) < 0 && errno != ENOENT)
			rc = hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	}
	if (rc != HB_OK)
		goto out;
	if (x.count < np) {
		long first = 0;

		if (nshards <= 0)
			nshards = sweep_shards_of_names(names, nnames);
		if (nshards > 0) {
			rc = sweep_shards_missing_msg(dir, np, nshards, index_has, &x, np - x.count, msg, n);
			goto out;
		}
		while (first < np && x.at[first] != INDEX_NONE)
			first++;
		rc = hb_status_set(msg, n, HB_EINVAL, "%s: %ld of %ld points are missing (the "
		                "first is point %ld); expected every shard to have finished "
		                "(%d journal%s found)", dir, np - x.count, np, first, nnames,
		                nnames == 1 ? "" : "s");
		goto out;
	}
headers:
	hb_sweep_runs_header(sw, hdr, sizeof hdr);
	if ((rc = sweep_collisions_header(sc, hb_sweep_error(sw), path, sizeof path, msg, n)) != HB_OK)
		goto out;
	snprintf(chdr, sizeof chdr, "id,%s", path);
	if (sink != NULL) {
		if ((rc = sink->begin(ctx, hdr, chdr, msg, n)) != HB_OK)
			goto out;
		sink_open = 1;
		goto rows;
	}
	hb_atomic_begin(&set);
	set_open = 1;
	snprintf(path, sizeof path, "%s/runs.csv", dir);
	if ((runs = hb_atomic_add(&set, path, msg, n)) == NULL) {
		rc = HB_EIO;
		goto out;
	}
	snprintf(path, sizeof path, "%s/collisions.csv", dir);
	if ((coll = hb_atomic_add(&set, path, msg, n)) == NULL) {
		rc = HB_EIO;
		goto out;
	}
	fprintf(runs, "%s\n", hdr);
	fprintf(coll, "%s\n", chdr);
rows:
	if (side) {
		/* each journal's next block, side by side: the point id is the
		 * head of exactly one of them */
		struct cursor *cur = calloc((size_t)nnames + 1, sizeof *cur);

		if (cur == NULL) {
			rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			goto out;
		}
		for (int i = 0; i < nnames && rc == HB_OK; i++) {
			cur[i].id = LONG_MAX;
			if (od.blocks[i] > 0 && (cur[i].len = read_block(fds[i], 0, &cur[i].blk,
			                                                 &cur[i].cap)) == 0)
				rc = hb_status_set(msg, n, HB_EIO, "%s/%s: short read", dir, names[i]);
			else if (od.blocks[i] > 0)
				cur[i].id = block_id(cur[i].blk);
		}
		for (long id = 0; id < np && rc == HB_OK; id++) {
			int i = 0;

			while (i < nnames && cur[i].id != id)
				i++;
			if (i == nnames) {
				rc = hb_status_set(msg, n, HB_EIO, "%s: point %ld: not where the journals "
				                   "were read to hold it", dir, id);
				break;
			}
			if ((rc = emit_block(cur[i].blk, sink, ctx, runs, coll, msg, n)) != HB_OK)
				break;
			cur[i].off += (off_t)cur[i].len;
			cur[i].id = LONG_MAX;
			if (++cur[i].done < od.blocks[i]) {
				if ((cur[i].len = read_block(fds[i], cur[i].off, &cur[i].blk,
				                             &cur[i].cap)) == 0)
					rc = hb_status_set(msg, n, HB_EIO, "%s/%s: short read", dir, names[i]);
				else
					cur[i].id = block_id(cur[i].blk);
			}
		}
		for (int i = 0; i < nnames; i++)
			free(cur[i].blk);
		free(cur);
		goto out;
	}
	for (long id = 0; id < np && rc == HB_OK; id++) {
		int fi = (int)(x.at[id] & 0xffff);

		if (read_block(fds[fi], (off_t)(x.at[id] >> 16), &blk, &cap) == 0) {
			rc = hb_status_set(msg, n, HB_EIO, "%s/%s: short read", dir, names[fi]);
			break;
		}
		rc = emit_block(blk, sink, ctx, runs, coll, msg, n);
	}
out:
	if (sink_open) {
		int e = sink->end(ctx, rc == HB_OK, rc == HB_OK ? msg : NULL, rc == HB_OK ? n : 0);

		if (rc == HB_OK)
			rc = e;
	}
	if (set_open) {
		if (rc == HB_OK)
			rc = hb_atomic_commit(&set, msg, n);   /* both files, or neither */
		else
			hb_atomic_abort(&set);
	}
	for (int i = 0; i < nnames; i++)
		if (fds && fds[i] >= 0)
			close(fds[i]);
	free(fds);
	sweep_names_free(names, nnames);
	free(blk);
	free(x.at);
	free(od.bits);
	free(od.last);
	free(od.blocks);
	return rc;
}
