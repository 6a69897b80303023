/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * mode.h - the explorer's modes, as tmux's window modes: each mode (the
 * explorer itself, the help, the log, the law and preset pickers, the
 * prompt, the data table of a fit, the sweep view, presentation) is a
 * struct mode in its own file, with its own key table.
 *
 * The modes open on a stack in the app state (struct app's mode[]): the
 * explorer at the bottom, the mode on top takes the keys.  A key is looked
 * up in the top mode's table; a key not in it goes to the mode's other()
 * (text typed into the prompt, "any other key closes" of the help), or,
 * for a mode that passes keys through (presentation), to the mode beneath.
 * Every key list the user reads (the help, the footer, the man page's
 * EXPLORER KEYS, the README's tables) is printed from these tables
 * (keys.c), one list per mode, in the order of the registry tui_modes
 * (modes.c).  Adding a mode is its file (its struct mode and its table)
 * and its line in tui_modes; tests/cli/modes.sh checks that every mode
 * defined is registered, and tests/test_tui_keys.c that each mode's keys
 * are in the help and the man page.
 */
#ifndef HYBOUNCE_MODE_H
#define HYBOUNCE_MODE_H

#include <stddef.h>

struct app;

/*
 * Where a binding applies: everywhere in its mode, or only in one of the
 * mode's contexts (its context()): the explorer's parameter panel has the
 * focus or not; the sweep view shows its curve or its map.
 */
enum key_ctx {
	CTX_ANY = 0, CTX_PARAMS, CTX_NOT_PARAMS, CTX_CURVE, CTX_MAP,
	/* a --script demo on the real screen: playing, paused, at a wait-key, ended */
	CTX_DEMO_PLAY, CTX_DEMO_PAUSED, CTX_DEMO_KEY, CTX_DEMO_END
};

typedef void mode_fn(struct app *a);

struct mode_key {
	/*
	 * curses key codes; key2 0 when none.  key 0: "any other key" in ctx
	 * (fn NULL; the mode's loop acts on it), written "any other key"
	 */
	int key, key2;
	int ctx;                /* enum key_ctx */
	mode_fn *fn;            /* what it does */
	const char *label;      /* how the keys are written: "Left h", "space" */
	const char *help;       /* what it does, one line */
	/*
	 * the footer's word ("help": "?:help"), or "KEYS:word" to write the keys
	 * otherwise; NULL: none.  The same words make the mode's hint
	 * (keys_hint: "Up/Down scroll, Enter opens") in its title.
	 */
	const char *footer;
};

struct mode {
	const char *name;       /* one word: "sweep" */
	const char *title;      /* its key list's heading: "the sweep view" */
	const char *opener;     /* the keys that open it, key names ("? F1"); NULL: the explorer itself */
	const struct mode_key *keys;
	size_t nkeys;
	/* what any other key does, for the key lists ("closes it"); NULL: nothing */
	const char *other_help;
	const char *other_hint; /* the same in the mode's hint ("closes"); NULL: none */
	void (*other)(struct app *a, int ch);   /* a key not in the table; NULL: ignored */
	int passthrough;        /* a key not in the table goes to the mode beneath instead */
	int (*context)(const struct app *a);    /* the enum key_ctx now; NULL: CTX_ANY */
	/* draws the mode over what is beneath it (self: this mode, for its footer); NULL: nothing */
	void (*draw)(const struct app *a, const struct mode *self);
	mode_fn *enter;         /* after it is pushed; NULL: nothing */
	mode_fn *leave;         /* before it is popped; NULL: nothing */
};

#define MODE_KEYS(t) (t), (sizeof(t) / sizeof((t)[0]))

/* The registry (modes.c): every mode, the explorer first, NULL-terminated. */
extern const struct mode *const tui_modes[];

extern const struct mode mode_main, mode_help, mode_log, mode_law, mode_preset, mode_prompt,
	mode_fit, mode_sweep, mode_present, mode_demo;

/* The stack (mode.c).  mode_push: m on top (enter); mode_pop: the top off (leave). */
void mode_push(struct app *a, const struct mode *m);
void mode_pop(struct app *a);
/* Takes m off the stack wherever it is (with what is above it). */
void mode_close(struct app *a, const struct mode *m);
const struct mode *mode_top(const struct app *a);
int mode_on(const struct app *a, const struct mode *m);  /* m is on the stack */
/* The binding of key in m in context ctx (enum key_ctx), or NULL. */
const struct mode_key *mode_binding(const struct mode *m, int key, int ctx);
/* The context of m now (its context(), or CTX_ANY). */
int mode_context(const struct app *a, const struct mode *m);
/* One key to the top mode: its table, its other(), or the mode beneath (passthrough). */
void mode_key(struct app *a, int ch);
/* Draws the modes on the stack, bottom first (each one's draw). */
void mode_draw(const struct app *a);

#endif
