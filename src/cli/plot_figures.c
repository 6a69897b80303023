/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_figures.c - the figures of a run as figure models (plot_model.h):
 * the state against t, the observables per collision, hysteresis loops.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/arc.h"
#include "hybounce/columns.h"
#include "hybounce/sim.h"
#include "cnum.h"
#include "plot_cmd.h"

static void
extent(const double *v, size_t n, double *lo, double *hi)
{
	*lo = INFINITY;
	*hi = -INFINITY;
	for (size_t i = 0; i < n; i++)
		if (isfinite(v[i])) {
			*lo = fmin(*lo, v[i]);
			*hi = fmax(*hi, v[i]);
		}
}

/* A panel with one series; the y axis fitted to it. */
static int
panel_of(struct plot_figure *f, const char *xt, const char *xu, const char *yt,
         const char *yu, const double *x, const double *y, size_t n, int line, int markers)
{
	struct plot_panel *p = plot_panel_add(f, xt, xu, yt, yu);
	double lo, hi;

	if (p == NULL || plot_series_add(p, "", x, y, n, 0, line, markers) != 0)
		return -1;
	extent(y, n, &lo, &hi);
	plot_axis_fit(&p->ya, lo, hi, yu, 0, 4);
	return 0;
}

/*
 * x against t, a flight's sparse samples (the closed-form parabola needs
 * few steps) joined by the cubic through their x and v = dx/dt, which is
 * that parabola, so that the curve is smooth at a figure's resolution.
 */
static int
panel_x(struct plot_figure *f, const struct hb_arc *a, double t_end)
{
	size_t n = hb_arc_len(a), m = 0, cap = n + 1;
	const double step = (t_end > 0 ? t_end : 1) / 400;
	double *x = NULL, *y = NULL;
	int rc;

	for (size_t i = 0; i + 1 < n; i++) {
		const struct hb_arc_sample *p = hb_arc_at(a, i), *q = hb_arc_at(a, i + 1);

		if (p->j == q->j && p->q == 0 && q->t - p->t > step)
			cap += (size_t)fmin(64, ceil((q->t - p->t) / step));
	}
	x = malloc(cap * sizeof *x);
	y = malloc(cap * sizeof *y);
	if (x == NULL || y == NULL) {
		free(x);
		free(y);
		return -1;
	}
	for (size_t i = 0; i < n; i++) {
		const struct hb_arc_sample *p = hb_arc_at(a, i), *q = i + 1 < n ? hb_arc_at(a, i + 1) : p;

		x[m] = p->t;
		y[m++] = p->x;
		if (q != p && p->j == q->j && p->q == 0 && q->t - p->t > step) {
			int k = (int)fmin(64, ceil((q->t - p->t) / step));
			double h = q->t - p->t;

			for (int l = 1; l < k; l++) {
				double s = (double)l / k, s2 = s * s, s3 = s2 * s;

				x[m] = p->t + s * h;
				y[m++] = (2 * s3 - 3 * s2 + 1) * p->x + (s3 - 2 * s2 + s) * h * p->v +
				         (-2 * s3 + 3 * s2) * q->x + (s3 - s2) * h * q->v;
			}
		}
	}
	rc = panel_of(f, "t", "s", "x", "m", x, y, m, 1, 0);
	free(x);
	free(y);
	return rc;
}

/* The collisions of the run, the contacts in progress last (a chain's, in increasing k, as batch). */
static size_t
collisions(const struct hb_sim *s, struct hb_collision **out)
{
	size_t n = hb_sim_ncollisions(s), nl = hb_sim_contacts_live(s), k;

	*out = malloc((n + nl + 1) * sizeof **out);
	if (*out == NULL)
		return (size_t)-1;
	for (k = 0; k < n; k++)
		(*out)[k] = *hb_sim_collision(s, k);
	for (k = 0; k < nl && hb_sim_contact_live_nth(s, k, &(*out)[n]); k++)
		n++;
	return n;
}

