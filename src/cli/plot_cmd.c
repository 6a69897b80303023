/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_cmd.c - `hybounce plot PRESET --out FILE.{png,pdf,svg,tex}`: runs the
 * preset and draws one figure of the run (plot_figures.c builds the
 * model, plot_cairo.c draws it, plot_tex.c writes it as pgfplots source);
 * several presets, --variant or --laws: the runs compared in one figure
 * (plot_compare.c); a sweep's folder: its figure (plot_sweep.c).  The
 * file is written by plot_out.c, as the --plot of batch, sweep and fit.
 *
 * Exit status as batch mode's: 0, 1 the run failed numerically (the figure
 * of what was computed is written), 2 bad input or an output that could
 * not be written, 128+n a signal (the figure of what was computed first).
 */
#include <getopt.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "cnum.h"
#include "plot_cairo.h"
#include "plot_cmd.h"
#include "plot_out.h"
#include "report.h"
#include "signals.h"

#define PROG "hybounce plot"

static void
usage(FILE *f)
{
	fprintf(f,
"usage: hybounce plot PRESET... --out FILE [--kind state|observables|loop]\n"
"                     [--set KEY=VALUE]... [--collisions I[,J...]]\n"
"                     [--variant KEY=VALUE[;KEY=VALUE...]]... [--laws LAW,...]\n"
"                     [--width LENGTH | --size WxH] [--dpi N] [--title TEXT]\n"
"       hybounce plot DIR --out FILE [--observable NAME] [--collisions I[,J...]]\n"
"                     [--width LENGTH | --size WxH] [--dpi N] [--title TEXT]\n"
"\n"
"Runs PRESET to its end and draws one figure of the run; several presets,\n"
"--variant or --laws: several runs compared in one figure, a curve each, the\n"
"legend saying what differs between them.  Or draws the sweep in DIR\n"
"(hybounce sweep --out DIR; or DIR/runs.csv), running nothing.\n"
"\n"
"  -o, --out FILE          the figure: FILE.png, FILE.pdf or FILE.svg (by its\n"
"                          extension), or FILE.tex: pgfplots source for pdflatex,\n"
"                          its data in FILE.dat beside it\n"
"  -k, --kind KIND         state (default): x, v, x_c, F_c, z_c (and F_e where it\n"
"                          acts) against t in stacked panels, contacts shaded;\n"
"                          observables: t_d, t_f, v_i, e, x_c^max, x_c^r,\n"
"                          F_c^max, W and Lambda against the collision index i;\n"
"                          loop: F_c against x_c over chosen collisions;\n"
"                          sweep (for DIR, the default): the observable against\n"
"                          the varied key, a curve per collision i, or a heat\n"
"                          map over two varied keys with its colour legend\n"
"  -y, --observable NAME   (sweep) a collision's, a column of collisions.csv: e\n"
"                          (default), v_i, t_d, x_c_max ...; or a run's, a column\n"
"                          of runs.csv: e_first, t_pc, collisions ...\n"
"  -s, --set KEY=VALUE     override one value of the preset (repeatable)\n"
"      --variant SETS      one run more with these values (KEY=VALUE, several\n"
"                          separated by ';'), e.g. --variant law.c=2000\n"
"                          --variant law.c=20000 (repeatable)\n"
"      --laws LAW,...      one run per contact law (scene.law), e.g.\n"
"                          shccl,bwshccl,bwmcl; at most 8 runs in all\n"
"  -c, --collisions I,J    (loop) the collisions drawn, by index i (default: the\n"
"                          first three; of several runs, one: default 0);\n"
"                          (sweep) the curves (default 0,1,2,3),\n"
"                          or the one collision of a heat map (default 0)\n"
"  -w, --width LENGTH      the figure's width: 3.5in (default, a journal column),\n"
"                          7in, 8.9cm, 252pt; the height follows the kind\n"
"      --size WxH          width and height: 1600x1200 (pixels at --dpi), 5x4in,\n"
"                          12x9cm, 400x300pt\n"
"      --dpi N             pixels per inch of a PNG (default 300)\n"
"      --title TEXT        a title above the figure (default none)\n"
"  -h, --help              show this help\n"
"\n"
"Exit status: 0 success, 1 the run failed numerically (the figure of what was\n"
"computed is written), 2 bad input or output that could not be written.\n"
"See hybounce(1).\n");
}

