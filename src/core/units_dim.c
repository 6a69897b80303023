/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * units_dim.c - dimensions (see units.h): the named ones (hb_unit_length
 * ...), their equality and their names in text ("N s m^-5/2").
 *
 * Dimensions are exponents of kg, m and s; two dimensions are equal when
 * every exponent agrees within 1e-9.  Parsing is in units.c, formatting
 * values in units_format.c.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/units.h"
#include "cnum.h"
#include "units_impl.h"


const struct hb_unit_dim hb_unit_none = { 0, 0, 0, 0, 0 };
const struct hb_unit_dim hb_unit_length = { 0, 1, 0, 0, 0 };
const struct hb_unit_dim hb_unit_time = { 0, 0, 1, 0, 0 };
const struct hb_unit_dim hb_unit_mass = { 1, 0, 0, 0, 0 };
const struct hb_unit_dim hb_unit_velocity = { 0, 1, -1, 0, 0 };
const struct hb_unit_dim hb_unit_accel = { 0, 1, -2, 0, 0 };
const struct hb_unit_dim hb_unit_force = { 1, 1, -2, 0, 0 };
const struct hb_unit_dim hb_unit_pressure = { 1, -1, -2, 0, 0 };
const struct hb_unit_dim hb_unit_density = { 1, -3, 0, 0, 0 };
const struct hb_unit_dim hb_unit_energy = { 1, 2, -2, 0, 0 };
const struct hb_unit_dim hb_unit_impulse = { 1, 1, -1, 0, 0 };

struct hb_unit_dim
hb_units_resolve(struct hb_unit_dim d, double p, double n)
{
	struct hb_unit_dim r = d;

	r.m = d.m + d.mp * p + d.mn * n;
	r.mp = 0;
	r.mn = 0;
	return r;
}

/* Exponents agree within 1e-9, relative for large ones (m^-1e17 and m^(1 - 1e17)). */
static int
exp_eq(double a, double b)
{
	return fabs(a - b) < UNITS_TOL * fmax(1.0, fmax(fabs(a), fabs(b)));
}

int
units_dim_eq(struct hb_unit_dim a, struct hb_unit_dim b)
{
	return exp_eq(a.kg, b.kg) && exp_eq(a.m, b.m) && exp_eq(a.s, b.s);
}

/*
 * Writes an exponent: "2", "-5/2", or all the digits that read back to the
 * same double ("1.23456789", "3000000000"), so that a unit written for a
 * law's exponent parses back to the same dimension.  "%.0f", never a cast
 * to int: an exponent may be far beyond INT_MAX.
 */
static void
exp_str(double e, char *buf, size_t n)
{
	double r2 = round(2 * e);

	if (fabs(e - round(e)) < UNITS_TOL && fabs(e) < 1e15)
		cnum_snprintf(buf, n, "%.0f", round(e) == 0 ? 0.0 : round(e));
	else if (fabs(2 * e - r2) < UNITS_TOL && fabs(e) < 1e15)
		cnum_snprintf(buf, n, "%.0f/2", r2);
	else
		cnum_snprintf(buf, n, "%.17g", e);
}

static void
append(char *buf, size_t n, const char *s)
{
	size_t l = strlen(buf);

	if (l + 1 < n)
		snprintf(buf + l, n - l, "%s", s);
}

/* Appends " SYM^E" (or "SYM" when e == 1) to buf. */
static void
append_factor(char *buf, size_t n, const char *sym, double e)
{
	char es[32];

	if (buf[0] != '\0' && buf[strlen(buf) - 1] != '/')
		append(buf, n, " ");
	append(buf, n, sym);
	if (fabs(e - 1) >= UNITS_TOL) {
		exp_str(e, es, sizeof es);
		append(buf, n, "^");
		append(buf, n, es);
	}
}

static int
is_zero(double e)
{
	return fabs(e) < UNITS_TOL;
}

static int
is_int(double e)
{
	return fabs(e - round(e)) < UNITS_TOL;
}

char *
hb_units_dim_str(struct hb_unit_dim d, char *buf, size_t n)
{
	static const struct {
		const char *name;
		double kg, m, s;
	} named[] = {
		{ "N", 1, 1, -2 }, { "Pa", 1, -1, -2 }, { "J", 1, 2, -2 }, { "W", 1, 2, -3 },
	};
	const char *sym[3];
	double e[3];
	int nf = 3, useN = 0;

	if (n == 0)
		return buf;
	buf[0] = '\0';
	d = hb_units_resolve(d, 0, 0);
	for (size_t i = 0; i < sizeof named / sizeof named[0]; i++) {
		struct hb_unit_dim nd = { named[i].kg, named[i].m, named[i].s, 0, 0 };
		if (units_dim_eq(d, nd)) {
			append(buf, n, named[i].name);
			return buf;
		}
	}
	/* N when the dimension holds kg m s^-2 and the rest reads well. */
	if (fabs(d.kg - 1) < UNITS_TOL && (fabs(d.s + 2) < UNITS_TOL || fabs(d.s + 1) < UNITS_TOL))
		useN = 1;
	if (useN) {
		sym[0] = "N", e[0] = 1;
		sym[1] = "s", e[1] = d.s + 2;
		sym[2] = "m", e[2] = d.m - 1;
	} else {
		sym[0] = "kg", e[0] = d.kg;
		sym[1] = "m", e[1] = d.m;
		sym[2] = "s", e[2] = d.s;
	}
	/*
	 * Positive exponents first; negative integer exponents after one '/'
	 * when there is a numerator and every negative exponent is an
	 * integer; otherwise negative exponents inline ("N s m^-5/2").
	 */
	int npos = 0, nneg = 0, negint = 1;
	for (int i = 0; i < nf; i++) {
		if (is_zero(e[i]))
			continue;
		if (e[i] > 0)
			npos++;
		else {
			nneg++;
			if (!is_int(e[i]))
				negint = 0;
		}
	}
	for (int i = 0; i < nf; i++)
		if (!is_zero(e[i]) && e[i] > 0)
			append_factor(buf, n, sym[i], e[i]);
	if (nneg == 0)
		return buf;
	if (npos > 0 && negint) {
		append(buf, n, "/");
		for (int i = 0; i < nf; i++)
			if (!is_zero(e[i]) && e[i] < 0)
				append_factor(buf, n, sym[i], -e[i]);
	} else {
		for (int i = 0; i < nf; i++)
			if (!is_zero(e[i]) && e[i] < 0)
				append_factor(buf, n, sym[i], e[i]);
	}
	return buf;
}