static int
build_state(struct plot_figure *f, const struct hb_sim *s, char *msg, size_t mn)
{
	const struct hb_arc *a = hb_sim_arc(s);
	const int nz = hb_sim_scene(s)->law->n_z;
	size_t n = hb_arc_len(a), nc;
	double *buf, *t, *col, t_end;
	struct hb_collision *cs;
	int fe = 0, rc = 0;

	buf = malloc((n > 0 ? n : 1) * 2 * sizeof *buf);
	nc = collisions(s, &cs);
	if (buf == NULL || nc == (size_t)-1) {
		free(buf);
		cnum_snprintf(msg, mn, "out of memory");
		return -1;
	}
	t = buf;
	col = buf + n;
	/* F_e where it acts: where it varies (a constant one is the weight) */
	for (size_t i = 0; i < n; i++) {
		t[i] = hb_arc_at(a, i)->t;
		fe |= hb_arc_at(a, i)->Fer != hb_arc_at(a, 0)->Fer;
	}
	t_end = n > 0 ? t[n - 1] : 0;
#define PANEL(title, unit, expr)                                                \
	do {                                                                    \
		for (size_t i = 0; i < n; i++) {                                \
			const struct hb_arc_sample *p_ = hb_arc_at(a, i);       \
			col[i] = (expr);                                        \
		}                                                               \
		rc |= panel_of(f, "t", "s", title, unit, t, col, n, 1, 0);      \
	} while (0)
	rc |= panel_x(f, a, t_end);
	PANEL("v", "m/s", p_->v);
	PANEL("x_c", "m", p_->xc);
	PANEL("F_c", "N", p_->Fc);
	for (int k = 0; k < nz && k < 3; k++) {
		char zt[16];

		if (nz == 1)
			cnum_snprintf(zt, sizeof zt, "z_c");
		else
			cnum_snprintf(zt, sizeof zt, "z_{c,%d}", k + 1);
		PANEL(zt, "", p_->z[k]);
	}
	if (fe)
		PANEL("F_e", "N", p_->Fer);
#undef PANEL
	if (rc == 0) {
		double *te = malloc((nc + 1) * sizeof *te), *ts = malloc((nc + 1) * sizeof *ts);

		if (te == NULL || ts == NULL)
			rc = -1;
		for (size_t k = 0; rc == 0 && k < nc; k++) {
			te[k] = cs[k].te;
			ts[k] = cs[k].ts;
		}
		for (int k = 0; rc == 0 && k < f->npanels; k++) {
			struct plot_panel *p = &f->p[k];

			p->xlabels = k == f->npanels - 1;
			plot_axis_fit(&p->xa, 0, t_end > 0 ? t_end : 1, "s", 1, 5);
			if (plot_bands_set(p, te, ts, nc) != 0)
				rc = -1;
		}
		free(te);
		free(ts);
	}
	if (rc == 0)
		plot_legend_add(f, "contact (q_c = 1)", -1, 0, 0);
	free(buf);
	free(cs);
	if (rc != 0)
		cnum_snprintf(msg, mn, "out of memory");
	return rc;
}

static int
build_observables(struct plot_figure *f, const struct hb_sim *s, char *msg, size_t mn)
{
	static const char *const names[] = { "t_d", "t_f", "v_i", "e", "x_c_max", "x_c_r",
	                                     "F_c_max", "W", "Lambda" };
	size_t n = hb_sim_ncollisions(s);
	double *x = malloc((n > 0 ? n : 1) * sizeof *x), *y = malloc((n > 0 ? n : 1) * sizeof *y);
	int rc = 0;

	if (x == NULL || y == NULL) {
		free(x);
		free(y);
		cnum_snprintf(msg, mn, "out of memory");
		return -1;
	}
	for (size_t k = 0; k < n; k++)
		x[k] = (double)hb_sim_collision(s, k)->i;
	for (size_t c = 0; rc == 0 && c < sizeof names / sizeof names[0]; c++) {
		const struct hb_collision_column *col = hb_collision_column_find(names[c]);
		const char *label = strcmp(col->name, "Lambda") == 0 ? "\xce\x9b" : col->label;
		double lo, hi;

		for (size_t k = 0; k < n; k++)
			y[k] = hb_collision_value(hb_sim_collision(s, k), col);
		rc = panel_of(f, "i", "", label, col->unit, x, y, n, 1, 1);
		if (rc == 0) {
			struct plot_panel *p = &f->p[f->npanels - 1];

			p->xa.whole = 1;
			extent(x, n, &lo, &hi);
			if (n == 0) {
				lo = 0;
				hi = 1;
			}
			plot_axis_fit(&p->xa, lo - 0.5, hi + 0.5, "", 1, 5);
		}
	}
	free(x);
	free(y);
	if (rc != 0)
		cnum_snprintf(msg, mn, "out of memory");
	return rc;
}

