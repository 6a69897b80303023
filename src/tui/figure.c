/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * figure.c - f: the view as a figure (PNG), through the figure model of
 * `hybounce plot` (src/cli/plot_model.h) and its cairo renderer
 * (plot_cairo.h): the plots as shown (x, x_c and F_c against t over the
 * view's range, or against j, or the hysteresis loop of the zoomed
 * collision), every run drawn (the pinned ones and the current one, each
 * in its style and labelled by what differs), the current run's contacts
 * shaded, and the cursor as a vertical line (a point on the loop).  While
 * the space-time view (V) is shown, that view (figure_spacetime.c).
 *
 * The file is PRESET-view.png in the working folder; a second save writes
 * PRESET-view-2.png (tui_unused_name), the output policy (outputs.h)
 * refuses an input or a shipped preset, and the file is written
 * atomically.  The message says where.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic.h"
#include "outputs.h"
#include "status.h"
#include "units.h"
#include "figure.h"
#include "spacetime.h"
#include "tui.h"
#include "../cli/plot_cairo.h"

enum { FIG_DPI = 150 };

static const char *const qname[3] = { "x", "x_c", "F_c" };
static const char *const qbase[3] = { "m", "m", "N" };

static double
qval(const struct hb_arc_sample *s, int q)
{
	return q == 0 ? s->x : q == 1 ? s->xc : s->Fc;
}

/* The runs drawn: pins first (styles 1..3), the current one last (style 0). */
static int
fig_runs(const struct app *a, const struct hb_sim **s, int *style, const char **label)
{
	int n = 0;

	for (int i = 0; i < a->npins; i++) {
		s[n] = a->pin[i].sim;
		style[n] = i + 1;
		label[n++] = a->pin[i].label;
	}
	s[n] = a->sim;
	style[n] = 0;
	label[n++] = a->run_label;
	return n;
}

/* One run's quantity q against the abscissa over [t0, t1] (one sample either side) as a series. */
static int
add_run(const struct app *a, struct plot_panel *p, const struct hb_sim *s, int q, double t0,
        double t1, const char *label, int style, double *lo, double *hi)
{
	const struct hb_arc *arc = hb_sim_arc(s);
	size_t n = hb_arc_len(arc), i0 = 0, i1 = n, m = 0;
	double *x, *y;
	int rc;

	if (n == 0)
		return 0;
	if (a->view != VIEW_J) {
		i0 = hb_arc_find_t(arc, t0);
		while (i0 > 0 && hb_arc_at(arc, i0 - 1)->t >= t0)
			i0--;
		i1 = hb_arc_find_t(arc, t1) + 2;
		i1 = i1 < n ? i1 : n;
	}
	/* room for a break (NaN) before each sample in the (t, j) view */
	x = malloc((2 * (i1 - i0) + 1) * sizeof *x);
	y = malloc((2 * (i1 - i0) + 1) * sizeof *y);
	if (x == NULL || y == NULL) {
		free(x);
		free(y);
		return -1;
	}
	for (size_t i = i0; i < i1; i++) {
		const struct hb_arc_sample *p_ = hb_arc_at(arc, i);
		double xv = a->view == VIEW_J ? (double)p_->j : p_->t;

		/* (t, j): a NaN breaks the line at each jump */
		if (a->view == VIEW_J && i > i0 && hb_arc_at(arc, i - 1)->j != p_->j) {
			x[m] = NAN;
			y[m++] = NAN;
		}
		x[m] = xv;
		y[m] = qval(p_, q);
		if (xv >= t0 && xv <= t1 && isfinite(y[m])) {
			*lo = fmin(*lo, y[m]);
			*hi = fmax(*hi, y[m]);
		}
		m++;
	}
	rc = plot_series_add(p, label, x, y, m, style, 1, 0);
	free(x);
	free(y);
	return rc;
}

