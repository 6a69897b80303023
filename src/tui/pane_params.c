/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_params.c - the parameter panel: hb_scene_key rows grouped by section
 * (bodies, derived, law, loads, initial, run) under headings; derived rows
 * are read-only (dim).  Drawing only, plus the pure row list.
 */
#include <curses.h>
#include <stdio.h>
#include <string.h>

#include "scene.h"
#include "tui.h"

/*
 * The panel's rows: a heading (key = -1) before each new section, then the
 * hb_scene_key indices of that section in the engine's order.  Returns the
 * number of rows (at most max).
 */
int
params_rows(const struct hb_scene *sc, struct param_row *rows, int max)
{
	int n = 0, nk = hb_scene_nkeys(sc);
	char last[16] = "";

	for (int i = 0; i < nk && n < max; i++) {
		struct hb_scene_keyinfo ki;
		if (hb_scene_key(sc, i, &ki) != 0)
			continue;
		if (strcmp(ki.section, last) != 0) {
			snprintf(last, sizeof last, "%s", ki.section);
			rows[n].key = -1;
			snprintf(rows[n].section, sizeof rows[n].section, "%s", ki.section);
			if (++n >= max)
				break;
		}
		rows[n].key = i;
		snprintf(rows[n].section, sizeof rows[n].section, "%s", ki.section);
		n++;
	}
	return n;
}

void
pane_params_draw(const struct app *a)
{
	const struct rect *r = &a->L.params;
	const struct hb_scene *sc = hb_sim_scene(a->sim);
	struct param_row rows[256];
	int n = params_rows(sc, rows, 256), top, i, h = r->h - 1;
	int focused = a->focus == FOCUS_PARAMS, sel = a->param_sel;
	char line[256], head[256];
	int lw = r->w >= 60 ? 16 : 14;

	if (r->h < 2)
		return;
	{
		struct hb_scene_keyinfo ks;
		if (sel >= 0 && sel < n && rows[sel].key >= 0 && hb_scene_key(sc, rows[sel].key, &ks) == 0)
			snprintf(head, sizeof head, "parameters %s %s: %s", focused ? "(Enter edits, +/- nudge)"
			         : "(Tab to edit)", ks.key, ks.help);
		else
			snprintf(head, sizeof head, "parameters (%s)", sc->law->name);
	}
	tui_puts(r->y, r->x, r->w, head, A_BOLD | (focused ? A_UNDERLINE : 0));
	top = layout_scroll(a->param_top, sel, h, n);
	for (i = top; i < n && i < top + h; i++) {
		int y = r->y + 1 + i - top, attr = 0;
		if (rows[i].key < 0) {
			snprintf(line, sizeof line, "-- %s --", rows[i].section);
			tui_puts(y, r->x, r->w, line, A_BOLD);
			continue;
		}
		struct hb_scene_keyinfo ki;
		if (hb_scene_key(sc, rows[i].key, &ki) != 0)
			continue;
		snprintf(line, sizeof line, "  %-*.*s %-18s %s", lw, lw, ki.label, ki.value,
		         r->w >= 70 ? ki.range : "");
		if (ki.readonly)
			attr |= A_DIM;
		if (i == sel)
			attr |= focused ? A_REVERSE : A_BOLD;
		tui_puts(y, r->x, r->w, line, attr);
	}
}
