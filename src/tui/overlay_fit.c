/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * overlay_fit.c - measured data over the explorer's scene, and the fit
 * started from there (issue 13, part 4).
 *
 * D (or --data FILE) opens a data file of `hybounce fit` (fit.h): a
 * bouncing sequence (t_e) or separate drops (v_i, e, x_c_r, t_d), or a
 * recording of a bouncing sequence (read by content, hb_fit_data_open),
 * whose onsets are the sequence.  A recording also gets a strip under the
 * plots on their t axis: its envelope, the impacts kept (o) and the clicks
 * dropped (x), and the run's impacts (+) (fitov_plot_recording).  The
 * data's observables are simulated for the current scene whenever it
 * changes (hb_fit_simulate), and shown
 *  - on the x plot: each measured impact of the first trial as 'o' on the
 *    axis x = 0, the clocks aligned at its first given impact (sequences);
 *  - in the collisions table: the first trial's measured t_e of each
 *    collision beside the simulated one, and their difference (sequences);
 *  - in a box (M, mode_fit.c): every data point as the fit takes it (hb_fit_data_points:
 *    missed values left out, trials and heights told apart), measured
 *    against simulated now, with the difference, for every kind of data.
 * F asks for the free keys and runs the fit one trust-region iteration per
 * frame (hb_fit_new / hb_fit_iterate), with a progress line; F again stops it.
 * When it stops, the run before the fit is pinned (when a pin is free) and
 * the current run takes the fitted values, so measured, start and fit are
 * drawn together.  What the panes draw of the data (read only) is
 * fitov_draw.c's.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "canvas.h"
#include "fit.h"
#include "onset.h"
#include "status.h"
#include "term.h"
#include "tui.h"
#include "units.h"
#include "fitov.h"


static prompt_fn fitov_prompt_done;

static struct fitov *
ov_get(struct app *a)
{
	if (a->fitov == NULL) {
		a->fitov = calloc(1, sizeof *a->fitov);
		if (a->fitov == NULL)
			term_oom();
	}
	return a->fitov;
}

static void
points_free(struct fitov *f)
{
	free(f->pt);
	free(f->sim);
	f->pt = NULL;
	f->sim = NULL;
	f->np = 0;
	f->first = -1;
	f->sim_valid = 0;
}

void
fitov_free(struct app *a)
{
	struct fitov *f = a->fitov;

	if (f == NULL)
		return;
	hb_fit_free(f->fit);
	points_free(f);
	hb_fit_data_free(&f->d);
	hb_onset_result_free(&f->rec);
	free(f);
	a->fitov = NULL;
}

/*
 * The data points as the fit takes them (hb_fit_data_points: missed values
 * left out, trials and heights told apart), and the first trial's first
 * given impact, at which a sequence's clock is aligned with the run's.
 */
static int
points_make(struct fitov *f)
{
	const struct hb_fit_data *d = &f->d;
	size_t n = hb_fit_npoints(d);

	f->pt = calloc(n ? n : 1, sizeof *f->pt);
	f->sim = calloc(n ? n : 1, sizeof *f->sim);
	if (!f->pt || !f->sim)
		return -1;
	f->np = hb_fit_data_points(d, f->pt);
	f->first = -1;
	if (d->kind == HB_FIT_SEQUENCE && d->ntrials > 0)
		for (size_t i = d->trial_row[0]; i < d->trial_row[1] && f->first < 0; i++)
			if (!isnan(d->col[HB_FIT_OBS_TE][i]))
				f->first = (long)(i - d->trial_row[0]);
	return 0;
}

int
fitov_load(struct app *a, const char *path, char *msg, size_t n)
{
	struct fitov *f = ov_get(a);
	struct hb_fit_data d;
	struct hb_onset_result on;

	if (f->fit != NULL) {
		snprintf(msg, n, "a fit is running (F stops it); the data stay %s", f->path);
		return -1;
	}
	/* the one loader (fit.h): a CSV file, or a recording read by content with its onsets */
	if (hb_fit_data_open(path, NULL, &d, &on, msg, n) != HB_OK) {
		hb_onset_result_free(&on);
		return -1;
	}
	points_free(f);
	hb_fit_data_free(&f->d);
	hb_onset_result_free(&f->rec);
	f->rec = on;
	f->d = d;
	f->loaded = 1;
	f->top = 0;
	f->last[0] = 0;
	snprintf(f->path, sizeof f->path, "%s", path);
	if (points_make(f) != 0)
		term_oom();
	return 0;
}

