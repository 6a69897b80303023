/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * prompt.c - the one-line prompt on the message line: a value to type, an
 * export name, a parameter to search for.  Keys typed into it are text
 * (UTF-8 as it arrives), not bindings.
 */
#include <curses.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "tui.h"

void
prompt_open(struct app *a, int kind, const char *text, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(a->prompt_title, sizeof a->prompt_title, fmt, ap);
	va_end(ap);
	a->overlay = OV_PROMPT;
	a->prompt_kind = kind;
	snprintf(a->prompt_buf, sizeof a->prompt_buf, "%s", text);
}

/* Removes the last UTF-8 character of s. */
static void
drop_char(char *s)
{
	size_t l = strlen(s);

	while (l > 0) {
		l--;
		if (((unsigned char)s[l] & 0xC0) != 0x80)
			break;
	}
	s[l] = 0;
}

void
prompt_key(struct app *a, int ch)
{
	size_t l = strlen(a->prompt_buf);

	if (ch == 27) {
		a->overlay = OV_NONE;
		if (a->prompt_kind == PROMPT_EDIT)
			a->branch_armed = 0;
		app_msg(a, 0, "cancelled");
		if (a->prompt_kind == PROMPT_SWEEP)
			sweep_prompt_done(a, "", 1);
	} else if (ch == '\n' || ch == '\r' || ch == KEY_ENTER) {
		char buf[256];
		snprintf(buf, sizeof buf, "%s", a->prompt_buf);
		a->overlay = OV_NONE;
		if (a->prompt_kind == PROMPT_EDIT)
			edit_value(a, a->prompt_key, buf);
		else if (a->prompt_kind == PROMPT_SEARCH)
			search_do(a, buf, 1);
		else if (a->prompt_kind == PROMPT_DATA || a->prompt_kind == PROMPT_FIT)
			fitov_prompt_done(a, buf);
		else if (a->prompt_kind == PROMPT_SWEEP)
			sweep_prompt_done(a, buf, 0);
		else
			export_do(a, buf);
	} else if (ch == KEY_BACKSPACE || ch == 127 || ch == 8) {
		drop_char(a->prompt_buf);
	} else if (ch == 21) { /* C-u */
		a->prompt_buf[0] = 0;
	} else if (ch >= 32 && ch < 256 && ch != 127 && l + 1 < sizeof a->prompt_buf) {
		/* bytes >= 0x80 are parts of a UTF-8 character, kept as they come */
		a->prompt_buf[l] = (char)ch;
		a->prompt_buf[l + 1] = 0;
	}
	if (a->overlay == OV_PROMPT && a->prompt_kind == PROMPT_SEARCH)
		search_do(a, a->prompt_buf, 0);
}
