/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_model.c - the figure model: panels, axes and ticks, and the layout
 * in points (plot_model.h).  No plotting library, no engine run.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/units.h"
#include "cnum.h"
#include "plot_model.h"

/* Okabe-Ito (Color Universal Design), in an order whose neighbours differ
 * in lightness too; each with a dash pattern of its own. */
static const struct plot_style styles[] = {
	{ 0.000, 0.447, 0.698, { 0 }, 0 },                   /* blue, solid */
	{ 0.835, 0.369, 0.000, { 4, 2 }, 2 },                /* vermillion, dashed */
	{ 0.000, 0.620, 0.451, { 1, 1.5 }, 2 },              /* bluish green, dotted */
	{ 0.800, 0.475, 0.655, { 5, 2, 1, 2 }, 4 },          /* reddish purple, dash-dot */
	{ 0.902, 0.624, 0.000, { 8, 2.5 }, 2 },              /* orange, long dash */
	{ 0.337, 0.706, 0.914, { 2, 2 }, 2 },                /* sky blue, short dash */
	{ 0.000, 0.000, 0.000, { 1, 1.5, 6, 1.5 }, 4 },       /* black, dot-dash */
	{ 0.941, 0.894, 0.259, { 0 }, 0 },                   /* yellow, solid */
};

const double plot_shade_rgb[3] = { 0.85, 0.85, 0.85 };

const struct plot_style *
plot_style_of(int k)
{
	int n = (int)(sizeof styles / sizeof styles[0]);

	return &styles[((k % n) + n) % n];
}

void
plot_figure_init(struct plot_figure *f, double w, double h)
{
	memset(f, 0, sizeof *f);
	f->w = w;
	f->h = h;
	f->ncols = 1;
	/* 8 pt at a journal column (3.5 in = 252 pt), larger on a wider figure */
	f->font = 8 * sqrt(w > 252 ? w / 252 : 1);
	f->lw = f->font / 8;
}

void
plot_figure_free(struct plot_figure *f)
{
	for (int k = 0; k < f->npanels; k++) {
		struct plot_panel *p = &f->p[k];

		for (int i = 0; i < p->ns; i++) {
			free(p->s[i].x);
			free(p->s[i].y);
		}
		free(p->band0);
		free(p->band1);
		free(p->mx);
		free(p->my);
		free(p->mv);
	}
	f->npanels = 0;
}

static void
copy_str(char *dst, size_t n, const char *src)
{
	size_t l = src != NULL ? strlen(src) : 0;

	if (l >= n)
		l = n - 1;
	if (l > 0)
		memcpy(dst, src, l);
	dst[l] = '\0';
}

struct plot_panel *
plot_panel_add(struct plot_figure *f, const char *xtitle, const char *xunit,
               const char *ytitle, const char *yunit)
{
	struct plot_panel *p;

	if (f->npanels >= PLOT_MAX_PANELS)
		return NULL;
	p = &f->p[f->npanels++];
	memset(p, 0, sizeof *p);
	copy_str(p->xa.title, sizeof p->xa.title, xtitle);
	copy_str(p->xa.unit, sizeof p->xa.unit, xunit);   /* the SI base until fitted */
	copy_str(p->ya.title, sizeof p->ya.title, ytitle);
	copy_str(p->ya.unit, sizeof p->ya.unit, yunit);
	p->xlabels = 1;
	return p;
}

int
plot_series_add(struct plot_panel *p, const char *label, const double *x, const double *y,
                size_t n, int style, int line, int markers)
{
	struct plot_series *s;

	if (p->ns >= PLOT_MAX_SERIES)
		return -1;
	s = &p->s[p->ns];
	memset(s, 0, sizeof *s);
	s->x = malloc((n > 0 ? n : 1) * sizeof *s->x);
	s->y = malloc((n > 0 ? n : 1) * sizeof *s->y);
	if (s->x == NULL || s->y == NULL) {
		free(s->x);
		free(s->y);
		return -1;
	}
	if (n > 0) {
		memcpy(s->x, x, n * sizeof *x);
		memcpy(s->y, y, n * sizeof *y);
	}
	s->n = n;
	copy_str(s->label, sizeof s->label, label);
	s->style = style;
	s->line = line;
	s->markers = markers;
	p->ns++;
	return 0;
}

