/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_cli.h - the "hybounce sweep" command (sweep.c) and its job files
 * for a scheduler (sweep_emit.c).
 */
#ifndef HYBOUNCE_CLI_SWEEP_H
#define HYBOUNCE_CLI_SWEEP_H

#include <stddef.h>
#include <stdio.h>

struct hb_sweep;
struct hb_sweep_refine_stats;

/* hybounce sweep ARGS (argv[0] is "sweep").  Returns the exit status. */
int
sweep_main(int argc, char **argv);

/* "sweep: refined: 2 boundaries located to ... (4.2%)", the summary of --refine. */
void
sweep_refine_summary(FILE *f, const struct hb_sweep *sw, const struct hb_sweep_refine_stats *s);

/* What --emit writes: the scheduler, the shards, and its options. */
struct sweep_emit_opts {
	const char *kind;       /* "slurm" or "parallel" */
	long shards;            /* >= 1 */
	const char *sshlogin;   /* parallel --sshlogin, or NULL */
	/* sbatch's --time, --partition, --account, --qos, --mem (NULL: none) */
	const char *time, *partition, *account, *qos, *mem;
	long max_array;         /* MaxArraySize; 0: from scontrol, else 1001 */
	int hdf5;               /* the merge writes sweep.h5 (--format hdf5) */
};

/*
 * --emit slurm|parallel: prepares DIR (sweep.preset, and DIR/logs for
 * Slurm) and prints to stdout the job script (slurm) or command line
 * (parallel) that runs the shards that DIR does not hold done, then the
 * merge.  Returns 0, or 2 / 1 with a message in msg.
 */
int
sweep_emit(const struct hb_sweep *sw, const char *dir, const struct sweep_emit_opts *e,
           char *msg, size_t n);

/* 1 for values sbatch takes: --time (M, M:S, H:M:S, D-H, D-H:M, D-H:M:S,
 * UNLIMITED), --mem (digits, then K, M, G or T), a partition, account or
 * QOS name (letters, digits, _ - . , +). */
int
slurm_time_ok(const char *t);
int
slurm_mem_ok(const char *t);
int
slurm_name_ok(const char *t);

#endif
