/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * log.c - messages: the message line, the log of every message (m), and
 * the scrolling of the two text overlays (help, log).
 *
 * The message line shows the latest message; one too long for it ends in
 * "... (m: whole message)" and the log shows it wrapped to the screen.
 */
#include <curses.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "keys.h"
#include "term.h"
#include "tui.h"

void
app_msg(struct app *a, int error, const char *fmt, ...)
{
	va_list ap;
	char *copy;
	int slot;

	va_start(ap, fmt);
	vsnprintf(a->msg, sizeof a->msg, fmt, ap);
	va_end(ap);
	a->msg_error = error;
	copy = malloc(strlen(a->msg) + 3);
	if (copy == NULL)
		term_oom();
	snprintf(copy, strlen(a->msg) + 3, "%c %s", error ? '!' : ' ', a->msg);
	slot = (a->log_head + a->log_n) % APP_LOG_MAX;
	if (a->log_n == APP_LOG_MAX) {
		free(a->log[a->log_head]);
		a->log_head = (a->log_head + 1) % APP_LOG_MAX;
		slot = (a->log_head + a->log_n - 1) % APP_LOG_MAX;
	} else {
		a->log_n++;
	}
	a->log[slot] = copy;
}

void
app_caption(struct app *a, const char *text, int large)
{
	snprintf(a->caption, sizeof a->caption, "%s", text);
	a->caption_large = large && text[0];
	if (text[0])
		app_msg(a, 0, "%s", text);   /* in the log too, and on the message line */
	else
		a->msg[0] = 0;
}

const char *
log_get(const struct app *a, int i)
{
	if (i < 0 || i >= a->log_n)
		return NULL;
	return a->log[(a->log_head + i) % APP_LOG_MAX];
}

void
log_free(struct app *a)
{
	for (int i = 0; i < a->log_n; i++)
		free(a->log[(a->log_head + i) % APP_LOG_MAX]);
	a->log_n = a->log_head = 0;
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

/* The overlay box: the plots' and bottom panes' rows, the full width but 2. */
static struct rect
overlay_rect(const struct app *a)
{
	struct rect r = { 1, 0, a->L.lines - 4, a->L.cols };

	if (r.w > 100) {
		r.x = (a->L.cols - 100) / 2;
		r.w = 100;
	}
	return r;
}

static int
help_lines(const struct app *a, struct wctx *c)
{
	size_t n;
	const struct key_binding *t = keys_table(&n);
	char line[512];
	int w = overlay_rect(a).w - 4;

	if (c)
		c->row = 0;
	int total = 0;
	for (size_t i = 0; i < n; i++) {
		snprintf(line, sizeof line, "%-9s %s", t[i].label, t[i].help);
		total += tui_wrap(line, w, 10, c ? put_line : NULL, c);
	}
	static const char *legend[] = {
		"",
		"Status line: the preset, law, t, j, q_c, the number of collisions, the playback speed (x0.02: simulated seconds per second), slow (in slow motion), playing/paused, and computing/finished/failed for the run; \"fails N checks\" when the ended run breaks the physics checks that --batch runs (m names each check and collision; the table marks an impossible value with \"!\").",
		"Readout: the sample at the cursor (#index), its t, j, q_c, x, v, x_c, F_c and z_c, with units.",
		"Contact strip under the plots: # a contact narrower than a column, [] a contact two columns wide, [===] a longer contact from t_e to t_s, ^ the cursor.",
		"Legend: each pinned run is labelled by what differs from the current one, in its own colour and marker.",
		"Edits restart the run from t = 0 and keep the cursor's t; b makes the next edit continue from the cursor (branch here).",
		"A line that ends in an ellipsis (> without UTF-8) goes on: a message is whole in the log (m); the table's columns past the screen's edge are in the status line (coll N), M (the data) and the log (the physics notes); a picker shows its selected entry whole under its list; Enter on a parameter shows its description whole; a long prompt has its title on the rows above it; every column is in the exported CSV.",
		"In a prompt: the value shown is replaced by the first key typed; Left/Right/Home/End (C-b C-f C-a C-e) keep it to edit; BSpace, C-d, C-k delete; C-u clears; Enter accepts, Esc cancels.",
	};
	for (size_t i = 0; i < sizeof legend / sizeof legend[0]; i++)
		total += tui_wrap(legend[i][0] ? legend[i] : " ", w, 2, c ? put_line : NULL, c);
	return total;
}

static int
log_lines(const struct app *a, struct wctx *c)
{
	int total = 0, w = overlay_rect(a).w - 4;

	if (c)
		c->row = 0;
	for (int i = 0; i < a->log_n; i++)
		total += tui_wrap(log_get(a, i), w, 2, c ? put_line : NULL, c);
	if (a->log_n == 0)
		total += tui_wrap("(no messages yet)", w, 0, c ? put_line : NULL, c);
	return total;
}

static int
clamp_top(int top, int total, int rows)
{
	if (top > total - rows)
		top = total - rows;
	return top < 0 ? 0 : top;
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
pane_help_draw(const struct app *a)
{
	struct rect r = overlay_rect(a);
	struct rect in = box_draw(r.y, r.x, r.h, r.w, " hybounce keys (Up/Down PgUp/PgDn scroll, any other key closes) ");
	struct wctx c = { in.y, in.x, in.w, 0, in.h, 0 };

	int total = help_lines(a, NULL);

	c.top = clamp_top(a->help_top, total, in.h);
	help_lines(a, &c);
	scroll_marks(&r, c.top, total, in.h);
}

void
pane_log_draw(const struct app *a)
{
	struct rect r = overlay_rect(a);
	struct rect in = box_draw(r.y, r.x, r.h, r.w, " messages, oldest first (Up/Down scroll, any other key closes) ");
	struct wctx c = { in.y, in.x, in.w, 0, in.h, 0 };
	int total = log_lines(a, NULL);

	/* log_top < 0: the end of the log (the newest messages) */
	c.top = clamp_top(a->log_top < 0 ? total : a->log_top, total, in.h);
	log_lines(a, &c);
	scroll_marks(&r, c.top, total, in.h);
}

void
overlay_key(struct app *a, int ch)
{
	struct rect r = overlay_rect(a);
	int rows = r.h - 2, total = a->overlay == OV_HELP ? help_lines(a, NULL) : log_lines(a, NULL);
	int *top = a->overlay == OV_HELP ? &a->help_top : &a->log_top;
	int d = 0;

	if (*top < 0)
		*top = clamp_top(total, total, rows);
	if (ch == KEY_DOWN || ch == 'j')
		d = 1;
	else if (ch == KEY_UP || ch == 'k')
		d = -1;
	else if (ch == KEY_NPAGE || ch == ' ')
		d = rows - 1;
	else if (ch == KEY_PPAGE)
		d = -(rows - 1);
	else if (ch == KEY_MOUSE) {
		MEVENT ev;
		if (getmouse(&ev) == OK && (ev.bstate & (BUTTON4_PRESSED | BUTTON5_PRESSED)))
			d = ev.bstate & BUTTON4_PRESSED ? -3 : 3;
		else
			return;
	} else if (ch == KEY_RESIZE) {
		return; /* app_key lays the screen out again before an overlay sees a key */
	} else {
		a->overlay = OV_NONE;
		return;
	}
	*top = clamp_top(*top + d, total, rows);
}

void
act_log(struct app *a)
{
	a->overlay = OV_LOG;
	a->log_top = -1;
}