int
plot_bands_set(struct plot_panel *p, const double *a, const double *b, size_t n)
{
	free(p->band0);
	free(p->band1);
	p->nband = 0;
	p->band0 = malloc((n > 0 ? n : 1) * sizeof *a);
	p->band1 = malloc((n > 0 ? n : 1) * sizeof *b);
	if (p->band0 == NULL || p->band1 == NULL)
		return -1;
	if (n > 0) {
		memcpy(p->band0, a, n * sizeof *a);
		memcpy(p->band1, b, n * sizeof *b);
	}
	p->nband = n;
	return 0;
}

void
plot_legend_add(struct plot_figure *f, const char *label, int style, int line, int markers)
{
	struct plot_legend_entry *e;

	if (f->nlegend >= PLOT_MAX_LEGEND)
		return;
	e = &f->legend[f->nlegend++];
	copy_str(e->label, sizeof e->label, label);
	e->style = style;
	e->line = line;
	e->markers = markers;
}

/* ------------------------------------------------------------------ */

void
plot_ticks(double lo, double hi, int want, int whole, double *t, int *n)
{
	double span = hi - lo, raw, mag, step, first;
	static const double nice[] = { 1, 2, 2.5, 5, 10 };

	*n = 0;
	if (!(span > 0) || !isfinite(span))
		return;
	if (want < 2)
		want = 2;
	raw = span / want;
	mag = pow(10, floor(log10(raw)));
	step = 10 * mag;
	for (size_t k = 0; k < sizeof nice / sizeof nice[0]; k++)
		if (nice[k] * mag >= raw && !(whole && nice[k] == 2.5)) {
			step = nice[k] * mag;
			break;
		}
	if (whole && step < 1)
		step = 1;
	if (whole)
		step = ceil(step);
	first = ceil(lo / step - 1e-9) * step;
	for (double v = first; v <= hi + step * 1e-9 && *n < PLOT_MAX_TICKS; v += step) {
		double r = fabs(v) < step * 1e-9 ? 0 : v;   /* no "-0" or 1e-17 */

		t[(*n)++] = r;
		if (*n > 0 && v == v + step)
			break;
	}
}

/* Ticks of a log axis [lo, hi] (lo > 0): decades, or 1-2-5 where fewer
 * than two decades show, else linear ones. */
static void
log_ticks(double lo, double hi, double *t, int *n)
{
	static const double mult[] = { 1, 2, 5 };

	*n = 0;
	for (int pass = 0; pass < 2 && *n < 2; pass++) {
		*n = 0;
		for (int e = (int)floor(log10(lo)) - 1; e <= (int)ceil(log10(hi)) + 1; e++)
			for (int m = 0; m < (pass ? 3 : 1); m++) {
				double v = mult[m] * pow(10, e);

				if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9) && *n < PLOT_MAX_TICKS)
					t[(*n)++] = v;
			}
	}
	if (*n < 2)
		plot_ticks(lo, hi, 3, 0, t, n);
}

/* about `want` ticks on a's range, as its kind asks */
static void
axis_ticks(struct plot_axis *a, int want)
{
	if (a->log && a->lo > 0)
		log_ticks(a->lo, a->hi, a->tick, &a->nticks);
	else
		plot_ticks(a->lo, a->hi, want, a->whole, a->tick, &a->nticks);
}

/* "10^{3}", "2×10^{-4}": a tick of a log axis */
static void
log_label(double v, char *buf, size_t n)
{
	int e = (int)floor(log10(v) + 1e-9);
	double m = v / pow(10, e);
	char ex[16];

	if (e < 0)
		cnum_snprintf(ex, sizeof ex, "\xe2\x88\x92%d", -e);
	else
		cnum_snprintf(ex, sizeof ex, "%d", e);
	if (fabs(m - 1) < 1e-6)
		cnum_snprintf(buf, n, "10^{%s}", ex);
	else
		cnum_snprintf(buf, n, "%.3g\xc3\x97" "10^{%s}", m, ex);
}

