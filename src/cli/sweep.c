/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep.c - the "hybounce sweep" command: a thin shell over the sweep
 * engine (src/core/sweep*.c).  It parses the options, loads the preset and
 * the --set overrides, builds the axes, refuses bad input before anything
 * runs (exit 2), and shows progress on stderr; the engine does the rest.
 *
 *     hybounce sweep PRESET [--set KEY=VALUE]... [--vary KEY=SPEC]...
 *                    [--refine OBS[:TOL]] [--error] [--format csv|hdf5] [--jobs N]
 *                    [--shard K/N]
 *                    [--quiet] --out DIR
 *     hybounce sweep PRESET ... --out DIR --emit slurm|parallel [--shards N]
 *                    [--sshlogin HOSTS] [--time T] [--partition P] [--account A]
 *                    [--qos Q] [--mem M] [--max-array N]
 *     hybounce sweep --merge DIR [--shards N] [--format csv|hdf5]
 *
 * Exit status: 0 the sweep is complete (points that failed numerically are
 * rows with their message); 1 it could not be completed (I/O, memory, an
 * incomplete merge); 2 bad input (also --merge of a folder without a sweep).
 */
#include <errno.h>
#include <signal.h>
#include <getopt.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "hybounce/atomic.h"
#include "hybounce/input.h"
#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"

#include "sweep_cli.h"
#include "plot_cmd.h"
#include "plot_out.h"
#include "sweep_hdf5.h"
#include "report.h"
#include "signals.h"
#include "clock.h"

#define PROG "hybounce sweep"

enum { OPT_EMIT = 256, OPT_SHARDS, OPT_SSHLOGIN, OPT_MERGE, OPT_PROGRESS, OPT_MAX_POINTS,
       OPT_TIME, OPT_PARTITION, OPT_ACCOUNT, OPT_QOS, OPT_MEM, OPT_MAX_ARRAY, OPT_PLOT, OPT_REFINE,
       OPT_FORMAT, OPT_ERROR };

static const struct option sweep_options_long[] = {
	{ "set",      required_argument, NULL, 's' },
	{ "vary",     required_argument, NULL, 'v' },
	{ "jobs",     required_argument, NULL, 'j' },
	{ "shard",    required_argument, NULL, 'k' },
	{ "out",      required_argument, NULL, 'o' },
	{ "quiet",    no_argument,       NULL, 'q' },
	{ "emit",     required_argument, NULL, OPT_EMIT },
	{ "shards",   required_argument, NULL, OPT_SHARDS },
	{ "sshlogin", required_argument, NULL, OPT_SSHLOGIN },
	{ "merge",    required_argument, NULL, OPT_MERGE },
	{ "progress", required_argument, NULL, OPT_PROGRESS },
	{ "max-points", required_argument, NULL, OPT_MAX_POINTS },
	{ "time",      required_argument, NULL, OPT_TIME },
	{ "partition", required_argument, NULL, OPT_PARTITION },
	{ "account",   required_argument, NULL, OPT_ACCOUNT },
	{ "qos",       required_argument, NULL, OPT_QOS },
	{ "mem",       required_argument, NULL, OPT_MEM },
	{ "max-array", required_argument, NULL, OPT_MAX_ARRAY },
	{ "plot",      required_argument, NULL, OPT_PLOT },
	{ "refine",    required_argument, NULL, OPT_REFINE },
	{ "format",    required_argument, NULL, OPT_FORMAT },
	{ "error",     no_argument,       NULL, OPT_ERROR },
	{ "help",     no_argument,       NULL, 'h' },
	{ NULL, 0, NULL, 0 },
};

