/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_body.c - the plots of one body b (B): its position y (its centre)
 * and its velocity u against t, stacked over the plots' time axis, in the
 * plots' rectangle.  The run's arc keeps one interface's state, not the
 * bodies', so both come from the space-time records (spacetime.c): y by
 * the records' cubic, u by its derivative, one point a pixel column.
 * Pinned runs are not drawn here.
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

enum { LM = 9, NQ = 2 };

static double
q_at(const struct spacetime *st, int b, int q, double t, size_t *hint)
{
	return q == 0 ? st_y_at(st, b, t, hint) : st_u_at(st, b, t, hint);
}

/* The range of y (q 0) or u (q 1) of body b over [t0, t1], one value a pixel column. */
static void
q_range(const struct spacetime *st, int b, int q, double t0, double t1, int pw, double *lo,
        double *hi)
{
	double tl = st->t[st->nrec - 1];
	size_t hint = 0;

	*lo = INFINITY;
	*hi = -INFINITY;
	for (int px = 0; px < pw; px++) {
		double t = t0 + (t1 - t0) * px / (pw > 1 ? pw - 1 : 1), v;
		if (t > tl)
			break;
		v = q_at(st, b, q, t, &hint);
		if (isfinite(v)) {
			*lo = fmin(*lo, v);
			*hi = fmax(*hi, v);
		}
	}
	if (!(*lo <= *hi))
		*lo = *hi = 0;
	if (q == 1) {   /* at rest is a line worth seeing */
		*lo = fmin(*lo, 0);
		*hi = fmax(*hi, 0);
	}
}

static void
q_draw(const struct spacetime *st, struct canvas *c, int b, int q, double t0, double t1)
{
	double tl = st->t[st->nrec - 1], pt = 0, py = 0;
	size_t hint = 0;
	int have = 0;

	for (int px = 0; px < c->pw; px++) {
		double t = t0 + (t1 - t0) * px / (c->pw > 1 ? c->pw - 1 : 1), v;
		if (t > tl)
			break;
		v = q_at(st, b, q, t, &hint);
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
pane_body_draw(const struct app *a)
{
	static const char *name[NQ] = { "y", "u" }, *base[NQ] = { "m", "m/s" };
	const struct rect *r = &a->L.plots;
	const struct spacetime *st = a->st;
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	int cw = r->w - LM, hs[NQ], y = r->y + 1, b = spacetime_body(a), nb = hb_sim_nbodies(a->sim);
	double t0, t1, tc = hb_arc_len(arc) ? hb_arc_at(arc, a->cursor)->t : 0;
	char title[160], line[1024];
	struct axis ax;

	if (cw < 10 || r->h < 3 + NQ)
		return;
	snprintf(title, sizeof title, "body %d of %d%s: position y and velocity u", b + 1, nb,
	         b == 0 && nb > 1 ? " (the lowest)" : b + 1 == nb && nb > 1 ? " (the top one)" : "");
	if (a->branch_t >= 0 || st == NULL || st->failed || st->nrec == 0) {
		snprintf(title + strlen(title), sizeof title - strlen(title), ": %s",
		         a->branch_t >= 0 ? "not for a branched run (B: back)" : "computing...");
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
		q_range(st, b, q, t0, t1, c->pw, &lo, &hi);
		canvas_axis(lo, hi, hs[q] / 2 + 2, base[q], &ay);
		canvas_range(c, t0, t1, ay.lo, ay.hi);
		q_draw(st, c, b, q, t0, t1);
		st_blit(a, c, y, r->x + LM, canvas_col(c, tc));
		st_ylabels(&ay, y, hs[q], name[q]);
		canvas_free(c);
		y += hs[q];
	}
	canvas_axis(t0, t1, cw / 10 > 2 ? cw / 10 : 2, "s", &ax);
	canvas_axis_line(&ax, t0, t1, cw, line, sizeof line);
	tui_puts(y, r->x + LM, cw, line, 0);
	tui_puts(y, 0, LM - 1, "t ->", A_BOLD);
}
