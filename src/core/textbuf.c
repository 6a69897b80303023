/* SPDX-License-Identifier: GPL-3.0-or-later */
/* textbuf.c - appending formatted text to a caller's buffer (see textbuf.h). */
#include <stdarg.h>
#include <stdio.h>

#include "textbuf.h"
#include "cnum.h"

void
textbuf_printf(struct textbuf *t, const char *fmt, ...)
{
	va_list ap;
	size_t room = t->len < t->n ? t->n - t->len : 0;
	int k;

	va_start(ap, fmt);
	k = cnum_vsnprintf(room ? t->buf + t->len : NULL, room, fmt, ap);
	va_end(ap);
	if (k > 0)
		t->len += (size_t)k;
}
