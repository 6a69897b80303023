/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * prompt.c - the one-line prompt on the message line: a value to type, an
 * export name, a parameter to search for, and its mode (mode.h): its keys
 * are line editing; any other key is text (UTF-8 as it arrives).  It is
 * drawn on the message line (pane_status.c).
 * What it is for is its opener's: the prompt reports Enter, Esc and each
 * edit to the function given to prompt_open, and calls no mode by name.
 */
#include <curses.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "mode.h"
#include "tui.h"

void
prompt_open(struct app *a, int kind, prompt_fn *done, const char *text, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(a->prompt_title, sizeof a->prompt_title, fmt, ap);
	va_end(ap);
	if (!mode_on(a, &mode_prompt))
		mode_push(a, &mode_prompt);
	a->prompt_kind = kind;
	a->prompt_done = done;
	snprintf(a->prompt_buf, sizeof a->prompt_buf, "%s", text);
	a->prompt_pos = strlen(a->prompt_buf);
	a->prompt_fresh = a->prompt_buf[0] != 0;
}

/* The byte offset of the UTF-8 character before (dir < 0) or after offset i of s. */
static size_t
char_step(const char *s, size_t i, int dir)
{
	size_t l = strlen(s);

	if (dir < 0) {
		while (i > 0) {
			i--;
			if (((unsigned char)s[i] & 0xC0) != 0x80)
				break;
		}
		return i;
	}
	if (i < l)
		for (i++; i < l && ((unsigned char)s[i] & 0xC0) == 0x80; i++)
			;
	return i;
}

/* Removes bytes [from, to) of s. */
static void
cut(char *s, size_t from, size_t to)
{
	memmove(s + from, s + to, strlen(s + to) + 1);
}

#define CTRL(c) ((c) & 0x1f)

/*
 * Line editing, as a shell's: a pre-filled text is replaced by the first
 * printable key, or kept and edited once the caret moves (Left, Right,
 * Home, End, C-a, C-e) or a character is deleted.
 */
static void
edit_key(struct app *a, int ch)
{
	char *b = a->prompt_buf;
	size_t l = strlen(b), pos = a->prompt_pos > l ? l : a->prompt_pos;

	if (ch == KEY_LEFT || ch == CTRL('b'))
		pos = char_step(b, pos, -1);
	else if (ch == KEY_RIGHT || ch == CTRL('f'))
		pos = char_step(b, pos, 1);
	else if (ch == KEY_HOME || ch == CTRL('a'))
		pos = 0;
	else if (ch == KEY_END || ch == CTRL('e'))
		pos = l;
	else if (ch == KEY_BACKSPACE || ch == 127 || ch == 8) {
		size_t from = char_step(b, pos, -1);
		cut(b, from, pos);
		pos = from;
	} else if (ch == KEY_DC || ch == CTRL('d')) {
		cut(b, pos, char_step(b, pos, 1));
	} else if (ch == CTRL('u')) {
		b[0] = 0;
		pos = 0;
	} else if (ch == CTRL('k')) {
		b[pos] = 0;
	} else if (ch >= 32 && ch < 256 && ch != 127) {
		/* bytes >= 0x80 are parts of a UTF-8 character, kept as they come */
		if (a->prompt_fresh) {
			b[0] = 0;
			pos = l = 0;
		}
		if (l + 1 < sizeof a->prompt_buf) {
			memmove(b + pos + 1, b + pos, l - pos + 1);
			b[pos++] = (char)ch;
		}
	} else {
		return; /* not an editing key: the text stays as it is */
	}
	a->prompt_fresh = 0;
	a->prompt_pos = pos;
}

/* After an edit: the opener sees the text as it is now. */
static void
typed(struct app *a)
{
	if (mode_top(a) == &mode_prompt && a->prompt_done != NULL)
		a->prompt_done(a, a->prompt_buf, PROMPT_TYPED);
}

static void
prompt_type(struct app *a, int ch)
{
	edit_key(a, ch);
	typed(a);
}

static void prompt_left(struct app *a) { prompt_type(a, KEY_LEFT); }
static void prompt_right(struct app *a) { prompt_type(a, KEY_RIGHT); }
static void prompt_home(struct app *a) { prompt_type(a, KEY_HOME); }
static void prompt_end(struct app *a) { prompt_type(a, KEY_END); }
static void prompt_bspace(struct app *a) { prompt_type(a, KEY_BACKSPACE); }
static void prompt_delete(struct app *a) { prompt_type(a, KEY_DC); }
static void prompt_kill(struct app *a) { prompt_type(a, CTRL('k')); }
static void prompt_clear(struct app *a) { prompt_type(a, CTRL('u')); }

static void
prompt_cancel(struct app *a)
{
	prompt_fn *done = a->prompt_done;

	mode_close(a, &mode_prompt);
	app_msg(a, 0, "cancelled");
	if (done != NULL)
		done(a, "", PROMPT_CANCEL);
}

static void
prompt_enter(struct app *a)
{
	prompt_fn *done = a->prompt_done;
	char buf[256];

	snprintf(buf, sizeof buf, "%s", a->prompt_buf);
	mode_close(a, &mode_prompt);
	if (done != NULL)
		done(a, buf, PROMPT_ENTER);
}

static const struct mode_key keys[] = {
	{ '\n', KEY_ENTER, CTX_ANY, prompt_enter, "Enter", "accept the text", NULL },
	{ 27, 0, CTX_ANY, prompt_cancel, "Esc", "cancel", NULL },
	{ KEY_LEFT, CTRL('b'), CTX_ANY, prompt_left, "Left C-b", "the caret a character left (keeps the value shown to edit it)", NULL },
	{ KEY_RIGHT, CTRL('f'), CTX_ANY, prompt_right, "Right C-f", "the caret a character right", NULL },
	{ KEY_HOME, CTRL('a'), CTX_ANY, prompt_home, "Home C-a", "the caret to the start", NULL },
	{ KEY_END, CTRL('e'), CTX_ANY, prompt_end, "End C-e", "the caret to the end", NULL },
	{ KEY_BACKSPACE, 127, CTX_ANY, prompt_bspace, "BSpace", "delete the character before the caret", NULL },
	{ KEY_DC, CTRL('d'), CTX_ANY, prompt_delete, "Delete C-d", "delete the character under the caret", NULL },
	{ CTRL('k'), 0, CTX_ANY, prompt_kill, "C-k", "delete to the end", NULL },
	{ CTRL('u'), 0, CTX_ANY, prompt_clear, "C-u", "clear the field", NULL },
};

static void
prompt_other(struct app *a, int ch)
{
	prompt_type(a, ch);
}

const struct mode mode_prompt = {
	.name = "prompt",
	.title = "a prompt",
	.opener = "Enter / e D F S",
	.keys = MODE_KEYS(keys),
	.other_help = "typed into the field; the value shown is replaced by the first key typed, unless a key above came first",
	.other = prompt_other,
};
