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
 *     dump FILE        writes the current screen to FILE
 *     size COLSxLINES  resizes the screen (as a terminal resize would;
 *                      ignored on a real terminal)
 *     caption TEXT     shows TEXT on the message line (for a presentation)
 * After each key one frame of work is done, as in the interactive loop.
 * The script ends at its last line, or at a `q` key; on a real terminal
 * any key pressed ends it too.  The man page (SCRIPTS) documents this.
 */
#include <curses.h>
#include <errno.h>
#include <limits.h>
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

static int live;   /* playing on the real screen */

/* On the real screen: draws a frame; a key pressed by the viewer ends the script. */
static void
frame(struct app *a)
{
	if (!live)
		return;
	app_draw(a);
	if (getch() != ERR)
		a->quit = 1;
}

/*
 * Work for up to ms milliseconds of wall time, or until idle; on the real
 * screen the whole time, drawing every frame.
 */
static void
wait_ms(struct app *a, double ms)
{
	double t0 = clock_seconds(CLOCK_MONOTONIC);

	while (!term_signalled() && !a->quit && (clock_seconds(CLOCK_MONOTONIC) - t0) * 1e3 < ms) {
		int computing = hb_sim_end(a->sim) == HB_SIM_RUNNING;
		if (!app_tick(a) && !live)
			break;
		frame(a);
		if (!computing)
			nap();
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
	FILE *f = fopen(path, "r");
	char line[1024];
	int lineno = 0, status = 0;
	struct stat st;

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
	live = isatty(STDIN_FILENO) && isatty(STDOUT_FILENO);
	if (live ? term_begin(msg, n) != 0 : term_begin_script(80, 24, msg, n) != 0) {
		fclose(f);
		return 1;
	}
	a->braille = term_utf8() && !a->opt->ascii;
	a->colour = live ? term_colour() : 0;
	if (live)
		timeout(0);
	app_relayout(a);
	app_tick(a);
	frame(a);
	while (!a->quit && !term_signalled() && fgets(line, sizeof line, f) != NULL) {
		size_t l = strlen(line);
		int key, cols, lines;
		lineno++;
		while (l > 0 && (line[l - 1] == '\n' || line[l - 1] == '\r'))
			line[--l] = 0;
		if (l == 0 || line[0] == '#')
			continue;
		if (strncmp(line, "text:", 5) == 0) {
			for (const char *p = line + 5; *p; p++)
				app_key(a, (unsigned char)*p);
			app_tick(a);
			frame(a);
		} else if (strncmp(line, "caption", 7) == 0 && (line[7] == ' ' || line[7] == 0)) {
			app_msg(a, 0, "%s", line[7] ? line + 8 : "");
			frame(a);
		} else if (strncmp(line, "wait-finished", 13) == 0 && line[13] == 0) {
			double t0 = clock_seconds(CLOCK_MONOTONIC);
			while (!all_ended(a) && !term_signalled()) {
				if (clock_seconds(CLOCK_MONOTONIC) - t0 > 120) {
					snprintf(msg, n, "%s:%d: wait-finished: still computing after 120 s",
					         path, lineno);
					status = 1;
					break;
				}
				app_tick(a);
				frame(a);
			}
			if (status)
				break;
		} else if (strncmp(line, "wait ", 5) == 0) {
			char *end;
			double ms = strtod(line + 5, &end);
			if (end == line + 5 || ms < 0) {
				snprintf(msg, n, "%s:%d: wait: expected a number of milliseconds", path, lineno);
				status = 2;
				break;
			}
			wait_ms(a, ms);
		} else if (strncmp(line, "dump ", 5) == 0) {
			app_draw(a);
			char why[1024];

			if (script_dump(line + 5, why, sizeof why) != 0) {
				/* an output the script names that cannot be written: bad input */
				snprintf(msg, n, "%s:%d: dump %s", path, lineno, why);
				status = 2;
				break;
			}
		} else if (sscanf(line, "size %dx%d", &cols, &lines) == 2) {
			if (cols < 1 || lines < 1 || cols > 1000 || lines > 1000) {
				snprintf(msg, n, "%s:%d: size: expected COLSxLINES", path, lineno);
				status = 2;
				break;
			}
			if (!live) {
				resizeterm(lines, cols);
				app_key(a, KEY_RESIZE);
			}
		} else if ((key = keys_from_name(line)) >= 0) {
			app_key(a, key);
			app_tick(a);
			frame(a);
		} else {
			snprintf(msg, n, "%s:%d: unknown script line '%s' (a key name, text:, wait, "
			         "wait-finished, dump, size or caption)", path, lineno, line);
			status = 2;
			break;
		}
	}
	if (status == 0 && ferror(f)) {
		snprintf(msg, n, "%s:%d: %s", path, lineno + 1, strerror(errno));
		status = 2;
	}
	fclose(f);
	term_end();
	if (status == 0 && term_signalled())
		status = 128 + term_signalled();
	return status;
}
