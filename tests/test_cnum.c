/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_cnum.c - cnum_g17 writes the bytes of snprintf("%.17g") in the C
 * locale, and they read back (cnum_strtod) to the same double: random bit
 * patterns, random values of every decade, subnormals, every power of two
 * and of ten with their neighbours, integers, ties (2^-25 has 18 digits
 * ending in 5), zeros and non-finite values; under a decimal-comma locale
 * too.  cnum_long writes what "%ld" writes.
 */
#define _GNU_SOURCE
#include <float.h>
#include <limits.h>
#include <locale.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <criterion/criterion.h>

#include "cnum.h"

static uint64_t rng = 0x9e3779b97f4a7c15ULL;

static uint64_t
next(void)
{
	rng ^= rng << 13;
	rng ^= rng >> 7;
	rng ^= rng << 17;
	return rng;
}

/* 1 when cnum_g17(v) is snprintf's %.17g of v and reads back to v. */
static int
same(double v)
{
	char a[CNUM_G17_MAX], b[64];
	size_t n = cnum_g17(a, v);
	double back;

	cnum_snprintf(b, sizeof b, "%.17g", v);
	if (strcmp(a, b) != 0 || n != strlen(b)) {
		cr_log_error("%a: cnum_g17 '%s', %%.17g '%s'", v, a, b);
		return 0;
	}
	if (isnan(v))
		return 1;
	back = cnum_strtod(a, NULL);
	if (memcmp(&back, &v, sizeof v) != 0) {
		cr_log_error("%a: '%s' reads back as %a", v, a, back);
		return 0;
	}
	return 1;
}

/* v and its k neighbours on each side */
static int
around(double v, int k)
{
	double lo = v, hi = v;
	int ok = same(v) && same(-v);

	for (int i = 0; i < k && ok; i++) {
		lo = nextafter(lo, -INFINITY);
		hi = nextafter(hi, INFINITY);
		ok = same(lo) && same(hi);
	}
	return ok;
}

Test(cnum, g17_random_bits)
{
	long bad = 0;

	for (long i = 0; i < 300000; i++) {
		uint64_t u = next();
		double v;

		memcpy(&v, &u, sizeof v);
		bad += !same(v);
	}
	cr_assert_eq(bad, 0, "%ld of 300000 differ", bad);
}

Test(cnum, g17_random_decades)
{
	long bad = 0;

	/* 53 random bits times 10^k, k from -320 to 308 */
	for (long i = 0; i < 300000; i++) {
		uint64_t u = next();
		double m = (double)(u >> 11) / 9007199254740992.0;
		int k = (int)(next() % 629) - 320;

		bad += !same(m * pow(10, k));
	}
	cr_assert_eq(bad, 0, "%ld differ", bad);
}

Test(cnum, g17_subnormals_and_limits)
{
	long bad = 0;

	for (long i = 0; i < 50000; i++) {
		uint64_t u = next() & ((1ULL << 52) - 1);
		double v;

		memcpy(&v, &u, sizeof v);
		bad += !same(v) + !same(-v);
	}
	bad += !around(DBL_TRUE_MIN, 50) + !around(DBL_MIN, 50) + !same(DBL_MAX) + !same(-DBL_MAX) +
	       !around(nextafter(DBL_MAX, 0), 50) + !around(DBL_EPSILON, 50);
	cr_assert_eq(bad, 0, "%ld differ", bad);
}

Test(cnum, g17_powers_integers_ties)
{
	long bad = 0;
	char s[32];

	/* every power of two: 2^-25 = 2.98023223876953125e-08, a tie, is among them */
	for (int e = -1074; e <= 1023; e++)
		bad += !around(ldexp(1, e), 3);
	for (int e = -323; e <= 308; e++) {
		snprintf(s, sizeof s, "1e%d", e);
		bad += !around(cnum_strtod(s, NULL), 3);
	}
	for (long i = 0; i <= 100000; i++)
		bad += !same((double)i) + !same((double)i / 1000);
	for (long i = -1000; i <= 1000; i++)
		bad += !same(9007199254740992.0 + (double)i * 2) + !same(1e17 + (double)i * 16);
	/* the ends of %g's fixed notation: exponents -5, -4, 16 and 17 */
	bad += !around(1e-5, 20) + !around(1e-4, 20) + !around(1e16, 20) + !around(1e17, 20) +
	       !around(0.1, 20) + !around(1.0 / 3, 20) + !around(123456789012345678.0, 20);
	cr_assert_eq(bad, 0, "%ld differ", bad);
}

Test(cnum, g17_zero_and_non_finite)
{
	char a[CNUM_G17_MAX];

	cr_assert_str_eq((cnum_g17(a, 0.0), a), "0");
	cr_assert_str_eq((cnum_g17(a, -0.0), a), "-0");
	cr_assert(same(INFINITY) && same(-INFINITY) && same(NAN) && same(-NAN));
	cr_assert_eq(cnum_g17(a, 0.5), 3);
	cr_assert_str_eq(a, "0.5");
}

Test(cnum, g17_in_a_decimal_comma_locale)
{
	locale_t de = newlocale(LC_ALL_MASK, "de_DE.UTF-8", (locale_t)0), old;
	char a[CNUM_G17_MAX];

	cr_assert_neq(de, (locale_t)0, "de_DE.UTF-8 is missing (make deps installs it)");
	old = uselocale(de);
	cnum_g17(a, 1.5);
	cr_assert_str_eq(a, "1.5");
	cnum_g17(a, 0.1);
	cr_assert_str_eq(a, "0.10000000000000001");
	cnum_g17(a, 1234.5e-7);
	cr_assert_str_eq(a, "0.00012344999999999999");
	cnum_g17(a, -2.5e-300);
	cr_assert_str_eq(a, "-2.5e-300");
	uselocale(old);
	freelocale(de);
}

Test(cnum, long_as_printf)
{
	static const long v[] = { 0, 1, -1, 9, 10, -10, 99, 100, 123456789, LONG_MAX, LONG_MIN,
	                          LONG_MIN + 1 };
	char a[24], b[24];

	for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
		size_t n = cnum_long(a, v[i]);

		snprintf(b, sizeof b, "%ld", v[i]);
		cr_assert_str_eq(a, b);
		cr_assert_eq(n, strlen(b));
	}
	for (int i = 0; i < 10000; i++) {
		long x = (long)next();

		cnum_long(a, x);
		snprintf(b, sizeof b, "%ld", x);
		cr_assert_str_eq(a, b);
	}
}
