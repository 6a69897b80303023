/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_cmd.c - `hybounce fit PRESET --data FILE --free KEY[,KEY...]`: reads
 * the data (a CSV file, or a recording whose onsets give the impact times,
 * shown first), fits, prints the estimates with standard errors, the
 * correlation matrix, the residuals and the cost, and writes the fitted
 * scene as a preset.  Progress goes to stderr, the report to stdout.
 */
#include <errno.h>
#include <stdarg.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "hybounce/atomic.h"
#include "hybounce/fit.h"
#include "hybounce/input.h"
#include "hybounce/onset.h"
#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "fit_cmd.h"
#include "plot_cmd.h"
#include "plot_out.h"
#include "report.h"
#include "signals.h"

#define PROG "hybounce"
/* The level of the chi-square test of stated noise (two-sided). */
#define FIT_NOISE_LEVEL 0.05

enum { OPT_ONSET_METHOD = 256, OPT_ONSET_THRESHOLD, OPT_ONSET_LEVEL, OPT_MIN_INTERVAL,
       OPT_MAX_ITER, OPT_RESIDUALS, OPT_ONSETS_OUT, OPT_MAX_RSE,
       OPT_REPORT, OPT_LAWS, OPT_PLOT };

static const struct option long_options[] = {
	{ "data",            required_argument, NULL, 'd' },
	{ "free",            required_argument, NULL, 'f' },
	{ "set",             required_argument, NULL, 's' },
	{ "out",             required_argument, NULL, 'o' },
	{ "residuals",       required_argument, NULL, OPT_RESIDUALS },
	{ "jobs",            required_argument, NULL, 'j' },
	{ "max-iter",        required_argument, NULL, OPT_MAX_ITER },
	{ "onset-method",    required_argument, NULL, OPT_ONSET_METHOD },
	{ "onset-threshold", required_argument, NULL, OPT_ONSET_THRESHOLD },
	{ "onset-level",     required_argument, NULL, OPT_ONSET_LEVEL },
	{ "min-interval",    required_argument, NULL, OPT_MIN_INTERVAL },
	{ "onsets-out",      required_argument, NULL, OPT_ONSETS_OUT },
	{ "max-relative-se", required_argument, NULL, OPT_MAX_RSE },
	{ "report",          required_argument, NULL, OPT_REPORT },
	{ "laws",            required_argument, NULL, OPT_LAWS },
	{ "plot",            required_argument, NULL, OPT_PLOT },
	{ "quiet",           no_argument,       NULL, 'q' },
	{ "help",            no_argument,       NULL, 'h' },
	{ NULL, 0, NULL, 0 },
};

