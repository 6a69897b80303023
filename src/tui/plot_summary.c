/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_summary.c - a frame's cost independent of the arc's length (see
 * plot_summary.h): a three-level min/max pyramid per run and quantity, and
 * the per-column strokes drawn from it.
 *
 * A summary belongs to a simulator (by address) and is checked against
 * its arc on every use: the arc must still hold the samples it summarised
 * (its length, and the t, j and values of the first, middle and last
 * summarised samples).  Anything else (a restart, an edit, a branch, a
 * thinning of a full arc, another run at the same address) builds it
 * again, which costs one pass over the arc.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "canvas.h"
#include "plot_summary.h"
#include "tui.h"

/* levels: blocks of 8, 64 and 512 samples */
enum { NLEV = 3, FAN = 8, NRUNS = APP_MAX_PINS + 1 };
static const size_t bsize[NLEV + 1] = { 1, FAN, FAN * FAN, FAN * FAN * FAN };

struct mm {
	double lo[PSUM_NQ], hi[PSUM_NQ];
};

struct plot_sum {
	const struct hb_sim *sim;
	const struct hb_arc *arc;
	size_t n;                 /* samples summarised (a whole number of level-1 blocks) */
	struct mm *b[NLEV];       /* level l + 1: nb[l] complete blocks of bsize[l + 1] samples */
	size_t nb[NLEV], cap[NLEV];
	struct hb_arc_sample first, mid, last; /* the check: as they were */
	unsigned long used;       /* the frame it was last used (for reuse of the slot) */
};

struct plot_sums {
	struct plot_sum r[NRUNS];
	unsigned long clock;
	struct {                  /* each plot's last canvas (psum_plot_get) */
		struct psum_view v;
		struct canvas *c;
		struct axis ay;
	} plot[PSUM_NQ];
};

_Static_assert((int)PSUM_MAXRUNS == (int)NRUNS, "a view names every run drawn");

double
psum_value(const struct hb_arc_sample *s, int q)
{
	return q == 0 ? s->x : q == 1 ? s->xc : s->Fc;
}

static void
mm_empty(struct mm *m)
{
	for (int q = 0; q < PSUM_NQ; q++) {
		m->lo[q] = INFINITY;
		m->hi[q] = -INFINITY;
	}
}

static void
mm_sample(struct mm *m, const struct hb_arc_sample *s)
{
	for (int q = 0; q < PSUM_NQ; q++) {
		double v = psum_value(s, q);

		if (v < m->lo[q])
			m->lo[q] = v;
		if (v > m->hi[q])
			m->hi[q] = v;
	}
}

static void
mm_merge(struct mm *m, const struct mm *o)
{
	for (int q = 0; q < PSUM_NQ; q++) {
		m->lo[q] = fmin(m->lo[q], o->lo[q]);
		m->hi[q] = fmax(m->hi[q], o->hi[q]);
	}
}

static int
same(const struct hb_arc_sample *a, const struct hb_arc_sample *b)
{
	return a->t == b->t && a->j == b->j && a->x == b->x && a->xc == b->xc && a->Fc == b->Fc;
}

/* 1 when the arc still holds the samples p summarised. */
static int
still_valid(const struct plot_sum *p, const struct hb_arc *arc)
{
	size_t n = hb_arc_len(arc);

	if (p->arc != arc || n < p->n)
		return 0;
	if (p->n == 0)
		return 1;
	return same(hb_arc_at(arc, 0), &p->first) && same(hb_arc_at(arc, p->n / 2), &p->mid) &&
	       same(hb_arc_at(arc, p->n - 1), &p->last);
}

static int
grow(struct mm **b, size_t *cap, size_t need)
{
	if (need <= *cap)
		return 0;
	size_t nc = *cap ? *cap : 64;
	while (nc < need)
		nc *= 2;
	struct mm *nb = realloc(*b, nc * sizeof *nb);
	if (nb == NULL)
		return -1;
	*b = nb;
	*cap = nc;
	return 0;
}