/* A refusal (report.h): "hybounce plot: ..." */
#define bad(...) cli_refuse(PROG, __VA_ARGS__)

/* A length: NUMBER with in, cm, mm or pt (px: pixels at dpi, where allowed)
 * into points; -1 when malformed. */
static double
parse_length(const char *s, size_t len, double dpi, int px_ok)
{
	char buf[64], *end;
	double v;

	if (len == 0 || len >= sizeof buf)
		return -1;
	memcpy(buf, s, len);
	buf[len] = '\0';
	v = cnum_strtod(buf, &end);
	if (end == buf || !(v > 0) || !isfinite(v))
		return -1;
	if (strcmp(end, "in") == 0)
		return v * 72;
	if (strcmp(end, "cm") == 0)
		return v * 72 / 2.54;
	if (strcmp(end, "mm") == 0)
		return v * 72 / 25.4;
	if (strcmp(end, "pt") == 0)
		return v;
	if (px_ok && (strcmp(end, "px") == 0 || *end == '\0'))
		return v * 72 / dpi;
	return -1;
}

/* "1600x1200", "5x4in": a unit after the height applies to both. */
static int
parse_size(const char *s, double dpi, double *w, double *h)
{
	const char *x = strchr(s, 'x');
	const char *unit;
	char wb[64];
	size_t wl;

	if (x == NULL)
		return -1;
	unit = x + 1 + strspn(x + 1, "0123456789.eE+-");
	wl = (size_t)(x - s);
	if (wl + strlen(unit) >= sizeof wb)
		return -1;
	memcpy(wb, s, wl);
	/* the width takes the height's unit unless it has its own */
	if (wl > 0 && strchr("0123456789.", s[wl - 1]) != NULL)
		strcpy(wb + wl, unit), wl += strlen(unit);
	*w = parse_length(wb, wl, dpi, 1);
	*h = parse_length(x + 1, strlen(x + 1), dpi, 1);
	return *w > 0 && *h > 0 ? 0 : -1;
}

/* "0,2,5" into idx (at most max); -1 when malformed. */
static int
parse_indices(const char *s, long *idx, int max)
{
	int n = 0;

	while (*s != '\0') {
		char *end;
		long v;

		if (!cnum_isdigit((unsigned char)*s))
			return -1;
		v = strtol(s, &end, 10);
		if (v < 0 || n >= max)
			return -1;
		idx[n++] = v;
		s = end;
		if (*s == ',')
			s++;
		else if (*s != '\0')
			return -1;
	}
	return n > 0 ? n : -1;
}

static const struct option long_options[] = {
	{ "out",        required_argument, NULL, 'o' },
	{ "kind",       required_argument, NULL, 'k' },
	{ "set",        required_argument, NULL, 's' },
	{ "collisions", required_argument, NULL, 'c' },
	{ "observable", required_argument, NULL, 'y' },
	{ "width",      required_argument, NULL, 'w' },
	{ "size",       required_argument, NULL, 'S' },
	{ "dpi",        required_argument, NULL, 'D' },
	{ "title",      required_argument, NULL, 'T' },
	{ "variant",    required_argument, NULL, 'V' },
	{ "laws",       required_argument, NULL, 'L' },
	{ "help",       no_argument,       NULL, 'h' },
	{ NULL, 0, NULL, 0 },
};

/* 1 if arg names a sweep: a folder, or a file ending in .csv. */
static int
is_sweep(const char *arg)
{
	struct stat sb;
	size_t l = strlen(arg);

	if (stat(arg, &sb) == 0 && S_ISDIR(sb.st_mode))
		return 1;
	return l > 4 && cnum_casecmp(arg + l - 4, ".csv") == 0;
}

