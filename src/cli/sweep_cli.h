/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_cli.h - the "hybounce sweep" command (sweep.c) and its job files
 * for a scheduler (sweep_emit.c).
 */
#ifndef HYBOUNCE_CLI_SWEEP_H
#define HYBOUNCE_CLI_SWEEP_H

#include <stddef.h>

struct hb_sweep;

/* hybounce sweep ARGS (argv[0] is "sweep").  Returns the exit status. */
int
sweep_main(int argc, char **argv);

/*
 * --emit slurm|parallel: prepares DIR (sweep.preset) and prints to stdout
 * the job script (slurm) or command line (parallel) that runs `shards`
 * shards and merges them.  Returns 0, or 2 / 1 with a message in msg.
 */
int
sweep_emit(const struct hb_sweep *sw, const char *dir, const char *kind, long shards,
           const char *sshlogin, char *msg, size_t n);

#endif
