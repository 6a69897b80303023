/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_cmd.h - `hybounce fit`: fit a scene's parameters to measured data
 * (fit_cmd.c), a thin shell over the engine's fit.h and onset.h.
 *
 * Exit status: 0 the fit converged; 1 it stopped without converging
 * (iteration cap, no progress, parameters not identifiable, runs failing):
 * or an estimate's relative standard error above --max-relative-se: the
 * best point is still reported and written; 2 bad input (options, preset,
 * --set, data file, a recording that is no bouncing sequence, a start at
 * which the runs fail, an unwritable output): nothing is written (but
 * --onsets-out).
 */
#ifndef HYBOUNCE_CLI_FIT_H
#define HYBOUNCE_CLI_FIT_H

#include <stdio.h>
#include "hybounce/fit.h"

/* argv[0] is "fit".  Returns the exit status. */
int
fit_main(int argc, char **argv);

struct hb_onset_result;

/* The onsets of a recording, then the clicks dropped with their reason. */
void
fit_print_onsets(const char *path, const struct hb_onset_result *on);

/* hb_atomic_write_with's filler for --onsets-out: the t_e CSV, dropped
 * clicks as comments; ctx is the struct hb_onset_result. */
void
fit_fill_onsets(FILE *f, const void *ctx);

/* The text plot of measured against simulated values (fit_plot.c). */
void
fit_plot(FILE *f, const struct hb_fit_result *r, const struct hb_fit_data *d);

#endif
