/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fitov.h - the measured data the explorer shows (private to
 * overlay_fit.c, which loads and fits them, fitov_draw.c, which draws and
 * tabulates them, and overlay_rec.c, which draws a recording's strip).
 */
#ifndef HYBOUNCE_TUI_FITOV_H
#define HYBOUNCE_TUI_FITOV_H

#include "fit.h"
#include "onset.h"
#include "tui.h"

struct fitov {
	struct hb_fit_data d;
	int loaded;
	char path[512];
	size_t np;                 /* data points */
	struct hb_fit_point *pt;   /* the fit's points (hb_fit_data_points), in its order */
	double *sim;               /* simulated for `for_scene`, as pt (NAN: not computed) */
	long first;                /* sequences: the first trial's first given impact (-1: none) */
	struct hb_scene for_scene;    /* the scene sim[] was computed for */
	int sim_valid;
	char sim_err[256];         /* why sim[] is missing */
	struct hb_fit *fit;           /* a fit in progress, or NULL */
	char keys_text[256];       /* the free keys as typed */
	char keys_buf[256];
	const char *keys[HB_FIT_MAX_FREE];
	int nkeys, iter;
	double cost, cost0;
	long runs;
	char last[256];            /* the last fit's outcome, for the box */
	int top;                   /* first row shown in the box */
	struct hb_onset_result rec; /* a recording's onsets and envelope (rec.nenv 0: a CSV file) */
};

/* What is loaded, in words: the file and its kind of data (fitov_draw.c). */
void
fitov_describe(const struct fitov *f, char *buf, size_t n);

/* The run's first collision time, to align the measured clock; -1: none yet. */
double
fitov_first_te(const struct app *a);

#endif
