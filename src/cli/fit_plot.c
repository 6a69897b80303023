/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_plot.c - the text plot of measured against simulated values that
 * `hybounce fit` prints after the residuals: one panel per observable,
 * 'o' measured, '+' simulated at the estimates, '@' where both fall in the
 * same cell, '.' simulated at the start (under the others).  Drops are plotted against |v_i|; a bouncing sequence as its
 * intervals between impacts (the flight times) against the impact number,
 * which shows the restitution where t_e itself would be a rising line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/fit.h"
#include "fit_cmd.h"

enum { PW = 56, PH = 12 };

/* Plots n points (x[i], measured ym[i], simulated ys[i]) under a title. */
static void
panel(FILE *f, const char *title, const char *xlabel, const double *x, const double *ym,
      const double *ys, const double *y0s, size_t n)
{
	char grid[PH][PW + 1];
	double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;

	for (size_t i = 0; i < n; i++) {
		x0 = fmin(x0, x[i]);
		x1 = fmax(x1, x[i]);
		y0 = fmin(y0, fmin(ym[i], fmin(ys[i], y0s[i])));
		y1 = fmax(y1, fmax(ym[i], fmax(ys[i], y0s[i])));
	}
	if (!(x1 > x0)) {
		x0 -= 0.5;
		x1 += 0.5;
	}
	if (!(y1 > y0)) {
		double h = y0 != 0 ? fabs(y0) * 0.1 : 1;

		y0 -= h;
		y1 += h;
	}
	for (int r = 0; r < PH; r++) {
		memset(grid[r], ' ', PW);
		grid[r][PW] = '\0';
	}
	for (int pass = -1; pass < 2; pass++)
		for (size_t i = 0; i < n; i++) {
			double y = pass < 0 ? y0s[i] : pass == 0 ? ym[i] : ys[i];
			int c = (int)lround((x[i] - x0) / (x1 - x0) * (PW - 1));
			int r = PH - 1 - (int)lround((y - y0) / (y1 - y0) * (PH - 1));
			char *cell = &grid[r][c];

			if (pass < 0)
				*cell = '.';
			else if (pass == 0)
				*cell = 'o';
			else
				*cell = *cell == 'o' || *cell == '@' ? '@' : '+';
		}
	fprintf(f, "\n  %s   (o measured, + fitted, @ both, . start)\n", title);
	for (int r = 0; r < PH; r++) {
		if (r == 0 || r == PH - 1)
			fprintf(f, "  %11.4g |%s\n", r == 0 ? y1 : y0, grid[r]);
		else
			fprintf(f, "  %11s |%s\n", "", grid[r]);
	}
	fprintf(f, "  %11s +", "");
	for (int c = 0; c < PW; c++)
		fputc('-', f);
	fprintf(f, "\n  %11s %-11.4g%*s%11.4g\n", "", x0, PW - 22, "", x1);
	fprintf(f, "  %11s %*s\n", "", (PW + (int)strlen(xlabel)) / 2, xlabel);
}

void
fit_plot(FILE *f, const struct hb_fit_result *r, const struct hb_fit_data *d)
{
	size_t n = r->npoints;
	double *x = malloc(4 * (n ? n : 1) * sizeof *x), *ym, *ys, *y0s;

	if (x == NULL)
		return;
	ym = x + n;
	ys = ym + n;
	y0s = ys + n;
	if (d->kind != HB_FIT_DROPS && (d->kind == HB_FIT_HEIGHTS || d->ntrials > 1
	                                || n + 1 != d->n)) {
		/* several trials, a missed impact or heights: each point as it is */
		for (size_t k = 0; k < n; k++) {
			x[k] = (double)(k + 1);
			ym[k] = r->point[k].measured;
			ys[k] = r->point[k].simulated;
			y0s[k] = r->point[k].start;
		}
		panel(f, d->kind == HB_FIT_HEIGHTS ? "rebound height (apex) [m]"
		      : "time since the trial's first impact [s]", "point", x, ym, ys, y0s, n);
		free(x);
		return;
	}
	if (d->kind == HB_FIT_SEQUENCE) {
		for (size_t k = 0; k < n; k++) {
			x[k] = (double)(k + 1);
			ym[k] = r->point[k].measured - (k > 0 ? r->point[k - 1].measured : 0);
			ys[k] = r->point[k].simulated - (k > 0 ? r->point[k - 1].simulated : 0);
			y0s[k] = r->point[k].start - (k > 0 ? r->point[k - 1].start : 0);
		}
		panel(f, "interval before each impact [s]", "impact", x, ym, ys, y0s, n);
		free(x);
		return;
	}
	for (int ob = HB_FIT_OBS_E; ob < HB_FIT_OBS_COUNT; ob++) {
		size_t m = 0;
		char title[64];

		for (size_t k = 0; k < n; k++)
			if (r->point[k].obs == ob) {
				x[m] = fabs(d->vi[r->point[k].row]);
				ym[m] = r->point[k].measured;
				ys[m] = r->point[k].simulated;
				y0s[m] = r->point[k].start;
				m++;
			}
		if (m == 0)
			continue;
		snprintf(title, sizeof title, "%s%s", hb_fit_obs_name(ob),
		    ob == HB_FIT_OBS_E ? "" : " [SI]");
		panel(f, title, "|v_i| [m/s]", x, ym, ys, y0s, m);
	}
	free(x);
}