/* The current run's contact intervals inside [t0, t1], shaded. */
static int
add_contacts(const struct app *a, struct plot_panel *p, double t0, double t1)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	size_t ni = hb_arc_nintervals(arc), m = 0;
	double *b0 = malloc((ni + 1) * sizeof *b0), *b1 = malloc((ni + 1) * sizeof *b1);
	int rc;

	if (b0 == NULL || b1 == NULL) {
		free(b0);
		free(b1);
		return -1;
	}
	for (size_t k = 0; k < ni; k++) {
		const struct hb_arc_interval *iv = hb_arc_interval_at(arc, k);

		if (!iv->q || iv->t1 < t0 || iv->t0 > t1)
			continue;
		b0[m] = fmax(iv->t0, t0);
		b1[m++] = fmin(iv->t1, t1);
	}
	rc = plot_bands_set(p, b0, b1, m);
	free(b0);
	free(b1);
	return rc;
}

/* The plots against t (or j): x, x_c, F_c. */
static int
build_time(const struct app *a, struct plot_figure *f, double t0, double t1, double tcur,
           const char *cursor_label)
{
	const struct hb_sim *s[APP_MAX_PINS + 1];
	const char *label[APP_MAX_PINS + 1];
	int style[APP_MAX_PINS + 1], n = fig_runs(a, s, style, label);

	for (int q = 0; q < 3; q++) {
		struct plot_panel *p = plot_panel_add(f, a->view == VIEW_J ? "j" : "t",
		                                      a->view == VIEW_J ? "" : "s", qname[q], qbase[q]);
		double lo = INFINITY, hi = -INFINITY;

		if (p == NULL)
			return -1;
		for (int k = 0; k < n; k++)
			if (add_run(a, p, s[k], q, t0, t1, q == 0 ? label[k] : "", style[k], &lo, &hi) != 0)
				return -1;
		if (!(lo <= hi))
			lo = hi = 0;
		if (isfinite(tcur)) {
			/* the cursor: a vertical line over the data's range */
			double cx[2] = { tcur, tcur }, cy[2] = { lo, hi };

			if (plot_series_add(p, "", cx, cy, 2, FIG_CURSOR_STYLE, 1, 0) != 0)
				return -1;
		}
		if (a->view != VIEW_J && add_contacts(a, p, t0, t1) != 0)
			return -1;
		p->xlabels = q == 2;
		plot_axis_fit(&p->xa, t0, t1, a->view == VIEW_J ? "" : "s", 1, 5);
		p->xa.whole = a->view == VIEW_J;
		plot_axis_fit(&p->ya, lo, hi, qbase[q], 0, 4);
	}
	for (int k = 0; k < n; k++)
		plot_legend_add(f, label[k], style[k], 1, 0);
	if (a->view != VIEW_J)
		plot_legend_add(f, "contact (q_c = 1)", -1, 0, 0);
	if (isfinite(tcur))
		plot_legend_add(f, cursor_label, FIG_CURSOR_STYLE, 1, 0);
	return 0;
}

