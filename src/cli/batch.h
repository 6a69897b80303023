/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch.h - batch mode of the command line: preset -> sim -> report, CSV.
 *
 * Every function here prints (to stdout for the report, to stderr for
 * errors; the report goes to stderr too when a CSV goes to stdout, "-")
 * and returns a process exit status:
 *     0  success;
 *     1  the run failed numerically (or --check found a violation): what was
 *        computed is still printed and written;
 *     2  bad input: a preset that does not resolve or load, a bad --set, an
 *        export path that cannot be written.  Nothing is written then.
 *        Also output that could not be written (an export, the report):
 *        what could be written is, and the failure is said on stderr.
 */
#ifndef HYBOUNCE_CLI_BATCH_H
#define HYBOUNCE_CLI_BATCH_H

struct batch_options {
	const char *preset;        /* name (presets/NAME.preset) or path */
	const char *const *sets;   /* "KEY=VALUE" overrides, applied in order */
	int nsets;
	const char *trace;         /* arc CSV, "-" for stdout, or NULL */
	const char *collisions;    /* collisions CSV, "-" for stdout, or NULL */
	const char *plot;          /* the figure of the state (plot_out.h), or NULL */
	const char *bodies;        /* each body's final state as CSV (batch_bodies.h), or NULL */
	int jumps;                 /* 1: print every jump's location record */
	int check;                 /* 1: run hb_check_solution_pair and report it */
	int quiet;                 /* 1: no header block and no collision table */
	int error;                 /* 1: error bars (error.h): a second run, printed and in the CSV */
};

/* Runs one preset to its end and reports.  Returns the exit status. */
int
batch_run(const struct batch_options *o);

/* --list-presets: name, title and description of each preset found. */
int
batch_list_presets(void);

/* --list-laws: each law with its parameters (unit, range, default). */
int
batch_list_laws(void);

/*
 * Flushes standard output and says on stderr why it failed, if it did
 * ("write error on standard output: REASON"), clearing its error.  Returns
 * 0, or 2 after the message.  A reader gone away (EPIPE) is no failure.
 */
int
batch_flush_stdout(void);

#endif
