/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_impl.h - what the sweep's files share inside the engine.
 */
#ifndef HYBOUNCE_SWEEP_IMPL_H
#define HYBOUNCE_SWEEP_IMPL_H

#include <stddef.h>
#include <stdio.h>
#include <sys/types.h>
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/sweep.h"

#define SWEEP_SPEC_NAME "sweep.preset"
#define SWEEP_MAX_POINTS 1000000000L
#define SWEEP_MAX_AXES 16
#define SWEEP_ERROR_LINE "; sweep: --error"

struct axis {
	char key[48];
	char spec[256];   /* as given, after '=' */
	long n;           /* values (a refined axis: those of its lattice) */
	char **val;       /* a list's n canonical texts, or NULL */
	double *num;      /* a range's n canonical values, or NULL: a list, or ramp */
	/* a range whose values are computed (sweep_axis_num), not kept: FROM and
	 * TO canonical, every value between them the double of the formula */
	struct {
		double from, to;
		int lg, on;
	} ramp;
	/* where a range's value is stored in the scene (sweep_axis.c: fast_ready) */
	size_t off;       /* a double at this offset of struct hb_scene, or */
	int par;          /* law parameter par (-1: off) */
};

/* Value i of a range axis (a->val == NULL): kept or computed. */
double
sweep_ramp_value(double from, double to, long n, int lg, long i);

static inline double
sweep_axis_num(const struct axis *a, long i)
{
	return a->num != NULL ? a->num[i] : sweep_ramp_value(a->ramp.from, a->ramp.to, a->n,
	                                                     a->ramp.lg, i);
}

/*
 * --refine (sweep_refine.c): the classes of a run that a boundary
 * separates, and the lattice the boundaries are located on.  A refined
 * axis FROM:TO:N holds the M = (N - 1) * 2^levels + 1 values of
 * FROM:TO:M (the same doubles as a uniform sweep of M values); the grid
 * of the spec is every step-th of them.
 */
struct sweep_refine {
	int on;
	int obs;          /* observables.h index */
	int op;           /* 0: the value's class; '<' or '>': against thr */
	double thr;
	double tol;       /* of each axis's span */
	int levels;       /* bisections from the grid to the lattice */
	long step;        /* 2^levels */
	long grid[2];     /* N of each axis */
	char spec[128];   /* as given */
};

struct hb_sweep {
	struct hb_scene base;
	long max_points;          /* the largest product accepted (hb_sweep_set_max_points) */
	char more[128];           /* how to ask for more, for the refusal */
	int naxes;
	struct axis ax[SWEEP_MAX_AXES];
	struct sweep_refine rf;
	int error;                /* --error: the error bars of each point (error.h) */
	/*
	 * When every axis is a range of a plain number (a double of the scene
	 * or a law parameter): the base with each axis's first value set (its
	 * flags, such as a material given, set too), into which a point writes
	 * its values before the scene is derived once (sweep.c: sweep_point_values).
	 */
	int fast;
	struct hb_scene fast_base;
};

/* Frees an axis's values and clears it. */
void
sweep_axis_free(struct axis *a);

/* The canonical text of value i of axis a (in buf for a range's number). */
const char *
sweep_axis_text(const struct axis *a, long i, char *buf, size_t n);

/* Index of axis k at point id (row-major, the last axis fastest). */
long
sweep_axis_index(const struct hb_sweep *sw, long id, int k);

/* The scene on which axis k's values are checked: base + earlier axes' first values. */
void
sweep_check_scene(const struct hb_sweep *sw, int k, struct hb_scene *sc);

/*
 * Each line of a preset's text that begins with tag ("; sweep: --vary "),
 * its rest given to take (hb_sweep_vary, hb_sweep_refine); a refusal as
 * "NAME:LINE: why" (name stands for the file).
 */
int
sweep_tagged_lines(struct hb_sweep *sw, const char *text, const char *name, const char *tag,
                   int (*take)(struct hb_sweep *, const char *, char *, size_t), char *msg, size_t n);

