/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * signals.h - the one signal policy of the command-line front ends
 * (batch, sweep, fit):
 *
 *  - SIGINT, SIGTERM and SIGHUP stop the work: the front end writes what
 *    was computed (the report and files of a batch run, the journal of a
 *    sweep, the best point of a fit) and exits 128 + the signal, as a
 *    shell reports a process killed by it;
 *  - a second one ends the process at once (the handler resets itself);
 *  - a signal the process inherited as ignored (nohup, `trap '' HUP`, the
 *    background jobs of a non-interactive shell) stays ignored.
 */
#ifndef HYBOUNCE_CLI_SIGNALS_H
#define HYBOUNCE_CLI_SIGNALS_H

#include <signal.h>

/* The signal caught (0: none yet); what hb_sweep_options.cancel watches. */
extern volatile sig_atomic_t cli_signal;

/* Catches SIGINT, SIGTERM and SIGHUP, those not ignored on entry; clears cli_signal. */
void
cli_signals_watch(void);

/* Puts back the dispositions cli_signals_watch() found. */
void
cli_signals_restore(void);

/* "SIGINT", "SIGTERM", "SIGHUP" or "signal N". */
const char *
cli_signal_name(int sig);

/* The exit status for a run stopped by sig: 128 + sig. */
int
cli_signal_status(int sig);

#endif
