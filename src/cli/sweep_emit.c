/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_emit.c - job files for a scheduler: "--emit slurm" prints a shell
 * script that submits the shards as Slurm job arrays (the shard from
 * SLURM_ARRAY_TASK_ID; one array per MaxArraySize shards) and a merge job
 * that runs once they have all ended, whatever their fate (afterany), and
 * names the shards that did not finish; "--emit parallel" prints a GNU
 * parallel command line that runs the shards, on this machine or on the
 * hosts of --sshlogin, then merges.  Both leave out the shards that the
 * folder holds done: after a failure, the same --emit computes only the
 * rest.
 *
 * Both name the binary and the folder by absolute path and the sweep by
 * DIR/sweep.preset, which is written first: every shard, wherever it runs,
 * reads the same spec, and the folder refuses any other sweep.  Whatever
 * comes from the user reaches the shell as one single-quoted word (put_sq),
 * never inside a here-document or a command text that another program
 * expands again.
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hybounce/status.h"
#include "hybounce/sweep.h"

#include "sweep_cli.h"

/* Slurm's default MaxArraySize: array indices 0 to 1000. */
#define SLURM_DEFAULT_MAX_ARRAY 1001L

/*
 * s as one word for sh: in single quotes, each ' written as '\'' (newlines
 * and every other byte stand as they are inside single quotes).  The one
 * quoting function of the emitted scripts: everything that comes from the
 * user (the folder, the program's path, the hosts) goes through it, and a
 * script that holds a script (sbatch --wrap) quotes the inner text again.
 */
static void
put_sq(FILE *f, const char *s)
{
	fputc('\'', f);
	for (; *s; s++)
		if (*s == '\'')
			fputs("'\\''", f);
		else
			fputc(*s, f);
	fputc('\'', f);
}

/*
 * "--chdir=DIR --output=/dev/null" and the options of the sweep's
 * resources (--time, --partition, ...), each value one quoted word: the job
 * runs in the folder.  Slurm reads --output as a file pattern, where % and
 * \ in the folder's name would mean something and cannot all be escaped;
 * so the job's own script sends its output to a file under logs/ there, and
 * --chdir takes the folder as it is.
 */
static void
put_output(FILE *f, const char *dir, const struct sweep_emit_opts *e)
{
	const char *name[] = { "time", "partition", "account", "qos", "mem" };
	const char *val[] = { e->time, e->partition, e->account, e->qos, e->mem };

	for (size_t i = 0; i < sizeof name / sizeof name[0]; i++)
		if (val[i] != NULL) {
			fprintf(f, "--%s=", name[i]);
			put_sq(f, val[i]);
			fputc(' ', f);
		}
	fputs("--chdir=", f);
	put_sq(f, dir);
	fputs(" --output=/dev/null", f);
}

/*
 * "--wrap=" then the quoted command "OUT; exec 'SELF' sweep ARGS" for sbatch:
 * the job's script is that text, run by sh on the node; OUT and REST are
 * fixed text of ours (e.g. "$SLURM_ARRAY_TASK_ID"), written as they are.  A here-document would
 * put the folder inside a script that the submitting shell expands.
 */
static int
put_wrap(FILE *f, const char *out, const char *self, const char *dir, const char *preset_suffix,
         const char *mid, const char *rest)
{
	char *cmd = NULL, *p = NULL;
	size_t len = 0, plen = 0;
	FILE *m;

	if ((m = open_memstream(&cmd, &len)) == NULL)
		return -1;
	fputs(out, m);
	fputs("; exec ", m);
	put_sq(m, self);
	fputs(" sweep ", m);
	if (preset_suffix != NULL) {
		FILE *pm = open_memstream(&p, &plen);
		if (pm == NULL || (fprintf(pm, "%s%s", dir, preset_suffix), fclose(pm)) != 0) {
			fclose(m);
			free(cmd);
			free(p);
			return -1;
		}
		put_sq(m, p);
		free(p);
	}
	fputs(mid, m);
	put_sq(m, dir);
	fputs(rest, m);
	if (fclose(m) != 0 || cmd == NULL) {
		free(cmd);
		return -1;
	}
	fputs("--wrap=", f);
	put_sq(f, cmd);
	free(cmd);
	return 0;
}

/* Slurm's time limit: M, M:S, H:M:S, D-H, D-H:M, D-H:M:S, or UNLIMITED. */
int
slurm_time_ok(const char *t)
{
	const char *p = t;
	int fields = 0, day = 0;

	if (strcmp(t, "UNLIMITED") == 0 || strcmp(t, "INFINITE") == 0)
		return 1;
	for (;;) {
		if (*p < '0' || *p > '9')
			return 0;
		while (*p >= '0' && *p <= '9')
			p++;
		fields++;
		if (*p == '-' && !day && fields == 1) {
			day = 1;
			fields = 0;
			p++;
		} else if (*p == ':' && fields < 3 - day) {
			p++;
		} else {
			return *p == '\0';
		}
	}
}

