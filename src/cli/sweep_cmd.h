/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_cmd.h - the parts of the "hybounce sweep" command that sweep_main
 * (sweep.c: its options and their order) calls: the input (sweep_input.c),
 * the progress on stderr (sweep_progress.c), and what it says it wrote and
 * --plot (sweep_output.c).  Each says why it refuses on stderr.
 */
#ifndef HYBOUNCE_CLI_SWEEP_CMD_H
#define HYBOUNCE_CLI_SWEEP_CMD_H

#include "hybounce/atomic.h"

struct hb_sweep;
struct hb_sweep_progress;

/*
 * The preset, the --set values and the axes; NULL after printing why (exit
 * 2).  out: the --out folder (its own sweep.preset was allowed its points
 * when it was made); max_points: --max-points, 0 for the default; refine:
 * --refine, or NULL for the preset's line; error: --error.  check: every
 * point's scene checked now (--emit, which writes jobs and runs none).
 */
struct hb_sweep *
sweep_build(const char *preset, const char *const *sets, int nsets,
            const char *const *varies, int nvaries, const char *out, long max_points,
            const char *refine, int error, int check);

/* The progress of a sweep (ctx of hb_sweep_options.progress). */
struct sweep_progress {
	long resumed, total;   /* points found done at the start, points of the shard */
	int tty, quiet;
	double step;       /* fraction between lines without a terminal */
	double next;       /* next fraction to report */
	double last_draw;  /* s, for the terminal bar */
};

/* hb_sweep_options.progress, with ctx a struct sweep_progress. */
void
sweep_on_progress(void *ctx, const struct hb_sweep_progress *p);

/* How DIR/runs.csv and DIR/collisions.csv will be written (before). */
struct sweep_dir_targets {
	char path[3][4200];
	struct hb_atomic_target t[3];
	int nfiles;    /* 3 with a refined sweep's boundaries.csv */
};

/*
 * Probes the files the sweep writes in dir (runs.csv and collisions.csv,
 * or sweep.h5 with hdf5; boundaries.csv when refined), before it runs.
 */
void
sweep_probe_dir(const char *dir, struct sweep_dir_targets *d, int refined, int hdf5);

/*
 * "wrote DIR/runs.csv (replaced the existing file)" ... (outputs.h); a
 * sweep found complete writes nothing: "kept DIR/runs.csv ...".
 */
void
sweep_print_wrote_dir(const struct sweep_dir_targets *d, int unchanged);

/* --plot FILE: the figure's path, by the output rules, before anything runs: 0, or 2 after saying why. */
int
sweep_plot_check(const char *plot, const char *dir);

/* --plot FILE: draws the sweep in dir to plot: 0, or 2 after saying why. */
int
sweep_plot_draw(const char *plot, const char *dir);

#endif
