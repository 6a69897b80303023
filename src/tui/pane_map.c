/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_map.c - draws the sweep view's 2-D map (sweep_map.c): the first key
 * across, the second up, each cell the shade of the grid point under it,
 * 8 shades of equal width from the least to the greatest value computed so
 * far, each with its range in the legend on the right.  Braille cells of
 * increasing dots in colour (dim to bold) or, in ASCII or without colour
 * (--ascii, NO_COLOR), ".:-=+*#@";
 * '?' where the observable does not exist, '!' a failed run, blank not
 * computed yet.  Only reads the state.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cnum.h" /* C-locale numbers (src/core) */
#include "keys.h"
#include "sweep_view.h"
#include "term.h"
#include "tui.h"

enum { NSHADE = 8, MLM = 10, LEGW = 24 };

static const char *const ascii_shade[NSHADE] = { ".", ":", "-", "=", "+", "*", "#", "@" };
static const char *const braille_shade[NSHADE] = {
	"\u2801", "\u2803", "\u2807", "\u2847", "\u284f", "\u285f", "\u287f", "\u28ff"
};

static int
shade_attr(const struct app *a, int s)
{
	int attr = s < NSHADE / 3 ? (int)A_DIM : s >= NSHADE - NSHADE / 3 ? (int)A_BOLD : 0;

	return a->colour ? (int)COLOR_PAIR(PAIR_INK1) | attr : attr;
}

static const char *
shade_glyph(const struct app *a, int s)
{
	/* without colour (NO_COLOR) the ASCII ramp reads better than dots */
	return a->braille && a->colour ? braille_shade[s] : ascii_shade[s];
}

static int
shade_of(double z, double lo, double hi)
{
	if (!(hi > lo))
		return NSHADE - 1;
	int s = (int)floor((z - lo) / (hi - lo) * NSHADE);
	return s < 0 ? 0 : s >= NSHADE ? NSHADE - 1 : s;
}

/*
 * The grid index whose value is nearest x, or -1 when x is off the grid's
 * span (or not a number).
 */
static long
nearest(const double *g, long n, double x)
{
	double lo = INFINITY, hi = -INFINITY, best = INFINITY;
	long k = -1;

	for (long i = 0; i < n; i++) {
		lo = fmin(lo, g[i]);
		hi = fmax(hi, g[i]);
	}
	if (!isfinite(x) || x < lo - 1e-9 * fabs(lo) || x > hi + 1e-9 * fabs(hi))
		return -1;
	for (long i = 0; i < n; i++)
		if (fabs(g[i] - x) < best) {
			best = fabs(g[i] - x);
			k = i;
		}
	return k;
}

/* The cell (of w) in the middle of those that show grid index i of n. */
static int
cell_of(long i, long n, int w)
{
	return (int)((2 * i + 1) * (long)w / (2 * n));
}