/* Slurm's memory size: digits, then K, M, G or T (megabytes without). */
int
slurm_mem_ok(const char *t)
{
	const char *p = t;

	while (*p >= '0' && *p <= '9')
		p++;
	if (p == t)
		return 0;
	if (*p != '\0' && strchr("KMGTkmgt", *p) != NULL)
		p++;
	return *p == '\0';
}

/* A partition, account or QOS name (or a comma list of them). */
int
slurm_name_ok(const char *t)
{
	if (*t == '\0')
		return 0;
	for (; *t; t++)
		if (!((*t >= 'a' && *t <= 'z') || (*t >= 'A' && *t <= 'Z') ||
		      (*t >= '0' && *t <= '9') || strchr("_-.,+", *t) != NULL))
			return 0;
	return 1;
}

/*
 * The cluster's MaxArraySize from "scontrol show config" (a fixed command
 * line, no user text in it), or 0 when scontrol does not answer.
 */
static long
slurm_max_array(void)
{
	char line[512];
	long v = 0;
	FILE *p = popen("scontrol show config 2>/dev/null", "r");

	if (p == NULL)
		return 0;
	while (fgets(line, sizeof line, p) != NULL) {
		char *eq;

		if (strncmp(line, "MaxArraySize", 12) != 0 || (eq = strchr(line, '=')) == NULL)
			continue;
		v = strtol(eq + 1, NULL, 10);
	}
	if (pclose(p) != 0)
		return 0;
	return v > 0 ? v : 0;
}

/* "0-3,7,9-12": the indices k - base of the shards pending[from, to). */
static void
put_array_spec(FILE *f, const long *pending, long from, long to, long base)
{
	for (long i = from; i < to; ) {
		long j = i;

		while (j + 1 < to && pending[j + 1] == pending[j] + 1)
			j++;
		if (i > from)
			fputc(',', f);
		if (j > i)
			fprintf(f, "%ld-%ld", pending[i] - base, pending[j] - base);
		else
			fprintf(f, "%ld", pending[i] - base);
		i = j + 1;
	}
}

static int
emit_slurm(const struct hb_sweep *sw, const char *self, const char *adir, const long *pending,
           long npending, const struct sweep_emit_opts *e, char *msg, size_t n)
{
	long ns = e->shards, max = e->max_array, narrays = 0;
	char out[160], rest[96];

	if (max <= 0 && (max = slurm_max_array()) <= 0) {
		max = SLURM_DEFAULT_MAX_ARRAY;
		if (npending > 0 && pending[npending - 1] >= max)
			fprintf(stderr, "sweep: scontrol does not answer here: arrays of at most "
			        "%ld shards (Slurm's default MaxArraySize; --max-array N sets "
			        "another)\n", max);
	}
	for (long i = 0; i < npending; ) {
		long j = i;

		while (j < npending && pending[j] / max == pending[i] / max)
			j++;
		narrays++;
		i = j;
	}
	printf("#!/bin/sh\n"
	       "# hybounce sweep of %ld points in %ld shards: %ld to compute (%ld done), as %ld\n"
	       "# Slurm job array%s of at most %ld tasks (MaxArraySize), then a merge job that\n"
	       "# runs once they have ended, whatever their fate (afterany): it writes\n"
	       "# runs.csv and collisions.csv, or fails naming the shards that did not\n"
	       "# finish; the same --emit command then submits only those.\n"
	       "# Submit with: sh THIS_FILE   (the jobs' output goes to DIR/logs/)\n"
	       "# sbatch's SBATCH_* environment variables apply (options given here win).\n"
	       "set -e\n"
	       "ids=\n"
	       "deps=\n", hb_sweep_npoints(sw), ns, npending, ns - npending, narrays,
	       narrays == 1 ? "" : "s", max);
	snprintf(rest, sizeof rest, " --shard \"$k/%ld\" --jobs \"${SLURM_CPUS_PER_TASK:-1}\"", ns);
	for (long i = 0; i < npending; ) {
		long base = pending[i] / max * max, j = i;

		while (j < npending && pending[j] / max == pending[i] / max)
			j++;
		fputs("a=$(sbatch --parsable --job-name=hybounce-sweep --array=", stdout);
		put_array_spec(stdout, pending, i, j, base);
		fputs(" \\\n    --ntasks=1 --cpus-per-task=1 ", stdout);
		put_output(stdout, adir, e);
		fputs(" \\\n    ", stdout);
		snprintf(out, sizeof out, "k=$((%ld + SLURM_ARRAY_TASK_ID)); exec "
		         ">\"logs/shard-$k-of-%ld.$SLURM_JOB_ID.out\" 2>&1", base, ns);
		if (put_wrap(stdout, out, self, adir, "/sweep.preset", " --out ", rest) != 0)
			goto nomem;
		printf(")\n"
		       "ids=\"$ids ${a%%%%;*}\"\n"
		       "deps=\"$deps:${a%%%%;*}\"\n");
		i = j;
	}
	printf("merge=$(sbatch --parsable --job-name=hybounce-merge "
	       "${deps:+--dependency=afterany$deps} \\\n"
	       "    --ntasks=1 ");
	put_output(stdout, adir, e);
	fputs(" \\\n    ", stdout);
	snprintf(rest, sizeof rest, " --shards %ld%s", ns, e->hdf5 ? " --format hdf5" : "");
	if (put_wrap(stdout, "exec >\"logs/merge.$SLURM_JOB_ID.out\" 2>&1", self, adir, NULL,
	             "--merge ", rest) != 0)
		goto nomem;
	printf(")\n"
	       "echo \"submitted array jobs${ids:- (none: every shard is done)} and merge "
	       "job ${merge%%%%;*}\"\n");
	return 0;
nomem:
	hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	return 1;
}

