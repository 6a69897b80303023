/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * script.c - scripted mode (--script FILE): plays keys from a file, on the
 * real screen when standard input and output are a terminal (a
 * presentation: waits take real time and every frame is drawn, captions
 * appear on the message line), otherwise without a terminal, dumping the
 * screen as text.
 *
 * What was chosen: the real curses code path, on a curses screen created
 * with newterm() whose output and input are /dev/null (term.c,
 * term_begin_script), 80x24 unless the script says `size`.  Every pane is
 * drawn exactly as in the interactive explorer; `dump` reads the cells
 * back from stdscr (mvwin_wch) and writes them as UTF-8 text, one line per
 * screen row, trailing blanks removed.  Keys do not go through getch():
 * each is handed to the same dispatcher (app_key) the interactive loop
 * uses.  So a script needs a terminal description (TERM, else xterm or
 * vt100 from the terminfo database) but no terminal.
 *
 * Script lines (blank lines and lines starting with '#' are skipped):
 *     KEY              a key name (see keys_from_name: space, Enter, Tab,
 *                      Esc, Left, Right, Up, Down, Home, End, PgUp, PgDn,
 *                      BSpace, C-x) or one literal character
 *     text:STRING      types STRING (e.g. into a prompt)
 *     wait MS          computes and plays for MS ms of wall time, or until idle
 *     wait-finished    computes until every run has ended (at most 120 s)
 *     wait-key         on the real screen, waits for the viewer's key
 *     dump FILE        writes the current screen to FILE
 *     size COLSxLINES  resizes the screen (as a terminal resize would;
 *                      ignored on a real terminal)
 *     caption TEXT     shows TEXT on the message line, wrapped above it
 *     caption-large TEXT  shows TEXT in a box over the plots
 * The whole file is read and checked first (script_load): every bad line
 * is reported with its number and nothing runs (exit 2).  After each key
 * one frame of work is done, as in the interactive loop.  On the real
 * screen a key pressed by the viewer pauses the demo and another resumes
 * it, q quits, and the end waits: the explorer is the viewer's until q
 * (the viewer's keys are the demo mode's table, mode_demo.c).
 * Without a terminal the script ends at its last line, or at a `q` key.
 * The man page (SCRIPTS) documents this.
 */
#include <curses.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include <wchar.h>

#include "hybounce/atomic.h"
#include "hybounce/outputs.h"
#include "hybounce/status.h"

#include "clock.h"
#include "keys.h"
#include "term.h"
#include "tui.h"

static void
nap(void)
{
	struct timespec ts = { 0, 5000000 };

	nanosleep(&ts, NULL);
}

/* Writes the dump through the atomic writer; -1 with "PATH: reason; accepted: ..." */
static int
write_dump(const char *path, const char *text, size_t len, char *msg, size_t n)
{
	struct hb_atomic_target t;

	if (hb_outputs_probe(path, &t, msg, n) != HB_OK)
		return -1;
	if (hb_atomic_write_file(path, text, len, msg, n) != HB_OK)
		return -1;
	return 0;
}

int
script_dump(const char *path, char *msg, size_t n)
{
	char row[4096], mb[MB_LEN_MAX + 1], *text = NULL;
	size_t tlen = 0;
	mbstate_t st;
	FILE *f = open_memstream(&text, &tlen);
	int rc;

	if (f == NULL) {
		snprintf(msg, n, "%s: out of memory", path);
		return -1;
	}
	for (int y = 0; y < LINES; y++) {
		size_t len = 0, keep = 0;
		for (int x = 0; x < COLS; x++) {
			cchar_t cc;
			wchar_t wch[CCHARW_MAX + 1];
			attr_t at;
			short pair;
			size_t l;
			if (mvwin_wch(stdscr, y, x, &cc) == ERR
			    || getcchar(&cc, wch, &at, &pair, NULL) == ERR || wch[0] == 0)
				wch[0] = L' ';
			memset(&st, 0, sizeof st);
			l = wcrtomb(mb, wch[0], &st);
			if (l == (size_t)-1) {
				mb[0] = '?';
				l = 1;
			}
			if (len + l >= sizeof row)
				break;
			memcpy(row + len, mb, l);
			len += l;
			if (wch[0] != L' ')
				keep = len;
		}
		row[keep] = 0;
		fprintf(f, "%s\n", row);
	}
	if (fclose(f) != 0 || text == NULL) {
		free(text);
		snprintf(msg, n, "%s: out of memory", path);
		return -1;
	}
	/* the output policy (outputs.h): written atomically, what is accepted said */
	rc = write_dump(path, text, tlen, msg, n);
	free(text);
	return rc;
}