/* A range FROM:TO:N[:log] (a->spec) into a->num; others: the other axes' points. */
int
sweep_parse_range(struct axis *a, const struct hb_scene *sc, const struct hb_sweep *sw,
            double others, char *msg, size_t n);

/*
 * The class of a point for --refine: points of one class are on the same
 * side of every boundary.  v is the observable's value (NAN: none).
 */
long
sweep_refine_class(const struct sweep_refine *rf, double v, int failed);

/*
 * The value of observable obs (observables.h) and whether the point
 * failed, read from a journal block's runs row ("r,ID,...").  HB_EINVAL
 * for a block without one.
 */
int
sweep_block_observable(const struct hb_sweep *sw, const char *blk, size_t len, int obs,
                       double *v, int *failed);

/* The lattice id of point g of a refined sweep's grid (row-major over the
 * grid of the specs), and the number of grid points. */
long
sweep_refine_grid_id(const struct hb_sweep *sw, long g);
long
sweep_refine_grid_points(const struct hb_sweep *sw);

/* The header of the collisions CSV (--collisions) of scene sc, no newline;
 * err: with the NAME_err columns of --error. */
int
sweep_collisions_header(const struct hb_scene *sc, int err, char *buf, size_t n, char *msg,
                        size_t mn);

/* hb_sweep_run for a refined sweep (sweep_refine_run.c). */
int
sweep_refine_run(const struct hb_sweep *sw, const struct hb_sweep_options *o, char *msg,
                 size_t n);

/*
 * The worker threads of hb_sweep_run: computes, on o->jobs threads, the
 * points ids[0 .. nids) (ids NULL: the points first, first + step, ...
 * below np that done does not hold, npending of them), appending each
 * block to the journal fd (jpath in messages) in the order they complete,
 * then calling got(ctx, id, blk, len) when got is not NULL; pr is
 * counted and reported (o->progress).  *ordered (may be NULL): 1 when every
 * block went to the journal in increasing id order.  Returns HB_OK, HB_EDONE
 * (cancelled; the points in hand are journaled), or an error with msg.
 */
int
sweep_compute(const struct hb_sweep *sw, const struct hb_sweep_options *o, int fd,
              const char *jpath, const long *ids, long nids, const unsigned char *done,
              long first, long step, long npending, struct hb_sweep_progress *pr, double t0,
              int (*got)(void *, long, const char *, size_t), void *ctx, int *ordered,
              char *msg, size_t n);

/* ---- the folder and its journals (sweep_journal.c) ---- */

/* The whole of a file into a malloc'd string (*len bytes), read once and
 * bounded (input.h).  NULL with msg on failure; errno ENOENT when absent. */
char *
sweep_slurp(const char *path, size_t *len, char *msg, size_t n);

/*
 * Reads a journal: calls seen(ctx, id, off, len) for each complete block
 * and cuts a partial block off the end when trunc is set.  Returns HB_OK
 * (also for a journal that is not there), HB_EIO, or HB_EINVAL for a
 * damaged journal.
 */
int
sweep_journal_scan(const char *path, long npoints, int trunc,
                   int (*seen)(void *, long, off_t, size_t), void *ctx, char *msg, size_t n);

/* write(2) of the whole of p (EINTR retried); 0, or -1 with errno. */
int
sweep_write_all(int fd, const char *p, size_t len);

/*
 * hb_sweep_prepare_dir_with, and what it made (*made): SWEEP_MADE_DIR, the
 * folder; SWEEP_MADE_SPEC, its sweep.preset.
 */
enum { SWEEP_MADE_DIR = 1, SWEEP_MADE_SPEC = 2, SWEEP_MADE_JOURNAL = 4 };
int
sweep_prepare_dir(const struct hb_sweep *sw, const char *dir, const char *provenance, int *made,
                  char *msg, size_t n);