/* Data file from the prompt (D) or --data. */
static void
load_from_prompt(struct app *a, const char *path)
{
	char emsg[512];

	if (path[0] == 0) {
		app_msg(a, 1, "no data file given (D asks again)");
		return;
	}
	if (fitov_load(a, path, emsg, sizeof emsg) != 0) {
		app_msg(a, 1, "data not loaded: %s", emsg);
		return;
	}
	fitov_announce(a);
}

void
fitov_announce(struct app *a)
{
	char what[320];

	fitov_describe(a->fitov, what, sizeof what);
	app_msg(a, 0, "data %s; M: measured against simulated, F: fit", what);
}

void
act_data(struct app *a)
{
	prompt_open(a, PROMPT_DATA, fitov_prompt_done, fitov_loaded(a) ? a->fitov->path : "",
	            "data file (t_e, or v_i,e[,x_c_r][,t_d] columns, or a recording; Enter opens)");
}

/*
 * The default free keys: the law's dissipation, law.c and law.alpha (what
 * a drop test determines best), those of them the law has; else its first
 * numeric key.
 */
static void
default_keys(const struct hb_scene *sc, char *buf, size_t n)
{
	static const char *const pref[] = { "law.c", "law.alpha" };
	int nk = hb_scene_nkeys(sc);

	buf[0] = 0;
	for (size_t k = 0; k < sizeof pref / sizeof pref[0]; k++) {
		struct hb_scene_keyinfo ki;
		size_t l = strlen(buf);
		if (hb_scene_get(sc, pref[k], &ki, NULL) == 0 && !ki.readonly && ki.kind == HB_SCENE_KEY_NUMBER)
			snprintf(buf + l, n - l, "%s%s", l ? "," : "", pref[k]);
	}
	for (int i = 0; i < nk && buf[0] == 0; i++) {
		struct hb_scene_keyinfo ki;
		if (hb_scene_key(sc, i, &ki) == 0 && !ki.readonly && ki.kind == HB_SCENE_KEY_NUMBER
		    && strcmp(ki.section, "law") == 0)
			snprintf(buf, n, "%s", ki.key);
	}
}

static void
progress_msg(struct app *a)
{
	const struct fitov *f = a->fitov;

	/* the progress line is not logged: only the outcome is */
	snprintf(a->msg, sizeof a->msg,
	         "fit %s: iteration %d, cost %.6g (start %.6g), %ld runs   F stops", f->keys_text,
	         f->iter, f->cost, f->cost0, f->runs);
	a->msg_error = 0;
}

static void
on_progress(void *ctx, int iter, double cost, long runs)
{
	struct fitov *f = ctx;

	f->iter = iter;
	f->cost = cost;
	f->runs = runs;
}

/* The fit stopped (or was stopped): the current run takes the best values. */
static void
fit_finish(struct app *a, int stopped)
{
	struct fitov *f = a->fitov;
	struct hb_fit_result r;
	char emsg[512], line[512], v[48], s[48];
	int restarted = 0, st;
	size_t l;

	memset(&r, 0, sizeof r);
	st = hb_fit_result_get(f->fit, &r, emsg, sizeof emsg);
	hb_fit_free(f->fit);
	f->fit = NULL;
	if (st != HB_OK) {
		app_msg(a, 1, "fit failed: %s", emsg);
		hb_fit_result_free(&r);
		return;
	}
	if (a->npins < APP_MAX_PINS)
		act_pin(a); /* the start stays drawn, pinned */
	if (hb_sim_set_scene(a->sim, &r.fitted, &restarted, emsg, sizeof emsg) != HB_OK
	    || (!restarted && hb_sim_restart(a->sim) != HB_OK)) {
		app_msg(a, 1, "fit done but its scene was refused: %s", emsg);
		hb_fit_result_free(&r);
		return;
	}
	app_label_runs(a);
	a->branch_t = -1;
	a->nbranches = 0;
	cursor_set(a, 0);
	a->playing = 1;
	snprintf(line, sizeof line, "fit %s after %d iterations, %ld runs, cost %.4g -> %.4g:",
	         stopped ? "stopped by F" : hb_fit_reason_str(r.reason), r.iter, r.runs, r.cost0,
	         r.cost);
	for (int k = 0; k < r.np; k++) {
		struct hb_scene_keyinfo ki;
		struct hb_unit_dim dim = hb_unit_none;
		if (hb_scene_get(&r.fitted, r.key[k], &ki, NULL) == 0 && ki.kind == HB_SCENE_KEY_NUMBER)
			dim = ki.dim;
		hb_units_format(r.value[k], dim, 5, v, sizeof v);
		if (isfinite(r.se[k]))
			hb_units_format(r.se[k], dim, 2, s, sizeof s);
		else
			snprintf(s, sizeof s, "? (not identifiable)");
		l = strlen(line);
		snprintf(line + l, sizeof line - l, " %s = %s +- %s%s", r.key[k], v, s,
		         k + 1 < r.np ? "," : "");
	}
	if (r.unident[0]) {
		l = strlen(line);
		snprintf(line + l, sizeof line - l, " (%s not identifiable from these data)", r.unident);
	}
	snprintf(f->last, sizeof f->last, "last fit: %s, cost %.4g -> %.4g",
	         stopped ? "stopped by F" : hb_fit_reason_str(r.reason), r.cost0, r.cost);
	app_msg(a, r.reason == HB_FIT_FAILED, "%s", line);
	hb_fit_result_free(&r);
}

