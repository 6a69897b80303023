/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * textbuf.h - appending formatted text to a caller's buffer, snprintf
 * style: the text is cut to the buffer (always terminated when n > 0) and
 * len counts the whole length, so a first pass with buf = NULL measures
 * (not a public header: the preset writer, the reference texts and the
 * explorer's generated key lists use it).
 */
#ifndef HYBOUNCE_TEXTBUF_H
#define HYBOUNCE_TEXTBUF_H

#include <stddef.h>

struct textbuf {
	char *buf;  /* may be NULL when n is 0 */
	size_t n;   /* size of buf */
	size_t len; /* length of the whole text so far */
};

/* Appends printf-formatted text. */
void
textbuf_printf(struct textbuf *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif
