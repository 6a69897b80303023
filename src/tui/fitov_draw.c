/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fitov_draw.c - what the explorer draws of the measured data
 * (overlay_fit.c loads them and fits): the o marks on the x plot, the
 * measured t_e beside each collision in the table, and the box (M) of
 * every data point measured against simulated.  Read only: it calls no
 * mode and no pane (tests/cli/calls.sh).
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "canvas.h"
#include "fitov.h"
#include "keys.h"
#include "units.h"

int
fitov_loaded(const struct app *a)
{
	return a->fitov != NULL && a->fitov->loaded;
}

/* Formats a value of observable ob with its unit. */
static char *
fmt_obs(int ob, double v, char *buf, size_t n)
{
	if (!isfinite(v))
		snprintf(buf, n, "-");
	else if (ob == HB_FIT_OBS_E)
		snprintf(buf, n, "%.4f", v);
	else
		hb_units_format(v, ob == HB_FIT_OBS_XCR || ob == HB_FIT_OBS_H ? hb_unit_length : hb_unit_time,
		                4, buf, n);
	return buf;
}

void
fitov_describe(const struct fitov *f, char *buf, size_t n)
{
	if (f->rec.nenv > 0) {
		char du[32];

		hb_units_format(f->rec.duration, hb_unit_time, 3, du, sizeof du);
		snprintf(buf, n, "%.200s: a recording (%.0f Hz, %s), %zu impacts (o) of %zu clicks", f->path,
		         f->rec.samplerate, du, f->d.n, f->rec.n + f->rec.ndrop);
	} else if (f->d.kind == HB_FIT_SEQUENCE && f->d.ntrials > 1)
		snprintf(buf, n, "%.200s: %zu bouncing sequences (trials), %zu points", f->path,
		         f->d.ntrials, f->np);
	else if (f->d.kind == HB_FIT_SEQUENCE)
		snprintf(buf, n, "%.200s: one bouncing sequence, %zu impacts", f->path, f->d.n);
	else if (f->d.kind == HB_FIT_HEIGHTS)
		snprintf(buf, n, "%.200s: %zu drops with their rebound heights, %zu points", f->path,
		         f->d.ntrials, f->np);
	else
		snprintf(buf, n, "%.200s: %zu separate drops, %zu points", f->path, f->d.n, f->np);
}

/* ---- drawing ------------------------------------------------------------ */

/* The run's first collision time, to align the measured clock; -1: none yet. */
double
fitov_first_te(const struct app *a)
{
	struct hb_collision live;
	const struct hb_collision *c = app_ncollisions(a) > 0 ? app_collision(a, 0, &live) : NULL;

	return c != NULL ? c->te : -1;
}

/*
 * The run's time of the impact at which the data's clock is aligned: the
 * first trial's first given impact (its index in the sequence); -1: none.
 */
static double
align_te(const struct app *a)
{
	const struct fitov *f = a->fitov;
	struct hb_collision live;
	const struct hb_collision *c;

	if (f->first < 0 || f->first >= app_ncollisions(a))
		return -1;
	c = app_collision(a, f->first, &live);
	return c != NULL ? c->te : -1;
}

/* The measured t_e of impact i of the first trial, since its first given impact (NAN: missed). */
static double
first_trial_te(const struct fitov *f, long i)
{
	const struct hb_fit_data *d = &f->d;
	size_t r = d->trial_row[0];

	if (f->first < 0 || i < 0 || (size_t)i >= d->trial_row[1] - r)
		return NAN;
	return d->col[HB_FIT_OBS_TE][r + (size_t)i] - d->col[HB_FIT_OBS_TE][r + (size_t)f->first];
}

void
fitov_plot_marks(const struct app *a, struct canvas *c, int q_is_x, double t0, double t1)
{
	const struct fitov *f = a->fitov;
	double te0;
	int row;

	if (f == NULL || !f->loaded || f->d.kind != HB_FIT_SEQUENCE || !q_is_x || a->view == VIEW_J
	    || (te0 = align_te(a)) < 0)
		return;
	row = (int)floor(canvas_pyf(c, 0) + 0.5);
	row = c->braille ? row / 4 : row;
	if (row >= c->h)
		row = c->h - 1;
	if (row < 0)
		row = 0;
	/* the first trial's impacts (every trial runs from the same start) */
	for (long i = 0; (size_t)i < f->d.trial_row[1] - f->d.trial_row[0]; i++) {
		double t = te0 + first_trial_te(f, i);
		int col = t >= t0 && t <= t1 ? canvas_col(c, t) : -1;
		if (col >= 0)
			canvas_mark(c, col, row, 'o', 1);
	}
}

