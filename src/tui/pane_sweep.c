/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_sweep.c - draws the sweep view over the plots and the tables: the
 * observable against the parameter, pinned curves first as ghosts (inks
 * 2..), the current curve last (ink 1), points not computed yet left out;
 * the current scene marked '@' on the curve (or '^' under its abscissa
 * while its value is not known); a log range on a logarithmic axis; the
 * current curve's boundaries (b) as columns of '|' (':' while bisected).
 * Only reads the state.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "canvas.h"
#include "keys.h"
#include "sweep_view.h"
#include "term.h"
#include "tui.h"

enum { SLM = 10 };  /* left margin: the ordinate's tick labels */

static double
xmap(const struct sweep_view *v, double x)
{
	return v->log ? log10(fabs(x)) : x;
}

/* Where boundary i of k lies: between its two points (halfway on the axis's scale). */
static double
boundary_x(const struct sweep_view *v, const struct sv_curve *k, long i)
{
	if (v->log)
		return copysign(sqrt(fabs(k->blo[i]) * fabs(k->bhi[i])), k->blo[i]);
	return (k->blo[i] + k->bhi[i]) / 2;
}

static int
ink_attr(const struct app *a, int ink)
{
	if (a->colour)
		return COLOR_PAIR(PAIR_INK1 + ink - 1) | (ink == 1 ? A_BOLD : 0);
	return ink == 1 ? A_BOLD : A_DIM;
}

static void
blit(const struct app *a, const struct canvas *c, int y, int x)
{
	char cell[8];

	for (int r = 0; r < c->h; r++)
		for (int k = 0; k < c->w; k++) {
			int ink = canvas_cell(c, k, r, cell);
			if (cell[0] == ' ')
				continue;
			tui_puts(y + r, x + k, 4, cell, ink > 0 ? ink_attr(a, ink) : 0);
		}
}

static void
draw_curve(struct canvas *c, const struct sweep_view *v, const struct sv_curve *k, int ink)
{
	int have = 0;
	double px = 0, py = 0;

	for (long i = 0; i < k->n; i++) {
		if (k->st[i] != HB_CURVE_DONE || !isfinite(k->y[i])) {
			have = 0;
			continue;
		}
		double x = xmap(v, k->x[i]);
		if (have)
			canvas_line(c, px, py, x, k->y[i], ink);
		else
			canvas_point(c, x, k->y[i], ink);
		px = x;
		py = k->y[i];
		have = 1;
	}
}

static void
extend(const struct sweep_view *v, const struct sv_curve *k, double *x0, double *x1, double *y0,
       double *y1)
{
	for (long i = 0; i < k->n; i++) {
		double x = xmap(v, k->x[i]);
		if (isfinite(x)) {
			*x0 = fmin(*x0, x);
			*x1 = fmax(*x1, x);
		}
		if (k->st[i] == HB_CURVE_DONE && isfinite(k->y[i])) {
			*y0 = fmin(*y0, k->y[i]);
			*y1 = fmax(*y1, k->y[i]);
		}
	}
}

/* The abscissa's labels: the axis line (linear), or decades and both ends (log). */
static void
x_labels(const struct sweep_view *v, const struct hb_scene_keyinfo *ki, const struct axis *ax,
         const struct canvas *c, int y, int x)
{
	char line[512], lab[48];

	if (!v->log) {
		canvas_axis_line(ax, ax->lo, ax->hi, c->w, line, sizeof line);
		tui_puts(y, x, c->w, line, 0);
		return;
	}
	memset(line, ' ', (size_t)c->w);
	line[c->w] = 0;
	double sg = v->cur.n > 0 ? copysign(1, v->cur.x[0]) : (v->npins ? copysign(1, v->pin[0].x[0]) : 1);
	int last = -100;
	for (double d = ceil(c->x0 - 1e-9); d <= c->x1 + 1e-9; d += 1) {
		int col = canvas_col(c, d);
		hb_units_format(sg * pow(10, d), ki->dim, 3, lab, sizeof lab);
		int l = (int)strlen(lab);
		int at = col - l / 2;
		if (at < 0)
			at = 0;
		if (at + l > c->w)
			at = c->w - l;
		if (col < 0 || at <= last + 1 || at < 0)
			continue;
		memcpy(line + at, lab, (size_t)l);
		last = at + l;
	}
	tui_puts(y, x, c->w, line, 0);
	tui_puts(y, x + c->w - 4 > x ? x + c->w - 4 : x, 4, line[c->w - 1] == ' ' ? "log" : "", A_DIM);
}

