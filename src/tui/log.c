/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * log.c - messages: the message line, the memory of every message (the
 * log, shown by mode_log.c), and a script's caption.
 *
 * The message line shows the latest message; one too long for it ends in
 * "... (m: whole message)" and the log shows it wrapped to the screen.
 */
#include <curses.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
