/*
 * pane_status.c - the status line, the message (or prompt) line, the
 * footer, the help overlay and the "terminal too small" screen.
 * Drawing only: reads the state, never changes it.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "keys.h"
#include "layout.h"
#include "term.h"
#include "tui.h"
#include "units.h"

/*
 * Writes UTF-8 text at (y, x), at most maxw columns (one column per
 * character: our texts are ASCII plus Braille, which is one column wide).
 */
void
tui_puts(int y, int x, int maxw, const char *s, int attr)
{
	int cols = 0;
	const unsigned char *p = (const unsigned char *)s, *start = p;

	if (y < 0 || y >= LINES || x >= COLS || maxw <= 0)
		return;
	if (x + maxw > COLS)
		maxw = COLS - x;
	while (*p && cols < maxw) {
		p++;
		while ((*p & 0xC0) == 0x80)
			p++;
		cols++;
	}
	attron(attr);
	mvaddnstr(y, x, (const char *)start, (int)(p - start));
	attroff(attr);
}

static const char *
state_name(const struct app *a)
{
	switch (sim_end(a->sim)) {
	case SIM_RUNNING: return "computing";
	case SIM_END_FAIL: return "failed";
	default: return "finished";
	}
}

void
pane_status_draw(const struct app *a)
{
	const struct arc *arc = sim_arc(a->sim);
	const struct arc_sample *s = arc_len(arc) ? arc_at(arc, a->cursor) : NULL;
	char line[512], tb[32], sp[32], foot[512];
	int attr = a->colour ? COLOR_PAIR(PAIR_STATUS) : A_REVERSE;
	const struct rect *r = &a->L.status;

	if (s != NULL)
		units_format(s->t, UNIT_TIME, 5, tb, sizeof tb);
	else
		snprintf(tb, sizeof tb, "-");
	units_format(a->speed, UNIT_NONE, 2, sp, sizeof sp);
	{
		char tail[256];
		int room;
		snprintf(tail, sizeof tail, " %s t=%s j=%ld q_c=%d coll %zu x%s%s %s %s",
		         sim_scene(a->sim)->law->name, tb, s ? s->j : 0L, s ? s->q : 0,
		         sim_ncollisions(a->sim), sp, a->in_slow ? " slow" : "",
		         a->playing ? "playing" : "paused", state_name(a));
		room = r->w - (int)strlen(tail) - 1;
		if (room < 8)
			room = 8;
		snprintf(line, sizeof line, " %.*s%s", room, a->preset, tail);
	}
	attron(attr);
	mvhline(r->y, 0, ' ', r->w);
	attroff(attr);
	tui_puts(r->y, 0, r->w, line, attr);

	/* message or prompt */
	r = &a->L.msg;
	if (a->overlay == OV_PROMPT) {
		snprintf(line, sizeof line, "%s: %s_", a->prompt_title, a->prompt_buf);
		tui_puts(r->y, 0, r->w, line, A_BOLD);
	} else {
		int mattr = a->msg_error ? (a->colour ? COLOR_PAIR(PAIR_ERROR) | A_BOLD : A_BOLD) : 0;
		tui_puts(r->y, 0, r->w, a->msg, mattr);
	}

	r = &a->L.footer;
	keys_footer(foot, sizeof foot, r->w - 1);
	tui_puts(r->y, 0, r->w, foot, A_DIM);
}

void
pane_help_draw(const struct app *a)
{
	size_t n, i;
	const struct key_binding *t = keys_table(&n);
	int w = a->L.cols - 4 < 96 ? a->L.cols - 4 : 96;
	int h = a->L.lines - 2, x0 = (a->L.cols - w) / 2, y0 = 1, row;
	int top = a->help_top;
	char line[256];

	if (top > (int)n - (h - 3))
		top = (int)n - (h - 3);
	if (top < 0)
		top = 0;
	for (row = 0; row < h; row++)
		mvhline(y0 + row, x0, ' ', w);
	attron(A_BOLD);
	mvhline(y0, x0, '-', w);
	mvhline(y0 + h - 1, x0, '-', w);
	attroff(A_BOLD);
	tui_puts(y0, x0 + 2, w - 4, " hybounce keys (Up/Down scroll, any other key closes) ", A_BOLD);
	for (i = (size_t)top, row = 1; i < n && row < h - 1; i++, row++) {
		snprintf(line, sizeof line, " %-9s %s", t[i].label, t[i].help);
		tui_puts(y0 + row, x0, w, line, 0);
	}
}

void
pane_too_small_draw(const struct app *a)
{
	char line[128];
	int y = a->L.lines / 2;

	snprintf(line, sizeof line, "terminal too small: need at least %dx%d", LAYOUT_MIN_COLS,
	         LAYOUT_MIN_LINES);
	tui_puts(y > 0 ? y - 1 : 0, 0, a->L.cols, line, A_BOLD);
	snprintf(line, sizeof line, "(now %dx%d; q quits)", a->L.cols, a->L.lines);
	tui_puts(y, 0, a->L.cols, line, 0);
}
