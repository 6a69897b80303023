/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset_ini.h - how presets are read with inih (private to the engine):
 * inih's options are process globals in this build, so every reader sets
 * them through preset_ini_options() before it parses.
 */
#ifndef HYBOUNCE_PRESET_INI_H
#define HYBOUNCE_PRESET_INI_H

/* Longest line of a preset, in bytes with the newline. */
#define PRESET_MAX_LINE 1024

/*
 * No multi-line values, inline comments after ';' or '#' preceded by white
 * space, no keys without a value, lines up to PRESET_MAX_LINE bytes.
 */
void
preset_ini_options(void);

#endif
