/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pick_preset.c - the preset picker (o): its mode and key table; the list itself is
 * pickers.c's, the choice goes to the function its opener gave.
 */
#include <curses.h>

#include "mode.h"
#include "tui.h"

static const struct mode_key keys[] = {
	PICK_KEYS("open the preset selected (the pins are kept)", "opens"),
};

const struct mode mode_preset = {
	.name = "preset",
	.title = "the preset picker",
	.opener = "o",
	.keys = MODE_KEYS(keys),
	.draw = pickers_draw,
};
