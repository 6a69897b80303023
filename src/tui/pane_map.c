/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_map.c - draws the sweep view's 2-D map (sweep_map.c): the first key
 * across, the second up, each cell the shade of the grid point under it,
 * 8 shades of equal width from the least to the greatest value of the
 * first row that has one (the range then stays: a value outside it takes
 * the end shade, and the legend counts them), each with its range in the
 * legend on the right.  X marks the current scene, 1 2 3 the pinned runs'
 * scenes; with b on, | a row's boundary located (: while bisected), as
 * the curve view marks them.  Braille cells of
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

/*
 * The column (of w) where x lies across the first key's grid (g, n points,
 * on a log scale when lg): its position between the grid's ends, the ends
 * being the middles of the first and last cells; -1 off the grid.
 */
static int
col_at(const double *g, long n, int lg, double x, int w)
{
	double a = g[0], b = g[n - 1], f;

	if (n < 2 || !isfinite(x))
		return -1;
	if (lg && a * x > 0 && b * x > 0)
		f = log(x / a) / log(b / a);
	else
		f = (x - a) / (b - a);
	if (!(f >= -1e-9 && f <= 1 + 1e-9))
		return -1;
	{
		double c0 = (double)w / (2.0 * (double)n), c1 = (double)w - c0;
		int c = (int)floor(c0 + f * (c1 - c0));
		return c < 0 ? 0 : c >= w ? w - 1 : c;
	}
}

/* Where boundary b of row j lies: between its two points (halfway on the axis's scale). */
static double
boundary_x(const struct sv_map *m, long j, int b)
{
	double lo = m->blo[j * SV_MAP_ROW_BOUNDS + b], hi = m->bhi[j * SV_MAP_ROW_BOUNDS + b];

	if (m->log1)
		return copysign(sqrt(fabs(lo) * fabs(hi)), lo);
	return (lo + hi) / 2;
}

/* The row (of the map's ch) and column of the scene sc, or -1 when it is off the map. */
static int
scene_cell(const struct sv_map *m, const struct hb_scene *sc, int ch, int cw, int *col)
{
	struct hb_scene_keyinfo ks;
	long s1 = -1, s2 = -1;

	if (hb_scene_get(sc, m->key1, &ks, NULL) == 0)
		s1 = nearest(m->x1, m->n1, ks.number);
	if (hb_scene_get(sc, m->key2, &ks, NULL) == 0)
		s2 = nearest(m->x2, m->n2, ks.number);
	if (s1 < 0 || s2 < 0)
		return -1;
	*col = cell_of(s1, m->n1, cw);
	return ch - 1 - cell_of(s2, m->n2, ch);
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
	long nnone = 0, nbelow = 0, nabove = 0, nbounds = 0;
	int xrow = -1, xcol = 0, npin_on = 0;

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
	/* the shades' range: fixed by the first row with a value; until then, the values so far */
	if (m->zfixed) {
		for (long i = 0; i < m->n1 * m->n2; i++)
			if (m->st[i] == HB_CURVE_DONE && isfinite(m->z[i])) {
				nbelow += m->z[i] < m->zlo;
				nabove += m->z[i] > m->zhi;
			}
		lo = m->zlo;
		hi = m->zhi;
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

	/* the boundaries each row located (b): | located, : while bisected */
	for (long j = 0; j < m->n2; j++)
		for (long b = 0; b < m->nb[j] && b < SV_MAP_ROW_BOUNDS; b++) {
			int c = col_at(m->x1, m->n1, m->log1, boundary_x(m, j, (int)b), cw);
			nbounds++;
			if (c >= 0)
				tui_puts(top + ch - cell_of(j, m->n2, ch), MLM + c, 1,
				         m->bloc[j * SV_MAP_ROW_BOUNDS + b] ? "|" : ":", A_BOLD);
		}

	/*
	 * The pinned runs' scenes (their number, as in the explorer's legend)
	 * and the current scene (X, drawn last): each on the cell of the grid
	 * point nearest it, when it is on the map.
	 */
	for (int p = 0; p < a->npins; p++) {
		int c, r = scene_cell(m, hb_sim_scene(a->pin[p].sim), ch, cw, &c);
		char d[2] = { (char)('1' + p % 9), 0 }; /* APP_MAX_PINS < 10 */
		if (r < 0)
			continue;
		tui_puts(top + 1 + r, MLM + c, 1, d, A_BOLD | A_REVERSE);
		npin_on++;
	}
	xrow = scene_cell(m, hb_sim_scene(a->sim), ch, cw, &xcol);
	if (xrow >= 0)
		tui_puts(top + 1 + xrow, MLM + xcol, 1, "X", A_BOLD | A_REVERSE);

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
		if (isfinite(lo) && y < bottom)
			tui_puts(y++, x, LEGW, !m->zfixed ? "(range so far: row 0)" : m->zrescaled ? "(range: r)" : "(range of the first row)", A_DIM);
		if ((nbelow || nabove) && y < bottom) {
			/* later values outside the range: the end shades */
			if (nbelow && nabove)
				snprintf(line, sizeof line, "%ld below, %ld above: r", nbelow, nabove);
			else
				snprintf(line, sizeof line, "%ld %s the range: r", nbelow + nabove, nbelow ? "below" : "above");
			tui_puts(y++, x, LEGW, line, A_BOLD);
		}
		if (y < bottom)
			tui_puts(y++, x, LEGW, "? no such value", A_DIM);
		if (y < bottom)
			tui_puts(y++, x, LEGW, "! failed run", A_DIM);
		if (y < bottom)
			tui_puts(y++, x, LEGW, "  blank: computing", A_DIM);
		if (y < bottom)
			tui_puts(y++, x, LEGW, xrow >= 0 ? "X the current scene" : "X scene: off the map", A_DIM);
		if (a->npins > 0 && y < bottom) {
			snprintf(line, sizeof line, "1..%d pins%s", a->npins,
			         npin_on < a->npins ? " (some off it)" : "");
			tui_puts(y++, x, LEGW, a->npins == 1 ? (npin_on ? "1 the pinned run" : "1 pin: off the map")
			                                     : line, A_DIM);
		}
		if (m->bounds && y < bottom) {
			snprintf(line, sizeof line, "| boundary, : bisecting%s", nbounds ? "" : " (none)");
			tui_puts(y++, x, LEGW, line, A_DIM);
		}
		(void)nnone;
	}

	move(a->L.footer.y, 0);
	clrtoeol();
	/* the sweep view's keys on the map, from its table */
	tui_puts(a->L.footer.y, 0, COLS, keys_footer(self, CTX_MAP, foot, sizeof foot, COLS - 1), A_REVERSE);
}