void
fitov_table_note(const struct app *a, long i, char *line, size_t n)
{
	const struct fitov *f = a->fitov;
	double te0, tm, te;
	char b1[32], b2[32], note[80];
	size_t l = strlen(line);
	struct hb_collision live;
	const struct hb_collision *c;

	if (f == NULL || !f->loaded || f->d.kind != HB_FIT_SEQUENCE)
		return;
	if (i < 0) {
		snprintf(line + l, n - l, "  %-24s",
		         f->d.ntrials > 1 ? "trial 1 t_e (sim - data)" : "data t_e (sim - data)");
		return;
	}
	tm = first_trial_te(f, i); /* since the first given impact; NAN: missed */
	if (isnan(tm) || (te0 = align_te(a)) < 0 || (c = app_collision(a, i, &live)) == NULL)
		return;
	te = c->te - te0;
	hb_units_format(te0 + tm, hb_unit_time, 5, b1, sizeof b1);
	hb_units_format(te - tm, hb_unit_time, 2, b2, sizeof b2);
	snprintf(note, sizeof note, "%s (%s%s)", b1, te - tm >= 0 ? "+" : "", b2);
	snprintf(line + l, n - l, "  %-24s", note);
}

void
fitov_draw(const struct app *a, const struct mode *self)
{
	const struct fitov *f = a->fitov;
	int h = a->L.lines - 4, w = a->L.cols - 6, y;
	struct rect in;
	char line[512], what[320], m[32], s[32], dlt[32];


	if (f == NULL || h < 6 || w < 40)
		return;
	if (w > 96)
		w = 96;
	fitov_describe(f, what, sizeof what);
	in = box_draw(2, (a->L.cols - w) / 2, h, w, " measured against simulated (M) ");
	y = in.y;
	tui_puts(y++, in.x, in.w, what, A_BOLD);
	if (f->sim_err[0])
		tui_puts(y++, in.x, in.w, f->sim_err, A_BOLD);
	else if (f->last[0])
		tui_puts(y++, in.x, in.w, f->last, 0);
	/* a recording: the clicks not taken as impacts, and why (x on the rec strip) */
	for (size_t k = 0; k < f->rec.ndrop && k < 3 && y < in.y + in.h - 4; k++) {
		hb_units_format(f->rec.drop[k].t, hb_unit_time, 5, m, sizeof m);
		snprintf(line, sizeof line, "dropped (x) at %s of the recording: %s", m, f->rec.drop[k].why);
		tui_puts(y++, in.x, in.w, line, A_DIM);
	}
	if (f->rec.ndrop > 3 && y < in.y + in.h - 4) {
		snprintf(line, sizeof line, "... and %zu more clicks dropped", f->rec.ndrop - 3);
		tui_puts(y++, in.x, in.w, line, A_DIM);
	}
	/* the fit's points: missed values left out, each trial told apart */
	snprintf(line, sizeof line, "%5s %5s %-8s %12s %12s %12s", "row", "trial", "obs",
	         f->d.kind == HB_FIT_SEQUENCE ? "data t-t0" : "data", "simulated", "sim - data");
	tui_puts(y++, in.x, in.w, line, A_UNDERLINE);
	for (int k = f->top; k < (int)f->np && y < in.y + in.h - 1; k++) {
		const struct hb_fit_point *p = &f->pt[k];
		char trial[16], obs[24];

		fmt_obs(p->obs, p->measured, m, sizeof m);
		fmt_obs(p->obs, f->sim_valid ? f->sim[k] : NAN, s, sizeof s);
		fmt_obs(p->obs, f->sim_valid ? f->sim[k] - p->measured : NAN, dlt, sizeof dlt);
		if (f->d.kind == HB_FIT_DROPS)
			snprintf(trial, sizeof trial, "-");
		else
			snprintf(trial, sizeof trial, "%zu", p->trial + 1);
		if (p->obs == HB_FIT_OBS_H)
			snprintf(obs, sizeof obs, "h_%zu", p->index);
		else if (p->obs == HB_FIT_OBS_TE)
			snprintf(obs, sizeof obs, "t_e %zu", p->index);
		else
			snprintf(obs, sizeof obs, "%s", hb_fit_obs_name(p->obs));
		snprintf(line, sizeof line, "%5zu %5s %-8s %12s %12s %12s", p->row, trial, obs, m, s, dlt);
		tui_puts(y++, in.x, in.w, line, 0);
	}
	tui_puts(in.y + in.h - 1, in.x, in.w, keys_hint(self, CTX_ANY, line, sizeof line), A_DIM);
}
