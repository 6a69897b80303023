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

struct mode;

struct app;

enum { SV_MAX_PINS = 3, SV_MAX_BOUNDS = 64, SV_MAP_ROW_BOUNDS = 16 };

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

/*
 * m: the 2-D map, the observable over the view's key (across, its range)
 * and the key swept before it (up, its range), computed one row at a time
 * by a background curve (sweep_map.c; the pane is pane_map.c).  With b on
 * (the view's bounds), each row locates its boundaries as the curve does.
 * The shades' range is fixed by the first row that has a value (zfixed),
 * so a shade means the same while the map computes.
 */
struct sv_map {
	int on;                  /* the view shows the map instead of the curve */
	int obs;                 /* the observable (enum hb_sweep_observable) */
	long coll;               /* and its collision */
	char key1[48], key2[48]; /* across, up */
	char spec1[160], spec2[160];
	int log1, log2;
	struct hb_sweep *rows;   /* key2's values: row j's scene */
	long n1, n2;             /* grid size */
	long row;                /* the row computing (n2: all done) */
	long done, failed;       /* grid points finished, failed */
	double *x1, *x2;         /* the keys' values, SI */
	double *z;               /* n1 * n2, row-major (i2 * n1 + i1) */
	int *st;                 /* HB_CURVE_* of each point */
	struct hb_sweep_curve *c;   /* the row computing */
	double *ry;
	int *rst;
	int jobs;                /* threads per row */
	int bounds;              /* rows locate their boundaries (SV_BOUND_TOL) */
	long *nb;                /* n2: boundaries found in each row (up to SV_MAP_ROW_BOUNDS kept) */
	double *blo, *bhi;       /* n2 * SV_MAP_ROW_BOUNDS: the parameter either side */
	int *bloc;               /* ... 1: located, 0: bisecting */
	int zfixed;              /* the shades' range is fixed: zlo .. zhi */
	int zrescaled;           /* ... by r, not by the first row */
	double zlo, zhi;
};

struct sweep_view {
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
	char prevkey[48];        /* the key swept before this one (m: the map's second key) */
	char prevspec[160];      /* and its range */
	struct sv_map map;
};

enum { SV_PROMPT_RANGE = 1, SV_PROMPT_EXPORT, SV_PROMPT_MAP_EXPORT };

/* sweep_map.c: starts the map (0, or -1 with the reason in msg), polls it
 * (1 while computing), writes it as CSV (i1,i2,KEY1,KEY2,OBS), frees it. */
int
sv_map_start(struct sweep_view *v, int jobs, char *msg, size_t n);
int
sv_map_tick(struct sv_map *m);
int
sv_map_write_csv(const struct sweep_view *v, const char *path, char *msg, size_t n);
void
sv_map_drop(struct sv_map *m);
/* Fixes the shades' range anew, to the values computed so far; -1 when there is none. */
int
sv_map_rescale(struct sv_map *m);

/* pane_map.c: draws the map and its legend. */
void
pane_map_draw(const struct app *a, const struct mode *self);

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
