/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * figure_spacetime.c - f while the space-time view (V) is shown: the view
 * as a figure, in the figure model of `hybounce plot` (plot_model.h), as
 * figure.c saves the plots.  One panel: each body's position y against t
 * over the view's time range (the records' cubic, spacetime.c, sampled
 * along the axis), every m-th body and the top one when there are more
 * than FIG_ST_BODIES, as the view thins them; each contact over its
 * extent at its contact point (the lower body's top, or the floor), with
 * a marker so that a contact shorter than a pixel shows; the cursor as a
 * vertical line.  A panel holds PLOT_MAX_SERIES series, so the bodies are
 * one series (a NaN between two bodies breaks the line), the contacts one.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "figure.h"
#include "spacetime.h"
#include "tui.h"
#include "../cli/plot_model.h"

enum { FIG_ST_BODIES = 40, FIG_ST_POINTS = 400, FIG_ST_CONTACT_POINTS = 8 };

/* Appends (x, y) to a growing pair of arrays; -1 out of memory. */
static int
push(double **x, double **y, size_t *n, size_t *cap, double xv, double yv)
{
	if (*n == *cap) {
		size_t c = *cap ? 2 * *cap : 1024;
		double *nx = realloc(*x, c * sizeof *nx), *ny;
		if (nx == NULL)
			return -1;
		*x = nx;
		ny = realloc(*y, c * sizeof *ny);
		if (ny == NULL)
			return -1;
		*y = ny;
		*cap = c;
	}
	(*x)[*n] = xv;
	(*y)[(*n)++] = yv;
	return 0;
}

/* The contact point of contact k at t: the lower body's top, or the floor. */
static double
contact_y(const struct spacetime *st, const struct st_contact *k, double t)
{
	size_t hint = 0;

	if (k->k == 0)
		return st->floor_y;
	return st_y_at(st, k->k - 1, t, &hint) + st->R[k->k - 1];
}

int
figure_spacetime(const struct app *a, struct plot_figure *f, double tcur, const char *cursor_label,
                 int *nbodies, long *ncontacts)
{
	const struct spacetime *st = a->st;
	struct plot_panel *p;
	double t0, t1, tl, *x = NULL, *y = NULL;
	size_t n = 0, cap = 0;
	int every = 1, rc = -1;
	char label[96];

	*nbodies = 0;
	*ncontacts = 0;
	if (st == NULL || st->failed || st->nrec == 0 || a->branch_t >= 0)
		return 1;
	st_time_range(a, st, &t0, &t1);
	tl = fmin(t1, st->t[st->nrec - 1]);
	p = plot_panel_add(f, "t", "s", "y", "m");
	if (p == NULL)
		return -1;
	if (st->nb > FIG_ST_BODIES)
		every = (st->nb + FIG_ST_BODIES - 1) / FIG_ST_BODIES;
	/* the bodies: one series, a NaN between two */
	for (int b = 0; b < st->nb; b++) {
		size_t hint = 0;
		if (b % every != 0 && b != st->nb - 1)
			continue;
		if (n > 0 && push(&x, &y, &n, &cap, NAN, NAN) != 0)
			goto out;
		for (int i = 0; i <= FIG_ST_POINTS && tl >= t0; i++) {
			double t = t0 + (tl - t0) * i / FIG_ST_POINTS;
			if (push(&x, &y, &n, &cap, t, st_y_at(st, b, t, &hint)) != 0)
				goto out;
		}
		(*nbodies)++;
	}
	if (every > 1)
		snprintf(label, sizeof label, "every %d%s of %d bodies", every,
		         every == 2 ? "nd" : every == 3 ? "rd" : "th", st->nb);
	else
		snprintf(label, sizeof label, "%d bod%s", st->nb, st->nb == 1 ? "y" : "ies");
	if (n > 0 && plot_series_add(p, label, x, y, n, 0, 1, 0) != 0)
		goto out;
	plot_legend_add(f, label, 0, 1, 0);
	/* the contacts: each over its extent at its contact point, one series */
	n = 0;
	for (size_t i = 0; i < st->nc; i++) {
		const struct st_contact *k = &st->c[i];
		double c0, c1;
		if (k->t1 < t0 || k->t0 > t1)
			continue;
		c0 = fmax(k->t0, t0);
		c1 = fmin(k->t1, t1);
		if (n > 0 && push(&x, &y, &n, &cap, NAN, NAN) != 0)
			goto out;
		for (int j = 0; j < FIG_ST_CONTACT_POINTS; j++) {
			double t = c0 + (c1 - c0) * j / (FIG_ST_CONTACT_POINTS - 1);
			if (push(&x, &y, &n, &cap, t, contact_y(st, k, t)) != 0)
				goto out;
		}
		(*ncontacts)++;
	}
	if (n > 0) {
		if (plot_series_add(p, "contact", x, y, n, 1, 1, 1) != 0)
			goto out;
		plot_legend_add(f, "contact", 1, 1, 1);
	}
	if (isfinite(tcur) && tcur >= t0 && tcur <= t1) {
		double cx[2] = { tcur, tcur }, cy[2] = { st->ylo, st->yhi };
		if (plot_series_add(p, "", cx, cy, 2, FIG_CURSOR_STYLE, 1, 0) != 0)
			goto out;
		plot_legend_add(f, cursor_label, FIG_CURSOR_STYLE, 1, 0);
	}
	p->xlabels = 1;
	plot_axis_fit(&p->xa, t0, t1, "s", 1, 5);
	plot_axis_fit(&p->ya, st->ylo, st->yhi > st->ylo ? st->yhi : st->ylo + 1e-3, "m", 0, 5);
	rc = 0;
out:
	free(x);
	free(y);
	return rc;
}