/* The fewest decimals that tell the ticks apart, in the unit shown. */
static void
tick_labels(struct plot_axis *a)
{
	int dec = 0;

	if (a->scale == 0)
		a->scale = 1;
	if (a->log && a->lo > 0) {
		for (int k = 0; k < a->nticks; k++)
			log_label(a->tick[k] / a->scale, a->ticklabel[k], sizeof a->ticklabel[k]);
		return;
	}

	if (a->nticks >= 2) {
		double step = fabs(a->tick[1] - a->tick[0]) / a->scale;

		while (dec < 8 && fabs(step * pow(10, dec) - nearbyint(step * pow(10, dec))) >
		       1e-6 * step * pow(10, dec))
			dec++;
	}
	for (int k = 0; k < a->nticks; k++) {
		double v = a->tick[k] / a->scale;

		if (fabs(v) < 1e-12 * (fabs(a->hi - a->lo) / a->scale))
			v = 0;
		/* a minus sign, not a hyphen */
		if (v < 0) {
			memcpy(a->ticklabel[k], "\xe2\x88\x92", 3);
			cnum_snprintf(a->ticklabel[k] + 3, sizeof a->ticklabel[k] - 3, "%.*f", dec, -v);
		} else {
			cnum_snprintf(a->ticklabel[k], sizeof a->ticklabel[k], "%.*f", dec, v);
		}
	}
}

void
plot_axis_fit(struct plot_axis *a, double lo, double hi, const char *base, int keep, int want)
{
	double mag;
	char unit[24];

	if (base != a->base)
		copy_str(a->base, sizeof a->base, base);
	if (a->log && !(lo > 0 && hi > lo && isfinite(hi)))
		a->log = 0;   /* a range that is not positive: linear */
	if (a->log) {
		double pad = keep ? 1 : pow(hi / lo, 0.05);

		a->lo = lo / pad;
		a->hi = hi * pad;
		a->scale = 1;
		if (base[0] != '\0')
			hb_units_axis(1, base, a->unit, sizeof a->unit);
		else
			a->unit[0] = '\0';
		axis_ticks(a, want);
		tick_labels(a);
		return;
	}
	if (!keep) {
		if (!isfinite(lo) || !isfinite(hi)) {
			lo = 0;
			hi = 1;
		}
		/* a constant (up to rounding) is shown around its value */
		if (hi - lo <= 1e-9 * fmax(fabs(lo), fabs(hi))) {
			lo = hi = 0.5 * (lo + hi);
		}
		if (hi <= lo) {
			double c = lo, d = c != 0 ? fabs(c) * 0.1 : 1;

			lo = c - d;
			hi = c + d;
		} else {
			double pad = 0.05 * (hi - lo);

			/* a range that starts at 0 keeps 0 at its edge */
			lo = lo == 0 ? 0 : lo - pad;
			hi = hi == 0 ? 0 : hi + pad;
		}
		if (a->whole) {
			lo = floor(lo);
			hi = ceil(hi);
			if (hi - lo < 1)
				hi = lo + 1;
		}
	}
	a->lo = lo;
	a->hi = hi;
	mag = fmax(fabs(lo), fabs(hi));
	if (base[0] != '\0') {
		a->scale = hb_units_axis(mag > 0 ? mag : 1, base, unit, sizeof unit);
		/* the micro sign in a figure, where the tables write "u" */
		if (unit[0] == 'u' && unit[1] != '\0' && strcmp(base, "u") != 0)
			cnum_snprintf(a->unit, sizeof a->unit, "\xc2\xb5%s", unit + 1);
		else
			copy_str(a->unit, sizeof a->unit, unit);
	} else if (!a->whole && mag > 0 && (mag < 1e-2 || mag >= 1e4)) {
		/* a pure number far from 1: a power of ten, as the SI
		 * prefixes step, named in the unit's place */
		int e = (int)floor(log10(mag) / 3) * 3;

		a->scale = pow(10, e);
		cnum_snprintf(a->unit, sizeof a->unit, "10^{%d}", e);
	} else {
		a->scale = 1;
		a->unit[0] = '\0';
	}
	plot_ticks(lo, hi, want, a->whole, a->tick, &a->nticks);
	tick_labels(a);
}