static void
sweep_usage(FILE *f)
{
	fprintf(f,
"usage: hybounce sweep PRESET [--set KEY=VALUE]... --vary KEY=SPEC [--vary ...]\n"
"                      [--refine OBS[:TOL]] [--error] [--format csv|hdf5]\n"
"                      [--jobs N] [--shard K/N] [--quiet] [--plot FILE] --out DIR\n"
"       hybounce sweep PRESET ... --out DIR --emit slurm|parallel [--shards N]\n"
"                      [--sshlogin HOSTS] [--time T] [--partition P]\n"
"                      [--account A] [--qos Q] [--mem M] [--max-array N]\n"
"       hybounce sweep --merge DIR [--shards N] [--format csv|hdf5] [--plot FILE]\n"
"\n"
"Runs the Cartesian product of the varied values (the last --vary varies\n"
"fastest); every other value comes from PRESET and --set.\n"
"\n"
"  -v, --vary KEY=SPEC     an axis: FROM:TO:N (N values, ends included),\n"
"                          FROM:TO:N:log (log spacing), or V1,V2,... (units as\n"
"                          in --set: --vary initial.x0='10 um,40 um'); the\n"
"                          preset's '; sweep: --vary' lines are axes too\n"
"  -s, --set KEY=VALUE     override one value of the preset (repeatable)\n"
"      --refine OBS[:TOL]  compute the grid of one or two ranges, then bisect\n"
"                          where the class of OBS (a runs.csv column) changes\n"
"                          until each boundary is within TOL of each axis\n"
"                          (default 1e-3); OBS<X or OBS>X: which side of X;\n"
"                          DIR/boundaries.csv, runs.csv's 'refined' column\n"
"      --error             error bars: each point run again with rk8pd at a\n"
"                          hundredth of the tolerances (about 2.5x the work);\n"
"                          runs.csv gets OBS_err beside the observables,\n"
"                          collisions.csv NAME_err columns, as --batch --error\n"
"  -j, --jobs N            worker threads (default: the online processors)\n"
"      --shard K/N         compute only shard K of N (points K, K+N, ...);\n"
"                          then merge with --merge DIR\n"
"  -o, --out DIR           the folder: runs.csv, collisions.csv, sweep.preset;\n"
"                          run again with the same command to resume\n"
"      --format hdf5       the runs and collisions as DIR/sweep.h5 (chunked,\n"
"                          compressed, units and spec as attributes) instead\n"
"                          of the CSV files (default: csv)\n"
"  -q, --quiet             no progress\n"
"      --progress PCT      without a terminal, a progress line every PCT %%\n"
"                          of the points (default 10)\n"
"      --plot FILE         when the sweep is complete, draw it (as hybounce plot\n"
"                          DIR): e against the varied key, one curve per\n"
"                          collision i = 0..3, or over two keys a heat map of\n"
"                          collision 0; FILE.png, .pdf, .svg or .tex\n"
"      --max-points N      allow a sweep of up to N points (default 1000000,\n"
"                          at most 1000000000); a larger sweep is refused\n"
"      --emit slurm        print a script that submits the shards as Slurm job\n"
"                          arrays and a merge job that runs after them\n"
"                          whatever their fate (sh FILE; logs in DIR/logs)\n"
"      --emit parallel     print a GNU parallel command line for the shards\n"
"                          and the merge\n"
"                          (both leave out the shards DIR holds done)\n"
"      --shards N          shards of --emit (default: the online processors)\n"
"      --sshlogin HOSTS    (--emit parallel) hosts for parallel --sshlogin;\n"
"                          DIR and the binary must be on a shared file system\n"
"      --time T            (--emit slurm) sbatch --time of every job, e.g. 2:00:00\n"
"      --partition P       (--emit slurm) sbatch --partition\n"
"      --account A         (--emit slurm) sbatch --account\n"
"      --qos Q             (--emit slurm) sbatch --qos\n"
"      --mem M             (--emit slurm) sbatch --mem of every job, e.g. 2G\n"
"      --max-array N       (--emit slurm) the cluster's MaxArraySize when\n"
"                          scontrol cannot tell it (default: scontrol's, else\n"
"                          1001); more shards go in several arrays\n"
"                          (other sbatch options: its SBATCH_* variables)\n"
"      --merge DIR         merge the shards' journals in DIR into runs.csv and\n"
"                          collisions.csv; with --shards N, name the shards\n"
"                          of N that did not finish\n"
"  -h, --help              show this help\n"
"\n"
"Exit status: 0 complete (numerically failed points are rows with their\n"
"message), 1 could not complete, 2 bad input, 128+N stopped by signal N\n"
"(SIGINT, SIGTERM, SIGHUP: the points done are kept; run again to resume).\n"
"See hybounce(1).\n");
}

