/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_plot.c - the plots: x, x_c and F_c against t, stacked over one time
 * axis, with a marker row for contacts ("[==]", "#" when a contact fits
 * in one column: its ends are the jumps), and the cursor as a highlighted
 * column.  Pinned runs are drawn first as ghosts (inks 2..), the current
 * run last (ink 1).  Views: whole run, follow the cursor, zoom on one
 * collision ([t_e, t_s] with a quarter of t_d either side), the F_c
 * against x_c hysteresis loop of one collision, and the arc against j.
 *
 * Everything is rasterised by canvas.c and copied cell by cell; drawing
 * only reads the state.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "blit.h"
#include "canvas.h"
#include "term.h"
#include "tui.h"
#include "plot_summary.h"
#include "spacetime.h"

enum { LM = 9 };  /* left margin: tick labels and the quantity's name */
enum { Q_X, Q_XC, Q_FC, NQ };

static const char *qname[NQ] = { "x", "x_c", "F_c" };
static const char *qbase[NQ] = { "m", "m", "N" };

static double
qval(const struct hb_arc_sample *s, int q)
{
	switch (q) {
	case Q_X: return s->x;
	case Q_XC: return s->xc;
	default: return s->Fc;
	}
}

/* The abscissa of a sample: t, or j in the (t, j) view. */
static double
absc(const struct app *a, const struct hb_arc_sample *s)
{
	return a->view == VIEW_J ? (double)s->j : s->t;
}

static struct canvas *
canvas_or_die(int w, int h, int braille)
{
	struct canvas *c = canvas_new(w, h, braille);

	if (c == NULL)
		term_oom();
	return c;
}

/* The runs to draw: pins first, then the current one (ink 1). */
static int
runs(const struct app *a, const struct hb_sim **s, int *ink)
{
	int n = 0;

	for (int i = 0; i < a->npins; i++) {
		s[n] = a->pin[i].sim;
		ink[n++] = i + 2;
	}
	s[n] = a->sim;
	ink[n++] = 1;
	return n;
}

/* The abscissa range of the view (t or j). */
static void
view_range(const struct app *a, double *lo, double *hi)
{
	const struct hb_sim *s[APP_MAX_PINS + 1];
	int ink[APP_MAX_PINS + 1], n = runs(a, s, ink);
	double end = 0;
	const struct hb_arc *arc = hb_sim_arc(a->sim);

	for (int k = 0; k < n; k++) {
		const struct hb_arc_sample *l = hb_arc_last(hb_sim_arc(s[k]));
		double e;
		if (a->view == VIEW_J)
			e = l ? (double)l->j : 0;
		else
			e = hb_sim_end(s[k]) == HB_SIM_RUNNING || l == NULL ? hb_sim_scene(s[k])->run.T : l->t;
		if (e > end)
			end = e;
	}
	*lo = 0;
	*hi = end > 0 ? end : 1;
	if (a->present && a->view == VIEW_FOLLOW && a->in_slow && a->slow_td > 0) {
		/* presentation, slow motion: the view on the contact as it forms */
		*lo = a->slow_t0 - 0.5 * a->slow_td;
		*hi = a->slow_t0 + 3.5 * a->slow_td;
	} else if (a->view == VIEW_FOLLOW && hb_arc_len(arc) > 0) {
		double w = *hi / 10, t = hb_arc_at(arc, a->cursor)->t;
		*lo = t - 0.7 * w;
		if (*lo < 0)
			*lo = 0;
		*hi = *lo + w;
	} else if (a->view == VIEW_ZOOM) {
		struct hb_collision live;
		const struct hb_collision *c = app_collision(a, a->zoom_i, &live);
		if (c != NULL) {
			double td = c->ts - c->te;
			if (!(td > 0))
				td = 1e-6;
			*lo = c->te - 0.25 * td;
			*hi = c->ts + 0.25 * td;
		}
	}
}

/* Visits the samples of arc with abscissa in [lo, hi] (and one either side). */
static void
sample_span(const struct app *a, const struct hb_arc *arc, double lo, double hi, size_t *i0, size_t *i1)
{
	size_t n = hb_arc_len(arc), i;

	*i0 = 0;
	*i1 = n;
	if (a->view == VIEW_J || n == 0)
		return;
	*i0 = hb_arc_find_t(arc, lo);
	/* hb_arc_find_t gives the last sample at lo of the greatest j: step back over a jump */
	while (*i0 > 0 && hb_arc_at(arc, *i0 - 1)->t >= lo)
		(*i0)--;
	i = hb_arc_find_t(arc, hi);
	*i1 = i + 2 < n ? i + 2 : n;
}

