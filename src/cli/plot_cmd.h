/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_cmd.h - `hybounce plot` (plot_cmd.c) and the figures it builds from
 * a run (plot_figures.c).
 */
#ifndef HYBOUNCE_CLI_PLOT_CMD_H
#define HYBOUNCE_CLI_PLOT_CMD_H

#include <stddef.h>

#include "plot_model.h"

struct hb_sim;

enum plot_kind { PLOT_STATE, PLOT_OBSERVABLES, PLOT_LOOP };

/* hybounce plot ARGS (argv[0] is "plot"); returns the exit status. */
int
plot_main(int argc, char **argv);

/*
 * The figure of a finished (or stopped) run: w x h points (h <= 0: from
 * the kind); for PLOT_LOOP the collisions coll[0 .. ncoll-1] by index i
 * (ncoll 0: the first three).  Returns 0, or -1 with msg (no such
 * collision, out of memory).
 */
int
plot_build(struct plot_figure *f, enum plot_kind kind, const struct hb_sim *s, double w,
           double h, const long *coll, int ncoll, char *msg, size_t n);

#endif
