/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * errbar.c - error bars in the explorer (E): each observable's global
 * error estimated as batch --error does (error.h), by a second run of the
 * scene with rk8pd at a hundredth of the tolerances.
 *
 * The second run is advanced a slice a frame, as the run itself (the
 * screen never waits for it), once the run has ended; hb_error_compare
 * then gives the bars, which stand for that scene until it changes: an
 * edit cancels a second run under way and starts another when the new
 * run has ended.  A run with what-if branches (b) gets none, as batch
 * --error refuses a preset that records them: the second run would have
 * no branches.  The table shows the bars of the selected collision in a
 * row under it ("+-"), the readout its e with as many digits as its error
 * bar allows.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "status.h"
#include "term.h"
#include "tui.h"

struct errbar {
	int on;
	struct hb_sim *t;             /* the second run under way, or NULL */
	struct hb_scene for_scene;    /* the scene whose run t, est or err are for */
	int valid;                    /* est holds the bars of for_scene's run */
	int failed;                   /* err says why for_scene's run has none */
	struct hb_error_estimate est;
	char err[256];
};

static void
forget(struct errbar *b)
{
	hb_sim_free(b->t);
	b->t = NULL;
	if (b->valid)
		hb_error_free(&b->est);
	b->valid = 0;
	b->failed = 0;
	b->err[0] = 0;
}

void
errbar_free(struct app *a)
{
	if (a->errbar == NULL)
		return;
	forget(a->errbar);
	free(a->errbar);
	a->errbar = NULL;
}

int
errbar_on(const struct app *a)
{
	return a->errbar != NULL && a->errbar->on;
}

void
act_errbar(struct app *a)
{
	if (a->errbar == NULL) {
		a->errbar = calloc(1, sizeof *a->errbar);
		if (a->errbar == NULL)
			term_oom();
	}
	a->errbar->on = !a->errbar->on;
	if (!a->errbar->on) {
		forget(a->errbar);
		app_msg(a, 0, "error bars off");
	} else if (a->nbranches > 0)
		app_msg(a, 1, "error bars: none for a run with what-if branches (b): its second run "
		        "would have none (E hides this)");
	else
		app_msg(a, 0, "error bars on: a second run with rk8pd at rtol / %g once the run has "
		        "ended, between frames (E hides them)", HB_ERROR_TIGHTEN);
}

/* The second run has ended: its bars, and a line on how large they are. */
static void
finish(struct app *a)
{
	struct errbar *b = a->errbar;
	char emsg[512];
	double worst = 0;

	if (hb_error_compare(a->sim, b->t, &b->est, emsg, sizeof emsg) != HB_OK) {
		snprintf(b->err, sizeof b->err, "%.200s", emsg);
		b->failed = 1;
		app_msg(a, 1, "error bars: %s", emsg);
	} else {
		b->valid = 1;
		if (hb_error_check(a->sim, &b->est, &worst, emsg, sizeof emsg) == HB_OK)
			app_msg(a, 0, "error bars: rk8pd at rtol %.3g%s; the largest %.2g x run.rtol, "
			        "within the %g x the check allows", b->est.rtol,
			        b->est.at_floor ? " (the floor: less sure)" : "", worst,
			        HB_ERROR_CHECK_FACTOR);
		else
			app_msg(a, 1, "error bars: %s", emsg);
	}
	hb_sim_free(b->t);
	b->t = NULL;
}

int
errbar_tick(struct app *a)
{
	struct errbar *b = a->errbar;
	const struct hb_scene *sc;
	char emsg[512];
	int rc;

	if (b == NULL || !b->on)
		return 0;
	sc = hb_sim_scene(a->sim);
	if ((b->t != NULL || b->valid || b->failed) && memcmp(&b->for_scene, sc, sizeof *sc) != 0)
		forget(b); /* an edit: the bars were another scene's */
	if (a->nbranches > 0) {
		forget(b);
		return 0;
	}
	if (b->valid || b->failed)
		return 0;
	if (b->t == NULL) {
		struct hb_scene tight;
		int at_floor;

		if (hb_sim_end(a->sim) == HB_SIM_RUNNING)
			return 0; /* the run first */
		b->for_scene = *sc;
		if (hb_sim_end(a->sim) == HB_SIM_END_FAIL) {
			snprintf(b->err, sizeof b->err, "the run failed: no error bars");
			b->failed = 1;
			return 0;
		}
		hb_error_scene(sc, &tight, &at_floor);
		b->t = hb_sim_new(&tight, emsg, sizeof emsg);
		if (b->t == NULL) {
			snprintf(b->err, sizeof b->err, "the second run was refused: %.200s", emsg);
			b->failed = 1;
			app_msg(a, 1, "error bars: %s", b->err);
			return 0;
		}
	}
	if (hb_sim_end(b->t) == HB_SIM_RUNNING) {
		rc = hb_sim_advance(b->t, 0, a->budget);
		if (rc != HB_OK && rc != HB_EDONE && hb_sim_end(b->t) == HB_SIM_RUNNING) {
			snprintf(b->err, sizeof b->err, "the second run failed: %s", hb_sim_errmsg(b->t));
			b->failed = 1;
			hb_sim_free(b->t);
			b->t = NULL;
			return 0;
		}
	}
	/* both ended (a restart of the same scene recomputes the run first) */
	if (hb_sim_end(b->t) != HB_SIM_RUNNING && hb_sim_end(a->sim) != HB_SIM_RUNNING)
		finish(a);
	return b->t != NULL && hb_sim_end(b->t) == HB_SIM_RUNNING;
}

const struct hb_collision *
errbar_find(const struct app *a, long i)
{
	const struct errbar *b = a->errbar;

	if (b == NULL || !b->on || !b->valid || a->nbranches > 0)
		return NULL;
	return hb_error_find(&b->est, i);
}

void
errbar_state(const struct app *a, char *buf, size_t n)
{
	const struct errbar *b = a->errbar;

	buf[0] = 0;
	if (b == NULL || !b->on)
		return;
	if (a->nbranches > 0)
		snprintf(buf, n, "+-: none (branches)");
	else if (b->failed)
		snprintf(buf, n, "+-: none");
	else if (!b->valid)
		snprintf(buf, n, "+-: computing");
	else
		snprintf(buf, n, "+-: rtol %.0e", b->est.rtol);
}

/* "NAME=VALUE+-ERR", the value with as many digits as its error bar allows (6 to 17). */
void
errbar_format(const char *name, double v, double err, char *buf, size_t n)
{
	int d = 6;

	if (err > 0 && isfinite(err) && v != 0 && isfinite(v))
		d = (int)floor(log10(fabs(v))) - (int)floor(log10(err)) + 1;
	d = d < 6 ? 6 : d > 17 ? 17 : d;
	if (isfinite(err))
		snprintf(buf, n, "%s=%.*g+-%.0e", name, d, v, err);
	else
		snprintf(buf, n, "%s=%.6g+-?", name, v);
}
