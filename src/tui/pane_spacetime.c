/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_spacetime.c - the space-time view (V), drawn over the plots'
 * rectangle: each body's centre against t, one line per body, the lowest
 * body at the bottom; '#' where an interface is in contact, at its
 * contact point; the cursor's time as a highlighted column and in the
 * title.  Every body is drawn when the lines can be two pixel rows apart;
 * otherwise every m-th (and the top one), and the title says so.  The
 * abscissa is the plots' (v): the whole run, the window that follows the
 * cursor, or the zoom on one collision; the whole run in the other views.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "blit.h"
#include "canvas.h"
#include "spacetime.h"
#include "term.h"
#include "tui.h"
#include "units.h"

enum { LM = 9, INK_BODY = 1, INK_CONTACT = 2 };

/* The contacts bold (in their colour), the bodies in the current run's. */
static void
st_style(int ink, int colour, attr_t *attr, short *pair)
{
	if (ink == INK_CONTACT) {
		*attr = A_BOLD;
		*pair = colour ? PAIR_CONTACT : 0;
	} else if (colour) {
		*pair = PAIR_INK1;
	}
}

void
st_blit(const struct app *a, const struct canvas *c, int y, int x, int curcol)
{
	blit_canvas(c, y, x, curcol, a->colour, st_style);
}

/* The y axis: its top and bottom ticks and the name (with the unit), in the left margin. */
void
st_ylabels(const struct axis *ay, int y, int h, const char *name)
{
	char lab[32], buf[40];

	canvas_tick_label(ay, ay->hi, lab, sizeof lab);
	snprintf(buf, sizeof buf, "%*s", LM - 1, lab);
	tui_puts(y, 0, LM - 1, buf, 0);
	canvas_tick_label(ay, ay->lo, lab, sizeof lab);
	snprintf(buf, sizeof buf, "%*s", LM - 1, lab);
	tui_puts(y + h - 1, 0, LM - 1, buf, 0);
	snprintf(buf, sizeof buf, ay->unit[0] ? "%s[%s]" : "%s", name, ay->unit);
	if (h >= 3)
		tui_puts(y + h / 2, 0, LM - 1, buf, A_BOLD);
}

/* The abscissa: as the plots' in the follow and zoom views, else the whole run. */
void
st_time_range(const struct app *a, const struct spacetime *st, double *t0, double *t1)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	const struct hb_arc_sample *l = hb_arc_last(arc);
	double end = st->T;

	if (hb_sim_end(a->sim) != HB_SIM_RUNNING && l != NULL && l->t > 0)
		end = l->t;
	*t0 = 0;
	*t1 = end > 0 ? end : 1;
	if (a->view == VIEW_FOLLOW && l != NULL) {
		double w = *t1 / 10, t = hb_arc_at(arc, a->cursor)->t;
		*t0 = fmax(0, t - 0.7 * w);
		*t1 = *t0 + w;
	} else if (a->view == VIEW_ZOOM) {
		struct hb_collision live;
		const struct hb_collision *c = app_collision(a, a->zoom_i, &live);
		if (c != NULL) {
			double td = c->ts - c->te > 0 ? c->ts - c->te : 1e-6;
			*t0 = c->te - 0.25 * td;
			*t1 = c->ts + 0.25 * td;
		}
	}
}

/* Body b's path over [t0, t1] (up to the last record) as one line. */
static void
body_line(const struct spacetime *st, struct canvas *c, int b, double t0, double t1)
{
	size_t hint = 0;
	double tl = st->t[st->nrec - 1], pt = 0, py = 0;
	int have = 0;

	for (int px = 0; px < c->pw; px++) {
		double t = t0 + (t1 - t0) * px / (c->pw > 1 ? c->pw - 1 : 1), y;
		if (t > tl) {
			if (have && pt < tl)   /* to the last record */
				canvas_line(c, pt, py, tl, st_y_at(st, b, tl, &hint), INK_BODY);
			break;
		}
		y = st_y_at(st, b, t, &hint);
		if (!isfinite(y))
			continue;
		if (have)
			canvas_line(c, pt, py, t, y, INK_BODY);
		else
			canvas_point(c, t, y, INK_BODY);
		pt = t;
		py = y;
		have = 1;
	}
}

/* '#' over each contact's extent, at its contact point (the lower body's top, or the floor). */
static void
contact_marks(const struct spacetime *st, struct canvas *c, double t0, double t1)
{
	size_t hint = 0;

	for (size_t i = 0; i < st->nc; i++) {
		const struct st_contact *k = &st->c[i];
		double tm, yc;
		int c0, c1, row;

		if (k->t1 < t0 || k->t0 > t1)
			continue;
		tm = 0.5 * (fmax(k->t0, t0) + fmin(k->t1, t1));
		if (k->k == 0) {
			yc = st->floor_y;
		} else {
			hint = 0;
			yc = st_y_at(st, k->k - 1, tm, &hint) + st->R[k->k - 1];
		}
		row = (int)floor(canvas_pyf(c, yc) / (c->braille ? 4 : 1));
		if (row < 0 || row >= c->h)
			continue;
		c0 = (int)floor(canvas_pxf(c, fmax(k->t0, t0)) / (c->braille ? 2 : 1));
		c1 = (int)floor(canvas_pxf(c, fmin(k->t1, t1)) / (c->braille ? 2 : 1));
		if (c0 < 0)
			c0 = 0;
		if (c1 >= c->w)
			c1 = c->w - 1;
		for (int col = c0; col <= c1; col++)
			canvas_mark(c, col, row, '#', INK_CONTACT);
	}
}

