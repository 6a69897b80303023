/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * frame.c - one frame of the explorer: a bounded slice of computation
 * (the run, the pinned runs, the fit, the error bars, the sweep), playback,
 * then the drawing of every pane and overlay.  The loop (app.c) and a
 * script (script.c) both play frames; a frame calls the modes and the
 * panes, never the loop (tests/cli/calls.sh).
 */
#include <curses.h>
#include <math.h>
#include <time.h>

#include "spacetime.h"
#include "status.h"
#include "mode.h"
#include "tui.h"

static double
now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* After an edit restarted the run: the cursor returns to its time once computed. */
static void
cursor_follow_want(struct app *a)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	const struct hb_arc_sample *l = hb_arc_last(arc);

	if (a->want_t < 0 || l == NULL)
		return;
	if (l->t >= a->want_t || hb_sim_end(a->sim) != HB_SIM_RUNNING) {
		/* the sample nearest to that time */
		size_t i = hb_arc_find_t(arc, a->want_t);
		if (i + 1 < hb_arc_len(arc)
		    && fabs(hb_arc_at(arc, i + 1)->t - a->want_t) < fabs(hb_arc_at(arc, i)->t - a->want_t))
			i++;
		a->cursor = i;
		a->tcur = hb_arc_at(arc, i)->t;
		a->want_t = -1;
		if (coll_at_cursor(a) >= 0 && table_shows(a, coll_at_cursor(a)))
			a->table_sel = coll_at_cursor(a);
	} else {
		a->cursor = hb_arc_len(arc) - 1;
		a->tcur = a->want_t;
	}
}

int
app_tick(struct app *a)
{
	double t = now_s(), dt = a->tick_last > 0 ? t - a->tick_last : 0;
	int busy = 0, rc;

	a->tick_last = t;
	if (dt > 0.25)
		dt = 0.25;
	if (hb_sim_end(a->sim) == HB_SIM_RUNNING) {
		physics_forget(a);
		rc = hb_sim_advance(a->sim, 0, a->budget);
		if (rc != HB_OK && rc != HB_EDONE) {
			app_msg(a, 1, "run failed: %s (everything before is kept)", hb_sim_errmsg(a->sim));
		} else if (hb_sim_end(a->sim) != HB_SIM_RUNNING && hb_sim_stats(a->sim)->stiff) {
			char note[160];

			app_msg(a, 0, "run computed%s", stiff_note(a, note, sizeof note));
		}
		if (hb_sim_end(a->sim) != HB_SIM_RUNNING)
			physics_run(a);
		busy = 1;
	}
	for (int i = 0; i < a->npins; i++)
		if (hb_sim_end(a->pin[i].sim) == HB_SIM_RUNNING) {
			hb_sim_advance(a->pin[i].sim, 0, a->budget / 4);
			busy = 1;
		}
	if (fitov_tick(a))
		busy = 1;
	if (errbar_tick(a))
		busy = 1;
	cursor_clamp(a);
	cursor_follow_want(a);
	if (playback_tick(a, dt))
		busy = 1;
	if (sweep_view_tick(a))
		busy = 1;
	if (spacetime_tick(a))
		busy = 1;
	return busy;
}

void
app_draw(struct app *a)
{
	erase();
	if (a->L.too_small) {
		pane_too_small_draw(a);
	} else {
		pane_plot_draw(a);
		if (a->L.table_visible)
			pane_table_draw(a);
		if (a->L.params_visible)
			pane_params_draw(a);
		pane_status_draw(a);
		mode_draw(a);   /* the modes open over the explorer, bottom first */
	}
	a->frames++;
	refresh();
}
