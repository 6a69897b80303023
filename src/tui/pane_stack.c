/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_stack.c - a pane of plots against t stacked over the plots' time
 * axis (pane_body.c's y and u of a body, pane_iface.c's x, x_c and F_c of
 * an interface): the title, the plots with their y labels and the time
 * cursor, the time axis; and the sampling of a function of t from the
 * space-time records, one point a pixel column.
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

enum { LM = 9 };

/* t of pixel column px of pw over [t0, t1] */
static double
px_t(double t0, double t1, int px, int pw)
{
	return t0 + (t1 - t0) * px / (pw > 1 ? pw - 1 : 1);
}

void
st_fn_widen(const struct spacetime *st, st_fn *fn, int who, int q, double t0, double t1, int pw,
            double *lo, double *hi)
{
	double tl = st->t[st->nrec - 1];
	size_t hint = 0;

	for (int px = 0; px < pw; px++) {
		double t = px_t(t0, t1, px, pw), v;
		if (t > tl)
			break;
		v = fn(st, who, q, t, &hint);
		if (isfinite(v)) {
			*lo = fmin(*lo, v);
			*hi = fmax(*hi, v);
		}
	}
}

void
st_fn_draw(const struct spacetime *st, struct canvas *c, st_fn *fn, int who, int q, double t0,
           double t1)
{
	double tl = st->t[st->nrec - 1], pt = 0, py = 0;
	size_t hint = 0;
	int have = 0;

	for (int px = 0; px < c->pw; px++) {
		double t = px_t(t0, t1, px, c->pw), v;
		if (t > tl)
			break;
		v = fn(st, who, q, t, &hint);
		if (!isfinite(v))
			continue;
		if (have)
			canvas_line(c, pt, py, t, v, 1);
		pt = t;
		py = v;
		have = 1;
	}
}

void
pane_stack_draw(const struct app *a, char *title, size_t tn, const struct stack_plots *sp)
{
	const struct rect *r = &a->L.plots;
	const struct spacetime *st = a->st;
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	int cw = r->w - LM, hs[STACK_MAXQ], y = r->y + 1;
	double t0, t1, tc = hb_arc_len(arc) ? hb_arc_at(arc, a->cursor)->t : 0;
	char line[1024];
	struct axis ax;

	if (cw < 10 || r->h < 3 + sp->nq)
		return;
	if (a->branch_t >= 0 || st == NULL || st->failed || st->nrec == 0) {
		if (a->branch_t >= 0)
			snprintf(title + strlen(title), tn - strlen(title),
			         ": not for a branched run (%c: back)", sp->key);
		else
			snprintf(title + strlen(title), tn - strlen(title), ": computing...");
		tui_puts(r->y, LM, cw, title, A_BOLD);
		return;
	}
	if (hb_sim_end(st->sh) == HB_SIM_RUNNING)
		snprintf(title + strlen(title), tn - strlen(title), "; computing %.0f%%",
		         100 * st->t[st->nrec - 1] / (st->T > 0 ? st->T : 1));
	tui_puts(r->y, LM, cw, title, A_BOLD);
	st_time_range(a, st, &t0, &t1);
	layout_stack(r->h - 1, sp->nq, 1, hs);
	for (int q = 0; q < sp->nq; q++) {
		double lo, hi;
		struct axis ay;
		struct canvas *c = canvas_new(cw, hs[q], a->braille);

		if (c == NULL)
			term_oom();
		sp->range(st, sp->ctx, q, t0, t1, c->pw, &lo, &hi);
		canvas_axis(lo, hi, hs[q] / 2 + 2, sp->unit[q], &ay);
		canvas_range(c, t0, t1, ay.lo, ay.hi);
		sp->draw(st, sp->ctx, c, q, t0, t1);
		st_blit(a, c, y, r->x + LM, canvas_col(c, tc));
		st_ylabels(&ay, y, hs[q], sp->name[q]);
		canvas_free(c);
		y += hs[q];
	}
	canvas_axis(t0, t1, cw / 10 > 2 ? cw / 10 : 2, "s", &ax);
	canvas_axis_line(&ax, t0, t1, cw, line, sizeof line);
	tui_puts(y, r->x + LM, cw, line, 0);
	tui_puts(y, 0, LM - 1, "t ->", A_BOLD);
}
