/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_draw.c - draws a laid-out figure model through a backend
 * (plot_backend.h): shaded intervals, curves and dots, frames with inward
 * ticks, tick labels, axis titles with units, the legend.
 */
#include <math.h>
#include <stddef.h>

#include "plot_backend.h"

/* Markup text; (ax, ay): anchor along and across the text (0 start/baseline
 * bottom, 0.5 centre, 1 end/top). */
static void
draw_text(const struct plot_backend *b, double x, double y, double angle, double size,
          const char *markup, double ax, double ay)
{
	struct plot_run r[16];
	int n = plot_markup(markup, r, 16);
	double w = plot_text_width(markup, size, b->text_width, b->ctx);
	double dx = cos(angle), dy = -sin(angle);      /* along the baseline */
	double ux = -sin(angle), uy = -cos(angle);     /* up */
	double along = -ax * w, up = -ay * 0.7 * size, sub = 0;

	x += along * dx + up * ux;
	y += along * dy + up * uy;
	for (int k = 0; k < n; k++) {
		double sz = r[k].kind ? 0.7 * size : size;
		double lift = r[k].kind == 1 ? -0.22 * size : r[k].kind == 2 ? 0.38 * size : 0;
		double rw = b->text_width(b->ctx, r[k].text, sz);

		/* a superscript right after a subscript stacks over it */
		if (r[k].kind == 2 && k > 0 && r[k - 1].kind == 1) {
			x -= sub * dx;
			y -= sub * dy;
		}
		b->text(b->ctx, x + lift * ux, y + lift * uy, angle, sz, r[k].text);
		if (r[k].kind == 2 && k > 0 && r[k - 1].kind == 1)
			rw = fmax(rw, sub);
		x += rw * dx;
		y += rw * dy;
		sub = r[k].kind == 1 ? rw : 0;
	}
}

/* x of value v in panel p, in points (a log axis by its logarithm) */
static double
px_of(const struct plot_panel *p, double v)
{
	return p->fx + plot_axis_pos(&p->xa, v) * p->fw;
}

static double
py_of(const struct plot_panel *p, double v)
{
	return p->fy + p->fh - plot_axis_pos(&p->ya, v) * p->fh;
}

static void
draw_series(const struct plot_figure *f, const struct plot_panel *p,
            const struct plot_series *s, const struct plot_backend *b)
{
	const struct plot_style *st = plot_style_of(s->style);
	double dash[4];
	int open = 0;

	for (int k = 0; k < st->ndash; k++)
		dash[k] = st->dash[k] * f->lw;
	b->colour(b->ctx, st->r, st->g, st->b);
	if (s->line) {
		/*
		 * Consecutive points within one column of 0.25 pt are drawn
		 * as their first, lowest, highest and last (in their order):
		 * the same picture at any resolution up to 300 dpi, from a
		 * few thousand points where an arc has a hundred thousand.
		 */
		const double col = 0.25;
		double bx = NAN, py[4], px[4];
		int k = 0;

		b->pen(b->ctx, f->lw, dash, st->ndash);
		for (size_t i = 0; i <= s->n; i++) {
			int fin = i < s->n && isfinite(s->x[i]) && isfinite(s->y[i]);
			double x = fin ? px_of(p, s->x[i]) : NAN;
			double y = fin ? py_of(p, s->y[i]) : NAN;

			fin = fin && isfinite(x) && isfinite(y);   /* <= 0 on a log axis */
			if (fin && k > 0 && floor(x / col) == bx) {
				/* 0 first, 1 min, 2 max, 3 last */
				if (y < py[1]) {
					py[1] = y;
					px[1] = x;
				}
				if (y > py[2]) {
					py[2] = y;
					px[2] = x;
				}
				py[3] = y;
				px[3] = x;
				k = 4;
				continue;
			}
			/* the column ends: its points, extremes in their order */
			if (k > 0) {
				int a = 1, c = 2;

				if (k == 4 && px[1] > px[2]) {
					a = 2;
					c = 1;
				}
				for (int j = 0; j < k; j++) {
					int q = k == 4 ? (j == 1 ? a : j == 2 ? c : j) : j;

					if (open)
						b->line_to(b->ctx, px[q], py[q]);
					else
						b->move_to(b->ctx, px[q], py[q]);
					open = 1;
				}
			}
			if (!fin) {
				open = 0;
				k = 0;
				continue;
			}
			bx = floor(x / col);
			px[0] = px[1] = px[2] = px[3] = x;
			py[0] = py[1] = py[2] = py[3] = y;
			k = 1;
		}
		b->stroke(b->ctx);
	}
	if (s->markers)
		for (size_t i = 0; i < s->n; i++)
			if (isfinite(s->x[i]) && isfinite(s->y[i]))
				b->fill_dot(b->ctx, px_of(p, s->x[i]),
				            py_of(p, s->y[i]),
				            1.6 * f->lw);
}

