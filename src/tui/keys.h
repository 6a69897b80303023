/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * keys.h - the explorer's one key table { key, action, label, help }.
 *
 * The help overlay, the footer, the man page's EXPLORER KEYS section (see
 * keys_man) and the scripted mode's key names all come from this table, so
 * they cannot drift apart.  Key codes are curses codes (KEY_LEFT ...), but
 * this header does not include curses.
 */
#ifndef HYBOUNCE_KEYS_H
#define HYBOUNCE_KEYS_H

#include <stddef.h>

enum key_action {
	ACT_NONE = 0,
	ACT_QUIT, ACT_HELP, ACT_PLAY, ACT_STEP_FWD, ACT_STEP_BACK,
	ACT_PREV_JUMP, ACT_NEXT_JUMP, ACT_PREV_COLL, ACT_NEXT_COLL,
	ACT_SCRUB_BACK, ACT_SCRUB_FWD, ACT_HOME, ACT_END,
	ACT_FASTER, ACT_SLOWER, ACT_SLOWMO,
	ACT_VIEW, ACT_ZOOM, ACT_LOOP, ACT_JVIEW,
	ACT_FOCUS, ACT_UP, ACT_DOWN, ACT_PGUP, ACT_PGDN, ACT_ENTER,
	ACT_NUDGE_UP, ACT_NUDGE_DOWN,
	ACT_LAW, ACT_PRESET, ACT_RESTART,
	ACT_PIN, ACT_UNPIN, ACT_STUDY3, ACT_EXPORT, ACT_REDRAW,
	ACT_BRANCH, ACT_SEARCH, ACT_TOP, ACT_BOTTOM, ACT_PREV_SECTION, ACT_NEXT_SECTION,
	ACT_LOG, ACT_PRESENT, ACT_COMPARE,
	ACT_DATA, ACT_DATA_TABLE, ACT_FIT,
	ACT_SWEEP,
	ACT_SEARCH_NEXT, ACT_SEARCH_PREV, ACT_UNDO, ACT_RESET,
	ACT_FIGURE, ACT_ERRBAR,
	ACT_SPACETIME, ACT_IFACE,
	ACT_COUNT
};

/* Where a binding applies: everywhere, or only when the parameter panel has the focus (or not). */
enum key_ctx { CTX_ANY = 0, CTX_PARAMS, CTX_NOT_PARAMS };

struct key_binding {
	int key, key2;          /* curses key codes; key2 0 when none */
	int ctx;                /* enum key_ctx */
	int action;             /* enum key_action */
	const char *label;      /* how the keys are written: "Left h", "space" */
	const char *help;       /* what it does, one line */
	const char *footer;     /* short footer word, NULL: not in the footer */
};

/* The table and its length. */
const struct key_binding *
keys_table(size_t *n);

/* The action bound to key in this context (params: 1 when the parameter panel has the focus). */
int
keys_action(int key, int params);

/*
 * The footer: "?:help space:run ..." entries that fit in width columns
 * (the text is cut at a whole entry).  Returns buf.
 */
char *
keys_footer(char *buf, size_t n, int width);

/*
 * The man page text (mdoc) of the EXPLORER KEYS list, from the table:
 * ".Bl -tag -width Ds" ... ".El".  Returns the length needed (like snprintf).
 */
size_t
keys_man(char *buf, size_t n);

/*
 * The same list as a Markdown table for the README's Explorer section
 * ("| Key | Action |" ...).  Returns the length needed (like snprintf).
 */
size_t
keys_markdown(char *buf, size_t n);

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
