/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset_ini.h - how presets are read with inih (private to the engine).
 *
 * inih's options are process globals in this build (Debian's libinih sets
 * them at run time), so every parse goes between preset_ini_begin() and
 * preset_ini_end(): under one lock, so that threads loading presets at
 * once neither race on the globals nor see each other's settings, and with
 * the values found put back after, so that a host that uses inih itself
 * finds its settings as it left them.
 */
#ifndef HYBOUNCE_PRESET_INI_H
#define HYBOUNCE_PRESET_INI_H

#include <stdbool.h>

/* Longest line of a preset, in bytes with the newline. */
#define PRESET_MAX_LINE 1024

/* The options found before a parse, put back after it. */
struct preset_ini_saved {
	bool multiline, inline_comments, no_value, stop_on_first_error;
	char *inline_prefixes, *start_prefixes;
	int max_line;
};

/*
 * Takes the lock, saves inih's options in *sv and sets them for a preset:
 * no multi-line values, inline comments after ';' or '#' preceded by white
 * space, no keys without a value, lines up to PRESET_MAX_LINE bytes.
 */
void
preset_ini_begin(struct preset_ini_saved *sv);

/* Puts the options of *sv back and releases the lock. */
void
preset_ini_end(const struct preset_ini_saved *sv);

#endif
