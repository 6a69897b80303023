/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * mode_fit.c - the data table (M): every data point, measured against
 * simulated for the current scene (drawn by fitov_draw.c).  Up/Down,
 * PgUp/PgDn scroll; F closes it and starts the fit; any other key closes
 * it.
 */
#include <curses.h>

#include "mode.h"
#include "tui.h"
#include "fitov.h"

void
act_data_table(struct app *a)
{
	if (!fitov_loaded(a)) {
		app_msg(a, 1, "no data: D opens a data file (or start with --data FILE)");
		return;
	}
	mode_push(a, &mode_fit);
}

static void
fit_scroll(struct app *a, int d)
{
	struct fitov *f = a->fitov;

	if (d < 0)
		f->top = f->top > -d ? f->top + d : 0;
	else if (f->top + d < (int)f->np)
		f->top += d;
}

static void fit_up(struct app *a) { fit_scroll(a, -1); }
static void fit_down(struct app *a) { fit_scroll(a, 1); }
static void fit_pgup(struct app *a) { fit_scroll(a, -10); }
static void fit_pgdn(struct app *a) { fit_scroll(a, 10); }

static void
fit_start(struct app *a)
{
	mode_pop(a);
	act_fit(a);
}

static void
fit_other(struct app *a, int ch)
{
	(void)ch;
	mode_pop(a);
}

static const struct mode_key keys[] = {
	{ KEY_UP, 'k', CTX_ANY, fit_up, "Up k", "scroll up a row", "scroll" },
	{ KEY_DOWN, 'j', CTX_ANY, fit_down, "Down j", "scroll down a row", "scroll" },
	{ KEY_PPAGE, 0, CTX_ANY, fit_pgup, "PgUp", "scroll up 10 rows", NULL },
	{ KEY_NPAGE, 0, CTX_ANY, fit_pgdn, "PgDn", "scroll down 10 rows", NULL },
	{ 'F', 0, CTX_ANY, fit_start, "F", "close the table and fit (as F in the explorer)", "fits" },
};

const struct mode mode_fit = {
	.name = "fit",
	.title = "the data table",
	.opener = "M",
	.keys = MODE_KEYS(keys),
	.other_help = "closes the table",
	.other_hint = "closes",
	.other = fit_other,
	.draw = fitov_draw,
};