static void
y_labels(const struct axis *ay, int y, int h)
{
	char lab[32], buf[40];
	int used[256] = { 0 };

	for (int i = 0; i < ay->nticks; i++) {
		int r = (int)lround((ay->hi - ay->tick[i]) / (ay->hi - ay->lo) * (h - 1));
		if (r < 0 || r >= h || r >= 256 || used[r] || (r > 0 && used[r - 1]))
			continue;
		canvas_tick_label(ay, ay->tick[i], lab, sizeof lab);
		snprintf(buf, sizeof buf, "%*s", SLM - 1, lab);
		tui_puts(y + r, 0, SLM - 1, buf, 0);
		used[r] = 1;
	}
}

void
pane_sweep_draw(const struct app *a, const struct mode *self)
{
	const struct sweep_view *v = a->sv;
	const struct sv_curve *cur = &v->cur;
	int top = a->L.status.y + 1, bottom = a->L.msg.y;      /* rows top .. bottom-1 */
	int cw = COLS - SLM - 1, ch = bottom - top - 3;        /* title, legend, x axis */
	double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY, xs = NAN, ys;
	struct hb_scene_keyinfo ki = { 0 };
	struct axis ax, ay;
	struct canvas *c;
	char line[512], vx[48], vy[48], foot[256];
	const char *on = hb_sweep_observable_name(v->obs), *ou = sv_obs_unit(v->obs);

	if (v->map.on) {
		pane_map_draw(a, self);
		return;
	}

	for (int r = top; r < bottom; r++) {
		move(r, 0);
		clrtoeol();
	}
	if (hb_scene_get(hb_sim_scene(a->sim), v->key, &ki, NULL) == 0)
		xs = ki.number;
	else
		hb_scene_get(&v->base, v->key, &ki, NULL);
	ys = sv_current_y(a, v->obs, v->coll);

	/* title: what is plotted and how far it is */
	if (v->obs == HB_CURVE_E || v->obs == HB_CURVE_VI || v->obs == HB_CURVE_XCR)
		snprintf(vy, sizeof vy, "%s of collision %ld", on, v->coll);
	else
		snprintf(vy, sizeof vy, "%s", on);
	if (cur->c != NULL)
		snprintf(line, sizeof line, "sweep: %s against %s = %s   %ld/%ld done%s", vy, v->key,
		         v->spec, cur->done, cur->n, cur->done < cur->n ? ", computing" : "");
	else
		snprintf(line, sizeof line, "sweep: %s against %s = %s   (pinned; L or r for a new curve)",
		         vy, v->key, v->spec);
	if (cur->failed) {
		size_t l = strlen(line);
		snprintf(line + l, sizeof line - l, ", %ld failed", cur->failed);
	}
	if (v->bounds && cur->c != NULL) {
		size_t l = strlen(line);
		int loc = 0;

		for (long i = 0; i < cur->nb && i < SV_MAX_BOUNDS; i++)
			loc += cur->bloc[i];
		snprintf(line + l, sizeof line - l, ", %ld boundar%s%s", cur->nb,
		         cur->nb == 1 ? "y" : "ies", loc < cur->nb ? ", locating" : " |");
	}
	tui_puts(top, 0, COLS, line, A_BOLD);

	/* legend: pins, then the current curve, then the current scene, then the boundaries */
	{
		int col = 0;
		for (int i = 0; i <= v->npins && col < COLS; i++) {
			const struct sv_curve *k = i < v->npins ? &v->pin[i] : cur;
			int ink = i < v->npins ? i + 2 : 1;
			if (k->c == NULL)
				continue;
			if (i < v->npins)
				snprintf(line, sizeof line, "%c%d %s (%ld/%ld)  ", canvas_glyph(ink), i + 1,
				         k->label, k->done, k->n);
			else
				snprintf(line, sizeof line, "%c now %s  ", canvas_glyph(ink), k->label);
			tui_puts(top + 1, col, COLS - col, line, ink_attr(a, ink));
			col += (int)strlen(line);
		}
		hb_units_format(xs, ki.dim, 4, vx, sizeof vx);
		if (isfinite(ys))
			hb_units_format(ys, sv_obs_dim(v->obs), 4, vy, sizeof vy);
		else
			snprintf(vy, sizeof vy, "%s", hb_sim_end(a->sim) == HB_SIM_RUNNING ? "computing" : "none");
		snprintf(line, sizeof line, "@ scene: %s = %s, %s = %s  ", ki.label, vx, on, vy);
		tui_puts(top + 1, col, COLS - col, line, A_BOLD);
		col += (int)strlen(line);
		for (long i = 0; v->bounds && i < cur->nb && i < SV_MAX_BOUNDS && col < COLS; i++) {
			hb_units_format(boundary_x(v, cur, i), ki.dim, 4, vx, sizeof vx);
			snprintf(line, sizeof line, "%c %s  ", cur->bloc[i] ? '|' : ':', vx);
			tui_puts(top + 1, col, COLS - col, line, ink_attr(a, 1));
			col += (int)strlen(line);
		}
	}
	if (cw < 10 || ch < 3)
		return;

	extend(v, cur, &x0, &x1, &y0, &y1);
	for (int i = 0; i < v->npins; i++)
		extend(v, &v->pin[i], &x0, &x1, &y0, &y1);
	if (isfinite(ys) && isfinite(xmap(v, xs)) && xmap(v, xs) >= x0 && xmap(v, xs) <= x1) {
		y0 = fmin(y0, ys);
		y1 = fmax(y1, ys);
	}
	if (!(y0 <= y1)) {
		y0 = 0;
		y1 = 1;
	}
	if (!(x0 <= x1)) {
		x0 = 0;
		x1 = 1;
	}
	canvas_axis(y0, y1, ch / 2 + 1 > 2 ? ch / 2 + 1 : 2, ou, &ay);
	if (v->log) {
		memset(&ax, 0, sizeof ax);
		ax.lo = x0;
		ax.hi = x1;
	} else {
		canvas_axis(x0, x1, cw / 12 > 2 ? cw / 12 : 2, ki.unit[0] ? ki.unit : NULL, &ax);
	}
	c = canvas_new(cw, ch, a->braille);
	if (c == NULL)
		term_oom();
	canvas_range(c, ax.lo, ax.hi, ay.lo, ay.hi);
	for (int i = 0; i < v->npins; i++)
		draw_curve(c, v, &v->pin[i], i + 2);
	draw_curve(c, v, cur, 1);
	for (long i = 0; v->bounds && i < cur->nb && i < SV_MAX_BOUNDS; i++) {
		int col = canvas_col(c, xmap(v, boundary_x(v, cur, i)));
		char cell[8];

		for (int row = 0; col >= 0 && row < ch; row++)
			if (canvas_cell(c, col, row, cell) == 0)
				canvas_mark(c, col, row, cur->bloc[i] ? '|' : ':', 1);
	}
	if (isfinite(xmap(v, xs))) {
		int col = canvas_col(c, xmap(v, xs));
		if (col >= 0 && isfinite(ys)) {
			int row = (int)floor(canvas_pyf(c, ys) * ch / c->ph);
			canvas_mark(c, col, row < 0 ? 0 : row >= ch ? ch - 1 : row, '@', 1);
		} else if (col >= 0) {
			canvas_mark(c, col, ch - 1, '^', 1);
		}
	}
	blit(a, c, top + 2, SLM);
	y_labels(&ay, top + 2, ch);
	snprintf(line, sizeof line, "%s%s%s%s", on, ou ? "[" : "", ou ? ay.unit : "", ou ? "]" : "");
	tui_puts(top + 2 + ch / 2, 0, SLM - 1, line, A_BOLD);
	x_labels(v, &ki, &ax, c, top + 2 + ch, SLM);
	snprintf(line, sizeof line, "%s ->", ki.label);
	tui_puts(top + 2 + ch, 0, SLM - 1, line, A_BOLD);
	canvas_free(c);

	/* footer: the view's own keys, from its table */
	move(a->L.footer.y, 0);
	clrtoeol();
	tui_puts(a->L.footer.y, 0, COLS, keys_footer(self, CTX_CURVE, foot, sizeof foot, COLS - 1), A_REVERSE);
}
