/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * layout.h - pane geometry from the terminal size (pure; no curses).
 *
 *   row 0           status line
 *   plots           x, x_c, F_c stacked over one time axis
 *   bottom          collisions table and parameter panel: side by side when
 *                   wide (>= LAYOUT_WIDE_COLS), otherwise one of them at a
 *                   time (Tab switches)
 *   readout         the values at the cursor: rows lines-4 and lines-3
 *                   from 23 lines when narrower than LAYOUT_READOUT_COLS,
 *                   else row lines-3 (what does not fit is left out)
 *   row lines-2     message / prompt line
 *   row lines-1     footer (keys)
 *
 * On wide terminals the parameter panel takes a column on the right of
 * the plots and the table instead.  Below LAYOUT_FULL_LINES rows the
 * bottom pane shrinks (to a header and 3 rows) so the plots keep 8 rows;
 * the smallest usable terminal is LAYOUT_MIN_COLS x LAYOUT_MIN_LINES
 * (80x23, what tmux or screen leave of an 80x24 terminal, gets the full
 * layout).
 */
#ifndef HYBOUNCE_LAYOUT_H
#define HYBOUNCE_LAYOUT_H

enum {
	LAYOUT_MIN_COLS = 60,
	LAYOUT_MIN_LINES = 16,
	LAYOUT_FULL_LINES = 21,
	LAYOUT_READOUT_COLS = 120,
	LAYOUT_WIDE_COLS = 130,
	LAYOUT_PARAMS_W = 52,
};

struct rect {
	int y, x, h, w;
};

struct layout {
	int cols, lines;
	int too_small;          /* below LAYOUT_MIN_COLS x LAYOUT_MIN_LINES: nothing else is set */
	int wide;               /* table and parameters both visible */
	struct rect status, plots, table, params, readout, msg, footer;
	int table_visible, params_visible;
};

/*
 * Computes the panes for a cols x lines terminal; show_params chooses the
 * bottom pane when only one fits.  Returns 0, or -1 when too small.
 */
int
layout_compute(int cols, int lines, int show_params, struct layout *L);

/* Presentation mode: the plots take the table's and the panel's rows. */
void
layout_present(struct layout *L);

/*
 * Splits a plot area of h rows into n stacked plots above `extra` shared
 * rows (marker and time axis): heights into hs[0..n-1], as equal as
 * possible, the first ones taller.  Returns the rows used by the plots.
 */
int
layout_stack(int h, int n, int extra, int *hs);

/*
 * The first of n rows to show in a window of h rows, moved as little as
 * possible from top so that row sel is in view (0 when all n fit).
 */
int
layout_scroll(int top, int sel, int h, int n);

#endif