/*
 * The canvas of the bodies and the contacts over [t0, t1], and the y
 * axis; last frame's while the records, the contacts, the range and the
 * size are the same (playback moves the cursor only).  *every: the
 * thinning (every *every-th body and the top one).
 */
static struct canvas *
st_canvas(const struct app *a, struct spacetime *st, double t0, double t1, int cw, int ch,
          struct axis *ay, int *every)
{
	struct canvas *c = st->cv;
	int ph = a->braille ? 4 * ch : ch;

	canvas_axis(st->ylo, st->yhi, ch / 2 + 2, "m", ay);
	*every = 1;
	if (st->nb > ph / 2)
		*every = (st->nb + ph / 2 - 1) / (ph / 2 > 0 ? ph / 2 : 1);
	if (c != NULL && st->cv_key.nrec == st->nrec && st->cv_key.nc == st->nc
	    && st->cv_key.t0 == t0 && st->cv_key.t1 == t1 && st->cv_key.w == cw && st->cv_key.h == ch
	    && st->cv_key.braille == a->braille && st->cv_key.t_last == st->t[st->nrec - 1]
	    && st->cv_key.c_last == (st->nc > 0 ? st->c[st->nc - 1].t1 : 0))
		return c;
	canvas_free(st->cv);
	st->cv = NULL;
	c = canvas_new(cw, ch, a->braille);
	if (c == NULL)
		term_oom();
	canvas_range(c, t0, t1, ay->lo, ay->hi);
	for (int b = 0; b < st->nb; b++)
		if (b % *every == 0 || b == st->nb - 1)
			body_line(st, c, b, t0, t1);
	contact_marks(st, c, t0, t1);
	st->cv = c;
	st->cv_key.nrec = st->nrec;
	st->cv_key.nc = st->nc;
	st->cv_key.t0 = t0;
	st->cv_key.t1 = t1;
	st->cv_key.w = cw;
	st->cv_key.h = ch;
	st->cv_key.braille = a->braille;
	st->cv_key.t_last = st->t[st->nrec - 1];
	st->cv_key.c_last = st->nc > 0 ? st->c[st->nc - 1].t1 : 0;   /* a contact still growing */
	return c;
}

void
pane_spacetime_draw(const struct app *a)
{
	const struct rect *r = &a->L.plots;
	struct spacetime *st = a->st;
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	int cw = r->w - LM, ch = r->h - 2, every, n;
	double t0, t1, tc = 0;
	char title[256], tbuf[48], line[1024];
	struct canvas *c;
	struct axis ax, ay;

	if (cw < 10 || ch < 2)
		return;
	if (hb_arc_len(arc) > 0)
		tc = hb_arc_at(arc, a->cursor)->t;
	hb_units_format(tc, hb_unit_time, 6, tbuf, sizeof tbuf);
	if (a->branch_t >= 0 || st == NULL || st->failed || st->nrec == 0) {
		snprintf(title, sizeof title, "space-time: %s",
		         a->branch_t >= 0 ? "not for a branched run (it runs the scene from t = 0)"
		         : st && st->failed ? "not available (out of memory)" : "computing...");
		tui_puts(r->y, LM, cw, title, A_BOLD);
		return;
	}
	st_time_range(a, st, &t0, &t1);
	c = st_canvas(a, st, t0, t1, cw, ch, &ay, &every);
	n = snprintf(title, sizeof title, "space-time: ");
	if (hb_sim_end(st->sh) == HB_SIM_RUNNING)
		n += snprintf(title + n, sizeof title - (size_t)n, "computing %.0f%%, ",
		              100 * st->t[st->nrec - 1] / (st->T > 0 ? st->T : 1));
	n += snprintf(title + n, sizeof title - (size_t)n, "%d bod%s", st->nb, st->nb == 1 ? "y" : "ies");
	if (every > 1)
		n += snprintf(title + n, sizeof title - (size_t)n, " (every %d%s drawn)", every,
		              every == 2 ? "nd" : every == 3 ? "rd" : "th");
	n += snprintf(title + n, sizeof title - (size_t)n, ", # contact; t = %s", tbuf);
	if (st->lost > 0)
		snprintf(title + n, sizeof title - (size_t)n, "; %ld contacts past the first %d unmarked",
		         st->lost, ST_MAX_CONTACTS);
	tui_puts(r->y, LM, cw, title, A_BOLD);
	st_blit(a, c, r->y + 1, r->x + LM, canvas_col(c, tc));
	st_ylabels(&ay, r->y + 1, ch, "y");
	canvas_axis(t0, t1, cw / 10 > 2 ? cw / 10 : 2, "s", &ax);
	canvas_axis_line(&ax, t0, t1, cw, line, sizeof line);
	tui_puts(r->y + 1 + ch, r->x + LM, cw, line, 0);
	tui_puts(r->y + 1 + ch, 0, LM - 1, "t ->", A_BOLD);
}
