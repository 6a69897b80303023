/*
 * layout.h - pane geometry from the terminal size (pure; no curses).
 *
 *   row 0           status line
 *   plots           x, x_c, F_c stacked over one time axis
 *   bottom          collisions table and parameter panel: side by side when
 *                   wide (>= LAYOUT_WIDE_COLS), otherwise one of them at a
 *                   time (Tab switches)
 *   row lines-2     message / prompt line
 *   row lines-1     footer (keys)
 *
 * On wide terminals the parameter panel takes a column on the right of
 * the plots and the table instead.
 */
#ifndef HYBOUNCE_LAYOUT_H
#define HYBOUNCE_LAYOUT_H

enum {
	LAYOUT_MIN_COLS = 80,
	LAYOUT_MIN_LINES = 24,
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
	struct rect status, plots, table, params, msg, footer;
	int table_visible, params_visible;
};

/*
 * Computes the panes for a cols x lines terminal; show_params chooses the
 * bottom pane when only one fits.  Returns 0, or -1 when too small.
 */
int
layout_compute(int cols, int lines, int show_params, struct layout *L);

/*
 * Splits a plot area of h rows into n stacked plots above `extra` shared
 * rows (marker and time axis): heights into hs[0..n-1], as equal as
 * possible, the first ones taller.  Returns the rows used by the plots.
 */
int
layout_stack(int h, int n, int extra, int *hs);

#endif