/* Summarises the complete blocks the arc has beyond p->n, each level from the one below. */
static int
extend(struct plot_sum *p)
{
	size_t n = hb_arc_len(p->arc), nb1 = n / FAN;

	if (nb1 <= p->nb[0])
		return 0;
	for (int l = 0; l < NLEV; l++)
		if (grow(&p->b[l], &p->cap[l], nb1 / bsize[l] + 1) != 0)
			return -1;
	for (size_t k = p->nb[0]; k < nb1; k++) {
		struct mm *m = &p->b[0][k];

		mm_empty(m);
		for (size_t i = k * FAN; i < (k + 1) * FAN; i++)
			mm_sample(m, hb_arc_at(p->arc, i));
		p->nb[0] = k + 1;
		/* the blocks above that this one completes */
		for (int l = 1; l < NLEV && p->nb[l - 1] % FAN == 0; l++) {
			struct mm *up = &p->b[l][p->nb[l]];

			mm_empty(up);
			for (size_t c = p->nb[l - 1] - FAN; c < p->nb[l - 1]; c++)
				mm_merge(up, &p->b[l - 1][c]);
			p->nb[l]++;
		}
	}
	p->n = p->nb[0] * FAN;
	p->first = *hb_arc_at(p->arc, 0);
	p->mid = *hb_arc_at(p->arc, p->n / 2);
	p->last = *hb_arc_at(p->arc, p->n - 1);
	return 0;
}

struct plot_sums *
psum_new(void)
{
	return calloc(1, sizeof(struct plot_sums));
}

const struct plot_sum *
psum_of(struct plot_sums *S, const struct hb_sim *s)
{
	struct plot_sum *p = NULL;

	if (S == NULL)
		return NULL;
	S->clock++;
	for (int k = 0; k < NRUNS && p == NULL; k++)
		if (S->r[k].sim == s)
			p = &S->r[k];
	if (p == NULL) {
		/* the slot used least recently */
		p = &S->r[0];
		for (int k = 1; k < NRUNS; k++)
			if (S->r[k].used < p->used)
				p = &S->r[k];
		p->sim = s;
		p->arc = NULL;
		p->n = 0;
	}
	p->used = S->clock;
	if (!still_valid(p, hb_sim_arc(s))) {
		p->arc = hb_sim_arc(s);
		p->n = 0;
		memset(p->nb, 0, sizeof p->nb);
	}
	if (extend(p) != 0) {
		p->sim = NULL;
		p->n = 0;
		memset(p->nb, 0, sizeof p->nb);
		return NULL;
	}
	return p;
}

void
psum_range(const struct plot_sum *p, size_t i0, size_t i1, int q, double *lo, double *hi)
{
	double l = INFINITY, h = -INFINITY, v;
	size_t i = i0;
	int lev = 0;

	/* NaN fails every comparison, so it never enters l or h */
#define TAKE(lv) do {                                                              \
		if ((lv) == 0) {                                                    \
			v = psum_value(hb_arc_at(p->arc, i), q);                     \
			l = v < l ? v : l;                                           \
			h = v > h ? v : h;                                           \
		} else {                                                            \
			const struct mm *b_ = &p->b[(lv) - 1][i / bsize[lv]];        \
			l = b_->lo[q] < l ? b_->lo[q] : l;                           \
			h = b_->hi[q] > h ? b_->hi[q] : h;                           \
		}                                                                   \
		i += bsize[lv];                                                     \
	} while (0)
	/* a block of level lv at i, whole inside [i, i1) and summarised */
#define FITS(lv) (i + bsize[lv] <= i1 && ((lv) == 0 || i / bsize[lv] < p->nb[(lv) - 1]))
	/* up: to the boundary of each next level */
	for (; lev < NLEV; lev++) {
		while (i % bsize[lev + 1] != 0 && FITS(lev))
			TAKE(lev);
		if (i % bsize[lev + 1] != 0 || !FITS(lev + 1))
			break;
	}
	/* across the largest blocks that fit, then down */
	for (; lev >= 0; lev--)
		while (FITS(lev))
			TAKE(lev);
#undef FITS
#undef TAKE
	if (l <= h) {
		*lo = fmin(*lo, l);
		*hi = fmax(*hi, h);
	}
}

