/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * app.h - the explorer (ncurses), as called by the command line (src/cli/main.c).
 */
#ifndef HYBOUNCE_APP_H
#define HYBOUNCE_APP_H

#include <stddef.h>

struct app_options {
	const char *preset;        /* path or name (presets/NAME.preset); NULL: the default preset */
	const char *const *sets;   /* "KEY=VALUE" overrides, as --set */
	int nsets;
	int ascii;                 /* 1: plain ASCII plots even in a UTF-8 locale (--ascii) */
	const char *script;        /* --script FILE: play keystrokes from a file; NULL: interactive */
	const char *data;          /* --data FILE: measured data shown over the scene (overlay_fit.c) */
	/* the provenance comment line of exported scenes (outputs.h); NULL: none */
	const char *provenance;
};

/*
 * Runs the explorer until the user quits.  Returns the process exit
 * status: 0 on a normal quit, 2 on bad input (a preset that does not load:
 * message in msg, printed by the caller after the terminal is restored),
 * 1 on other failures.  The terminal is always restored before it returns.
 */
int
app_run(const struct app_options *o, char *msg, size_t n);

#endif
