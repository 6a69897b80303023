/*
 * pane_table.c - the collisions table (paper eqs. t_d .. Lambda): one row
 * per completed collision, then the contact in progress marked "live".
 * The unit of each column is chosen from its largest value (units_axis)
 * and written in the header.  With compare on (c), the columns are those
 * of the comparison: each collision against the one of the same index in
 * a pinned run, the differences (now - pinned) of t_e, e and x_c^max.
 * Drawing only.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "term.h"
#include "tui.h"
#include "units.h"

enum { COL_I, COL_TE, COL_TD, COL_VI, COL_E, COL_XCMAX, COL_FCMAX, COL_XCR, COL_LAMBDA,
       COL_DTE, COL_DE, COL_DXC, NCOL };

static const int plain[] = { COL_I, COL_TE, COL_TD, COL_VI, COL_E, COL_XCMAX, COL_FCMAX, COL_XCR,
                             COL_LAMBDA, -1 };
static const int compared[] = { COL_I, COL_TE, COL_DTE, COL_E, COL_DE, COL_XCMAX, COL_DXC,
                                COL_FCMAX, -1 };

static const struct {
	const char *name;
	const char *base;   /* NULL: no prefix */
	int width;
} cols[NCOL] = {
	{ "i", NULL, 4 },
	{ "t_e", "s", 9 },
	{ "t_d", "s", 8 },
	{ "v_i", NULL, 10 },
	{ "e", NULL, 7 },
	{ "xc^max", "m", 11 },
	{ "Fc^max", "N", 10 },
	{ "xc^r", "m", 10 },
	{ "Lambda", NULL, 10 },
	{ "dt_e", "s", 10 },
	{ "de", NULL, 10 },
	{ "dxc^max", "m", 12 },
};

static double
colval(const struct collision *c, const struct collision *p, int k)
{
	switch (k) {
	case COL_DTE: return p ? c->te - p->te : NAN;
	case COL_DE: return p && c->complete ? c->e - p->e : NAN;
	case COL_DXC: return p ? c->xcmax - p->xcmax : NAN;
	case COL_I: return (double)c->i;
	case COL_TE: return c->te;
	case COL_TD: return c->td;
	case COL_VI: return c->vi;
	case COL_E: return c->e;
	case COL_XCMAX: return c->xcmax;
	case COL_FCMAX: return c->Fcmax;
	case COL_XCR: return c->xcr;
	default: return c->Lambda;
	}
}

/* Collision i of a pinned run (completed ones only), or NULL. */
static const struct collision *
pinned(const struct sim *ps, long i)
{
	if (ps == NULL || i < 0 || (size_t)i >= sim_ncollisions(ps))
		return NULL;
	return sim_collision(ps, (size_t)i);
}

void
pane_table_draw(const struct app *a)
{
	const struct rect *r = &a->L.table;
	long n = app_ncollisions(a), top, i, rows = r->h - 1, sel = a->table_sel;
	double scale[NCOL], mag[NCOL];
	char unit[NCOL][16], line[512], cell[64];
	int k, m, focused = a->focus == FOCUS_TABLE;
	const struct sim *ps = a->compare > 0 && a->compare <= a->npins ? a->pin[a->compare - 1].sim : NULL;
	const int *set = ps ? compared : plain;
	long at = -1;
	const struct arc *arc = sim_arc(a->sim);
	struct collision live;

	if (r->h < 2)
		return;
	if (arc_len(arc) > 0 && arc_at(arc, a->cursor)->q) {
		long jc = arc_at(arc, a->cursor)->j;
		for (i = 0; i < n; i++) {
			const struct collision *c = app_collision(a, i, &live);
			if (c && c->j == jc)
				at = i;
		}
	}
	for (k = 0; k < NCOL; k++)
		mag[k] = 0;
	for (i = 0; i < n; i++) {
		const struct collision *c = app_collision(a, i, &live), *p = pinned(ps, i);
		for (k = 0; c && k < NCOL; k++)
			if (isfinite(colval(c, p, k)) && fabs(colval(c, p, k)) > mag[k])
				mag[k] = fabs(colval(c, p, k));
	}
	line[0] = 0;
	for (m = 0; (k = set[m]) >= 0; m++) {
		char h[48];
		if (cols[k].base) {
			scale[k] = units_axis(mag[k] > 0 ? mag[k] : 1, cols[k].base, unit[k], sizeof unit[k]);
			snprintf(h, sizeof h, "%s[%s]", cols[k].name, unit[k]);
		} else {
			scale[k] = 1;
			snprintf(h, sizeof h, "%s%s", cols[k].name, k == COL_VI ? "[m/s]" : "");
		}
		if (k == COL_DTE || k == COL_DXC) {
			/* a difference: the prefix of its own magnitude */
			scale[k] = units_axis(mag[k] > 0 ? mag[k] : 1, cols[k].base, unit[k], sizeof unit[k]);
			snprintf(h, sizeof h, "%s[%s]", cols[k].name, unit[k]);
		}
		snprintf(cell, sizeof cell, "%*s", cols[k].width, h);
		strncat(line, cell, sizeof line - strlen(line) - 1);
	}
	if (ps)
		snprintf(cell, sizeof cell, "  vs %d", a->compare);
	else
		snprintf(cell, sizeof cell, "  collisions: %zu%s", sim_ncollisions(a->sim),
		         n > (long)sim_ncollisions(a->sim) ? " + live" : "");
	strncat(line, cell, sizeof line - strlen(line) - 1);
	tui_puts(r->y, r->x, r->w, line, A_BOLD | (focused ? A_UNDERLINE : 0));

	/* scroll so the selection is visible */
	top = a->table_top;
	if (sel >= n)
		sel = n - 1;
	if (sel < top)
		top = sel;
	if (sel >= top + rows)
		top = sel - rows + 1;
	if (top > n - rows)
		top = n - rows;
	if (top < 0)
		top = 0;
	for (i = top; i < n && i < top + rows; i++) {
		const struct collision *c = app_collision(a, i, &live), *p = pinned(ps, i);
		int attr = 0;
		if (c == NULL)
			continue;
		line[0] = 0;
		for (m = 0; (k = set[m]) >= 0; m++) {
			double v = colval(c, p, k);
			if (k == COL_I)
				snprintf(cell, sizeof cell, "%s%ld", i == at ? ">" : " ", c->i);
			else if (!c->complete && k == COL_E)
				snprintf(cell, sizeof cell, "live");
			else if (!c->complete && (k == COL_XCR || k == COL_LAMBDA))
				snprintf(cell, sizeof cell, "-");
			else if (!isfinite(v))
				snprintf(cell, sizeof cell, "-");
			else {
				snprintf(cell, sizeof cell, "%.4g", v / scale[k]);
				if ((int)strlen(cell) >= cols[k].width)
					snprintf(cell, sizeof cell, "%.1e", v / scale[k]);
			}
			char w[64];
			snprintf(w, sizeof w, "%*s", cols[k].width, cell);
			strncat(line, w, sizeof line - strlen(line) - 1);
		}
		if (!c->complete)
			strncat(line, "  live (in contact)", sizeof line - strlen(line) - 1);
		if (i == sel)
			attr = focused ? A_REVERSE : A_BOLD;
		if (!c->complete && a->colour)
			attr |= COLOR_PAIR(PAIR_CONTACT);
		tui_puts(r->y + 1 + (int)(i - top), r->x, r->w, line, attr);
	}
	if (n == 0)
		tui_puts(r->y + 1, r->x, r->w, "  (no collision yet)", A_DIM);
}
