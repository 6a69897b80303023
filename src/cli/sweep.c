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
 *
 * This file holds the command line: its options, --help, and the order of
 * what the command does with them (a merge, --emit, or a run).  The input
 * is read by sweep_input.c, the progress drawn by sweep_progress.c, the
 * files written named and --plot drawn by sweep_output.c (sweep_cmd.h).
 */
#include <errno.h>
#include <signal.h>
#include <getopt.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "hybounce/status.h"
#include "hybounce/sweep.h"

#include "sweep_cli.h"
#include "sweep_cmd.h"
#include "sweep_hdf5.h"
#include "report.h"
#include "signals.h"

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
		if (plot != NULL && sweep_plot_check(plot, merge) != 0)
			goto done;   /* exit 2 */
		struct sweep_dir_targets dt;

		sweep_probe_dir(merge, &dt, 0, hdf5);
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
			sweep_print_wrote_dir(&dt, 0);
		status = plot != NULL ? sweep_plot_draw(plot, merge) : 0;
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
	if (plot != NULL && sweep_plot_check(plot, out) != 0)
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
	sw = sweep_build(argv[optind], sets, nsets, varies, nvaries, out, max_points, refine,
	                 error, emit != NULL);
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
		struct sweep_progress g = { 0 };
		struct hb_sweep_options o = { 0 };
		struct hb_sweep_refine_stats rs = { 0 };
		struct sweep_dir_targets dt;

		g.tty = isatty(STDERR_FILENO);
		g.quiet = quiet;
		g.step = (double)pct / 100;
		g.next = g.step;
		o.dir = out;
		o.jobs = (int)(jobs ? jobs : online_cpus());
		o.shard_k = shard_k;
		o.shard_n = shard_n;
		o.progress = sweep_on_progress;
		o.ctx = &g;
		o.provenance = cli_provenance();
		o.refine_stats = &rs;
		/* SIGINT, SIGTERM, SIGHUP (those not ignored): the points done are
		 * journaled, exit 128 + N (signals.h). */
		cli_signals_watch();
		o.cancel = &cli_signal;
		sweep_probe_dir(out, &dt, hb_sweep_refined(sw), hdf5);
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
				sweep_print_wrote_dir(&dt, g.total > 0 && g.resumed == g.total);
			if (rs.runs > 0)
				sweep_refine_summary(stderr, sw, &rs);
		}
		if (status == HB_OK && plot != NULL)
			status = sweep_plot_draw(plot, out);
	}
done:
	sweep_hdf5_free(h5);
	hb_sweep_free(sw);
	free(sets);
	free(varies);
	return status;
}
