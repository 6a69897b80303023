/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_table.c - the collisions table (paper eqs. t_d .. Lambda): one row
 * per completed collision, then the contact in progress marked "live".
 * The unit of each column is chosen from its largest value (hb_units_axis)
 * and written in the header.  With compare on (c), the columns are those
 * of the comparison: each collision against the one of the same index in
 * a pinned run, with the differences (now - pinned) of t_e, e and x_c^max
 * in columns "dt_e", "de", "dx_c^max".  With i on a chain the rows are
 * those of one interface k (cursor.c: table_shows), the k column's
 * heading "k=K" and the note "collisions: 3 of 12 (k=K)"; the units are
 * chosen from the rows shown.  Drawing only.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "term.h"
#include "tui.h"
#include "columns.h"
#include "units.h"

enum { NCOL_MAX = 16 };

/* The comparison's columns: a column of columns.h, or (delta) its difference. */
static const struct {
	const char *name;
	int delta;
} compared[] = {
	{ "i", 0 }, { "t_e", 0 }, { "t_e", 1 }, { "e", 0 }, { "e", 1 },
	{ "x_c_max", 0 }, { "x_c_max", 1 }, { "F_c_max", 0 },
};

/* A chain's interface k (not in columns.h: a whole number, the chain's alone). */
static const struct hb_collision_column kcol = { "k", "k", "", "interface", 0, 0, 0 };

/*
 * The explorer's columns, from the table of columns.h, with their widths;
 * delta[k] 1 where column k is a difference against a pinned run; a
 * chain's interface k after the index, kw wide.
 */
static int
columns(int compare, int chain, int kw, const struct hb_collision_column **cols, int *width, int *delta)
{
	int n = 0;

	if (compare) {
		for (size_t k = 0; k < sizeof compared / sizeof compared[0]; k++) {
			const struct hb_collision_column *c = hb_collision_column_find(compared[k].name);
			if (c == NULL)
				continue;
			cols[n] = c;
			delta[n] = compared[k].delta;
			width[n] = c->index ? 4 : (int)(strlen(c->label) + strlen(c->unit) + 4 + delta[n]);
			if (!c->index && width[n] < 7)
				width[n] = 7;
			n++;
		}
		return n;
	}
	for (int k = 0; k < hb_collision_ncolumns && n < NCOL_MAX; k++) {
		const struct hb_collision_column *c = &hb_collision_columns[k];
		if (!(c->shown & HB_COLUMN_EXPLORER))
			continue;
		if (chain && n == 1 && n < NCOL_MAX - 1) {
			cols[n] = &kcol;
			delta[n] = 0;
			width[n++] = kw;
		}
		cols[n] = c;
		delta[n] = 0;
		/* room for " LABEL[pUNIT]", or for a ratio such as -0.01122 */
		if (c->index)
			width[n] = 4;
		else if (c->unit[0])
			width[n] = (int)(strlen(c->label) + strlen(c->unit) + 4);
		else
			width[n] = (int)strlen(c->label) + 3 > 7 ? (int)strlen(c->label) + 3 : 7;
		n++;
	}
	return n;
}

/* Collision i of a pinned run (completed ones only), or NULL. */
static const struct hb_collision *
pinned(const struct hb_sim *ps, long i)
{
	if (ps == NULL || i < 0 || (size_t)i >= hb_sim_ncollisions(ps))
		return NULL;
	return hb_sim_collision(ps, (size_t)i);
}

/* The value shown in column k: the column's, or its difference against p. */
static double
value(const struct hb_collision *c, const struct hb_collision *p, const struct hb_collision_column *col,
      int delta)
{
	if (col == &kcol)
		return delta ? NAN : (double)c->k;
	if (!delta)
		return hb_collision_value(c, col);
	if (p == NULL || (!c->complete && strcmp(col->name, "e") == 0))
		return NAN;
	return hb_collision_value(c, col) - hb_collision_value(p, col);
}

/*
 * A row wider than the pane loses whole cells, not digits.  Notes after
 * the cells (the data column, a physics note, "collisions: N") are cut
 * where the room ends, with the mark; when the cells fill the room
 * exactly, the rows keep their cells and the header ends in the cut mark
 * (its last label moved a column left into its padding).  Otherwise the row is cut at the last cell boundary
 * (ends[0..n-1], in columns) that leaves a column for the mark.  The rest
 * is read whole elsewhere: the data column in M, a physics note in the
 * log (m), every column in the exported collisions CSV.
 */
