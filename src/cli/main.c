/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * main.c - the command line: parse options, then open the explorer or run
 * a preset in batch mode.
 *
 *     hybounce [OPTIONS] [PRESET]          the explorer
 *     hybounce --batch PRESET [OPTIONS]    batch mode (batch.c)
 *     hybounce --list-presets | --list-laws | --help | --version
 *     hybounce fit PRESET --data FILE --free KEY,...   (fit_cmd.c)
 *     hybounce plot PRESET --out FILE.png              (plot_cmd.c)
 *
 * Exit status: 0 success; 1 the run failed numerically; 2 bad input
 * (unknown option, bad preset, bad --set, unwritable export path) or
 * output that could not be written (standard output too: finish()).
 * Messages from the explorer are printed here, after it has restored the
 * terminal.
 */
#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>

#include "hybounce/status.h"
#include "hybounce/version.h"
#include "app.h"
#include "batch.h"
#include "sweep_cli.h"
#include "fit_cmd.h"
#include "plot_cmd.h"
#include "report.h"
#include "signals.h"

#define PROG "hybounce"
#define DEFAULT_PRESET "steel-on-bitumen"

enum {
	OPT_JUMPS = 256,
	OPT_PLOT,
	OPT_CHECK,
	OPT_ASCII,
	OPT_SCRIPT,
	OPT_LIST_PRESETS,
	OPT_LIST_LAWS,
	OPT_DATA,
	OPT_ERROR,
	OPT_BODIES,
};

static const struct option long_options[] = {
	{ "batch",        required_argument, NULL, 'b' },
	{ "set",          required_argument, NULL, 's' },
	{ "trace",        required_argument, NULL, 't' },
	{ "collisions",   required_argument, NULL, 'c' },
	{ "jumps",        no_argument,       NULL, OPT_JUMPS },
	{ "plot",         required_argument, NULL, OPT_PLOT },
	{ "bodies",       required_argument, NULL, OPT_BODIES },
	{ "check",        no_argument,       NULL, OPT_CHECK },
	{ "error",        no_argument,       NULL, OPT_ERROR },
	{ "quiet",        no_argument,       NULL, 'q' },
	{ "ascii",        no_argument,       NULL, OPT_ASCII },
	{ "script",       required_argument, NULL, OPT_SCRIPT },
	{ "data",         required_argument, NULL, OPT_DATA },
	{ "list-presets", no_argument,       NULL, OPT_LIST_PRESETS },
	{ "list-laws",    no_argument,       NULL, OPT_LIST_LAWS },
	{ "help",         no_argument,       NULL, 'h' },
	{ "version",      no_argument,       NULL, 'V' },
	{ NULL, 0, NULL, 0 },
};