static void
usage(FILE *f)
{
	fprintf(f,
"usage: hybounce fit PRESET --data FILE --free KEY[,KEY...] [--set KEY=VALUE]...\n"
"                [--out FILE] [--residuals FILE] [--jobs N] [--max-iter N]\n"
"                [--onset-method M] [--onset-threshold X] [--onset-level X]\n"
"                [--min-interval T] [--onsets-out FILE] [--max-relative-se X]\n"
"                [--report FILE.json] [--plot FILE] [--laws LAW,LAW...] [--quiet]\n"
"\n"
"Fits the free keys of PRESET so that its runs reproduce the measured\n"
"collisions (nonlinear least squares, GSL trust region), and writes the\n"
"fitted scene as a preset.\n"
"\n"
"  -d, --data FILE         the measurements: a CSV file with a column t_e (impact\n"
"                          times of a bouncing sequence; several with a column\n"
"                          trial), h_0, h_1, ... (drop and rebound heights, a\n"
"                          drop per row), or v_i with e, x_c_r and/or t_d\n"
"                          (separate drops), each optionally with sd_NAME and a\n"
"                          unit in the header (t_e [ms]); NA or an empty cell\n"
"                          for a missed value; or a recording of a bouncing\n"
"                          sequence (WAV, FLAC, Ogg, MP3, M4A, AIFF: known by\n"
"                          its content)\n"
"  -f, --free KEY,...      the keys to fit, e.g. law.c,law.alpha (repeatable)\n"
"  -s, --set KEY=VALUE     change the preset first, e.g. a start (repeatable)\n"
"  -o, --out FILE          the fitted preset (default: DATA's name + -fit.preset)\n"
"      --residuals FILE    write the points as CSV: measured, simulated, sd ...\n"
"      --report FILE.json  write the report as JSON: dof, cost, reduced chi-square,\n"
"                          the noise test, AIC, BIC, estimates, numerical\n"
"                          errors, 95%% intervals, correlations, the verdict and\n"
"                          the residuals\n"
"      --plot FILE         draw measured against fitted, the residuals below, to\n"
"                          FILE.png, .pdf, .svg or .tex (as hybounce plot)\n"
"  -j, --jobs N            runs in parallel (default: every core)\n"
"      --max-iter N        iteration cap (default 100)\n"
"      --max-relative-se X a credible estimate's standard error is at most X\n"
"                          of its value (default 0.1), else exit 1\n"
"      --laws LAW,...      fit each law to the same data and rank them by AIC\n"
"                          (e.g. shccl,bwshccl,bwmcl); free keys per law: --free\n"
"                          LAW:KEY, else --free KEY, else the law's default (shccl:\n"
"                          law.c; bwshccl, bwmcl: law.c,law.alpha); starts per law:\n"
"                          --set LAW:KEY=VALUE; --out, --residuals, --plot: the\n"
"                          best law;\n"
"                          exit status: the best law's\n"
"      --onset-method M    aubio onset method for a recording (default hfc)\n"
"      --onset-threshold X aubio's peak-picking threshold (default 0.3)\n"
"      --onset-level X     a click starts where it reaches X (0 < X <= 1) of its\n"
"                          peak (default 0.3)\n"
"      --min-interval T    shortest interval between clicks (default 2 ms)\n"
"      --onsets-out FILE   write a recording's impact times as a t_e CSV (to\n"
"                          correct by hand and fit with --data)\n"
"  -q, --quiet             no progress lines on stderr, no residual table\n"
"\n"
"Exit status: 0 converged to credible estimates, 1 not credible (stopped\n"
"without converging: iteration cap, no progress, parameters not identifiable;\n"
"an estimate's relative standard error above --max-relative-se; an\n"
"estimate's numerical error, how far it moves when the runs are made with\n"
"rk8pd at run.rtol/100 (one more evaluation of the data), above 0.1 of its\n"
"standard error; with sd columns, residuals inconsistent with them: a\n"
"two-sided chi-square test at 5%%): the reasons on stderr, the estimates\n"
"still reported and written,\n"
"2 bad input (a recording that is no bouncing sequence too), 128+N stopped by signal\n"
"N (SIGINT, SIGTERM, SIGHUP: the best point so far is written).  See hybounce(1).\n");
}

/* Refusals (report.h): "hybounce fit: ...", and with where usage is. */
#define bad(...) cli_refuse(PROG " fit", __VA_ARGS__)
#define bad_usage(...) cli_refuse_usage(PROG " fit", "hybounce fit", __VA_ARGS__)

/* Parses a positive whole number for an option. */
static int
parse_int(const char *opt, const char *s, int *out)
{
	char *end;
	long v;

	errno = 0;
	v = strtol(s, &end, 10);
	if (*s == '\0' || *end != '\0' || errno != 0 || v < 1 || v > 100000)
		return bad("%s '%s': accepted: a whole number from 1 to 100000", opt, s);
	*out = (int)v;
	return 0;
}

/* Parses a fraction in (0, 1] for an option. */
static int
parse_fraction(const char *opt, const char *s, double *out)
{
	char *end;
	double v = strtod(s, &end);

	if (*s == '\0' || *end != '\0' || !(v > 0) || !(v <= 1))
		return bad("%s '%s': accepted: a fraction > 0 and <= 1", opt, s);
	*out = v;
	return 0;
}

static int
parse_pos(const char *opt, const char *s, double *out)
{
	char *end;
	double v = strtod(s, &end);

	if (*s == '\0' || *end != '\0' || !(v > 0) || !isfinite(v))
		return bad("%s '%s': accepted: a number > 0", opt, s);
	*out = v;
	return 0;
}