int
plot_size_parse(const char *width_s, const char *size_s, const char *dpi_s, double *w,
                double *h, double *dpi, char *msg, size_t n)
{
	*w = 252;
	*h = -1;
	*dpi = 300;
	if (dpi_s != NULL) {
		char *end;

		*dpi = cnum_strtod(dpi_s, &end);
		if (end == dpi_s || *end != '\0' || !(*dpi >= 36 && *dpi <= 2400)) {
			cnum_snprintf(msg, n, "--dpi %s: expected a number of pixels per inch from 36 "
			              "to 2400", dpi_s);
			return -1;
		}
	}
	if (width_s != NULL && size_s != NULL) {
		cnum_snprintf(msg, n, "--width and --size both given; expected one of them");
		return -1;
	}
	if (width_s != NULL && (*w = parse_length(width_s, strlen(width_s), *dpi, 0)) < 0) {
		cnum_snprintf(msg, n, "--width %s: expected a length such as 3.5in, 8.9cm, 90mm or "
		              "252pt", width_s);
		return -1;
	}
	if (size_s != NULL && parse_size(size_s, *dpi, w, h) != 0) {
		cnum_snprintf(msg, n, "--size %s: expected WIDTHxHEIGHT such as 1600x1200 (pixels), "
		              "5x4in, 12x9cm or 400x300pt", size_s);
		return -1;
	}
	if (*w < 72 || *w > 72 * 100 || (*h > 0 && (*h < 72 || *h > 72 * 100))) {
		cnum_snprintf(msg, n, "%s %s: the figure would be %.3g x %.3g in; expected 1 to 100 "
		              "in a side", size_s != NULL ? "--size" : "--width",
		              size_s != NULL ? size_s : width_s, *w / 72, *h > 0 ? *h / 72 : *w / 72);
		return -1;
	}
	return 0;
}

int
plot_write_run(struct plot_out *o, const struct hb_outputs *pol, enum plot_kind kind,
               const struct hb_sim *s, char *msg, size_t n)
{
	struct plot_figure *fig = plot_out_figure(o, msg, n);

	if (fig == NULL)
		return -1;
	return plot_out_finish(o, pol, fig, plot_build(fig, kind, s, 252, -1, NULL, 0, msg, n), msg,
	                       n);
}

enum { MAX_RUNS = PLOT_MAX_SERIES };

/* One run of the comparison: its preset and the --set texts it adds. */
struct run_spec {
	const char *preset;
	char extra[256];     /* "KEY=VALUE;KEY=VALUE" of a --variant or a law, "" none */
	char name[160];      /* the preset's name, for a legend of presets */
};

/* Splits "a=1;b=2" (in place) into sets after the first n; the new count. */
static int
add_sets(char *text, const char **sets, int n, int max)
{
	for (char *save = NULL, *t = strtok_r(text, ";", &save); t != NULL && n < max;
	     t = strtok_r(NULL, ";", &save))
		sets[n++] = t;
	return n;
}

/*
 * The runs of presets (each, times each --variant, times each law of
 * --laws), drawn in one figure: plot_build for one, plot_build_compare for
 * several.  Returns the exit status.
 */
