/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * term.c - curses setup and teardown (like htop's CRT.c).
 *
 * Signals: SIGINT, SIGTERM, SIGHUP and SIGQUIT (Ctrl-\) only set a
 * volatile sig_atomic_t flag (installed without SA_RESTART so a blocking
 * read returns); the loop in app.c sees it, leaves through term_end()
 * (cursor shown, alternate screen left, modes reset) and the program exits
 * with 128 + the signal's number.  Nothing is drawn from a handler.
 * SIGWINCH and SIGTSTP belong to ncurses.
 */
#include <curses.h>
#include <langinfo.h>
#include <locale.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cnum.h" /* ASCII case fold (src/core) */
#include "term.h"

static volatile sig_atomic_t stop_signal;
static int active;       /* curses is set up */
static int colour;
static int utf8;
static SCREEN *script_screen;
static FILE *script_out, *script_in;

static void
on_signal(int sig)
{
	stop_signal = sig;
}

static void
signals_install(void)
{
	struct sigaction sa;

	memset(&sa, 0, sizeof sa);
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	sa.sa_flags = 0; /* no SA_RESTART: getch returns on a signal */
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	sigaction(SIGHUP, &sa, NULL);
	sigaction(SIGQUIT, &sa, NULL);
}

static void
locale_setup(void)
{
	const char *cs;

	/*
	 * The character set only (UTF-8 text, Braille plots): numbers stay in
	 * the C numeric locale (LC_NUMERIC is never taken from the
	 * environment), so fields, exports and presets read and write a dot
	 * under LANG=de_DE.UTF-8 as under LANG=C.
	 */
	setlocale(LC_CTYPE, "");
	cs = nl_langinfo(CODESET);
	utf8 = cs != NULL && (cnum_casecmp(cs, "UTF-8") == 0 || cnum_casecmp(cs, "utf8") == 0);
}

/*
 * The colour pairs of the dark theme (the terminal's own background) or of
 * the light one (dark inks on white, for a projector); nothing without
 * colours.
 */
void
term_light(int on)
{
	short bg = on ? COLOR_WHITE : -1;

	if (!colour)
		return;
	init_pair(PAIR_INK1, on ? COLOR_BLUE : COLOR_CYAN, bg);
	init_pair(PAIR_INK1 + 1, on ? COLOR_RED : COLOR_YELLOW, bg);
	init_pair(PAIR_INK1 + 2, COLOR_MAGENTA, bg);
	init_pair(PAIR_INK1 + 3, COLOR_GREEN, bg);
	init_pair(PAIR_INK1 + 4, on ? COLOR_BLACK : COLOR_RED, bg);
	init_pair(PAIR_INK1 + 5, on ? COLOR_CYAN : COLOR_BLUE, bg);
	init_pair(PAIR_CONTACT, COLOR_RED, bg);
	init_pair(PAIR_STATUS, on ? COLOR_WHITE : COLOR_BLACK, on ? COLOR_BLUE : COLOR_CYAN);
	init_pair(PAIR_ERROR, COLOR_RED, bg);
	init_pair(PAIR_CURSOR, COLOR_WHITE, COLOR_BLUE);
	init_pair(PAIR_TITLE, on ? COLOR_BLUE : COLOR_YELLOW, bg);
	init_pair(PAIR_PAPER, on ? COLOR_BLACK : -1, bg);
	bkgd(on ? COLOR_PAIR(PAIR_PAPER) : 0);
}

static void
colours_setup(void)
{
	const char *nc = getenv("NO_COLOR");

	colour = 0;
	if ((nc != NULL && nc[0] != 0) || !has_colors())
		return;
	if (start_color() != OK)
		return;
	use_default_colors();
	colour = 1;
	term_light(0);
	colour = 1;
}

static void
modes_setup(void)
{
	cbreak();
	noecho();
	nonl();
	keypad(stdscr, TRUE);
	curs_set(0);
	set_escdelay(25);
}

int
term_begin(char *msg, size_t n)
{
	locale_setup();
	stop_signal = 0;
	if (newterm(NULL, stdout, stdin) == NULL) {
		snprintf(msg, n, "cannot open the terminal (TERM=%s): expected a terminal type known to "
		         "the terminfo database (see toe -a), such as xterm-256color or vt100",
		         getenv("TERM") ? getenv("TERM") : "unset");
		return -1;
	}
	active = 1;
	modes_setup();
	colours_setup();
	signals_install();
	return 0;
}

int
term_begin_script(int cols, int lines, char *msg, size_t n)
{
	static const char *types[] = { NULL, "xterm-256color", "xterm", "vt100", "ansi" };
	size_t i;

	locale_setup();
	stop_signal = 0;
	script_out = fopen("/dev/null", "w");
	script_in = fopen("/dev/null", "r");
	if (script_out == NULL || script_in == NULL) {
		snprintf(msg, n, "cannot open /dev/null");
		goto fail;
	}
	/* the size comes from LINES/COLUMNS when the output is not a terminal */
	{
		char b[16];
		snprintf(b, sizeof b, "%d", lines);
		setenv("LINES", b, 1);
		snprintf(b, sizeof b, "%d", cols);
		setenv("COLUMNS", b, 1);
	}
	for (i = 0; i < sizeof types / sizeof types[0]; i++) {
		const char *t = types[i] ? types[i] : getenv("TERM");
		if (t == NULL || t[0] == 0)
			continue;
		script_screen = newterm(t, script_out, script_in);
		if (script_screen != NULL)
			break;
	}
	if (script_screen == NULL) {
		snprintf(msg, n, "scripted mode: no usable terminal description (tried TERM, xterm, vt100)");
		goto fail;
	}
	active = 1;
	if (LINES != lines || COLS != cols)
		resizeterm(lines, cols);
	cbreak();
	noecho();
	keypad(stdscr, TRUE);
	colour = 0;
	signals_install();
	return 0;
fail:
	if (script_out)
		fclose(script_out);
	if (script_in)
		fclose(script_in);
	script_out = script_in = NULL;
	return -1;
}

void
term_end(void)
{
	if (!active)
		return;
	active = 0;
	mousemask(0, NULL);
	curs_set(1);
	endwin();
	if (script_screen != NULL) {
		delscreen(script_screen);
		script_screen = NULL;
		fclose(script_out);
		fclose(script_in);
		script_out = script_in = NULL;
	}
}

void
term_mouse(int on)
{
	if (!active)
		return;
	if (on) {
		mousemask(BUTTON1_PRESSED | BUTTON1_CLICKED | BUTTON4_PRESSED | BUTTON5_PRESSED, NULL);
		mouseinterval(0);
	} else {
		mousemask(0, NULL);
	}
}

int
term_colour(void)
{
	return colour;
}

int
term_utf8(void)
{
	return utf8;
}

int
term_signalled(void)
{
	return (int)stop_signal;
}

_Noreturn void
term_oom(void)
{
	term_end();
	fputs("hybounce: out of memory\n", stderr);
	abort();
}

void *
term_xcalloc(size_t nmemb, size_t size)
{
	void *p = calloc(nmemb ? nmemb : 1, size ? size : 1);

	if (p == NULL)
		term_oom();
	return p;
}
