/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * mode_help.c - the help (? or F1): every mode's keys, printed from their
 * tables (keys_help) in the order of the registry the app holds
 * (a->modes), the explorer's first, then the legend of the screen.
 * Opened from a mode other than the explorer, it starts at that mode's
 * list.  Up/Down, PgUp/PgDn scroll; any other key closes it.
 */
#include <curses.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "keys.h"
#include "mode.h"
#include "term.h"
#include "tui.h"

static const char *const legend[] = {
	"",
	"Status line: the preset, law, t, j, q_c, the number of collisions, the playback speed (x0.02: simulated seconds per second), slow (in slow motion), playing/paused, and computing/finished/failed for the run; \"fails N checks\" when the ended run breaks the physics checks that --batch runs (m names each check and collision; the table marks an impossible value with \"!\").",
	"Readout: the sample at the cursor (#index), its t, j, q_c, x, v, x_c, F_c and z_c, with units.",
	"Contact strip under the plots: # a contact narrower than a column, [] a contact two columns wide, [===] a longer contact from t_e to t_s, ^ the cursor.",
	"Legend: each pinned run is labelled by what differs from the current one, in its own colour and marker.",
	"Edits restart the run from t = 0 and keep the cursor's t; b makes the next edit continue from the cursor (branch here).",
	"A line that ends in an ellipsis (> without UTF-8) goes on: a message is whole in the log (m); the table's columns past the screen's edge are in the status line (coll N), M (the data) and the log (the physics notes); a picker shows its selected entry whole under its list; Enter on a parameter shows its description whole; a long prompt has its title on the rows above it; every column is in the exported CSV.",
};

/* The lines of mode m's list; returns the rows they take at width w. */
static int
mode_lines(const struct mode *m, int w, textov_out *out, void *ctx)
{
	size_t n = keys_help(m, NULL, 0) + 1;
	char *text = malloc(n), *line, *save;
	int rows = 0;

	if (text == NULL)
		term_oom();
	keys_help(m, text, n);
	for (line = strtok_r(text, "\n", &save); line; line = strtok_r(NULL, "\n", &save))
		rows += tui_wrap(line, w, line[0] == 'I' && m->opener ? 2 : 10, out, ctx);
	free(text);
	return rows;
}

/*
 * Every line of the help (out NULL: counts them).  stop: the rows before
 * that mode's list, for the help to start there (NULL: all of them).
 */
static int
help_rows(const struct app *a, int w, textov_out *out, void *ctx, const struct mode *stop)
{
	const struct mode *const *m = a->modes;
	int rows = 0;

	if (m == NULL || m[0] == NULL)
		return 0;
	rows += mode_lines(m[0], w, out, ctx);
	for (size_t i = 0; i < sizeof legend / sizeof legend[0]; i++)
		rows += tui_wrap(legend[i][0] ? legend[i] : " ", w, 2, out, ctx);
	for (size_t k = 1; m[k] != NULL; k++) {
		if (m[k] == stop)
			return rows;
		rows += tui_wrap(" ", w, 0, out, ctx);
		rows += mode_lines(m[k], w, out, ctx);
	}
	return stop != NULL ? 0 : rows;
}

static int
help_lines(const struct app *a, int w, textov_out *out, void *ctx)
{
	return help_rows(a, w, out, ctx, NULL);
}

static void
help_enter(struct app *a)
{
	const struct mode *under = a->nmodes >= 2 ? a->mode[a->nmodes - 2] : NULL;

	/*
	 * From the sweep view (say): at its keys, the blank row before them
	 * included; from the explorer, or a mode that passes its keys to it
	 * (presentation), at the top.
	 */
	a->help_top = 0;
	if (under != NULL && under->opener != NULL && !under->passthrough)
		a->help_top = help_rows(a, textov_width(a), NULL, NULL, under);
}

static void help_down(struct app *a) { textov_scroll(a, help_lines, &a->help_top, 1); }
static void help_up(struct app *a) { textov_scroll(a, help_lines, &a->help_top, -1); }
static void help_pgdn(struct app *a) { textov_scroll(a, help_lines, &a->help_top, textov_page(a) - 1); }
static void help_pgup(struct app *a) { textov_scroll(a, help_lines, &a->help_top, -(textov_page(a) - 1)); }

static void
help_other(struct app *a, int ch)
{
	if (ch == KEY_MOUSE)
		textov_wheel(a, help_lines, &a->help_top);
	else
		mode_pop(a);
}

static void
help_draw(const struct app *a, const struct mode *self)
{
	char title[160], hint[120];

	snprintf(title, sizeof title, " hybounce keys (%s) ", keys_hint(self, CTX_ANY, hint, sizeof hint));
	textov_draw(a, title, help_lines, a->help_top);
}

static const struct mode_key keys[] = {
	{ KEY_UP, 'k', CTX_ANY, help_up, "Up k", "scroll up a line", "scroll" },
	{ KEY_DOWN, 'j', CTX_ANY, help_down, "Down j", "scroll down a line", "scroll" },
	{ KEY_PPAGE, 0, CTX_ANY, help_pgup, "PgUp", "scroll up a page", "scroll" },
	{ KEY_NPAGE, ' ', CTX_ANY, help_pgdn, "PgDn space", "scroll down a page", "scroll" },
};

const struct mode mode_help = {
	.name = "help",
	.title = "the help",
	.opener = "? F1",
	.keys = MODE_KEYS(keys),
	.other_help = "closes the help (the mouse wheel scrolls it)",
	.other_hint = "closes",
	.other = help_other,
	.draw = help_draw,
	.enter = help_enter,
};