static int
plot_runs(char **presets, int npresets, const char **sets, int nsets, const char **variants,
          int nvariants, const char *laws_s, enum plot_kind kind, const long *coll, int ncoll,
          double w, double h, const char *title, struct plot_out *po)
{
	struct run_spec run[MAX_RUNS];
	struct hb_sim *s[MAX_RUNS] = { 0 };
	struct hb_scene sc[MAX_RUNS];
	const struct hb_scene *scp[MAX_RUNS];
	char paths[MAX_RUNS][1024], labels[MAX_RUNS][64], msg[4096], lawbuf[256];
	const char *names[MAX_RUNS], *lab[MAX_RUNS], *laws[MAX_RUNS];
	const char **all = calloc((size_t)nsets + 16, sizeof *all);
	int nlaws = 0, nruns = 0, status = 0, sig = 0, rc;
	struct hb_outputs pol;
	struct plot_figure *fig = NULL;

	if (all == NULL)
		return bad("out of memory");
	if (laws_s != NULL) {
		cnum_snprintf(lawbuf, sizeof lawbuf, "%s", laws_s);
		for (char *save = NULL, *t = strtok_r(lawbuf, ",", &save); t != NULL;
		     t = strtok_r(NULL, ",", &save)) {
			if (nlaws == MAX_RUNS) {
				free(all);
				return bad("--laws %s: more than %d laws; expected at most %d", laws_s,
				           MAX_RUNS, MAX_RUNS);
			}
			laws[nlaws++] = t;
		}
		if (nlaws == 0) {
			free(all);
			return bad("--laws '%s': no law; expected names such as shccl,bwshccl,bwmcl",
			           laws_s);
		}
	}
	if (nvariants > MAX_RUNS ||
	    (long)npresets * (nvariants ? nvariants : 1) * (nlaws ? nlaws : 1) > MAX_RUNS) {
		free(all);
		return bad("%d preset%s x %d variant%s x %d law%s: more than %d runs in one figure; "
		           "expected at most %d", npresets, npresets == 1 ? "" : "s",
		           nvariants ? nvariants : 1, nvariants > 1 ? "s" : "", nlaws ? nlaws : 1,
		           nlaws > 1 ? "s" : "", MAX_RUNS, MAX_RUNS);
	}
	if (ncoll > 1 && npresets * (nvariants ? nvariants : 1) * (nlaws ? nlaws : 1) > 1) {
		free(all);
		return bad("--collisions: a comparison of runs draws one collision's loop; expected "
		           "one index i");
	}
	for (int p = 0; p < npresets; p++)
		for (int v = 0; v < (nvariants ? nvariants : 1); v++)
			for (int l = 0; l < (nlaws ? nlaws : 1); l++) {
				struct run_spec *r = &run[nruns++];
				const char *slash = strrchr(presets[p], '/');

				r->preset = presets[p];
				cnum_snprintf(r->name, sizeof r->name, "%s", slash ? slash + 1 : presets[p]);
				if (strlen(r->name) > 7 && strcmp(r->name + strlen(r->name) - 7, ".preset") == 0)
					r->name[strlen(r->name) - 7] = '\0';
				cnum_snprintf(r->extra, sizeof r->extra, "%s%s%s%s",
				              nlaws ? "scene.law=" : "", nlaws ? laws[l] : "",
				              nlaws && nvariants ? ";" : "", nvariants ? variants[v] : "");
			}
	hb_outputs_init(&pol);
	for (int r = 0; r < nruns; r++) {
		int n = nsets;

		memcpy(all, sets, (size_t)nsets * sizeof *all);
		n = add_sets(run[r].extra, all, n, nsets + 16);
		msg[0] = '\0';
		if (hb_preset_open_named(run[r].preset, all, n, &sc[r], paths[r], sizeof paths[r], msg,
		                         sizeof msg) != HB_OK) {
			free(all);
			return bad("%s", msg[0] ? msg : run[r].preset);
		}
		hb_outputs_input(&pol, paths[r], "the preset being run");
		scp[r] = &sc[r];
		names[r] = run[r].name;
	}
	free(all);
	/* The output policy (outputs.h): never a preset run, never a shipped
	 * preset, a folder or an unwritable place. */
	msg[0] = '\0';
	if (plot_out_register(po, &pol, msg, sizeof msg) != 0)
		return bad("%s", msg);

	cli_signals_watch();
	for (int r = 0; r < nruns && cli_signal == 0; r++) {
		msg[0] = '\0';
		s[r] = hb_sim_new(&sc[r], msg, sizeof msg);
		if (s[r] == NULL) {
			status = bad("%s: %s", paths[r], msg[0] ? msg : "cannot start the run");
			goto done;
		}
		rc = HB_OK;
		while (cli_signal == 0) {
			rc = hb_sim_advance(s[r], 0, 0.1);
			if (rc != HB_OK || hb_sim_end(s[r]) != HB_SIM_RUNNING)
				break;
		}
		if (hb_sim_end(s[r]) == HB_SIM_END_FAIL || (rc != HB_OK && rc != HB_EDONE)) {
			status = 1;
			fprintf(stderr, PROG ": the run%s%s failed: %s; the figure shows what was "
			        "computed\n", nruns > 1 ? " of " : "", nruns > 1 ? names[r] : "",
			        hb_sim_errmsg(s[r])[0] ? hb_sim_errmsg(s[r]) : hb_status_str(rc));
		}
	}
	sig = cli_signal;
	if (sig != 0) {
		fprintf(stderr, PROG ": %s: the run stopped; the figure shows what was computed\n",
		        cli_signal_name(sig));
		while (nruns > 1 && s[nruns - 1] == NULL)
			nruns--;   /* the runs not started are left out */
		if (s[0] == NULL)
			goto done;   /* nothing computed, nothing to draw */
	}

	fig = malloc(sizeof *fig);
	if (fig == NULL) {
		status = bad("out of memory");
		goto done;
	}
	msg[0] = '\0';
	if (nruns == 1) {
		rc = plot_build(fig, kind, s[0], w, h, coll, ncoll, msg, sizeof msg);
	} else {
		plot_compare_labels(scp, names, nruns, labels);
		for (int r = 0; r < nruns; r++)
			lab[r] = labels[r];
		rc = plot_build_compare(fig, kind, (const struct hb_sim *const *)s, lab, nruns, w, h,
		                        ncoll > 0 ? coll[0] : 0, msg, sizeof msg);
	}
	if (rc != 0) {
		free(fig);
		fig = NULL;
		status = bad("%s", msg);
		goto done;
	}
	if (title != NULL)
		cnum_snprintf(fig->title, sizeof fig->title, "%s", title);
	msg[0] = '\0';
	if (plot_out_write(po, &pol, fig, msg, sizeof msg) != 0)
		status = bad("%s", msg);
done:
	if (fig != NULL) {
		plot_figure_free(fig);
		free(fig);
	}
	for (int r = 0; r < MAX_RUNS; r++)
		hb_sim_free(s[r]);
	if (sig == 0)
		sig = cli_signal;
	cli_signals_restore();
	return sig != 0 ? cli_signal_status(sig) : status;
}

