/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * signals.c - the signal policy of the command-line front ends (signals.h),
 * and the provenance line their outputs carry.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "signals.h"

volatile sig_atomic_t cli_signal;

static const int watched[] = { SIGINT, SIGTERM, SIGHUP };
enum { NWATCHED = sizeof watched / sizeof watched[0] };
static struct sigaction saved[NWATCHED];
static int installed[NWATCHED];

static void
on_signal(int sig)
{
	cli_signal = sig;
}

void
cli_signals_watch(void)
{
	cli_signal = 0;
	for (int i = 0; i < NWATCHED; i++) {
		struct sigaction sa;

		installed[i] = 0;
		if (sigaction(watched[i], NULL, &saved[i]) != 0 || saved[i].sa_handler == SIG_IGN)
			continue;   /* ignored on entry (nohup): stays ignored */
		memset(&sa, 0, sizeof sa);
		sa.sa_handler = on_signal;
		sa.sa_flags = SA_RESETHAND;   /* a second one ends the process */
		sigemptyset(&sa.sa_mask);
		if (sigaction(watched[i], &sa, NULL) == 0)
			installed[i] = 1;
	}
}

void
cli_signals_restore(void)
{
	for (int i = 0; i < NWATCHED; i++)
		if (installed[i]) {
			sigaction(watched[i], &saved[i], NULL);
			installed[i] = 0;
		}
}

const char *
cli_signal_name(int sig)
{
	static char buf[32];

	switch (sig) {
	case SIGINT: return "SIGINT";
	case SIGTERM: return "SIGTERM";
	case SIGHUP: return "SIGHUP";
	default:
		snprintf(buf, sizeof buf, "signal %d", sig);
		return buf;
	}
}

int
cli_signal_status(int sig)
{
	return 128 + sig;
}
