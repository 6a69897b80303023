/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_summary.h - what the plots draw of a long arc, at a cost that does
 * not grow with it (plot_summary.c).
 *
 * For each run drawn, the minimum and maximum of x, x_c and F_c over
 * blocks of 8, 64 and 512 samples (a three-level pyramid), brought
 * up to date as the arc grows (only the new samples are read) and built
 * again when the arc changed under it (a restart, an edit, a branch,
 * thinning).  A range of samples then has its extremes in at most about
 * 50 reads, and a plot column its vertical stroke: a frame costs the
 * pixel columns drawn, not the samples.  And a plot whose runs and range
 * did not change since the last frame (playback moves only the cursor) is
 * not drawn again: its canvas is kept (psum_plot_get, psum_plot_put).
 */
#ifndef HYBOUNCE_TUI_PLOT_SUMMARY_H
#define HYBOUNCE_TUI_PLOT_SUMMARY_H

#include <stddef.h>

#include "arc.h"
#include "sim.h"
#include "canvas.h"

struct plot_sums;   /* the summaries of the runs drawn, owned by struct app (psum) */
struct plot_sum;    /* one run's */

enum { PSUM_NQ = 3 };   /* x, x_c, F_c: pane_plot.c's Q_X, Q_XC, Q_FC */
enum { PSUM_MAXRUNS = 4 };   /* APP_MAX_PINS + 1 */

/* Quantity q of a sample: 0 x, 1 x_c, 2 F_c. */
double
psum_value(const struct hb_arc_sample *s, int q);

/* Room for the summaries of the runs drawn (NULL on no memory: every sample is drawn). */
struct plot_sums *
psum_new(void);

/* s's summary, up to date; NULL when ps is NULL or on no memory. */
const struct plot_sum *
psum_of(struct plot_sums *ps, const struct hb_sim *s);

/* Widens [*lo, *hi] to the finite values of quantity q of samples [i0, i1). */
void
psum_range(const struct plot_sum *p, size_t i0, size_t i1, int q, double *lo, double *hi);

/*
 * Draws quantity q against t over [t0, t1] into c, one stroke per pixel
 * column from the smallest to the largest value in it, joined to the
 * samples either side, in ink.
 */
void
psum_draw(const struct plot_sum *p, struct canvas *c, int q, double t0, double t1, int ink);

/*
 * What a plot shows: two plots with equal views draw the same canvas.  The
 * runs are named by their simulator, arc length and last sample, so that a
 * run that changed (computed further, restarted, edited) is another view.
 */
struct psum_view {
	int q, view, w, h, braille, n;
	double t0, t1;
	const struct hb_sim *sim[PSUM_MAXRUNS];
	size_t len[PSUM_MAXRUNS];
	double last_t[PSUM_MAXRUNS], last_x[PSUM_MAXRUNS], mid_x[PSUM_MAXRUNS];
	int ink[PSUM_MAXRUNS];
};
void
psum_view_of(struct psum_view *v, int q, int view, double t0, double t1, int w, int h,
             int braille, const struct hb_sim *const *s, const int *ink, int n);

/* Last frame's canvas and axis of plot v.q when it showed v (borrowed), else NULL. */
struct canvas *
psum_plot_get(struct plot_sums *ps, const struct psum_view *v, struct axis *ay);

/* Keeps c (the cache takes it: 0) and its axis as plot v.q's for the next frame; -1: not kept. */
int
psum_plot_put(struct plot_sums *ps, const struct psum_view *v, struct canvas *c,
              const struct axis *ay);

void
psum_free(struct plot_sums *ps);

#endif
