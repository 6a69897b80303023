/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_fit.c - the figure of a fit (plot_cmd.h: plot_build_fit): the
 * measured values and the fitted run's against the impact index (a
 * bouncing sequence: the interval before each impact, whose ratios are
 * the restitution) or against |v_i| (drops: e, x_c^r, t_d), each with the
 * residuals, fitted - measured, in a panel below it.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/fit.h"
#include "cnum.h"
#include "plot_cmd.h"
#include "plot_out.h"

static void
extent2(const double *a, const double *b, size_t n, double *lo, double *hi)
{
	for (size_t k = 0; k < n; k++) {
		if (isfinite(a[k])) {
			*lo = fmin(*lo, a[k]);
			*hi = fmax(*hi, a[k]);
		}
		if (b != NULL && isfinite(b[k])) {
			*lo = fmin(*lo, b[k]);
			*hi = fmax(*hi, b[k]);
		}
	}
}

/* sort idx[0..n) by x (insertion: a fit has tens of points) */
static void
order(size_t *idx, const double *x, size_t n)
{
	for (size_t a = 1; a < n; a++) {
		size_t v = idx[a], b = a;

		while (b > 0 && x[idx[b - 1]] > x[v]) {
			idx[b] = idx[b - 1];
			b--;
		}
		idx[b] = v;
	}
}

/*
 * One observable: its panel (measured as dots over the fitted values as
 * a dashed line, in x order) and its residual panel below it.
 */
static int
add_pair(struct plot_figure *f, struct plot_panel *top, struct plot_panel *bot,
         const char *xt, const char *xu, const char *yu, int xwhole, const double *x,
         const double *ym, const double *ys, size_t m)
{
	size_t *idx = malloc((m ? m : 1) * sizeof *idx);
	double *sx = calloc(4 * (m ? m : 1), sizeof *sx), *sm, *ss, *sr;
	double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
	double rlo = INFINITY, rhi = -INFINITY;
	int rc = 0;

	if (idx == NULL || sx == NULL) {
		free(idx);
		free(sx);
		return -1;
	}
	sm = sx + m;
	ss = sm + m;
	sr = ss + m;
	for (size_t k = 0; k < m; k++)
		idx[k] = k;
	order(idx, x, m);
	for (size_t k = 0; k < m; k++) {
		sx[k] = x[idx[k]];
		sm[k] = ym[idx[k]];
		ss[k] = ys[idx[k]];
		sr[k] = ys[idx[k]] - ym[idx[k]];
	}
	(void)xt;
	(void)xu;
	/* the fitted line under the measured dots, which stay in sight */
	rc |= plot_series_add(top, "fitted", sx, ss, m, 1, 1, 0);
	rc |= plot_series_add(top, "measured", sx, sm, m, 0, 0, 1);
	rc |= plot_series_add(bot, "", sx, sr, m, 0, 0, 1);
	extent2(sx, NULL, m, &xlo, &xhi);
	extent2(sm, ss, m, &ylo, &yhi);
	extent2(sr, NULL, m, &rlo, &rhi);
	if (rlo > 0)
		rlo = 0;    /* the zero line shows */
	if (rhi < 0)
		rhi = 0;
	top->xa.whole = bot->xa.whole = xwhole;
	if (xwhole) {
		xlo -= 0.5;
		xhi += 0.5;
	}
	plot_axis_fit(&top->xa, xlo, xhi, xu, xwhole, 5);
	plot_axis_fit(&bot->xa, xlo, xhi, xu, xwhole, 5);
	plot_axis_fit(&top->ya, ylo, yhi, yu, 0, 4);
	plot_axis_fit(&bot->ya, rlo, rhi, yu, 0, 3);
	top->xlabels = 0;
	{
		double zx[2] = { bot->xa.lo, bot->xa.hi }, zy[2] = { 0, 0 };

		rc |= plot_series_add(bot, "", zx, zy, 2, 6, 1, 0);
	}
	free(idx);
	free(sx);
	(void)f;
	return rc != 0 ? -1 : 0;
}

