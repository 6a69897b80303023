/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch.c - batch mode: load a preset, apply --set overrides, run the
 * simulator to its end, print a report for a reader of the paper and write
 * the CSV files.
 *
 * The report (stdout; stderr when a CSV goes to stdout) has three parts:
 *  1. a header block: preset, law, system, bodies, loads, initial state,
 *     derived values and the run settings (with the per-component scales
 *     of the absolute tolerance);
 *  2. the collision table, one row per completed collision, in fixed units
 *     chosen per column from the data's magnitude (ASCII only), then the
 *     contact in progress if any;
 *  3. a summary: why the run ended, the end state and the work done.
 * --quiet keeps only the summary.  Errors, and the "wrote FILE" lines of an
 * export, go to stderr.
 *
 * "--trace -" or "--collisions -" (not both) writes that CSV to stdout,
 * after the files, and then the report goes to stderr, so that stdout holds
 * the CSV alone (GNU tar sends its -v listing to stderr with -f - the same
 * way).  No "wrote" line and no .preset beside "-": the scene is saved
 * beside the other CSV when that one is a file.  A reader that stops
 * early (| head) ends the process by SIGPIPE, or, with SIGPIPE ignored,
 * the write stops at the EPIPE without a message.
 *
 * Bad input is refused before anything runs: the preset, every --set and
 * the export paths are checked first, so a bad invocation (exit 2) never
 * leaves a CSV behind.  A run that fails numerically (exit 1) still prints
 * and writes what it computed.
 *
 * This file holds the run itself: the checks of the input and the export
 * paths, the run with its progress line and signals, the order of the
 * report and of the outputs.  The report's parts are in batch_header.c,
 * batch_table.c, batch_summary.c and batch_check.c (batch_report.h);
 * --bodies in batch_bodies.c; the listings in batch_list.c.
 */
#include <errno.h>
#include <signal.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "hybounce/arc.h"
#include "hybounce/atomic.h"
#include "hybounce/collisions.h"
#include "hybounce/csv.h"
#include "hybounce/error.h"
#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "batch.h"
#include "batch_bodies.h"
#include "batch_report.h"
#include "plot_cmd.h"
#include "plot_out.h"
#include "report.h"
#include "signals.h"
#include "clock.h"

#define PROG "hybounce"

static void
err(const char *msg)
{
	fprintf(stderr, PROG ": %s\n", msg);
}

/* ------------------------------------------------------------------ */
/* Input: preset, --set, export paths                                  */

/* 1 if an export path names standard output ("-"). */
static int
is_stdout(const char *path)
{
	return path != NULL && strcmp(path, "-") == 0;
}

/* 1 if path ends in suffix. */
static int
ends_with(const char *path, const char *suffix)
{
	size_t a = strlen(path), b = strlen(suffix);

	return a >= b && strcmp(path + a - b, suffix) == 0;
}

/*
 * Checks, before the run, that an export path can be written (atomic.h:
 * a new or replaced file needs a writable folder, a device or FIFO is
 * written in place, a folder is refused).  Returns 0, or 2 after printing
 * why.
 */
static int
check_export_path(const char *opt, const char *path)
{
	struct hb_atomic_target t;
	char msg[1024];

	if (path[0] == '\0') {
		fprintf(stderr, PROG ": %s: empty file name; accepted: %s, e.g. run.csv\n", opt,
		        HB_OUTPUTS_ACCEPTED);
		return 2;
	}
	if (ends_with(path, ".preset")) {
		fprintf(stderr, PROG ": %s %s: the scene is saved beside the CSV as "
		        "NAME.preset; give the CSV another extension (e.g. .csv)\n",
		        opt, path);
		return 2;
	}
	msg[0] = '\0';
	/* the output policy's words (outputs.h): "PATH: reason; accepted: ..." */
	if (hb_outputs_probe(path, &t, msg, sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": %s %s\n", opt, msg);
		return 2;
	}
	return 0;
}

/* ------------------------------------------------------------------ */
/* The run: signals and progress                                       */

/*
 * Runs s in slices of 0.1 s to its end or to a caught signal (*sig).
 * Past one second, standard error a terminal, a progress line there,
 * rewritten in place four times a second and erased at the end.
 */
