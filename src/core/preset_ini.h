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
#include <stddef.h>
#include <string.h>

#include "hybounce/sim.h"

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

/* One "key = value" of a preset, with its [section] and line. */
struct preset_entry {
	char section[32];
	char name[64];
	char *value;
	int line;
};

/*
 * Loads a preset's text onto sc (preset.c); name is the file's for the
 * messages.  With keep, [branch N] sections are taken and every entry is
 * handed back in *keep, *nkeep (preset_entries_free them); else they are
 * refused.  Returns 0, or a status with "NAME:LINE: ..." in msg.
 */
int
preset_load_text(const char *text, const char *name, struct hb_scene *sc,
                 struct preset_entry **keep, int *nkeep, char *msg, size_t n);

/* Frees entries e[0..n) and their values (e may be NULL). */
void
preset_entries_free(struct preset_entry *e, int n);

/* The scene's sections, in the order a preset is written (preset.c). */
enum { PRESET_NSECTIONS = 9 };
extern const char *const preset_sections[PRESET_NSECTIONS];

/* 1 for a [branch N] section (preset_branch.c). */
static inline int
preset_is_branch(const char *section)
{
	return strncmp(section, "branch", 6) == 0;
}

/*
 * The [branch N] sections among the entries e[0..n), read on top of sc
 * (the scene with its --set): each branch's scene is the one before it
 * with the branch's keys.  *br is malloc'd (NULL when none).  Returns 0,
 * or HB_EINVAL with "FILE:LINE: [branch N] key: ...; accepted: ...".
 */
int
preset_branches_read(const struct preset_entry *e, int n, const char *file,
                     const struct hb_scene *sc, struct hb_branch **br, size_t *nbr, char *msg,
                     size_t mn);

#endif
