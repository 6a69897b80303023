/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * draw.c - the explorer's text drawing primitives: text clipped to its
 * room with a cut mark, a box, text wrapped at blanks.  They call only
 * curses and term.c, never a pane or a mode, so that every pane and mode
 * can use them without a cycle of calls (tests/cli/calls.sh).
 */
#include <curses.h>
#include <stdio.h>
#include <string.h>

#include "term.h"
#include "tui.h"

/* The mark at the end of a text cut to its room: an ellipsis, or > without UTF-8. */
const char *
tui_cut_mark(void)
{
	return term_utf8() ? "\xe2\x80\xa6" : ">";
}

/*
 * Writes UTF-8 text at (y, x), at most maxw columns (one column per
 * character: our texts are ASCII plus Braille, which is one column wide).
 * Text cut to fit (more than blanks left over) ends in the cut mark in
 * its last column: nothing is cut without a mark.
 */
void
tui_puts(int y, int x, int maxw, const char *s, int attr)
{
	int cols = 0;
	const unsigned char *p = (const unsigned char *)s, *start = p, *last = p, *rest;

	if (y < 0 || y >= LINES || x >= COLS || maxw <= 0)
		return;
	if (x + maxw > COLS)
		maxw = COLS - x;
	while (*p && cols < maxw) {
		last = p;
		p++;
		while ((*p & 0xC0) == 0x80)
			p++;
		cols++;
	}
	for (rest = p; *rest == ' '; rest++)
		;
	attron(attr);
	if (*rest != 0 && cols > 0) {
		/* cut: the last column shows the mark instead of its character */
		mvaddnstr(y, x, (const char *)start, (int)(last - start));
		mvaddstr(y, x + cols - 1, tui_cut_mark());
	} else {
		mvaddnstr(y, x, (const char *)start, (int)(p - start));
	}
	attroff(attr);
}

struct rect
box_draw(int y, int x, int h, int w, const char *title)
{
	struct rect in = { y + 1, x + 2, h - 2, w - 4 };

	for (int r = 0; r < h; r++)
		mvhline(y + r, x, ' ', w);
	attron(A_BOLD);
	mvhline(y, x + 1, ACS_HLINE, w - 2);
	mvhline(y + h - 1, x + 1, ACS_HLINE, w - 2);
	mvvline(y + 1, x, ACS_VLINE, h - 2);
	mvvline(y + 1, x + w - 1, ACS_VLINE, h - 2);
	mvaddch(y, x, ACS_ULCORNER);
	mvaddch(y, x + w - 1, ACS_URCORNER);
	mvaddch(y + h - 1, x, ACS_LLCORNER);
	mvaddch(y + h - 1, x + w - 1, ACS_LRCORNER);
	attroff(A_BOLD);
	tui_puts(y, x + 2, w - 4, title, A_BOLD);
	return in;
}

/*
 * Wraps s into lines of at most w columns at blanks (a word longer than w
 * is cut); calls out for each line with its text.  Returns the line count.
 * indent: columns of blank put before every line after the first.
 */
int
tui_wrap(const char *s, int w, int indent, void (*out)(void *, int, const char *), void *ctx)
{
	char line[1024];
	int n = 0, first = 1;

	if (w < 8)
		w = 8;
	while (*s) {
		int room = first ? w : w - indent, len = (int)strlen(s), cut = len;
		if (len > room) {
			cut = room;
			while (cut > room / 2 && s[cut] != ' ')
				cut--;
			if (s[cut] != ' ')
				cut = room;
		}
		snprintf(line, sizeof line, "%*s%.*s", first ? 0 : indent, "", cut, s);
		if (out)
			out(ctx, n, line);
		n++;
		s += cut;
		while (*s == ' ')
			s++;
		first = 0;
	}
	return n;
}

struct bctx {
	int y, x, w, maxrows;
	int attr;
	int total;
};

static void
put_bounded(void *p, int k, const char *line)
{
	struct bctx *c = p;
	char buf[1100];

	if (k < c->maxrows - 1 || (k == c->maxrows - 1 && c->total <= c->maxrows)) {
		tui_puts(c->y + k, c->x, c->w, line, c->attr);
	} else if (k == c->maxrows - 1) {
		/* the last row there is room for, with more to come: the mark says so */
		snprintf(buf, sizeof buf, "%s%*s", line, c->w, "");
		tui_puts(c->y + k, c->x, c->w, buf, c->attr);
		mvaddstr(c->y + k, c->x + c->w - 1, tui_cut_mark());
	}
}

int
tui_wrap_rows(const char *s, int w)
{
	return tui_wrap(s, w, 0, NULL, NULL);
}

int
tui_wrap_draw(int y, int x, int w, int maxrows, const char *s, int attr)
{
	struct bctx c = { y, x, w, maxrows, attr, 0 };

	if (maxrows < 1 || w < 1)
		return 0;
	c.total = tui_wrap(s, w, 0, NULL, NULL);
	tui_wrap(s, w, 0, put_bounded, &c);
	return c.total < maxrows ? c.total : maxrows;
}
