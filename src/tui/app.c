/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * app.c - the explorer's loop: key (with a timeout) -> action -> a bounded
 * slice of computation -> playback -> one frame.
 *
 * The simulation computes ahead of the display: every frame calls
 * hb_sim_advance(sim, 0, budget) with a budget of a few milliseconds, so the
 * screen never freezes however long or stiff a run is.  Playback
 * (playback.c) moves the cursor in simulated time.  Keys are dispatched
 * through the action table (actions.c).
 *
 * Errors from the engine go to the message line; nothing computed is lost
 * by a refused edit or a failed export.  The terminal is restored on every
 * way out, and a signal ends the program with 128 + its number.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "app.h"
#include "status.h"
#include "term.h"
#include "tui.h"
#include "plot_summary.h"

#define DEFAULT_PRESET "steel-on-bitumen"
#define FRAME_MS 20           /* frame period while computing or playing */
#define IDLE_MS 250           /* getch timeout when idle (to see signals) */
#define COMPUTE_BUDGET 0.012  /* s of computation per frame */

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
		if (coll_at_cursor(a) >= 0)
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
		if (sweep_view_open(a))
			pane_sweep_draw(a);
		if (a->overlay == OV_HELP)
			pane_help_draw(a);
		else if (a->overlay == OV_LOG)
			pane_log_draw(a);
		else if (a->overlay == OV_LAW || a->overlay == OV_PRESET)
			pickers_draw(a);
		else if (a->overlay == OV_FIT)
			fitov_draw(a);
	}
	a->frames++;
	refresh();
}

static int
loop(struct app *a)
{
	int ch, busy = 1;

	while (!a->quit) {
		if (term_signalled())
			return 128 + term_signalled();
		/*
		 * While the current run computes, keys are only polled: the frame
		 * is its budget of computing plus the drawing (a few hundred
		 * microseconds, plot_summary.c), so the explorer computes at about
		 * the batch rate; otherwise a frame every FRAME_MS.
		 */
		timeout(!busy ? IDLE_MS : hb_sim_end(a->sim) == HB_SIM_RUNNING ? 0 : FRAME_MS);
		ch = getch();
		if (ch != ERR)
			app_key(a, ch);
		if (a->quit)
			break;
		busy = app_tick(a);
		app_draw(a);
	}
	return a->exit_status;
}

int
app_run(const struct app_options *o, char *msg, size_t n)
{
	struct app *a;
	struct hb_sim *s;
	char path[512];
	int status;

	if (n > 0)
		msg[0] = 0;
	/* bad input first: a bad preset or --set is reported alike with or without a terminal */
	s = load_sim(o->preset ? o->preset : DEFAULT_PRESET, o->sets, o->nsets, path,
	             sizeof path, msg, n);
	if (s == NULL)
		return 2;
	a = calloc(1, sizeof *a);
	if (a == NULL) {
		hb_sim_free(s);
		snprintf(msg, n, "out of memory");
		return 1;
	}
	a->opt = o;
	a->budget = COMPUTE_BUDGET;
	a->psum = psum_new();   /* NULL: the plots draw every sample */
	app_adopt(a, s, path);
	a->playing = 1;
	a->slowmo = 1;
	a->focus = FOCUS_TABLE;

	/*
	 * Every input of the command line (preset and --set above, --data here,
	 * --script as it is played) before a terminal is required: bad input is
	 * reported as such, with or without a terminal.
	 */
	if (o->data != NULL && fitov_load(a, o->data, msg, n) != 0) {
		status = 2;
	} else if (o->script != NULL) {
		status = script_run(a, o->script, msg, n);
	} else if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
		snprintf(msg, n, "the explorer needs a terminal: standard %s is not one; expected a "
		         "terminal there, or --batch PRESET for a report, or --script FILE to play keys "
		         "without a terminal",
		         !isatty(STDIN_FILENO) ? "input" : "output");
		status = 2;
	} else {
		if (term_begin(msg, n) != 0) { /* an unknown TERM is bad input */
			status = 2;
			goto done;
		}
		a->braille = term_utf8() && !o->ascii;
		a->colour = term_colour();
		term_mouse(1);
		app_relayout(a);
		app_msg(a, 0, "%s: %s   (? or F1 for help)", a->preset, hb_sim_scene(a->sim)->name);
		if (fitov_loaded(a))
			fitov_announce(a);   /* --data: what was read (a recording says so) */
		status = loop(a);
		term_end();
		if (term_signalled()) {
			snprintf(msg, n, "stopped by signal %d", term_signalled());
			status = 128 + term_signalled();
		}
	}
done:
	psum_free(a->psum);
	fitov_free(a);
	errbar_free(a);
	sweep_view_free(a);
	physics_forget(a);
	pins_clear(a);
	hb_sim_free(a->sim);
	log_free(a);
	free(a->presets);
	free(a);
	return status;
}
