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
 * reads the same spec, and the folder refuses any other sweep.
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/status.h"
#include "hybounce/sweep.h"

#include "sweep_cli.h"

/* s in single quotes for sh ('...'\''...'). */
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

int
sweep_emit(const struct hb_sweep *sw, const char *dir, const char *kind, long shards,
           const char *sshlogin, char *msg, size_t n)
{
	char self[PATH_MAX], adir[PATH_MAX];
	int rc;

	if ((rc = hb_sweep_prepare_dir(sw, dir, msg, n)) != HB_OK)
		return rc == HB_EINVAL ? 2 : 1;
	if (realpath("/proc/self/exe", self) == NULL || realpath(dir, adir) == NULL) {
		hb_status_set(msg, n, HB_EIO, "%s: %s", dir, strerror(errno));
		return 1;
	}
	if (strcmp(kind, "parallel") == 0) {
		/* One line: the shards, one per free core (per host), then the merge. */
		fputs("parallel --halt now,fail=1", stdout);
		if (sshlogin != NULL) {
			fputs(" --sshlogin ", stdout);
			put_sq(stdout, sshlogin);
		}
		fputc(' ', stdout);
		put_sq(stdout, self);
		fputs(" sweep ", stdout);
		put_sq(stdout, adir);
		fputs("/sweep.preset --jobs 1 --quiet --out ", stdout);
		put_sq(stdout, adir);
		printf(" --shard {}/%ld :::", shards);
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
		fputs("HYBOUNCE=", stdout);
		put_sq(stdout, self);
		fputs("\nDIR=", stdout);
		put_sq(stdout, adir);
		printf("\n"
		       "array=$(sbatch --parsable --job-name=hybounce-sweep --array=0-%ld \\\n"
		       "    --ntasks=1 --cpus-per-task=1 --output=\"$DIR/slurm-%%A_%%a.out\" <<EOF\n"
		       "#!/bin/sh\n"
		       "exec \"$HYBOUNCE\" sweep \"$DIR/sweep.preset\" --out \"$DIR\" \\\n"
		       "    --shard \"\\$SLURM_ARRAY_TASK_ID/%ld\" --jobs \"\\${SLURM_CPUS_PER_TASK:-1}\"\n"
		       "EOF\n"
		       ")\n"
		       "array=${array%%%%;*}\n"
		       "merge=$(sbatch --parsable --job-name=hybounce-merge --dependency=afterok:$array \\\n"
		       "    --ntasks=1 --output=\"$DIR/slurm-%%j-merge.out\" <<EOF\n"
		       "#!/bin/sh\n"
		       "exec \"$HYBOUNCE\" sweep --merge \"$DIR\"\n"
		       "EOF\n"
		       ")\n"
		       "echo \"submitted array job $array and merge job ${merge%%%%;*}\"\n",
		       shards - 1, shards);
	}
	if (fflush(stdout) != 0 || ferror(stdout)) {
		hb_status_set(msg, n, HB_EIO, "standard output: %s", strerror(errno));
		return 1;
	}
	return 0;
}
