/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pick_law.c - the law picker (L): its mode and key table; the list itself is
 * pickers.c's, the choice goes to the function its opener gave.
 */
#include <curses.h>

#include "mode.h"
#include "tui.h"

static const struct mode_key keys[] = {
	PICK_KEYS("use the law selected (the run restarts, as after an edit)", "chooses"),
};

const struct mode mode_law = {
	.name = "law",
	.title = "the law picker",
	.opener = "L",
	.keys = MODE_KEYS(keys),
	.draw = pickers_draw,
};
