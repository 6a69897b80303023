/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law_pow.h - powers shared by the power-law contact laws (private to the engine).
 */
#ifndef HYBOUNCE_LAW_POW_H
#define HYBOUNCE_LAW_POW_H

#include <math.h>

/*
 * Powers of the law, cheap enough for the right-hand side: the common
 * exponents 1, 1.5 and 2 avoid pow(), and no expression evaluates pow(0, q)
 * with q < 0, so every value and partial is finite at x = 0 for p >= 1.
 */

/* |x|^p. */
static inline double
apow(double x, double p)
{
	double a = fabs(x);

	if (p == 1.5)
		return a * sqrt(a);
	if (p == 2.0)
		return a * a;
	if (p == 1.0)
		return a;
	return pow(a, p);
}

/* The odd power x|x|^(p-1). */
static inline double
spow(double x, double p)
{
	double a = apow(x, p);

	return x < 0 ? -a : a;
}

/* d/dx x|x|^(p-1) = p|x|^(p-1) (1 at x = 0 when p = 1). */
static inline double
dspow(double x, double p)
{
	double a = fabs(x);

	if (p == 1.5)
		return 1.5 * sqrt(a);
	if (p == 2.0)
		return 2.0 * a;
	if (p == 1.0)
		return 1.0;
	return p * pow(a, p - 1.0);
}

/* d/dx |x|; at the kink x = 0 the left derivative, -1. */
static inline double
dabs1(double x)
{
	return x > 0 ? 1.0 : -1.0;
}

/* d/dx |x|^p = p x|x|^(p-2) (left derivative -1 at x = 0 when p = 1). */
static inline double
dapow(double x, double p)
{
	double d;

	if (p == 1.0)
		return dabs1(x);
	d = dspow(x, p);
	return x < 0 ? -d : d;
}

#endif
