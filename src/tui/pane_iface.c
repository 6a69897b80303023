/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_iface.c - the plots of one interface k of a chain (K): its gap x,
 * indentation x_c and contact force F_c against t, stacked over the
 * plots' time axis, in the plots' rectangle.
 *
 * The run's arc records, in each flow interval, the interface of that
 * interval only.  Within each contact of k (the space-time buffer's
 * contacts, spacetime.c, whose j is the arc's) the arc's own samples are
 * k's and are drawn; elsewhere x_c and F_c of k are 0 (rule: F_c = -q_c
 * Phi, q_c = 0 in flight), and x is the gap between its two bodies from
 * the buffer's positions, one point a pixel column (pane_stack.c).
 * Pinned runs are not drawn here.
 */
#include <math.h>
#include <stdio.h>

#include "canvas.h"
#include "spacetime.h"
#include "tui.h"

struct iface {
	int k;
	const struct hb_arc *arc;
};

/* The gap of interface k at t from the records (no hint: st_gap_at keeps none). */
static double
gap_at(const struct spacetime *st, int k, int q, double t, size_t *hint)
{
	(void)q;
	(void)hint;
	return st_gap_at(st, k, t);
}

static double
qv(const struct hb_arc_sample *p, int q)
{
	return q == 0 ? p->x : q == 1 ? p->xc : p->Fc;
}

/* Visits the arc's samples of contact c (interval c->j): fn(p) for each. */
static size_t
contact_first(const struct hb_arc *arc, const struct st_contact *c)
{
	size_t i = hb_arc_find(arc, c->t0, c->j);

	while (i < hb_arc_len(arc) && hb_arc_at(arc, i)->j < c->j)
		i++;
	return i;
}

/* The range of quantity q of interface ctx->k over [t0, t1] (0 included). */
static void
q_range(const struct spacetime *st, const void *ctx, int q, double t0, double t1, int pw,
        double *lo, double *hi)
{
	const struct iface *f = ctx;
	const struct hb_arc *arc = f->arc;
	int k = f->k;

	*lo = *hi = 0;
	if (q == 0)
		st_fn_widen(st, gap_at, k, 0, t0, t1, pw, lo, hi);
	for (size_t i = 0; i < st->nc; i++) {
		const struct st_contact *c = &st->c[i];
		if (c->k != k || c->t1 < t0 || c->t0 > t1)
			continue;
		for (size_t s = contact_first(arc, c); s < hb_arc_len(arc); s++) {
			const struct hb_arc_sample *p = hb_arc_at(arc, s);
			if (p->j != c->j)
				break;
			if (p->t >= t0 && p->t <= t1 && isfinite(qv(p, q))) {
				*lo = fmin(*lo, qv(p, q));
				*hi = fmax(*hi, qv(p, q));
			}
		}
	}
}

static void
q_draw(const struct spacetime *st, const void *ctx, struct canvas *c, int q, double t0, double t1)
{
	const struct iface *f = ctx;
	const struct hb_arc *arc = f->arc;
	double te = fmin(t1, st->t[st->nrec - 1]);
	int k = f->k;

	if (q == 0)
		st_fn_draw(st, c, gap_at, k, 0, t0, t1);
	else if (te > t0)
		canvas_line(c, t0, 0, te, 0, 1);   /* 0 out of contact */
	for (size_t i = 0; i < st->nc; i++) {
		const struct st_contact *ct = &st->c[i];
		const struct hb_arc_sample *o = NULL;
		if (ct->k != k || ct->t1 < t0 || ct->t0 > t1)
			continue;
		for (size_t s = contact_first(arc, ct); s < hb_arc_len(arc); s++) {
			const struct hb_arc_sample *p = hb_arc_at(arc, s);
			if (p->j != ct->j)
				break;
			if (o != NULL)
				canvas_line(c, o->t, qv(o, q), p->t, qv(p, q), 1);
			o = p;
		}
	}
}

void
pane_iface_draw(const struct app *a)
{
	const struct iface f = { spacetime_iface(a), hb_sim_arc(a->sim) };
	const struct stack_plots sp = { 3, { "x", "x_c", "F_c" }, { "m", "m", "N" }, 'K', &f,
		                        q_range, q_draw };
	char title[160];

	if (f.k == 0)
		snprintf(title, sizeof title, "interface 0 (floor and body 1)");
	else
		snprintf(title, sizeof title, "interface %d (bodies %d and %d)", f.k, f.k, f.k + 1);
	pane_stack_draw(a, title, sizeof title, &sp);
}
