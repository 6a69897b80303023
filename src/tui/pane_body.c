/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_body.c - the plots of one body b (B): its position y (its centre)
 * and its velocity u against t, stacked over the plots' time axis, in the
 * plots' rectangle (pane_stack.c).  The run's arc keeps one interface's
 * state, not the bodies', so both come from the space-time records
 * (spacetime.c): y by the records' cubic, u by its derivative, one point a
 * pixel column.  Pinned runs are not drawn here.
 */
#include <math.h>
#include <stdio.h>

#include "spacetime.h"
#include "tui.h"

static double
q_at(const struct spacetime *st, int b, int q, double t, size_t *hint)
{
	return q == 0 ? st_y_at(st, b, t, hint) : st_u_at(st, b, t, hint);
}

/* The range of y (q 0) or u (q 1) of body *ctx over [t0, t1], one value a pixel column. */
static void
q_range(const struct spacetime *st, const void *ctx, int q, double t0, double t1, int pw,
        double *lo, double *hi)
{
	*lo = INFINITY;
	*hi = -INFINITY;
	st_fn_widen(st, q_at, *(const int *)ctx, q, t0, t1, pw, lo, hi);
	if (!(*lo <= *hi))
		*lo = *hi = 0;
	if (q == 1) {   /* at rest is a line worth seeing */
		*lo = fmin(*lo, 0);
		*hi = fmax(*hi, 0);
	}
}

static void
q_draw(const struct spacetime *st, const void *ctx, struct canvas *c, int q, double t0, double t1)
{
	st_fn_draw(st, c, q_at, *(const int *)ctx, q, t0, t1);
}

void
pane_body_draw(const struct app *a)
{
	int b = spacetime_body(a), nb = hb_sim_nbodies(a->sim);
	const struct stack_plots sp = { 2, { "y", "u" }, { "m", "m/s" }, 'B', &b, q_range, q_draw };
	char title[160];

	snprintf(title, sizeof title, "body %d of %d%s: position y and velocity u", b + 1, nb,
	         b == 0 && nb > 1 ? " (the lowest)" : b + 1 == nb && nb > 1 ? " (the top one)" : "");
	pane_stack_draw(a, title, sizeof title, &sp);
}