int
plot_main(int argc, char **argv)
{
	const char *out = NULL, *kind_s = NULL, *width_s = NULL, *size_s = NULL, *title = NULL;
	const char *coll_s = NULL, *dpi_s = NULL, *obs = NULL, *preset, *laws_s = NULL;
	const char *variants[PLOT_MAX_SERIES];
	int nvariants = 0, npresets;
	const char **sets = calloc((size_t)argc + 1, sizeof *sets);
	int nsets = 0, c, status = 0, rc, ncoll = 0, sweep;
	long coll[PLOT_MAX_SERIES];
	enum plot_kind kind = PLOT_STATE;
	double dpi, w, h;
	char msg[4096];
	struct hb_outputs pol;
	struct plot_figure *fig = NULL;
	struct plot_out po;

	if (sets == NULL)
		return bad("out of memory");
	opterr = 1;
	optind = 1;
	while ((c = getopt_long(argc, argv, "o:k:s:c:y:w:h", long_options, NULL)) != -1) {
		switch (c) {
		case 'o': out = optarg; break;
		case 'k': kind_s = optarg; break;
		case 's': sets[nsets++] = optarg; break;
		case 'c': coll_s = optarg; break;
		case 'y': obs = optarg; break;
		case 'w': width_s = optarg; break;
		case 'S': size_s = optarg; break;
		case 'D': dpi_s = optarg; break;
		case 'T': title = optarg; break;
		case 'V':
			if (nvariants < PLOT_MAX_SERIES)
				variants[nvariants] = optarg;
			nvariants++;
			break;
		case 'L': laws_s = optarg; break;
		case 'h':
			usage(stdout);
			free(sets);
			return 0;
		default:
			fprintf(stderr, "Try 'hybounce plot --help'.\n");
			free(sets);
			return 2;
		}
	}
	if (optind >= argc) {
		free(sets);
		return bad("no preset given; expected hybounce plot PRESET --out FILE.png (or a "
		           "sweep's folder for PRESET)");
	}
	npresets = argc - optind;
	preset = argv[optind];
	sweep = is_sweep(preset);
	if (sweep && npresets > 1) {
		free(sets);
		return bad("more than one sweep or preset given ('%s' ...); a sweep's figure draws "
		           "one sweep: expected one sweep's folder", argv[optind + 1]);
	}
	if (out == NULL) {
		free(sets);
		return bad("no --out FILE; expected " PLOT_OUT_ACCEPTED);
	}
	msg[0] = '\0';
	if (plot_out_parse(&po, "--out", out, msg, sizeof msg) != 0) {
		free(sets);
		return bad("%s", msg);
	}
	if (kind_s == NULL)
		kind_s = sweep ? "sweep" : "state";
	if (strcmp(kind_s, "state") == 0)
		kind = PLOT_STATE;
	else if (strcmp(kind_s, "observables") == 0)
		kind = PLOT_OBSERVABLES;
	else if (strcmp(kind_s, "loop") == 0)
		kind = PLOT_LOOP;
	else if (strcmp(kind_s, "sweep") != 0) {
		free(sets);
		return bad("--kind %s: unknown; expected state, observables, loop or sweep", kind_s);
	}
	if (sweep != (strcmp(kind_s, "sweep") == 0)) {
		free(sets);
		return bad(sweep ? "%s is a sweep (a folder or its runs.csv); --kind %s draws a run "
		           "of a preset: expected --kind sweep or none" : "%s: --kind %s draws a sweep: expected its folder or its "
		           "runs.csv", preset, kind_s);
	}
	if (sweep && (nvariants > 0 || laws_s != NULL)) {
		free(sets);
		return bad("%s: a sweep's figure draws what the sweep computed; --variant and --laws "
		           "compare runs of presets: expected presets", nvariants ? "--variant" : "--laws");
	}
	if (sweep && nsets > 0) {
		rc = bad("--set %s: a sweep's figure draws what the sweep computed; expected no "
		         "--set", sets[0]);
		free(sets);
		return rc;
	}
	if (!sweep && obs != NULL) {
		free(sets);
		return bad("--observable %s: only a sweep's figure takes an observable; expected a "
		           "sweep's folder (DIR or DIR/runs.csv)", obs);
	}
	msg[0] = '\0';
	if (plot_size_parse(width_s, size_s, dpi_s, &w, &h, &dpi, msg, sizeof msg) != 0) {
		free(sets);
		return bad("%s", msg);
	}
	po.dpi = dpi;
	if (coll_s != NULL) {
		if (!sweep && kind != PLOT_LOOP) {
			free(sets);
			return bad("--collisions %s: only --kind loop and a sweep's figure draw chosen "
			           "collisions; expected --kind loop", coll_s);
		}
		ncoll = parse_indices(coll_s, coll, PLOT_MAX_SERIES);
		if (ncoll < 0) {
			free(sets);
			return bad("--collisions %s: expected collision indices i (from 0) separated "
			           "by commas, at most %d, e.g. 0,1,4", coll_s, PLOT_MAX_SERIES);
		}
	}

	if (sweep) {
		free(sets);
		hb_outputs_init(&pol);
		fig = malloc(sizeof *fig);
		if (fig == NULL)
			return bad("out of memory");
		msg[0] = '\0';
		if (plot_build_sweep(fig, preset, obs, coll, ncoll, w, h, &pol, msg, sizeof msg)
		    != 0) {
			free(fig);
			return bad("%s", msg);
		}
		if (title != NULL)
			cnum_snprintf(fig->title, sizeof fig->title, "%s", title);
		msg[0] = '\0';
		if (plot_out_register(&po, &pol, msg, sizeof msg) != 0)
			status = bad("%s", msg);
		else if (plot_out_write(&po, &pol, fig, msg, sizeof msg) != 0)
			status = bad("%s", msg);
		plot_figure_free(fig);
		free(fig);
		return status;
	}

	status = plot_runs(argv + optind, npresets, sets, nsets, variants, nvariants, laws_s, kind,
	                   coll, ncoll, w, h, title, &po);
	free(sets);
	return status;
}
