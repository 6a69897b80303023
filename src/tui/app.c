/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * app.c - the explorer's loop: key (with a timeout) -> action -> a bounded
 * slice of computation -> playback -> one frame.
 *
 * The simulation computes ahead of the display: every frame calls
 * hb_sim_advance(sim, 0, budget) with a budget of a few milliseconds, so the
 * screen never freezes however long or stiff a run is.  Playback
 * (playback.c) moves the cursor in simulated time.  Keys are dispatched
 * through the action table (actions.c).  One frame, its computing and
 * its drawing (app_tick, app_draw), is frame.c's, which a script
 * (script.c) plays too.
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
#include "mode.h"
#include "spacetime.h"
#include "status.h"
#include "term.h"
#include "tui.h"
#include "plot_summary.h"

#define DEFAULT_PRESET "steel-on-bitumen"
#define FRAME_MS 20           /* frame period while computing or playing */
#define IDLE_MS 250           /* getch timeout when idle (to see signals) */
#define COMPUTE_BUDGET 0.012  /* s of computation per frame */

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
	a->modes = tui_modes;        /* every mode, for the help */
	mode_push(a, &mode_main);    /* the explorer, at the bottom of the stack */
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
	spacetime_free(a);
	physics_forget(a);
	pins_clear(a);
	hb_sim_free(a->sim);
	log_free(a);
	free(a->presets);
	free(a);
	return status;
}
