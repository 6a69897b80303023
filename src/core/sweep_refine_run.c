/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_refine_run.c - running a refined sweep (--refine; see sweep.h,
 * "Refinement", and sweep_refine.c for the lattice).
 *
 * Rounds.  Round 0 computes the grid of the specs.  A cell of the grid
 * (an interval for one axis, a square of four points for two) is mixed
 * when its corners are not all of one class.  Round L + 1 halves every
 * mixed cell of round L: it computes the corners of the halves that are
 * not known yet (one point an interval, up to five a square), and the
 * halves that are mixed go on.  After `levels` rounds the mixed cells are
 * one lattice step wide: their edges whose ends differ are the
 * boundaries (boundaries.csv).  Each round's points run on the sweep's
 * worker threads (sweep_compute), the rounds one after another.
 *
 * Resuming.  The points go to DIR/points.journal as those of any sweep.
 * The rounds depend on nothing but the points' classes, so a restart reads
 * the journal's points (their classes from their runs rows), plays the
 * rounds again and computes only the points that the journal lacks.
 * Memory: about 48 bytes a computed point (a hash table of the points,
 * sweep_refine_table.c), never the points' text.
 *
 * The files.  runs.csv and collisions.csv hold the computed points sorted
 * by id (ids of the lattice, as in the uniform sweep FROM:TO:M), runs.csv
 * with the column `refined`: 0 for a point of the grid, L for a point that
 * round L added.  The three files are one set of the atomic writer.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "hybounce/atomic.h"
#include "hybounce/observables.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "clock.h"
#include "csv_impl.h"
#include "sweep_impl.h"
#include "sweep_refine_table.h"

#define BOUNDARIES_NAME "boundaries.csv"

/* sweep_compute's callback: the block was just appended to the journal. */
static int
got_block(void *ctx, long id, const char *blk, size_t len)
{
	struct refine_state *r = ctx;
	int rc = sweep_refine_note(r, id, blk, len, r->jsize);

	r->jsize += (int64_t)len;
	return rc;
}

/* sweep_journal_scan's callback on a restart. */
static int
seen_block(void *ctx, long id, off_t off, size_t len)
{
	struct refine_state *r = ctx;

	if (len > UINT32_MAX)
		return r->err = HB_EINVAL;
	if (len + 1 > r->buf_cap) {
		char *nb = realloc(r->buf, len + 1);

		if (nb == NULL)
			return r->err = HB_ENOMEM;
		r->buf = nb;
		r->buf_cap = len + 1;
	}
	if (pread(r->rfd, r->buf, len, off) != (ssize_t)len)
		return r->err = HB_EIO;
	r->buf[len] = '\0';
	return r->err = sweep_refine_note(r, id, r->buf, len, (int64_t)off);
}

/* Lattice strides: one axis 1; two axes M2 and 1. */
static void
strides(const struct hb_sweep *sw, long st[2])
{
	st[0] = sw->naxes == 2 ? sw->ax[1].n : 1;
	st[1] = 1;
}

/* 1 when the corners of the cell at c, side s, are not all of one class. */
static int
mixed(const struct refine_state *r, long c, long s)
{
	long st[2], first = 0;
	int d = r->sw->naxes;

	strides(r->sw, st);
	for (int m = 0; m < (1 << d); m++) {
		long id = c;
		const struct refine_node *x;

		for (int k = 0; k < d; k++)
			if (m & (1 << k))
				id += s * st[k];
		x = sweep_refine_node_get(r, id);
		if (x == NULL || !x->have)
			return 0;   /* cannot happen: a round computes every corner */
		if (m == 0)
			first = x->cls;
		else if (x->cls != first)
			return 1;
	}
	return 0;
}

static int
cmp_long(const void *a, const void *b)
{
	long x = *(const long *)a, y = *(const long *)b;

	return x < y ? -1 : x > y;
}

/* The boundaries: edges of the finest mixed cells whose ends differ, as id_a * 2 + axis. */
static long
edges(const struct refine_state *r, const long *cells, long ncells, long **out)
{
	long st[2], ne = 0, *e;
	int d = r->sw->naxes;

	strides(r->sw, st);
	e = malloc((size_t)(ncells * 4 + 1) * sizeof *e);
	if (e == NULL)
		return -1;
	for (long i = 0; i < ncells; i++)
		for (int k = 0; k < d; k++)
			for (int a = 0; a < (d == 2 ? 2 : 1); a++) {
				long p = cells[i] + (d == 2 ? a * st[1 - k] : 0);
				const struct refine_node *x = sweep_refine_node_get(r, p);
				const struct refine_node *y = sweep_refine_node_get(r, p + st[k]);

				if (x && y && x->cls != y->cls)
					e[ne++] = p * 2 + k;
			}
	qsort(e, (size_t)ne, sizeof *e, cmp_long);
	{
		long w = 0;

		for (long i = 0; i < ne; i++)
			if (w == 0 || e[w - 1] != e[i])
				e[w++] = e[i];
		ne = w;
	}
	*out = e;
	return ne;
}

