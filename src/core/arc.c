/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * arc.c - the hybrid arc (see arc.h).
 *
 * Invariants:
 *  - samples are in hybrid-time order: j non-decreasing, and t
 *    non-decreasing within each j (so t is non-decreasing overall);
 *  - iv[] lists the flow intervals in order; iv[k].first..last are the
 *    sample indices of interval k and cover the samples without gap;
 *  - jp[] lists the jumps in order; jump k leads from interval j to j + 1
 *    and both of its samples are present;
 *  - memory: the samples, intervals and jump records together hold at most
 *    what max_samples samples would.  At the bound the interior samples of
 *    the older three quarters are thinned by half; when that frees little
 *    (an arc made mostly of jumps, whose first and last samples are kept),
 *    every other whole flow interval of the older three quarters goes too,
 *    with the jumps into and out of it.  The first interval (t = 0, so that
 *    rewind reaches it) and the interval in progress are never removed.
 *    skipped counts the intervals removed: where j steps by more than one
 *    between two samples, that many were thinned out (check.c checks the
 *    count).
 */
#include <stdlib.h>
#include <string.h>

#include "hybounce/status.h"
#include "arc_impl.h"

struct hb_arc {
	struct hb_arc_sample *s;
	size_t n, cap;
	struct hb_arc_interval *iv;
	size_t niv, ivcap;
	struct hb_arc_jump *jp;
	size_t nj, jcap;
	size_t max;
	int thinned;
	long skipped;     /* flow intervals removed by thin_jumps() */
};

enum { ARC_CHUNK = 4096 };

struct hb_arc *
arc_new(size_t max_samples)
{
	struct hb_arc *a = calloc(1, sizeof *a);

	if (a == NULL)
		return NULL;
	a->max = max_samples < 1024 ? 1024 : max_samples;
	return a;
}

void
arc_free(struct hb_arc *a)
{
	if (a == NULL)
		return;
	free(a->s);
	free(a->iv);
	free(a->jp);
	free(a);
}

static int
grow(void **p, size_t *cap, size_t need, size_t size)
{
	size_t c = *cap;
	void *q;

	if (need <= c)
		return 0;
	while (c < need)
		c = c < ARC_CHUNK ? ARC_CHUNK : c * 2;
	q = realloc(*p, c * size);
	if (q == NULL)
		return HB_ENOMEM;
	*p = q;
	*cap = c;
	return 0;
}

/* Rebuilds the interval index from the samples. */
static int
reindex(struct hb_arc *a)
{
	size_t i;

	a->niv = 0;
	for (i = 0; i < a->n; i++) {
		const struct hb_arc_sample *s = &a->s[i];

		if (a->niv == 0 || a->iv[a->niv - 1].j != s->j) {
			if (grow((void **)&a->iv, &a->ivcap, a->niv + 1, sizeof *a->iv))
				return HB_ENOMEM;
			a->iv[a->niv] = (struct hb_arc_interval){ s->j, s->q, i, i, s->t, s->t };
			a->niv++;
		} else {
			a->iv[a->niv - 1].last = i;
			a->iv[a->niv - 1].t1 = s->t;
		}
	}
	return 0;
}

/*
 * Removes every other interior sample in [0, upto): a sample is interior
 * when it is neither the first nor the last of its interval.  The interval
 * index is rebuilt afterwards.
 */
static void
thin(struct hb_arc *a, size_t upto)
{
	size_t i, w = 0;
	int drop = 0;

	for (i = 0; i < a->n; i++) {
		int first = i == 0 || a->s[i - 1].j != a->s[i].j;
		int last = i + 1 == a->n || a->s[i + 1].j != a->s[i].j;

		if (i < upto && !first && !last) {
			drop = !drop;
			if (drop)
				continue;
		}
		a->s[w++] = a->s[i];
	}
	a->n = w;
	a->thinned++;
	reindex(a); /* cannot fail: the index only shrinks */
}

/*
 * Removes every other whole flow interval among those that end before
 * sample upto, never the first nor the last, with the jump records into
 * and out of them.  The interval index is rebuilt afterwards.
 */
static void
thin_jumps(struct hb_arc *a, size_t upto)
{
	size_t k, i, w = 0, r, kw;

	for (k = 0; k < a->niv; k++) {
		const struct hb_arc_interval *iv = &a->iv[k];

		if (k % 2 == 1 && k + 1 < a->niv && iv->last < upto) {
			a->skipped++;
			continue;
		}
		for (i = iv->first; i <= iv->last; i++)
			a->s[w++] = a->s[i];
	}
	a->n = w;
	a->thinned++;
	reindex(a);
	/* Keep a jump record when both intervals it joins are kept. */
	for (r = 0, kw = 0, k = 0; r < a->nj; r++) {
		long j = a->jp[r].j;

		while (k < a->niv && a->iv[k].j < j)
			k++;
		if (k + 1 < a->niv && a->iv[k].j == j && a->iv[k + 1].j == j + 1)
			a->jp[kw++] = a->jp[r];
	}
	a->nj = kw;
}

/* Bytes in use: samples, intervals and jump records. */
static size_t
used(const struct hb_arc *a)
{
	return a->n * sizeof *a->s + a->niv * sizeof *a->iv + a->nj * sizeof *a->jp;
}

