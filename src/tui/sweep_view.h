/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_view.h - the explorer's sweep view (private to src/tui/): one
 * observable over one parameter, computed by background threads
 * (hb_sweep_curve_start), with pinned curves to compare laws.
 *
 * sweep_view.c owns the state and its keys; pane_sweep.c draws it;
 * sweep_obs.c has the observables' units and the current run's value.
 */
#ifndef HYBOUNCE_SWEEP_VIEW_H
#define HYBOUNCE_SWEEP_VIEW_H

#include "scene.h"
#include "sweep.h"

struct app;

enum { SV_MAX_PINS = 3, SV_MAX_BOUNDS = 64 };

/* b: boundaries located to this fraction of the range (hb_sweep_curve_start_refined). */
#define SV_BOUND_TOL 1e-3

/* One curve: the engine's computation and the last copy of its points. */
struct sv_curve {
	struct hb_sweep_curve *c;
	char label[64];          /* "shccl" (the law), shown in the legend */
	long n, done, failed;
	double *x, *y;
	int *st;
	long nb;                 /* boundaries found (the first SV_MAX_BOUNDS kept) */
	double blo[SV_MAX_BOUNDS], bhi[SV_MAX_BOUNDS]; /* the parameter either side */
	int bloc[SV_MAX_BOUNDS]; /* 1: located (one lattice step), 0: bisecting */
};

struct sweep_view {
	int open;                /* the view covers the plots */
	char key[48];            /* the parameter swept */
	char spec[160];          /* FROM:TO:N[:log] as typed */
	int log;                 /* the range is logarithmic */
	int obs;                 /* enum hb_sweep_observable */
	long coll;               /* collision index (0-based) for e, v_i, x_c^r */
	struct hb_scene base;       /* the scene the curve starts from (its law may differ) */
	struct sv_curve cur;     /* cur.c NULL: nothing computing (just pinned) */
	struct sv_curve pin[SV_MAX_PINS];
	int npins;
	int prompt;              /* what the open prompt is for: SV_PROMPT_* */
	int bounds;              /* b: locate the boundaries of the current curve */
};

enum { SV_PROMPT_RANGE = 1, SV_PROMPT_EXPORT };

/* SI base unit of an observable for axis labels ("m", "m/s", "s"), NULL for a plain number. */
struct hb_unit_dim
sv_obs_dim(int obs);
/* The same as text. */
const char *
sv_obs_unit(int obs);

/* The current scene's value of the observable (NAN when not computed yet). */
double
sv_current_y(const struct app *a, int obs, long coll);

#endif
