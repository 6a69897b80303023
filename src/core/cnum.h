/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * cnum.h - numbers and keys read and written the same way whatever the
 * locale (not a public header).
 *
 * Every number the engine reads (presets, --set values, units, CSV data,
 * sweep ranges) or writes (presets, CSV, sweep files, messages) goes
 * through these functions, which work in the C numeric locale (a dot as
 * the decimal separator, no grouping) whatever the process's locale
 * (setlocale) or the calling thread's (uselocale) is: a host program or a
 * front end that sets LC_NUMERIC=de_DE.UTF-8 gets the same bytes as
 * under LANG=C.  The switch is per thread (uselocale) and undone before
 * each function returns, so nothing process-wide changes and threads may
 * call these at once.
 *
 * Keys, unit names and choices are compared with an ASCII case fold:
 * strcasecmp follows LC_CTYPE, under which 'I' and 'i' are not the same
 * letter in a Turkish locale.
 */
#ifndef HYBOUNCE_CNUM_H
#define HYBOUNCE_CNUM_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

/* strtod in the C locale. */
double
cnum_strtod(const char *s, char **end);

/* snprintf, vsnprintf, fprintf and vfprintf in the C numeric locale. */
int
cnum_snprintf(char *buf, size_t n, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
int
cnum_vsnprintf(char *buf, size_t n, const char *fmt, va_list ap)
    __attribute__((format(printf, 3, 0)));
int
cnum_fprintf(FILE *f, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
int
cnum_vfprintf(FILE *f, const char *fmt, va_list ap) __attribute__((format(printf, 2, 0)));

/*
 * v as snprintf(buf, n, "%.17g", v) writes it in the C locale, the same
 * bytes, at a tenth of the cost (cnum_g17.c): buf holds at least
 * CNUM_G17_MAX bytes.  Returns the length written before the '\0'.
 */
enum { CNUM_G17_MAX = 32 };
size_t
cnum_g17(char *buf, double v);

/* v in decimal as "%ld" writes it (buf: at least 21 bytes); the length. */
size_t
cnum_long(char *buf, long v);

/* ASCII-only character classes and case fold (no locale). */
static inline int
cnum_isspace(int c)
{
	return c == ' ' || (c >= '\t' && c <= '\r');
}

static inline int
cnum_isdigit(int c)
{
	return c >= '0' && c <= '9';
}

static inline int
cnum_isalpha(int c)
{
	return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

static inline int
cnum_tolower(int c)
{
	return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c;
}

/* strcasecmp and strncasecmp folding ASCII letters only. */
int
cnum_casecmp(const char *a, const char *b);
int
cnum_ncasecmp(const char *a, const char *b, size_t n);

#endif