static int
run_watched(struct hb_sim *s, int *sig)
{
	const double T = hb_sim_scene(s)->run.T;
	const int tty = isatty(STDERR_FILENO);
	double start = clock_seconds(CLOCK_MONOTONIC), shown = 0;
	int rc = HB_OK;

	while (cli_signal == 0) {
		double now;

		rc = hb_sim_advance(s, 0, 0.1);
		if (rc != HB_OK || hb_sim_end(s) != HB_SIM_RUNNING)
			break;
		now = clock_seconds(CLOCK_MONOTONIC);
		if (tty && now - start > 1.0 && now - shown >= 0.25) {
			const struct hb_arc_sample *p = hb_arc_last(hb_sim_arc(s));
			char tb[32], Tb[32];

			batch_fmt(p != NULL ? p->t : 0, hb_unit_time, tb, sizeof tb);
			batch_fmt(T, hb_unit_time, Tb, sizeof Tb);
			fprintf(stderr, "\r" PROG ": t = %s of %s (%.0f%%), j = %ld, %zu collisions, "
			        "%.0f s; Ctrl-C stops and writes\033[K", tb, Tb,
			        p != NULL && T > 0 ? 100 * p->t / T : 0.0,
			        p != NULL ? p->j : 0L, hb_sim_ncollisions(s), now - start);
			shown = now;
		}
	}
	if (shown > 0)
		fprintf(stderr, "\r\033[K");
	*sig = cli_signal;
	return rc;
}

/*
 * Takes the branches a preset records, as the explorer took them
 * (hb_sim_branch_at).  A branch that begins where this run has no sample
 * is refused (-1); one whose state there differs from the recorded one is
 * taken with a warning: the run is not the one exported.
 */
static int
replay_branches(struct hb_sim *s, const char *path, const struct hb_branch *br, size_t nbr)
{
	char msg[1024];

	for (size_t k = 0; k < nbr; k++) {
		int same = 0, restarted = 0;

		msg[0] = '\0';
		if (hb_sim_branch_at(s, &br[k], &same, &restarted, msg, sizeof msg) != HB_OK) {
			fprintf(stderr, PROG ": %s: [branch %zu]: %s\n", path, k + 1, msg);
			return -1;
		}
		if (restarted) {
			fprintf(stderr, PROG ": %s: [branch %zu]: its values cannot continue the run there "
			        "(the law or the bodies changed in contact); accepted: a branch the explorer "
			        "made\n", path, k + 1);
			return -1;
		}
		if (!same)
			fprintf(stderr, PROG ": warning: %s: [branch %zu]: the state at t = %.9g s differs "
			        "from the one recorded: this run is not the one the file was exported from\n",
			        path, k + 1, br[k].t);
	}
	return 0;
}

/* ------------------------------------------------------------------ */