static void
fit_start(struct app *a, const char *text)
{
	struct fitov *f = a->fitov;
	struct hb_fit_options o;
	char emsg[512], *p, *tok;

	snprintf(f->keys_text, sizeof f->keys_text, "%s", text);
	snprintf(f->keys_buf, sizeof f->keys_buf, "%s", text);
	f->nkeys = 0;
	for (tok = strtok_r(f->keys_buf, ", ", &p); tok; tok = strtok_r(NULL, ", ", &p)) {
		if (f->nkeys == HB_FIT_MAX_FREE) {
			app_msg(a, 1, "fit: at most %d free keys", HB_FIT_MAX_FREE);
			return;
		}
		f->keys[f->nkeys++] = tok;
	}
	if (f->nkeys == 0) {
		app_msg(a, 1, "fit: no free key given (e.g. law.c,law.alpha)");
		return;
	}
	memset(&o, 0, sizeof o);
	o.keys = f->keys;
	o.nkeys = f->nkeys;
	o.progress = on_progress;
	o.ctx = f;
	f->iter = 0;
	f->runs = 0;
	f->cost = f->cost0 = NAN;
	f->fit = hb_fit_new(hb_sim_scene(a->sim), &f->d, &o, emsg, sizeof emsg);
	if (f->fit == NULL) {
		app_msg(a, 1, "fit not started: %s", emsg);
		return;
	}
	{
		struct hb_fit_result r;
		memset(&r, 0, sizeof r);
		if (hb_fit_result_get(f->fit, &r, emsg, sizeof emsg) == HB_OK) {
			f->cost = f->cost0 = r.cost0;
			f->runs = r.runs;
		}
		hb_fit_result_free(&r);
	}
	app_msg(a, 0, "fit %s to %s started", f->keys_text, f->path);
	progress_msg(a);
}

void
act_fit(struct app *a)
{
	struct fitov *f = a->fitov;
	char def[256];

	if (!fitov_loaded(a)) {
		app_msg(a, 1, "no data to fit: D opens a data file (or start with --data FILE)");
		return;
	}
	if (f->fit != NULL) {
		fit_finish(a, 1);
		return;
	}
	if (f->keys_text[0])
		snprintf(def, sizeof def, "%s", f->keys_text);
	else
		default_keys(hb_sim_scene(a->sim), def, sizeof def);
	prompt_open(a, PROMPT_FIT, fitov_prompt_done, def, "fit to %.40s: free keys (KEY,KEY...; Enter starts)",
	            f->path);
}

/* The data and fit prompts' report: Enter loads the file or starts the fit. */
static void
fitov_prompt_done(struct app *a, const char *text, int how)
{
	if (how != PROMPT_ENTER)
		return;
	if (a->prompt_kind == PROMPT_DATA)
		load_from_prompt(a, text);
	else if (fitov_loaded(a))
		fit_start(a, text);
}

int
fitov_tick(struct app *a)
{
	struct fitov *f = a->fitov;
	const struct hb_scene *sc;
	char emsg[256];

	if (f == NULL || !f->loaded)
		return 0;
	if (f->fit != NULL) {
		if (hb_fit_iterate(f->fit))
			fit_finish(a, 0);
		else
			progress_msg(a);
		return 1;
	}
	sc = hb_sim_scene(a->sim);
	if (f->sim_valid && memcmp(&f->for_scene, sc, sizeof *sc) == 0)
		return 0;
	f->for_scene = *sc;
	f->sim_valid = 1;
	f->sim_err[0] = 0;
	if (hb_fit_simulate(sc, &f->d, 0, f->sim, emsg, sizeof emsg) != HB_OK) {
		snprintf(f->sim_err, sizeof f->sim_err, "%s", emsg);
		for (size_t k = 0; k < f->np; k++)
			if (!isfinite(f->sim[k]))
				f->sim[k] = NAN;
	}
	return 0;
}