/* Thins until the arc is within its bound; 0 if nothing more can go. */
static int
make_room(struct hb_arc *a, size_t bound, size_t upto)
{
	size_t before = used(a);

	thin(a, upto);
	if (used(a) > before - before / 8)   /* mostly jumps: thin them too */
		thin_jumps(a, upto < a->n ? upto : a->n);
	return used(a) < before && used(a) >= bound;
}

int
arc_push(struct hb_arc *a, const struct hb_arc_sample *s)
{
	if (used(a) + sizeof *s >= a->max * sizeof *s)
		make_room(a, 0, a->n - a->n / 4);
	if (grow((void **)&a->s, &a->cap, a->n + 1, sizeof *a->s))
		return HB_ENOMEM;
	if (a->niv == 0 || a->iv[a->niv - 1].j != s->j) {
		if (grow((void **)&a->iv, &a->ivcap, a->niv + 1, sizeof *a->iv))
			return HB_ENOMEM;
		a->iv[a->niv] = (struct hb_arc_interval){ s->j, s->q, a->n, a->n, s->t, s->t };
		a->niv++;
	} else {
		a->iv[a->niv - 1].last = a->n;
		a->iv[a->niv - 1].t1 = s->t;
	}
	a->s[a->n++] = *s;
	return 0;
}

int
arc_push_jump(struct hb_arc *a, const struct hb_arc_jump *jr)
{
	if (grow((void **)&a->jp, &a->jcap, a->nj + 1, sizeof *a->jp))
		return HB_ENOMEM;
	a->jp[a->nj++] = *jr;
	return 0;
}

void
arc_truncate(struct hb_arc *a, size_t keep)
{
	long jlast;

	if (keep >= a->n)
		return;
	a->n = keep;
	reindex(a);
	/* The intervals thinned out that are still before the end. */
	a->skipped = 0;
	for (size_t k = 1; k < a->niv; k++)
		a->skipped += a->iv[k].j - a->iv[k - 1].j - 1;
	jlast = a->n ? a->s[a->n - 1].j : -1;
	while (a->nj > 0 && a->jp[a->nj - 1].j >= jlast)
		a->nj--;
}

void
arc_clear(struct hb_arc *a, size_t max_samples)
{
	a->n = a->niv = a->nj = 0;
	a->thinned = 0;
	a->skipped = 0;
	a->max = max_samples < 1024 ? 1024 : max_samples;
}

void
arc_set_max(struct hb_arc *a, size_t max_samples)
{
	a->max = max_samples < 1024 ? 1024 : max_samples;
	while (used(a) > a->max * sizeof *a->s && make_room(a, a->max * sizeof *a->s, a->n))
		;
}

size_t
hb_arc_len(const struct hb_arc *a)
{
	return a->n;
}

const struct hb_arc_sample *
hb_arc_at(const struct hb_arc *a, size_t i)
{
	return i < a->n ? &a->s[i] : NULL;
}

const struct hb_arc_sample *
hb_arc_last(const struct hb_arc *a)
{
	return a->n ? &a->s[a->n - 1] : NULL;
}

size_t
hb_arc_nintervals(const struct hb_arc *a)
{
	return a->niv;
}

const struct hb_arc_interval *
hb_arc_interval_at(const struct hb_arc *a, size_t k)
{
	return k < a->niv ? &a->iv[k] : NULL;
}

size_t
hb_arc_interval_of(const struct hb_arc *a, size_t i)
{
	size_t lo = 0, hi = a->niv;

	/* the last interval whose first sample is <= i */
	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;

		if (a->iv[mid].first <= i)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

size_t
hb_arc_njumps(const struct hb_arc *a)
{
	return a->nj;
}

const struct hb_arc_jump *
hb_arc_jump_at(const struct hb_arc *a, size_t k)
{
	return k < a->nj ? &a->jp[k] : NULL;
}

/* 1 if sample s is at or before (t, j) in hybrid-time order. */
static int
not_after(const struct hb_arc_sample *s, double t, long j)
{
	return s->j < j || (s->j == j && s->t <= t);
}

size_t
hb_arc_find(const struct hb_arc *a, double t, long j)
{
	size_t lo = 0, hi = a->n;

	if (a->n == 0 || !not_after(&a->s[0], t, j))
		return 0;
	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;

		if (not_after(&a->s[mid], t, j))
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

size_t
hb_arc_find_t(const struct hb_arc *a, double t)
{
	size_t lo = 0, hi = a->n;

	if (a->n == 0 || a->s[0].t > t)
		return 0;
	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;

		if (a->s[mid].t <= t)
			lo = mid;
		else
			hi = mid;
	}
	return lo;
}

int
hb_arc_thinned(const struct hb_arc *a)
{
	return a->thinned;
}

long
hb_arc_skipped(const struct hb_arc *a)
{
	return a->skipped;
}

size_t
hb_arc_bytes(const struct hb_arc *a)
{
	return sizeof *a + a->cap * sizeof *a->s + a->ivcap * sizeof *a->iv +
	       a->jcap * sizeof *a->jp;
}