int
batch_run(const struct batch_options *o)
{
	struct hb_scene sc;
	char path[1024], msg[4096]; /* the resolver names a refused preset whole */
	struct hb_sim *s;
	struct hb_csv_export_opts eo = { 0 };
	struct plot_out po;
	struct hb_outputs pol;
	struct hb_error_estimate est_store, *est = NULL;
	struct hb_branch *br = NULL;
	size_t nbr = 0;
	int status = 0, rc, sig = 0;
	const int trace_out = is_stdout(o->trace), coll_out = is_stdout(o->collisions);
	/* The files to export; "-" goes to stdout after them. */
	const char *trace_file = trace_out ? NULL : o->trace;
	const char *coll_file = coll_out ? NULL : o->collisions;
	/* A CSV on stdout sends the report to stderr, as tar -v does with -f -. */
	FILE *out = trace_out || coll_out ? stderr : stdout;

	msg[0] = '\0';
	/* a preset may record branches (the explorer's b): they are replayed below */
	if (hb_preset_open_branched(o->preset, o->sets, o->nsets, &sc, &br, &nbr, path, sizeof path,
	                            msg, sizeof msg) != HB_OK) {
		err(msg[0] ? msg : o->preset);
		return 2;
	}
	if (o->error && nbr > 0) {
		fprintf(stderr, PROG ": --error: %s records %zu branch%s (the explorer's b); error "
		        "bars are made by a second run from t = 0, which has none; accepted: --error "
		        "on a preset without [branch] sections\n", path, nbr, nbr == 1 ? "" : "es");
		free(br);
		return 2;
	}
	if (trace_out && coll_out) {
		fprintf(stderr, PROG ": --trace - and --collisions -: only one CSV can go "
		        "to standard output; expected a file path for the other, e.g. "
		        "--trace - --collisions coll.csv\n");
		return 2;
	}
	if (trace_file != NULL && check_export_path("--trace", trace_file) != 0)
		return 2;
	if (coll_file != NULL && check_export_path("--collisions", coll_file) != 0)
		return 2;
	if (trace_file != NULL && coll_file != NULL && strcmp(trace_file, coll_file) == 0) {
		fprintf(stderr, PROG ": --trace and --collisions name the same file %s; "
		        "expected two different paths\n", trace_file);
		return 2;
	}
	/* The output policy (outputs.h): never the preset run, a shipped preset ... */
	eo.trace = trace_file;
	eo.coll = coll_file;
	eo.run_preset = path;
	eo.provenance = cli_provenance();
	eo.errors = NULL; /* set after the run, with --error */
	msg[0] = '\0';
	if ((trace_file != NULL || coll_file != NULL) &&
	    hb_csv_export_check_with(&eo, msg, sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": export: %s\n", msg);
		return 2;
	}

	/* --plot: the figure's own rules, the CSVs and the preset as the others (plot_out.h) */
	hb_outputs_init(&pol);
	hb_outputs_input(&pol, path, "the preset being run");
	/* --bodies: the same rules, with the CSVs and the scene saved beside them */
	if (o->bodies != NULL) {
		msg[0] = '\0';
		if (batch_bodies_check(&pol, o->bodies, trace_file, coll_file, msg, sizeof msg) != 0) {
			err(msg);
			return 2;
		}
	}
	if (o->plot != NULL) {
		msg[0] = '\0';
		if ((o->bodies == NULL && trace_file != NULL && hb_outputs_add(&pol, trace_file,
		                                  "--trace", msg, sizeof msg) != HB_OK) ||
		    (o->bodies == NULL && coll_file != NULL && hb_outputs_add(&pol, coll_file,
		                                  "--collisions", msg, sizeof msg) != HB_OK) ||
		    plot_out_parse(&po, "--plot", o->plot, msg, sizeof msg) != 0 ||
		    plot_out_register(&po, &pol, msg, sizeof msg) != 0) {
			err(msg);
			return 2;
		}
	}

	/*
	 * SIGINT, SIGTERM and SIGHUP end the run, and what was computed is
	 * reported and written, as after a numerical failure (signals.h).
	 */
	cli_signals_watch();
	msg[0] = '\0';
	s = hb_sim_new(&sc, msg, sizeof msg);
	if (s == NULL) {
		fprintf(stderr, PROG ": %s: %s\n", path, msg[0] ? msg : "cannot start the run");
		cli_signals_restore();
		free(br);
		return 2;
	}
	if (replay_branches(s, path, br, nbr) != 0) {
		hb_sim_free(s);
		cli_signals_restore();
		free(br);
		return 2;
	}
	free(br);
	rc = run_watched(s, &sig);
	if (hb_sim_end(s) == HB_SIM_END_FAIL || (rc != HB_OK && rc != HB_EDONE))
		status = 1;

	/* --error: the run again at a hundredth of the tolerances (error.h). */
	if (o->error && sig == 0 && hb_sim_end(s) != HB_SIM_END_FAIL) {
		msg[0] = '\0';
		if (hb_error_estimate(s, (const volatile int *)&cli_signal, &est_store, msg,
		                      sizeof msg) == HB_OK)
			est = &est_store;
		else if (cli_signal == 0) {
			fprintf(stderr, PROG ": --error: no error bars: %s\n", msg);
			status = 1;
		}
		sig = cli_signal;
	}

	/* The header comes after the run: the tolerance scales are set per contact. */
	if (!o->quiet) {
		/* the scene from t = 0, then where the branches the preset records begin */
		batch_print_header(out, o->preset, path, hb_sim_scene0(s), hb_sim_stats(s));
		for (size_t k = 0; k < hb_sim_nbranches(s); k++) {
			char tb[64];

			fprintf(out, "branch %-4zu from t = %s (j = %ld) on, with the values of its "
			        "[branch %zu]\n", k + 1, batch_fmt(hb_sim_branch_get(s, k)->t,
			        hb_unit_time, tb, sizeof tb), hb_sim_branch_get(s, k)->j, k + 1);
		}
		batch_print_table(out, s, est);
	}
	if (o->jumps)
		batch_print_jumps(out, hb_sim_arc(s));
	batch_print_summary(out, s, sig, est);

	if (batch_print_checks(out, s, o->check, est) && status == 0)
		status = 1;
	/* Now: the messages below come after the report. */
	if (out == stdout) {
		if (batch_flush_stdout() != 0)
			status = 2;
	} else {
		fflush(out);
	}
	/* After the report, so that it is the last thing a terminal shows. */
	if (sig != 0)
		fprintf(stderr, PROG ": interrupted by %s: what was computed is reported "
		        "and written\n", cli_signal_name(sig));
	else if (status == 1 && hb_sim_end(s) == HB_SIM_END_FAIL)
		fprintf(stderr, PROG ": the run failed: %s\n",
		        hb_sim_errmsg(s)[0] ? hb_sim_errmsg(s) : hb_status_str(rc));
	else if (rc != HB_OK && rc != HB_EDONE)
		fprintf(stderr, PROG ": the run stopped: %s\n", hb_status_str(rc));

	/*
	 * The files first, then stdout: a reader that stops early (| head)
	 * ends the process by SIGPIPE, and the files are written by then.
	 */
	if (trace_file != NULL || coll_file != NULL) {
		struct hb_csv_export_report rep;

		msg[0] = '\0';
		eo.errors = est;
		if (hb_csv_export_with(s, &eo, &rep, msg, sizeof msg) != HB_OK) {
			fprintf(stderr, PROG ": export failed: %s\n", msg);
			status = 2;
		} else {
			if (trace_file != NULL)
				cli_print_wrote(trace_file, &rep.target[0]);
			if (coll_file != NULL)
				cli_print_wrote(coll_file, &rep.target[1]);
			if (rep.scene[0])
				cli_print_wrote(rep.scene, &rep.target[2]);
		}
	}
	if (o->bodies != NULL) {
		msg[0] = '\0';
		if (batch_bodies_write(&pol, o->bodies, s, msg, sizeof msg) != 0) {
			fprintf(stderr, PROG ": --bodies: %s\n", msg);
			status = 2;
		}
	}
	if (o->plot != NULL) {
		msg[0] = '\0';
		if (plot_write_run(&po, &pol, PLOT_STATE, s, msg, sizeof msg) != 0) {
			err(msg);
			status = 2;
		}
	}
	if (trace_out || coll_out) {
		msg[0] = '\0';
		rc = trace_out ? hb_csv_stream_arc(stdout, s, msg, sizeof msg)
		               : hb_csv_stream_collisions_err(stdout, s, est, msg, sizeof msg);
		/*
		 * EPIPE (SIGPIPE ignored): the reader has all it wanted; stop
		 * quietly, like a killed writer, with the run's status.
		 */
		if (rc != HB_OK && errno != EPIPE) {
			fprintf(stderr, PROG ": export failed: standard output: %s\n", msg);
			status = 2;
		}
		clearerr(stdout);   /* said here (or quiet on EPIPE): not again in main */
	}
	hb_error_free(est);
	hb_sim_free(s);
	if (sig == 0)
		sig = cli_signal;   /* caught while reporting: the report is whole */
	cli_signals_restore();
	/* An interrupted run: 128 + the signal, as a shell reports a kill. */
	return sig != 0 ? cli_signal_status(sig) : status;
}

int
batch_flush_stdout(void)
{
	int e = 0;

	errno = 0;
	if (fflush(stdout) != 0)
		e = errno != 0 ? errno : EIO;
	else if (ferror(stdout))
		e = EIO;
	clearerr(stdout);
	if (e == 0 || e == EPIPE)
		return 0;
	fprintf(stderr, PROG ": write error on standard output: %s\n", strerror(e));
	return 2;
}