/* The default output: the data file's base name without extension + -fit.preset. */
static void
default_out(const char *data, char *out, size_t n)
{
	const char *b = strrchr(data, '/');
	const char *dot;
	int len;

	b = b != NULL ? b + 1 : data;
	dot = strrchr(b, '.');
	len = dot != NULL && dot != b ? (int)(dot - b) : (int)strlen(b);
	snprintf(out, n, "%.*s-fit.preset", len, b);
}

static void
progress(void *ctx, int iter, double cost, long runs)
{
	(void)ctx;
	fprintf(stderr, PROG " fit: iteration %d: cost %.6g (%ld runs)\n", iter, cost, runs);
}

int
fit_main(int argc, char **argv)
{
	const char *data = NULL, *out = NULL, *resid_path = NULL, *preset, *onsets_path = NULL;
	const char *report_path = NULL, *laws = NULL;
	const char **sets = NULL, **nonlaw_sets = NULL, *keys[HB_FIT_MAX_FREE];
	char *freebuf = NULL, path[1024], outbuf[1024], msg[4096];
	struct hb_onset_options oo = { 0 };
	double max_rse = 0.1;
	/* with each estimate's numerical error (fit.h), also of each law of --laws */
	struct hb_fit_options fo = { .numerical = 1 };
	struct hb_fit_data d = { 0 };
	struct hb_fit_result r = { 0 };
	struct hb_scene sc;
	struct hb_outputs pol;
	struct hb_fit *fit = NULL;
	int nsets = 0, nkeys = 0, quiet = 0, c, status = 2, sig = 0, k_out, k_resid = -1, k_ons = -1;
	int k_report = -1, nnonlaw = 0;
	const char *plot_path = NULL;
	struct plot_out po;
	struct hb_fit_stats fst;
	struct fit_verdict v;
	struct fit_report_ctx rc;
	size_t freelen = 0;

	if ((sets = calloc((size_t)argc + 1, sizeof *sets)) == NULL)
		return bad("out of memory");
	if ((nonlaw_sets = calloc((size_t)argc + 1, sizeof *sets)) == NULL) {
		free(sets);
		return bad("out of memory");
	}
	optind = 1;
	while ((c = getopt_long(argc, argv, "d:f:s:o:j:qh", long_options, NULL)) != -1) {
		switch (c) {
		case 'd': data = optarg; break;
		case 'f': {
			size_t l = strlen(optarg);
			char *nb = realloc(freebuf, freelen + l + 2);

			if (nb == NULL) {
				status = bad("out of memory");
				goto out;
			}
			freebuf = nb;
			if (freelen > 0)
				freebuf[freelen++] = ',';
			memcpy(freebuf + freelen, optarg, l + 1);
			freelen += l;
			break;
		}
		case 's': sets[nsets++] = optarg; break;
		case 'o': out = optarg; break;
		case OPT_RESIDUALS: resid_path = optarg; break;
		case 'j':
			if (parse_int("--jobs", optarg, &fo.jobs))
				goto out;
			break;
		case OPT_MAX_ITER:
			if (parse_int("--max-iter", optarg, &fo.max_iter))
				goto out;
			break;
		case OPT_ONSET_METHOD: oo.method = optarg; break;
		case OPT_ONSET_THRESHOLD:
			if (parse_pos("--onset-threshold", optarg, &oo.threshold))
				goto out;
			break;
		case OPT_ONSET_LEVEL:
			if (parse_fraction("--onset-level", optarg, &oo.level))
				goto out;
			break;
		case OPT_MIN_INTERVAL:
			if (parse_pos("--min-interval", optarg, &oo.min_interval))
				goto out;
			break;
		case OPT_ONSETS_OUT: onsets_path = optarg; break;
		case OPT_REPORT: report_path = optarg; break;
		case OPT_LAWS: laws = optarg; break;
		case OPT_PLOT: plot_path = optarg; break;
		case OPT_MAX_RSE:
			if (parse_pos("--max-relative-se", optarg, &max_rse))
				goto out;
			break;
		case 'q': quiet = 1; break;
		case 'h':
			usage(stdout);
			status = 0;
			goto out;
		default:
			fprintf(stderr, "Try 'hybounce fit --help'.\n");
			goto out;
		}
	}
	if (optind >= argc) {
		status = bad_usage("no preset given; expected: hybounce fit PRESET --data FILE "
		                   "--free KEY,...");
		goto out;
	}
	if (argc - optind > 1) {
		status = bad_usage("more than one preset given ('%s' ...); expected one PRESET",
		                   argv[optind + 1]);
		goto out;
	}
	preset = argv[optind];
	if (data == NULL) {
		status = bad_usage("--data FILE is required; accepted: a CSV file of measurements "
		                   "or a .wav recording");
		goto out;
	}
	if (freebuf == NULL && laws == NULL) {
		status = bad("--free KEY[,KEY...] is required, e.g. --free law.c,law.alpha");
		goto out;
	}
	for (char *save = NULL, *k = freebuf != NULL ? strtok_r(freebuf, ", \t", &save) : NULL;
	     k != NULL;
	     k = strtok_r(NULL, ", \t", &save)) {
		if (nkeys == HB_FIT_MAX_FREE) {
			status = bad("--free: more than %d keys; accepted: at most %d",
			             HB_FIT_MAX_FREE, HB_FIT_MAX_FREE);
			goto out;
		}
		keys[nkeys++] = k;
	}
	if (nkeys == 0 && laws == NULL) {
		status = bad("--free: no key given, e.g. --free law.c,law.alpha");
		goto out;
	}

	msg[0] = '\0';
	/* with --laws, a --set LAW:KEY=VALUE is for that law's fit only (fit_laws.c) */
	for (int i = 0; i < nsets; i++)
		if (laws == NULL || fit_laws_prefix(sets[i], NULL) == 0)
			nonlaw_sets[nnonlaw++] = sets[i];
	if (hb_preset_open_named(preset, nonlaw_sets, nnonlaw, &sc, path, sizeof path, msg,
	                         sizeof msg) != HB_OK) {
		status = bad("%s", msg[0] ? msg : preset);
		goto out;
	}
	if (out == NULL) {
		default_out(data, outbuf, sizeof outbuf);
		out = outbuf;
	}
	/*
	 * The output policy (outputs.h), before the fit: never the data or the
	 * preset being fitted, never a shipped preset, never one file twice.
	 */
	hb_outputs_init(&pol);
	hb_outputs_input(&pol, data, "the data file (--data)");
	hb_outputs_input(&pol, path, "the preset being fitted");
	msg[0] = '\0';
	if (hb_outputs_add(&pol, out, "--out", msg, sizeof msg) != HB_OK) {
		status = bad("%s%s", strncmp(msg, "--out ", 6) == 0 ? "" : "--out ", msg);
		goto out;
	}
	k_out = pol.nout - 1;
	if (resid_path != NULL) {
		if (hb_outputs_add(&pol, resid_path, "--residuals", msg, sizeof msg) != HB_OK) {
			status = bad("%s%s", strncmp(msg, "--residuals ", 12) == 0 ? "" : "--residuals ",
			             msg);
			goto out;
		}
		k_resid = pol.nout - 1;
	}
	if (onsets_path != NULL) {
		if (hb_outputs_add(&pol, onsets_path, "--onsets-out", msg, sizeof msg) != HB_OK) {
			status = bad("%s%s", strncmp(msg, "--onsets-out ", 13) == 0 ? ""
			             : "--onsets-out ", msg);
			goto out;
		}
		k_ons = pol.nout - 1;
	}
	if (report_path != NULL) {
		if (hb_outputs_add(&pol, report_path, "--report", msg, sizeof msg) != HB_OK) {
			status = bad("%s%s", strncmp(msg, "--report ", 9) == 0 ? "" : "--report ", msg);
			goto out;
		}
		k_report = pol.nout - 1;
	}
	if (plot_path != NULL && (plot_out_parse(&po, "--plot", plot_path, msg, sizeof msg) != 0 ||
	                          plot_out_register(&po, &pol, msg, sizeof msg) != 0)) {
		status = bad("%s", msg);
		goto out;
	}
	printf("hybounce %s fit\n", HYBOUNCE_VERSION);
	printf("preset      %s (%s)\n", preset, path);
	/*
	 * The data, through the one loader (fit.h: a recording known by its
	 * content, whose onsets are shown first, even when they make no
	 * sequence; any other file a CSV read once and bounded).
	 */
	{
		struct hb_onset_result on;
		int st = hb_fit_data_open(data, &oo, &d, &on, msg, sizeof msg);
		const int recording = on.samplerate > 0;

		if (on.n + on.ndrop > 0)
			fit_print_onsets(data, &on);
		fflush(stdout);
		/* the clicks found, also of a refused take: to correct by hand */
		if (onsets_path != NULL && on.n + on.ndrop > 0 && (st == HB_OK || st == HB_EINVAL)) {
			char m[512];

			if (hb_atomic_write_with(onsets_path, fit_fill_onsets, &on, m, sizeof m)
			    != HB_OK) {
				hb_onset_result_free(&on);
				status = bad("--onsets-out %s", m);
				goto out;
			}
			cli_print_wrote(onsets_path, &pol.out[k_ons].target);
		}
		hb_onset_result_free(&on);
		if (st != HB_OK) {
			status = bad("--data %s", msg);
			goto out;
		}
		if (onsets_path != NULL && !recording) {
			status = bad("--onsets-out %s: --data %s is no recording; accepted: --onsets-out "
			             "with a recording (it writes the recording's impact times)",
			             onsets_path, data);
			goto out;
		}
	}
	{
		const int ob = d.kind == HB_FIT_SEQUENCE ? HB_FIT_OBS_TE : d.kind == HB_FIT_HEIGHTS
		             ? HB_FIT_OBS_H : HB_FIT_OBS_E;
		size_t missed = 0, rows = d.kind == HB_FIT_HEIGHTS ? d.ntrials : d.n;
		char what[160];

		for (int k = 0; k < HB_FIT_OBS_COUNT; k++)
			for (size_t i = 0; d.col[k] != NULL && i < d.n; i++)
				missed += isnan(d.col[k][i]);
		if (d.kind == HB_FIT_SEQUENCE && d.ntrials > 1)
			snprintf(what, sizeof what, "%zu bouncing sequences (trials, fitted jointly; t_e, "
			    "the first of each aligns its clocks)", d.ntrials);
		else if (d.kind == HB_FIT_SEQUENCE)
			snprintf(what, sizeof what, "one bouncing sequence (t_e; the first aligns the "
			    "clocks)");
		else if (d.kind == HB_FIT_HEIGHTS)
			snprintf(what, sizeof what, "rebound heights of %zu drop%s (trials, fitted jointly; "
			    "each from rest at its h_0)", d.ntrials, d.ntrials == 1 ? "" : "s");
		else
			snprintf(what, sizeof what, "separate drops (one run per row from contact at v_i)");
		printf("data        %s: %s, %zu row%s, %zu points", data, what, rows,
		    rows == 1 ? "" : "s", hb_fit_npoints(&d));
		if (missed > 0)
			printf(", %zu missed (NA)", missed);
		printf(", %s\n", d.sd[ob] != NULL ? "weighted by sd" : "no standard deviations");
	}
	if (laws != NULL) {
		struct fit_laws_args la = {
			.laws = laws, .preset = preset, .data = data, .sets = sets, .nsets = nsets,
			.keys = keys, .nkeys = nkeys, .d = &d, .fo = &fo, .max_rse = max_rse,
			.quiet = quiet, .out = out, .resid_path = resid_path,
			.report_path = report_path, .pol = &pol, .k_out = k_out, .k_resid = k_resid,
			.k_report = k_report, .plot = plot_path != NULL ? &po : NULL,
		};

		status = fit_laws(&la);
		goto out;
	}
	printf("free        ");
	for (int i = 0; i < nkeys; i++)
		printf("%s%s", i ? ", " : "", keys[i]);
	printf("\n");
	fflush(stdout);

	fo.keys = keys;
	fo.nkeys = nkeys;
	fo.progress = quiet ? NULL : progress;
	/*
	 * SIGINT, SIGTERM, SIGHUP (signals.h): the fit stops after the
	 * iteration in hand, and the best point so far is reported and written,
	 * marked as interrupted; exit 128 + N.
	 */
	cli_signals_watch();
	msg[0] = '\0';
	if ((fit = hb_fit_new(&sc, &d, &fo, msg, sizeof msg)) == NULL) {
		cli_signals_restore();
		if (cli_signal != 0) {
			status = cli_signal_status(cli_signal);
			fprintf(stderr, PROG " fit: interrupted by %s before the start was computed: "
			        "nothing written\n", cli_signal_name(cli_signal));
			goto out;
		}
		status = bad("%s", msg);
		goto out;
	}
	while (cli_signal == 0 && !hb_fit_iterate(fit))
		;
	sig = cli_signal;
	if (hb_fit_result_get(fit, &r, msg, sizeof msg) != HB_OK) {
		cli_signals_restore();
		status = bad("%s", msg);
		goto out;
	}
	if (sig != 0)
		snprintf(r.why, sizeof r.why, "interrupted by %s (the best point so far)",
		         cli_signal_name(sig));
	hb_fit_stats(&r, FIT_NOISE_LEVEL, &fst);
	/* where the time went: a measurement, so on stderr with the progress */
	if (!quiet)
		fprintf(stderr, PROG " fit: runs: %.3g s of CPU; %.3g s on %d thread%s with a core "
		        "each (%.2fx)\n", r.run_cpu, r.run_span, r.threads, r.threads == 1 ? "" : "s",
		        r.run_span > 0 ? r.run_cpu / r.run_span : 1.0);
	fit_report_print(&r, &d, &fst, quiet);
	fit_verdict(&r, &fst, max_rse, &v);
	if (sig != 0) {
		v.status = cli_signal_status(sig);
		snprintf(v.reason[0], sizeof v.reason[0], "%.500s", r.why);
		v.n = 1;
	}
	rc = (struct fit_report_ctx){ .preset = preset, .data = data, .d = &d, .r = &r, .st = &fst,
	                              .v = &v, .status = v.status, .sig = sig };

	/* The fitted scene: named after the data, reproducing the best fit. */
	{
		char name[sizeof r.fitted.name], desc[sizeof r.fitted.description];
		size_t len;

		snprintf(name, sizeof name, "%.70s (fitted)", sc.name);
		snprintf(desc, sizeof desc, "Fitted to %.80s:", data);
		for (int i = 0; i < r.np; i++) {
			len = strlen(desc);
			snprintf(desc + len, sizeof desc - len, " %s = %.9g", r.key[i], r.value[i]);
		}
		len = strlen(desc);
		if (sig != 0)
			snprintf(desc + len, sizeof desc - len, " (interrupted by %s after %d "
			         "iteration%s: the best point so far, not converged).",
			         cli_signal_name(sig), r.iter, r.iter == 1 ? "" : "s");
		else
			snprintf(desc + len, sizeof desc - len, " (%.60s).",
			         hb_fit_reason_str(r.reason));
		memcpy(r.fitted.name, name, sizeof name);
		memcpy(r.fitted.description, desc, sizeof desc);
	}
	fflush(stdout);
	if (fit_write_outputs(out, &r.fitted, resid_path, &r, &pol, k_out, k_resid, report_path,
	                      fit_report_json, &rc, k_report) != 0)
		goto out;
	if (plot_path != NULL && plot_write_fit(&po, &pol, &r, &d, msg, sizeof msg) != 0) {
		status = bad("%s", msg);
		goto out;
	}
	if (sig == 0)
		sig = cli_signal;   /* caught while writing: the files are whole */
	if (sig != 0) {
		fprintf(stderr, PROG " fit: interrupted by %s: the best point so far is "
		        "reported and written\n", cli_signal_name(sig));
		status = cli_signal_status(sig);
	} else {
		status = v.status;
		for (int i = 0; i < v.n; i++)
			fprintf(stderr, PROG " fit: not credible: %s\n", v.reason[i]);
		if (v.n > 0)
			fprintf(stderr, PROG " fit: the estimates are reported and written\n");
	}
out:
	cli_signals_restore();
	hb_fit_free(fit);
	hb_fit_result_free(&r);
	hb_fit_data_free(&d);
	free(freebuf);
	free(sets);
	free(nonlaw_sets);
	return status;
}