/* A refusal (report.h): "hybounce sweep: ...", then where usage is. */
#define bad(...) cli_refuse_usage(PROG, PROG, __VA_ARGS__)

static int
parse_long(const char *t, long lo, long hi, long *out)
{
	char *end;
	long v;

	errno = 0;
	v = strtol(t, &end, 10);
	if (end == t || *end != '\0' || errno != 0 || v < lo || v > hi)
		return -1;
	*out = v;
	return 0;
}

static long
online_cpus(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);

	return n < 1 ? 1 : n;
}

/* ------------------------------------------------------------------ */
/* Progress                                                            */

struct progress {
	long resumed, total;   /* points found done at the start, points of the shard */
	int tty, quiet;
	double step;       /* fraction between lines without a terminal */
	double next;       /* next fraction to report */
	double last_draw;  /* s, for the terminal bar */
};

static void
fmt_eta(double s, char *buf, size_t n)
{
	long t = (long)(s + 0.5);

	if (s != s || s < 0 || s > 1e8)
		snprintf(buf, n, "--:--");
	else if (t >= 3600)
		snprintf(buf, n, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
	else
		snprintf(buf, n, "%ld:%02ld", t / 60, t % 60);
}

static void
on_progress(void *ctx, const struct hb_sweep_progress *p)
{
	struct progress *g = ctx;
	long computed = p->done - p->resumed;
	double frac = p->total ? (double)p->done / (double)p->total : 1;
	double rate = p->elapsed > 0 ? (double)computed / p->elapsed : 0;
	double eta = rate > 0 ? (double)(p->total - p->done) / rate : -1;
	char e[32];

	if (computed == 0) {
		g->resumed = p->resumed;
		g->total = p->total;
	}
	if (g->quiet)
		return;
	if (computed == 0) {
		if (p->resumed > 0)
			fprintf(stderr, "sweep: resuming: %ld of %ld points already done\n",
			        p->resumed, p->total);
		return;
	}
	fmt_eta(eta, e, sizeof e);
	if (g->tty) {
		double now = clock_seconds(CLOCK_MONOTONIC);
		int w = 30, fill = (int)(frac * w);

		if (p->done < p->total && now - g->last_draw < 0.1)
			return;
		g->last_draw = now;
		fprintf(stderr, "\r[%.*s%*s] %ld/%ld %3.0f%%  %.1f points/s  ETA %s  failed %ld\033[K",
		        fill, "##############################", w - fill, "", p->done,
		        p->total, 100 * frac, rate, e, p->failed);
		if (p->done == p->total)
			fputc('\n', stderr);
		return;
	}
	if (frac + 1e-12 < g->next && p->done < p->total)
		return;
	while (g->next <= frac + 1e-12)
		g->next += g->step;
	fprintf(stderr, "sweep: %ld/%ld points (%.0f%%), %.1f points/s, ETA %s, %ld failed\n",
	        p->done, p->total, 100 * frac, rate, e, p->failed);
}

/* ------------------------------------------------------------------ */
/* Output                                                              */

/* How DIR/runs.csv and DIR/collisions.csv will be written (before). */
struct dir_targets {
	char path[3][4200];
	struct hb_atomic_target t[3];
	int nfiles;    /* 3 with a refined sweep's boundaries.csv */
};

static void
probe_dir(const char *dir, struct dir_targets *d, int refined, int hdf5)
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
static void
print_wrote_dir(const struct dir_targets *d, int unchanged)
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
static int
plot_check(const char *plot, const char *dir)
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
static int
plot_draw_dir(const char *plot, const char *dir)
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

/* ------------------------------------------------------------------ */
/* Input                                                               */

/*
 * The preset, the --set values and the axes; NULL after printing why (exit
 * 2).  check: every point's scene checked now (--emit, which writes jobs
 * and runs none); a sweep that runs checks each point once, in its run
 * (hb_sim_new), and is refused with the same message.
 */
static struct hb_sweep *
build(const char *preset, const char *const *sets, int nsets,
      const char *const *varies, int nvaries, const char *out, long max_points,
      const char *refine, int error, int check)
{
	char path[4096], spec[4200], msg[4096], more[128];
	struct hb_scene sc;
	struct hb_sweep *sw;
	char *text = NULL;

	msg[0] = '\0';
	/* Read once (a pipe or FIFO works), bounded; the scene and the axes come from it. */
	if (hb_preset_open_text(preset, sets, nsets, &sc, path, sizeof path, &text, msg,
	                        sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": %s\n", msg[0] ? msg : preset);
		return NULL;
	}
	sw = hb_sweep_new(&sc, msg, sizeof msg);
	if (sw == NULL) {
		fprintf(stderr, PROG ": %s\n", msg);
		free(text);
		return NULL;
	}
	/*
	 * Work bounded: at most max_points unless asked for.  The folder's own
	 * sweep.preset (a shard of --emit, a resume) was allowed when it was made.
	 */
	snprintf(spec, sizeof spec, "%s/sweep.preset", out);
	if (max_points == 0 && hb_outputs_same_file(path, spec))
		max_points = 1000000000L;
	snprintf(more, sizeof more, "--max-points N allows up to N (at most 1000000000)");
	hb_sweep_set_max_points(sw, max_points ? max_points : HB_SWEEP_MAX_POINTS, more);
	msg[0] = '\0';
	if (hb_sweep_vary_from_preset(sw, text, path, msg, sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": %s\n", msg);
		free(text);
		hb_sweep_free(sw);
		return NULL;
	}
	for (int i = 0; i < nvaries; i++) {
		msg[0] = '\0';
		if (hb_sweep_vary(sw, varies[i], msg, sizeof msg) != HB_OK) {
			fprintf(stderr, PROG ": %s\n", msg);
			free(text);
			hb_sweep_free(sw);
			return NULL;
		}
	}
	/* --error: the command line's, or the preset's line */
	hb_sweep_error_from_preset(sw, text);
	if (error)
		hb_sweep_set_error(sw, 1);
	/* --refine after every axis: the command line's, else the preset's line */
	msg[0] = '\0';
	if (hb_sweep_npoints(sw) > 0 &&
	    (refine != NULL ? hb_sweep_refine(sw, refine, msg, sizeof msg)
	                    : hb_sweep_refine_from_preset(sw, text, path, msg, sizeof msg)) != HB_OK) {
		fprintf(stderr, PROG ": %s\n", msg);
		free(text);
		hb_sweep_free(sw);
		return NULL;
	}
	free(text);
	if (hb_sweep_npoints(sw) == 0) {
		bad("nothing to vary: expected --vary KEY=SPEC (e.g. --vary "
		    "law.c=1e8:1e10:20:log), or a preset with '; sweep: --vary' lines");
		hb_sweep_free(sw);
		return NULL;
	}
	msg[0] = '\0';
	if (check && hb_sweep_check(sw, msg, sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": %s\n", msg);
		hb_sweep_free(sw);
		return NULL;
	}
	return sw;
}

int
sweep_main(int argc, char **argv)
{
	const char **sets, **varies;
	int nsets = 0, nvaries = 0, quiet = 0, c, status = 2;
	long jobs = 0, shard_k = 0, shard_n = 1, shards = 0, pct = 10, max_points = 0;
	const char *out = NULL, *emit = NULL, *sshlogin = NULL, *merge = NULL, *slurm_opt = NULL;
	const char *plot = NULL;
	const char *refine = NULL;
	int hdf5 = 0, error = 0;
	struct sweep_hdf5 *h5 = NULL;
	struct sweep_emit_opts eo = { 0 };
	struct hb_sweep *sw = NULL;
	char msg[2048];

	sets = calloc((size_t)argc + 1, sizeof *sets);
	varies = calloc((size_t)argc + 1, sizeof *varies);
	if (sets == NULL || varies == NULL) {
		free(sets);
		free(varies);
		fprintf(stderr, PROG ": out of memory\n");
		return 1;
	}
	optind = 1;
	while ((c = getopt_long(argc, argv, "s:v:j:o:qh", sweep_options_long, NULL)) != -1) {
		switch (c) {
		case 's': sets[nsets++] = optarg; break;
		case 'v': varies[nvaries++] = optarg; break;
		case 'j':
			if (parse_long(optarg, 1, 4096, &jobs) != 0) {
				status = bad("--jobs '%s': accepted: an integer from 1 to 4096", optarg);
				goto done;
			}
			break;
		case 'k': {
			const char *sl = strchr(optarg, '/');
			char kk[32];

			snprintf(kk, sizeof kk, "%.*s", sl ? (int)(sl - optarg) : 0, optarg);
			if (sl == NULL || parse_long(sl + 1, 1, 1000000, &shard_n) != 0 ||
			    parse_long(kk, 0, shard_n - 1, &shard_k) != 0) {
				status = bad("--shard '%s': expected K/N with 0 <= K < N, e.g. "
				             "--shard 0/4", optarg);
				goto done;
			}
			break;
		}
		case 'o': out = optarg; break;
		case 'q': quiet = 1; break;
		case OPT_EMIT:
			if (strcmp(optarg, "slurm") != 0 && strcmp(optarg, "parallel") != 0) {
				status = bad("--emit '%s': accepted: slurm, parallel", optarg);
				goto done;
			}
			emit = optarg;
			break;
		case OPT_SHARDS:
			if (parse_long(optarg, 1, 1000000, &shards) != 0) {
				status = bad("--shards '%s': accepted: an integer from 1 to 1000000",
				             optarg);
				goto done;
			}
			break;
		case OPT_SSHLOGIN: sshlogin = optarg; break;
		case OPT_PLOT: plot = optarg; break;
		case OPT_MERGE: merge = optarg; break;
		case OPT_PROGRESS:
			if (parse_long(optarg, 1, 100, &pct) != 0) {
				status = bad("--progress '%s': accepted: a percentage from 1 to 100",
				             optarg);
				goto done;
			}
			break;
		case OPT_MAX_POINTS:
			if (parse_long(optarg, 1, 1000000000L, &max_points) != 0) {
				status = bad("--max-points '%s': accepted: an integer from 1 to "
				             "1000000000", optarg);
				goto done;
			}
			break;
		case OPT_TIME:
			if (!slurm_time_ok(optarg)) {
				status = bad("--time '%s': accepted: Slurm's time limit, MINUTES, "
				             "MINUTES:SECONDS, HOURS:MINUTES:SECONDS, DAYS-HOURS, "
				             "DAYS-HOURS:MINUTES[:SECONDS] or UNLIMITED (e.g. 2:00:00)",
				             optarg);
				goto done;
			}
			eo.time = optarg;
			slurm_opt = "--time";
			break;
		case OPT_PARTITION:
		case OPT_ACCOUNT:
		case OPT_QOS: {
			const char *what = c == OPT_PARTITION ? "--partition"
			                 : c == OPT_ACCOUNT ? "--account" : "--qos";

			if (!slurm_name_ok(optarg)) {
				status = bad("%s '%s': accepted: a name of letters, digits and _ - . "
				             "(a comma list for several)", what, optarg);
				goto done;
			}
			*(c == OPT_PARTITION ? &eo.partition : c == OPT_ACCOUNT ? &eo.account
			  : &eo.qos) = optarg;
			slurm_opt = what;
			break;
		}
		case OPT_MEM:
			if (!slurm_mem_ok(optarg)) {
				status = bad("--mem '%s': accepted: Slurm's memory size, megabytes or a "
				             "number with K, M, G or T (e.g. 2G)", optarg);
				goto done;
			}
			eo.mem = optarg;
			slurm_opt = "--mem";
			break;
		case OPT_MAX_ARRAY:
			if (parse_long(optarg, 1, 4000001, &eo.max_array) != 0) {
				status = bad("--max-array '%s': accepted: the cluster's MaxArraySize, "
				             "an integer from 1 to 4000001", optarg);
				goto done;
			}
			slurm_opt = "--max-array";
			break;
		case OPT_REFINE: refine = optarg; break;
		case OPT_ERROR: error = 1; break;
		case OPT_FORMAT:
			if (strcmp(optarg, "csv") != 0 && strcmp(optarg, "hdf5") != 0) {
				status = bad("--format '%s': accepted: csv, hdf5", optarg);
				goto done;
			}
			hdf5 = strcmp(optarg, "hdf5") == 0;
			break;
		case 'h':
			sweep_usage(stdout);
			status = 0;
			goto done;
		default:
			fprintf(stderr, "Try 'hybounce sweep --help'.\n");
			goto done;
		}
	}

	if (plot != NULL && hdf5) {
		status = bad("--plot %s: the figure is drawn from the sweep's CSV files; accepted: "
		             "--plot with --format csv (or hybounce plot on a CSV sweep)", plot);
		goto done;
	}
	if (merge != NULL) {
		if (optind < argc || nvaries || nsets || out || emit || sshlogin || slurm_opt || refine ||
		    error) {
			status = bad("--merge DIR takes no preset and no other option but "
			             "--shards N, --format, --plot FILE and --quiet");
			goto done;
		}
		if (plot != NULL && plot_check(plot, merge) != 0)
			goto done;   /* exit 2 */
		struct dir_targets dt;

		probe_dir(merge, &dt, 0, hdf5);
		msg[0] = '\0';
		if (hdf5 && (h5 = sweep_hdf5_new(merge, msg, sizeof msg)) == NULL) {
			fprintf(stderr, PROG ": %s\n", msg);
			status = 1;
			goto done;
		}
		char shards_txt[24] = "N";

		if (shards > 0)
			snprintf(shards_txt, sizeof shards_txt, "%ld", shards);
		if (hb_sweep_merge_to(merge, shards, h5 ? &sweep_hdf5_sink : NULL, h5, msg,
		                      sizeof msg) != HB_OK) {
			char spec[4200];
			struct stat sb;

			fprintf(stderr, PROG ": merge: %s\n", msg);
			if (strstr(msg, " shards incomplete: ") || strstr(msg, " shard incomplete: "))
				fprintf(stderr, PROG ": the same --emit command (e.g. hybounce sweep "
				        "%s/sweep.preset --out %s --emit slurm --shards %s%s) computes "
				        "only those, then merges\n", merge, merge, shards_txt,
				        hdf5 ? " --format hdf5" : "");
			/* a folder that holds no sweep is bad input; an incomplete one is not */
			snprintf(spec, sizeof spec, "%s/sweep.preset", merge);
			status = stat(spec, &sb) == 0 && S_ISREG(sb.st_mode) ? 1 : 2;
			goto done;
		}
		if (!quiet)
			print_wrote_dir(&dt, 0);
		status = plot != NULL ? plot_draw_dir(plot, merge) : 0;
		goto done;
	}
	if (optind >= argc) {
		status = bad("no preset; expected hybounce sweep PRESET --vary KEY=SPEC "
		             "--out DIR");
		goto done;
	}
	if (argc - optind > 1) {
		status = bad("more than one preset given ('%s' ...)", argv[optind + 1]);
		goto done;
	}
	if (out == NULL) {
		status = bad("no output folder; expected --out DIR");
		goto done;
	}
	if (emit == NULL && (shards || sshlogin || slurm_opt)) {
		status = bad("%s is an option of --emit", shards ? "--shards"
		             : sshlogin ? "--sshlogin" : slurm_opt);
		goto done;
	}
	if (plot != NULL && (emit != NULL || shard_n > 1)) {
		status = bad("--plot %s: %s", plot, emit != NULL
		             ? "the emitted jobs compute the sweep later; draw it when it is merged "
		               "(--merge DIR --plot FILE, or hybounce plot DIR)"
		             : "a shard holds part of the sweep; draw it when it is merged "
		               "(--merge DIR --plot FILE)");
		goto done;
	}
	if (plot != NULL && plot_check(plot, out) != 0)
		goto done;   /* exit 2 */
	if (emit != NULL && slurm_opt != NULL && strcmp(emit, "slurm") != 0) {
		status = bad("--emit %s: %s goes with --emit slurm", emit, slurm_opt);
		goto done;
	}
	if (emit != NULL && (shard_n > 1 || (sshlogin && strcmp(emit, "slurm") == 0))) {
		status = bad("--emit %s: %s", emit, shard_n > 1 ? "the emitted jobs choose "
		             "their shards; --shard goes without --emit"
		             : "--sshlogin goes with --emit parallel");
		goto done;
	}
	sw = build(argv[optind], sets, nsets, varies, nvaries, out, max_points, refine, error,
	           emit != NULL);
	if (sw == NULL)
		goto done;      /* exit 2: build said why */
	if (hb_sweep_refined(sw) && (emit != NULL || shard_n > 1)) {
		status = bad("%s: a refined sweep (--refine) runs its rounds one after another on "
		             "one machine (on --jobs threads); accepted: --refine without --emit "
		             "and --shard", emit != NULL ? "--emit" : "--shard");
		goto done;
	}

	if (emit != NULL) {
		if (shards == 0)
			shards = online_cpus();
		msg[0] = '\0';
		/* sweep.preset with its provenance line first; sweep_emit finds it in place. */
		status = hb_sweep_prepare_dir_with(sw, out, cli_provenance(), msg, sizeof msg);
		if (status != HB_OK) {
			fprintf(stderr, PROG ": %s\n", msg);
			status = status == HB_EINVAL ? 2 : 1;
			goto done;
		}
		eo.kind = emit;
		eo.shards = shards;
		eo.hdf5 = hdf5;
		eo.sshlogin = sshlogin;
		status = sweep_emit(sw, out, &eo, msg, sizeof msg);
		if (status != 0)
			fprintf(stderr, PROG ": %s\n", msg);
		goto done;
	}

	{
		struct progress g = { 0 };
		struct hb_sweep_options o = { 0 };
		struct hb_sweep_refine_stats rs = { 0 };
		struct dir_targets dt;

		g.tty = isatty(STDERR_FILENO);
		g.quiet = quiet;
		g.step = (double)pct / 100;
		g.next = g.step;
		o.dir = out;
		o.jobs = (int)(jobs ? jobs : online_cpus());
		o.shard_k = shard_k;
		o.shard_n = shard_n;
		o.progress = on_progress;
		o.ctx = &g;
		o.provenance = cli_provenance();
		o.refine_stats = &rs;
		/* SIGINT, SIGTERM, SIGHUP (those not ignored): the points done are
		 * journaled, exit 128 + N (signals.h). */
		cli_signals_watch();
		o.cancel = &cli_signal;
		probe_dir(out, &dt, hb_sweep_refined(sw), hdf5);
		msg[0] = '\0';
		if (hdf5 && (h5 = sweep_hdf5_new(out, msg, sizeof msg)) == NULL) {
			fprintf(stderr, PROG ": %s\n", msg);
			status = 1;
			goto done;
		}
		o.sink = h5 ? &sweep_hdf5_sink : NULL;
		o.sink_ctx = h5;
		status = hb_sweep_run(sw, &o, msg, sizeof msg);
		cli_signals_restore();
		if (status == HB_EDONE) {
			/* Interrupted: what was done is journaled; exit as the signal would. */
			if (g.tty && !quiet)
				fputc('\n', stderr);
			fprintf(stderr, PROG ": %s\n", msg);
			status = cli_signal_status((int)cli_signal);
		} else if (status == HB_EINVAL) {
			fprintf(stderr, PROG ": %s\n", msg);
			status = 2;
		} else if (status != HB_OK) {
			fprintf(stderr, PROG ": %s\n", msg);
			status = 1;
		} else if (!quiet) {
			if (shard_n > 1)
				fprintf(stderr, "sweep: shard %ld of %ld done in %s; merge the shards "
				        "with: hybounce sweep --merge %s\n", shard_k, shard_n, out, out);
			else
				print_wrote_dir(&dt, g.total > 0 && g.resumed == g.total);
			if (rs.runs > 0)
				sweep_refine_summary(stderr, sw, &rs);
		}
		if (status == HB_OK && plot != NULL)
			status = plot_draw_dir(plot, out);
	}
done:
	sweep_hdf5_free(h5);
	hb_sweep_free(sw);
	free(sets);
	free(varies);
	return status;
}
