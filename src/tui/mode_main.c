/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * mode_main.c - the explorer itself: the mode at the bottom of the stack
 * (mode.h), its key table and the few actions that are the loop's own.
 *
 * Each key's function lives with the state it changes: nav.c (cursor,
 * selection), playback.c (playing, views), edit.c (the what-if loop),
 * runs.c (pins, presets, export), and the file of the mode it opens
 * (mode_help.c, mode_log.c, sweep_view.c, mode_present.c ...).  The help,
 * the footer, the man page's list and the README's table are printed from
 * this table (keys.c).
 */
#include <curses.h>
#include <stdio.h>

#include "keys.h"
#include "mode.h"
#include "spacetime.h"
#include "tui.h"

#define CTRL(c) ((c) & 0x1f)

static void act_quit(struct app *a) { a->quit = 1; }
static void act_help(struct app *a) { mode_push(a, &mode_help); }
static void act_redraw(struct app *a) { clear(); app_relayout(a); }

static const struct mode_key keys[] = {
	{ '?', KEY_F(1), CTX_ANY, act_help, "? F1", "show this help (its title says how to scroll and close it)", "help" },
	{ 'q', KEY_F(10), CTX_ANY, act_quit, "q F10", "quit, restoring the terminal", "quit" },
	{ ' ', 0, CTX_ANY, act_play, "space", "play / pause the cursor (the run computes ahead either way)", "play" },
	{ '.', 0, CTX_ANY, act_step_fwd, ".", "step the cursor one sample forward (pauses)", NULL },
	{ ',', 0, CTX_ANY, act_step_back, ",", "step the cursor one sample back (pauses)", NULL },
	{ '[', 0, CTX_ANY, act_prev_jump, "[", "cursor to the previous jump", NULL },
	{ ']', 0, CTX_ANY, act_next_jump, "]", "cursor to the next jump", NULL },
	{ '{', 0, CTX_NOT_PARAMS, act_prev_coll, "{", "cursor to the previous collision (selects its row)", NULL },
	{ '}', 0, CTX_NOT_PARAMS, act_next_coll, "}", "cursor to the next collision (selects its row)", NULL },
	{ '{', 0, CTX_PARAMS, act_prev_section, "{", "(parameter panel) the previous section", NULL },
	{ '}', 0, CTX_PARAMS, act_next_section, "}", "(parameter panel) the next section", NULL },
	{ KEY_LEFT, 'h', CTX_ANY, act_scrub_back, "Left h", "scrub the cursor back in time (1/100 of the view)", NULL },
	{ KEY_RIGHT, 'l', CTX_ANY, act_scrub_fwd, "Right l", "scrub the cursor forward in time", NULL },
	{ KEY_HOME, 'g', CTX_NOT_PARAMS, act_home, "Home g", "cursor to t = 0", NULL },
	{ KEY_END, 'G', CTX_NOT_PARAMS, act_end, "End G", "cursor to the last computed sample", NULL },
	{ KEY_HOME, 'g', CTX_PARAMS, act_top, "Home g", "(parameter panel) the first row", NULL },
	{ KEY_END, 'G', CTX_PARAMS, act_bottom, "End G", "(parameter panel) the last row", NULL },
	{ '+', '=', CTX_NOT_PARAMS, act_faster, "+ =", "faster playback (1-2-5 steps)", NULL },
	{ '-', '_', CTX_NOT_PARAMS, act_slower, "- _", "slower playback", NULL },
	{ 's', 0, CTX_ANY, act_slowmo, "s", "slow motion through contacts on / off", NULL },
	{ 'v', 0, CTX_ANY, act_view, "v", "next view: whole run, follow, zoom, loop, (t, j)", "view" },
	{ 'z', 0, CTX_ANY, act_zoom, "z", "zoom on the collision at the cursor (or the selected row)", NULL },
	{ 'y', 0, CTX_ANY, act_loop, "y", "hysteresis loop F_c against x_c of that collision", NULL },
	{ 'J', 0, CTX_ANY, act_jview, "J", "the arc against the jump counter j", NULL },
	{ 'V', 0, CTX_ANY, act_spacetime, "V",
	  "space-time view on / off: every body's position against t, # at each contact of each interface, the cursor's time", NULL },
	{ 'K', 0, CTX_ANY, act_iface, "K",
	  "a chain's next interface k for the plots (x, x_c, F_c of k; k= in the status line), then each interval's own", NULL },
	{ 'B', 0, CTX_ANY, act_body, "B",
	  "the next body for the plots (its position y and velocity u; b= in the status line, 1 the lowest), then the run's own", NULL },
	{ 'i', 0, CTX_ANY, act_table_iface, "i",
	  "a chain's collisions table: interface k's alone (k=K heads its column), each i the next k, then every interface's again", NULL },
	{ '\t', 0, CTX_ANY, act_focus, "Tab", "switch the focus: collisions table / parameter panel", "params" },
	{ KEY_UP, 'k', CTX_ANY, act_up, "Up k", "previous row of the focused table", NULL },
	{ KEY_DOWN, 'j', CTX_ANY, act_down, "Down j", "next row of the focused table", NULL },
	{ KEY_PPAGE, 0, CTX_ANY, act_pgup, "PgUp", "a page up in the focused table", NULL },
	{ KEY_NPAGE, 0, CTX_ANY, act_pgdn, "PgDn", "a page down in the focused table", NULL },
	{ '/', 0, CTX_ANY, act_search, "/",
	  "search the parameters by name, parameters before derived values (focuses the panel)", "search" },
	{ 'n', 0, CTX_ANY, act_search_next, "n", "the next match of the last search", NULL },
	{ 'N', 0, CTX_ANY, act_search_prev, "N", "the previous match of the last search", NULL },
	{ '\n', KEY_ENTER, CTX_ANY, act_enter, "Enter",
	  "collisions: zoom on the row and move the cursor there; parameters: type a new value", "edit" },
	{ '+', '=', CTX_PARAMS, act_nudge_up, "+ =", "(parameter panel) multiply the value by 1.1, or take the next choice", NULL },
	{ '-', '_', CTX_PARAMS, act_nudge_down, "- _", "(parameter panel) divide the value by 1.1, or take the previous choice", NULL },
	{ 'u', 0, CTX_ANY, act_undo, "u",
	  "undo the last edit (a value or the law): the scene before it runs again, as after an edit", NULL },
	{ 'a', 0, CTX_ANY, act_add, "a",
	  "a chain: add a key of one body or interface the panel does not list (body.I.R, initial.body.I.v, interface.K.law ...), then its value", NULL },
	{ 'U', 0, CTX_PARAMS, act_reset, "U",
	  "(parameter panel) reset the selected value to the scene as opened (the preset and its --set)", NULL },
	{ 'b', 0, CTX_ANY, act_branch, "b",
	  "branch here: the next edit continues the run from the cursor instead of restarting it (an export records the branch)", NULL },
	{ 'L', 0, CTX_ANY, act_law, "L", "choose the contact law", "law" },
	{ 'o', 0, CTX_ANY, act_preset, "o", "open a preset", NULL },
	{ 'r', 0, CTX_ANY, act_restart, "r", "restart the run from t = 0", NULL },
	{ 'p', 0, CTX_ANY, act_pin, "p", "pin the run to compare with (up to 3); edits then change a copy", "pin" },
	{ 'P', 0, CTX_ANY, act_unpin, "P", "clear the pinned runs", NULL },
	{ 'c', 0, CTX_ANY, act_compare, "c", "table: differences against pinned run 1, 2, 3, off", NULL },
	{ '3', 0, CTX_ANY, act_study3, "3",
	  "the paper's third study: permanent-contact-shccl, -bwshccl, -bwmcl pinned together", NULL },
	{ 'E', 0, CTX_ANY, act_errbar, "E",
	  "error bars on / off: a second run at rtol / 100, between frames once the run has ended; "
	  "+- under the selected collision and in the readout", NULL },
	{ 'e', 0, CTX_ANY, act_export, "e", "export BASE-trace.csv, BASE-collisions.csv and the scene BASE.preset", "export" },
	{ 'f', 0, CTX_ANY, act_figure, "f",
	  "save the view as a figure, PRESET-view.png (the plots as shown, the pins, the cursor, or the space-time view while V shows it; -2, -3 ... never over an earlier one)", NULL },
	{ 'S', 0, CTX_ANY, act_sweep, "S",
	  "sweep view: the selected parameter over a range against e, v_i, x_c^r, collisions or t_pc, computed in the background; m in it maps two keys", NULL },
	{ 'm', 0, CTX_ANY, act_log, "m", "the message log: every message, whole", "log" },
	{ 'T', 0, CTX_ANY, act_present, "T",
	  "presentation: no table, large plots with thick lines and held scales, each contact formed in slow motion, looping; T again: the light theme, then off", NULL },
	{ 'D', 0, CTX_ANY, act_data, "D",
	  "open measured data or a recording (as hybounce fit --data): impacts as o on the x plot and in the table; a recording's envelope on a rec strip", NULL },
	{ 'M', 0, CTX_ANY, act_data_table, "M", "every data point: measured against simulated now", NULL },
	{ 'F', 0, CTX_ANY, act_fit, "F",
	  "fit free keys to the data, one iteration a frame (F again stops); the start is pinned", NULL },
	{ CTRL('l'), 0, CTX_ANY, act_redraw, "C-l", "redraw the screen", NULL },
};

/* The mouse, or a key bound to nothing. */
static void
main_other(struct app *a, int ch)
{
	char name[32];

	if (ch == KEY_MOUSE) {
		mouse_event(a);
		return;
	}
	app_msg(a, 1, "unknown key %s: ? (or F1) for help", keys_name(ch, name, sizeof name));
}

static int
main_context(const struct app *a)
{
	return a->focus == FOCUS_PARAMS ? CTX_PARAMS : CTX_NOT_PARAMS;
}

const struct mode mode_main = {
	.name = "explorer",
	.title = "the explorer",
	.keys = MODE_KEYS(keys),
	.other = main_other,
	.context = main_context,
};