/*
 * The size of the y titles: the text size, or smaller (down to 0.6 of it)
 * where a title is longer than its panel is high (a slide of many short
 * panels), the same for every panel.
 */
static double
ytitle_size(const struct plot_figure *f, const struct plot_backend *b)
{
	double size = f->font;
	char lab[96];

	for (int k = 0; k < f->npanels; k++) {
		const struct plot_panel *p = &f->p[k];
		double tw;

		plot_axis_label(&p->ya, lab, sizeof lab);
		tw = plot_text_width(lab, f->font, b->text_width, b->ctx);
		if (tw > p->fh)
			size = fmin(size, fmax(f->font * p->fh / tw, 0.6 * f->font));
	}
	return size;
}

/*
 * A heat map's cells, each a rectangle of its colour, drawn from the top
 * row down and from left to right, each reaching over the next cell to
 * its right and the one below it, which are drawn after it: an edge
 * between two cells blends their colours, never the white beneath (as
 * cells that merely touch would at a fraction of a pixel).
 */
static void
draw_map(const struct plot_panel *p, const struct plot_backend *b)
{
	for (size_t jj = p->mny; jj-- > 0;) {
		double top = py_of(p, p->my[jj + 1]), bot = py_of(p, p->my[jj > 0 ? jj - 1 : 0]);

		for (size_t i = 0; i < p->mnx; i++) {
			double x0 = px_of(p, p->mx[i]);
			double x1 = px_of(p, p->mx[i + 2 <= p->mnx ? i + 2 : p->mnx]), rgb[3];
			double v = p->mv[jj * p->mnx + i];

			if (!isfinite(v) || !isfinite(x0) || !isfinite(x1) || !isfinite(top) ||
			    !isfinite(bot))
				continue;
			/* a cell without value is white: so is what reaches into it */
			if (i + 1 < p->mnx && (!isfinite(p->mv[jj * p->mnx + i + 1]) ||
			                       (jj > 0 && !isfinite(p->mv[(jj - 1) * p->mnx + i + 1]))))
				x1 = px_of(p, p->mx[i + 1]);
			if (jj > 0 && !isfinite(p->mv[(jj - 1) * p->mnx + i]))
				bot = py_of(p, p->my[jj]);
			plot_map_colour(p, v, rgb);
			b->colour(b->ctx, rgb[0], rgb[1], rgb[2]);
			b->fill_rect(b->ctx, fmin(x0, x1), fmin(top, bot), fabs(x1 - x0),
			             fabs(bot - top));
			bot = py_of(p, p->my[jj > 0 ? jj - 1 : 0]);
		}
	}
}

