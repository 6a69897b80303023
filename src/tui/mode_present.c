/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * mode_present.c - presentation, for teaching (T): no table nor panel,
 * the plots take their rows, the view follows the cursor, each contact is
 * played in slow motion with the view on the contact as it forms, each
 * axis holds its scale over the run (playback.c's hold), lines are thick,
 * and the run loops.  T again: the same on the light theme (with
 * colours); T a third time restores what was before.  Every other key is
 * the explorer's (the mode passes it through).
 */
#include <curses.h>

#include "mode.h"
#include "term.h"
#include "tui.h"

static void
present_enter(struct app *a)
{
	a->present = 1;
	a->present_view = a->view;
	a->present_slowmo = a->slowmo;
	a->view = VIEW_FOLLOW;
	a->slowmo = 1;
	a->playing = 1;
	a->hold.n = 0;
	hold_update(a);
	if (hb_sim_end(a->sim) != HB_SIM_RUNNING && a->cursor + 1 >= hb_arc_len(hb_sim_arc(a->sim)))
		cursor_set(a, 0);
	app_msg(a, 0, "presentation: contacts in slow motion, looping (T: %s)",
	        a->colour ? "light theme" : "back");
	app_relayout(a);
}

static void
present_leave(struct app *a)
{
	if (a->present == 2)
		term_light(0);
	a->present = 0;
	a->view = a->present_view;
	a->slowmo = a->present_slowmo;
	app_msg(a, 0, "presentation off");
	app_relayout(a);
}

/* T in the explorer. */
void
act_present(struct app *a)
{
	mode_push(a, &mode_present);
}

/* T in presentation: the light theme (with colours), then off. */
static void
present_next(struct app *a)
{
	if (a->present == 1 && a->colour) {
		a->present = 2;
		term_light(1);
		app_msg(a, 0, "presentation on the light theme (T: back)");
		app_relayout(a);
	} else {
		mode_close(a, &mode_present);
	}
}

static const struct mode_key keys[] = {
	{ 'T', 0, CTX_ANY, present_next, "T", "the light theme (with colours), then presentation off", NULL },
};

const struct mode mode_present = {
	.name = "present",
	.title = "presentation",
	.opener = "T",
	.keys = MODE_KEYS(keys),
	.other_help = "as in the explorer",
	.passthrough = 1,
	.enter = present_enter,
	.leave = present_leave,
};
