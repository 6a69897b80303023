/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * term.h - curses setup and teardown, colours, signal flags.
 *
 * The only caller of initscr/newterm/endwin.  term_end() is safe to call
 * more than once and on every exit path (also from term_oom()).
 */
#ifndef HYBOUNCE_TERM_H
#define HYBOUNCE_TERM_H

#include <stddef.h>

/* Colour pairs (used only when term_colour()). */
enum {
	PAIR_INK1 = 1,     /* ink k (1 = the current run, 2.. pins) is pair PAIR_INK1 + k - 1 */
	PAIR_CONTACT = 9,  /* contact marker row */
	PAIR_STATUS = 10,  /* status line */
	PAIR_ERROR = 11,   /* messages that say something failed */
	PAIR_CURSOR = 12,  /* the cursor column */
	PAIR_TITLE = 13,
	PAIR_PAPER = 14,   /* plain text: black on white in the light theme */
};

/* The light theme (dark inks on white, for a projector) or the dark one; needs colours. */
void
term_light(int on);

/*
 * Interactive setup: setlocale, initscr, cbreak, noecho, keypad,
 * curs_set(0), set_escdelay(25), colours unless NO_COLOR is set or the
 * terminal has none, and the signal handlers.  Returns 0, or -1 with a
 * message in msg (no terminal).
 */
int
term_begin(char *msg, size_t n);

/*
 * Scripted setup: a curses screen of cols x lines written to /dev/null
 * (newterm), so no terminal is needed; no colours.  Returns 0 or -1.
 */
int
term_begin_script(int cols, int lines, char *msg, size_t n);

/* Restores the terminal (endwin) if it was set up; idempotent. */
void
term_end(void);

/* 1 if colours are in use. */
int
term_colour(void);

/* Mouse reports on (clicks and the wheel) or off; a no-op without a terminal. */
void
term_mouse(int on);

/* 1 if the locale's codeset is UTF-8 (Braille plots possible). */
int
term_utf8(void);

/* The signal that asked to stop (SIGINT, SIGTERM, SIGHUP), or 0. */
int
term_signalled(void);

/* Out of memory in the explorer: restore the terminal, then abort. */
_Noreturn void
term_oom(void);

/* malloc/calloc that call term_oom() on failure. */
void *
term_xcalloc(size_t nmemb, size_t size);

#endif
