/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * citizen.c - libhybounce leaves the process as its host set it
 * (tests/cli/host.sh).  The host sets its own GSL error handler, locale,
 * dispositions of SIGINT, SIGTERM, SIGHUP and SIGPIPE, signal mask,
 * buffering of stdout, environment, umask, working directory and inih's
 * options; then loads PRESET, runs it, exports CSV, runs a small sweep and
 * a fit on DATA, and checks that each is as it set it.  setvbuf and its
 * relatives are the host's own (they count calls, then do the work), so
 * that the library calling them shows.
 *
 *     citizen PRESET DATA OUT       (absolute paths)
 *
 * One line "ok - WHAT" or "not ok - WHAT" per property; exit 0 when all hold.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <locale.h>
#include <signal.h>
#include <stdio.h>
#include <stdio_ext.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>
#include <ini.h>

#include <hybounce/csv.h>
#include <hybounce/fit.h>
#include <hybounce/preset.h>
#include <hybounce/sim.h>
#include <hybounce/status.h>
#include <hybounce/sweep.h>

extern char **environ;

static int fails, gsl_errors, armed, buffering_calls;

static void
check(int ok, const char *what)
{
	printf("%s - %s\n", ok ? "ok" : "not ok", what);
	fails += !ok;
}

static void
host_gsl_handler(const char *reason, const char *file, int line, int gsl_errno)
{
	(void)reason; (void)file; (void)line; (void)gsl_errno;
	gsl_errors++;
}

static void host_on_int(int sig) { (void)sig; }
static void host_on_hup(int sig) { (void)sig; }

/* The host's setvbuf and relatives: counted once armed, then glibc's. */
int
setvbuf(FILE *f, char *buf, int mode, size_t size)
{
	int (*real)(FILE *, char *, int, size_t) =
	    (int (*)(FILE *, char *, int, size_t))dlsym(RTLD_NEXT, "setvbuf");

	buffering_calls += armed;
	return real(f, buf, mode, size);
}

void
setbuf(FILE *f, char *buf)
{
	buffering_calls += armed;
	setvbuf(f, buf, buf ? _IOFBF : _IONBF, BUFSIZ);
}

void
setbuffer(FILE *f, char *buf, size_t size)
{
	buffering_calls += armed;
	setvbuf(f, buf, buf ? _IOFBF : _IONBF, size);
}

void
setlinebuf(FILE *f)
{
	buffering_calls += armed;
	setvbuf(f, NULL, _IOLBF, 0);
}

static const int sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGPIPE };
#define NSIGS (sizeof sigs / sizeof sigs[0])

struct state {
	char locale[512];
	locale_t thread_locale;
	struct sigaction sa[NSIGS];
	sigset_t mask;
	char **environ_ptr;
	char *env[256];
	int nenv;
	mode_t umask;
	char cwd[4096];
	size_t bufsize;
	int linebuf;
	bool ini_multiline, ini_inline, ini_no_value, ini_stop;
	char *ini_inline_prefixes, *ini_start_prefixes;
	int ini_max_line;
};

static void
snapshot(struct state *st)
{
	memset(st, 0, sizeof *st);
	snprintf(st->locale, sizeof st->locale, "%s", setlocale(LC_ALL, NULL));
	st->thread_locale = uselocale((locale_t)0);
	for (size_t i = 0; i < NSIGS; i++)
		sigaction(sigs[i], NULL, &st->sa[i]);
	sigprocmask(SIG_BLOCK, NULL, &st->mask);
	st->environ_ptr = environ;
	for (char **e = environ; *e != NULL && st->nenv < 256; e++)
		st->env[st->nenv++] = strdup(*e);
	st->umask = umask(0);
	umask(st->umask);
	if (getcwd(st->cwd, sizeof st->cwd) == NULL)
		st->cwd[0] = '\0';
	st->bufsize = __fbufsize(stdout);
	st->linebuf = __flbf(stdout);
	st->ini_multiline = ini_allow_multiline;
	st->ini_inline = ini_allow_inline_comments;
	st->ini_no_value = ini_allow_no_value;
	st->ini_stop = ini_stop_on_first_error;
	st->ini_inline_prefixes = ini_inline_comment_prefixes;
	st->ini_start_prefixes = ini_start_comment_prefixes;
	st->ini_max_line = ini_max_line;
}

static void
snapshot_free(struct state *st)
{
	for (int i = 0; i < st->nenv; i++)
		free(st->env[i]);
	st->nenv = 0;
}

static int
same_env(const struct state *a, const struct state *b)
{
	if (a->environ_ptr != b->environ_ptr || a->nenv != b->nenv)
		return 0;
	for (int i = 0; i < a->nenv; i++)
		if (strcmp(a->env[i], b->env[i]) != 0)
			return 0;
	return 1;
}

/* The same signals in both sets (sigset_t holds more than the kernel fills). */
static int
same_set(const sigset_t *a, const sigset_t *b)
{
	for (int sig = 1; sig < SIGRTMAX; sig++)
		if (sigismember(a, sig) != sigismember(b, sig))
			return 0;
	return 1;
}

static int
same_signals(const struct state *a, const struct state *b)
{
	for (size_t i = 0; i < NSIGS; i++)
		if (a->sa[i].sa_handler != b->sa[i].sa_handler ||
		    a->sa[i].sa_flags != b->sa[i].sa_flags ||
		    !same_set(&a->sa[i].sa_mask, &b->sa[i].sa_mask))
			return 0;
	return same_set(&a->mask, &b->mask);
}

static void
fail(const char *what, const char *msg)
{
	printf("not ok - %s (%s)\n", what, msg);
	fails++;
}

