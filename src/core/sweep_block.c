/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_block.c - a point's journal block (see sweep_impl.h): the point
 * run, its collisions exactly as --collisions writes them, each row
 * prefixed "c,ID,", then its runs row "r,ID,...".  The block is built in
 * one buffer (no stream), its numbers written by cnum_g17, the bytes of
 * %.17g.  A worker runs its points on one simulator, made again for each
 * (hbs_sim_renew: no allocator round trip of its block, its arc's buffers
 * and its root finder; the run the same to the byte, tests/test_sim_renew.c).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hybounce/csv.h"
#include "hybounce/error.h"
#include "hybounce/observables.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "clock.h"
#include "sweep_impl.h"
#include "sim_life.h"
#include "cnum.h"

/*
 * A block being built: text appended to a malloc'd buffer that becomes the
 * block itself (no stream, no copy).  oom: a realloc failed, the text is
 * incomplete.
 */
struct sbuf {
	char *p;
	size_t len, cap;
	int oom;
};

/* Grows b to hold n more bytes and a '\0'; NULL when it cannot. */
static char *
sb_grow(struct sbuf *b, size_t n)
{
	size_t cap = b->cap ? b->cap : 256;
	char *q;

	while (cap < b->len + n + 1)
		cap *= 2;
	if (b->oom || (q = realloc(b->p, cap)) == NULL) {
		b->oom = 1;
		return NULL;
	}
	b->p = q;
	b->cap = cap;
	return b->p + b->len;
}

static inline char *
sb_room(struct sbuf *b, size_t n)
{
	return b->len + n + 1 <= b->cap ? b->p + b->len : sb_grow(b, n);
}

static inline void
sb_put(struct sbuf *b, const char *s, size_t n)
{
	char *d = sb_room(b, n);

	if (d != NULL) {
		memcpy(d, s, n);
		b->len += n;
	}
}

static void
sb_long(struct sbuf *b, long v)
{
	char t[24];

	sb_put(b, t, cnum_long(t, v));
}

/* A field as csv_put_field writes it: quoted when it holds , " CR or LF. */
static void
sb_field(struct sbuf *b, const char *s)
{
	if (strpbrk(s, ",\"\r\n") == NULL) {
		sb_put(b, s, strlen(s));
		return;
	}
	sb_put(b, "\"", 1);
	for (; *s != '\0'; s++) {
		if (*s == '"')
			sb_put(b, "\"", 1);
		sb_put(b, s, 1);
	}
	sb_put(b, "\"", 1);
}

/* ",v" as csv_put_num writes it: %.17g, a negative zero as 0, NaN empty. */
static void
sb_num(struct sbuf *b, double v)
{
	char *d = sb_room(b, CNUM_G17_MAX + 1);

	if (d == NULL)
		return;
	*d = ',';
	b->len += 1 + (isnan(v) ? 0 : cnum_g17(d + 1, v == 0 ? 0.0 : v));
}

/*
 * The runs row of a finished sim (no newline); est: its error bars, when
 * sw->error (NULL: none could be had, the bars empty, why in note).
 */
static void
runs_row(struct sbuf *f, const struct hb_sweep *sw, long id, const struct hb_sim *s,
         const struct hb_error_estimate *est, const char *note, double cpu)
{
	int failed = hb_sim_end(s) == HB_SIM_END_FAIL;
	char t[64];

	sb_put(f, "r,", 2);
	sb_long(f, id);
	for (int k = 0; k < sw->naxes; k++) {
		sb_put(f, ",", 1);
		sb_field(f, sweep_axis_text(&sw->ax[k], sweep_axis_index(sw, id, k), t, sizeof t));
	}
	if (failed)
		sb_put(f, ",failed,", 8);
	else
		sb_put(f, ",ok,", 4);
	if (note != NULL && note[0] != '\0') {
		char m[768];

		snprintf(m, sizeof m, "%s; %s", hb_sim_end_str(s), note);
		sb_field(f, m);
	} else {
		sb_field(f, failed && hb_sim_errmsg(s)[0] ? hb_sim_errmsg(s) : hb_sim_end_str(s));
	}
	for (int k = 0; k < HB_OBS_COUNT; k++) {
		double v = hb_observable_value(s, k);

		if (hb_observables[k].whole) {
			sb_put(f, ",", 1);
			sb_long(f, (long)v);
		} else {
			sb_num(f, v);
		}
	}
	for (int k = 0; sw->error && k < HB_OBS_COUNT; k++)
		if (hb_error_observable(k))
			sb_num(f, est != NULL ? est->obs[k] : NAN);
	sb_num(f, cpu);
	sb_put(f, "\n", 1);
}

