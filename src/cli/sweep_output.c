/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_output.c - what "hybounce sweep" says it wrote (sweep_cmd.h): the
 * files of the folder, probed before the run and named after it ("wrote",
 * "kept" for a sweep found complete); and --plot FILE, the figure of the
 * sweep in the folder, checked by the output rules before anything runs
 * and drawn when the sweep is complete (plot_out.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/atomic.h"
#include "hybounce/outputs.h"
#include "hybounce/status.h"

#include "sweep_cmd.h"
#include "plot_cmd.h"
#include "plot_out.h"
#include "sweep_hdf5.h"
#include "report.h"

#define PROG "hybounce sweep"

/* A refusal (report.h): "hybounce sweep: ...", then where usage is. */
#define bad(...) cli_refuse_usage(PROG, PROG, __VA_ARGS__)

void
sweep_probe_dir(const char *dir, struct sweep_dir_targets *d, int refined, int hdf5)
{
	static const char *const names[2][3] = {
		{ "runs.csv", "collisions.csv", "boundaries.csv" },
		{ SWEEP_HDF5_NAME, "boundaries.csv", "" },
	};
	char m[256];

	d->nfiles = (hdf5 ? 1 : 2) + refined;
	for (int k = 0; k < d->nfiles; k++) {
		snprintf(d->path[k], sizeof d->path[k], "%s/%s", dir, names[hdf5][k]);
		if (hb_atomic_probe(d->path[k], &d->t[k], m, sizeof m) != HB_OK)
			memset(&d->t[k], 0, sizeof d->t[k]);
	}
}

/*
 * "wrote DIR/runs.csv (replaced the existing file)" ... (outputs.h); a
 * sweep found complete writes nothing: "kept DIR/runs.csv ...".
 */
void
sweep_print_wrote_dir(const struct sweep_dir_targets *d, int unchanged)
{
	for (int k = 0; k < d->nfiles; k++) {
		if (unchanged) {
			fprintf(stderr, "kept %s (the sweep was complete)\n", d->path[k]);
			continue;
		}
		cli_print_wrote(d->path[k], &d->t[k]);
	}
}

/* ------------------------------------------------------------------ */
/* --plot FILE: the figure of the sweep in dir (plot_out.h)           */

/* The figure's path, by the output rules, before anything runs: 0, or 2 after saying why. */
int
sweep_plot_check(const char *plot, const char *dir)
{
	struct plot_out po;
	struct hb_outputs pol;
	char m[3][4200], msg[4200];

	hb_outputs_init(&pol);
	snprintf(m[0], sizeof m[0], "%s/runs.csv", dir);
	snprintf(m[1], sizeof m[1], "%s/collisions.csv", dir);
	snprintf(m[2], sizeof m[2], "%s/sweep.preset", dir);
	hb_outputs_input(&pol, m[0], "the sweep's runs.csv");
	hb_outputs_input(&pol, m[1], "the sweep's collisions.csv");
	hb_outputs_input(&pol, m[2], "the sweep's sweep.preset");
	msg[0] = '\0';
	if (plot_out_parse(&po, "--plot", plot, msg, sizeof msg) != 0 ||
	    plot_out_register(&po, &pol, msg, sizeof msg) != 0)
		return bad("%s", msg);
	return 0;
}

/* Draws the sweep in dir to plot: 0, or 2 after saying why. */
int
sweep_plot_draw(const char *plot, const char *dir)
{
	struct plot_out po;
	struct hb_outputs pol;
	struct plot_figure *fig = malloc(sizeof *fig);
	char msg[4200];
	int status = 0;

	if (fig == NULL)
		return bad("--plot %s: out of memory", plot);
	hb_outputs_init(&pol);
	msg[0] = '\0';
	if (plot_out_parse(&po, "--plot", plot, msg, sizeof msg) != 0) {
		free(fig);
		return bad("%s", msg);
	}
	if (plot_build_sweep(fig, dir, NULL, NULL, 0, 252, -1, &pol, msg, sizeof msg) != 0) {
		free(fig);
		return bad("--plot %s: %s", plot, msg);
	}
	if (plot_out_register(&po, &pol, msg, sizeof msg) != 0 ||
	    plot_out_write(&po, &pol, fig, msg, sizeof msg) != 0)
		status = bad("%s", msg);
	plot_figure_free(fig);
	free(fig);
	return status;
}