int
plot_build_fit(struct plot_figure *f, const struct hb_fit_result *r,
               const struct hb_fit_data *d, double w, double h, char *msg, size_t n)
{
	static const char *const label[HB_FIT_OBS_COUNT] = { "t_e", "e", "x_c^r", "t_d" };
	static const char *const unit[HB_FIT_OBS_COUNT] = { "s", "", "m", "s" };
	size_t np = r->npoints;
	double *x = malloc(3 * (np ? np : 1) * sizeof *x), *ym, *ys;
	int obs[HB_FIT_OBS_COUNT], nobs = 0, rc = 0;

	if (x == NULL) {
		cnum_snprintf(msg, n, "out of memory");
		return -1;
	}
	ym = x + np;
	ys = ym + np;
	for (int ob = 0; ob < HB_FIT_OBS_COUNT; ob++)
		for (size_t k = 0; k < np; k++)
			if (r->point[k].obs == ob) {
				obs[nobs++] = ob;
				break;
			}
	if (nobs == 0) {
		free(x);
		cnum_snprintf(msg, n, "the fit has no data point to draw");
		return -1;
	}
	plot_figure_init(f, w, h > 0 ? h : 0.8 * w);
	f->ncols = nobs;
	/* the value panels in a row, their residuals in the row below */
	for (int c = 0; c < nobs; c++) {
		const char *yt = obs[c] == HB_FIT_OBS_TE ? "\xce\x94t_e" : label[obs[c]];

		if (d->kind == HB_FIT_SEQUENCE)
			plot_panel_add(f, "i", "", yt, unit[obs[c]]);
		else
			plot_panel_add(f, "|v_{i}|", "m/s", yt, unit[obs[c]]);
	}
	for (int c = 0; c < nobs; c++) {
		char rt[48];

		cnum_snprintf(rt, sizeof rt, "%s fit \xe2\x88\x92 data", label[obs[c]]);
		plot_panel_add(f, d->kind == HB_FIT_SEQUENCE ? "i" : "|v_{i}|",
		               d->kind == HB_FIT_SEQUENCE ? "" : "m/s", rt, unit[obs[c]]);
	}
	for (int c = 0; rc == 0 && c < nobs; c++) {
		size_t m = 0;
		double pm = 0, ps = 0;

		for (size_t k = 0; k < np; k++) {
			const struct hb_fit_point *p = &r->point[k];

			if (p->obs != obs[c])
				continue;
			if (d->kind == HB_FIT_SEQUENCE && obs[c] == HB_FIT_OBS_TE) {
				/* the interval before impact i: the restitution shows in
				 * their ratios, where t_e itself is a rising line; the
				 * residual is that of t_e, which is what is fitted */
				x[m] = (double)p->row;
				ym[m] = p->measured - pm;
				ys[m] = p->simulated - ps;
				pm = p->measured;
				ps = p->simulated;
			} else {
				x[m] = p->row < d->n && d->vi != NULL ? fabs(d->vi[p->row]) : (double)p->row;
				ym[m] = p->measured;
				ys[m] = p->simulated;
			}
			m++;
		}
		if (d->kind == HB_FIT_SEQUENCE && obs[c] == HB_FIT_OBS_TE) {
			/* residuals of t_e, not of the intervals: the bottom panel's */
			struct plot_panel *top = &f->p[c], *bot = &f->p[nobs + c];
			double *rm = malloc(2 * (m ? m : 1) * sizeof *rm), *rs;
			size_t j = 0;

			if (rm == NULL) {
				rc = -1;
				break;
			}
			rs = rm + m;
			for (size_t k = 0; k < np; k++)
				if (r->point[k].obs == obs[c]) {
					rm[j] = r->point[k].measured;
					rs[j++] = r->point[k].simulated;
				}
			rc = add_pair(f, top, bot, "i", "", "s", 1, x, ym, ys, m);
			if (rc == 0) {
				/* replace the residual series by t_e's own */
				double lo = 0, hi = 0;

				for (size_t k = 0; k < m; k++) {
					bot->s[0].y[k] = rs[k] - rm[k];
					lo = fmin(lo, bot->s[0].y[k]);
					hi = fmax(hi, bot->s[0].y[k]);
				}
				plot_axis_fit(&bot->ya, lo, hi, "s", 0, 3);
			}
			free(rm);
		} else {
			rc = add_pair(f, &f->p[c], &f->p[nobs + c], "",
			              d->kind == HB_FIT_SEQUENCE ? "" : "m/s", unit[obs[c]],
			              d->kind == HB_FIT_SEQUENCE, x, ym, ys, m);
		}
	}
	free(x);
	if (rc != 0) {
		plot_figure_free(f);
		cnum_snprintf(msg, n, "out of memory");
		return -1;
	}
	plot_legend_add(f, "measured", 0, 0, 1);
	plot_legend_add(f, "fitted", 1, 1, 0);
	if (h <= 0 && nobs > 1)
		f->h = 0.8 * w * 0.75;
	return 0;
}

int
plot_write_fit(struct plot_out *o, const struct hb_outputs *pol, const struct hb_fit_result *r,
               const struct hb_fit_data *d, char *msg, size_t n)
{
	struct plot_figure *fig = plot_out_figure(o, msg, n);

	if (fig == NULL)
		return -1;
	return plot_out_finish(o, pol, fig, plot_build_fit(fig, r, d, 252, -1, msg, n), msg, n);
}
