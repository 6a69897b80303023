/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pickers.c - the law picker (hb_law_list: name, title, description,
 * parameters) and the preset picker (hb_preset_list: the *.preset files of presets/ and
 * $HYBOUNCE_PRESETS, with descriptions), drawn as a box over the plots:
 * the list and its moves, for the two modes (pick_law.c, pick_preset.c)
 * whose tables bind them.
 */
#include <curses.h>
#include <stdio.h>
#include <string.h>

#include "keys.h"
#include "law.h"
#include "mode.h"
#include "tui.h"

static int
count(const struct app *a)
{
	int n = 0;

	if (a->pick_kind == PICK_PRESET)
		return a->npresets;
	while (hb_law_list()[n])
		n++;
	return n;
}

/* The selected entry whole: name and title, description, then path or parameters. */
static void
details(const struct app *a, char *out, size_t n)
{
	int sel = a->pick_sel;

	out[0] = 0;
	if (sel < 0 || sel >= count(a))
		return;
	if (a->pick_kind == PICK_PRESET) {
		const struct hb_preset_info *p = &a->presets[sel];
		snprintf(out, n, "%s: %s. %s (%s)", p->name, p->title, p->description, p->path);
	} else {
		const struct hb_law_type *l = hb_law_list()[sel];
		size_t len;
		snprintf(out, n, "%s: %s. %s n_z = %d; parameters:", l->name, l->title, l->description, l->n_z);
		for (int k = 0; k < l->n_params; k++) {
			len = strlen(out);
			snprintf(out + len, n - len, " %s", l->params[k].name);
		}
	}
}

/*
 * The box's geometry: h rows from y0 = 1, w columns; inside,
 * the list's rows, a blank row, then the selected entry's details wrapped
 * (at most half the inside, a cut ending in the mark).
 */
static void
geometry(const struct app *a, int *h, int *w, int *list, int *drows)
{
	char d[2048];
	int in;

	*h = a->L.lines - 4;   /* as the help and the log: over the plots and the bottom pane */
	if (*h < 8)
		*h = a->L.plots.h + 1;
	*w = a->L.cols - 6;
	if (*w > 110)
		*w = 110;
	in = *h - 2;
	details(a, d, sizeof d);
	*drows = tui_wrap_rows(d, *w - 3);
	if (*drows > in / 2)
		*drows = in / 2;
	if (*drows < 1)
		*drows = 1;
	*list = in - 1 - *drows;
	if (*list < 1)
		*list = 1;
}

/* Rows of the picker's list (as pickers_draw lays it out). */
static int
page(const struct app *a)
{
	int h, w, list, drows;

	geometry(a, &h, &w, &list, &drows);
	return list;
}

void pick_up(struct app *a) { if (a->pick_sel > 0) a->pick_sel--; }
void pick_down(struct app *a) { if (a->pick_sel + 1 < count(a)) a->pick_sel++; }
void pick_home(struct app *a) { a->pick_sel = 0; }
void pick_end(struct app *a) { a->pick_sel = count(a) - 1; }
void pick_close(struct app *a) { mode_pop(a); }

void
pick_pgup(struct app *a)
{
	a->pick_sel -= page(a);
	if (a->pick_sel < 0)
		a->pick_sel = 0;
}

void
pick_pgdn(struct app *a)
{
	int n = count(a);

	a->pick_sel += page(a);
	if (a->pick_sel >= n)
		a->pick_sel = n - 1;
}

void
pick_choose(struct app *a)
{
	int n = count(a);
	char name[512];

	mode_pop(a);
	if (a->pick_sel < 0 || a->pick_sel >= n || a->pick_done == NULL)
		return;
	/* the opener's function takes the choice: the picker calls no mode by name */
	snprintf(name, sizeof name, "%s", a->pick_kind == PICK_PRESET ? a->presets[a->pick_sel].path
	                                                            : hb_law_list()[a->pick_sel]->name);
	a->pick_done(a, name);
}

void
pickers_draw(const struct app *a, const struct mode *self)
{
	int n = count(a), h, w, rows, drows, x0 = 3, y0 = 1, top = 0, i;
	char line[512], d[2048];

	geometry(a, &h, &w, &rows, &drows);
	if (a->pick_sel >= rows)
		top = a->pick_sel - rows + 1;
	{
		char title[160], hint[120];
		snprintf(title, sizeof title, " %s (%s) ", a->pick_kind == PICK_PRESET ? "open a preset" : "contact law",
		         keys_hint(self, CTX_ANY, hint, sizeof hint));
		box_draw(y0, x0, h, w, title);
	}
	/* the text inside the border; a cut entry is whole in the details below */
	x0++;
	w -= 2;
	for (i = top; i < n && i < top + rows; i++) {
		int attr = i == a->pick_sel ? A_REVERSE : 0;
		if (a->pick_kind == PICK_PRESET)
			snprintf(line, sizeof line, " %-28s %s", a->presets[i].name, a->presets[i].title);
		else
			snprintf(line, sizeof line, " %-10s %s%s", hb_law_list()[i]->name, hb_law_list()[i]->title,
			         hb_law_list()[i] == hb_sim_scene(a->sim)->law ? "  (current)" : "");
		tui_puts(y0 + 1 + i - top, x0, w, line, attr);
	}
	/* the selected entry whole, wrapped on the last rows of the box */
	details(a, d, sizeof d);
	tui_wrap_draw(y0 + h - 1 - drows, x0 + 1, w - 1, drows, d, A_DIM);
}