/* The current run's ink bold, the pins' in their colours (dim without colours). */
static void
plot_style(int ink, int colour, attr_t *attr, short *pair)
{
	if (colour) {
		*pair = (short)(PAIR_INK1 + ink - 1);
		*attr = ink == 1 ? A_BOLD : 0;
	} else if (ink > 1) {
		*attr = A_DIM;
	}
}

static void
blit(const struct app *a, const struct canvas *c, int y, int x, int curcol)
{
	blit_canvas(c, y, x, curcol, a->colour, plot_style);
}

static void
margin_labels(const struct axis *ax, int y, int h, const char *name)
{
	char lab[32], nm[32];
	int used[256] = { 0 };

	if (h > 256)
		h = 256;
	for (int i = 0; i < ax->nticks; i++) {
		int r = (int)lround((ax->hi - ax->tick[i]) / (ax->hi - ax->lo) * (h - 1));
		if (r < 0 || r >= h || used[r] || (r > 0 && used[r - 1]) || (r + 1 < h && used[r + 1]))
			continue;
		if (h <= 4 && r != 0 && r != h - 1)
			continue; /* small plots: top and bottom only, room for the name */
		canvas_tick_label(ax, ax->tick[i], lab, sizeof lab);
		char buf[40];
		snprintf(buf, sizeof buf, "%*s", LM - 1, lab);
		tui_puts(y + r, 0, LM - 1, buf, 0);
		used[r] = 1;
	}
	snprintf(nm, sizeof nm, ax->unit[0] ? "%s[%s]" : "%s", name, ax->unit);
	for (int r = h / 2 - (h > 2 ? 0 : 1); r < h; r++)
		if (r >= 0 && !used[r]) {
			tui_puts(y + r, 0, LM - 1, nm, A_BOLD);
			break;
		}
}

static int
ink_attr(const struct app *a, int ink)
{
	if (a->colour)
		return COLOR_PAIR(PAIR_INK1 + ink - 1) | A_BOLD;
	return ink == 1 ? A_BOLD : 0;
}

/*
 * Row 0 of the plots: the view's title on the left, then one entry per run
 * ("1. c = 4400 N s/m"), each in its colour with its marker, the current
 * run last; entries that do not fit are cut at the right.
 */
static void
legend(const struct app *a, int y, int x, int w, const char *title)
{
	char item[128];
	int col = x, end = x + w;

	tui_puts(y, col, end - col, title, A_BOLD);
	col += (int)strlen(title);
	if (a->npins == 0)
		return;
	for (int i = 0; i <= a->npins && col + 4 < end; i++) {
		int ink = i < a->npins ? i + 2 : 1;
		if (i < a->npins)
			snprintf(item, sizeof item, "  %c%d %s", canvas_glyph(ink), i + 1, a->pin[i].label);
		else
			snprintf(item, sizeof item, "  %c now %s", canvas_glyph(1), a->run_label);
		tui_puts(y, col, end - col, item, ink_attr(a, ink));
		col += (int)strlen(item);
	}
}

/*
 * Braille dots carry no glyph: each pinned run also gets its marker
 * (canvas_glyph) on its curve every few columns, so the runs can be told
 * apart without colour.  In ASCII the curve is drawn with the glyph.
 */
static void
pin_marks(const struct app *a, struct canvas *c, const struct hb_sim *const *s, const int *ink,
          int n, int q, double t0, double t1)
{
	if (!c->braille)
		return;
	for (int k = 0; k < n; k++) {
		const struct hb_arc *ak = hb_sim_arc(s[k]);
		if (ink[k] == 1 || hb_arc_len(ak) == 0)
			continue;
		for (int col = 2 + 3 * (ink[k] - 2); col < c->w; col += 10) {
			double t = t0 + (t1 - t0) * (col + 0.5) / c->w;
			const struct hb_arc_sample *p;
			int row;
			if (a->view == VIEW_J || t > hb_arc_last(ak)->t)
				break;
			p = hb_arc_at(ak, hb_arc_find_t(ak, t));
			row = (int)floor(canvas_pyf(c, qval(p, q)) / 4);
			if (row >= 0 && row < c->h)
				canvas_mark(c, col, row, canvas_glyph(ink[k]), ink[k]);
		}
	}
}