/* ---- the script as commands, checked before anything runs ------------------------ */

enum cmd_kind { CMD_KEY, CMD_TEXT, CMD_WAIT, CMD_WAIT_FINISHED, CMD_WAIT_KEY, CMD_DUMP, CMD_SIZE,
                CMD_CAPTION, CMD_CAPTION_LARGE };

struct cmd {
	enum cmd_kind kind;
	int line;           /* its line number in the file */
	int key;            /* CMD_KEY */
	double ms;          /* CMD_WAIT */
	int cols, lines;    /* CMD_SIZE */
	char *arg;          /* CMD_TEXT, CMD_DUMP, CMD_CAPTION*: the rest of the line */
};

struct script {
	struct cmd *c;
	size_t n, cap;
};

static void
script_free(struct script *sc)
{
	for (size_t i = 0; i < sc->n; i++)
		free(sc->c[i].arg);
	free(sc->c);
	sc->c = NULL;
	sc->n = sc->cap = 0;
}

/* "WORD" alone or "WORD ARG": the argument (may be ""), or NULL when line is not WORD */
static const char *
word_arg(const char *line, const char *word)
{
	size_t l = strlen(word);

	if (strncmp(line, word, l) != 0)
		return NULL;
	if (line[l] == 0)
		return line + l;
	return line[l] == ' ' ? line + l + 1 : NULL;
}

/*
 * One line into a command; 0, or -1 with the reason in why (without the
 * FILE:LINE prefix).
 */
static int
parse_line(const char *line, struct cmd *c, char *why, size_t n)
{
	const char *arg;
	char *end;
	int key;

	memset(c, 0, sizeof *c);
	if (strncmp(line, "text:", 5) == 0) {
		c->kind = CMD_TEXT;
		arg = line + 5;
	} else if ((arg = word_arg(line, "caption-large")) != NULL) {
		c->kind = CMD_CAPTION_LARGE;
	} else if ((arg = word_arg(line, "caption")) != NULL) {
		c->kind = CMD_CAPTION;
	} else if (strcmp(line, "wait-finished") == 0) {
		c->kind = CMD_WAIT_FINISHED;
		arg = NULL;
	} else if (strcmp(line, "wait-key") == 0) {
		c->kind = CMD_WAIT_KEY;
		arg = NULL;
	} else if ((arg = word_arg(line, "wait")) != NULL) {
		c->kind = CMD_WAIT;
		errno = 0;
		c->ms = strtod(arg, &end);
		if (end == arg || *end != 0 || !(c->ms >= 0) || !isfinite(c->ms) || errno == ERANGE) {
			snprintf(why, n, "wait: expected a number of milliseconds, got '%s'", arg);
			return -1;
		}
		arg = NULL;
	} else if ((arg = word_arg(line, "dump")) != NULL) {
		c->kind = CMD_DUMP;
		if (*arg == 0) {
			snprintf(why, n, "dump: expected a file name");
			return -1;
		}
	} else if ((arg = word_arg(line, "size")) != NULL) {
		char extra;
		c->kind = CMD_SIZE;
		if (sscanf(arg, "%dx%d%c", &c->cols, &c->lines, &extra) != 2 || c->cols < 1 || c->lines < 1
		    || c->cols > 1000 || c->lines > 1000) {
			snprintf(why, n, "size: expected COLSxLINES (1 to 1000 each), got '%s'", arg);
			return -1;
		}
		arg = NULL;
	} else if ((key = keys_from_name(line)) >= 0) {
		c->kind = CMD_KEY;
		c->key = key;
		arg = NULL;
	} else {
		snprintf(why, n, "unknown script line '%s' (a key name, text:, wait, wait-finished, "
		         "wait-key, dump, size, caption or caption-large)", line);
		return -1;
	}
	if (arg != NULL && (c->arg = strdup(arg)) == NULL) {
		snprintf(why, n, "out of memory");
		return -1;
	}
	return 0;
}

/*
 * Reads and checks the whole script: every error with its line number in
 * msg, and 2 (nothing has run yet); 0 with the commands in sc.
 */