void
sweep_wbuf_free(struct sweep_wbuf *w)
{
	if (w->coll != NULL)
		fclose(w->coll);
	free(w->cbuf);
	hb_sim_free(w->sim);
	memset(w, 0, sizeof *w);
}

/* See sweep_impl.h. */
int
sweep_point_block_buf(const struct hb_sweep *sw, long id, struct sweep_wbuf *w,
                      struct sweep_block *out, char *msg, size_t n)
{
	double c0 = clock_seconds(CLOCK_THREAD_CPUTIME_ID);
	struct hb_error_estimate est_store, none, *est = NULL;
	struct sbuf b = { out->p, 0, out->cap, 0 };
	struct hb_scene sc;
	struct hb_sim *s;
	char m[512], note[600];
	FILE *f;
	int rc;

	if (sw->error) {   /* (only --error uses them: ~200 bytes to clear) */
		memset(&est_store, 0, sizeof est_store);
		memset(&none, 0, sizeof none);
	}
	out->len = 0;
	out->failed = 0;
	out->cpu = 0;
	note[0] = '\0';
	/* Validated once, by hb_sim_new; its refusal names the point as hb_sweep_check does. */
	if ((rc = sweep_point_values(sw, id, &sc, msg, n)) != HB_OK)
		return rc;
	m[0] = '\0';
	/* the worker's simulator made again in its own memory (on failure freed, NULL) */
	s = w->sim = w->sim != NULL ? hbs_sim_renew(w->sim, &sc, m, sizeof m) : hb_sim_new(&sc, m, sizeof m);
	if (s == NULL)
		return sweep_point_refused(sw, id, m[0] ? m : "no memory", msg, n);
	(void)hb_sim_run(s);
	out->failed = hb_sim_end(s) == HB_SIM_END_FAIL;
	/* --error: the same estimate as hybounce --batch --error (error.h) */
	if (sw->error && !out->failed) {
		m[0] = '\0';
		if (hb_error_estimate(s, NULL, &est_store, m, sizeof m) == HB_OK)
			est = &est_store;
		else
			snprintf(note, sizeof note, "no error bars: %.500s", m);
	}

	/* The collisions exactly as --collisions writes them, each row prefixed. */
	if (w->coll == NULL)
		w->coll = open_memstream(&w->cbuf, &w->clen);
	f = w->coll != NULL && fseeko(w->coll, 0, SEEK_SET) == 0 ? w->coll : NULL;
	if (f == NULL) {
		if (sw->error)
			hb_error_free(&est_store);
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	}
	/* flushes: cbuf holds clen bytes */
	rc = hb_csv_stream_collisions_err(f, s, !sw->error ? NULL : est != NULL ? est : &none, m,
	                                  sizeof m);
	if (rc != HB_OK || w->cbuf == NULL) {
		if (sw->error)
			hb_error_free(&est_store);
		return hb_status_set(msg, n, HB_ENOMEM, "point %ld: collisions: %s", id, m);
	}
	{
		const char *p = memchr(w->cbuf, '\n', w->clen), *end = w->cbuf + w->clen;
		char pre[32];
		size_t pl;

		pre[0] = 'c';
		pre[1] = ',';
		pl = 2 + cnum_long(pre + 2, id);
		pre[pl++] = ',';
		p = p ? p + 1 : end;    /* skip the header */
		/* the collisions, their prefixes and the runs row (~300 bytes) */
		(void)sb_room(&b, (size_t)(end - p) + 32 * (size_t)hb_sim_ncollisions(s) + 512);
		while (p < end) {
			const char *e = memchr(p, '\n', (size_t)(end - p));
			size_t l = e ? (size_t)(e - p) : (size_t)(end - p);

			sb_put(&b, pre, pl);
			sb_put(&b, p, l);
			sb_put(&b, "\n", 1);
			p += l + (e != NULL);
		}
	}
	out->cpu = clock_seconds(CLOCK_THREAD_CPUTIME_ID) - c0;
	runs_row(&b, sw, id, s, est, note, out->cpu);
	if (sw->error)
		hb_error_free(&est_store);
	/* the buffer is the caller's, grown or not, whatever happened */
	out->p = b.p;
	out->cap = b.cap;
	if (b.oom || b.p == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	b.p[b.len] = '\0';
	out->len = b.len;
	return HB_OK;
}

int
hb_sweep_point_block(const struct hb_sweep *sw, long id, char **out, int *failed,
                  char *msg, size_t n)
{
	struct sweep_wbuf w = { 0 };
	struct sweep_block b = { 0 };
	int rc = sweep_point_block_buf(sw, id, &w, &b, msg, n);

	sweep_wbuf_free(&w);
	*failed = b.failed;
	*out = rc == HB_OK ? b.p : NULL;
	if (rc != HB_OK)
		free(b.p);
	return rc;
}
