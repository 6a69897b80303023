/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * keys.h - key names, and the key lists printed from the modes' key
 * tables (mode.h): the help, the footer, the man page and the README
 * lists come from the same tables as the dispatch, so they cannot drift
 * apart.  Key codes are curses codes (KEY_LEFT ...), but this header does
 * not include curses.
 */
#ifndef HYBOUNCE_KEYS_H
#define HYBOUNCE_KEYS_H

#include <stddef.h>

#include "mode.h"

/*
 * The footer of mode m in context ctx (enum key_ctx): "?:help space:run
 * ..." entries that fit in width columns (the text is cut at a whole
 * entry).  Returns buf.  keys_has_footer: m has footer entries.
 */
char *
keys_footer(const struct mode *m, int ctx, char *buf, size_t n, int width);
int
keys_has_footer(const struct mode *m);

/*
 * The hint of mode m in context ctx, for its title or footer: its
 * bindings' footer words, each after its keys ("Up/Down/PgUp/PgDn scroll,
 * Enter opens"; a key 0 binding is "any key"), then ", any other key"
 * and its other_hint.  Returns buf.
 */
char *
keys_hint(const struct mode *m, int ctx, char *buf, size_t n);

/* The column the help's key labels of mode m take: its longest label, at least 9. */
int
keys_label_width(const struct mode *m);

/*
 * The help's lines of mode m, each ending in a newline: its heading ("In
 * the sweep view (S):"; none for the explorer), then "LABEL     what it
 * does" for each key (the labels padded to keys_label_width), then what any other key does.  Returns the length
 * needed (like snprintf).
 */
size_t
keys_help(const struct mode *m, char *buf, size_t n);

/*
 * The man page text (mdoc) of the EXPLORER KEYS lists, one ".Bl -tag" list
 * per mode of modes (NULL-terminated), each after its heading.  Returns
 * the length needed (like snprintf).
 */
size_t
keys_man(const struct mode *const *modes, char *buf, size_t n);

/*
 * The same lists as Markdown tables for the README's Explorer section
 * ("| Key | Action |" ...).  Returns the length needed (like snprintf).
 */
size_t
keys_markdown(const struct mode *const *modes, char *buf, size_t n);

/*
 * A key name as used by scripts and labels: "space", "Enter", "Tab", "Esc",
 * "Left", "Right", "Up", "Down", "Home", "End", "PgUp", "PgDn", "BSpace",
 * "C-l" (control keys), or one literal character.  Returns the key code,
 * or -1 for an unknown name.
 */
int
keys_from_name(const char *name);

/* The name of a key code (inverse of keys_from_name). Returns buf. */
char *
keys_name(int key, char *buf, size_t n);

#endif