static int
script_load(const char *path, struct script *sc, char *msg, size_t n)
{
	FILE *f = fopen(path, "r");
	char line[1024], why[1200], errs[3072];
	int lineno = 0, errors = 0;
	size_t used = 0;
	struct stat st;

	memset(sc, 0, sizeof *sc);
	if (f == NULL) {
		snprintf(msg, n, "%s: %s", path, strerror(errno));
		return 2;
	}
	/* fopen() opens a directory; reading it would end the script at once, exit 0 */
	if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
		snprintf(msg, n, "--script %s: is a directory; expected a file of script lines "
		         "(see SCRIPTS in the man page)", path);
		fclose(f);
		return 2;
	}
	while (fgets(line, sizeof line, f) != NULL) {
		size_t l = strlen(line);
		struct cmd c;
		lineno++;
		if (l == sizeof line - 1 && line[l - 1] != '\n') {
			int ch;
			while ((ch = fgetc(f)) != EOF && ch != '\n')
				;
			snprintf(why, sizeof why, "line longer than %zu characters", sizeof line - 2);
			goto bad;
		}
		while (l > 0 && (line[l - 1] == '\n' || line[l - 1] == '\r'))
			line[--l] = 0;
		if (l == 0 || line[0] == '#')
			continue;
		if (parse_line(line, &c, why, sizeof why) != 0)
			goto bad;
		if (sc->n == sc->cap) {
			size_t cap = sc->cap ? 2 * sc->cap : 64;
			struct cmd *m = realloc(sc->c, cap * sizeof *m);
			if (m == NULL) {
				free(c.arg);
				snprintf(why, sizeof why, "out of memory");
				goto bad;
			}
			sc->c = m;
			sc->cap = cap;
		}
		c.line = lineno;
		sc->c[sc->n++] = c;
		continue;
bad:
		/* every error, one a line, as many as the buffer holds */
		if (used < sizeof errs) {
			int w = snprintf(errs + used, sizeof errs - used, "\n%s:%d: %s", path, lineno, why);
			used += w > 0 ? (size_t)w : 0;
		}
		errors++;
	}
	if (ferror(f)) {
		if (used < sizeof errs)
			snprintf(errs + used, sizeof errs - used, "\n%s:%d: %s", path, lineno + 1,
			         strerror(errno));
		errors++;
	}
	fclose(f);
	if (errors > 0) {
		snprintf(msg, n, "--script %s: %d error%s, nothing played:%s", path, errors,
		         errors == 1 ? "" : "s", errs);
		script_free(sc);
		return 2;
	}
	return 0;
}

/* ---- playing ------------------------------------------------------------------- */

/*
 * Draws and ticks the explorer until the viewer presses a key (a resize is
 * handled and waited past), which goes to demo_viewer_key.
 */
static void
await_viewer_key(struct app *a)
{
	int ch;

	while (!term_signalled() && !a->quit) {
		app_draw(a);
		if ((ch = getch()) != ERR && ch != KEY_MOUSE) {
			if (ch == KEY_RESIZE) {
				app_key(a, ch);
				continue;
			}
			demo_viewer_key(a, ch);
			break;
		}
		if (!app_tick(a))
			nap();
	}
}

/*
 * The viewer paused the demo: the cursor stops, the run keeps computing,
 * until a key resumes it (q quits).  Returns the seconds paused.
 */
static double
paused(struct app *a)
{
	double t0 = clock_seconds(CLOCK_MONOTONIC);
	int was = a->playing;

	a->playing = 0;
	a->demo_ctx = CTX_DEMO_PAUSED;
	await_viewer_key(a);
	a->playing = was;
	a->demo_ctx = CTX_DEMO_PLAY;
	return clock_seconds(CLOCK_MONOTONIC) - t0;
}

/*
 * On the real screen: draws a frame; a key pauses the demo, q quits it.
 * Returns the seconds the demo was paused.
 */
static double
frame(struct app *a)
{
	int ch;

	if (!a->script_live)
		return 0;
	app_draw(a);
	if ((ch = getch()) == ERR || ch == KEY_MOUSE)
		return 0;
	if (ch == KEY_RESIZE) {
		app_key(a, ch);
		return 0;
	}
	if (demo_viewer_key(a, ch))
		return 0;
	return paused(a);
}

/*
 * Work for up to ms milliseconds of wall time, or until idle; on the real
 * screen the whole time, drawing every frame (a pause does not count).
 */