/*
 * After a point was refused (HB_EINVAL: bad input), removes what this call
 * made (made: SWEEP_MADE_*; SWEEP_MADE_JOURNAL: the journal jpath held no
 * point before), so that a refused sweep leaves no folder behind, as one
 * refused before it runs.
 */
void
sweep_refused_undo(const char *dir, int made, const char *jpath);

/* DIR/points.journal for one shard, DIR/shard-K-of-N.journal otherwise. */
void
sweep_journal_name(char *buf, size_t n, const char *dir, long k, long nshards);

/*
 * An exclusive lock on the journal open as fd (flock; a second process on
 * the same shard is refused, HB_EIO).  fd < 0: the open's errno.
 */
int
sweep_journal_lock(int fd, const char *path, char *msg, size_t n);

/*
 * A worker's buffer for the collisions of its points, reused from point
 * to point (an open_memstream(3) a point costs about 9k instructions).  Zeroed to start; sweep_wbuf_free at the end.
 */
struct sweep_wbuf {
	FILE *coll;
	char *cbuf;
	size_t clen;
	struct hb_sim *sim;   /* the last point's, made again for the next (hbs_sim_renew) */
};

void
sweep_wbuf_free(struct sweep_wbuf *w);

/* The base scene with the axes' values of point id, not validated. */
int
sweep_point_values(const struct hb_sweep *sw, long id, struct hb_scene *out, char *msg, size_t n);

/*
 * HB_EINVAL with the message of a point whose scene is refused: "point ID
 * (KEY=VALUE ...): why" (hb_sweep_check's, and a run's).
 */
int
sweep_point_refused(const struct hb_sweep *sw, long id, const char *why, char *msg, size_t n);

/*
 * hb_sweep_point_block with w's buffers.  The scene is validated once, by
 * hb_sim_new: a refused point is HB_EINVAL with sweep_point_refused's
 * message (a sweep that runs is not checked point by point before).
 */
struct sweep_block {
	char *p;        /* the block, len bytes and a '\0', in a buffer of cap bytes */
	size_t len, cap;
	int failed;     /* the run failed (a row with its message) */
	double cpu;     /* the point's CPU time, s (its runs row's cpu_s) */
};

/* The block is built in b->p (cap bytes, may be NULL), grown as needed;
 * the buffer stays the caller's whatever the outcome. */
int
sweep_point_block_buf(const struct hb_sweep *sw, long id, struct sweep_wbuf *w,
                      struct sweep_block *b, char *msg, size_t n);

/* The base scene of a sweep (the preset and --set, before any axis). */
const struct hb_scene *
sweep_base(const struct hb_sweep *sw);

/* The shards of a folder (sweep_shards.c). */

/* The names of the journals in dir (malloc'd, *count of them; sweep_names_free). */
int
sweep_journals_list(const char *dir, char ***names, int *count, char *msg, size_t n);
void
sweep_names_free(char **names, int count);

/* The shard count of the journals when they all name the same one, else 0. */
long
sweep_shards_of_names(char *const *names, int count);

/*
 * HB_EINVAL with "2 of 4 shards incomplete: shard 1 (not started), shard 3
 * (3 of 5 points); 8 of 20 points missing" in msg, from have(ctx, id).
 */
int
sweep_shards_missing_msg(const char *dir, long np, long ns, int (*have)(const void *, long),
                         const void *ctx, long missing, char *msg, size_t n);

/*
 * hb_sweep_merge_shards for a sweep in hand, which DIR/sweep.preset holds
 * (hb_sweep_prepare_dir checked it): its values are not made again.
 * whole: the folder's one journal, points.journal, is known to hold every
 * point once, in id order (hb_sweep_run wrote it so in one go), so it is
 * not read a first time to find that out.
 */
int
sweep_merge_into(const struct hb_sweep *sw, const char *dir, long nshards, int whole,
                 const struct hb_sweep_sink *sink, void *ctx, char *msg, size_t n);

#endif
