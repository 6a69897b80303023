/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pick_preset.c - the preset picker (o): its mode and key table; the list itself is
 * pickers.c's, the choice goes to the function its opener gave.
 */
#include <curses.h>

#include "mode.h"
#include "tui.h"

static const struct mode_key keys[] = {
	{ KEY_UP, 'k', CTX_ANY, pick_up, "Up k", "the previous entry", NULL },
	{ KEY_DOWN, 'j', CTX_ANY, pick_down, "Down j", "the next entry", NULL },
	{ KEY_PPAGE, 0, CTX_ANY, pick_pgup, "PgUp", "a page up", NULL },
	{ KEY_NPAGE, 0, CTX_ANY, pick_pgdn, "PgDn", "a page down", NULL },
	{ KEY_HOME, 'g', CTX_ANY, pick_home, "Home g", "the first entry", NULL },
	{ KEY_END, 'G', CTX_ANY, pick_end, "End G", "the last entry", NULL },
	{ '\n', KEY_ENTER, CTX_ANY, pick_choose, "Enter", "open the preset selected (the pins are kept)", "opens" },
	{ 27, 'q', CTX_ANY, pick_close, "Esc q", "close, choosing nothing", "closes" },
};

const struct mode mode_preset = {
	.name = "preset",
	.title = "the preset picker",
	.opener = "o",
	.keys = MODE_KEYS(keys),
	.draw = pickers_draw,
};