/* The first sample with t >= t. */
static size_t
first_at(const struct hb_arc *arc, double t)
{
	size_t i = hb_arc_find_t(arc, t);

	if (hb_arc_at(arc, i)->t < t)
		return i + 1;
	while (i > 0 && hb_arc_at(arc, i - 1)->t >= t)
		i--;
	return i;
}

void
psum_draw(const struct plot_sum *p, struct canvas *c, int q, double t0, double t1, int ink)
{
	const struct hb_arc *arc = p->arc;
	size_t n = hb_arc_len(arc), ia, joined = 0;
	double dt;

	if (n == 0 || c->pw < 2 || !(t1 > t0))
		return;
	dt = (t1 - t0) / (c->pw - 1);
	ia = first_at(arc, t0 - 0.5 * dt);
	for (int px = 0; px < c->pw && ia <= n; px++) {
		double t = t0 + px * dt;
		size_t ib = px + 1 < c->pw ? first_at(arc, t + 0.5 * dt) : n, from = ia;

		if (ia > 0 && ia < n && ia != joined) {
			const struct hb_arc_sample *s0 = hb_arc_at(arc, ia - 1), *s1 = hb_arc_at(arc, ia);

			if (ib > ia && s0->t >= t - 1.5 * dt)
				from = ia - 1;   /* in the column before: the stroke reaches it */
			else   /* a segment from further back, drawn once */
				canvas_line(c, s0->t, psum_value(s0, q), s1->t, psum_value(s1, q), ink);
			joined = ia;
		}
		if (ib > ia) {
			double lo = INFINITY, hi = -INFINITY;

			psum_range(p, from, ib, q, &lo, &hi);
			if (lo <= hi)
				canvas_line(c, t, lo, t, hi, ink);
		}
		ia = ib;
	}
}

void
psum_free(struct plot_sums *ps)
{
	if (ps == NULL)
		return;
	for (int k = 0; k < NRUNS; k++)
		for (int l = 0; l < NLEV; l++)
			free(ps->r[k].b[l]);
	for (int q = 0; q < PSUM_NQ; q++)
		canvas_free(ps->plot[q].c);
	free(ps);
}

void
psum_view_of(struct psum_view *v, int q, int view, double t0, double t1, int w, int h,
             int braille, const struct hb_sim *const *s, const int *ink, int n)
{
	memset(v, 0, sizeof *v);   /* padding too: views are compared with memcmp */
	v->q = q;
	v->view = view;   /* with the presentation mode: it may draw otherwise */
	v->t0 = t0;
	v->t1 = t1;
	v->w = w;
	v->h = h;
	v->braille = braille;
	v->n = n < PSUM_MAXRUNS ? n : PSUM_MAXRUNS;
	for (int k = 0; k < v->n; k++) {
		const struct hb_arc *arc = hb_sim_arc(s[k]);
		size_t len = hb_arc_len(arc);

		v->sim[k] = s[k];
		v->len[k] = len;
		v->ink[k] = ink[k];
		if (len > 0) {
			v->last_t[k] = hb_arc_at(arc, len - 1)->t;
			v->last_x[k] = hb_arc_at(arc, len - 1)->x;
			v->mid_x[k] = hb_arc_at(arc, len / 2)->x;
		}
	}
}

struct canvas *
psum_plot_get(struct plot_sums *ps, const struct psum_view *v, struct axis *ay)
{
	if (ps == NULL || v->q < 0 || v->q >= PSUM_NQ || ps->plot[v->q].c == NULL ||
	    memcmp(&ps->plot[v->q].v, v, sizeof *v) != 0)
		return NULL;
	*ay = ps->plot[v->q].ay;
	return ps->plot[v->q].c;
}

int
psum_plot_put(struct plot_sums *ps, const struct psum_view *v, struct canvas *c,
              const struct axis *ay)
{
	if (ps == NULL || v->q < 0 || v->q >= PSUM_NQ)
		return -1;
	canvas_free(ps->plot[v->q].c);
	ps->plot[v->q].v = *v;
	ps->plot[v->q].c = c;
	ps->plot[v->q].ay = *ay;
	return 0;
}
