/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * textov.c - a text overlay: a box over the plots and the bottom pane
 * (the full width but 2, at most 100 columns) whose lines scroll, with
 * "more above (Up)" / "more below (Down)" on its bottom border.  The help
 * (mode_help.c) and the log (mode_log.c) are two.
 */
#include <curses.h>
#include <stdio.h>
#include <string.h>

#include "tui.h"

static struct rect
rect_of(const struct app *a)
{
	struct rect r = { 1, 0, a->L.lines - 4, a->L.cols };

	if (r.w > 100) {
		r.x = (a->L.cols - 100) / 2;
		r.w = 100;
	}
	return r;
}

int
textov_width(const struct app *a)
{
	return rect_of(a).w - 4;
}

int
textov_page(const struct app *a)
{
	return rect_of(a).h - 2;
}

static int
clamp_top(int top, int total, int rows)
{
	if (top > total - rows)
		top = total - rows;
	return top < 0 ? 0 : top;
}

struct wctx {
	int y0, x0, w, top, rows, row;
};

static void
put_line(void *p, int k, const char *line)
{
	struct wctx *c = p;

	(void)k;
	if (c->row >= c->top && c->row < c->top + c->rows)
		tui_puts(c->y0 + c->row - c->top, c->x0, c->w, line, 0);
	c->row++;
}

/* On the box's bottom border: what lies above and below the rows shown. */
static void
scroll_marks(const struct rect *r, int top, int total, int rows)
{
	char m[64];

	if (top <= 0 && top + rows >= total)
		return;
	snprintf(m, sizeof m, " %s%s%s ", top > 0 ? "more above (Up)" : "",
	         top > 0 && top + rows < total ? ", " : "",
	         top + rows < total ? "more below (Down)" : "");
	tui_puts(r->y + r->h - 1, r->x + r->w - 2 - (int)strlen(m), (int)strlen(m), m, A_BOLD);
}

void
textov_draw(const struct app *a, const char *title, textov_lines *lines, int top)
{
	struct rect r = rect_of(a);
	struct rect in = box_draw(r.y, r.x, r.h, r.w, title);
	struct wctx c = { in.y, in.x, in.w, 0, in.h, 0 };
	int total = lines(a, textov_width(a), NULL, NULL);

	/* top < 0: the end (the newest messages of the log) */
	c.top = clamp_top(top < 0 ? total : top, total, in.h);
	lines(a, textov_width(a), put_line, &c);
	scroll_marks(&r, c.top, total, in.h);
}

void
textov_scroll(struct app *a, textov_lines *lines, int *top, int d)
{
	int rows = textov_page(a), total = lines(a, textov_width(a), NULL, NULL);

	if (*top < 0)
		*top = clamp_top(total, total, rows);
	*top = clamp_top(*top + d, total, rows);
}

void
textov_wheel(struct app *a, textov_lines *lines, int *top)
{
	MEVENT ev;

	if (getmouse(&ev) == OK && (ev.bstate & (BUTTON4_PRESSED | BUTTON5_PRESSED)))
		textov_scroll(a, lines, top, ev.bstate & BUTTON4_PRESSED ? -3 : 3);
}
