/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * relayout.c - the explorer's layout from the terminal's size, the focus
 * and the presentation mode (layout.c computes it).  Every mode that
 * changes one of them calls this; it calls no mode (tests/cli/calls.sh).
 */
#include <curses.h>

#include "tui.h"

void
app_relayout(struct app *a)
{
	layout_compute(COLS, LINES, a->focus == FOCUS_PARAMS && !a->present, &a->L);
	if (a->present && !a->L.too_small)
		layout_present(&a->L);
}