static void
wait_ms(struct app *a, double ms)
{
	double t0 = clock_seconds(CLOCK_MONOTONIC);

	while (!term_signalled() && !a->quit && (clock_seconds(CLOCK_MONOTONIC) - t0) * 1e3 < ms) {
		int computing = hb_sim_end(a->sim) == HB_SIM_RUNNING;
		if (!app_tick(a) && !a->script_live)
			break;
		t0 += frame(a);
		if (!computing)
			nap();
	}
}

/* wait-key: on the real screen, until the viewer presses a key (q quits) */
static void
wait_key(struct app *a)
{
	if (!a->script_live)
		return;
	a->demo_ctx = CTX_DEMO_KEY;
	await_viewer_key(a);
	a->demo_ctx = CTX_DEMO_PLAY;
}

/* The end of a demo on the real screen: it waits; the explorer goes on until q. */
static void
the_end(struct app *a)
{
	int ch;

	a->demo_ctx = CTX_DEMO_END;
	timeout(40);
	while (!term_signalled() && !a->quit) {
		app_draw(a);
		if ((ch = getch()) != ERR) {
			if (ch != KEY_RESIZE && ch != KEY_MOUSE && a->demo_ctx != 0) {
				/* the viewer's first key: the footer's keys again, the last caption gone */
				a->demo_ctx = 0;
				a->caption[0] = 0;
			}
			app_key(a, ch);
		}
		app_tick(a);
	}
}

static int
all_ended(const struct app *a)
{
	if (hb_sim_end(a->sim) == HB_SIM_RUNNING)
		return 0;
	for (int i = 0; i < a->npins; i++)
		if (hb_sim_end(a->pin[i].sim) == HB_SIM_RUNNING)
			return 0;
	return 1;
}

int
script_run(struct app *a, const char *path, char *msg, size_t n)
{
	struct script sc;
	int status = 0;

	if (script_load(path, &sc, msg, n) != 0)
		return 2;
	a->script_live = isatty(STDIN_FILENO) && isatty(STDOUT_FILENO);
	if (a->script_live ? term_begin(msg, n) != 0 : term_begin_script(80, 24, msg, n) != 0) {
		script_free(&sc);
		return 1;
	}
	a->braille = term_utf8() && !a->opt->ascii;
	a->colour = a->script_live ? term_colour() : 0;
	if (a->script_live) {
		timeout(0);
		a->demo_ctx = CTX_DEMO_PLAY;
	}
	app_relayout(a);
	app_tick(a);
	frame(a);
	for (size_t k = 0; k < sc.n && !a->quit && !term_signalled(); k++) {
		const struct cmd *c = &sc.c[k];
		switch (c->kind) {
		case CMD_TEXT:
			for (const char *p = c->arg; *p; p++)
				app_key(a, (unsigned char)*p);
			app_tick(a);
			frame(a);
			break;
		case CMD_CAPTION:
		case CMD_CAPTION_LARGE:
			app_caption(a, c->arg, c->kind == CMD_CAPTION_LARGE);
			frame(a);
			break;
		case CMD_WAIT_FINISHED: {
			double t0 = clock_seconds(CLOCK_MONOTONIC);
			while (!all_ended(a) && !term_signalled() && !a->quit) {
				if (clock_seconds(CLOCK_MONOTONIC) - t0 > 120) {
					snprintf(msg, n, "%s:%d: wait-finished: still computing after 120 s",
					         path, c->line);
					status = 1;
					break;
				}
				app_tick(a);
				frame(a);
			}
			break;
		}
		case CMD_WAIT:
			wait_ms(a, c->ms);
			break;
		case CMD_WAIT_KEY:
			wait_key(a);
			break;
		case CMD_DUMP: {
			char why[1024];
			app_draw(a);
			if (script_dump(c->arg, why, sizeof why) != 0) {
				/* an output the script names that cannot be written: bad input */
				snprintf(msg, n, "%s:%d: dump %s", path, c->line, why);
				status = 2;
			}
			break;
		}
		case CMD_SIZE:
			if (!a->script_live) {
				resizeterm(c->lines, c->cols);
				app_key(a, KEY_RESIZE);
			}
			break;
		case CMD_KEY:
			app_key(a, c->key);
			app_tick(a);
			frame(a);
			break;
		}
		if (status != 0)
			break;
	}
	if (a->script_live && status == 0)
		the_end(a);
	script_free(&sc);
	term_end();
	if (status == 0 && term_signalled())
		status = 128 + term_signalled();
	return status;
}