/* The loop F_c against x_c of the zoomed collision, every run; the cursor as a dot. */
static int
build_loop(const struct app *a, struct plot_figure *f, const char *cursor_label)
{
	const struct hb_sim *s[APP_MAX_PINS + 1];
	const char *label[APP_MAX_PINS + 1];
	int style[APP_MAX_PINS + 1], n = fig_runs(a, s, style, label);
	struct plot_panel *p = plot_panel_add(f, "x_c", "m", "F_c", "N");
	double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;

	if (p == NULL)
		return -1;
	for (int k = 0; k < n; k++) {
		struct hb_collision live;
		const struct hb_collision *col;
		const struct hb_arc *arc = hb_sim_arc(s[k]);
		size_t m = 0, cap = 64;
		double *x = malloc(cap * sizeof *x), *y = malloc(cap * sizeof *y);
		int rc;

		col = s[k] == a->sim ? app_collision(a, a->zoom_i, &live)
		      : a->zoom_i >= 0 && (size_t)a->zoom_i < hb_sim_ncollisions(s[k])
		      ? hb_sim_collision(s[k], (size_t)a->zoom_i) : NULL;
		if (x == NULL || y == NULL) {
			free(x);
			free(y);
			return -1;
		}
		for (size_t i = col != NULL && hb_arc_len(arc) > 0 ? hb_arc_find(arc, col->te, col->j)
		                                                   : hb_arc_len(arc);
		     i < hb_arc_len(arc) && hb_arc_at(arc, i)->j == col->j; i++) {
			if (m == cap) {
				double *nx, *ny;

				cap *= 2;
				nx = realloc(x, cap * sizeof *nx);
				if (nx != NULL)
					x = nx;
				ny = nx != NULL ? realloc(y, cap * sizeof *ny) : NULL;
				if (ny == NULL) {
					free(x);
					free(y);
					return -1;
				}
				y = ny;
			}
			x[m] = hb_arc_at(arc, i)->xc;
			y[m] = hb_arc_at(arc, i)->Fc;
			xlo = fmin(xlo, x[m]);
			xhi = fmax(xhi, x[m]);
			ylo = fmin(ylo, y[m]);
			yhi = fmax(yhi, y[m]);
			m++;
		}
		rc = plot_series_add(p, label[k], x, y, m, style[k], 1, 0);
		free(x);
		free(y);
		if (rc != 0)
			return -1;
		plot_legend_add(f, label[k], style[k], 1, 0);
	}
	if (hb_arc_len(hb_sim_arc(a->sim)) > 0) {
		const struct hb_arc_sample *c = hb_arc_at(hb_sim_arc(a->sim), a->cursor);
		struct hb_collision live;
		const struct hb_collision *col = app_collision(a, a->zoom_i, &live);

		if (col != NULL && c->j == col->j) {
			double cx = c->xc, cy = c->Fc;

			if (plot_series_add(p, "", &cx, &cy, 1, FIG_CURSOR_STYLE, 0, 1) != 0)
				return -1;
			plot_legend_add(f, cursor_label, FIG_CURSOR_STYLE, 0, 1);
		}
	}
	if (!(xlo <= xhi))
		xlo = xhi = ylo = yhi = 0;
	plot_axis_fit(&p->xa, xlo, xhi, "m", 0, 5);
	plot_axis_fit(&p->ya, ylo, yhi, "N", 0, 5);
	p->xlabels = 1;
	return 0;
}

/* "wrote PATH" words for how the file was written. */
static const char *
how(const struct hb_atomic_target *t, char *buf, size_t n)
{
	hb_outputs_how(t, buf, n);
	return buf;
}

