/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cnum.c - numbers in the C locale whatever the locale (see cnum.h). */
#include <locale.h>
#include <pthread.h>
#include <stdlib.h>

#include "cnum.h"

static locale_t cnum_locale;
static pthread_once_t cnum_once = PTHREAD_ONCE_INIT;

static void
cnum_locale_make(void)
{
	/* (locale_t)0 as the base: every category is C, LC_NUMERIC included. */
	cnum_locale = newlocale(LC_NUMERIC_MASK, "C", (locale_t)0);
}

/* Switches the calling thread to the C locale; returns the locale to give
 * back to cnum_leave, or (locale_t)0 when there is none to switch to (a
 * failed newlocale: then the thread's locale stays, which is C unless the
 * host changed it). */
static locale_t
cnum_enter(void)
{
	pthread_once(&cnum_once, cnum_locale_make);
	return cnum_locale != (locale_t)0 ? uselocale(cnum_locale) : (locale_t)0;
}

static void
cnum_leave(locale_t old)
{
	if (old != (locale_t)0)
		uselocale(old);
}

double
cnum_strtod(const char *s, char **end)
{
	locale_t old = cnum_enter();
	double v = strtod(s, end);

	cnum_leave(old);
	return v;
}

int
cnum_vsnprintf(char *buf, size_t n, const char *fmt, va_list ap)
{
	locale_t old = cnum_enter();
	int k = vsnprintf(buf, n, fmt, ap);

	cnum_leave(old);
	return k;
}

int
cnum_snprintf(char *buf, size_t n, const char *fmt, ...)
{
	va_list ap;
	int k;

	va_start(ap, fmt);
	k = cnum_vsnprintf(buf, n, fmt, ap);
	va_end(ap);
	return k;
}

int
cnum_vfprintf(FILE *f, const char *fmt, va_list ap)
{
	locale_t old = cnum_enter();
	int k = vfprintf(f, fmt, ap);

	cnum_leave(old);
	return k;
}

int
cnum_fprintf(FILE *f, const char *fmt, ...)
{
	va_list ap;
	int k;

	va_start(ap, fmt);
	k = cnum_vfprintf(f, fmt, ap);
	va_end(ap);
	return k;
}

int
cnum_ncasecmp(const char *a, const char *b, size_t n)
{
	for (; n > 0; a++, b++, n--) {
		int ca = cnum_tolower((unsigned char)*a), cb = cnum_tolower((unsigned char)*b);

		if (ca != cb)
			return ca - cb;
		if (ca == 0)
			break;
	}
	return 0;
}

int
cnum_casecmp(const char *a, const char *b)
{
	return cnum_ncasecmp(a, b, (size_t)-1);
}