int
main(int argc, char **argv)
{
	static char outbuf[4096];
	char msg[1024], trace[4096], dir[4096];
	struct hb_scene sc;
	struct hb_sim *s;
	struct state before, after;
	struct sigaction sa;
	gsl_error_handler_t *prev;

	if (argc != 4 || argv[1][0] != '/' || argv[2][0] != '/' || argv[3][0] != '/') {
		fprintf(stderr, "usage: %s /PRESET /DATA /OUT\n", argv[0]);
		return 2;
	}

	/* The host's own state. */
	gsl_set_error_handler(host_gsl_handler);
	if (setlocale(LC_ALL, "C.UTF-8") == NULL) {
		fprintf(stderr, "citizen: no C.UTF-8 locale\n");
		return 2;
	}
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = host_on_int;
	sa.sa_flags = SA_RESTART;
	sigaddset(&sa.sa_mask, SIGUSR1);
	sigaction(SIGINT, &sa, NULL);
	sa.sa_handler = host_on_hup;
	sa.sa_flags = SA_NODEFER;
	sigaction(SIGHUP, &sa, NULL);
	signal(SIGTERM, SIG_IGN);
	signal(SIGPIPE, SIG_IGN);
	{
		sigset_t m;

		sigemptyset(&m);
		sigaddset(&m, SIGUSR2);
		sigprocmask(SIG_BLOCK, &m, NULL);
	}
	setvbuf(stdout, outbuf, _IOFBF, sizeof outbuf);
	setenv("HB_HOST_MARK", "host's value", 1);
	umask(027);
	if (chdir(argv[3]) != 0) {
		perror(argv[3]);
		return 2;
	}
	ini_allow_multiline = 1;
	ini_allow_inline_comments = 0;
	ini_allow_no_value = 1;
	ini_stop_on_first_error = 1;
	ini_inline_comment_prefixes = (char *)"!";
	ini_start_comment_prefixes = (char *)"%";
	ini_max_line = 77;
	snapshot(&before);
	armed = 1;

	/* The library at work: a preset, a run, an export, a sweep, a fit. */
	if (hb_preset_load(argv[1], &sc, msg, sizeof msg) != 0)
		fail("preset loaded", msg);
	else if ((s = hb_sim_new(&sc, msg, sizeof msg)) == NULL)
		fail("sim made", msg);
	else {
		struct hb_csv_export_report rep;

		check(hb_sim_run(s) == 0 && hb_sim_ncollisions(s) > 0, "the preset runs");
		snprintf(trace, sizeof trace, "%s/citizen-trace.csv", argv[3]);
		memset(&rep, 0, sizeof rep);
		if (hb_csv_export_files(s, trace, NULL, argv[1], &rep, msg, sizeof msg) != 0)
			fail("CSV exported", msg);
		else
			check(access(trace, R_OK) == 0, "CSV exported");
		hb_sim_free(s);
	}
	{
		struct hb_sweep *sw = hb_sweep_new(&sc, msg, sizeof msg);
		struct hb_sweep_options o = { 0 };

		snprintf(dir, sizeof dir, "%s/citizen-sweep", argv[3]);
		o.dir = dir;
		o.jobs = 2;
		o.shard_n = 1;
		if (sw == NULL || hb_sweep_vary(sw, "run.T=20 ms:40 ms:3", msg, sizeof msg) != 0 ||
		    hb_sweep_run(sw, &o, msg, sizeof msg) != 0)
			fail("a sweep of 3 points runs", msg);
		else
			check(1, "a sweep of 3 points runs");
		hb_sweep_free(sw);
	}
	{
		struct hb_fit_data d = { 0 };
		struct hb_fit_result r;
		const char *keys[] = { "law.c" };
		struct hb_fit_options o = { 0 };

		memset(&r, 0, sizeof r);
		o.keys = keys;
		o.nkeys = 1;
		o.jobs = 2;
		o.max_iter = 5;
		if (hb_fit_data_load(argv[2], &d, msg, sizeof msg) != 0 ||
		    hb_fit_run(&sc, &d, &o, &r, msg, sizeof msg) != 0)
			fail("a fit runs", msg);
		else
			check(r.iter >= 1, "a fit runs");
		hb_fit_result_free(&r);
		hb_fit_data_free(&d);
	}

	armed = 0;
	snapshot(&after);
	prev = gsl_set_error_handler(host_gsl_handler);
	check(prev == host_gsl_handler, "GSL's error handler is the host's");
	check(gsl_errors == 0, "GSL's error handler was never called");
	check(strcmp(before.locale, after.locale) == 0 && strcmp(after.locale, "C.UTF-8") == 0 &&
	    before.thread_locale == after.thread_locale, "the locale is the host's (C.UTF-8)");
	check(same_signals(&before, &after),
	    "SIGINT, SIGTERM, SIGHUP, SIGPIPE dispositions and the signal mask are the host's");
	check(buffering_calls == 0 && after.bufsize == sizeof outbuf && !after.linebuf,
	    "stdout's buffering is the host's (no setvbuf, setbuf, setbuffer, setlinebuf call)");
	check(same_env(&before, &after) && strcmp(getenv("HB_HOST_MARK"), "host's value") == 0,
	    "the environment is the host's");
	check(after.umask == 027, "the umask is the host's (027)");
	check(strcmp(before.cwd, after.cwd) == 0, "the working directory is the host's");
	check(after.ini_multiline == 1 && after.ini_inline == 0 && after.ini_no_value == 1 &&
	    after.ini_stop == 1 && after.ini_max_line == 77 &&
	    after.ini_inline_prefixes == before.ini_inline_prefixes &&
	    after.ini_start_prefixes == before.ini_start_prefixes, "inih's options are the host's");
	snapshot_free(&before);
	snapshot_free(&after);
	fflush(stdout);
	return fails != 0;
}