void
pane_map_draw(const struct app *a, const struct mode *self)
{
	const struct sv_map *m = &a->sv->map;
	char foot[256];
	int top = a->L.status.y + 1, bottom = a->L.msg.y;      /* rows top .. bottom-1 */
	int cw = COLS - MLM - LEGW - 1, ch = bottom - top - 2;  /* title, x axis */
	double lo = INFINITY, hi = -INFINITY;
	struct hb_scene_keyinfo k1 = { 0 }, k2 = { 0 };
	char line[512], a1[48], a2[48];
	const char *on = hb_sweep_observable_name(m->obs), *ou = sv_obs_unit(m->obs);
	long nnone = 0, s1 = -1, s2 = -1;
	struct hb_scene_keyinfo ks;

	for (int r = top; r < bottom; r++) {
		move(r, 0);
		clrtoeol();
	}
	hb_scene_get(&a->sv->base, m->key1, &k1, NULL);
	hb_scene_get(&a->sv->base, m->key2, &k2, NULL);
	for (long i = 0; i < m->n1 * m->n2; i++) {
		if (m->st[i] != HB_CURVE_DONE)
			continue;
		if (isfinite(m->z[i])) {
			lo = fmin(lo, m->z[i]);
			hi = fmax(hi, m->z[i]);
		} else {
			nnone++;
		}
	}
	if (m->obs == HB_CURVE_E || m->obs == HB_CURVE_VI || m->obs == HB_CURVE_XCR)
		snprintf(a1, sizeof a1, "%s of collision %ld", on, m->coll);
	else
		snprintf(a1, sizeof a1, "%s", on);
	snprintf(line, sizeof line, "map: %s over %s (across) and %s (up)   %ld/%ld done%s", a1,
	         m->key1, m->key2, m->done, m->n1 * m->n2, m->done < m->n1 * m->n2 ? ", computing" : "");
	if (m->failed) {
		size_t l = strlen(line);
		snprintf(line + l, sizeof line - l, ", %ld failed", m->failed);
	}
	tui_puts(top, 0, COLS, line, A_BOLD);
	if (cw < 4 || ch < 2)
		return;

	/* the cells: each the grid point under its centre */
	for (int r = 0; r < ch; r++)
		for (int c = 0; c < cw; c++) {
			long i1 = (long)c * m->n1 / cw, i2 = (long)(ch - 1 - r) * m->n2 / ch;
			long k = i2 * m->n1 + i1;
			const char *g;
			int attr = 0;

			if (m->st[k] == HB_CURVE_PENDING)
				continue;
			if (m->st[k] == HB_CURVE_FAILED) {
				g = "!";
				attr = A_BOLD;
			} else if (!isfinite(m->z[k])) {
				g = "?";
				attr = A_DIM;
			} else {
				int s = shade_of(m->z[k], lo, hi);
				g = shade_glyph(a, s);
				attr = shade_attr(a, s);
			}
			tui_puts(top + 1 + r, MLM + c, 1, g, attr);
		}

	/*
	 * The current scene (the run's values of the two keys): X on the cell
	 * of the grid point nearest it, when it is on the map.
	 */
	if (hb_scene_get(hb_sim_scene(a->sim), m->key1, &ks, NULL) == 0)
		s1 = nearest(m->x1, m->n1, ks.number);
	if (hb_scene_get(hb_sim_scene(a->sim), m->key2, &ks, NULL) == 0)
		s2 = nearest(m->x2, m->n2, ks.number);
	if (s1 >= 0 && s2 >= 0)
		tui_puts(top + ch - cell_of(s2, m->n2, ch), MLM + cell_of(s1, m->n1, cw), 1, "X",
		         A_BOLD | A_REVERSE);

	/* the second key's ends on the left, the first key's under the map */
	cnum_snprintf(a2, sizeof a2, "%.3g", m->x2[m->n2 - 1]);
	tui_puts(top + 1, 0, MLM - 1, a2, 0);
	cnum_snprintf(a2, sizeof a2, "%.3g", m->x2[0]);
	tui_puts(top + ch, 0, MLM - 1, a2, 0);
	if (k2.unit[0] != 0) {
		snprintf(line, sizeof line, "[%s]", k2.unit);
		tui_puts(top + 2 + ch / 2, 0, MLM - 1, line, 0);
	}
	snprintf(line, sizeof line, "%s ^", k2.label[0] ? k2.label : m->key2);
	tui_puts(top + 1 + ch / 2, 0, MLM - 1, line, A_BOLD);
	hb_units_format(m->x1[0], k1.dim, 3, a1, sizeof a1);
	hb_units_format(m->x1[m->n1 - 1], k1.dim, 3, a2, sizeof a2);
	snprintf(line, sizeof line, "%s%s -> %s%*s", a1, m->log1 ? " (log)" : "",
	         k1.label[0] ? k1.label : m->key1, 1, "");
	tui_puts(top + 1 + ch, MLM, cw, line, 0);
	tui_puts(top + 1 + ch, MLM + cw - (int)strlen(a2) > MLM + (int)strlen(line)
	                           ? MLM + cw - (int)strlen(a2) : MLM + (int)strlen(line),
	         (int)strlen(a2), a2, 0);

	/* the legend: each shade's range, greatest first */
	{
		int x = COLS - LEGW, y = top + 1;
		snprintf(line, sizeof line, "legend: %s%s%s%s", on, ou ? " [" : "", ou ? ou : "", ou ? "]" : "");
		tui_puts(y++, x, LEGW, line, A_BOLD);
		for (int s = NSHADE - 1; s >= 0 && y < bottom && isfinite(lo); s--) {
			double l = hi > lo ? lo + (hi - lo) * s / NSHADE : lo;
			double h = hi > lo ? lo + (hi - lo) * (s + 1) / NSHADE : hi;
			if (!(hi > lo) && s < NSHADE - 1)
				break;
			tui_puts(y, x, 1, shade_glyph(a, s), shade_attr(a, s));
			cnum_snprintf(line, sizeof line, " %.3g..%.3g", l, h);
			tui_puts(y++, x + 1, LEGW - 1, line, 0);
		}
		if (!isfinite(lo) && y < bottom)
			tui_puts(y++, x, LEGW, "(no value yet)", A_DIM);
		if (y < bottom)
			tui_puts(y++, x, LEGW, "? no such value", A_DIM);
		if (y < bottom)
			tui_puts(y++, x, LEGW, "! failed run", A_DIM);
		if (y < bottom)
			tui_puts(y++, x, LEGW, "  blank: computing", A_DIM);
		if (y < bottom)
			tui_puts(y++, x, LEGW, s1 >= 0 && s2 >= 0 ? "X the current scene" : "X scene: off the map",
			         A_DIM);
		(void)nnone;
	}

	move(a->L.footer.y, 0);
	clrtoeol();
	/* the sweep view's keys on the map, from its table */
	tui_puts(a->L.footer.y, 0, COLS, keys_footer(self, CTX_MAP, foot, sizeof foot, COLS - 1), A_REVERSE);
}
