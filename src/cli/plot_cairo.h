/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_cairo.h - figures as PNG, PDF and SVG through cairo (plot_cairo.c).
 */
#ifndef HYBOUNCE_CLI_PLOT_CAIRO_H
#define HYBOUNCE_CLI_PLOT_CAIRO_H

#include <stddef.h>
#include <stdio.h>

#include "plot_model.h"

enum plot_format { PLOT_PNG, PLOT_PDF, PLOT_SVG, PLOT_TEX };

/*
 * Lays out f and writes it to out as fmt (PNG at dpi pixels per inch).
 * Returns 0, or -1 with msg set (libcairo missing, a write error).
 */
int
plot_cairo_write(struct plot_figure *f, enum plot_format fmt, double dpi, FILE *out,
                 char *msg, size_t n);

#endif