/* The F_c against x_c loop of collision a->zoom_i, for every run. */
static void
draw_loop(const struct app *a)
{
	const struct rect *r = &a->L.plots;
	const struct hb_sim *s[APP_MAX_PINS + 1];
	int ink[APP_MAX_PINS + 1], n = runs(a, s, ink), ch = r->h - 2, cw = r->w - LM;
	double xlo = 0, xhi = 0, ylo = 0, yhi = 0;
	struct canvas *c = NULL;
	struct axis ax, ay;
	char line[512], title[96];
	int curcol = -1;

	if (ch < 2 || cw < 10)
		return;
	for (int pass = 0; pass < 2; pass++) {
		for (int k = 0; k < n; k++) {
			struct hb_collision live;
			const struct hb_collision *col;
			const struct hb_arc *arc = hb_sim_arc(s[k]);
			if (s[k] == a->sim)
				col = app_collision(a, a->zoom_i, &live);
			else
				col = a->zoom_i >= 0 && (size_t)a->zoom_i < hb_sim_ncollisions(s[k])
				      ? hb_sim_collision(s[k], (size_t)a->zoom_i) : NULL;
			if (col == NULL || hb_arc_len(arc) == 0)
				continue;
			for (size_t i = hb_arc_find(arc, col->te, col->j); i < hb_arc_len(arc); i++) {
				const struct hb_arc_sample *p = hb_arc_at(arc, i);
				if (p->j != col->j)
					break;
				if (pass == 0) {
					xlo = fmin(xlo, p->xc);
					xhi = fmax(xhi, p->xc);
					ylo = fmin(ylo, p->Fc);
					yhi = fmax(yhi, p->Fc);
				} else if (c == NULL) {
					break;
				} else if (i > 0 && hb_arc_at(arc, i - 1)->j == p->j) {
					const struct hb_arc_sample *q = hb_arc_at(arc, i - 1);
					canvas_line(c, q->xc, q->Fc, p->xc, p->Fc, ink[k]);
				} else {
					canvas_point(c, p->xc, p->Fc, ink[k]);
				}
			}
		}
		if (pass == 0) {
			canvas_axis(xlo, xhi, cw / 10 > 2 ? cw / 10 : 2, "m", &ax);
			canvas_axis(ylo, yhi, ch / 2 + 1 > 2 ? ch / 2 + 1 : 2, "N", &ay);
			c = canvas_or_die(cw, ch, a->braille);
			canvas_range(c, ax.lo, ax.hi, ay.lo, ay.hi);
		}
	}
	/* the cursor, when it lies in this collision */
	{
		const struct hb_arc *arc = hb_sim_arc(a->sim);
		if (hb_arc_len(arc) > 0) {
			const struct hb_arc_sample *p = hb_arc_at(arc, a->cursor);
			struct hb_collision live;
			const struct hb_collision *col = app_collision(a, a->zoom_i, &live);
			if (col && p->j == col->j) {
				int cc = canvas_col(c, p->xc);
				double py = floor(canvas_pyf(c, p->Fc) + 0.5);
				int row = c->braille ? (int)py / 4 : (int)py;
				canvas_mark(c, cc, row, 'O', 1);
				curcol = -1;
			}
		}
	}
	snprintf(title, sizeof title, "hysteresis loop: F_c against x_c, collision %ld", a->zoom_i);
	legend(a, r->y, LM, cw, title);
	blit(a, c, r->y + 1, r->x + LM, curcol);
	margin_labels(&ay, r->y + 1, ch, "F_c");
	canvas_axis_line(&ax, ax.lo, ax.hi, cw, line, sizeof line);
	tui_puts(r->y + 1 + ch, LM, cw, line, 0);
	tui_puts(r->y + 1 + ch, 0, LM - 1, "x_c ->", A_BOLD);
	canvas_free(c);
}

/* Widens [*lo, *hi] to the finite values of quantity q of the n runs in [t0, t1]. */
static void
value_range(const struct app *a, const struct hb_sim *const *s, int n, int q, double t0, double t1,
            double *lo, double *hi)
{
	for (int k = 0; k < n; k++) {
		const struct hb_arc *ak = hb_sim_arc(s[k]);
		const struct plot_sum *ps;
		size_t i, end;

		sample_span(a, ak, t0, t1, &i, &end);
		if (a->view != VIEW_J && end - i > 64 && (ps = psum_of(a->psum, s[k])) != NULL) {
			/* the samples strictly inside [t0, t1] (sample_span adds one either side) */
			size_t a0 = i, a1 = end;

			while (a0 < a1 && hb_arc_at(ak, a0)->t < t0)
				a0++;
			while (a1 > a0 && hb_arc_at(ak, a1 - 1)->t > t1)
				a1--;
			psum_range(ps, a0, a1, q, lo, hi);
			continue;
		}
		for (; i < end; i++) {
			double xv = absc(a, hb_arc_at(ak, i)), v = qval(hb_arc_at(ak, i), q);

			if (xv >= t0 && xv <= t1 && isfinite(v)) {
				*lo = fmin(*lo, v);
				*hi = fmax(*hi, v);
			}
		}
	}
}