/* ------------------------------------------------------------------ */

int
plot_markup(const char *s, struct plot_run *runs, int max)
{
	int n = 0, kind = 0;
	size_t len = 0;

	if (max <= 0)
		return 0;
	runs[0].text[0] = '\0';
	runs[0].kind = 0;
	while (*s != '\0' && n < max) {
		if ((*s == '_' || *s == '^') && s[1] != '\0') {
			int k = *s == '_' ? 1 : 2;
			const char *e;

			if (len > 0 && ++n >= max)
				break;
			s++;
			if (*s == '{') {
				e = strchr(s, '}');
				s++;
			} else {
				e = s + strcspn(s, "_^ ()");
			}
			if (e == NULL)
				e = s + strlen(s);
			len = (size_t)(e - s) < sizeof runs[n].text ? (size_t)(e - s)
			                                             : sizeof runs[n].text - 1;
			memcpy(runs[n].text, s, len);
			runs[n].text[len] = '\0';
			runs[n].kind = k;
			s = *e == '}' ? e + 1 : e;
			/* a superscript right after a subscript stacks over it */
			if (++n >= max)
				break;
			len = 0;
			runs[n].text[0] = '\0';
			runs[n].kind = kind;
			continue;
		}
		if (len + 1 < sizeof runs[n].text) {
			runs[n].text[len++] = *s;
			runs[n].text[len] = '\0';
		}
		s++;
	}
	return n < max && len > 0 ? n + 1 : n;
}

/* The width of markup text at size (scripts at 0.7 of it). */
double
plot_text_width(const char *markup, double size,
                double (*text_width)(void *ctx, const char *s, double size), void *ctx)
{
	struct plot_run r[16];
	int n = plot_markup(markup, r, 16);
	double w = 0, sub = 0;

	for (int k = 0; k < n; k++) {
		double sz = r[k].kind ? 0.7 * size : size, rw;

		if (text_width != NULL) {
			rw = text_width(ctx, r[k].text, sz);
		} else {
			size_t chars = 0;

			for (const char *c = r[k].text; *c; c++)
				chars += ((unsigned char)*c & 0xc0) != 0x80;
			rw = 0.55 * sz * (double)chars;
		}
		/* a superscript over the subscript before it */
		if (r[k].kind == 2 && k > 0 && r[k - 1].kind == 1) {
			w += fmax(0, rw - sub);
			sub = 0;
			continue;
		}
		sub = r[k].kind == 1 ? rw : 0;
		w += rw;
	}
	return w;
}

/* "x_c (µm)", "e", "i" */
static void
axis_label(const struct plot_axis *a, char *buf, size_t n)
{
	if (a->unit[0] != '\0')
		cnum_snprintf(buf, n, "%s (%s)", a->title, a->unit);
	else
		cnum_snprintf(buf, n, "%s", a->title);
}

