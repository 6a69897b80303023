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
struct hb_outputs;
struct hb_fit_result;
struct hb_fit_data;

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

struct plot_out;

/*
 * The figure of kind of the run s (3.5 in wide) written to o (plot_out.h:
 * registered with pol): the --plot of batch.  Returns 0, or -1 with msg.
 */
int
plot_write_run(struct plot_out *o, const struct hb_outputs *pol, enum plot_kind kind,
               const struct hb_sim *s, char *msg, size_t n);

/*
 * --width, --size and --dpi (each NULL when not given) into a figure's
 * w x h points (h -1: from the kind) and a PNG's dpi: 0, or -1 with msg
 * naming the option and what it accepts.
 */
int
plot_size_parse(const char *width_s, const char *size_s, const char *dpi_s, double *w,
                double *h, double *dpi, char *msg, size_t n);

/*
 * The figure of a sweep (plot_sweep.c) from its folder dir (or its
 * runs.csv): the observable obs (NULL: e) against the varied key, one
 * curve per collision index coll[0 .. ncoll-1] (ncoll 0: the first four)
 * for a collision's observable (a collisions.csv column: e, v_i, t_d ...),
 * one curve for a run's (a runs.csv column: e_first, t_pc ...); over two
 * varied keys a heat map of one collision (coll[0], default 0) with its
 * colour legend.  The files read are declared inputs of pol (outputs.h).
 * Returns 0, or -1 with msg (what is wrong and what is accepted).
 */
int
plot_build_sweep(struct plot_figure *f, const char *dir, const char *obs, const long *coll,
                 int ncoll, double w, double h, struct hb_outputs *pol, char *msg, size_t n);

/*
 * The figure of a fit (plot_fit.c): per observable fitted, the measured
 * values and the fitted run's (a sequence: the interval before each
 * impact against its index i; drops: e, x_c^r, t_d against |v_i|), the
 * residuals (fitted - measured; a sequence: of t_e) in a panel below.
 * w x h points (h <= 0: from the observables).  0, or -1 with msg.
 */
int
plot_build_fit(struct plot_figure *f, const struct hb_fit_result *r,
               const struct hb_fit_data *d, double w, double h, char *msg, size_t n);

/* plot_build_fit (3.5 in wide) written to o (registered with pol): fit --plot. */
int
plot_write_fit(struct plot_out *o, const struct hb_outputs *pol, const struct hb_fit_result *r,
               const struct hb_fit_data *d, char *msg, size_t n);

/*
 * Several runs in one figure (plot_compare.c): the figure of kind of each
 * run s[0 .. n-1] (n <= PLOT_MAX_SERIES), their curves in the first run's
 * panels, run k in style k, labels[k] its legend entry; a loop of
 * collision coll of each.  0, or -1 with msg.
 */
int
plot_build_compare(struct plot_figure *f, enum plot_kind kind, const struct hb_sim *const *s,
                   const char *const *labels, int n, double w, double h, long coll, char *msg,
                   size_t mn);

struct hb_scene;

/*
 * The legend of runs of the scenes sc[0 .. n-1]: what differs between them,
 * "law.c = 2 kN s/m, law.alpha = 0.3" (the keys every scene has whose
 * values differ, at most three, derived ones and the scene's name left
 * out); the names (names[k], their presets) where they differ and so do
 * more than three keys, or where no key differs.
 */
void
plot_compare_labels(const struct hb_scene *const *sc, const char *const *names, int n,
                    char (*labels)[64]);

#endif
