/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * prompt.c - the one-line prompt on the message line: a value to type, an
 * export name, a parameter to search for.  Keys typed into it are text
 * (UTF-8 as it arrives) and line editing, not bindings.  What it is for
 * is its opener's: the prompt reports Enter, Esc and each edit to the
 * function given to prompt_open, and calls no mode by name.
 */
#include <curses.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "tui.h"

void
prompt_open(struct app *a, int kind, prompt_fn *done, const char *text, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(a->prompt_title, sizeof a->prompt_title, fmt, ap);
	va_end(ap);
	a->overlay = OV_PROMPT;
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

void
prompt_key(struct app *a, int ch)
{
	prompt_fn *done = a->prompt_done;

	if (ch == 27) {
		a->overlay = OV_NONE;
		app_msg(a, 0, "cancelled");
		if (done != NULL)
			done(a, "", PROMPT_CANCEL);
	} else if (ch == '\n' || ch == '\r' || ch == KEY_ENTER) {
		char buf[256];
		snprintf(buf, sizeof buf, "%s", a->prompt_buf);
		a->overlay = OV_NONE;
		if (done != NULL)
			done(a, buf, PROMPT_ENTER);
	} else {
		edit_key(a, ch);
		if (a->overlay == OV_PROMPT && done != NULL)
			done(a, a->prompt_buf, PROMPT_TYPED);
	}
}
