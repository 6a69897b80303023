/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_emit.c - job files for a scheduler: "--emit slurm" prints a shell
 * script that submits the shards as a Slurm job array (sbatch
 * --array=0-(N-1), the shard from SLURM_ARRAY_TASK_ID) and a merge job that
 * depends on the whole array (afterok); "--emit parallel" prints a GNU
 * parallel command line that runs the shards, on this machine or on the
 * hosts of --sshlogin, then merges.
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

#include "hybounce/status.h"
#include "hybounce/sweep.h"

#include "sweep_cli.h"

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
 * "--chdir=DIR --output=/dev/null": the job runs in the folder.  Slurm reads
 * --output as a file pattern, where % and \ in the folder's name would
 * mean something and cannot all be escaped; so the job's own script sends
 * its output to a file there (WRAP_OUT), and --chdir takes the folder as
 * it is.
 */
static void
put_output(FILE *f, const char *dir)
{
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

int
sweep_emit(const struct hb_sweep *sw, const char *dir, const char *kind, long shards,
           const char *sshlogin, char *msg, size_t n)
{
	char self[PATH_MAX], adir[PATH_MAX], rest[96];
	int rc;

	if ((rc = hb_sweep_prepare_dir(sw, dir, msg, n)) != HB_OK)
		return rc == HB_EINVAL ? 2 : 1;
	if (realpath("/proc/self/exe", self) == NULL || realpath(dir, adir) == NULL) {
		hb_status_set(msg, n, HB_EIO, "%s: %s", dir, strerror(errno));
		return 1;
	}
	if (strcmp(kind, "parallel") == 0) {
		/*
		 * One line: the shards, one per free core (per host), then the
		 * merge.  parallel hands its command to a shell after replacing
		 * {}, {.}, {#} ... in it, and splits ::: values at newlines: the
		 * program and the folder reach the shards in the environment
		 * (--env for other hosts), never in parallel's command text.
		 */
		fputs("HB_SWEEP_BIN=", stdout);
		put_sq(stdout, self);
		fputs(" HB_SWEEP_DIR=", stdout);
		put_sq(stdout, adir);
		fputs(" parallel --halt now,fail=1", stdout);
		if (sshlogin != NULL) {
			fputs(" --sshlogin ", stdout);
			put_sq(stdout, sshlogin);
			fputs(" --env HB_SWEEP_BIN --env HB_SWEEP_DIR", stdout);
		}
		printf(" '\"$HB_SWEEP_BIN\" sweep \"$HB_SWEEP_DIR/sweep.preset\" --jobs 1 --quiet "
		       "--out \"$HB_SWEEP_DIR\" --shard {}/%ld' :::", shards);
		for (long k = 0; k < shards; k++)
			printf(" %ld", k);
		fputs(" && ", stdout);
		put_sq(stdout, self);
		fputs(" sweep --quiet --merge ", stdout);
		put_sq(stdout, adir);
		fputc('\n', stdout);
	} else {
		printf("#!/bin/sh\n"
		       "# hybounce sweep of %ld points: %ld shards as a Slurm job array, then\n"
		       "# a merge job that runs once every shard has succeeded.\n"
		       "# Submit with: sh THIS_FILE   (the output goes to DIR/slurm-*.out)\n"
		       "set -e\n", hb_sweep_npoints(sw), shards);
		printf("array=$(sbatch --parsable --job-name=hybounce-sweep --array=0-%ld \\\n"
		       "    --ntasks=1 --cpus-per-task=1 ", shards - 1);
		snprintf(rest, sizeof rest, " --shard \"$SLURM_ARRAY_TASK_ID/%ld\" "
		         "--jobs \"${SLURM_CPUS_PER_TASK:-1}\"", shards);
		put_output(stdout, adir);
		fputs(" \\\n    ", stdout);
		if (put_wrap(stdout, "exec >\"slurm-${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID}.out\" 2>&1",
		             self, adir, "/sweep.preset", " --out ", rest) != 0)
			goto nomem;
		printf(")\n"
		       "array=${array%%%%;*}\n"
		       "merge=$(sbatch --parsable --job-name=hybounce-merge "
		       "--dependency=afterok:$array \\\n"
		       "    --ntasks=1 ");
		put_output(stdout, adir);
		fputs(" \\\n    ", stdout);
		if (put_wrap(stdout, "exec >\"slurm-${SLURM_JOB_ID}-merge.out\" 2>&1", self, adir,
		             NULL, "--merge ", "") != 0)
			goto nomem;
		printf(")\n"
		       "echo \"submitted array job $array and merge job ${merge%%%%;*}\"\n");
	}
	if (fflush(stdout) != 0 || ferror(stdout)) {
		hb_status_set(msg, n, HB_EIO, "standard output: %s", strerror(errno));
		return 1;
	}
	return 0;
nomem:
	hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	return 1;
}
