/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * modes.c - the registry: every mode of the explorer (mode.h), the
 * explorer itself first.  The help, the man page's and the README's key
 * lists follow this order.  A new mode is its own file and its line here;
 * tests/cli/modes.sh fails when a mode defined in src/tui is not listed.
 */
#include <stddef.h>

#include "mode.h"

const struct mode *const tui_modes[] = {
	&mode_main,
	&mode_present,
	&mode_help,
	&mode_log,
	&mode_law,
	&mode_preset,
	&mode_prompt,
	&mode_fit,
	&mode_sweep,
	&mode_demo,
	NULL,
};
