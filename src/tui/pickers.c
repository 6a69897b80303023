/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pickers.c - the law picker (hb_law_list: name, title, description,
 * parameters) and the preset picker (hb_preset_list: the *.preset files of presets/ and
 * $HYBOUNCE_PRESETS, with descriptions), drawn as a box over the plots.
 * Up/Down (k/j) move, PgUp/PgDn a page, Home/End (g/G) to the ends,
 * Enter chooses, Esc or q closes.
 */
#include <curses.h>
#include <stdio.h>
#include <string.h>

#include "law.h"
#include "tui.h"

static int
count(const struct app *a)
{
	int n = 0;

	if (a->overlay == OV_PRESET)
		return a->npresets;
	while (hb_law_list()[n])
		n++;
	return n;
}

/* Rows of the picker's list (as pickers_draw lays it out). */
static int
page(const struct app *a)
{
	int rows = a->L.plots.h + 1 - 5;

	return rows > 1 ? rows : 1;
}

void
pickers_key(struct app *a, int ch)
{
	int n = count(a), kind = a->overlay;
	char name[512];

	switch (ch) {
	case KEY_UP:
	case 'k':
		if (a->pick_sel > 0)
			a->pick_sel--;
		break;
	case KEY_DOWN:
	case 'j':
		if (a->pick_sel + 1 < n)
			a->pick_sel++;
		break;
	case KEY_PPAGE:
		a->pick_sel -= page(a);
		if (a->pick_sel < 0)
			a->pick_sel = 0;
		break;
	case KEY_NPAGE:
		a->pick_sel += page(a);
		if (a->pick_sel >= n)
			a->pick_sel = n - 1;
		break;
	case KEY_HOME:
	case 'g':
		a->pick_sel = 0;
		break;
	case KEY_END:
	case 'G':
		a->pick_sel = n - 1;
		break;
	case KEY_RESIZE:
		app_relayout(a);
		break;
	case 27:
	case 'q':
		a->overlay = OV_NONE;
		break;
	case '\n':
	case '\r':
	case KEY_ENTER:
		a->overlay = OV_NONE;
		if (a->pick_sel < 0 || a->pick_sel >= n)
			break;
		if (kind == OV_PRESET) {
			snprintf(name, sizeof name, "%s", a->presets[a->pick_sel].path);
			app_open_preset(a, name);
		} else {
			app_set_law(a, hb_law_list()[a->pick_sel]->name);
		}
		break;
	default:
		break;
	}
}

void
pickers_draw(const struct app *a)
{
	int n = count(a), w = a->L.cols - 6, h = a->L.plots.h + 1, x0 = 3, y0 = 1;
	int rows = h - 5, top = 0, i;
	char line[512];

	if (w > 110)
		w = 110;
	if (rows < 1)
		rows = 1;
	if (a->pick_sel >= rows)
		top = a->pick_sel - rows + 1;
	box_draw(y0, x0, h, w, a->overlay == OV_PRESET ? " open a preset (Enter opens, Esc closes) "
	                                               : " contact law (Enter chooses, Esc closes) ");
	/* the text inside the border */
	x0++;
	w -= 2;
	for (i = top; i < n && i < top + rows; i++) {
		int attr = i == a->pick_sel ? A_REVERSE : 0;
		if (a->overlay == OV_PRESET)
			snprintf(line, sizeof line, " %-28s %s", a->presets[i].name, a->presets[i].title);
		else
			snprintf(line, sizeof line, " %-10s %s%s", hb_law_list()[i]->name, hb_law_list()[i]->title,
			         hb_law_list()[i] == hb_sim_scene(a->sim)->law ? "  (current)" : "");
		tui_puts(y0 + 1 + i - top, x0, w, line, attr);
	}
	/* the description of the selected entry, on the last rows of the box */
	if (a->pick_sel >= 0 && a->pick_sel < n) {
		if (a->overlay == OV_PRESET) {
			snprintf(line, sizeof line, " %s", a->presets[a->pick_sel].description);
			tui_puts(y0 + h - 3, x0, w, line, A_DIM);
			snprintf(line, sizeof line, " %.500s", a->presets[a->pick_sel].path);
			tui_puts(y0 + h - 2, x0, w, line, A_DIM);
		} else {
			const struct hb_law_type *l = hb_law_list()[a->pick_sel];
			size_t len;
			snprintf(line, sizeof line, " %s", l->description);
			tui_puts(y0 + h - 3, x0, w, line, A_DIM);
			snprintf(line, sizeof line, " n_z = %d; parameters:", l->n_z);
			for (int k = 0; k < l->n_params; k++) {
				len = strlen(line);
				snprintf(line + len, sizeof line - len, " %s", l->params[k].name);
			}
			tui_puts(y0 + h - 2, x0, w, line, A_DIM);
		}
	}
}