static void
usage(FILE *f)
{
	fprintf(f,
"usage: hybounce [OPTIONS] [PRESET]     open the explorer (default preset: "
DEFAULT_PRESET ")\n"
"       hybounce --batch PRESET [--set KEY=VALUE]... [--trace FILE]\n"
"                [--collisions FILE] [--bodies FILE] [--plot FILE] [--jumps] [--check]\n"
"                [--error] [--quiet]\n"
"       hybounce --list-presets | --list-laws | --help | --version\n"
"       hybounce sweep PRESET --vary KEY=SPEC... --out DIR   (see hybounce sweep --help)\n"
"       hybounce fit PRESET --data FILE --free KEY[,KEY...] [OPTIONS]\n"
"                               fit parameters to measurements (hybounce fit --help)\n"
"       hybounce plot PRESET... | DIR --out FILE.{png,pdf,svg,tex} [--kind KIND]\n"
"                               draw a figure of runs or of a sweep (hybounce\n"
"                               plot --help)\n"
"\n"
"Repeated impacts of two bodies under incremental contact laws, as a hybrid\n"
"system (flows and jumps over hybrid time (t, j)).\n"
"\n"
"  -b, --batch PRESET      run PRESET to its end without the explorer and print\n"
"                          the scene, the collision table and a summary\n"
"  -s, --set KEY=VALUE     override one value of the preset (repeatable), e.g.\n"
"                          --set law.c=0.4 --set initial.x0='40 um'\n"
"                          --set scene.law=hertz --set run.rtol=1e-9\n"
"  -t, --trace FILE        (batch) write the hybrid arc as CSV to FILE\n"
"  -c, --collisions FILE   (batch) write the collisions as CSV to FILE;\n"
"                          the scene is saved beside the first file as .preset.\n"
"                          FILE - (for one of the two) is standard output, and\n"
"                          the report then goes to standard error\n"
"      --bodies FILE       (batch) write each body's final state as CSV to FILE:\n"
"                          body, m, y, u, K (SI), numbered from the bottom\n"
"      --plot FILE         (batch) draw the run's state against t (as hybounce\n"
"                          plot --kind state) to FILE.png, .pdf, .svg or .tex\n"
"      --jumps             (batch) print how each jump was located\n"
"      --check             (batch) check the computed solution pair (paper,\n"
"                          section Simulation) and report it; with --error,\n"
"                          also that every error bar is within 100 x run.rtol\n"
"      --error             (batch) an error bar on every observable: the run\n"
"                          again with rk8pd at rtol/100, atol/100; the values\n"
"                          as NAME = VALUE +- ERROR, the collisions CSV with\n"
"                          NAME_err columns\n"
"  -q, --quiet             (batch) print only the summary, no table\n"
"      --ascii             (explorer) plain ASCII plots, even in a UTF-8 locale\n"
"      --script FILE       (explorer) play keystrokes from FILE\n"
"      --data FILE         (explorer) measured data over the scene, as for\n"
"                          hybounce fit (keys D, M and F)\n"
"      --list-presets      list the presets: name, title, description\n"
"      --list-laws         list the contact laws and their parameters\n"
"  -h, --help              show this help\n"
"  -V, --version           show the version and the commit it was built from\n"
"\n"
"PRESET is a name (presets/NAME.preset, searched in $HYBOUNCE_PRESETS,\n"
"./presets and the installed presets) or a path to a .preset file.\n"
"Exit status: 0 success, 1 the run failed numerically, 2 bad input or output\n"
"that could not be written.\n"
"See hybounce(1).\n");
}

