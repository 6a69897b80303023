/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * mouse.c - clicks and the wheel (ncurses mouse events).  Everything here
 * is also reachable from the keyboard: a click on a table row selects that
 * collision (as Up/Down then Enter), a click in the plots moves the
 * cursor to that time (as scrubbing), the wheel scrolls the pane under it.
 */
#include <curses.h>

#include "tui.h"

/* The table row under (y): the collision index, or -1 (mirrors pane_table.c's scrolling). */
static long
table_row_at(const struct app *a, int y)
{
	const struct rect *r = &a->L.table;
	long n = table_nrows(a), rows = r->h - 1, top = table_row_of(a, a->table_sel) - rows + 1;

	if (top > n - rows)
		top = n - rows;
	if (top < 0)
		top = 0;
	if (y <= r->y || y >= r->y + r->h)
		return -1;
	if (top + (y - r->y - 1) >= n)
		return -1;
	return table_row_coll(a, top + (y - r->y - 1));
}

static int
inside(const struct rect *r, int y, int x)
{
	return r->h > 0 && y >= r->y && y < r->y + r->h && x >= r->x && x < r->x + r->w;
}

void
mouse_event(struct app *a)
{
	MEVENT ev;
	int wheel;

	if (getmouse(&ev) != OK)
		return;
	wheel = ev.bstate & BUTTON4_PRESSED ? -1 : ev.bstate & BUTTON5_PRESSED ? 1 : 0;
	if (a->L.table_visible && inside(&a->L.table, ev.y, ev.x)) {
		if (wheel) {
			a->focus = FOCUS_TABLE;
			sel_move(a, 3 * wheel);
			return;
		}
		long i = table_row_at(a, ev.y);
		if (i >= 0) {
			a->focus = FOCUS_TABLE;
			a->playing = 0;
			cursor_to_collision(a, i);
		}
	} else if (a->L.params_visible && inside(&a->L.params, ev.y, ev.x)) {
		if (a->focus != FOCUS_PARAMS) {
			a->focus = FOCUS_PARAMS;
			app_relayout(a);
		}
		if (wheel) {
			sel_move(a, 3 * wheel);
		} else if (ev.y > a->L.params.y) {
			/* rows are drawn from param_top, scrolled to keep param_sel in view */
			struct param_row rows[256];
			int n = params_rows(hb_sim_scene(a->sim), rows, 256);
			int top = layout_scroll(a->param_top, a->param_sel, a->L.params.h - 1, n);
			int row = top + ev.y - a->L.params.y - 1;
			if (row >= 0 && row < n && rows[row].key >= 0)
				a->param_sel = row;
		}
	} else if (inside(&a->L.plots, ev.y, ev.x)) {
		if (wheel) {
			if (wheel < 0)
				act_scrub_back(a);
			else
				act_scrub_fwd(a);
			return;
		}
		double t;
		if (plot_abscissa_at(a, ev.x, &t) == 0 && hb_arc_len(hb_sim_arc(a->sim)) > 0) {
			const struct hb_arc *arc = hb_sim_arc(a->sim);
			a->playing = 0;
			if (a->view == VIEW_J) {
				/* the first sample of the interval at that j */
				size_t i = 0, n = hb_arc_len(arc);
				while (i + 1 < n && (double)hb_arc_at(arc, i)->j < t - 0.5)
					i++;
				cursor_set(a, i);
			} else {
				if (t < 0)
					t = 0;
				cursor_set(a, hb_arc_find_t(arc, t));
			}
			{
				long i = coll_at_cursor(a);
				if (i >= 0 && table_shows(a, i))
					a->table_sel = i;
			}
		}
	}
}
