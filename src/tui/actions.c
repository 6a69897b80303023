/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * actions.c - what each action of the key table does: one function per
 * action (as htop's Action functions), found by the action's number.
 *
 * keys.c maps a key to an action (the table that also prints the help,
 * the footer, the man page and the README list); this file maps the
 * action to its function; app_key() is the whole dispatcher.  The
 * functions live with the state they change: nav.c (cursor, selection),
 * playback.c (playing, views), edit.c (the what-if loop), runs.c (pins,
 * presets, export), log.c (messages), app.c (the loop).
 */
#include <curses.h>
#include <stdio.h>

#include "keys.h"
#include "spacetime.h"
#include "tui.h"

static void act_quit(struct app *a) { a->quit = 1; }
static void act_help(struct app *a) { a->overlay = OV_HELP; a->help_top = 0; }
static void act_redraw(struct app *a) { clear(); app_relayout(a); }

static action_fn *const actions[ACT_COUNT] = {
	[ACT_QUIT] = act_quit, [ACT_HELP] = act_help, [ACT_PLAY] = act_play,
	[ACT_STEP_FWD] = act_step_fwd, [ACT_STEP_BACK] = act_step_back,
	[ACT_PREV_JUMP] = act_prev_jump, [ACT_NEXT_JUMP] = act_next_jump,
	[ACT_PREV_COLL] = act_prev_coll, [ACT_NEXT_COLL] = act_next_coll,
	[ACT_SCRUB_BACK] = act_scrub_back, [ACT_SCRUB_FWD] = act_scrub_fwd,
	[ACT_HOME] = act_home, [ACT_END] = act_end,
	[ACT_FASTER] = act_faster, [ACT_SLOWER] = act_slower, [ACT_SLOWMO] = act_slowmo,
	[ACT_VIEW] = act_view, [ACT_ZOOM] = act_zoom, [ACT_LOOP] = act_loop, [ACT_JVIEW] = act_jview,
	[ACT_FOCUS] = act_focus, [ACT_UP] = act_up, [ACT_DOWN] = act_down,
	[ACT_PGUP] = act_pgup, [ACT_PGDN] = act_pgdn, [ACT_ENTER] = act_enter,
	[ACT_NUDGE_UP] = act_nudge_up, [ACT_NUDGE_DOWN] = act_nudge_down,
	[ACT_LAW] = act_law, [ACT_PRESET] = act_preset, [ACT_RESTART] = act_restart,
	[ACT_PIN] = act_pin, [ACT_UNPIN] = act_unpin, [ACT_STUDY3] = act_study3,
	[ACT_EXPORT] = act_export, [ACT_REDRAW] = act_redraw,
	[ACT_BRANCH] = act_branch, [ACT_SEARCH] = act_search,
	[ACT_TOP] = act_top, [ACT_BOTTOM] = act_bottom,
	[ACT_PREV_SECTION] = act_prev_section, [ACT_NEXT_SECTION] = act_next_section,
	[ACT_LOG] = act_log, [ACT_PRESENT] = act_present, [ACT_COMPARE] = act_compare,
	[ACT_DATA] = act_data, [ACT_DATA_TABLE] = act_data_table, [ACT_FIT] = act_fit, [ACT_ERRBAR] = act_errbar,
	[ACT_SWEEP] = act_sweep,
	[ACT_SEARCH_NEXT] = act_search_next, [ACT_SEARCH_PREV] = act_search_prev,
	[ACT_UNDO] = act_undo, [ACT_RESET] = act_reset,
	[ACT_FIGURE] = act_figure,
	[ACT_SPACETIME] = act_spacetime, [ACT_IFACE] = act_iface,
};

action_fn *
action_get(int act)
{
	if (act <= ACT_NONE || act >= ACT_COUNT)
		return NULL;
	return actions[act];
}

void
app_key(struct app *a, int ch)
{
	action_fn *f;
	int act;

	if (ch == KEY_RESIZE) {
		app_relayout(a);
		return;
	}
	if (a->L.too_small) {
		if (ch == 'q' || ch == KEY_F(10))
			a->quit = 1;
		return;
	}
	switch (a->overlay) {
	case OV_PROMPT:
		prompt_key(a, ch);
		return;
	case OV_LAW:
	case OV_PRESET:
		pickers_key(a, ch);
		return;
	case OV_HELP:
	case OV_LOG:
		overlay_key(a, ch);
		return;
	case OV_FIT:
		fitov_key(a, ch);
		return;
	default:
		break;
	}
	if (sweep_view_open(a)) {
		sweep_view_key(a, ch);
		return;
	}
	if (ch == KEY_MOUSE) {
		mouse_event(a);
		return;
	}
	act = keys_action(ch, a->focus == FOCUS_PARAMS);
	f = action_get(act);
	if (f == NULL) {
		char name[32];
		app_msg(a, 1, "unknown key %s: ? (or F1) for help", keys_name(ch, name, sizeof name));
		return;
	}
	f(a);
}
