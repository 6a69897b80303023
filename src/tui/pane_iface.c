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
 * the buffer's positions, one point a pixel column.  Pinned runs are not
 * drawn here.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "canvas.h"
#include "layout.h"
#include "spacetime.h"
#include "term.h"
#include "tui.h"

enum { LM = 9, NQ = 3 };

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

/* The range of quantity q of interface k over [t0, t1] (0 included). */
static void
q_range(const struct spacetime *st, const struct hb_arc *arc, int k, int q, double t0, double t1,
        int pw, double *lo, double *hi)
{
	double tl = st->t[st->nrec - 1];

	*lo = *hi = 0;
	if (q == 0)
		for (int px = 0; px < pw; px++) {
			double t = t0 + (t1 - t0) * px / (pw > 1 ? pw - 1 : 1), x;
			if (t > tl)
				break;
			x = st_gap_at(st, k, t);
			if (isfinite(x)) {
				*lo = fmin(*lo, x);
				*hi = fmax(*hi, x);
			}
		}
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
q_draw(const struct spacetime *st, const struct hb_arc *arc, struct canvas *c, int k, int q,
       double t0, double t1)
{
	double tl = st->t[st->nrec - 1], te = fmin(t1, tl), pt = 0, py = 0;
	int have = 0;

	if (q == 0) {
		for (int px = 0; px < c->pw; px++) {
			double t = t0 + (t1 - t0) * px / (c->pw > 1 ? c->pw - 1 : 1), x;
			if (t > tl)
				break;
			x = st_gap_at(st, k, t);
			if (!isfinite(x))
				continue;
			if (have)
				canvas_line(c, pt, py, t, x, 1);
			pt = t;
			py = x;
			have = 1;
		}
	} else if (te > t0) {
		canvas_line(c, t0, 0, te, 0, 1);   /* 0 out of contact */
	}
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
	static const char *name[NQ] = { "x", "x_c", "F_c" }, *base[NQ] = { "m", "m", "N" };
	const struct rect *r = &a->L.plots;
	const struct spacetime *st = a->st;
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	int cw = r->w - LM, hs[NQ], y = r->y + 1, k = spacetime_iface(a), curcol = -1;
	double t0, t1, tc = hb_arc_len(arc) ? hb_arc_at(arc, a->cursor)->t : 0;
	char title[160], line[1024];
	struct axis ax;

	if (cw < 10 || r->h < 3 + NQ)
		return;
	if (k == 0)
		snprintf(title, sizeof title, "interface 0 (floor and body 1)");
	else
		snprintf(title, sizeof title, "interface %d (bodies %d and %d)", k, k, k + 1);
	if (a->branch_t >= 0 || st == NULL || st->failed || st->nrec == 0) {
		snprintf(title + strlen(title), sizeof title - strlen(title), ": %s",
		         a->branch_t >= 0 ? "not for a branched run (K: back)" : "computing...");
		tui_puts(r->y, LM, cw, title, A_BOLD);
		return;
	}
	if (hb_sim_end(st->sh) == HB_SIM_RUNNING)
		snprintf(title + strlen(title), sizeof title - strlen(title), "; computing %.0f%%",
		         100 * st->t[st->nrec - 1] / (st->T > 0 ? st->T : 1));
	tui_puts(r->y, LM, cw, title, A_BOLD);
	st_time_range(a, st, &t0, &t1);
	layout_stack(r->h - 1, NQ, 1, hs);
	for (int q = 0; q < NQ; q++) {
		double lo, hi;
		struct axis ay;
		struct canvas *c = canvas_new(cw, hs[q], a->braille);

		if (c == NULL)
			term_oom();
		q_range(st, arc, k, q, t0, t1, c->pw, &lo, &hi);
		canvas_axis(lo, hi, hs[q] / 2 + 2, base[q], &ay);
		canvas_range(c, t0, t1, ay.lo, ay.hi);
		q_draw(st, arc, c, k, q, t0, t1);
		curcol = canvas_col(c, tc);
		st_blit(a, c, y, r->x + LM, curcol);
		st_ylabels(&ay, y, hs[q], name[q]);
		canvas_free(c);
		y += hs[q];
	}
	canvas_axis(t0, t1, cw / 10 > 2 ? cw / 10 : 2, "s", &ax);
	canvas_axis_line(&ax, t0, t1, cw, line, sizeof line);
	tui_puts(y, r->x + LM, cw, line, 0);
	tui_puts(y, 0, LM - 1, "t ->", A_BOLD);
}
