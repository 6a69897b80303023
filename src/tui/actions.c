/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * actions.c - the dispatcher: a key from getch (or a script) goes to the
 * mode on top of the stack (mode.h), which looks it up in its own key
 * table.  What is here applies in every mode: a new size lays the screen
 * out again, and a terminal too small takes only q and F10.
 */
#include <curses.h>

#include "mode.h"
#include "tui.h"

void
app_key(struct app *a, int ch)
{
	if (ch == KEY_RESIZE) {
		app_relayout(a);
		return;
	}
	if (a->L.too_small) {
		if (ch == 'q' || ch == KEY_F(10))
			a->quit = 1;
		return;
	}
	mode_key(a, ch);
}