static void
fit_row(char *line, size_t size, const int *ends, int n, int w, int header)
{
	int len = (int)strlen(line), keep = 0;

	if (len <= w || w < 2 || n < 1)
		return;
	if (ends[n - 1] < w) {
		/* the notes cut where the room ends, marked (tui_puts) */
		return;
	}
	if (ends[n - 1] == w) {
		keep = ends[n - 1];
		line[keep] = 0;
		if (!header)
			return;
		/* the last label one column left, into the blank before it */
		int b = keep - 1;
		while (b > 0 && line[b] != ' ')
			b--;
		if (line[b] == ' ') {
			memmove(line + b, line + b + 1, (size_t)(keep - b - 1));
			snprintf(line + keep - 1, size - (size_t)keep + 1, "%s", tui_cut_mark());
		}
		return;
	}
	for (int k = 0; k < n; k++)
		if (ends[k] <= w - 1 && ends[k] > keep)
			keep = ends[k];
	if (keep == 0)
		keep = w - 1;
	snprintf(line + keep, size - (size_t)keep, "%*s%s", w - 1 - keep, "", tui_cut_mark());
}

/*
 * The error bars of a collision (E), in the table's columns and scales:
 * "+-" in the index column, each bar to one digit, "-" where none.
 */
static void
bars_row(const struct hb_collision *d, const struct hb_collision_column *const *cols,
         const int *width, const double *scale, int ncol, char *line, size_t size, int *ends)
{
	char cell[64], w[80];

	line[0] = 0;
	for (int k = 0; k < ncol; k++) {
		double v = cols[k]->index || cols[k] == &kcol ? NAN : hb_collision_value(d, cols[k]);

		if (cols[k]->index)
			snprintf(cell, sizeof cell, "+-");
		else if (cols[k] == &kcol)
			snprintf(cell, sizeof cell, " ");
		else if (!isfinite(v))
			snprintf(cell, sizeof cell, "-");
		else
			snprintf(cell, sizeof cell, "%.0e", v / scale[k]);
		snprintf(w, sizeof w, "%*s", width[k], cell);
		strncat(line, w, size - strlen(line) - 1);
		ends[k] = (int)strlen(line);
	}
	strncat(line, "  error bars (E)", size - strlen(line) - 1);
}

