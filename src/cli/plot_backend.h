/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_backend.h - what a renderer of figures provides to plot_draw.c:
 * lines, filled rectangles and dots, clipping and text, in points from the
 * top left of the figure.  One backend: cairo (plot_cairo.c), for PNG, PDF
 * and SVG.  The pgfplots source (plot_tex.c) is written from the model
 * itself, not drawn.
 */
#ifndef HYBOUNCE_CLI_PLOT_BACKEND_H
#define HYBOUNCE_CLI_PLOT_BACKEND_H

#include "plot_model.h"

struct plot_backend {
	void *ctx;
	void (*colour)(void *ctx, double r, double g, double b);
	/* width in points; dash lengths in points (n = 0: solid) */
	void (*pen)(void *ctx, double width, const double *dash, int n);
	void (*move_to)(void *ctx, double x, double y);
	void (*line_to)(void *ctx, double x, double y);
	void (*stroke)(void *ctx);
	void (*fill_rect)(void *ctx, double x, double y, double w, double h);
	void (*fill_dot)(void *ctx, double x, double y, double r);
	void (*clip)(void *ctx, double x, double y, double w, double h);
	void (*unclip)(void *ctx);
	/* plain text with its baseline's left end at (x, y), turned by angle
	 * radians counter-clockwise */
	void (*text)(void *ctx, double x, double y, double angle, double size, const char *s);
	double (*text_width)(void *ctx, const char *s, double size);
	/* a raster backend: (x, y) moved to the middle of its pixel and the
	 * width to whole pixels, so that a frame is a crisp line; NULL for
	 * vector output */
	void (*snap)(void *ctx, double *x, double *y, double *width);
};

/* Draws the figure (laid out) through b. */
void
plot_draw(const struct plot_figure *f, const struct plot_backend *b);

#endif