void
plot_figure_layout(struct plot_figure *f, double (*text_width)(void *ctx, const char *s,
                   double size), void *ctx)
{
	const double fs = f->font, pad = 0.5 * fs;
	int ncols = f->ncols > 0 ? f->ncols : 1, nrows, r, c;
	double top = pad, right_pad = 1.2 * fs, row_h, ygap, xlab_h;
	double colw;

	/* a colour legend (the last panel) takes a strip at the right: the
	 * grid is laid out in what is left of the width, then it beside its map */
	const int cbar = f->npanels >= 2 && f->p[f->npanels - 1].colorbar;
	const int np = f->npanels - cbar;
	const double full_w = f->w;
	double strip = 0;

	if (cbar) {
		struct plot_panel *b = &f->p[f->npanels - 1];
		double tw = 0;

		for (int t = 0; t < b->ya.nticks; t++)
			tw = fmax(tw, plot_text_width(b->ya.ticklabel[t], fs, text_width, ctx));
		strip = 0.8 * fs + 1.0 * fs + 0.4 * fs + tw + 0.5 * fs + 1.4 * fs;
		f->w -= strip;
	}
	nrows = (np + ncols - 1) / ncols;
	if (nrows < 1) {
		f->w = full_w;
		return;
	}
	if (f->title[0] != '\0')
		top += 1.5 * fs;

	/* the legend: entries in rows across the figure */
	f->lx = pad;
	f->ly = top;
	f->lw_box = f->w - 2 * pad;
	f->lh_box = 0;
	if (f->nlegend > 0) {
		double x = 0, rows = 1;

		for (int k = 0; k < f->nlegend; k++) {
			double ew = 2.5 * fs + 0.4 * fs +
			            plot_text_width(f->legend[k].label, fs, text_width, ctx) + fs;

			if (x > 0 && x + ew > f->lw_box) {
				rows++;
				x = 0;
			}
			x += ew;
		}
		f->lh_box = rows * 1.4 * fs + 0.3 * fs;
		top += f->lh_box + 0.3 * fs;
	}
	top += 0.5 * fs;   /* room for the top tick label's half height */

	/* the left margin of each column: its widest y tick label, then the
	 * rotated y title */
	double left[PLOT_MAX_PANELS] = { 0 };

	for (int k = 0; k < np; k++) {
		struct plot_panel *p = &f->p[k];

		for (int t = 0; t < p->ya.nticks; t++) {
			double w = plot_text_width(p->ya.ticklabel[t], fs, text_width, ctx);

			if (w > left[k % ncols])
				left[k % ncols] = w;
		}
	}
	for (c = 0; c < ncols; c++)
		left[c] += 0.4 * fs + 1.4 * fs + 0.3 * fs;   /* tick gap, title height, edge */
	xlab_h = 1.2 * fs + 0.3 * fs + 1.3 * fs;       /* tick labels, gap, title */
	ygap = 1.0 * fs;
	colw = (f->w - pad) / ncols;
	{
		double avail = f->h - top - pad, fixed = 0;

		for (r = 0; r < nrows; r++) {
			int last = r == nrows - 1, shows = 0;

			for (c = 0; c < ncols && r * ncols + c < np; c++)
				shows |= f->p[r * ncols + c].xlabels;
			fixed += shows ? xlab_h + (last ? 0 : ygap) : (last ? 0 : ygap);
		}
		row_h = (avail - fixed) / nrows;
		if (row_h < 2 * fs)
			row_h = 2 * fs;
	}
	{
		double y = top;

		for (r = 0; r < nrows; r++) {
			int shows = 0;

			for (c = 0; c < ncols && r * ncols + c < np; c++) {
				struct plot_panel *p = &f->p[r * ncols + c];

				p->fx = c * colw + left[c];
				p->fy = y;
				p->fw = colw - left[c] - right_pad;
				p->fh = row_h;
				shows |= p->xlabels;
			}
			y += row_h + (shows ? xlab_h : 0) + ygap;
		}
	}
	f->w = full_w;
	if (cbar) {
		struct plot_panel *b = &f->p[f->npanels - 1], *m = &f->p[f->npanels - 2];

		b->fx = m->fx + m->fw + 0.8 * fs;
		b->fy = m->fy;
		b->fw = 1.0 * fs;
		b->fh = m->fh;
		b->xlabels = 0;
	}
	/* ticks again for the frame's size: about one per 2.5 em of height,
	 * one per 5 em of width */
	for (int k = 0; k < f->npanels; k++) {
		struct plot_panel *p = &f->p[k];
		int wy = (int)(p->fh / (2.2 * fs)), wx = (int)(p->fw / (5 * fs));

		axis_ticks(&p->ya, wy < 2 ? 2 : wy);
		tick_labels(&p->ya);
		if (p->colorbar)
			continue;   /* a colour legend has no x ticks */
		axis_ticks(&p->xa, wx < 2 ? 2 : wx);
		tick_labels(&p->xa);
	}
}

double
plot_axis_pos(const struct plot_axis *a, double v)
{
	if (a->log && a->lo > 0)
		return v > 0 ? log10(v / a->lo) / log10(a->hi / a->lo) : NAN;
	return (v - a->lo) / (a->hi - a->lo);
}

void
plot_axis_label(const struct plot_axis *a, char *buf, size_t n)
{
	axis_label(a, buf, n);
}