/* The runs row "r,ID,...,CPU\n" (l bytes) as "ID,...,LEVEL,CPU" into *t; its length or 0. */
static size_t
runs_row_text(const char *p, size_t l, int level, char **t, size_t *cap)
{
	const char *last = p + l - 1;
	size_t head, w;

	while (last > p && *last != ',')
		last--;
	head = (size_t)(last - p) - 2;
	if (l + 16 > *cap) {
		char *nb = realloc(*t, l + 16);

		if (nb == NULL)
			return 0;
		*t = nb;
		*cap = l + 16;
	}
	memcpy(*t, p + 2, head);
	w = head + (size_t)snprintf(*t + head, 16, ",%d", level);
	memcpy(*t + w, last, (size_t)(p + l - 1 - last));
	w += (size_t)(p + l - 1 - last);
	(*t)[w] = '\0';
	return w;
}

static int
write_files(struct refine_state *r, const char *dir, const long *e, long ne, long *nrows,
            const struct hb_sweep_sink *sink, void *sctx, char *msg, size_t n)
{
	const struct hb_sweep *sw = r->sw;
	struct hb_atomic_set set;
	FILE *runs = NULL, *coll = NULL, *bnd;
	char path[4200], hdr[4096], chdr[4300], *row = NULL;
	size_t rowcap = 0;
	long *ids, nid = 0;
	int rc = HB_OK, sink_open = 0;

	ids = malloc((r->count + 1) * sizeof *ids);
	if (ids == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	for (size_t i = 0; i < r->cap; i++)
		if (r->t[i].id >= 0 && r->t[i].have && r->t[i].level >= 0)
			ids[nid++] = r->t[i].id;
	qsort(ids, (size_t)nid, sizeof *ids, cmp_long);
	*nrows = nid;
	hb_atomic_begin(&set);
	if (sink == NULL) {
		snprintf(path, sizeof path, "%s/runs.csv", dir);
		runs = hb_atomic_add(&set, path, msg, n);
		snprintf(path, sizeof path, "%s/collisions.csv", dir);
		coll = runs ? hb_atomic_add(&set, path, msg, n) : NULL;
	}
	snprintf(path, sizeof path, "%s/" BOUNDARIES_NAME, dir);
	bnd = coll || sink ? hb_atomic_add(&set, path, msg, n) : NULL;
	if (bnd == NULL) {
		rc = HB_EIO;
		goto out;
	}
	hb_sweep_runs_header(sw, hdr, sizeof hdr);
	if ((rc = sweep_collisions_header(&sw->base, sw->error, path, sizeof path, msg, n)) != HB_OK)
		goto out;
	snprintf(chdr, sizeof chdr, "id,%s", path);
	if (sink != NULL) {
		if ((rc = sink->begin(sctx, hdr, chdr, msg, n)) != HB_OK)
			goto out;
		sink_open = 1;
	} else {
		fprintf(runs, "%s\n", hdr);
		fprintf(coll, "%s\n", chdr);
	}
	for (long i = 0; i < nid && rc == HB_OK; i++) {
		const struct refine_node *x = sweep_refine_node_get(r, ids[i]);
		const char *p;

		if (x->len + 1 > r->buf_cap) {
			char *nb = realloc(r->buf, x->len + 1);

			if (nb == NULL) {
				rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
				break;
			}
			r->buf = nb;
			r->buf_cap = x->len + 1;
		}
		if (pread(r->rfd, r->buf, x->len, (off_t)x->off) != (ssize_t)x->len) {
			rc = hb_status_set(msg, n, HB_EIO, "%s/points.journal: short read", dir);
			break;
		}
		r->buf[x->len] = '\0';
		for (p = r->buf; *p; ) {
			const char *end = strchr(p, '\n');
			size_t l = (size_t)(end - p) + 1;

			if (p[0] == 'r') {
				size_t w = runs_row_text(p, l, x->level, &row, &rowcap);

				if (w == 0)
					rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
				else if (sink != NULL)
					rc = sink->row(sctx, 1, row, w, msg, n);
				else
					fprintf(runs, "%s\n", row);
			} else if (sink != NULL) {
				rc = sink->row(sctx, 0, p + 2, l - 3, msg, n);
			} else {
				fwrite(p + 2, 1, l - 2, coll);
			}
			if (rc != HB_OK)
				break;
			p += l;
		}
	}
	/* boundaries.csv: id_a,id_b,axis,from,to, point a's values, the observable at a and b */
	fprintf(bnd, "id_a,id_b,axis,from,to");
	for (int k = 0; k < sw->naxes; k++)
		fprintf(bnd, ",%s", sw->ax[k].key);
	fprintf(bnd, ",%s_a,%s_b\n", hb_observables[sw->rf.obs].name,
	        hb_observables[sw->rf.obs].name);
	for (long i = 0; i < ne && rc == HB_OK; i++) {
		long a = e[i] / 2, st[2], b;
		int k = (int)(e[i] % 2);
		char t[64];

		strides(sw, st);
		b = a + st[k];
		fprintf(bnd, "%ld,%ld,%s,", a, b, sw->ax[k].key);
		fputs(sweep_axis_text(&sw->ax[k], sweep_axis_index(sw, a, k), t, sizeof t), bnd);
		fputc(',', bnd);
		fputs(sweep_axis_text(&sw->ax[k], sweep_axis_index(sw, b, k), t, sizeof t), bnd);
		for (int j = 0; j < sw->naxes; j++) {
			fputc(',', bnd);
			fputs(sweep_axis_text(&sw->ax[j], sweep_axis_index(sw, a, j), t, sizeof t), bnd);
		}
		csv_put_num(bnd, sweep_refine_node_get(r, a)->v);
		csv_put_num(bnd, sweep_refine_node_get(r, b)->v);
		fputc('\n', bnd);
	}
out:
	free(ids);
	free(row);
	if (sink_open) {
		/* the sink's file first: boundaries.csv follows it in place */
		int e2 = sink->end(sctx, rc == HB_OK, rc == HB_OK ? msg : NULL, rc == HB_OK ? n : 0);

		if (rc == HB_OK)
			rc = e2;
	}
	if (rc == HB_OK)
		return hb_atomic_commit(&set, msg, n);
	hb_atomic_abort(&set);
	return rc;
}

/* Computes the round's points (r->pending). */
static int
compute(struct refine_state *r, const struct hb_sweep_options *o, int fd, const char *jpath,
        struct hb_sweep_progress *pr, double t0, char *msg, size_t n)
{
	int rc;

	if (r->npending == 0)
		return HB_OK;
	/* in id order: the journal's order does not change the files */
	qsort(r->pending, (size_t)r->npending, sizeof *r->pending, cmp_long);
	pr->total += r->npending;
	rc = sweep_compute(r->sw, o, fd, jpath, r->pending, r->npending, NULL, 0, 1, r->npending, pr, t0,
	                   got_block, r, NULL, msg, n);
	r->npending = 0;
	return rc;
}

int
sweep_refine_run(const struct hb_sweep *sw, const struct hb_sweep_options *o, char *msg,
                 size_t n)
{
	const struct sweep_refine *rf = &sw->rf;
	struct refine_state r;
	struct hb_sweep_progress pr;
	long *cells = NULL, ncells = 0, *next = NULL, *e = NULL, ne = 0, st[2], nrows = 0;
	long np = hb_sweep_npoints(sw);
	char jpath[4200], path[4200];
	int fd = -1, rc, d = sw->naxes, made = 0, computing = 0;
	double t0 = clock_seconds(CLOCK_MONOTONIC);

	memset(&r, 0, sizeof r);
	memset(&pr, 0, sizeof pr);
	r.sw = sw;
	r.rfd = -1;
	if ((rc = sweep_prepare_dir(sw, o->dir, o->provenance, &made, msg, n)) != HB_OK)
		return rc;
	sweep_journal_name(jpath, sizeof jpath, o->dir, 0, 1);
	if (access(jpath, F_OK) != 0 && errno == ENOENT) {
		char c[4200], b[4200];

		/* Written and its journal removed: the sweep is complete. */
		snprintf(path, sizeof path, "%s/runs.csv", o->dir);
		snprintf(c, sizeof c, "%s/collisions.csv", o->dir);
		snprintf(b, sizeof b, "%s/" BOUNDARIES_NAME, o->dir);
		if (o->sink != NULL) {
			snprintf(path, sizeof path, "%s/%s", o->dir, o->sink->name);
			snprintf(c, sizeof c, "%s", path);
		}
		if (access(path, F_OK) == 0 && access(c, F_OK) == 0 && access(b, F_OK) == 0) {
			pr.total = pr.done = pr.resumed = 1;
			if (o->progress)
				o->progress(o->ctx, &pr);
			return HB_OK;
		}
	}
	fd = open(jpath, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
	if ((rc = sweep_journal_lock(fd, jpath, msg, n)) != HB_OK)
		goto out;
	r.rfd = open(jpath, O_RDONLY | O_CLOEXEC);
	if (r.rfd < 0) {
		rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
		goto out;
	}
	/* The journal's points and their classes (a torn end cut off first). */
	rc = sweep_journal_scan(jpath, np, 1, seen_block, &r, msg, n);
	if (r.err == HB_EINVAL)
		rc = hb_status_set(msg, n, HB_EINVAL, "%s: a point without its observable; remove "
		                   "the file to compute its points again", jpath);
	else if (r.err != HB_OK)
		rc = hb_status_set(msg, n, r.err, "%s: %s", jpath, r.err == HB_ENOMEM
		                   ? "out of memory" : "cannot read it");
	if (rc != HB_OK)
		goto out;
	r.jsize = (int64_t)lseek(fd, 0, SEEK_END);
	if (r.count == 0)
		made |= SWEEP_MADE_JOURNAL;   /* no point before: this call's */
	pr.resumed = pr.done = pr.total = (long)r.count;
	if (o->progress)
		o->progress(o->ctx, &pr);

	strides(sw, st);
	computing = 1;   /* an HB_EINVAL from here to the files is a refused point */
	/* Round 0: the grid, then its mixed cells. */
	for (long g = 0; g < sweep_refine_grid_points(sw) && rc == HB_OK; g++)
		rc = sweep_refine_request(&r, sweep_refine_grid_id(sw, g), 0);
	if (rc == HB_OK)
		rc = compute(&r, o, fd, jpath, &pr, t0, msg, n);
	if (rc != HB_OK)
		goto out;
	{
		long cn = (rf->grid[0] - 1) * (d == 2 ? rf->grid[1] - 1 : 1);

		cells = malloc((size_t)(cn + 1) * sizeof *cells);
		if (cells == NULL) {
			rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			goto out;
		}
		for (long g = 0; g < cn; g++) {
			long c = d == 1 ? g * rf->step
			       : (g / (rf->grid[1] - 1)) * rf->step * st[0] + (g % (rf->grid[1] - 1)) * rf->step;

			if (mixed(&r, c, rf->step))
				cells[ncells++] = c;
		}
	}
	/* Rounds 1 .. levels: halve the mixed cells. */
	for (int lv = 1; lv <= rf->levels; lv++) {
		long h = rf->step >> lv, nn = 0;
		int per = d == 1 ? 3 : 9, nchild = 1 << d;

		for (long i = 0; i < ncells && rc == HB_OK; i++)
			for (int q = 0; q < per && rc == HB_OK; q++) {
				long id = cells[i] + (q % 3) * h * (d == 1 ? 1 : st[1]) +
				          (d == 2 ? (q / 3) * h * st[0] : 0);

				rc = sweep_refine_request(&r, id, lv);
			}
		if (rc == HB_OK)
			rc = compute(&r, o, fd, jpath, &pr, t0, msg, n);
		if (rc != HB_OK)
			goto out;
		next = malloc((size_t)(ncells * nchild + 1) * sizeof *next);
		if (next == NULL) {
			rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			goto out;
		}
		for (long i = 0; i < ncells; i++)
			for (int m = 0; m < nchild; m++) {
				long c = cells[i];

				for (int k = 0; k < d; k++)
					if (m & (1 << k))
						c += h * (d == 1 ? 1 : st[k]);
				if (mixed(&r, c, h))
					next[nn++] = c;
			}
		free(cells);
		cells = next;
		next = NULL;
		ncells = nn;
	}
	computing = 0;
	if (close(fd) != 0) {
		fd = -1;
		rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
		goto out;
	}
	fd = -1;
	if ((ne = edges(&r, cells, ncells, &e)) < 0) {
		rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		goto out;
	}
	if ((rc = write_files(&r, o->dir, e, ne, &nrows, o->sink, o->sink_ctx, msg, n)) != HB_OK)
		goto out;
	if (unlink(jpath) != 0 && errno != ENOENT) {
		rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
		goto out;
	}
	if (o->refine_stats != NULL) {
		struct hb_sweep_refine_stats *s = o->refine_stats;

		s->runs = nrows;
		s->grid = sweep_refine_grid_points(sw);
		s->uniform = np;
		s->boundaries = ne;
		s->levels = rf->levels;
		s->resolution = 0;
		for (int k = 0; k < d; k++)
			if (1.0 / (double)(sw->ax[k].n - 1) > s->resolution)
				s->resolution = 1.0 / (double)(sw->ax[k].n - 1);
	}
out:
	/* A refused point (bad input): a sweep begun by this call leaves nothing. */
	if (rc == HB_EINVAL && computing && (made & SWEEP_MADE_JOURNAL))
		sweep_refused_undo(o->dir, made, jpath);
	if (fd >= 0)
		close(fd);
	if (r.rfd >= 0)
		close(r.rfd);
	free(cells);
	free(next);
	free(e);
	free(r.t);
	free(r.pending);
	free(r.buf);
	return rc;
}