static int
build_loop(struct plot_figure *f, const struct hb_sim *s, const long *coll, int ncoll,
           char *msg, size_t mn)
{
	const struct hb_arc *a = hb_sim_arc(s);
	size_t nc = hb_sim_ncollisions(s), ni = hb_arc_nintervals(a);
	long first[3];
	struct plot_panel *p = plot_panel_add(f, "x_c", "m", "F_c", "m");
	double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;

	if (p == NULL)
		return -1;
	cnum_snprintf(p->ya.unit, sizeof p->ya.unit, "N");
	if (ncoll == 0) {
		for (size_t k = 0; k < nc && k < 3; k++)
			first[k] = hb_sim_collision(s, k)->i;
		ncoll = nc < 3 ? (int)nc : 3;
		coll = first;
		if (ncoll == 0) {
			cnum_snprintf(msg, mn, "the run has no complete collision to draw a loop of; "
			              "expected a run with collisions (a longer run.T?)");
			return -1;
		}
	}
	for (int c = 0; c < ncoll; c++) {
		const struct hb_collision *col = NULL;
		double *x, *y;
		size_t m = 0, cap = 0;
		char lab[32];

		for (size_t k = 0; k < nc; k++)
			if (hb_sim_collision(s, k)->i == coll[c])
				col = hb_sim_collision(s, k);
		if (col == NULL) {
			if (nc > 0)
				cnum_snprintf(msg, mn, "--collisions: the run has no collision i = %ld; "
				              "expected an index i of the %zu it kept, from %ld to %ld",
				              coll[c], nc, hb_sim_collision(s, 0)->i,
				              hb_sim_collision(s, nc - 1)->i);
			else
				cnum_snprintf(msg, mn, "--collisions: the run has no collision i = %ld; "
				              "expected a run with collisions (a longer run.T?)", coll[c]);
			return -1;
		}
		for (size_t k = 0; k < ni; k++) {
			const struct hb_arc_interval *iv = hb_arc_interval_at(a, k);

			if (iv->j == col->j && iv->q == 1)
				cap += iv->last - iv->first + 1;
		}
		x = malloc((cap > 0 ? cap : 1) * sizeof *x);
		y = malloc((cap > 0 ? cap : 1) * sizeof *y);
		if (x == NULL || y == NULL) {
			free(x);
			free(y);
			cnum_snprintf(msg, mn, "out of memory");
			return -1;
		}
		for (size_t k = 0; k < ni; k++) {
			const struct hb_arc_interval *iv = hb_arc_interval_at(a, k);

			if (iv->j != col->j || iv->q != 1)
				continue;
			for (size_t i = iv->first; i <= iv->last; i++) {
				x[m] = hb_arc_at(a, i)->xc;
				y[m] = hb_arc_at(a, i)->Fc;
				m++;
			}
		}
		cnum_snprintf(lab, sizeof lab, "i = %ld", coll[c]);
		if (plot_series_add(p, lab, x, y, m, c, 1, 0) != 0) {
			free(x);
			free(y);
			cnum_snprintf(msg, mn, "out of memory");
			return -1;
		}
		plot_legend_add(f, lab, c, 1, 0);
		for (size_t i = 0; i < m; i++) {
			xlo = fmin(xlo, x[i]);
			xhi = fmax(xhi, x[i]);
			ylo = fmin(ylo, y[i]);
			yhi = fmax(yhi, y[i]);
		}
		free(x);
		free(y);
	}
	plot_axis_fit(&p->xa, xlo, xhi, "m", 0, 5);
	plot_axis_fit(&p->ya, ylo, yhi, "N", 0, 5);
	return 0;
}

int
plot_build(struct plot_figure *f, enum plot_kind kind, const struct hb_sim *s, double w,
           double h, const long *coll, int ncoll, char *msg, size_t n)
{
	int rc;

	plot_figure_init(f, w, h > 0 ? h : w);
	switch (kind) {
	case PLOT_STATE:
		rc = build_state(f, s, msg, n);
		if (h <= 0)
			f->h = w / 252 * 72 * (0.7 + 0.85 * f->npanels);
		break;
	case PLOT_OBSERVABLES:
		f->ncols = w < 6 * 72 ? 2 : 3;
		rc = build_observables(f, s, msg, n);
		if (h <= 0)
			f->h = w / 252 * 72 * (0.3 + 1.25 * ((f->npanels + f->ncols - 1) / f->ncols));
		break;
	default:
		rc = build_loop(f, s, coll, ncoll, msg, n);
		if (h <= 0)
			f->h = 0.85 * w;
		break;
	}
	if (rc != 0)
		plot_figure_free(f);
	return rc;
}