static void
emit_parallel(const char *self, const char *adir, const long *pending, long npending,
              const struct sweep_emit_opts *e)
{
	/*
	 * One line: the shards, one per free core (per host), then the merge,
	 * which runs whatever the shards' fate and names those that did not
	 * finish.  parallel hands its command to a shell after replacing {},
	 * {.}, {#} ... in it, and splits ::: values at newlines: the program
	 * and the folder reach the shards in the environment (--env for other
	 * hosts), never in parallel's command text.
	 */
	if (npending > 0) {
		fputs("HB_SWEEP_BIN=", stdout);
		put_sq(stdout, self);
		fputs(" HB_SWEEP_DIR=", stdout);
		put_sq(stdout, adir);
		fputs(" parallel", stdout);
		if (e->sshlogin != NULL) {
			fputs(" --sshlogin ", stdout);
			put_sq(stdout, e->sshlogin);
			fputs(" --env HB_SWEEP_BIN --env HB_SWEEP_DIR", stdout);
		}
		printf(" '\"$HB_SWEEP_BIN\" sweep \"$HB_SWEEP_DIR/sweep.preset\" --jobs 1 --quiet "
		       "--out \"$HB_SWEEP_DIR\" --shard {}/%ld' :::", e->shards);
		for (long k = 0; k < npending; k++)
			printf(" %ld", pending[k]);
		fputs("; ", stdout);
	}
	put_sq(stdout, self);
	printf(" sweep --quiet --merge ");
	put_sq(stdout, adir);
	printf(" --shards %ld%s\n", e->shards, e->hdf5 ? " --format hdf5" : "");
}

int
sweep_emit(const struct hb_sweep *sw, const char *dir, const struct sweep_emit_opts *e,
           char *msg, size_t n)
{
	char self[PATH_MAX], adir[PATH_MAX], logs[PATH_MAX + 8];
	unsigned char *done;
	long *pending, npending = 0, ndone;
	int rc;

	if ((rc = hb_sweep_prepare_dir(sw, dir, msg, n)) != HB_OK)
		return rc == HB_EINVAL ? 2 : 1;
	if (realpath("/proc/self/exe", self) == NULL || realpath(dir, adir) == NULL) {
		hb_status_set(msg, n, HB_EIO, "%s: %s", dir, strerror(errno));
		return 1;
	}
	snprintf(logs, sizeof logs, "%s/logs", adir);
	if (strcmp(e->kind, "slurm") == 0 && mkdir(logs, 0777) != 0 && errno != EEXIST) {
		hb_status_set(msg, n, HB_EIO, "%s: %s", logs, strerror(errno));
		return 1;
	}
	done = calloc((size_t)e->shards, 1);
	pending = malloc((size_t)e->shards * sizeof *pending);
	if (done == NULL || pending == NULL) {
		free(done);
		free(pending);
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		return 1;
	}
	if ((ndone = hb_sweep_shards_done(sw, adir, e->shards, done, msg, n)) < 0) {
		free(done);
		free(pending);
		return 1;
	}
	for (long k = 0; k < e->shards; k++)
		if (!done[k])
			pending[npending++] = k;
	if (ndone > 0)
		fprintf(stderr, "sweep: %ld of %ld shards already done in %s; the %s runs the "
		        "other %ld, then the merge\n", ndone, e->shards, dir,
		        strcmp(e->kind, "slurm") == 0 ? "script" : "command line", npending);
	if (strcmp(e->kind, "parallel") == 0)
		emit_parallel(self, adir, pending, npending, e);
	else
		rc = emit_slurm(sw, self, adir, pending, npending, e, msg, n);
	free(done);
	free(pending);
	if (rc != 0)
		return rc;
	if (fflush(stdout) != 0 || ferror(stdout)) {
		hb_status_set(msg, n, HB_EIO, "standard output: %s", strerror(errno));
		return 1;
	}
	return 0;
}
