/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * overlay_rec.c - a recording opened with D or --data, on the plots' t
 * axis: a strip under the plots with the recording's envelope, the clicks
 * taken as impacts ('o', the sequence the fit uses) and those dropped
 * ('x', with their reasons in the M box), and the run's own impacts ('+'),
 * the clocks aligned at the first impact.  When the scene fits, each '+'
 * stands under its 'o'.
 */
#include <math.h>

#include "canvas.h"
#include "fitov.h"

int
fitov_recording(const struct app *a)
{
	return a->fitov != NULL && a->fitov->loaded && a->fitov->rec.nenv > 0 &&
	       a->fitov->d.kind == HB_FIT_SEQUENCE && a->fitov->d.n > 0;
}

/* The loudest block of the envelope, for the strip's scale. */
double
fitov_recording_peak(const struct app *a)
{
	const struct hb_onset_result *r = &a->fitov->rec;
	float m = 0;

	for (size_t k = 0; k < r->nenv; k++)
		m = r->env[k] > m ? r->env[k] : m;
	return m > 0 ? m : 1;
}

/*
 * The recording's strip on the plots' t axis (the clocks aligned at the
 * first impact, as the 'o' on the x plot): the envelope filled from 0, each
 * impact kept as 'o' and each click dropped as 'x' on the top row, and the
 * run's impacts (t_e of its collisions) as '+' on the row below, so that
 * measured and simulated impacts line up when the scene fits.
 */
void
fitov_plot_recording(const struct app *a, struct canvas *c, double t0, double t1)
{
	const struct fitov *f = a->fitov;
	const struct hb_onset_result *r = &f->rec;
	double te0 = fitov_first_te(a), off, dt;
	struct hb_collision live;

	if (te0 < 0 || !(t1 > t0))
		return;
	off = te0 - f->d.col[HB_FIT_OBS_TE][0];   /* run time = recording time + off */
	dt = (t1 - t0) / (c->pw > 1 ? c->pw - 1 : 1);
	for (int px = 0; px < c->pw; px++) {
		double t = t0 + px * dt, ta = t - 0.5 * dt - off, tb = t + 0.5 * dt - off;
		long b0 = (long)floor(ta / r->env_dt), b1 = (long)floor(tb / r->env_dt);
		float m = 0;

		if (b1 < 0 || b0 >= (long)r->nenv)
			continue;
		b0 = b0 < 0 ? 0 : b0;
		b1 = b1 >= (long)r->nenv ? (long)r->nenv - 1 : b1;
		for (long b = b0; b <= b1; b++)
			m = r->env[b] > m ? r->env[b] : m;
		if (m > 0)
			canvas_line(c, t, 0, t, m, 1);
	}
	for (size_t k = 0; k < r->ndrop; k++) {
		double t = r->drop[k].t + off;

		if (t >= t0 && t <= t1)
			canvas_mark(c, canvas_col(c, t), 0, 'x', 2);
	}
	for (size_t k = 0; k < f->d.n; k++) {
		double t = f->d.col[HB_FIT_OBS_TE][k] + off;

		if (t >= t0 && t <= t1)
			canvas_mark(c, canvas_col(c, t), 0, 'o', 3);
	}
	for (long i = 0, n = app_ncollisions(a); i < n; i++) {
		const struct hb_collision *col = app_collision(a, i, &live);

		if (col != NULL && col->te >= t0 && col->te <= t1)
			canvas_mark(c, canvas_col(c, col->te), c->h > 1 ? 1 : 0, '+', 1);
	}
}

