/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_tex.h - a figure as pgfplots source (plot_tex.c).
 */
#ifndef HYBOUNCE_CLI_PLOT_TEX_H
#define HYBOUNCE_CLI_PLOT_TEX_H

#include <stddef.h>
#include <stdio.h>

#include "plot_model.h"

/*
 * Lays out fig (text widths estimated) and writes it as a standalone
 * LaTeX file to tex and its data to dat, which the .tex names datname
 * (a file name in the .tex's folder).  provenance: a comment line at the
 * top of both (NULL: none).  Returns 0, or -1 with msg (out of memory).
 */
int
plot_tex_write(struct plot_figure *fig, FILE *tex, FILE *dat, const char *datname,
               const char *provenance, char *msg, size_t n);

#endif