static int bad_usage(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Prints a usage error and returns exit status 2. */
static int
bad_usage(const char *fmt, ...)
{
	va_list ap;

	fprintf(stderr, PROG ": ");
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fprintf(stderr, "\nTry 'hybounce --help'.\n");
	return 2;
}

/*
 * Keeps descriptors 0, 1 and 2 taken: one closed by the caller gets
 * /dev/null read-only, so that a file the program opens cannot become its
 * standard output and a write to a closed stdout still fails (EBADF).
 */
static void
hold_std_fds(void)
{
	for (int fd = 0; fd <= 2; fd++)
		if (fcntl(fd, F_GETFD) == -1 && errno == EBADF) {
			int nfd = open("/dev/null", O_RDONLY);

			if (nfd >= 0 && nfd != fd) {
				dup2(nfd, fd);
				close(nfd);
			}
		}
}

static int hybounce_main(int argc, char **argv);

int
main(int argc, char **argv)
{
	hold_std_fds();
	/*
	 * The library leaves GSL's error handler as the host set it (GSL's
	 * default aborts); the program reports GSL's errors through the
	 * engine's return codes, as GSL advises for a program that checks them.
	 */
	gsl_set_error_handler_off();
	cli_provenance_init(argc, argv);   /* before getopt or the subcommands touch argv */
	int status = hybounce_main(argc, argv);

	/* Output that could not all be written is exit 2 (batch.h). */
	return batch_flush_stdout() != 0 ? 2 : status;
}

static int
hybounce_main(int argc, char **argv)
{
	struct batch_options bo;
	struct app_options ao;
	const char **sets;
	const char *batch = NULL, *script = NULL, *data = NULL;
	int nsets = 0, ascii = 0, list_presets = 0, list_laws = 0, c, status;
	char msg[4096];

	if (argc > 1 && strcmp(argv[1], "sweep") == 0)
		return sweep_main(argc - 1, argv + 1);   /* hybounce sweep ... (sweep.c) */
	if (argc > 1 && strcmp(argv[1], "plot") == 0) {
		static char plotprog[] = PROG " plot";

		argv[1] = plotprog;
		return plot_main(argc - 1, argv + 1);   /* hybounce plot ... (plot_cmd.c) */
	}
	if (argc > 1 && strcmp(argv[1], "fit") == 0) {
		static char fitprog[] = PROG " fit";

		argv[1] = fitprog;
		return fit_main(argc - 1, argv + 1);
	}
	memset(&bo, 0, sizeof bo);
	sets = calloc((size_t)argc + 1, sizeof *sets);
	if (sets == NULL) {
		fprintf(stderr, PROG ": out of memory\n");
		return 1;
	}
	static char prog[] = PROG; /* getopt's messages name the program, not its path */

	argv[0] = prog;
	opterr = 1;
	while ((c = getopt_long(argc, argv, "b:s:t:c:qhV", long_options, NULL)) != -1) {
		switch (c) {
		case 'b':
			if (batch != NULL) {
				free(sets);
				return bad_usage("--batch given twice (%s)", optarg);
			}
			batch = optarg;
			break;
		case 's': /* read with the preset, by hb_preset_open_named */
			sets[nsets++] = optarg;
			break;
		case 't': bo.trace = optarg; break;
		case 'c': bo.collisions = optarg; break;
		case OPT_JUMPS: bo.jumps = 1; break;
		case OPT_PLOT: bo.plot = optarg; break;
		case OPT_BODIES: bo.bodies = optarg; break;
		case OPT_CHECK: bo.check = 1; break;
		case OPT_ERROR: bo.error = 1; break;
		case 'q': bo.quiet = 1; break;
		case OPT_ASCII: ascii = 1; break;
		case OPT_SCRIPT: script = optarg; break;
		case OPT_DATA: data = optarg; break;
		case OPT_LIST_PRESETS: list_presets = 1; break;
		case OPT_LIST_LAWS: list_laws = 1; break;
		case 'h':
			usage(stdout);
			free(sets);
			return 0;
		case 'V':
			/* "hybounce 0.2.0 (commit HASH)": the release, then the
			 * commit of the engine it runs (version.h) */
			printf("hybounce %d.%d.%d (commit %s)\n", HB_VERSION_MAJOR, HB_VERSION_MINOR,
			    HB_VERSION_PATCH, hb_version_commit());
			free(sets);
			return 0;
		default: /* getopt_long has said what was wrong */
			fprintf(stderr, "Try 'hybounce --help'.\n");
			free(sets);
			return 2;
		}
	}

	if (list_presets || list_laws) {
		if (batch != NULL || optind < argc) {
			free(sets);
			return bad_usage("%s takes no preset", list_laws ? "--list-laws"
			                                                : "--list-presets");
		}
		status = 0;
		if (list_laws)
			status = batch_list_laws();
		if (list_presets && status == 0) {
			if (list_laws)
				printf("\n");
			status = batch_list_presets();
		}
		free(sets);
		return status;
	}

	if (batch != NULL) {
		if (optind < argc) {
			free(sets);
			return bad_usage("unexpected argument '%s' (the preset of batch "
			                 "mode is the argument of --batch)", argv[optind]);
		}
		if (ascii || script != NULL || data != NULL) {
			free(sets);
			return bad_usage("%s is an option of the explorer, not of --batch",
			                 ascii ? "--ascii" : script ? "--script" : "--data");
		}
		bo.preset = batch;
		bo.sets = sets;
		bo.nsets = nsets;
		status = batch_run(&bo);
		free(sets);
		return status;
	}

	/* The explorer. */
	if (bo.trace != NULL || bo.collisions != NULL || bo.jumps || bo.check || bo.quiet ||
	    bo.plot != NULL || bo.error || bo.bodies != NULL) {
		const char *o = bo.trace ? "--trace" : bo.collisions ? "--collisions"
		              : bo.plot ? "--plot" : bo.bodies ? "--bodies"
		              : bo.jumps ? "--jumps" : bo.check ? "--check"
		              : bo.error ? "--error" : "--quiet";

		free(sets);
		return bad_usage("%s needs --batch PRESET (the explorer exports with "
		                 "its own key)", o);
	}
	if (argc - optind > 1) {
		free(sets);
		return bad_usage("more than one preset given ('%s' ...)", argv[optind + 1]);
	}
	memset(&ao, 0, sizeof ao);
	ao.preset = optind < argc ? argv[optind] : NULL;
	ao.sets = sets;
	ao.nsets = nsets;
	ao.ascii = ascii;
	ao.script = script;
	ao.data = data;
	ao.provenance = cli_provenance();
	msg[0] = '\0';
	status = app_run(&ao, msg, sizeof msg);
	if (msg[0] != '\0')
		fprintf(stderr, PROG ": %s\n", msg);
	free(sets);
	return status;
}
