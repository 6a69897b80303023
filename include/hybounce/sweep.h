/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep.h - parameter sweeps: the Cartesian product of varied scene values,
 * run on every core, resumable, in shards for a cluster.
 *
 *     struct hb_sweep *sw = hb_sweep_new(&scene, msg, sizeof msg);  // preset + --set
 *     hb_sweep_vary(sw, "law.c=1e8:1e10:50:log", msg, sizeof msg);
 *     hb_sweep_check(sw, msg, sizeof msg);           // every point valid? (optional)
 *     hb_sweep_run(sw, &opts, msg, sizeof msg);     // DIR/runs.csv, collisions.csv
 *     hb_sweep_free(sw);
 *
 * Points.  Axis k holds n_k values; point ids run over the product in
 * row-major order, the last --vary varying fastest.  The scene of a point
 * is the base scene with each axis's value applied by hb_scene_set() in the
 * order of the axes, so it equals the scene of
 *     hybounce --batch SPEC.preset --set KEY1=V1 --set KEY2=V2 ...
 * with the values as runs.csv shows them (%.17g SI numbers, which hb_scene_set
 * reads back to the same doubles), and the results are bit-identical.
 *
 * Spec values: FROM:TO:N (N values, evenly spaced, both ends included),
 * FROM:TO:N:log (evenly spaced logarithms; FROM and TO of the same sign,
 * not 0), or V1,V2,... (each value as --set takes it; units allowed: "40 um").
 *
 * Files in DIR (see hb_sweep_run):
 *     sweep.preset     the base scene, then one "; sweep: --vary KEY=SPEC"
 *                      line per axis (and "; sweep: --refine", "; sweep:
 *                      --error" lines): it reproduces the sweep, and a DIR
 *                      holding another sweep is refused;
 *     runs.csv         one row per point, sorted by id;
 *     collisions.csv   id, then the columns of --collisions;
 *     *.journal        points done so far (one per shard), appended one
 *                      whole point at a time; what a restart reads;
 *     boundaries.csv   (a refined sweep) the pairs of neighbouring points
 *                      whose classes differ;
 *     sweep.h5 ...     instead of runs.csv and collisions.csv, what a sink
 *                      writes (hb_sweep_sink; hybounce sweep --format hdf5).
 *
 * Re-entrancy: a point uses only its own scene, sim and buffers; the
 * engine keeps no mutable static state and writes no process-wide state
 * (sim.h), so a sweep's threads share nothing but the sweep itself, which
 * they only read.
 * Nothing here prints or exits.
 */
#ifndef HB_SWEEP_H
#define HB_SWEEP_H

#include "export.h"
HB_BEGIN_DECLS

#include <signal.h>
#include <stddef.h>
#include "observables.h"
#include "scene.h"

struct hb_sweep;

/* A sweep of the base scene (copied), without axes yet.  NULL: no memory. */
struct hb_sweep *
hb_sweep_new(const struct hb_scene *base, char *msg, size_t n);

void
hb_sweep_free(struct hb_sweep *sw);

/*
 * The work a sweep may ask for: a sweep accepts at most
 * HB_SWEEP_MAX_POINTS points unless the caller allows more (or fewer) with
 * hb_sweep_set_max_points, before its axes: a larger product is refused
 * by hb_sweep_vary (HB_EINVAL, before any value is made) with a message
 * naming the count and the limit, then `more` (how to ask for more, e.g.
 * "--max-points N allows more"; may be NULL).  Up to 10^9.
 */
#define HB_SWEEP_MAX_POINTS 1000000L

void
hb_sweep_set_max_points(struct hb_sweep *sw, long max, const char *more);

/*
 * Adds an axis from "KEY=SPEC".  A key already varied is replaced (so a
 * command line's --vary overrides a preset's "; sweep:" line).  Each value
 * is checked against the key alone here; HB_EINVAL with a message naming
 * the key and what is accepted.
 */
int
hb_sweep_vary(struct hb_sweep *sw, const char *arg, char *msg, size_t n);

/*
 * Adds the axes of the "; sweep: --vary KEY=SPEC" lines of a preset's text
 * (`name` stands for the file in messages), as hb_sweep_vary does for each:
 * call it before the command line's --vary, which then replaces an axis
 * of the same key in place.  Returns HB_OK or HB_EINVAL.
 */
int
hb_sweep_vary_from_preset(struct hb_sweep *sw, const char *text, const char *name,
                       char *msg, size_t n);

int
hb_sweep_naxes(const struct hb_sweep *sw);
/*
 * Refinement: --refine OBSERVABLE[:TOL].  Instead of every point of the
 * grid, a refined sweep computes the grid of its one or two ranges, then
 * bisects every interval (every cell, for two axes) whose ends fall in
 * different classes of the observable, round after round, until each
 * boundary lies between two points TOL of each axis's span apart (or
 * closer; default 1e-3).  Classes: a whole observable's value (collisions,
 * j_end, q_c_end ...); another observable's existence (t_pc: permanent
 * contact or not; e_first: a collision that ended or not); with OBS<X or
 * OBS>X, which side of X (NAN a class of its own); a failed run is a class
 * of its own.  The points are those of the uniform sweep FROM:TO:M with
 * M = (N - 1) * 2^L + 1 (hb_sweep_npoints counts them; ids are theirs),
 * bit-identical to it, so a boundary is where that uniform sweep puts it
 * when the class changes once between two grid points (for two axes:
 * where a grid cell's corners differ; an island inside a cell whose
 * corners agree is not seen).
 *
 * Call it after every axis (an axis varied later is refused); the spec
 * gets a "; sweep: --refine SPEC" line, which hb_sweep_refine_from_preset
 * reads back.  HB_EINVAL with a message: an unknown observable, a TOL not
 * in (0, 1), more than two axes, a list axis, a lattice of more than 2^20
 * intervals.
 */
int
hb_sweep_refine(struct hb_sweep *sw, const char *spec, char *msg, size_t n);
int
hb_sweep_refine_from_preset(struct hb_sweep *sw, const char *text, const char *name,
                            char *msg, size_t n);
/* 1 for a refined sweep. */
int
hb_sweep_refined(const struct hb_sweep *sw);

/*
 * Error bars: with on set, every point is also estimated by
 * hb_error_estimate (error.h: a second run with rk8pd at a hundredth of
 * the tolerances, about 2.5 times the work of a point): runs.csv gets an
 * OBS_err column after the observables for each observable with an error
 * bar (hb_error_observable), collisions.csv a NAME_err column per value
 * column, as hybounce --batch --error --collisions writes them (a point's
 * rows are bit-identical to it).  A failed point, or one whose second run
 * failed (its message then says "no error bars: ..."), has them empty.
 * The spec gets a "; sweep: --error" line, which
 * hb_sweep_error_from_preset reads back (so a resume, a shard and a merge
 * keep it).
 */
void
hb_sweep_set_error(struct hb_sweep *sw, int on);
/* Sets it when text (a preset's) holds a "; sweep: --error" line. */
void
hb_sweep_error_from_preset(struct hb_sweep *sw, const char *text);
/* 1 for a sweep with error bars. */
int
hb_sweep_error(const struct hb_sweep *sw);

/* What a refined sweep cost and found (hb_sweep_options.refine_stats). */
struct hb_sweep_refine_stats {
	long runs;         /* points computed (runs.csv's rows) */
	long grid;         /* points of the grid of the specs */
	long uniform;      /* points of the uniform grid of the same resolution */
	long boundaries;   /* pairs of neighbouring points of different classes */
	int levels;        /* bisections from the grid's step to the lattice's */
	double resolution; /* the lattice's step over the axis's span (the largest) */
};

/* Points in the product (0 with no axis). */
long
hb_sweep_npoints(const struct hb_sweep *sw);

/*
 * Checks that every point's scene is valid (combinations included, e.g.
 * gamma in [-beta, beta] when both vary).  HB_EINVAL names the first bad
 * point, its values and the reason.  hb_sweep_run checks each point once,
 * in its run, with the same message: this is for refusing a sweep before
 * anything runs (--emit), at the cost of a second check of every point.
 */
int
hb_sweep_check(const struct hb_sweep *sw, char *msg, size_t n);

/* The scene of point id.  HB_EINVAL for a bad id or an invalid scene. */
int
hb_sweep_point_scene(const struct hb_sweep *sw, long id, struct hb_scene *out, char *msg, size_t n);

/*
 * The text of sweep.preset (the spec): the base scene as a preset, then the
 * axis lines.  Returns the length needed, like snprintf.
 */
size_t
hb_sweep_spec_format(const struct hb_sweep *sw, char *buf, size_t n);

/* The header of runs.csv, without "\n", into buf (like snprintf). */
size_t
hb_sweep_runs_header(const struct hb_sweep *sw, char *buf, size_t n);

/* The value of axis k at point id as runs.csv shows it (and --set takes it). */
int
hb_sweep_point_value(const struct hb_sweep *sw, long id, int k, char *buf, size_t n);

/*
 * Runs point id and returns its journal block (malloc'd, *out; the caller
 * frees): the collisions rows "c,ID,..." then the runs row "r,ID,...".
 * *failed is set to 1 when the run failed numerically (still HB_OK: a
 * failed point is a row with its message).  HB_ENOMEM or HB_EINVAL else.
 */
int
hb_sweep_point_block(const struct hb_sweep *sw, long id, char **out, int *failed,
                  char *msg, size_t n);

struct hb_sweep_progress {
	long done;        /* points of this shard done (including resumed ones) */
	long total;       /* points of this shard */
	long resumed;     /* points found done in the journal at the start */
	long failed;      /* points that failed numerically so far */
	double elapsed;   /* s since hb_sweep_run began */
	double point_cpu; /* CPU time of the points computed in this run, s */
};

/*
 * Another format for the merged files: a sink is given the headers of
 * runs.csv and collisions.csv (without newline), then every row of both in
 * the order the CSV files would hold them (a point's collisions, then its
 * runs row; points by id), as CSV text without newline, then end(ok):
 * ok 1, put the file in place; ok 0, remove what was written.  Memory is
 * the sink's affair: the merge streams.  `name` is the file the sink
 * writes in DIR (e.g. "sweep.h5"): a folder holding it and no journal
 * holds the sweep complete.  Each function returns HB_OK, or an error
 * with msg (the merge stops and calls end(0)).
 */
struct hb_sweep_sink {
	const char *name;
	int (*begin)(void *ctx, const char *runs_header, const char *collisions_header,
	             char *msg, size_t n);
	int (*row)(void *ctx, int runs, const char *row, size_t len, char *msg, size_t n);
	int (*end)(void *ctx, int ok, char *msg, size_t n);
};

struct hb_sweep_options {
	const char *dir;  /* the output folder (created if missing) */
	int jobs;         /* worker threads, >= 1 */
	long shard_k, shard_n; /* this is shard k of n (0 <= k < n); 0/1: all */
	/* Called on the calling thread after each point (and once at the start). */
	void (*progress)(void *ctx, const struct hb_sweep_progress *p);
	void *ctx;
	/*
	 * May be NULL.  When *cancel becomes nonzero (e.g. from a SIGINT
	 * handler) the workers finish their points, which are journaled, and
	 * hb_sweep_run returns HB_EDONE ("stopped with N of M points done").
	 */
	volatile sig_atomic_t *cancel;
	/*
	 * May be NULL.  A comment line (outputs.h: hb_outputs_provenance)
	 * written at the end of a new sweep.preset: the program and command
	 * that made the folder.  Such lines are left out when a folder's
	 * sweep.preset is compared with the sweep, so that another command
	 * line (--jobs, --quiet) resumes it.
	 */
	const char *provenance;
	/* May be NULL.  A refined sweep fills it in when it completes. */
	struct hb_sweep_refine_stats *refine_stats;
	/* May be NULL (runs.csv and collisions.csv): where a one-shard sweep merges. */
	const struct hb_sweep_sink *sink;
	void *sink_ctx;
};

/*
 * Prepares DIR for the sweep: creates it, refuses a folder that holds a
 * different sweep or other files (HB_EINVAL), and writes sweep.preset
 * (atomically, unless it is already there).  hb_sweep_run calls it; --emit
 * calls it alone.
 */
int
hb_sweep_prepare_dir(const struct hb_sweep *sw, const char *dir, char *msg, size_t n);

/* The same, with a provenance line for a new sweep.preset (NULL: none). */
int
hb_sweep_prepare_dir_with(const struct hb_sweep *sw, const char *dir, const char *provenance,
                          char *msg, size_t n);

/*
 * Computes the points of the shard that its journal
 * (DIR/shard-K-of-N.journal, or DIR/points.journal for 0/1) does not hold
 * yet, on o->jobs threads, appending each to the journal as it completes.
 * A one-shard sweep then writes runs.csv and collisions.csv (hb_sweep_merge)
 * and removes its journal.  The journal is locked (flock) while the shard
 * runs: a second run of the same shard gets HB_EIO ("another process is
 * computing these points") and leaves it alone.  Each point's scene is
 * checked once, in its run: a bad one stops the sweep with HB_EINVAL and
 * hb_sweep_check's message, and what this call began (the folder, its
 * sweep.preset, a journal that held no point) is removed, but for a shard
 * of several.  Returns HB_OK (failed points included), HB_EDONE
 * (cancelled, see sweep_options), HB_EINVAL (bad DIR, a bad point), HB_EIO
 * or HB_ENOMEM.
 */
int
hb_sweep_run(const struct hb_sweep *sw, const struct hb_sweep_options *o, char *msg, size_t n);

/*
 * Merges the journals in DIR (all shards of one count N, or the one-shard
 * journal) into runs.csv and collisions.csv sorted by id, atomically.
 * HB_EINVAL when incomplete, naming the shards that are not started or
 * incomplete ("2 of 4 shards incomplete: shard 1 (not started), shard 3
 * (3 of 5 points); ..."), with N from the journals' names when they all
 * name one; else the missing points.
 */
int
hb_sweep_merge(const char *dir, char *msg, size_t n);

/* The same for a sweep run as nshards shards (0: from the journals' names). */
int
hb_sweep_merge_shards(const char *dir, long nshards, char *msg, size_t n);

/* The same into a sink (NULL: the CSV files). */
int
hb_sweep_merge_to(const char *dir, long nshards, const struct hb_sweep_sink *sink, void *ctx,
                  char *msg, size_t n);

/*
 * Which of nshards shards the folder DIR holds done: done[k] = 1 when
 * every point of shard k (ids k, k + nshards, ...) is in one of its
 * journals, whatever shards computed it, or when DIR holds the merged
 * runs.csv and collisions.csv.  Returns the number done, or -1 with msg
 * (a damaged journal, I/O, memory).  DIR must hold this sweep (see
 * hb_sweep_prepare_dir).
 */
long
hb_sweep_shards_done(const struct hb_sweep *sw, const char *dir, long nshards,
                     unsigned char *done, char *msg, size_t n);

/*
 * Curves for the explorer: one parameter, one observable, computed by
 * background threads while the caller keeps drawing.
 *
 *     c = hb_sweep_curve_start(&scene, "initial.v0", "-1mm/s:-1m/s:40:log",
 *                           HB_CURVE_E, 0, 2, msg, sizeof msg);
 *     each frame: k = hb_sweep_curve_poll(c, x, y, st, n);  // never blocks long
 *     hb_sweep_curve_free(c);   // cancels: workers stop within one slice
 *
 * The points are those of the sweep with that one axis (the same scenes,
 * the same runs: bit-identical to --batch), taken in order.  A curve has
 * at most HB_SWEEP_CURVE_MAX_POINTS points: a longer range is refused
 * (HB_EINVAL, nothing started) with a message naming the limit.
 */
#define HB_SWEEP_CURVE_MAX_POINTS 10000L

enum hb_sweep_observable {
	HB_CURVE_E = 0,      /* e of collision i (i among all: NAN if thinned out) */
	HB_CURVE_VI,         /* v_i of collision i, m/s */
	HB_CURVE_XCR,        /* x_c^r of collision i, m */
	HB_CURVE_RUN,        /* HB_CURVE_RUN + k: run observable k (observables.h) */
	HB_CURVE_COLLISIONS = HB_CURVE_RUN + HB_OBS_COLLISIONS, /* every completed collision */
	HB_CURVE_TPC = HB_CURVE_RUN + HB_OBS_T_PC,    /* time of permanent contact, s */
	HB_CURVE_XCR_TOTAL = HB_CURVE_RUN + HB_OBS_X_C_R_TOTAL, /* sum of x_c^r, m */
	HB_CURVE_COUNT = HB_CURVE_RUN + HB_OBS_COUNT
};

enum { HB_CURVE_PENDING = 0, HB_CURVE_DONE, HB_CURVE_FAILED };

/*
 * Name of an observable ("e", "v_i", "x_c_r", then the run observables'
 * names: "collisions", "t_pc" ...), NULL if out of range.
 */
const char *
hb_sweep_observable_name(int obs);

/*
 * The observable obs of a run (of collision i where it applies), as the
 * curve takes it once the run has ended: NAN when it does not exist.  A run
 * observable is hb_observable_value(s, obs - HB_CURVE_RUN), as in runs.csv.
 */
struct hb_sim;
double
hb_sweep_observe(const struct hb_sim *s, int obs, long i);

struct hb_sweep_curve;

/*
 * Starts computing obs (of collision coll_i where it applies) over key=spec
 * on `jobs` threads.  NULL with HB_EINVAL's message in msg on a bad key,
 * spec or point.
 */
struct hb_sweep_curve *
hb_sweep_curve_start(const struct hb_scene *base, const char *key, const char *spec, int obs,
                  long coll_i, int jobs, char *msg, size_t n);

/*
 * The same, and once two neighbouring points are done and their classes
 * differ (as --refine classes a run: a whole run observable's value, else
 * whether the observable exists; a failed run a class of its own), the
 * workers bisect that interval on the lattice of the range (hb_sweep_refine)
 * until it is tol of the range wide or less (0 < tol < 1; tol 0: no
 * boundaries, as hb_sweep_curve_start).  A list, or a tol whose lattice
 * would be too fine, is refused (NULL, HB_EINVAL's message).
 */
struct hb_sweep_curve *
hb_sweep_curve_start_refined(const struct hb_scene *base, const char *key, const char *spec,
                             int obs, long coll_i, double tol, int jobs, char *msg, size_t n);

long
hb_sweep_curve_npoints(const struct hb_sweep_curve *c);

/*
 * The boundaries found so far (up to n of them): each lies between the
 * parameter values lo[i] and hi[i] (SI; the points on either side), and
 * located[i] is 1 once they are one lattice step apart (0 while it is
 * being bisected).  Returns the number found (0 for a curve without
 * boundaries).  Never waits for a point.
 */
long
hb_sweep_curve_boundaries(struct hb_sweep_curve *c, double *lo, double *hi, int *located,
                          long n);

/*
 * Copies up to n points: x (the parameter, SI), y (the observable; NAN when
 * it does not exist, e.g. no collision i) and state (HB_CURVE_PENDING, _DONE,
 * _FAILED).  Returns the number of points finished so far.
 */
long
hb_sweep_curve_poll(struct hb_sweep_curve *c, double *x, double *y, int *state, long n);

/*
 * Writes the finished points as CSV ("KEY,OBS" header, %.17g, empty for
 * NAN), to a temporary name renamed over path.  HB_EIO with a message.
 */
int
hb_sweep_curve_write_csv(struct hb_sweep_curve *c, const char *path, char *msg, size_t n);

/* Stops the workers (each after at most one slice of its run) and frees. */
void
hb_sweep_curve_free(struct hb_sweep_curve *c);

HB_END_DECLS

#endif
