/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_out.h - writing a figure to a file, for every front end that draws
 * one: `hybounce plot --out FILE` and the `--plot FILE` of batch, sweep and
 * fit.  One set of rules: the format from the extension (.png, .pdf, .svg;
 * .tex is pgfplots source with its data in .dat beside it), the output
 * policy (outputs.h: never an input, a shipped preset or another output
 * of the command), atomic writes (atomic.h), the "wrote" lines.
 *
 *     struct plot_out po;
 *     if (plot_out_parse(&po, "--plot", path, msg, n) != 0) ... refuse, exit 2
 *     if (plot_out_register(&po, &pol, msg, n) != 0) ... refuse, exit 2
 *     ... compute, build the figure ...
 *     if (plot_out_write(&po, &pol, fig, msg, n) != 0) ... exit 2
 */
#ifndef HYBOUNCE_CLI_PLOT_OUT_H
#define HYBOUNCE_CLI_PLOT_OUT_H

#include <stddef.h>

#include "hybounce/outputs.h"
#include "plot_cairo.h"
#include "plot_model.h"

struct plot_out {
	const char *opt;        /* "--plot", "--out": named in messages */
	const char *path;       /* borrowed */
	enum plot_format fmt;
	double dpi;             /* of a PNG: 300 unless set */
	char datpath[4096];     /* FILE.dat of a .tex */
	const char *datname;    /* its name as the .tex reads it */
	int slot, datslot;      /* their index in the outputs policy, -1 none */
};

/* What --plot/--out accept, for messages. */
#define PLOT_OUT_ACCEPTED "a file ending in .png, .pdf, .svg or .tex"

/*
 * The format of path from its extension; 0, or -1 with msg ("--plot F:
 * unknown format; expected ...").
 */
int
plot_out_parse(struct plot_out *o, const char *opt, const char *path, char *msg, size_t n);

/*
 * The figure (and the .dat of a .tex) checked and recorded as outputs of
 * the command (outputs.h), before anything runs: 0, or -1 with msg.
 */
int
plot_out_register(struct plot_out *o, struct hb_outputs *pol, char *msg, size_t n);

/*
 * Writes fig (its title set, not yet laid out) atomically, then "wrote
 * PATH" on stderr (pol: the policy the paths were registered with, for
 * how; NULL: plain lines).  0, or -1 with msg ("--plot FILE: reason").
 */
int
plot_out_write(struct plot_out *o, const struct hb_outputs *pol, struct plot_figure *fig,
               char *msg, size_t n);

/* A figure to build for o (malloc'd); NULL with msg ("--plot FILE: out of memory"). */
struct plot_figure *
plot_out_figure(const struct plot_out *o, char *msg, size_t n);

/*
 * After fig (from plot_out_figure) was built (built: the build's 0, or -1
 * with msg): writes it (plot_out_write) and frees it.  0, or -1 with msg.
 */
int
plot_out_finish(struct plot_out *o, const struct hb_outputs *pol, struct plot_figure *fig,
                int built, char *msg, size_t n);

#endif