void
pane_plot_draw(const struct app *a)
{
	const struct rect *r = &a->L.plots;
	const struct hb_sim *s[APP_MAX_PINS + 1];
	int ink[APP_MAX_PINS + 1], n, hs[NQ + 1], cw = r->w - LM, y, curcol = -1, nq = NQ;
	double t0, t1;
	char line[1024], title[128];
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	static const char *vname[VIEW_COUNT] = { "whole run", "follow the cursor", "zoom",
	                                         "loop", "against j" };

	if (spacetime_on(a)
	    || ((spacetime_iface(a) >= 0 || spacetime_body(a) >= 0) && a->view != VIEW_LOOP && a->view != VIEW_J)) {
		(spacetime_on(a) ? pane_spacetime_draw : spacetime_body(a) >= 0 ? pane_body_draw : pane_iface_draw)(a);
		return;
	}
	if (a->view == VIEW_LOOP) {
		draw_loop(a);
		return;
	}
	if (cw < 10 || r->h < 3 + NQ)
		return;
	n = runs(a, s, ink);
	view_range(a, &t0, &t1);
	if (a->view == VIEW_ZOOM)
		snprintf(title, sizeof title, "zoom: collision %ld", a->zoom_i);
	else
		snprintf(title, sizeof title, "%s", vname[a->view]);
	/* row 0: title and legend; then the plots; then markers and the axis */
	legend(a, r->y, LM, cw, title);
	/* a recording opened with D or --data: its strip under the plots, on the same t axis */
	if (fitov_recording(a) && a->view != VIEW_J && r->h >= 4 + NQ)
		nq = NQ + 1;
	layout_stack(r->h - 1, nq, 2, hs);
	y = r->y + 1;
	for (int q = 0; q < nq; q++) {
		double lo = 0, hi = 0;
		struct axis ay;
		struct canvas *c;
		struct psum_view pv;
		int cacheable = a->psum != NULL, cached = 0;

		if (q == NQ) {
			canvas_axis(0, fitov_recording_peak(a), hs[q] / 2 + 2, NULL, &ay);
			c = canvas_or_die(cw, hs[q], a->braille);
			canvas_range(c, t0, t1, 0, ay.hi);
			fitov_plot_recording(a, c, t0, t1);
			blit(a, c, y, r->x + LM, curcol);
			margin_labels(&ay, y, hs[q], "rec");
			canvas_free(c);
			y += hs[q];
			continue;
		}

		/* the same runs over the same range: last frame's canvas (playback moves the cursor only) */
		if (fitov_loaded(a) || a->present)
			cacheable = 0;   /* presentation draws the current run up to the cursor */
		if (cacheable) {
			psum_view_of(&pv, q, a->view + 16 * a->present, t0, t1, cw, hs[q], a->braille, s, ink, n);
			if ((c = psum_plot_get(a->psum, &pv, &ay)) != NULL) {
				cached = 1;
				goto blit;
			}
		}
		if (a->present && a->hold.n > 0) {
			/* presentation: the scale over the run, held */
			lo = a->hold.lo[q];
			hi = a->hold.hi[q];
		} else {
			value_range(a, s, n, q, t0, t1, &lo, &hi);
		}
		canvas_axis(lo, hi, hs[q] / 2 + 2, qbase[q], &ay);
		c = canvas_or_die(cw, hs[q], a->braille);
		c->thick = a->present;
		canvas_range(c, t0, t1, ay.lo, ay.hi);
		for (int k = 0; k < n; k++) {
			const struct hb_arc *ak = hb_sim_arc(s[k]);
			const struct plot_sum *ps;
			size_t i0, i1;
			sample_span(a, ak, t0, t1, &i0, &i1);
			/* presentation: the current run drawn up to the cursor, forming */
			if (a->present && s[k] == a->sim && i1 > a->cursor + 1)
				i1 = a->cursor + 1;
			/* many samples to a column: one stroke a column (plot_summary.c) */
			else if (a->view != VIEW_J && i1 - i0 > 4 * (size_t)c->pw
			         && (ps = psum_of(a->psum, s[k])) != NULL) {
				psum_draw(ps, c, q, t0, t1, ink[k]);
				continue;
			}
			for (size_t i = i0; i < i1; i++) {
				const struct hb_arc_sample *p = hb_arc_at(ak, i);
				if (i > i0) {
					const struct hb_arc_sample *o = hb_arc_at(ak, i - 1);
					if (a->view != VIEW_J || o->j == p->j) {
						canvas_line(c, absc(a, o), qval(o, q), absc(a, p), qval(p, q), ink[k]);
						continue;
					}
				}
				canvas_point(c, absc(a, p), qval(p, q), ink[k]);
			}
		}
		pin_marks(a, c, s, ink, n, q, t0, t1);
		fitov_plot_marks(a, c, q == Q_X, t0, t1);
blit:
		if (hb_arc_len(arc) > 0)
			curcol = canvas_col(c, absc(a, hb_arc_at(arc, a->cursor)));
		blit(a, c, y, r->x + LM, curcol);
		margin_labels(&ay, y, hs[q], qname[q]);
		/* kept for the next frame (the cache owns it), else freed */
		if (!cached && !(cacheable && psum_plot_put(a->psum, &pv, c, &ay) == 0))
			canvas_free(c);
		y += hs[q];
	}
	/* marker row: contacts of the current run */
	memset(line, ' ', (size_t)cw);
	line[cw] = 0;
	if (a->view != VIEW_J) {
		for (size_t k = 0; k < hb_arc_nintervals(arc); k++) {
			const struct hb_arc_interval *iv = hb_arc_interval_at(arc, k);
			double c0, c1;
			int k0, k1;
			if (!iv->q || iv->t1 < t0 || iv->t0 > t1)
				continue;
			c0 = (fmax(iv->t0, t0) - t0) / (t1 - t0) * (cw - 1);
			c1 = (fmin(iv->t1, t1) - t0) / (t1 - t0) * (cw - 1);
			k0 = (int)lround(c0);
			k1 = (int)lround(c1);
			if (k0 < 0)
				k0 = 0;
			if (k1 >= cw)
				k1 = cw - 1;
			if (k1 <= k0) {
				line[k0] = '#';
				continue;
			}
			for (int k2 = k0; k2 <= k1; k2++)
				line[k2] = '=';
			if (iv->t0 >= t0)
				line[k0] = '[';
			if (iv->t1 <= t1)
				line[k1] = ']';
		}
	} else {
		/* (t, j) view: the phase of each interval at its j */
		for (size_t k = 0; k < hb_arc_nintervals(arc); k++) {
			const struct hb_arc_interval *iv = hb_arc_interval_at(arc, k);
			int col = (int)lround(((double)iv->j - t0) / (t1 - t0) * (cw - 1));
			if (col >= 0 && col < cw)
				line[col] = iv->q ? 'c' : 'f';
		}
	}
	if (curcol >= 0 && curcol < cw && line[curcol] == ' ')
		line[curcol] = '^';
	tui_puts(y, 0, LM - 1, a->view == VIEW_J ? "phase" : "contact", A_DIM);
	tui_puts(y, r->x + LM, cw, line, a->colour ? COLOR_PAIR(PAIR_CONTACT) : 0);
	y++;
	/* the axis */
	{
		struct axis ax;
		canvas_axis(t0, t1, cw / 10 > 2 ? cw / 10 : 2, a->view == VIEW_J ? NULL : "s", &ax);
		canvas_axis_line(&ax, t0, t1, cw, line, sizeof line);
		tui_puts(y, r->x + LM, cw, line, 0);
		tui_puts(y, 0, LM - 1, a->view == VIEW_J ? "j ->" : "t ->", A_BOLD);
	}
}

void
plot_view_range(const struct app *a, double *t0, double *t1)
{
	view_range(a, t0, t1);
}

int
plot_abscissa_at(const struct app *a, int x, double *t)
{
	const struct rect *r = &a->L.plots;
	int cw = r->w - LM;
	double t0, t1;

	if (a->view == VIEW_LOOP || cw < 10 || x < r->x + LM || x >= r->x + r->w)
		return -1;
	view_range(a, &t0, &t1);
	*t = t0 + (t1 - t0) * (double)(x - r->x - LM) / (cw - 1);
	return 0;
}
