/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * mode_log.c - the message log (m): every message, whole, wrapped to the
 * screen, oldest first; it opens at the newest.  Up/Down, PgUp/PgDn
 * scroll; any other key closes it.
 */
#include <curses.h>
#include <stdio.h>

#include "keys.h"
#include "mode.h"
#include "tui.h"

static int
log_lines(const struct app *a, int w, textov_out *out, void *ctx)
{
	int total = 0;

	for (int i = 0; i < a->log_n; i++)
		total += tui_wrap(log_get(a, i), w, 2, out, ctx);
	if (a->log_n == 0)
		total += tui_wrap("(no messages yet)", w, 0, out, ctx);
	return total;
}

static void log_enter(struct app *a) { a->log_top = -1; }   /* the end: the newest messages */
static void log_down(struct app *a) { textov_scroll(a, log_lines, &a->log_top, 1); }
static void log_up(struct app *a) { textov_scroll(a, log_lines, &a->log_top, -1); }
static void log_pgdn(struct app *a) { textov_scroll(a, log_lines, &a->log_top, textov_page(a) - 1); }
static void log_pgup(struct app *a) { textov_scroll(a, log_lines, &a->log_top, -(textov_page(a) - 1)); }

static void
log_other(struct app *a, int ch)
{
	if (ch == KEY_MOUSE)
		textov_wheel(a, log_lines, &a->log_top);
	else
		mode_pop(a);
}

static void
log_draw(const struct app *a, const struct mode *self)
{
	char title[160], hint[120];

	snprintf(title, sizeof title, " messages, oldest first (%s) ",
	         keys_hint(self, CTX_ANY, hint, sizeof hint));
	textov_draw(a, title, log_lines, a->log_top);
}

void
act_log(struct app *a)
{
	mode_push(a, &mode_log);
}

static const struct mode_key keys[] = {
	{ KEY_UP, 'k', CTX_ANY, log_up, "Up k", "scroll up a line (to older messages)", "scroll" },
	{ KEY_DOWN, 'j', CTX_ANY, log_down, "Down j", "scroll down a line", "scroll" },
	{ KEY_PPAGE, 0, CTX_ANY, log_pgup, "PgUp", "scroll up a page", "scroll" },
	{ KEY_NPAGE, ' ', CTX_ANY, log_pgdn, "PgDn space", "scroll down a page", "scroll" },
};

const struct mode mode_log = {
	.name = "log",
	.title = "the message log",
	.opener = "m",
	.keys = MODE_KEYS(keys),
	.other_help = "closes the log (the mouse wheel scrolls it)",
	.other_hint = "closes",
	.other = log_other,
	.draw = log_draw,
	.enter = log_enter,
};
