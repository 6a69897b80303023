/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * report.h - what the command-line front ends (batch, sweep, fit, plot)
 * say about the files they write: the provenance line every output
 * carries, and the "wrote PATH" line that names an overwrite (outputs.h);
 * and how they refuse bad input.
 */
#ifndef HYBOUNCE_CLI_REPORT_H
#define HYBOUNCE_CLI_REPORT_H

#include "hybounce/atomic.h"

/*
 * The provenance line of this process's outputs (outputs.h): version,
 * commit and the command line as main() received it (cli_provenance_init).
 */
void
cli_provenance_init(int argc, char **argv);

const char *
cli_provenance(void);

/* "wrote PATH" on stderr, with how when it was not a plain new file (hb_outputs_how). */
void
cli_print_wrote(const char *path, const struct hb_atomic_target *t);

/*
 * A refusal of bad input: "PROG: MESSAGE" on stderr, and with usage (not
 * NULL) a line "Try 'USAGE --help'." after it.  Returns 2, the exit status
 * of bad input.
 */
int
cli_refuse(const char *prog, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

int
cli_refuse_usage(const char *prog, const char *usage, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