void
pane_table_draw(const struct app *a)
{
	const struct rect *r = &a->L.table;
	long n = app_ncollisions(a), top, i, rows = r->h - 1, sel = a->table_sel, row;
	const struct hb_sim *ps = a->compare > 0 && a->compare <= a->npins ? a->pin[a->compare - 1].sim : NULL;
	const struct hb_collision_column *cols[NCOL_MAX];
	int width[NCOL_MAX], delta[NCOL_MAX], only = table_iface(a);
	char khead[16];
	int ncol, kw;
	double scale[NCOL_MAX], mag[NCOL_MAX];
	char unit[NCOL_MAX][16], line[512], cell[64];
	int ends[NCOL_MAX + 1];
	int k, focused = a->focus == FOCUS_TABLE, below = 0;
	const struct hb_collision *bars = NULL;
	struct hb_collision live;

	if (r->h < 2)
		return;
	/* the k column's heading: "k", or "k=K" while it shows interface K alone */
	snprintf(khead, sizeof khead, only >= 0 ? "k=%d" : "k", only);
	kw = (int)strlen(khead) + 1 > 4 ? (int)strlen(khead) + 1 : 4;
	ncol = columns(ps != NULL, hb_sim_scene(a->sim)->chain.n > 0, kw, cols, width, delta);
	for (k = 0; k < ncol; k++)
		mag[k] = 0;
	for (i = 0; i < n; i++) {
		const struct hb_collision *c = app_collision(a, i, &live), *p = pinned(ps, i);
		if (only >= 0 && !table_shows(a, i))
			continue;
		for (k = 0; c && k < ncol; k++) {
			double v = value(c, p, cols[k], delta[k]);
			if (isfinite(v) && fabs(v) > mag[k])
				mag[k] = fabs(v);
		}
	}
	line[0] = 0;
	for (k = 0; k < ncol; k++) {
		char h[48];
		if (cols[k] == &kcol) {
			scale[k] = 1;
			snprintf(h, sizeof h, "%s", khead);
		} else if (cols[k]->unit[0]) {
			scale[k] = hb_units_axis(mag[k] > 0 ? mag[k] : 1, cols[k]->unit, unit[k], sizeof unit[k]);
			snprintf(h, sizeof h, "%s%s[%s]", delta[k] ? "d" : "", cols[k]->label, unit[k]);
		} else {
			scale[k] = 1;
			snprintf(h, sizeof h, "%s%s", delta[k] ? "d" : "", cols[k]->label);
		}
		snprintf(cell, sizeof cell, "%*s", width[k], h);
		strncat(line, cell, sizeof line - strlen(line) - 1);
		ends[k] = (int)strlen(line);
	}
	fitov_table_note(a, -1, line, sizeof line);
	if (ps)
		snprintf(cell, sizeof cell, only >= 0 ? "  vs %d, k=%d alone" : "  vs %d", a->compare, only);
	else if (only >= 0)
		snprintf(cell, sizeof cell, "  collisions: %ld of %ld (k=%d)", table_nrows(a), n, only);
	else
		snprintf(cell, sizeof cell, "  collisions: %zu%s", hb_sim_ncollisions(a->sim),
		         n > (long)hb_sim_ncollisions(a->sim) ? " + live" : "");
	strncat(line, cell, sizeof line - strlen(line) - 1);
	fit_row(line, sizeof line, ends, ncol, r->w, 1);
	tui_puts(r->y, r->x, r->w, line, A_BOLD | (focused ? A_UNDERLINE : 0));

	/* scroll so the selection is visible (and its error bars, E, under it) */
	if (sel >= n)
		sel = n - 1;
	if (sel >= 0 && !table_shows(a, sel))
		sel = -1;       /* not a row: none highlighted (the rows about where it would be) */
	if (sel >= 0 && rows > 2) {
		const struct hb_collision *c = app_collision(a, sel, &live);
		bars = c != NULL && c->complete ? errbar_find(a, c->i) : NULL;
	}
	if (bars != NULL)
		rows--;
	top = layout_scroll(a->table_top, table_row_of(a, a->table_sel < n ? a->table_sel : n - 1), rows,
	                    table_nrows(a));
	for (i = 0, row = -1; i < n; i++) {
		const struct hb_collision *c = app_collision(a, i, &live), *p = pinned(ps, i);
		int attr = 0;
		unsigned flag;
		if (c == NULL || (only >= 0 && !table_shows(a, i)))
			continue;
		if (++row < top)
			continue;
		if (row >= top + rows)
			break;
		flag = c->complete ? physics_flag(a, i) : 0;
		line[0] = 0;
		for (k = 0; k < ncol; k++) {
			double v = value(c, p, cols[k], delta[k]);
			const char *nm = cols[k]->name;
			if (cols[k]->index)
				snprintf(cell, sizeof cell, "%s%ld", coll_in_progress(a, c) ? ">" : " ", c->i);
			else if (cols[k] == &kcol)
				snprintf(cell, sizeof cell, "%d", c->k);
			else if (!c->complete && strcmp(nm, "e") == 0 && !delta[k])
				snprintf(cell, sizeof cell, "live");
			else if (!c->complete && (strcmp(nm, "x_c_r") == 0 || strcmp(nm, "Lambda") == 0))
				snprintf(cell, sizeof cell, "-");
			else if (!isfinite(v))
				snprintf(cell, sizeof cell, "-");
			else {
				/*
				 * a cell leaves a space before it: fewer digits where they
				 * would fill it; "!" after a value the law cannot give
				 * (physics.c), in its own column of the cell
				 */
				int bad = !delta[k] && ((strcmp(nm, "e") == 0 && (flag & HB_CHECK_BAD_E))
				                        || (strcmp(nm, "W") == 0 && (flag & HB_CHECK_BAD_W)));
				int room = width[k] - bad;
				snprintf(cell, sizeof cell, "%.4g", v / scale[k]);
				if ((int)strlen(cell) >= room)
					snprintf(cell, sizeof cell, "%.1e", v / scale[k]);
				if ((int)strlen(cell) >= room)
					snprintf(cell, sizeof cell, "%.0e", v / scale[k]);
				if (bad)
					strncat(cell, "!", sizeof cell - strlen(cell) - 1);
			}
			char w[64];
			snprintf(w, sizeof w, "%*s", width[k], cell);
			strncat(line, w, sizeof line - strlen(line) - 1);
			ends[k] = (int)strlen(line);
		}
		if (!c->complete)
			strncat(line, "  live (in contact)", sizeof line - strlen(line) - 1);
		else if (flag)
			strncat(line, (flag & HB_CHECK_BAD_E) && (flag & HB_CHECK_BAD_W)
			        ? "  ! e, W: impossible for the law" : (flag & HB_CHECK_BAD_E)
			        ? "  ! e: impossible for the law" : "  ! W: impossible for the law",
			        sizeof line - strlen(line) - 1);
		else
			fitov_table_note(a, i, line, sizeof line);
		if (i == sel)
			attr = focused ? A_REVERSE : A_BOLD;
		if (flag && i != sel)
			attr |= a->colour ? COLOR_PAIR(PAIR_ERROR) : A_BOLD;
		if (!c->complete && a->colour)
			attr |= COLOR_PAIR(PAIR_CONTACT);
		fit_row(line, sizeof line, ends, ncol, r->w, 0);
		tui_puts(r->y + 1 + below + (int)(row - top), r->x, r->w, line, attr);
		if (i == sel && bars != NULL) {
			bars_row(bars, cols, width, scale, ncol, line, sizeof line, ends);
			fit_row(line, sizeof line, ends, ncol, r->w, 0);
			below = 1;
			tui_puts(r->y + 1 + below + (int)(row - top), r->x, r->w, line, A_DIM);
		}
	}
	if (n == 0)
		tui_puts(r->y + 1, r->x, r->w, "  (no collision yet)", A_DIM);
	else if (row < 0 && only >= 0)
		tui_puts(r->y + 1, r->x, r->w, "  (no collision of this interface yet; i: the next)", A_DIM);
}