void
act_figure(struct app *a)
{
	static const char *const vname[VIEW_COUNT] = { "whole run", "follow the cursor", "zoom",
	                                               "loop", "against j" };
	struct plot_figure *f;
	struct hb_outputs pol;
	struct hb_atomic_set set;
	char want[600], path[600], msg[512], tb[32], hw[128], cursor_label[64];
	double t0, t1, tcur = NAN;
	FILE *out;
	int rc, st_bodies = 0;
	long st_contacts = 0;

	if (hb_arc_len(hb_sim_arc(a->sim)) == 0) {
		app_msg(a, 1, "figure: nothing computed yet");
		return;
	}
	snprintf(want, sizeof want, "%.500s-view.png", a->preset);
	if (tui_unused_name(want, path, sizeof path) < 0) {
		app_msg(a, 1, "figure not written: %.500s and -2 ... -999 are all taken", want);
		return;
	}
	hb_outputs_init(&pol);
	hb_outputs_input(&pol, a->preset_path, "the preset being run");
	if (a->opt != NULL)
		hb_outputs_input(&pol, a->opt->data, "the data file (--data)");
	msg[0] = 0;
	if (hb_outputs_add(&pol, path, "the figure", msg, sizeof msg) != HB_OK) {
		app_msg(a, 1, "figure not written: %s", msg);
		return;
	}
	f = calloc(1, sizeof *f);
	if (f == NULL) {
		app_msg(a, 1, "figure not written: out of memory");
		return;
	}
	cursor_clamp(a);
	plot_view_range(a, &t0, &t1);
	if (spacetime_on(a)) {
		const struct hb_arc_sample *c = hb_arc_at(hb_sim_arc(a->sim), a->cursor);

		hb_units_format(c->t, hb_unit_time, 4, tb, sizeof tb);
		snprintf(cursor_label, sizeof cursor_label, "cursor, t = %s", tb);
		plot_figure_init(f, 7 * 72, 5.5 * 72);
		rc = figure_spacetime(a, f, c->t, cursor_label, &st_bodies, &st_contacts);
		if (rc == 1) {
			plot_figure_free(f);
			free(f);
			app_msg(a, 1, "figure not written: the space-time view has nothing to draw yet");
			return;
		}
		snprintf(f->title, sizeof f->title, "%.26s: space-time", a->preset);
	} else if (a->view == VIEW_LOOP) {
		plot_figure_init(f, 5 * 72, 4.25 * 72);
		snprintf(cursor_label, sizeof cursor_label, "cursor");
		rc = build_loop(a, f, cursor_label);
		snprintf(f->title, sizeof f->title, "%.26s: collision %ld", a->preset, a->zoom_i);
	} else {
		const struct hb_arc_sample *c = hb_arc_at(hb_sim_arc(a->sim), a->cursor);

		tcur = a->view == VIEW_J ? (double)c->j : c->t;
		hb_units_format(c->t, hb_unit_time, 4, tb, sizeof tb);
		snprintf(cursor_label, sizeof cursor_label, "cursor, t = %s", tb);
		plot_figure_init(f, 7 * 72, 5.5 * 72);
		rc = build_time(a, f, t0, t1, tcur, cursor_label);
		/* a markup run holds 47 bytes (plot_model.h): the title stays short */
		if (a->view == VIEW_ZOOM)
			snprintf(f->title, sizeof f->title, "%.26s: collision %ld", a->preset, a->zoom_i);
		else
			snprintf(f->title, sizeof f->title, "%.26s: %s", a->preset, vname[a->view]);
	}
	if (rc != 0) {
		plot_figure_free(f);
		free(f);
		app_msg(a, 1, "figure not written: out of memory");
		return;
	}
	hb_atomic_begin(&set);
	out = hb_atomic_add(&set, path, msg, sizeof msg);
	rc = out == NULL ? -1 : plot_cairo_write(f, PLOT_PNG, FIG_DPI, out, msg, sizeof msg);
	if (rc != 0 || hb_atomic_commit(&set, msg, sizeof msg) != HB_OK) {
		if (rc != 0 && out != NULL)
			hb_atomic_abort(&set);
		app_msg(a, 1, "figure not written: %s", msg);
	} else if (spacetime_on(a)) {
		char of[32] = "";

		if (st_bodies < a->st->nb)
			snprintf(of, sizeof of, " of %d", a->st->nb);
		app_msg(a, 0, "wrote %s%s: the space-time view (%d%s bod%s, %ld contact%s, the cursor)%s",
		        path, how(&pol.out[0].target, hw, sizeof hw), st_bodies, of,
		        st_bodies == 1 && !of[0] ? "y" : "ies",
		        st_contacts, st_contacts == 1 ? "" : "s",
		        strcmp(path, want) != 0 ? "; an earlier figure is kept" : "");
	} else {
		app_msg(a, 0, "wrote %s%s: the view as a figure (%d panel%s, %d run%s, the cursor)%s", path,
		        how(&pol.out[0].target, hw, sizeof hw), f->npanels, f->npanels == 1 ? "" : "s",
		        a->npins + 1, a->npins ? "s" : "", strcmp(path, want) != 0 ? "; an earlier figure is kept" : "");
	}
	plot_figure_free(f);
	free(f);
}