static void
draw_panel(const struct plot_figure *f, const struct plot_panel *p,
           const struct plot_backend *b, double ysize)
{
	const double fs = f->font, tl = 0.35 * fs, frame = 0.5 * f->lw;
	char lab[96];

	b->clip(b->ctx, p->fx, p->fy, p->fw, p->fh);
	if (p->nband > 0) {
		b->colour(b->ctx, plot_shade_rgb[0], plot_shade_rgb[1], plot_shade_rgb[2]);
		for (size_t k = 0; k < p->nband; k++) {
			double x0 = px_of(p, p->band0[k]);
			double x1 = px_of(p, p->band1[k]);
			/* at least a hairline: a contact of a microsecond on a
			 * second's axis still shows */
			double w = fmax(x1 - x0, 0.75 * f->lw);

			b->fill_rect(b->ctx, 0.5 * (x0 + x1) - 0.5 * w, p->fy, w, p->fh);
		}
	}
	if (p->mnx > 0 && p->mny > 0)
		draw_map(p, b);
	for (int k = 0; k < p->ns; k++)
		draw_series(f, p, &p->s[k], b);
	b->unclip(b->ctx);

	/* the frame and its inward ticks, on all four sides */
	{
		double x0 = p->fx, y0 = p->fy, x1 = p->fx + p->fw, y1 = p->fy + p->fh, fw = frame;

		if (b->snap != NULL) {
			b->snap(b->ctx, &x0, &y0, &fw);
			b->snap(b->ctx, &x1, &y1, &fw);
		}
		b->colour(b->ctx, 0, 0, 0);
		b->pen(b->ctx, fw, NULL, 0);
		b->move_to(b->ctx, x0, y0);
		b->line_to(b->ctx, x1, y0);
		b->line_to(b->ctx, x1, y1);
		b->line_to(b->ctx, x0, y1);
		b->line_to(b->ctx, x0, y0);
		b->stroke(b->ctx);
		b->pen(b->ctx, frame, NULL, 0);
	}
	for (int k = 0; k < p->xa.nticks; k++) {
		double x = px_of(p, p->xa.tick[k]);

		b->move_to(b->ctx, x, p->fy + p->fh);
		b->line_to(b->ctx, x, p->fy + p->fh - tl);
		b->move_to(b->ctx, x, p->fy);
		b->line_to(b->ctx, x, p->fy + tl);
	}
	for (int k = 0; k < p->ya.nticks; k++) {
		double y = py_of(p, p->ya.tick[k]);

		if (p->colorbar) {   /* outward on its right: the colours stay whole */
			b->move_to(b->ctx, p->fx + p->fw, y);
			b->line_to(b->ctx, p->fx + p->fw + 0.6 * tl, y);
			continue;
		}
		b->move_to(b->ctx, p->fx, y);
		b->line_to(b->ctx, p->fx + tl, y);
		b->move_to(b->ctx, p->fx + p->fw, y);
		b->line_to(b->ctx, p->fx + p->fw - tl, y);
	}
	b->stroke(b->ctx);

	/* labels; a colour legend's on its right */
	if (p->colorbar) {
		double wmax = 0;

		for (int k = 0; k < p->ya.nticks; k++) {
			double y = py_of(p, p->ya.tick[k]);

			draw_text(b, p->fx + p->fw + 0.4 * fs, y, 0, fs, p->ya.ticklabel[k], 0, 0.5);
			wmax = fmax(wmax, plot_text_width(p->ya.ticklabel[k], fs, b->text_width, b->ctx));
		}
		plot_axis_label(&p->ya, lab, sizeof lab);
		draw_text(b, p->fx + p->fw + 0.4 * fs + wmax + 0.5 * fs + 0.7 * fs,
		          p->fy + p->fh / 2, M_PI / 2, ysize, lab, 0.5, 0.5);
		return;
	}
	for (int k = 0; k < p->ya.nticks; k++) {
		double y = py_of(p, p->ya.tick[k]);

		draw_text(b, p->fx - 0.4 * fs, y, 0, fs, p->ya.ticklabel[k], 1, 0.5);
	}
	plot_axis_label(&p->ya, lab, sizeof lab);
	{
		double wmax = 0;

		for (int k = 0; k < p->ya.nticks; k++)
			wmax = fmax(wmax, plot_text_width(p->ya.ticklabel[k], fs, b->text_width, b->ctx));
		draw_text(b, p->fx - 0.4 * fs - wmax - 0.5 * fs, p->fy + p->fh / 2, M_PI / 2, ysize,
		          lab, 0.5, 0);
	}
	if (p->xlabels) {
		for (int k = 0; k < p->xa.nticks; k++) {
			double x = px_of(p, p->xa.tick[k]);

			draw_text(b, x, p->fy + p->fh + 0.3 * fs, 0, fs, p->xa.ticklabel[k], 0.5, 1);
		}
		plot_axis_label(&p->xa, lab, sizeof lab);
		draw_text(b, p->fx + p->fw / 2, p->fy + p->fh + 1.5 * fs, 0, fs, lab, 0.5, 1);
	}
}

static void
draw_legend(const struct plot_figure *f, const struct plot_backend *b)
{
	const double fs = f->font;
	double x = f->lx, y = f->ly + 0.3 * fs + 0.7 * fs;

	for (int k = 0; k < f->nlegend; k++) {
		const struct plot_legend_entry *e = &f->legend[k];
		double ew = 2.5 * fs + 0.4 * fs + plot_text_width(e->label, fs, b->text_width, b->ctx);

		if (x > f->lx && x + ew > f->lx + f->lw_box) {
			x = f->lx;
			y += 1.4 * fs;
		}
		if (e->style < 0) {
			b->colour(b->ctx, plot_shade_rgb[0], plot_shade_rgb[1], plot_shade_rgb[2]);
			b->fill_rect(b->ctx, x, y - 0.5 * fs, 2.5 * fs, fs);
		} else {
			const struct plot_style *st = plot_style_of(e->style);
			double dash[4];

			for (int i = 0; i < st->ndash; i++)
				dash[i] = st->dash[i] * f->lw;
			b->colour(b->ctx, st->r, st->g, st->b);
			if (e->line) {
				b->pen(b->ctx, f->lw, dash, st->ndash);
				b->move_to(b->ctx, x, y);
				b->line_to(b->ctx, x + 2.5 * fs, y);
				b->stroke(b->ctx);
			}
			if (e->markers)
				b->fill_dot(b->ctx, x + 1.25 * fs, y, 1.6 * f->lw);
		}
		b->colour(b->ctx, 0, 0, 0);
		draw_text(b, x + 2.9 * fs, y, 0, fs, e->label, 0, 0.5);
		x += ew + fs;
	}
}

void
plot_draw(const struct plot_figure *f, const struct plot_backend *b)
{
	const double ysize = ytitle_size(f, b);

	b->colour(b->ctx, 1, 1, 1);
	b->fill_rect(b->ctx, 0, 0, f->w, f->h);
	if (f->title[0] != '\0') {
		b->colour(b->ctx, 0, 0, 0);
		draw_text(b, f->w / 2, 0.5 * f->font, 0, f->font, f->title, 0.5, 1);
	}
	for (int k = 0; k < f->npanels; k++)
		draw_panel(f, &f->p[k], b, ysize);
	if (f->nlegend > 0)
		draw_legend(f, b);
}
